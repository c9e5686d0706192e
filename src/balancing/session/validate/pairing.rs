//! Pairing readings into rows: the reference run's speeds clustered into
//! speed points, every reading placed in its (speed point, sensor) cell, and
//! the rows with their readings in the internal frame (`Y`, method 2.1).
//!
//! Cells are dense indices, `point × sensors + sensor` (at most
//! `speed_points × sensors` of them, the limits), cheaper than hashing the
//! pair; the readings' cells overwrite their sensor indices in place, so
//! nothing is allocated per reading (issue 15).

use nalgebra::DMatrix;
use num_complex::Complex64;

use super::runs::RunFields;
use super::{Row, SPEED_TOLERANCE};
use crate::balancing::error::InputError;
use crate::balancing::model::{Conventions, Session};
use crate::balancing::phasor::reading_in;

mod unpaired;
use unpaired::reference_read;

/// Cluster sorted speeds: a new point starts where a speed is more than 1 % above the point's lowest.
pub(super) fn cluster_speeds(mut speeds: Vec<f64>) -> Vec<Vec<f64>> {
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
pub(super) fn nearest_point(points: &[Vec<f64>], speed: f64) -> Option<usize> {
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

/// Place every reading of run `i = runs[k]` in its cell, in place of its
/// sensor index in `cells`; `k + 1` stamps the run in `seen`. No chaining (issue 12): every point, all runs together, spans
/// at most 1 % from its lowest to its highest speed. `span` starts as the
/// reference's speeds; in `runs` order, the first reading that would stretch
/// it further is rejected, so a speed 1 % from another sensor's is never
/// paired with a reading 2 % away. `seen[cell]` is the last run (`stamp`) that
/// had a reading there, and that reading: a repeat within a run is a duplicate.
fn place_run(
    session: &Session,
    runs: &[usize],
    k: usize,
    points: &[Vec<f64>],
    span: &mut [(f64, f64)],
    seen: &mut [(u32, u32)],
    cells: &mut [u32],
) -> Result<(), InputError> {
    let nsens = session.sensors.len();
    let (i, stamp) = (runs[k], k as u32 + 1);
    // The point of the previous reading's speed: the sensors of one speed
    // usually follow each other, and the search is a function of the speed.
    // A repeated speed is in its point's span already (spans only grow, and
    // each growth was checked), so only a new speed is searched and checked.
    let mut last: Option<(f64, usize)> = None;
    for (j, r) in session.runs[i].readings.iter().enumerate() {
        let f = || format!("runs[{i}].readings[{j}]");
        let point = match last {
            Some((speed, p)) if speed == r.speed_rpm => p,
            _ => {
                let point = nearest_point(points, r.speed_rpm).ok_or_else(|| {
                    let read = reference_read(session, runs[0], &r.sensor, r.speed_rpm);
                    InputError::invalid("unpaired_reading", format!("{}.speed_rpm", f()), format!("the reference run has no reading within 1 % of {} rpm to pair this one with{read}", r.speed_rpm))
                })?;
                let (lo, hi) = span[point];
                let (lo, hi) = (lo.min(r.speed_rpm), hi.max(r.speed_rpm));
                if hi > lo * (1.0 + SPEED_TOLERANCE) * (1.0 + 1e-12) {
                    return Err(InputError::invalid("unpaired_reading", format!("{}.speed_rpm", f()), format!("{} rpm would put readings from {lo} to {hi} rpm, more than 1 % apart, in one speed point: readings are paired only when all the speeds of a point lie within 1 % of each other", r.speed_rpm)));
                }
                span[point] = (lo, hi);
                last = Some((r.speed_rpm, point));
                point
            }
        };
        let cell = point * nsens + cells[j] as usize;
        let (run, prior) = seen[cell];
        if run == stamp {
            return Err(InputError::invalid(
                "duplicate_reading",
                f(),
                format!("run '{}' already has a reading of sensor '{}' at this speed (readings[{prior}]); put repeated readings in `samples`", session.runs[i].id, r.sensor),
            ));
        }
        seen[cell] = (stamp, j as u32);
        cells[j] = cell as u32;
    }
    Ok(())
}

/// The paired rows: rows ordered by (point, sensor), the reading index of
/// every row and run (runs × rows, a run's rows together) and `Y` (rows × runs).
pub(super) struct Paired {
    pub rows: Vec<Row>,
    pub index: Vec<u32>,
    pub y: DMatrix<Complex64>,
}

/// Pair the readings of every run (`runs`: the reference first) into rows,
/// and form `Y` with each sensor's runout subtracted. Errors in pairing come
/// run by run in `runs` order; then a reading a row misses (first row, first
/// run), then a trial reading of a cell the reference lacks.
pub(super) fn pair(
    session: &Session,
    conventions: Conventions,
    points: &[Vec<f64>],
    runs: &[usize],
    mut fields: RunFields,
    runout: &[Option<Complex64>],
) -> Result<Paired, InputError> {
    let nsens = session.sensors.len();
    let ncells = points.len() * nsens;
    let mut span: Vec<(f64, f64)> = points.iter().map(|p| (p[0], p[p.len() - 1])).collect();
    let mut seen: Vec<(u32, u32)> = vec![(0, 0); ncells];
    let range = |i: usize| {
        let start = fields.start[i];
        start..start + session.runs[i].readings.len()
    };
    for (k, &i) in runs.iter().enumerate() {
        let r = range(i);
        let cells = &mut fields.sensor[r];
        place_run(session, runs, k, points, &mut span, &mut seen, cells)?;
    }
    let cells = &fields.sensor;

    // Rows: the reference run's cells in ascending order; `row_of[cell]` is
    // first the reference reading there plus 1, then the row's index plus 1
    // (0: the reference has no reading there).
    let ref_run = &session.runs[runs[0]];
    let mut row_of = vec![0u32; ncells];
    for (j, &cell) in cells[range(runs[0])].iter().enumerate() {
        row_of[cell as usize] = j as u32 + 1;
    }
    let nrows = ref_run.readings.len();
    let nruns = runs.len();
    let mut rows = Vec::with_capacity(nrows);
    let mut index = vec![u32::MAX; nrows * nruns];
    for (cell, slot) in row_of.iter_mut().enumerate() {
        if *slot == 0 {
            continue;
        }
        let j = *slot - 1;
        index[rows.len()] = j;
        rows.push(Row {
            point: cell / nsens,
            sensor: cell % nsens,
            speed_rpm: ref_run.readings[j as usize].speed_rpm,
        });
        *slot = rows.len() as u32;
    }

    // The trial runs' readings into their rows.
    let mut unpaired: Option<(usize, usize)> = None;
    let mut filled = nrows;
    for (k, &i) in runs.iter().enumerate().skip(1) {
        let of = &mut index[k * nrows..(k + 1) * nrows];
        for (j, &cell) in cells[range(i)].iter().enumerate() {
            match row_of[cell as usize] {
                0 => {
                    unpaired.get_or_insert((i, j));
                }
                a => {
                    of[a as usize - 1] = j as u32;
                    filled += 1;
                }
            }
        }
    }
    if filled < nrows * nruns {
        for (a, row) in rows.iter().enumerate() {
            if let Some(k) = (0..nruns).position(|k| index[k * nrows + a] == u32::MAX) {
                let i = runs[k];
                return Err(unpaired::missing(
                    session,
                    runs,
                    k,
                    row,
                    &cells[range(i)],
                    &row_of,
                ));
            }
        }
    }
    // A trial reading of a cell the reference lacks cannot be paired; it is
    // reported after any reading a row misses.
    if let Some((i, j)) = unpaired {
        return Err(InputError::invalid(
            "unpaired_reading",
            format!("runs[{i}].readings[{j}]"),
            "the reference run has no reading of this sensor at this speed to pair this one with",
        ));
    }

    // `Y`, a run's column at a time, written once (no zeros first). Without
    // runout nothing is subtracted: `x − 0` is `x`, bit for bit.
    let mut y = Vec::with_capacity(nrows * nruns);
    for (k, &i) in runs.iter().enumerate() {
        let readings = &session.runs[i].readings;
        let of = &index[k * nrows..(k + 1) * nrows];
        for &j in of {
            let r = &readings[j as usize];
            y.push(reading_in(conventions, r.amplitude, r.phase_deg));
        }
    }
    if runout.iter().any(Option::is_some) {
        for (k, column) in y.chunks_mut(nrows).enumerate() {
            debug_assert!(k < nruns);
            for (z, row) in column.iter_mut().zip(&rows) {
                *z -= runout[row.sensor].unwrap_or_default();
            }
        }
    }
    Ok(Paired {
        rows,
        index,
        y: DMatrix::from_vec(nrows, nruns, y),
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
