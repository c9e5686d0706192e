//! What a job and its runs are, as clients record them (docs/session-format.md,
//! "What a job and its runs are"): a run's `purpose` and a trim job's `trim`
//! are stored and given back unchanged, through the session and the run
//! endpoints, and refused naming the field where they mean nothing; a machine
//! may be stored without a name and is then given back without one.

use crate::common;

use common::{example, fresh_server, post, send};
use serde_json::{json, Value};

fn error_of(body: &Value) -> (&str, Option<&str>) {
    (
        body["error"]["code"].as_str().unwrap_or(""),
        body["error"]["field"].as_str(),
    )
}

#[tokio::test]
async fn run_purposes_and_a_trim_are_stored_and_given_back_unchanged() {
    let (_dir, server, client) = fresh_server().await;
    let mut session = example("pump-two-plane-exact.json")["session"].clone();
    // A trim naming a machine's coefficients is stored and given back as it
    // is (solving it reads them: tests/api/store/trim_jobs.rs).
    let mut trimmed = session.clone();
    trimmed["trim"] = json!({"coefficients_from": {"machine": "PUMP-1", "version": 2}});
    let (status, headers, created) = post(&client, &server.url("/api/v1/sessions"), &trimmed).await;
    assert_eq!(status, 201, "{created}");
    let (_, _, back) = send(client.get(server.url(headers["location"].to_str().unwrap()))).await;
    let back = back.get("session").cloned().unwrap_or(back);
    assert_eq!(back["trim"], trimmed["trim"], "{back}");

    session["runs"][1]["purpose"] = json!("trial");
    // A check run named as a trial: the purpose says what it is.
    session["runs"][2]["purpose"] = json!("check");
    session["runs"][2]["id"] = json!("trial again");
    let (status, headers, created) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    assert_eq!(status, 201, "{created}");
    let location = headers["location"].to_str().unwrap().to_string();
    let (status, _, back) = send(client.get(server.url(&location))).await;
    assert_eq!(status, 200);
    let back = back.get("session").cloned().unwrap_or(back);
    assert_eq!(back["runs"][0].get("purpose"), None, "{back}");
    assert_eq!(back["runs"][1]["purpose"], "trial");
    assert_eq!(back["runs"][2]["purpose"], "check");

    // A run appended with its purpose reads back with it, alone too.
    let mut check = session["runs"][2].clone();
    check["id"] = json!("check 2");
    let runs = server.url(&format!("{location}/runs"));
    let (status, _, added) = post(&client, &runs, &check).await;
    assert_eq!(status, 201, "{added}");
    let (status, _, run) = send(client.get(format!("{runs}/check%202"))).await;
    assert_eq!(status, 200, "{run}");
    assert_eq!(run["purpose"], "check", "{run}");

    // The solve does not read the purposes: the same answer as without them.
    let url = server.url(&format!("{location}/solutions"));
    let (status, _, with) = post(&client, &url, &json!({})).await;
    assert_eq!(status, 201, "{with}");
    let mut plain = session.clone();
    for r in plain["runs"].as_array_mut().unwrap() {
        r.as_object_mut().unwrap().remove("purpose");
    }
    plain["runs"]
        .as_array_mut()
        .unwrap()
        .push(json!({"id": "check 2", "weights": check["weights"], "readings": check["readings"]}));
    let (status, _, without) = post(
        &client,
        &server.url("/api/v1/solve"),
        &json!({"session": plain}),
    )
    .await;
    assert_eq!(status, 200, "{without}");
    assert_eq!(with["solution"]["corrections"], without["corrections"]);
    // A trim from a check run's state: that run is the rebased reference.
    let (status, _, trim) = post(&client, &url, &json!({"from_run": "check 2"})).await;
    assert_eq!(status, 201, "{trim}");
    assert_eq!(trim["solution"]["from_run"], "check 2");

    // Supplied coefficients are a trim too.
    let mut supplied = trimmed.clone();
    supplied["trim"] = json!({"influence_coefficients": [
        {"speed_rpm": 2950.0, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1.5, "phase_deg": 40.0}]});
    let (status, headers, created) =
        post(&client, &server.url("/api/v1/sessions"), &supplied).await;
    assert_eq!(status, 201, "{created}");
    let (_, _, back) = send(client.get(server.url(headers["location"].to_str().unwrap()))).await;
    let back = back.get("session").cloned().unwrap_or(back);
    assert_eq!(back["trim"], supplied["trim"]);
}

