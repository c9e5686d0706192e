//! Machines through the real server on a temporary SQLite file: create (409 on
//! a taken id), list in pages, read with sessions and coefficient versions,
//! pool sessions into versions (never colliding), solve a new job from stored
//! coefficients, and every error naming its field.

mod ids;
mod sessions_page;

use crate::common;
use crate::job_support;

use common::{fresh_server, post, send, store_solution};
use fieldbal::balancing::model::Conventions;
use fieldbal::balancing::phasor::{angle_diff_deg, weight_out};
use job_support::*;
use serde_json::{json, Value};

fn job_session(rotor: &Rotor, machine: &str, trials: bool, seed: u64) -> Value {
    let conv = Conventions::default();
    let mut n = if seed == 0 {
        Noise::none()
    } else {
        Noise::new(1.0, 1.0, seed)
    };
    let mut s = session(conv, opening_runs(rotor, conv, trials, &mut n));
    s["machine"] = json!(machine);
    s
}

async fn store(client: &reqwest::Client, server: &common::Server, s: &Value) -> String {
    let (status, _, created) = post(client, &server.url("/api/v1/sessions"), s).await;
    assert_eq!(status, 201, "{created}");
    created["id"].as_str().unwrap().to_string()
}

fn error_of(body: &Value) -> (&str, Option<&str>) {
    (
        body["error"]["code"].as_str().unwrap_or(""),
        body["error"]["field"].as_str(),
    )
}

#[tokio::test]
async fn a_machine_is_created_once_listed_in_pages_and_deleted_without_its_sessions() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/machines");
    let body = json!({"id": "ID-FAN-3", "name": "ID fan 3",
        "rotor": {"mass_kg": 420, "service_speed_rpm": 1480, "balance_grade": "G6.3"}, "notes": "coupling end"});
    let (status, headers, created) = post(&client, &url, &body).await;
    assert_eq!(status, 201, "{created}");
    assert_eq!(headers["location"], "/api/v1/machines/ID-FAN-3");
    assert_eq!(created["rotor"]["mass_kg"].as_f64(), Some(420.0));
    assert_eq!(created["rotor"]["balance_grade"], "G6.3");
    let (status, _, dup) = post(&client, &url, &json!({"id": "ID-FAN-3", "name": "again"})).await;
    assert_eq!(status, 409);
    assert_eq!(error_of(&dup), ("duplicate_id", Some("id")));

    for k in 0..4 {
        let (status, _, _) = post(
            &client,
            &url,
            &json!({"id": format!("M{k}"), "name": "pump"}),
        )
        .await;
        assert_eq!(status, 201);
    }
    let (status, _, page) = send(client.get(server.url("/api/v1/machines?limit=2"))).await;
    assert_eq!(status, 200);
    assert_eq!(page["total"], 5);
    let ids: Vec<&str> = page["machines"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| m["id"].as_str().unwrap())
        .collect();
    assert_eq!(ids, ["M3", "M2"]);
    let (_, _, last) = send(client.get(server.url("/api/v1/machines?limit=2&offset=4"))).await;
    assert_eq!(last["machines"][0]["id"], "ID-FAN-3");
    assert_eq!(last["machines"].as_array().unwrap().len(), 1);
    for (query, field) in [
        ("limit=0", "limit"),
        ("limit=1001", "limit"),
        ("offset=-1", "offset"),
    ] {
        let (status, _, err) =
            send(client.get(server.url(&format!("/api/v1/machines?{query}")))).await;
        assert_eq!((status, error_of(&err).1), (422, Some(field)), "{query}");
    }

    let session = store(
        &client,
        &server,
        &job_session(&Rotor::new(), "ID-FAN-3", true, 0),
    )
    .await;
    let (status, _, _) = send(client.delete(server.url("/api/v1/machines/ID-FAN-3"))).await;
    assert_eq!(status, 204);
    let (status, _, err) = send(client.get(server.url("/api/v1/machines/ID-FAN-3"))).await;
    assert_eq!((status, error_of(&err).0), (404, "not_found"));
    let (status, _, _) = send(client.delete(server.url("/api/v1/machines/ID-FAN-3"))).await;
    assert_eq!(status, 404);
    let (status, _, _) = send(client.get(server.url(&format!("/api/v1/sessions/{session}")))).await;
    assert_eq!(status, 200, "a machine's deletion keeps its sessions");
}

