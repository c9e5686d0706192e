//! The exact fits of the residual-unbalance check, their misfit test and
//! their first-order uncertainty, in the internal frame (method §1).
//!
//! A linear rotor read at one plane gives, with the trial unbalance `U_t` at
//! internal angle `φ`, `V(φ) = h·(U_r + U_t e^{iφ}) = a + c e^{iφ}` (method 2.1
//! with one plane). With phases, `a` and `c` come from complex least squares
//! through the SVD and `U_r = U_t·a/c`. Without, `|V|² = |a|² + |c|² +
//! 2|a||c| cos(φ − ψ)` is linear in `1, cos φ, sin φ`: `ψ = arg(U_r)` follows,
//! but `|a|` and `|c|` only as a pair, so `U_r = x·U_t` and `U_t/x` fit alike.

use nalgebra::{DMatrix, DVector, Matrix2, Vector2};
use num_complex::Complex64;

use super::validate::Input;
use super::{
    allowable_gmm, FitCheck, Method, ResidualCheck, ResidualRequest, ResidualUncertainty, Worksheet,
};
use crate::balancing::error::InputError;
use crate::balancing::phasor::{reading_in, weight_out, wrap_deg};
use crate::balancing::solution::Warning;
use crate::balancing::uncertainty::CHI2_2_95;

/// One fit: the residual unbalance (internal frame, g·mm), the other root of
/// the amplitude fit, and the misfit of every reading over its standard deviation.
struct Estimate {
    u: Complex64,
    alternative: Option<f64>,
    misfit: Vec<f64>,
    rms_misfit: f64,
}

fn no_effect() -> InputError {
    InputError::invalid(
        "no_trial_effect",
        "readings",
        "the readings do not change with the trial weight's position: the trial weight is far too small, or the readings are not of this plane",
    )
}

/// Complex least squares `v ≈ a + c e^{iφ}` through the SVD.
fn circle(input: &Input, amplitude: &[f64], phase_deg: &[f64]) -> Result<Estimate, InputError> {
    let n = amplitude.len();
    let v = DVector::from_fn(n, |k, _| reading_in(input.conv, amplitude[k], phase_deg[k]));
    let m = DMatrix::from_fn(n, 2, |k, j| {
        if j == 0 {
            Complex64::new(1.0, 0.0)
        } else {
            Complex64::from_polar(1.0, input.phi[k])
        }
    });
    let x = m
        .clone()
        .svd(true, true)
        .solve(&v, 1e-13)
        .map_err(|_| no_effect())?;
    let (a, c) = (x[0], x[1]);
    let scale = v.iter().map(|z| z.norm()).fold(0.0, f64::max);
    // (Written so that a NaN norm also counts as no effect.)
    if c.norm().partial_cmp(&(1e-9 * scale)) != Some(std::cmp::Ordering::Greater) {
        return Err(no_effect());
    }
    let fitted = &m * &x;
    let (sa, sp) = (
        input.amplitude_noise_pct / 100.0,
        input.phase_noise_deg.to_radians(),
    );
    let floor = 1e-6 * scale;
    let misfit = (0..n)
        .map(|k| {
            let f = fitted[k];
            let amp = f.norm().max(floor);
            let dir = if f.norm() > floor {
                f / f.norm()
            } else {
                Complex64::new(1.0, 0.0)
            };
            let r = (v[k] - f) * dir.conj();
            ((r.re / (sa * amp)).powi(2) + (r.im / (sp * amp)).powi(2)).sqrt()
        })
        .collect();
    let rms = ((&v - &fitted).norm_squared() / n as f64).sqrt();
    Ok(Estimate {
        u: input.u_trial * a / c,
        alternative: None,
        misfit,
        rms_misfit: rms,
    })
}

/// Real least squares `|V|² ≈ p + q cos φ + r sin φ` through the SVD, then the
/// root with the residual below the trial.
fn amplitude_only(input: &Input, amplitude: &[f64]) -> Result<Estimate, InputError> {
    let n = amplitude.len();
    let y = DVector::from_fn(n, |k, _| amplitude[k] * amplitude[k]);
    let m = DMatrix::from_fn(n, 3, |k, j| match j {
        0 => 1.0,
        1 => input.phi[k].cos(),
        _ => input.phi[k].sin(),
    });
    let x = m
        .clone()
        .svd(true, true)
        .solve(&y, 1e-13)
        .map_err(|_| no_effect())?;
    let (p, q, r) = (x[0], x[1], x[2]);
    let s = q.hypot(r);
    if !(p > 0.0 && s > 1e-9 * p) {
        return Err(no_effect());
    }
    // (|a| + |c|)² = p + s and (|a| − |c|)² = p − s (clamped: noise can push it below 0).
    let (s1, s2) = ((p + s).sqrt(), (p - s).max(0.0).sqrt());
    let ratio = (s1 - s2) / (s1 + s2);
    let fitted = &m * &x;
    let sa = input.amplitude_noise_pct / 100.0;
    let floor = 1e-6 * y.max();
    // sd of |V|² is 2|V|·sd(|V|) = 2·sa·|V|².
    let misfit = (0..n)
        .map(|k| ((y[k] - fitted[k]) / (2.0 * sa * fitted[k].max(floor))).abs())
        .collect();
    let rms = ((&y - &fitted).norm_squared() / n as f64).sqrt();
    Ok(Estimate {
        u: Complex64::from_polar(input.u_trial * ratio, r.atan2(q)),
        alternative: (ratio > 0.0).then(|| input.u_trial / ratio),
        misfit,
        rms_misfit: rms,
    })
}

