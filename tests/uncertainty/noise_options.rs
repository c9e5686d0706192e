//! Where the noise comes from (options or samples), what it flags
//! (`trial_effect_small`), and which noise options are refused.

use fieldbal::balancing::model::SolveOptions;
use fieldbal::balancing::{self, ErrorKind, Solution};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;

use super::{c, estimate, noisy, session, solve, Rotor, LAG_AGAINST, LEAD_WITH};

/// `n` samples around each exact reading, with the options' noise model at `pct` %/`deg`°,
/// recentred so that their mean is the reading.
fn with_samples(
    y: &[Vec<Complex64>],
    n: usize,
    pct: f64,
    deg: f64,
    seed: u64,
) -> Vec<Vec<Vec<Complex64>>> {
    let mut rng = StdRng::seed_from_u64(seed);
    y.iter()
        .map(|run| {
            run.iter()
                .map(|&z| {
                    let s: Vec<Complex64> = (0..n).map(|_| noisy(z, pct, deg, &mut rng)).collect();
                    let shift = z - s.iter().sum::<Complex64>() / n as f64;
                    s.into_iter().map(|x| x + shift).collect()
                })
                .collect()
        })
        .collect()
}

fn options(pct: f64, deg: f64) -> SolveOptions {
    SolveOptions {
        amplitude_noise_pct: Some(pct),
        phase_noise_deg: Some(deg),
        ..SolveOptions::default()
    }
}

#[test]
fn the_scatter_of_samples_is_used_instead_of_the_options() {
    let rotor = Rotor::two_plane(0.8);
    let y = rotor.readings();
    // 30 samples per reading scattering 10 % / 10°, far above the options' noise.
    let samples = with_samples(&y, 30, 10.0, 10.0, 7);
    let s = session(LAG_AGAINST, &rotor.trial, &y, Some(&samples));
    let var = |sol: &Solution| estimate(sol, 0).1.trace();
    let quiet_options = solve(&s, &options(0.5, 0.5));
    let loud_options = solve(&s, &options(5.0, 5.0));
    let no_samples = solve(
        &session(LAG_AGAINST, &rotor.trial, &y, None),
        &options(0.5, 0.5),
    );
    // The options change the answer only through the 2-sample prior (2 of 31 parts).
    assert!(
        (var(&loud_options) / var(&quiet_options) - 1.0).abs() < 0.2,
        "{} vs {}",
        var(&loud_options),
        var(&quiet_options)
    );
    // The samples' mean has (10 %)²/30 of variance per reading against the options' (0.5 %)²:
    // the region is wider by about (10/0.5)²/30 ≈ 13 in variance.
    let ratio = var(&quiet_options) / var(&no_samples);
    assert!((8.0..20.0).contains(&ratio), "{ratio}");
    // Twice the scatter, four times the variance.
    let doubled: Vec<Vec<Vec<Complex64>>> = samples
        .iter()
        .zip(&y)
        .map(|(run, yr)| {
            run.iter()
                .zip(yr)
                .map(|(s, &z)| s.iter().map(|&x| z + 2.0 * (x - z)).collect())
                .collect()
        })
        .collect();
    let louder = solve(
        &session(LAG_AGAINST, &rotor.trial, &y, Some(&doubled)),
        &options(0.5, 0.5),
    );
    // First order exactly 4; the second-order term (1 + κ) grows with the
    // noise too (κ four times larger), which adds a little.
    let ratio = var(&louder) / var(&quiet_options);
    assert!((3.6..4.6).contains(&ratio), "{ratio}");
}

/// Warnings of one code and plane.
fn warnings<'s>(s: &'s Solution, code: &str, plane: &str) -> Vec<&'s str> {
    s.warnings
        .iter()
        .filter(|w| w.code == code && w.plane.as_deref() == Some(plane))
        .map(|w| w.message.as_str())
        .collect()
}

