//! The wire model of a balancing session and of solve options
//! (`docs/session-format.md`), exactly as it is posted and read back.
//!
//! These types only describe the JSON shape (unknown fields are rejected);
//! `validate` turns them into checked types. Optional fields stay `Option`
//! so that a session reads back exactly as it was posted.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// How the instrument reports the phase of the 1X vibration (method §1, 1.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum PhaseConvention {
    /// Phase lag after the once-per-revolution mark (most analysers).
    #[default]
    Lag,
    /// Phase lead.
    Lead,
}

/// Direction in which weight angles are counted from the reference mark (method §1, 1.2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum AngleDirection {
    #[default]
    AgainstRotation,
    WithRotation,
}

/// The session's angle conventions; every angle in requests and responses uses them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Conventions {
    #[serde(default)]
    pub phase: PhaseConvention,
    #[serde(default)]
    pub angle_direction: AngleDirection,
}

impl Conventions {
    /// The four combinations a user can choose; each must give the same physical correction.
    pub const ALL: [Conventions; 4] = [
        Conventions {
            phase: PhaseConvention::Lag,
            angle_direction: AngleDirection::AgainstRotation,
        },
        Conventions {
            phase: PhaseConvention::Lag,
            angle_direction: AngleDirection::WithRotation,
        },
        Conventions {
            phase: PhaseConvention::Lead,
            angle_direction: AngleDirection::AgainstRotation,
        },
        Conventions {
            phase: PhaseConvention::Lead,
            angle_direction: AngleDirection::WithRotation,
        },
    ];
}

/// Rotor data for the ISO 21940-11 tolerance (method §5.2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Rotor {
    /// Kilograms, greater than 0 and at most 1e7.
    pub mass_kg: f64,
    /// From 1 to 1e6 rpm.
    pub service_speed_rpm: f64,
    /// One of G0.4, G1, G2.5, G6.3, G16, G40, G100, G250, G630, G1600, G4000.
    pub balance_grade: String,
}

/// A correction plane.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Plane {
    pub id: String,
    /// Radius at which weights are fitted, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius_mm: Option<f64>,
    /// Number of equally spaced fixed places (2 or more), place 0 at angle 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub positions: Option<u32>,
    /// Explicit angles of the fixed places (irregular holes), in the session's
    /// `angle_direction`, each in `[0, 360)` and distinct; instead of `positions`.
    /// Place `p` is the `p`-th angle of this list.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub places_deg: Option<Vec<f64>>,
    /// The weight sizes at hand for this plane (needs `positions` or `places_deg`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kit: Option<Kit>,
}

/// The weights a fitter has for a plane: any number of each size, stacked at most
/// `max_per_place` at one place.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Kit {
    /// The weight sizes, grams (finite, greater than 0).
    pub masses_g: Vec<f64>,
    /// How many weights may be stacked at one place (1 to 4).
    pub max_per_place: u32,
    /// How many places of the plane one fit may use (1 to 4, default 2): a
    /// fitter splits a weight over two places, and without a bound the exact
    /// optimum would stack dozens of small weights round the plane to hit
    /// fractions of a gram (and the choices would be past counting).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_places: Option<u32>,
}

/// Unit of a sensor's amplitudes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum Unit {
    UmPp,
    MilsPp,
    MmSRms,
    MmSPk,
    InSPk,
    GPk,
}

/// A vibration sensor.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Sensor {
    pub id: String,
    pub unit: Unit,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub label: Option<String>,
}

/// A weight on the rotor during a run, relative to the reference state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Weight {
    pub plane: String,
    /// Grams, from 1e-6 (a microgram) to 1e7.
    pub mass_g: f64,
    /// In the session's `angle_direction`, degrees from the reference mark.
    pub angle_deg: f64,
}

/// One repeated 1X sample of a reading.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Sample {
    pub amplitude: f64,
    pub phase_deg: f64,
}

/// One 1X reading of one sensor at one speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Reading {
    pub speed_rpm: f64,
    pub sensor: String,
    /// In the sensor's unit.
    pub amplitude: f64,
    /// In the session's `phase` convention, degrees.
    pub phase_deg: f64,
    /// Repeated 1X readings of this point; `amplitude`/`phase_deg` are their mean.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub samples: Option<Vec<Sample>>,
}

/// A run: the weights on the rotor and the readings taken.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Run {
    pub id: String,
    /// All weights on the rotor during the run; empty for the reference run.
    pub weights: Vec<Weight>,
    pub readings: Vec<Reading>,
    /// What the run was taken for, as the client says (a trial or a check
    /// run); stored and given back unchanged, not read by the solve. Never on
    /// the reference run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub purpose: Option<RunPurpose>,
}