#[tokio::test]
async fn invalid_machines_are_rejected_naming_the_field() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/machines");
    let long = "x".repeat(65);
    let cases = [
        (json!({"id": "", "name": "a"}), 422, "invalid_value", "id"),
        (json!({"id": long, "name": "a"}), 422, "invalid_value", "id"),
        (
            json!({"id": "M", "name": " "}),
            422,
            "invalid_value",
            "name",
        ),
        (
            json!({"id": "M", "name": "a", "rotor": {"mass_kg": 1, "service_speed_rpm": 1, "balance_grade": "G7"}}),
            422,
            "invalid_value",
            "rotor.balance_grade",
        ),
        (
            json!({"id": "M", "name": "a", "rotor": {"mass_kg": -1, "service_speed_rpm": 1, "balance_grade": "G1"}}),
            422,
            "invalid_value",
            "rotor.mass_kg",
        ),
        (
            json!({"id": "M", "name": "a", "colour": "red"}),
            400,
            "unknown_field",
            "colour",
        ),
        (json!({"name": "a"}), 422, "missing_field", "id"),
    ];
    for (body, status, code, field) in cases {
        let (got, _, err) = post(&client, &url, &body).await;
        assert_eq!(
            (got, error_of(&err)),
            (status, (code, Some(field))),
            "{body}"
        );
    }
    let (_, _, list) = send(client.get(url)).await;
    assert_eq!(list["total"], 0, "nothing half-stored");
}

