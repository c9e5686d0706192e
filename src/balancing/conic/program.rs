//! The cone program itself: Clarabel's standard form assembled in triplets, and
//! Clarabel's verdict turned into a solution or a 422.

use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettings, DefaultSolver, IPSolver, SolverStatus, SupportedConeT};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::Limits;
use crate::balancing::error::InputError;
use crate::balancing::model::Objective;

/// The scaled problem `min ‖b + A y‖` (2-norm or largest entry) with
/// `|y_k| ≤ m_k` for each `(k, m_k)` in `bounds`, on the rows `rows` of `a`, `b`.
pub(super) fn solve_on(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    objective: Objective,
    bounds: &[(usize, f64)],
    rows: &[usize],
    limits: Limits,
) -> Result<(Vec<Complex64>, u32, String), InputError> {
    let mut problem = Problem::new(a.ncols());
    let col = |i: usize, k: usize| a[(rows[i], k)];
    let rhs = |i: usize| b[rows[i]];
    match objective {
        Objective::LeastSquares => problem.least_squares(rows.len(), col, rhs),
        Objective::MinMax => problem.min_max(rows.len(), col, rhs),
    }
    for &(k, m) in bounds {
        problem.bound(k, m);
    }
    problem.solve(limits)
}

/// The scaled least-mass program of `least_mass`: `min ½‖c + M z‖²` subject
/// to `|b_a + (A z)_a| ≤ caps[a]` on every row of `a`, `b`, and, when
/// `whole` is `(A₂, b₂, cap)`, to `‖b₂ + A₂ z‖₂ ≤ cap` (least squares).
pub(super) fn least_norm_capped(
    m: &DMatrix<Complex64>,
    c: &DVector<Complex64>,
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    caps: &[f64],
    whole: Option<(&DMatrix<Complex64>, &DVector<Complex64>, f64)>,
    limits: Limits,
) -> Result<(Vec<Complex64>, u32, String), InputError> {
    let mut problem = Problem::new(m.ncols());
    problem.least_squares(m.nrows(), |i, k| m[(i, k)], |i| c[i]);
    for (row, &cap) in caps.iter().enumerate() {
        problem.capped(&|k| a[(row, k)], b[row], cap);
    }
    if let Some((a2, b2, cap)) = whole {
        problem.norm_capped(a2, b2, cap);
    }
    problem.solve(limits)
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
        let unit = |j| Complex64::new(if j == k { 1.0 } else { 0.0 }, 0.0);
        self.capped(&unit, Complex64::new(0.0, 0.0), m);
    }

    /// `|c + Σ_k coef(k) y_k| ≤ cap` as the cone (cap, Re, Im).
    fn capped(&mut self, coef: &dyn Fn(usize) -> Complex64, c: Complex64, cap: f64) {
        self.push([], cap);
        // No variable beside y: zero coefficients are left out.
        self.push_residual(coef, c, [(0, 0.0), (0, 0.0)]);
        self.cones.push(SupportedConeT::SecondOrderConeT(3));
    }

    /// `‖c + A y‖₂ ≤ cap` over all rows of `a`, `c` as one cone
    /// `(cap, Re r₁, Im r₁, …)` of dimension `1 + 2 rows`.
    fn norm_capped(&mut self, a: &DMatrix<Complex64>, c: &DVector<Complex64>, cap: f64) {
        self.push([], cap);
        for row in 0..a.nrows() {
            self.push_residual(&|k| a[(row, k)], c[row], [(0, 0.0), (0, 0.0)]);
        }
        self.cones
            .push(SupportedConeT::SecondOrderConeT(1 + 2 * a.nrows()));
    }

    /// Run Clarabel; the complex solution y, iterations and status, or a 422.
    fn solve(self, limits: Limits) -> Result<(Vec<Complex64>, u32, String), InputError> {
        let (m, nv) = (self.rhs.len(), self.vars);
        let (pi, pv): (Vec<usize>, Vec<f64>) = self.p_diag.iter().copied().unzip();
        let p = CscMatrix::new_from_triplets(nv, nv, pi.clone(), pi, pv);
        let a = CscMatrix::new_from_triplets(m, nv, self.ai, self.aj, self.av);
        let settings = DefaultSettings {
            verbose: false,
            max_iter: limits.max_iter,
            time_limit: limits.time_limit_s,
            // Tighter than Clarabel's 1e-8: a small optimal residual beside a large
            // as-found vibration would otherwise be known to only ~1e-5.
            tol_gap_abs: 1e-11,
            tol_gap_rel: 1e-10,
            tol_feas: 1e-10,
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
                return Err(failed(format!(
                    "no convergence within {} s",
                    limits.time_limit_s
                )))
            }
            SolverStatus::MaxIterations => {
                return Err(failed(format!(
                    "no convergence within {} iterations",
                    limits.max_iter
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
