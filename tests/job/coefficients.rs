//! Trim balancing from supplied or pooled coefficients: a session with only its
//! reference run solves against `influence_coefficients`; trial runs check them
//! (`coefficients_disagree`); sessions pool into one influence matrix with its
//! covariance, naming a session whose rotor changed.

use crate::support;

use fieldbal::balancing::job::pool::{pool, PoolOptions};
use fieldbal::balancing::model::Conventions;
use fieldbal::balancing::phasor::{angle_diff_deg, weight_out};
use fieldbal::balancing::Session;
use serde_json::{json, Value};
use support::*;

/// The rotor's exact coefficients as the option lists them, in `conv`.
fn exact_coefficients(rotor: &Rotor, conv: Conventions, sd: Option<f64>) -> Value {
    supplied(&rotor.w, conv, |_, _| {
        sd.map(|sd| [[sd * sd, 0.0], [0.0, sd * sd]])
    })
}

/// A reference run and trials (one per plane, or none), from `rotor`.
fn runs(rotor: &Rotor, conv: Conventions, trials: bool, noise: &mut Noise) -> Vec<Value> {
    let mut r = opening_runs(rotor, conv, trials, noise);
    if !trials {
        return r;
    }
    r.push(run(
        rotor,
        conv,
        "both",
        &vec![(0, 30.0, 200.0), (1, 30.0, 300.0)],
        &vec![(0, 30.0, 200.0), (1, 30.0, 300.0)],
        noise,
        &NO_RUNOUT,
    ));
    r
}

#[test]
fn a_session_with_only_its_reference_run_solves_against_supplied_coefficients() {
    let rotor = Rotor::new();
    let best = rotor.optimum();
    for conv in Conventions::ALL {
        let s = session(conv, runs(&rotor, conv, false, &mut Noise::none()));
        let sol = solve_json(
            &s,
            json!({"influence_coefficients": exact_coefficients(&rotor, conv, None)}),
        );
        for (j, p) in PLANES.iter().enumerate() {
            assert!(
                (correction(conv, &sol, p) - best[j]).norm() < 1e-9 * best[j].norm(),
                "{conv:?} {p}"
            );
        }
        assert!(sol.run_checks.is_none());
        assert!(
            !sol.warnings.iter().any(|w| w.code == "trial_effect_small"),
            "{:?}",
            sol.warnings
        );
        assert_eq!(sol.influence_coefficients.len(), 8);
    }
}

#[test]
fn the_coefficients_covariance_widens_the_correction_uncertainty() {
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let s = session(conv, runs(&rotor, conv, false, &mut Noise::none()));
    let without = solve_json(
        &s,
        json!({"influence_coefficients": exact_coefficients(&rotor, conv, None)}),
    );
    let with = solve_json(
        &s,
        json!({"influence_coefficients": exact_coefficients(&rotor, conv, Some(0.05))}),
    );
    for (a, b) in without.corrections.iter().zip(&with.corrections) {
        let (ua, ub) = (
            a.uncertainty.as_ref().unwrap(),
            b.uncertainty.as_ref().unwrap(),
        );
        let tr = |u: &fieldbal::balancing::solution::Uncertainty| {
            u.covariance_g2[0][0] + u.covariance_g2[1][1]
        };
        assert!(tr(ub) > 1.5 * tr(ua), "{}: {ua:?} vs {ub:?}", a.plane);
        assert!((a.mass_g - b.mass_g).abs() < 1e-9 * a.mass_g);
    }
}

#[test]
fn trial_runs_of_a_changed_rotor_disagree_with_supplied_coefficients() {
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let coefficients = exact_coefficients(&rotor, conv, Some(0.01));
    let same = session(conv, runs(&rotor, conv, true, &mut Noise::new(1.0, 1.0, 7)));
    let sol = solve_json(&same, json!({"influence_coefficients": coefficients}));
    assert!(
        !sol.warnings
            .iter()
            .any(|w| w.code == "coefficients_disagree"),
        "{:?}",
        sol.warnings
    );
    assert_eq!(sol.run_checks.as_ref().map(Vec::len), Some(3));

    let changed = session(
        conv,
        runs(&rotor.scaled(1.3), conv, true, &mut Noise::new(1.0, 1.0, 7)),
    );
    let sol = solve_json(&changed, json!({"influence_coefficients": coefficients}));
    assert!(
        sol.warnings
            .iter()
            .any(|w| w.code == "coefficients_disagree"),
        "{:?}",
        sol.warnings
    );
    assert!(sol.run_checks.unwrap().iter().all(|c| !c.consistent));
}

