//! `identify/rotor`: per sensor and plane, the one-mass rotor (method §6, 6.1)
//! fitted to a multi-speed session's influence coefficients (`Z = W·D`, the
//! trial weight the known unbalance), with API 684's amplification factor and
//! separation margin.
//!
//! Units: the model's `Z` is a displacement. Readings in `um_pp`/`mils_pp`
//! are taken as displacement (half the peak-to-peak); velocity readings
//! (`mm_s_rms`, `mm_s_pk`, `in_s_pk`) as the phasor of the velocity `iωZ`, and
//! `g_pk` as that of the acceleration `−ω²Z`: the instrument's phase is the
//! phase of the quantity it measures. Each is brought to metres before the fit,
//! so a velocity sensor's `ω` factor cannot pass for a resonance.
//!
//! A known `options.mass_kg` outside 1e-9 to 1e9 kg and a
//! `cross_coupling_ratio` beyond ±10 are refused naming the option
//! ([`super::ranges`] says why): a mass of 1e300 kg overflowed `√(cm)` and
//! answered `no_mode` for a clean resonance. A `speed_range_rpm` must be
//! `[lo, hi]`, `lo < hi`, each within [`super::ranges::SPEED_RPM`].
//!
//! A damping ratio within its resolution of zero (the readings cannot tell it
//! from undamped) is reported as a bound with a `damping_unresolved` warning:
//! see the `damping` module.

use nalgebra::DMatrix;
use num_complex::Complex64;
mod damping;
pub(crate) mod student;
mod wire;

pub use wire::{
    CrossCoupling, RotorIdentification, RotorOptions, RotorRequest, RotorResult, UnbalanceAngle,
};

use super::onemass::{self, Coupling, Point, Setup};
use super::{api684, lsq, ranges};
use crate::balancing::error::within;
use crate::balancing::model::Unit;
use crate::balancing::solution::Warning;
use crate::balancing::validate::Checked;
use crate::balancing::{influence, validate, InputError};

/// Relative residual above which the fit is called poor.
pub const POOR_FIT: f64 = 0.1;

/// Metres of displacement per unit of a reading at `w` (see the module's units).
pub fn displacement_per_unit(unit: Unit, w: f64) -> Complex64 {
    let i = Complex64::i();
    match unit {
        Unit::UmPp => Complex64::new(0.5e-6, 0.0),
        Unit::MilsPp => Complex64::new(0.5 * 25.4e-6, 0.0),
        Unit::MmSRms => Complex64::new(std::f64::consts::SQRT_2 * 1e-3, 0.0) / (i * w),
        Unit::MmSPk => Complex64::new(1e-3, 0.0) / (i * w),
        Unit::InSPk => Complex64::new(0.0254, 0.0) / (i * w),
        Unit::GPk => Complex64::new(-9.80665 / (w * w), 0.0),
    }
}

/// The selected ids' indices, refused as `/solve` refuses its selection
/// (`balancing::session::select`): an unknown id (`unknown_sensor`,
/// `unknown_plane`) or a repeated one (`duplicate_id`) naming the entry, an
/// empty list naming the list (`no_rows` for sensors, `no_planes`: it
/// answered 200 with no results, session 19).
fn indices(
    field: &str,
    wanted: &Option<Vec<String>>,
    ids: &[&str],
    what: &str,
) -> Result<Vec<usize>, InputError> {
    let Some(wanted) = wanted else {
        return Ok((0..ids.len()).collect());
    };
    if wanted.is_empty() {
        let code = if what == "plane" {
            "no_planes"
        } else {
            "no_rows"
        };
        return Err(InputError::invalid(
            code,
            format!("options.{field}"),
            format!("every {what} is excluded: select at least one {what}, or leave the option out for all"),
        ));
    }
    let mut out = Vec::with_capacity(wanted.len());
    for (i, id) in wanted.iter().enumerate() {
        let f = format!("options.{field}[{i}]");
        let k = ids.iter().position(|x| x == id).ok_or_else(|| {
            InputError::invalid(
                if what == "plane" {
                    "unknown_plane"
                } else {
                    "unknown_sensor"
                },
                f.clone(),
                format!("the session has no {what} '{id}'"),
            )
        })?;
        if out.contains(&k) {
            return Err(InputError::invalid(
                "duplicate_id",
                f,
                format!("{what} '{id}' is listed twice"),
            ));
        }
        out.push(k);
    }
    Ok(out)
}

