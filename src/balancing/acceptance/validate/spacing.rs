//! The positions of a residual-unbalance check: equally spaced, each once
//! (the first may be repeated at the end). A position off the spacing is
//! named against the grid most readings fit (session 16).

use super::{MAX_POSITIONS, MIN_POSITIONS, SPACING_TOL_DEG};
use crate::balancing::acceptance::ResidualRequest;
use crate::balancing::error::{shown, InputError};
use crate::balancing::phasor::{angle_diff_deg, wrap_deg};

/// The number of distinct, equally spaced positions; the last reading may
/// repeat the first position (API's worksheet closes the polar plot so).
///
/// Accepted as before: every position on the grid through readings[0], each
/// once. A refusal names the first reading off the grid that most readings
/// fit (`best_origin`), so a wrong readings[0] is named itself rather than
/// its correct neighbour (session 16); a repeat names the later reading.
pub(super) fn spacing(req: &ResidualRequest) -> Result<usize, InputError> {
    // Counted before the spacing is read: past the most a tolerance tells
    // apart, a repeat of the first position cannot be told either.
    if req.readings.len() > MAX_POSITIONS + 1 {
        return Err(too_many(req.readings.len()));
    }
    let angles: Vec<f64> = req.readings.iter().map(|r| r.angle_deg).collect();
    let repeat =
        angles.len() >= 2 && angle_diff_deg(angles[0], angles[angles.len() - 1]) <= SPACING_TOL_DEG;
    let n = angles.len() - usize::from(repeat);
    if n < MIN_POSITIONS {
        return Err(InputError::invalid(
            "too_few_positions",
            "readings",
            format!(
                "the check needs the trial weight at {MIN_POSITIONS} or more equally spaced positions (API asks 6 or 12); {n} given"
            ),
        ));
    }
    if n > MAX_POSITIONS {
        return Err(too_many(n));
    }
    let angles = &angles[..n];
    let step = 360.0 / n as f64;
    let Some(first) = misfits(angles, 0, step).first().copied() else {
        return Ok(n);
    };
    let origin = best_origin(angles, step);
    // Past 2·tolerance apart the grid through `origin` can fit every reading
    // while the one through readings[0] does not: then readings[0]'s fault.
    let faults = misfits(angles, origin, step);
    let (origin, faults) = if faults.is_empty() {
        (0, vec![first])
    } else {
        (origin, faults)
    };
    let (k, repeats) = faults[0];
    let a = angles[k];
    let what = match repeats {
        Some(i) => format!(
            "{}° repeats the position of readings[{i}] ({}°)",
            shown(a),
            shown(angles[i])
        ),
        None => format!(
            "{} of them fit that spacing from {}° (readings[{origin}]), {}° is not on it",
            n - faults.iter().filter(|f| f.1.is_none()).count(),
            shown(angles[origin]),
            shown(a)
        ),
    };
    let others: Vec<String> = faults[1..]
        .iter()
        .take(5)
        .map(|&(k, _)| format!("readings[{k}]"))
        .collect();
    let also = if others.is_empty() {
        String::new()
    } else {
        let more = if faults.len() > 6 { ", …" } else { "" };
        format!("; also off: {}{more}", others.join(", "))
    };
    Err(InputError::invalid(
        "positions_not_equally_spaced",
        format!("readings[{k}].angle_deg"),
        format!(
            "{n} positions must be {step:.1}° apart, each once (the first may be repeated at the end); {what}{also}"
        ),
    ))
}

fn too_many(n: usize) -> InputError {
    InputError::invalid(
        "too_many_positions",
        "readings",
        format!(
            "the check takes at most {MAX_POSITIONS} positions, 2° apart (API asks 6 or 12; the first may be repeated at the end); {n} given"
        ),
    )
}

/// The readings off the grid of `step` through `angles[origin]`, in order:
/// each index with, for a repeat, the earlier reading at that position.
fn misfits(angles: &[f64], origin: usize, step: f64) -> Vec<(usize, Option<usize>)> {
    let n = angles.len();
    let mut seen: Vec<Option<usize>> = vec![None; n];
    let mut faults = Vec::new();
    for (k, &a) in angles.iter().enumerate() {
        let q = wrap_deg(a - angles[origin]) / step;
        let place = q.round();
        let slot = (place as usize) % n;
        if (q - place).abs() * step > SPACING_TOL_DEG {
            faults.push((k, None));
        } else if let Some(i) = seen[slot] {
            faults.push((k, Some(i)));
        } else {
            seen[slot] = Some(k);
        }
    }
    faults
}

/// The reading whose grid of `step` the most readings lie on (ties: the
/// earliest). A reading is on the grid through reading j when its offset
/// within one step is within the tolerance of j's, around the circle; the
/// offsets sorted, each count is two binary searches, O(n log n) in all
/// (the request's readings are limited only by the body size).
fn best_origin(angles: &[f64], step: f64) -> usize {
    if 2.0 * SPACING_TOL_DEG >= step {
        return 0; // every reading is on every grid
    }
    let offset = |a: f64| wrap_deg(a - angles[0]) % step;
    let mut sorted: Vec<f64> = angles.iter().map(|&a| offset(a)).collect();
    sorted.sort_by(f64::total_cmp);
    // One step either side, so a window across 0 or `step` counts once.
    let around: Vec<f64> = sorted
        .iter()
        .map(|r| r - step)
        .chain(sorted.iter().copied())
        .chain(sorted.iter().map(|r| r + step))
        .collect();
    let fits = |x: f64| {
        around.partition_point(|&r| r <= x + SPACING_TOL_DEG)
            - around.partition_point(|&r| r < x - SPACING_TOL_DEG)
    };
    let mut best = (0, 0);
    for (j, &a) in angles.iter().enumerate() {
        let c = fits(offset(a));
        if c > best.1 {
            best = (j, c);
        }
    }
    best.0
}
