//! The output-error fit of a decay, started from the linear discrete models
//! (7.1 viscous, 7.2 turbulent).
//!
//! The recurrence `y_k = λ1 y_{k−1} + λ2 y_{k−2}` is exact for exact samples,
//! but fitted by least squares to noisy ones it has the noise on both sides
//! (errors in the variables): `λ` shrinks and the damping comes out high. A
//! 5 Hz decay of ζ = 0.02, 20 samples a period, answered ζ 0.042 to 0.051
//! with 1 % noise and 0.47 to 0.59 with 5 % (review, session 20). Its answer
//! is a good start, though, for the fit of the decay itself,
//! `y_k ≈ m + e^{−n t_k} (a cos ω_d t_k + b sin ω_d t_k)`, whose error the noise
//! does not bias: Levenberg–Marquardt over `(a, b, n, ω_d, m)`, each step a
//! linear least-squares problem solved through the SVD (`lsq::solve`, never
//! the normal equations). Its Jacobian at the minimum gives the parameters'
//! covariance, `σ² (JᵀJ)⁻¹` with `σ²` the residual over `N − 5` degrees of
//! freedom, from the SVD too. The offset `m` (a proximity probe's gap
//! voltage, an accelerometer's bias) is a parameter unless the client gave
//! it: left out, an offset of 10 % of the amplitude moved the frequency
//! 2.5 % and ζ 30 % (review, session 20). Held at 0, the fit is over
//! `(a, b, n, ω_d)` and `N − 4` degrees of freedom.

use nalgebra::{DMatrix, DVector};

use super::super::lsq;

/// The envelope of a decay, per step `k`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Envelope {
    /// `e^{−ν k}`.
    Exponential,
    /// `1/(1 + l k)`.
    Hyperbolic,
}

impl Envelope {
    /// The envelope and its derivative in its parameter at step `k`.
    fn at(self, d: f64, k: f64) -> (f64, f64) {
        match self {
            Envelope::Exponential => {
                let g = (-d * k).exp();
                (g, -k * g)
            }
            Envelope::Hyperbolic => {
                let g = 1.0 / (1.0 + d * k);
                (g, -k * g * g)
            }
        }
    }
}

/// The fitted decay, per step, and the covariance of `(d, θ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Refined {
    /// The envelope's parameter: `ν = nτ` or `l`.
    pub d: f64,
    /// `θ = ω_d τ`.
    pub theta: f64,
    /// Sum of squared residuals.
    pub rss: f64,
    /// Covariance of `(d, θ)`: `[[var d, cov], [cov, var θ]]`.
    pub cov: [[f64; 2]; 2],
}

/// The fitted parameters: `(a, b, d, θ, m)`.
const P: usize = 5;

fn model(e: Envelope, p: &[f64; P], k: f64) -> f64 {
    let [a, b, d, theta, m] = *p;
    m + e.at(d, k).0 * (a * (theta * k).cos() + b * (theta * k).sin())
}

fn rss(e: Envelope, y: &[f64], p: &[f64; P]) -> f64 {
    y.iter()
        .enumerate()
        .map(|(k, &yk)| (yk - model(e, p, k as f64)).powi(2))
        .sum()
}

/// The Jacobian's columns: `(a, b, d, θ)`, and `m` with an offset.
fn jacobian(e: Envelope, y: &[f64], p: &[f64; P], cols: usize) -> DMatrix<f64> {
    let [a, b, d, theta, _] = *p;
    DMatrix::from_fn(y.len(), cols, |k, j| {
        let k = k as f64;
        let (g, dg) = e.at(d, k);
        let (c, s) = ((theta * k).cos(), (theta * k).sin());
        match j {
            0 => g * c,
            1 => g * s,
            2 => dg * (a * c + b * s),
            3 => k * g * (b * c - a * s),
            _ => 1.0,
        }
    })
}

