//! QR of a tall real matrix for the conditioning on all rows (method 8.8)
//! by modified Gram–Schmidt, the right-hand side carried as a last column
//! (Björck 1967, "Solving linear least squares problems by Gram–Schmidt
//! orthogonalization", BIT 7; Björck & Paige 1992, SIAM J. Matrix Anal.
//! Appl. 13: numerically the Householder QR of `[0; X]`, so `R` and `Qᵀy`
//! are as accurate as Householder's and the least-squares solution is
//! backward stable). Unlike Householder's, its `Q` comes out explicitly at
//! no extra cost, and the conditioning needs exactly that: the rows'
//! leverages `Q_a Q_aᵀ` give `W_a Λ⁻¹ W_aᵀ` (joint.rs) without the `2q × 2q ×
//! 2 rows` product `R⁻ᵀ Wᵀ`. The computed `Q` departs from orthonormal by
//! about `κ(X)·ε` (ibid.), so a leverage is good to about `κ ε` of the
//! row's scale: 10⁻⁶ where the caller's rank test (`R`'s diagonal above
//! 10⁻¹⁰ of its largest) lets the stack through at all.
//!
//! Cost (issue 15; session 11): `m n²` multiply-adds in dot products and
//! updates over columns of length `m`. Written as plain Rust the compiler
//! packed them two lanes at a time with shuffles (session 10's Householder
//! kernel: 2.6 instructions per multiply-add, 6.9 M on the large job). Here,
//! where the processor has AVX2 and FMA, they are written with those
//! instructions, four lanes and four independent sums, and the trailing
//! columns are updated two at a time so that `q_k` is read once per pair:
//! about 0.7 instructions per multiply-add (callgrind, BENCHMARKS.md "Issue
//! 12, session 11"). The fused multiply-add rounds once where the plain
//! kernel rounds twice, so the two kernels agree to rounding, not to the bit
//! (as `matrixmultiply`, which the solve already uses, does with and without
//! FMA).

use nalgebra::{DMatrix, DVector};

/// The portable kernels: four interleaved partial sums.
mod plain {
    #[inline(always)]
    pub fn dot(a: &[f64], b: &[f64]) -> f64 {
        let n = a.len();
        let b = &b[..n];
        let body = n - n % 4;
        let mut s = [0.0f64; 4];
        for (a, b) in a[..body].chunks_exact(4).zip(b[..body].chunks_exact(4)) {
            for l in 0..4 {
                s[l] += a[l] * b[l];
            }
        }
        let mut t = (s[0] + s[1]) + (s[2] + s[3]);
        for i in body..n {
            t += a[i] * b[i];
        }
        t
    }

    /// `(u·a, u·b)`.
    #[inline(always)]
    pub fn dot2(u: &[f64], a: &[f64], b: &[f64]) -> (f64, f64) {
        (dot(u, a), dot(u, b))
    }

    /// `y ← y − d x`.
    #[inline(always)]
    pub fn sub(y: &mut [f64], d: f64, x: &[f64]) {
        for (y, x) in y.iter_mut().zip(x) {
            *y -= d * x;
        }
    }

    /// `a ← a − da x`, `b ← b − db x`.
    #[inline(always)]
    pub fn sub2(a: &mut [f64], da: f64, b: &mut [f64], db: f64, x: &[f64]) {
        sub(a, da, x);
        sub(b, db, x);
    }
}

/// The same with AVX2 and FMA (module doc).
#[cfg(target_arch = "x86_64")]
#[path = "mgs_fma.rs"]
mod fma;

