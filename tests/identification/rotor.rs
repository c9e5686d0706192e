//! `identify/rotor` on sessions generated from Jeffcott rotors of known
//! stiffness, damping and mass: exact without noise, within 0.5 % (critical
//! speed) and 5 % (damping ratio) with 2 % reading noise over several seeds;
//! velocity and acceleration sensors; API 684's margins; two modes in range.

use crate::support;

use fieldbal::balancing::model::Unit;
use fieldbal::identification::api684;
use fieldbal::identification::rotor::{
    identify, CrossCoupling, RotorOptions, RotorRequest, RotorResult, UnbalanceAngle,
};
use support::{session, session_with_weights, speeds, Jeffcott};

fn one(req: &RotorRequest) -> RotorResult {
    let out = identify(req).unwrap();
    assert_eq!(out.results.len(), 1, "{out:?}");
    out.results[0].clone()
}

fn rel(got: f64, want: f64) -> f64 {
    (got - want).abs() / want.abs()
}

#[test]
fn a_noise_free_jeffcott_rotor_is_identified_exactly_for_every_sensor_unit() {
    let rotor = Jeffcott {
        sensor_turn: 0.6,
        ..Jeffcott::with(120.0, 2400.0, 0.04)
    };
    for unit in [
        Unit::UmPp,
        Unit::MilsPp,
        Unit::MmSRms,
        Unit::MmSPk,
        Unit::InSPk,
        Unit::GPk,
    ] {
        let s = session(&[rotor], &speeds(1200.0, 3600.0, 9), unit, 0.0, 0);
        let r = one(&RotorRequest {
            session: s,
            options: RotorOptions::default(),
        });
        assert!(
            rel(r.critical_speed_rpm, rotor.critical_rpm()) < 1e-7,
            "{unit:?}: {r:?}"
        );
        assert!(rel(r.damping_ratio, rotor.zeta()) < 1e-6, "{unit:?}: {r:?}");
        assert!(
            rel(r.mass_kg.unwrap(), rotor.mass_kg) < 1e-6,
            "{unit:?}: {r:?}"
        );
        assert!(
            rel(r.stiffness_n_per_m.unwrap(), rotor.stiffness) < 1e-6,
            "{unit:?}: {r:?}"
        );
        assert!(r.fit_rms_relative < 1e-8, "{unit:?}: {r:?}");
    }
}

#[test]
fn the_literal_model_with_the_forcing_at_the_weight_is_exact_for_a_sensor_at_the_mark() {
    let rotor = Jeffcott::with(80.0, 3000.0, 0.06);
    let s = session(&[rotor], &speeds(1800.0, 4200.0, 7), Unit::UmPp, 0.0, 0);
    for mass_kg in [None, Some(80.0)] {
        let options = RotorOptions {
            unbalance_angle: Some(UnbalanceAngle::AtWeight),
            mass_kg,
            ..Default::default()
        };
        let r = one(&RotorRequest {
            session: s.clone(),
            options,
        });
        assert!(rel(r.critical_speed_rpm, 3000.0) < 1e-7, "{r:?}");
        assert!(rel(r.damping_ratio, 0.06) < 1e-6, "{r:?}");
    }
}

