//! The job goes on: reference → trials → correction (fitted 10 % off) → check
//! run → trim from the check run (`from_run`) → check, on runs generated from
//! an exact influence matrix (tests/job/support.rs).

use crate::support;

use fieldbal::balancing::model::Conventions;
use fieldbal::balancing::solution::RunCheck;
use fieldbal::balancing::Solution;
use num_complex::Complex64;
use serde_json::{json, Value};
use support::*;

/// The one-shot correction fitted with a 10 % error in mass and 6° in angle.
fn fitted(conv: Conventions, one_shot: &Solution) -> Weights {
    PLANES
        .iter()
        .enumerate()
        .map(|(j, p)| {
            let c =
                correction(conv, one_shot, p) * 1.1 * Complex64::from_polar(1.0, 6f64.to_radians());
            typed(conv, j, c)
        })
        .collect()
}

/// The job up to the check run: (session with the check run, one-shot solution, fitted weights).
fn job(conv: Conventions, noise: &mut Noise, typo: f64) -> (Value, Solution, Weights) {
    let rotor = Rotor::new();
    let mut runs = first_runs(&rotor, conv, noise, &NO_RUNOUT, typo);
    let one_shot = solve_json(&session(conv, runs.clone()), json!({}));
    let fit = fitted(conv, &one_shot);
    runs.push(run(&rotor, conv, "check", &fit, &fit, noise, &NO_RUNOUT));
    (session(conv, runs), one_shot, fit)
}

/// The trim from the check run, and that run's check.
fn trim_from_the_check_run(s: &Value) -> (Solution, RunCheck) {
    let sol = solve_json(s, json!({"from_run": "check"}));
    let check = sol
        .run_checks
        .as_ref()
        .expect("run checks")
        .iter()
        .find(|c| c.run == "check")
        .expect("check run checked")
        .clone();
    (sol, check)
}

fn close(a: Complex64, b: Complex64, rel: f64) -> bool {
    (a - b).norm() <= rel * b.norm().max(1e-9)
}

#[test]
fn a_trim_from_the_check_run_reaches_the_exact_optimum_in_every_convention() {
    let rotor = Rotor::new();
    let best = rotor.optimum();
    let optimum = rotor.response(&best);
    for conv in Conventions::ALL {
        let (s, one_shot, fit) = job(conv, &mut Noise::none(), 0.0);
        let trim = solve_json(&s, json!({"from_run": "check"}));
        assert_eq!(trim.from_run.as_deref(), Some("check"));
        let on = internal(conv, &fit);
        let mut after = on.clone();
        for (j, p) in PLANES.iter().enumerate() {
            // `total` replaces every weight in the plane: the one-shot answer.
            assert!(
                close(total(conv, &trim, p), best[j], 1e-6),
                "{conv:?} {p}: total"
            );
            assert!(
                close(total(conv, &trim, p), correction(conv, &one_shot, p), 1e-6),
                "{conv:?} {p}"
            );
            // The correction is what to add to the weights already on.
            assert!(
                close(correction(conv, &trim, p), best[j] - on[j], 1e-6),
                "{conv:?} {p}: add"
            );
            after[j] += correction(conv, &trim, p);
        }
        // Fitting the trim brings the rotor to the exact optimum, as predicted.
        let reached = rotor.response(&after);
        for (a, r) in trim.predicted_residual.iter().enumerate() {
            assert!(
                (reached[a].norm() - optimum[a].norm()).abs() < 1e-6 * optimum.norm(),
                "{conv:?} row {a}"
            );
            assert!(
                (r.amplitude - optimum[a].norm()).abs() < 1e-6 * optimum.norm(),
                "{conv:?} row {a}"
            );
        }
    }
}

#[test]
fn a_trim_from_a_rotor_already_at_the_optimum_adds_nothing() {
    let conv = Conventions::default();
    let rotor = Rotor::new();
    let (s, _, fit) = job(conv, &mut Noise::none(), 0.0);
    let trim = solve_json(&s, json!({"from_run": "check"}));
    // Second check: the fitted weights and the trim, each listed (two per plane).
    let mut on = fit.clone();
    for (j, p) in PLANES.iter().enumerate() {
        on.push(typed(conv, j, correction(conv, &trim, p)));
    }
    let mut v = s.clone();
    v["runs"].as_array_mut().unwrap().push(run(
        &rotor,
        conv,
        "check 2",
        &on,
        &on,
        &mut Noise::none(),
        &NO_RUNOUT,
    ));
    let again = solve_json(&v, json!({"from_run": "check 2"}));
    let best = rotor.optimum();
    for (j, p) in PLANES.iter().enumerate() {
        assert!(
            correction(conv, &again, p).norm() < 1e-6 * best[j].norm(),
            "{p}"
        );
        assert!(close(total(conv, &again, p), best[j], 1e-6), "{p}");
    }
    let checks = again.run_checks.expect("run checks");
    assert!(checks.iter().all(|c| c.consistent), "{checks:?}");
}

