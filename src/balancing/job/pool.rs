//! A machine's influence coefficients pooled from several sessions (v2
//! "Machines"): every session's trial runs against its own reference run, one
//! influence matrix for all — `ΔY` and `T` stacked across sessions and
//! `W = ΔY T⁺` through the SVD (method 2.1) — with each coefficient's
//! covariance from the readings' noise. A session whose runs disagree with
//! what the other sessions' coefficients predict (the χ² test of
//! [`super::linear`], 99 %) is named in `coefficients_disagree`, and left out
//! with `exclude_disagreeing`.
//!
//! Rows are the (sensor, speed point) pairs that every session measured
//! (sensors by id, speeds within 1 %, the first session's speeds); planes are
//! matched by id (a plane a session lacks had no weight in it).

use nalgebra::{DMatrix, DVector, Matrix2};
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::checks;
use super::linear::{self, Data, Source, Trial};
use super::supplied::{covariance_frame, resolvable, unit_name};
use crate::balancing::error::InputError;
use crate::balancing::model::{Conventions, Session, SolveOptions, SuppliedCoefficient};
use crate::balancing::phasor::reading_out;
use crate::balancing::solution::Warning;
use crate::balancing::uncertainty::{noise_options, Noise};
use crate::balancing::validate::{check, Checked};

/// Options of a pooling.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct PoolOptions {
    /// Leave out the sessions named in `coefficients_disagree`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub exclude_disagreeing: Option<bool>,
    /// 1X amplitude repeatability, percent (default 2), where a reading has no samples.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amplitude_noise_pct: Option<f64>,
    /// 1X phase repeatability, degrees (default 2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub phase_noise_deg: Option<f64>,
}

/// A session compared with the others' coefficients.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct SessionCheck {
    pub session: String,
    pub consistent: bool,
    pub chi2: f64,
    pub dof: usize,
}

/// Pooled coefficients, in the first session's conventions.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Pooled {
    pub conventions: Conventions,
    /// Sessions whose runs were pooled.
    pub sessions: Vec<String>,
    /// Sessions left out by `exclude_disagreeing`.
    pub excluded: Vec<String>,
    pub influence_coefficients: Vec<SuppliedCoefficient>,
    pub checks: Vec<SessionCheck>,
    pub warnings: Vec<Warning>,
}

/// Pool the sessions `(id, session)`; errors name `sessions[i]` or `options.…`.
pub fn pool(sessions: &[(String, Session)], options: &PoolOptions) -> Result<Pooled, InputError> {
    check_options(sessions.len(), options)?;
    let checked = sessions
        .iter()
        .enumerate()
        .map(|(i, (_, s))| check(s).map_err(|e| e.under(&format!("sessions[{i}]"))))
        .collect::<Result<Vec<_>, _>>()?;
    let names: Vec<&str> = sessions.iter().map(|(id, _)| id.as_str()).collect();
    pool_checked(&names, &checked, options)
}

/// Most sessions one pool may list: the service reads each whole from the
/// database before the fit, so an unbounded list (a 4 MiB body holds
/// 400,000 ids) would tie up the request for minutes; `fieldbal
/// coefficients` reads as many files.
pub const MAX_POOLED_SESSIONS: usize = 1000;

/// The sessions a pool names, checked before any is read: 1 to
/// [`MAX_POOLED_SESSIONS`] of them, none named twice (it would count its
/// runs twice). The one rule of the service's pool (session ids) and of
/// `fieldbal coefficients` (file paths as given); errors name `sessions` or
/// `sessions[i]`, the second of a pair.
pub fn check_names<S: AsRef<str>>(names: &[S]) -> Result<(), InputError> {
    if names.is_empty() {
        return Err(no_session());
    }
    if names.len() > MAX_POOLED_SESSIONS {
        return Err(crate::balancing::limits::too_large(
            "sessions",
            "sessions to pool",
            names.len(),
            MAX_POOLED_SESSIONS,
        ));
    }
    let mut seen = std::collections::HashSet::with_capacity(names.len());
    for (i, s) in names.iter().enumerate() {
        let s = s.as_ref();
        if !seen.insert(s) {
            return Err(InputError::invalid(
                "duplicate_id",
                format!("sessions[{i}]"),
                format!("session '{s}' is listed twice"),
            ));
        }
    }
    Ok(())
}

