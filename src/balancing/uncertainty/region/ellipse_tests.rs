//! The closed-form extremes against the boundary sampled densely and refined
//! by golden-section search (what `region` did before issue 15), on random
//! and degenerate ellipses.

use nalgebra::{Matrix2, Vector2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use super::super::{axes, CHI2_2_95};
use super::Ellipse;

/// Maximum of a periodic `f` over `[0, 2π)`: the best of 2048 samples refined
/// by golden-section search between its neighbours.
fn sampled_max(f: impl Fn(f64) -> f64) -> f64 {
    let n = 2048;
    let step = std::f64::consts::TAU / n as f64;
    let best = (0..n)
        .map(|i| i as f64 * step)
        .max_by(|x, y| f(*x).total_cmp(&f(*y)))
        .expect("samples");
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (best - step, best + step);
    for _ in 0..60 {
        let (x1, x2) = (b - g * (b - a), a + g * (b - a));
        if f(x1) < f(x2) {
            a = x1;
        } else {
            b = x2;
        }
    }
    f(best).max(f((a + b) / 2.0))
}

/// `[nearest, farthest, lowest offset, highest offset]` by sampling.
fn sampled(c: Complex64, cov: &Matrix2<f64>) -> [f64; 4] {
    let (k, ax) = (CHI2_2_95.sqrt(), axes(cov));
    let (l1, l2) = (ax[0].0.sqrt() * k, ax[1].0.sqrt() * k);
    let point = |t: f64| {
        let v = ax[0].1 * (l1 * t.cos()) + ax[1].1 * (l2 * t.sin());
        c + Complex64::new(v.x, v.y)
    };
    let offset = |t: f64| (point(t) * c.conj()).arg();
    [
        -sampled_max(|t| -point(t).norm()),
        sampled_max(|t| point(t).norm()),
        -sampled_max(|t| -offset(t)),
        sampled_max(offset),
    ]
}

fn closed(c: Complex64, cov: &Matrix2<f64>) -> [f64; 4] {
    let e = Ellipse::new(c, &axes(cov), CHI2_2_95.sqrt());
    let (lo, hi) = e.tangent_offsets();
    [e.nearest(), e.farthest(), lo, hi]
}

fn outside(c: Complex64, cov: &Matrix2<f64>) -> bool {
    cov.try_inverse().is_some_and(|inv| {
        let v = Vector2::new(c.re, c.im);
        (v.transpose() * inv * v)[0] > CHI2_2_95 * (1.0 + 1e-6)
    })
}

fn assert_close(c: Complex64, cov: &Matrix2<f64>, with_origin_outside: bool) {
    let (want, got) = (sampled(c, cov), closed(c, cov));
    let scale = c.norm() + cov.trace().sqrt();
    let checked = if with_origin_outside { 0..4 } else { 1..2 };
    for i in checked {
        let tol = if i < 2 { 1e-9 * scale } else { 1e-9 };
        assert!(
            (got[i] - want[i]).abs() <= tol,
            "{i}: {} against {} for c = {c}, Σ = {cov}",
            got[i],
            want[i]
        );
    }
}

fn random_cov(rng: &mut StdRng, scale: f64) -> Matrix2<f64> {
    let (s1, s2, phi) = (
        scale * rng.gen_range(0.01..1.0),
        scale * rng.gen_range(0.001..1.0),
        rng.gen_range(0.0..std::f64::consts::PI),
    );
    let (s, co) = phi.sin_cos();
    let r = Matrix2::new(co, -s, s, co);
    r * Matrix2::new(s1 * s1, 0.0, 0.0, s2 * s2) * r.transpose()
}

#[test]
fn the_closed_form_extremes_equal_the_sampled_boundarys_on_random_ellipses() {
    let mut rng = StdRng::seed_from_u64(15);
    let mut tested = [0, 0];
    for _ in 0..400 {
        let c = Complex64::from_polar(
            rng.gen_range(1.0..100.0),
            rng.gen_range(0.0..std::f64::consts::TAU),
        );
        let spread = c.norm() * rng.gen_range(0.02..1.5);
        let cov = random_cov(&mut rng, spread);
        let out = outside(c, &cov);
        tested[usize::from(out)] += 1;
        assert_close(c, &cov, out);
    }
    assert!(tested[0] > 20 && tested[1] > 20, "{tested:?}");
}

#[test]
fn the_closed_form_extremes_hold_for_circles_segments_and_centred_ellipses() {
    let c = Complex64::new(3.0, 4.0);
    let cases = [
        // A circle, the origin outside and inside.
        (c, Matrix2::identity() * 0.5, true),
        (c, Matrix2::identity() * 9.0, false),
        // The origin on an axis of the ellipse, beyond and within its reach.
        (
            Complex64::new(10.0, 0.0),
            Matrix2::new(4.0, 0.0, 0.0, 1.0),
            true,
        ),
        (
            Complex64::new(0.0, 10.0),
            Matrix2::new(4.0, 0.0, 0.0, 1.0),
            true,
        ),
        (
            Complex64::new(1.0, 0.0),
            Matrix2::new(4.0, 0.0, 0.0, 1.0),
            false,
        ),
        (
            Complex64::new(0.0, 1.0),
            Matrix2::new(9.0, 0.0, 0.0, 1.0),
            false,
        ),
        // Centred on the origin.
        (
            Complex64::new(0.0, 0.0),
            Matrix2::new(4.0, 1.0, 1.0, 1.0),
            false,
        ),
        // A reaching, thin ellipse whose far end lies beyond 90° from c.
        (
            Complex64::new(1.0, 0.0),
            Matrix2::new(1.0, -10.0, -10.0, 100.1) * 0.1,
            true,
        ),
    ];
    for (c, cov, out) in cases {
        assert_eq!(outside(c, &cov), out, "{c} {cov}");
        assert_close(c, &cov, out);
    }
}

#[test]
fn a_segment_gives_the_extremes_of_its_ends_and_its_projection() {
    let k = CHI2_2_95.sqrt();
    // Spread along Re only, half-length 2k, centred at 3 + 4i: nearest at
    // the projection of the origin (3 < 2k), 4 away; farthest at an end.
    let e = Ellipse::new(
        Complex64::new(3.0, 4.0),
        &axes(&Matrix2::new(4.0, 0.0, 0.0, 0.0)),
        k,
    );
    assert!((e.nearest() - 4.0).abs() < 1e-12, "{}", e.nearest());
    let far = (3.0 + 2.0 * k).hypot(4.0);
    assert!((e.farthest() - far).abs() < 1e-12, "{}", e.farthest());
    let (lo, hi) = e.tangent_offsets();
    let c_arg = 4f64.atan2(3.0);
    let ends = [
        4f64.atan2(3.0 + 2.0 * k) - c_arg,
        4f64.atan2(3.0 - 2.0 * k) - c_arg,
    ];
    assert!(
        (lo - ends[0]).abs() < 1e-12 && (hi - ends[1]).abs() < 1e-12,
        "{lo} {hi}"
    );
    // Along c: every point has c's angle.
    let e = Ellipse::new(
        Complex64::new(10.0, 0.0),
        &axes(&Matrix2::new(4.0, 0.0, 0.0, 0.0)),
        k,
    );
    assert_eq!(e.tangent_offsets(), (0.0, 0.0));
    assert!((e.nearest() - (10.0 - 2.0 * k)).abs() < 1e-12);
    assert!((e.farthest() - (10.0 + 2.0 * k)).abs() < 1e-12);
}
