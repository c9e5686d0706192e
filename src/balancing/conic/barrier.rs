//! A small dense interior-point solver for the scaled min-max program
//! (method 4.1, issue 15): `min t` subject to `|b_a + (A y)_a| ≤ t` on the
//! given rows and `|y_k| ≤ m_k` on the bounded columns.
//!
//! Why not Clarabel here: the working sets of `active_set` have a few dozen
//! rows and `2n + 1 ≤ 33` real unknowns, where Clarabel's sparse setup,
//! equilibration and factorisation cost far more than the arithmetic. This
//! is the textbook barrier method (Boyd & Vandenberghe §11.3) on the
//! self-concordant barrier `−log(t² − |r_a|²)` of each 3-dimensional
//! second-order cone (parameter 2) and `−log(m_k² − |y_k|²)` of each bound:
//! Newton's method with a backtracking line search on `τ t + Σ barriers`,
//! `τ` raised tenfold per centring until the duality gap bound `ν / τ` is
//! below [`GAP`] (`ν` = 2 per cone). The program is always strictly feasible
//! (`y = 0`, `t > max |b|`: bounds are positive) and bounded below by 0, so
//! no phase I and no infeasibility test are needed.
//!
//! The Newton systems are `(2n+1) × (2n+1)` and dense (a Cholesky of the
//! barrier's Hessian, not of the least-squares normal equations). When one
//! fails (a Hessian that rounding has left indefinite) the caller falls back
//! to Clarabel, so the answer never depends on this solver's luck.

use std::time::Instant;

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::Limits;
use crate::balancing::error::InputError;

/// Relative duality-gap bound `ν / (τ t)` at which the optimum is taken as
/// found: Clarabel's `tol_gap_rel` for the same program (`program.rs`).
const GAP: f64 = 1e-10;
/// Absolute gap bound for an optimum near zero (exact data): Clarabel's
/// `tol_gap_abs`.
const GAP_ABS: f64 = 1e-11;
/// Newton steps after which the barrier gives way to Clarabel (it typically
/// takes 50 to 90).
const BUDGET: u32 = 150;
/// Newton decrement `λ²/2` at which a centring counts as converged. An
/// off-centre point costs about `λ²/τ` in the objective on top of `ν/τ`, so a
/// loose centring is as good as a tight one; and near the optimum rounding
/// keeps `λ²` at about 1e-7 whatever the number of steps.
const CENTRED: f64 = 1e-5;
/// `τ` grows by this factor per centring.
const MU: f64 = 30.0;

/// One cone row in real form: `Re r = re0 + p·x`, `Im r = im0 + q·x`, over
/// `x = (Re y, Im y)` (the `t` entry is the last unknown).
struct Row {
    re0: f64,
    im0: f64,
    p: Vec<f64>,
    q: Vec<f64>,
}

/// The optimal `y` (complex, one per column of `a`) and the Newton steps
/// taken; `Ok(None)` when the arithmetic failed or the step budget ran out
/// and Clarabel should solve the program instead; a 422 when the time limit
/// ends the solve.
pub(super) fn min_max(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    rows: &[usize],
    limits: Limits,
) -> Result<Option<(Vec<Complex64>, u32)>, InputError> {
    let n = a.ncols();
    let dim = 2 * n + 1;
    let t_at = 2 * n;
    let cones: Vec<Row> = rows
        .iter()
        .map(|&i| {
            let mut p = vec![0.0; 2 * n];
            let mut q = vec![0.0; 2 * n];
            for k in 0..n {
                let c = a[(i, k)];
                // r = b + Σ c_k (u_k + i v_k): Re = Σ Re c u − Im c v, Im = Σ Im c u + Re c v.
                p[k] = c.re;
                p[n + k] = -c.im;
                q[k] = c.im;
                q[n + k] = c.re;
            }
            Row {
                re0: b[i].re,
                im0: b[i].im,
                p,
                q,
            }
        })
        .collect();
    let nu = 2.0 * (cones.len() + bounds.len()) as f64;
    let start = Instant::now();

    // Strictly feasible start: y = 0, t above every |b_a|.
    let mut x = vec![0.0; dim];
    let b_max = rows.iter().map(|&i| b[i].norm()).fold(0.0, f64::max);
    x[t_at] = 1.5 * b_max + 1e-3;
    let mut tau = nu / x[t_at];
    let mut steps = 0u32;

    // f(x) = τ t + Σ −log(slack), or None outside the domain.
    let value = |x: &[f64], tau: f64| -> Option<f64> {
        let t = x[t_at];
        if t <= 0.0 {
            return None;
        }
        let mut f = tau * t;
        for c in &cones {
            let (re, im) = residual(c, x);
            let d = t * t - re * re - im * im;
            if d <= 0.0 {
                return None;
            }
            f -= d.ln();
        }
        for &(k, m) in bounds {
            let d = m * m - x[k] * x[k] - x[n + k] * x[n + k];
            if d <= 0.0 {
                return None;
            }
            f -= d.ln();
        }
        Some(f)
    };

    loop {
        let last = nu / tau <= (GAP * x[t_at]).max(GAP_ABS);
        // Centre: Newton on τ t + barriers.
        loop {
            steps += 1;
            if steps > limits.max_iter.min(BUDGET) {
                // Clarabel, within the same limits, decides.
                return Ok(None);
            }
            if start.elapsed().as_secs_f64() > limits.time_limit_s {
                return Err(failed(format!(
                    "no convergence within {} s",
                    limits.time_limit_s
                )));
            }
            let (grad, hess) = newton_system(&cones, bounds, n, &x, tau);
            let Some(chol) = hess.cholesky() else {
                return Ok(None);
            };
            let step = chol.solve(&(-&grad));
            let decrement = -grad.dot(&step);
            if !decrement.is_finite() {
                return Ok(None);
            }
            if decrement / 2.0 <= CENTRED {
                break;
            }
            // Backtracking: stay inside every cone, then Armijo.
            let f0 = value(&x, tau).expect("the iterate is strictly feasible");
            let mut s = 1.0;
            let moved = loop {
                let trial: Vec<f64> = x.iter().zip(step.iter()).map(|(v, d)| v + s * d).collect();
                if let Some(f) = value(&trial, tau) {
                    if f <= f0 - 0.01 * s * decrement {
                        break Some(trial);
                    }
                }
                s *= 0.5;
                if s < 1e-12 {
                    break None;
                }
            };
            match moved {
                Some(trial) => x = trial,
                // No progress at this τ: centred as far as rounding allows.
                None => break,
            }
        }
        if last {
            break;
        }
        tau *= MU;
    }
    let y = (0..n).map(|k| Complex64::new(x[k], x[n + k])).collect();
    Ok(Some((y, steps)))
}