#[test]
fn a_trial_effect_within_three_times_its_noise_is_flagged_even_above_thirty_percent() {
    let rotor = Rotor::two_plane(0.35);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let quiet = solve(&s, &SolveOptions::default());
    assert!(
        quiet
            .warnings
            .iter()
            .all(|w| w.code != "trial_effect_small"),
        "{:?}",
        quiet.warnings
    );
    assert!(
        quiet
            .planes
            .iter()
            .all(|p| p.trial_effect_snr.unwrap() > 3.0),
        "{:?}",
        quiet.planes
    );
    // A noisy instrument: 15 % and 15° make a 35 % change indistinguishable from noise.
    let noisy = solve(&s, &options(15.0, 15.0));
    for p in &noisy.planes {
        let snr = p.trial_effect_snr.unwrap();
        assert!(snr < 3.0, "{} {snr}", p.plane);
        let w = warnings(&noisy, "trial_effect_small", &p.plane);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].contains("measurement noise"), "{}", w[0]);
    }
}

#[test]
fn a_trial_too_small_by_both_tests_gets_one_warning_that_says_both() {
    let rotor = Rotor::two_plane(0.05);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let sol = solve(&s, &SolveOptions::default());
    let w = warnings(&sol, "trial_effect_small", "P0");
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("30 %") && w[0].contains("measurement noise"),
        "{}",
        w[0]
    );
}

#[test]
fn a_zero_covariance_is_written_without_minus_signs_in_either_angle_direction() {
    // Against rotation the off-diagonal is negated for the wire: a zero one
    // came out as `-0.0`, which the contract's numbers never are.
    let rotor = Rotor::two_plane(1.0);
    for conv in [LAG_AGAINST, LEAD_WITH] {
        let sol = solve(
            &session(conv, &rotor.trial, &rotor.readings(), None),
            &options(0.0, 0.0),
        );
        for corr in &sol.corrections {
            let u = corr.uncertainty.as_ref().unwrap();
            for x in u.covariance_g2.iter().flatten() {
                assert!(x.is_sign_positive(), "{conv:?} {}: {u:?}", corr.plane);
            }
        }
        let json = serde_json::to_string(&sol).unwrap();
        for end in [",", "]", "}"] {
            assert!(!json.contains(&format!("-0.0{end}")), "{conv:?}: {json}");
        }
    }
}

#[test]
fn without_noise_the_regions_shrink_to_the_correction() {
    let rotor = Rotor::two_plane(1.0);
    let sol = solve(
        &session(LEAD_WITH, &rotor.trial, &rotor.readings(), None),
        &options(0.0, 0.0),
    );
    for corr in &sol.corrections {
        let u = corr.uncertainty.as_ref().unwrap();
        assert_eq!(u.covariance_g2, [[0.0; 2]; 2]);
        assert!(
            (u.mass_g.unwrap()[0] - corr.mass_g).abs() < 1e-9
                && (u.mass_g.unwrap()[1] - corr.mass_g).abs() < 1e-9
        );
    }
    for r in &sol.predicted_residual {
        assert!((r.amplitude_95.unwrap() - r.amplitude).abs() < 1e-9);
    }
    assert!(sol.planes.iter().all(|p| p.trial_effect_snr.is_none()));
}

#[test]
fn invalid_noise_options_are_rejected_naming_the_option() {
    let rotor = Rotor::two_plane(1.0);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let cases: [(&str, Option<f64>, Option<f64>, &str); 7] = [
        (
            "negative amplitude noise",
            Some(-1.0),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "NaN amplitude noise",
            Some(f64::NAN),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "infinite amplitude noise",
            Some(f64::INFINITY),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "amplitude noise above 100 %",
            Some(150.0),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "negative phase noise",
            None,
            Some(-0.5),
            "options.phase_noise_deg",
        ),
        (
            "phase noise above 90°",
            None,
            Some(360.0),
            "options.phase_noise_deg",
        ),
        (
            "NaN phase noise",
            None,
            Some(f64::NAN),
            "options.phase_noise_deg",
        ),
    ];
    for (what, pct, deg, field) in cases {
        let o = SolveOptions {
            amplitude_noise_pct: pct,
            phase_noise_deg: deg,
            ..SolveOptions::default()
        };
        let err = balancing::solve(&s, &o).expect_err(what);
        assert_eq!(err.kind, ErrorKind::Invalid, "{what}");
        assert_eq!(err.field.as_deref(), Some(field), "{what}");
    }
}