fn parsed(v: &Value) -> Session {
    serde_json::from_value(v.clone()).unwrap()
}

/// `(id, session)` of a job on `rotor` with trials, 1 % / 1° noise from `seed`.
fn noisy(id: &str, rotor: &Rotor, conv: Conventions, seed: u64) -> (String, Session) {
    let runs = runs(rotor, conv, true, &mut Noise::new(1.0, 1.0, seed));
    (id.to_string(), parsed(&session(conv, runs)))
}

#[test]
fn two_sessions_pool_into_coefficients_that_give_the_exact_correction_within_their_uncertainty() {
    let rotor = Rotor::new();
    let best = rotor.optimum();
    for conv in [Conventions::default(), Conventions::ALL[3]] {
        let sessions = vec![noisy("s1", &rotor, conv, 11), noisy("s2", &rotor, conv, 12)];
        let pooled = pool(&sessions, &PoolOptions::default()).expect("pools");
        assert!(pooled.warnings.is_empty(), "{:?}", pooled.warnings);
        assert_eq!(pooled.sessions, ["s1", "s2"]);
        assert_eq!(pooled.influence_coefficients.len(), 8);
        // A new job: only its reference run (exact readings), the pooled coefficients.
        let s = session(conv, runs(&rotor, conv, false, &mut Noise::none()));
        let coefficients = serde_json::to_value(&pooled.influence_coefficients).unwrap();
        let sol = solve_json(&s, json!({"influence_coefficients": coefficients}));
        for (j, p) in PLANES.iter().enumerate() {
            let c = sol.corrections.iter().find(|c| c.plane == *p).unwrap();
            let u = c.uncertainty.as_ref().unwrap();
            let (m, a) = weight_out(conv, best[j]);
            assert!(
                u.mass_g.unwrap()[0] <= m && m <= u.mass_g.unwrap()[1],
                "{conv:?} {p}: {m} outside {:?}",
                u.mass_g
            );
            let mid = (u.angle_deg[0] + u.angle_deg[1]) / 2.0;
            let half = (u.angle_deg[1] - u.angle_deg[0]) / 2.0;
            assert!(
                angle_diff_deg(a, mid) <= half,
                "{conv:?} {p}: {a} outside {:?}",
                u.angle_deg
            );
            // The uncertainty is that of the coefficients: not zero, not useless.
            assert!(
                u.mass_g.unwrap()[1] - u.mass_g.unwrap()[0] > 0.0
                    && u.mass_g.unwrap()[1] - u.mass_g.unwrap()[0] < 0.5 * m,
                "{u:?}"
            );
        }
    }
}

#[test]
fn a_session_whose_rotor_changed_is_named_and_left_out_on_request() {
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let sessions = vec![
        noisy("s1", &rotor, conv, 21),
        noisy("s2", &rotor, conv, 22),
        noisy("changed", &rotor.scaled(1.3), conv, 23),
    ];
    let pooled = pool(&sessions, &PoolOptions::default()).expect("pools");
    let w = pooled
        .warnings
        .iter()
        .find(|w| w.code == "coefficients_disagree")
        .expect("warned");
    assert!(w.message.contains("'changed'"), "{}", w.message);
    let flagged: Vec<&str> = pooled
        .checks
        .iter()
        .filter(|c| !c.consistent)
        .map(|c| c.session.as_str())
        .collect();
    assert_eq!(flagged, ["changed"]);
    assert_eq!(pooled.sessions.len(), 3);

    let options = PoolOptions {
        exclude_disagreeing: Some(true),
        ..PoolOptions::default()
    };
    let kept = pool(&sessions, &options).expect("pools");
    assert_eq!(kept.sessions, ["s1", "s2"]);
    assert_eq!(kept.excluded, ["changed"]);
    // Without the changed session the coefficients are the rotor's.
    for c in &kept.influence_coefficients {
        let a = SENSORS.iter().position(|s| *s == c.sensor).unwrap()
            + 2 * SPEEDS.iter().position(|s| *s == c.speed_rpm).unwrap();
        let j = PLANES.iter().position(|p| *p == c.plane).unwrap();
        let w = phasor(conv, c.amplitude_per_g, c.phase_deg);
        // Within 3 standard deviations of their own stated covariance.
        let cov = c.covariance.expect("covariance");
        let sd = (cov[0][0] + cov[1][1]).sqrt();
        assert!((w - rotor.w[(a, j)]).norm() < 3.0 * sd, "{c:?}");
    }
}

