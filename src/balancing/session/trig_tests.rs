//! `trig` against libm on seeded random points (rand's `StdRng`, fixed seed) and on
//! the exact cases; the bound is the prototype's worst case against 120-bit
//! `mpmath` (4.4·10⁻¹⁶) plus libm's own half ulp, rounded up.

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use super::arg;

#[test]
fn arg_is_libm_atan2_within_a_few_ulps() {
    let mut rng = StdRng::seed_from_u64(0x9e37_79b9_7f4a_7c15);
    let mut worst = (0.0f64, 0.0f64);
    for i in 0..2_000_000 {
        let x = (2.0 * rng.gen::<f64>() - 1.0) * 10f64.powf(20.0 * rng.gen::<f64>() - 10.0);
        let mut y = (2.0 * rng.gen::<f64>() - 1.0) * 10f64.powf(20.0 * rng.gen::<f64>() - 10.0);
        if i % 3 == 0 {
            // Near the diagonals, where the octant changes.
            y = x * (0.9 + 0.2 * rng.gen::<f64>()) * if i % 2 == 0 { 1.0 } else { -1.0 };
        }
        let (fast, libm) = (arg(y, x), y.atan2(x));
        let e = (fast - libm).abs();
        worst.0 = worst.0.max(e);
        worst.1 = worst.1.max(e / libm.abs());
        assert!(
            e <= 8e-16 && e <= 8e-16 * libm.abs(),
            "atan2({y:e}, {x:e}): {fast} against {libm}"
        );
    }
    eprintln!(
        "arg: worst {:.2e} absolute, {:.2e} relative",
        worst.0, worst.1
    );
}

#[test]
fn arg_keeps_libm_on_axes_diagonals_and_special_values() {
    let specials = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        3.5,
        -2.0,
        1e-310,
        -1e-310,
        1e300,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
    ];
    for &y in &specials {
        for &x in &specials {
            let (fast, libm) = (arg(y, x), y.atan2(x));
            let same = fast.to_bits() == libm.to_bits() || (fast - libm).abs() <= 4e-16;
            assert!(
                same || (fast.is_nan() && libm.is_nan()),
                "{y} {x}: {fast} {libm}"
            );
        }
    }
    assert_eq!(arg(1.0, 1.0), std::f64::consts::FRAC_PI_4);
    assert_eq!(arg(-1.0, -1.0), -3.0 * std::f64::consts::FRAC_PI_4);
}
