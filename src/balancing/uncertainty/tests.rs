//! Unit tests of the 95 % figures against closed forms and a Monte Carlo of the Gaussian.

use nalgebra::{Matrix2, Vector2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, StandardNormal};

use super::region::amplitude_95_by_quadrature;
use super::region::quantile::polar::Polar;
use super::{amplitude_95, correction_uncertainty, normal_cdf, CHI2_2_95};
use crate::balancing::model::{AngleDirection, Conventions, PhaseConvention};

const WITH: Conventions = Conventions {
    phase: PhaseConvention::Lead,
    angle_direction: AngleDirection::WithRotation,
};
const AGAINST: Conventions = Conventions {
    phase: PhaseConvention::Lag,
    angle_direction: AngleDirection::AgainstRotation,
};

#[test]
fn the_normal_distribution_function_matches_known_values() {
    for (x, p) in [
        (0.0, 0.5),
        (1.0, 0.841_344_746),
        (-1.959_963_985, 0.025),
        (1.644_853_627, 0.95),
        (-4.0, 3.167_124e-5),
    ] {
        assert!(
            (normal_cdf(x) - p).abs() < 2e-7 * p.max(1e-3),
            "{x}: {} vs {p}",
            normal_cdf(x)
        );
    }
}

#[test]
fn a_centred_isotropic_residual_has_the_rayleigh_quantile() {
    let s = 0.7;
    let q = amplitude_95(Complex64::new(0.0, 0.0), &(Matrix2::identity() * s * s));
    // Within the documented 10⁻³σ.
    assert!((q - s * CHI2_2_95.sqrt()).abs() < 1e-3 * s, "{q}");
}

#[test]
fn the_amplitude_bound_holds_95_percent_of_gaussian_draws() {
    // Centred, far along the mean (→ |μ| + 1.645 σ), pure phase noise across
    // the mean (a thin ellipse), and a correlated one at 45°.
    let cases = [
        (Complex64::new(0.0, 0.0), Matrix2::new(1.0, 0.3, 0.3, 0.2)),
        (Complex64::new(20.0, 0.0), Matrix2::new(1.0, 0.0, 0.0, 1.0)),
        (Complex64::new(0.0, 10.0), Matrix2::new(4.0, 0.0, 0.0, 1e-6)),
        (Complex64::new(3.0, 3.0), Matrix2::new(2.0, 1.5, 1.5, 2.0)),
        (
            Complex64::new(1.0, -0.5),
            Matrix2::new(0.5, -0.2, -0.2, 0.3),
        ),
    ];
    let mut rng = StdRng::seed_from_u64(11);
    for (mu, cov) in cases {
        let bound = amplitude_95(mu, &cov);
        let l = cov.cholesky().expect("positive definite").l();
        let n = 40_000;
        let below = (0..n)
            .filter(|_| {
                let z = Vector2::new(
                    StandardNormal.sample(&mut rng),
                    StandardNormal.sample(&mut rng),
                );
                let d = l * z;
                (mu + Complex64::new(d.x, d.y)).norm() <= bound
            })
            .count();
        let p = below as f64 / n as f64;
        // Binomial sd 0.11 %: ±0.5 % is 4.5 sd.
        assert!((p - 0.95).abs() < 0.005, "{mu} {cov}: {p} below {bound}");
    }
    // Far from the origin the bound tends to |μ| + 1.645 σ.
    let far = amplitude_95(Complex64::new(100.0, 0.0), &Matrix2::identity());
    assert!((far - 101.645).abs() < 0.02, "{far}");
}

#[test]
fn an_isotropic_region_gives_symmetric_mass_and_angle_intervals() {
    let s = 2.0;
    let c = Complex64::from_polar(50.0, 40f64.to_radians());
    let u = correction_uncertainty(c, &(Matrix2::identity() * s * s), WITH);
    let r = CHI2_2_95.sqrt() * s;
    assert!(
        (u.mass_g.unwrap()[0] - (50.0 - r)).abs() < 1e-6
            && (u.mass_g.unwrap()[1] - (50.0 + r)).abs() < 1e-6,
        "{u:?}"
    );
    let half = (r / 50.0).asin().to_degrees();
    assert!(
        (u.angle_deg[0] - (40.0 - half)).abs() < 1e-6
            && (u.angle_deg[1] - (40.0 + half)).abs() < 1e-6,
        "{u:?}"
    );
}