/// What a run with weights was taken for: names are the technician's to
/// choose, so a client that must tell a check run from a trial says so here.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum RunPurpose {
    /// A trial weight, to learn the influence coefficients.
    Trial,
    /// Weights fitted as a correction, run to check it.
    Check,
}

/// A balancing session (`docs/session-format.md`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Session {
    pub name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub machine: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub conventions: Option<Conventions>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotor: Option<Rotor>,
    pub planes: Vec<Plane>,
    pub sensors: Vec<Sensor>,
    pub runs: Vec<Run>,
    /// Slow-roll (runout) vectors, subtracted from every reading of their sensor (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub runout: Option<Vec<Runout>>,
    /// A trim job: the coefficients it is to be solved with, known before it
    /// (stored and given back unchanged, not read by the solve).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub trim: Option<Trim>,
}

/// The coefficients a trim job is to be solved with, instead of trial runs:
/// exactly one of the two, each the shape of the solve option of its name.
/// A record for whoever reopens the job; a solve uses coefficients only as
/// its options give them.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Trim {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coefficients_from: Option<CoefficientsFrom>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub influence_coefficients: Option<Vec<SuppliedCoefficient>>,
}

/// The slow-roll vector of a sensor (v2 "Runout"): in the sensor's unit and
/// the session's phase convention.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Runout {
    pub sensor: String,
    pub amplitude: f64,
    pub phase_deg: f64,
}

/// A supplied influence coefficient (v2 "Coefficients supplied or stored"):
/// the solution's shape, with an optional covariance.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct SuppliedCoefficient {
    pub speed_rpm: f64,
    pub sensor: String,
    pub plane: String,
    /// Sensor unit per gram: 0 (not seen), or 1e-16 to 1e15.
    pub amplitude_per_g: f64,
    /// In the session's `phase` convention.
    pub phase_deg: f64,
    /// 2×2 covariance of the coefficient's real and imaginary parts, (unit/g)²,
    /// real axis at phase 0 and imaginary axis at +90° in the session's phase convention.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub covariance: Option<[[f64; 2]; 2]>,
    /// The unit the coefficient's amplitude is in (per gram); when given it
    /// must be the session's unit of that sensor. Pooled coefficients carry it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unit: Option<Unit>,
}

/// Which machine's stored coefficients a solve uses (latest version when absent).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct CoefficientsFrom {
    pub machine: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub version: Option<i64>,
}

/// What the correction minimises.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum Objective {
    /// Sum of squared residual amplitudes over the selected rows.
    #[default]
    LeastSquares,
    /// Largest residual amplitude over the selected rows.
    MinMax,
}

/// A weight on the rows that match a sensor, a speed, or both.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct RowWeight {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensor: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed_rpm: Option<f64>,
    /// 0 (the rows it matches are left out), or from 1e-6 to 1e6; the
    /// weights that match one row multiply to 1e-12 to 1e12.
    pub weight: f64,
}

/// Solve options; all optional.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct SolveOptions {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speeds_rpm: Option<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensors: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub planes: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub objective: Option<Objective>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub row_weights: Option<Vec<RowWeight>>,
    /// Upper bound on the correction mass per plane id, grams.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        deserialize_with = "crate::balancing::wire::unique_keys"
    )]
    pub max_mass_g: Option<BTreeMap<String, f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub drop_dependent_planes: Option<bool>,
    /// 1X amplitude repeatability, percent of the reading (default 2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amplitude_noise_pct: Option<f64>,
    /// 1X phase repeatability, degrees (default 2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub phase_noise_deg: Option<f64>,
    /// Correct from the rotor as it was in this run, its weights still on (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from_run: Option<String>,
    /// Influence coefficients to use instead of estimating them from trial runs (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub influence_coefficients: Option<Vec<SuppliedCoefficient>>,
    /// A machine's stored coefficients, resolved by the service (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coefficients_from: Option<CoefficientsFrom>,
    /// Fit whole weights from each plane's kit at its fixed places, jointly
    /// over all planes: the solution adds `fit` and `fit_summary`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub discrete: Option<bool>,
    /// Time bound of the discrete fit's search, milliseconds (1 to 60000,
    /// default 1000); past it the best fit found is given with `optimal: false`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fit_time_limit_ms: Option<u64>,
}

/// The body of `POST /api/v1/solve`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct SolveRequest {
    pub session: Session,
    #[serde(default)]
    pub options: SolveOptions,
}

// Objects only: a positional array is refused (see `wire`).
objects_only!(
    Conventions,
    Rotor,
    Plane,
    Kit,
    Sensor,
    Weight,
    Sample,
    Reading,
    Run,
    Session,
    Runout,
    SuppliedCoefficient,
    CoefficientsFrom,
    Trim,
    RowWeight,
    SolveOptions,
    SolveRequest,
);
