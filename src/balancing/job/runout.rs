//! Runout (slow-roll) compensation (v2 "Runout"): a sensor's slow-roll vector
//! is subtracted from every reading of that sensor, at every speed and in every
//! run, before anything else (so the influence coefficients, corrections, run
//! checks and pooled coefficients all see compensated readings).
//!
//! The noise model of a reading is relative to the reading as measured, before
//! compensation (`Checked::measured`): the instrument's repeatability
//! (`amplitude_noise_pct`, `phase_noise_deg`) scales with what it read, so a
//! reading that is mostly runout is no more precise for it (a reading equal to
//! its runout once gave a 0 g correction within [0, 0] g). Samples are
//! compensated by the same constant, which leaves their scatter unchanged.
//! The runout vector itself is taken as exact (the contract gives it no
//! noise).

use num_complex::Complex64;

use crate::balancing::error::InputError;
use crate::balancing::model::{Conventions, Session};
use crate::balancing::phasor::reading_in;
use crate::balancing::validate::{MAX_AMPLITUDE, MAX_ANGLE_DEG, MIN_AMPLITUDE};

/// The runout phasor of each sensor (internal frame), by sensor index; `None`
/// for a sensor without one. Errors name `runout[i].…`.
pub fn vectors(session: &Session, conv: Conventions) -> Result<Vec<Option<Complex64>>, InputError> {
    let mut out = vec![None; session.sensors.len()];
    for (i, r) in session.runout.iter().flatten().enumerate() {
        let f = |x: &str| format!("runout[{i}].{x}");
        let Some(s) = session.sensors.iter().position(|s| s.id == r.sensor) else {
            return Err(InputError::invalid(
                "unknown_sensor",
                f("sensor"),
                format!("no sensor has the id '{}'", r.sensor),
            ));
        };
        if out[s].is_some() {
            return Err(InputError::invalid(
                "duplicate_id",
                f("sensor"),
                format!(
                    "sensor '{}' has a runout vector already: give one per sensor",
                    r.sensor
                ),
            ));
        }
        // 0, or a reading's range: a smaller runout than any reading resolves
        // is no runout (1e-320 was taken where a reading of it is refused).
        let a = r.amplitude;
        if !(a == 0.0 || (MIN_AMPLITUDE..=MAX_AMPLITUDE).contains(&a)) {
            return Err(InputError::invalid(
                "invalid_value",
                f("amplitude"),
                format!("the runout amplitude must be 0 or a finite number from {MIN_AMPLITUDE:e} to {MAX_AMPLITUDE:e}, as a reading's"),
            ));
        }
        if !(r.phase_deg.is_finite() && r.phase_deg.abs() <= MAX_ANGLE_DEG) {
            return Err(InputError::invalid(
                "invalid_value",
                f("phase_deg"),
                format!("an angle in degrees must be finite and within ±{MAX_ANGLE_DEG}"),
            ));
        }
        out[s] = Some(reading_in(conv, r.amplitude, r.phase_deg));
    }
    Ok(out)
}
