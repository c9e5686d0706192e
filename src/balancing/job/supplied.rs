//! Supplied influence coefficients (v2 "Coefficients supplied or stored"):
//! the option `influence_coefficients` (from another tool, a rotor model, or a
//! machine's stored coefficients) used instead of estimating `W` from trial
//! runs, and the uncertainty of a correction computed with them.
//!
//! Uncertainty (method 3.2, 3.3 differentiated): with `A = G W`, `b = G Y0`,
//! `r = A C + b`, `dC = −A⁺(dA C + db) − (AᴴA)⁻¹ dAᴴ r`. Two independent
//! contributions are added: [`reading_part`], the noise of the reference
//! readings `Y0` (the only readings the correction uses here), and
//! [`coefficient_part`], the supplied covariance of each `W_aj`. The residual's
//! bound adds `dY0 + dW C` per row the same way.

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

use crate::balancing::error::InputError;
use crate::balancing::model::{Conventions, PhaseConvention, SolveOptions, SuppliedCoefficient};
use crate::balancing::phasor::reading_in;
use crate::balancing::solution::{Solution, Warning};
use crate::balancing::solve::Fit;
use crate::balancing::uncertainty::{amplitude_95, correction_uncertainty, reading_noise, Noise};
use crate::balancing::validate::Checked;

const FIELD: &str = "options.influence_coefficients";

/// Supplied coefficients on the session's rows, internal frame.
#[derive(Debug, Clone)]
pub struct Supplied {
    /// Rows × planes; 0 where none was supplied (a plane not solved for).
    pub w: DMatrix<Complex64>,
    /// `[row][plane]` covariance of `(Re, Im)` of `W_aj`, internal frame.
    pub cov: Vec<Vec<Matrix2<f64>>>,
    /// Which `(row, plane)` were supplied.
    pub given: DMatrix<bool>,
}

/// Flip of the imaginary axis between the session's phase convention and the
/// internal frame (lag counts phase the other way).
fn frame(conv: Conventions) -> Matrix2<f64> {
    match conv.phase {
        PhaseConvention::Lag => Matrix2::new(1.0, 0.0, 0.0, -1.0),
        PhaseConvention::Lead => Matrix2::identity(),
    }
}

/// A coefficient's covariance from the wire (session's convention) to the
/// internal frame, or back: the same flip.
pub fn covariance_frame(conv: Conventions, c: &Matrix2<f64>) -> Matrix2<f64> {
    let f = frame(conv);
    f * c * f
}

fn bad(field: String, message: impl Into<String>) -> InputError {
    InputError::invalid("invalid_value", field, message)
}

fn check_entry(i: usize, c: &SuppliedCoefficient) -> Result<Option<Matrix2<f64>>, InputError> {
    let f = |x: &str| format!("{FIELD}[{i}].{x}");
    if !(c.speed_rpm.is_finite() && c.speed_rpm > 0.0) {
        return Err(bad(
            f("speed_rpm"),
            "a speed must be a finite number greater than 0",
        ));
    }
    if !(c.amplitude_per_g.is_finite() && c.amplitude_per_g >= 0.0) {
        return Err(bad(
            f("amplitude_per_g"),
            "must be a finite number, 0 or more",
        ));
    }
    if !(c.phase_deg.is_finite() && c.phase_deg.abs() <= 1e6) {
        return Err(bad(
            f("phase_deg"),
            "an angle in degrees must be finite and within ±1e6",
        ));
    }
    let Some(m) = c.covariance else {
        return Ok(None);
    };
    let m = Matrix2::new(m[0][0], m[0][1], m[1][0], m[1][1]);
    let finite = m.iter().all(|x| x.is_finite());
    let sym = (m[(0, 1)] - m[(1, 0)]).abs() <= 1e-9 * (m[(0, 0)].abs() + m[(1, 1)].abs());
    let psd = m[(0, 0)] >= 0.0
        && m[(1, 1)] >= 0.0
        && m.determinant() >= -1e-9 * (m[(0, 0)] * m[(1, 1)]).max(f64::MIN_POSITIVE);
    if !(finite && sym && psd) {
        return Err(bad(
            f("covariance"),
            "a covariance is a symmetric positive semi-definite 2×2 matrix of finite numbers",
        ));
    }
    Ok(Some(m))
}

