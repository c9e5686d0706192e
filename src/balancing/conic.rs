//! Min-max and mass-bounded corrections as second-order cone programs
//! (method §4.1), solved exactly by Clarabel rather than by a home-made iteration.
//!
//! The caller hands over the weighted problem `r = b + A x` (rows of `A` and `b`
//! already multiplied by the row weights, method 3.3) in the internal frame; this
//! module only knows complex matrices, not sessions.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::error::InputError;
use super::model::Objective;

/// Wall-clock limit of one cone solve: a request that does not converge gets a
/// 422, never a hang. The 1,000-row × 16-plane benchmark solves in milliseconds.
pub const TIME_LIMIT_S: f64 = 5.0;
/// Interior-point iteration limit (Clarabel typically needs 10–30).
pub const MAX_ITER: u32 = 200;
/// A bound counts as binding when the mass reaches it to this relative tolerance;
/// the interior-point solution approaches the boundary only to solver accuracy.
const BINDING_TOL: f64 = 1e-5;

/// The optimal correction of a cone solve.
#[derive(Debug, Clone, PartialEq)]
pub struct ConeSolution {
    /// Corrections, one per column of `A`, internal frame.
    pub x: DVector<Complex64>,
    /// Per column: its bound `|x_j| ≤ max_abs[j]` is binding at the optimum.
    pub bound_active: Vec<bool>,
    /// The optimal objective, recomputed from `x`: `‖r‖₂` or `max_a |r_a|`.
    pub value: f64,
    /// Interior-point iterations Clarabel took.
    pub iterations: u32,
    /// Clarabel's final status (`Solved`, or `AlmostSolved` at reduced accuracy).
    pub status: String,
}

/// Minimise the residual r = b + A x over complex x (rows of A and b already weighted
/// by the caller): objective LeastSquares → ‖r‖₂, MinMax → max_a |r_a|;
/// subject to |x_j| ≤ max_abs[j] where Some. A: rows × planes, internal frame.
pub fn solve_cone(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    objective: Objective,
    max_abs: &[Option<f64>],
) -> Result<ConeSolution, InputError> {
    check_input(a, b, max_abs)?;
    let (rows, planes) = a.shape();
    let beta = b.iter().map(|z| z.norm()).fold(0.0, f64::max);
    // Columns the sensors do not see cannot lower any residual: their best (and
    // least-mass) correction is zero, and leaving them out keeps the cone program
    // free of directions it cannot pin down.
    let live: Vec<usize> = (0..planes).filter(|&j| a.column(j).norm() > 0.0).collect();
    if beta == 0.0 || live.is_empty() {
        let x = DVector::zeros(planes);
        let value = objective_value(a, b, &x, objective);
        return Ok(ConeSolution {
            x,
            bound_active: vec![false; planes],
            value,
            iterations: 0,
            status: "Trivial".into(),
        });
    }
    // Scale so Clarabel sees numbers of order 1 whatever the units (amplitudes
    // 1e-3..1e3, grams 1..1e4): x_j = β d_j y_j with d_j = 1/‖A_:j‖ and β = max|b_a|
    // gives r/β = b/β + Σ_j (A_:j d_j) y_j, unit columns and a right side of norm ~1.
    let d: Vec<f64> = live.iter().map(|&j| 1.0 / a.column(j).norm()).collect();
    let n = live.len();
    let mut scaled = Problem::new(n);
    // Real form of column k of A d: Re/Im parts, rows × n.
    let col = |row: usize, k: usize| a[(row, live[k])] * d[k];
    let rhs = |row: usize| b[row] / beta;
    match objective {
        Objective::LeastSquares => scaled.least_squares(rows, col, rhs),
        Objective::MinMax => scaled.min_max(rows, col, rhs),
    }
    let bounds: Vec<(usize, f64)> = live
        .iter()
        .enumerate()
        .filter_map(|(k, &j)| max_abs[j].map(|m| (k, m / (beta * d[k]))))
        .collect();
    for &(k, m) in &bounds {
        scaled.bound(k, m);
    }
    let (y, iterations, status) = scaled.solve()?;
    let mut x = DVector::zeros(planes);
    let mut bound_active = vec![false; planes];
    for (k, &j) in live.iter().enumerate() {
        let mut xj = y[k] * (beta * d[k]);
        if let Some(m) = max_abs[j] {
            bound_active[j] = xj.norm() >= m * (1.0 - BINDING_TOL);
            // The interior point may overshoot the boundary by solver accuracy;
            // the bound is a promise to the fitter, so keep it exactly.
            if xj.norm() > m {
                xj *= m / xj.norm();
            }
        }
        x[j] = xj;
    }
    let value = objective_value(a, b, &x, objective);
    Ok(ConeSolution {
        x,
        bound_active,
        value,
        iterations,
        status,
    })
}

