//! `identify/free-decay` (method §7): the paper's experiment — turbulent
//! damping `c/m = 39.4784`, `b/m = 0.00375` (δ0 = 0.01), 21 samples rounded
//! to 4, 3 and 2 decimals at steps 0.2 and 0.25 — against the finite-difference
//! model; viscous decays; and a noise sweep showing where estimates degrade.
//! Decays are integrated by RK4 with a step of 1e-4 s.

use crate::support;

use fieldbal::identification::decay::{identify, DampingLaw, FreeDecay, FreeDecayRequest};
use nalgebra::{DMatrix, DVector};
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};
use support::{rk4_samples, round_to};

const C_M: f64 = 39.4784;
const B_M: f64 = 0.00375;
const H: f64 = 1e-4;

/// The paper's decay `y'' + (c/m) y + (b/m) y'|y'| = 0`, `y(0) = 1`, `y'(0) = 0`.
fn turbulent_decay(step: f64, samples: usize) -> Vec<f64> {
    let every = (step / H).round() as usize;
    rk4_samples(
        |y, v| -C_M * y - B_M * v * v.abs(),
        1.0,
        0.0,
        H,
        every,
        samples,
    )
}

fn fit(samples: &[f64], dt_s: f64, damping: DampingLaw) -> FreeDecay {
    fit_with(samples, dt_s, damping, None)
}

/// As [`fit`], with the request's `offset` (known; absent, fitted).
fn fit_with(samples: &[f64], dt_s: f64, damping: DampingLaw, offset: Option<f64>) -> FreeDecay {
    identify(&FreeDecayRequest {
        samples: samples.to_vec(),
        dt_s,
        damping,
        offset,
    })
    .unwrap()
}

/// The finite-difference model `α1 y(k−1) + α2 (y(k) − y(k−2))|y(k) − y(k−2)| = y(k) + y(k−2)`
/// (central differences): `c/m = (2 − α1)/τ²`, `b/m = −4 α2`.
fn finite_difference(y: &[f64], tau: f64) -> (f64, f64) {
    let rows = y.len() - 2;
    let a = DMatrix::from_fn(rows, 2, |r, j| {
        let k = r + 2;
        let d = y[k] - y[k - 2];
        if j == 0 {
            y[k - 1]
        } else {
            d * d.abs()
        }
    });
    let b = DVector::from_iterator(rows, (2..y.len()).map(|k| y[k] + y[k - 2]));
    let x = a.svd(true, true).solve(&b, 1e-14).unwrap();
    ((2.0 - x[0]) / (tau * tau), -4.0 * x[1])
}

fn err(got: f64, want: f64) -> f64 {
    (got - want).abs() / want
}

/// The paper's samples have no offset: given as known (`offset` 0), (7.2)
/// is the paper's and keeps its accuracy, b/m under 2 %. Fitted, the offset
/// costs accuracy on these 21 samples: at τ = 0.25 s (four samples a period)
/// rounded to two decimals the rounding leaves a constant of −0.0014 (the
/// fit without it explains the record worse, F = 14.5 against 4.5 at 95 %),
/// and with it taken out b/m is 3.2 % off (1.5 % left in).
#[test]
fn the_papers_experiment_is_reproduced_and_beats_finite_differences_tenfold() {
    for (offset, b_bound) in [(Some(0.0), 0.02), (None, 0.035)] {
        for step in [0.2, 0.25] {
            let exact = turbulent_decay(step, 21);
            for decimals in [4, 3, 2] {
                let y: Vec<f64> = exact.iter().map(|&v| round_to(v, decimals)).collect();
                let got = fit_with(&y, step, DampingLaw::Turbulent, offset);
                let (ec, eb) = (err(got.c_over_m, C_M), err(got.b_over_m, B_M));
                let (fc, fb) = finite_difference(&y, step);
                let (fec, feb) = (err(fc, C_M), err(fb, B_M));
                let what = format!("offset {offset:?}, τ = {step}, {decimals} decimals");
                println!(
                    "{what}: c/m {:.5} ({:.4} %), b/m {:.6} ({:.2} %); finite differences {:.3} %, {:.1} %",
                    got.c_over_m, 100.0 * ec, got.b_over_m, 100.0 * eb, 100.0 * fec, 100.0 * feb
                );
                assert!(ec < 0.001, "{what}: c/m off by {:.4} %", 100.0 * ec);
                assert!(eb < b_bound, "{what}: b/m off by {:.3} %", 100.0 * eb);
                assert!(
                    fec > 10.0 * ec && feb > 10.0 * eb,
                    "{what}: finite differences not ten times worse: {fec} vs {ec}, {feb} vs {eb}"
                );
                assert!(
                    (got.decrement - 0.01).abs() < b_bound * 0.01,
                    "{what}: {got:?}"
                );
                assert!((got.amplitude - 1.0).abs() < 0.01, "{what}: {got:?}");
            }
        }
    }
}

