//! Min-max, mass limits and row weights through the public `balancing::solve`
//! (issue 5): on the public examples and on synthesised rotors.

use super::support;

use fieldbal::balancing::model::{Objective, SolveOptions};
use fieldbal::balancing::{self, ErrorKind, Solution};
use num_complex::Complex64;
use serde_json::{json, Value};
use support::{example, mass, rotor, sensor_residuals, solve, with, BALANCING_EXAMPLES};

#[test]
fn min_max_never_leaves_a_larger_maximum_than_least_squares_on_the_public_examples() {
    for name in BALANCING_EXAMPLES {
        let (session, options) = example(name);
        let ls = solve(&session, &options);
        let mm = solve(&session, &with(&options, json!({"objective": "min_max"})));
        assert_eq!(mm.objective, Objective::MinMax);
        let tol = 1e-6 * ls.summary.max_before;
        assert!(
            mm.summary.max_after <= ls.summary.max_after + tol,
            "{name}: {} > {}",
            mm.summary.max_after,
            ls.summary.max_after
        );
        // Goodman (1964): the least-squares RMS is a floor for any maximum.
        assert!(mm.summary.max_after >= ls.summary.rms_after - tol, "{name}");
    }
}

#[test]
fn min_max_beats_least_squares_on_the_worst_bearing_of_a_noisy_rotor() {
    let session = rotor(4, 11, 1, 4, 6.0);
    let ls = solve(&session, &SolveOptions::default());
    let mm = solve(
        &session,
        &with(&SolveOptions::default(), json!({"objective": "min_max"})),
    );
    assert!(
        mm.summary.max_after < 0.99 * ls.summary.max_after,
        "{:?} vs {:?}",
        mm.summary,
        ls.summary
    );
    assert!(mm.summary.rms_after >= ls.summary.rms_after * (1.0 - 1e-9));
}

#[test]
fn a_binding_mass_limit_is_kept_and_named_for_both_objectives() {
    let (session, options) = example("compressor-multispeed-noisy.json");
    for objective in ["least_squares", "min_max"] {
        let free = solve(&session, &with(&options, json!({"objective": objective})));
        let plane = free.corrections[0].plane.clone();
        let limit = (0.5 * free.corrections[0].mass_g * 1000.0).round() / 1000.0;
        let s = solve(
            &session,
            &with(
                &options,
                json!({"objective": objective, "max_mass_g": {plane.clone(): limit}}),
            ),
        );
        assert!(
            mass(&s, &plane) <= limit,
            "{objective}: {} > {limit}",
            mass(&s, &plane)
        );
        let binding: Vec<_> = s
            .warnings
            .iter()
            .filter(|w| w.code == "mass_limit_active")
            .collect();
        assert_eq!(binding.len(), 1, "{objective}: {:?}", s.warnings);
        assert_eq!(binding[0].plane.as_deref(), Some(plane.as_str()));
        assert!(
            binding[0].message.contains(&format!("{limit} g")),
            "{}",
            binding[0].message
        );
        // Holding a plane back can only cost: the objective's own measure rises.
        let (before, after) = match objective {
            "min_max" => (free.summary.max_after, s.summary.max_after),
            _ => (free.summary.rms_after, s.summary.rms_after),
        };
        assert!(
            after >= before * (1.0 - 1e-7),
            "{objective}: {after} < {before}"
        );
    }
}

#[test]
fn loose_mass_limits_give_the_unlimited_answer_without_warnings() {
    let (session, options) = example("compressor-multispeed-noisy.json");
    for objective in ["least_squares", "min_max"] {
        let free = solve(&session, &with(&options, json!({"objective": objective})));
        let limits: serde_json::Map<String, Value> = free
            .corrections
            .iter()
            .map(|c| (c.plane.clone(), json!(c.mass_g * 3.0 + 1.0)))
            .collect();
        let s = solve(
            &session,
            &with(
                &options,
                json!({"objective": objective, "max_mass_g": limits}),
            ),
        );
        assert!(
            s.warnings.iter().all(|w| w.code != "mass_limit_active"),
            "{objective}"
        );
        for c in &free.corrections {
            assert!(
                (mass(&s, &c.plane) - c.mass_g).abs() <= 1e-5 * c.mass_g + 1e-9,
                "{objective} {}",
                c.plane
            );
        }
    }
}

