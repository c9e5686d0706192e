//! Among equally good corrections, the one of least mass: min-max, and
//! least squares under a binding bound (session 20; below).
//!
//! When planes are dependent (the sensors see two trial weights alike) the
//! min-max optimum is not a point but a set: moving mass between the
//! dependent planes changes no reading. Which point the interior point
//! returns is an accident of its path: with two planes of identical
//! influence the job without a bound gave 10.69 g / 10.69 g, the same job
//! with a `max_mass_g` of 1e7 g on one plane (a bound the solver keeps)
//! 0.43 g / 21.1 g, the same peak (session 16). A technician expects the
//! least-mass answer, the one least squares gives through its pseudo-inverse
//! (method 3.2). So where some plane is undetermined or nearly so, a second
//! program moves the first answer `y₁` only along the combinations of planes
//! the sensors (nearly) do not see, `y = y₁ + V z` (`V`: the right singular
//! vectors of the column-scaled `A` whose singular value is at most
//! 1/[`NEARLY_DEPENDENT`] of the largest), to the least total squared mass:
//!
//! `min_z Σ_j |x_j|²  subject to  |r_a| ≤ t₁ + ε (t₁ + max_a |b_a|)` on
//! every row and `|x_j| ≤ max_mass_g` on every bound that can bind,
//!
//! a least-norm objective over second-order cones, solved by Clarabel
//! (`program::least_norm_capped`) on all rows with `2k` real unknowns for
//! `k` lost combinations. The determined part of the correction is the
//! first solve's. (A cap alone, over all directions, let the pull toward
//! least mass move the determined sum by more than 10⁻⁶ of it in the unit
//! tests below: at a min-max optimum the peak can be flat to first order
//! along a direction the sensors see.)
//!
//! - `ε` = [`SLACK`] = 1e-8, the peak's room: along exactly lost
//!   combinations the residuals do not move at all; along nearly lost ones
//!   (relative singular value `σ ≤ 10⁻⁶`) they move by `σ |z|`, and the cap
//!   lets the correction go toward least mass as far as the peak stays within
//!   2·10⁻⁸ of the as-found maximum above `t₁` (`t₁ ≤ max_a |b_a|`): a
//!   hundred times the first solve's accuracy (relative gap 1e-10,
//!   `program.rs`), far below any reading's precision.
//! - When: the scaled condition number (columns at unit norm) of the solve's
//!   `A` at or above [`NEARLY_DEPENDENT`] = 1e6 (`wiring`, from the solve's
//!   one factorisation, so other jobs cost nothing extra). Along a
//!   combination of relative singular value `σ` the peak changes by `σ` per
//!   unit of `y`, so the first answer is fixed there only to about its
//!   accuracy over `σ`: at `σ ≤ 10⁻⁶` that reaches 10⁻⁴ of the correction's
//!   scale, a visible share of a mass in grams.
//! - Bounds: a bound above `√2` times the first answer's whole mass put in
//!   plane `k` (`√(Σ_j w_j |y₁_j|² / w_k)`, `w_j ∝ d_j²`) cannot bind at an
//!   answer of no more mass and is left out, so a huge `max_mass_g` never
//!   reaches Clarabel (`loose`).
//! - The second answer is taken only when its peak is within twice the room
//!   of `t₁` (Clarabel meets a cap to its feasibility tolerance), it keeps
//!   every bound and has no more mass than the first; else, or when Clarabel
//!   fails, the first answer stands: the choice among optima never costs the
//!   job its answer.
//!
//! Least squares under a bound (session 20): unbounded, it takes the
//! pseudo-inverse's least-norm answer and never comes here; with a bound
//! that the least-norm answer breaks it is a cone program, whose answer on
//! two identical planes was any split of the sum that kept the bound (the
//! pump's planes with a bound of a quarter of the sum on the inboard one:
//! 5·10⁻⁸ g / 21.6 g). The same second program moves it to the least-mass
//! split, with one cap on the residual's 2-norm instead of one per row,
//! `‖r‖₂ ≤ ‖r₁‖₂ + ε (‖r₁‖₂ + ‖b‖₂)`: the bounded plane at its bound in the
//! sum's direction, the other plane the rest (5.41 g / 16.22 g).
//!
//! Measured (tests/solve/minmax/dependent.rs): the pump with identical
//! planes and a 1e7 g bound now gives 10.692479 g / 10.692479 g (was
//! 0.433 g / 21.124 g), the unbounded job 10.692491 g each, peaks 8e-11
//! apart relative. Cost (a throwaway example, release build, this machine,
//! 5 runs each; a job of `benches/support/conic_jobs.rs` with its last
//! plane 2i times its first and a 1e7 g bound on the first): 1,000 × 16
//! 45.5 ms without the second program, 46.5 ms with it; 11 × 4 0.34 ms and
//! 0.33 ms. With the last plane off by 1e-8 relative (11 × 4) the first
//! answer had `‖x‖₂` = 43.2 g, the second 21.06 g, the exact case's least
//! mass, its peak 3.6e-9 higher relative.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::{program, Limits};
use crate::balancing::model::Objective;

