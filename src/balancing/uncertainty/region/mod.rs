//! The contract's 95 % figures from a 2×2 covariance: the confidence region of
//! a correction with its mass and angle intervals, and the upper bound of a
//! residual amplitude; conversion to the session's angle convention.

use nalgebra::{Matrix2, SymmetricEigen, Vector2};
use num_complex::Complex64;

use crate::balancing::model::{AngleDirection, Conventions};
use crate::balancing::phasor::{weight_out, wrap_deg};
use crate::balancing::solution::Uncertainty;
use ellipse::Ellipse;
use quantile::newton::newton;
use quantile::polar::Polar;
use quantile::quadrature;

mod ellipse;
pub(super) mod quantile;

/// 95 % quantile of χ² with 2 degrees of freedom, `−2 ln 0.05`.
pub const CHI2_2_95: f64 = 5.991_464_547_107_979;
/// Eigen-decomposition of a covariance, variances clipped at 0, larger first.
pub(super) fn axes(cov: &Matrix2<f64>) -> [(f64, Vector2<f64>); 2] {
    let sym = (cov + cov.transpose()) / 2.0;
    let e = SymmetricEigen::new(sym);
    let mut ax = [0, 1].map(|i| {
        (
            e.eigenvalues[i].max(0.0),
            e.eigenvectors.column(i).into_owned(),
        )
    });
    if ax[0].0 < ax[1].0 {
        ax.swap(0, 1);
    }
    ax
}

/// The 95 % confidence region of a correction `c` (internal frame, grams) with
/// covariance `cov` of (Re c, Im c), in the session's conventions.
///
/// Region: the χ²₂ ellipse `{z : (z − c)ᵀ Σ⁻¹ (z − c) ≤ 5.991}`, which holds the
/// true correction with probability 95 % when the error is Gaussian (first order).
/// The intervals are its projections: the mass interval is `[min |z|, max |z|]`
/// and the angle interval the range of `arg z` over the ellipse (found on its
/// boundary, where these extremes lie). Both therefore hold at least 95 %
/// (they are simultaneous, slightly wider than one-at-a-time intervals). When
/// the ellipse contains the origin the angle is undetermined: mass from 0,
/// angle `[0, 360]`.
///
/// The angle interval is in the session's `angle_direction`, lower end in
/// `[0, 360)`, upper end = lower + width (so it may exceed 360). The covariance
/// is reported with the imaginary axis at +90° in that direction: against
/// rotation flips the imaginary axis, which flips the sign of the off-diagonal.
pub fn correction_uncertainty(c: Complex64, cov: &Matrix2<f64>, conv: Conventions) -> Uncertainty {
    let k = CHI2_2_95.sqrt();
    let ax = axes(cov);
    // Mahalanobis distance of the origin; a zero variance along a direction in
    // which the origin differs makes it infinitely far.
    let d2: f64 = ax
        .iter()
        .map(|(lam, v)| {
            let p = v.x * c.re + v.y * c.im;
            if *lam > 0.0 {
                p * p / lam
            } else if p.abs() > 0.0 {
                f64::INFINITY
            } else {
                0.0
            }
        })
        .sum();
    let (mass, theta) = weight_out(conv, c);
    let ellipse = Ellipse::new(c, &ax, k);
    let (mass_g, angle_deg) = if d2 <= CHI2_2_95 {
        ([0.0, ellipse.farthest()], [0.0, 360.0])
    } else if ax[0].0 == 0.0 {
        ([mass, mass], [theta, theta])
    } else {
        // Angle offset from c's own angle, internal frame (with rotation):
        // continuous over the ellipse, which holds neither the origin nor
        // (being convex) any point opposite c.
        let (dlo, dhi) = ellipse.tangent_offsets();
        let (a, b) = match conv.angle_direction {
            AngleDirection::WithRotation => (dlo, dhi),
            AngleDirection::AgainstRotation => (-dhi, -dlo),
        };
        let lower = wrap_deg(theta + a.to_degrees());
        (
            [ellipse.nearest(), ellipse.farthest()],
            [lower, lower + (b - a).to_degrees()],
        )
    };
    let off = match conv.angle_direction {
        AngleDirection::WithRotation => cov[(0, 1)],
        // `+ 0.0`: a zero off-diagonal stays 0, not `-0.0` on the wire.
        AngleDirection::AgainstRotation => -cov[(0, 1)] + 0.0,
    };
    Uncertainty {
        mass_g: Some(mass_g),
        angle_deg,
        covariance_g2: [[cov[(0, 0)], off], [off, cov[(1, 1)]]],
        bias_corrected: None,
    }
}

