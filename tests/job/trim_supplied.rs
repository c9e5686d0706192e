//! Trim from the state of a run (`from_run`) with supplied or stored
//! coefficients (`influence_coefficients`, `coefficients_from`;
//! docs/session-format.md "v2 additions"), on noise-free runs of the exact
//! rotor of tests/job/support.rs, where the answer is known by construction: the
//! weights to add are what the supplied `W` implies for the rebased state,
//! `C = −W⁺ Y_r` (method 3.2 with `Y_r` the run's readings), and `total` is
//! `T_r + C`; the solution echoes `from_run` and the coefficients' source; the
//! supplied covariance widens the uncertainty by exactly what a
//! finite-difference propagation through the solve itself gives; an unknown
//! run is named. Through the core API and through the service (a machine's
//! stored coefficients).

use crate::common;
use crate::support;

use crate::trim_support;

use common::{fresh_server, post, send};
use fieldbal::balancing::model::Conventions;
use fieldbal::balancing::Solution;
use nalgebra::Matrix2;
use num_complex::Complex64;
use serde_json::json;
use support::*;
use trim_support::*;

#[test]
fn the_trim_adds_what_the_supplied_coefficients_imply_for_the_state_of_the_run() {
    let rotor = Rotor::new();
    let best = rotor.optimum();
    let other = skewed(&rotor.w);
    for conv in Conventions::ALL {
        let t = internal(conv, &on_weights(&rotor, conv));
        for trials in [false, true] {
            let s = trim_session(&rotor, conv, trials);
            for (w, exact) in [(&rotor.w, true), (&other, false)] {
                let options = json!({"from_run": "check",
                    "influence_coefficients": supplied(w, conv, |_, _| None),
                    "coefficients_from": {"machine": "ID-FAN-3", "version": 2}});
                let sol = solve_json(&s, options);
                let (add, total_) = implied(&rotor, w, &t);
                assert_trim(conv, &sol, &add, &total_);
                assert_eq!(sol.from_run.as_deref(), Some("check"));
                assert_eq!(
                    serde_json::to_value(&sol.coefficients_from).unwrap(),
                    json!({"machine": "ID-FAN-3", "version": 2})
                );
                // The coefficients reported are the supplied ones.
                assert_eq!(sol.influence_coefficients.len(), 8);
                for (k, c) in sol.influence_coefficients.iter().enumerate() {
                    let got = phasor(conv, c.amplitude_per_g, c.phase_deg);
                    assert!(near(got, w[(k / 2, k % 2)], 1.0), "{conv:?} {c:?}");
                }
                // The predicted vibration is the run's readings plus `w C`.
                let predicted = rotor.response(&t) + w * &add;
                for (a, r) in sol.predicted_residual.iter().enumerate() {
                    let m = predicted[a].norm();
                    assert!(
                        (r.amplitude - m).abs() <= 1e-9 * predicted.norm(),
                        "row {a}"
                    );
                }
                if exact {
                    // The rotor's own coefficients: `total` is the one-shot optimum.
                    for (j, p) in PLANES.iter().enumerate() {
                        assert!(near(total(conv, &sol, p), best[j], best.norm()), "{p}");
                    }
                    let codes: Vec<&str> = sol.warnings.iter().map(|w| w.code.as_str()).collect();
                    assert!(!codes.contains(&"coefficients_disagree"), "{codes:?}");
                    if trials {
                        let checks = sol.run_checks.as_ref().expect("run checks");
                        assert!(checks.iter().all(|c| c.consistent), "{checks:?}");
                    }
                }
            }
        }
    }
}

