//! The stored resources: sessions, their runs (with versions and ETags) and
//! machines with their pooled coefficient versions.

pub mod coefficients_from;
pub mod created;
pub mod machines;
pub mod runs;
pub mod sessions;