#[test]
fn two_percent_reading_noise_keeps_critical_speed_within_half_a_percent_and_damping_within_five() {
    let rotor = Jeffcott {
        sensor_turn: -0.4,
        ..Jeffcott::with(150.0, 2400.0, 0.05)
    };
    let mut worst = (0.0f64, 0.0f64);
    for seed in 1..=8 {
        let s = session(
            &[rotor],
            &speeds(1200.0, 3600.0, 25),
            Unit::UmPp,
            0.02,
            seed,
        );
        let r = one(&RotorRequest {
            session: s,
            options: RotorOptions::default(),
        });
        let (ec, ez) = (
            rel(r.critical_speed_rpm, rotor.critical_rpm()),
            rel(r.damping_ratio, rotor.zeta()),
        );
        println!(
            "seed {seed}: critical {:.2} rpm ({:.3} %), zeta {:.5} ({:.2} %)",
            r.critical_speed_rpm,
            100.0 * ec,
            r.damping_ratio,
            100.0 * ez
        );
        worst = (worst.0.max(ec), worst.1.max(ez));
        assert!(r.fit_rms_relative < 0.1, "seed {seed}: {r:?}");
    }
    assert!(
        worst.0 < 0.005,
        "critical speed off by {:.3} %",
        100.0 * worst.0
    );
    assert!(
        worst.1 < 0.05,
        "damping ratio off by {:.2} %",
        100.0 * worst.1
    );
}

#[test]
fn the_amplification_factor_and_margins_follow_api_684_on_the_fitted_curve() {
    // ζ = 0.05: AF ≈ 1/(2ζ) = 10 > 2.5, so a margin is required; the critical (2400) is below service (3000).
    let rotor = Jeffcott::with(150.0, 2400.0, 0.05);
    let s = session(&[rotor], &speeds(1200.0, 3600.0, 13), Unit::UmPp, 0.0, 0);
    let r = one(&RotorRequest {
        session: s,
        options: RotorOptions::default(),
    });
    assert_eq!(r.amplification_method, "half_power_bandwidth");
    assert!((r.amplification_factor - 10.0).abs() < 0.3, "{r:?}");
    assert!(rel(r.separation_margin_pct.unwrap(), 20.0) < 1e-6, "{r:?}");
    let want = (17.0 * (1.0 - 1.0 / (r.amplification_factor - 1.5))).min(16.0);
    assert!(
        (r.required_margin_pct.unwrap() - want).abs() < 1e-9,
        "{r:?}"
    );
    // A heavily damped rotor needs no margin.
    let damped = Jeffcott::with(150.0, 2400.0, 0.3);
    let s = session(&[damped], &speeds(1200.0, 3600.0, 13), Unit::UmPp, 0.0, 0);
    let r = one(&RotorRequest {
        session: s,
        options: RotorOptions::default(),
    });
    assert!(r.amplification_factor < api684::AF_NO_MARGIN, "{r:?}");
    assert_eq!(r.required_margin_pct, Some(0.0));
}

#[test]
fn two_modes_in_range_give_a_poor_fit_warning_and_a_speed_range_fits_each() {
    let first = Jeffcott::with(150.0, 1500.0, 0.04);
    let second = Jeffcott::with(60.0, 4000.0, 0.04);
    let s = session(
        &[first, second],
        &speeds(900.0, 5000.0, 42),
        Unit::UmPp,
        0.0,
        0,
    );
    let all = identify(&RotorRequest {
        session: s.clone(),
        options: RotorOptions::default(),
    })
    .unwrap();
    println!("both modes: {all:?}");
    let poor = all.warnings.iter().find(|w| w.code == "poor_fit");
    let poor = poor.unwrap_or_else(|| panic!("{all:?}"));
    // Both causes and what to do about each (it named modes only, while
    // noisy coefficients fire it as often: session 23's measurements).
    assert!(
        poor.message.contains("speed_range_rpm") && poor.message.contains("heavier trial"),
        "{}",
        poor.message
    );
    for (range, rotor) in [([1200.0, 1800.0], first), ([3500.0, 4500.0], second)] {
        let options = RotorOptions {
            speed_range_rpm: Some(range.to_vec()),
            ..Default::default()
        };
        let out = identify(&RotorRequest {
            session: s.clone(),
            options,
        })
        .unwrap();
        println!("{range:?}: {out:?}");
        let r = &out.results[0];
        // The other mode's tail remains: within a few per cent, not exact.
        assert!(
            rel(r.critical_speed_rpm, rotor.critical_rpm()) < 0.02,
            "{range:?}: {r:?}"
        );
        assert!(
            !out.warnings.iter().any(|w| w.code == "poor_fit"),
            "{range:?}: {out:?}"
        );
    }
}

