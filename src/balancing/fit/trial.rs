//! Trial-weight suggestions (`POST /api/v1/trial-weights`): one trial weight
//! per plane that should move the vibration by about 30 %, the change field
//! practice asks of a trial run (the `trial_effect_small` threshold).
//!
//! - `coefficients` (influence coefficients known, method §2): the mass
//!   `m = 0.3 ‖G Y0‖ / ‖G Wⱼ‖` moves the weighted selected vibration by 30 %
//!   (so at least one row moves by 30 % or more), at the angle that lowers it
//!   most, `arg(−Wⱼᴴ Gᴴ G Y0)`. `expected_change_pct` is `100 ‖G Wⱼ m‖/‖G Y0‖`
//!   for the weight given (after rounding to the kit).
//! - `rotor` (nothing known but the rotor): the weight whose centrifugal force
//!   at service speed is [`FORCE_FRACTION`] (10 %) of the rotor's weight share
//!   on the plane, `m r ω² = 0.10 · (M / P) · g`, at angle 0: the rule of thumb
//!   of field-balancing guides (a force of about a tenth of the static load on
//!   the bearing moves the 1X vibration clearly without risk to the machine).
//!
//! With a kit, the suggestion is the stack of kit weights at one place whose
//! vector is nearest to the ideal one.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::candidates::{loads, Load};
use super::places::place_angles_deg;
use crate::balancing::error::InputError;
use crate::balancing::influence::influence_matrix;
use crate::balancing::model::{Conventions, Session, SolveOptions};
use crate::balancing::phasor::{weight_in, weight_out};
use crate::balancing::select::select;
use crate::balancing::validate::check;

/// Change of the vibration a trial weight is sized for.
pub const TARGET_CHANGE: f64 = 0.30;
/// Centrifugal force of a `rotor`-basis trial weight, as a fraction of the rotor's weight share on the plane.
pub const FORCE_FRACTION: f64 = 0.10;
const G_M_S2: f64 = 9.80665;

/// What a suggestion was sized from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum Basis {
    /// Known influence coefficients: 30 % of the vibration, at the angle that lowers it.
    Coefficients,
    /// Rotor mass, service speed and plane radius: a force of 10 % of the rotor's weight share.
    Rotor,
}

/// A suggested trial weight for one plane.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct TrialSuggestion {
    pub plane: String,
    pub mass_g: f64,
    /// In the session's `angle_direction`.
    pub angle_deg: f64,
    /// The plane's fitting radius, when known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius_mm: Option<f64>,
    pub basis: Basis,
    /// With `coefficients`: the predicted change of the selected vibration,
    /// `100 ‖ΔY‖/‖Y0‖` over the used rows (row weights applied), percent.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub expected_change_pct: Option<f64>,
    /// With a kit: the place the stack goes to (its angle is `angle_deg`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub place: Option<u32>,
    /// With a kit: the stacked kit weights, grams, adding up to `mass_g`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub weights: Option<Vec<f64>>,
}

/// The ideal trial weight of plane column `a` (weighted) against the weighted
/// vibration `y`: internal vector, grams.
pub fn from_coefficients(a: &DVector<Complex64>, y: &DVector<Complex64>) -> Complex64 {
    let na = a.norm();
    if na == 0.0 {
        return Complex64::new(0.0, 0.0);
    }
    let m = TARGET_CHANGE * y.norm() / na;
    let dir = -a.dotc(y); // aᴴ y, negated: the direction that lowers ‖y + a u‖
    if dir.norm() == 0.0 {
        Complex64::new(m, 0.0)
    } else {
        dir / dir.norm() * m
    }
}

/// The `rotor`-basis mass, grams: `m = f · (M/P) · g / (r ω²)`.
pub fn from_rotor(mass_kg: f64, planes: usize, speed_rpm: f64, radius_mm: f64) -> f64 {
    let omega = speed_rpm * std::f64::consts::TAU / 60.0;
    let share = mass_kg / planes.max(1) as f64;
    1000.0 * FORCE_FRACTION * share * G_M_S2 / (radius_mm / 1000.0 * omega * omega)
}

