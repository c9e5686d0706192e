//! The identification endpoints through a real server: the textbook's
//! one-mass rotor case posted as a session, the three endpoints answering
//! what `fieldbal identify` prints, and bad input answered with the
//! contract's 4xx errors naming the field.

mod common;
mod identification_support;

use std::process::Command;

use common::{example, post, start_server};
use fieldbal::balancing::model::{Conventions, Unit};
use fieldbal::balancing::phasor::reading_out;
use identification_support::{session, speeds, Jeffcott};
use num_complex::Complex64;
use serde_json::{json, Value};

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
    let dir = tempfile::tempdir().unwrap();
    let (_, server) = start_server(&dir.path().join("t.db")).await;
    let client = reqwest::Client::new();
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

fn free_decay_request() -> Value {
    let samples: Vec<f64> = (0..30)
        .map(|k| (-0.05 * k as f64).exp() * (0.7 * k as f64 + 0.3).cos())
        .collect();
    json!({"samples": samples, "dt_s": 0.05, "damping": "viscous"})
}

fn model_request() -> Value {
    json!({
        "mass": {"fixed": [[2.0, 0.0], [0.0, 1.0]]},
        "stiffness": {"fixed": [[0.0, 0.0], [0.0, 0.0]], "parameters": [[[1.0, 0.0], [0.0, 0.0]], [[1.0, -1.0], [-1.0, 1.0]]]},
        "modes": [{"frequency_hz": 4.11, "shape": [0.4, 0.93]}, {"frequency_hz": 10.3, "shape": [0.66, -0.61]}]
    })
}