#[test]
fn supplied_coefficients_that_miss_a_sensor_or_name_an_unknown_one_are_rejected() {
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let s = parsed(&session(
        conv,
        runs(&rotor, conv, false, &mut Noise::none()),
    ));
    let full = exact_coefficients(&rotor, conv, None);
    let mut missing = full.clone();
    missing.as_array_mut().unwrap().pop();
    let mut unknown = full.clone();
    unknown[3]["sensor"] = json!("9X");
    let mut bad_cov = full.clone();
    bad_cov[2]["covariance"] = json!([[1.0, 0.0], [0.0, -1.0]]);
    let mut nan = full.clone();
    nan[1]["amplitude_per_g"] = json!(-1.0);
    // Below what any readings could give (1e-9 of a unit over 1e7 g): 1e-300
    // unit/g made a correction of 1e302 g whose covariance overflowed and
    // was answered as `null`.
    let mut tiny = full.clone();
    tiny[2]["amplitude_per_g"] = json!(1e-300);
    // Below 1 rpm, as no reading is (session 21).
    let mut slow = full.clone();
    slow[0]["speed_rpm"] = json!(1e-320);
    let cases = [
        (
            slow,
            "invalid_value",
            "options.influence_coefficients[0].speed_rpm",
        ),
        (
            tiny,
            "invalid_value",
            "options.influence_coefficients[2].amplitude_per_g",
        ),
        (
            missing,
            "missing_coefficient",
            "options.influence_coefficients",
        ),
        (
            unknown,
            "unknown_sensor",
            "options.influence_coefficients[3].sensor",
        ),
        (
            bad_cov,
            "invalid_value",
            "options.influence_coefficients[2].covariance",
        ),
        (
            nan,
            "invalid_value",
            "options.influence_coefficients[1].amplitude_per_g",
        ),
        (
            json!(null),
            "coefficients_unavailable",
            "options.coefficients_from",
        ),
    ];
    for (coefficients, code, field) in cases {
        let o = if coefficients.is_null() {
            json!({"coefficients_from": {"machine": "ID-FAN-3"}})
        } else {
            json!({"influence_coefficients": coefficients})
        };
        let options = serde_json::from_value(o).unwrap();
        let err = fieldbal::balancing::solve(&s, &options).unwrap_err();
        assert_eq!(
            (err.code, err.field.as_deref()),
            (code, Some(field)),
            "{err:?}"
        );
    }
}

#[test]
fn a_plane_that_supplied_coefficients_say_moves_no_reading_is_undetermined() {
    // Every coefficient of plane B zero: any mass in B leaves every reading as
    // it is, as a trial that changed nothing does with estimated coefficients.
    // The correction in B cannot be known (no mass interval, the warning
    // `plane_undetermined`), not "0 g within [0, 0]"; A's stays determined.
    let rotor = Rotor::new();
    for conv in Conventions::ALL {
        let s = parsed(&session(
            conv,
            runs(&rotor, conv, false, &mut Noise::none()),
        ));
        let mut coefficients = exact_coefficients(&rotor, conv, Some(0.01));
        for c in coefficients.as_array_mut().unwrap() {
            if c["plane"] == "B" {
                c["amplitude_per_g"] = json!(0.0);
            }
        }
        let options =
            serde_json::from_value(json!({"influence_coefficients": coefficients})).unwrap();
        let sol = fieldbal::balancing::solve(&s, &options).unwrap();
        let b = sol.corrections.iter().find(|c| c.plane == "B").unwrap();
        let u = b.uncertainty.as_ref().unwrap();
        assert_eq!((u.mass_g, u.angle_deg), (None, [0.0, 360.0]), "{conv:?}");
        let undetermined: Vec<_> = sol
            .warnings
            .iter()
            .filter(|w| w.code == "plane_undetermined")
            .map(|w| w.plane.as_deref())
            .collect();
        assert_eq!(undetermined, [Some("B")], "{conv:?}: {:?}", sol.warnings);
        let a = sol.corrections.iter().find(|c| c.plane == "A").unwrap();
        assert!(a.uncertainty.as_ref().unwrap().mass_g.is_some(), "{conv:?}");
    }
}