#[test]
fn an_integrated_viscous_decay_is_identified_from_rounded_samples() {
    let (w0, zeta) = (2.0 * std::f64::consts::PI * 1.3, 0.02);
    let step = 0.1;
    let exact = rk4_samples(
        |y, v| -w0 * w0 * y - 2.0 * zeta * w0 * v,
        0.5,
        1.0,
        H,
        (step / H) as usize,
        40,
    );
    let y: Vec<f64> = exact.iter().map(|&v| round_to(v, 4)).collect();
    let got = fit(&y, step, DampingLaw::Viscous);
    assert!(err(got.c_over_m, w0 * w0) < 1e-3, "{got:?}");
    assert!(err(got.b_over_m, 2.0 * zeta * w0) < 0.03, "{got:?}");
    let log_dec = 2.0 * std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt();
    assert!(err(got.decrement, log_dec) < 0.03, "{got:?}");
    assert!(got.fit_rms < 1e-4, "{got:?}");
    // The exact samples give the initial state back: y0 = a cos ψ.
    let exact_fit = fit(&exact, step, DampingLaw::Viscous);
    assert!(
        (exact_fit.amplitude * exact_fit.phase_deg.to_radians().cos() - 0.5).abs() < 1e-6,
        "{exact_fit:?}"
    );
}

/// Mean relative errors of (c/m, b/m) over seeds with Gaussian noise of `sigma` (× a0).
fn noisy_errors(
    exact: &[f64],
    step: f64,
    law: DampingLaw,
    truth: (f64, f64),
    sigma: f64,
) -> (f64, f64) {
    let seeds = 20;
    let gauss = Normal::new(0.0, 1.0).unwrap();
    let mut sum = (0.0, 0.0);
    for seed in 0..seeds {
        let mut rng = StdRng::seed_from_u64(seed);
        let y: Vec<f64> = exact
            .iter()
            .map(|&v| v + sigma * gauss.sample(&mut rng))
            .collect();
        match identify(&FreeDecayRequest {
            samples: y,
            dt_s: step,
            damping: law,
            offset: None,
        }) {
            Ok(got) => {
                sum.0 += err(got.c_over_m, truth.0);
                sum.1 += err(got.b_over_m, truth.1).min(10.0);
            }
            // A decay lost in noise may not fit at all: count it as a 1000 % error.
            Err(_) => {
                sum.0 += 10.0;
                sum.1 += 10.0;
            }
        }
    }
    (sum.0 / seeds as f64, sum.1 / seeds as f64)
}

#[test]
fn a_noise_sweep_shows_the_estimates_degrading_with_the_noise() {
    let levels = [1e-5, 1e-4, 1e-3, 1e-2, 3e-2];
    let cases = [
        (
            "turbulent",
            DampingLaw::Turbulent,
            turbulent_decay(0.2, 21),
            0.2,
            (C_M, B_M),
        ),
        (
            "viscous",
            DampingLaw::Viscous,
            {
                let w0 = 2.0 * std::f64::consts::PI;
                rk4_samples(|y, v| -w0 * w0 * y - 0.1 * v, 1.0, 0.0, H, 2000, 21)
            },
            0.2,
            (4.0 * std::f64::consts::PI.powi(2), 0.1),
        ),
    ];
    for (name, law, exact, step, truth) in cases {
        let errors: Vec<(f64, f64)> = levels
            .iter()
            .map(|&s| noisy_errors(&exact, step, law, truth, s))
            .collect();
        for (s, e) in levels.iter().zip(&errors) {
            println!(
                "{name}: noise {s:.0e}: c/m {:.4} %, b/m {:.2} %",
                100.0 * e.0,
                100.0 * e.1
            );
        }
        // At low noise the paper's accuracy holds; the damping degrades first.
        assert!(
            errors[0].0 < 1e-3 && errors[0].1 < 0.02,
            "{name}: {errors:?}"
        );
        assert!(
            errors[4].1 > 10.0 * errors[0].1,
            "{name}: damping does not degrade: {errors:?}"
        );
        // Monotone-ish: each level is no better than half the previous one's error.
        for w in errors.windows(2) {
            assert!(w[1].1 > 0.5 * w[0].1, "{name}: {errors:?}");
        }
    }
}