#[test]
fn the_supplied_covariance_widens_the_trim_uncertainty_as_propagated_through_the_solve() {
    let rotor = Rotor::new();
    // Correlated, each coefficient's own size: (4 % of |W|)² scaled.
    let cov = |a: usize, j: usize| {
        let v = (0.04 * rotor.w[(a, j)].norm()).powi(2);
        Some([[v, 0.4 * v], [0.4 * v, 0.7 * v]])
    };
    for conv in Conventions::ALL {
        let s = trim_session(&rotor, conv, false);
        let bare = supplied(&rotor.w, conv, |_, _| None);
        let without = trim_with(&s, &bare);
        let with = trim_with(&s, &supplied(&rotor.w, conv, cov));
        // d(correction vector)/d(Re, Im of each supplied coefficient, wire
        // frame) by central differences through the whole trim solve.
        let h = 1e-5;
        let mut expected = [Matrix2::zeros(); 2];
        for (k, c) in bare.as_array().unwrap().iter().enumerate() {
            let z = Complex64::from_polar(
                c["amplitude_per_g"].as_f64().unwrap(),
                c["phase_deg"].as_f64().unwrap().to_radians(),
            );
            let mut jac = [Matrix2::zeros(); 2];
            for (col, dz) in [Complex64::new(h, 0.0), Complex64::new(0.0, h)]
                .into_iter()
                .enumerate()
            {
                let moved = |sign: f64| {
                    let mut list = bare.clone();
                    let z = z + dz * sign;
                    list[k]["amplitude_per_g"] = json!(z.norm());
                    list[k]["phase_deg"] = json!(z.arg().to_degrees());
                    trim_with(&s, &list)
                };
                let (plus, minus) = (moved(1.0), moved(-1.0));
                for (p, jp) in jac.iter_mut().enumerate() {
                    let d = (vector(&plus, p) - vector(&minus, p)) / (2.0 * h);
                    jp[(0, col)] = d.re;
                    jp[(1, col)] = d.im;
                }
            }
            let m = cov(k / 2, k % 2).unwrap();
            let sigma = Matrix2::new(m[0][0], m[0][1], m[1][0], m[1][1]);
            for p in 0..2 {
                expected[p] += jac[p] * sigma * jac[p].transpose();
            }
        }
        for (p, e) in expected.iter().enumerate() {
            let (a, b) = (covariance(&without, p), covariance(&with, p));
            // Theirs is a large share here, so the comparison can fail.
            assert!(e.trace() > 0.5 * a.trace(), "{conv:?} {p}: {e} vs {a}");
            assert!(
                (b - a - e).norm() <= 1e-6 * e.norm(),
                "{conv:?} plane {p}: with − without {} vs propagated {e}",
                b - a
            );
            let width = |s: &Solution| {
                let m = s.corrections[p]
                    .uncertainty
                    .as_ref()
                    .unwrap()
                    .mass_g
                    .unwrap();
                m[1] - m[0]
            };
            assert!(width(&with) > width(&without), "{conv:?} {p}");
        }
        // The predicted vibration's bound includes `dW C` too.
        for (a, (rw, ro)) in with
            .predicted_residual
            .iter()
            .zip(&without.predicted_residual)
            .enumerate()
        {
            assert!(
                rw.amplitude_95.unwrap() > ro.amplitude_95.unwrap(),
                "{conv:?} row {a}"
            );
        }
    }
}

