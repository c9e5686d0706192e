//! Unit tests of the 95 % figures against closed forms and a Monte Carlo of the Gaussian.

use nalgebra::{Matrix2, Vector2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, StandardNormal};

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
