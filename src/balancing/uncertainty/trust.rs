//! When the first-order figures can be trusted: `trial_effect_small` from the
//! noise of each plane's influence coefficients beside their signal (issue 12,
//! item 4).
//!
//! The first-order regions treat the correction as linear in the readings;
//! the terms that linearisation leaves out (the errors-in-variables bias of
//! `bias`, and the heavy tails of a ratio of noisy quantities) grow with
//! `κ_j = M_jj · [(AᴴA)⁻¹]_jj`, where `M_jj = Σ_a g_a² Var(W_aj)` is the noise
//! energy of plane `j`'s influence coefficients over the used rows (from the
//! readings' own noise: the options or the samples' scatter) and
//! `[(AᴴA)⁻¹]_jj` the inverse of the part of its signal energy that the other
//! planes do not explain (`A = G W`, method 3.3). `1/√κ_j` is the signal-to-
//! noise ratio of the plane's whole trial effect over all sensors and speeds;
//! it grows in proportion to the trial mass, so `κ ∝ 1/m²`.
//!
//! The regions are widened by `(1 + κ_j)` ([`second_order`], method 8.4) and
//! hold 93–97 % pooled over the planes at any trial size on the rotor model of
//! tests/uncertainty/eiv.rs. Single planes above the limit hold less: 90 % at
//! ten speeds with 10 % trials there, 84–91 % at two to four speeds, 86–88 % on
//! the held-out rotor at ten speeds 1000–5500 rpm (method §8, "Session 17"),
//! which is why the warning says the widened interval can still miss.
//! What `κ` above [`KAPPA_LIMIT`] also means is that the correction itself is
//! poor: at one speed with 10–20 % trials the estimates scatter by as much as
//! their own size and their mean is 0.13–0.19 sd off (a ratio's heavy tails),
//! where below the limit it is within 0.1 sd. So the warning fires there and
//! asks for `√(κ / KAPPA_LIMIT)` times the trial mass, which brings `κ` under
//! the limit (`κ ∝ 1/m²`; tested in tests/uncertainty/noise_options.rs).
//! `κ` is large for a large trial too where the sensors see the plane much
//! like a combination of the others (little of its effect is its own, however
//! heavy the trial): there the warning says so and asks first for a sensor or
//! speed that tells the planes apart.
//!
//! Session 24: the planes that pass the test are selected by it. `κ̂_j =
//! M_jj / o_j` divides by the noisy own energy `o_j = 1/[(ÂᴴÂ)⁻¹]_jj`, and
//! the noise that lengthens `o_j` (makes the trial look strong, so that it
//! passes) also makes the correction and its errors-in-variables estimate
//! `C*` short: near the limit the planes with no warning are those whose
//! `C*` is not de-attenuated enough and whose region (formed at `C*`) is
//! small. With 15 % trials at ten speeds (true `κ` 0.15–0.17, at the limit)
//! a fifth of the jobs passed, and their planes held 88.5–89.3 % with the
//! exact correction outward of `Ĉ` by 0.9–1.1 of the region's radial sd on
//! average; `|C*|/|C|` was 0.90–0.93 there against 1.03–1.08 on the warned
//! planes (method §8, "Session 24"). [`selection_stretch`] takes the
//! selection's mean out of `o_j`, which lengthens `C*` for the region of an
//! unwarned plane (bias/region.rs); far from the limit it is 1.

use super::hidden::Denoised;
use super::Propagation;
use crate::balancing::solution::{Solution, Warning};
use crate::balancing::solve::Fit;

/// Largest `κ` (noise over signal energy of a plane's influence coefficients)
/// at which the first-order 95 % figures are still calibrated (module doc).
pub const KAPPA_LIMIT: f64 = 0.15;

/// The factor `1 + κ_j` that takes the correction's covariance to second
/// order in the coefficients' noise, `(1 + κ_j) Σ_j` (method 8.4). Expanding `Â⁺ = A⁺ − A⁺ E A⁺ + …` (`Â = A + E`), the
/// correction error gains the term `−A⁺ E (Ĉ − C)`, the noise of the
/// coefficients acting on the error of the correction itself; for plane `j`
/// its variance is `[(AᴴA)⁻¹]_jj M_jj Var(Ĉ_j) = κ_j Σ_j` (own plane; the
/// cross-plane terms are smaller where the planes are told apart). This is the
/// second-order variance of a ratio estimate (Fuller 1987, *Measurement Error
/// Models*, §1.2; Fieller's ratio `a/b` has relative variance `(1 + CV_b²)`
/// times the first-order one to the same order). It matters only where the
/// first-order figures are about to fail (`κ` up to [`KAPPA_LIMIT`] adds up to
/// 15 % to the variance).
pub fn second_order(kappa: Option<f64>) -> f64 {
    1.0 + kappa.unwrap_or(0.0)
}