#[test]
fn with_supplied_coefficients_an_unknown_from_run_or_a_missing_coefficient_names_its_field() {
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let s: fieldbal::balancing::Session =
        serde_json::from_value(trim_session(&rotor, conv, true)).unwrap();
    let exact = supplied(&rotor.w, conv, |_, _| None);
    let mut missing = exact.clone();
    missing.as_array_mut().unwrap().remove(5);
    // Finite but past anything readings could give: 1e300 unit/g made the
    // SVD's singular values NaN and the solver panic (a 500 before session 14).
    let mut huge = exact.clone();
    huge[3]["amplitude_per_g"] = json!(1e300);
    let mut huge_cov = exact.clone();
    huge_cov[2]["covariance"] = json!([[1e300, 0.0], [0.0, 1e300]]);
    let cases = [
        (
            json!({"from_run": "no such run", "influence_coefficients": exact}),
            "unknown_run",
            "options.from_run",
        ),
        (
            json!({"from_run": "no such run", "influence_coefficients": exact,
                   "coefficients_from": {"machine": "ID-FAN-3", "version": 1}}),
            "unknown_run",
            "options.from_run",
        ),
        (
            json!({"from_run": "check", "influence_coefficients": missing}),
            "missing_coefficient",
            "options.influence_coefficients",
        ),
        (
            json!({"from_run": "check", "influence_coefficients": huge}),
            "invalid_value",
            "options.influence_coefficients[3].amplitude_per_g",
        ),
        (
            json!({"from_run": "check", "influence_coefficients": huge_cov}),
            "invalid_value",
            "options.influence_coefficients[2].covariance",
        ),
    ];
    for (o, code, field) in cases {
        let options = serde_json::from_value(o.clone()).unwrap();
        let err = fieldbal::balancing::solve(&s, &options).unwrap_err();
        assert_eq!((err.code, err.field.as_deref()), (code, Some(field)), "{o}");
    }
}

#[tokio::test]
async fn a_trim_from_a_machines_stored_coefficients_through_the_service() {
    let (_dir, server, client) = fresh_server().await;
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let (status, _, m) = post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "ID-FAN-3", "name": "ID fan 3"}),
    )
    .await;
    assert_eq!(status, 201, "{m}");
    // Two noise-free sessions with trials pool into version 1.
    let mut ids = Vec::new();
    for _ in 0..2 {
        let s = session(
            conv,
            first_runs(&rotor, conv, &mut Noise::none(), &NO_RUNOUT, 0.0),
        );
        let (status, _, created) = post(&client, &server.url("/api/v1/sessions"), &s).await;
        assert_eq!(status, 201, "{created}");
        ids.push(created["id"].as_str().unwrap().to_string());
    }
    let url = server.url("/api/v1/machines/ID-FAN-3/coefficients");
    let (status, _, v1) = post(&client, &url, &json!({"sessions": ids})).await;
    assert_eq!(status, 201, "{v1}");
    let (_, _, stored) = send(client.get(&url)).await;
    let list = stored["influence_coefficients"].clone();
    let w = matrix_of(&list, conv);
    assert!(
        (&w - &rotor.w).norm() <= 1e-9 * rotor.w.norm(),
        "noise-free pooling is exact"
    );

    let trim = trim_session(&rotor, conv, false);
    let body = json!({"session": trim,
        "options": {"from_run": "check", "coefficients_from": {"machine": "ID-FAN-3"}}});
    let (status, _, answer) = post(&client, &server.url("/api/v1/solve"), &body).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["from_run"], "check");
    assert_eq!(
        answer["coefficients_from"],
        json!({"machine": "ID-FAN-3", "version": 1})
    );
    let sol: Solution = serde_json::from_value(answer).unwrap();
    let t = internal(conv, &on_weights(&rotor, conv));
    let (add, total_) = implied(&rotor, &w, &t);
    assert_trim(conv, &sol, &add, &total_);
    // The stored covariance is in the uncertainty: the core's answer with the
    // stored list supplied, not the one with its covariances left out.
    let core = trim_with(&trim, &list);
    let mut bare = list.clone();
    for c in bare.as_array_mut().unwrap() {
        c.as_object_mut()
            .unwrap()
            .remove("covariance")
            .expect("stored with covariance");
    }
    let without = trim_with(&trim, &bare);
    for p in 0..2 {
        let (got, same, less) = (
            covariance(&sol, p),
            covariance(&core, p),
            covariance(&without, p),
        );
        assert!(
            (got - same).norm() <= 1e-12 * same.norm(),
            "{p}: {got} vs {same}"
        );
        assert!(got.trace() > less.trace(), "{p}: {got} vs {less}");
    }

    // An unknown run is named, in the solve's body and in a stored session's.
    let body = json!({"session": trim,
        "options": {"from_run": "nope", "coefficients_from": {"machine": "ID-FAN-3"}}});
    let (status, _, err) = post(&client, &server.url("/api/v1/solve"), &body).await;
    assert_eq!(
        (status, &err["error"]["code"], &err["error"]["field"]),
        (422, &json!("unknown_run"), &json!("options.from_run")),
        "{err}"
    );
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &trim).await;
    let solutions = server.url(&format!(
        "/api/v1/sessions/{}/solutions",
        created["id"].as_str().unwrap()
    ));
    let (status, _, stored) = post(
        &client,
        &solutions,
        &json!({"from_run": "check", "coefficients_from": {"machine": "ID-FAN-3"}}),
    )
    .await;
    assert_eq!(status, 201, "{stored}");
    assert_eq!(stored["solution"]["from_run"], "check");
    assert_eq!(stored["solution"]["coefficients_from"]["version"], 1);
    let (status, _, err) = post(
        &client,
        &solutions,
        &json!({"from_run": "nope", "coefficients_from": {"machine": "ID-FAN-3"}}),
    )
    .await;
    assert_eq!(
        (status, &err["error"]["code"], &err["error"]["field"]),
        (422, &json!("unknown_run"), &json!("from_run")),
        "{err}"
    );
}

