//! The accepted ranges of the identification endpoints' numbers, and why.
//!
//! Each range is either physical plausibility for a rotor on a test stand
//! (P) or numerical safety (N), as marked. Past them the answers were
//! meaningless though finite (review, session 17, and tidy18's sweep):
//! masses of 1e-9 and 1e9 kg side by side answered 0 Hz beside 6.9e9 Hz, a
//! stiffness entry of 1e20 answered 0 Hz, a stiffness pattern entry of
//! 1e-300 a parameter of 3.6e303, a measured frequency of 1e10 Hz was ignored
//! (the other mode's equations decided alone), a mode shape of 1e-300
//! underflowed its norm (a residual of 1.5e7), a weight of 1e-300 silently
//! dropped its mode, and a known rotor mass of 1e300 kg overflowed `√(cm)`
//! (a `no_mode` warning for a clean resonance).
//!
//! Ranges of single numbers cannot exclude every bad combination: a model's
//! masses and stiffnesses of in-range sizes may still give a natural
//! frequency of 0 (a rigid-body mode, or one lost to rounding) or of 1e10 Hz.
//! The frequencies a model or a free decay answers are therefore checked
//! against [`FREQUENCY_HZ`] too ([`frequencies`]), and refused naming the
//! fields that produced them.

use crate::balancing::error::{shown, within};
use crate::balancing::validate::{MAX_SPEED_RPM, MIN_SERVICE_SPEED_RPM};
use crate::balancing::InputError;

/// Magnitude of a mass entry other than 0 on the diagonal (`identify/model`'s
/// `M0` and every `Mᵢ`; any other entry at most the upper bound), and of a
/// rotor's known `options.mass_kg`. (P) A microgram, the service's lightest
/// trial weight, to a million tonnes, in kg; the range allows grams or tonnes
/// too. (N) Masses of 1e300 and 1e-300 gave 0 Hz and stiffnesses of 1e286
/// (review, session 17); a rotor mass of 1e300 overflowed `√(cm)`.
pub const MASS: (f64, f64) = (1e-9, 1e9);

/// A rotor's `options.speed_range_rpm` `[lo, hi]`: two finite numbers,
/// `lo < hi`, each within these bounds, else refused naming
/// `options.speed_range_rpm`. (P) The bounds of speeds elsewhere: 1 rpm, the
/// slowest service speed a session and the residual-unbalance check accept,
/// to 1e6 rpm, the fastest reading. Before session 19 only `0 < lo < hi` was
/// checked: `[1000, 1e300]` was taken for a range.
pub const SPEED_RPM: (f64, f64) = (MIN_SERVICE_SPEED_RPM, MAX_SPEED_RPM);

/// Natural frequencies, Hz, measured (`modes[j].frequency_hz`) or answered.
/// (P) 0.01 Hz is a period of 100 s, slower than the pendulum mode of any
/// soft-mounted stand (about 1 Hz); 1e5 Hz is beyond the bandwidth of the
/// vibration sensors of a stand (accelerometers reach tens of kHz). (N) The
/// squared angular frequencies then span 1e14, within double precision.
pub const FREQUENCY_HZ: (f64, f64) = (1e-2, 1e5);

/// Magnitude of a stiffness entry other than 0 on the diagonal; any other
/// entry is at most the upper bound in magnitude. (P) Bearings and shafts of
/// stand rotors are 1e5 to 1e10 N/m; 1e12 leaves two decades, and kN/m with
/// masses in tonnes stays inside. The lower bound lets the lightest mass
/// (1e-9 kg) have a mode at the lowest frequency (k = mω² ≈ 4e-12). (N)
/// Beyond, a fixed 1e20 beside parameters of order 1e3 cancelled to 0 Hz, and
/// a pattern of 1e-300 made its parameter 3.6e303.
pub const STIFFNESS: (f64, f64) = (1e-12, 1e12);

/// Largest magnitude of a mode-shape entry, and least magnitude of a shape's
/// largest entry. (P) A mass-normalised shape is about `1/√m`, 3e-5 to 3e4
/// for the accepted masses; shapes of any other scale are accepted where
/// they would be (known masses) within the same bounds. (N) The squares of
/// 200 entries stay far from overflow and underflow (a shape of 1e-300 had a
/// norm of 0).
pub const SHAPE: (f64, f64) = (1e-6, 1e6);

