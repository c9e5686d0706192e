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
//! barrier's Hessian, not of the least-squares normal equations). Each
//! cone's share of the Hessian has rank two in the unknowns `y` (it lives in
//! the span of the row's real and imaginary coefficient vectors), so the
//! `y` block is one product `B Bᵀ` of a `2n × 2m` matrix, which nalgebra
//! hands to `matrixmultiply`'s SIMD kernels; along a Newton step the
//! residuals move linearly, so the line search costs `O(m)` a trial. When one
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

/// The working rows in real form, one column per row: `Re r = re0 + pᵀ x`,
/// `Im r = im0 + qᵀ x` over `x = (Re y, Im y)` (the `t` entry is the last unknown).
struct Cones {
    re0: DVector<f64>,
    im0: DVector<f64>,
    p: DMatrix<f64>,
    q: DMatrix<f64>,
}

/// Buffers of one Newton step, allocated once per solve.
struct Work {
    re: DVector<f64>,
    im: DVector<f64>,
    /// Per row: weights of `p`, `q` in the gradient, then in the Hessian's `t` column.
    gp: DVector<f64>,
    gq: DVector<f64>,
    hp: DVector<f64>,
    hq: DVector<f64>,
    /// `B` and `Bᵀ`, the factor of the Hessian's `y` block.
    b: DMatrix<f64>,
    bt: DMatrix<f64>,
    grad: DVector<f64>,
    hess: DMatrix<f64>,
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
    let (n2, m) = (2 * n, rows.len());
    let dim = n2 + 1;
    let t_at = n2;
    let mut cones = Cones {
        re0: DVector::zeros(m),
        im0: DVector::zeros(m),
        p: DMatrix::zeros(n2, m),
        q: DMatrix::zeros(n2, m),
    };
    for (col, &i) in rows.iter().enumerate() {
        for k in 0..n {
            let c = a[(i, k)];
            // r = b + Σ c_k (u_k + i v_k): Re = Σ Re c u − Im c v, Im = Σ Im c u + Re c v.
            cones.p[(k, col)] = c.re;
            cones.p[(n + k, col)] = -c.im;
            cones.q[(k, col)] = c.im;
            cones.q[(n + k, col)] = c.re;
        }
        cones.re0[col] = b[i].re;
        cones.im0[col] = b[i].im;
    }
    let mut w = Work {
        re: DVector::zeros(m),
        im: DVector::zeros(m),
        gp: DVector::zeros(m),
        gq: DVector::zeros(m),
        hp: DVector::zeros(m),
        hq: DVector::zeros(m),
        b: DMatrix::zeros(n2, 2 * m),
        bt: DMatrix::zeros(2 * m, n2),
        grad: DVector::zeros(dim),
        hess: DMatrix::zeros(dim, dim),
    };
    let (mut dre, mut dim_) = (DVector::zeros(m), DVector::zeros(m));
    let nu = 2.0 * (m + bounds.len()) as f64;
    let start = Instant::now();

