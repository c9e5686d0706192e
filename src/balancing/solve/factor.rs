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

use super::householder::Householder;

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

    /// `(AᴴA)⁺` (`q × q`) with singular values at or below `tol` left out:
    /// `V Σ⁺² Vᴴ`, without `A⁺`.
    pub fn gram_inv(&self, tol: f64) -> DMatrix<Complex64> {
        let q = self.v_t.ncols();
        let kept: Vec<(usize, f64)> = self.kept(tol).collect();
        if kept.is_empty() {
            return DMatrix::zeros(q, q);
        }
        let v_s2 = DMatrix::from_fn(q, kept.len(), |j, c| {
            let (i, s) = kept[c];
            self.v_t[(i, j)].conj() * (1.0 / s).powi(2)
        });
        let v = DMatrix::from_fn(q, kept.len(), |j, c| self.v_t[(kept[c].0, j)].conj());
        v_s2 * v.adjoint()
    }

    /// `(A⁺, (AᴴA)⁺)`, `q × m` and `q × q`, with singular values at or below
    /// `tol` left out: `V Σ⁺ Uᴴ` and `V Σ⁺² Vᴴ`, one product each.
    pub fn pinv_and_gram_inv(&self, tol: f64) -> (DMatrix<Complex64>, DMatrix<Complex64>) {
        let (m, q) = (self.u.nrows(), self.v_t.ncols());
        let kept: Vec<(usize, f64)> = self.kept(tol).collect();
        if kept.is_empty() {
            return (DMatrix::zeros(q, m), DMatrix::zeros(q, q));
        }
        // V Σ⁺, only the kept columns; (AᴴA)⁺ as `gram_inv`.
        let v_s = DMatrix::from_fn(q, kept.len(), |j, c| {
            let (i, s) = kept[c];
            self.v_t[(i, j)].conj() * (1.0 / s)
        });
        let u = DMatrix::from_fn(m, kept.len(), |a, c| self.u[(a, kept[c].0)]);
        (v_s * u.adjoint(), self.gram_inv(tol))
    }
}

/// The weighted matrix `A = G W` of a solve (method 3.3), factored once and
/// shared by everything the solve asks of it (issue 15): the least-squares
/// correction, the significance factors, the condition number, the
/// undetermined planes and the uncertainty propagation each factored the same
/// `m × q` matrix again.
///
/// For a tall `A = Q R` the `q × q` `R` carries everything but the left
/// vectors: scaling `A`'s columns to unit norm is scaling `R`'s
/// (`A D = Q (R D)`), so `cond(A D)` and the right singular vectors of `A D`
/// come from the small `R D`.
#[derive(Debug, Clone)]
pub struct Factored {
    /// `Q` of `A = Q R`, as its reflectors, when `A` has more rows than
    /// columns; else `None`, and `r` is `A`.
    q: Option<Householder>,
    /// `R` (`q × q`, upper triangular), or `A` itself.
    r: DMatrix<Complex64>,
    /// The SVD of `r`: its `u` is `U_R`, the left vectors of `A` are `Q U_R`.
    svd: ThinSvd,
    /// Singular values of `R D` (columns of `A` at unit norm).
    scaled: DVector<f64>,
    /// Rows of `A`.
    rows: usize,
}

impl Factored {
    /// One QR (when tall) and one SVD of the small factor.
    pub fn of(a: &DMatrix<Complex64>) -> Factored {
        let (q, r) = if a.nrows() > a.ncols() {
            let qr = Householder::of(a);
            let r = qr.r().clone();
            (Some(qr), r)
        } else {
            (None, a.clone())
        };
        let svd = ThinSvd::of(&r);
        let scaled = if r.is_empty() {
            DVector::zeros(0)
        } else {
            unit_columns(&r).singular_values()
        };
        Factored {
            q,
            r,
            svd,
            scaled,
            rows: a.nrows(),
        }
    }

    /// Largest singular value of `A`.
    pub fn max(&self) -> f64 {
        self.svd.max()
    }

    /// Singular values of `A`.
    pub fn singular_values(&self) -> &DVector<f64> {
        &self.svd.singular_values
    }

    /// `Qᴴ c`: `c` in the coordinates of `R` (the identity when not tall).
    fn project(&self, c: &DVector<Complex64>) -> DVector<Complex64> {
        match &self.q {
            Some(q) => q.adjoint_apply(c),
            None => c.clone(),
        }
    }