/// `frequency_hz` is the undamped `ω0/2π` (the contract's); a technician
/// comparing with a spectrum reads the damped `ω_d/2π`. At ζ = 0.2 they differ
/// by 2 % (`√(1 − ζ²)` = 0.980): the answer names both, read here by name as a
/// client does, from a closed-form viscous decay.
#[test]
fn a_well_damped_decay_names_its_damped_and_undamped_frequencies() {
    let (f0, zeta, tau) = (3.0_f64, 0.2_f64, 0.02);
    let w0 = std::f64::consts::TAU * f0;
    let (n, wd) = (zeta * w0, w0 * (1.0 - zeta * zeta).sqrt());
    let samples: Vec<f64> = (0..60)
        .map(|k| {
            let t = k as f64 * tau;
            1.5 * (-n * t).exp() * (wd * t + 0.3).cos()
        })
        .collect();
    let got = serde_json::to_value(fit(&samples, tau, DampingLaw::Viscous)).unwrap();
    let num = |key: &str| {
        got[key]
            .as_f64()
            .unwrap_or_else(|| panic!("no number {key}: {got}"))
    };
    let fd = wd / std::f64::consts::TAU;
    assert!(err(num("frequency_hz"), f0) < 1e-9, "{got}");
    assert!(err(num("undamped_frequency_hz"), f0) < 1e-9, "{got}");
    assert!(err(num("damped_frequency_hz"), fd) < 1e-9, "{got}");
    assert!(err(num("damping_ratio"), zeta) < 1e-9, "{got}");
    // Measurably different: 2 % apart, far beyond the fit's 1e-9.
    assert!(err(fd, f0) > 0.015);
}

/// Turbulent damping does not shift the frequency to first order (the averaged
/// solution oscillates at ω0): both frequencies are the fitted one.
#[test]
fn a_turbulent_decay_gives_one_frequency_for_damped_and_undamped() {
    let got =
        serde_json::to_value(fit(&turbulent_decay(0.2, 21), 0.2, DampingLaw::Turbulent)).unwrap();
    let f = got["frequency_hz"].as_f64().unwrap();
    assert!(err(f, C_M.sqrt() / std::f64::consts::TAU) < 1e-3, "{got}");
    assert_eq!(got["damped_frequency_hz"].as_f64(), Some(f), "{got}");
    assert_eq!(got["undamped_frequency_hz"].as_f64(), Some(f), "{got}");
}

/// A closed-form viscous decay, `a e^{−nt} cos(ω_d t + ψ)` with `ζ` and `f0`,
/// plus Gaussian noise of `noise` (× the first amplitude), seeded.
fn noisy_viscous(f0: f64, zeta: f64, tau: f64, count: usize, noise: f64, seed: u64) -> Vec<f64> {
    let w0 = std::f64::consts::TAU * f0;
    let (n, wd) = (zeta * w0, w0 * (1.0 - zeta * zeta).sqrt());
    let mut rng = StdRng::seed_from_u64(seed);
    let gauss = Normal::new(0.0, 1.0).unwrap();
    (0..count)
        .map(|k| {
            let t = k as f64 * tau;
            (-n * t).exp() * (wd * t + 0.3).cos() + noise * gauss.sample(&mut rng)
        })
        .collect()
}

