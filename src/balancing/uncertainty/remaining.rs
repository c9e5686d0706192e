//! The 95 % upper bound of the vibration that will really remain at a row once
//! the reported correction is fitted (`amplitude_95`, issue 12).
//!
//! Two errors meet at a row `a` (first order, method 3.1): the vibration that
//! will remain, `R_a = Y0_a + W_a Ĉ = r_a + u_a`, scatters around the exact
//! least-squares residual `r_a` through the error of the correction only,
//! `u_a = W_a dC` (covariance `Σ_u = W_a Cov(C) W_aᴴ`); the reported prediction
//! `R̂_a = r_a + v_a` scatters around it by `v_a` (covariance `Σ_v`,
//! `Propagation::prediction`). Bounding `|R_a|` by the 95 % quantile of
//! `N(R̂_a, Σ_u + Σ_v)` (the pivot `R_a − R̂_a`, what this module did first)
//! counts the noise twice where `r_a` is small: `|R̂_a|` is then already
//! inflated by `v_a` (a Rice distribution's bias), and the bound held 98–100 %
//! of the time on a rotor model. Where `|r_a|` is large beside the noise the
//! uncertainty of the centre moves `|R_a|` one for one and must be counted.
//!
//! So the centre is the estimate of `r_a` with its modulus corrected for that
//! bias, `m̂ = R̂ √max(0, 1 − tr Σ_v / |R̂|²)` (the moment estimate of a Rice
//! amplitude: `E|R̂|² = |r|² + tr Σ_v`), and the covariance
//! `Σ_u + ω Σ_v` with `ω = |m̂|² / (|m̂|² + tr Σ_v)`: the centre's uncertainty
//! counts in full where it is well away from the origin (`ω → 1`, the bound
//! tends to `|R̂| + 1.645 σ_radial` of the pivot) and not where it is noise
//! itself (`ω → 0`: the Rayleigh quantile of `u_a` alone). With as many rows as
//! planes `R̂ ≡ 0`, `Σ_v = 0`, and this is exactly the pivot bound. Checked on
//! the rotor model of tests/uncertainty/eiv.rs (93–97 % within binomial error).

use nalgebra::Matrix2;
use num_complex::Complex64;

use super::amplitude_95;

/// The 95 % bound of the remaining amplitude at a row: prediction `r_hat`,
/// covariance `prediction` of `R̂` and `through_c` of `W_a dC` (module doc).
pub fn remaining_amplitude_95(
    r_hat: Complex64,
    prediction: &Matrix2<f64>,
    through_c: &Matrix2<f64>,
) -> f64 {
    let tv = prediction.trace().max(0.0);
    let m2 = r_hat.norm_sqr();
    let shrink = if m2 > 0.0 {
        (1.0 - tv / m2).max(0.0).sqrt()
    } else {
        0.0
    };
    let centre = r_hat * shrink;
    let c2 = centre.norm_sqr();
    let omega = if c2 + tv > 0.0 { c2 / (c2 + tv) } else { 0.0 };
    amplitude_95(centre, &(through_c + prediction * omega))
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::DMatrix;

    /// Reference form (what `propagate` reads off its products, issue 15): real covariance of `Σ_j w_j C_j` from the joint real covariance of the
    /// corrections (`2q × 2q`, ordered Re C₀, Im C₀, Re C₁, …).
    fn through_correction(w: &[Complex64], full: &DMatrix<f64>) -> Matrix2<f64> {
        // Jacobian rows: Re(w C) = Re w·x − Im w·y, Im(w C) = Im w·x + Re w·y.
        let q = w.len();
        let jac = |o: usize, col: usize| {
            let z = w[col / 2];
            match (o, col % 2) {
                (0, 0) => z.re,
                (0, _) => -z.im,
                (_, 0) => z.im,
                _ => z.re,
            }
        };
        let mut out = Matrix2::zeros();
        for o in 0..2 {
            for p in 0..2 {
                let mut s = 0.0;
                for i in 0..2 * q {
                    let ji = jac(o, i);
                    if ji == 0.0 {
                        continue;
                    }
                    for k in 0..2 * q {
                        s += ji * full[(i, k)] * jac(p, k);
                    }
                }
                out[(o, p)] = s;
            }
        }
        out
    }

    #[test]
    fn the_propagation_gives_each_rows_covariance_through_the_correction() {
        // Two planes, one trial each, five rows: W from the runs (method 2.1),
        // and every row's `w K wᴴ`, `w J wᵀ` as the reference form gives it.
        let c = |re: f64, im: f64| Complex64::new(re, im);
        let t =
            DMatrix::from_row_slice(2, 2, &[c(10.0, 0.0), c(0.0, 0.0), c(0.0, 0.0), c(0.0, 8.0)]);
        let w = DMatrix::from_fn(5, 2, |a, j| {
            c(1.0 + a as f64 * 0.3, 0.5 - j as f64 + 0.1 * a as f64)
        });
        let y0 = DMatrix::from_fn(5, 1, |a, _| c(20.0 - 3.0 * a as f64, 4.0 + a as f64));
        let y = DMatrix::from_fn(5, 3, |a, k| match k {
            0 => y0[(a, 0)],
            _ => y0[(a, 0)] + w[(a, k - 1)] * t[(k - 1, k - 1)],
        });
        let cov: Vec<Vec<Matrix2<f64>>> = (0..5)
            .map(|a| {
                (0..3)
                    .map(|k| Matrix2::new(1.0 + a as f64, 0.2, 0.2, 0.5 + k as f64))
                    .collect()
            })
            .collect();
        let rows: Vec<usize> = (0..5).collect();
        let weights = vec![1.0, 2.0, 1.0, 0.5, 1.0];
        let corr = nalgebra::DVector::from_vec(vec![c(-3.0, 1.0), c(2.0, -2.5)]);
        let prop =
            crate::balancing::uncertainty::propagate(&t, &y, &cov, &rows, &weights, &[0, 1], &corr);
        for a in 0..5 {
            let row: Vec<Complex64> = (0..2).map(|j| w[(a, j)]).collect();
            let expected = through_correction(&row, &prop.correction_full);
            let got = prop.through_correction[a];
            assert!(
                (got - expected).norm() <= 1e-9 * expected.norm(),
                "row {a}: {got} against {expected}"
            );
        }
    }

    #[test]
    fn with_no_prediction_noise_the_bound_is_that_of_the_correction_error() {
        let cov = Matrix2::new(2.0, 0.3, 0.3, 1.0);
        let r = Complex64::new(0.0, 0.0);
        let b = remaining_amplitude_95(r, &Matrix2::zeros(), &cov);
        assert_eq!(b, amplitude_95(r, &cov));
    }

    #[test]
    fn the_covariance_through_the_correction_matches_the_complex_product() {
        // One plane, isotropic C error of variance 1 per axis: |w|² per axis.
        let w = [Complex64::new(3.0, 4.0)];
        let full = DMatrix::identity(2, 2);
        let s = through_correction(&w, &full);
        assert!((s - Matrix2::identity() * 25.0).norm() < 1e-12, "{s}");
    }

    #[test]
    fn a_prediction_that_is_noise_itself_is_centred_at_zero() {
        let v = Matrix2::identity() * 1.0;
        let u = Matrix2::identity() * 0.5;
        // |R̂|² = 1 < tr Σ_v = 2: the centre shrinks to 0, Σ_v does not count.
        let b = remaining_amplitude_95(Complex64::new(1.0, 0.0), &v, &u);
        assert!((b - amplitude_95(Complex64::new(0.0, 0.0), &u)).abs() < 1e-12);
    }
}
