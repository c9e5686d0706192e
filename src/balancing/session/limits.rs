//! The size limits of a session and of solve options (contract v2 "Limits"):
//! every count that work or memory grows with is bounded, and checked before
//! anything is allocated in proportion to a product of counts.
//!
//! The limits are one process-wide setting: `fieldbal serve` may raise or
//! lower them once at start ([`Limits::configure`]); everything else (the
//! CLI, tests) uses the defaults. A global keeps every caller of the core
//! bounded, including endpoints that reach it through `validate::check`.

use std::sync::RwLock;

use crate::balancing::error::InputError;
use crate::balancing::model::{Session, SolveOptions};

/// Largest counts a session may have.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    pub planes: usize,
    pub sensors: usize,
    /// Speed points of the reference run (speeds more than 1 % apart).
    pub speed_points: usize,
    pub runs: usize,
    /// Readings over all runs.
    pub readings: usize,
    /// Repeated samples of one reading.
    pub samples_per_reading: usize,
    /// Repeated samples over all readings.
    pub samples: usize,
}

impl Limits {
    /// The documented defaults (README, "Settings").
    pub const DEFAULT: Limits = Limits {
        planes: 64,
        sensors: 256,
        speed_points: 200,
        runs: 200,
        readings: 50_000,
        samples_per_reading: 1_000,
        samples: 200_000,
    };

    /// The limits in force in this process.
    pub fn current() -> Limits {
        *LIMITS.read().unwrap_or_else(|e| e.into_inner())
    }

    /// Set the limits of this process (`fieldbal serve` at start).
    pub fn configure(limits: Limits) {
        *LIMITS.write().unwrap_or_else(|e| e.into_inner()) = limits;
    }
}

impl Default for Limits {
    fn default() -> Self {
        Limits::DEFAULT
    }
}

static LIMITS: RwLock<Limits> = RwLock::new(Limits::DEFAULT);

/// Longest list of `row_weights`: each row is matched against every entry.
pub const MAX_ROW_WEIGHTS: usize = 1_000;

/// The contract's `too_large` error: `what` has `n`, the limit is `limit`.
pub fn too_large(field: impl Into<String>, what: &str, n: usize, limit: usize) -> InputError {
    InputError::invalid(
        "too_large",
        field,
        format!("{what}: {n} given, the limit is {limit}"),
    )
}

fn at_most(field: &str, what: &str, n: usize, limit: usize) -> Result<(), InputError> {
    at_most_at(|| field.to_string(), what, n, limit)
}

/// `at_most` for a field path that is built only when the count is over: the
/// checks below run on every reading of every request.
fn at_most_at(
    field: impl FnOnce() -> String,
    what: &str,
    n: usize,
    limit: usize,
) -> Result<(), InputError> {
    if n > limit {
        return Err(too_large(field(), what, n, limit));
    }
    Ok(())
}

/// Check every count of a session that is known without pairing readings
/// (speed points are checked by `validate` once the reference run's speeds
/// are clustered). Linear in the length of the lists, allocates nothing.
pub fn check_session(session: &Session, limits: &Limits) -> Result<(), InputError> {
    at_most("planes", "planes", session.planes.len(), limits.planes)?;
    at_most("sensors", "sensors", session.sensors.len(), limits.sensors)?;
    at_most("runs", "runs", session.runs.len(), limits.runs)?;
    let mut readings = 0usize;
    let mut samples = 0usize;
    for (i, run) in session.runs.iter().enumerate() {
        readings += run.readings.len();
        if readings > limits.readings {
            return Err(too_large(
                format!("runs[{i}].readings"),
                "readings over all runs",
                session.runs.iter().map(|r| r.readings.len()).sum(),
                limits.readings,
            ));
        }
        // A weight per plane is all a run can mean; more only costs time.
        let weights = run.weights.len();
        let weight_limit = limits.planes.max(1) * 16;
        at_most_at(
            || format!("runs[{i}].weights"),
            "weights in one run",
            weights,
            weight_limit,
        )?;
        for (j, r) in run.readings.iter().enumerate() {
            let n = r.samples.as_ref().map_or(0, Vec::len);
            at_most_at(
                || format!("runs[{i}].readings[{j}].samples"),
                "samples of one reading",
                n,
                limits.samples_per_reading,
            )?;
            samples += n;
            if samples > limits.samples {
                return Err(too_large(
                    format!("runs[{i}].readings[{j}].samples"),
                    "samples over all readings",
                    samples,
                    limits.samples,
                ));
            }
        }
    }
    Ok(())
}

/// Check the lengths of the option lists: each is matched against the rows
/// or ids of the session, so an unbounded list costs time in proportion to a
/// product.
pub fn check_options(options: &SolveOptions, limits: &Limits) -> Result<(), InputError> {
    if let Some(s) = &options.speeds_rpm {
        at_most("options.speeds_rpm", "speeds", s.len(), limits.speed_points)?;
    }
    if let Some(s) = &options.sensors {
        at_most("options.sensors", "sensors", s.len(), limits.sensors)?;
    }
    if let Some(p) = &options.planes {
        at_most("options.planes", "planes", p.len(), limits.planes)?;
    }
    if let Some(m) = &options.max_mass_g {
        at_most("options.max_mass_g", "planes", m.len(), limits.planes)?;
    }
    if let Some(r) = &options.row_weights {
        at_most(
            "options.row_weights",
            "row weights",
            r.len(),
            MAX_ROW_WEIGHTS,
        )?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    // Built from JSON so that fields other helpers add to `Session` do not break it.
    fn session(planes: usize, sensors: usize, runs: usize) -> Session {
        let planes: Vec<_> = (0..planes)
            .map(|i| serde_json::json!({"id": format!("P{i}")}))
            .collect();
        let sensors: Vec<_> = (0..sensors)
            .map(|i| serde_json::json!({"id": format!("S{i}"), "unit": "um_pp"}))
            .collect();
        let runs: Vec<_> = (0..runs)
            .map(|i| serde_json::json!({"id": format!("R{i}"), "weights": [], "readings": []}))
            .collect();
        serde_json::from_value(serde_json::json!({
            "name": "n", "planes": planes, "sensors": sensors, "runs": runs
        }))
        .expect("a session")
    }

    #[test]
    fn each_count_over_its_limit_is_named_with_the_limit() {
        let l = Limits::DEFAULT;
        let cases = [
            (session(l.planes + 1, 1, 1), "planes"),
            (session(1, l.sensors + 1, 1), "sensors"),
            (session(1, 1, l.runs + 1), "runs"),
        ];
        for (s, field) in cases {
            let e = check_session(&s, &l).unwrap_err();
            assert_eq!(e.code, "too_large");
            assert_eq!(e.field.as_deref(), Some(field));
            assert!(e.message.contains("the limit is"), "{}", e.message);
        }
    }

    #[test]
    fn counts_at_the_limit_pass() {
        let l = Limits::DEFAULT;
        assert!(check_session(&session(l.planes, l.sensors, l.runs), &l).is_ok());
    }
}