/// A change to the example session that makes it wrong.
type Change = Box<dyn Fn(&mut Value)>;

#[tokio::test]
async fn a_purpose_or_trim_that_means_nothing_is_refused_naming_its_field() {
    let (_dir, server, client) = fresh_server().await;
    let base = example("pump-two-plane-exact.json")["session"].clone();
    let cases: Vec<(Change, u16, &str, &str)> = vec![
        (
            Box::new(|s| s["runs"][0]["purpose"] = json!("check")),
            422,
            "invalid_value",
            "runs[0].purpose",
        ),
        (
            Box::new(|s| s["runs"][1]["purpose"] = json!("probe")),
            422,
            "invalid_type",
            "runs[1].purpose",
        ),
        (
            Box::new(|s| s["trim"] = json!({})),
            422,
            "invalid_value",
            "trim",
        ),
        (
            Box::new(|s| {
                s["trim"] =
                    json!({"coefficients_from": {"machine": "M"}, "influence_coefficients": []})
            }),
            422,
            "invalid_value",
            "trim",
        ),
        (
            Box::new(|s| s["trim"] = json!({"coefficients_from": {"machine": ""}})),
            422,
            "invalid_value",
            "trim.coefficients_from.machine",
        ),
        (
            Box::new(|s| s["trim"] = json!({"coefficients_from": {"machine": "M", "version": 0}})),
            422,
            "out_of_range",
            "trim.coefficients_from.version",
        ),
        (
            Box::new(|s| s["trim"] = json!({"influence_coefficients": []})),
            422,
            "invalid_value",
            "trim.influence_coefficients",
        ),
        (
            Box::new(|s| {
                s["trim"] = json!({"influence_coefficients": [
                    {"speed_rpm": 2950, "sensor": "DE-H", "plane": "middle", "amplitude_per_g": 1, "phase_deg": 0}]})
            }),
            422,
            "invalid_value",
            "trim.influence_coefficients[0].plane",
        ),
        (
            Box::new(|s| {
                s["trim"] = json!({"influence_coefficients": [
                    {"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": -1, "phase_deg": 0}]})
            }),
            422,
            "invalid_value",
            "trim.influence_coefficients[0].amplitude_per_g",
        ),
        (
            // Below what any reading resolves, as the solve option refuses it.
            Box::new(|s| {
                s["trim"] = json!({"influence_coefficients": [
                    {"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1e-300, "phase_deg": 0}]})
            }),
            422,
            "invalid_value",
            "trim.influence_coefficients[0].amplitude_per_g",
        ),
    ];
    for (change, want_status, want_code, want_field) in cases {
        let mut s = base.clone();
        change(&mut s);
        let (status, _, body) = post(&client, &server.url("/api/v1/sessions"), &s).await;
        assert_eq!(status, want_status, "{want_field}: {body}");
        let (code, field) = error_of(&body);
        assert_eq!(code, want_code, "{body}");
        assert_eq!(field, Some(want_field), "{body}");
    }
    let list = send(client.get(server.url("/api/v1/sessions"))).await.2;
    assert_eq!(list["total"], 0, "nothing refused was stored: {list}");
}

#[tokio::test]
async fn a_machine_without_a_name_is_given_back_without_one() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/machines");
    let (status, _, created) = post(&client, &url, &json!({"id": "FAN-7"})).await;
    assert_eq!(status, 201, "{created}");
    assert_eq!(created.get("name"), None, "{created}");
    let (_, _, read) = send(client.get(server.url("/api/v1/machines/FAN-7"))).await;
    assert_eq!(read.get("name"), None, "{read}");
    let (_, _, list) = send(client.get(&url)).await;
    assert_eq!(list["machines"][0]["id"], "FAN-7");
    assert_eq!(list["machines"][0].get("name"), None, "{list}");
    // A name given is still one that says something.
    let (status, _, body) = post(&client, &url, &json!({"id": "FAN-8", "name": " "})).await;
    assert_eq!(status, 422, "{body}");
    assert_eq!(error_of(&body), ("invalid_value", Some("name")));
}
