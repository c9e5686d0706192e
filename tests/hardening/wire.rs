//! The wire model at the edge: structs posted as positional arrays are
//! refused naming the field; tiny amplitudes never give a non-number; and
//! `fieldbal solve FILE | head` (and every other file command) stops quietly
//! when the pipe closes.

use crate::common;

use std::process::{Command, Stdio};

use common::{example, fresh_server, post};
use serde_json::{json, Value};

#[tokio::test]
async fn structs_posted_as_positional_arrays_are_refused_naming_the_field() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let as_array =
        |v: &Value| -> Value { Value::Array(v.as_object().unwrap().values().cloned().collect()) };
    let mut plane = session.clone();
    plane["planes"][0] = as_array(&session["planes"][0]);
    let mut reading = session.clone();
    reading["runs"][1]["readings"][0] = as_array(&session["runs"][1]["readings"][0]);
    let mut run = session.clone();
    run["runs"][0] = as_array(&session["runs"][0]);
    // (case, path, body, field named)
    let cases: Vec<(&str, &str, Value, Option<&str>)> = vec![
        ("session", "/api/v1/sessions", as_array(&session), None),
        ("plane", "/api/v1/sessions", plane, Some("planes[0]")),
        (
            "reading",
            "/api/v1/sessions",
            reading.clone(),
            Some("runs[1].readings[0]"),
        ),
        ("run", "/api/v1/sessions", run, Some("runs[0]")),
        ("solve request", "/api/v1/solve", json!([session, {}]), None),
        (
            "solve session",
            "/api/v1/solve",
            json!({"session": as_array(&session)}),
            Some("session"),
        ),
        (
            "solve options",
            "/api/v1/solve",
            json!({"session": session, "options": []}),
            Some("options"),
        ),
    ];
    for (case, path, body, field) in cases {
        let (status, _, answer) = post(&client, &server.url(path), &body).await;
        // 422 invalid_type, as for any value of the wrong type (the v1 table
        // already expects that for a session posted as an array).
        assert_eq!(status, 422, "{case}: {answer}");
        assert_eq!(answer["error"]["code"], "invalid_type", "{case}");
        let message = answer["error"]["message"].as_str().unwrap();
        assert!(message.contains("not a list"), "{case}: {message}");
        assert_eq!(answer["error"]["field"].as_str(), field, "{case}");
    }
}

#[tokio::test]
async fn a_null_or_a_number_where_an_object_belongs_is_not_called_an_array() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    for (body, field) in [
        (
            json!({"session": session, "options": null}),
            Some("options"),
        ),
        (json!({"session": session, "options": 5}), Some("options")),
        (json!(null), None),
    ] {
        let (status, _, answer) = post(&client, &server.url("/api/v1/solve"), &body).await;
        assert_eq!(status, 422, "{answer}");
        assert_eq!(answer["error"]["field"].as_str(), field, "{answer}");
        let message = answer["error"]["message"].as_str().unwrap();
        assert!(
            message.starts_with("expected an object, got ") && !message.contains("list"),
            "{message}"
        );
    }
}

/// Every number in `v`, with its path; panics on a null where a number was.
#[tokio::test]
async fn every_request_type_refuses_a_positional_array() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let residual: Value = serde_json::from_str(
        &std::fs::read_to_string("tests/data/residual/left-plane-12-positions.json").unwrap(),
    )
    .unwrap();
    let as_array =
        |v: &Value| -> Value { Value::Array(v.as_object().unwrap().values().cloned().collect()) };
    // (path, body, field named): the body or one of its structs as an array.
    let cases: Vec<(&str, Value, Option<&str>)> = vec![
        ("/api/v1/trial-weights", json!([session, {}]), None),
        (
            "/api/v1/trial-weights",
            json!({"session": session, "options": []}),
            Some("options"),
        ),
        ("/api/v1/residual-unbalance", as_array(&residual), None),
        ("/api/v1/identify/rotor", json!([session, {}]), None),
        (
            "/api/v1/identify/rotor",
            json!({"session": session, "options": []}),
            Some("options"),
        ),
        (
            "/api/v1/identify/free-decay",
            json!([0.001, [1.0, 0.5]]),
            None,
        ),
        ("/api/v1/identify/model", json!([[[1.0]], [[1.0]]]), None),
    ];
    for (path, body, field) in cases {
        let (status, _, answer) = post(&client, &server.url(path), &body).await;
        assert_eq!(status, 422, "{path} {body}: {answer}");
        assert_eq!(answer["error"]["code"], "invalid_type", "{path}");
        let message = answer["error"]["message"].as_str().unwrap();
        assert!(message.contains("not a list"), "{path}: {message}");
        assert_eq!(answer["error"]["field"].as_str(), field, "{path} {body}");
    }
}

