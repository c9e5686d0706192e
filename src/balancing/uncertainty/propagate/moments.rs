//! Complex and real forms of a noise covariance: the second moments
//! (`E|z|²`, `E[z²]`; `K = E[z zᴴ]`, `J = E[z zᵀ]`) in which the propagation
//! sums its terms, their real 2×2 and `2q × 2q` covariances, and the
//! pseudo-inverses of the SVD that the propagation's callers share.

use nalgebra::{DMatrix, Matrix2};
use num_complex::Complex64;

use super::RANK_TOLERANCE;
use crate::balancing::factor::ThinSvd;

/// `(A⁺, (AᴴA)⁺)` from the SVD of `A`, never forming `AᴴA` itself; the thin
/// SVD goes through the QR of a tall `A` (`factor`, issue 15).
pub(in crate::balancing::uncertainty) fn svd_parts(
    a: &DMatrix<Complex64>,
) -> (DMatrix<Complex64>, DMatrix<Complex64>) {
    let svd = ThinSvd::of(a);
    svd.pinv_and_gram_inv(RANK_TOLERANCE * svd.max())
}

/// Second moments of a complex error `z`: `k = E[z z̄]` and the pseudo-
/// covariance `p = E[z²]`; for a vector, `K = E[z zᴴ]` and `J = E[z zᵀ]`.
/// Together they are the real covariance of (Re z, Im z) (see [`real_cov`]),
/// and for `dC = α δ + β δ̄` they sum over independent readings without ever
/// forming a per-reading Jacobian.
pub(in crate::balancing::uncertainty) fn moments(cov: &Matrix2<f64>) -> (f64, Complex64) {
    (
        cov[(0, 0)] + cov[(1, 1)],
        Complex64::new(cov[(0, 0)] - cov[(1, 1)], cov[(0, 1)] + cov[(1, 0)]),
    )
}

/// The real 2×2 covariance of (Re z, Im z) from `k = E|z|²` and `p = E[z²]`.
pub(super) fn real_cov(k: f64, p: Complex64) -> Matrix2<f64> {
    Matrix2::new((k + p.re) / 2.0, p.im / 2.0, p.im / 2.0, (k - p.re) / 2.0)
}

/// The real `2q × 2q` covariance, ordered (Re z₀, Im z₀, Re z₁, …), from
/// `K = E[z zᴴ]` and `J = E[z zᵀ]`: `E[x_j x_l] = Re(K+J)/2`,
/// `E[y_j y_l] = Re(K−J)/2`, `E[x_j y_l] = Im(J−K)/2`, `E[y_j x_l] = Im(J+K)/2`.
pub(super) fn real_cov_full(k: &DMatrix<Complex64>, j: &DMatrix<Complex64>) -> DMatrix<f64> {
    let q = k.nrows();
    DMatrix::from_fn(2 * q, 2 * q, |r, c| {
        let (kk, jj) = (k[(r / 2, c / 2)], j[(r / 2, c / 2)]);
        match (r % 2, c % 2) {
            (0, 0) => (kk.re + jj.re) / 2.0,
            (1, 1) => (kk.re - jj.re) / 2.0,
            (0, _) => (jj.im - kk.im) / 2.0,
            _ => (jj.im + kk.im) / 2.0,
        }
    })
}
