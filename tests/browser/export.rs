//! End-to-end test of the form's exports: the session typed into the form
//! comes back as exactly the example's JSON (with each trial run's purpose), and the readings and results as CSV.

use crate::common;

use crate::harness::form::{self, type_run, type_setup};
use crate::harness::Browser;
use serde_json::Value;

/// Where two JSON values differ, numbers compared as f64 (`30` and `30.0` are the same number).
fn difference(a: &Value, b: &Value, path: &str) -> Option<String> {
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            (x.as_f64() != y.as_f64()).then(|| format!("{path}: {x} != {y}"))
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => x
            .iter()
            .zip(y)
            .enumerate()
            .find_map(|(i, (x, y))| difference(x, y, &format!("{path}[{i}]"))),
        (Value::Object(x), Value::Object(y)) if x.len() == y.len() => {
            x.iter().find_map(|(k, v)| {
                y.get(k).map_or_else(
                    || Some(format!("{path}.{k}: missing")),
                    |w| difference(v, w, &format!("{path}.{k}")),
                )
            })
        }
        _ => (a != b).then(|| format!("{path}: {a} != {b}")),
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_typed_session_exports_as_the_same_json_and_its_readings_and_results_as_csv() {
    let dir = tempfile::tempdir().expect("temporary directory");
    let (_, server) = common::start_server(&dir.path().join("export.db")).await;
    let b = Browser::start().await;
    b.client
        .goto(&server.url("/"))
        .await
        .expect("the form loads");
    let example = common::example("pump-two-plane-exact.json");
    let session = &example["session"];
    type_setup(&b, session).await;
    b.click("#step-setup button.next").await;
    for k in 0..session["runs"].as_array().unwrap().len() {
        type_run(&b, session, k, false).await;
    }
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    form::corrections_on_page(&b).await;

    b.click("nav [data-step=\"sessions\"]").await;
    b.click("button.export-json").await;
    let exported: Value =
        serde_json::from_slice(&b.downloaded("pump-two-plane-exact.json").await).expect("JSON");
    // The example as typed, with what each run is: the form stores the
    // trial runs' purpose (a check run may be named anything).
    let mut typed = session.clone();
    for run in typed["runs"].as_array_mut().unwrap() {
        if !run["weights"].as_array().unwrap().is_empty() {
            run["purpose"] = serde_json::json!("trial");
        }
    }
    assert_eq!(
        difference(&exported, &typed, "session"),
        None,
        "the exported session is the example, number for number"
    );

    b.click("button.export-readings").await;
    let readings =
        String::from_utf8(b.downloaded("pump-two-plane-exact-readings.csv").await).unwrap();
    let lines: Vec<&str> = readings.lines().collect();
    assert_eq!(
        lines.len(),
        1 + 3 * 4,
        "a header and a line per run and sensor:\n{readings}"
    );
    assert!(
        lines[0].starts_with("\"run\",\"weights (angles with_rotation)\",\"speed_rpm\""),
        "{}",
        lines[0]
    );
    assert!(lines[1].contains("\"465.37419496698874\""), "{}", lines[1]);

    b.click("button.export-results").await;
    let results =
        String::from_utf8(b.downloaded("pump-two-plane-exact-results.csv").await).unwrap();
    let corrections: Vec<&str> = results
        .lines()
        .filter(|l| l.starts_with("\"correction\""))
        .collect();
    assert_eq!(corrections.len(), 2, "{results}");
    assert!(
        corrections[0].starts_with("\"correction\",\"inboard\",\"\",\"29.99"),
        "{}",
        corrections[0]
    );
    assert_eq!(
        results
            .lines()
            .filter(|l| l.starts_with("\"residual\""))
            .count(),
        4
    );

    // A trial weight weighed to the milligram, at an angle read to the
    // hundredth of a degree: the readings file has them as stored (it gave
    // the grid header's one decimal, 12.3 g at 123.5°).
    let mut precise = session.clone();
    precise["name"] = serde_json::json!("precise trial");
    precise["runs"][1]["weights"][0] =
        serde_json::json!({"plane": "inboard", "mass_g": 12.345, "angle_deg": 123.45});
    let (status, _, created) = common::post(
        &reqwest::Client::new(),
        &server.url("/api/v1/sessions"),
        &precise,
    )
    .await;
    assert_eq!(status, 201, "{created}");
    let id = created["id"].as_str().expect("stored");
    b.open_fresh(&server.url(&format!("/#session={id}&step=solve")))
        .await;
    b.wait_for("#step-solve button.solve").await;
    b.click("nav [data-step=\"sessions\"]").await;
    b.click("button.export-readings").await;
    let readings = String::from_utf8(b.downloaded("precise-trial-readings.csv").await).unwrap();
    let trial: Vec<&str> = readings
        .lines()
        .filter(|l| {
            l.starts_with(&format!(
                "\"{}\"",
                precise["runs"][1]["id"].as_str().unwrap()
            ))
        })
        .collect();
    assert!(!trial.is_empty(), "{readings}");
    for line in trial {
        assert!(
            line.contains("\"inboard: 12.345 g at 123.45°\""),
            "the weight as stored: {line}"
        );
    }
    b.close().await;
    server.shutdown().await;
}