#[tokio::test]
async fn the_v2_structs_refuse_a_positional_array_too() {
    // A machine, a runout vector, a supplied coefficient and
    // `coefficients_from` posted as arrays were taken field by field in the
    // order of the Rust struct (`["ID-FAN-3", "fan"]` stored a machine).
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let sensor = session["sensors"][0]["id"].clone();
    let plane = session["planes"][0]["id"].clone();
    let speed = session["runs"][0]["readings"][0]["speed_rpm"].clone();
    let mut runout = session.clone();
    runout["runout"] = json!([[sensor, 12.0, 30.0]]);
    let mut reference_only = session.clone();
    reference_only["runs"].as_array_mut().unwrap().truncate(1);
    let cases: Vec<(&str, Value, Option<&str>)> = vec![
        ("/api/v1/machines", json!(["ID-FAN-3", "fan"]), None),
        (
            "/api/v1/solve",
            json!({"session": runout}),
            Some("session.runout[0]"),
        ),
        (
            "/api/v1/solve",
            json!({"session": reference_only,
                   "options": {"influence_coefficients": [[speed, sensor, plane, 2.0, 180.0]]}}),
            Some("options.influence_coefficients[0]"),
        ),
        (
            "/api/v1/solve",
            json!({"session": session, "options": {"coefficients_from": ["ID-FAN-3"]}}),
            Some("options.coefficients_from"),
        ),
    ];
    for (path, body, field) in cases {
        let (status, _, answer) = post(&client, &server.url(path), &body).await;
        assert_eq!(status, 422, "{path} {body}: {answer}");
        assert_eq!(answer["error"]["code"], "invalid_type", "{path}");
        let message = answer["error"]["message"].as_str().unwrap();
        assert!(message.contains("not a list"), "{path}: {message}");
        assert_eq!(answer["error"]["field"].as_str(), field, "{path} {body}");
    }
}

fn assert_no_null(v: &Value, path: &str) {
    match v {
        Value::Null => panic!("null at {path}"),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .for_each(|(i, x)| assert_no_null(x, &format!("{path}[{i}]"))),
        Value::Object(o) => o
            .iter()
            .for_each(|(k, x)| assert_no_null(x, &format!("{path}.{k}"))),
        _ => {}
    }
}

#[tokio::test]
async fn tiny_amplitudes_never_give_a_non_number() {
    let (_dir, server, client) = fresh_server().await;
    for name in [
        "pump-two-plane-exact.json",
        "compressor-multispeed-noisy.json",
    ] {
        for scale in [1e-7, 1e-100, 1e-300, 1e100] {
            let mut session = example(name)["session"].clone();
            for run in session["runs"].as_array_mut().unwrap() {
                for r in run["readings"].as_array_mut().unwrap() {
                    let a = r["amplitude"].as_f64().unwrap();
                    r["amplitude"] = json!(a * scale);
                    for s in r["samples"].as_array_mut().into_iter().flatten() {
                        let a = s["amplitude"].as_f64().unwrap();
                        s["amplitude"] = json!(a * scale);
                    }
                }
            }
            let (status, _, answer) = post(
                &client,
                &server.url("/api/v1/solve"),
                &json!({"session": session}),
            )
            .await;
            match status {
                200 => assert_no_null(&answer, "solution"),
                422 => assert!(answer["error"]["field"].is_string(), "{answer}"),
                _ => panic!("{name} × {scale}: {status} {answer}"),
            }
        }
    }
}

/// Run the binary with `args`, its standard output's read end closed at
/// once (like `head` after its lines: every write then meets a closed
/// pipe); its exit and standard error.
fn run_into_a_closed_pipe(args: &[impl AsRef<std::ffi::OsStr>]) -> (std::process::Output, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out, stderr)
}

#[test]
fn solve_piped_into_a_closed_reader_exits_quietly() {
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/examples/compressor-multispeed-noisy.json"
    );
    let (out, stderr) = run_into_a_closed_pipe(&["solve", file]);
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(out.status.code(), Some(0), "{stderr}");
}

/// `residual`, `coefficients` and `identify` print their answers as `solve`
/// does: a reader that closed the pipe (`| head`) is no crash. They printed
/// with `println!`, which panicked (exit 101) on the closed pipe (session 21).
#[test]
fn every_file_command_piped_into_a_closed_reader_exits_quietly() {
    let data = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data");
    let dir = tempfile::tempdir().unwrap();
    let model = dir.path().join("model.json");
    std::fs::write(
        &model,
        json!({
            "mass": {"fixed": [[2.0, 0.0], [0.0, 1.0]], "parameters": []},
            "stiffness": {"fixed": [[0.0, 0.0], [0.0, 0.0]],
                          "parameters": [[[1.0, 0.0], [0.0, 0.0]], [[1.0, -1.0], [-1.0, 1.0]]]},
            "modes": [{"frequency_hz": 4.007338783024648, "shape": [0.5, 0.8]},
                      {"frequency_hz": 7.7415840504266225, "shape": [0.4, -1.1]}]
        })
        .to_string(),
    )
    .unwrap();
    let model = model.to_str().unwrap().to_string();
    let cases: Vec<(&str, Vec<String>)> = vec![
        (
            "residual",
            vec![
                "residual".into(),
                format!("{data}/residual/left-plane-12-positions.json"),
            ],
        ),
        (
            "coefficients",
            vec![
                "coefficients".into(),
                format!("{data}/examples/pump-two-plane-exact.json"),
            ],
        ),
        (
            "identify model",
            vec!["identify".into(), "model".into(), model],
        ),
        // An error body goes to the same closed pipe.
        (
            "residual error",
            vec![
                "residual".into(),
                format!("{data}/examples/pump-two-plane-exact.json"),
            ],
        ),
    ];
    for (name, args) in cases {
        let (out, stderr) = run_into_a_closed_pipe(&args);
        assert!(!stderr.contains("panicked"), "{name}: {stderr}");
        assert!(
            matches!(out.status.code(), Some(0) | Some(2)),
            "{name}: {:?} {stderr}",
            out.status
        );
    }
}

#[test]
fn solve_piped_into_head_prints_the_first_lines() {
    let bin = env!("CARGO_BIN_EXE_fieldbal");
    let file = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/examples/compressor-multispeed-noisy.json"
    );
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!("'{bin}' solve '{file}' | head -n 2"))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.starts_with('{'), "{stdout}");
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
}
