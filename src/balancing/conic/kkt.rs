//! The min-max program of `primal_dual` in the form `G z + s = h` over
//! `z = (Re y, Im y, t)`, with `G z`, `Gᵀ u` and the reduced KKT matrix
//! `Σ Gᵢᵀ Sᵢ Gᵢ` written as loops over each row's real-form coefficients,
//! and that matrix's Cholesky factor kept in one fixed buffer.
//!
//! Why loops and not nalgebra: the working sets are a few dozen rows and
//! `2n + 1 ≤ 33` unknowns, where nalgebra's dynamic products spent more on
//! dispatch, temporaries and allocation than on arithmetic (issue 15,
//! session 6: ~2.4 k instructions per `G z` on the 11×4 job).

use nalgebra::DMatrix;
use num_complex::Complex64;

use super::soc::V3;

/// Real unknowns `2n` from which the x block is one `gemm` (`x_block_gemm`).
const GEMM_FROM: usize = 16;

/// Row cone `a` is `s = (t, Re r_a, Im r_a)` with `Re r = re0 + pₐ·x`,
/// `Im r = im0 + qₐ·x`, `x = (Re y, Im y)`; bound cone `(k, m)` is
/// `s = (m, Re y_k, Im y_k)`. `p`, `q` hold `2n` entries per row.
pub(super) struct Program<'a> {
    pub(super) n: usize,
    pub(super) m: usize,
    pub(super) r0: Vec<[f64; 2]>,
    p: Vec<f64>,
    q: Vec<f64>,
    pub(super) bounds: &'a [(usize, f64)],
}

impl<'a> Program<'a> {
    /// The rows `rows` of `b + A y`, in real form.
    pub(super) fn new(
        a: &DMatrix<Complex64>,
        b: &[Complex64],
        bounds: &'a [(usize, f64)],
        rows: &[usize],
    ) -> Self {
        let (n, m) = (a.ncols(), rows.len());
        let (mut p, mut q) = (vec![0.0; 2 * n * m], vec![0.0; 2 * n * m]);
        for (row, &i) in rows.iter().enumerate() {
            let (p, q) = (&mut p[2 * n * row..], &mut q[2 * n * row..]);
            for k in 0..n {
                let c = a[(i, k)];
                // r = b + Σ c_k (u_k + i v_k): Re = Σ Re c u − Im c v, Im = Σ Im c u + Re c v.
                p[k] = c.re;
                p[n + k] = -c.im;
                q[k] = c.im;
                q[n + k] = c.re;
            }
        }
        let r0 = rows.iter().map(|&i| [b[i].re, b[i].im]).collect();
        Program {
            n,
            m,
            r0,
            p,
            q,
            bounds,
        }
    }

    pub(super) fn cones(&self) -> usize {
        self.m + self.bounds.len()
    }

    /// Unknowns `2n + 1`.
    pub(super) fn dim(&self) -> usize {
        2 * self.n + 1
    }

    fn row(&self, a: usize) -> (&[f64], &[f64]) {
        let n2 = 2 * self.n;
        (&self.p[n2 * a..n2 * (a + 1)], &self.q[n2 * a..n2 * (a + 1)])
    }

    /// `h`, one 3-vector per cone.
    pub(super) fn h(&self, out: &mut Vec<V3>) {
        out.clear();
        out.extend(self.r0.iter().map(|r| [0.0, r[0], r[1]]));
        out.extend(self.bounds.iter().map(|&(_, mk)| [mk, 0.0, 0.0]));
    }

    /// `G z` for every cone, into `out`.
    pub(super) fn apply(&self, z: &[f64], out: &mut [V3]) {
        let (n, n2) = (self.n, 2 * self.n);
        let (x, t) = (&z[..n2], z[n2]);
        for (a, o) in out[..self.m].iter_mut().enumerate() {
            let (p, q) = self.row(a);
            let (mut re, mut im) = (0.0, 0.0);
            for ((p, q), x) in p.iter().zip(q).zip(x) {
                re += p * x;
                im += q * x;
            }
            *o = [-t, -re, -im];
        }
        for (&(k, _), o) in self.bounds.iter().zip(&mut out[self.m..]) {
            *o = [0.0, -z[k], -z[n + k]];
        }
    }

    /// `Gᵀ u` for one 3-vector per cone, into `out` (`2n + 1` entries).
    pub(super) fn apply_tr(&self, u: &[V3], out: &mut [f64]) {
        let (n, n2) = (self.n, 2 * self.n);
        out.fill(0.0);
        let mut t = 0.0;
        for (a, v) in u[..self.m].iter().enumerate() {
            let (p, q) = self.row(a);
            for ((o, p), q) in out[..n2].iter_mut().zip(p).zip(q) {
                *o -= p * v[1] + q * v[2];
            }
            t += v[0];
        }
        out[n2] = -t;
        for (&(k, _), v) in self.bounds.iter().zip(&u[self.m..]) {
            out[k] -= v[1];
            out[n + k] -= v[2];
        }
    }

