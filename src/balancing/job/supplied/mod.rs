//! Supplied influence coefficients (v2 "Coefficients supplied or stored"):
//! the option `influence_coefficients` (from another tool, a rotor model, or a
//! machine's stored coefficients) used instead of estimating `W` from trial
//! runs. [`resolve`] reads the option onto the session's rows (`resolve.rs`);
//! [`fill`] gives a correction computed with them its uncertainty, from the
//! reference readings' noise and the coefficients' supplied covariance
//! (`uncertainty.rs`, method 3.2 and 3.3 differentiated).

use nalgebra::{DMatrix, Matrix2};
use num_complex::Complex64;

mod resolve;
mod uncertainty;

pub(crate) use resolve::{check_entry, check_unit};
pub use resolve::{covariance_frame, resolvable, resolve, unit_name};
pub use uncertainty::fill;

/// Supplied coefficients on the session's rows, internal frame.
#[derive(Debug, Clone)]
pub struct Supplied {
    /// Rows × planes; 0 where none was supplied (a plane not solved for).
    pub w: DMatrix<Complex64>,
    /// `[row][plane]` covariance of `(Re, Im)` of `W_aj`, internal frame.
    pub cov: Vec<Vec<Matrix2<f64>>>,
    /// Which `(row, plane)` were supplied.
    pub given: DMatrix<bool>,
}
