//! The uncertainty of a correction computed with supplied coefficients
//! (method 3.2, 3.3 differentiated): with `A = G W`, `b = G Y0`,
//! `r = A C + b`, `dC = −A⁺(dA C + db) − (AᴴA)⁻¹ dAᴴ r`. Two independent
//! contributions are added: `reading_part`, the noise of the reference
//! readings `Y0` (the only readings the correction uses here), and
//! `coefficient_part`, the supplied covariance of each `W_aj`. The residual's
//! bound adds `dY0 + dW C` per row the same way.
//!
//! `A⁺` and `(AᴴA)⁺` come from the solve's own factorisation of `A`
//! (`fit.factor`, QR then the SVD of `R`), not an SVD of their own (session
//! 10): against the former full SVD of `A` (`uncertainty_tests.rs`), `A⁺`,
//! `(AᴴA)⁺`, `−A⁺ b` and both covariance parts agree within 2.9·10⁻¹⁴ relative
//! (Frobenius) on the five examples and 200 seeded random supplied jobs
//! (condition numbers up to 41); the tests assert 10⁻¹².

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

use super::Supplied;
use crate::balancing::diagnostics::undetermined;
use crate::balancing::model::SolveOptions;
use crate::balancing::phasor::reading_in;
use crate::balancing::solution::{Solution, Warning};
use crate::balancing::solve::Fit;
use crate::balancing::uncertainty::{
    amplitude_95, correction_uncertainty, reading_noise, undetermined_warning, Noise,
};

/// Real 2×2 matrix of `δ ↦ α δ + β δ̄` on (Re δ, Im δ).
fn real_map(alpha: Complex64, beta: Complex64) -> Matrix2<f64> {
    Matrix2::new(
        alpha.re + beta.re,
        beta.im - alpha.im,
        alpha.im + beta.im,
        alpha.re - beta.re,
    )
}

/// Singular values of `A` at or below this times the largest are left out of
/// `A⁺` and `(AᴴA)⁺`, as in `uncertainty::propagate`.
const RANK_TOLERANCE: f64 = 1e-10;

/// The weighted problem's parts: `A⁺`, `(AᴴA)⁺`, `r`.
struct Parts {
    pinv: DMatrix<Complex64>,
    gram: DMatrix<Complex64>,
    r: DVector<Complex64>,
}

/// `A⁺` and `(AᴴA)⁺` from the solve's own factorisation of `A = G W`
/// (`fit.factor`, the matrix of the used rows and `fit.planes`), no second SVD.
fn parts(fit: &Fit) -> Parts {
    let sel = &fit.selection;
    let r = DVector::from_fn(sel.rows.len(), |i, _| {
        fit.residual[sel.rows[i]] * sel.weights[i]
    });
    let (pinv, gram) = fit
        .factor
        .pinv_and_gram_inv(RANK_TOLERANCE * fit.factor.max());
    Parts { pinv, gram, r }
}

fn add_block(cov: &mut DMatrix<f64>, jac: &DMatrix<f64>, sigma: &Matrix2<f64>) {
    let s = DMatrix::from_fn(2, 2, |i, j| sigma[(i, j)]);
    *cov += jac * s * jac.transpose();
}

/// Covariance of all corrections (`2q × 2q`) from the reference readings' noise.
fn reading_part(fit: &Fit, p: &Parts, y0_cov: &[Matrix2<f64>]) -> DMatrix<f64> {
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
fn coefficient_part(fit: &Fit, p: &Parts, s: &Supplied) -> DMatrix<f64> {
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

/// Covariance of each reference reading `Y0` (every row): from its samples,
/// else from the stated noise (method 8.1).
fn reference_covariances(fit: &Fit, noise: Noise) -> Vec<Matrix2<f64>> {
    let checked = &fit.checked;
    let conv = checked.conventions;
    (0..checked.rows.len())
        .map(|a| {
            let samples: Option<Vec<Complex64>> = checked.reading(a, 0).samples.as_ref().map(|x| {
                x.iter()
                    .map(|x| reading_in(conv, x.amplitude, x.phase_deg))
                    .collect()
            });
            reading_noise(
                checked.measured(a, 0),
                samples.as_deref(),
                noise.amplitude_pct,
                noise.phase_deg,
            )
        })
        .collect()
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
    let conv = fit.checked.conventions;
    let y0_cov = reference_covariances(fit, noise);
    // The solve's factorisation of the weighted problem, for both contributions.
    let p = parts(fit);
    let full = reading_part(fit, &p, &y0_cov) + coefficient_part(fit, &p, s);
    // A plane the coefficients say moves no reading (or only as other planes
    // do) has no determined correction: as with estimated coefficients.
    let lost = undetermined(&fit.factor);
    for (jj, ((corr, &c), &lost)) in solution
        .corrections
        .iter_mut()
        .zip(fit.c.iter())
        .zip(&lost)
        .enumerate()
    {
        let b = full.fixed_view::<2, 2>(2 * jj, 2 * jj).into_owned();
        let mut u = correction_uncertainty(c, &b, conv);
        if lost {
            u.mass_g = None;
            u.angle_deg = [0.0, 360.0];
            solution.warnings.push(undetermined_warning(corr));
        }
        corr.uncertainty = Some(u);
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

#[cfg(test)]
#[path = "uncertainty_tests.rs"]
mod tests;