/// `‖b + A x‖₂` or `max_a |b_a + (A x)_a|`.
pub fn objective_value(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    x: &DVector<Complex64>,
    objective: Objective,
) -> f64 {
    let r = b + a * x;
    match objective {
        Objective::LeastSquares => r.norm(),
        Objective::MinMax => r.iter().map(|z| z.norm()).fold(0.0, f64::max),
    }
}

fn check_input(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    max_abs: &[Option<f64>],
) -> Result<(), InputError> {
    let (rows, planes) = a.shape();
    if planes == 0 {
        return Err(InputError::unsolvable(
            "no_planes",
            "no correction plane is left to solve for",
        ));
    }
    if rows == 0 {
        return Err(InputError::unsolvable(
            "no_rows",
            "no sensor reading is left to balance against",
        ));
    }
    if b.len() != rows || max_abs.len() != planes {
        return Err(InputError::unsolvable(
            "solver_failed",
            format!(
                "internal shape mismatch: {rows}×{planes} matrix, {} right-hand sides, {} bounds",
                b.len(),
                max_abs.len()
            ),
        ));
    }
    let finite = |z: &Complex64| z.re.is_finite() && z.im.is_finite();
    if !a.iter().all(finite) || !b.iter().all(finite) {
        return Err(InputError::unsolvable(
            "solver_failed",
            "the balancing problem contains a non-finite number",
        ));
    }
    if let Some(j) = max_abs
        .iter()
        .position(|m| m.is_some_and(|m| !(m.is_finite() && m > 0.0)))
    {
        return Err(InputError::unsolvable(
            "infeasible",
            format!("the mass bound of plane {j} must be a positive finite number"),
        ));
    }
    Ok(())
}

/// Clarabel's standard form `min ½zᵀPz + qᵀz  s.t.  b − Az ∈ K`, assembled in
/// triplets. Variables: `[Re y (n); Im y (n); extra]`, where `extra` is `t` for
/// min-max and the stacked real residual `w` for least squares.
struct Problem {
    n: usize,
    vars: usize,
    p_diag: Vec<(usize, f64)>,
    q: Vec<f64>,
    ai: Vec<usize>,
    aj: Vec<usize>,
    av: Vec<f64>,
    rhs: Vec<f64>,
    cones: Vec<SupportedConeT<f64>>,
}

impl Problem {
    fn new(n: usize) -> Self {
        Problem {
            n,
            vars: 2 * n,
            p_diag: Vec::new(),
            q: Vec::new(),
            ai: Vec::new(),
            aj: Vec::new(),
            av: Vec::new(),
            rhs: Vec::new(),
            cones: Vec::new(),
        }
    }

    fn push(&mut self, coeffs: impl IntoIterator<Item = (usize, f64)>, rhs: f64) {
        let row = self.rhs.len();
        for (j, v) in coeffs {
            if v != 0.0 {
                self.ai.push(row);
                self.aj.push(j);
                self.av.push(v);
            }
        }
        self.rhs.push(rhs);
    }

    /// Constraint rows making the slack equal `Re` then `Im` of `c + Σ_k col_k y_k`:
    /// `s = rhs − A z`, so A holds minus the real-form coefficients (method 3, stretched form).
    fn push_residual(
        &mut self,
        coef: &dyn Fn(usize) -> Complex64,
        c: Complex64,
        extra: [(usize, f64); 2],
    ) {
        let n = self.n;
        let re = (0..n).flat_map(|k| [(k, -coef(k).re), (n + k, coef(k).im)]);
        self.push(re.chain([extra[0]]), c.re);
        let im = (0..n).flat_map(|k| [(k, -coef(k).im), (n + k, -coef(k).re)]);
        self.push(im.chain([extra[1]]), c.im);
    }

