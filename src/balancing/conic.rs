//! Min-max and mass-bounded corrections as second-order cone programs
//! (method §4.1), solved exactly by Clarabel; min-max working sets of many
//! rows (`active_set`) by a small dense primal-dual method (`primal_dual`), checked
//! against Clarabel's full program (tests/solve/minmax/equivalence.rs), with
//! Clarabel again wherever that method's arithmetic fails; the answer is
//! then polished to rounding on its active set (`polish`). Where planes
//! are undetermined or nearly so, both objectives pick the least-mass
//! optimum among the equally good ones (`least_mass`).
//!
//! The caller hands over the weighted problem `r = b + A x` (rows of `A` and `b`
//! already multiplied by the row weights, method 3.3) in the internal frame; `solve_cone`
//! only knows complex matrices, `wiring` connects it to a session solve and
//! `program` holds the Clarabel formulation.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::error::InputError;
use super::model::Objective;

mod active_set;
mod kkt;
mod least_mass;
mod loose;
mod polish;
mod primal_dual;
mod program;
mod soc;
pub mod wiring;

pub use least_mass::NEARLY_DEPENDENT;

/// How min-max rows reach the cone solver.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Strategy {
    /// Cones only for the rows that matter: a working set grown by the
    /// violated rows until none is left (`active_set`). The default.
    #[default]
    ActiveSet,
    /// One cone per row in a single program: the reference formulation.
    Full,
}

/// When a cone solve gives up: a request that does not converge gets a 422,
/// never a hang.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Interior-point iterations (Clarabel typically needs 10–30).
    pub max_iter: u32,
    /// Wall-clock seconds; the 1,000-row × 16-plane benchmark needs well under one.
    pub time_limit_s: f64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_iter: 200,
            time_limit_s: 5.0,
        }
    }
}

/// A bound counts as binding when the mass reaches it to this relative tolerance;
/// the interior-point solution approaches the boundary only to solver accuracy,
/// which on an ill-conditioned job (scaled columns of very different size) was
/// seen to leave a binding bound 1.3·10⁻⁵ short (issue 12). A mass within 0.1 %
/// of its bound is held by it for any practical purpose.
const BINDING_TOL: f64 = 1e-3;

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
/// subject to |x_j| ≤ `max_abs[j]` where Some. A: rows × planes, internal frame.
pub fn solve_cone(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    objective: Objective,
    max_abs: &[Option<f64>],
) -> Result<ConeSolution, InputError> {
    solve_cone_within(a, b, objective, max_abs, Limits::default())
}

/// [`solve_cone`] with explicit iteration and time limits.
pub fn solve_cone_within(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    objective: Objective,
    max_abs: &[Option<f64>],
    limits: Limits,
) -> Result<ConeSolution, InputError> {
    solve_cone_with(a, b, objective, max_abs, limits, Strategy::default(), false)
}

/// [`solve_cone`] for a job whose `A` has the scaled condition number
/// `condition` (columns at unit norm; the solve's one factorisation): from
/// [`NEARLY_DEPENDENT`] on, where some plane is undetermined or nearly so and
/// the first optimum an accident of the solver's path, the answer is the
/// optimum of least total squared mass (`least_mass`): for min-max, and for
/// least squares under a binding bound (unbounded least squares has it from
/// the pseudo-inverse, without a cone program).
pub fn solve_cone_conditioned(
    condition: f64,
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    objective: Objective,
    max_abs: &[Option<f64>],
) -> Result<ConeSolution, InputError> {
    let least_mass = condition >= NEARLY_DEPENDENT;
    let (limits, strategy) = (Limits::default(), Strategy::default());
    solve_cone_with(a, b, objective, max_abs, limits, strategy, least_mass)
}

/// [`solve_cone_within`] with the min-max rows handled by `strategy`; both
/// give the same answer to the solver's tolerance (tests/solve/minmax/equivalence.rs).
/// `least_mass` asks for the optimum of least total squared mass
/// where several are equally good ([`solve_cone_conditioned`] says when).
pub fn solve_cone_with(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    objective: Objective,
    max_abs: &[Option<f64>],
    limits: Limits,
    strategy: Strategy,
    least_mass: bool,
) -> Result<ConeSolution, InputError> {
    check_input(a, b, max_abs)?;
    let planes = a.ncols();
    // Columns the sensors do not see cannot lower any residual: their best (and
    // least-mass) correction is zero, and leaving them out keeps the cone program
    // free of directions it cannot pin down.
    let live: Vec<usize> = (0..planes).filter(|&j| a.column(j).norm() > 0.0).collect();
    let mut a_used = a.select_columns(&live);
    let mut b_used = b.clone();
    if objective == Objective::LeastSquares && a_used.nrows() > live.len() && !live.is_empty() {
        // With A = QR (thin), ‖b + Ax‖² = ‖Qᴴb + Rx‖² + ‖(I − QQᴴ)b‖²: the same
        // minimiser from a planes × planes problem, whatever the number of rows.
        let qr = a_used.clone().qr();
        b_used = qr.q().ad_mul(b);
        a_used = qr.r();
    }
    let rows = a_used.nrows();
    let beta = b_used.iter().map(|z| z.norm()).fold(0.0, f64::max);
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
    let d: Vec<f64> = a_used.column_iter().map(|c| 1.0 / c.norm()).collect();
    let n = live.len();
    let a_s = DMatrix::from_fn(rows, n, |i, k| a_used[(i, k)] * d[k]);
    let b_s = b_used.map(|z| z / beta);
    let bounds: Vec<(usize, f64)> = live
        .iter()
        .enumerate()
        .filter_map(|(k, &j)| max_abs[j].map(|m| (k, m / (beta * d[k]))))
        .collect();
    // Bounds that cannot bind are left out: a huge one stalled Clarabel (`loose`).
    let program = |bounds: &[(usize, f64)]| match (objective, strategy) {
        (Objective::MinMax, Strategy::ActiveSet) => active_set::min_max(&a_s, &b_s, bounds, limits),
        _ => {
            let all: Vec<usize> = (0..rows).collect();
            program::solve_on(&a_s, &b_s, objective, bounds, &all, limits)
        }
    };
    let mut solved = loose::solve(&a_s, &b_s, &bounds, program)?;
    // The interior point fixes the objective to its gap but the correction
    // only to about the gap's square root (min-max) or the gap over the
    // curvature (least squares): Newton on the active set, taken with a
    // certificate of optimality (`polish`).
    let polished = match objective {
        Objective::MinMax => polish::polish(&a_s, &b_s, &bounds, &solved.0),
        Objective::LeastSquares => polish::polish_least_squares(&a_s, &b_s, &bounds, &solved.0),
    };
    if let Some(y) = polished {
        solved.0 = y;
    }
    if least_mass {
        solved = least_mass::refine(objective, &a_s, &b_s, &bounds, &d, solved, limits);
    }
    let (y, iterations, status) = solved;
    let mut x = DVector::zeros(planes);
    let mut bound_active = vec![false; planes];
    for (k, &j) in live.iter().enumerate() {
        let mut xj = y[k] * (beta * d[k]);
        if let Some(m) = max_abs[j] {
            bound_active[j] = xj.norm() >= m * (1.0 - BINDING_TOL);
            // The interior point may overshoot the boundary by solver accuracy;
            // the bound is a promise to the fitter, so keep it exactly.
            // (A hair inside, as m/|x|·x can round a last bit above m.)
            if xj.norm() > m {
                xj *= m / xj.norm() * (1.0 - 4.0 * f64::EPSILON);
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
