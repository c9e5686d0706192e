//! A solve's `coefficients_from` (v2 "Coefficients supplied or stored"): a
//! machine's stored coefficient version read from the database and put into
//! the options as `influence_coefficients`, for `POST /api/v1/solve`, a stored
//! session's solutions and trial weights.

use crate::balancing::job::pool::{self, Pooled};
use crate::balancing::job::supplied::unit_name;
use crate::balancing::job::trim;
use crate::balancing::model::{Session, SolveOptions};
use crate::balancing::InputError;
use crate::db::machines::{self, Missing};
use crate::http::error::ApiError;
use crate::http::AppState;

/// Resolve a solve's `coefficients_from` into `influence_coefficients` in the
/// conventions of `session` (the one to be solved), and name the version used.
/// `name_field` puts the option paths (`options.coefficients_from.…`) in terms
/// of the posted body.
pub async fn resolve(
    state: &AppState,
    session: &Session,
    options: SolveOptions,
    name_field: fn(InputError) -> InputError,
) -> Result<SolveOptions, ApiError> {
    // A trim job whose options name no coefficients is solved with the
    // trim's; errors then name the trim's fields.
    let (mut options, from_trim) = match trim::options_for(session, &options) {
        Some(with_trim) => (with_trim, true),
        None => (options, false),
    };
    // The trim's machine is looked up only once the trim could name one (as
    // a session is stored): an id no machine could have is that, not unknown.
    if let Some(t) = session.trim.as_ref().filter(|_| from_trim) {
        crate::balancing::validate::check_trim_source(t)
            .map_err(|e| ApiError::from(name_field(e)))?;
    }
    let Some(from) = options.coefficients_from.clone() else {
        return Ok(options);
    };
    let conventions = session.conventions.unwrap_or_default();
    let fail = |e: InputError| -> ApiError {
        name_field(if from_trim { trim::named_in_trim(e) } else { e }).into()
    };
    // The core's rule (not both ways of giving coefficients, a version
    // from 1), as `fieldbal solve` applies it.
    crate::balancing::job::check_coefficients_from(&options).map_err(fail)?;
    let stored = match machines::coefficients(&state.db, &from.machine, from.version).await? {
        Ok(s) => s,
        Err(Missing::Machine) => {
            return Err(fail(InputError::invalid(
                "unknown_machine",
                "options.coefficients_from.machine",
                format!("no machine has the id '{}'", from.machine),
            )))
        }
        Err(Missing::Version) => {
            return Err(fail(InputError::invalid(
                "unknown_version",
                "options.coefficients_from.version",
                format!(
                    "machine '{}' has no coefficient version {}",
                    from.machine,
                    from.version.unwrap_or_default()
                ),
            )))
        }
        Err(Missing::Retired(last)) => {
            return Err(fail(InputError::invalid(
                "unknown_version",
                "options.coefficients_from.version",
                super::machines::retired_version(
                    &from.machine,
                    from.version.unwrap_or_default(),
                    last,
                ),
            )))
        }
        Err(Missing::NoVersions) => {
            return Err(fail(InputError::invalid(
                "unknown_version",
                "options.coefficients_from.machine",
                format!("machine '{}' has no stored coefficients yet", from.machine),
            )))
        }
    };
    let mut body = stored.body.clone();
    body.insert("sessions".into(), serde_json::json!(stored.sessions));
    let pooled: Pooled = serde_json::from_value(serde_json::Value::Object(body))
        .map_err(|e| ApiError::internal(&e))?;
    // Stored coefficients are in their sensors' units: a session that reads
    // a sensor in another unit would get a correction off by their ratio.
    for c in &pooled.influence_coefficients {
        let (Some(unit), Some(sensor)) =
            (c.unit, session.sensors.iter().find(|s| s.id == c.sensor))
        else {
            continue;
        };
        if unit != sensor.unit {
            return Err(fail(InputError::invalid(
                "unit_mismatch",
                "options.coefficients_from",
                format!(
                    "machine '{}' coefficient version {} is in {} per gram for sensor '{}', which this session reads in {}: give the sensor that unit (and its readings in it), or pool coefficients from sessions in {}",
                    from.machine,
                    stored.version,
                    unit_name(unit),
                    c.sensor,
                    unit_name(sensor.unit),
                    unit_name(sensor.unit)
                ),
            )));
        }
    }
    options.influence_coefficients = Some(pool::convert(
        &pooled.influence_coefficients,
        pooled.conventions,
        conventions,
    ));
    options.coefficients_from = Some(crate::balancing::model::CoefficientsFrom {
        machine: from.machine,
        version: Some(stored.version),
    });
    Ok(options)
}
