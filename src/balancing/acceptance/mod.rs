//! Test-stand acceptance (issue 17): the API 617 / API 684 residual-unbalance
//! check computed exactly from all trial positions, and the ISO 21940-11
//! verdict of a solution against its grade. Wire types live here; `validate`
//! checks a request, `fit` does the least squares, `iso` the verdict.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::error::InputError;
use super::model::Conventions;
use super::solution::Warning;

mod fit;
pub mod iso;
mod validate;

/// Default 1X amplitude repeatability of the balancing machine, percent.
pub const DEFAULT_AMPLITUDE_NOISE_PCT: f64 = 2.0;
/// Default 1X phase repeatability, degrees.
pub const DEFAULT_PHASE_NOISE_DEG: f64 = 2.0;

/// The trial weight moved from position to position.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct TrialWeight {
    /// Grams, 1e-6 to 1e7.
    pub mass_g: f64,
    /// Millimetres, 1e-3 to 1e5.
    pub radius_mm: f64,
}

/// The 1X reading with the trial weight at one position.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct PositionReading {
    /// Where the trial weight sits, in the request's `angle_direction`; within ±1e6.
    pub angle_deg: f64,
    /// Amplitude in any one unit (balancing-machine units, µm, mm/s…): only ratios
    /// count. 0, or 1e-9 to 1e9.
    pub amplitude: f64,
    /// In the request's `phase` convention; give it for every reading or for none.
    /// Within ±1e6.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub phase_deg: Option<f64>,
}

/// The body of `POST /api/v1/residual-unbalance` (`docs/session-format.md`,
/// "Residual-unbalance check").
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct ResidualRequest {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub plane: Option<String>,
    /// rpm, 1 to 1e6.
    pub speed_rpm: f64,
    pub trial: TrialWeight,
    /// Static load on the journal nearest the plane, kg (API's W), 1e-3 to 1e7.
    pub journal_load_kg: f64,
    pub readings: Vec<PositionReading>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub conventions: Option<Conventions>,
    /// Added: the machine's 1X amplitude repeatability, percent (default 2; 1e-6 to 100).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amplitude_noise_pct: Option<f64>,
    /// Added: the machine's 1X phase repeatability, degrees (default 2; 1e-6 to 90).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub phase_noise_deg: Option<f64>,
}

/// Which exact fit was used.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Readings with phases: `V(θ) = a + c·e^{iθ}` by complex least squares (a circle
    /// in the complex plane whose points sit at the known trial angles).
    CircleFit,
    /// Amplitudes only: `|V(θ)|² = p + q cos θ + r sin θ` by least squares.
    AmplitudeFit,
}

/// API's paper shortcut, for comparison.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct Worksheet {
    pub max_amplitude: f64,
    pub min_amplitude: f64,
    /// `(max − min)/2`.
    pub y: f64,
    /// `(max + min)/2`.
    pub z: f64,
    /// `trial · Y/Z`, g·mm.
    pub residual_unbalance_gmm: f64,
    pub pass: bool,
    /// Worksheet answer minus the exact one, g·mm.
    pub difference_gmm: f64,
}

/// First-order uncertainty of the exact estimate from the readings' repeatability.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct ResidualUncertainty {
    /// `first_order`: the estimate's Jacobian (central differences) times the
    /// readings' amplitude and phase variances.
    pub method: String,
    pub residual_unbalance_sd_gmm: f64,
    /// 95 % interval of the residual unbalance, g·mm.
    pub residual_unbalance_gmm: [f64; 2],
    /// 95 % interval of the angle, degrees (it starts in [0, 360); the upper end
    /// may exceed 360 when it wraps); `[0, 360]` when undetermined.
    pub residual_angle_deg: [f64; 2],
}

/// How well the points lie on the fitted curve, against the stated repeatability.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct FitCheck {
    /// Σ (misfit / its standard deviation)², about χ² with `degrees_of_freedom`.
    pub statistic: f64,
    pub degrees_of_freedom: usize,
    /// 99 % quantile of χ² with those degrees of freedom.
    pub threshold: f64,
    /// RMS misfit of the readings, in their unit (amplitude fit: of `|V|²`).
    pub rms_misfit: f64,
    pub holds: bool,
}

/// The answer of `POST /api/v1/residual-unbalance`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct ResidualCheck {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub plane: Option<String>,
    /// Exact least-squares estimate, g·mm.
    pub residual_unbalance_gmm: f64,
    /// Where the residual unbalance (its heavy spot) is, in the request's `angle_direction`.
    pub residual_angle_deg: f64,
    /// API's `6350 · W / N`, g·mm.
    pub allowable_gmm: f64,
    pub pass: bool,
    /// Residual over allowable.
    pub ratio: f64,
    pub method: Method,
    pub worksheet: Worksheet,
    /// Added: `trial.mass_g · trial.radius_mm`, g·mm.
    pub trial_unbalance_gmm: f64,
    /// Added: trial over allowable (API asks 1 to 2).
    pub trial_ratio: f64,
    /// Added (amplitude fit): the other residual the amplitudes allow, `U_trial/x`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub alternative_residual_gmm: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub uncertainty: Option<ResidualUncertainty>,
    pub fit: FitCheck,
    /// Distinct positions used.
    pub positions: usize,
    pub conventions: Conventions,
    pub warnings: Vec<Warning>,
}

/// Parse and check a request posted as JSON.
pub fn parse(bytes: &[u8]) -> Result<ResidualRequest, InputError> {
    super::from_json(bytes)
}

/// The residual-unbalance check of a request, or a 4xx naming the field at fault.
pub fn check(req: &ResidualRequest) -> Result<ResidualCheck, InputError> {
    let input = validate::check(req)?;
    fit::evaluate(req, &input)
}

/// API's allowable residual unbalance `6350 · W / N` g·mm (4W/N in oz·in, lb, rpm).
pub fn allowable_gmm(journal_load_kg: f64, speed_rpm: f64) -> f64 {
    6350.0 * journal_load_kg / speed_rpm
}

// Objects only: a positional array is refused (see `balancing::wire`).
crate::balancing::wire::objects_only!(TrialWeight, PositionReading, ResidualRequest);
