//! The two-sided 95 % quantile of Student's t: how many standard deviations
//! a 95 % interval spans when the standard deviation is itself estimated from
//! the residual over `ν` degrees of freedom (1.96 for a known one, 12.71 at
//! `ν = 1`).

/// `P(|T| > t) = I_{ν/(ν+t²)}(ν/2, 1/2)` for Student's `T` with `ν` degrees
/// of freedom (`I` the regularised incomplete beta function).
fn two_sided_tail(t: f64, nu: f64) -> f64 {
    incomplete_beta(nu / (nu + t * t), 0.5 * nu, 0.5)
}

/// The regularised incomplete beta function `I_x(a, b)`, by its continued
/// fraction (modified Lentz), on the side where it converges fast.
fn incomplete_beta(x: f64, a: f64, b: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    if x >= 1.0 {
        return 1.0;
    }
    let ln_front =
        libm::lgamma(a + b) - libm::lgamma(a) - libm::lgamma(b) + a * x.ln() + b * (1.0 - x).ln();
    let front = ln_front.exp();
    if x < (a + 1.0) / (a + b + 2.0) {
        front * continued_fraction(x, a, b) / a
    } else {
        1.0 - front * continued_fraction(1.0 - x, b, a) / b
    }
}

fn continued_fraction(x: f64, a: f64, b: f64) -> f64 {
    const TINY: f64 = 1e-300;
    let mut c = 1.0;
    let mut d = 1.0 - (a + b) * x / (a + 1.0);
    if d.abs() < TINY {
        d = TINY;
    }
    d = 1.0 / d;
    let mut h = d;
    for m in 1..=300 {
        let m = m as f64;
        let m2 = 2.0 * m;
        for aa in [
            m * (b - m) * x / ((a + m2 - 1.0) * (a + m2)),
            -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0)),
        ] {
            d = 1.0 + aa * d;
            if d.abs() < TINY {
                d = TINY;
            }
            c = 1.0 + aa / c;
            if c.abs() < TINY {
                c = TINY;
            }
            d = 1.0 / d;
            h *= d * c;
        }
        if (d * c - 1.0).abs() < 1e-15 {
            break;
        }
    }
    h
}

/// `t` with `P(|T| > t) = 0.05` for `ν ≥ 1` degrees of freedom (the normal
/// 1.959964 for infinite `ν`), by bisection.
pub fn t_95(nu: f64) -> f64 {
    if !nu.is_finite() {
        return 1.959_963_984_540_054;
    }
    let nu = nu.max(1.0);
    // P(|T| > t) falls with t; at ν = 1 the quantile is 12.71.
    let (mut lo, mut hi) = (1.9, 13.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if two_sided_tail(mid, nu) > 0.05 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::t_95;

    #[test]
    fn the_quantiles_are_the_tables() {
        // ν = 1 and 2 in closed form: tan(0.475π) and 0.95·√(2/0.0975).
        let one = (0.475 * std::f64::consts::PI).tan();
        let two = 0.95 * (2.0f64 / 0.0975).sqrt();
        for (nu, want) in [
            (1.0, one),
            (2.0, two),
            (3.0, 3.182_446_305),
            (5.0, 2.570_581_836),
            (10.0, 2.228_138_852),
            (30.0, 2.042_272_456),
            (1000.0, 1.962_339_081),
        ] {
            let got = t_95(nu);
            assert!(
                (got - want).abs() < 1e-8 * want,
                "ν = {nu}: {got} vs {want}"
            );
        }
        assert!((t_95(f64::INFINITY) - 1.959_963_985).abs() < 1e-9);
    }
}
