//! A trim job's `trim` (the coefficients it is to be solved with) and each
//! run's `purpose`: records for the client that reopens a job, stored and
//! given back unchanged, so checked only for what would make them mean nothing.

use super::fields::{check_machine_id, invalid};
use super::IdIndex;
use crate::balancing::error::InputError;
use crate::balancing::job::supplied::{check_entry, check_unit};
use crate::balancing::model::{Session, Trim};

/// The trim's source, as it must be before a machine's coefficients are read
/// for it (the service reads them before it solves): exactly one source,
/// naming a machine id a machine could have and a version from 1, or a list
/// that is not empty.
pub fn check_source(trim: &Trim) -> Result<(), InputError> {
    match (&trim.coefficients_from, &trim.influence_coefficients) {
        (Some(from), None) => {
            check_machine_id(|| "trim.coefficients_from.machine".into(), &from.machine)?;
            if let Some(v) = from.version.filter(|&v| v < 1) {
                return Err(InputError::invalid(
                    "out_of_range",
                    "trim.coefficients_from.version",
                    version_below_one(v),
                ));
            }
            Ok(())
        }
        (None, Some(list)) if list.is_empty() => Err(invalid(
            "trim.influence_coefficients",
            "list the coefficients, or leave trim out",
        )),
        (None, Some(_)) => Ok(()),
        _ => Err(invalid(
            "trim",
            "give either coefficients_from or influence_coefficients",
        )),
    }
}

/// Exactly one source of coefficients, naming a machine or listing known
/// planes' and sensors' coefficients.
pub(super) fn check_trim(
    session: &Session,
    trim: &Trim,
    planes: &IdIndex<'_>,
    sensors: &IdIndex<'_>,
) -> Result<(), InputError> {
    check_source(trim)?;
    match &trim.influence_coefficients {
        Some(list) => {
            for (k, c) in list.iter().enumerate() {
                let f = |what: &str| format!("trim.influence_coefficients[{k}].{what}");
                if !planes.contains_key(c.plane.as_str()) {
                    return Err(invalid(
                        f("plane"),
                        format!("no plane has the id '{}'", c.plane),
                    ));
                }
                let Some(&s) = sensors.get(c.sensor.as_str()) else {
                    return Err(invalid(
                        f("sensor"),
                        format!("no sensor has the id '{}'", c.sensor),
                    ));
                };
                // What the solve option refuses is not stored: a client
                // sends these back as that option (session 21).
                check_unit(|| f("unit"), c.unit, &c.sensor, session.sensors[s].unit)?;
                // Its numbers by the solve option's rule: a client sends
                // these back as that option.
                check_entry("trim.influence_coefficients", k, c)?;
            }
            Ok(())
        }
        None => Ok(()),
    }
}

/// A `purpose` only on runs with weights: the reference run is neither a
/// trial nor a check.
pub(super) fn check_purposes(session: &Session) -> Result<(), InputError> {
    for (i, run) in session.runs.iter().enumerate() {
        if run.purpose.is_some() && run.weights.is_empty() {
            return Err(invalid(
                format!("runs[{i}].purpose"),
                format!("run '{}' has no weights: it is the reference run (the rotor as found), neither a trial nor a check; leave purpose out, or list the weights on the rotor during it", run.id),
            ));
        }
    }
    Ok(())
}

/// Why a coefficient version below 1 is refused (`out_of_range`), in the
/// words every place that takes a version uses: a machine's coefficients
/// (`?version=`), a solve's `coefficients_from` and a trim job's.
pub fn version_below_one(v: i64) -> String {
    format!("versions are numbered from 1; this one is {v}")
}
