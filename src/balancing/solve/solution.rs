//! The solution as the contract describes it, plus added fields.
//!
//! Every angle here is in the session's conventions, echoed in `conventions`:
//! correction and weight angles in its `angle_direction`, vibration phases in
//! its `phase` convention.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::shared_id::SharedId;
use crate::balancing::model::{Conventions, Objective, Unit};

/// One part of a correction split over two neighbouring fixed places (method 5.1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct SplitPart {
    /// Place number, 0 at angle 0.
    pub position: u32,
    pub angle_deg: f64,
    pub mass_g: f64,
}

/// 95 % confidence region of a correction.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Uncertainty {
    /// 95 % interval of the mass, g; absent when the readings cannot determine
    /// this plane's correction (warning `plane_undetermined`, angle `[0, 360]`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_g: Option<[f64; 2]>,
    /// 95 % interval of the angle, degrees (the upper end may exceed 360 when it wraps).
    pub angle_deg: [f64; 2],
    /// Covariance of the correction's real and imaginary parts, g², with the
    /// real axis at angle 0 and the imaginary axis at 90° in the session's `angle_direction`.
    pub covariance_g2: [[f64; 2]; 2],
    /// The errors-in-variables estimate of the exact correction (method 8.3):
    /// the correction less the second-order bias that the coefficients'
    /// noise gives least squares. Present only where that bias is estimated
    /// (least squares without a binding bound, more rows than planes, and the
    /// noise stated in the options or measured by `samples`). It is an
    /// estimate, not the weight to fit: unbiased over many jobs, it leaves
    /// more vibration than the correction itself in most single jobs at one
    /// speed (method 8, "What the bias correction costs in vibration"). The
    /// region above is centred on the correction and includes this bias
    /// (method 8.11).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub bias_corrected: Option<BiasCorrected>,
}

/// A plane's errors-in-variables estimate (method 8.3), as a weight.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct BiasCorrected {
    /// Grams, at the plane's fitting radius.
    pub mass_g: f64,
    /// In the session's `angle_direction`.
    pub angle_deg: f64,
}

/// The correction weight for one plane.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Correction {
    pub plane: String,
    pub mass_g: f64,
    /// Where to fit the weight, in the session's `angle_direction`.
    pub angle_deg: f64,
    /// `mass_g · radius_mm`, when the plane has a radius.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub unbalance_gmm: Option<f64>,
    /// The correction split over the two neighbouring fixed places, when the plane has `positions`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub split: Option<Vec<SplitPart>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub uncertainty: Option<Uncertainty>,
    /// With `from_run`: the one weight in this plane that replaces every weight
    /// in it, relative to the reference state (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub total: Option<TotalWeight>,
}

/// One weight per plane, relative to the reference state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct TotalWeight {
    pub mass_g: f64,
    /// In the session's `angle_direction`.
    pub angle_deg: f64,
}

/// One row of a run check: a reading and what the other runs predict for it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct RunCheckRow {
    pub speed_rpm: f64,
    pub sensor: String,
    /// The run's reading (runout subtracted): amplitude, sensor unit.
    pub measured: f64,
    /// Its phase, session's phase convention.
    pub measured_phase_deg: f64,
    /// The amplitude predicted from the influence coefficients of the other runs.
    pub predicted: f64,
    pub predicted_phase_deg: f64,
    /// 95 % upper bound of the amplitude the reading should show if the run is
    /// what its weights say (prediction and reading noise).
    pub amplitude_95: f64,
}

/// A run compared with its prediction from the other runs (v2 `run_checks`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct RunCheck {
    pub run: String,
    pub rows: Vec<RunCheckRow>,
    pub rms_measured: f64,
    pub rms_predicted: f64,
    /// False when the run differs from its prediction by more than the
    /// readings' noise explains (χ² test at the 99 % level).
    pub consistent: bool,
    /// The χ² statistic of the differences against their covariance.
    pub chi2: f64,
    /// Its degrees of freedom (2 per row).
    pub dof: usize,
}

/// Vibration expected after the corrections at one sensor and speed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Residual {
    pub speed_rpm: f64,
    pub sensor: String,
    pub unit: Unit,
    /// Amplitude before the corrections, in the sensor's unit: the reference
    /// run's reading, or with `from_run` that run's (runout subtracted).
    pub amplitude_before: f64,
    /// Predicted amplitude after correction, in the sensor's unit.
    pub amplitude: f64,
    /// In the session's `phase` convention.
    pub phase_deg: f64,
    /// 95 % upper bound of the predicted amplitude.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplitude_95: Option<f64>,
    /// Whether this row was part of the fit (selected by `speeds_rpm`/`sensors`, weight > 0).
    pub used: bool,
}

/// Experimental influence coefficient: the 1X vibration caused by 1 g at angle 0 of a plane.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct InfluenceCoefficient {
    pub speed_rpm: f64,
    /// Shared by the coefficients that name it (issue 15).
    #[schema(value_type = String)]
    pub sensor: SharedId,
    #[schema(value_type = String)]
    pub plane: SharedId,
    /// Sensor unit per gram.
    pub amplitude_per_g: f64,
    /// Phase of that vibration, in the session's `phase` convention.
    pub phase_deg: f64,
}

/// Before/after amplitudes over the rows used in the fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Summary {
    pub rms_before: f64,
    pub rms_after: f64,
    pub max_before: f64,
    pub max_after: f64,
}