    /// min ½‖w‖² with w = [Re r; Im r] pinned by equalities: smooth at a zero
    /// residual and never forms AᴴA (the normal equations).
    fn least_squares(
        &mut self,
        rows: usize,
        col: impl Fn(usize, usize) -> Complex64,
        rhs: impl Fn(usize) -> Complex64,
    ) {
        let w0 = self.vars;
        self.vars += 2 * rows;
        self.p_diag = (w0..self.vars).map(|v| (v, 1.0)).collect();
        self.q = vec![0.0; self.vars];
        for row in 0..rows {
            let coef = |k| col(row, k);
            self.push_residual(
                &coef,
                rhs(row),
                [(w0 + 2 * row, 1.0), (w0 + 2 * row + 1, 1.0)],
            );
        }
        self.cones.push(SupportedConeT::ZeroConeT(2 * rows));
    }

    /// min t with (t, Re r_a, Im r_a) in a 3-dimensional second-order cone per row.
    fn min_max(
        &mut self,
        rows: usize,
        col: impl Fn(usize, usize) -> Complex64,
        rhs: impl Fn(usize) -> Complex64,
    ) {
        let t = self.vars;
        self.vars += 1;
        self.q = vec![0.0; self.vars];
        self.q[t] = 1.0;
        for row in 0..rows {
            self.push([(t, -1.0)], 0.0);
            let coef = |k| col(row, k);
            self.push_residual(&coef, rhs(row), [(t, 0.0), (t, 0.0)]);
            self.cones.push(SupportedConeT::SecondOrderConeT(3));
        }
    }

    /// |y_k| ≤ m as the cone (m, Re y_k, Im y_k).
    fn bound(&mut self, k: usize, m: f64) {
        self.push([], m);
        self.push([(k, -1.0)], 0.0);
        self.push([(self.n + k, -1.0)], 0.0);
        self.cones.push(SupportedConeT::SecondOrderConeT(3));
    }

    /// Run Clarabel; the complex solution y, iterations and status, or a 422.
    fn solve(self) -> Result<(Vec<Complex64>, u32, String), InputError> {
        let (m, nv) = (self.rhs.len(), self.vars);
        let (pi, pv): (Vec<usize>, Vec<f64>) = self.p_diag.iter().copied().unzip();
        let p = CscMatrix::new_from_triplets(nv, nv, pi.clone(), pi, pv);
        let a = CscMatrix::new_from_triplets(m, nv, self.ai, self.aj, self.av);
        let settings = DefaultSettings {
            verbose: false,
            max_iter: MAX_ITER,
            time_limit: TIME_LIMIT_S,
            ..DefaultSettings::default()
        };
        let failed = |why: String| {
            InputError::unsolvable(
                "solver_failed",
                format!("the cone solver could not solve this balancing problem: {why}"),
            )
        };
        let mut solver = DefaultSolver::new(&p, &self.q, &a, &self.rhs, &self.cones, settings)
            .map_err(|e| failed(e.to_string()))?;
        solver.solve();
        let sol = &solver.solution;
        match sol.status {
            SolverStatus::Solved | SolverStatus::AlmostSolved => {}
            SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => {
                return Err(InputError::unsolvable(
                    "infeasible",
                    "no correction satisfies every mass bound",
                ))
            }
            SolverStatus::MaxTime => {
                return Err(failed(format!("no convergence within {TIME_LIMIT_S} s")))
            }
            SolverStatus::MaxIterations => {
                return Err(failed(format!(
                    "no convergence within {MAX_ITER} iterations"
                )))
            }
            other => return Err(failed(format!("{other:?}"))),
        }
        let n = self.n;
        let y = (0..n)
            .map(|k| Complex64::new(sol.x[k], sol.x[n + k]))
            .collect::<Vec<_>>();
        if y.iter().any(|z| !(z.re.is_finite() && z.im.is_finite())) {
            return Err(failed("non-finite solution".into()));
        }
        Ok((y, sol.iterations, format!("{:?}", sol.status)))
    }
}
