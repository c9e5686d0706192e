//! From a fit in the internal frame to the contract's solution, in the
//! session's conventions: corrections, residuals, coefficients, diagnostics.

use crate::balancing::diagnostics::{
    trial_effect_ratio, SIGNIFICANCE_THRESHOLD, TRIAL_EFFECT_THRESHOLD,
};
use crate::balancing::model::{Objective, SolveOptions};
use crate::balancing::phasor::{modulus, reading_out, weight_out};
use crate::balancing::practical::{grade_value, permissible_unbalance_gmm, split_places};
use crate::balancing::solution::{
    Correction, InfluenceCoefficient, IsoTolerance, PlaneDiagnostics, Residual, Solution, Summary,
    Warning,
};
use crate::balancing::solve::shared_id::SharedId;
use crate::balancing::solve::Fit;

fn warning(code: &str, plane: Option<&str>, message: String) -> Warning {
    Warning {
        code: code.to_string(),
        message,
        plane: plane.map(str::to_string),
    }
}

/// RMS and maximum of the amplitudes `f(a)` over `rows`.
fn rms_max(rows: &[usize], f: impl Fn(usize) -> f64) -> (f64, f64) {
    let n = rows.len().max(1) as f64;
    let sq: f64 = rows.iter().map(|&a| f(a).powi(2)).sum();
    let max = rows.iter().map(|&a| f(a)).fold(0.0, f64::max);
    ((sq / n).sqrt(), max)
}

fn corrections(fit: &Fit, warnings: &mut Vec<Warning>) -> Vec<Correction> {
    let session = fit.checked.session;
    let conv = fit.checked.conventions;
    fit.planes
        .iter()
        .zip(fit.c.iter())
        .map(|(&j, &c)| {
            let plane = &session.planes[j];
            let (mass_g, angle_deg) = weight_out(conv, c);
            let places = crate::balancing::fit::places::place_angles_deg(plane);
            let split = places.map(|places| {
                let (parts, exact) = split_places(mass_g, angle_deg, &places);
                if !exact {
                    warnings.push(warning(
                        "split_approximate",
                        Some(&plane.id),
                        format!(
                            "plane {} has no two places less than 180° apart round the correction's angle (2 opposite places, or a wide gap): the weight can go only along the nearer place, so part of the correction cannot be fitted; fit it at its exact angle if the plane allows",
                            plane.id
                        ),
                    ));
                }
                parts
            });
            Correction {
                plane: plane.id.clone(),
                mass_g,
                angle_deg,
                unbalance_gmm: plane.radius_mm.map(|r| mass_g * r),
                split,
                uncertainty: None,
                total: None,
            }
        })
        .collect()
}

fn diagnostics(fit: &Fit, warnings: &mut Vec<Warning>) -> Vec<PlaneDiagnostics> {
    let session = fit.checked.session;
    let y0_abs: Vec<f64> = fit
        .checked
        .y
        .column(0)
        .iter()
        .map(|&y| modulus(y))
        .collect();
    fit.selection
        .planes
        .iter()
        .zip(&fit.factors)
        .map(|(&j, &factor)| {
            let id = &session.planes[j].id;
            let ratio = trial_effect_ratio(&fit.w, &y0_abs, &fit.checked.t, j, &fit.selection.rows);
            let dropped = fit.dropped.contains(&j);
            if ratio < TRIAL_EFFECT_THRESHOLD {
                let more = if ratio > 0.0 { format!(" (about {:.1} times the mass)", TRIAL_EFFECT_THRESHOLD / ratio) } else { String::new() };
                warnings.push(warning(
                    "trial_effect_small",
                    Some(id),
                    format!(
                        "the trial weight in plane {id} changed the vibration by at most {:.0} % of the reference amplitude; field practice asks for 30 %. Its influence coefficients are mostly measurement noise: repeat the trial run with a heavier trial weight{more}, or at a larger radius",
                        100.0 * ratio
                    ),
                ));
            }
            if factor < SIGNIFICANCE_THRESHOLD && !dropped {
                warnings.push(warning(
                    "ill_conditioned",
                    Some(id),
                    format!(
                        "plane {id} acts on the sensors almost like a combination of the other planes (significance factor {factor:.2}, below {SIGNIFICANCE_THRESHOLD}): the corrections may come out large and cancelling. Solve without this plane (drop_dependent_planes), or use a plane farther away or another sensor or speed that tells them apart"
                    ),
                ));
            }
            PlaneDiagnostics { plane: id.clone(), significance_factor: factor, trial_effect_ratio: ratio, trial_effect_snr: None, dropped }
        })
        .collect()
}

