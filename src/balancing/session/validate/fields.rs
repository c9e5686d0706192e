//! Checks of single fields (ids, texts, positive numbers, amplitudes, angles)
//! and of the session's setup: name, rotor, planes and sensors.
//!
//! Every check builds its field path only on an error: they run on every
//! reading of every request (issue 15).

use std::collections::HashMap;

use super::{IdIndex, GRADES, MAX_AMPLITUDE, MAX_ANGLE_DEG, MAX_SPEED_RPM, MIN_AMPLITUDE};
use crate::balancing::error::{shown, InputError};
use crate::balancing::model::{Rotor, Session};

pub(crate) const MAX_RADIUS_MM: f64 = 1e5;
/// Smallest plane radius, mm (the residual check's smallest trial radius):
/// a trial weight sized from the rotor is inversely proportional to it, and
/// 1e-310 mm gave an infinite one, answered as `null` (session 21).
pub(crate) const MIN_RADIUS_MM: f64 = 1e-3;
/// Lightest rotor, kg (the residual check's lightest journal load): below
/// it the permissible unbalance and a trial weight sized from the rotor
/// came out 0 g·mm and 0 g (1e-320 kg, session 21).
pub(crate) const MIN_ROTOR_MASS_KG: f64 = 1e-3;
/// Slowest service speed of a rotor, rpm.
pub(crate) const MIN_SERVICE_SPEED_RPM: f64 = 1.0;
const MAX_TEXT: usize = 200;

pub(super) fn invalid(field: impl Into<String>, message: impl Into<String>) -> InputError {
    InputError::invalid("invalid_value", field, message)
}

fn check_id(field: impl FnOnce() -> String, id: &str) -> Result<(), InputError> {
    let n = id.chars().count();
    if n == 0 || n > 64 {
        return Err(invalid(
            field(),
            format!("ids are 1 to 64 characters; this one has {n}"),
        ));
    }
    check_id_chars(field, id)
}

/// A machine's id where a session names one (its `machine`, its
/// `trim.coefficients_from.machine`): 1 to 64 characters, none a control
/// character, as a machine's own id. The one rule for the store and the
/// solve. `validate` applies it to the trim; a session's `machine` is
/// checked where a request defines it (the store's posted session, the
/// solve's), since a stored session may name one from before the rule.
pub fn check_machine_id(field: impl FnOnce() -> String, id: &str) -> Result<(), InputError> {
    let n = id.chars().count();
    if n == 0 || n > 64 {
        return Err(invalid(
            field(),
            format!("a machine id has 1 to 64 characters; this one has {n}"),
        ));
    }
    // A blank id names a machine no one can tell from none (a blank name
    // is refused too).
    if id.trim().is_empty() {
        return Err(invalid(
            field(),
            "a machine id is not blank: it holds a character other than spaces",
        ));
    }
    check_id_chars(field, id)
}

/// The first character of `s` that `bad` refuses, with its position (from 1).
fn first(s: &str, bad: impl Fn(char) -> bool) -> Option<(usize, char)> {
    s.chars()
        .enumerate()
        .find(|&(_, c)| bad(c))
        .map(|(i, c)| (i + 1, c))
}

fn refused(field: String, what: &str, at: usize, c: char) -> InputError {
    invalid(
        field,
        format!(
            "{what}; this one has U+{:04X} at character {at}",
            u32::from(c)
        ),
    )
}

/// What an id may hold, the one rule for every id a client chooses (planes,
/// sensors, runs, machines; the store's too): no control character (Unicode
/// Cc: U+0000 to U+001F, U+007F to U+009F). Ids go into paths, headers, file
/// names and lists, where a newline or a NUL is invisible or breaks the line.
pub fn check_id_chars(field: impl FnOnce() -> String, id: &str) -> Result<(), InputError> {
    match first(id, char::is_control) {
        None => Ok(()),
        Some((at, c)) => Err(refused(
            field(),
            "an id holds no control characters (U+0000 to U+001F, U+007F to U+009F)",
            at,
            c,
        )),
    }
}