fn estimate(
    input: &Input,
    amplitude: &[f64],
    phase: Option<&[f64]>,
) -> Result<Estimate, InputError> {
    match phase {
        Some(p) => circle(input, amplitude, p),
        None => amplitude_only(input, amplitude),
    }
}

/// 99 % quantile of χ² with `k` degrees of freedom (Wilson–Hilferty; within
/// 0.3 % from k = 1 on, ample for a warning threshold).
fn chi2_99(k: usize) -> f64 {
    let k = k as f64;
    let h = 2.0 / (9.0 * k);
    k * (1.0 - h + 2.326_347_874 * h.sqrt()).powi(3)
}

/// Covariance of `(Re U, Im U)` by first-order propagation: the Jacobian of
/// the whole estimate by central differences in each amplitude and phase,
/// times their variances (independent readings).
fn covariance(input: &Input) -> Matrix2<f64> {
    let mut amp = input.amplitude.clone();
    let mut phase = input.phase_deg.clone();
    let mean = amp.iter().sum::<f64>() / amp.len() as f64;
    let mut cov = Matrix2::zeros();
    let mut add = |d_plus: Option<Complex64>, d_minus: Option<Complex64>, h: f64, var: f64| {
        if let (Some(p), Some(m)) = (d_plus, d_minus) {
            let g = (p - m) / (2.0 * h);
            let g = Vector2::new(g.re, g.im);
            cov += g * g.transpose() * var;
        }
    };
    let at = |amp: &[f64], phase: &Option<Vec<f64>>| {
        estimate(input, amp, phase.as_deref()).ok().map(|e| e.u)
    };
    for k in 0..amp.len() {
        let a0 = amp[k];
        let h = 1e-6 * a0.max(1e-3 * mean);
        amp[k] = a0 + h;
        let plus = at(&amp, &phase);
        amp[k] = a0 - h;
        let minus = at(&amp, &phase);
        amp[k] = a0;
        add(
            plus,
            minus,
            h,
            (input.amplitude_noise_pct / 100.0 * a0).powi(2),
        );
        if let Some(p0) = phase.as_ref().map(|p| p[k]) {
            let h = 1e-5;
            phase.as_mut().expect("phases")[k] = p0 + h;
            let plus = at(&amp, &phase);
            phase.as_mut().expect("phases")[k] = p0 - h;
            let minus = at(&amp, &phase);
            phase.as_mut().expect("phases")[k] = p0;
            add(plus, minus, h, input.phase_noise_deg.powi(2));
        }
    }
    cov
}

fn uncertainty(input: &Input, u: Complex64) -> Option<ResidualUncertainty> {
    let cov = covariance(input);
    let m = u.norm();
    let (dir, perp) = if m > 0.0 {
        (Vector2::new(u.re, u.im) / m, Vector2::new(-u.im, u.re) / m)
    } else {
        (Vector2::new(1.0, 0.0), Vector2::new(0.0, 1.0))
    };
    let sd = (dir.transpose() * cov * dir)[0].max(0.0).sqrt();
    let sd_angle = ((perp.transpose() * cov * perp)[0].max(0.0).sqrt() / m).to_degrees();
    // The angle is undetermined when the χ²₂ 95 % ellipse holds zero.
    let z = Vector2::new(u.re, u.im);
    let holds_zero = cov
        .try_inverse()
        .is_none_or(|inv| (z.transpose() * inv * z)[0] <= CHI2_2_95);
    let (_, angle) = weight_out(input.conv, u);
    // As a correction's interval: it starts in [0, 360) and its upper end
    // runs past 360 when it wraps (a heavy spot near 0° gave [-1.7, 1.7]).
    let half = 1.96 * sd_angle;
    let angle_deg = if holds_zero || !half.is_finite() || half >= 180.0 {
        [0.0, 360.0]
    } else {
        let lower = wrap_deg(angle - half);
        [lower, lower + 2.0 * half]
    };
    sd.is_finite().then(|| ResidualUncertainty {
        method: "first_order".to_string(),
        residual_unbalance_sd_gmm: sd,
        residual_unbalance_gmm: [(m - 1.96 * sd).max(0.0), m + 1.96 * sd],
        residual_angle_deg: angle_deg,
    })
}

