//! Householder QR of a tall complex matrix that keeps its reflectors
//! (issue 15): `Qᴴ c` and `Q [Y; 0]` are applied reflector by reflector,
//! never forming the `m × q` `Q` (nalgebra's `QR::q` builds it from the
//! reflectors at twice the cost of the factorisation, and the large solve
//! only ever multiplies by it).
//!
//! Reflector `k` is `H_k = I − 2 u_k u_kᴴ` with `‖u_k‖ = 1`, zero above row
//! `k`: Hermitian and unitary, and `H_k x = −e^{i arg x₀} ‖x‖ e₀` for the part
//! `x` of column `k` from row `k` down (the sign that avoids cancellation).
//! `A = Q R` with `Q = H₀ H₁ ⋯ H_{q−1}` (first `q` columns).

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::factor::cmul;

/// `A = Q R` of an `m × q` matrix, `m ≥ q`, `Q` kept as its reflectors.
#[derive(Debug, Clone)]
pub struct Householder {
    /// `m × q`: column `k` is `u_k` (zero above row `k`; all zero when
    /// column `k` had nothing left to reflect, `H_k = I`).
    u: DMatrix<Complex64>,
    /// `q × q`, upper triangular.
    r: DMatrix<Complex64>,
}

/// `Σ_i conj(u_i) x_i`, in four interleaved partial sums: one running sum
/// is a chain the compiler may not reorder, four independent ones overlap
/// (issue 15: the same sum to rounding, in another order).
#[inline]
fn dot_conj(u: &[Complex64], x: &[Complex64]) -> Complex64 {
    let n = u.len().min(x.len());
    let body = n - n % 4;
    let (mut re, mut im) = ([0.0f64; 4], [0.0f64; 4]);
    for (a, b) in u[..body].chunks_exact(4).zip(x[..body].chunks_exact(4)) {
        for l in 0..4 {
            re[l] += a[l].re * b[l].re + a[l].im * b[l].im;
            im[l] += a[l].re * b[l].im - a[l].im * b[l].re;
        }
    }
    let (mut sr, mut si) = (
        (re[0] + re[1]) + (re[2] + re[3]),
        (im[0] + im[1]) + (im[2] + im[3]),
    );
    for (a, b) in u[body..n].iter().zip(&x[body..n]) {
        sr += a.re * b.re + a.im * b.im;
        si += a.re * b.im - a.im * b.re;
    }
    Complex64::new(sr, si)
}

/// `x ← x − 2 u (uᴴ x)`: one reflector on one column.
#[inline]
fn reflect(u: &[Complex64], x: &mut [Complex64]) {
    let d = dot_conj(u, x) * 2.0;
    for (a, b) in u.iter().zip(x.iter_mut()) {
        b.re -= a.re * d.re - a.im * d.im;
        b.im -= a.re * d.im + a.im * d.re;
    }
}

impl Householder {
    /// Factor `a` (`m × q`, `m ≥ q`).
    pub fn of(a: &DMatrix<Complex64>) -> Householder {
        let (m, q) = a.shape();
        assert!(m >= q, "Householder QR of a wide matrix");
        let mut w = a.clone();
        let mut u = DMatrix::from_element(m, q, Complex64::new(0.0, 0.0));
        for k in 0..q {
            let (head, tail) = w.as_mut_slice().split_at_mut((k + 1) * m);
            let x = &mut head[k * m + k..];
            let norm = x.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
            if norm == 0.0 {
                continue;
            }
            let x0 = x[0];
            let phase = if x0 == Complex64::new(0.0, 0.0) {
                Complex64::new(1.0, 0.0)
            } else {
                x0 / x0.norm()
            };
            let uk = &mut u.as_mut_slice()[k * m + k..(k + 1) * m];
            uk.copy_from_slice(x);
            uk[0] += phase * norm;
            let unorm = uk.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
            for z in uk.iter_mut() {
                *z /= unorm;
            }
            // Column k becomes −e^{iθ}‖x‖ e₀; the columns right of it are reflected.
            x[0] = -phase * norm;
            for z in x[1..].iter_mut() {
                *z = Complex64::new(0.0, 0.0);
            }
            let uk = &u.as_slice()[k * m + k..(k + 1) * m];
            for col in tail.chunks_exact_mut(m) {
                reflect(uk, &mut col[k..]);
            }
        }
        let r = DMatrix::from_fn(q, q, |i, j| {
            if i <= j {
                w[(i, j)]
            } else {
                Complex64::new(0.0, 0.0)
            }
        });
        Householder { u, r }
    }