#[tokio::test]
async fn stored_coefficients_in_another_unit_than_the_sessions_sensor_are_refused() {
    // A machine's coefficients pooled from sessions reading in µm pk-pk, used
    // by a new job whose set-up reads the same sensor in mils: the correction
    // came out 25.4 times off without a word. Pooled coefficients carry
    // their sensor's unit, and `coefficients_from` refuses a mismatch.
    let (_dir, server, client) = fresh_server().await;
    let rotor = Rotor::new();
    let conv = Conventions::default();
    let (status, _, m) = post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "ID-FAN-3", "name": "ID fan 3"}),
    )
    .await;
    assert_eq!(status, 201, "{m}");
    let s = session(
        conv,
        first_runs(&rotor, conv, &mut Noise::none(), &NO_RUNOUT, 0.0),
    );
    let (status, _, created) = post(&client, &server.url("/api/v1/sessions"), &s).await;
    assert_eq!(status, 201, "{created}");
    let url = server.url("/api/v1/machines/ID-FAN-3/coefficients");
    let (status, _, v1) = post(&client, &url, &json!({"sessions": [created["id"]]})).await;
    assert_eq!(status, 201, "{v1}");
    for c in v1["influence_coefficients"].as_array().unwrap() {
        assert_eq!(c["unit"], "um_pp", "{c}");
    }

    let mut trim = trim_session(&rotor, conv, false);
    let sensor = trim["sensors"][1]["id"].clone();
    trim["sensors"][1]["unit"] = json!("mils_pp");
    let body = json!({"session": trim, "options": {"coefficients_from": {"machine": "ID-FAN-3"}}});
    let (status, _, err) = post(&client, &server.url("/api/v1/solve"), &body).await;
    assert_eq!(
        (status, &err["error"]["code"], &err["error"]["field"]),
        (
            422,
            &json!("unit_mismatch"),
            &json!("options.coefficients_from")
        ),
        "{err}"
    );
    let message = err["error"]["message"].as_str().unwrap();
    assert!(
        message.contains(sensor.as_str().unwrap()) && message.contains("mils_pp"),
        "{message}"
    );

    // Supplied with their unit, the same list is refused naming the entry.
    let list = v1["influence_coefficients"].clone();
    let s: fieldbal::balancing::Session = serde_json::from_value(trim).unwrap();
    let options = serde_json::from_value(json!({"influence_coefficients": list})).unwrap();
    let err = fieldbal::balancing::solve(&s, &options).unwrap_err();
    assert_eq!(err.code, "unit_mismatch", "{err:?}");
    assert!(
        err.field.as_deref().is_some_and(
            |f| f.starts_with("options.influence_coefficients[") && f.ends_with("].unit")
        ),
        "{err:?}"
    );
}