#[test]
fn the_check_run_is_consistent_when_the_readings_differ_by_noise_only() {
    for seed in 1..=5 {
        let (s, _, _) = job(Conventions::default(), &mut Noise::new(1.0, 1.0, seed), 0.0);
        let (sol, check) = trim_from_the_check_run(&s);
        assert!(check.consistent, "seed {seed}: {check:?}");
        assert_eq!(check.rows.len(), 4);
        assert!(
            !sol.warnings.iter().any(|w| w.code == "run_inconsistent"),
            "seed {seed}: {:?}",
            sol.warnings
        );
    }
}

#[test]
fn a_trial_angle_typed_90_degrees_off_makes_the_check_run_inconsistent() {
    for seed in 1..=3 {
        let (s, _, _) = job(
            Conventions::default(),
            &mut Noise::new(1.0, 1.0, seed),
            90.0,
        );
        let (sol, check) = trim_from_the_check_run(&s);
        assert!(!check.consistent, "seed {seed}: {check:?}");
        let warned = sol
            .warnings
            .iter()
            .any(|w| w.code == "run_inconsistent" && w.message.contains("'check'"));
        assert!(warned, "seed {seed}: {:?}", sol.warnings);
    }
}

#[test]
fn the_check_of_a_run_compares_its_reading_with_the_prediction_of_the_others() {
    let conv = Conventions::default();
    let rotor = Rotor::new();
    let (s, _, fit) = job(conv, &mut Noise::none(), 0.0);
    let sol = solve_json(&s, json!({}));
    let checks = sol.run_checks.expect("run checks");
    // Every run with weights is predictable from the other two here.
    let runs: Vec<&str> = checks.iter().map(|c| c.run.as_str()).collect();
    assert_eq!(runs, ["trial A", "trial B", "check"]);
    let y = rotor.response(&internal(conv, &fit));
    let check = &checks[2];
    for (a, row) in check.rows.iter().enumerate() {
        assert!((row.measured - y[a].norm()).abs() < 1e-9 * y[a].norm());
        assert!((row.predicted - y[a].norm()).abs() < 1e-6 * y[a].norm());
        assert!(row.amplitude_95 >= row.predicted);
    }
}

#[test]
fn a_session_with_one_trial_per_plane_has_no_run_checks_and_no_total() {
    let conv = Conventions::default();
    let mut noise = Noise::none();
    let s = session(
        conv,
        first_runs(&Rotor::new(), conv, &mut noise, &NO_RUNOUT, 0.0),
    );
    let sol = solve_json(&s, json!({}));
    assert!(sol.run_checks.is_none());
    assert!(sol.from_run.is_none());
    assert!(sol.corrections.iter().all(|c| c.total.is_none()));
    let v = serde_json::to_value(&sol).unwrap();
    for key in ["run_checks", "from_run", "runout", "coefficients_from"] {
        assert!(
            v.get(key).is_none(),
            "{key} must be absent from a v1 answer"
        );
    }
}

#[test]
fn from_run_with_the_reference_run_gives_the_v1_correction_as_total() {
    let conv = Conventions::default();
    let (s, _, _) = job(conv, &mut Noise::none(), 0.0);
    let v1 = solve_json(&s, json!({}));
    let from_zero = solve_json(&s, json!({"from_run": "zero"}));
    for p in PLANES {
        let c = correction(conv, &v1, p);
        assert!(close(correction(conv, &from_zero, p), c, 1e-9));
        assert!(close(total(conv, &from_zero, p), c, 1e-9));
    }
}

#[test]
fn from_run_naming_no_run_is_rejected_naming_the_option() {
    let conv = Conventions::default();
    let (s, _, _) = job(conv, &mut Noise::none(), 0.0);
    let session: fieldbal::balancing::Session = serde_json::from_value(s).unwrap();
    let options = serde_json::from_value(json!({"from_run": "no such run"})).unwrap();
    let err = fieldbal::balancing::solve(&session, &options).unwrap_err();
    assert_eq!(err.code, "unknown_run");
    assert_eq!(err.field.as_deref(), Some("options.from_run"));
}

#[test]
fn from_run_with_a_weight_at_the_largest_angle_gives_the_same_trim() {
    // A kept weight at 1e6° (the largest angle a session allows) is the same
    // weight as at 1e6 mod 360 = 280°; rebasing once turned it to 1e6 + 180°,
    // which the check refused with an error that named no field (session 15).
    let conv = Conventions::default();
    let (s, _, _) = job(conv, &mut Noise::none(), 0.0);
    let check = s["runs"]
        .as_array()
        .unwrap()
        .iter()
        .position(|r| r["id"] == "check")
        .unwrap();
    let at = |angle: f64| {
        let mut s = s.clone();
        // The same physical weight at both angles: the solutions must agree.
        s["runs"][check]["weights"][0]["angle_deg"] = json!(angle);
        s
    };
    let far = solve_json(&at(1e6), json!({"from_run": "check"}));
    let near = solve_json(&at(280.0), json!({"from_run": "check"}));
    for p in PLANES {
        let c = correction(conv, &near, p);
        assert!(close(correction(conv, &far, p), c, 1e-9), "{p}");
        assert!(close(total(conv, &far, p), total(conv, &near, p), 1e-9));
    }
}
