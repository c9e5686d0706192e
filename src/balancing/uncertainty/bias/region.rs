//! The region of the least-squares correction where the errors-in-variables
//! estimate `C*` is formed (method 8.11): the correction's mean square error,
//! its scatter and its bias.
//!
//! The bias `b(C) = B C + b₀` is complex-affine in `C` ([`super::Unbiased`]),
//! so `Ĉ = C* + b(C*) = (I + B) C* + b₀`: `Ĉ` scatters as `(I + B) Σ (I +
//! B)ᴴ`, `Σ` the scatter of `C*` (8.2 formed at `C*`), and the estimated bias
//! `b̂ = Ĉ − C* = b(C*)` errs from `b(C)` by `B (C* − C)`, so `b̂ b̂ᴴ − B Σ
//! Bᴴ` estimates `b bᴴ` (positive part). With one complex degree of freedom
//! over the planes `I + B ≈ (ÂᴴÂ)⁻¹(ÂᴴÂ − M̂)` is near singular (method 8.3,
//! "one speed"), and the region is `Σ + b̂ b̂ᵀ` instead. Measured in method
//! §8, session 13.
//!
//! The same simpler form where `‖B‖₂` reaches [`super::CONTRACTION`]
//! (session 15): there the fixed point of (8.3) does not contract, `C*` is
//! the partial correction and short of the exact one (0.75–0.89 sd on the
//! calibration rotor at four speeds 1500–4500 rpm with 10 % trials, `‖B‖₂`
//! 0.5–2.2), so the map form's `b̂ b̂ᴴ − B Σ Bᴴ` understates the bias and its
//! `(I + B)` is an expansion that does not converge: that case's ellipses
//! held 82.5 %, now 93.0 % (tests/uncertainty/few_speeds.rs holds it).
//! eiv.rs's ten speeds never reach it (identical figures).

use nalgebra::{DMatrix, DVector, Matrix2, Vector2};
use num_complex::Complex64;

use super::Unbiased;

/// What every plane's region needs, formed once per solve.
pub struct Region {
    /// `b̂ = Ĉ − C*` per used plane.
    bias: DVector<Complex64>,
    /// `(I + B) Σ (I + B)ᵀ` and `B Σ Bᵀ` in real `2q × 2q` form; `None` for
    /// the simpler form (one complex degree of freedom over the planes).
    spread_leak: Option<(DMatrix<f64>, DMatrix<f64>)>,
}

impl Region {
    /// `c` the fitted correction, `sigma` the real joint covariance of
    /// `C*` (`Propagation::correction_full`), `map_form` whether the map
    /// form applies (two or more complex degrees of freedom over the planes).
    pub fn new(
        u: &Unbiased,
        c: &DVector<Complex64>,
        sigma: &DMatrix<f64>,
        map_form: bool,
    ) -> Region {
        // The map form only where the expansion behind it contracts (module doc).
        let contracts = || {
            let norm = u.map.clone().svd(false, false).singular_values.max();
            norm < super::CONTRACTION
        };
        let spread_leak = (map_form && contracts()).then(|| {
            let rb = real_form(&u.map);
            let i_rb = DMatrix::<f64>::identity(rb.nrows(), rb.ncols()) + &rb;
            (
                &i_rb * sigma * i_rb.transpose(),
                &rb * sigma * rb.transpose(),
            )
        });
        Region {
            bias: c - &u.c,
            spread_leak,
        }
    }

    /// Plane `col`'s mean square error (8.11): `widened` its covariance
    /// `Σ_jj` already scaled by `scale` ((8.4) and the samples' widening),
    /// which scales the map form's blocks alike.
    pub fn plane(&self, col: usize, widened: &Matrix2<f64>, scale: f64) -> Matrix2<f64> {
        let b = self.bias[col];
        let b = Vector2::new(b.re, b.im);
        let bb = b * b.transpose();
        match &self.spread_leak {
            Some((spread, leak)) => {
                let block = |m: &DMatrix<f64>| m.fixed_view::<2, 2>(2 * col, 2 * col) * scale;
                block(spread) + positive_part(&(bb - block(leak)))
            }
            None => widened + bb,
        }
    }
}

/// The real `2q × 2q` form of a complex `q × q` map, in the order
/// (Re C₀, Im C₀, Re C₁, …) of `Propagation::correction_full`.
fn real_form(m: &DMatrix<Complex64>) -> DMatrix<f64> {
    DMatrix::from_fn(2 * m.nrows(), 2 * m.ncols(), |r, c| {
        let z = m[(r / 2, c / 2)];
        match (r % 2, c % 2) {
            (0, 0) | (1, 1) => z.re,
            (0, 1) => -z.im,
            _ => z.im,
        }
    })
}