    // Strictly feasible start: y = 0, t above every |b_a|.
    let mut x = DVector::zeros(dim);
    let b_max = rows.iter().map(|&i| b[i].norm()).fold(0.0, f64::max);
    x[t_at] = 1.5 * b_max + 1e-3;
    let mut tau = nu / x[t_at];
    let mut steps = 0u32;

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
            let head = x.rows(0, n2);
            w.re.copy_from(&cones.re0);
            w.re.gemv_tr(1.0, &cones.p, &head, 1.0);
            w.im.copy_from(&cones.im0);
            w.im.gemv_tr(1.0, &cones.q, &head, 1.0);
            newton_system(&cones, &mut w, bounds, n, &x, tau);
            let Some(step) = w.hess.clone().cholesky().map(|c| c.solve(&(-&w.grad))) else {
                return Ok(None);
            };
            let decrement = -w.grad.dot(&step);
            if !decrement.is_finite() {
                return Ok(None);
            }
            if decrement / 2.0 <= CENTRED {
                break;
            }
            // Backtracking: stay inside every cone, then Armijo. The
            // residuals move linearly along the step: r + s·dr.
            let ahead = step.rows(0, n2);
            dre.gemv_tr(1.0, &cones.p, &ahead, 0.0);
            dim_.gemv_tr(1.0, &cones.q, &ahead, 0.0);
            // f(x + s·step) = τ t + Σ −log(slack), or None outside the domain.
            let along = |s: f64| -> Option<f64> {
                let t = x[t_at] + s * step[t_at];
                if t <= 0.0 {
                    return None;
                }
                let mut f = tau * t;
                for a in 0..m {
                    let (re, im) = (w.re[a] + s * dre[a], w.im[a] + s * dim_[a]);
                    let d = t * t - re * re - im * im;
                    if d <= 0.0 {
                        return None;
                    }
                    f -= d.ln();
                }
                for &(k, mk) in bounds {
                    let (u, v) = (x[k] + s * step[k], x[n + k] + s * step[n + k]);
                    let d = mk * mk - u * u - v * v;
                    if d <= 0.0 {
                        return None;
                    }
                    f -= d.ln();
                }
                Some(f)
            };
            let f0 = along(0.0).expect("the iterate is strictly feasible");
            let mut s = 1.0;
            let moved = loop {
                if let Some(f) = along(s) {
                    if f <= f0 - 0.01 * s * decrement {
                        break Some(s);
                    }
                }
                s *= 0.5;
                if s < 1e-12 {
                    break None;
                }
            };
            match moved {
                Some(s) => x.axpy(s, &step, 1.0),
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

/// Gradient and Hessian of `τ t + Σ −log d` into `w.grad`, `w.hess`, from
/// the residuals `w.re`, `w.im` at `x`: for a cone `d = t² − |r|²`,
/// `∇(−log d) = −∇d / d` and `∇²(−log d) = ∇d ∇dᵀ / d² − ∇²d / d`, with
/// `∇d = (−2u, 2t)`, `u = Re r p + Im r q`.
fn newton_system(
    cones: &Cones,
    w: &mut Work,
    bounds: &[(usize, f64)],
    n: usize,
    x: &DVector<f64>,
    tau: f64,
) {
    let n2 = 2 * n;
    let t = x[n2];
    let mut grad_t = tau;
    let mut hess_tt = 0.0;
    for a in 0..cones.re0.len() {
        let (re, im) = (w.re[a], w.im[a]);
        let d = t * t - re * re - im * im;
        let (inv, inv2) = (1.0 / d, 1.0 / (d * d));
        // Gradient: 2u/d in y, −2t/d in t.
        w.gp[a] = 2.0 * re * inv;
        w.gq[a] = 2.0 * im * inv;
        grad_t -= 2.0 * t * inv;
        // The y–t column: (−2u)(2t)/d²; the t–t entry: 4t²/d² − 2/d.
        w.hp[a] = -4.0 * t * re * inv2;
        w.hq[a] = -4.0 * t * im * inv2;
        hess_tt += 4.0 * t * t * inv2 - 2.0 * inv;
        // The y block: 4uuᵀ/d² + 2(ppᵀ + qqᵀ)/d = P S Pᵀ with P = [p q] and
        // S = (2/d) I + (4/d²) r rᵀ, r = (Re r, Im r); S = L Lᵀ (2 × 2 Cholesky).
        let (beta, alpha) = (2.0 * inv, 4.0 * inv2);
        let s11 = beta + alpha * re * re;
        let l11 = s11.sqrt();
        let l21 = alpha * re * im / l11;
        let l22 = (beta * (beta + alpha * (re * re + im * im)) / s11).sqrt();
        let (p, q) = (cones.p.column(a), cones.q.column(a));
        for k in 0..n2 {
            let (pk, qk) = (p[k], q[k]);
            let (u, v) = (l11 * pk + l21 * qk, l22 * qk);
            w.b[(k, 2 * a)] = u;
            w.b[(k, 2 * a + 1)] = v;
            w.bt[(2 * a, k)] = u;
            w.bt[(2 * a + 1, k)] = v;
        }
    }
    let mut gy = w.grad.rows_mut(0, n2);
    gy.gemv(1.0, &cones.p, &w.gp, 0.0);
    gy.gemv(1.0, &cones.q, &w.gq, 1.0);
    w.grad[n2] = grad_t;
    w.hess
        .view_mut((0, 0), (n2, n2))
        .gemm(1.0, &w.b, &w.bt, 0.0);
    let mut hyt = w.hess.column_mut(n2);
    let mut hyt = hyt.rows_mut(0, n2);
    hyt.gemv(1.0, &cones.p, &w.hp, 0.0);
    hyt.gemv(1.0, &cones.q, &w.hq, 1.0);
    for k in 0..n2 {
        w.hess[(n2, k)] = w.hess[(k, n2)];
    }
    w.hess[(n2, n2)] = hess_tt;
    for &(k, m) in bounds {
        let (u, v) = (x[k], x[n + k]);
        let d = m * m - u * u - v * v;
        // ∇d = (−2u, −2v) at (k, n+k); −∇²d / d = 2 I / d.
        let (gu, gv) = (-2.0 * u, -2.0 * v);
        w.grad[k] -= gu / d;
        w.grad[n + k] -= gv / d;
        let inv2 = 1.0 / (d * d);
        w.hess[(k, k)] += gu * gu * inv2 + 2.0 / d;
        w.hess[(n + k, n + k)] += gv * gv * inv2 + 2.0 / d;
        w.hess[(k, n + k)] += gu * gv * inv2;
        w.hess[(n + k, k)] += gu * gv * inv2;
    }
}

fn failed(why: String) -> InputError {
    InputError::unsolvable(
        "solver_failed",
        format!("the cone solver could not solve this balancing problem: {why}"),
    )
}
