//! The uncertainty step of a solve: checks the noise options, builds each
//! reading's covariance, propagates it, and fills the solution's `uncertainty`,
//! `amplitude_95`, `trial_effect_snr` and the noise side of `trial_effect_small`.

use nalgebra::Matrix2;
use num_complex::Complex64;

use super::{
    correction_uncertainty, reading_noise, DEFAULT_AMPLITUDE_NOISE_PCT, DEFAULT_PHASE_NOISE_DEG,
    MAX_AMPLITUDE_NOISE_PCT, MAX_PHASE_NOISE_DEG,
};
use crate::balancing::diagnostics::undetermined;
use crate::balancing::error::InputError;
use crate::balancing::model::{Objective, SolveOptions};
use crate::balancing::phasor::{modulus, reading_in, weight_out};
use crate::balancing::solution::{BiasCorrected, Correction, Solution, Warning};
use crate::balancing::solve::Fit;
use crate::balancing::validate::Checked;

/// A trial effect below this many standard deviations of its noise at every
/// used row cannot be told from noise (the complex error exceeds 3σ with
/// probability about e⁻⁹ ≈ 10⁻⁴ when isotropic).
pub const SNR_THRESHOLD: f64 = 3.0;

/// The 1X repeatability the solve assumes where a reading has no samples.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Noise {
    pub amplitude_pct: f64,
    pub phase_deg: f64,
}

fn check(
    field: &str,
    value: Option<f64>,
    default: f64,
    max: f64,
    unit: &str,
) -> Result<f64, InputError> {
    let x = value.unwrap_or(default);
    if !x.is_finite() || !(0.0..=max).contains(&x) {
        return Err(InputError::invalid(
            "invalid_value",
            field,
            format!(
                "the 1X repeatability must be a finite number from 0 to {max} {unit}, got {}",
                crate::balancing::error::shown(x)
            ),
        ));
    }
    Ok(x)
}

/// `amplitude_noise_pct` and `phase_noise_deg` with their defaults (2 %, 2°),
/// or a 422 naming the option.
pub fn noise_options(options: &SolveOptions) -> Result<Noise, InputError> {
    Ok(Noise {
        amplitude_pct: check(
            "options.amplitude_noise_pct",
            options.amplitude_noise_pct,
            DEFAULT_AMPLITUDE_NOISE_PCT,
            MAX_AMPLITUDE_NOISE_PCT,
            "%",
        )?,
        phase_deg: check(
            "options.phase_noise_deg",
            options.phase_noise_deg,
            DEFAULT_PHASE_NOISE_DEG,
            MAX_PHASE_NOISE_DEG,
            "degrees",
        )?,
    })
}

/// Covariance of every reading, `[row][run]`, internal frame.
///
/// A reading without samples has the option model alone (`reading_noise`
/// without samples is `reading_covariance`), formed straight from `y`; a
/// reading is looked up only when the job has samples at all, and its
/// samples are converted into one reused buffer (issue 15, session 9: a
/// lookup and an `Option<Vec>` per reading were 160 instructions each on the
/// 21,760 readings of a large job).
pub fn reading_covariances(checked: &Checked, noise: Noise) -> Vec<Vec<Matrix2<f64>>> {
    let conv = checked.conventions;
    let runs = checked.runs.len();
    let sampled = checked.runs.iter().any(|&i| {
        checked.session.runs[i]
            .readings
            .iter()
            .any(|r| r.samples.is_some())
    });
    let mut buf: Vec<Complex64> = Vec::new();
    (0..checked.rows.len())
        .map(|a| {
            let mut row = Vec::with_capacity(runs);
            for k in 0..runs {
                // The noise is relative to the reading as measured, not as
                // compensated for runout (a reading that is all runout is
                // no more precise than any other).
                let y = checked.measured(a, k);
                let samples = if sampled {
                    checked.reading(a, k).samples.as_ref()
                } else {
                    None
                };
                row.push(match samples {
                    Some(s) => {
                        buf.clear();
                        buf.extend(s.iter().map(|x| reading_in(conv, x.amplitude, x.phase_deg)));
                        reading_noise(y, Some(&buf), noise.amplitude_pct, noise.phase_deg)
                    }
                    None => super::reading_covariance(y, noise.amplitude_pct, noise.phase_deg),
                });
            }
            row
        })
        .collect()
}