#[test]
fn pooled_coefficients_below_what_readings_resolve_are_zero_and_solve_again() {
    // Sensor 2H barely moved (a rounding's worth) under a heavy trial weight:
    // its pooled coefficient is far below 1e-16 unit/g, which the option
    // `influence_coefficients` refuses. Pooled (stored, then used through
    // `coefficients_from`, or printed by `fieldbal coefficients`) it is 0, the
    // sensor does not see the plane, so that the coefficients solve again.
    let reading = |sensor: &str, amplitude: f64, phase: f64| json!({"speed_rpm": 1480, "sensor": sensor, "amplitude": amplitude, "phase_deg": phase});
    let s = parsed(&json!({
        "name": "hair", "machine": "M",
        "planes": [{"id": "A"}],
        "sensors": [{"id": "1H", "unit": "um_pp"}, {"id": "2H", "unit": "um_pp"}],
        "runs": [
            {"id": "zero", "weights": [],
             "readings": [reading("1H", 88.0, 47.0), reading("2H", 50.0, 10.0)]},
            {"id": "trial", "weights": [{"plane": "A", "mass_g": 1e5, "angle_deg": 0}],
             "readings": [reading("1H", 60.0, 120.0), reading("2H", 50.000000000000014, 10.0)]}
        ]
    }));
    let pooled = pool(&[("s1".to_string(), s.clone())], &PoolOptions::default()).expect("pools");
    let seen: Vec<f64> = pooled
        .influence_coefficients
        .iter()
        .map(|c| c.amplitude_per_g)
        .collect();
    assert!(seen.iter().all(|&a| a == 0.0 || a >= 1e-16), "{seen:?}");
    assert!(seen.contains(&0.0), "{seen:?}");
    let coefficients = serde_json::to_value(&pooled.influence_coefficients).unwrap();
    let options = serde_json::from_value(json!({"influence_coefficients": coefficients})).unwrap();
    fieldbal::balancing::solve(&s, &options).expect("the pooled coefficients solve");
}

/// A plane whose trial moved no reading pools into coefficients that are 0
/// at every sensor and speed: stored as a version, every solve with it warns
/// `plane_undetermined` and every trial-weight sizing refuses it. The pool
/// says so where the version is made (it said nothing, session 21); the
/// plane that moved the readings is not named.
#[test]
fn a_plane_whose_trial_moved_no_reading_is_named_in_the_pool_warnings() {
    let reading = |sensor: &str, amplitude: f64, phase: f64| json!({"speed_rpm": 1480, "sensor": sensor, "amplitude": amplitude, "phase_deg": phase});
    let zero = vec![reading("1H", 88.0, 47.0), reading("2H", 61.5, 301.0)];
    let s = parsed(&json!({
        "name": "still", "machine": "M",
        "planes": [{"id": "A"}, {"id": "B"}],
        "sensors": [{"id": "1H", "unit": "um_pp"}, {"id": "2H", "unit": "um_pp"}],
        "runs": [
            {"id": "zero", "weights": [], "readings": zero},
            {"id": "trial A", "weights": [{"plane": "A", "mass_g": 40, "angle_deg": 0}], "readings": zero},
            {"id": "trial B", "weights": [{"plane": "B", "mass_g": 40, "angle_deg": 90}],
             "readings": [reading("1H", 120.0, 80.0), reading("2H", 40.0, 250.0)]}
        ]
    }));
    let pooled = pool(&[("s1".to_string(), s)], &PoolOptions::default()).expect("pools");
    let named: Vec<(&str, Option<&str>)> = pooled
        .warnings
        .iter()
        .map(|w| (w.code.as_str(), w.plane.as_deref()))
        .collect();
    assert_eq!(named, vec![("plane_undetermined", Some("A"))], "{named:?}");
}

#[test]
fn sessions_that_read_a_sensor_in_different_units_are_not_pooled() {
    // The same sensor id in µm pk-pk in one session and in mils in another:
    // pooled as they were, the coefficient averaged numbers of two units (and
    // the first session's disagreement named a unit slip a "changed rotor").
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let (_, first) = noisy("s1", &rotor, conv, 11);
    let mut v = serde_json::to_value(noisy("s2", &rotor, conv, 12).1).unwrap();
    v["sensors"][1]["unit"] = json!("mils_pp");
    let id = v["sensors"][1]["id"].clone();
    for run in v["runs"].as_array_mut().unwrap() {
        for r in run["readings"].as_array_mut().unwrap() {
            if r["sensor"] == id {
                r["amplitude"] = json!(r["amplitude"].as_f64().unwrap() / 25.4);
            }
        }
    }
    let sensor = v["sensors"][1]["id"].as_str().unwrap().to_string();
    let sessions = vec![("s1".to_string(), first), ("s2".to_string(), parsed(&v))];
    let err = pool(&sessions, &PoolOptions::default()).unwrap_err();
    assert_eq!(
        (err.code, err.field.as_deref()),
        ("unit_mismatch", Some("sessions[1]")),
        "{err:?}"
    );
    assert!(
        err.message.contains(&sensor) && err.message.contains("mils_pp"),
        "{}",
        err.message
    );
}
