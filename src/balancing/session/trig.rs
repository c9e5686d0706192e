//! The phase of a phasor for the report (method §1): `atan2` without libm.
//! libm's `atan2` costs about 140 instructions a call, and a large solve
//! (16 planes, 1,280 rows) reports 21,760 phases (issue 15, session 9); this
//! takes about a third of that. No `mul_add` or `round`: without FMA and
//! SSE4.1 in the build's target they are library calls themselves.
//!
//! Accuracy (`trig_tests.rs`, 2·10⁶ seeded points against libm; the
//! prototype against 120-bit `mpmath` gave 4.4·10⁻¹⁶): within 8·10⁻¹⁶ rad,
//! absolute and relative, of `f64::atan2`, i.e. 5·10⁻¹⁴ ° at most (issue 15
//! asked 10⁻¹²). Zero, infinite and NaN parts go to libm.
//!
//! A sine and cosine reduced in degrees (fdlibm's kernels) was tried for the
//! readings' phasors too and dropped: a reading moved by an ulp moves the
//! small predicted residuals' phases by up to 1.5·10⁻¹¹ relative, past the
//! 10⁻¹² the report's equivalence allows.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// `atan(k/8)`, k = 0..=8, correctly rounded (120-bit `mpmath`).
const ATAN_EIGHTHS: [f64; 9] = [
    0.0,
    0.12435499454676144,
    0.24497866312686414,
    0.35877067027057225,
    0.4636476090008061,
    0.5585993153435624,
    0.6435011087932844,
    0.7188299996216245,
    FRAC_PI_4,
];

/// `atan u` for `|u| ≤ 1/16`: the Taylor series to `u¹³`; the first term
/// left out, `u¹⁵/15`, is below 10⁻¹⁸ of `u`.
#[inline]
fn atan_small(u: f64) -> f64 {
    let z = u * u;
    let p = ((((z * (-1.0 / 13.0) + 1.0 / 11.0) * z - 1.0 / 9.0) * z + 1.0 / 7.0) * z - 1.0 / 5.0)
        * z
        + 1.0 / 3.0;
    // u − u³/3 + u⁵/5 − … = u − u z p.
    u - u * z * p
}

/// `1.5·2⁵²`: added to a number in `[0, 2⁵¹)` it rounds it to an integer
/// (the sum's ulp is 1), which the sum's low bits then hold.
const ROUND: f64 = 6_755_399_441_055_744.0;

/// `atan2(y, x)`, the argument of `x + iy` in `(−π, π]`, as `Complex64::arg`.
///
/// `t = min/max` of `|x|, |y|` in `[0, 1]`; with `c = k/8` nearest `t`,
/// `atan t = atan c + atan((t − c)/(1 + t c))` (`t − c` exact by Sterbenz's
/// lemma), the second by `atan_small` on `|u| ≤ 1/16`; then the octant.
/// One division for `t`, no branch on the octant before it; about 45
/// instructions.
#[inline]
pub fn arg(y: f64, x: f64) -> f64 {
    // A finite non-zero product: both parts finite and non-zero (an
    // underflowing or overflowing product just takes libm's way).
    let p = x * y;
    if !(p.is_finite() && p != 0.0) {
        return y.atan2(x);
    }
    let (ax, ay) = (x.abs(), y.abs());
    let t = ax.min(ay) / ax.max(ay);
    let r = t * 8.0 + ROUND;
    let k = (r.to_bits() & 15) as usize;
    let c = (r - ROUND) * 0.125;
    let u = (t - c) / (1.0 + t * c);
    let mut theta = ATAN_EIGHTHS[k.min(8)] + atan_small(u);
    if ay > ax {
        theta = FRAC_PI_2 - theta;
    }
    if x < 0.0 {
        theta = PI - theta;
    }
    if y < 0.0 {
        -theta
    } else {
        theta
    }
}

#[cfg(test)]
#[path = "trig_tests.rs"]
mod tests;