#[tokio::test]
async fn a_new_job_with_only_its_reference_run_is_trimmed_from_the_machines_stored_coefficients() {
    let (_dir, server, client) = fresh_server().await;
    let rotor = Rotor::new();
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "ID-FAN-3", "name": "ID fan 3"}),
    )
    .await;
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "OTHER", "name": "other"}),
    )
    .await;
    let s1 = store(&client, &server, &job_session(&rotor, "ID-FAN-3", true, 31)).await;
    let s2 = store(&client, &server, &job_session(&rotor, "ID-FAN-3", true, 32)).await;
    let other = store(&client, &server, &job_session(&rotor, "OTHER", true, 33)).await;
    let solved = store_solution(&client, &server, &s1).await;

    let (status, _, m) = send(client.get(server.url("/api/v1/machines/ID-FAN-3"))).await;
    assert_eq!(status, 200);
    let sessions = m["sessions"].as_array().unwrap();
    assert_eq!(sessions.len(), 2);
    assert_eq!(sessions[0]["id"], s1.as_str());
    assert_eq!(sessions[0]["runs"], 3);
    assert_eq!(sessions[0]["summary"], solved["solution"]["summary"]);
    assert!(sessions[1].get("summary").is_none());
    assert_eq!(m["coefficients"], json!([]));

    let url = server.url("/api/v1/machines/ID-FAN-3/coefficients");
    let (status, _, err) = send(client.get(&url)).await;
    assert_eq!(status, 404, "no version yet: {err}");
    let (status, _, v1) = post(&client, &url, &json!({"sessions": [s1, s2]})).await;
    assert_eq!(status, 201, "{v1}");
    assert_eq!(v1["version"], 1);
    assert_eq!(v1["machine"], "ID-FAN-3");
    assert_eq!(v1["sessions"], json!([s1, s2]));
    assert_eq!(v1["influence_coefficients"].as_array().unwrap().len(), 8);
    let (_, _, v2) = post(&client, &url, &json!({"sessions": [s2]})).await;
    assert_eq!(v2["version"], 2);
    let (status, _, latest) = send(client.get(&url)).await;
    assert_eq!((status, latest["version"].clone()), (200, json!(2)));
    let (_, _, first) = send(client.get(format!("{url}?version=1"))).await;
    assert_eq!(
        first["influence_coefficients"],
        v1["influence_coefficients"]
    );
    assert!(first["created_at"].is_string());
    let (_, _, m) = send(client.get(server.url("/api/v1/machines/ID-FAN-3"))).await;
    let versions: Vec<i64> = m["coefficients"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["version"].as_i64().unwrap())
        .collect();
    assert_eq!(versions, [1, 2]);

    // The new job: its reference run only, solved from version 1.
    let conv = Conventions::default();
    let new_job = job_session(&rotor, "ID-FAN-3", false, 0);
    let body = json!({"session": new_job, "options": {"coefficients_from": {"machine": "ID-FAN-3", "version": 1}}});
    let (status, _, sol) = post(&client, &server.url("/api/v1/solve"), &body).await;
    assert_eq!(status, 200, "{sol}");
    assert_eq!(
        sol["coefficients_from"],
        json!({"machine": "ID-FAN-3", "version": 1})
    );
    let best = rotor.optimum();
    for (j, p) in PLANES.iter().enumerate() {
        let c = sol["corrections"]
            .as_array()
            .unwrap()
            .iter()
            .find(|c| c["plane"] == *p)
            .unwrap();
        let u = &c["uncertainty"];
        let (m, a) = weight_out(conv, best[j]);
        let (lo, hi) = (
            u["mass_g"][0].as_f64().unwrap(),
            u["mass_g"][1].as_f64().unwrap(),
        );
        assert!(lo <= m && m <= hi, "{p}: exact {m} g outside [{lo}, {hi}]");
        let (alo, ahi) = (
            u["angle_deg"][0].as_f64().unwrap(),
            u["angle_deg"][1].as_f64().unwrap(),
        );
        assert!(
            angle_diff_deg(a, (alo + ahi) / 2.0) <= (ahi - alo) / 2.0,
            "{p}: exact {a}° outside [{alo}, {ahi}]"
        );
    }
    // Latest by default, also for a stored session's solution.
    let id = store(&client, &server, &new_job).await;
    let (status, _, stored) = post(
        &client,
        &server.url(&format!("/api/v1/sessions/{id}/solutions")),
        &json!({"coefficients_from": {"machine": "ID-FAN-3"}}),
    )
    .await;
    assert_eq!(status, 201, "{stored}");
    assert_eq!(stored["solution"]["coefficients_from"]["version"], 2);

    // A rotor that changed (coefficients 30 % off): its trial runs disagree.
    let changed = job_session(&rotor.scaled(1.3), "ID-FAN-3", true, 34);
    let body =
        json!({"session": changed, "options": {"coefficients_from": {"machine": "ID-FAN-3"}}});
    let (status, _, sol) = post(&client, &server.url("/api/v1/solve"), &body).await;
    assert_eq!(status, 200, "{sol}");
    let codes: Vec<&str> = sol["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["code"].as_str().unwrap())
        .collect();
    assert!(codes.contains(&"coefficients_disagree"), "{codes:?}");
    // The machine's stored coefficients are not called "supplied" (session 21).
    let disagree = sol["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| w["code"] == "coefficients_disagree")
        .unwrap()["message"]
        .as_str()
        .unwrap();
    assert!(
        disagree.contains("stored for its machine") && !disagree.contains("the supplied"),
        "{disagree}"
    );
    // Pooled with the others, that session is named and can be left out.
    let s3 = store(&client, &server, &changed).await;
    let (_, _, v3) = post(&client, &url, &json!({"sessions": [s1, s2, s3]})).await;
    assert!(
        v3["warnings"][0]["message"].as_str().unwrap().contains(&s3),
        "{v3}"
    );
    let (status, _, v4) = post(
        &client,
        &url,
        &json!({"sessions": [s1, s2, s3], "options": {"exclude_disagreeing": true}}),
    )
    .await;
    assert_eq!(status, 201);
    assert_eq!(v4["sessions"], json!([s1, s2]));
    assert_eq!(v4["excluded"], json!([s3]));

    // Errors: unknown machine, version, session, a session of another machine, run id.
    let ghost = "00000000-0000-0000-0000-000000000000";
    let cases: Vec<(String, Value, u16, &str, Option<&str>)> = vec![
        (
            server.url("/api/v1/machines/NOPE/coefficients"),
            json!({"sessions": [s1]}),
            404,
            "not_found",
            None,
        ),
        (
            url.clone(),
            json!({"sessions": [s1, ghost]}),
            422,
            "unknown_session",
            Some("sessions[1]"),
        ),
        (
            url.clone(),
            json!({"sessions": [s1, other]}),
            422,
            "other_machine",
            Some("sessions[1]"),
        ),
        (
            url.clone(),
            json!({"sessions": [s1, s1]}),
            422,
            "duplicate_id",
            Some("sessions[1]"),
        ),
        (
            url.clone(),
            json!({"sessions": []}),
            422,
            "invalid_value",
            Some("sessions"),
        ),
        (
            url.clone(),
            json!({"sessions": [s1], "options": {"exclude": true}}),
            400,
            "unknown_field",
            Some("options.exclude"),
        ),
        (
            server.url("/api/v1/solve"),
            json!({"session": new_job, "options": {"coefficients_from": {"machine": "NOPE"}}}),
            422,
            "unknown_machine",
            Some("options.coefficients_from.machine"),
        ),
        (
            server.url("/api/v1/solve"),
            json!({"session": new_job, "options": {"coefficients_from": {"machine": "ID-FAN-3", "version": 99}}}),
            422,
            "unknown_version",
            Some("options.coefficients_from.version"),
        ),
        (
            server.url("/api/v1/solve"),
            json!({"session": new_job, "options": {"coefficients_from": {"machine": "OTHER"}}}),
            422,
            "unknown_version",
            Some("options.coefficients_from.machine"),
        ),
        (
            server.url("/api/v1/solve"),
            json!({"session": new_job, "options": {"coefficients_from": {"machine": "ID-FAN-3"}, "influence_coefficients": []}}),
            422,
            "conflicting_options",
            Some("options.influence_coefficients"),
        ),
        (
            server.url("/api/v1/solve"),
            json!({"session": new_job, "options": {"coefficients_from": {"machine": "ID-FAN-3"}, "from_run": "check"}}),
            422,
            "unknown_run",
            Some("options.from_run"),
        ),
        (
            server.url(&format!("/api/v1/sessions/{id}/solutions")),
            json!({"coefficients_from": {"machine": "NOPE"}}),
            422,
            "unknown_machine",
            Some("coefficients_from.machine"),
        ),
        (
            server.url(&format!("/api/v1/sessions/{s1}/solutions")),
            json!({"from_run": "nope"}),
            422,
            "unknown_run",
            Some("from_run"),
        ),
    ];
    for (u, body, status, code, field) in cases {
        let (got, _, err) = post(&client, &u, &body).await;
        assert_eq!((got, error_of(&err)), (status, (code, field)), "{u} {body}");
    }
    for (query, status, field) in [
        ("?version=99", 404, Some("version")),
        ("?version=x", 400, Some("version")),
    ] {
        let (got, _, err) = send(client.get(format!("{url}{query}"))).await;
        assert_eq!((got, error_of(&err).1), (status, field), "{query}: {err}");
    }
    let (status, _, _) = send(client.get(server.url("/api/v1/machines/NOPE/coefficients"))).await;
    assert_eq!(status, 404);
}

#[tokio::test]
async fn versions_pooled_at_the_same_time_are_consecutive_and_never_collide() {
    let (_dir, server, client) = fresh_server().await;
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "M", "name": "m"}),
    )
    .await;
    let s = store(&client, &server, &job_session(&Rotor::new(), "M", true, 41)).await;
    let url = server.url("/api/v1/machines/M/coefficients");
    let posts = (0..8).map(|_| {
        let (client, url, s) = (client.clone(), url.clone(), s.clone());
        tokio::spawn(async move { post(&client, &url, &json!({"sessions": [s]})).await })
    });
    let mut versions = Vec::new();
    for p in posts {
        let (status, _, body) = p.await.unwrap();
        assert_eq!(status, 201, "{body}");
        versions.push(body["version"].as_i64().unwrap());
    }
    versions.sort_unstable();
    assert_eq!(versions, (1..=8).collect::<Vec<i64>>());
}