/// What a free text (a name, a label, notes) may hold: tabs and line breaks,
/// but no other control character. The core does not apply it to a
/// session's texts (a stored session may hold them from before the rule);
/// the store applies it to what a request defines.
pub fn check_text_chars(field: impl FnOnce() -> String, text: &str) -> Result<(), InputError> {
    match first(text, |c| c.is_control() && !matches!(c, '\t' | '\n' | '\r')) {
        None => Ok(()),
        Some((at, c)) => Err(refused(
            field(),
            "a text holds no control characters but tabs and line breaks",
            at,
            c,
        )),
    }
}

/// The strings a request that defines a session sets, beyond its ids
/// (which `validate` checks wherever a session is validated): its `name`
/// and sensors' `label`s (texts, [`check_text_chars`]) and the `machine` it
/// names ([`check_machine_id`]); fields named from the session's root. The
/// one rule for the store's posted session and the stateless endpoints that
/// take a session (`/solve`, `/trial-weights`, `/identify/rotor`): left out
/// of `validate` because a session stored before the rule may hold them and
/// must still take runs and solve.
pub fn check_defined_strings(s: &Session) -> Result<(), InputError> {
    check_text_chars(|| "name".into(), &s.name)?;
    if let Some(m) = &s.machine {
        // Looked up as a machine's id: an empty one named no machine, yet
        // was stored as naming one.
        check_machine_id(|| "machine".into(), m)?;
    }
    for (i, x) in s.sensors.iter().enumerate() {
        if let Some(l) = &x.label {
            check_text_chars(|| format!("sensors[{i}].label"), l)?;
        }
    }
    Ok(())
}

fn check_text(field: &str, text: &str, required: bool) -> Result<(), InputError> {
    if required && text.trim().is_empty() {
        return Err(invalid(field, "must not be empty"));
    }
    if text.chars().count() > MAX_TEXT {
        return Err(invalid(field, format!("at most {MAX_TEXT} characters")));
    }
    Ok(())
}

/// A finite number in `(0, max]` (or `[0, max]` when `zero_ok`).
pub(super) fn check_positive(
    field: impl FnOnce() -> String,
    x: f64,
    max: f64,
    zero_ok: bool,
    what: &str,
) -> Result<(), InputError> {
    if !x.is_finite() {
        return Err(invalid(field(), format!("{what} must be a finite number")));
    }
    if x < 0.0 || (x == 0.0 && !zero_ok) {
        let bound = if zero_ok {
            "0 or more"
        } else {
            "greater than 0"
        };
        return Err(invalid(
            field(),
            format!("{what} must be {bound}, got {}", shown(x)),
        ));
    }
    if x > max {
        return Err(invalid(
            field(),
            format!(
                "{what} of {} is beyond the plausible limit of {}",
                shown(x),
                shown(max)
            ),
        ));
    }
    Ok(())
}

/// An amplitude: 0, or from [`MIN_AMPLITUDE`] to [`MAX_AMPLITUDE`].
pub(super) fn check_amplitude(field: impl Fn() -> String, x: f64) -> Result<(), InputError> {
    check_positive(&field, x, MAX_AMPLITUDE, true, "the amplitude")?;
    if x != 0.0 && x < MIN_AMPLITUDE {
        return Err(invalid(
            field(),
            format!("the amplitude {} is below {MIN_AMPLITUDE} of its unit, which no instrument resolves: give 0 for no vibration, or use a smaller unit", shown(x)),
        ));
    }
    Ok(())
}

pub(super) fn check_angle(field: impl FnOnce() -> String, x: f64) -> Result<(), InputError> {
    if !x.is_finite() || x.abs() > MAX_ANGLE_DEG {
        return Err(invalid(
            field(),
            format!("an angle in degrees must be finite and within ±{MAX_ANGLE_DEG}"),
        ));
    }
    Ok(())
}

