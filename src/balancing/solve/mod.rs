//! From a checked session to an answer: the influence matrix (method §2),
//! its thin factorisations, the weighted least-squares correction (method §3),
//! the diagnostics, and the solution and report built from them.

pub mod diagnostics;
pub mod factor;
pub mod householder;
pub mod influence;
pub mod practical;
pub mod report;
pub mod shared_id;
pub mod solution;
mod weighted;

pub use weighted::{least_squares, solve, solve_checked, solve_kept, weighted_problem, Fit};
