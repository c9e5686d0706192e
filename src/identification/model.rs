//! `identify/model`: the wire form of the lecture's discrete-model correction
//! and its validation. `M = M0 + Σ mᵢ Mᵢ`, `K = K0 + Σ kᵢ Kᵢ`, matrices as
//! arrays of rows; measured modes with frequency, shape (entries `null` where
//! not measured; the whole shape may be left out) and weight.
//!
//! Every number is refused outside its range ([`super::ranges`], which says
//! why), naming its field: mass entries (of `M0` and of every `Mᵢ`) outside
//! [`MASS`] (a diagonal entry 0 or of magnitude 1e-9 to 1e9, any other at
//! most 1e9), stiffness entries likewise outside [`STIFFNESS`], measured
//! frequencies outside [`FREQUENCY_HZ`], shape entries above 1e6 in size
//! (the largest at least 1e-6), weights outside [`WEIGHT`] and starting
//! parameters above [`INITIAL`] in size.

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::lsq::finite;
use super::ranges::{self, FREQUENCY_HZ, INITIAL, MASS, SHAPE, STIFFNESS, WEIGHT};
use crate::balancing::error::{shown, within};
use crate::balancing::InputError;

/// Largest model accepted (degrees of freedom).
pub const MAX_DOF: usize = 200;

/// A matrix family `A0 + Σ pᵢ Aᵢ`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct MatrixFamily {
    /// `A0`, rows.
    pub fixed: Vec<Vec<f64>>,
    /// `A1, A2, …`; their coefficients are estimated.
    #[serde(default)]
    pub parameters: Vec<Vec<Vec<f64>>>,
}

/// A measured mode.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Mode {
    pub frequency_hz: f64,
    /// Mass-normalised when masses are estimated; `null` entries not measured.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shape: Option<Vec<Option<f64>>>,
    /// Weight `G` of this mode's equations (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weight: Option<f64>,
}

/// Starting parameters (default 1 each): where the fit of partly measured
/// shapes starts, and the unmeasured entries with it.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct Initial {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass_parameters: Option<Vec<f64>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness_parameters: Option<Vec<f64>>,
}

/// The body of `POST /api/v1/identify/model`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct ModelRequest {
    pub mass: MatrixFamily,
    pub stiffness: MatrixFamily,
    pub modes: Vec<Mode>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial: Option<Initial>,
}

/// The corrected model.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct ModelCorrection {
    pub mass_parameters: Vec<f64>,
    pub stiffness_parameters: Vec<f64>,
    /// Natural frequencies of the corrected model, ascending, Hz.
    pub frequencies_hz: Vec<f64>,
    /// Least-squares solves made (1 when every shape is fully measured).
    pub iterations: usize,
    /// RMS of the weighted, scaled equation residuals of the last solve.
    pub residual: f64,
}

/// A request checked into matrices.
#[derive(Debug, Clone)]
pub struct Checked {
    pub m0: DMatrix<f64>,
    pub mi: Vec<DMatrix<f64>>,
    pub k0: DMatrix<f64>,
    pub ki: Vec<DMatrix<f64>>,
    /// Ω² per mode, 1/s².
    pub w2: Vec<f64>,
    /// Per mode, per degree of freedom: the measured entry.
    pub shapes: Vec<Vec<Option<f64>>>,
    pub weights: Vec<f64>,
    pub initial: Vec<f64>,
}

fn matrix(field: &str, rows: &[Vec<f64>], n: Option<usize>) -> Result<DMatrix<f64>, InputError> {
    let size = n.unwrap_or(rows.len());
    if rows.is_empty() || rows.len() > MAX_DOF {
        return Err(InputError::invalid(
            "invalid_value",
            field,
            format!("a matrix of 1 to {MAX_DOF} rows is needed"),
        ));
    }
    if rows.len() != size {
        return Err(InputError::invalid(
            "wrong_size",
            field,
            format!(
                "{} rows; the model has {size} degrees of freedom",
                rows.len()
            ),
        ));
    }
    for (i, r) in rows.iter().enumerate() {
        if r.len() != size {
            return Err(InputError::invalid(
                "not_square",
                format!("{field}[{i}]"),
                format!(
                    "row {i} has {} entries; a square matrix of {size} rows needs {size}",
                    r.len()
                ),
            ));
        }
        for (j, &x) in r.iter().enumerate() {
            finite(|| format!("{field}[{i}][{j}]"), x)?;
        }
    }
    let a = DMatrix::from_fn(size, size, |i, j| rows[i][j]);
    let tol = 1e-9 * a.amax();
    for i in 0..size {
        for j in 0..i {
            if (a[(i, j)] - a[(j, i)]).abs() > tol {
                return Err(InputError::invalid(
                    "not_symmetric",
                    format!("{field}[{i}][{j}]"),
                    format!(
                        "the matrix must be symmetric: [{i}][{j}] = {} but [{j}][{i}] = {}",
                        shown(a[(i, j)]),
                        shown(a[(j, i)])
                    ),
                ));
            }
        }
    }
    Ok(a)
}