/// The factorisation in place of `x` (`m × cols` column-major, `m ≥ n`):
/// the first `n` columns become `Q`'s, the columns after them (the
/// right-hand sides) their residuals; `r` (`n × cols`, column-major)
/// receives `R` and, in its last columns, `Qᵀy`. A column with nothing left
/// (`r_kk = 0`) is left at zero and takes nothing from the others.
macro_rules! kernel_body {
    ($m:ident, $n:ident, $x:ident, $r:ident, $dot:path, $dot2:path, $sub:path, $sub2:path) => {
        for k in 0..$n {
            let (head, tail) = $x.split_at_mut((k + 1) * $m);
            let qk = &mut head[k * $m..];
            let rkk = $dot(qk, qk).sqrt();
            $r[k * $n + k] = rkk;
            if rkk == 0.0 {
                continue;
            }
            let inv = 1.0 / rkk;
            for v in qk.iter_mut() {
                *v *= inv;
            }
            let qk = &*qk;
            let mut j = k + 1;
            let mut pairs = tail.chunks_exact_mut(2 * $m);
            for pair in &mut pairs {
                let (a, b) = pair.split_at_mut($m);
                let (da, db) = $dot2(qk, a, b);
                $sub2(a, da, b, db, qk);
                $r[j * $n + k] = da;
                $r[(j + 1) * $n + k] = db;
                j += 2;
            }
            for col in pairs.into_remainder().chunks_exact_mut($m) {
                let d = $dot(qk, col);
                $sub(col, d, qk);
                $r[j * $n + k] = d;
            }
        }
    };
}

fn kernel_plain(m: usize, n: usize, x: &mut [f64], r: &mut [f64]) {
    kernel_body!(m, n, x, r, plain::dot, plain::dot2, plain::sub, plain::sub2);
}

/// [`kernel_plain`] with AVX2 and FMA.
///
/// # Safety
/// Only on a processor with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn kernel_fma(m: usize, n: usize, x: &mut [f64], r: &mut [f64]) {
    kernel_body!(m, n, x, r, fma::dot, fma::dot2, fma::sub, fma::sub2);
}

fn has_fma() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

fn run(m: usize, n: usize, x: &mut [f64], r: &mut [f64]) {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the processor was just found to have AVX2 and FMA.
        return unsafe { kernel_fma(m, n, x, r) };
    }
    kernel_plain(m, n, x, r)
}

/// `Σ_i a_i b_i` (`b` at least as long as `a`), with the fastest kernel the
/// processor has.
#[cfg(test)]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the processor was just found to have AVX2 and FMA.
        return unsafe { fma::dot(a, b) };
    }
    plain::dot(a, b)
}

/// `X = Q R` with the right-hand side `y`: from `data` = `X` (`m × n`,
/// column-major, `m ≥ n`) followed by `y` (`m`), overwritten with `Q`
/// (`m × n`) and the least-squares residual `y − Q Qᵀy`; returns `R` (`n × n`,
/// upper triangular, diagonal `≥ 0`) and `Qᵀy`.
pub fn qr_in_place(m: usize, n: usize, data: &mut [f64]) -> (DMatrix<f64>, DVector<f64>) {
    assert!(
        m >= n && data.len() == m * (n + 1),
        "qr_in_place: dimensions"
    );
    let mut r = vec![0.0; n * (n + 1)];
    run(m, n, data, &mut r);
    let qty = DVector::from_column_slice(&r[n * n..]);
    r.truncate(n * n);
    (DMatrix::from_vec(n, n, r), qty)
}

/// `c_i += a_i a_i` and `d_i += a_i a_{i+1}` (`d`'s last entry untouched)
/// for every column `a` of `q` (`m` rows, column-major): the rows'
/// leverages from `Q`'s columns (joint.rs), four lanes with FMA where the
/// processor has them.
pub fn squares_and_neighbours(m: usize, q: &[f64], c: &mut [f64], d: &mut [f64]) {
    assert!(m > 0 && c.len() == m && d.len() == m && q.len() % m == 0);
    #[cfg(target_arch = "x86_64")]
    if has_fma() {
        // SAFETY: the processor was just found to have AVX2 and FMA.
        return unsafe { fma::squares_and_neighbours(m, q, c, d) };
    }
    for a in q.chunks_exact(m) {
        for (c, x) in c.iter_mut().zip(a) {
            *c += x * x;
        }
        for ((d, x), y) in d.iter_mut().zip(a).zip(&a[1..]) {
            *d += x * y;
        }
    }
}

#[cfg(test)]
#[path = "mgs_tests.rs"]
mod tests;