/// The recurrence (7.1) fitted by least squares has the noisy samples on
/// both sides: its coefficients shrink, and the damping comes out too high.
/// A 5 Hz decay of ζ = 0.02 sampled 20 times a period with 1 % noise
/// answered ζ 0.042 to 0.051, with 5 % noise 0.47 to 0.59 and the frequency
/// 14 % high; ζ = 0.2 with 2 % noise answered 0.47 and 6.2 Hz (review,
/// session 20). The recurrence's answer is now the start of an output-error
/// fit of the decay itself, whose error the noise does not bias, and the
/// answer gives the 95 % resolutions of the frequency and the damping ratio,
/// which cover the truth.
#[test]
fn a_noisy_viscous_decay_gives_the_damping_and_frequency_within_their_resolutions() {
    for (zeta, noise) in [(0.02, 0.01), (0.02, 0.05), (0.2, 0.02)] {
        let (mut missed, mut worst) = (0, 0.0f64);
        let seeds = 40;
        for seed in 1..=seeds {
            let y = noisy_viscous(5.0, zeta, 0.01, 200, noise, seed);
            let got = serde_json::to_value(fit(&y, 0.01, DampingLaw::Viscous)).unwrap();
            let num = |key: &str| {
                got[key]
                    .as_f64()
                    .unwrap_or_else(|| panic!("no number {key}: {got}"))
            };
            let (z, f) = (num("damping_ratio"), num("frequency_hz"));
            worst = worst.max(err(z, zeta));
            if (z - zeta).abs() > num("damping_ratio_resolution")
                || (f - 5.0).abs() > num("frequency_resolution_hz")
            {
                missed += 1;
            }
        }
        println!(
            "ζ {zeta}, noise {noise}: worst ζ error {:.1} %, {missed} of {seeds} missed",
            100.0 * worst
        );
        // Unbiased: the worst of 40 within a quarter of the truth (was 2.5 to 30 times it).
        assert!(worst < 0.25, "ζ {zeta}, noise {noise}: worst {worst}");
        // Two 95 % intervals: about 10 % miss one, 4 of 40 (sd 1.9).
        assert!(
            missed <= 9,
            "ζ {zeta}, noise {noise}: {missed} of {seeds} missed"
        );
    }
}

/// A record without damping (or with less than its noise resolves) answers
/// no damping ratio as an estimate: the fitted one lies within its 95 %
/// resolution of zero, so the answer is the most the samples allow, marked
/// `damping_ratio_bound: "upper"` with a `damping_unresolved` warning (an
/// undamped record answered ζ = −2.2e-11 ± 7e-11 as an estimate, review,
/// session 25). A damping the samples resolve is answered as before.
#[test]
fn an_undamped_decay_gives_the_damping_ratio_as_an_upper_bound() {
    // Undamped: the fitted ratio lies within its 95 % resolution of zero in
    // about 95 % of the records (2 of 40 outside expected, sd 1.4).
    let (mut records, mut bounded) = (0, 0);
    for seed in 1..=20 {
        for noise in [0.01, 0.03] {
            let y = noisy_viscous(5.0, 0.0, 0.01, 200, noise, seed);
            let got = serde_json::to_value(fit(&y, 0.01, DampingLaw::Viscous)).unwrap();
            records += 1;
            if got.get("damping_ratio_bound").is_none() {
                continue;
            }
            bounded += 1;
            let z = got["damping_ratio"].as_f64().expect("a damping ratio");
            let r = got["damping_ratio_resolution"]
                .as_f64()
                .expect("its resolution");
            assert_eq!(got["damping_ratio_bound"], "upper", "{got}");
            assert!(z >= r && z <= 2.0 * r, "the most allowed: {got}");
            let codes: Vec<&str> = got["warnings"]
                .as_array()
                .unwrap()
                .iter()
                .filter_map(|w| w["code"].as_str())
                .collect();
            assert!(codes.contains(&"damping_unresolved"), "{got}");
        }
    }
    assert!(bounded >= records - 8, "{bounded} of {records} bounded");
    // Resolved damping: answered as an estimate, as before.
    for seed in 1..=20 {
        let y = noisy_viscous(5.0, 0.02, 0.01, 200, 0.01, seed);
        let got = serde_json::to_value(fit(&y, 0.01, DampingLaw::Viscous)).unwrap();
        assert!(got.get("damping_ratio_bound").is_none(), "{got}");
        assert!(
            !got["warnings"].to_string().contains("damping_unresolved"),
            "{got}"
        );
    }
}

/// A data logger samples a 5 Hz mode at 10 kHz: 2000 samples a period, where
/// consecutive samples differ by less than 1 % noise. The recurrence (7.1)
/// on such samples fitted `e^{−2nτ} ≤ 0` and the record was refused as "no
/// decaying oscillation" (`not_oscillatory`) even with 0.1 % noise (review,
/// session 20). The recurrence now starts from the samples taken every 2nd,
/// 4th, … as well, the start that fits the whole record best is refined on
/// all samples.
#[test]
fn an_oversampled_noisy_decay_is_identified_not_refused() {
    for (noise, seed) in [(0.001, 1), (0.01, 2), (0.01, 3)] {
        let y = noisy_viscous(5.0, 0.02, 1e-4, 20_000, noise, seed);
        let got = identify(&FreeDecayRequest {
            samples: y,
            dt_s: 1e-4,
            damping: DampingLaw::Viscous,
            offset: None,
        })
        .unwrap_or_else(|e| panic!("noise {noise}: {e:?}"));
        let z = got.damping_ratio.unwrap();
        assert!(err(got.frequency_hz, 5.0) < 0.005, "noise {noise}: {got:?}");
        assert!(err(z, 0.02) < 0.1, "noise {noise}: {got:?}");
        assert!(
            (z - 0.02).abs() <= got.damping_ratio_resolution.unwrap(),
            "noise {noise}: {got:?}"
        );
    }
}

