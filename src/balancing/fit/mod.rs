//! Weights a fitter can bolt on (v2 "Weights that can be fitted"): fixed
//! places and kits per plane, the exact joint discrete fit (`discrete: true`),
//! the static/couple parts of a two-plane correction, and trial-weight
//! suggestions.
//!
//! The discrete fit chooses, for every plane solved, a loading of its places
//! with whole kit weights so that the solve's own objective — the weighted sum
//! of squares (3.3), or the largest weighted residual with `min_max` (4.1) —
//! on the vibration those exact weights leave, `R = Y0 + W·(Σ weights)` (3.1),
//! is least over all planes *jointly*. `candidates` lists each plane's
//! distinct vector sums; `search` is the exact branch-and-bound over them (its
//! module doc proves the bound); `discrete` wires both into a solve.

pub mod candidates;
pub mod discrete;
pub mod places;
pub mod search;
pub mod static_couple;
pub mod trial;

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::error::InputError;
use super::model::SolveOptions;
use super::solution::Solution;
use super::solve::Fit;

/// Add the fit's parts to a solution: `static_couple` for two planes, and
/// `fit`/`fit_summary` when `options.discrete` asks. `a`, `b` are the weighted
/// problem (3.3) that was solved.
pub fn fill(
    fit: &Fit,
    options: &SolveOptions,
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    solution: &mut Solution,
) -> Result<(), InputError> {
    solution.static_couple = static_couple::of(fit);
    discrete::fill(fit, options, a, b, solution)
}
