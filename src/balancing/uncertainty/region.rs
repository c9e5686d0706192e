//! The contract's 95 % figures from a 2×2 covariance: the confidence region of
//! a correction with its mass and angle intervals, and the upper bound of a
//! residual amplitude; conversion to the session's angle convention.

use nalgebra::{Matrix2, SymmetricEigen, Vector2};
use num_complex::Complex64;

use crate::balancing::model::{AngleDirection, Conventions};
use crate::balancing::phasor::{weight_out, wrap_deg};
use crate::balancing::solution::Uncertainty;

/// 95 % quantile of χ² with 2 degrees of freedom, `−2 ln 0.05`.
pub const CHI2_2_95: f64 = 5.991_464_547_107_979;
/// Points on the ellipse boundary searched for the extreme mass and angle; the
/// error of an extreme is below `(π/N)²/2 ≈ 2·10⁻⁶` of the ellipse's size.
const BOUNDARY_POINTS: usize = 1440;

/// Eigen-decomposition of a covariance, variances clipped at 0, larger first.
fn axes(cov: &Matrix2<f64>) -> [(f64, Vector2<f64>); 2] {
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
    let (mass_g, angle_deg) = if d2 <= CHI2_2_95 {
        let max = boundary(c, &ax, k).map(|z| z.norm()).fold(0.0, f64::max);
        ([0.0, max], [0.0, 360.0])
    } else {
        let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
        let (mut dlo, mut dhi) = (0.0f64, 0.0f64);
        for z in boundary(c, &ax, k) {
            lo = lo.min(z.norm());
            hi = hi.max(z.norm());
            // Angle offset from c's own angle, internal frame (with rotation).
            let d = (z * c.conj()).arg();
            dlo = dlo.min(d);
            dhi = dhi.max(d);
        }
        if hi == 0.0 {
            lo = mass;
            hi = mass;
        }
        let (a, b) = match conv.angle_direction {
            AngleDirection::WithRotation => (dlo, dhi),
            AngleDirection::AgainstRotation => (-dhi, -dlo),
        };
        let lower = wrap_deg(theta + a.to_degrees());
        ([lo, hi], [lower, lower + (b - a).to_degrees()])
    };
    let off = match conv.angle_direction {
        AngleDirection::WithRotation => cov[(0, 1)],
        AngleDirection::AgainstRotation => -cov[(0, 1)],
    };
    Uncertainty {
        mass_g,
        angle_deg,
        covariance_g2: [[cov[(0, 0)], off], [off, cov[(1, 1)]]],
    }
}

/// Points `c + k·L·(cos t, sin t)` on the ellipse boundary, `L Lᵀ = Σ`.
fn boundary(
    c: Complex64,
    ax: &[(f64, Vector2<f64>); 2],
    k: f64,
) -> impl Iterator<Item = Complex64> + '_ {
    let (l1, l2) = (ax[0].0.sqrt() * k, ax[1].0.sqrt() * k);
    (0..BOUNDARY_POINTS).map(move |i| {
        let (s, co) = (std::f64::consts::TAU * i as f64 / BOUNDARY_POINTS as f64).sin_cos();
        let v = ax[0].1 * (l1 * co) + ax[1].1 * (l2 * s);
        c + Complex64::new(v.x, v.y)
    })
}

