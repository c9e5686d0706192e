//! Issue 12's calibration on the flexible rotor model (`rotor_model`): for
//! trial effects of 10 %, 20 %, 30 % and 100 % of the vibration, at one speed
//! and at ten, with the options' noise model and with `samples` scatter, the
//! 95 % ellipses hold the exact correction and `amplitude_95` holds the
//! vibration that really remains in 93–97 % of realisations, and the mean
//! errors-in-variables estimate (`uncertainty.bias_corrected`, reported
//! beside the least-squares correction since session 13; the ellipse and
//! `amplitude_95` are those of the correction itself, the weight that is
//! fitted) lies within 0.1 standard deviations of the exact correction in
//! every case but one regime: one speed (four sensors, three planes: one complex
//! degree of freedom beyond the planes) with trials of 10–20 %, where the
//! answer flags most planes `trial_effect_small`. There the mean is 0.13–0.19
//! sd off and is held within 0.25 sd instead, because no estimator tried can
//! do better without an unbounded scatter (method 8.3, "one speed"): the
//! estimator that removes the errors-in-variables bias in full divides by
//! `ÂᴴÂ − M̂`, which is singular with appreciable probability there (on this
//! rotor, 20,000 realisations: mean within 0.02 sd, but an rms error 50–460
//! times the correction and a 95th percentile error 8–31 times it), and the
//! estimators with finite moments are 0.6–1.6 sd off (least squares, Fuller's
//! α-modification with α ≥ 0). Ten speeds, also flagged at 10 %, are not
//! exempt.
//!
//! Binomial tolerance. A case's ellipse checks are realisations × planes,
//! its `amplitude_95` checks realisations × rows; the checks of one
//! realisation are correlated (they share its readings), so the standard
//! error of a case's coverage is taken from the spread of the per-realisation
//! hit fractions, `sd = √(Var(h_r) / R)` (the cluster standard error; never
//! below the independent-checks binomial `√(0.95·0.05 / N)`). Each case must lie
//! in 93–97 % widened by 3 sd. The measured sd is 0.6–1.1 % at 400
//! realisations (one speed's three planes err together, so more than the
//! 0.63 % of 1200 independent checks). A correct method (true coverage in
//! 93–97 %) then fails a case with probability below 0.14 %; one at a true
//! 85 % (the first-order regions held 67–84 % at small trials) fails it
//! with probability above 99 %, one at 90 % with probability 40–85 % by the
//! case's sd. All eight cases of a noise source pooled (sd ≈ 0.3 % for the
//! ellipses, 0.14 % for `amplitude_95`, whose 40 rows at ten speeds err less
//! together) must lie in 93–97 % widened by 3 pooled sd (92.1–97.9 % and
//! 92.6–97.4 %): a method at 90 % (or 99 %) in every case fails that with
//! certainty (5 sd and more), and an `amplitude_95` at 98 % fails it by 4
//! pooled sd (checked: the pivot bound, 98.6–100 %, pools to 99.4 %, and an
//! empirical Bayes weight hedged upwards by its posterior mean pooled to
//! 97.9–98.0 %; both fail). A case alone at one speed (sd 0.5 %) lets 98 %
//! pass; at ten speeds (sd 0.2–0.3 %) it does not.
//!
//! Mean correction within 0.1 sd. Per plane the mean error over `R`
//! realisations and their sample covariance `S` give Hotelling's
//! `T² = R·m̄ᵀ S⁻¹ m̄`; a bias of `β` sd (`β² = bᵀΣ⁻¹b / 2`, the mean square
//! over both axes) makes `T²` noncentral χ²₂ with `λ = 2Rβ²`. A case sums the
//! three planes, χ²₆(λ): at `β = 0.1` in every plane `λ = 24`, whose 99 %
//! quantile is 59.3 (Patnaik's two-moment approximation with Wilson–Hilferty:
//! `c = (6+2λ)/(6+λ) = 1.8`, `h = (6+λ)²/(6+2λ) = 16.7`,
//! `c·h·(1 − 2/9h + 2.326·√(2/9h))³ = 59.3`). A case passes when the sum is
//! at most that (an observed root-mean-square bias of 0.157 sd): a method
//! within 0.1 sd passes with probability above 99 %, one 0.2 sd off
//! (`λ = 96`, mean 102, sd 20) fails with probability about 98 %. In the
//! exempted regime the limit is the same quantile at 0.25 sd (`λ = 150`,
//! `c = 1.96`, `h = 79.5`: 219.3): one 0.35 sd off (`λ = 294`, mean 300, sd
//! 34) fails it with probability about 99 %.

