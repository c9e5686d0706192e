//! The output-error fit of a viscous decay, started from the recurrence (7.1).
//!
//! The recurrence `y_k = λ1 y_{k−1} + λ2 y_{k−2}` is exact for exact samples,
//! but fitted by least squares to noisy ones it has the noise on both sides
//! (errors in the variables): `λ` shrinks and the damping comes out high. A
//! 5 Hz decay of ζ = 0.02, 20 samples a period, answered ζ 0.042 to 0.051
//! with 1 % noise and 0.47 to 0.59 with 5 % (review, session 20). Its answer
//! is a good start, though, for the fit of the decay itself,
//! `y_k ≈ e^{−n t_k} (a cos ω_d t_k + b sin ω_d t_k)`, whose error the noise
//! does not bias: Levenberg–Marquardt over `(a, b, n, ω_d)`, each step a
//! linear least-squares problem solved through the SVD (`lsq::solve`, never
//! the normal equations). Its Jacobian at the minimum gives the parameters'
//! covariance, `σ² (JᵀJ)⁻¹` with `σ²` the residual over `N − 4` degrees of
//! freedom, from the SVD too.

use nalgebra::{DMatrix, DVector};

use super::super::lsq;

/// The fitted decay and the covariance of `(n, ω_d)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Refined {
    pub n: f64,
    pub wd: f64,
    /// Sum of squared residuals.
    pub rss: f64,
    /// Covariance of `(n, ω_d)`: `[[var n, cov], [cov, var ω_d]]`.
    pub cov: [[f64; 2]; 2],
}

fn model(p: &[f64; 4], t: f64) -> f64 {
    let [a, b, n, wd] = *p;
    (-n * t).exp() * (a * (wd * t).cos() + b * (wd * t).sin())
}

fn rss(y: &[f64], tau: f64, p: &[f64; 4]) -> f64 {
    y.iter()
        .enumerate()
        .map(|(k, &yk)| (yk - model(p, k as f64 * tau)).powi(2))
        .sum()
}

fn jacobian(y: &[f64], tau: f64, p: &[f64; 4]) -> DMatrix<f64> {
    let [a, b, n, wd] = *p;
    DMatrix::from_fn(y.len(), 4, |k, j| {
        let t = k as f64 * tau;
        let (e, c, s) = ((-n * t).exp(), (wd * t).cos(), (wd * t).sin());
        match j {
            0 => e * c,
            1 => e * s,
            2 => -t * e * (a * c + b * s),
            _ => t * e * (b * c - a * s),
        }
    })
}

/// The least-squares `(a, b)` for a given `(n, ω_d)`.
fn linear_part(y: &[f64], tau: f64, n: f64, wd: f64) -> Option<[f64; 4]> {
    let m = DMatrix::from_fn(y.len(), 2, |k, j| {
        let t = k as f64 * tau;
        (-n * t).exp()
            * if j == 0 {
                (wd * t).cos()
            } else {
                (wd * t).sin()
            }
    });
    let ab = lsq::solve(m, &DVector::from_column_slice(y), "the decay's amplitude").ok()?;
    Some([ab[0], ab[1], n, wd])
}

/// Refine `(n0, wd0)` by the output-error fit; `None` when it cannot be had
/// (then the recurrence's answer stands).
pub fn viscous(y: &[f64], tau: f64, n0: f64, wd0: f64) -> Option<Refined> {
    let mut p = linear_part(y, tau, n0, wd0)?;
    let mut cost = rss(y, tau, &p);
    let mut mu: f64 = 1e-3;
    for _ in 0..200 {
        let j = jacobian(y, tau, &p);
        let r = DVector::from_iterator(
            y.len(),
            y.iter()
                .enumerate()
                .map(|(k, &yk)| yk - model(&p, k as f64 * tau)),
        );
        // Marquardt's damping, scaled by each column's size: rows √μ·‖J_j‖.
        let mut a = DMatrix::zeros(y.len() + 4, 4);
        a.rows_mut(0, y.len()).copy_from(&j);
        for (c, col) in j.column_iter().enumerate() {
            a[(y.len() + c, c)] = mu.sqrt() * col.norm();
        }
        let mut rhs = DVector::zeros(y.len() + 4);
        rhs.rows_mut(0, y.len()).copy_from(&r);
        let Ok(d) = lsq::solve(a, &rhs, "the decay's output-error fit") else {
            break;
        };
        let q = [p[0] + d[0], p[1] + d[1], p[2] + d[2], p[3] + d[3]];
        let next = rss(y, tau, &q);
        if next.is_finite() && next < cost && q[3] > 0.0 {
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
    // ωτ within (0, π): the samples alias otherwise, as for (7.1).
    if !(p[3] > 0.0 && p[3] * tau < std::f64::consts::PI && cost.is_finite()) {
        return None;
    }
    let dof = y.len().saturating_sub(4);
    if dof == 0 {
        return None;
    }
    let sigma2 = cost / dof as f64;
    // (JᵀJ)⁻¹ = S⁻¹ V Σ⁻² Vᵀ S⁻¹ from the SVD of the column-scaled J.
    let mut j = jacobian(y, tau, &p);
    let scale = lsq::unit_columns(&mut j);
    let svd = j.svd(false, true);
    let vt = svd.v_t?;
    let smax = svd.singular_values.max();
    if !(smax > 0.0 && svd.singular_values.min() > lsq::RANK_TOLERANCE * smax) {
        return None;
    }
    let entry = |r: usize, c: usize| {
        (0..4)
            .map(|k| vt[(k, r)] * vt[(k, c)] / svd.singular_values[k].powi(2))
            .sum::<f64>()
            * sigma2
            / (scale[r] * scale[c])
    };
    Some(Refined {
        n: p[2],
        wd: p[3],
        rss: cost,
        cov: [[entry(2, 2), entry(2, 3)], [entry(3, 2), entry(3, 3)]],
    })
}