/// `κ_j` of every plane of `fit.planes` (module doc); `None` where the plane
/// is undetermined (no signal energy of its own).
pub fn kappa(fit: &Fit, prop: &Propagation) -> Vec<Option<f64>> {
    let checked = &fit.checked;
    let sel = &fit.selection;
    // `[(AᴴA)⁻¹]_jj` from the propagation's thin SVD of `A` (issue 15).
    let Some(inv) = &prop.gram_inv_diag else {
        return vec![None; fit.planes.len()];
    };
    fit.planes
        .iter()
        .zip(inv)
        .map(|(&plane, &inv)| {
            let tau = (0..checked.t.ncols())
                .map(|k| checked.t[(plane, k)].norm())
                .fold(0.0, f64::max);
            let noise: f64 = sel
                .rows
                .iter()
                .zip(&sel.weights)
                .map(|(&row, g)| (g * prop.effect_sd[(row, plane)] / tau).powi(2))
                .sum();
            Some(noise * inv).filter(|k| k.is_finite())
        })
        .collect()
}

/// For a plane that passed the `κ` test (`κ̂_j ≤` [`KAPPA_LIMIT`]), the factor
/// by which its errors-in-variables estimate `C*_j` is short because it
/// passed (module doc, session 24); `1.0` where the test failed or the noise
/// is not known (`denoised` none).
///
/// The test passes where the own energy `o = 1/[(ÂᴴÂ)⁻¹]_jj` exceeds `T =
/// M_jj / KAPPA_LIMIT`. To first order `o = S + N⊥ + σ X` (`S` the own signal
/// energy, `N⊥` the noise's mean outside the other columns' span, `σ` the
/// noise's sd of `o`, all of [`Denoised`]; `X ~ N(0, 1)`), so among the planes
/// that pass, `o` exceeds its mean: the mean `μ = S + N⊥` is estimated from
/// the likelihood of `o` given that it passed (the normal truncated at `T`),
/// maximised over `μ` with `S` bounded below ([`stretch_given_pass`]). The
/// own signal is then `Ŝ = μ̂ − N⊥` rather than `o − N⊥`, and as `Ĉ_j ≈ C_j S
/// / o` along the plane's own direction, `C*_j ≈ Ĉ_j o / (o − N⊥)` falls short
/// of `C_j` by the ratio returned, `(o − N⊥) / Ŝ`. Far above the limit the
/// ratio is 1 (ten speeds with 20 % trials, any 100 % trial at ten speeds);
/// `σ/S ≈ √(2κ/rows)`: 7 % at `κ` 0.15 over forty rows. Until session 24's
/// second round `Ŝ` was `o − N⊥ − σ λ(x)`, `λ` the inverse Mills ratio at `x
/// = (T − o)/σ` taken at the observed `o` (Johnson, Kotz and Balakrishnan
/// 1994, *Continuous Univariate Distributions* 1, §13.10.1): the selection's
/// mean for a plane whose mean sits where it was seen, at most `0.80 σ`,
/// where a plane that passes near the limit mostly has its mean below it
/// (method §8, "Session 24, sel24").
pub fn selection_stretch(
    kappa: Option<f64>,
    col: usize,
    prop: &Propagation,
    denoised: Option<&Denoised>,
) -> f64 {
    let (Some(k), Some(d), Some(inv)) = (kappa, denoised, prop.gram_inv_diag.as_ref()) else {
        return 1.0;
    };
    if k > KAPPA_LIMIT {
        return 1.0;
    }
    let o = 1.0 / inv[col];
    stretch_given_pass(o, d.own[col], d.own_sd[col], d.noise[col] / KAPPA_LIMIT)
}

/// Largest [`selection_stretch`]: the conditional likelihood is flat in the
/// own signal as the observed own energy nears the test's limit, so the
/// estimate is bounded (session 24, sel24: at 1.5 and over the one speed
/// with samples at 20 % trials held 97.3–97.4 %, over the 93–97 % band; at
/// 1.25 the table's lines stay inside it and the planes at the limit gain as
/// much as without a bound).
pub const MAX_STRETCH: f64 = 1.25;

