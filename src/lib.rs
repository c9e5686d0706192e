//! fieldbal: field balancing of rotors by experimental influence coefficients.
//!
//! - [`balancing`]: the pure core (session model, validation, influence
//!   coefficients, least-squares and min-max corrections, uncertainty).
//! - [`identification`]: the pure identification core (one-mass rotor from
//!   influence coefficients, free decay, discrete-model correction).
//! - [`http`]: the REST service and the embedded web form.
//! - [`db`]: storage of sessions, runs and solutions in SQLite.
//! - [`cli`]: `fieldbal serve`, `fieldbal solve` and `fieldbal identify`.
//!
//! Angle conventions are the session's own at every edge (phase `lag`/`lead`,
//! weight angles `against_rotation`/`with_rotation`); see `balancing`.

pub mod balancing;
pub mod cli;
pub mod db;
pub mod http;
pub mod identification;
