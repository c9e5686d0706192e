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
//! `σ_min` taken less `1e-12 σ_max` (the SVD's rounding). When `A` has
//! dependent columns (no `σ_min` above that) no bound can be proven loose and
//! all are kept.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

/// Bounds (scaled) at most this large are kept without the test: a correction
/// of a well-conditioned job is of order 1 in the scaled units, and the test's
/// SVD is then not worth its cost.
const TESTED_ABOVE: f64 = 1e6;

/// `bounds` (`(column, bound on |y_column|)`) without those that cannot bind.
pub(super) fn drop_loose(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: Vec<(usize, f64)>,
) -> Vec<(usize, f64)> {
    if bounds.iter().all(|&(_, m)| m <= TESTED_ABOVE) || a.nrows() < a.ncols() {
        return bounds;
    }
    let sv = a.clone().singular_values();
    // A lower bound on the true σ_min: the SVD's error is a few ε·σ_max.
    let sigma_min = sv.min() - 1e-12 * sv.max();
    let b_max = b.iter().map(|z| z.norm()).fold(0.0, f64::max);
    let y = (b.norm() + (a.nrows() as f64).sqrt() * b_max) / sigma_min;
    if !(y.is_finite() && sigma_min > 0.0) {
        return bounds;
    }
    bounds
        .into_iter()
        .filter(|&(_, m)| m <= TESTED_ABOVE || m <= 2.0 * y)
        .collect()
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
        // Dependent columns: nothing can be proven, everything is kept.
        let mut dep = a.clone();
        let col = dep.column(0).clone_owned();
        dep.set_column(1, &col);
        assert_eq!(drop_loose(&dep, &b, vec![(0, 1e300)]), vec![(0, 1e300)]);
    }
}