/// `options.speed_range_rpm`: `[lo, hi]`, `lo < hi`, both within
/// [`ranges::SPEED_RPM`], else an error naming the option.
fn speed_range(r: &[f64]) -> Result<(f64, f64), InputError> {
    let field = "options.speed_range_rpm";
    let [lo, hi] = r else {
        return Err(InputError::invalid(
            "invalid_value",
            field,
            format!("give [lo, hi] in rpm, two numbers; got {}", r.len()),
        ));
    };
    for (name, x) in [("lo", *lo), ("hi", *hi)] {
        within(
            || field.into(),
            x,
            ranges::SPEED_RPM,
            &format!("{name} of [lo, hi] (rpm)"),
        )?;
    }
    if lo >= hi {
        return Err(InputError::invalid(
            "invalid_value",
            field,
            format!("give [lo, hi] in rpm with lo < hi; got lo {lo}, hi {hi}"),
        ));
    }
    Ok((*lo, *hi))
}

fn check_options(o: &RotorOptions) -> Result<(Option<(f64, f64)>, Setup), InputError> {
    let range = match &o.speed_range_rpm {
        None => None,
        Some(r) => Some(speed_range(r)?),
    };
    if let Some(m) = o.mass_kg {
        within(
            || "options.mass_kg".into(),
            m,
            ranges::MASS,
            "a known modal mass in kg",
        )?;
    }
    let coupling = match (o.cross_coupling_ratio, o.cross_coupling.unwrap_or_default()) {
        (Some(k), _) => Coupling::Tied(within(
            || "options.cross_coupling_ratio".into(),
            k,
            (-ranges::CROSS_COUPLING_RATIO, ranges::CROSS_COUPLING_RATIO),
            "the cross-coupling ratio (the cross-coupling stiffness over the damping coefficient times the speed)",
        )?),
        (None, CrossCoupling::Estimated) => Coupling::Estimated,
        (None, CrossCoupling::Zero) => Coupling::Zero,
    };
    let setup = Setup {
        mass: o.mass_kg,
        forcing_at_weight: o.unbalance_angle.unwrap_or_default() == UnbalanceAngle::AtWeight,
        coupling,
    };
    Ok((range, setup))
}

/// Identify the one-mass model of every selected sensor and plane.
pub fn identify(req: &RotorRequest) -> Result<RotorIdentification, InputError> {
    let session = &req.session;
    let checked = validate::check(session).map_err(|e| e.under("session"))?;
    let (range, setup) = check_options(&req.options)?;
    let sensor_ids: Vec<&str> = session.sensors.iter().map(|s| s.id.as_str()).collect();
    let plane_ids: Vec<&str> = session.planes.iter().map(|p| p.id.as_str()).collect();
    let sensors = indices("sensors", &req.options.sensors, &sensor_ids, "sensor")?;
    let planes = indices("planes", &req.options.planes, &plane_ids, "plane")?;
    let w = influence::influence_matrix(&checked).map_err(|e| e.under("session"))?;
    let in_range = |s: f64| range.is_none_or(|(lo, hi)| s >= lo && s <= hi);
    let mut out = RotorIdentification {
        results: Vec::new(),
        warnings: Vec::new(),
    };
    for &s in &sensors {
        let rows: Vec<usize> = (0..checked.rows.len())
            .filter(|&a| checked.rows[a].sensor == s && in_range(checked.rows[a].speed_rpm))
            .collect();
        let needed =
            (if setup.mass.is_some() { 2 } else { 3 }).max((setup.unknowns() + 1).div_ceil(2));
        if rows.len() < needed {
            let field = if range.is_some() {
                "options.speed_range_rpm".to_string()
            } else {
                format!("session.runs[{}].readings", checked.runs[0])
            };
            return Err(InputError::invalid(
                "too_few_speeds",
                field,
                format!("sensor '{}' has readings at {} speed(s){}; the one-mass model needs at least {needed}", sensor_ids[s], rows.len(), if range.is_some() { " in speed_range_rpm" } else { "" }),
            ));
        }
        for &p in &planes {
            fit_one(&checked, &w, &rows, s, p, &setup, &mut out)?;
        }
    }
    Ok(out)
}