#[test]
fn against_rotation_mirrors_the_angles_and_flips_the_covariance_off_diagonal() {
    let c = Complex64::from_polar(30.0, 10f64.to_radians()); // internal: 10° with rotation
    let cov = Matrix2::new(4.0, 1.5, 1.5, 2.0);
    let w = correction_uncertainty(c, &cov, WITH);
    let a = correction_uncertainty(c, &cov, AGAINST);
    assert_eq!(w.covariance_g2, [[4.0, 1.5], [1.5, 2.0]]);
    assert_eq!(a.covariance_g2, [[4.0, -1.5], [-1.5, 2.0]]);
    assert_eq!(w.mass_g, a.mass_g);
    // [lo, hi] with rotation is [360 − hi, 360 − lo] against it.
    assert!(
        (a.angle_deg[0] - (360.0 - w.angle_deg[1])).abs() < 1e-9,
        "{w:?} {a:?}"
    );
    assert!(
        (a.angle_deg[1] - (360.0 - w.angle_deg[0])).abs() < 1e-9,
        "{w:?} {a:?}"
    );
    // The interval is around the correction's own angle, wrapping past 360.
    assert!(w.angle_deg[0] < 10.0 && w.angle_deg[1] > 10.0);
    assert!(a.angle_deg[0] < 350.0 && a.angle_deg[1] > 350.0);
}

#[test]
fn an_interval_across_zero_degrees_ends_above_360() {
    let c = Complex64::from_polar(20.0, 2f64.to_radians());
    let u = correction_uncertainty(c, &(Matrix2::identity() * 1.0), WITH);
    assert!(u.angle_deg[0] > 350.0 && u.angle_deg[1] > 360.0, "{u:?}");
}

#[test]
fn a_region_around_the_origin_leaves_the_angle_open() {
    let c = Complex64::new(1.0, 1.0);
    let u = correction_uncertainty(c, &(Matrix2::identity() * 4.0), AGAINST);
    assert_eq!(u.angle_deg, [0.0, 360.0]);
    assert_eq!(u.mass_g.unwrap()[0], 0.0);
    assert!(
        (u.mass_g.unwrap()[1] - (2f64.sqrt() + 2.0 * CHI2_2_95.sqrt())).abs() < 1e-6,
        "{u:?}"
    );
}

#[test]
fn a_singular_covariance_still_gives_the_exact_bound() {
    // Spread only across the mean: |R| = √(10² + (2z)²), so q = √(100 + 4·1.96²).
    let q = amplitude_95(Complex64::new(0.0, 10.0), &Matrix2::new(4.0, 0.0, 0.0, 0.0));
    let exact = (100.0 + 4.0 * 1.959_964f64.powi(2)).sqrt();
    assert!((q - exact).abs() < 1e-3, "{q} vs {exact}");
}

/// A covariance with standard deviations `s1`, `s2` along axes turned by `phi`.
fn turned(s1: f64, s2: f64, phi: f64) -> Matrix2<f64> {
    let (s, c) = phi.sin_cos();
    let r = Matrix2::new(c, -s, s, c);
    r * Matrix2::new(s1 * s1, 0.0, 0.0, s2 * s2) * r.transpose()
}

/// Seeded rows over the regimes the bound meets: centred and off-centre,
/// isotropic to degenerate, mean from 0 to 30 σ₁.
fn random_rows(n: usize) -> Vec<(Complex64, Matrix2<f64>)> {
    use rand::Rng;
    let mut rng = StdRng::seed_from_u64(15);
    (0..n)
        .map(|i| {
            let s1 = rng.gen_range(-3.0f64..3.0).exp();
            let ratio = match i % 5 {
                0 => 1.0,
                1 => rng.gen_range(0.8..1.0),
                2 => rng.gen_range(0.0..1.0),
                3 => 10f64.powf(rng.gen_range(-4.0..0.0)),
                _ => 0.0,
            };
            let m = s1
                * match i % 3 {
                    0 => 0.0,
                    1 => rng.gen_range(0.0..3.0),
                    _ => rng.gen_range(0.0..30.0),
                };
            let mean = Complex64::from_polar(m, rng.gen_range(0.0..std::f64::consts::TAU));
            (
                mean,
                turned(s1, s1 * ratio, rng.gen_range(0.0..std::f64::consts::PI)),
            )
        })
        .collect()
}

#[test]
fn the_polar_rule_gives_the_rayleigh_distribution_to_rounding() {
    for (s, rho) in [(0.7, 0.1), (0.7, 1.7), (3.0, 7.4), (1e-3, 2.5e-3)] {
        let mut ring = Polar::new(0.0, 0.0, s, s).expect("isotropic");
        let [p, dp] = ring.inside(rho).expect("converges");
        let e = (-0.5 * rho * rho / (s * s)).exp();
        assert!((p - (1.0 - e)).abs() < 1e-14, "{p} vs {}", 1.0 - e);
        assert!((dp - rho / (s * s) * e).abs() < 1e-13 * dp, "{dp}");
    }
}

#[test]
fn the_polar_rule_agrees_with_the_quadrature_wherever_it_converges() {
    let (mut worst, mut used) = (0.0f64, 0);
    for (mean, cov) in random_rows(600) {
        let ax = super::region::principal(&mean, &cov);
        let Some([mu1, mu2, s1, s2]) = ax else {
            continue;
        };
        let Some(mut ring) = Polar::new(mu1, mu2, s1, s2) else {
            continue;
        };
        // Around the 95 % quantile and well below and above it.
        let q = amplitude_95_by_quadrature(mean, &cov);
        for rho in [0.5 * q, q, 1.3 * q] {
            let Some([p, _]) = ring.inside(rho) else {
                continue;
            };
            let [r, _] = super::region::quantile::quadrature::inside(mu1, mu2, s1, s2, rho);
            worst = worst.max((p - r).abs());
            used += 1;
        }
    }
    eprintln!("polar against quadrature: {used} points, largest difference {worst:e}");
    assert!(
        used > 600,
        "the fast rule converged for {used} of 1800 points"
    );
    assert!(worst < 1e-7, "largest difference in probability {worst:e}");
}

