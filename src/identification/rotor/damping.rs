//! How much of a mode's damping the readings resolve, and what is reported
//! when they do not.
//!
//! The smallest damping ratio the readings tell from zero is taken as the
//! half-width of the fitted one's 95 % interval: its standard deviation
//! ([`Fit::damping_ratio_sd`]) times Student's quantile for the residual's
//! degrees of freedom (real equations minus unknowns; 2.01 at 25 speeds,
//! 12.7 at three with the forcing estimated, one degree of freedom). The
//! standard deviation comes from the scatter of the responses about the
//! fitted curve (the readings' noise, and whatever the one-mass model
//! misses), carried to `ζ` through where the speeds
//! lie (a speed near the critical says much about the damping, the far tails
//! little). A fitted `ζ` within that of zero (either side: noise can make it
//! negative) is not an estimate: undamped, noise-free readings fitted
//! `ζ ≈ 1e-18` and answered an amplification factor of 2.4e13 (session 19).
//! The relative noise is taken as at least [`NOISE_FLOOR`].
//! Then the damping ratio reported is the most the readings allow,
//! `max(ζ, 0) + resolution`, the amplification factor `1/(2·that)` the least,
//! and the required margin API 684's largest (any factor above the bound is as
//! consistent with the readings).

use super::super::api684::{self, Amplification, Method};
use super::super::onemass::{Coupling, Fit, Point, Setup};
use super::student::t_95;

/// Relative noise below this is taken as this. A smaller residual is rounding,
/// not a measure of what the readings resolve: noise-free readings leave
/// 1e-16, and with it undamped readings fitted ζ of ±1e-16 (an amplification
/// factor of 1e15, or `no_mode` when the sign came out negative). A millionth
/// is three decades finer than any vibration reading (a phase to 0.1° is 2e-3
/// of the reading), so it never hides real noise, and ten decades above the
/// rounding, so rounding never passes for resolution.
pub const NOISE_FLOOR: f64 = 1e-6;

/// The resolution of `fit`'s damping ratio, when it can be had: the 95 %
/// half-width. The noise is estimated from the residual, so the quantile is
/// Student's for its degrees of freedom, not the normal's: with twice the
/// standard deviation, three speeds (one degree of freedom) missed the true
/// damping in 46 of 200 noisy records, once by 7.7 resolutions (review,
/// session 20).
pub fn resolution(fit: &Fit, setup: &Setup, points: &[Point]) -> Option<f64> {
    let t = t_95((2 * points.len()).saturating_sub(setup.unknowns()) as f64);
    let r = t * fit.damping_ratio_sd(setup, points, NOISE_FLOOR);
    r.is_finite().then_some(r)
}

/// The 95 % half-width of the natural frequency `√(c/m)`, 1/s, when it can
/// be had.
pub fn natural_w_resolution(fit: &Fit, setup: &Setup, points: &[Point]) -> Option<f64> {
    let t = t_95((2 * points.len()).saturating_sub(setup.unknowns()) as f64);
    let r = t * fit.natural_w_sd(setup, points, NOISE_FLOOR);
    r.is_finite().then_some(r)
}

/// The 95 % resolutions of `b/m` and `q/m` (as the damping ratio's), when
/// they can be had; `q/m`'s is 0 when `q` is not estimated.
pub fn split_resolution(fit: &Fit, setup: &Setup, points: &[Point]) -> Option<(f64, f64)> {
    let t = t_95((2 * points.len()).saturating_sub(setup.unknowns()) as f64);
    let rb = t * fit.b_over_m_sd(setup, points, NOISE_FLOOR);
    let rq = t * fit.q_over_m_sd(setup, points, NOISE_FLOOR);
    (rb.is_finite() && rq.is_finite()).then_some((rb, rq))
}

/// How many of its 95 % half-widths `b/m` must clear, with the
/// cross-coupling estimated, for the split of the damping into direct
/// damping and cross-coupling to count as resolved (see [`split_resolved`]).
pub const SPLIT_CLEARANCE: f64 = 2.0;

/// The fewest residual degrees of freedom (real equations less unknowns)
/// with which a split is given when the cross-coupling is estimated.
pub const SPLIT_MIN_DOF: usize = 3;

/// Whether `b_over_m`, with its 95 % half-width `rb` from `points.len()`
/// speeds, resolves the split of the damping into direct damping and
/// cross-coupling (then `b/m` and `q/m` are given).
///
/// With `q` not estimated (taken as zero or tied to `b`) `b/m` follows the
/// damping ratio, and clearing zero by its half-width is enough. With `q`
/// estimated, synchronous readings fix `ωb − q` near the critical and split
/// it only through the few per cent the speed changes across the resonance,
/// so the split is nearly always unresolved; `b/m > rb` is then a test at
/// 5 % that passes the records whose noise pushed `b/m` far up, and the few
/// it passed mostly missed the truth (12 of 47 held at 3 to 40 speeds,
/// session 23, scripts/ident_rotor_coverage.py). Whatever the truth, a
/// record given must now have the interval's lower end a half-width above
/// zero ([`SPLIT_CLEARANCE`]), which noise alone (a true `b/m` of zero)
/// passes 0.4 % of the time at three degrees of freedom and far less with
/// more, and at least
/// [`SPLIT_MIN_DOF`] degrees of freedom: at one (three speeds, five
/// unknowns) Student's tail is Cauchy's, and the half-width held the truth
/// in 172 of 192 records given even where the split was resolved.
pub fn split_resolved(setup: &Setup, speeds: usize, b_over_m: f64, rb: f64) -> bool {
    if setup.coupling != Coupling::Estimated {
        return b_over_m > rb;
    }
    let dof = (2 * speeds).saturating_sub(setup.unknowns());
    dof >= SPLIT_MIN_DOF && b_over_m > SPLIT_CLEARANCE * rb
}

/// The damping and amplification reported for one mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Damping {
    pub ratio: f64,
    pub resolution: Option<f64>,
    pub amplification: Amplification,
    /// The ratio is an upper bound and the factor a lower one.
    pub bounds: bool,
}

impl Damping {
    /// A resolved (or unresolvable-to-judge) damping: the fit's, API 684's
    /// factor on the fitted curve.
    pub fn resolved(fit: &Fit, wn: f64, zeta: f64, resolution: Option<f64>) -> Self {
        Damping {
            ratio: zeta,
            resolution,
            amplification: api684::amplification(|x| fit.response(x).norm(), wn, zeta),
            bounds: false,
        }
    }

    /// A damping ratio `zeta` within `resolution` of zero.
    pub fn unresolved(zeta: f64, resolution: f64) -> Self {
        let upper = zeta.max(0.0) + resolution;
        Damping {
            ratio: upper,
            resolution: Some(resolution),
            amplification: Amplification {
                factor: 1.0 / (2.0 * upper),
                peak_w: None,
                method: Method::DampingRatio,
            },
            bounds: true,
        }
    }

    /// The factor API 684's required margin is read for: with bounds any
    /// factor above the lower one fits the readings, so the largest margin.
    pub fn margin_factor(&self) -> f64 {
        if self.bounds {
            f64::INFINITY
        } else {
            self.amplification.factor
        }
    }
}