    /// `Σ Gᵢᵀ Sᵢ Gᵢ` for the symmetric 3 × 3 `Sᵢ = Wᵢ⁻²`, (at least) its
    /// lower triangle row by row into `nm` (`dim²` entries), then factored in place.
    /// `false` when rounding has left it not positive definite.
    pub(super) fn normal(&self, sq: &[[V3; 3]], nm: &mut [f64]) -> bool {
        let (n, n2, d) = (self.n, 2 * self.n, self.dim());
        let wide = n2 >= GEMM_FROM;
        nm.fill(0.0);
        for (a, s) in sq[..self.m].iter().enumerate() {
            // Gₐ = −(e_t; pᵀ; qᵀ): the x block is Σ S_ij gᵢ gⱼᵀ over (p, q),
            // i.e. u pᵀ + w qᵀ with u = S₁₁p + S₁₂q, w = S₂₁p + S₂₂q; the
            // x–t row S₁₀p + S₂₀q; the t–t entry S₀₀.
            let (p, q) = self.row(a);
            for i in 0..n2 {
                if !wide {
                    let u = s[1][1] * p[i] + s[1][2] * q[i];
                    let w = s[2][1] * p[i] + s[2][2] * q[i];
                    // The whole row, not its lower part: a fixed length the
                    // compiler vectorises, where the triangle's short varying
                    // loops cost ~25 instructions an entry (the upper half is
                    // never read).
                    let out = &mut nm[d * i..d * i + n2];
                    for ((o, pj), qj) in out.iter_mut().zip(p).zip(q) {
                        *o += u * pj + w * qj;
                    }
                }
                nm[d * n2 + i] += s[1][0] * p[i] + s[2][0] * q[i];
            }
            nm[d * n2 + n2] += s[0][0];
        }
        if wide {
            self.x_block_gemm(sq, nm);
        }
        for (&(k, _), s) in self.bounds.iter().zip(&sq[self.m..]) {
            nm[d * k + k] += s[1][1];
            nm[d * (n + k) + n + k] += s[2][2];
            nm[d * (n + k) + k] += s[2][1];
        }
        cholesky(nm, d)
    }
}

impl Program<'_> {
    /// The x block as one product `B Bᵀ` of a `2n × 2m` matrix (`L Lᵀ` the
    /// Cholesky of each row's lower 2 × 2 block of `S`), which nalgebra hands
    /// to `matrixmultiply`'s SIMD kernels: faster than the per-row loops
    /// from [`GEMM_FROM`] unknowns on (the 1000×16 jobs), slower below.
    fn x_block_gemm(&self, sq: &[[V3; 3]], nm: &mut [f64]) {
        let (n2, d, m) = (2 * self.n, self.dim(), self.m);
        let mut b = DMatrix::zeros(n2, 2 * m);
        for (a, s) in sq[..m].iter().enumerate() {
            let l11 = s[1][1].sqrt();
            let l21 = s[2][1] / l11;
            let l22 = (s[2][2] - l21 * l21).max(0.0).sqrt();
            let (p, q) = self.row(a);
            for k in 0..n2 {
                b[(k, 2 * a)] = l11 * p[k] + l21 * q[k];
                b[(k, 2 * a + 1)] = l22 * q[k];
            }
        }
        let bt = b.transpose();
        let mut bb = DMatrix::zeros(n2, n2);
        bb.gemm(1.0, &b, &bt, 0.0);
        for i in 0..n2 {
            for j in 0..=i {
                nm[d * i + j] += bb[(i, j)];
            }
        }
    }
}

/// `L` with `L Lᵀ` the matrix whose lower triangle is in `a` (row-major,
/// `d × d`), in place; `false` on a pivot that is not positive and finite.
fn cholesky(a: &mut [f64], d: usize) -> bool {
    for j in 0..d {
        let (done, rest) = a.split_at_mut(d * j);
        let row_j = &mut rest[..d];
        for k in 0..j {
            let row_k = &done[d * k..d * k + k + 1];
            let dot: f64 = row_j[..k].iter().zip(&row_k[..k]).map(|(x, y)| x * y).sum();
            row_j[k] = (row_j[k] - dot) / row_k[k];
        }
        let pivot = row_j[j] - row_j[..j].iter().map(|x| x * x).sum::<f64>();
        if !(pivot > 0.0 && pivot.is_finite()) {
            return false;
        }
        row_j[j] = pivot.sqrt();
    }
    true
}

/// Solves `L Lᵀ x = r` in place for the factor `cholesky` left in `l`.
pub(super) fn solve(l: &[f64], d: usize, x: &mut [f64]) {
    for i in 0..d {
        let row = &l[d * i..d * i + i];
        let dot: f64 = row.iter().zip(&x[..i]).map(|(a, b)| a * b).sum();
        x[i] = (x[i] - dot) / l[d * i + i];
    }
    for i in (0..d).rev() {
        let mut v = x[i];
        for k in i + 1..d {
            v -= l[d * k + i] * x[k];
        }
        x[i] = v / l[d * i + i];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fixed_buffer_cholesky_solves_a_positive_definite_system() {
        let d = 4;
        let m = DMatrix::from_fn(d, d, |i, j| {
            1.0 / (1.0 + i as f64 + j as f64) + if i == j { 0.3 } else { 0.0 }
        });
        let mut l: Vec<f64> = (0..d * d).map(|k| m[(k / d, k % d)]).collect();
        assert!(cholesky(&mut l, d));
        let want = [1.0, -2.0, 0.5, 3.0];
        let rhs = &m * nalgebra::DVector::from_row_slice(&want);
        let mut x: Vec<f64> = rhs.iter().copied().collect();
        solve(&l, d, &mut x);
        for (x, w) in x.iter().zip(want) {
            assert!((x - w).abs() < 1e-12, "{x} against {w}");
        }
    }

    #[test]
    fn the_fixed_buffer_cholesky_refuses_an_indefinite_matrix() {
        let mut a = vec![1.0, 0.0, 2.0, 1.0];
        assert!(!cholesky(&mut a, 2));
    }
}