/// The supplied coefficients on `checked`'s rows, or `None` without the
/// option. Every row of the reference run needs a coefficient for every plane
/// solved for (`options.planes`, or all); coefficients for other speeds or
/// sensors are ignored.
pub fn resolve(checked: &Checked, options: &SolveOptions) -> Result<Option<Supplied>, InputError> {
    let Some(list) = &options.influence_coefficients else {
        return Ok(None);
    };
    let session = checked.session;
    let conv = checked.conventions;
    let (n, p) = (checked.rows.len(), session.planes.len());
    let mut w = DMatrix::zeros(n, p);
    let mut cov = vec![vec![Matrix2::zeros(); p]; n];
    let mut given = DMatrix::from_element(n, p, false);
    for (i, c) in list.iter().enumerate() {
        let m = check_entry(i, c)?;
        let Some(s) = session.sensors.iter().position(|s| s.id == c.sensor) else {
            return Err(InputError::invalid(
                "unknown_sensor",
                format!("{FIELD}[{i}].sensor"),
                format!("the session has no sensor '{}'", c.sensor),
            ));
        };
        let Some(j) = session.planes.iter().position(|pl| pl.id == c.plane) else {
            return Err(InputError::invalid(
                "unknown_plane",
                format!("{FIELD}[{i}].plane"),
                format!("the session has no plane '{}'", c.plane),
            ));
        };
        let Some(point) = checked.point_of(c.speed_rpm) else {
            continue;
        };
        let Some(a) = checked
            .rows
            .iter()
            .position(|r| r.point == point && r.sensor == s)
        else {
            continue;
        };
        if given[(a, j)] {
            return Err(InputError::invalid(
                "duplicate_coefficient",
                format!("{FIELD}[{i}]"),
                format!(
                    "a coefficient of sensor '{}' at {} rpm for plane '{}' is given twice",
                    c.sensor, c.speed_rpm, c.plane
                ),
            ));
        }
        given[(a, j)] = true;
        w[(a, j)] = reading_in(conv, c.amplitude_per_g, c.phase_deg);
        cov[a][j] = m.map(|m| covariance_frame(conv, &m)).unwrap_or_default();
    }
    let wanted: Vec<usize> = match &options.planes {
        Some(ids) => session
            .planes
            .iter()
            .enumerate()
            .filter(|(_, pl)| ids.contains(&pl.id))
            .map(|(j, _)| j)
            .collect(),
        None => (0..p).collect(),
    };
    for (a, row) in checked.rows.iter().enumerate() {
        if let Some(&j) = wanted.iter().find(|&&j| !given[(a, j)]) {
            return Err(InputError::invalid(
                "missing_coefficient",
                FIELD,
                format!(
                    "no influence coefficient of sensor '{}' at {} rpm for plane '{}': give one for every sensor and speed of the reference run and every plane solved for",
                    session.sensors[row.sensor].id, row.speed_rpm, session.planes[j].id
                ),
            ));
        }
    }
    Ok(Some(Supplied { w, cov, given }))
}

/// Real 2×2 matrix of `δ ↦ α δ + β δ̄` on (Re δ, Im δ).
fn real_map(alpha: Complex64, beta: Complex64) -> Matrix2<f64> {
    Matrix2::new(
        alpha.re + beta.re,
        beta.im - alpha.im,
        alpha.im + beta.im,
        alpha.re - beta.re,
    )
}

/// The weighted problem's parts: `A⁺`, `(AᴴA)⁺` (from the SVD), `r`.
struct Parts {
    pinv: DMatrix<Complex64>,
    gram: DMatrix<Complex64>,
    r: DVector<Complex64>,
}

fn parts(fit: &Fit) -> Parts {
    let sel = &fit.selection;
    let a = DMatrix::from_fn(sel.rows.len(), fit.planes.len(), |i, j| {
        fit.w[(sel.rows[i], fit.planes[j])] * sel.weights[i]
    });
    let r = DVector::from_fn(sel.rows.len(), |i, _| {
        fit.residual[sel.rows[i]] * sel.weights[i]
    });
    let (m, q) = a.shape();
    let mut pinv = DMatrix::zeros(q, m);
    let mut gram = DMatrix::zeros(q, q);
    let svd = a.svd(true, true);
    if let (Some(u), Some(vt)) = (svd.u, svd.v_t) {
        let smax = svd.singular_values.max();
        for (i, &s) in svd.singular_values.iter().enumerate() {
            if s <= 1e-10 * smax || s == 0.0 {
                continue;
            }
            let v = vt.row(i).adjoint();
            pinv += &v * u.column(i).adjoint() / Complex64::from(s);
            gram += &v * v.adjoint() / Complex64::from(s * s);
        }
    }
    Parts { pinv, gram, r }
}

