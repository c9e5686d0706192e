//! A small dense primal-dual interior-point solver for the scaled min-max
//! program (method 4.1, issue 15): `min t` subject to `|b_a + (A y)_a| ≤ t`
//! on the given rows and `|y_k| ≤ m_k` on the bounded columns.
//!
//! Why not Clarabel here: the working sets of `active_set` have a few dozen
//! rows and `2n + 1 ≤ 33` real unknowns, where Clarabel's sparse setup,
//! equilibration and factorisation cost far more than the arithmetic. The
//! method is Clarabel's own, without the homogeneous embedding (the program
//! is always feasible and bounded): Nesterov–Todd scaling of each
//! 3-dimensional second-order cone and Mehrotra's predictor–corrector
//! (Vandenberghe, "The CVXOPT linear and quadratic cone program solvers",
//! §§ 4–5), about a dozen iterations where the barrier method it replaces
//! took 60 to 90 Newton steps. It starts primal and dual feasible (`y = 0`,
//! `t > max |b|`; `λ_a = (1/m, 0, 0)`), so the duality gap `Σ s·λ` bounds the
//! distance to the optimum at every iteration; it stops at Clarabel's
//! tolerances for the same program (`program.rs`).
//!
//! The reduced system `Σ Gᵢᵀ Wᵢ⁻² Gᵢ Δz = r` is `(2n+1) × (2n+1)` and dense
//! (a Cholesky of the scaled cone Hessians, not of the least-squares normal
//! equations); each row cone's share of its `y` block has rank two (the span
//! of the row's real and imaginary coefficient vectors), so that block is
//! one product `B Bᵀ` of a `2n × 2m` matrix, which nalgebra hands to
//! `matrixmultiply`'s SIMD kernels. When the arithmetic fails (a Cholesky
//! that rounding has left indefinite, no convergence within [`BUDGET`]) the
//! caller falls back to Clarabel, so the answer never depends on this
//! solver's luck.

use std::time::Instant;

use nalgebra::{Cholesky, DMatrix, DVector, Dyn};
use num_complex::Complex64;

use super::soc::{dot, jordan, jordan_div, max_step, Scaling, V3};
use super::Limits;
use crate::balancing::error::InputError;

/// Relative duality gap `Σ s·λ / t` at which the optimum is taken as found:
/// Clarabel's `tol_gap_rel` for the same program (`program.rs`).
const GAP: f64 = 1e-10;
/// Absolute gap for an optimum near zero (exact data): Clarabel's `tol_gap_abs`.
const GAP_ABS: f64 = 1e-11;
/// Primal and dual residuals (scaled units, `max |b| = 1`): Clarabel's `tol_feas`.
const FEAS: f64 = 1e-10;
/// Iterations after which Clarabel takes over (this method needs 10 to 20).
const BUDGET: u32 = 80;
/// Fraction of the way to the cone boundary a step may go.
const STEP: f64 = 0.99;

/// The program in the form `G z + s = h`, `s` in the product of cones, over
/// `z = (Re y, Im y, t)`: row cone `a` is `s = (t, Re r_a, Im r_a)` with
/// `Re r = re0 + pᵀ x`, `Im r = im0 + qᵀ x` (columns of `p`, `q`); bound
/// cone `(k, m)` is `s = (m, Re y_k, Im y_k)`.
struct Program<'a> {
    n: usize,
    re0: DVector<f64>,
    im0: DVector<f64>,
    p: DMatrix<f64>,
    q: DMatrix<f64>,
    bounds: &'a [(usize, f64)],
}