#[tokio::test]
async fn the_openapi_document_lists_the_machine_endpoints() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    for path in [
        "/api/v1/machines",
        "/api/v1/machines/{id}",
        "/api/v1/machines/{id}/coefficients",
    ] {
        assert!(doc["paths"].get(path).is_some(), "{path} missing");
    }
}

/// Each solved job on the machine's page says the unit of its before/after
/// figures: the one unit of the sensors its latest solution summarised
/// (`unit`), or `null` with `units` listing them when they differ. The page
/// fetched every job's whole session to read its sensors' units, one request
/// per job.
#[tokio::test]
async fn a_machines_jobs_say_the_unit_of_their_summary() {
    let (_dir, server, client) = fresh_server().await;
    let rotor = Rotor::new();
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "ID-FAN-3"}),
    )
    .await;
    let mut mils = job_session(&rotor, "ID-FAN-3", true, 41);
    for sensor in mils["sensors"].as_array_mut().unwrap() {
        sensor["unit"] = json!("mils_pp");
    }
    let mut mixed = job_session(&rotor, "ID-FAN-3", true, 42);
    mixed["sensors"][1]["unit"] = json!("mm_s_rms");
    let in_mils = store(&client, &server, &mils).await;
    let both = store(&client, &server, &mixed).await;
    let one_of_both = store(&client, &server, &mixed).await;
    let unsolved = store(&client, &server, &mils).await;
    store_solution(&client, &server, &in_mils).await;
    let solved = store_solution(&client, &server, &both).await;
    let codes: Vec<&str> = solved["solution"]["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|w| w["code"].as_str())
        .collect();
    assert!(codes.contains(&"mixed_units"), "{solved}");
    // Solved first over both sensors, then (the latest) over the second alone:
    // the summary is over that one sensor, in its unit.
    store_solution(&client, &server, &one_of_both).await;
    let url = server.url(&format!("/api/v1/sessions/{one_of_both}/solutions"));
    let (status, _, latest) =
        post(&client, &url, &json!({"sensors": ["2H"], "planes": ["A"]})).await;
    assert_eq!(status, 201, "{latest}");

    let (status, _, m) = send(client.get(server.url("/api/v1/machines/ID-FAN-3"))).await;
    assert_eq!(status, 200, "{m}");
    let entry = |id: &str| {
        m["sessions"]
            .as_array()
            .unwrap()
            .iter()
            .find(|s| s["id"] == id)
            .unwrap_or_else(|| panic!("{id} listed: {m}"))
            .clone()
    };
    let jobs = [
        (&in_mils, json!("mils_pp"), json!(["mils_pp"])),
        (&both, Value::Null, json!(["um_pp", "mm_s_rms"])),
        (&one_of_both, json!("mm_s_rms"), json!(["mm_s_rms"])),
    ];
    for (id, unit, units) in jobs {
        let job = entry(id);
        assert!(job["summary"].is_object(), "{job}");
        assert_eq!(job.get("unit"), Some(&unit), "{job}");
        assert_eq!(job["units"], units, "{job}");
    }
    assert_eq!(
        entry(&one_of_both)["summary"],
        latest["solution"]["summary"]
    );
    let job = entry(&unsolved);
    for key in ["summary", "unit", "units"] {
        assert!(job.get(key).is_none(), "no solution, no {key}: {job}");
    }
}