/// Scaled condition number at and above which min-max looks for the
/// least-mass optimum, and the inverse of the relative singular value at
/// and below which a combination of planes counts as lost (module docs).
pub const NEARLY_DEPENDENT: f64 = 1e6;

/// Relative room above the first optimum's peak (module docs).
const SLACK: f64 = 1e-8;

/// Clarabel's feasibility tolerance (`program.rs`), scaled units: the
/// overshoot of a bound that still counts as keeping it.
const FEAS: f64 = 1e-10;

/// A cone solve's answer: `y`, iterations, status.
type Solved = (Vec<Complex64>, u32, String);

/// The least-mass optimum near `first`, the scaled min-max answer of `a`, `b`
/// under `bounds`; `d[k]` is column `k`'s scale (`x_k = β d_k y_k`), so the
/// mass in grams² is `β² Σ_k d_k² |y_k|²`.
pub(super) fn refine(
    objective: Objective,
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    d: &[f64],
    first: Solved,
    limits: Limits,
) -> Solved {
    let (rows, n) = a.shape();
    let lost = lost_combinations(a);
    if lost.ncols() == 0 {
        return first;
    }
    let y1 = DVector::from_column_slice(&first.0);
    let r1 = b + a * &y1;
    // The objective: the peak (min-max) or the 2-norm (least squares).
    let peak = |r: &DVector<Complex64>| match objective {
        Objective::MinMax => r.iter().map(|z| z.norm()).fold(0.0, f64::max),
        Objective::LeastSquares => r.norm(),
    };
    let b_max = peak(b);
    let t1 = peak(&r1);
    let room = SLACK * (t1 + b_max);
    let top = d.iter().copied().fold(0.0, f64::max);
    let w: Vec<f64> = d.iter().map(|&dk| (dk / top).powi(2)).collect();
    let mass =
        |y: &DVector<Complex64>| -> f64 { y.iter().zip(&w).map(|(z, wk)| wk * z.norm_sqr()).sum() };
    let mass1 = mass(&y1);
    // The objective ½ Σ_k w_k |y₁_k + (V z)_k|² as ½‖c + M z‖².
    let sqrt_w = DVector::from_iterator(n, w.iter().map(|wk| Complex64::from(wk.sqrt())));
    let m = DMatrix::from_fn(n, lost.ncols(), |k, i| lost[(k, i)] * sqrt_w[k]);
    let c = y1.component_mul(&sqrt_w);
    // An answer of no more mass has `|V z| ≤ |y₂| + |y₁| ≤ 2 √(mass₁ / min w)`:
    // rows it cannot lift to the cap, and bounds it cannot reach, are left out
    // (along exactly lost combinations that is every row: their coefficients
    // are rounding, which Clarabel's equilibration blew up, InsufficientProgress).
    let reach = 2.0 * (mass1 / w.iter().copied().fold(f64::INFINITY, f64::min)).sqrt();
    let cap = t1 + room;
    let av = a * &lost;
    // Min-max caps every row it can move; least squares caps the residual's
    // norm, one cone over all rows, when the move can reach it.
    let moving: Vec<usize> = match objective {
        Objective::MinMax => (0..rows)
            .filter(|&i| r1[i].norm() + av.row(i).norm() * reach > cap)
            .collect(),
        Objective::LeastSquares => Vec::new(),
    };
    let whole = (objective == Objective::LeastSquares && t1 + av.norm() * reach > cap)
        .then_some((&av, &r1, cap));
    let binding: Vec<(usize, f64)> = bounds
        .iter()
        .copied()
        .filter(|&(k, mk)| y1[k].norm() + lost.row(k).norm() * reach > mk)
        .collect();
    // Rows: the peak where it can move, then the bounds that can bind.
    let capped = moving.len() + binding.len();
    let ac = DMatrix::from_fn(capped, lost.ncols(), |i, j| match moving.get(i) {
        Some(&row) => av[(row, j)],
        None => lost[(binding[i - moving.len()].0, j)],
    });
    let bc = DVector::from_fn(capped, |i, _| match moving.get(i) {
        Some(&row) => r1[row],
        None => y1[binding[i - moving.len()].0],
    });
    let caps: Vec<f64> = (0..capped)
        .map(|i| {
            moving
                .get(i)
                .map_or_else(|| binding[i - moving.len()].1, |_| cap)
        })
        .collect();
    let Ok((z, iterations, status)) =
        program::least_norm_capped(&m, &c, &ac, &bc, &caps, whole, limits)
    else {
        return first;
    };
    let y2 = &y1 + &lost * DVector::from_column_slice(&z);
    let keeps = peak(&(b + a * &y2)) <= t1 + 2.0 * room
        && bounds
            .iter()
            .all(|&(k, mk)| y2[k].norm() <= mk * (1.0 + FEAS) + FEAS)
        && mass(&y2) <= mass1;
    if keeps {
        (y2.iter().copied().collect(), first.1 + iterations, status)
    } else {
        first
    }
}

