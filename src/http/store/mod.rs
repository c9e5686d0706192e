//! The stored resources: sessions, their runs (with versions and ETags) and
//! machines with their pooled coefficient versions; `text` is what their
//! stored strings may hold.

pub mod coefficients_from;
pub mod created;
pub mod machines;
pub mod runs;
pub mod sessions;
pub mod text;