/// Fill the solution's uncertainty fields from reading noise.
///
/// Min-max objective and binding mass bounds: the propagation differentiates
/// the least-squares solution (`propagate`), evaluated at the reported
/// correction. That is the sensitivity of a least-squares fit to the same rows,
/// not of the min-max or bounded solution itself (whose derivative depends on
/// which rows or bounds are active, and jumps when they change); a binding bound
/// in truth narrows the mass interval. The solution then carries the warning
/// `uncertainty_approximate` saying so.
pub fn fill(fit: &Fit, options: &SolveOptions, cov: &[Vec<Matrix2<f64>>], solution: &mut Solution) {
    let checked = &fit.checked;
    let conv = checked.conventions;
    let sel = &fit.selection;
    let problem = super::Problem {
        t: &checked.t,
        y: &checked.y,
        cov,
        used_rows: &sel.rows,
        row_weights: &sel.weights,
        used_planes: &fit.planes,
    };
    // The readings' noise is formed where the exact correction is best
    // estimated: at the errors-in-variables estimate `C*` where there is one
    // (method 8.11), whose coefficients are not attenuated.
    let known = fit.t_pinv.as_ref().map(|t_pinv| super::Known {
        t_pinv,
        w: &fit.w,
        factor: &fit.factor,
    });
    let c_star = fit.unbiased.as_ref().map(|u| &u.c);
    let prop = super::propagate(&problem, c_star.unwrap_or(&fit.c), known);

    // The region of the fitted correction where `C*` is formed (8.11).
    let biased = fit
        .unbiased
        .as_ref()
        .map(|u| super::bias::Region::new(u, &fit.c));
    let undetermined = undetermined(&fit.factor);
    let kappas = super::kappa(fit, &prop);
    // Covariances estimated from samples: Hotelling's quantile for their
    // degrees of freedom (`dof`, method 8.5).
    let prior = noise_options(options).map_or(true, |n| n.amplitude_pct > 0.0 || n.phase_deg > 0.0);
    let dofs = super::dof::degrees_of_freedom(fit, cov, prior);
    // The coefficients' energies with their noise known (hidden.rs): for the
    // regions of planes that pass `trial_effect_small` (trust.rs) and for
    // `regions_unreliable`.
    let denoised = super::hidden::denoised(fit, options, &prop, cov);
    for (col, (((((corr, &c), cc), &lost), &k), &nu)) in solution
        .corrections
        .iter_mut()
        .zip(fit.c.iter())
        .zip(&prop.correction)
        .zip(&undetermined)
        .zip(&kappas)
        .zip(&dofs)
        .enumerate()
    {
        // (8.4) and, for samples, Hotelling's widening (8.5).
        let scale = super::second_order(k) * super::dof::widening(nu);
        let mut widened = cc * scale;
        // Where the errors-in-variables estimate `C*` (8.3) is formed, the
        // correction `c` (the minimiser) errs by its bias as well as its
        // scatter: the region around `c` is its mean square error (8.11).
        if let Some(region) = &biased {
            let stretch = super::trust::selection_stretch(k, col, &prop, denoised.as_ref());
            widened = region.plane(col, &widened, stretch);
        }
        let unbiased = c_star.map(|cu| cu[col]);
        let mut u = correction_uncertainty(c, &widened, conv);
        u.bias_corrected = unbiased.map(|cu| {
            let (mass_g, angle_deg) = weight_out(conv, cu);
            BiasCorrected { mass_g, angle_deg }
        });
        if lost {
            // Any mass fits the readings as well along the undetermined
            // combination: no interval can be given (issue 12).
            u.mass_g = None;
            u.angle_deg = [0.0, 360.0];
            solution.warnings.push(undetermined_warning(corr));
        }
        corr.uncertainty = Some(u);
    }
    // The remaining vibration's bound, for the correction that is fitted:
    // its own noise at `Ĉ` (a second propagation where `C*` is formed).
    let at_fitted = c_star.map(|_| super::propagate(&problem, &fit.c, known));
    super::remaining::fitted::fill(
        fit,
        cov,
        at_fitted.as_ref().unwrap_or(&prop),
        c_star.map(|_| &prop),
        solution,
    );

    for (diag, &j) in solution.planes.iter_mut().zip(&sel.planes) {
        let tau = checked
            .t
            .row(j)
            .iter()
            .map(|x| x.norm())
            .fold(0.0, f64::max);
        // Largest effect-to-noise ratio over the used rows; none where there is no noise.
        let snr = sel
            .rows
            .iter()
            .filter(|&&a| prop.effect_sd[(a, j)] > 0.0)
            .map(|&a| modulus(fit.w[(a, j)]) * tau / prop.effect_sd[(a, j)])
            .reduce(f64::max);
        diag.trial_effect_snr = snr;
        let Some(snr) = snr.filter(|&s| s < SNR_THRESHOLD) else {
            continue;
        };
        let id = diag.plane.clone();
        let more = if snr > 0.0 {
            format!(" (about {:.1} times the mass)", SNR_THRESHOLD / snr)
        } else {
            String::new()
        };
        let text = format!(
            "the trial weight in plane {id} changed the vibration by at most {snr:.1} times the measurement noise of that change (from the readings' repeatability: amplitude_noise_pct, phase_noise_deg, or the samples' scatter); below {SNR_THRESHOLD} times it cannot be told from noise at any sensor and speed, so the influence coefficients and the correction for this plane are unreliable: repeat the trial run with a heavier trial weight{more}, or at a larger radius"
        );
        super::trust::trial_warning(&mut solution.warnings, id, text);
    }

    // Coefficients' noise beside their signal: the trial too small to trust (issue 12).
    super::warn_untrusted(fit, &prop, &kappas, solution);
    // Nearly alike planes or a small trial beside the others: every plane's
    // region may be off (issue 12), also where only the coefficients' noise
    // makes the planes look told apart.
    let shares = denoised.as_ref().map(|d| d.shares());
    super::hidden::warn_regions_unreliable(fit, shares.as_deref(), solution);

    let min_max = options.objective == Some(Objective::MinMax);
    let bound = solution
        .warnings
        .iter()
        .any(|w| w.code == "mass_limit_active");
    if min_max || bound {
        let why = if min_max {
            "the min-max objective"
        } else {
            "a binding mass bound"
        };
        solution.warnings.push(Warning {
            code: "uncertainty_approximate".into(),
            message: format!(
                "with {why} the confidence intervals are those of a least-squares fit to the same readings, evaluated at this correction: indicative of the scatter to expect, not exact for this solution"
            ),
            plane: None,
        });
    }
}

/// The warning `plane_undetermined` for `corr`, whose uncertainty is then open.
pub(crate) fn undetermined_warning(corr: &Correction) -> Warning {
    Warning {
        code: "plane_undetermined".into(),
        message: format!(
            "the readings cannot determine the correction in plane {0}: its trial weight changed no reading, or the sensors see it exactly as a combination of other planes, so only that combination is known and the {1:.3} g shown is one of many equally good answers. Repeat the trial run in {0} with a heavier weight or at a larger radius, add a sensor or speed that sees {0} differently, or solve without it (options.planes)",
            corr.plane, corr.mass_g
        ),
        plane: Some(corr.plane.clone()),
    }
}
