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
//!
//! The columns are kept as separate real and imaginary parts (issue 15):
//! interleaved complex numbers defeat the compiler's vector instructions,
//! split ones are plain `f64` lanes it packs two (SSE2) or four (AVX2, where
//! the processor has it) to an instruction. The sums are the same, in the
//! same order, as one complex number at a time.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::factor::cmul;

/// `A = Q R` of an `m × q` matrix, `m ≥ q`, `Q` kept as its reflectors.
#[derive(Debug, Clone)]
pub struct Householder {
    /// Rows `m`.
    m: usize,
    /// Columns `q`.
    q: usize,
    /// Real and imaginary parts of the reflectors, column-major `m × q`:
    /// column `k` from row `k` down is `u_k` (all zero when column `k` had
    /// nothing left to reflect, `H_k = I`); above row `k`, `R`'s entries,
    /// never read as `u_k`.
    ur: Vec<f64>,
    ui: Vec<f64>,
    /// `q × q`, upper triangular.
    r: DMatrix<Complex64>,
}

/// `Σ_i (a_i b_i ± c_i d_i)` in four interleaved partial sums: one running
/// sum is a chain the compiler may not reorder, four independent ones overlap
/// and pack into vector lanes (issue 15: the same sum to rounding, in
/// another order).
#[inline(always)]
fn dot4<const MINUS: bool>(a: &[f64], b: &[f64], c: &[f64], d: &[f64]) -> f64 {
    let n = a.len();
    let (b, c, d) = (&b[..n], &c[..n], &d[..n]);
    let body = n - n % 4;
    let mut s = [0.0f64; 4];
    let chunks = a[..body]
        .chunks_exact(4)
        .zip(b[..body].chunks_exact(4))
        .zip(c[..body].chunks_exact(4).zip(d[..body].chunks_exact(4)));
    for ((a, b), (c, d)) in chunks {
        for l in 0..4 {
            s[l] += if MINUS {
                a[l] * b[l] - c[l] * d[l]
            } else {
                a[l] * b[l] + c[l] * d[l]
            };
        }
    }
    let mut t = (s[0] + s[1]) + (s[2] + s[3]);
    for i in body..n {
        t += if MINUS {
            a[i] * b[i] - c[i] * d[i]
        } else {
            a[i] * b[i] + c[i] * d[i]
        };
    }
    t
}

/// `Σ_i conj(u_i) x_i`, real and imaginary parts: each its own pass of
/// [`dot4`], which the compiler packs lane by lane (one pass for both it
/// pairs them up instead, with shuffles).
#[inline(always)]
fn dot_conj(ur: &[f64], ui: &[f64], xr: &[f64], xi: &[f64]) -> (f64, f64) {
    (dot4::<false>(ur, xr, ui, xi), dot4::<true>(ur, xi, ui, xr))
}

/// `x ← x − 2 u (uᴴ x)`: one reflector on one column.
#[inline(always)]
fn reflect(ur: &[f64], ui: &[f64], xr: &mut [f64], xi: &mut [f64]) {
    let n = ur.len();
    let (ui, xr, xi) = (&ui[..n], &mut xr[..n], &mut xi[..n]);
    let (dr, di) = dot_conj(ur, ui, xr, xi);
    let (dr, di) = (dr * 2.0, di * 2.0);
    for i in 0..n {
        xr[i] -= ur[i] * dr - ui[i] * di;
        xi[i] -= ur[i] * di + ui[i] * dr;
    }
}

/// `‖x‖₂` of the complex vector with parts `xr`, `xi` (the same sum in the
/// same order wherever the kernel needs a norm).
#[inline(always)]
fn norm2(xr: &[f64], xi: &[f64]) -> f64 {
    xr.iter()
        .zip(xi.iter())
        .map(|(a, b)| a * a + b * b)
        .sum::<f64>()
        .sqrt()
}

/// The factorisation of `w` (real and imaginary parts, `m × q` column-major)
/// in place, LAPACK's way: from row `k` down, column `k` becomes the
/// reflector `u_k` (zero when there was nothing to reflect); above row `k`
/// it is `R`'s column, whose diagonal goes to `diag` (no second `m × q`
/// array, no copy of each column into it).
#[inline(always)]
fn factor_kernel(m: usize, q: usize, wr: &mut [f64], wi: &mut [f64], diag: &mut [Complex64]) {
    for k in 0..q {
        let (hr, tr) = wr.split_at_mut((k + 1) * m);
        let (hi, ti) = wi.split_at_mut((k + 1) * m);
        let (xr, xi) = (&mut hr[k * m + k..], &mut hi[k * m + k..]);
        let norm = norm2(xr, xi);
        if norm == 0.0 {
            // Nothing to reflect: `H_k = I`, `u_k = 0` (and `R_kk = 0`).
            diag[k] = Complex64::new(0.0, 0.0);
            continue;
        }
        let x0 = Complex64::new(xr[0], xi[0]);
        let phase = if x0 == Complex64::new(0.0, 0.0) {
            Complex64::new(1.0, 0.0)
        } else {
            x0 / x0.norm()
        };
        // Column k of R is −e^{iθ}‖x‖ e₀; x itself becomes u_k.
        diag[k] = -phase * norm;
        let head = phase * norm;
        xr[0] += head.re;
        xi[0] += head.im;
        let unorm = norm2(xr, xi);
        for (a, b) in xr.iter_mut().zip(xi.iter_mut()) {
            *a /= unorm;
            *b /= unorm;
        }
        let (vr, vi) = (&*xr, &*xi);
        for (cr, ci) in tr.chunks_exact_mut(m).zip(ti.chunks_exact_mut(m)) {
            reflect(vr, vi, &mut cr[k..], &mut ci[k..]);
        }
    }
}

