//! The option `influence_coefficients` read onto the session's rows: each
//! entry checked, placed at its (sensor, speed point) row and plane, and
//! brought into the internal frame with its covariance.

use nalgebra::{DMatrix, Matrix2};

use super::Supplied;
use crate::balancing::error::InputError;
use crate::balancing::model::{
    Conventions, PhaseConvention, SolveOptions, SuppliedCoefficient, Unit,
};
use crate::balancing::phasor::reading_in;
use crate::balancing::validate::{Checked, MAX_AMPLITUDE_PER_G, MIN_AMPLITUDE_PER_G};

const FIELD: &str = "options.influence_coefficients";

/// A coefficient computed here (pooled, or converted from a stored version)
/// as the option accepts it: below `MIN_AMPLITUDE_PER_G` (1e-16 unit/g) it is a rounding's
/// worth of readings that did not change, so 0 (the sensor does not see the
/// plane); a pooled 2e-19 unit/g was otherwise refused when used again.
pub fn resolvable(amplitude_per_g: f64) -> f64 {
    if amplitude_per_g < MIN_AMPLITUDE_PER_G {
        0.0
    } else {
        amplitude_per_g
    }
}
/// The square of `MAX_AMPLITUDE_PER_G`, for the covariance's entries.
const MAX_COVARIANCE: f64 = 1e30;

/// Flip of the imaginary axis between the session's phase convention and the
/// internal frame (lag counts phase the other way).
fn frame(conv: Conventions) -> Matrix2<f64> {
    match conv.phase {
        PhaseConvention::Lag => Matrix2::new(1.0, 0.0, 0.0, -1.0),
        PhaseConvention::Lead => Matrix2::identity(),
    }
}

/// A coefficient's covariance from the wire (session's convention) to the
/// internal frame, or back: the same flip.
pub fn covariance_frame(conv: Conventions, c: &Matrix2<f64>) -> Matrix2<f64> {
    let f = frame(conv);
    f * c * f
}

/// A unit as the wire spells it (`um_pp`).
pub fn unit_name(unit: Unit) -> String {
    serde_json::to_value(unit)
        .ok()
        .and_then(|v| v.as_str().map(str::to_string))
        .unwrap_or_default()
}

fn bad(field: String, message: impl Into<String>) -> InputError {
    InputError::invalid("invalid_value", field, message)
}

/// A supplied coefficient's numbers, entry `i` of the list at `list` (the
/// option's, or a trim job's record of it: one rule for both): speed from 1
/// rpm, amplitude 0 or in range, a finite angle, a valid covariance.
pub(crate) fn check_entry(
    list: &str,
    i: usize,
    c: &SuppliedCoefficient,
) -> Result<Option<Matrix2<f64>>, InputError> {
    let f = |x: &str| format!("{list}[{i}].{x}");
    // From 1 rpm, as a reading's (a coefficient at a slower speed pairs
    // with no reading).
    if !(c.speed_rpm.is_finite()
        && (crate::balancing::validate::MIN_SERVICE_SPEED_RPM
            ..=crate::balancing::validate::MAX_SPEED_RPM)
            .contains(&c.speed_rpm))
    {
        return Err(bad(
            f("speed_rpm"),
            format!(
                "a speed must be a finite number from {} to {:e} rpm, as a reading's",
                crate::balancing::validate::MIN_SERVICE_SPEED_RPM,
                crate::balancing::validate::MAX_SPEED_RPM
            ),
        ));
    }
    let a = c.amplitude_per_g;
    if !(a == 0.0 || (MIN_AMPLITUDE_PER_G..=MAX_AMPLITUDE_PER_G).contains(&a)) {
        return Err(bad(
            f("amplitude_per_g"),
            format!(
                "must be 0 (the sensor does not see the plane) or a finite number from {MIN_AMPLITUDE_PER_G:e} to {MAX_AMPLITUDE_PER_G:e} (sensor unit per gram)"
            ),
        ));
    }
    if !(c.phase_deg.is_finite() && c.phase_deg.abs() <= 1e6) {
        return Err(bad(
            f("phase_deg"),
            "an angle in degrees must be finite and within ±1e6",
        ));
    }
    let Some(m) = c.covariance else {
        return Ok(None);
    };
    check_covariance(|| f("covariance"), m).map(Some)
}

