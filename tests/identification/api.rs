//! The identification endpoints through a real server: the textbook's
//! one-mass rotor case posted as a session, the three endpoints answering
//! what `fieldbal identify` prints (bad input: `errors.rs`).

use crate::common;
use crate::support;

use std::process::Command;

use common::{example, fresh_server, post};
use fieldbal::balancing::model::{Conventions, Unit};
use fieldbal::balancing::phasor::reading_out;
use num_complex::Complex64;
use serde_json::{json, Value};
use support::{free_decay_request, model_request, session, speeds, Jeffcott};

/// The textbook's second case (m = 10 kg, e = 1e-4 m, q = 0.5 b ω) as a
/// session: a 10 g trial weight at 0° on a 100 mm radius is its unbalance
/// D = m·e = 1e-3 kg·m; a still reference run; the responses in µm pk-pk.
fn textbook_rotor_request(case: &Value) -> Value {
    let conv = Conventions::default();
    let readings: Vec<Value> = case["readings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let z = Complex64::new(r["Zr"].as_f64().unwrap(), r["Zi"].as_f64().unwrap());
            let (amplitude, phase_deg) = reading_out(conv, z / 0.5e-6);
            let rpm = r["w"].as_f64().unwrap() * 30.0 / std::f64::consts::PI;
            json!({"speed_rpm": rpm, "sensor": "1H", "amplitude": amplitude, "phase_deg": phase_deg})
        })
        .collect();
    let still: Vec<Value> = readings
        .iter()
        .map(|r| json!({"speed_rpm": r["speed_rpm"], "sensor": "1H", "amplitude": 0.0, "phase_deg": 0.0}))
        .collect();
    json!({
        "session": {
            "name": "textbook one-mass rotor",
            "planes": [{"id": "A", "radius_mm": 100}],
            "sensors": [{"id": "1H", "unit": "um_pp"}],
            "runs": [
                {"id": "zero", "weights": [], "readings": still},
                {"id": "trial", "weights": [{"plane": "A", "mass_g": 10, "angle_deg": 0}], "readings": readings}
            ]
        },
        "options": {"mass_kg": case["known"]["m"], "cross_coupling_ratio": 0.5, "unbalance_angle": "at_weight"}
    })
}

#[tokio::test]
async fn the_textbooks_one_mass_rotor_case_is_reproduced_through_the_endpoint() {
    let file = example("textbook-regression.json");
    let case = file["cases"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["known"]["e"].is_number())
        .expect("the rotor case");
    let (_dir, server, client) = fresh_server().await;
    let (status, _, body) = post(
        &client,
        &server.url("/api/v1/identify/rotor"),
        &textbook_rotor_request(case),
    )
    .await;
    assert_eq!(status, 200, "{body}");
    let r = &body["results"][0];
    let published = &case["published_estimate"];
    for (got, want) in [
        (&r["stiffness_n_per_m"], &published["c"]),
        (&r["damping_n_s_per_m"], &published["b"]),
    ] {
        let (g, w) = (got.as_f64().unwrap(), want.as_f64().unwrap());
        assert!((g - w).abs() <= 5e-5 * w, "{g} vs published {w}: {body}");
    }
    server.shutdown().await;
}

fn cli(what: &str, request: &Value) -> (bool, Value) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("request.json");
    std::fs::write(&path, serde_json::to_vec(request).unwrap()).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["identify", what])
        .arg(&path)
        .output()
        .unwrap();
    (
        out.status.success(),
        serde_json::from_slice(&out.stdout).unwrap(),
    )
}

#[tokio::test]
async fn each_endpoint_answers_what_the_command_line_prints() {
    let rotor = Jeffcott::with(100.0, 2000.0, 0.05);
    let rotor_request =
        json!({"session": session(&[rotor], &speeds(1000.0, 3000.0, 11), Unit::UmPp, 0.0, 0)});
    let (_dir, server, client) = fresh_server().await;
    for (what, request) in [
        ("rotor", rotor_request),
        ("free-decay", free_decay_request()),
        ("model", model_request()),
    ] {
        let (status, _, body) = post(
            &client,
            &server.url(&format!("/api/v1/identify/{what}")),
            &request,
        )
        .await;
        assert_eq!(status, 200, "{what}: {body}");
        let (ok, printed) = cli(what, &request);
        assert!(ok, "{what}: {printed}");
        assert_eq!(printed, body, "{what}");
    }
    server.shutdown().await;
}