/// The stack of kit weights at one place nearest to `ideal` (internal frame).
fn nearest_stack(
    conv: Conventions,
    angles: &[f64],
    stacks: &[Load],
    ideal: Complex64,
) -> (usize, usize) {
    let mut best = (0, 0, f64::INFINITY);
    for (p, &deg) in angles.iter().enumerate() {
        let u = weight_in(conv, 1.0, deg);
        for (l, load) in stacks.iter().enumerate() {
            let d = (u * load.mass_g - ideal).norm();
            if d < best.2 {
                best = (p, l, d);
            }
        }
    }
    (best.0, best.1)
}

/// The solve options a trial weight is sized with; any other is refused.
const USED_OPTIONS: &str =
    "planes, sensors, speeds_rpm, row_weights, influence_coefficients and coefficients_from";

/// Refuse a solve option that sizing a trial weight does not use (422
/// `unused_option`, naming `options.<key>`): answering as if it were not
/// there left a client that asked for `discrete` or `from_run` believing it
/// had been applied. Its value does not matter: the option is not read.
pub fn check_options(options: &SolveOptions) -> Result<(), InputError> {
    // Named one by one, so that a new solve option must be placed here.
    let SolveOptions {
        speeds_rpm: _,
        sensors: _,
        planes: _,
        row_weights: _,
        influence_coefficients: _,
        coefficients_from: _,
        objective,
        max_mass_g,
        drop_dependent_planes,
        amplitude_noise_pct,
        phase_noise_deg,
        from_run,
        discrete,
        fit_time_limit_ms,
    } = options;
    let unused = [
        ("objective", objective.is_some()),
        ("max_mass_g", max_mass_g.is_some()),
        ("drop_dependent_planes", drop_dependent_planes.is_some()),
        ("amplitude_noise_pct", amplitude_noise_pct.is_some()),
        ("phase_noise_deg", phase_noise_deg.is_some()),
        ("from_run", from_run.is_some()),
        ("discrete", discrete.is_some()),
        ("fit_time_limit_ms", fit_time_limit_ms.is_some()),
    ];
    match unused.iter().find(|(_, given)| *given) {
        None => Ok(()),
        Some((key, _)) => Err(InputError::invalid(
            "unused_option",
            format!("options.{key}"),
            format!("{key} is a solve option that sizing a trial weight does not use (it uses {USED_OPTIONS}): leave it out"),
        )),
    }
}

