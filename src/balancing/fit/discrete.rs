//! `discrete: true` in a solve: each solved plane's candidates from its kit,
//! the joint exact search, and the `fit`/`fit_summary` of the solution.

use std::time::Duration;

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::candidates::{count_loadings, loads, plane_candidates, PlaneCandidates, MAX_CANDIDATES};
use super::places::{place_angles_deg, DEFAULT_MAX_PLACES};
use super::search::{search, Problem, NODE_LIMIT};
use crate::balancing::error::InputError;
use crate::balancing::model::{Session, SolveOptions};
use crate::balancing::phasor::weight_in;
use crate::balancing::solution::{FitPlane, FitSummary, FitWeight, Solution, Warning};
use crate::balancing::solve::Fit;

/// Default time bound of the search.
pub const DEFAULT_TIME_LIMIT_MS: u64 = 1000;
const MAX_TIME_LIMIT_MS: u64 = 60_000;

/// The search's time bound from `fit_time_limit_ms`, checked.
pub fn time_limit(options: &SolveOptions) -> Result<Duration, InputError> {
    let ms = options.fit_time_limit_ms.unwrap_or(DEFAULT_TIME_LIMIT_MS);
    if !(1..=MAX_TIME_LIMIT_MS).contains(&ms) {
        return Err(InputError::invalid(
            "invalid_value",
            "options.fit_time_limit_ms",
            format!("the fit's time bound is 1 to {MAX_TIME_LIMIT_MS} ms, got {ms}"),
        ));
    }
    Ok(Duration::from_millis(ms))
}

/// The candidates of plane `j` of the session, its places' angles in the
/// session's direction, given its `max_mass_g`.
pub fn candidates_of(
    session: &Session,
    j: usize,
    mass_bound: Option<f64>,
) -> Result<(PlaneCandidates, Vec<f64>), InputError> {
    let plane = &session.planes[j];
    let conv = session.conventions.unwrap_or_default();
    let (Some(kit), Some(angles)) = (&plane.kit, place_angles_deg(plane)) else {
        return Err(InputError::invalid(
            "no_kit",
            "options.discrete",
            format!(
                "plane {} has no kit (and fixed places): a discrete fit needs planes[].kit and positions or places_deg on every plane solved",
                plane.id
            ),
        ));
    };
    let max_places = kit.max_places.unwrap_or(DEFAULT_MAX_PLACES);
    let l = loads(&kit.masses_g, kit.max_per_place);
    let n = count_loadings(angles.len(), l.len(), max_places);
    if n > MAX_CANDIDATES as f64 {
        return Err(InputError::invalid(
            "fit_too_large",
            format!("planes[{j}].kit"),
            format!(
                "plane {}: {} places × {} distinct stacks over up to {max_places} places make {n:.0} loadings, more than the {MAX_CANDIDATES} a fit may search: use fewer sizes, fewer stacked weights or fewer places per fit",
                plane.id, angles.len(), l.len()
            ),
        ));
    }
    let units: Vec<Complex64> = angles.iter().map(|&a| weight_in(conv, 1.0, a)).collect();
    Ok((plane_candidates(&units, l, max_places, mass_bound), angles))
}

/// The candidate nearest to `c` (the solve's continuous correction): the
/// rounding that starts the search.
fn nearest(c: &PlaneCandidates, target: Complex64) -> usize {
    (0..c.candidates.len())
        .min_by(|&a, &b| {
            let da = (c.candidates[a].sum - target).norm_sqr();
            let db = (c.candidates[b].sum - target).norm_sqr();
            da.total_cmp(&db)
        })
        .unwrap_or(0)
}

fn weights_of(c: &PlaneCandidates, k: usize, angles: &[f64]) -> Vec<FitWeight> {
    let cand = &c.candidates[k];
    let mut out = Vec::new();
    for &(place, load) in &cand.parts[..usize::from(cand.used)] {
        for &mass_g in &c.loads[usize::from(load)].weights {
            out.push(FitWeight {
                place: u32::from(place),
                angle_deg: angles[usize::from(place)],
                mass_g,
            });
        }
    }
    out.sort_by_key(|w| w.place);
    out
}

/// Add `fit` and `fit_summary` when `options.discrete` is true.
pub fn fill(
    fit: &Fit,
    options: &SolveOptions,
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    solution: &mut Solution,
) -> Result<(), InputError> {
    let limit = time_limit(options)?;
    if options.discrete != Some(true) {
        return Ok(());
    }
    let session = fit.checked.session;
    let bounds = options.max_mass_g.as_ref();
    let mut planes = Vec::with_capacity(fit.planes.len());
    for &j in &fit.planes {
        let bound = bounds.and_then(|m| m.get(&session.planes[j].id).copied());
        planes.push(candidates_of(session, j, bound)?);
    }
    let start: Vec<usize> = planes
        .iter()
        .zip(fit.c.iter())
        .map(|((c, _), &target)| nearest(c, target))
        .collect();
    let problem = Problem {
        a,
        b,
        sums: planes
            .iter()
            .map(|(c, _)| c.candidates.iter().map(|k| k.sum).collect())
            .collect(),
        objective: options.objective.unwrap_or_default(),
        time_limit: limit,
        node_limit: NODE_LIMIT,
    };
    let found = search(&problem, start);

    let s = DVector::from_fn(fit.planes.len(), |k, _| problem.sums[k][found.choice[k]]);
    let w_used = DMatrix::from_fn(fit.w.nrows(), fit.planes.len(), |i, k| {
        fit.w[(i, fit.planes[k])]
    });
    let residual = fit.checked.y.column(0) + &w_used * s;
    let rows = &fit.selection.rows;
    let n = rows.len().max(1) as f64;
    let rms_after = (rows.iter().map(|&i| residual[i].norm_sqr()).sum::<f64>() / n).sqrt();
    let max_after = rows.iter().map(|&i| residual[i].norm()).fold(0.0, f64::max);

    solution.fit = Some(
        fit.planes
            .iter()
            .zip(&planes)
            .zip(&found.choice)
            .map(|((&j, (c, angles)), &k)| FitPlane {
                plane: session.planes[j].id.clone(),
                weights: weights_of(c, k, angles),
            })
            .collect(),
    );
    solution.fit_summary = Some(FitSummary {
        rms_after,
        max_after,
        optimal: found.optimal,
    });
    if !found.optimal {
        solution.warnings.push(Warning {
            code: "fit_not_proven".to_string(),
            message: format!(
                "the search for the best kit weights stopped at its bound ({} ms, or {} candidates looked at) before it could prove the fit the best: it is the best found; allow more time with fit_time_limit_ms, or use fewer sizes or places per fit",
                limit.as_millis(),
                found.nodes
            ),
            plane: None,
        });
    }
    Ok(())
}