#[test]
fn the_fast_amplitude_bound_equals_the_quadratures_within_1e_5_relative() {
    let mut worst = 0.0f64;
    for (mean, cov) in random_rows(3000) {
        let (fast, slow) = (
            amplitude_95(mean, &cov),
            amplitude_95_by_quadrature(mean, &cov),
        );
        worst = worst.max((fast - slow).abs() / slow);
    }
    eprintln!("fast against quadrature: largest relative difference {worst:e}");
    assert!(worst <= 1e-5, "largest relative difference {worst:e}");
}

#[test]
fn the_polar_rule_matches_a_direct_sum_over_the_disc() {
    // Midpoint sums in angle (exact to rounding for a periodic integrand) and
    // radius (error of order 10⁻⁷ with 2000 steps) of the density itself.
    let direct = |[mu1, mu2, s1, s2]: [f64; 4], rho: f64| {
        let n = 2000;
        let mut p = 0.0;
        for i in 0..n {
            let (s, c) = ((i as f64 + 0.5) / n as f64 * std::f64::consts::TAU).sin_cos();
            for j in 0..n {
                let r = (j as f64 + 0.5) / n as f64 * rho;
                let (x, y) = ((r * c - mu1) / s1, (r * s - mu2) / s2);
                p += r * (-0.5 * (x * x + y * y)).exp();
            }
        }
        p * (rho / n as f64) / (n as f64 * s1 * s2)
    };
    // Off-centre, thin, far out, centred and eccentric.
    for (axes, rho) in [
        ([-0.0912, -0.2376, 0.1729, 0.0188], 0.2251),
        ([1.5, 0.4, 0.3, 0.2], 1.9),
        ([0.0, 0.0, 12.9, 3.18], 12.76),
        ([0.028, -0.15, 0.118, 0.089], 0.34),
    ] {
        let [mu1, mu2, s1, s2] = axes;
        let [p, _] = Polar::new(mu1, mu2, s1, s2)
            .and_then(|mut r| r.inside(rho))
            .expect("converges");
        let d = direct(axes, rho);
        assert!((p - d).abs() < 1e-6, "{axes:?} {rho}: {p} against {d}");
    }
}

#[test]
fn the_arc_rule_agrees_with_the_quadrature_for_means_far_from_the_origin() {
    use rand::Rng;
    // Residual rows of a min-max job: the mean 8 to 10⁴ σ₁ from the origin,
    // isotropic to thin, any direction (the full-turn rule gives up there).
    // A mass thin across the circle |R| = ρ makes the ray integrals step
    // sharply in angle: there the rule gives up and the quadrature answers.
    let mut rng = StdRng::seed_from_u64(16);
    let (mut worst_p, mut worst_bound, mut used) = (0.0f64, 0.0f64, 0);
    for _ in 0..400 {
        let s1 = rng.gen_range(-3.0f64..3.0).exp();
        let s2 = s1 * 10f64.powf(rng.gen_range(-3.0..0.0));
        let m = s1 * 10f64.powf(rng.gen_range(8f64.log10()..4.0));
        let mean = Complex64::from_polar(m, rng.gen_range(0.0..std::f64::consts::TAU));
        let cov = turned(s1, s2, rng.gen_range(0.0..std::f64::consts::PI));
        let [mu1, mu2, s1, s2] = super::region::principal(&mean, &cov).expect("spread");
        let q = amplitude_95_by_quadrature(mean, &cov);
        // None: too thin across for the arc's finest level (the quadrature answers).
        if let Some(mut arc) = super::region::quantile::arc::Arc::new(mu1, mu2, s1, s2) {
            for rho in [q - 2.0 * s1, q, q + s1] {
                if let Some([p, _]) = arc.inside(rho) {
                    let [r, _] = super::region::quantile::quadrature::inside(mu1, mu2, s1, s2, rho);
                    worst_p = worst_p.max((p - r).abs());
                    used += 1;
                }
            }
        }
        worst_bound = worst_bound.max((amplitude_95(mean, &cov) - q).abs() / q);
    }
    eprintln!(
        "arc against quadrature: {used} of 1200 points, {worst_p:e} in probability, bound {worst_bound:e} relative"
    );
    assert!(
        used > 400,
        "the arc rule converged for {used} of 1200 points"
    );
    assert!(
        worst_p < 1e-7,
        "largest difference in probability {worst_p:e}"
    );
    assert!(
        worst_bound <= 1e-5,
        "largest relative difference {worst_bound:e}"
    );
}