/// The least-squares `(a, b)`, and `m` with an offset, for a given `(d, θ)`.
fn linear_part(e: Envelope, y: &[f64], d: f64, theta: f64, cols: usize) -> Option<[f64; P]> {
    let m = DMatrix::from_fn(y.len(), cols - 2, |k, j| {
        let k = k as f64;
        match j {
            0 => e.at(d, k).0 * (theta * k).cos(),
            1 => e.at(d, k).0 * (theta * k).sin(),
            _ => 1.0,
        }
    });
    let abm = lsq::solve(m, &DVector::from_column_slice(y), "the decay's amplitude").ok()?;
    Some([abm[0], abm[1], d, theta, abm.get(2).copied().unwrap_or(0.0)])
}

/// Whether `p` is a decay the samples can show: `θ` within `(0, π)` (more
/// than two samples a period), a hyperbolic envelope positive throughout.
fn admissible(e: Envelope, p: &[f64; P], n: usize) -> bool {
    let ok_theta = p[3] > 0.0 && p[3] < std::f64::consts::PI;
    ok_theta && (e == Envelope::Exponential || 1.0 + p[2] * (n as f64 - 1.0) > 0.0 && p[2] > -1.0)
}

/// Refine the start `(d0, θ0)` by the output-error fit, with the offset `m`
/// as a parameter or held at 0; `None` when it cannot be had (then the
/// linear model's answer stands).
pub fn fit(e: Envelope, y: &[f64], d0: f64, theta0: f64, with_offset: bool) -> Option<Refined> {
    let cols = if with_offset { P } else { P - 1 };
    let mut p = linear_part(e, y, d0, theta0, cols)?;
    if !admissible(e, &p, y.len()) {
        return None;
    }
    let mut cost = rss(e, y, &p);
    let mut mu: f64 = 1e-3;
    for _ in 0..200 {
        let j = jacobian(e, y, &p, cols);
        let r = DVector::from_iterator(
            y.len(),
            y.iter()
                .enumerate()
                .map(|(k, &yk)| yk - model(e, &p, k as f64)),
        );
        // Marquardt's damping, scaled by each column's size: rows √μ·‖J_j‖.
        let mut a = DMatrix::zeros(y.len() + cols, cols);
        a.rows_mut(0, y.len()).copy_from(&j);
        for (c, col) in j.column_iter().enumerate() {
            a[(y.len() + c, c)] = mu.sqrt() * col.norm();
        }
        let mut rhs = DVector::zeros(y.len() + cols);
        rhs.rows_mut(0, y.len()).copy_from(&r);
        let Ok(step) = lsq::solve(a, &rhs, "the decay's output-error fit") else {
            break;
        };
        let q: [f64; P] = std::array::from_fn(|i| p[i] + step.get(i).copied().unwrap_or(0.0));
        let next = rss(e, y, &q);
        if next.is_finite() && next < cost && admissible(e, &q, y.len()) {
            let settled = cost - next <= 1e-14 * cost;
            p = q;
            cost = next;
            mu = (mu / 10.0).max(1e-12);
            if settled {
                break;
            }
        } else {
            mu *= 10.0;
            if mu > 1e10 {
                break;
            }
        }
    }
    let dof = y.len().saturating_sub(cols);
    if dof == 0 || !cost.is_finite() {
        return None;
    }
    let sigma2 = cost / dof as f64;
    // (JᵀJ)⁻¹ = S⁻¹ V Σ⁻² Vᵀ S⁻¹ from the SVD of the column-scaled J.
    let mut j = jacobian(e, y, &p, cols);
    let scale = lsq::unit_columns(&mut j);
    let svd = j.svd(false, true);
    let vt = svd.v_t?;
    let smax = svd.singular_values.max();
    if !(smax > 0.0 && svd.singular_values.min() > lsq::RANK_TOLERANCE * smax) {
        return None;
    }
    let entry = |r: usize, c: usize| {
        (0..cols)
            .map(|k| vt[(k, r)] * vt[(k, c)] / svd.singular_values[k].powi(2))
            .sum::<f64>()
            * sigma2
            / (scale[r] * scale[c])
    };
    Some(Refined {
        d: p[2],
        theta: p[3],
        rss: cost,
        cov: [[entry(2, 2), entry(2, 3)], [entry(3, 2), entry(3, 3)]],
    })
}