#[test]
fn min_max_and_binding_mass_bounds_say_their_intervals_are_approximate() {
    let rotor = Rotor::two_plane(1.0);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let o = SolveOptions {
        objective: Some(fieldbal::balancing::model::Objective::MinMax),
        ..SolveOptions::default()
    };
    let sol = solve(&s, &o);
    assert!(
        sol.warnings
            .iter()
            .any(|w| w.code == "uncertainty_approximate"),
        "{:?}",
        sol.warnings
    );
    assert!(sol.corrections.iter().all(|c| c.uncertainty.is_some()));
    let ls = solve(&s, &SolveOptions::default());
    assert!(ls
        .warnings
        .iter()
        .all(|w| w.code != "uncertainty_approximate"));
}

#[test]
fn a_trial_too_small_for_its_noise_says_how_much_to_enlarge_it_and_that_much_is_enough() {
    let mut rotor = Rotor::two_plane(0.05);
    let noise = options(2.0, 2.0);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let small = solve(&s, &noise);
    let factor = |text: &str| -> f64 {
        let (before, _) = text
            .split_once(" times the trial mass")
            .unwrap_or_else(|| panic!("no enlargement in: {text}"));
        before.rsplit(' ').next().unwrap().parse().unwrap()
    };
    let mut told = Vec::new();
    for (j, t) in rotor.trial.iter_mut().enumerate() {
        let w = warnings(&small, "trial_effect_small", &format!("P{j}"));
        let said = w
            .iter()
            .find(|m| m.contains(" times the trial mass"))
            .unwrap_or_else(|| panic!("P{j}: {:?}", small.warnings));
        let f = factor(said);
        assert!(f > 1.0, "{said}");
        told.push(f);
        // The stated factor, with a margin for its one-decimal rounding.
        *t *= f * 1.1;
    }
    let enlarged = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let sol = solve(&enlarged, &noise);
    for j in 0..rotor.trial.len() {
        let w = warnings(&sol, "trial_effect_small", &format!("P{j}"));
        assert!(
            w.iter().all(|m| !m.contains("times the trial mass")),
            "told {told:?}, still: {w:?}"
        );
    }
}

#[test]
fn a_plane_too_like_the_others_is_told_to_be_told_apart_not_only_to_take_a_heavier_trial() {
    // Three planes; P2 acts almost as P0 + P1 (significance well under 0.2),
    // each trial moving the vibration by as much as it is: the trials are not
    // small, the part of P2's effect that is its own is.
    let cols = [
        [c(1.2, 0.8), c(0.3, -0.4), c(-0.5, 1.1), c(0.9, 0.2)],
        [c(2.0, -0.6), c(0.7, 0.9), c(0.4, 0.5), c(-1.3, 0.6)],
    ];
    let w = nalgebra::DMatrix::from_fn(4, 3, |a, j| match j {
        2 => (cols[0][a] + cols[1][a]) * 0.5 + c(0.004, -0.003) * (a as f64 - 1.5),
        _ => cols[j][a],
    });
    let c_true = nalgebra::DVector::from_vec(vec![c(30.0, 10.0), c(-12.0, 20.0), c(5.0, -25.0)]);
    let rotor = Rotor::with_trials(w.clone(), c_true.clone(), -(&w * &c_true), 1.0);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let sol = solve(&s, &options(2.0, 2.0));
    assert!(
        sol.warnings.iter().any(|w| w.code == "ill_conditioned"),
        "{:?}",
        sol.warnings
    );
    let said = warnings(&sol, "trial_effect_small", "P2");
    assert!(
        said.iter().any(
            |m| m.contains("given how alike the planes look to the sensors")
                && m.contains("tells plane P2 from the others")
                && m.contains("the sensors see it much like the other planes together")
                && m.contains(" times the trial mass")
        ),
        "{said:?}"
    );
    // A plane the others do not mimic is told only to take a heavier trial.
    let small = Rotor::two_plane(0.05);
    let s = session(LAG_AGAINST, &small.trial, &small.readings(), None);
    let sol = solve(&s, &options(2.0, 2.0));
    let said = warnings(&sol, "trial_effect_small", "P0");
    assert!(
        said.iter().any(|m| m.contains(" times the trial mass")),
        "{said:?}"
    );
    assert!(said.iter().all(|m| !m.contains("tells plane")), "{said:?}");
}
