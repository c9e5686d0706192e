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
/// that pass, `o` exceeds its mean by `σ λ(x)` on average, `λ(x) = φ(x) / (1 −
/// Φ(x))` the inverse Mills ratio at `x = (T − o) / σ` (the truncation point,
/// taken at the observed `o`; Johnson, Kotz and Balakrishnan 1994,
/// *Continuous Univariate Distributions* 1, §13.10.1). The own signal is then
/// `S ≈ o − N⊥ − σ λ(x)` rather than `o − N⊥`, and as `Ĉ_j ≈ C_j S / o` along the
/// plane's own direction, `C*_j ≈ Ĉ_j o / (o − N⊥)` falls short of `C_j` by
/// the ratio returned, `(o − N⊥) / (o − N⊥ − σ λ)`. Far above the limit `λ →
/// 0` and the ratio is 1 (ten speeds with 20 % trials, any 100 % trial at ten
/// speeds); just above it `λ = 0.8` (`σ/S ≈ √(2κ/rows)`: 7 % at `κ` 0.15
/// over forty rows).
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
    let (own, sigma) = (d.own[col], d.own_sd[col]);
    let x = (d.noise[col] / KAPPA_LIMIT - o) / sigma;
    let pass = 1.0 - super::normal_cdf(x);
    if !(own > 0.0 && sigma > 0.0 && pass > 0.0 && x.is_finite()) {
        return 1.0;
    }
    let density = (-0.5 * x * x).exp() / std::f64::consts::TAU.sqrt();
    let signal = own - sigma * density / pass;
    if signal > 0.0 {
        (own / signal).max(1.0)
    } else {
        1.0
    }
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