#[test]
fn a_heavier_row_weight_lowers_that_sensors_residual_for_both_objectives() {
    let session = rotor(9, 6, 2, 3, 8.0);
    for objective in ["least_squares", "min_max"] {
        let plain = solve(
            &session,
            &with(&SolveOptions::default(), json!({"objective": objective})),
        );
        // The sensor least favoured by the unweighted answer.
        let worst = (0..6)
            .map(|s| format!("S{s}"))
            .max_by(|x, y| {
                sensor_residuals(&plain, x)
                    .iter()
                    .sum::<f64>()
                    .total_cmp(&sensor_residuals(&plain, y).iter().sum())
            })
            .unwrap();
        // Min-max: a weight that makes this sensor dominate the unweighted maximum
        // guarantees its own maximum cannot rise; least squares: any weight > 1.
        let g = (2.0 * plain.summary.max_after
            / sensor_residuals(&plain, &worst)
                .iter()
                .cloned()
                .fold(0.0, f64::max))
        .max(5.0);
        let weighted = solve(
            &session,
            &with(
                &SolveOptions::default(),
                json!({"objective": objective, "row_weights": [{"sensor": worst.clone(), "weight": g}]}),
            ),
        );
        let measure = |s: &Solution| -> f64 {
            let r = sensor_residuals(s, &worst);
            match objective {
                "min_max" => r.iter().cloned().fold(0.0, f64::max),
                _ => r.iter().map(|x| x * x).sum::<f64>().sqrt(),
            }
        };
        if objective == "min_max" {
            // And it is the weighted maximum that was minimised: weighted least
            // squares does no better on it.
            let ls = solve(
                &session,
                &with(
                    &SolveOptions::default(),
                    json!({"row_weights": [{"sensor": worst.clone(), "weight": g}]}),
                ),
            );
            let weighted_max = |s: &Solution| -> f64 {
                s.predicted_residual
                    .iter()
                    .filter(|r| r.used)
                    .map(|r| {
                        if r.sensor == worst {
                            g * r.amplitude
                        } else {
                            r.amplitude
                        }
                    })
                    .fold(0.0, f64::max)
            };
            assert!(
                weighted_max(&weighted) < 0.99 * weighted_max(&ls),
                "{} vs {}",
                weighted_max(&weighted),
                weighted_max(&ls)
            );
        }
        assert!(
            measure(&weighted) < 0.95 * measure(&plain),
            "{objective}: {} vs {}",
            measure(&weighted),
            measure(&plain)
        );
    }
}

#[test]
fn min_max_solves_without_the_dependent_planes_when_asked() {
    let mut session = rotor(2, 5, 2, 3, 1.0);
    // Plane P2's trial moves the rotor almost exactly like P0's, turned by 40°.
    let turn = Complex64::from_polar(1.0, 0.7);
    for a in 0..session.runs[0].readings.len() {
        let y = |r: &fieldbal::balancing::model::Reading| {
            Complex64::from_polar(r.amplitude, r.phase_deg.to_radians())
        };
        let y0 = y(&session.runs[0].readings[a]);
        let d0 = y(&session.runs[1].readings[a]) - y0;
        let t = y0 + d0 * turn * (1.0 + 0.01 * (a as f64).sin());
        session.runs[3].readings[a].amplitude = t.norm();
        session.runs[3].readings[a].phase_deg = t.arg().to_degrees();
    }
    let options = with(
        &SolveOptions::default(),
        json!({"objective": "min_max", "drop_dependent_planes": true}),
    );
    let s = solve(&session, &options);
    let ls = solve(
        &session,
        &with(
            &SolveOptions::default(),
            json!({"drop_dependent_planes": true}),
        ),
    );
    assert_eq!(s.dropped_planes.len(), 1, "{:?}", s.planes);
    assert_eq!(s.dropped_planes, ls.dropped_planes);
    assert!(s.summary.max_after < 0.99 * ls.summary.max_after);
    assert!(s
        .planes
        .iter()
        .any(|p| p.dropped && p.plane == s.dropped_planes[0]));
    assert_eq!(s.corrections.len(), 2);
}

#[test]
fn bad_mass_limits_and_empty_selections_are_rejected_with_the_field_at_fault() {
    let (session, options) = example("pump-two-plane-exact.json");
    let cases: [(&str, Value, &str, &str); 6] = [
        (
            "unknown plane",
            json!({"max_mass_g": {"nowhere": 10}}),
            "unknown_plane",
            "options.max_mass_g.nowhere",
        ),
        (
            "zero grams",
            json!({"max_mass_g": {"inboard": 0}}),
            "invalid_value",
            "options.max_mass_g.inboard",
        ),
        (
            "negative grams",
            json!({"max_mass_g": {"inboard": -5}}),
            "invalid_value",
            "options.max_mass_g.inboard",
        ),
        (
            "unknown plane under min-max",
            json!({"objective": "min_max", "max_mass_g": {"x": 1}}),
            "unknown_plane",
            "options.max_mass_g.x",
        ),
        (
            "every plane excluded",
            json!({"objective": "min_max", "planes": []}),
            "no_planes",
            "options.planes",
        ),
        (
            "every sensor excluded",
            json!({"objective": "min_max", "sensors": []}),
            "no_rows",
            "options.sensors",
        ),
    ];
    for (what, extra, code, field) in cases {
        let err = balancing::solve(&session, &with(&options, extra)).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Invalid, "{what}");
        assert_eq!(
            (err.code, err.field.as_deref()),
            (code, Some(field)),
            "{what}"
        );
    }
    let mut nan = with(&options, json!({}));
    nan.max_mass_g = Some([("inboard".to_string(), f64::NAN)].into());
    let err = balancing::solve(&session, &nan).unwrap_err();
    assert_eq!(err.field.as_deref(), Some("options.max_mass_g.inboard"));
}
