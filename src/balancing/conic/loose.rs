//! Mass bounds that cannot bind, left out of the cone program.
//!
//! A bound far beyond any correction the problem can want (`max_mass_g` of
//! 1e50 to 1e300 g, "no bound" in practice) made Clarabel stop with
//! `InsufficientProgress`, a 422 `solver_failed` that named no field
//! (fuzzing, session 15): the interior point starts its slacks at the scale of
//! the bound. Such a bound can be dropped without changing the optimum.
//!
//! In the scaled problem `r = b + A y` of [`super::solve_cone`] (`m` rows),
//! `y = 0` keeps every bound, so any optimum of either objective is no worse
//! than `y = 0`: `‖r‖₂ ≤ ‖b‖₂` (least squares) or `max|r_a| ≤ max|b_a|`
//! (min-max, so `‖r‖₂ ≤ √m · max|b_a|`). Then
//! `σ_min(A) ‖y‖₂ ≤ ‖A y‖₂ ≤ ‖r‖₂ + ‖b‖₂`, hence for both objectives
//!
//! `|y_j| ≤ ‖y‖₂ ≤ Y = (‖b‖₂ + √m · max_a |b_a|) / σ_min(A)`.
//!
//! An optimum of the problem without a bound above `Y` keeps that bound, so it
//! is an optimum of the problem with it. Bounds above `2Y` are dropped, with
//! `σ_min` taken less `1e-12 σ_max` (the SVD's rounding).
//!
//! Dependent columns (planes the sensors cannot tell apart, singular values
//! at most `2e-12 σ_max`; session 16): the residual does not see `y`'s part in
//! `A`'s null space, so the optimum with none (the least-norm one) has
//! `‖y‖₂ ≤ Y⁺`, the same `Y` with the smallest singular value above that
//! rounding level: it keeps every bound above `Y⁺`. But the solver may return
//! another optimum, one with a null-space part; and near-dependent columns are
//! not exactly blind. So the answer of the program without the dropped bounds
//! is checked against each of them ([`solve`]): kept, it is feasible and optimal
//! for the program with them; broken, the program is solved with every bound.
//! With exactly dependent planes and a bound of 1e40 g Clarabel used to stop
//! with `InsufficientProgress` (min-max; least squares answers from the SVD
//! when the bound holds); now the answer is the one without the bound.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use crate::balancing::error::InputError;

/// Bounds (scaled) at most this large are kept without the test: a correction
/// of a well-conditioned job is of order 1 in the scaled units, and the test's
/// SVD is then not worth its cost.
const TESTED_ABOVE: f64 = 1e6;

/// Singular values at most this fraction of the largest are rounding: their
/// directions are dependent columns.
const DEPENDENT: f64 = 2e-12;

/// A cone solve's answer: `y`, iterations, status.
type Solved = (Vec<Complex64>, u32, String);

/// `bounds` (`(column, bound on |y_column|)`) without those that cannot bind
/// at the least-norm optimum (every optimum when `A`'s columns are independent).
pub(super) fn drop_loose(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: Vec<(usize, f64)>,
) -> Vec<(usize, f64)> {
    if bounds.iter().all(|&(_, m)| m <= TESTED_ABOVE) {
        return bounds;
    }
    let sv = a.clone().singular_values();
    let top = sv.max();
    // The smallest singular value above rounding, less the SVD's error
    // (a few ε·σ_max): a lower bound on the true one.
    let smallest = sv
        .iter()
        .copied()
        .filter(|&s| s > DEPENDENT * top)
        .fold(f64::INFINITY, f64::min);
    let sigma = smallest - 1e-12 * top;
    let b_max = b.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let y = (b.norm() + (a.nrows() as f64).sqrt() * b_max) / sigma;
    if !(y.is_finite() && sigma > 0.0) {
        return bounds;
    }
    bounds
        .into_iter()
        .filter(|&(_, m)| m <= TESTED_ABOVE || m <= 2.0 * y)
        .collect()
}

