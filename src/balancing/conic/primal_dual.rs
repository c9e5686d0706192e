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
//! equations); each row cone adds a rank-two share to its `y` block (the
//! span of the row's real and imaginary coefficient vectors), accumulated
//! by explicit loops in `kkt.rs`. Every buffer is allocated once per solve
//! ([`Work`]). When the arithmetic fails (a Cholesky
//! that rounding has left indefinite, no convergence within [`BUDGET`]) the
//! caller falls back to Clarabel, so the answer never depends on this
//! solver's luck.

use std::time::Instant;

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::kkt::{self, Program};
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

fn add(u: &V3, v: &V3) -> V3 {
    [u[0] + v[0], u[1] + v[1], u[2] + v[2]]
}

/// One Newton direction `(Δz, Δλ, Δs)`.
struct Direction {
    dz: Vec<f64>,
    dl: Vec<V3>,
    ds: Vec<V3>,
}

impl Direction {
    fn new(dim: usize, cones: usize) -> Self {
        Direction {
            dz: vec![0.0; dim],
            dl: vec![[0.0; 3]; cones],
            ds: vec![[0.0; 3]; cones],
        }
    }

    /// The longest step from `(s, λ)` along this direction inside every cone.
    fn longest(&self, s: &[V3], l: &[V3]) -> f64 {
        (0..s.len()).fold(f64::INFINITY, |a, i| {
            a.min(max_step(&s[i], &self.ds[i]))
                .min(max_step(&l[i], &self.dl[i]))
        })
    }
}

/// The buffers of one iteration, allocated once per solve.
struct Work {
    rz: Vec<f64>,
    rs: Vec<V3>,
    sc: Vec<Scaling>,
    v: Vec<V3>,
    sq: Vec<[V3; 3]>,
    chol: Vec<f64>,
    /// The complementarity right side `v ∘ d` of the direction being solved.
    d: Vec<V3>,
    u: Vec<V3>,
    gdz: Vec<V3>,
    affine: Direction,
    step: Direction,
}

impl Work {
    fn new(dim: usize, cones: usize) -> Self {
        Work {
            rz: vec![0.0; dim],
            rs: vec![[0.0; 3]; cones],
            sc: Vec::with_capacity(cones),
            v: vec![[0.0; 3]; cones],
            sq: vec![[[0.0; 3]; 3]; cones],
            chol: vec![0.0; dim * dim],
            d: vec![[0.0; 3]; cones],
            u: vec![[0.0; 3]; cones],
            gdz: vec![[0.0; 3]; cones],
            affine: Direction::new(dim, cones),
            step: Direction::new(dim, cones),
        }
    }

    /// The Newton direction for the right side `v ∘ d` into `affine` or
    /// `step`: Δz from the reduced system,
    /// Δλ = W⁻¹(W⁻¹(G Δz + r_s) + d), Δs = −r_s − G Δz.
    fn direction(&mut self, prog: &Program, corrector: bool) {
        let Work {
            rz,
            rs,
            sc,
            chol,
            d,
            u,
            gdz,
            affine,
            step,
            ..
        } = self;
        let out = if corrector { step } else { affine };
        for (i, u) in u.iter_mut().enumerate() {
            *u = sc[i].w_inv(&add(&sc[i].w_inv(&rs[i]), &d[i]));
        }
        prog.apply_tr(u, &mut out.dz);
        for (x, r) in out.dz.iter_mut().zip(rz.iter()) {
            *x = -r - *x;
        }
        kkt::solve(chol, prog.dim(), &mut out.dz);
        prog.apply(&out.dz, gdz);
        for (i, g) in gdz.iter().enumerate() {
            let g = add(g, &rs[i]);
            out.dl[i] = sc[i].w_inv(&add(&sc[i].w_inv(&g), &d[i]));
            out.ds[i] = g.map(|x| -x);
        }
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
    let prog = Program::new(a, b.as_slice(), bounds, rows);
    let (n, m, dim, cones) = (prog.n, prog.m, prog.dim(), prog.cones());
    let n2 = 2 * n;
    let mut h = Vec::with_capacity(cones);
    prog.h(&mut h);
    // Primal feasible: y = 0, t above every |b_a|; dual feasible: Σ λ_a0 = 1.
    let mut z = vec![0.0; dim];
    let largest = prog.r0.iter().map(|r| r[0].hypot(r[1]));
    z[n2] = 1.5 * largest.fold(f64::NEG_INFINITY, f64::max) + 1e-3;
    let mut s = vec![[0.0; 3]; cones];
    prog.apply(&z, &mut s);
    for (s, h) in s.iter_mut().zip(&h) {
        *s = [h[0] - s[0], h[1] - s[1], h[2] - s[2]];
    }
    let mut l: Vec<V3> = vec![[1.0 / m as f64, 0.0, 0.0]; cones];
    let mut w = Work::new(dim, cones);
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
        // r_z = c + Gᵀλ with c = e_t; r_s = G z + s − h.
        prog.apply_tr(&l, &mut w.rz);
        w.rz[n2] += 1.0;
        prog.apply(&z, &mut w.rs);
        for ((r, s), h) in w.rs.iter_mut().zip(&s).zip(&h) {
            *r = std::array::from_fn(|i| r[i] + s[i] - h[i]);
        }
        let feas = w.rz.iter().chain(w.rs.iter().flatten());
        let feas = feas.fold(0.0_f64, |f, x| f.max(x.abs()));
        if !(gap.is_finite() && feas.is_finite()) {
            return Ok(None);
        }
        if gap <= (GAP * z[n2]).max(GAP_ABS) && feas <= FEAS {
            let y = (0..n).map(|k| Complex64::new(z[k], z[n + k])).collect();
            return Ok(Some((y, it)));
        }
        w.sc.clear();
        for (s, l) in s.iter().zip(&l) {
            let Some(sc) = Scaling::of(s, l) else {
                return Ok(None);
            };
            w.sc.push(sc);
        }
        for (i, sc) in w.sc.iter().enumerate() {
            w.v[i] = sc.w(&l[i]);
            w.sq[i] = sc.w_inv_sq();
            // The predictor (affine scaling) direction's right side: −v ∘ v.
            w.d[i] = w.v[i].map(|x| -x);
        }
        if !prog.normal(&w.sq, &mut w.chol) {
            return Ok(None);
        }
        w.direction(&prog, false);
        // Mehrotra's centring and corrector.
        let sigma = (1.0 - w.affine.longest(&s, &l).min(1.0)).powi(3);
        let mu = gap / cones as f64;
        for (i, (v, sc)) in w.v.iter().zip(&w.sc).enumerate() {
            let vv = jordan(v, v);
            let corr = jordan(&sc.w_inv(&w.affine.ds[i]), &sc.w(&w.affine.dl[i]));
            let rc = [
                -vv[0] + sigma * mu - corr[0],
                -vv[1] - corr[1],
                -vv[2] - corr[2],
            ];
            w.d[i] = jordan_div(v, &rc);
        }
        w.direction(&prog, true);
        let alpha = (STEP * w.step.longest(&s, &l)).min(1.0);
        if !(alpha.is_finite() && alpha > 0.0) {
            return Ok(None);
        }
        for (z, dz) in z.iter_mut().zip(&w.step.dz) {
            *z += alpha * dz;
        }
        for i in 0..cones {
            for j in 0..3 {
                s[i][j] += alpha * w.step.ds[i][j];
                l[i][j] += alpha * w.step.dl[i][j];
            }
        }
    }
    Ok(None)
}