/// [`selection_stretch`] from the observed own energy `o`, its de-noised
/// part `own = o − N⊥`, the noise's sd `sigma` and the test's limit `t`:
/// `own / Ŝ`, `Ŝ = μ̂ − N⊥` with `μ̂` the conditional maximum-likelihood
/// estimate of `o`'s mean given `o > t` (`o` normal about `μ` with sd `σ`,
/// truncated at `t`), bounded by `Ŝ ≥ own /` [`MAX_STRETCH`]. The score of
/// `ln φ((o − μ)/σ) − ln(1 − Φ((t − μ)/σ))` vanishes where `o − μ = σ λ(u)`,
/// `u = (t − μ)/σ`, `λ` the inverse Mills ratio; `λ(u) − u` falls strictly
/// (its slope is `λ(λ − u) − 1 ∈ (−1, 0)`), so the root in `u` is one:
/// Newton's method finds it, safeguarded by the bracket. `o` far above `t`: `μ̂ → o`, the ratio 1; `o` near `t`:
/// `μ̂` runs far below `t`, hence the bound.
pub fn stretch_given_pass(o: f64, own: f64, sigma: f64, t: f64) -> f64 {
    if !(own > 0.0 && sigma > 0.0 && o.is_finite() && t.is_finite()) {
        return 1.0;
    }
    let above = ((o - t) / sigma).max(0.0);
    let score = |u: f64| mills(u) - u - above;
    let noise_off = o - own;
    // The bound `Ŝ ≥ own / MAX_STRETCH` in `u`.
    let mut hi = (t - noise_off - own / MAX_STRETCH) / sigma;
    if score(hi) >= 0.0 {
        return MAX_STRETCH;
    }
    // `λ(u) > 0`, so the score is positive at `u = −above − 1`. Newton's
    // steps on the score (its slope `λ(λ − u) − 1`) kept inside the bracket,
    // halving it where a step would leave it: a handful of the erfc
    // evaluations that plain bisection took a hundred of (the two-plane
    // solve with stated noise went from 24 to 50 µs with those).
    let mut lo = -above - 1.0;
    let mut u = 0.5 * (lo + hi);
    for _ in 0..100 {
        let l = mills(u);
        let f = l - u - above;
        if f > 0.0 {
            lo = u;
        } else {
            hi = u;
        }
        if f.abs() <= 1e-13 * (1.0 + above) || hi - lo <= 1e-13 * (1.0 + u.abs()) {
            break;
        }
        let next = u - f / (l * (l - u) - 1.0);
        u = if next > lo && next < hi {
            next
        } else {
            0.5 * (lo + hi)
        };
    }
    let signal = t - sigma * u - noise_off;
    if signal > 0.0 {
        (own / signal).clamp(1.0, MAX_STRETCH)
    } else {
        MAX_STRETCH
    }
}

/// `ln(1 − Φ(x))`, accurate far into the upper tail (`erfc` underflows past
/// `x ≈ 37`; there the asymptotic series of Mills' ratio).
fn ln_upper_tail(x: f64) -> f64 {
    if x < 30.0 {
        (0.5 * libm::erfc(x * std::f64::consts::FRAC_1_SQRT_2)).ln()
    } else {
        let x2 = x * x;
        -0.5 * x2 - (x * std::f64::consts::TAU.sqrt()).ln()
            + (1.0 - 1.0 / x2 + 3.0 / (x2 * x2)).ln()
    }
}

/// The inverse Mills ratio `λ(u) = φ(u) / (1 − Φ(u))`.
fn mills(u: f64) -> f64 {
    (-0.5 * u * u - ln_upper_tail(u)).exp() / std::f64::consts::TAU.sqrt()
}

/// Add `trial_effect_small` for every plane whose `κ` exceeds
/// [`KAPPA_LIMIT`], merging with an existing one.
pub fn warn_untrusted(
    fit: &Fit,
    prop: &Propagation,
    kappas: &[Option<f64>],
    solution: &mut Solution,
) {
    for (col, (&k, &j)) in kappas.iter().zip(&fit.planes).enumerate() {
        let Some(k) = k.filter(|&k| k > KAPPA_LIMIT) else {
            continue;
        };
        let id = fit.checked.session.planes[j].id.clone();
        let enlarge = (k / KAPPA_LIMIT).sqrt();
        // `1/√κ` is the effect-to-noise ratio of the part of the plane's effect
        // that the other planes do not also produce (module doc). Where that
        // part is a small share of the whole (the sensors see the plane much
        // like a combination of the others), the trial is not what is small:
        // telling the planes apart helps as much as a heavier trial.
        let share = own_share(fit, prop, col, j);
        let dependent = share < DEPENDENT_SHARE;
        let given = if dependent {
            ", given how alike the planes look to the sensors"
        } else {
            ""
        };
        let (why, remedy) = if dependent {
            (
                format!(" (only {:.0} % of plane {id}'s effect is its own: the sensors see it much like the other planes together)", 100.0 * share),
                format!("add a sensor or speed that tells plane {id} from the others, solve without it, or repeat the trial run with about {enlarge:.1} times the trial mass"),
            )
        } else {
            (
                String::new(),
                format!("repeat the trial run with about {enlarge:.1} times the trial mass, or at a larger radius"),
            )
        };
        let text = format!(
            "the trial weight in plane {id} is too small for the readings' noise{given}: over all sensors and speeds, the part of its effect that the other planes do not also produce is only {:.1} times its noise{why} (from amplitude_noise_pct, phase_noise_deg or the samples' scatter), and below {:.1} times the correction for {id} scatters too widely to be worth fitting (its interval is widened for this, but with a trial this small it can still hold well under 95 % of the time): {remedy}",
            1.0 / k.sqrt(),
            1.0 / KAPPA_LIMIT.sqrt(),
        );
        trial_warning(&mut solution.warnings, id, text);
    }
}