/// `program` (a cone solve under the bounds it is given) without the bounds
/// that cannot bind; its answer is checked against the dropped ones, and the
/// program solved with every bound when the answer breaks one (see the module
/// docs: with dependent columns only the least-norm optimum is sure to keep them).
pub(super) fn solve(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    program: impl Fn(&[(usize, f64)]) -> Result<Solved, InputError>,
) -> Result<Solved, InputError> {
    let kept = drop_loose(a, b, bounds.to_vec());
    if kept.len() == bounds.len() {
        return program(bounds);
    }
    if let Ok(got) = program(&kept) {
        if bounds.iter().all(|&(k, m)| got.0[k].norm() <= m) {
            return Ok(got);
        }
    }
    program(bounds)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::balancing::conic::{solve_cone, ConeSolution};
    use crate::balancing::model::Objective;

    fn c(re: f64, im: f64) -> Complex64 {
        Complex64::new(re, im)
    }

    /// The two-plane pump of the examples in miniature: four sensors, two
    /// planes of different effect, amplitudes of a few hundred.
    fn problem() -> (DMatrix<Complex64>, DVector<Complex64>) {
        let a = DMatrix::from_row_slice(
            4,
            2,
            &[
                c(3.1, 1.2),
                c(0.4, -0.9),
                c(-1.5, 2.2),
                c(1.1, 0.3),
                c(0.8, 0.1),
                c(2.9, -1.7),
                c(0.2, 0.6),
                c(-2.4, -0.8),
            ],
        );
        let b = DVector::from_row_slice(&[
            c(465.0, 28.0),
            c(-173.0, 66.0),
            c(377.0, -214.0),
            c(-90.0, 301.0),
        ]);
        (a, b)
    }

    fn close(got: &ConeSolution, want: &ConeSolution) {
        let scale = want.x.norm();
        assert!(
            (&got.x - &want.x).norm() <= 1e-6 * scale,
            "{} vs {}",
            got.x,
            want.x
        );
        assert!(!got.bound_active.iter().any(|&b| b));
    }

    #[test]
    fn a_bound_far_beyond_any_correction_gives_the_unbounded_answer() {
        let (a, b) = problem();
        for objective in [Objective::MinMax, Objective::LeastSquares] {
            let free = solve_cone(&a, &b, objective, &[None, None]).unwrap();
            for m in [1e50, 1e150, 1e300, f64::MAX] {
                let got = solve_cone(&a, &b, objective, &[Some(m), None])
                    .unwrap_or_else(|e| panic!("{objective:?}, bound {m} g: {e:?}"));
                close(&got, &free);
                let both = solve_cone(&a, &b, objective, &[Some(m), Some(m)]).unwrap();
                close(&both, &free);
            }
        }
    }

    #[test]
    fn a_bound_that_may_bind_is_kept() {
        let (a, b) = problem();
        let scaled = |bounds: Vec<(usize, f64)>| drop_loose(&a, &b, bounds);
        // Below the test's threshold: kept without the SVD.
        assert_eq!(scaled(vec![(0, 5.0)]), vec![(0, 5.0)]);
        // Above 2Y for this well-conditioned A: dropped; a small one beside it kept.
        assert_eq!(scaled(vec![(0, 1e300), (1, 0.5)]), vec![(1, 0.5)]);
        // Dependent columns: the least-norm optimum keeps a bound above Y⁺.
        let mut dep = a.clone();
        let col = dep.column(0).clone_owned();
        dep.set_column(1, &col);
        assert_eq!(
            drop_loose(&dep, &b, vec![(0, 1e300), (1, 0.5)]),
            vec![(1, 0.5)]
        );
    }

    #[test]
    fn a_huge_bound_on_dependent_columns_gives_the_unbounded_answer() {
        // Clarabel stopped with InsufficientProgress on min-max (session 16).
        let (mut a, b) = problem();
        let col = a.column(0).clone_owned();
        a.set_column(1, &col);
        for objective in [Objective::MinMax, Objective::LeastSquares] {
            let free = solve_cone(&a, &b, objective, &[None, None]).unwrap();
            for m in [1e40, 1e300, f64::MAX] {
                for bounds in [[Some(m), None], [Some(m), Some(m)]] {
                    let got = solve_cone(&a, &b, objective, &bounds)
                        .unwrap_or_else(|e| panic!("{objective:?}, {bounds:?}: {e:?}"));
                    close(&got, &free);
                }
            }
        }
    }

    #[test]
    fn an_answer_that_breaks_a_dropped_bound_is_solved_again_with_every_bound() {
        let (mut a, b) = problem();
        let col = a.column(0).clone_owned();
        a.set_column(1, &col);
        let bounds = [(0, 1e300), (1, 1e9)];
        let calls = std::cell::RefCell::new(Vec::new());
        // A program that answers with a large part in the null space when
        // unbounded, as an interior point may.
        let program = |given: &[(usize, f64)]| {
            calls.borrow_mut().push(given.to_vec());
            let big = if given.len() == bounds.len() {
                1.0
            } else {
                1e10
            };
            Ok((vec![c(big, 0.0), c(-big, 0.0)], 1, "Solved".to_string()))
        };
        let got = solve(&a, &b, &bounds, program).unwrap();
        assert_eq!(got.0[0], c(1.0, 0.0));
        assert_eq!(*calls.borrow(), vec![vec![], bounds.to_vec()]);
        // One that keeps them is taken as it is.
        calls.borrow_mut().clear();
        let keeps = |given: &[(usize, f64)]| {
            calls.borrow_mut().push(given.to_vec());
            Ok((vec![c(2.0, 0.0), c(-2.0, 0.0)], 1, "Solved".to_string()))
        };
        assert_eq!(solve(&a, &b, &bounds, keeps).unwrap().0[0], c(2.0, 0.0));
        assert_eq!(calls.borrow().len(), 1);
    }
}
