//! Degrees of freedom of a covariance estimated from `samples`, and the
//! widening of the 95 % region they call for (issue 12: honest with few
//! samples).
//!
//! With the options' noise model the readings' covariances are stated, and the
//! χ²₂ ellipse is the 95 % region to first order. With `samples` they are
//! estimated from the samples' scatter (pooled with the options as a prior
//! worth [`super::PRIOR_SAMPLES`] samples, `reading_noise`): reading `r`'s
//! covariance carries `ν_r = n_r − 1 + ν₀` degrees of freedom, and the
//! correction's covariance `Σ̂_j = Σ_r w_rj Ŝ_r` is a weighted sum of them.
//! Its degrees of freedom follow Satterthwaite (1946, "An approximate
//! distribution of estimates of variance components", Biometrics Bulletin 2):
//! `ν_j = (Σ_r w_rj)² / Σ_r w_rj² / ν_r`, with `w_rj` the share of reading
//! `r` in the variance of plane `j` (first order: `g_i² |λ_k|² |A⁺_ji|² tr S_r`,
//! the leading term of `propagate`). A 2-vector error standardised by a
//! covariance with `ν` degrees of freedom is Hotelling's `T²`, whose 95 %
//! quantile is `2ν/(ν−1) F₂,ν₋₁(0.95) = ν (0.05^(−2/(ν−1)) − 1)` (method
//! 8.5), which tends to `χ²₂(0.95) = 5.991` as `ν → ∞`. The reported
//! covariance is multiplied by that quantile over 5.991, so its χ²₂ ellipse,
//! the intervals and `amplitude_95` stay one formula for every source of noise.

use nalgebra::{DMatrix, Matrix2};
use num_complex::Complex64;

use super::propagate::{svd_parts, RANK_TOLERANCE};
use super::CHI2_2_95;
use crate::balancing::solve::Fit;

/// Smallest degrees of freedom used: `T²` has no 95 % quantile at `ν ≤ 1`.
const MIN_DOF: f64 = 2.0;

/// 95 % quantile of Hotelling's `T²` in 2 dimensions with `ν` degrees of
/// freedom, `ν (0.05^(−2/(ν−1)) − 1)`; `χ²₂` for infinite `ν`.
pub fn hotelling_95(nu: f64) -> f64 {
    if !nu.is_finite() {
        return CHI2_2_95;
    }
    let nu = nu.max(MIN_DOF);
    nu * (0.05f64.powf(-2.0 / (nu - 1.0)) - 1.0)
}

/// Degrees of freedom of each used plane's covariance (module doc), infinite
/// where no used reading has samples. `cov[a][k]` as in `propagate`, `prior`:
/// whether the options' noise was pooled with the samples (`reading_noise`).
pub fn degrees_of_freedom(fit: &Fit, cov: &[Vec<Matrix2<f64>>], prior: bool) -> Vec<f64> {
    let checked = &fit.checked;
    let sel = &fit.selection;
    let q = fit.planes.len();
    let runs = checked.runs.len();
    // ν of each reading used, `None` for stated noise (known, infinite ν).
    let nu = |a: usize, k: usize| {
        let n = checked.reading(a, k).samples.as_ref().map_or(0, Vec::len);
        let pooled = if prior { super::PRIOR_SAMPLES } else { 0.0 };
        (n >= 2).then_some(n as f64 - 1.0 + pooled)
    };
    if !sel
        .rows
        .iter()
        .any(|&a| (0..runs).any(|k| nu(a, k).is_some()))
    {
        return vec![f64::INFINITY; q];
    }
    // `A⁺` from the solve's own factorisation of `A = G W` (issue 15: it was
    // formed and factored again here), at `propagate`'s rank tolerance.
    let (apinv, _) = fit
        .factor
        .pinv_and_gram_inv(RANK_TOLERANCE * fit.factor.max());
    let (tp, _) = svd_parts(&checked.t);
    // λ_k = ω_k·C (+1 for the reference): how reading k of a row moves its residual.
    let lambda: Vec<Complex64> = (0..runs)
        .map(|k| {
            let omega = |j: usize| match k {
                0 => -tp.column(fit.planes[j]).sum(),
                _ => tp[(k - 1, fit.planes[j])],
            };
            (0..q).map(|j| omega(j) * fit.c[j]).sum::<Complex64>() + if k == 0 { 1.0 } else { 0.0 }
        })
        .collect();
    let share = DMatrix::from_fn(sel.rows.len(), runs, |i, k| {
        let a = sel.rows[i];
        sel.weights[i].powi(2) * lambda[k].norm_sqr() * cov[a][k].trace()
    });
    (0..q)
        .map(|j| {
            let (mut sum, mut sum_sq) = (0.0, 0.0);
            for (i, &a) in sel.rows.iter().enumerate() {
                let lever = apinv[(j, i)].norm_sqr();
                for k in 0..runs {
                    let w = share[(i, k)] * lever;
                    sum += w;
                    if let Some(n) = nu(a, k) {
                        sum_sq += w * w / n;
                    }
                }
            }
            if sum_sq > 0.0 && sum > 0.0 {
                sum * sum / sum_sq
            } else {
                f64::INFINITY
            }
        })
        .collect()
}

/// The factor on a covariance with `nu` degrees of freedom that makes its
/// χ²₂ ellipse the Hotelling 95 % region.
pub fn widening(nu: f64) -> f64 {
    hotelling_95(nu) / CHI2_2_95
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hotelling_quantile_tends_to_chi_square_and_matches_the_f_table() {
        assert_eq!(hotelling_95(f64::INFINITY), CHI2_2_95);
        assert!((hotelling_95(1e7) - CHI2_2_95).abs() < 1e-5);
        // F(2, 9; 0.95) = 4.2565 (tables): T² = 2·10/9 · 4.2565 at ν = 10.
        assert!((hotelling_95(10.0) - 20.0 / 9.0 * 4.2565).abs() < 1e-3);
        assert!(widening(30.0) > 1.0 && widening(10.0) > widening(30.0));
    }
}
