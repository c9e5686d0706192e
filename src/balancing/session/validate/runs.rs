//! Per-field checks of every run, in session order: its weights, its
//! readings (finding each reading's sensor), and which run is the reference.
//!
//! One pass over the readings without allocating per reading: a reading whose
//! fields are all plainly in range and whose sensor is the one after the
//! previous reading's is accepted by a few comparisons; any other goes through
//! the full checks, which report the first bad field exactly as before (issue 15).

use std::collections::HashMap;

use super::fields::{at_least, check_amplitude, check_angle, check_positive};
use super::{
    IdIndex, MAX_AMPLITUDE, MAX_ANGLE_DEG, MAX_SPEED_RPM, MIN_AMPLITUDE, MIN_SERVICE_SPEED_RPM,
};
use crate::balancing::error::InputError;
use crate::balancing::model::{Reading, Sensor, Session};

pub(crate) const MAX_MASS_G: f64 = 1e7;
/// A trial mass below a microgram is no balancing weight; below it the
/// influence coefficients `ΔY / T` (method 2.1) could overflow (a trial mass
/// of 1e-320 g made every coefficient infinite and the solver panic).
pub(crate) const MIN_MASS_G: f64 = 1e-6;

/// What the field checks of the runs found.
pub(super) struct RunFields {
    /// Index of the reference run (the one without weights) in `session.runs`.
    pub reference: usize,
    /// Sensor index of every reading, all runs' readings one after the other.
    pub sensor: Vec<u32>,
    /// Where each run's readings start in `sensor`.
    pub start: Vec<usize>,
}

/// Check one reading and find its sensor; `hint` is the sensor index to try
/// first (readings usually list the sensors in order, and comparing one id is
/// far cheaper than hashing it: issue 15).
#[inline(never)]
fn check_reading(
    f: &dyn Fn() -> String,
    r: &Reading,
    sensors: &HashMap<&str, usize>,
    ids: &[Sensor],
    hint: usize,
) -> Result<usize, InputError> {
    check_positive(
        || format!("{}.speed_rpm", f()),
        r.speed_rpm,
        MAX_SPEED_RPM,
        false,
        "the speed",
    )?;
    // As a rotor's service speed (fuzzing, session 21: 1e-320 rpm was read).
    at_least(
        &format!("{}.speed_rpm", f()),
        r.speed_rpm,
        MIN_SERVICE_SPEED_RPM,
        "the speed",
        "rpm",
    )?;
    let sensor = match ids.get(hint) {
        // Ids are unique (checked before), so a match is the one the map gives.
        Some(s) if s.id == r.sensor => hint,
        _ => *sensors.get(r.sensor.as_str()).ok_or_else(|| {
            InputError::invalid(
                "unknown_sensor",
                format!("{}.sensor", f()),
                format!("no sensor has the id '{}'", r.sensor),
            )
        })?,
    };
    check_amplitude(|| format!("{}.amplitude", f()), r.amplitude)?;
    check_angle(|| format!("{}.phase_deg", f()), r.phase_deg)?;
    if let Some(samples) = &r.samples {
        if samples.len() < 2 {
            return Err(super::fields::invalid(
                format!("{}.samples", f()),
                "give at least 2 samples, or leave the list out",
            ));
        }
        for (k, s) in samples.iter().enumerate() {
            check_amplitude(|| format!("{}.samples[{k}].amplitude", f()), s.amplitude)?;
            check_angle(|| format!("{}.samples[{k}].phase_deg", f()), s.phase_deg)?;
        }
    }
    Ok(sensor)
}

/// Whether [`check_reading`] surely passes `r`'s numbers: the same bounds,
/// written so that NaN and infinities fail them. Samples take the full checks.
#[inline]
fn plainly_valid(r: &Reading) -> bool {
    let a = r.amplitude;
    r.speed_rpm >= MIN_SERVICE_SPEED_RPM
        && r.speed_rpm <= MAX_SPEED_RPM
        && (a == 0.0 || (MIN_AMPLITUDE..=MAX_AMPLITUDE).contains(&a))
        && r.phase_deg.abs() <= MAX_ANGLE_DEG
        && r.samples.is_none()
}

/// `a == b`, compared in line: ids are short, and a call to `bcmp` cost
/// more than the comparison on every reading (issue 15).
#[inline]
fn same_id(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x == y)
}

/// The per-field checks of every run and the reference run.
pub(super) fn check_runs(
    session: &Session,
    planes: &IdIndex<'_>,
    sensors: &IdIndex<'_>,
) -> Result<RunFields, InputError> {
    let ids = &session.sensors;
    let total: usize = session.runs.iter().map(|r| r.readings.len()).sum();
    let mut sensor = Vec::with_capacity(total);
    let mut start = Vec::with_capacity(session.runs.len());
    let mut reference: Option<usize> = None;
    for (i, run) in session.runs.iter().enumerate() {
        for (j, w) in run.weights.iter().enumerate() {
            let f = || format!("runs[{i}].weights[{j}]");
            if !planes.contains_key(w.plane.as_str()) {
                return Err(InputError::invalid(
                    "unknown_plane",
                    format!("{}.plane", f()),
                    format!("no plane has the id '{}'", w.plane),
                ));
            }
            check_positive(
                || format!("{}.mass_g", f()),
                w.mass_g,
                MAX_MASS_G,
                false,
                "the mass",
            )?;
            if w.mass_g < MIN_MASS_G {
                return Err(InputError::invalid(
                    "invalid_value",
                    format!("{}.mass_g", f()),
                    format!("the trial mass {} g is below {MIN_MASS_G} g, lighter than any balancing weight: give the mass in grams", crate::balancing::error::shown(w.mass_g)),
                ));
            }
            check_angle(|| format!("{}.angle_deg", f()), w.angle_deg)?;
        }
        start.push(sensor.len());
        let mut hint = 0;
        for (j, r) in run.readings.iter().enumerate() {
            let s = match ids.get(hint) {
                Some(s) if plainly_valid(r) && same_id(&s.id, &r.sensor) => hint,
                _ => check_reading(
                    &|| format!("runs[{i}].readings[{j}]"),
                    r,
                    sensors,
                    ids,
                    hint,
                )?,
            };
            // After the last sensor the list usually starts again (next speed).
            hint = if s + 1 == ids.len() { 0 } else { s + 1 };
            sensor.push(s as u32);
        }
        if run.weights.is_empty() {
            if let Some(first) = reference {
                return Err(InputError::invalid(
                    "second_reference_run",
                    format!("runs[{i}].weights"),
                    format!("run '{}' has no weights, like run '{}': exactly one run is the reference (zero) run; list every weight on the rotor in the others", run.id, session.runs[first].id),
                ));
            }
            reference = Some(i);
        }
    }
    let Some(reference) = reference else {
        return Err(InputError::invalid("no_reference_run", "runs", "no reference run: exactly one run must have an empty weights list (the rotor as found)"));
    };
    if session.runs[reference].readings.is_empty() {
        return Err(super::fields::invalid(
            format!("runs[{reference}].readings"),
            "the reference run needs at least one reading",
        ));
    }
    Ok(RunFields {
        reference,
        sensor,
        start,
    })
}