fn iso(fit: &Fit, corrections: &[Correction]) -> Option<IsoTolerance> {
    let rotor = fit.checked.session.rotor.as_ref()?;
    let g = grade_value(&rotor.balance_grade)?;
    let u_per = permissible_unbalance_gmm(g, rotor.mass_kg, rotor.service_speed_rpm);
    let per_plane = u_per / corrections.len().max(1) as f64;
    let as_found: Option<Vec<f64>> = corrections.iter().map(|c| c.unbalance_gmm).collect();
    let within = as_found.as_ref().map(|u| u.iter().all(|&x| x <= per_plane));
    Some(IsoTolerance {
        balance_grade: rotor.balance_grade.clone(),
        permissible_residual_unbalance_gmm: u_per,
        permissible_per_plane_gmm: per_plane,
        as_found_unbalance_gmm: as_found,
        as_found_within_tolerance: within,
        planes: None,
        pass: None,
        after_correction_pass: None,
    })
}

/// The solution for `fit`.
pub fn solution(fit: &Fit, options: &SolveOptions) -> Solution {
    let checked = &fit.checked;
    let session = checked.session;
    let conv = checked.conventions;
    let mut warnings = Vec::new();
    let corrections = corrections(fit, &mut warnings);
    let planes = diagnostics(fit, &mut warnings);

    let mut used = vec![false; checked.rows.len()];
    for &a in &fit.selection.rows {
        used[a] = true;
    }
    let predicted_residual = checked
        .rows
        .iter()
        .enumerate()
        .map(|(a, row)| {
            let (amplitude, phase_deg) = reading_out(conv, fit.residual[a]);
            let sensor = &session.sensors[row.sensor];
            Residual {
                speed_rpm: row.speed_rpm,
                sensor: sensor.id.clone(),
                unit: sensor.unit,
                amplitude_before: modulus(checked.y[(a, 0)]),
                amplitude,
                phase_deg,
                amplitude_95: None,
                used: used[a],
            }
        })
        .collect();

    let mut influence_coefficients = Vec::with_capacity(checked.rows.len() * session.planes.len());
    // Each id once, shared by its coefficients (issue 15).
    let sensor_ids: Vec<SharedId> = session
        .sensors
        .iter()
        .map(|s| SharedId::from(s.id.as_str()))
        .collect();
    let plane_ids: Vec<SharedId> = session
        .planes
        .iter()
        .map(|p| SharedId::from(p.id.as_str()))
        .collect();
    for (a, row) in checked.rows.iter().enumerate() {
        for (j, plane) in plane_ids.iter().enumerate() {
            // 1 g at angle 0 is the internal weight 1 in either angle direction.
            let (amplitude_per_g, phase_deg) = reading_out(conv, fit.w[(a, j)]);
            influence_coefficients.push(InfluenceCoefficient {
                speed_rpm: row.speed_rpm,
                sensor: sensor_ids[row.sensor].clone(),
                plane: plane.clone(),
                amplitude_per_g,
                phase_deg,
            });
        }
    }

    let rows = &fit.selection.rows;
    let (rms_before, max_before) = rms_max(rows, |a| modulus(checked.y[(a, 0)]));
    let (rms_after, max_after) = rms_max(rows, |a| modulus(fit.residual[a]));

    // One unit or several: compared, not formatted per row (issue 15).
    let unit_of = |a: usize| session.sensors[checked.rows[a].sensor].unit;
    let mixed = rows.iter().any(|&a| unit_of(a) != unit_of(rows[0]));
    if mixed {
        warnings.push(warning(
            "mixed_units",
            None,
            "the selected sensors measure in different units, and least squares adds their amplitudes as they are: give row_weights that make them comparable, or select sensors of one unit".to_string(),
        ));
    }

    Solution {
        iso_21940: iso(fit, &corrections),
        corrections,
        predicted_residual,
        influence_coefficients,
        summary: Summary {
            rms_before,
            rms_after,
            max_before,
            max_after,
        },
        condition_number: fit.factor.condition_number(),
        warnings,
        conventions: conv,
        objective: options.objective.unwrap_or(Objective::LeastSquares),
        planes,
        dropped_planes: fit
            .dropped
            .iter()
            .map(|&j| session.planes[j].id.clone())
            .collect(),
        runout: None,
        from_run: None,
        run_checks: None,
        coefficients_from: None,
        fit: None,
        fit_summary: None,
        static_couple: None,
    }
}
