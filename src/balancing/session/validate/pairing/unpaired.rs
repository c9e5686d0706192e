//! The errors of a trial run's reading that no reference reading pairs with:
//! most likely its speed is wrong (a reference run at 3000 rpm, trial runs
//! at 3100 rpm), so the error names its `speed_rpm` and gives the speed at
//! which the reference run read that sensor (session 16).

use super::super::Row;
use crate::balancing::error::{shown, InputError};
use crate::balancing::model::Session;

/// What the reference run read of `sensor` nearest to `speed`, for a reading
/// of a trial run at `speed` that nothing pairs with: "; it read sensor 'S' at
/// N rpm (x % from `speed`) ...", or nothing if it never read the sensor.
/// Only on the error path: a scan of the reference's readings.
pub(super) fn reference_read(
    session: &Session,
    reference: usize,
    sensor: &str,
    speed: f64,
) -> String {
    let rel = |m: f64| (speed - m).abs() / m;
    let nearest = session.runs[reference]
        .readings
        .iter()
        .filter(|r| r.sensor == sensor)
        .map(|r| r.speed_rpm)
        .min_by(|&a, &b| rel(a).total_cmp(&rel(b)));
    match nearest {
        Some(m) => format!(
            "; it read sensor '{sensor}' at {} rpm, {:.1} % from {} rpm, and readings pair only within 1 %: correct this reading's speed (or the reference run's)",
            shown(m),
            100.0 * rel(m),
            shown(speed)
        ),
        None => String::new(),
    }
}

/// The error for `row` of the reference missing from run `runs[k]`, whose
/// readings' cells are `cells` (`row_of[cell]`: 0 where the reference has no
/// reading). When the run read the row's sensor at a speed the reference did
/// not, most likely that speed is wrong: `unpaired_reading` names it (the
/// reading nearest the row's speed); otherwise `missing_reading` names the run.
pub(super) fn missing(
    session: &Session,
    runs: &[usize],
    k: usize,
    row: &Row,
    cells: &[u32],
    row_of: &[u32],
) -> InputError {
    let i = runs[k];
    let nsens = session.sensors.len();
    let readings = &session.runs[i].readings;
    let gap = |j: usize| (readings[j].speed_rpm / row.speed_rpm).ln().abs();
    let off_speed = cells
        .iter()
        .enumerate()
        .filter(|&(_, &c)| c as usize % nsens == row.sensor && row_of[c as usize] == 0)
        .map(|(j, _)| j)
        .min_by(|&x, &y| gap(x).total_cmp(&gap(y)));
    if let Some(j) = off_speed {
        let r = &readings[j];
        let read = reference_read(session, runs[0], &r.sensor, r.speed_rpm);
        return InputError::invalid(
            "unpaired_reading",
            format!("runs[{i}].readings[{j}].speed_rpm"),
            format!(
                "run '{}' read sensor '{}' at {} rpm, where the reference run has no reading of it to pair with{read}",
                session.runs[i].id, r.sensor, shown(r.speed_rpm)
            ),
        );
    }
    InputError::invalid(
        "missing_reading",
        format!("runs[{i}].readings"),
        format!(
            "run '{}' has no reading of sensor '{}' at {} rpm, which the reference run has",
            session.runs[i].id,
            session.sensors[row.sensor].id,
            shown(row.speed_rpm)
        ),
    )
}