/// Index of an id in a list, checking uniqueness of the list as it goes.
pub(super) fn unique_ids<'s>(
    field: &str,
    ids: impl Iterator<Item = &'s str>,
) -> Result<HashMap<&'s str, usize>, InputError> {
    let mut seen = HashMap::new();
    for (i, id) in ids.enumerate() {
        // Built only for an error: this runs for every id of every request.
        let f = || format!("{field}[{i}].id");
        check_id(f, id)?;
        if seen.insert(id, i).is_some() {
            return Err(InputError::invalid(
                "duplicate_id",
                f(),
                format!("the id '{id}' is used twice"),
            ));
        }
    }
    Ok(seen)
}

/// `x` (already checked positive) is at least `min`, else a value error
/// "`what` must be at least `min` `unit`, got `x`".
pub(super) fn at_least(
    field: &str,
    x: f64,
    min: f64,
    what: &str,
    unit: &str,
) -> Result<(), InputError> {
    if x < min {
        return Err(invalid(
            field,
            format!(
                "{what} must be at least {} {unit}, got {}",
                shown(min),
                shown(x)
            ),
        ));
    }
    Ok(())
}

/// The rotor data of a session or a machine (ISO 21940-11 inputs).
pub fn check_rotor(r: &Rotor) -> Result<(), InputError> {
    check_positive(
        || "rotor.mass_kg".into(),
        r.mass_kg,
        1e7,
        false,
        "the rotor mass",
    )?;
    at_least(
        "rotor.mass_kg",
        r.mass_kg,
        MIN_ROTOR_MASS_KG,
        "the rotor mass",
        "kg",
    )?;
    check_positive(
        || "rotor.service_speed_rpm".into(),
        r.service_speed_rpm,
        MAX_SPEED_RPM,
        false,
        "the service speed",
    )?;
    // The permissible unbalance 9549·G·m/n (method §5.2) was infinite for a
    // subnormal speed (fuzzing, session 15); no balanced rotor turns slower.
    at_least(
        "rotor.service_speed_rpm",
        r.service_speed_rpm,
        MIN_SERVICE_SPEED_RPM,
        "the service speed",
        "rpm",
    )?;
    if !GRADES.contains(&r.balance_grade.as_str()) {
        return Err(invalid(
            "rotor.balance_grade",
            format!(
                "'{}' is not an ISO 21940-11 grade; use one of {}",
                r.balance_grade,
                GRADES.join(", ")
            ),
        ));
    }
    Ok(())
}

/// Name, machine, rotor, planes and sensors; the planes' and sensors' id indices.
pub(super) fn check_setup(session: &Session) -> Result<(IdIndex<'_>, IdIndex<'_>), InputError> {
    check_text("name", &session.name, true)?;
    if let Some(m) = &session.machine {
        check_text("machine", m, false)?;
    }
    if let Some(r) = &session.rotor {
        check_rotor(r)?;
    }
    if session.planes.is_empty() {
        return Err(invalid("planes", "at least one correction plane is needed"));
    }
    let planes = unique_ids("planes", session.planes.iter().map(|p| p.id.as_str()))?;
    for (i, p) in session.planes.iter().enumerate() {
        if let Some(r) = p.radius_mm {
            check_positive(
                || format!("planes[{i}].radius_mm"),
                r,
                MAX_RADIUS_MM,
                false,
                "the radius",
            )?;
            at_least(
                &format!("planes[{i}].radius_mm"),
                r,
                MIN_RADIUS_MM,
                "the radius",
                "mm",
            )?;
        }
        if let Some(n) = p.positions {
            if !(2..=3600).contains(&n) {
                return Err(invalid(
                    format!("planes[{i}].positions"),
                    format!("2 to 3600 fixed places, got {n}"),
                ));
            }
        }
        crate::balancing::fit::places::check_plane(i, p)?;
    }
    if session.sensors.is_empty() {
        return Err(invalid("sensors", "at least one sensor is needed"));
    }
    let sensors = unique_ids("sensors", session.sensors.iter().map(|s| s.id.as_str()))?;
    for (i, s) in session.sensors.iter().enumerate() {
        if let Some(l) = &s.label {
            check_text(&format!("sensors[{i}].label"), l, false)?;
        }
    }
    Ok((planes, sensors))
}
