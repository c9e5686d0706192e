//! A trim job is solved with the coefficients its session names (`trim`):
//! the solve, a stored session's solutions, the trial weights and `fieldbal
//! solve` take them when the options give none. The session said where its
//! coefficients were, yet a job with its reference run alone was refused
//! "2 correction planes need at least 2 trial runs" unless the client copied
//! `trim` into the options by hand.

use crate::common;

use common::{binary, example, fresh_server, post, send};
use serde_json::{json, Value};

/// The pump example and the influence coefficients its trial runs give.
async fn pump_and_its_coefficients(client: &reqwest::Client, url: &str) -> (Value, Value) {
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let (status, _, full) = post(client, url, &json!({ "session": session })).await;
    assert_eq!(status, 200, "{full}");
    (session, full)
}

/// The job's reference run alone, with `trim`.
fn trim_job(session: &Value, trim: Value) -> Value {
    let mut job = session.clone();
    job["runs"] = json!([session["runs"][0]]);
    job["trim"] = trim;
    job
}

/// Store `session` and solve it with no options: the solve's status and
/// answer, and where the session is.
async fn store_and_solve(
    client: &reqwest::Client,
    server: &common::Server,
    session: &Value,
) -> (u16, Value, String) {
    let (status, headers, created) = post(client, &server.url("/api/v1/sessions"), session).await;
    assert_eq!(status, 201, "{created}");
    let location = headers["location"].to_str().unwrap().to_string();
    let (status, _, solved) = post(
        client,
        &server.url(&format!("{location}/solutions")),
        &json!({}),
    )
    .await;
    (status, solved, location)
}

fn masses(solution: &Value) -> Vec<(String, f64, f64)> {
    solution["corrections"]
        .as_array()
        .expect("corrections")
        .iter()
        .map(|c| {
            (
                c["plane"].as_str().unwrap().to_string(),
                c["mass_g"].as_f64().unwrap(),
                c["angle_deg"].as_f64().unwrap(),
            )
        })
        .collect()
}

fn assert_same(got: &Value, want: &Value) {
    let (got, want) = (masses(got), masses(want));
    assert_eq!(got.len(), want.len(), "{got:?} {want:?}");
    for ((p, m, a), (q, n, b)) in got.iter().zip(&want) {
        assert_eq!(p, q);
        assert!((m - n).abs() <= 1e-9 * n.max(1.0), "{p}: {m} g, want {n} g");
        let d = (a - b).rem_euclid(360.0);
        assert!(d.min(360.0 - d) <= 1e-7, "{p}: {a}°, want {b}°");
    }
}

#[tokio::test]
async fn a_trim_job_is_solved_with_the_coefficients_it_names() {
    let (_dir, server, client) = fresh_server().await;
    let solve = server.url("/api/v1/solve");
    let (session, full) = pump_and_its_coefficients(&client, &solve).await;
    let job = trim_job(
        &session,
        json!({ "influence_coefficients": full["influence_coefficients"] }),
    );

    // Posted: no options, the trim's coefficients.
    let (status, _, posted) = post(&client, &solve, &json!({ "session": job })).await;
    assert_eq!(status, 200, "{posted}");
    assert_same(&posted, &full);

    // Stored, solved with an empty body.
    let (status, stored, location) = store_and_solve(&client, &server, &job).await;
    assert_eq!(status, 201, "{stored}");
    let solutions = server.url(&format!("{location}/solutions"));
    assert_same(&stored["solution"], &full);

    // The trial weights are sized from them too (no trial run to size from).
    let (status, _, trial) = post(
        &client,
        &server.url("/api/v1/trial-weights"),
        &json!({ "session": job }),
    )
    .await;
    assert_eq!(status, 200, "{trial}");
    for s in trial["suggestions"].as_array().expect("suggestions") {
        assert_eq!(s["basis"], "coefficients", "{s}");
    }

    // Coefficients in the options win over the trim's: twice as sensitive,
    // half the mass.
    let mut doubled = full["influence_coefficients"].clone();
    for c in doubled.as_array_mut().unwrap() {
        c["amplitude_per_g"] = json!(2.0 * c["amplitude_per_g"].as_f64().unwrap());
    }
    let (status, _, given) = post(
        &client,
        &solutions,
        &json!({ "influence_coefficients": doubled }),
    )
    .await;
    assert_eq!(status, 201, "{given}");
    for ((_, m, _), (_, n, _)) in masses(&given["solution"]).iter().zip(&masses(&full)) {
        assert!((m - n / 2.0).abs() <= 1e-9 * n, "{m} g against {n} g / 2");
    }

    // Offline, the same.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("trim.json");
    std::fs::write(&file, job.to_string()).unwrap();
    let (ok, offline) = binary::solve(&[&file]);
    assert!(ok, "{offline}");
    assert_same(&offline, &full);
}