fn factor_plain(m: usize, q: usize, wr: &mut [f64], wi: &mut [f64], diag: &mut [Complex64]) {
    factor_kernel(m, q, wr, wi, diag)
}

/// [`factor_kernel`] compiled for AVX2: four lanes to an instruction. The
/// same operations in the same order (no fused multiply-add), so the same
/// bits as [`factor_plain`].
///
/// # Safety
/// Only on a processor with AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn factor_avx2(m: usize, q: usize, wr: &mut [f64], wi: &mut [f64], diag: &mut [Complex64]) {
    factor_kernel(m, q, wr, wi, diag)
}

fn factor(m: usize, q: usize, wr: &mut [f64], wi: &mut [f64], diag: &mut [Complex64]) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the processor was just found to have AVX2.
        return unsafe { factor_avx2(m, q, wr, wi, diag) };
    }
    factor_plain(m, q, wr, wi, diag)
}

impl Householder {
    /// Factor `a` (`m × q`, `m ≥ q`).
    pub fn of(a: &DMatrix<Complex64>) -> Householder {
        let (m, q) = a.shape();
        assert!(m >= q, "Householder QR of a wide matrix");
        // The storage slice, not `a.iter()`: nalgebra's element iterator
        // steps through strides at several times the cost.
        let mut ur: Vec<f64> = a.as_slice().iter().map(|z| z.re).collect();
        let mut ui: Vec<f64> = a.as_slice().iter().map(|z| z.im).collect();
        let mut diag = vec![Complex64::new(0.0, 0.0); q];
        factor(m, q, &mut ur, &mut ui, &mut diag);
        let r = DMatrix::from_fn(q, q, |i, j| match i.cmp(&j) {
            std::cmp::Ordering::Less => Complex64::new(ur[j * m + i], ui[j * m + i]),
            std::cmp::Ordering::Equal => diag[i],
            std::cmp::Ordering::Greater => Complex64::new(0.0, 0.0),
        });
        Householder { m, q, ur, ui, r }
    }

    /// `R` (`q × q`, upper triangular).
    pub fn r(&self) -> &DMatrix<Complex64> {
        &self.r
    }

    /// The first `q` entries of `Qᴴ c` (`c` of `m` entries).
    pub fn adjoint_apply(&self, c: &DVector<Complex64>) -> DVector<Complex64> {
        let (m, q) = (self.m, self.q);
        let mut xr: Vec<f64> = c.as_slice().iter().map(|z| z.re).collect();
        let mut xi: Vec<f64> = c.as_slice().iter().map(|z| z.im).collect();
        for k in 0..q {
            let s = k * m + k..(k + 1) * m;
            reflect(&self.ur[s.clone()], &self.ui[s], &mut xr[k..], &mut xi[k..]);
        }
        DVector::from_fn(q, |i, _| Complex64::new(xr[i], xi[i]))
    }

    /// The reflectors as one complex `m × q` matrix.
    fn u(&self) -> DMatrix<Complex64> {
        DMatrix::from_fn(self.m, self.q, |i, k| {
            if i < k {
                Complex64::new(0.0, 0.0)
            } else {
                Complex64::new(self.ur[k * self.m + i], self.ui[k * self.m + i])
            }
        })
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
        let (m, q) = (self.m, self.q);
        assert_eq!(y.nrows(), q, "Householder::apply: dimensions mismatch");
        let u = self.u();
        let g = cmul(&u.adjoint(), &u);
        let mut t = DMatrix::from_element(q, q, Complex64::new(0.0, 0.0));
        for k in 0..q {
            t[(k, k)] = Complex64::new(2.0, 0.0);
            if k > 0 {
                let col =
                    t.view((0, 0), (k, k)) * g.view((0, k), (k, 1)) * Complex64::new(-2.0, 0.0);
                t.view_mut((0, k), (k, 1)).copy_from(&col);
            }
        }
        let z = &t * (u.rows(0, q).adjoint() * y);
        let mut x = -cmul(&u, &z);
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

    #[test]
    fn the_vector_and_the_plain_kernels_give_the_same_bits() {
        let mut seed = 11;
        let a = random(37, 5, &mut seed);
        let run = |avx: bool| {
            let mut wr: Vec<f64> = a.as_slice().iter().map(|z| z.re).collect();
            let mut wi: Vec<f64> = a.as_slice().iter().map(|z| z.im).collect();
            let mut diag = vec![Complex64::new(0.0, 0.0); 5];
            if avx {
                factor(37, 5, &mut wr, &mut wi, &mut diag);
            } else {
                factor_plain(37, 5, &mut wr, &mut wi, &mut diag);
            }
            (wr, wi, diag)
        };
        assert_eq!(run(true), run(false));
    }
}