/// A session holding only its reference run adds nothing to a pool (no trial
/// to difference against it), yet was listed among the version's sessions
/// with no word, as if its readings had been used (qa22 noticed). The
/// version now warns `no_trial_runs` naming it; the coefficients are those
/// of the other sessions alone.
#[tokio::test]
async fn a_session_without_trial_runs_in_a_pool_is_named_as_adding_nothing() {
    let (_dir, server, client) = fresh_server().await;
    let rotor = Rotor::new();
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "M-REF"}),
    )
    .await;
    let full = store(&client, &server, &job_session(&rotor, "M-REF", true, 41)).await;
    let reference = store(&client, &server, &job_session(&rotor, "M-REF", false, 42)).await;
    let url = server.url("/api/v1/machines/M-REF/coefficients");
    let (status, _, alone) = post(&client, &url, &json!({"sessions": [full]})).await;
    assert_eq!(status, 201, "{alone}");
    assert!(
        alone["warnings"]
            .as_array()
            .is_none_or(|w| w.iter().all(|x| x["code"] != "no_trial_runs")),
        "{alone}"
    );
    let (status, _, both) = post(&client, &url, &json!({"sessions": [full, reference]})).await;
    assert_eq!(status, 201, "{both}");
    let said: Vec<&Value> = both["warnings"]
        .as_array()
        .into_iter()
        .flatten()
        .filter(|x| x["code"] == "no_trial_runs")
        .collect();
    assert_eq!(said.len(), 1, "{both}");
    assert!(
        said[0]["message"].as_str().unwrap().contains(&reference),
        "names the session: {both}"
    );
    assert_eq!(
        both["influence_coefficients"], alone["influence_coefficients"],
        "the same coefficients as without it"
    );
}

