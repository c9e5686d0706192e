//! The textbook's worked one-mass cases (method §6, examples/textbook-regression.json):
//! stiffness, damping and cross-coupling by linear least squares (6.1) from
//! responses given directly, with known mass and forcing.

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use crate::balancing::InputError;

/// One steady response `Z = Zr + i Zi` at angular speed `w` (1/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Response {
    pub w: f64,
    pub zr: f64,
    pub zi: f64,
}

/// The one-mass model `m z̈ + b ż + c z − i q z = f(ω) e^{iωt}` with known mass
/// and forcing, and the cross-coupling either tied to damping (`q = κ b ω`) or unknown.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OneMass {
    pub mass: f64,
    /// Force amplitude at `ω`: `F` for a fixed force, `D ω²` for an unbalance `D`.
    pub force: Forcing,
    /// `Some(κ)`: `q = κ b ω` (κ = 0 for a plain oscillator); `None`: `q` is estimated too.
    pub cross_coupling: Option<f64>,
}

/// How the model is driven.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Forcing {
    /// A force of fixed amplitude `F`.
    Force(f64),
    /// A known unbalance `D = m·e` at the reference mark: force `D ω²`.
    Unbalance(f64),
}

/// Estimated parameters: stiffness `c`, damping `b`, cross-coupling `q` (when estimated).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Estimate {
    pub c: f64,
    pub b: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub q: Option<f64>,
}

/// Least-squares estimate of (6.1) stacked over the responses, through the SVD.
///
/// Rows per speed, with `κ` folding `q = κ b ω` into the damping column:
/// `Zr·c − (1−κ) ω Zi·b [+ Zi·q] = f + m ω² Zr` and
/// `Zi·c + (1−κ) ω Zr·b [− Zr·q] = m ω² Zi`.
pub fn estimate(model: &OneMass, responses: &[Response]) -> Result<Estimate, InputError> {
    let unknowns = if model.cross_coupling.is_some() { 2 } else { 3 };
    if 2 * responses.len() < unknowns {
        return Err(InputError::unsolvable(
            "too_few_readings",
            format!(
                "{unknowns} unknowns need at least {} responses",
                unknowns.div_ceil(2)
            ),
        ));
    }
    let kappa = model.cross_coupling.unwrap_or(0.0);
    let mut k = DMatrix::zeros(2 * responses.len(), unknowns);
    let mut y = DVector::zeros(2 * responses.len());
    for (i, r) in responses.iter().enumerate() {
        let f = match model.force {
            Forcing::Force(f) => f,
            Forcing::Unbalance(d) => d * r.w * r.w,
        };
        let mw2 = model.mass * r.w * r.w;
        let (a, b) = (2 * i, 2 * i + 1);
        k[(a, 0)] = r.zr;
        k[(a, 1)] = -(1.0 - kappa) * r.w * r.zi;
        k[(b, 0)] = r.zi;
        k[(b, 1)] = (1.0 - kappa) * r.w * r.zr;
        if unknowns == 3 {
            k[(a, 2)] = r.zi;
            k[(b, 2)] = -r.zr;
        }
        y[a] = f + mw2 * r.zr;
        y[b] = mw2 * r.zi;
    }
    // Scale columns so that c (large) and b (small) are of one size for the SVD.
    let scale = super::lsq::unit_columns(&mut k);
    let svd = k.svd(true, true);
    let eps = 1e-13 * svd.singular_values.max();
    let theta = svd
        .solve(&y, eps)
        .map_err(|e| InputError::unsolvable("solver_failed", e.to_string()))?;
    let p: Vec<f64> = theta.iter().zip(&scale).map(|(t, s)| t / s).collect();
    Ok(Estimate {
        c: p[0],
        b: p[1],
        q: p.get(2).copied(),
    })
}

/// A worked estimation case in the examples' `textbook-regression.json` form.
#[derive(Debug, Clone, Deserialize)]
pub struct Case {
    pub name: String,
    /// The model in words; a cross-coupling tied to damping is written `q = κ b w`.
    pub model: String,
    pub known: Known,
    pub readings: Vec<CaseReading>,
    #[serde(flatten)]
    pub rest: serde_json::Map<String, serde_json::Value>,
}

/// Known mass and forcing: a force `F`, or an eccentricity `e` (unbalance `D = m e`).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Known {
    pub m: f64,
    #[serde(rename = "F")]
    pub force: Option<f64>,
    pub e: Option<f64>,
}

/// A response given as `Xr`/`Xi` (oscillator) or `Zr`/`Zi` (rotor).
#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CaseReading {
    pub w: f64,
    #[serde(alias = "Xr", rename = "Zr")]
    pub zr: f64,
    #[serde(alias = "Xi", rename = "Zi")]
    pub zi: f64,
}

/// `κ` of `q = κ b w` in the model text, if the model ties q to damping.
fn kappa_in(model: &str) -> Option<f64> {
    let after = model.split("q = ").nth(1)?;
    let number = after.split_whitespace().next()?;
    after[number.len()..]
        .trim_start()
        .starts_with("b w")
        .then(|| number.parse().ok())?
}

/// Estimate the parameters of one worked case.
pub fn estimate_case(case: &Case) -> Result<Estimate, InputError> {
    let forcing = match (case.known.force, case.known.e) {
        (Some(f), None) => Forcing::Force(f),
        (None, Some(e)) => Forcing::Unbalance(case.known.m * e),
        _ => {
            return Err(InputError::invalid(
                "invalid_value",
                "known",
                "give exactly one of F (force) or e (eccentricity)",
            ))
        }
    };
    // A plain forced oscillator has no cross-coupling; a rotor's is estimated unless tied to b.
    let cross_coupling = match forcing {
        Forcing::Force(_) => Some(0.0),
        Forcing::Unbalance(_) => kappa_in(&case.model),
    };
    let responses: Vec<Response> = case
        .readings
        .iter()
        .map(|r| Response {
            w: r.w,
            zr: r.zr,
            zi: r.zi,
        })
        .collect();
    estimate(
        &OneMass {
            mass: case.known.m,
            force: forcing,
            cross_coupling,
        },
        &responses,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kappa_is_read_from_the_model_text() {
        assert_eq!(kappa_in("m z'' + ... , q = 0.5 b w; rows"), Some(0.5));
        assert_eq!(kappa_in("m x'' + alpha x' + c x = F sin(w t)"), None);
    }

    #[test]
    fn noise_free_responses_give_back_the_true_parameters() {
        let (m, c, b, q) = (10.0, 1e5, 1e4, 3e3);
        let d = 1e-3;
        let responses: Vec<Response> = [60.0, 90.0, 120.0]
            .iter()
            .map(|&w| {
                let z = num_complex::Complex64::new(d * w * w, 0.0)
                    / num_complex::Complex64::new(c - m * w * w, w * b - q);
                Response {
                    w,
                    zr: z.re,
                    zi: z.im,
                }
            })
            .collect();
        let est = estimate(
            &OneMass {
                mass: m,
                force: Forcing::Unbalance(d),
                cross_coupling: None,
            },
            &responses,
        )
        .unwrap();
        assert!((est.c - c).abs() < 1e-6 * c && (est.b - b).abs() < 1e-6 * b);
        assert!((est.q.unwrap() - q).abs() < 1e-6 * q);
    }
}