impl Program<'_> {
    fn cones(&self) -> usize {
        self.re0.len() + self.bounds.len()
    }

    /// `h`, one 3-vector per cone.
    fn h(&self) -> Vec<V3> {
        let rows = (0..self.re0.len()).map(|a| [0.0, self.re0[a], self.im0[a]]);
        let bounds = self.bounds.iter().map(|&(_, mk)| [mk, 0.0, 0.0]);
        rows.chain(bounds).collect()
    }

    /// `G z` for every cone.
    fn apply(&self, z: &DVector<f64>) -> Vec<V3> {
        let n2 = 2 * self.n;
        let head = z.rows(0, n2);
        let re = self.p.tr_mul(&head);
        let im = self.q.tr_mul(&head);
        let rows = (0..self.re0.len()).map(|a| [-z[n2], -re[a], -im[a]]);
        let bounds = self
            .bounds
            .iter()
            .map(|&(k, _)| [0.0, -z[k], -z[self.n + k]]);
        rows.chain(bounds).collect()
    }

    /// `Gᵀ u` for one 3-vector per cone.
    fn apply_tr(&self, u: &[V3]) -> DVector<f64> {
        let (n, m) = (self.n, self.re0.len());
        let mut out = DVector::zeros(2 * n + 1);
        let u1 = DVector::from_fn(m, |a, _| u[a][1]);
        let u2 = DVector::from_fn(m, |a, _| u[a][2]);
        let mut head = out.rows_mut(0, 2 * n);
        head.gemv(-1.0, &self.p, &u1, 0.0);
        head.gemv(-1.0, &self.q, &u2, 1.0);
        out[2 * n] = -u[..m].iter().map(|v| v[0]).sum::<f64>();
        for (&(k, _), v) in self.bounds.iter().zip(&u[m..]) {
            out[k] -= v[1];
            out[n + k] -= v[2];
        }
        out
    }

    /// `Σ Gᵢᵀ Sᵢ Gᵢ` for the symmetric 3 × 3 `Sᵢ = Wᵢ⁻²`, factored.
    fn normal(&self, sq: &[[V3; 3]]) -> Option<Cholesky<f64, Dyn>> {
        let (n, m) = (self.n, self.re0.len());
        let n2 = 2 * n;
        let mut b = DMatrix::zeros(n2, 2 * m);
        let mut bt = DMatrix::zeros(2 * m, n2);
        let (mut hp, mut hq) = (DVector::zeros(m), DVector::zeros(m));
        let mut tt = 0.0;
        for (a, s) in sq[..m].iter().enumerate() {
            // Gₐ = −(e_t; pᵀ; qᵀ): the y block is P S₁₁ Pᵀ with P = [p q] and
            // S₁₁ the lower 2 × 2 block of S = L Lᵀ; the y–t column P S₁₀.
            tt += s[0][0];
            hp[a] = s[1][0];
            hq[a] = s[2][0];
            let l11 = s[1][1].sqrt();
            let l21 = s[2][1] / l11;
            let l22 = (s[2][2] - l21 * l21).max(0.0).sqrt();
            let (p, q) = (self.p.column(a), self.q.column(a));
            for k in 0..n2 {
                let (u, v) = (l11 * p[k] + l21 * q[k], l22 * q[k]);
                b[(k, 2 * a)] = u;
                b[(k, 2 * a + 1)] = v;
                bt[(2 * a, k)] = u;
                bt[(2 * a + 1, k)] = v;
            }
        }
        let mut nm = DMatrix::zeros(n2 + 1, n2 + 1);
        nm.view_mut((0, 0), (n2, n2)).gemm(1.0, &b, &bt, 0.0);
        let mut col = nm.column_mut(n2);
        let mut yt = col.rows_mut(0, n2);
        yt.gemv(1.0, &self.p, &hp, 0.0);
        yt.gemv(1.0, &self.q, &hq, 1.0);
        for k in 0..n2 {
            nm[(n2, k)] = nm[(k, n2)];
        }
        nm[(n2, n2)] = tt;
        for (&(k, _), s) in self.bounds.iter().zip(&sq[m..]) {
            nm[(k, k)] += s[1][1];
            nm[(n + k, n + k)] += s[2][2];
            nm[(k, n + k)] += s[1][2];
            nm[(n + k, k)] += s[2][1];
        }
        nm.cholesky()
    }
}