/// The 95 % upper bound of the amplitude `|R|` when `R` is Gaussian with mean
/// `mean` and covariance `cov` of (Re, Im).
///
/// Not an approximation by a simpler distribution: the 95 % quantile of `|R|`
/// is found by bisection on `P(|R| ≤ ρ)`, computed by one-dimensional
/// quadrature in the principal axes (`R = μ + σ₁z₁e₁ + σ₂z₂e₂`, σ₁ ≥ σ₂):
/// `P = ∫ φ(z₁) [Φ((h−μ₂)/σ₂) − Φ((−h−μ₂)/σ₂)] dz₁`, `h = √(ρ² − (μ₁+σ₁z₁)²)`,
/// over `z₁ ∈ [−9, 9]` (less where `|μ₁+σ₁z₁| > ρ`) by adaptive Simpson on unit panels (tolerance 10⁻⁷; the integrand has
/// kinks where `h → 0`, and steps when σ₂ is tiny, which the adaptivity
/// resolves). Φ is within 1.2·10⁻⁷ (see [`normal_cdf`]). The approximation is
/// the first-order (Gaussian) error model itself; the test compares the bound
/// with a Monte Carlo of the Gaussian. For `μ = 0` and isotropic σ this is the
/// Rayleigh quantile `σ√5.991`; for `|μ| ≫ σ` it tends to `|μ| + 1.645 σ_radial`.
pub fn amplitude_95(mean: Complex64, cov: &Matrix2<f64>) -> f64 {
    let ax = axes(cov);
    let (s1, s2) = (ax[0].0.sqrt(), ax[1].0.sqrt());
    let m = mean.norm();
    if s1.is_nan() || s1 <= 1e-12 * m || !s1.is_finite() {
        return m;
    }
    let mu1 = ax[0].1.x * mean.re + ax[0].1.y * mean.im;
    let mu2 = ax[1].1.x * mean.re + ax[1].1.y * mean.im;
    // P(|R| ≤ |μ| + 4σ₁) ≥ P(χ²₂ ≤ 16) = 1 − e⁻⁸, so the quantile lies below.
    let (mut lo, mut hi) = (0.0, m + 4.0 * s1);
    while hi - lo > 1e-7 * hi {
        let mid = 0.5 * (lo + hi);
        if inside(mu1, mu2, s1, s2, mid) < 0.95 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    hi
}

/// `P((μ₁+σ₁z₁)² + (μ₂+σ₂z₂)² ≤ ρ²)` for independent standard normal z₁, z₂.
fn inside(mu1: f64, mu2: f64, s1: f64, s2: f64, rho: f64) -> f64 {
    let inner = |z: f64| {
        let x = mu1 + s1 * z;
        let h2 = rho * rho - x * x;
        if h2 <= 0.0 {
            return 0.0;
        }
        let h = h2.sqrt();
        let p = if s2 > 0.0 {
            normal_cdf((h - mu2) / s2) - normal_cdf((-h - mu2) / s2)
        } else if mu2.abs() <= h {
            1.0
        } else {
            0.0
        };
        p * (-0.5 * z * z).exp() / (std::f64::consts::TAU).sqrt()
    };
    let a = ((-rho - mu1) / s1).max(-9.0);
    let b = ((rho - mu1) / s1).min(9.0);
    if a >= b {
        return 0.0;
    }
    // Start from panels of at most one unit of z₁: a support narrower than one
    // panel that all the panel's nodes miss holds under 0.4 of the probability,
    // so it cannot decide whether P reaches 0.95.
    let panels = ((b - a).ceil() as usize).max(1);
    let step = (b - a) / panels as f64;
    (0..panels)
        .map(|i| {
            let lo = a + step * i as f64;
            simpson(&inner, lo, lo + step, 1e-7 / panels as f64, 40)
        })
        .sum()
}

/// Adaptive Simpson quadrature.
fn simpson(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64, depth: u32) -> f64 {
    let (fa, fm, fb) = (f(a), f(0.5 * (a + b)), f(b));
    let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    refine(f, a, b, fa, fm, fb, whole, tol, depth)
}

#[allow(clippy::too_many_arguments)]
fn refine(
    f: &dyn Fn(f64) -> f64,
    a: f64,
    b: f64,
    fa: f64,
    fm: f64,
    fb: f64,
    whole: f64,
    tol: f64,
    depth: u32,
) -> f64 {
    let m = 0.5 * (a + b);
    let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
    let (flm, frm) = (f(lm), f(rm));
    let left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
    let right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
    let delta = left + right - whole;
    if depth == 0 || delta.abs() <= 15.0 * tol {
        return left + right + delta / 15.0;
    }
    refine(f, a, m, fa, flm, fm, left, tol / 2.0, depth - 1)
        + refine(f, m, b, fm, frm, fb, right, tol / 2.0, depth - 1)
}

/// Standard normal distribution function, through the complementary error
/// function of Numerical Recipes (`erfcc`, Chebyshev fit, fractional error
/// below 1.2·10⁻⁷ everywhere).
pub fn normal_cdf(x: f64) -> f64 {
    let z = -x / std::f64::consts::SQRT_2;
    let a = z.abs();
    let t = 1.0 / (1.0 + 0.5 * a);
    let poly = -a * a - 1.265_512_23
        + t * (1.000_023_68
            + t * (0.374_091_96
                + t * (0.096_784_18
                    + t * (-0.186_288_06
                        + t * (0.278_868_07
                            + t * (-1.135_203_98
                                + t * (1.488_515_87 + t * (-0.822_152_23 + t * 0.170_872_77))))))));
    let erfc = t * poly.exp();
    0.5 * if z >= 0.0 { erfc } else { 2.0 - erfc }
}