#[tokio::test]
async fn a_trim_job_from_a_machines_coefficients_names_the_version_it_used() {
    let (_dir, server, client) = fresh_server().await;
    let (session, full) = pump_and_its_coefficients(&client, &server.url("/api/v1/solve")).await;
    let (status, _, machine) = post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "PUMP-1", "name": "pump"}),
    )
    .await;
    assert_eq!(status, 201, "{machine}");
    let mut tried = session.clone();
    tried["machine"] = json!("PUMP-1");
    let (status, _, stored) = post(&client, &server.url("/api/v1/sessions"), &tried).await;
    assert_eq!(status, 201, "{stored}");
    let (status, _, version) = post(
        &client,
        &server.url("/api/v1/machines/PUMP-1/coefficients"),
        &json!({"sessions": [stored["id"]]}),
    )
    .await;
    assert_eq!(status, 201, "{version}");

    let job = trim_job(
        &session,
        json!({"coefficients_from": {"machine": "PUMP-1"}}),
    );
    let (status, solved, _) = store_and_solve(&client, &server, &job).await;
    assert_eq!(status, 201, "{solved}");
    assert_same(&solved["solution"], &full);
    assert_eq!(
        solved["solution"]["coefficients_from"],
        json!({"machine": "PUMP-1", "version": 1})
    );

    // A machine that has none: refused naming the trim's field, as
    // `session.trim.…` for the stored session as for the posted one.
    let nowhere = trim_job(
        &session,
        json!({"coefficients_from": {"machine": "NO-SUCH"}}),
    );
    let (status, refused, location) = store_and_solve(&client, &server, &nowhere).await;
    assert_eq!(status, 422, "{refused}");
    assert_eq!(refused["error"]["code"], "unknown_machine", "{refused}");
    assert_eq!(
        refused["error"]["field"], "session.trim.coefficients_from.machine",
        "{refused}"
    );
    let (status, _, refused) = post(
        &client,
        &server.url("/api/v1/solve"),
        &json!({ "session": nowhere }),
    )
    .await;
    assert_eq!(status, 422, "{refused}");
    assert_eq!(
        refused["error"]["field"], "session.trim.coefficients_from.machine",
        "{refused}"
    );
    let (_, _, listed) = send(client.get(server.url(&format!("{location}/solutions")))).await;
    assert_eq!(listed, json!([]), "nothing stored: {listed}");

    // Offline a machine's coefficients cannot be read: said, naming the trim.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("trim.json");
    std::fs::write(&file, job.to_string()).unwrap();
    let (ok, offline) = binary::solve(&[&file]);
    assert!(!ok, "{offline}");
    assert_eq!(
        offline["error"]["code"], "coefficients_unavailable",
        "{offline}"
    );
    assert_eq!(
        offline["error"]["field"], "trim.coefficients_from",
        "{offline}"
    );
}

/// A stored session that cannot be solved names its field as `/solve` does
/// (`session.runs`); such faults had no field, the body being the options.
#[tokio::test]
async fn a_stored_sessions_fault_names_its_field_under_session() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let mut job = session.clone();
    job["runs"] = json!([session["runs"][0]]);
    let (status, refused, _) = store_and_solve(&client, &server, &job).await;
    assert_eq!(status, 422, "{refused}");
    assert_eq!(refused["error"]["code"], "too_few_trial_runs", "{refused}");
    assert_eq!(refused["error"]["field"], "session.runs", "{refused}");
}