    /// `R` (`q × q`, upper triangular).
    pub fn r(&self) -> &DMatrix<Complex64> {
        &self.r
    }

    /// The first `q` entries of `Qᴴ c` (`c` of `m` entries).
    pub fn adjoint_apply(&self, c: &DVector<Complex64>) -> DVector<Complex64> {
        let (m, q) = self.u.shape();
        let mut x = c.clone();
        let u = self.u.as_slice();
        for k in 0..q {
            reflect(&u[k * m + k..(k + 1) * m], &mut x.as_mut_slice()[k..]);
        }
        x.rows(0, q).into_owned()
    }

    /// `Q [y; 0]` (`m × p`) for `y` of `q` rows: the first `q` columns of `Q`
    /// times `y`.
    ///
    /// In compact WY form (LAPACK's `zlarft`): `Q = I − V T Vᴴ` with `V` the
    /// reflectors and `T` upper triangular, `T_kk = 2`,
    /// `T[..k, k] = −2 T[..k, ..k] V[:, ..k]ᴴ v_k`. Since `[y; 0]` is zero
    /// below row `q`, `Vᴴ [y; 0]` is `V`'s top `q × q` block, and the whole is
    /// two products of `m × q` matrices (`factor::cmul`, SIMD) instead of `q`
    /// reflections of every column one at a time.
    pub fn apply(&self, y: &DMatrix<Complex64>) -> DMatrix<Complex64> {
        let (m, q) = self.u.shape();
        assert_eq!(y.nrows(), q, "Householder::apply: dimensions mismatch");
        let g = cmul(&self.u.adjoint(), &self.u);
        let mut t = DMatrix::from_element(q, q, Complex64::new(0.0, 0.0));
        for k in 0..q {
            t[(k, k)] = Complex64::new(2.0, 0.0);
            if k > 0 {
                let col =
                    t.view((0, 0), (k, k)) * g.view((0, k), (k, 1)) * Complex64::new(-2.0, 0.0);
                t.view_mut((0, k), (k, 1)).copy_from(&col);
            }
        }
        let z = &t * (self.u.rows(0, q).adjoint() * y);
        let mut x = -cmul(&self.u, &z);
        let mut top = x.rows_mut(0, q);
        top += y;
        debug_assert_eq!(x.nrows(), m);
        x
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn random(m: usize, q: usize, seed: &mut u64) -> DMatrix<Complex64> {
        DMatrix::from_fn(m, q, |_, _| {
            let mut next = || {
                *seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                (*seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
            };
            Complex64::new(next(), next())
        })
    }

    #[test]
    fn the_reflectors_reproduce_the_matrix_and_q_has_orthonormal_columns() {
        let mut seed = 7;
        for (m, q) in [(5, 3), (40, 16), (3, 3), (9, 1)] {
            let mut a = random(m, q, &mut seed);
            if q > 2 {
                // A zero column and a repeated one: nothing to reflect, and R singular.
                a.column_mut(1).fill(Complex64::new(0.0, 0.0));
                let c0 = a.column(0).clone_owned();
                a.column_mut(2).copy_from(&c0);
            }
            let h = Householder::of(&a);
            let qm = h.apply(&DMatrix::identity(q, q));
            assert!(
                (&qm * h.r() - &a).norm() < 1e-13 * (1.0 + a.norm()),
                "{m}x{q}"
            );
            assert!((qm.adjoint() * &qm - DMatrix::identity(q, q)).norm() < 1e-13);
            let c = random(m, 1, &mut seed).column(0).clone_owned();
            assert!((h.adjoint_apply(&c) - qm.adjoint() * &c).norm() < 1e-13);
            for i in 0..q {
                for j in 0..i {
                    assert_eq!(h.r()[(i, j)], Complex64::new(0.0, 0.0));
                }
            }
        }
    }
}
