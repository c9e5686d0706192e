//! Validation: a wire `Session` becomes a `Checked` session whose readings are
//! paired into rows and turned into internal phasors, or an error naming the field.
//!
//! Everything the contract requires is checked here except solvability (the rank
//! of the trial weights), which `influence` checks when solving, because a stored
//! session may still be waiting for its trial runs. The checks come in the
//! contract's order, so the first error reported is always the same one:
//! sizes, the setup (`fields`), every run's fields (`runs`), then pairing
//! (`pairing`).

mod fields;
mod pairing;
mod runs;
mod trim;

use std::collections::HashMap;

use nalgebra::DMatrix;
use num_complex::Complex64;

pub use fields::{
    check_defined_strings, check_id_chars, check_machine_id, check_rotor, check_text_chars,
};
pub(crate) use fields::{MAX_RADIUS_MM, MIN_RADIUS_MM, MIN_ROTOR_MASS_KG, MIN_SERVICE_SPEED_RPM};
pub(crate) use runs::{MAX_MASS_G, MIN_MASS_G};
pub use trim::{check_source as check_trim_source, version_below_one};

use crate::balancing::error::InputError;
use crate::balancing::limits::{check_session, too_large, Limits};
use crate::balancing::model::{Conventions, Reading, Session};
use crate::balancing::phasor::{reading_in, weight_in};

/// Speeds closer than this (relative) are the same speed point (contract).
pub const SPEED_TOLERANCE: f64 = 0.01;
/// The ranges of a session's numbers, shared with the requests that take
/// the same quantities (the residual-unbalance check, runout).
pub(crate) const MAX_SPEED_RPM: f64 = 1e6;
pub(crate) const MAX_AMPLITUDE: f64 = 1e9;
/// Smallest non-zero amplitude: no instrument resolves 1e-9 of its unit, and
/// far smaller ones (1e-100) underflow when squared twice in the 95 % figures.
pub(crate) const MIN_AMPLITUDE: f64 = 1e-9;
/// The range of a supplied influence coefficient (solve option, trim record).
/// The largest coefficient a session's readings could give: the largest
/// amplitude (1e9) over the lightest trial mass (1e-6 g). Beyond it the
/// fit's products overflow (1e300 unit/g made the SVD's singular values NaN
/// and the solver panic).
pub(crate) const MAX_AMPLITUDE_PER_G: f64 = 1e15;
/// The smallest non-zero coefficient a session's readings could give: the
/// smallest non-zero amplitude (1e-9) over the heaviest trial mass (1e7 g).
/// Below it the correction's covariance overflows (1e-300 unit/g gave a
/// 1e302 g correction whose covariance was answered as `null`). 0 stays
/// valid: the sensor does not see the plane.
pub(crate) const MIN_AMPLITUDE_PER_G: f64 = 1e-16;
/// Largest angle or phase a session may give, degrees (either sign).
pub(crate) const MAX_ANGLE_DEG: f64 = 1e6;
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
    /// For row `a` and run `k` (of `runs`), the index of its reading in
    /// `session.runs[runs[k]].readings`, at `k × rows + a` (one flat list, not
    /// a list per row: issue 15).
    index: Vec<u32>,
}

impl Checked<'_> {
    /// The index of the speed point `speed` falls in, if any.
    pub fn point_of(&self, speed: f64) -> Option<usize> {
        pairing::nearest_point(&self.points, speed)
    }

    /// The index in its run's `readings` of the reading of run `k` (index
    /// into `self.runs`) for row `a`.
    pub fn reading_index(&self, a: usize, k: usize) -> usize {
        self.index[k * self.rows.len() + a] as usize
    }

    /// The reading of run `k` (index into `self.runs`) for row `a`.
    pub fn reading(&self, a: usize, k: usize) -> &Reading {
        &self.session.runs[self.runs[k]].readings[self.reading_index(a, k)]
    }

    /// The reading of run `k` for row `a` as the instrument gave it (internal
    /// frame), before its sensor's runout vector is subtracted: what the
    /// readings' repeatability (`amplitude_noise_pct`, `phase_noise_deg`) is
    /// relative to. `y[(a, k)]` itself where the session has no runout.
    pub fn measured(&self, a: usize, k: usize) -> Complex64 {
        if self.session.runout.is_none() {
            return self.y[(a, k)];
        }
        let r = self.reading(a, k);
        reading_in(self.conventions, r.amplitude, r.phase_deg)
    }
}

/// Validate a session and bring it into the internal frame.
pub fn check(session: &Session) -> Result<Checked<'_>, InputError> {
    // Counts first: nothing below allocates more than the lists' lengths allow.
    let limits = Limits::current();
    check_session(session, &limits)?;
    let conventions = session.conventions.unwrap_or_default();
    let (planes, sensors) = fields::check_setup(session)?;
    if let Some(t) = &session.trim {
        trim::check_trim(session, t, &planes, &sensors)?;
    }
    // Runout vectors (v2), subtracted from the readings when pairing.
    let runout = crate::balancing::job::runout::vectors(session, conventions)?;
    fields::unique_ids("runs", session.runs.iter().map(|r| r.id.as_str()))?;

    let found = runs::check_runs(session, &planes, &sensors)?;
    trim::check_purposes(session)?;
    let reference = found.reference;
    let ref_run = &session.runs[reference];
    let points = pairing::cluster_speeds(ref_run.readings.iter().map(|r| r.speed_rpm).collect());
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
    let paired = pairing::pair(session, conventions, &points, &runs, found, &runout)?;

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
        rows: paired.rows,
        runs,
        y: paired.y,
        t,
        index: paired.index,
    })
}
