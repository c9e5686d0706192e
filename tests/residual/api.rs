//! The residual-unbalance check through the real server and the command line
//! (issue 17), and the ISO 21940-11 verdict of a stored session's solution.

use crate::common;
use crate::support;

use common::{example, fresh_server, post, store_solution};
use fieldbal::balancing::acceptance::check;
use fieldbal::balancing::model::Conventions;
use serde_json::{json, Value};
use support::{allowable, request, Rotor};

fn body(phases: bool) -> Value {
    let rotor = Rotor::new(180.0, 250.0, Conventions::ALL[3]);
    serde_json::to_value(request(&rotor, 1.5 * allowable(), 12, phases, Some(7))).unwrap()
}

#[tokio::test]
async fn the_server_answers_the_same_check_as_the_core_with_and_without_phases() {
    let (_dir, server, client) = fresh_server().await;
    for phases in [true, false] {
        let b = body(phases);
        let (status, _, got) = post(&client, &server.url("/api/v1/residual-unbalance"), &b).await;
        assert_eq!(status, 200, "{got}");
        let want = check(&serde_json::from_value(b).unwrap()).unwrap();
        assert_eq!(got, serde_json::to_value(&want).unwrap());
        assert_eq!(
            got["method"],
            if phases {
                "circle_fit"
            } else {
                "amplitude_fit"
            }
        );
        assert!(got["worksheet"]["residual_unbalance_gmm"].is_number());
        assert_eq!(
            got["conventions"],
            json!({"phase": "lead", "angle_direction": "with_rotation"})
        );
    }
    server.shutdown().await;
}

#[tokio::test]
async fn bad_checks_get_the_contracts_error_naming_the_field() {
    let (_dir, server, client) = fresh_server().await;
    let with = |f: &dyn Fn(&mut Value)| {
        let mut b = body(true);
        f(&mut b);
        b
    };
    #[rustfmt::skip]
    let cases: Vec<(&str, Value, u16, &str, &str)> = vec![
        ("three positions", with(&|b| { b["readings"].as_array_mut().unwrap().truncate(3); }), 422, "too_few_positions", "readings"),
        ("not equally spaced", with(&|b| b["readings"][7]["angle_deg"] = json!(200.5)), 422, "positions_not_equally_spaced", "readings[7].angle_deg"),
        ("the first position off", with(&|b| b["readings"][0]["angle_deg"] = json!(7.0)), 422, "positions_not_equally_spaced", "readings[0].angle_deg"),
        ("zero load", with(&|b| b["journal_load_kg"] = json!(0)), 422, "invalid_value", "journal_load_kg"),
        ("negative speed", with(&|b| b["speed_rpm"] = json!(-3000)), 422, "invalid_value", "speed_rpm"),
        ("negative trial mass", with(&|b| b["trial"]["mass_g"] = json!(-2)), 422, "invalid_value", "trial.mass_g"),
        ("a string for a phase", with(&|b| b["readings"][1]["phase_deg"] = json!("NaN")), 422, "invalid_type", "readings[1].phase_deg"),
        ("unknown field", with(&|b| b["readings"][0]["phase_dg"] = json!(3)), 400, "unknown_field", "readings[0].phase_dg"),
        ("missing trial", with(&|b| { b.as_object_mut().unwrap().remove("trial"); }), 422, "missing_field", "trial"),
        // Numbers past these ranges were answered 200 with `null` where the
        // result overflowed (fuzzing, session 15).
        ("huge amplitude", with(&|b| b["readings"][4]["amplitude"] = json!(1e300)), 422, "invalid_value", "readings[4].amplitude"),
        ("subnormal speed", with(&|b| b["speed_rpm"] = json!(1e-320)), 422, "invalid_value", "speed_rpm"),
        ("subnormal journal load", with(&|b| b["journal_load_kg"] = json!(1e-320)), 422, "invalid_value", "journal_load_kg"),
        ("huge trial mass", with(&|b| b["trial"]["mass_g"] = json!(1e300)), 422, "invalid_value", "trial.mass_g"),
        ("huge trial radius", with(&|b| b["trial"]["radius_mm"] = json!(1e300)), 422, "invalid_value", "trial.radius_mm"),
        ("subnormal repeatability", with(&|b| b["phase_noise_deg"] = json!(1e-320)), 422, "invalid_value", "phase_noise_deg"),
        ("huge first angle", with(&|b| b["readings"][0]["angle_deg"] = json!(1.7e308)), 422, "invalid_value", "readings[0].angle_deg"),
    ];
    for (name, b, status, code, field) in cases {
        let (got_status, _, got) =
            post(&client, &server.url("/api/v1/residual-unbalance"), &b).await;
        assert_eq!(got_status, status, "{name}: {got}");
        assert_eq!(got["error"]["code"], code, "{name}: {got}");
        assert_eq!(got["error"]["field"], field, "{name}: {got}");
    }
    let (status, _, doc) = common::send(client.get(server.url("/api/v1/openapi.json"))).await;
    assert_eq!(status, 200);
    assert!(doc["paths"]["/api/v1/residual-unbalance"]["post"].is_object());
    server.shutdown().await;
}

#[tokio::test]
async fn a_stored_session_with_a_rotor_ends_with_an_iso_verdict_per_plane() {
    let (_dir, server, client) = fresh_server().await;
    let mut session = example("pump-two-plane-exact.json")["session"].clone();
    session["rotor"] = json!({"mass_kg": 420, "service_speed_rpm": 1480, "balance_grade": "G6.3"});
    let (status, _, stored) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    assert_eq!(status, 201, "{stored}");
    let id = stored["id"].as_str().unwrap();
    let sol = store_solution(&client, &server, id).await;
    let iso = &sol["solution"]["iso_21940"];
    let share = iso["permissible_per_plane_gmm"].as_f64().unwrap();
    let planes = iso["planes"].as_array().unwrap_or_else(|| panic!("{iso}"));
    let corrections = sol["solution"]["corrections"].as_array().unwrap();
    assert_eq!(planes.len(), corrections.len());
    for (v, c) in planes.iter().zip(corrections) {
        let u = v["residual_unbalance_gmm"].as_f64().unwrap();
        assert!((u - c["unbalance_gmm"].as_f64().unwrap()).abs() < 1e-9 * u.max(1.0));
        assert_eq!(v["pass"].as_bool().unwrap(), u <= share);
        let after = v["after_correction_95_gmm"].as_f64().unwrap();
        assert_eq!(
            v["after_correction_pass"].as_bool().unwrap(),
            after <= share
        );
    }
    let all = planes.iter().all(|v| v["pass"].as_bool().unwrap());
    assert_eq!(iso["pass"].as_bool(), Some(all));
    server.shutdown().await;
}

#[test]
fn the_command_line_checks_a_file_and_refuses_a_bad_one_with_status_2() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.json");
    std::fs::write(&good, body(true).to_string()).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["residual", good.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success());
    let got: Value = serde_json::from_slice(&out.stdout).unwrap();
    let want = check(&serde_json::from_value(body(true)).unwrap()).unwrap();
    assert_eq!(got, serde_json::to_value(&want).unwrap());

    let bad = dir.path().join("bad.json");
    let mut b = body(false);
    b["speed_rpm"] = json!(0);
    std::fs::write(&bad, b.to_string()).unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["residual", bad.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(err["error"]["field"], "speed_rpm");
}
