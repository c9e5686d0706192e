//! Phasors and the session's angle conventions: the only place where a user's
//! angle becomes an internal one and back (method §1).
//!
//! Internal frame: a reading is `Y` with `x(t) = Re(Y e^{iωt})` (phase lead), a
//! weight is `m e^{iθ}` with `θ` counted with rotation. In that frame the
//! response is complex-linear in the weight.

use num_complex::Complex64;

use super::trig;
use crate::balancing::model::{AngleDirection, Conventions, PhaseConvention};

/// `|z|` as `√(re² + im²)`, a tenth of the cost of `hypot` (`Complex64::norm`),
/// whose guard against overflow and underflow no figure within the limits
/// needs: outside `|z|²` in `(1e-290, 1e290)` it is `hypot` after all. Within
/// an ulp or so of `hypot` (issue 15: a large solve takes ~100,000 moduli).
#[inline]
pub fn modulus(z: Complex64) -> f64 {
    let s = z.re * z.re + z.im * z.im;
    if s > 1e-290 && s < 1e290 {
        s.sqrt()
    } else {
        z.norm()
    }
}

/// Degrees in `[0, 360)`.
pub fn wrap_deg(deg: f64) -> f64 {
    // Within one turn `rem_euclid` (an `fmod`, exact) is `deg` or `deg + 360`:
    // the same bits without the call, on every angle a solve reports (issue 15).
    let w = if deg.abs() < 360.0 {
        if deg < 0.0 {
            deg + 360.0
        } else {
            deg
        }
    } else {
        deg.rem_euclid(360.0)
    };
    // rem_euclid can return 360.0 for tiny negative inputs
    if w >= 360.0 {
        0.0
    } else {
        // −0.0 (the angle of a zero correction against rotation) prints as "-0.0".
        w + 0.0
    }
}

/// Internal angle (radians, with rotation) of a weight at `deg` in the session's
/// direction (1.2): against rotation `θ ↦ −θ`, with rotation `θ ↦ θ`.
pub fn weight_angle_in(conv: Conventions, deg: f64) -> f64 {
    let rad = deg.to_radians();
    match conv.angle_direction {
        AngleDirection::AgainstRotation => -rad,
        AngleDirection::WithRotation => rad,
    }
}

/// A weight `m` at `deg` (session direction) as the internal complex number `m e^{iθ}`.
pub fn weight_in(conv: Conventions, mass_g: f64, deg: f64) -> Complex64 {
    Complex64::from_polar(mass_g, weight_angle_in(conv, deg))
}

/// An internal weight as (mass, angle in degrees in the session's direction, `[0, 360)`).
pub fn weight_out(conv: Conventions, w: Complex64) -> (f64, f64) {
    polar_out(w, conv.angle_direction == AngleDirection::AgainstRotation)
}

/// A reading (amplitude, phase in the session's convention) as an internal
/// phasor (1.1): lag `A e^{−iφ}`, lead `A e^{+iφ}`.
pub fn reading_in(conv: Conventions, amplitude: f64, phase_deg: f64) -> Complex64 {
    let rad = phase_deg.to_radians();
    match conv.phase {
        PhaseConvention::Lag => Complex64::from_polar(amplitude, -rad),
        PhaseConvention::Lead => Complex64::from_polar(amplitude, rad),
    }
}

/// An internal phasor as (amplitude, phase in degrees in the session's convention, `[0, 360)`).
/// The argument is [`trig::arg`] (within 4.5·10⁻¹⁶ rad of the exact `atan2`).
pub fn reading_out(conv: Conventions, y: Complex64) -> (f64, f64) {
    polar_out(y, conv.phase == PhaseConvention::Lag)
}

/// `z` as (modulus, angle in degrees in `[0, 360)`), the angle negated when
/// `negate` (lag phases, angles against rotation): the one conversion behind
/// [`weight_out`] and [`reading_out`].
fn polar_out(z: Complex64, negate: bool) -> (f64, f64) {
    let arg = trig::arg(z.im, z.re);
    let deg = if negate { -arg } else { arg }.to_degrees();
    (modulus(z), wrap_deg(deg))
}

/// Smallest absolute difference of two angles in degrees, in `[0, 180]`.
pub fn angle_diff_deg(a: f64, b: f64) -> f64 {
    let d = wrap_deg(a - b);
    d.min(360.0 - d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn readings_and_weights_round_trip_in_every_convention() {
        for conv in Conventions::ALL {
            for deg in [0.0, 12.5, 90.0, 181.0, 359.9] {
                let (a, p) = reading_out(conv, reading_in(conv, 3.5, deg));
                assert!(
                    (a - 3.5).abs() < 1e-12 && angle_diff_deg(p, deg) < 1e-9,
                    "{conv:?} {deg}"
                );
                let (m, t) = weight_out(conv, weight_in(conv, 7.0, deg));
                assert!(
                    (m - 7.0).abs() < 1e-12 && angle_diff_deg(t, deg) < 1e-9,
                    "{conv:?} {deg}"
                );
            }
        }
    }

    #[test]
    fn a_lag_of_90_degrees_is_a_quarter_turn_behind() {
        let conv = Conventions {
            phase: PhaseConvention::Lag,
            angle_direction: AngleDirection::AgainstRotation,
        };
        let y = reading_in(conv, 1.0, 90.0);
        assert!((y - Complex64::new(0.0, -1.0)).norm() < 1e-12);
    }

    #[test]
    fn wrapped_angles_stay_below_360() {
        assert_eq!(wrap_deg(-1e-15), 0.0);
        assert_eq!(wrap_deg(720.0), 0.0);
        assert!(wrap_deg(-0.0).is_sign_positive());
        assert!((wrap_deg(-90.0) - 270.0).abs() < 1e-12);
    }
}
