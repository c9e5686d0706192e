//! Issue 12's calibration on the flexible rotor model (`rotor_model`): for
//! trial effects of 10 %, 20 %, 30 % and 100 % of the vibration, at one speed
//! and at ten, with the options' noise model and with `samples` scatter, the
//! 95 % ellipses hold the exact correction and `amplitude_95` holds the
//! vibration that really remains in 93–97 % of realisations, and the mean
//! correction lies within 0.1 standard deviations of the exact one.
//!
//! Binomial tolerance. A case tallies `N` = realisations × planes ellipse
//! checks (and realisations × rows residual checks). For a method whose true
//! coverage lies in 93–97 %, the observed fraction lies within
//! 3 sd = 3·√(p(1−p)/N) of that window with probability above 99.8 %, so each
//! case asserts the window widened by 3 sd (about ±1.9 % at N = 1200): a correct
//! method passes reliably, and one at 90 % or below (the first-order regions
//! at small trials, issue 12) or at 99 % or above (the old `amplitude_95`)
//! fails. All cases pooled (N ≈ 10⁴, sd ≈ 0.2 %) must lie in 93–97 % itself.

use fieldbal::balancing::model::{AngleDirection, Conventions, PhaseConvention, SolveOptions};
use fieldbal::balancing::phasor::weight_in;
use fieldbal::balancing::uncertainty::CHI2_2_95;
use nalgebra::{DVector, Vector2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;

use super::rotor_model::{rotor, session};
use super::{estimate, noisy, solve, LAG_AGAINST, LEAD_WITH};

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
    ellipse: (usize, usize),
    /// Ellipse checks of the planes without `trial_effect_small`.
    trusted: (usize, usize),
    amplitude: (usize, usize),
    /// Per plane: sum of (estimate − exact) and of |estimate − mean|² pieces.
    errors: Vec<Vec<Complex64>>,
}

fn window(hits: usize, n: usize, pad_sd: f64) -> (f64, f64, f64) {
    let p = hits as f64 / n as f64;
    let sd = (0.95 * 0.05 / n as f64).sqrt();
    (p, 0.93 - pad_sd * sd, 0.97 + pad_sd * sd)
}

/// Noisy realisations of one case. `samples`: each reading the mean of 6
/// samples scattering 5 %/5° (about 2 %/2° for the mean, like the default).
fn run(speeds: &[f64], effect: f64, conv: Conventions, samples: bool, seed: u64) -> Tally {
    let rotor = rotor(speeds, effect);
    let exact = rotor.readings();
    let mut rng = StdRng::seed_from_u64(seed);
    // The noise is stated (or measured by the samples): the solve removes the
    // errors-in-variables bias only then (uncertainty::bias).
    let pct = if samples { 5.0 } else { 2.0 };
    let options = SolveOptions {
        amplitude_noise_pct: Some(pct),
        phase_noise_deg: Some(pct),
        ..SolveOptions::default()
    };
    let planes = rotor.trial.len();
    let mut t = Tally {
        errors: vec![Vec::new(); planes],
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
            let y: Vec<Vec<Complex64>> = exact
                .iter()
                .map(|run| run.iter().map(|&z| noisy(z, 2.0, 2.0, &mut rng)).collect())
                .collect();
            (y, None)
        };
        let sol = solve(
            &session(conv, speeds, &rotor.trial, &y, s.as_deref()),
            &options,
        );
        for j in 0..planes {
            let (z, cov) = estimate(&sol, j);
            let d = z - rotor.correction(conv, j);
            t.errors[j].push(d);
            let v = Vector2::new(d.re, d.im);
            let inside = cov
                .try_inverse()
                .is_some_and(|inv| (v.transpose() * inv * v)[0] <= CHI2_2_95);
            t.ellipse.0 += usize::from(inside);
            t.ellipse.1 += 1;
            let plane = format!("P{j}");
            let warned = sol
                .warnings
                .iter()
                .any(|w| w.code == "trial_effect_small" && w.plane.as_deref() == Some(&plane));
            if !warned {
                t.trusted.0 += usize::from(inside);
                t.trusted.1 += 1;
            }
        }
        let fitted = DVector::from_fn(planes, |j, _| {
            let c = &sol.corrections[j];
            weight_in(conv, c.mass_g, c.angle_deg)
        });
        let actual = &rotor.y0 + &rotor.w * fitted;
        for (a, r) in sol.predicted_residual.iter().enumerate() {
            t.amplitude.0 += usize::from(actual[a].norm() <= r.amplitude_95.unwrap());
            t.amplitude.1 += 1;
        }
    }
    t
}