    /// `A⁺ c` with singular values at or below `tol` left out.
    pub fn solve(&self, c: &DVector<Complex64>, tol: f64) -> DVector<Complex64> {
        self.svd.solve(&self.project(c), tol)
    }

    /// `(A⁺, (AᴴA)⁺)` as [`ThinSvd::pinv_and_gram_inv`]: `R⁺ Qᴴ` and `(RᴴR)⁺`.
    pub fn pinv_and_gram_inv(&self, tol: f64) -> (DMatrix<Complex64>, DMatrix<Complex64>) {
        let (r_pinv, gram_inv) = self.svd.pinv_and_gram_inv(tol);
        match &self.q {
            Some(q) => (q.apply(&r_pinv.adjoint()).adjoint(), gram_inv),
            None => (r_pinv, gram_inv),
        }
    }

    /// `(AᴴA)⁺ = (RᴴR)⁺` as [`ThinSvd::gram_inv`].
    pub fn gram_inv(&self, tol: f64) -> DMatrix<Complex64> {
        self.svd.gram_inv(tol)
    }

    /// `R` (or `A` when not tall): `AᴴA = RᴴR` in `q` rows.
    pub fn small(&self) -> &DMatrix<Complex64> {
        &self.r
    }

    /// `cond(A D)`, columns at unit norm: σ_max/σ_min, capped at 1e16.
    pub fn condition_number(&self) -> f64 {
        let (max, min) = (self.scaled.max(), self.scaled.min());
        if self.scaled.is_empty() || max == 0.0 {
            return 1e16;
        }
        (max / min.max(max * 1e-16)).min(1e16)
    }

    /// Rows of `A`.
    pub fn nrows(&self) -> usize {
        self.rows
    }

    /// The SVD of `A D` (columns at unit norm), singular values and `Vᴴ`,
    /// only when one of its singular values is at or below `tol` times the
    /// largest (else `None`: no combination of columns is lost).
    pub fn scaled_null(&self, tol: f64) -> Option<(DVector<f64>, DMatrix<Complex64>)> {
        let smax = self.scaled.max();
        if !self.scaled.iter().any(|&s| s <= tol * smax) {
            return None;
        }
        let svd = unit_columns(&self.r).svd(false, true);
        Some((svd.singular_values, svd.v_t.expect("SVD computed with Vᴴ")))
    }
}

/// `a` with every nonzero column scaled to unit norm.
fn unit_columns(a: &DMatrix<Complex64>) -> DMatrix<Complex64> {
    let mut s = a.clone();
    for mut col in s.column_iter_mut() {
        let norm = col.norm();
        if norm > 0.0 {
            col /= Complex64::from(norm);
        }
    }
    s
}

/// `a b` for complex matrices through four real products (issue 15):
/// nalgebra multiplies `f64` matrices with the blocked SIMD kernels of
/// `matrixmultiply` but complex ones with a plain loop, several times slower
/// on the `rows × planes` products of a large solve. Same sums, rounded in
/// another order.
pub fn cmul(a: &DMatrix<Complex64>, b: &DMatrix<Complex64>) -> DMatrix<Complex64> {
    assert_eq!(a.ncols(), b.nrows(), "cmul: dimensions mismatch");
    // Small products gain nothing from the split.
    if a.nrows() * a.ncols() * b.ncols() < 4096 {
        return a * b;
    }
    let (ar, ai) = split(a);
    let (br, bi) = split(b);
    let re = &ar * &br - &ai * &bi;
    let im = &ar * &bi + &ai * &br;
    // Through the storage slices: nalgebra's `map` and `zip_map` step
    // element by element through strides, several times the cost.
    let data = re
        .as_slice()
        .iter()
        .zip(im.as_slice())
        .map(|(&re, &im)| Complex64::new(re, im))
        .collect();
    DMatrix::from_vec(a.nrows(), b.ncols(), data)
}

/// Real and imaginary parts of `a`, as two real matrices.
fn split(a: &DMatrix<Complex64>) -> (DMatrix<f64>, DMatrix<f64>) {
    let (m, n) = a.shape();
    let s = a.as_slice();
    (
        DMatrix::from_vec(m, n, s.iter().map(|z| z.re).collect()),
        DMatrix::from_vec(m, n, s.iter().map(|z| z.im).collect()),
    )
}