fn residual(c: &Row, x: &[f64]) -> (f64, f64) {
    let mut re = c.re0;
    let mut im = c.im0;
    for ((&v, &p), &q) in x.iter().zip(&c.p).zip(&c.q) {
        re += p * v;
        im += q * v;
    }
    (re, im)
}

/// Gradient and Hessian of `τ t + Σ −log d`: for a cone `d = t² − Re r² − Im r²`,
/// `∇(−log d) = −∇d / d` and `∇²(−log d) = ∇d ∇dᵀ / d² − ∇²d / d`.
fn newton_system(
    cones: &[Row],
    bounds: &[(usize, f64)],
    n: usize,
    x: &[f64],
    tau: f64,
) -> (DVector<f64>, DMatrix<f64>) {
    let dim = 2 * n + 1;
    let t_at = 2 * n;
    let t = x[t_at];
    let mut grad = DVector::zeros(dim);
    grad[t_at] = tau;
    let mut hess = DMatrix::zeros(dim, dim);
    let mut g = vec![0.0; dim];
    for c in cones {
        let (re, im) = residual(c, x);
        let d = t * t - re * re - im * im;
        // ∇d = (−2 Re r p − 2 Im r q, 2t).
        for ((gj, &pj), &qj) in g.iter_mut().zip(&c.p).zip(&c.q) {
            *gj = -2.0 * (re * pj + im * qj);
        }
        g[t_at] = 2.0 * t;
        let (inv, inv2) = (1.0 / d, 1.0 / (d * d));
        for (gr, &gj) in grad.iter_mut().zip(&g) {
            *gr -= gj * inv;
        }
        // −∇²d / d = (2ppᵀ + 2qqᵀ − 2 e_t e_tᵀ) / d, plus ∇d ∇dᵀ / d².
        for col in 0..dim {
            let (gc, pc, qc) = if col < 2 * n {
                (g[col] * inv2, c.p[col] * 2.0 * inv, c.q[col] * 2.0 * inv)
            } else {
                (g[col] * inv2, 0.0, 0.0)
            };
            // Column-major storage: column `col` is one contiguous slice.
            let column = &mut hess.as_mut_slice()[col * dim..(col + 1) * dim];
            for row in 0..2 * n {
                column[row] += g[row] * gc + c.p[row] * pc + c.q[row] * qc;
            }
            column[t_at] += g[t_at] * gc;
        }
        hess[(t_at, t_at)] -= 2.0 * inv;
    }
    for &(k, m) in bounds {
        let (u, v) = (x[k], x[n + k]);
        let d = m * m - u * u - v * v;
        // ∇d = (−2u, −2v) at (k, n+k); −∇²d / d = 2 I / d.
        let (gu, gv) = (-2.0 * u, -2.0 * v);
        grad[k] -= gu / d;
        grad[n + k] -= gv / d;
        let inv2 = 1.0 / (d * d);
        hess[(k, k)] += gu * gu * inv2 + 2.0 / d;
        hess[(n + k, n + k)] += gv * gv * inv2 + 2.0 / d;
        hess[(k, n + k)] += gu * gv * inv2;
        hess[(n + k, k)] += gu * gv * inv2;
    }
    (grad, hess)
}

fn failed(why: String) -> InputError {
    InputError::unsolvable(
        "solver_failed",
        format!("the cone solver could not solve this balancing problem: {why}"),
    )
}
