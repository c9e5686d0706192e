//! Min-max on many rows by constraint generation (issue 15): at the optimum
//! only a few rows reach the largest residual (at most `2n + 1` for `n`
//! complex unknowns, the dimension of the real problem plus one), so the cone
//! program is solved on a working set of rows and grown by the rows it
//! violates, most violated first, until none is left.
//!
//! Exactness: the working-set optimum `t_W` is a lower bound of the full
//! optimum (fewer constraints), and its `y` is feasible for the full problem
//! with objective `max_a |r_a| ≤ t_W + tol` once no row exceeds `t_W` by more
//! than `tol`: then it is optimal to that tolerance. Each round adds at least
//! one row, so the loop ends; the time limit is shared by all rounds.

use std::time::Instant;

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::primal_dual;
use super::program::solve_on;
use super::Limits;
use crate::balancing::error::InputError;
use crate::balancing::model::Objective;

/// Rows beyond `2n` in the first working set: the active rows are at most
/// `2n + 1`, and a few spare rows save a round most of the time.
const SPARE_ROWS: usize = 8;
/// A row outside the working set is violated when its residual exceeds the
/// working optimum by more than this, in the scaled units (`max |b| = 1`):
/// ten times Clarabel's feasibility tolerance, so solver noise adds no round.
const VIOLATION_TOL: f64 = 1e-9;

/// The scaled min-max problem `min_y max_a |b_a + (A y)_a|` with the bound
/// cones `bounds`; the answer of the full program to the solver's tolerance.
pub(super) fn min_max(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    limits: Limits,
) -> Result<(Vec<Complex64>, u32, String), InputError> {
    let (rows, n) = a.shape();
    let first = 2 * n + SPARE_ROWS;
    let batch = n.max(SPARE_ROWS);
    if rows <= first + batch {
        // Too few rows for a second round to pay off: one program on all.
        let all: Vec<usize> = (0..rows).collect();
        return solve(a, b, bounds, &all, limits);
    }
    let start = Instant::now();
    let mut working = first_rows(a, b, first);
    let mut in_set = vec![false; rows];
    for &i in &working {
        in_set[i] = true;
    }
    let mut iterations = 0;
    loop {
        let left = limits.time_limit_s - start.elapsed().as_secs_f64();
        if left <= 0.0 {
            return Err(InputError::unsolvable(
                "solver_failed",
                format!(
                    "the cone solver could not solve this balancing problem: no convergence within {} s",
                    limits.time_limit_s
                ),
            ));
        }
        let round = Limits {
            time_limit_s: left,
            ..limits
        };
        let (y, it, status) = solve(a, b, bounds, &working, round)?;
        iterations += it;
        let r = b + a * DVector::from_column_slice(&y);
        let t = working.iter().map(|&i| r[i].norm()).fold(0.0, f64::max);
        let mut violated: Vec<(usize, f64)> = (0..rows)
            .filter(|&i| !in_set[i])
            .map(|i| (i, r[i].norm()))
            .filter(|&(_, x)| x > t + VIOLATION_TOL)
            .collect();
        if violated.is_empty() {
            return Ok((y, iterations, status));
        }
        violated.sort_by(|p, q| q.1.total_cmp(&p.1));
        for &(i, _) in violated.iter().take(batch) {
            in_set[i] = true;
            working.push(i);
        }
    }
}

/// The min-max program on `rows`: the dense primal-dual method, or
/// Clarabel's one-cone-per-row program where its arithmetic fails.
fn solve(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    rows: &[usize],
    limits: Limits,
) -> Result<(Vec<Complex64>, u32, String), InputError> {
    match primal_dual::min_max(a, b, bounds, rows, limits)? {
        Some((y, steps)) => Ok((y, steps, "Solved".into())),
        None => solve_on(a, b, Objective::MinMax, bounds, rows, limits),
    }
}

/// The `count` rows with the largest least-squares residual (the rows a
/// min-max correction has to hold down), or with the largest `|b|` when the
/// least-squares solve fails.
fn first_rows(a: &DMatrix<Complex64>, b: &DVector<Complex64>, count: usize) -> Vec<usize> {
    let qr = a.clone().qr();
    let size: Vec<f64> = match qr.r().solve_upper_triangular(&(-qr.q().ad_mul(b))) {
        Some(y) if y.iter().all(|z| z.re.is_finite() && z.im.is_finite()) => {
            (b + a * y).iter().map(|z| z.norm()).collect()
        }
        _ => b.iter().map(|z| z.norm()).collect(),
    };
    let mut order: Vec<usize> = (0..size.len()).collect();
    order.sort_by(|&i, &j| size[j].total_cmp(&size[i]));
    order.truncate(count);
    order
}
