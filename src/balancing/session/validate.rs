//! Validation: a wire `Session` becomes a `Checked` session whose readings are
//! paired into rows and turned into internal phasors, or an error naming the field.
//!
//! Everything the contract requires is checked here except solvability (the rank
//! of the trial weights), which `influence` checks when solving, because a stored
//! session may still be waiting for its trial runs.

use std::collections::HashMap;

use nalgebra::DMatrix;
use num_complex::Complex64;

use crate::balancing::error::InputError;
use crate::balancing::limits::{check_session, too_large, Limits};
use crate::balancing::model::{Conventions, Reading, Rotor, Session};
use crate::balancing::phasor::{reading_in, weight_in};

/// Speeds closer than this (relative) are the same speed point (contract).
pub const SPEED_TOLERANCE: f64 = 0.01;
const MAX_SPEED_RPM: f64 = 1e6;
const MAX_AMPLITUDE: f64 = 1e9;
/// Smallest non-zero amplitude: no instrument resolves 1e-9 of its unit, and
/// far smaller ones (1e-100) underflow when squared twice in the 95 % figures.
const MIN_AMPLITUDE: f64 = 1e-9;
const MAX_MASS_G: f64 = 1e7;
const MAX_RADIUS_MM: f64 = 1e5;
const MAX_ANGLE_DEG: f64 = 1e6;
const MAX_TEXT: usize = 200;
/// ISO 21940-11 balance grades G, mm/s (method 5.2).
pub const GRADES: [&str; 11] = [
    "G0.4", "G1", "G2.5", "G6.3", "G16", "G40", "G100", "G250", "G630", "G1600", "G4000",
];

/// Position of each id in its list.
type IdIndex<'s> = HashMap<&'s str, usize>;

/// One (speed point, sensor) pair measured in the reference run.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// Index into `Checked::points`.
    pub point: usize,
    /// Index into `session.sensors`.
    pub sensor: usize,
    /// Speed of the reference reading, rpm.
    pub speed_rpm: f64,
    /// For each run of `Checked::runs`, the index of its reading in `runs[r].readings`.
    pub readings: Vec<usize>,
}

/// A session that passed validation, in the internal frame.
#[derive(Debug, Clone)]
pub struct Checked<'a> {
    pub session: &'a Session,
    pub conventions: Conventions,
    /// Speed points: the reference run's speeds, clustered within 1 %, ascending.
    /// Each point is the list of reference speeds that fall in it.
    pub points: Vec<Vec<f64>>,
    /// Rows ordered by speed point, then by sensor as listed in the session.
    pub rows: Vec<Row>,
    /// Indices into `session.runs`: the reference run first, then the trial runs in order.
    pub runs: Vec<usize>,
    /// Readings, rows × runs (column 0 is the reference `Y0`), internal phasors.
    pub y: DMatrix<Complex64>,
    /// Weights, planes × trial runs (`T` of method 2.1), internal frame, grams.
    pub t: DMatrix<Complex64>,
}

impl Checked<'_> {
    /// The index of the speed point `speed` falls in, if any.
    pub fn point_of(&self, speed: f64) -> Option<usize> {
        nearest_point(&self.points, speed)
    }

    /// The reading of run `k` (index into `self.runs`) for row `a`.
    pub fn reading(&self, a: usize, k: usize) -> &Reading {
        &self.session.runs[self.runs[k]].readings[self.rows[a].readings[k]]
    }
}

fn invalid(field: impl Into<String>, message: impl Into<String>) -> InputError {
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
fn check_positive(
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
        return Err(invalid(field(), format!("{what} must be {bound}, got {x}")));
    }
    if x > max {
        return Err(invalid(
            field(),
            format!("{what} of {x} is beyond the plausible limit of {max}"),
        ));
    }
    Ok(())
}

/// An amplitude: 0, or from [`MIN_AMPLITUDE`] to [`MAX_AMPLITUDE`].
fn check_amplitude(field: impl Fn() -> String, x: f64) -> Result<(), InputError> {
    check_positive(&field, x, MAX_AMPLITUDE, true, "the amplitude")?;
    if x != 0.0 && x < MIN_AMPLITUDE {
        return Err(invalid(
            field(),
            format!("the amplitude {x} is below {MIN_AMPLITUDE} of its unit, which no instrument resolves: give 0 for no vibration, or use a smaller unit"),
        ));
    }
    Ok(())
}