/// One machine's sessions: a coefficient version is one machine's. Sessions
/// that name no machine pool with those that name one (`fieldbal
/// coefficients` pools files; the service pools only sessions of the
/// machine it stores the version under). The error names the first
/// session whose `machine` differs from an earlier one's.
fn check_one_machine(names: &[&str], checked: &[Checked<'_>]) -> Result<(), InputError> {
    let mut first: Option<(usize, &str)> = None;
    for (i, c) in checked.iter().enumerate() {
        let Some(m) = c.session.machine.as_deref() else {
            continue;
        };
        match first {
            None => first = Some((i, m)),
            Some((j, n)) if n != m => {
                return Err(InputError::invalid(
                    "other_machine",
                    format!("sessions[{i}].machine"),
                    format!(
                        "session '{}' is of machine '{m}' and session '{}' of '{n}': coefficients are pooled from one machine's sessions",
                        names.get(i).unwrap_or(&""),
                        names.get(j).unwrap_or(&"")
                    ),
                ))
            }
            Some(_) => {}
        }
    }
    Ok(())
}

fn no_session() -> InputError {
    InputError::invalid("invalid_value", "sessions", "list at least one session")
}

/// The errors of [`pool`] that come before the sessions' own: no session,
/// or bad noise options.
fn check_options(sessions: usize, options: &PoolOptions) -> Result<Noise, InputError> {
    if sessions == 0 {
        return Err(no_session());
    }
    noise_options(&SolveOptions {
        amplitude_noise_pct: options.amplitude_noise_pct,
        phase_noise_deg: options.phase_noise_deg,
        ..SolveOptions::default()
    })
}

/// [`pool`] of sessions their caller has already validated (`fieldbal
/// coefficients` validates each file as it reads it), named `names`: each
/// session is validated once.
pub fn pool_checked(
    names: &[&str],
    checked: &[Checked<'_>],
    options: &PoolOptions,
) -> Result<Pooled, InputError> {
    let noise = check_options(checked.len(), options)?;
    check_one_machine(names, checked)?;
    let first = &checked[0];
    let conv = first.conventions;
    // Rows of the first session found in every session: index per session.
    let mut rows: Vec<Vec<usize>> = Vec::new();
    for (a, row) in first.rows.iter().enumerate() {
        let sensor = &first.session.sensors[row.sensor].id;
        let found: Option<Vec<usize>> = checked
            .iter()
            .map(|c| {
                let point = c.point_of(row.speed_rpm)?;
                c.rows
                    .iter()
                    .position(|r| r.point == point && &c.session.sensors[r.sensor].id == sensor)
            })
            .collect();
        if let Some(f) = found {
            debug_assert_eq!(f[0], a);
            rows.push(f);
        }
    }
    if rows.is_empty() {
        return Err(InputError::invalid(
            "no_common_rows",
            "sessions",
            "the sessions have no sensor and speed in common to pool",
        ));
    }
    // A pooled coefficient is in its sensor's unit: one unit per sensor.
    for f in &rows {
        let sensor = &first.session.sensors[first.rows[f[0]].sensor];
        for (s, c) in checked.iter().enumerate().skip(1) {
            let unit = c.session.sensors[c.rows[f[s]].sensor].unit;
            if unit != sensor.unit {
                return Err(InputError::invalid(
                    "unit_mismatch",
                    format!("sessions[{s}]"),
                    format!(
                        "sensor '{}' reads in {} in session '{}' but in {} in session '{}': pooled coefficients are in one unit per sensor, so give the sensor the same unit (and its readings in it) in every session pooled",
                        sensor.id, unit_name(unit), names[s], unit_name(sensor.unit), names[0]
                    ),
                ));
            }
        }
    }
    let mut plane_ids: Vec<String> = Vec::new();
    for c in checked {
        for p in &c.session.planes {
            if !plane_ids.contains(&p.id) {
                plane_ids.push(p.id.clone());
            }
        }
    }
    // Merge the sessions' data on the common rows and planes.
    let n = rows.len();
    let mut cols: Vec<DVector<num_complex::Complex64>> = Vec::new();
    let mut cov: Vec<Vec<Matrix2<f64>>> = vec![Vec::new(); n];
    let mut trials = Vec::new();
    let mut owner = Vec::new();
    for (s, c) in checked.iter().enumerate() {
        let d = checks::data(c, noise);
        let base = cols.len();
        for m in 0..d.y.ncols() {
            cols.push(DVector::from_fn(n, |a, _| d.y[(rows[a][s], m)]));
            for (a, cv) in cov.iter_mut().enumerate() {
                cv.push(d.cov[rows[a][s]][m]);
            }
        }
        for tr in d.trials {
            let mut w = DVector::zeros(plane_ids.len());
            for (j, p) in c.session.planes.iter().enumerate() {
                let k = plane_ids
                    .iter()
                    .position(|x| x == &p.id)
                    .expect("plane listed");
                w[k] = tr.weights[j];
            }
            trials.push(Trial {
                col: base + tr.col,
                reference: base + tr.reference,
                weights: w,
            });
            owner.push(s);
        }
    }
    let data = Data {
        y: DMatrix::from_columns(&cols),
        cov,
        trials,
        planes: plane_ids.len(),
    };
    let all_rows: Vec<usize> = (0..n).collect();
    // Backward elimination: test every active session against the other
    // active ones; the worst inconsistent one is named and leaves the pool for
    // the next round (one changed rotor must not spoil the others' check).
    // Two sessions that disagree cannot be told apart: both are named.
    let test_one = |s: usize, active: &[usize]| -> Option<linear::Test> {
        let tested: Vec<usize> = (0..data.trials.len()).filter(|&k| owner[k] == s).collect();
        let others: Vec<usize> = (0..data.trials.len())
            .filter(|&k| owner[k] != s && active.contains(&owner[k]))
            .collect();
        if tested.is_empty() {
            return None;
        }
        let est = linear::estimate(&data, &others)?;
        Some(linear::test(
            &data,
            &tested,
            &all_rows,
            Source::Estimated(&est),
        ))
    };
    let mut active: Vec<usize> = (0..checked.len()).collect();
    let mut bad: Vec<usize> = Vec::new();
    let mut results: Vec<Option<linear::Test>> = vec![None; checked.len()];
    for _ in 0..checked.len() {
        let round: Vec<(usize, linear::Test)> = active
            .iter()
            .filter_map(|&s| test_one(s, &active).map(|t| (s, t)))
            .collect();
        for (s, t) in &round {
            results[*s] = Some(t.clone());
        }
        let worst = round
            .iter()
            .filter(|(_, t)| !t.consistent)
            .max_by(|(_, a), (_, b)| {
                let ra = a.chi2 / linear::chi2_quantile(a.dof);
                let rb = b.chi2 / linear::chi2_quantile(b.dof);
                ra.total_cmp(&rb)
            })
            .map(|(s, _)| *s);
        let Some(w) = worst else { break };
        if active.len() == 2 {
            bad.extend(active.iter().copied());
            break;
        }
        bad.push(w);
        active.retain(|&s| s != w);
    }
    bad.sort_unstable();
    let checks_out: Vec<SessionCheck> = results
        .iter()
        .enumerate()
        .filter_map(|(s, t)| {
            t.as_ref().map(|t| SessionCheck {
                session: names[s].to_string(),
                consistent: !bad.contains(&s),
                chi2: t.chi2,
                dof: t.dof,
            })
        })
        .collect();
    let mut warnings = Vec::new();
    if !bad.is_empty() {
        let quoted: Vec<String> = bad.iter().map(|&s| format!("'{}'", names[s])).collect();
        warnings.push(Warning {
            code: "coefficients_disagree".into(),
            message: format!(
                "session(s) {} disagree with the coefficients of the other sessions by more than the readings' noise explains: the rotor, its mounting or its speed may have changed, or a weight was typed wrong; pool with options.exclude_disagreeing to leave them out",
                quoted.join(", ")
            ),
            plane: None,
        });
    }
    // A session with no trial run has nothing to difference its reference
    // against: it adds nothing to the coefficients, though it is listed.
    for (s, name) in names.iter().enumerate() {
        if !owner.contains(&s) {
            warnings.push(Warning {
                code: "no_trial_runs".into(),
                message: format!(
                    "session '{name}' has no trial run (only its reference run), so it adds nothing to these coefficients; pool it once it has a trial run in each plane, or leave it out"
                ),
                plane: None,
            });
        }
    }
    let exclude = options.exclude_disagreeing.unwrap_or(false);
    let used: Vec<usize> = (0..checked.len())
        .filter(|s| !(exclude && bad.contains(s)))
        .collect();
    let set: Vec<usize> = (0..data.trials.len())
        .filter(|&k| used.contains(&owner[k]))
        .collect();
    let est = linear::estimate(&data, &set).ok_or_else(|| {
        InputError::invalid(
            "dependent_trials",
            "sessions",
            "the pooled trial runs do not give every plane an independent trial (or every session was left out)",
        )
    })?;
    let wcov = linear::covariance(&data, &est);
    let mut coefficients = Vec::with_capacity(n * plane_ids.len());
    for (a, r) in rows.iter().enumerate() {
        let row = &first.rows[r[0]];
        for (j, plane) in plane_ids.iter().enumerate() {
            let (amplitude_per_g, phase_deg) = reading_out(conv, est.w[(a, j)]);
            let c = covariance_frame(conv, &wcov[a][j]);
            let sensor = &first.session.sensors[row.sensor];
            coefficients.push(SuppliedCoefficient {
                speed_rpm: row.speed_rpm,
                sensor: sensor.id.clone(),
                unit: Some(sensor.unit),
                plane: plane.clone(),
                amplitude_per_g: resolvable(amplitude_per_g),
                phase_deg,
                covariance: Some([[c[(0, 0)], c[(0, 1)]], [c[(1, 0)], c[(1, 1)]]]),
            });
        }
    }
    // A plane whose trials moved no reading pools into zeros: every solve
    // with this version would warn plane_undetermined and every trial-weight
    // sizing refuse it, so say so where the version is made (session 21).
    for plane in &plane_ids {
        let mut its = coefficients.iter().filter(|c| &c.plane == plane);
        if its.all(|c| c.amplitude_per_g == 0.0) {
            warnings.push(Warning {
                code: "plane_undetermined".into(),
                message: format!(
                    "the pooled trial runs in plane {plane} changed no reading: its coefficients are 0 at every sensor and speed, so a solve with them cannot correct in {plane}. Pool a session whose trial in {plane} moved the vibration (a heavier weight, or at a larger radius)"
                ),
                plane: Some(plane.clone()),
            });
        }
    }
    Ok(Pooled {
        conventions: conv,
        sessions: used.iter().map(|&s| names[s].to_string()).collect(),
        excluded: (0..checked.len())
            .filter(|s| !used.contains(s))
            .map(|s| names[s].to_string())
            .collect(),
        influence_coefficients: coefficients,
        checks: checks_out,
        warnings,
    })
}

/// Coefficients from one phase convention to another (the angle direction
/// does not enter: 1 g at angle 0 is the same weight either way).
pub fn convert(
    coefficients: &[SuppliedCoefficient],
    from: Conventions,
    to: Conventions,
) -> Vec<SuppliedCoefficient> {
    use crate::balancing::phasor::reading_in;
    coefficients
        .iter()
        .map(|c| {
            let w = reading_in(from, c.amplitude_per_g, c.phase_deg);
            let (amplitude_per_g, phase_deg) = reading_out(to, w);
            let covariance = c.covariance.map(|m| {
                let m = Matrix2::new(m[0][0], m[0][1], m[1][0], m[1][1]);
                let m = covariance_frame(to, &covariance_frame(from, &m));
                [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]]
            });
            SuppliedCoefficient {
                amplitude_per_g: resolvable(amplitude_per_g),
                phase_deg,
                covariance,
                ..c.clone()
            }
        })
        .collect()
}

// Objects only: a positional array is refused (see `balancing::wire`).
crate::balancing::wire::objects_only!(PoolOptions);