/// Mean error of each plane's correction in units of its spread.
fn bias_in_sd(t: &Tally) -> Vec<f64> {
    t.errors
        .iter()
        .map(|e| {
            let n = e.len() as f64;
            let mean = e.iter().sum::<Complex64>() / n;
            let var = e.iter().map(|d| (d - mean).norm_sqr()).sum::<f64>() / (n - 1.0);
            mean.norm() / var.sqrt()
        })
        .collect()
}

fn calibration(samples: bool, seed: u64) {
    let mut pooled = Tally::default();
    let mut failures = Vec::new();
    let convs = [LAG_AGAINST, LEAD_WITH, LEAD_AGAINST, LAG_WITH];
    for (case, (speeds, effect)) in [&ONE_SPEED[..], &TEN_SPEEDS[..]]
        .into_iter()
        .flat_map(|s| [0.1, 0.2, 0.3, 1.0].map(|e| (s, e)))
        .enumerate()
    {
        let conv = convs[case % convs.len()];
        let t = run(speeds, effect, conv, samples, seed + case as u64);
        let e = window(t.ellipse.0, t.ellipse.1, 3.0);
        let u = window(t.trusted.0, t.trusted.1.max(1), 3.0);
        let a = window(t.amplitude.0, t.amplitude.1, 3.0);
        let flagged = 1.0 - t.trusted.1 as f64 / t.ellipse.1 as f64;
        let bias = bias_in_sd(&t);
        eprintln!(
            "{} speed(s), trial {:.0} %: ellipse {:.3}, unflagged {:.3} ({:.0} % flagged), amplitude_95 {:.3}, bias/sd {:.3?}",
            speeds.len(),
            effect * 100.0,
            e.0,
            u.0,
            flagged * 100.0,
            a.0,
            bias
        );
        let what = format!("{} speeds, trial {effect}", speeds.len());
        // amplitude_95 holds everywhere.
        if !(a.1..=a.2).contains(&a.0) {
            failures.push(format!("{what}: amplitude {a:?}"));
        }
        // Where the warning stays silent the ellipses hold (with enough
        // unflagged checks to tell) ...
        if t.trusted.1 >= 200 && !(u.1..=u.2).contains(&u.0) {
            failures.push(format!("{what}: unflagged ellipse {u:?}"));
        }
        // ... and a case whose ellipses do not hold is flagged, mostly.
        if !(e.1..=e.2).contains(&e.0) && flagged < 0.5 {
            failures.push(format!("{what}: ellipse {e:?}, flagged {flagged}"));
        }
        // Unbiased where trusted.
        if flagged < 0.5 && bias.iter().any(|&b| b > 0.1) {
            failures.push(format!("{what}: mean error {bias:?} sd"));
        }
        pooled.trusted.0 += t.trusted.0;
        pooled.trusted.1 += t.trusted.1;
        pooled.amplitude.0 += t.amplitude.0;
        pooled.amplitude.1 += t.amplitude.1;
    }
    let e = window(pooled.trusted.0, pooled.trusted.1, 0.0);
    let a = window(pooled.amplitude.0, pooled.amplitude.1, 0.0);
    eprintln!(
        "pooled: unflagged ellipse {:.4}, amplitude_95 {:.4}",
        e.0, a.0
    );
    if !(0.93..=0.97).contains(&e.0) || !(0.93..=0.97).contains(&a.0) {
        failures.push(format!("pooled: unflagged ellipse {e:?}, amplitude {a:?}"));
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
    // with the noise stated the solve removes that bias (uncertainty::bias).
    let t = run(&ONE_SPEED, 1.0, LAG_AGAINST, false, 7);
    let bias = bias_in_sd(&t);
    eprintln!("bias/sd {bias:?}");
    assert!(bias.iter().all(|&b| b < 0.1), "{bias:?}");
}

#[test]
fn with_samples_scatter_the_regions_hold_95_percent_and_the_mean_correction_is_unbiased_at_any_trial_size(
) {
    calibration(true, 200);
}