/// The right singular vectors of `a` (columns at unit norm) whose singular
/// value is at most `1/NEARLY_DEPENDENT` of the largest, as columns: the
/// combinations of columns the rows (nearly) do not see. A matrix of fewer
/// rows than columns is padded with zero rows, so its null space is counted.
fn lost_combinations(a: &DMatrix<Complex64>) -> DMatrix<Complex64> {
    let (rows, n) = a.shape();
    let square = if rows < n {
        a.clone().resize_vertically(n, Complex64::new(0.0, 0.0))
    } else {
        a.clone()
    };
    let svd = square.svd(false, true);
    let v_t = svd.v_t.expect("SVD computed with Vᴴ");
    let top = svd.singular_values.max();
    let lost: Vec<usize> = (0..svd.singular_values.len())
        .filter(|&i| svd.singular_values[i] <= top / NEARLY_DEPENDENT)
        .collect();
    DMatrix::from_fn(n, lost.len(), |k, i| v_t[(lost[i], k)].conj())
}

#[cfg(test)]
mod tests {
    use crate::balancing::conic::{objective_value, solve_cone, solve_cone_conditioned};
    use crate::balancing::model::Objective;
    use nalgebra::{DMatrix, DVector};
    use num_complex::Complex64;

    fn c(re: f64, im: f64) -> Complex64 {
        Complex64::new(re, im)
    }

    /// Five sensors, two planes the sensors see identically.
    fn dependent() -> (DMatrix<Complex64>, DVector<Complex64>) {
        let col = [
            c(3.1, 1.2),
            c(-1.5, 2.2),
            c(0.8, 0.1),
            c(0.2, 0.6),
            c(-0.7, -1.9),
        ];
        let a = DMatrix::from_fn(5, 2, |i, _| col[i]);
        let b = DVector::from_row_slice(&[
            c(465.0, 28.0),
            c(-173.0, 66.0),
            c(377.0, -214.0),
            c(-90.0, 301.0),
            c(120.0, 45.0),
        ]);
        (a, b)
    }

    #[test]
    fn identical_planes_share_the_correction_equally_whatever_the_bounds() {
        let (a, b) = dependent();
        let free = solve_cone(&a, &b, Objective::MinMax, &[None, None]).unwrap();
        let sum = free.x[0] + free.x[1];
        for bounds in [[Some(1e5), None], [None, Some(1e5)], [Some(1e5), Some(1e5)]] {
            let got = solve_cone_conditioned(1e16, &a, &b, Objective::MinMax, &bounds).unwrap();
            // The same peak (at most 4e-8 of max|b| above, ~6e-8 of the peak) ...
            assert!(got.value <= free.value * (1.0 + 1e-7), "{bounds:?}");
            // ... and the least-mass split, half each, of the same sum: to
            // 1e-9 (the peak can be flat to second order there, so the
            // solvers' relative gap of 1e-10 fixed the sum only to ~√1e-10,
            // 2.7e-6 apart, 1.75e-5 with a binding bound, until the polish
            // of session 20, `polish.rs`).
            let half = (got.x[0] + got.x[1]) / 2.0;
            assert!((half * 2.0 - sum).norm() <= 1e-9 * sum.norm(), "{bounds:?}");
            assert!((got.x[0] - half).norm() <= 1e-8 * sum.norm(), "{}", got.x);
            assert!(!got.bound_active.iter().any(|&b| b));
        }
    }

    #[test]
    fn a_binding_bound_takes_what_it_can_and_the_other_plane_the_rest() {
        // Bound plane 0 at a quarter of the sum: the peak is still reachable
        // (plane 1 takes three quarters), and that is the least-mass split.
        let (a, b) = dependent();
        let free = solve_cone(&a, &b, Objective::MinMax, &[None, None]).unwrap();
        let sum = free.x[0] + free.x[1];
        let m = sum.norm() / 4.0;
        let got =
            solve_cone_conditioned(1e16, &a, &b, Objective::MinMax, &[Some(m), None]).unwrap();
        let peak = objective_value(&a, &b, &got.x, Objective::MinMax);
        assert!(
            peak <= free.value * (1.0 + 1e-7),
            "{peak} vs {}",
            free.value
        );
        // The sum to 1e-9 (polished, above); the
        // bounded plane at its bound in the sum's direction.
        let got_sum = got.x[0] + got.x[1];
        assert!((got_sum - sum).norm() <= 1e-9 * sum.norm(), "{}", got.x);
        let at_bound = got_sum * (m / got_sum.norm());
        assert!(
            (got.x[0] - at_bound).norm() <= 1e-8 * sum.norm(),
            "{}",
            got.x
        );
        assert_eq!(got.bound_active, vec![true, false]);
    }
}