/// A coefficient's covariance (the option's, or a trim job's record of it):
/// symmetric, positive semi-definite, finite and at most 1e30 (unit/g)².
fn check_covariance(
    field: impl FnOnce() -> String,
    m: [[f64; 2]; 2],
) -> Result<Matrix2<f64>, InputError> {
    let m = Matrix2::new(m[0][0], m[0][1], m[1][0], m[1][1]);
    let finite = m.iter().all(|x| x.is_finite() && x.abs() <= MAX_COVARIANCE);
    let sym = (m[(0, 1)] - m[(1, 0)]).abs() <= 1e-9 * (m[(0, 0)].abs() + m[(1, 1)].abs());
    let psd = m[(0, 0)] >= 0.0
        && m[(1, 1)] >= 0.0
        && m.determinant() >= -1e-9 * (m[(0, 0)] * m[(1, 1)]).max(f64::MIN_POSITIVE);
    if !(finite && sym && psd) {
        return Err(bad(
            field(),
            "a covariance is a symmetric positive semi-definite 2×2 matrix of finite numbers, each at most 1e30 (unit/g)²",
        ));
    }
    Ok(m)
}

/// A coefficient's `unit` other than its sensor's: `unit_mismatch` at `field`.
pub(crate) fn check_unit(
    field: impl FnOnce() -> String,
    given: Option<Unit>,
    sensor: &str,
    unit: Unit,
) -> Result<(), InputError> {
    match given.filter(|&u| u != unit) {
        Some(u) => Err(InputError::invalid(
            "unit_mismatch",
            field(),
            format!(
                "the coefficient is in {} per gram but the session reads sensor '{sensor}' in {}",
                unit_name(u),
                unit_name(unit)
            ),
        )),
        None => Ok(()),
    }
}

/// The supplied coefficients on `checked`'s rows, or `None` without the
/// option. Every row of the reference run needs a coefficient for every plane
/// solved for (`options.planes`, or all); coefficients for other speeds or
/// sensors are ignored.
pub fn resolve(checked: &Checked, options: &SolveOptions) -> Result<Option<Supplied>, InputError> {
    let Some(list) = &options.influence_coefficients else {
        return Ok(None);
    };
    let session = checked.session;
    let conv = checked.conventions;
    let (n, p) = (checked.rows.len(), session.planes.len());
    let mut w = DMatrix::zeros(n, p);
    let mut cov = vec![vec![Matrix2::zeros(); p]; n];
    let mut given = DMatrix::from_element(n, p, false);
    for (i, c) in list.iter().enumerate() {
        let m = check_entry(FIELD, i, c)?;
        let Some(s) = session.sensors.iter().position(|s| s.id == c.sensor) else {
            return Err(InputError::invalid(
                "unknown_sensor",
                format!("{FIELD}[{i}].sensor"),
                format!("the session has no sensor '{}'", c.sensor),
            ));
        };
        check_unit(
            || format!("{FIELD}[{i}].unit"),
            c.unit,
            &c.sensor,
            session.sensors[s].unit,
        )?;
        let Some(j) = session.planes.iter().position(|pl| pl.id == c.plane) else {
            return Err(InputError::invalid(
                "unknown_plane",
                format!("{FIELD}[{i}].plane"),
                format!("the session has no plane '{}'", c.plane),
            ));
        };
        let Some(point) = checked.point_of(c.speed_rpm) else {
            continue;
        };
        let Some(a) = checked
            .rows
            .iter()
            .position(|r| r.point == point && r.sensor == s)
        else {
            continue;
        };
        if given[(a, j)] {
            return Err(InputError::invalid(
                "duplicate_coefficient",
                format!("{FIELD}[{i}]"),
                format!(
                    "a coefficient of sensor '{}' at {} rpm for plane '{}' is given twice",
                    c.sensor, c.speed_rpm, c.plane
                ),
            ));
        }
        given[(a, j)] = true;
        w[(a, j)] = reading_in(conv, c.amplitude_per_g, c.phase_deg);
        cov[a][j] = m.map(|m| covariance_frame(conv, &m)).unwrap_or_default();
    }
    let wanted: Vec<usize> = match &options.planes {
        Some(ids) => session
            .planes
            .iter()
            .enumerate()
            .filter(|(_, pl)| ids.contains(&pl.id))
            .map(|(j, _)| j)
            .collect(),
        None => (0..p).collect(),
    };
    for (a, row) in checked.rows.iter().enumerate() {
        if let Some(&j) = wanted.iter().find(|&&j| !given[(a, j)]) {
            return Err(InputError::invalid(
                "missing_coefficient",
                FIELD,
                format!(
                    "no influence coefficient of sensor '{}' at {} rpm for plane '{}': give one for every sensor and speed of the reference run and every plane solved for",
                    session.sensors[row.sensor].id, crate::balancing::error::shown(row.speed_rpm), session.planes[j].id
                ),
            ));
        }
    }
    Ok(Some(Supplied { w, cov, given }))
}