/// The turbulent model (7.2) has `k·y_k` among its regressors: noise there
/// grows with `k`. A decay of the paper's oscillator with b/m = 0.05 (δ0 =
/// 0.13), 200 samples over ten periods, was refused as "no decaying
/// oscillation of the form a0/(1 + λt) cos(ωt + ψ0)" with 1 % noise (review,
/// session 20). The model's answer, or the viscous recurrence's where it has
/// none, now starts an output-error fit of `a0/(1 + l k) cos(kθ + ψ0)`.
#[test]
fn a_noisy_turbulent_decay_is_identified_not_refused() {
    let b_m = 0.05;
    let exact = rk4_samples(|y, v| -C_M * y - b_m * v * v.abs(), 1.0, 0.0, H, 500, 200);
    let gauss = Normal::new(0.0, 1.0).unwrap();
    let mut worst = (0.0f64, 0.0f64);
    for seed in 1..=10 {
        let mut rng = StdRng::seed_from_u64(seed);
        let y: Vec<f64> = exact
            .iter()
            .map(|&v| v + 0.01 * gauss.sample(&mut rng))
            .collect();
        let got = identify(&FreeDecayRequest {
            samples: y,
            dt_s: 0.05,
            damping: DampingLaw::Turbulent,
            offset: None,
        })
        .unwrap_or_else(|e| panic!("seed {seed}: {e:?}"));
        worst = (
            worst.0.max(err(got.c_over_m, C_M)),
            worst.1.max(err(got.b_over_m, b_m)),
        );
    }
    println!(
        "worst c/m {:.3} %, b/m {:.1} %",
        100.0 * worst.0,
        100.0 * worst.1
    );
    assert!(worst.0 < 0.002 && worst.1 < 0.1, "{worst:?}");
}

/// A number of an answer, read by name as a client does.
fn number(got: &FreeDecay, key: &str) -> f64 {
    let v = serde_json::to_value(got).unwrap();
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number {key}: {v}"))
}

/// A proximity probe's record sits on its gap voltage, an accelerometer's on
/// its bias: an offset of 10 % of the amplitude moved the frequency 2.5 %
/// and ζ 30 %, and a large one was refused (review, session 20). The offset
/// is now fitted with the decay and answered (`offset`); a record and the
/// same record shifted by 0, 10 %, 100 %, 10 and 1000 times its amplitude
/// (a probe's gap voltage is hundreds of times its vibration) give the same
/// frequency and ζ, exact or with 1 % noise.
#[test]
fn an_offset_record_gives_the_frequency_and_damping_of_the_decay_and_its_offset() {
    let (f0, zeta, tau) = (5.0, 0.02, 0.01);
    for noise in [0.0, 0.01] {
        for seed in 1..=5 {
            let y = noisy_viscous(f0, zeta, tau, 200, noise, seed);
            let plain = fit(&y, tau, DampingLaw::Viscous);
            for offset in [0.0, 0.1, 1.0, 10.0, 1000.0] {
                let shifted: Vec<f64> = y.iter().map(|v| v + offset).collect();
                let got = fit(&shifted, tau, DampingLaw::Viscous);
                let (f, z) = (got.frequency_hz, got.damping_ratio.unwrap());
                let what = format!("noise {noise}, seed {seed}, offset {offset}: {got:?}");
                // The shift moves neither: the same fit of the same decay.
                assert!(err(f, plain.frequency_hz) < 1e-9, "{what}");
                assert!(err(z, plain.damping_ratio.unwrap()) < 1e-6, "{what}");
                assert!(
                    (number(&got, "offset") - number(&plain, "offset") - offset).abs() < 1e-9,
                    "{what}"
                );
                if noise == 0.0 {
                    assert!(err(f, f0) < 1e-9 && err(z, zeta) < 1e-7, "{what}");
                    assert!((number(&got, "offset") - offset).abs() < 1e-9, "{what}");
                } else {
                    assert!(err(f, f0) < 1e-3 && err(z, zeta) < 0.25, "{what}");
                    assert!((number(&got, "offset") - offset).abs() < 0.01, "{what}");
                }
            }
        }
    }
}