/// The optimal `y` (complex, one per column of `a`) and the iterations
/// taken; `Ok(None)` when the arithmetic failed or the iteration budget ran
/// out and Clarabel should solve the program instead; a 422 when the time
/// limit ends the solve.
pub(super) fn min_max(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    rows: &[usize],
    limits: Limits,
) -> Result<Option<(Vec<Complex64>, u32)>, InputError> {
    let (n, m) = (a.ncols(), rows.len());
    let n2 = 2 * n;
    let mut prog = Program {
        n,
        re0: DVector::from_fn(m, |a, _| b[rows[a]].re),
        im0: DVector::from_fn(m, |a, _| b[rows[a]].im),
        p: DMatrix::zeros(n2, m),
        q: DMatrix::zeros(n2, m),
        bounds,
    };
    for (col, &i) in rows.iter().enumerate() {
        for k in 0..n {
            let c = a[(i, k)];
            // r = b + Σ c_k (u_k + i v_k): Re = Σ Re c u − Im c v, Im = Σ Im c u + Re c v.
            prog.p[(k, col)] = c.re;
            prog.p[(n + k, col)] = -c.im;
            prog.q[(k, col)] = c.im;
            prog.q[(n + k, col)] = c.re;
        }
    }
    let cones = prog.cones();
    let h = prog.h();
    let sub = |u: &V3, v: &V3| -> V3 { [u[0] - v[0], u[1] - v[1], u[2] - v[2]] };
    // Primal feasible: y = 0, t above every |b_a|; dual feasible: Σ λ_a0 = 1.
    let mut z = DVector::zeros(n2 + 1);
    z[n2] = 1.5 * prog.re0.zip_map(&prog.im0, f64::hypot).max() + 1e-3;
    let mut s: Vec<V3> = h
        .iter()
        .zip(prog.apply(&z))
        .map(|(h, g)| sub(h, &g))
        .collect();
    let mut l: Vec<V3> = vec![[1.0 / m as f64, 0.0, 0.0]; cones];
    let mut c = DVector::zeros(n2 + 1);
    c[n2] = 1.0;
    let start = Instant::now();
    for it in 0..limits.max_iter.min(BUDGET) {
        if start.elapsed().as_secs_f64() > limits.time_limit_s {
            return Err(InputError::unsolvable(
                "solver_failed",
                format!(
                    "the cone solver could not solve this balancing problem: no convergence within {} s",
                    limits.time_limit_s
                ),
            ));
        }
        let gap: f64 = s.iter().zip(&l).map(|(s, l)| dot(s, l)).sum();
        let rz = &c + prog.apply_tr(&l);
        let rs: Vec<V3> = prog
            .apply(&z)
            .iter()
            .zip(&s)
            .zip(&h)
            .map(|((g, s), h)| std::array::from_fn(|i| g[i] + s[i] - h[i]))
            .collect();
        let feas = rs.iter().flatten().fold(rz.amax(), |f, x| f.max(x.abs()));
        if !(gap.is_finite() && feas.is_finite()) {
            return Ok(None);
        }
        if gap <= (GAP * z[n2]).max(GAP_ABS) && feas <= FEAS {
            let y = (0..n).map(|k| Complex64::new(z[k], z[n + k])).collect();
            return Ok(Some((y, it)));
        }
        let Some(sc) = s
            .iter()
            .zip(&l)
            .map(|(s, l)| Scaling::of(s, l))
            .collect::<Option<Vec<_>>>()
        else {
            return Ok(None);
        };
        let v: Vec<V3> = sc.iter().zip(&l).map(|(w, l)| w.w(l)).collect();
        let unit = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let sq: Vec<[V3; 3]> = sc
            .iter()
            .map(|w| unit.map(|e| w.w_inv(&w.w_inv(&e))))
            .collect();
        let Some(chol) = prog.normal(&sq) else {
            return Ok(None);
        };
        // The Newton direction for the complementarity right side `v ∘ d`:
        // Δz from the reduced system, Δλ = W⁻¹(W⁻¹(G Δz + r_s) + d), Δs = −r_s − G Δz.
        let direction = |d: &[V3]| {
            let u: Vec<V3> = (0..cones)
                .map(|i| {
                    let x = sc[i].w_inv(&rs[i]);
                    sc[i].w_inv(&[x[0] + d[i][0], x[1] + d[i][1], x[2] + d[i][2]])
                })
                .collect();
            let dz = chol.solve(&(-&rz - prog.apply_tr(&u)));
            let gdz = prog.apply(&dz);
            let dl: Vec<V3> = (0..cones)
                .map(|i| {
                    let x = sc[i].w_inv(&[
                        gdz[i][0] + rs[i][0],
                        gdz[i][1] + rs[i][1],
                        gdz[i][2] + rs[i][2],
                    ]);
                    sc[i].w_inv(&[x[0] + d[i][0], x[1] + d[i][1], x[2] + d[i][2]])
                })
                .collect();
            let ds: Vec<V3> = (0..cones)
                .map(|i| std::array::from_fn(|j| -rs[i][j] - gdz[i][j]))
                .collect();
            (dz, dl, ds)
        };
        let longest = |dl: &[V3], ds: &[V3]| {
            (0..cones).fold(f64::INFINITY, |a, i| {
                a.min(max_step(&s[i], &ds[i])).min(max_step(&l[i], &dl[i]))
            })
        };
        // Predictor (affine scaling), then Mehrotra's centring and corrector.
        let affine: Vec<V3> = v.iter().map(|v| v.map(|x| -x)).collect();
        let (_, dl_a, ds_a) = direction(&affine);
        let sigma = (1.0 - longest(&dl_a, &ds_a).min(1.0)).powi(3);
        let mu = gap / cones as f64;
        let d: Vec<V3> = (0..cones)
            .map(|i| {
                let vv = jordan(&v[i], &v[i]);
                let corr = jordan(&sc[i].w_inv(&ds_a[i]), &sc[i].w(&dl_a[i]));
                let rc = [
                    -vv[0] + sigma * mu - corr[0],
                    -vv[1] - corr[1],
                    -vv[2] - corr[2],
                ];
                jordan_div(&v[i], &rc)
            })
            .collect();
        let (dz, dl, ds) = direction(&d);
        let alpha = (STEP * longest(&dl, &ds)).min(1.0);
        if !(alpha.is_finite() && alpha > 0.0) {
            return Ok(None);
        }
        z.axpy(alpha, &dz, 1.0);
        for i in 0..cones {
            for j in 0..3 {
                s[i][j] += alpha * ds[i][j];
                l[i][j] += alpha * dl[i][j];
            }
        }
    }
    Ok(None)
}