/// A symmetric 2×2 matrix with its negative eigenvalues set to 0, in closed
/// form (no iteration; with `λ₁ > 0 > λ₂` the part is `λ₁ (M − λ₂ I) / (λ₁ −
/// λ₂)`, the projector on `λ₁`'s axis). A matrix that is not finite is
/// returned as it is.
fn positive_part(m: &Matrix2<f64>) -> Matrix2<f64> {
    let m = (m + m.transpose()) * 0.5;
    if !m.iter().all(|x| x.is_finite()) {
        return m;
    }
    let (a, b, d) = (m[(0, 0)], m[(0, 1)], m[(1, 1)]);
    let mid = 0.5 * (a + d);
    let rad = (0.5 * (a - d)).hypot(b);
    let (hi, lo) = (mid + rad, mid - rad);
    if lo >= 0.0 {
        m
    } else if hi <= 0.0 {
        Matrix2::zeros()
    } else {
        (m - Matrix2::identity() * lo) * (hi / (hi - lo))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_real_form_multiplies_as_the_complex_map_does() {
        let m = DMatrix::from_row_slice(
            2,
            2,
            &[
                Complex64::new(0.3, -1.2),
                Complex64::new(-0.7, 0.4),
                Complex64::new(2.0, 0.5),
                Complex64::new(0.1, 0.9),
            ],
        );
        let z = DVector::from_vec(vec![Complex64::new(1.5, -0.25), Complex64::new(-3.0, 2.0)]);
        let x = DVector::from_fn(4, |i, _| if i % 2 == 0 { z[i / 2].re } else { z[i / 2].im });
        let want = &m * &z;
        let got = real_form(&m) * x;
        for j in 0..2 {
            assert!((got[2 * j] - want[j].re).abs() < 1e-12, "{got} {want}");
            assert!((got[2 * j + 1] - want[j].im).abs() < 1e-12, "{got} {want}");
        }
    }

    #[test]
    fn the_positive_part_keeps_a_covariance_and_drops_what_is_negative() {
        let cov = Matrix2::new(2.0, 0.5, 0.5, 1.0);
        assert!((positive_part(&cov) - cov).norm() < 1e-12);
        assert!(positive_part(&(-cov)).norm() < 1e-12);
        // One axis of each sign: only the positive one is kept.
        let mixed = Matrix2::new(1.0, 0.0, 0.0, -4.0);
        assert!((positive_part(&mixed) - Matrix2::new(1.0, 0.0, 0.0, 0.0)).norm() < 1e-12);
        // Off the axes: eigenvalues 3 and −1 along (1, 1)/√2 and (1, −1)/√2.
        let turned = Matrix2::new(1.0, 2.0, 2.0, 1.0);
        assert!((positive_part(&turned) - Matrix2::new(1.5, 1.5, 1.5, 1.5)).norm() < 1e-12);
        // Not finite: returned as it is, never an endless iteration.
        assert!(positive_part(&Matrix2::new(f64::NAN, 0.0, 0.0, 1.0))[(0, 0)].is_nan());
    }

    #[test]
    fn with_no_bias_map_the_region_is_the_scatter_plus_the_bias_squared() {
        let u = Unbiased {
            c: DVector::from_vec(vec![Complex64::new(1.0, 1.0)]),
            map: DMatrix::from_element(1, 1, Complex64::new(-0.2, 0.0)),
        };
        let c = DVector::from_vec(vec![Complex64::new(0.8, 0.9)]);
        let sigma = DMatrix::from_row_slice(2, 2, &[0.04, 0.0, 0.0, 0.04]);
        let widened = Matrix2::new(0.05, 0.0, 0.0, 0.05);
        let simple = Region::new(&u, &c, &sigma, false).plane(0, &widened, 1.25);
        let b = Vector2::new(-0.2, -0.1);
        assert!((simple - (widened + b * b.transpose())).norm() < 1e-12);
        // The map form: B = −0.2 shrinks the scatter to 0.64 Σ and takes
        // B Σ Bᵀ = 0.04 Σ off the bias' square (scaled alike).
        let mapped = Region::new(&u, &c, &sigma, true).plane(0, &widened, 1.25);
        let leak = Matrix2::new(0.0016, 0.0, 0.0, 0.0016) * 1.25;
        let want = Matrix2::new(0.0256, 0.0, 0.0, 0.0256) * 1.25
            + positive_part(&(b * b.transpose() - leak));
        assert!((mapped - want).norm() < 1e-12, "{mapped} {want}");
    }
}
