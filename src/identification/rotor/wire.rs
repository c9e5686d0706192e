//! The wire form of `identify/rotor`: request, options and answer
//! (`docs/session-format.md`, "Identification"; options and answer fields
//! beyond the contract's are additions).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::balancing::model::Session;
use crate::balancing::solution::Warning;

/// How the forcing of (6.1) is taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum UnbalanceAngle {
    /// Size and angle of the forcing estimated (default): robust to the
    /// sensor's angle from the reference mark.
    #[default]
    Estimated,
    /// The forcing is the trial weight at its own angle: (6.1) literally.
    AtWeight,
}

/// The cross-coupling `q` of (6.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum CrossCoupling {
    #[default]
    Estimated,
    Zero,
}

/// Options of `identify/rotor`; all optional.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct RotorOptions {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensors: Option<Vec<String>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub planes: Option<Vec<String>>,
    /// `[lo, hi]`, rpm: fit one mode of a flexible rotor at a time.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub speed_range_rpm: Option<Vec<f64>>,
    /// A known modal mass, kg (then the planes need `radius_mm`); estimated when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_kg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unbalance_angle: Option<UnbalanceAngle>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cross_coupling: Option<CrossCoupling>,
    /// `κ` of `q = κ·b·ω` (the textbook's tied cross-coupling); overrides `cross_coupling`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cross_coupling_ratio: Option<f64>,
}

/// The body of `POST /api/v1/identify/rotor`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct RotorRequest {
    pub session: Session,
    #[serde(default)]
    pub options: RotorOptions,
}

/// The one-mass model of one sensor and plane.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct RotorResult {
    pub sensor: String,
    pub plane: String,
    /// Undamped critical speed `√(c/m)`, rpm.
    pub critical_speed_rpm: f64,
    /// 95 % half-width of `critical_speed_rpm` (as `damping_ratio_resolution`;
    /// absent when it cannot be had).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub critical_speed_resolution_rpm: Option<f64>,
    /// Of the forward mode at the critical: `(b − q/ω_n) / (2√(cm))` (`b/(2√(cm))` without cross-coupling).
    /// With `damping_ratio_bound` `upper`, the most the readings allow instead.
    pub damping_ratio: f64,
    /// The smallest damping ratio these readings tell from zero: the 95 %
    /// half-width of the fitted one, its standard deviation times Student's
    /// quantile for the residual's degrees of freedom (absent when it cannot
    /// be had).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_ratio_resolution: Option<f64>,
    /// `upper` when the fitted damping ratio is within its resolution of zero:
    /// then `damping_ratio` is the most the readings allow, not an estimate.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_ratio_bound: Option<String>,
    /// API 684 amplification factor (see `amplification_method`).
    pub amplification_factor: f64,
    /// `lower` when the damping is unresolved: `amplification_factor` is
    /// `1/(2·damping_ratio)` of the upper bound, the least the readings allow.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub amplification_factor_bound: Option<String>,
    /// `half_power_bandwidth` (N_c/(N2 − N1) on the fitted displacement response) or `one_over_two_zeta`.
    pub amplification_method: String,
    /// Speed of the fitted response's peak, rpm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub peak_speed_rpm: Option<f64>,
    /// `100·|N_c − N_service| / N_service`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub separation_margin_pct: Option<f64>,
    /// API 684's required margin for this amplification factor (0: none required).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub required_margin_pct: Option<f64>,
    /// RMS of fitted minus measured influence coefficients, the sensor's unit per gram.
    pub fit_rms: f64,
    /// `fit_rms` over the RMS of the measured coefficients.
    pub fit_rms_relative: f64,
    /// Speed points fitted.
    pub speeds: usize,
    /// `c/m` (1/s²).
    pub c_over_m: f64,
    /// `b/m` (1/s) and `q/m` (1/s², its constant part). Absent when the
    /// damping is unresolved (`damping_ratio_bound` `upper`): the fitted
    /// ones are then noise (a little below zero, or large and cancelling in
    /// `b − q/ω_n`), and the damping ratio's bound is all the readings tell.
    /// Absent too when the damping ratio is resolved but its split into `b`
    /// and `q` is not (`b/m` within its resolution of zero; with `q`
    /// estimated, within twice it or under 3 degrees of freedom; warning
    /// `damping_split_unresolved`): synchronous readings fix `ωb − q` near the
    /// critical and split it only through the speed's change across the
    /// resonance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub b_over_m: Option<f64>,
    /// 95 % half-width of `b_over_m` (as `damping_ratio_resolution`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub b_over_m_resolution: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_over_m: Option<f64>,
    /// 95 % half-width of `q_over_m` (0 when `q` is not estimated).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub q_over_m_resolution: Option<f64>,
    /// Absolute parameters, when the plane's radius makes the unbalance known
    /// (damping and cross-coupling not when the damping is unresolved, as
    /// `b_over_m` and `q_over_m`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_kg: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness_n_per_m: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_n_s_per_m: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cross_coupling_n_per_m: Option<f64>,
}

/// The answer of `identify/rotor`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct RotorIdentification {
    pub results: Vec<RotorResult>,
    /// `poor_fit` (several modes in range, or coefficients too noisy for their trial), `critical_outside_range`, `no_mode`,
    /// `damping_unresolved` (a damping ratio within its resolution of zero),
    /// `damping_split_unresolved` (a damping ratio resolved, its split into
    /// direct damping and cross-coupling not).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<Warning>,
}

// Objects only: a positional array is refused (see `balancing::wire`).
crate::balancing::wire::objects_only!(RotorOptions, RotorRequest);