fn family(
    field: &str,
    f: &MatrixFamily,
    n: usize,
) -> Result<(DMatrix<f64>, Vec<DMatrix<f64>>), InputError> {
    let a0 = matrix(&format!("{field}.fixed"), &f.fixed, Some(n))?;
    let ai = f
        .parameters
        .iter()
        .enumerate()
        .map(|(i, p)| matrix(&format!("{field}.parameters[{i}]"), p, Some(n)))
        .collect::<Result<_, _>>()?;
    Ok((a0, ai))
}

fn initial(field: &str, given: Option<&Vec<f64>>, count: usize) -> Result<Vec<f64>, InputError> {
    match given {
        None => Ok(vec![1.0; count]),
        Some(v) if v.len() != count => Err(InputError::invalid(
            "wrong_length",
            field,
            format!("{} values for {count} parameters", v.len()),
        )),
        Some(v) => v
            .iter()
            .enumerate()
            .map(|(i, &x)| {
                within(
                    || format!("{field}[{i}]"),
                    x.abs(),
                    (0.0, INITIAL),
                    "a starting parameter's size",
                )
                .map(|_| x)
            })
            .collect(),
    }
}

/// Check a request against the contract, naming the field at fault.
pub fn check(req: &ModelRequest) -> Result<Checked, InputError> {
    let n = matrix("mass.fixed", &req.mass.fixed, None)?.nrows();
    let (m0, mi) = family("mass", &req.mass, n)?;
    let (k0, ki) = family("stiffness", &req.stiffness, n)?;
    for (name, f, range) in [
        ("mass", &req.mass, MASS),
        ("stiffness", &req.stiffness, STIFFNESS),
    ] {
        ranges::entries(&format!("{name}.fixed"), &f.fixed, range, name)?;
        for (l, p) in f.parameters.iter().enumerate() {
            ranges::entries(&format!("{name}.parameters[{l}]"), p, range, name)?;
        }
    }
    if mi.is_empty() && ki.is_empty() {
        return Err(InputError::invalid(
            "no_parameters",
            "stiffness.parameters",
            "give at least one mass or stiffness parameter matrix to estimate",
        ));
    }
    if req.modes.is_empty() {
        return Err(InputError::invalid(
            "too_few_modes",
            "modes",
            "at least one measured mode is needed",
        ));
    }
    // An n-DOF model has n modes. Unbounded (until session 19), 200,000
    // modes of a 1-mass model (within the body limit) with its mass
    // estimated would ask for a matrix of 4e10 rows, 640 GB, and a failed
    // allocation aborts the whole service.
    if req.modes.len() > n {
        return Err(InputError::invalid(
            "too_many_modes",
            "modes",
            format!(
                "{} modes for a model of {n} degrees of freedom, which has {n}; give each measured mode once",
                req.modes.len()
            ),
        ));
    }
    let mut w2 = Vec::new();
    let mut shapes = Vec::new();
    let mut weights = Vec::new();
    for (j, mode) in req.modes.iter().enumerate() {
        let f = within(
            || format!("modes[{j}].frequency_hz"),
            mode.frequency_hz,
            FREQUENCY_HZ,
            "a natural frequency in Hz",
        )?;
        w2.push((std::f64::consts::TAU * f).powi(2));
        let shape = match &mode.shape {
            None => vec![None; n],
            Some(s) if s.len() != n => {
                return Err(InputError::invalid(
                    "wrong_length",
                    format!("modes[{j}].shape"),
                    format!("{} entries; the model has {n} degrees of freedom", s.len()),
                ))
            }
            Some(s) => {
                ranges::vector(
                    &format!("modes[{j}].shape"),
                    s.iter().copied(),
                    SHAPE,
                    "a shape entry",
                    "a shape of zeros says nothing of its mode",
                )?;
                s.clone()
            }
        };
        shapes.push(shape);
        let w = within(
            || format!("modes[{j}].weight"),
            mode.weight.unwrap_or(1.0),
            WEIGHT,
            "a mode's weight",
        )?;
        weights.push(w);
    }
    let init = req.initial.clone().unwrap_or_default();
    let mut start = initial(
        "initial.mass_parameters",
        init.mass_parameters.as_ref(),
        mi.len(),
    )?;
    start.extend(initial(
        "initial.stiffness_parameters",
        init.stiffness_parameters.as_ref(),
        ki.len(),
    )?);
    Ok(Checked {
        m0,
        mi,
        k0,
        ki,
        w2,
        shapes,
        weights,
        initial: start,
    })
}

// Objects only: a positional array is refused (see `balancing::wire`).
crate::balancing::wire::objects_only!(MatrixFamily, Mode, Initial, ModelRequest);
