//! The solution's diagnostics and practical forms: trial-effect and
//! conditioning warnings, dropped planes, split over fixed places, unbalance,
//! the ISO tolerance, and the row selection options.

use fieldbal::balancing::model::{Session, SolveOptions};
use fieldbal::balancing::phasor::{reading_in, reading_out, weight_in};
use fieldbal::balancing::{self, Solution};
use num_complex::Complex64;
use serde_json::{json, Value};

fn example(name: &str) -> Value {
    let path = format!("{}/tests/data/examples/{name}", env!("CARGO_MANIFEST_DIR"));
    serde_json::from_slice::<Value>(&std::fs::read(path).unwrap()).unwrap()["session"].clone()
}

fn solve(session: &Value, options: Value) -> Solution {
    let s: Session = balancing::parse_session(&serde_json::to_vec(session).unwrap()).unwrap();
    let o: SolveOptions = serde_json::from_value(options).unwrap();
    balancing::solve(&s, &o).unwrap()
}

fn codes(s: &Solution) -> Vec<(String, Option<String>)> {
    s.warnings
        .iter()
        .map(|w| (w.code.clone(), w.plane.clone()))
        .collect()
}

/// Replace run `r`'s readings by `Y0 + f(ΔY_a, Y0_a)` for every row.
fn reshape_trial(
    session: &mut Value,
    r: usize,
    f: impl Fn(Complex64, Complex64, usize) -> Complex64,
) {
    let s: Session = serde_json::from_value(session.clone()).unwrap();
    let conv = s.conventions.unwrap_or_default();
    for (a, (zero, trial)) in s.runs[0]
        .readings
        .iter()
        .zip(&s.runs[r].readings)
        .enumerate()
    {
        let y0 = reading_in(conv, zero.amplitude, zero.phase_deg);
        let dy = reading_in(conv, trial.amplitude, trial.phase_deg) - y0;
        let (amp, phase) = reading_out(conv, y0 + f(dy, y0, a));
        session["runs"][r]["readings"][a]["amplitude"] = json!(amp);
        session["runs"][r]["readings"][a]["phase_deg"] = json!(phase);
    }
}

#[test]
fn a_trial_that_moves_no_reading_by_ten_percent_is_flagged() {
    let mut session = example("pump-two-plane-exact.json");
    // Scale the inboard trial's effect so its largest relative change is 10 %.
    reshape_trial(&mut session, 1, |dy, _, _| dy * (0.10 / 2.368));
    let s = solve(&session, json!({}));
    assert!(
        codes(&s).contains(&("trial_effect_small".into(), Some("inboard".into()))),
        "{:?}",
        s.warnings
    );
    assert!(!codes(&s).contains(&("trial_effect_small".into(), Some("outboard".into()))));
    let p = s.planes.iter().find(|p| p.plane == "inboard").unwrap();
    assert!(
        (p.trial_effect_ratio - 0.10).abs() < 0.01,
        "{}",
        p.trial_effect_ratio
    );
}

#[test]
fn a_normal_trial_is_not_flagged() {
    let s = solve(&example("pump-two-plane-exact.json"), json!({}));
    assert!(
        s.warnings.iter().all(|w| w.code != "trial_effect_small"),
        "{:?}",
        s.warnings
    );
    assert!(s.planes.iter().all(|p| p.trial_effect_ratio > 1.0));
}

/// The outboard trial made to act almost like the inboard one.
fn dependent_session() -> Value {
    let mut session = example("pump-two-plane-exact.json");
    let inboard: Vec<Complex64> = {
        let s: Session = serde_json::from_value(session.clone()).unwrap();
        let conv = s.conventions.unwrap();
        (0..4)
            .map(|a| {
                let r = |k: usize| {
                    reading_in(
                        conv,
                        s.runs[k].readings[a].amplitude,
                        s.runs[k].readings[a].phase_deg,
                    )
                };
                r(1) - r(0)
            })
            .collect()
    };
    reshape_trial(&mut session, 2, |_, _, a| {
        inboard[a] * Complex64::new(0.0, 0.8) * (1.0 + 0.02 * a as f64)
    });
    session
}

#[test]
fn nearly_dependent_planes_are_flagged_with_their_significance_factor() {
    let s = solve(&dependent_session(), json!({}));
    let low: Vec<&str> = s
        .planes
        .iter()
        .filter(|p| p.significance_factor < 0.2)
        .map(|p| p.plane.as_str())
        .collect();
    assert_eq!(low.len(), 1, "{:?}", s.planes);
    assert!(
        codes(&s).contains(&("ill_conditioned".into(), Some(low[0].into()))),
        "{:?}",
        s.warnings
    );
    assert!(s.condition_number > 10.0);
}