fn warning(code: &str, plane: &Option<String>, message: String) -> Warning {
    Warning {
        code: code.to_string(),
        message,
        plane: plane.clone(),
    }
}

/// The whole check of a validated request.
pub fn evaluate(req: &ResidualRequest, input: &Input) -> Result<ResidualCheck, InputError> {
    let est = estimate(input, &input.amplitude, input.phase_deg.as_deref())?;
    let method = if input.phase_deg.is_some() {
        Method::CircleFit
    } else {
        Method::AmplitudeFit
    };
    let allowable = allowable_gmm(req.journal_load_kg, req.speed_rpm);
    let (residual, angle) = weight_out(input.conv, est.u);
    let n = input.amplitude.len();
    let dof = match method {
        Method::CircleFit => 2 * n - 4,
        Method::AmplitudeFit => n - 3,
    };
    let statistic: f64 = est.misfit.iter().map(|m| m * m).sum();
    let threshold = chi2_99(dof);
    let fit = FitCheck {
        statistic,
        degrees_of_freedom: dof,
        threshold,
        rms_misfit: est.rms_misfit,
        holds: statistic <= threshold,
    };

    let max = input.amplitude.iter().copied().fold(0.0, f64::max);
    let min = input
        .amplitude
        .iter()
        .copied()
        .fold(f64::INFINITY, f64::min);
    let (y, z) = ((max - min) / 2.0, (max + min) / 2.0);
    let sheet_u = input.u_trial * y / z;
    let worksheet = Worksheet {
        max_amplitude: max,
        min_amplitude: min,
        y,
        z,
        residual_unbalance_gmm: sheet_u,
        pass: sheet_u <= allowable,
        difference_gmm: sheet_u - residual,
    };

    let plane = &req.plane;
    let trial_ratio = input.u_trial / allowable;
    let mut warnings = Vec::new();
    if !(1.0 - 1e-9..=2.0 + 1e-9).contains(&trial_ratio) {
        warnings.push(warning("trial_outside_range", plane, format!(
            "the trial unbalance is {:.0} g·mm, {trial_ratio:.2} times the allowable {allowable:.0} g·mm; API asks for 1 to 2 times. Choose a trial mass of {:.2} to {:.2} g at {} mm",
            input.u_trial, allowable / req.trial.radius_mm, 2.0 * allowable / req.trial.radius_mm, req.trial.radius_mm
        )));
    }
    if let Some(alt) = est.alternative {
        warnings.push(warning("magnitude_ambiguous", plane, format!(
            "amplitudes alone fit a residual of {residual:.1} g·mm and one of {alt:.1} g·mm (trial/x and x·trial) equally well; the smaller is reported, as API's test presumes the residual is below the trial. Readings with phases settle it"
        )));
    } else if residual > input.u_trial {
        warnings.push(warning("residual_exceeds_trial", plane, format!(
            "the residual unbalance ({residual:.0} g·mm) is larger than the trial ({:.0} g·mm): the test presumes a trial above the residual. Balance the rotor further, or repeat with a heavier trial weight",
            input.u_trial
        )));
    }
    if !fit.holds {
        let worst = (0..n)
            .max_by(|&i, &j| est.misfit[i].total_cmp(&est.misfit[j]))
            .unwrap_or(0);
        warnings.push(warning("fit_does_not_hold", plane, format!(
            "the readings do not lie on the curve a linear rotor gives (misfit statistic {statistic:.1} against {threshold:.1} for the stated repeatability); the worst is readings[{worst}] at {}°. A reading typed wrong, a trial weight misplaced, or a rotor that is not linear: check it and repeat",
            req.readings[worst].angle_deg
        )));
    }

    Ok(ResidualCheck {
        plane: req.plane.clone(),
        residual_unbalance_gmm: residual,
        residual_angle_deg: angle,
        allowable_gmm: allowable,
        pass: residual <= allowable,
        ratio: residual / allowable,
        method,
        worksheet,
        trial_unbalance_gmm: input.u_trial,
        trial_ratio,
        alternative_residual_gmm: est.alternative,
        uncertainty: uncertainty(input, est.u),
        fit,
        positions: input.positions,
        conventions: input.conv,
        warnings,
    })
}

#[cfg(test)]
mod tests {
    use super::chi2_99;

    #[test]
    fn the_chi_square_quantile_is_close_to_the_tables() {
        // χ²(0.99) from the tables: k = 3 → 11.345, 8 → 20.090, 20 → 37.566.
        for (k, q) in [(3, 11.345), (8, 20.090), (20, 37.566)] {
            assert!((chi2_99(k) - q).abs() < 0.01 * q, "{k}");
        }
    }
}