/// The 95 % upper bound of the amplitude `|R|` when `R` is Gaussian with mean
/// `mean` and covariance `cov` of (Re, Im) (method §8, formula 8.6).
///
/// Not an approximation by a simpler distribution: the 95 % quantile of `|R|`
/// is found by safeguarded Newton on `P(|R| ≤ ρ) = 0.95` (to 10⁻⁷ in
/// probability, about 10⁻⁶σ in the bound, `newton::TOL_Q`), with `P` and its
/// derivatives from the trapezoidal rule over the direction seen from the
/// mean, the integral along each ray in closed form, with as many directions
/// as the rule's analytic error bound asks for (`polar`, issue 15, session 8:
/// within 10⁻⁹ in probability); where that would take more than 1280
/// directions (ρ within a hair of `|μ|`, which Newton seldom visits) by
/// one-dimensional adaptive quadrature in the principal axes
/// (`quadrature`). The one approximation is the first-order (Gaussian)
/// error model itself. Tests compare the bound with a Monte Carlo of the
/// Gaussian and with bisection on the quadrature.
/// For `μ = 0` and isotropic σ this is the Rayleigh quantile `σ√5.991`; for
/// `|μ| ≫ σ` it tends to `|μ| + 1.645 σ_radial`.
pub fn amplitude_95(mean: Complex64, cov: &Matrix2<f64>) -> f64 {
    quantile(mean, cov, |mu1, mu2, s1, s2| {
        let mut ring = Polar::new(mu1, mu2, s1, s2);
        move |rho| {
            #[cfg(test)]
            EVALS.with(|n| n.set(n.get() + 1));
            if let Some(p) = ring.as_mut().and_then(|r| r.moments(rho)) {
                return p;
            }
            by_quadrature(mu1, mu2, s1, s2, rho)
        }
    })
}

#[cfg(test)]
thread_local! {
    /// Evaluations of the rule by `amplitude_95` on this thread (tests).
    pub(super) static EVALS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

/// `amplitude_95` with the adaptive quadrature alone (what it was before
/// issue 15's fast path): the reference of the tests.
#[cfg(test)]
pub fn amplitude_95_by_quadrature(mean: Complex64, cov: &Matrix2<f64>) -> f64 {
    quantile(mean, cov, |mu1, mu2, s1, s2| {
        move |rho| by_quadrature(mu1, mu2, s1, s2, rho)
    })
}

/// `[P, P', NaN, NaN]` from the quadrature, which has no higher derivatives
/// (`newton` then estimates `P''` from its previous step).
fn by_quadrature(mu1: f64, mu2: f64, s1: f64, s2: f64, rho: f64) -> [f64; 4] {
    let [p, dp] = quadrature::inside(mu1, mu2, s1, s2, rho);
    [p, dp, f64::NAN, f64::NAN]
}

/// `[μ₁, μ₂, σ₁, σ₂]`: the mean and standard deviations in the principal
/// axes of `cov` (σ₁ ≥ σ₂); `None` where there is no spread beside `|μ|`.
pub(super) fn principal(mean: &Complex64, cov: &Matrix2<f64>) -> Option<[f64; 4]> {
    let ax = axes(cov);
    let (s1, s2) = (ax[0].0.sqrt(), ax[1].0.sqrt());
    if s1.is_nan() || s1 <= 1e-12 * mean.norm() || !s1.is_finite() {
        return None;
    }
    let mu1 = ax[0].1.x * mean.re + ax[0].1.y * mean.im;
    let mu2 = ax[1].1.x * mean.re + ax[1].1.y * mean.im;
    Some([mu1, mu2, s1, s2])
}

/// The Newton iteration of [`amplitude_95`]; `rule(μ₁, μ₂, σ₁, σ₂)` gives
/// `ρ ↦ [P(|R| ≤ ρ), P', P'', P''']` in the principal axes (σ₁ ≥ σ₂), the
/// last two NaN where the rule has none.
fn quantile<P: FnMut(f64) -> [f64; 4]>(
    mean: Complex64,
    cov: &Matrix2<f64>,
    rule: impl FnOnce(f64, f64, f64, f64) -> P,
) -> f64 {
    let m = mean.norm();
    let Some([mu1, mu2, s1, s2]) = principal(&mean, cov) else {
        return m;
    };
    let inside = rule(mu1, mu2, s1, s2);
    // The quantile lies in [|μ|, |μ| + 2.448σ₁]: the disc of radius |μ| lies in
    // a half-plane through μ (probability ½), and the disc of radius
    // √5.991·σ₁ around μ holds the χ²₂ 95 % ellipse. Newton's method on
    // P(ρ) = 0.95 with P' from the same rule, kept inside the bracket by
    // bisection. The first guess matches `|R|² ≈ c χ²_ν` in mean
    // `E = |μ|² + tr Σ` and variance `V = 2 tr Σ² + 4 μᵀΣμ` (Patnaik 1949)
    // and takes that quantile by Wilson and Hilferty's cube root (1931):
    // a third fewer steps than `|μ| + 1.645 σ_radial` (2 to 3; issue 15,
    // session 6).
    let (lo, hi) = (m, m + CHI2_2_95.sqrt() * s1);
    let mv = Vector2::new(mean.re, mean.im);
    let e = m * m + cov.trace();
    let v = 2.0 * (cov * cov).trace() + 4.0 * (mv.transpose() * cov * mv)[0];
    let nu = 2.0 * e * e / v;
    let w = 2.0 / (9.0 * nu);
    let x = (v / (2.0 * e) * nu * (1.0 - w + 1.644_853_626_951_472_2 * w.sqrt()).powi(3)).sqrt();
    newton(inside, x, lo, hi)
}

/// Standard normal distribution function, `½ erfc(−x/√2)` with musl's
/// `erfc` (`libm`, within an ulp or two). Until issue 15's session 8 this
/// was Numerical Recipes' `erfcc`, within 1.2·10⁻⁷ only: the quadrature
/// reference of the tests was then up to 9·10⁻⁷ off in probability for
/// masses thin across the circle, more than the polar rule it checks.
pub fn normal_cdf(x: f64) -> f64 {
    0.5 * libm::erfc(-x * std::f64::consts::FRAC_1_SQRT_2)
}