#[test]
fn dropping_dependent_planes_solves_with_the_rest_and_says_so() {
    let s = solve(&dependent_session(), json!({"drop_dependent_planes": true}));
    assert_eq!(s.dropped_planes.len(), 1);
    assert_eq!(s.corrections.len(), 1);
    assert_ne!(s.corrections[0].plane, s.dropped_planes[0]);
    assert!(s
        .planes
        .iter()
        .any(|p| p.dropped && p.plane == s.dropped_planes[0]));
    assert!(s.warnings.iter().all(|w| w.code != "ill_conditioned"));
}

#[test]
fn a_plane_with_fixed_places_gets_the_correction_split_between_neighbours() {
    let mut session = example("pump-two-plane-exact.json");
    session["planes"][0]["positions"] = json!(12);
    let s = solve(&session, json!({}));
    let c = &s.corrections[0];
    let split = c.split.as_ref().expect("split given");
    assert_eq!(split.len(), 2);
    // 255° lies between places 8 (240°) and 9 (270°).
    assert_eq!((split[0].position, split[1].position), (8, 9));
    let sum: Complex64 = split
        .iter()
        .map(|p| weight_in(s.conventions, p.mass_g, p.angle_deg))
        .sum();
    assert!((sum - weight_in(s.conventions, c.mass_g, c.angle_deg)).norm() < 1e-9);
    assert!((c.unbalance_gmm.unwrap() - c.mass_g * 180.0).abs() < 1e-9);
    assert!(s.corrections[1].split.is_none());
}

#[test]
fn the_iso_tolerance_is_given_when_the_rotor_is_described() {
    let mut session = example("pump-two-plane-exact.json");
    // 30 g at 180 mm and 22 g at 160 mm as found: 5400 and 3520 g·mm.
    session["rotor"] = json!({"mass_kg": 420, "service_speed_rpm": 1480, "balance_grade": "G6.3"});
    let iso = solve(&session, json!({}))
        .iso_21940
        .expect("tolerance given");
    assert!((iso.permissible_residual_unbalance_gmm - 9549.0 * 6.3 * 420.0 / 1480.0).abs() < 1e-6);
    assert!(
        (iso.permissible_per_plane_gmm - iso.permissible_residual_unbalance_gmm / 2.0).abs() < 1e-9
    );
    let as_found = iso.as_found_unbalance_gmm.unwrap();
    assert!((as_found[0] - 5400.0).abs() < 1e-6 && (as_found[1] - 3520.0).abs() < 1e-6);
    assert_eq!(iso.as_found_within_tolerance, Some(true));
    // A rotor ten times lighter tolerates ten times less.
    session["rotor"]["mass_kg"] = json!(42);
    let iso = solve(&session, json!({})).iso_21940.unwrap();
    assert_eq!(iso.as_found_within_tolerance, Some(false));
}

#[test]
fn a_heavily_weighted_sensor_ends_with_less_vibration() {
    let session = example("compressor-multispeed-noisy.json");
    let plain = solve(&session, json!({}));
    let weighted = solve(
        &session,
        json!({"row_weights": [{"sensor": "MID", "weight": 10}]}),
    );
    let mid = |s: &Solution| {
        s.predicted_residual
            .iter()
            .filter(|r| r.sensor == "MID")
            .map(|r| r.amplitude.powi(2))
            .sum::<f64>()
    };
    assert!(
        mid(&weighted) < mid(&plain),
        "{} vs {}",
        mid(&weighted),
        mid(&plain)
    );
}

#[test]
fn selecting_speeds_and_sensors_fits_only_those_rows() {
    let session = example("compressor-multispeed-noisy.json");
    let s = solve(
        &session,
        json!({"speeds_rpm": [3600, 6000], "sensors": ["B1X", "B2X", "MID"]}),
    );
    for r in &s.predicted_residual {
        let want = [3600.0, 6000.0].contains(&r.speed_rpm)
            && ["B1X", "B2X", "MID"].contains(&r.sensor.as_str());
        assert_eq!(r.used, want, "{r:?}");
    }
    let used: Vec<f64> = s
        .predicted_residual
        .iter()
        .filter(|r| r.used)
        .map(|r| r.amplitude_before)
        .collect();
    let max = used.iter().cloned().fold(0.0, f64::max);
    assert!((s.summary.max_before - max).abs() < 1e-12);
}