/// Per-plane diagnostics behind the warnings.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct PlaneDiagnostics {
    pub plane: String,
    /// Darlow's significance factor (0..1): the part of the plane's normalised
    /// influence column independent of the more significant planes. Below 0.2 the
    /// plane is nearly dependent.
    pub significance_factor: f64,
    /// Largest change the trial weight caused at any used row, relative to that
    /// row's reference amplitude (|ΔY|/|Y0|). Field practice asks for at least 0.3.
    pub trial_effect_ratio: f64,
    /// Largest trial effect relative to its standard deviation from reading noise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trial_effect_snr: Option<f64>,
    /// Whether the plane was left out of the solve by `drop_dependent_planes`.
    pub dropped: bool,
}

/// ISO 21940-11 permissible residual unbalance (method 5.2).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct IsoTolerance {
    pub balance_grade: String,
    /// `U_per = 9549 · G · m / n`, g·mm, for the whole rotor.
    pub permissible_residual_unbalance_gmm: f64,
    /// `U_per` shared equally over the correction planes, g·mm.
    pub permissible_per_plane_gmm: f64,
    /// Estimated unbalance as found per plane (|correction| · radius), g·mm, when every plane has a radius.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub as_found_unbalance_gmm: Option<Vec<f64>>,
    /// Whether the rotor as found was already within the tolerance in every plane.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub as_found_within_tolerance: Option<bool>,
    /// Added (issue 17): the verdict per plane, when every solved plane has a radius.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub planes: Option<Vec<IsoPlaneVerdict>>,
    /// Added: every plane within its permissible share as the rotor was measured.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pass: Option<bool>,
    /// Added: every plane's 95 % bound after the correction within its share.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub after_correction_pass: Option<bool>,
}

/// ISO 21940-11 verdict for one plane (issue 17).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct IsoPlaneVerdict {
    pub plane: String,
    /// Residual unbalance of the rotor in the state the solve describes
    /// (|correction| · radius), g·mm.
    pub residual_unbalance_gmm: f64,
    /// The plane's share of `U_per`, g·mm.
    pub permissible_gmm: f64,
    pub pass: bool,
    /// 95 % upper bound of the unbalance left once the correction is fitted
    /// (the correction's own uncertainty · radius), g·mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub after_correction_95_gmm: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub after_correction_pass: Option<bool>,
}

/// A condition the technician should know about.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Warning {
    /// `trial_effect_small`, `ill_conditioned`, `mass_limit_active`, `mixed_units`, …
    pub code: String,
    /// Plain words, with what to do.
    pub message: String,
    /// The plane concerned, if one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plane: Option<String>,
}

/// The answer to a solve.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Solution {
    pub corrections: Vec<Correction>,
    pub predicted_residual: Vec<Residual>,
    pub influence_coefficients: Vec<InfluenceCoefficient>,
    pub summary: Summary,
    /// cond(W) of the used rows and planes after scaling columns to unit norm.
    pub condition_number: f64,
    pub warnings: Vec<Warning>,
    /// The conventions every angle in this solution uses.
    pub conventions: Conventions,
    pub objective: Objective,
    pub planes: Vec<PlaneDiagnostics>,
    /// Planes left out by `drop_dependent_planes`.
    pub dropped_planes: Vec<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub iso_21940: Option<IsoTolerance>,
    /// The session's runout vectors, as subtracted (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub runout: Option<Vec<crate::balancing::model::Runout>>,
    /// The run whose state the corrections are added to (v2 `from_run`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub from_run: Option<String>,
    /// Runs compared with their prediction from the other runs (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub run_checks: Option<Vec<RunCheck>>,
    /// The machine and version of the stored coefficients used (v2).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coefficients_from: Option<crate::balancing::model::CoefficientsFrom>,
    /// With `discrete: true`: the kit weights to fit, per plane, chosen jointly.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fit: Option<Vec<FitPlane>>,
    /// With `discrete: true`: the vibration those exact weights leave.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fit_summary: Option<FitSummary>,
    /// For a two-plane correction: its static and couple parts.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub static_couple: Option<StaticCouple>,
}

/// One kit weight to fit at a fixed place.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct FitWeight {
    /// Place number: index into `places_deg`, or `p` of `positions` (place 0 at angle 0).
    pub place: u32,
    /// The place's angle, in the session's `angle_direction`.
    pub angle_deg: f64,
    /// One kit weight, grams (a place appears once per stacked weight).
    pub mass_g: f64,
}

/// The kit weights to fit in one plane.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct FitPlane {
    pub plane: String,
    /// Empty when the best choice leaves the plane as it is.
    pub weights: Vec<FitWeight>,
}

/// The predicted vibration with the fitted weights (method 3.1), over the rows used.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct FitSummary {
    pub rms_after: f64,
    pub max_after: f64,
    /// Proven best among every choice the kits allow (within `max_mass_g`,
    /// `max_per_place` and `max_places`); false when the time or node bound
    /// stopped the search first (the fit is then the best found).
    pub optimal: bool,
}

/// A weight as mass and angle.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct PlaneWeight {
    pub plane: String,
    /// Grams, at the plane's fitting radius.
    pub mass_g: f64,
    /// In the session's `angle_direction`.
    pub angle_deg: f64,
}

/// The static and couple parts of a two-plane correction `C₁`, `C₂` (as
/// vectors of grams in the session's angle convention): `static` is
/// `(C₁ + C₂)/2`, the same weight in each plane; `couple` is `+(C₁ − C₂)/2` in
/// the first plane and `−(C₁ − C₂)/2` in the second (equal masses, opposite
/// angles). Static plus couple in a plane gives that plane's correction.
/// Masses are grams as fitted: with different radii in the two planes these
/// are parts of the weights, not of the unbalance (g·mm).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct StaticCouple {
    /// The static part, fitted in each of the two planes.
    #[serde(rename = "static")]
    pub static_part: Vec<PlaneWeight>,
    /// The couple part per plane: equal masses 180° apart.
    pub couple: Vec<PlaneWeight>,
}