fn add_block(cov: &mut DMatrix<f64>, jac: &DMatrix<f64>, sigma: &Matrix2<f64>) {
    let s = DMatrix::from_fn(2, 2, |i, j| sigma[(i, j)]);
    *cov += jac * s * jac.transpose();
}

/// Covariance of all corrections (`2q × 2q`) from the reference readings' noise.
pub fn reading_part(fit: &Fit, y0_cov: &[Matrix2<f64>]) -> DMatrix<f64> {
    let p = parts(fit);
    let q = fit.planes.len();
    let mut cov = DMatrix::zeros(2 * q, 2 * q);
    for (i, &a) in fit.selection.rows.iter().enumerate() {
        let g = fit.selection.weights[i];
        let jac = DMatrix::from_fn(2 * q, 2, |r, c| {
            real_map(-p.pinv[(r / 2, i)] * g, Complex64::default())[(r % 2, c)]
        });
        add_block(&mut cov, &jac, &y0_cov[a]);
    }
    cov
}

/// Covariance of all corrections (`2q × 2q`) from the supplied coefficients' covariance.
pub fn coefficient_part(fit: &Fit, s: &Supplied) -> DMatrix<f64> {
    let p = parts(fit);
    let q = fit.planes.len();
    let mut cov = DMatrix::zeros(2 * q, 2 * q);
    for (i, &a) in fit.selection.rows.iter().enumerate() {
        let g = fit.selection.weights[i];
        for (jj, &j) in fit.planes.iter().enumerate() {
            let jac = DMatrix::from_fn(2 * q, 2, |r, c| {
                let alpha = -p.pinv[(r / 2, i)] * g * fit.c[jj];
                let beta = -p.gram[(r / 2, jj)] * g * p.r[i];
                real_map(alpha, beta)[(r % 2, c)]
            });
            add_block(&mut cov, &jac, &s.cov[a][j]);
        }
    }
    cov
}

/// Fill the uncertainty fields of a solution computed with supplied
/// coefficients: corrections from both contributions, each row's
/// `amplitude_95` from `dY0 + dW C`; no trial-effect figures (no trials were
/// used to estimate `W`).
pub fn fill(
    fit: &Fit,
    s: &Supplied,
    options: &SolveOptions,
    noise: Noise,
    solution: &mut Solution,
) {
    let checked = &fit.checked;
    let conv = checked.conventions;
    let y0_cov: Vec<Matrix2<f64>> = (0..checked.rows.len())
        .map(|a| {
            let samples: Option<Vec<Complex64>> = checked.reading(a, 0).samples.as_ref().map(|x| {
                x.iter()
                    .map(|x| reading_in(conv, x.amplitude, x.phase_deg))
                    .collect()
            });
            reading_noise(
                checked.y[(a, 0)],
                samples.as_deref(),
                noise.amplitude_pct,
                noise.phase_deg,
            )
        })
        .collect();
    let full = reading_part(fit, &y0_cov) + coefficient_part(fit, s);
    for (jj, (corr, &c)) in solution
        .corrections
        .iter_mut()
        .zip(fit.c.iter())
        .enumerate()
    {
        let b = full.fixed_view::<2, 2>(2 * jj, 2 * jj).into_owned();
        corr.uncertainty = Some(correction_uncertainty(c, &b, conv));
    }
    for (a, res) in solution.predicted_residual.iter_mut().enumerate() {
        let mut cov = y0_cov[a];
        for (jj, &j) in fit.planes.iter().enumerate() {
            let r = real_map(fit.c[jj], Complex64::default());
            cov += r * s.cov[a][j] * r.transpose();
        }
        res.amplitude_95 = Some(amplitude_95(fit.residual[a], &cov));
    }
    for d in &mut solution.planes {
        d.trial_effect_snr = None;
    }
    let approximate = options.objective == Some(crate::balancing::model::Objective::MinMax)
        || solution
            .warnings
            .iter()
            .any(|w| w.code == "mass_limit_active");
    if approximate {
        solution.warnings.push(Warning {
            code: "uncertainty_approximate".into(),
            message: "with the min-max objective or a binding mass bound the confidence intervals are those of a least-squares fit to the same readings, evaluated at this correction: indicative, not exact".into(),
            plane: None,
        });
    }
    // Only the supplied coefficients are reported.
    let given = &s.given;
    let mut k = 0;
    solution.influence_coefficients.retain(|_| {
        let (a, j) = (k / given.ncols(), k % given.ncols());
        k += 1;
        given[(a, j)]
    });
}