/// The paper's oscillator, turbulent: its 21 samples at 0.2 s exact, and a
/// decay of b/m = 0.05 over ten periods (200 samples at 0.05 s) with 1 %
/// noise, each shifted by 0, 10 %, 100 %, 10 and 1000 times the amplitude,
/// give the same c/m and b/m, and the offset they were shifted by.
#[test]
fn an_offset_turbulent_decay_gives_the_same_coefficients_and_its_offset() {
    let b_m = 0.05;
    let long = rk4_samples(|y, v| -C_M * y - b_m * v * v.abs(), 1.0, 0.0, H, 500, 200);
    let gauss = Normal::new(0.0, 1.0).unwrap();
    let mut rng = StdRng::seed_from_u64(7);
    let noisy: Vec<f64> = long
        .iter()
        .map(|&v| v + 0.01 * gauss.sample(&mut rng))
        .collect();
    for (y, step, truth, noise) in [
        (turbulent_decay(0.2, 21), 0.2, B_M, 0.0),
        (noisy, 0.05, b_m, 0.01),
    ] {
        let plain = fit(&y, step, DampingLaw::Turbulent);
        for offset in [0.0, 0.1, 1.0, 10.0, 1000.0] {
            let shifted: Vec<f64> = y.iter().map(|v| v + offset).collect();
            let got = fit(&shifted, step, DampingLaw::Turbulent);
            let what = format!("noise {noise}, offset {offset}: {got:?}");
            println!(
                "noise {noise}, offset {offset}: c/m {:.4} %, b/m {:.3} %, offset {:.2e}",
                100.0 * err(got.c_over_m, C_M),
                100.0 * err(got.b_over_m, truth),
                number(&got, "offset") - offset
            );
            assert!(err(got.c_over_m, plain.c_over_m) < 1e-9, "{what}");
            assert!(err(got.b_over_m, plain.b_over_m) < 1e-6, "{what}");
            assert!(err(got.c_over_m, C_M) < 1e-3, "{what}");
            assert!(err(got.b_over_m, truth) < 0.1, "{what}");
            let tolerance = if noise == 0.0 { 1e-3 } else { 0.01 };
            assert!(
                (number(&got, "offset") - offset).abs() < tolerance,
                "{what}"
            );
        }
    }
}

/// An offset the client knows (`offset` in the request) is taken out, not
/// fitted: the answer is the one for the samples less it, and names it.
#[test]
fn a_known_offset_is_taken_out_and_answered() {
    let exact = turbulent_decay(0.2, 21);
    let y: Vec<f64> = exact.iter().map(|&v| round_to(v, 2)).collect();
    for law in [DampingLaw::Viscous, DampingLaw::Turbulent] {
        let at_zero = fit_with(&y, 0.2, law, Some(0.0));
        let shifted: Vec<f64> = y.iter().map(|v| v + 2.5).collect();
        let got = fit_with(&shifted, 0.2, law, Some(2.5));
        assert!(
            err(got.b_over_m, at_zero.b_over_m) < 1e-9,
            "{law:?}: {got:?}"
        );
        assert!(
            err(got.c_over_m, at_zero.c_over_m) < 1e-12,
            "{law:?}: {got:?}"
        );
        assert_eq!(number(&got, "offset"), 2.5, "{law:?}");
        assert_eq!(number(&at_zero, "offset"), 0.0, "{law:?}");
        // Fitted instead, the offset is the rounding's constant, not 0.
        let fitted = fit(&y, 0.2, law);
        assert!(number(&fitted, "offset") != 0.0, "{law:?}: {fitted:?}");
    }
}

/// Gaussian noise of standard deviation 1, `count` samples, seeded.
fn pure_noise(count: usize, seed: u64) -> Vec<f64> {
    let mut rng = StdRng::seed_from_u64(seed);
    let gauss = Normal::new(0.0, 1.0).unwrap();
    (0..count).map(|_| gauss.sample(&mut rng)).collect()
}

