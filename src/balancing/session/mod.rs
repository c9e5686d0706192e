//! What a session is and how it enters the core: the wire structs, their
//! limits and validation, the error type that names the bad field, the
//! conventions that turn readings into phasors (method §1), which sensors
//! and speeds a solve selects, and how session files are read.

#[macro_use]
pub mod wire;
pub mod error;
pub mod file;
pub mod limits;
pub mod model;
pub mod phasor;
pub mod select;
pub mod trig;
pub mod validate;
pub mod words;