/// The answer as JSON: these tests read the fields the contract added for an
/// unresolved damping by name, as a client does.
fn answer(req: &RotorRequest) -> serde_json::Value {
    serde_json::to_value(identify(req).unwrap()).unwrap()
}

/// The service's answer for `rotor` read at `n` speeds from `lo` to `hi` rpm
/// with relative reading noise `noise` (seeded).
fn noisy(
    rotor: Jeffcott,
    (lo, hi, n): (f64, f64, usize),
    noise: f64,
    seed: u64,
    options: RotorOptions,
) -> serde_json::Value {
    answer(&RotorRequest {
        session: session(&[rotor], &speeds(lo, hi, n), Unit::UmPp, noise, seed),
        options,
    })
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no number {key}: {v}"))
}

/// Undamped, noise-free readings fitted ζ ≈ 1e-18 and answered an
/// amplification factor of 2.4e13 as if measured (session 19). The damping is
/// now reported as what it is: within its resolution of zero, the ratio an
/// upper bound, the factor a lower bound, API 684's largest margin, a warning
/// naming the mode; the critical speed is as exact as before.
#[test]
fn undamped_readings_give_a_damping_bound_and_a_warning_not_a_number() {
    // 2450 rpm: no speed of the grid falls on the critical (an infinite response).
    let rotor = Jeffcott::with(150.0, 2450.0, 0.0);
    for options in [
        RotorOptions::default(),
        RotorOptions {
            unbalance_angle: Some(UnbalanceAngle::AtWeight),
            ..Default::default()
        },
    ] {
        let s = session(&[rotor], &speeds(1200.0, 3600.0, 9), Unit::UmPp, 0.0, 0);
        let out = answer(&RotorRequest {
            session: s,
            options: options.clone(),
        });
        let results = out["results"].as_array().unwrap();
        assert_eq!(results.len(), 1, "{options:?}: {out}");
        let r = &results[0];
        assert!(rel(num(r, "critical_speed_rpm"), 2450.0) < 1e-7, "{out}");
        assert_eq!(r["damping_ratio_bound"], "upper", "{out}");
        assert_eq!(r["amplification_factor_bound"], "lower", "{out}");
        let (zeta, resolution) = (num(r, "damping_ratio"), num(r, "damping_ratio_resolution"));
        // The bound is the resolution (the fit is at zero), and far above rounding.
        assert!(zeta > 0.0 && zeta <= 1.0001 * resolution, "{out}");
        assert!(resolution > 1e-12 && resolution < 1e-4, "{out}");
        assert!(
            rel(num(r, "amplification_factor"), 1.0 / (2.0 * zeta)) < 1e-12,
            "{out}"
        );
        assert_eq!(r["amplification_method"], "one_over_two_zeta", "{out}");
        assert!(r.get("peak_speed_rpm").is_none(), "{out}");
        // The critical (2450) is below service (3000): API 684's most is 16 %.
        assert_eq!(num(r, "required_margin_pct"), 16.0, "{out}");
        let warned: Vec<_> = out["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|w| w["code"] == "damping_unresolved")
            .collect();
        assert_eq!(warned.len(), 1, "{out}");
        assert_eq!(warned[0]["plane"], "A", "{out}");
        let message = warned[0]["message"].as_str().unwrap();
        assert!(
            message.contains("sensor '1H', plane 'A'") && message.contains("2450 rpm"),
            "{message}"
        );
    }
}

/// With 2 % noise the fitted damping of an undamped rotor scatters about zero
/// either side: a negative one answered `no_mode` and no result, a positive
/// one an amplification factor in the thousands. Every seed now gives the
/// mode, its critical within 0.5 %, and the damping as unresolved.
#[test]
fn noisy_undamped_readings_give_the_mode_with_its_damping_unresolved() {
    let rotor = Jeffcott {
        sensor_turn: -0.4,
        ..Jeffcott::with(150.0, 2450.0, 0.0)
    };
    for seed in 1..=8 {
        let out = noisy(
            rotor,
            (1200.0, 3600.0, 25),
            0.02,
            seed,
            RotorOptions::default(),
        );
        let r = &out["results"][0];
        assert!(r.is_object(), "seed {seed}: {out}");
        assert!(
            rel(num(r, "critical_speed_rpm"), 2450.0) < 0.005,
            "seed {seed}: {out}"
        );
        assert_eq!(r["damping_ratio_bound"], "upper", "seed {seed}: {out}");
        assert!(
            out["warnings"]
                .as_array()
                .unwrap()
                .iter()
                .any(|w| w["code"] == "damping_unresolved"),
            "seed {seed}: {out}"
        );
    }
}

/// The resolution is honest the other way too: a real damping of 1 % read
/// with 2 % noise is resolved (no bound, no warning) and lies within the
/// resolution of the fitted one, for every seed and with the forcing fitted
/// or taken at the weight; noise-free, 0.2 % is resolved as well.
#[test]
fn a_real_damping_is_resolved_and_within_its_resolution_of_the_truth() {
    let check = |zeta_true: f64, noise: f64, seed: u64, options: &RotorOptions| {
        let rotor = Jeffcott::with(150.0, 2450.0, zeta_true);
        let out = noisy(rotor, (1200.0, 3600.0, 25), noise, seed, options.clone());
        let r = &out["results"][0];
        assert!(r.get("damping_ratio_bound").is_none(), "{out}");
        // No warning but, with the cross-coupling estimated, that the damping
        // does not split into b and q (see the split's test below).
        assert!(
            out.get("warnings").is_none_or(|w| w
                .as_array()
                .unwrap()
                .iter()
                .all(|w| w["code"] == "damping_split_unresolved")),
            "{out}"
        );
        let (zeta, resolution) = (num(r, "damping_ratio"), num(r, "damping_ratio_resolution"));
        assert!(
            (zeta - zeta_true).abs() < resolution && resolution < zeta_true / 5.0,
            "seed {seed}: {out}"
        );
    };
    for options in [
        RotorOptions::default(),
        RotorOptions {
            unbalance_angle: Some(UnbalanceAngle::AtWeight),
            ..Default::default()
        },
    ] {
        for seed in 1..=8 {
            check(0.01, 0.02, seed, &options);
        }
        check(0.002, 0.0, 0, &options);
    }
}

/// `b_over_m`, `q_over_m`, `damping_n_s_per_m` and `cross_coupling_n_per_m`
/// were the raw fit even when the damping ratio was reported as unresolved:
/// undamped readings fitted a damping coefficient a little below zero for
/// some seeds, a negative damping given as a number beside the bound that
/// says the readings cannot tell it from zero. Now, when the damping is
/// unresolved, none of them is given as a number (the damping ratio's bound
/// is all the readings tell), and no answer ever carries a negative damping
/// coefficient as a measured one.
#[test]
fn an_unresolved_damping_gives_no_damping_coefficient_and_never_a_negative_one() {
    let rotor = Jeffcott {
        sensor_turn: -0.4,
        ..Jeffcott::with(150.0, 2450.0, 0.0)
    };
    for (noise, seeds) in [(0.0, 0..=0), (0.02, 1..=8)] {
        for seed in seeds {
            for options in [
                RotorOptions::default(),
                RotorOptions {
                    cross_coupling: Some(fieldbal::identification::rotor::CrossCoupling::Zero),
                    ..Default::default()
                },
                RotorOptions {
                    unbalance_angle: Some(UnbalanceAngle::AtWeight),
                    ..Default::default()
                },
            ] {
                let out = noisy(rotor, (1200.0, 3600.0, 25), noise, seed, options.clone());
                let r = &out["results"][0];
                assert_eq!(r["damping_ratio_bound"], "upper", "seed {seed}: {out}");
                // The old answer: 14 negative coefficients over these 27 fits.
                for key in ["b_over_m", "damping_n_s_per_m"] {
                    assert!(
                        !r[key].as_f64().is_some_and(|x| x < 0.0),
                        "seed {seed}, {options:?}: a negative {key}: {out}"
                    );
                }
                for key in [
                    "b_over_m",
                    "q_over_m",
                    "damping_n_s_per_m",
                    "cross_coupling_n_per_m",
                ] {
                    assert!(
                        r.get(key).is_none(),
                        "seed {seed}, {options:?}: {key}: {out}"
                    );
                }
                // What is known stays: the critical speed, the stiffness (the
                // mass, hence the stiffness, is estimated from the forcing's
                // size: within 15 % at this noise).
                assert!(rel(num(r, "critical_speed_rpm"), 2450.0) < 0.005, "{out}");
                assert!(
                    rel(num(r, "stiffness_n_per_m"), rotor.stiffness) < 0.15,
                    "{out}"
                );
                assert!(num(r, "c_over_m") > 0.0, "{out}");
            }
        }
    }
}

/// Whether the answer's damping covers the truth: a resolved ratio within its
/// resolution of it, an unresolved one (an upper bound) at or above it.
fn covers(r: &serde_json::Value, zeta_true: f64) -> bool {
    let zeta = num(r, "damping_ratio");
    if r.get("damping_ratio_bound").is_some() {
        zeta >= zeta_true
    } else {
        (zeta - zeta_true).abs() <= num(r, "damping_ratio_resolution")
    }
}

/// The resolution is "about 95 %": with few speeds the noise it is built on is
/// itself estimated from a residual of few degrees of freedom (three speeds,
/// six equations, five unknowns: one), and twice the standard deviation
/// missed the true damping in 18 % of 200 noisy records, once by 7.7 times
/// the resolution (review, session 20). Student's quantile for those degrees
/// of freedom keeps the misses near 5 % at three speeds as at many.
#[test]
fn the_damping_resolution_covers_the_truth_about_95_percent_of_the_time_even_at_three_speeds() {
    let rotor = Jeffcott {
        sensor_turn: -0.4,
        ..Jeffcott::with(150.0, 2450.0, 0.05)
    };
    for grid in [vec![2000.0, 2400.0, 2800.0], speeds(1200.0, 3600.0, 25)] {
        let seeds = 200;
        let missed = (1..=seeds)
            .filter(|&seed| {
                let s = session(&[rotor], &grid, Unit::UmPp, 0.02, seed);
                let out = answer(&RotorRequest {
                    session: s,
                    options: RotorOptions::default(),
                });
                !covers(&out["results"][0], rotor.zeta())
            })
            .count();
        println!("{} speeds: {missed} of {seeds} missed", grid.len());
        // 95 % of 200: 10 expected, binomial standard deviation 3.
        assert!(
            missed <= 18,
            "{} speeds: {missed} of {seeds} missed",
            grid.len()
        );
    }
}

/// Synchronous readings fix `ωb − q` near the critical, which splits into
/// direct damping `b` and cross-coupling `q` only through the few per cent
/// the speed changes across the resonance. With both estimated (the default)
/// and 2 % noise, 20 records of one rotor (true b/m = 25.7 1/s, q = 0)
/// answered damping coefficients from 167 to 8207 N·s/m (true 3848) and
/// cross-coupling from −9.4e5 to 1.1e6 N/m as plain numbers, while the
/// damping ratio agreed within 4 % (review, session 20). Each is now given
/// with its 95 % resolution, and only where b/m clears twice it (session
/// 23: at this noise 1 record of 40; how often the given ones hold is
/// measured in tests/identification/split.rs); otherwise the split is not
/// resolved: neither is given (a warning says so), never a negative
/// damping coefficient as a number.
#[test]
fn the_split_of_damping_and_cross_coupling_is_given_with_its_resolution_or_not_at_all() {
    let rotor = Jeffcott {
        sensor_turn: -0.4,
        ..Jeffcott::with(150.0, 2450.0, 0.05)
    };
    let b_over_m = rotor.damping / rotor.mass_kg;
    let (mut given, mut missed, mut withheld) = (0, 0, 0);
    for seed in 1..=40 {
        let out = noisy(
            rotor,
            (1200.0, 3600.0, 25),
            0.02,
            seed,
            RotorOptions::default(),
        );
        let r = &out["results"][0];
        assert!(r.get("damping_ratio_bound").is_none(), "seed {seed}: {out}");
        match r.get("b_over_m") {
            Some(b) => {
                given += 1;
                let b = b.as_f64().unwrap();
                let (rb, rq) = (num(r, "b_over_m_resolution"), num(r, "q_over_m_resolution"));
                assert!(
                    b > 2.0 * rb,
                    "seed {seed}: b/m within twice its resolution of zero: {out}"
                );
                assert!(num(r, "damping_n_s_per_m") > 0.0, "seed {seed}: {out}");
                if (b - b_over_m).abs() > rb || num(r, "q_over_m").abs() > rq {
                    missed += 1;
                }
            }
            None => {
                withheld += 1;
                for key in ["q_over_m", "damping_n_s_per_m", "cross_coupling_n_per_m"] {
                    assert!(r.get(key).is_none(), "seed {seed}: {key}: {out}");
                }
                assert!(
                    out["warnings"]
                        .as_array()
                        .is_some_and(|w| w.iter().any(|w| w["code"] == "damping_split_unresolved")),
                    "seed {seed}: {out}"
                );
            }
        }
    }
    println!("given {given}, missed {missed}, withheld {withheld}");
    assert!(missed <= 4, "{missed} of {given} given missed the truth");
    // With the cross-coupling taken as zero, the damping coefficient is as
    // well resolved as the damping ratio: given every time, and right.
    for seed in 1..=8 {
        let out = noisy(
            rotor,
            (1200.0, 3600.0, 25),
            0.02,
            seed,
            RotorOptions {
                cross_coupling: Some(fieldbal::identification::rotor::CrossCoupling::Zero),
                ..Default::default()
            },
        );
        let r = &out["results"][0];
        let (b, rb) = (num(r, "b_over_m"), num(r, "b_over_m_resolution"));
        assert!(
            (b - b_over_m).abs() <= rb && rb < 0.1 * b_over_m,
            "seed {seed}: {out}"
        );
    }
}

/// The critical speed was a bare number: with 2 % noise a heavily damped
/// rotor's (ζ = 0.7 to 1.5) came out up to 22 % off, and a sweep on one side
/// of a lightly damped critical up to 1.2 % off, with nothing to say how
/// well the readings fix it (review, session 20). Each result now gives
/// `critical_speed_resolution_rpm`, the 95 % half-width, which covers the
/// truth about 95 % of the time on such sweeps.
#[test]
fn the_critical_speed_comes_with_a_resolution_that_covers_the_truth() {
    let cases = [
        (0.7, speeds(600.0, 6000.0, 25)),
        (1.5, speeds(600.0, 6000.0, 25)),
        (0.02, speeds(800.0, 2000.0, 8)),
        (0.02, speeds(3000.0, 5000.0, 8)),
        (0.05, vec![2000.0, 2400.0, 2800.0]),
    ];
    for (zeta, grid) in cases {
        let rotor = Jeffcott {
            sensor_turn: 0.5,
            ..Jeffcott::with(150.0, 2450.0, zeta)
        };
        let seeds = 100;
        let mut worst = 0.0f64;
        let (mut square_sum, mut widths) = (0.0, Vec::new());
        let missed = (1..=seeds)
            .filter(|&seed| {
                let s = session(&[rotor], &grid, Unit::UmPp, 0.02, seed);
                let out = answer(&RotorRequest {
                    session: s,
                    options: RotorOptions::default(),
                });
                let r = &out["results"][0];
                let (n, res) = (
                    num(r, "critical_speed_rpm"),
                    num(r, "critical_speed_resolution_rpm"),
                );
                worst = worst.max((n - 2450.0).abs() / 2450.0);
                square_sum += (n - 2450.0).powi(2);
                widths.push(res);
                (n - 2450.0).abs() > res
            })
            .count();
        println!(
            "ζ {zeta}, {} speeds: worst {:.2} %, {missed} of {seeds} missed",
            grid.len(),
            100.0 * worst
        );
        // 95 % of 100: 5 expected, binomial standard deviation 2.2.
        assert!(
            missed <= 11,
            "ζ {zeta}, {} speeds: {missed} of {seeds} missed",
            grid.len()
        );
        // And not by being wide: the median within twice the errors' 95 %
        // spread (at three speeds, one degree of freedom, Student's quantile
        // is 12.7 and the width itself scatters: there it must be wide).
        widths.sort_by(f64::total_cmp);
        let spread = 1.96 * (square_sum / seeds as f64).sqrt();
        assert!(
            grid.len() < 8 || widths[widths.len() / 2] < 2.0 * spread,
            "ζ {zeta}: {widths:?} vs {spread}"
        );
    }
}

/// (6.1) multiplies the unknowns by the measured coefficients themselves, so
/// its least squares are biased by the noise's square (errors in the
/// variables), a bias that does not shrink with the number of speeds while
/// the scatter does: with coefficients scattering ~20 % about the curve (5 %
/// and 5° readings, a trial weight of 30 % of the vibration) at 25 speeds the
/// damping ratio came out 0.040 for 0.05, and its 95 % half-width held the
/// truth in 71 % of 600 records (session 23,
/// scripts/ident_rotor_coverage.py). The fit now takes its first-order bias
/// out. Here 10 % reading noise, a trial of 6 g beside 20 g of unbalance
/// (the coefficients scatter ~20 %), 25 speeds across the critical.
#[test]
fn the_damping_resolution_covers_the_truth_on_noisy_coefficients_at_many_speeds() {
    let rotor = Jeffcott {
        sensor_turn: 0.3,
        ..Jeffcott::with(150.0, 2450.0, 0.05)
    };
    // The cross-coupling estimated (held in the correction) and taken as
    // zero (the plain fit missed 34 % of 600 records so, session 23).
    for coupling in [CrossCoupling::Estimated, CrossCoupling::Zero] {
        let seeds = 100;
        let (mut missed, mut sum) = (0, 0.0);
        for seed in 1..=seeds {
            let grid = speeds(1715.0, 3185.0, 25);
            let s = session_with_weights(&[rotor], &grid, Unit::UmPp, 0.1, seed, 20.0, 6.0);
            let out = answer(&RotorRequest {
                session: s,
                options: RotorOptions {
                    cross_coupling: Some(coupling),
                    ..Default::default()
                },
            });
            let r = &out["results"][0];
            sum += num(r, "damping_ratio");
            missed += usize::from(!covers(r, rotor.zeta()));
        }
        let mean = sum / seeds as f64;
        println!("{coupling:?}: {missed} of {seeds} missed, mean ζ {mean:.4}");
        // 95 % of 100: 5 expected, binomial standard deviation 2.2.
        assert!(
            missed <= 12,
            "{coupling:?}: {missed} of {seeds} missed, mean ζ {mean:.4}"
        );
        // Not by being wide: the fitted damping is right on average (its
        // scatter is under 0.01, the mean's under 0.001).
        assert!(
            (mean - 0.05).abs() < 0.0025,
            "{coupling:?}: mean ζ {mean:.4}"
        );
    }
}