/// A record of pure noise, no decay in it, was answered as one: a frequency,
/// a damping ratio and their resolutions (review, session 21; 260 of 300
/// records of 200 samples). The fitted decay must explain the samples better
/// than a fit of its kind explains noise (F of 10, `MIN_F`): refused as
/// `not_oscillatory` naming `samples`. A decay whose RMS is about a third of
/// the noise's is still answered.
#[test]
fn a_record_of_pure_noise_is_refused_naming_the_samples() {
    for count in [20, 200, 2000] {
        for seed in 1..=20 {
            let y = pure_noise(count, seed);
            for law in [DampingLaw::Viscous, DampingLaw::Turbulent] {
                let got = identify(&FreeDecayRequest {
                    samples: y.clone(),
                    dt_s: 0.01,
                    damping: law,
                    offset: None,
                });
                let e = got.expect_err(&format!("{count} samples, seed {seed}, {law:?}"));
                // Some fit as growing, refused so already.
                assert!(
                    e.code == "not_oscillatory" || e.code == "not_decaying",
                    "{e:?}"
                );
                assert_eq!(e.field.as_deref(), Some("samples"), "{e:?}");
                assert!(
                    e.message.starts_with("no decaying oscillation found"),
                    "{e:?}"
                );
            }
        }
    }
    // Noisy, but a decay: 200 samples, noise of 30 % of the first amplitude.
    for seed in 1..=20 {
        let y = noisy_viscous(5.0, 0.02, 0.01, 200, 0.3, seed);
        let got = fit(&y, 0.01, DampingLaw::Viscous);
        assert!(err(got.frequency_hz, 5.0) < 0.02, "seed {seed}: {got:?}");
    }
}

/// Heavily damped decays, ζ 0.3 to 0.7, of which two periods are sampled
/// (one or two cycles visible), exact and with 1 % noise, on an offset:
/// answered with their frequency and damping ratio, within the resolutions.
#[test]
fn a_heavily_damped_decay_of_one_or_two_cycles_is_identified() {
    for zeta in [0.3, 0.5, 0.7] {
        for (noise, seed) in [(0.0, 0), (0.01, 1), (0.01, 2), (0.01, 3)] {
            let y: Vec<f64> = noisy_viscous(5.0, zeta, 0.005, 80, noise, seed)
                .iter()
                .map(|v| v + 0.3)
                .collect();
            let got = fit(&y, 0.005, DampingLaw::Viscous);
            let z = got.damping_ratio.unwrap();
            let what = format!("ζ {zeta}, noise {noise}, seed {seed}: {got:?}");
            if noise == 0.0 {
                assert!(err(got.frequency_hz, 5.0) < 1e-9, "{what}");
                assert!(err(z, zeta) < 1e-9, "{what}");
            } else {
                assert!(
                    (got.frequency_hz - 5.0).abs() < got.frequency_resolution_hz.unwrap(),
                    "{what}"
                );
                assert!(
                    (z - zeta).abs() < got.damping_ratio_resolution.unwrap(),
                    "{what}"
                );
            }
            assert!((got.offset - 0.3).abs() < 0.01, "{what}");
        }
    }
}

/// Sampled at fewer than two samples a period, a decay's samples are those
/// of a slower one (its alias, `1/dt_s − f`, with the same decay a sample):
/// nothing in them tells the two apart, and the answer is the alias, as
/// docs/session-format.md says; it was given with no word of it. Near two
/// samples a period the frequency and damping are answered, and any answer
/// of fewer than three warns `few_samples_per_period`, naming the mode above
/// the Nyquist frequency that would give the same samples.
#[test]
fn a_decay_sampled_near_or_below_twice_a_period_answers_what_the_samples_show_and_warns() {
    let warned = |got: &FreeDecay| {
        let v = serde_json::to_value(got).unwrap();
        let codes: Vec<&str> = v["warnings"]
            .as_array()
            .unwrap_or_else(|| panic!("no warnings: {v}"))
            .iter()
            .map(|w| w["code"].as_str().unwrap())
            .collect();
        match codes.as_slice() {
            [] => None,
            ["few_samples_per_period"] => {
                Some(v["warnings"][0]["message"].as_str().unwrap().to_string())
            }
            _ => panic!("{codes:?}"),
        }
    };
    for (per_period, noise, seed) in [
        (2.2, 0.0, 0),
        (2.05, 0.0, 0),
        (2.2, 0.01, 1),
        (2.2, 0.01, 2),
        (5.0, 0.0, 0),
        (3.1, 0.01, 1),
    ] {
        let tau = 1.0 / (5.0 * per_period);
        let got = fit(
            &noisy_viscous(5.0, 0.02, tau, 100, noise, seed),
            tau,
            DampingLaw::Viscous,
        );
        let what = format!("{per_period} a period, noise {noise}: {got:?}");
        if noise == 0.0 {
            assert!(err(got.frequency_hz, 5.0) < 1e-9, "{what}");
            assert!(err(got.damping_ratio.unwrap(), 0.02) < 1e-9, "{what}");
        } else {
            assert!(
                (got.frequency_hz - 5.0).abs() < got.frequency_resolution_hz.unwrap(),
                "{what}"
            );
        }
        assert_eq!(warned(&got).is_some(), per_period < 3.0, "{what}");
    }
    // 1.9 samples a period (9.5 Hz): the 4.5 Hz alias, the same n = ζω0,
    // and the warning names the 5 Hz mode that gives the same samples.
    let tau = 1.0 / 9.5;
    let got = fit(
        &noisy_viscous(5.0, 0.02, tau, 100, 0.0, 0),
        tau,
        DampingLaw::Viscous,
    );
    let fd = 5.0 * (1.0f64 - 0.02 * 0.02).sqrt();
    assert!(err(got.damped_frequency_hz, 9.5 - fd) < 1e-9, "{got:?}");
    assert!(
        err(got.b_over_m, 2.0 * 0.02 * std::f64::consts::TAU * 5.0) < 1e-9,
        "{got:?}"
    );
    let message = warned(&got).expect("warned");
    assert!(
        message.contains(&format!("a mode at {fd:.4} Hz")),
        "{message}"
    );
}