#[tokio::test]
async fn each_endpoint_answers_what_the_command_line_prints() {
    let rotor = Jeffcott::with(100.0, 2000.0, 0.05);
    let rotor_request =
        json!({"session": session(&[rotor], &speeds(1000.0, 3000.0, 11), Unit::UmPp, 0.0, 0)});
    let dir = tempfile::tempdir().unwrap();
    let (_, server) = start_server(&dir.path().join("t.db")).await;
    let client = reqwest::Client::new();
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

/// A valid rotor request with `change` applied to it.
fn rotor_with(change: impl FnOnce(&mut Value)) -> Value {
    let rotor = Jeffcott::with(100.0, 2000.0, 0.05);
    let mut v = json!({"session": session(&[rotor], &speeds(1000.0, 3000.0, 5), Unit::UmPp, 0.0, 0), "options": {}});
    change(&mut v);
    v
}

fn with(mut v: Value, change: impl FnOnce(&mut Value)) -> Value {
    change(&mut v);
    v
}

#[tokio::test]
async fn bad_input_is_refused_with_the_field_named() {
    let two_speeds = rotor_with(|v| {
        for run in v["session"]["runs"].as_array_mut().unwrap() {
            run["readings"].as_array_mut().unwrap().truncate(2);
        }
    });
    let cases: Vec<(&str, &str, Value, u16, &str)> = vec![
        (
            "two speeds",
            "rotor",
            two_speeds,
            422,
            "session.runs[0].readings",
        ),
        (
            "range leaves too few speeds",
            "rotor",
            rotor_with(|v| v["options"]["speed_range_rpm"] = json!([900, 1600])),
            422,
            "options.speed_range_rpm",
        ),
        (
            "reversed range",
            "rotor",
            rotor_with(|v| v["options"]["speed_range_rpm"] = json!([3000, 1000])),
            422,
            "options.speed_range_rpm",
        ),
        (
            "unknown sensor",
            "rotor",
            rotor_with(|v| v["options"]["sensors"] = json!(["9V"])),
            422,
            "options.sensors[0]",
        ),
        (
            "negative mass",
            "rotor",
            rotor_with(|v| v["options"]["mass_kg"] = json!(-3)),
            422,
            "options.mass_kg",
        ),
        (
            "known mass, no radius",
            "rotor",
            rotor_with(|v| {
                v["options"]["mass_kg"] = json!(100);
                v["session"]["planes"][0]
                    .as_object_mut()
                    .unwrap()
                    .remove("radius_mm");
            }),
            422,
            "session.planes[0].radius_mm",
        ),
        (
            "negative amplitude",
            "rotor",
            rotor_with(|v| v["session"]["runs"][1]["readings"][0]["amplitude"] = json!(-1)),
            422,
            "session.runs[1].readings[0].amplitude",
        ),
        (
            "no trial run",
            "rotor",
            rotor_with(|v| {
                v["session"]["runs"].as_array_mut().unwrap().pop();
            }),
            422,
            "session.runs",
        ),
        (
            "unknown option",
            "rotor",
            rotor_with(|v| v["options"]["speed_rang_rpm"] = json!([1, 2])),
            400,
            "options.speed_rang_rpm",
        ),
        (
            "seven samples",
            "free-decay",
            with(free_decay_request(), |v| {
                v["samples"].as_array_mut().unwrap().truncate(7);
            }),
            422,
            "samples",
        ),
        (
            "zero step",
            "free-decay",
            with(free_decay_request(), |v| v["dt_s"] = json!(0)),
            422,
            "dt_s",
        ),
        (
            "negative step",
            "free-decay",
            with(free_decay_request(), |v| v["dt_s"] = json!(-0.1)),
            422,
            "dt_s",
        ),
        (
            "NaN sample",
            "free-decay",
            with(free_decay_request(), |v| v["samples"][3] = json!("NaN")),
            422,
            "samples[3]",
        ),
        (
            "all zero",
            "free-decay",
            with(free_decay_request(), |v| {
                v["samples"] = json!(vec![0.0; 12])
            }),
            422,
            "samples",
        ),
        (
            "unknown law",
            "free-decay",
            with(free_decay_request(), |v| v["damping"] = json!("coulomb")),
            422,
            "damping",
        ),
        (
            "non-square",
            "model",
            with(model_request(), |v| v["mass"]["fixed"][1] = json!([1.0])),
            422,
            "mass.fixed[1]",
        ),
        (
            "asymmetric",
            "model",
            with(model_request(), |v| {
                v["stiffness"]["parameters"][1][1][0] = json!(-2.0)
            }),
            422,
            "stiffness.parameters[1][1][0]",
        ),
        (
            "wrong size",
            "model",
            with(model_request(), |v| {
                v["stiffness"]["parameters"][0] = json!([[1.0]])
            }),
            422,
            "stiffness.parameters[0]",
        ),
        (
            "shape too long",
            "model",
            with(model_request(), |v| {
                v["modes"][1]["shape"] = json!([1.0, 2.0, 3.0])
            }),
            422,
            "modes[1].shape",
        ),
        (
            "NaN in a matrix",
            "model",
            with(model_request(), |v| v["mass"]["fixed"][0][0] = json!("NaN")),
            422,
            "mass.fixed[0][0]",
        ),
        (
            "zero frequency",
            "model",
            with(model_request(), |v| {
                v["modes"][0]["frequency_hz"] = json!(0)
            }),
            422,
            "modes[0].frequency_hz",
        ),
        (
            "negative weight",
            "model",
            with(model_request(), |v| v["modes"][0]["weight"] = json!(-1)),
            422,
            "modes[0].weight",
        ),
        (
            "no parameters",
            "model",
            with(model_request(), |v| {
                v["stiffness"]["parameters"] = json!([])
            }),
            422,
            "stiffness.parameters",
        ),
        (
            "initial of wrong length",
            "model",
            with(model_request(), |v| {
                v["initial"] = json!({"stiffness_parameters": [1.0]})
            }),
            422,
            "initial.stiffness_parameters",
        ),
    ];
    let dir = tempfile::tempdir().unwrap();
    let (_, server) = start_server(&dir.path().join("t.db")).await;
    let client = reqwest::Client::new();
    for (name, what, body, want_status, want_field) in cases {
        let (status, _, answer) = post(
            &client,
            &server.url(&format!("/api/v1/identify/{what}")),
            &body,
        )
        .await;
        assert_eq!(status, want_status, "{name}: {answer}");
        assert_eq!(answer["error"]["field"], want_field, "{name}: {answer}");
        assert!(
            answer["error"]["code"].is_string() && answer["error"]["message"].is_string(),
            "{name}: {answer}"
        );
    }
    server.shutdown().await;
}
