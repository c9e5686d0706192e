//! The thin SVD of a tall weighted matrix, through its QR (issue 15): the
//! least-squares correction (3.2), the pseudo-inverse and `(AᴴA)⁺` the
//! uncertainty propagation needs, without ever forming `AᴴA`.
//!
//! Why QR first: for `A` of `m` rows and `q ≤ m` columns, `A = Q R` with `Q`
//! `m × q` orthonormal and `R` `q × q` (Householder, backward stable), and the
//! SVD of the small `R = U_R Σ Vᴴ` gives `A = (Q U_R) Σ Vᴴ`, the same singular
//! values and right vectors as an SVD of `A` itself, to rounding. nalgebra's
//! SVD bidiagonalises the whole tall matrix and iterates on it with `m`-long
//! rotations; QR then a `q × q` SVD costs `O(m q²)` once, and everything after
//! works on `q × q` matrices or multiplies by `Q`.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

/// `A = Q U Σ Vᴴ` with `Q U` of orthonormal columns (only the `k = min(m, q)`
/// columns that can carry a nonzero singular value).
#[derive(Debug, Clone)]
pub struct ThinSvd {
    /// `m × k`, orthonormal columns: the left singular vectors.
    pub u: DMatrix<Complex64>,
    /// `k` singular values, in the order of `u`'s columns and `v_t`'s rows.
    pub singular_values: DVector<f64>,
    /// `k × q`: the right singular vectors, conjugate-transposed.
    pub v_t: DMatrix<Complex64>,
}

impl ThinSvd {
    /// The thin SVD of `a` (QR first when it has more rows than columns).
    pub fn of(a: &DMatrix<Complex64>) -> ThinSvd {
        let (m, q) = a.shape();
        if m == 0 || q == 0 {
            return ThinSvd {
                u: DMatrix::zeros(m, 0),
                singular_values: DVector::zeros(0),
                v_t: DMatrix::zeros(0, q),
            };
        }
        if m <= q {
            let svd = a.clone().svd(true, true);
            return ThinSvd {
                u: svd.u.expect("SVD computed with U"),
                singular_values: svd.singular_values,
                v_t: svd.v_t.expect("SVD computed with Vᴴ"),
            };
        }
        let qr = a.clone().qr();
        let svd = qr.r().svd(true, true);
        ThinSvd {
            u: qr.q() * svd.u.expect("SVD computed with U"),
            singular_values: svd.singular_values,
            v_t: svd.v_t.expect("SVD computed with Vᴴ"),
        }
    }

    /// Largest singular value (0 for an empty matrix).
    pub fn max(&self) -> f64 {
        self.singular_values.iter().copied().fold(0.0, f64::max)
    }

    /// Indices of the singular values above `tol` (and above 0).
    fn kept(&self, tol: f64) -> impl Iterator<Item = (usize, f64)> + '_ {
        self.singular_values
            .iter()
            .copied()
            .enumerate()
            .filter(move |&(_, s)| s > tol && s > 0.0)
    }

    /// `A⁺ c` with singular values at or below `tol` left out.
    pub fn solve(&self, c: &DVector<Complex64>, tol: f64) -> DVector<Complex64> {
        let uc = self.u.ad_mul(c);
        let mut x = DVector::zeros(self.v_t.ncols());
        for (i, s) in self.kept(tol) {
            // Multiply by a real reciprocal: a complex division squares its
            // divisor's modulus, which underflows for tiny singular values.
            x += self.v_t.row(i).adjoint() * (uc[i] * (1.0 / s));
        }
        x
    }

    /// `(A⁺, (AᴴA)⁺)`, `q × m` and `q × q`, with singular values at or below
    /// `tol` left out: `V Σ⁺ Uᴴ` and `V Σ⁺² Vᴴ`, one product each.
    pub fn pinv_and_gram_inv(&self, tol: f64) -> (DMatrix<Complex64>, DMatrix<Complex64>) {
        let (m, q) = (self.u.nrows(), self.v_t.ncols());
        let kept: Vec<(usize, f64)> = self.kept(tol).collect();
        if kept.is_empty() {
            return (DMatrix::zeros(q, m), DMatrix::zeros(q, q));
        }
        // V Σ⁺ and V Σ⁺², only the kept columns.
        let v_s = DMatrix::from_fn(q, kept.len(), |j, c| {
            let (i, s) = kept[c];
            self.v_t[(i, j)].conj() * (1.0 / s)
        });
        let v_s2 = DMatrix::from_fn(q, kept.len(), |j, c| {
            let (i, s) = kept[c];
            self.v_t[(i, j)].conj() * (1.0 / s).powi(2)
        });
        let v = DMatrix::from_fn(q, kept.len(), |j, c| self.v_t[(kept[c].0, j)].conj());
        let u = DMatrix::from_fn(m, kept.len(), |a, c| self.u[(a, kept[c].0)]);
        (v_s * u.adjoint(), v_s2 * v.adjoint())
    }
}

/// Singular values and right singular vectors (`Vᴴ`, `k × q`) of `a`, QR
/// first when tall; no left vectors are formed.
pub fn right_svd(a: &DMatrix<Complex64>) -> (DVector<f64>, DMatrix<Complex64>) {
    let small = if a.nrows() > a.ncols() {
        a.clone().qr().r()
    } else {
        a.clone()
    };
    let svd = small.svd(false, true);
    (svd.singular_values, svd.v_t.expect("SVD computed with Vᴴ"))
}

/// Singular values of `a`, QR first when tall.
pub fn singular_values(a: &DMatrix<Complex64>) -> DVector<f64> {
    if a.nrows() > a.ncols() {
        a.clone().qr().r().singular_values()
    } else {
        a.singular_values()
    }
}