/// A mode's weight `G`. (P) Relative confidence in one mode over another:
/// six decades is more than any test gives. (N) Rows weighted 1e12 apart
/// fall under the rank tolerance of the least squares (1e-11) and a mode was
/// silently dropped.
pub const WEIGHT: (f64, f64) = (1e-3, 1e3);

/// Magnitude of a starting parameter (0 allowed). (N) only: a parameter
/// times a matrix entry of 1e12 stays below 1e27, whose squares in the
/// Cholesky factor and the eigensolver are far from overflow.
pub const INITIAL: f64 = 1e15;

/// Magnitude of a free decay's sample, and least magnitude of its largest.
/// (P) Samples are in any unit (µm, mm/s, g): twelve decades either side of
/// 1 hold any stand's readings. (N) A sample of 1e150 beside ones of order 1
/// overflowed the misfit (fuzzing, session 15); samples of 1e-300 underflow
/// the squares of the least squares.
pub const SAMPLE: (f64, f64) = (1e-12, 1e12);

/// `κ` of a rotor's tied cross-coupling `q = κ b ω`. (P) The textbook's case
/// has κ = 0.5 (half-frequency whirl of fluid-film bearings); ten times the
/// direct damping is past any rotor that can be run through its critical.
pub const CROSS_COUPLING_RATIO: f64 = 10.0;

/// An entry of a symmetric matrix: on the diagonal 0 or of magnitude
/// `lo..=hi`, off it at most `hi` in magnitude, naming `field[i][j]`.
pub fn entries(
    field: &str,
    rows: &[Vec<f64>],
    (lo, hi): (f64, f64),
    what: &str,
) -> Result<(), InputError> {
    for (i, r) in rows.iter().enumerate() {
        for (j, &x) in r.iter().enumerate() {
            let f = || format!("{field}[{i}][{j}]");
            if i != j {
                within(
                    f,
                    x.abs(),
                    (0.0, hi),
                    &format!("an off-diagonal {what} entry's size"),
                )?;
            } else if x != 0.0 {
                within(
                    f,
                    x.abs(),
                    (lo, hi),
                    &format!("a diagonal {what} entry's size (or 0)"),
                )?;
            }
        }
    }
    Ok(())
}

/// Entries of a vector (`None`: not measured) at most `hi` in magnitude,
/// naming `field[i]`, and the largest at least `lo`, naming `field`: `what`
/// names an entry, `hint` says what to do about a vector that small.
pub fn vector(
    field: &str,
    entries: impl IntoIterator<Item = Option<f64>>,
    (lo, hi): (f64, f64),
    what: &str,
    hint: &str,
) -> Result<(), InputError> {
    let mut largest: Option<f64> = None;
    for (i, x) in entries.into_iter().enumerate() {
        if let Some(x) = x {
            within(
                || format!("{field}[{i}]"),
                x.abs(),
                (0.0, hi),
                &format!("{what}'s size"),
            )?;
            largest = Some(largest.unwrap_or(0.0).max(x.abs()));
        }
    }
    match largest {
        Some(a) if a < lo => Err(InputError::invalid(
            "invalid_value",
            field,
            format!(
                "the largest entry of {field} must be at least {} in size, got {}: {hint}",
                shown(lo),
                shown(a)
            ),
        )),
        _ => Ok(()),
    }
}

/// Check squared angular frequencies `w2` (1/s²) against [`FREQUENCY_HZ`];
/// `from` names the fields that gave them. Returns them in Hz.
pub fn frequencies(w2: &[f64], from: &str) -> Result<Vec<f64>, InputError> {
    let (lo, hi) = FREQUENCY_HZ;
    let mut hz = Vec::with_capacity(w2.len());
    for &x in w2 {
        let f = x.max(0.0).sqrt() / std::f64::consts::TAU;
        if !(f.is_finite() && (lo..=hi).contains(&f)) {
            let negative = if x < 0.0 {
                " (a negative squared frequency: the stiffness matrix is not positive definite)"
            } else {
                ""
            };
            return Err(InputError::unsolvable(
                "frequency_out_of_range",
                format!(
                    "{from} give a natural frequency of {} Hz{negative}, outside the {} to {} Hz of a rotor on a test stand; check their units and sizes",
                    shown(f),
                    shown(lo),
                    shown(hi)
                ),
            ));
        }
        hz.push(f);
    }
    Ok(hz)
}