use fieldbal::balancing::model::{AngleDirection, Conventions, PhaseConvention, SolveOptions};
use fieldbal::balancing::uncertainty::CHI2_2_95;
use fieldbal::balancing::Solution;
use nalgebra::{Matrix2, Vector2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;

use super::rotor_model::{rotor, session};
use super::{estimate, noisy, noisy_runs, remaining_held, solve, LAG_AGAINST, LEAD_WITH};

const LAG_WITH: Conventions = Conventions {
    phase: PhaseConvention::Lag,
    angle_direction: AngleDirection::WithRotation,
};
const LEAD_AGAINST: Conventions = Conventions {
    phase: PhaseConvention::Lead,
    angle_direction: AngleDirection::AgainstRotation,
};

const ONE_SPEED: [f64; 1] = [3000.0];
const TEN_SPEEDS: [f64; 10] = [
    1200.0, 1700.0, 2200.0, 2700.0, 3200.0, 3700.0, 4200.0, 4700.0, 5200.0, 5700.0,
];
const REALISATIONS: usize = 400;

/// What one case tallied.
#[derive(Default)]
struct Tally {
    /// Per realisation: the fraction of planes whose ellipse held the exact correction.
    ellipse: Vec<f64>,
    /// Per realisation: the fraction of rows whose `amplitude_95` held.
    amplitude: Vec<f64>,
    /// Checks per realisation: planes, rows.
    checks: (usize, usize),
    /// Plane checks under a `trial_effect_small` warning.
    flagged: usize,
    /// Per plane: realisations whose ellipse held (printed, not asserted: the
    /// window is asserted on the planes pooled, method §8 "Session 17").
    plane_held: Vec<usize>,
    /// Per plane: estimate − exact, per realisation.
    errors: Vec<Vec<Complex64>>,
}

/// Coverage of per-realisation hit fractions, with its standard error (module doc).
pub(super) fn coverage(hits: &[f64], checks: usize) -> (f64, f64) {
    let r = hits.len() as f64;
    let p = hits.iter().sum::<f64>() / r;
    let var = hits.iter().map(|h| (h - p).powi(2)).sum::<f64>() / (r - 1.0);
    let binomial = (0.95 * 0.05 / (r * checks as f64)).sqrt();
    (p, (var / r).sqrt().max(binomial))
}

/// Whether a coverage `p` with standard error `sd` lies in 93–97 % widened by 3 sd.
pub(super) fn in_window((p, sd): (f64, f64)) -> bool {
    (0.93 - 3.0 * sd..=0.97 + 3.0 * sd).contains(&p)
}

/// 99 % quantile of the summed `T²` of three planes each biased by 0.1 sd (module doc).
const BIAS_T2_LIMIT: f64 = 59.3;
/// The same at 0.25 sd, for the one exempted regime (module doc).
const EXEMPT_T2_LIMIT: f64 = 219.3;

/// Noisy realisations of one case. `samples`: each reading the mean of 6
/// samples scattering 5 %/5° (about 2 %/2° for the mean, like the default).
fn run(speeds: &[f64], effect: f64, conv: Conventions, samples: bool, seed: u64) -> Tally {
    let rotor = rotor(speeds, effect);
    let exact = rotor.readings();
    let mut rng = StdRng::seed_from_u64(seed);
    // The noise is stated (or measured by the samples): the solve estimates
    // the errors-in-variables bias only then (uncertainty::bias).
    let pct = if samples { 5.0 } else { 2.0 };
    let options = SolveOptions {
        amplitude_noise_pct: Some(pct),
        phase_noise_deg: Some(pct),
        ..SolveOptions::default()
    };
    let planes = rotor.trial.len();
    let mut t = Tally {
        errors: vec![Vec::new(); planes],
        plane_held: vec![0; planes],
        checks: (planes, rotor.y0.len()),
        ..Tally::default()
    };
    for _ in 0..REALISATIONS {
        let (y, s) = if samples {
            let s: Vec<Vec<Vec<Complex64>>> = exact
                .iter()
                .map(|run| {
                    run.iter()
                        .map(|&z| (0..6).map(|_| noisy(z, 5.0, 5.0, &mut rng)).collect())
                        .collect()
                })
                .collect();
            let y = s
                .iter()
                .map(|run| {
                    run.iter()
                        .map(|x: &Vec<Complex64>| x.iter().sum::<Complex64>() / 6.0)
                        .collect()
                })
                .collect();
            (y, Some(s))
        } else {
            let y = noisy_runs(&exact, &mut rng);
            (y, None)
        };
        let sol = solve(
            &session(conv, speeds, &rotor.trial, &y, s.as_deref()),
            &options,
        );
        let mut held = 0;
        for j in 0..planes {
            let (z, cov) = estimate(&sol, j);
            let exact = rotor.correction(conv, j);
            // The mean is that of the errors-in-variables estimate, reported
            // beside the correction where the noise is stated or measured.
            t.errors[j].push(unbiased(&sol, j) - exact);
            let d = z - exact;
            let v = Vector2::new(d.re, d.im);
            let inside = cov
                .try_inverse()
                .is_some_and(|inv| (v.transpose() * inv * v)[0] <= CHI2_2_95);
            held += usize::from(inside);
            t.plane_held[j] += usize::from(inside);
            let plane = format!("P{j}");
            t.flagged += usize::from(
                sol.warnings
                    .iter()
                    .any(|w| w.code == "trial_effect_small" && w.plane.as_deref() == Some(&plane)),
            );
        }
        t.ellipse.push(held as f64 / planes as f64);
        t.amplitude
            .push(remaining_held(&sol, conv, &rotor.w, &rotor.y0));
    }
    t
}

/// Plane `j`'s errors-in-variables estimate (`uncertainty.bias_corrected`),
/// as a complex mass in the session's angle convention. Every job here has
/// more rows than planes and its noise stated or measured, so the estimate
/// is always formed: its absence fails the test rather than letting the
/// least-squares correction stand in for it.
fn unbiased(sol: &Solution, j: usize) -> Complex64 {
    let c = &sol.corrections[j];
    let b = c
        .uncertainty
        .as_ref()
        .and_then(|u| u.bias_corrected.as_ref())
        .unwrap_or_else(|| panic!("plane {}: no bias_corrected", c.plane));
    Complex64::from_polar(b.mass_g, b.angle_deg.to_radians())
}

/// Per plane: Hotelling's `T²` of the mean error, and the bias in sd it
/// shows, `√(m̄ᵀ S⁻¹ m̄ / 2)` (module doc).
fn bias_t2(t: &Tally) -> Vec<(f64, f64)> {
    t.errors
        .iter()
        .map(|e| {
            let n = e.len() as f64;
            let mean = e.iter().sum::<Complex64>() / n;
            let mut s = Matrix2::zeros();
            for d in e {
                let v = Vector2::new(d.re - mean.re, d.im - mean.im);
                s += v * v.transpose() / (n - 1.0);
            }
            let m = Vector2::new(mean.re, mean.im);
            let q = (m.transpose() * s.try_inverse().expect("errors scatter") * m)[0];
            (n * q, (q / 2.0).sqrt())
        })
        .collect()
}

fn calibration(samples: bool, seed: u64) {
    let mut failures = Vec::new();
    let mut pooled = [(0.0, 0.0); 2];
    let convs = [LAG_AGAINST, LEAD_WITH, LEAD_AGAINST, LAG_WITH];
    let cases: Vec<(&[f64], f64)> = [&ONE_SPEED[..], &TEN_SPEEDS[..]]
        .into_iter()
        .flat_map(|s| [0.1, 0.2, 0.3, 1.0].map(|e| (s, e)))
        .collect();
    for (case, &(speeds, effect)) in cases.iter().enumerate() {
        let conv = convs[case % convs.len()];
        let t = run(speeds, effect, conv, samples, seed + case as u64);
        let e = coverage(&t.ellipse, t.checks.0);
        let a = coverage(&t.amplitude, t.checks.1);
        let bias = bias_t2(&t);
        let t2: f64 = bias.iter().map(|b| b.0).sum();
        let what = format!(
            "{} {} speed(s), trial {:.0} %, {conv:?}",
            if samples { "samples" } else { "stated" },
            speeds.len(),
            effect * 100.0
        );
        eprintln!(
            "{what}: ellipse {:.3} ± {:.3} (per plane {:.3?}), amplitude_95 {:.3} ± {:.3}, bias/sd {:.3?} (T² {t2:.1}), {:.0} % flagged",
            e.0,
            e.1,
            t.plane_held
                .iter()
                .map(|&h| h as f64 / t.ellipse.len() as f64)
                .collect::<Vec<_>>(),
            a.0,
            a.1,
            bias.iter().map(|b| b.1).collect::<Vec<_>>(),
            100.0 * t.flagged as f64 / (t.ellipse.len() * t.checks.0) as f64,
        );
        if !in_window(e) {
            failures.push(format!("{what}: ellipse {e:?}"));
        }
        if !in_window(a) {
            failures.push(format!("{what}: amplitude_95 {a:?}"));
        }
        // The one exemption (module doc): one speed, where the rows exceed
        // the planes by one, trials of 10–20 %, and the answer flags most
        // planes `trial_effect_small`. There the mean is held within 0.25 sd.
        let flagged = t.flagged * 2 >= t.ellipse.len() * t.checks.0;
        let exempt = flagged && speeds.len() == 1 && effect <= 0.2;
        let limit = if exempt {
            EXEMPT_T2_LIMIT
        } else {
            BIAS_T2_LIMIT
        };
        if t2 > limit {
            failures.push(format!("{what}: mean error T² {t2:.1} > {limit}"));
        }
        for (sum, x) in pooled.iter_mut().zip([e, a]) {
            sum.0 += x.0 / cases.len() as f64;
            sum.1 += (x.1 / cases.len() as f64).powi(2);
        }
    }
    let pooled = pooled.map(|(p, v)| (p, v.sqrt()));
    eprintln!(
        "pooled: ellipse {:.4}, amplitude_95 {:.4}",
        pooled[0].0, pooled[1].0
    );
    if !pooled.iter().all(|&x| in_window(x)) {
        failures.push(format!("pooled: ellipse, amplitude {pooled:?}"));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

#[test]
fn on_a_flexible_rotor_the_regions_hold_95_percent_and_the_mean_correction_is_unbiased_at_any_trial_size(
) {
    calibration(false, 100);
}

#[test]
fn with_a_well_sized_trial_at_one_speed_the_mean_correction_is_within_a_tenth_of_its_spread() {
    // Plain least squares is 0.13–0.2 sd off here (errors in variables);
    // with the noise stated the solve reports the estimate with that bias
    // removed beside it (`bias_corrected`, uncertainty::bias).
    let t = run(&ONE_SPEED, 1.0, LAG_AGAINST, false, 7);
    let bias = bias_t2(&t);
    eprintln!("T², bias/sd {bias:?}");
    assert!(bias.iter().all(|&(_, b)| b < 0.1), "{bias:?}");
}

#[test]
fn with_samples_scatter_the_regions_hold_95_percent_and_the_mean_correction_is_unbiased_at_any_trial_size(
) {
    calibration(true, 200);
}
