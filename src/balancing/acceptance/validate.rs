//! Checks of a residual-unbalance request: every number finite and in its
//! range (the ranges of a session's numbers, below),
//! at least 4 equally spaced positions (the first may be repeated at the end),
//! phases for every reading or for none. Each refusal names its field.

use super::{ResidualRequest, DEFAULT_AMPLITUDE_NOISE_PCT, DEFAULT_PHASE_NOISE_DEG};
use crate::balancing::error::{shown, within, InputError};
use crate::balancing::model::Conventions;
use crate::balancing::phasor::weight_angle_in;
use crate::balancing::validate::{
    MAX_AMPLITUDE, MAX_ANGLE_DEG, MAX_MASS_G, MAX_RADIUS_MM, MAX_SPEED_RPM, MIN_AMPLITUDE,
    MIN_MASS_G, MIN_RADIUS_MM, MIN_ROTOR_MASS_KG, MIN_SERVICE_SPEED_RPM,
};

/// Fewest distinct positions: the amplitude fit has 3 unknowns and needs one
/// more reading to test the fit at all.
pub const MIN_POSITIONS: usize = 4;
/// The most positions a check takes: 2° apart, four times the spacing's
/// tolerance, so that a position and its neighbour are told apart (under 1°
/// apart the 0.5° tolerance cannot say which reading repeats which).
pub const MAX_POSITIONS: usize = 180;
/// How far a position may be from its place on the equal spacing, degrees.
const SPACING_TOL_DEG: f64 = 0.5;

mod spacing;
use spacing::spacing;

/// A checked request in the internal frame (method §1).
#[derive(Debug, Clone)]
pub struct Input {
    pub conv: Conventions,
    /// Trial unbalance, g·mm.
    pub u_trial: f64,
    /// Internal angle of the trial weight at each reading, radians.
    pub phi: Vec<f64>,
    pub amplitude: Vec<f64>,
    /// Phases in the request's convention, degrees, when given.
    pub phase_deg: Option<Vec<f64>>,
    /// Distinct positions.
    pub positions: usize,
    pub amplitude_noise_pct: f64,
    pub phase_noise_deg: f64,
}

// The ranges of the numbers, a session's own (`validate`): past them the
// squares of the fit, the allowable 6350·W/N and the ratios over it became
// infinite and were answered as `null` (fuzzing, session 15).
/// Speed, rpm: a rotor's service speed.
const SPEED_RPM: (f64, f64) = (MIN_SERVICE_SPEED_RPM, MAX_SPEED_RPM);
/// Journal load, kg.
const JOURNAL_LOAD_KG: (f64, f64) = (MIN_ROTOR_MASS_KG, 1e7);
/// Trial mass, g (a session's weights).
const TRIAL_MASS_G: (f64, f64) = (MIN_MASS_G, MAX_MASS_G);
/// Trial radius, mm.
const TRIAL_RADIUS_MM: (f64, f64) = (MIN_RADIUS_MM, MAX_RADIUS_MM);
/// Amplitudes other than 0 (a session's readings).
const AMPLITUDE: (f64, f64) = (MIN_AMPLITUDE, MAX_AMPLITUDE);
/// Smallest repeatability, percent or degrees: the misfits are divided by it.
const MIN_NOISE: f64 = 1e-6;

fn angle(field: String, x: f64) -> Result<f64, InputError> {
    if x.is_finite() && x.abs() <= MAX_ANGLE_DEG {
        Ok(x)
    } else {
        Err(InputError::invalid(
            "invalid_value",
            field,
            format!("an angle in degrees must be finite and within ±{MAX_ANGLE_DEG}"),
        ))
    }
}

fn noise(field: &str, x: Option<f64>, default: f64, max: f64) -> Result<f64, InputError> {
    within(
        || field.into(),
        x.unwrap_or(default),
        (MIN_NOISE, max),
        "the repeatability",
    )
}

/// Check `req`; the first fault found is named.
pub fn check(req: &ResidualRequest) -> Result<Input, InputError> {
    if let Some(p) = &req.plane {
        if p.is_empty() || p.chars().count() > 64 {
            return Err(InputError::invalid(
                "invalid_value",
                "plane",
                "a plane id has 1 to 64 characters",
            ));
        }
        // The id rule of every id (it was answered back holding a NUL).
        crate::balancing::validate::check_id_chars(|| "plane".into(), p)?;
    }
    within(|| "speed_rpm".into(), req.speed_rpm, SPEED_RPM, "the speed")?;
    within(
        || "journal_load_kg".into(),
        req.journal_load_kg,
        JOURNAL_LOAD_KG,
        "the journal load",
    )?;
    let mass = within(
        || "trial.mass_g".into(),
        req.trial.mass_g,
        TRIAL_MASS_G,
        "the trial mass",
    )?;
    let radius = within(
        || "trial.radius_mm".into(),
        req.trial.radius_mm,
        TRIAL_RADIUS_MM,
        "the trial radius",
    )?;
    let amplitude_noise_pct = noise(
        "amplitude_noise_pct",
        req.amplitude_noise_pct,
        DEFAULT_AMPLITUDE_NOISE_PCT,
        100.0,
    )?;
    let phase_noise_deg = noise(
        "phase_noise_deg",
        req.phase_noise_deg,
        DEFAULT_PHASE_NOISE_DEG,
        90.0,
    )?;
    let conv = req.conventions.unwrap_or_default();

    let with_phase = req.readings.first().is_some_and(|r| r.phase_deg.is_some());
    for (k, r) in req.readings.iter().enumerate() {
        angle(format!("readings[{k}].angle_deg"), r.angle_deg)?;
        let a = r.amplitude;
        if !(a == 0.0 || (a.is_finite() && (AMPLITUDE.0..=AMPLITUDE.1).contains(&a))) {
            return Err(InputError::invalid(
                "invalid_value",
                format!("readings[{k}].amplitude"),
                format!(
                    "an amplitude is 0 or a finite number from {} to {}, got {}",
                    shown(AMPLITUDE.0),
                    shown(AMPLITUDE.1),
                    shown(a)
                ),
            ));
        }
        match r.phase_deg {
            Some(p) => {
                angle(format!("readings[{k}].phase_deg"), p)?;
                if !with_phase {
                    return Err(InputError::invalid(
                        "mixed_phases",
                        format!("readings[{k}].phase_deg"),
                        "give a phase for every reading or for none (the first reading has none)",
                    ));
                }
            }
            None if with_phase => {
                return Err(InputError::invalid(
                    "mixed_phases",
                    format!("readings[{k}].phase_deg"),
                    "give a phase for every reading or for none (the first reading has one)",
                ))
            }
            None => {}
        }
    }
    let positions = spacing(req)?;
    if req.readings.iter().all(|r| r.amplitude == 0.0) {
        return Err(InputError::invalid(
            "no_response",
            "readings",
            "every amplitude is 0: the trial weight moved nothing the machine could read",
        ));
    }
    Ok(Input {
        conv,
        u_trial: mass * radius,
        phi: req
            .readings
            .iter()
            .map(|r| weight_angle_in(conv, r.angle_deg))
            .collect(),
        amplitude: req.readings.iter().map(|r| r.amplitude).collect(),
        phase_deg: with_phase.then(|| {
            req.readings
                .iter()
                .map(|r| r.phase_deg.unwrap_or(0.0))
                .collect()
        }),
        positions,
        amplitude_noise_pct,
        phase_noise_deg,
    })
}