/// Below this share of its own (a sine of 0.5: 30° from the others' span) a
/// plane's dependence on the others at least halves its effect-to-noise ratio.
const DEPENDENT_SHARE: f64 = 0.5;

/// The share of plane `plane`'s weighted influence column `a_j` (column `col`
/// of `A = G W`) that the other columns do not span, `‖(I − P) a_j‖ / ‖a_j‖`:
/// the residual of `a_j` on the others has squared norm `1 / [(AᴴA)⁻¹]_jj`,
/// which the propagation already holds (no second factorisation).
fn own_share(fit: &Fit, prop: &Propagation, col: usize, plane: usize) -> f64 {
    let Some(inv) = prop.gram_inv_diag.as_ref().and_then(|d| d.get(col)) else {
        return 0.0;
    };
    let sel = &fit.selection;
    let norm2: f64 = sel
        .rows
        .iter()
        .zip(&sel.weights)
        .map(|(&row, g)| (g * fit.w[(row, plane)].norm()).powi(2))
        .sum();
    if norm2 <= 0.0 || *inv <= 0.0 {
        return 0.0;
    }
    (1.0 / (norm2 * inv)).sqrt().min(1.0)
}

/// Give plane `id` a `trial_effect_small` warning saying `text`, appended to
/// the one it already has: the effect-to-noise test and the `κ` test each
/// say what to do, in their own terms.
pub fn trial_warning(warnings: &mut Vec<Warning>, id: String, text: String) {
    let existing = warnings
        .iter_mut()
        .find(|w| w.code == "trial_effect_small" && w.plane.as_deref() == Some(id.as_str()));
    match existing {
        Some(w) => w.message = format!("{}. Also, {text}", w.message.trim_end_matches('.')),
        None => warnings.push(Warning {
            code: "trial_effect_small".into(),
            message: text,
            plane: Some(id),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The own energy's de-noised part 1.0 over a noise mean of 0.3 outside
    /// the others' span, its sd 0.07 (`κ` about 0.15 over forty rows).
    const OWN: f64 = 1.0;
    const OFF: f64 = 0.3;
    const SD: f64 = 0.07;

    #[test]
    fn just_above_the_limit_the_stretch_is_the_conditional_maximum_likelihood() {
        let o = OWN + OFF;
        let t = o - 0.5 * SD;
        let s = stretch_given_pass(o, OWN, SD, t);
        // The estimated mean `μ̂ = N⊥ + Ŝ` zeroes the truncated normal's
        // score: `o − μ̂ = σ λ((t − μ̂)/σ)`, here about 1.63 σ below `o`
        // (the inverse Mills ratio at the observed `o` took 0.51 σ).
        let mu = OFF + OWN / s;
        let u = (t - mu) / SD;
        let score = (o - mu) / SD - mills(u);
        assert!(score.abs() < 1e-9, "stretch {s}, score {score}");
        assert!((o - mu) / SD > 1.5 && s < MAX_STRETCH, "stretch {s}");
    }

    #[test]
    fn far_above_the_limit_nothing_is_stretched_and_at_it_the_bound_holds() {
        let o = OWN + OFF;
        let far = stretch_given_pass(o, OWN, SD, o - 10.0 * SD);
        assert!((far - 1.0).abs() < 1e-12, "{far}");
        // At the limit the likelihood keeps rising as the mean falls.
        assert_eq!(stretch_given_pass(o, OWN, SD, o), MAX_STRETCH);
        // Unknown noise: no stretch.
        assert_eq!(stretch_given_pass(o, OWN, 0.0, o), 1.0);
    }

    #[test]
    fn the_inverse_mills_ratio_holds_far_into_the_tail() {
        // `λ(0) = 2/√(2π)`; `λ(u) → u + 1/u` for large `u`, past erfc's range.
        assert!((mills(0.0) - (2.0 / std::f64::consts::PI).sqrt()).abs() < 1e-14);
        for u in [10.0, 29.9, 30.1, 60.0] {
            let want = u + 1.0 / u - 2.0 / (u * u * u);
            assert!((mills(u) - want).abs() < 2e-5 * want, "{u} {}", mills(u));
        }
    }
}