fn check_angle(field: impl FnOnce() -> String, x: f64) -> Result<(), InputError> {
    if !x.is_finite() || x.abs() > MAX_ANGLE_DEG {
        return Err(invalid(
            field(),
            format!("an angle in degrees must be finite and within ±{MAX_ANGLE_DEG}"),
        ));
    }
    Ok(())
}

/// Index of an id in a list, checking uniqueness of the list as it goes.
fn unique_ids<'s>(
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

/// Cluster sorted speeds: a new point starts where a speed is more than 1 % above the point's lowest.
fn cluster_speeds(mut speeds: Vec<f64>) -> Vec<Vec<f64>> {
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    let mut points: Vec<Vec<f64>> = Vec::new();
    for s in speeds {
        match points.last_mut() {
            Some(p) if s <= p[0] * (1.0 + SPEED_TOLERANCE) => p.push(s),
            _ => points.push(vec![s]),
        }
    }
    points
}

/// The point with a member speed within 1 % of `speed`, the nearest one if several.
///
/// Members are sorted across points (clusters do not overlap), and the relative
/// distance `|speed − m| / m` falls as `m` rises towards `speed` from below and
/// grows as `m` rises above it, so only the two members around `speed` can be
/// nearest: a binary search, O(log speeds) per reading.
fn nearest_point(points: &[Vec<f64>], speed: f64) -> Option<usize> {
    // Points whose lowest member is <= speed: the last of them holds the member below.
    let p = points.partition_point(|members| members[0] <= speed);
    let below = p.checked_sub(1).map(|q| {
        let k = points[q].partition_point(|&m| m <= speed);
        (q, points[q][k - 1])
    });
    let above = match below {
        Some((q, _)) => {
            let k = points[q].partition_point(|&m| m < speed);
            points[q]
                .get(k)
                .map(|&m| (q, m))
                .or_else(|| points.get(q + 1).map(|n| (q + 1, n[0])))
        }
        None => points.first().map(|n| (0, n[0])),
    };
    let mut best: Option<(usize, f64)> = None;
    for (q, m) in below.into_iter().chain(above) {
        let rel = (speed - m).abs() / m;
        if rel <= SPEED_TOLERANCE * (1.0 + 1e-12) && best.is_none_or(|(_, r)| rel < r) {
            best = Some((q, rel));
        }
    }
    best.map(|(q, _)| q)
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
    check_positive(
        || "rotor.service_speed_rpm".into(),
        r.service_speed_rpm,
        MAX_SPEED_RPM,
        false,
        "the service speed",
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

fn check_setup(session: &Session) -> Result<(IdIndex<'_>, IdIndex<'_>), InputError> {
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

/// Check one reading and find its sensor; `hint` is the sensor index to try
/// first (readings usually list the sensors in order, and comparing one id is
/// far cheaper than hashing it: issue 15).
fn check_reading(
    f: &dyn Fn() -> String,
    r: &Reading,
    sensors: &HashMap<&str, usize>,
    ids: &[crate::balancing::model::Sensor],
    hint: usize,
) -> Result<usize, InputError> {
    check_positive(
        || format!("{}.speed_rpm", f()),
        r.speed_rpm,
        MAX_SPEED_RPM,
        false,
        "the speed",
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
            return Err(invalid(
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

/// Validate a session and bring it into the internal frame.
pub fn check(session: &Session) -> Result<Checked<'_>, InputError> {
    // Counts first: nothing below allocates more than the lists' lengths allow.
    let limits = Limits::current();
    check_session(session, &limits)?;
    let conventions = session.conventions.unwrap_or_default();
    let (planes, sensors) = check_setup(session)?;
    // Runout vectors (v2), subtracted from the readings below.
    let runout = crate::balancing::job::runout::vectors(session, conventions)?;
    unique_ids("runs", session.runs.iter().map(|r| r.id.as_str()))?;

    // Per-field checks of every run, and the reference run.
    let mut reference: Option<usize> = None;
    let mut sensor_of: Vec<Vec<usize>> = Vec::with_capacity(session.runs.len());
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
            check_angle(|| format!("{}.angle_deg", f()), w.angle_deg)?;
        }
        let mut s = Vec::with_capacity(run.readings.len());
        let mut hint = 0;
        for (j, r) in run.readings.iter().enumerate() {
            let f = || format!("runs[{i}].readings[{j}]");
            let sensor = check_reading(&f, r, &sensors, &session.sensors, hint)?;
            hint = sensor + 1;
            s.push(sensor);
        }
        sensor_of.push(s);
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
    let ref_run = &session.runs[reference];
    if ref_run.readings.is_empty() {
        return Err(invalid(
            format!("runs[{reference}].readings"),
            "the reference run needs at least one reading",
        ));
    }

    let points = cluster_speeds(ref_run.readings.iter().map(|r| r.speed_rpm).collect());
    if points.len() > limits.speed_points {
        return Err(too_large(
            format!("runs[{reference}].readings"),
            "speed points (speeds more than 1 % apart) in the reference run",
            points.len(),
            limits.speed_points,
        ));
    }
    let runs: Vec<usize> = std::iter::once(reference)
        .chain((0..session.runs.len()).filter(|&i| i != reference))
        .collect();

    // Pair readings: (point, sensor) -> reading index, per run.
    // No chaining (issue 12): every point, all runs together, spans at most 1 %
    // from its lowest to its highest speed. `span` starts as the reference's
    // speeds; in session order, the first reading that would stretch it further
    // is rejected, so a speed 1 % from another sensor's is never paired with a
    // reading 2 % away.
    let mut span: Vec<(f64, f64)> = points.iter().map(|p| (p[0], p[p.len() - 1])).collect();
    // (point, sensor) cells, dense: at most `speed_points × sensors` of them
    // (the limits), and an index is cheaper than hashing the pair (issue 15).
    // `seen[cell]` is the last run (its position in `runs`, plus 1) that had
    // a reading there, and that reading: a repeat within a run is a duplicate.
    let nsens = session.sensors.len();
    let mut seen: Vec<(u32, u32)> = vec![(0, 0); points.len() * nsens];
    // Per run (in `runs` order), the cell of each reading.
    let mut cells: Vec<Vec<u32>> = Vec::with_capacity(runs.len());
    for (k, &i) in runs.iter().enumerate() {
        let stamp = k as u32 + 1;
        let mut of = Vec::with_capacity(session.runs[i].readings.len());
        // The point of the previous reading's speed: the sensors of one speed
        // usually follow each other, and the search is a function of the speed.
        let mut last: Option<(f64, usize)> = None;
        for (j, r) in session.runs[i].readings.iter().enumerate() {
            let f = || format!("runs[{i}].readings[{j}]");
            let point = match last {
                Some((speed, p)) if speed == r.speed_rpm => p,
                _ => nearest_point(&points, r.speed_rpm).ok_or_else(|| {
                    InputError::invalid("unpaired_reading", format!("{}.speed_rpm", f()), format!("the reference run has no reading within 1 % of {} rpm to pair this one with", r.speed_rpm))
                })?,
            };
            last = Some((r.speed_rpm, point));
            let (lo, hi) = span[point];
            let (lo, hi) = (lo.min(r.speed_rpm), hi.max(r.speed_rpm));
            if hi > lo * (1.0 + SPEED_TOLERANCE) * (1.0 + 1e-12) {
                return Err(InputError::invalid("unpaired_reading", format!("{}.speed_rpm", f()), format!("{} rpm would put readings from {lo} to {hi} rpm, more than 1 % apart, in one speed point: readings are paired only when all the speeds of a point lie within 1 % of each other", r.speed_rpm)));
            }
            span[point] = (lo, hi);
            let cell = point * nsens + sensor_of[i][j];
            let (run, prior) = seen[cell];
            if run == stamp {
                return Err(InputError::invalid(
                    "duplicate_reading",
                    f(),
                    format!("run '{}' already has a reading of sensor '{}' at this speed (readings[{prior}]); put repeated readings in `samples`", session.runs[i].id, r.sensor),
                ));
            }
            seen[cell] = (stamp, j as u32);
            of.push(cell as u32);
        }
        cells.push(of);
    }

    // Rows: the reference run's cells in (point, sensor) order; `row_of[cell]`
    // is the row's index plus 1 (0: the reference has no reading there).
    let mut keys: Vec<(u32, usize)> = cells[0].iter().enumerate().map(|(j, &c)| (c, j)).collect();
    keys.sort_unstable();
    let mut row_of = vec![0u32; points.len() * nsens];
    let mut rows = Vec::with_capacity(keys.len());
    for (a, &(cell, j)) in keys.iter().enumerate() {
        row_of[cell as usize] = a as u32 + 1;
        let mut readings = vec![usize::MAX; runs.len()];
        readings[0] = j;
        rows.push(Row {
            point: cell as usize / nsens,
            sensor: cell as usize % nsens,
            speed_rpm: ref_run.readings[j].speed_rpm,
            readings,
        });
    }
    // A trial reading of a cell the reference lacks cannot be paired; it is
    // reported after any reading a row misses, as before.
    let mut unpaired: Option<(usize, usize)> = None;
    for (k, of) in cells.iter().enumerate().skip(1) {
        for (j, &cell) in of.iter().enumerate() {
            match row_of[cell as usize] {
                0 => {
                    unpaired.get_or_insert((runs[k], j));
                }
                a => rows[a as usize - 1].readings[k] = j,
            }
        }
    }
    for row in &rows {
        if let Some(k) = row.readings.iter().position(|&j| j == usize::MAX) {
            let i = runs[k];
            return Err(InputError::invalid(
                "missing_reading",
                format!("runs[{i}].readings"),
                format!(
                    "run '{}' has no reading of sensor '{}' at {} rpm, which the reference run has",
                    session.runs[i].id, session.sensors[row.sensor].id, row.speed_rpm
                ),
            ));
        }
    }
    if let Some((i, j)) = unpaired {
        return Err(InputError::invalid(
            "unpaired_reading",
            format!("runs[{i}].readings[{j}]"),
            "the reference run has no reading of this sensor at this speed to pair this one with",
        ));
    }

    let y = DMatrix::from_fn(rows.len(), runs.len(), |a, k| {
        let r = &session.runs[runs[k]].readings[rows[a].readings[k]];
        let sensor = rows[a].sensor;
        reading_in(conventions, r.amplitude, r.phase_deg) - runout[sensor].unwrap_or_default()
    });
    let mut t = DMatrix::zeros(session.planes.len(), runs.len() - 1);
    for (k, &i) in runs.iter().enumerate().skip(1) {
        for w in &session.runs[i].weights {
            t[(planes[w.plane.as_str()], k - 1)] += weight_in(conventions, w.mass_g, w.angle_deg);
        }
    }
    Ok(Checked {
        session,
        conventions,
        points,
        rows,
        runs,
        y,
        t,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The scan over every member that the binary search replaced.
    fn nearest_by_scan(points: &[Vec<f64>], speed: f64) -> Option<usize> {
        let mut best: Option<(usize, f64)> = None;
        for (p, members) in points.iter().enumerate() {
            for &m in members {
                let rel = (speed - m).abs() / m;
                if rel <= SPEED_TOLERANCE * (1.0 + 1e-12) && best.is_none_or(|(_, r)| rel < r) {
                    best = Some((p, rel));
                }
            }
        }
        best.map(|(p, _)| p)
    }

    #[test]
    fn the_binary_search_finds_the_point_the_full_scan_finds() {
        let speeds = vec![
            1000.0, 1004.0, 1009.0, 1012.0, 1019.0, 1500.0, 1503.0, 3000.0, 3029.0, 3031.0,
        ];
        let points = cluster_speeds(speeds);
        let mut s = 900.0;
        while s < 3200.0 {
            assert_eq!(
                nearest_point(&points, s),
                nearest_by_scan(&points, s),
                "{s}"
            );
            s += 0.37;
        }
    }
}