/// A session that names no machine, listed in a machine's pool, is refused
/// saying so and how to fix it; the message called it a session of machine
/// '(none)', which reads as a machine with that id.
#[tokio::test]
async fn a_session_naming_no_machine_is_refused_saying_it_names_none() {
    let (_dir, server, client) = fresh_server().await;
    let rotor = Rotor::new();
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "M-N"}),
    )
    .await;
    let mut loose = job_session(&rotor, "M-N", true, 0);
    loose.as_object_mut().unwrap().remove("machine");
    let loose = store(&client, &server, &loose).await;
    let url = server.url("/api/v1/machines/M-N/coefficients");
    let (status, _, body) = post(&client, &url, &json!({"sessions": [loose]})).await;
    assert_eq!(status, 422, "{body}");
    assert_eq!(error_of(&body), ("other_machine", Some("sessions[0]")));
    let message = body["error"]["message"].as_str().unwrap();
    assert!(
        message.contains("names no machine")
            && message.contains("'M-N'")
            && !message.contains("(none)"),
        "{message}"
    );
}

/// A machine's name that is refused says why: blank, or how long it is
/// (both read "a name of 1 to 200 characters, or no name at all", which a
/// name of two spaces has).
#[tokio::test]
async fn a_refused_machine_name_says_why() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/machines");
    for (name, said) in [("  ", "blank"), (&*"n".repeat(201), "201")] {
        let (status, _, err) = post(&client, &url, &json!({"id": "M", "name": name})).await;
        assert_eq!(
            (status, error_of(&err)),
            (422, ("invalid_value", Some("name")))
        );
        let message = err["error"]["message"].as_str().unwrap();
        assert!(
            message.contains(said) && message.contains("200"),
            "{message}"
        );
    }
}
