//! The service itself: the `fieldbal serve` binary and its behaviour around
//! the API (request ids, limits, time limits).

mod behaviour;
mod form_files;
mod serve;