fn warn(out: &mut RotorIdentification, code: &str, plane: &str, message: String) {
    out.warnings.push(Warning {
        code: code.into(),
        message,
        plane: Some(plane.into()),
    });
}

fn fit_one(
    checked: &Checked,
    w: &DMatrix<Complex64>,
    rows: &[usize],
    s: usize,
    p: usize,
    setup: &Setup,
    out: &mut RotorIdentification,
) -> Result<(), InputError> {
    let session = checked.session;
    let (sensor, plane) = (&session.sensors[s], &session.planes[p]);
    let unit = sensor.unit;
    // Unbalance per gram of weight, kg·m; 1 (an unknown scale) without a radius.
    let d = plane.radius_mm.map(|r| r * 1e-6);
    if setup.mass.is_some() && d.is_none() {
        return Err(InputError::invalid(
            "missing_radius",
            format!("session.planes[{p}].radius_mm"),
            "a known mass_kg needs the plane's radius to make the trial unbalance known",
        ));
    }
    let scale = d.unwrap_or(1.0);
    let omega = |a: usize| checked.rows[a].speed_rpm * std::f64::consts::PI / 30.0;
    let points: Vec<Point> = rows
        .iter()
        .map(|&a| Point {
            w: omega(a),
            z: w[(a, p)] * displacement_per_unit(unit, omega(a)) / scale,
        })
        .collect();
    // The fit's own refusals named no field (review, session 20): a tied
    // cross-coupling of κ = 1 leaves no damping term (ωb − κbω = 0), so the
    // option is at fault; otherwise the plane's trial runs, whose readings
    // gave coefficients the model cannot fit (a trial that changed nothing).
    let field = if matches!(setup.coupling, Coupling::Tied(k) if (1.0 - k).abs() < 1e-9) {
        "options.cross_coupling_ratio".to_string()
    } else {
        session
            .runs
            .iter()
            .position(|r| r.weights.iter().any(|w| w.plane == plane.id))
            .map_or("session.runs".to_string(), |r| {
                format!("session.runs[{r}].readings")
            })
    };
    let fit = onemass::fit(setup, &points).map_err(|e| InputError {
        message: format!(
            "sensor '{}', plane '{}': {}",
            sensor.id, plane.id, e.message
        ),
        field: e.field.or(Some(field)),
        ..e
    })?;
    let label = format!("sensor '{}', plane '{}'", sensor.id, plane.id);
    let (wn, zeta) = (fit.natural_w(), fit.damping_ratio());
    let resolution = damping::resolution(&fit, setup, &points);
    let unresolved = resolution.is_some_and(|r| zeta.abs() < r);
    if !(wn.is_finite() && zeta.is_finite() && wn > 0.0 && (zeta > 0.0 || unresolved)) {
        warn(out, "no_mode", &plane.id, format!("{label}: the fit has no damped critical speed (c_over_m {:.4e} 1/s², b_over_m {:.4e} 1/s, as answered); the data do not show a resonance of one mode", fit.c / fit.m, fit.b / fit.m));
        return Ok(());
    }
    let measured: Vec<Complex64> = rows.iter().map(|&a| w[(a, p)]).collect();
    let fitted: Vec<Complex64> = points
        .iter()
        .map(|pt| fit.response(pt.w) * scale / displacement_per_unit(unit, pt.w))
        .collect();
    let fit_rms = lsq::rms(measured.iter().zip(&fitted).map(|(m, f)| (m - f).norm()));
    let size = lsq::rms(measured.iter().map(|m| m.norm()));
    let fit_rms_relative = if size > 0.0 { fit_rms / size } else { 0.0 };
    let to_rpm = 30.0 / std::f64::consts::PI;
    let critical = wn * to_rpm;
    let damping = match resolution {
        Some(r) if unresolved => {
            warn(out, "damping_unresolved", &plane.id, format!("{label}: the mode at {critical:.0} rpm has a damping ratio the readings cannot tell from zero (fitted {zeta:.2e}, resolution {r:.2e}); the damping ratio given is the most they allow, the amplification factor the least, the required margin the most API 684 asks. Read more speeds close to the critical, or with less noise, to resolve it"));
            damping::Damping::unresolved(zeta, r)
        }
        _ => damping::Damping::resolved(&fit, wn, zeta, resolution),
    };
    let speeds: Vec<f64> = rows.iter().map(|&a| checked.rows[a].speed_rpm).collect();
    let (lo, hi) = speeds
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
    if fit_rms_relative > POOR_FIT {
        warn(out, "poor_fit", &plane.id, format!("{label}: the one-mass model leaves {:.0} % of the coefficients unexplained: several modes in the speed range (fit one at a time with speed_range_rpm), or coefficients too noisy for their trial (a heavier trial weight, or readings averaged over more revolutions)", 100.0 * fit_rms_relative));
    }
    if critical < lo || critical > hi {
        warn(out, "critical_outside_range", &plane.id, format!("{label}: the critical speed {critical:.0} rpm lies outside the measured {lo:.0}–{hi:.0} rpm; it is extrapolated"));
    }
    let service = session.rotor.as_ref().map(|r| r.service_speed_rpm);
    let absolute = d.is_some();
    // With mass and forcing both estimated the fit is per unit mass: |U| = D/m with D = 1 here.
    let m_abs = if setup.mass.is_none() && !setup.forcing_at_weight {
        1.0 / fit.u.norm()
    } else {
        fit.m
    };
    let k = m_abs / fit.m;
    // An unresolved damping gives no damping or cross-coupling coefficient:
    // the fitted ones were noise, a negative damping among them (review,
    // session 20); the damping ratio's bound says what the readings allow.
    // Nor does a resolved one whose split into b and q is not: b/m within its
    // resolution of zero (or below it), and with q estimated within twice it
    // or with under three degrees of freedom (`damping::split_resolved`).
    // With q estimated, 2 % noise gave damping coefficients from 167 to
    // 8207 N·s/m for a true 3848.
    let split = damping::split_resolution(&fit, setup, &points);
    let b_over_m = fit.b / fit.m;
    let resolved = !damping.bounds
        && split.is_some_and(|(rb, _)| damping::split_resolved(setup, points.len(), b_over_m, rb));
    if !damping.bounds && !resolved {
        warn(out, "damping_split_unresolved", &plane.id, format!("{label}: the readings give the damping ratio of the mode at {critical:.0} rpm, but cannot split it into direct damping and cross-coupling (b_over_m {b_over_m:.3e} 1/s, resolution {}{}); neither coefficient is given. Fit with cross_coupling \"zero\" if the rotor has none, or read more speeds across the resonance", split.map_or("none".to_string(), |(rb, _)| format!("{rb:.2e}")), if setup.coupling == Coupling::Estimated { format!("; with the cross-coupling estimated b/m must exceed {} resolutions, with at least {} degrees of freedom", damping::SPLIT_CLEARANCE, damping::SPLIT_MIN_DOF) } else { String::new() }));
    }
    out.results.push(RotorResult {
        sensor: sensor.id.clone(),
        plane: plane.id.clone(),
        critical_speed_rpm: critical,
        critical_speed_resolution_rpm: damping::natural_w_resolution(&fit, setup, &points)
            .map(|r| r * to_rpm),
        damping_ratio: damping.ratio,
        damping_ratio_resolution: damping.resolution,
        damping_ratio_bound: damping.bounds.then(|| "upper".into()),
        amplification_factor: damping.amplification.factor,
        amplification_factor_bound: damping.bounds.then(|| "lower".into()),
        amplification_method: damping.amplification.method.name().into(),
        peak_speed_rpm: damping.amplification.peak_w.map(|x| x * to_rpm),
        separation_margin_pct: service.map(|n| api684::separation_margin_pct(critical, n)),
        required_margin_pct: service
            .map(|n| api684::required_margin_pct(damping.margin_factor(), critical, n)),
        fit_rms,
        fit_rms_relative,
        speeds: rows.len(),
        c_over_m: fit.c / fit.m,
        b_over_m: resolved.then_some(b_over_m),
        b_over_m_resolution: split.filter(|_| resolved).map(|(rb, _)| rb),
        q_over_m: resolved.then_some(fit.q / fit.m),
        q_over_m_resolution: split.filter(|_| resolved).map(|(_, rq)| rq),
        mass_kg: absolute.then_some(m_abs),
        stiffness_n_per_m: absolute.then_some(fit.c * k),
        damping_n_s_per_m: (absolute && resolved).then_some(fit.b * k),
        cross_coupling_n_per_m: (absolute && resolved).then_some(fit.q * k),
    });
    Ok(())
}