/// Suggest a trial weight per selected plane. `coefficients`: a known influence
/// matrix (rows × planes, internal frame) when supplied or stored; without it
/// the session's own trial runs are used if they determine one, else the rotor.
pub fn suggest(
    session: &Session,
    options: &SolveOptions,
    coefficients: Option<DMatrix<Complex64>>,
) -> Result<Vec<TrialSuggestion>, InputError> {
    check_options(options)?;
    // A trim job whose options name no coefficients is sized from the trim's.
    if let Some(with_trim) = crate::balancing::job::trim::options_for(session, options) {
        return suggest(session, &with_trim, coefficients)
            .map_err(crate::balancing::job::trim::named_in_trim);
    }
    let checked = check(session)?;
    let selection = select(&checked, options)?;
    let conv = checked.conventions;
    // Coefficients given by the caller, else supplied in the options (v2
    // `influence_coefficients`, or a machine's stored ones resolved by the
    // service), else those the session's own trial runs determine.
    let supplied = match coefficients {
        Some(w) => Some(w),
        None => crate::balancing::job::supplied::resolve(&checked, options)?.map(|s| s.w),
    };
    let w = supplied.or_else(|| influence_matrix(&checked).ok());
    let y = DVector::from_fn(selection.rows.len(), |i, _| {
        checked.y[(selection.rows[i], 0)] * selection.weights[i]
    });
    let mut out = Vec::with_capacity(selection.planes.len());
    for &j in &selection.planes {
        let plane = &session.planes[j];
        // The plane's coefficients on the selected rows; all zero (the plane
        // moves no reading) they cannot size a trial weight (it was 0 g).
        let column = w
            .as_ref()
            .map(|w| {
                DVector::from_fn(selection.rows.len(), |i, _| {
                    w[(selection.rows[i], j)] * selection.weights[i]
                })
            })
            .filter(|a| a.norm() > 0.0);
        let (ideal, basis) = match &column {
            Some(a) => (from_coefficients(a, &y), Basis::Coefficients),
            None => {
                let rotor = session.rotor.as_ref().ok_or_else(|| {
                    let message = if w.is_some() {
                        format!("the influence coefficients of plane {} are 0 at every sensor and speed selected, so they cannot size its trial weight: give rotor (mass_kg, service_speed_rpm) and the plane's radius_mm to size it from the rotor, or coefficients that see the plane", plane.id)
                    } else {
                        "no influence coefficients are known for this session, so a trial weight is sized from the rotor: give rotor (mass_kg, service_speed_rpm) and each plane's radius_mm, or supply coefficients".to_string()
                    };
                    InputError::invalid("no_basis", "rotor", message)
                })?;
                let r = plane.radius_mm.ok_or_else(|| {
                    InputError::invalid(
                        "no_basis",
                        format!("planes[{j}].radius_mm"),
                        format!(
                            "plane {} needs its radius to size a trial weight from the rotor",
                            plane.id
                        ),
                    )
                })?;
                let m = from_rotor(
                    rotor.mass_kg,
                    session.planes.len(),
                    rotor.service_speed_rpm,
                    r,
                );
                (weight_in(conv, m, 0.0), Basis::Rotor)
            }
        };
        let (mut weight, mut place, mut stack) = (ideal, None, None);
        if let (Some(kit), Some(angles)) = (&plane.kit, place_angles_deg(plane)) {
            let stacks = loads(&kit.masses_g, kit.max_per_place);
            let (p, l) = nearest_stack(conv, &angles, &stacks, ideal);
            weight = weight_in(conv, stacks[l].mass_g, angles[p]);
            place = Some(p as u32);
            stack = Some(stacks[l].weights.clone());
        }
        let expected_change_pct = match (&w, basis) {
            (Some(w), Basis::Coefficients) => {
                let dy = DVector::from_fn(selection.rows.len(), |i, _| {
                    w[(selection.rows[i], j)] * selection.weights[i] * weight
                });
                Some(100.0 * dy.norm() / y.norm().max(f64::MIN_POSITIVE))
            }
            _ => None,
        };
        let (mass_g, mut angle_deg) = weight_out(conv, weight);
        if let (Some(p), Some(angles)) = (place, place_angles_deg(plane)) {
            angle_deg = angles[p as usize];
        }
        out.push(TrialSuggestion {
            plane: plane.id.clone(),
            mass_g,
            angle_deg,
            radius_mm: plane.radius_mm,
            basis,
            expected_change_pct,
            place,
            weights: stack,
        });
    }
    Ok(out)
}

/// The body of `POST /api/v1/trial-weights`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct TrialRequest {
    /// A session; its reference run alone is enough.
    pub session: Session,
    /// Solve options: `planes`, `sensors`, `speeds_rpm` and `row_weights` choose
    /// the planes suggested for and the vibration a suggestion is sized against;
    /// `influence_coefficients` or `coefficients_from` give coefficients. Any
    /// other solve option is refused (422 `unused_option`, naming it).
    #[serde(default)]
    pub options: SolveOptions,
}

/// The answer of `POST /api/v1/trial-weights`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct TrialResponse {
    pub suggestions: Vec<TrialSuggestion>,
}

// Objects only: a positional array is refused (see `balancing::wire`).
crate::balancing::wire::objects_only!(TrialRequest);