/// A record whose first swings ran into the recorder's range (clipped flat at
/// 0.6 of a decay starting at 1) was answered with ζ 0.0168 ± 0.0005 for a
/// true 0.02, and no word of the clipping: flat tops make the decay look
/// slower (review, session 22: 0 of 100 such records covered the truth). It
/// now warns `clipped`, naming the rail; the same records unclipped, and
/// rounded to a coarse step (8 and 5 levels a swing: the largest value repeats
/// at several peaks, but the decay passes through them), do not warn.
#[test]
fn a_clipped_decay_warns_and_a_coarsely_rounded_one_does_not() {
    let codes =
        |got: &FreeDecay| -> Vec<String> { got.warnings.iter().map(|w| w.code.clone()).collect() };
    let tau = 1.0 / (5.0 * 20.0);
    for (seed, noise) in [(1, 0.0), (2, 0.01), (3, 0.01)] {
        let clean = noisy_viscous(5.0, 0.02, tau, 400, noise, seed);
        let clipped: Vec<f64> = clean.iter().map(|y| y.clamp(-0.6, 0.6)).collect();
        let got = fit(&clipped, tau, DampingLaw::Viscous);
        assert_eq!(codes(&got), ["clipped"], "{got:?}");
        assert!(got.warnings[0].message.contains("0.6"), "{got:?}");
        for law in [DampingLaw::Viscous, DampingLaw::Turbulent] {
            let got = fit(&clipped, tau, law);
            assert!(codes(&got).contains(&"clipped".to_string()), "{got:?}");
        }
        assert!(codes(&fit(&clean, tau, DampingLaw::Viscous)).is_empty());
        for step in [0.125, 0.2] {
            let rounded: Vec<f64> = clean.iter().map(|y| round_to(y / step, 0) * step).collect();
            let got = fit(&rounded, tau, DampingLaw::Viscous);
            assert!(codes(&got).is_empty(), "step {step}: {got:?}");
        }
    }
}

/// A record that swings at half the sampling rate (two samples a period,
/// `+a, −a, +a, …`) was refused with words about damping only ("they die
/// away too fast"), sending the technician after the wrong cause (review,
/// session 22). The refusal now names too few samples a period, and asks for
/// a shorter `dt_s`.
#[test]
fn a_record_at_half_the_sampling_rate_is_refused_naming_too_few_samples_a_period() {
    let y: Vec<f64> = (0..100)
        .map(|k| if k % 2 == 0 { 1.0 } else { -1.0 } * 0.99f64.powi(k))
        .collect();
    for law in [DampingLaw::Viscous, DampingLaw::Turbulent] {
        let e = identify(&FreeDecayRequest {
            samples: y.clone(),
            dt_s: 0.01,
            damping: law,
            offset: None,
        })
        .expect_err("two samples a period");
        assert_eq!(e.field.as_deref(), Some("samples"), "{e:?}");
        assert!(
            e.message.contains("two samples a period") && e.message.contains("dt_s"),
            "{law:?}: {e:?}"
        );
    }
}
