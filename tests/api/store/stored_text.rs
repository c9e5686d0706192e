//! Strings a client sends to be stored or looked up, answered alike on both
//! engines: a NUL (which PostgreSQL's text cannot hold: it answered 500 where
//! SQLite stored it) or another control character is refused with 422 naming
//! the field; a lookup by such a key finds nothing (404, or the field's 422),
//! never a 500; and what was stored before these rules stays readable and
//! writable. Timestamps, the strings the service stores itself, have one
//! form on both.

use crate::common;

use common::{example, fresh_server, path_segment, post, send, start_server};
use serde_json::{json, Value};

fn error_of(body: &Value) -> (&str, Option<&str>) {
    (
        body["error"]["code"].as_str().unwrap_or(""),
        body["error"]["field"].as_str(),
    )
}

fn pump() -> Value {
    example("pump-two-plane-exact.json")["session"].clone()
}

#[tokio::test]
async fn control_characters_in_stored_strings_are_refused_naming_the_field() {
    let (_dir, server, client) = fresh_server().await;
    let nul = "\u{0}";
    type Edit = fn(&mut Value, &str);
    let cases: [(&str, Edit); 7] = [
        ("name", |s, c| s["name"] = json!(format!("pump{c}"))),
        ("machine", |s, c| s["machine"] = json!(format!("P-1{c}"))),
        ("runs[1].id", |s, c| {
            s["runs"][1]["id"] = json!(format!("trial{c}"))
        }),
        ("planes[0].id", |s, c| {
            let id = format!("inboard{c}");
            s["planes"][0]["id"] = json!(id);
            for r in s["runs"].as_array_mut().unwrap() {
                for w in r["weights"].as_array_mut().unwrap() {
                    if w["plane"] == "inboard" {
                        w["plane"] = json!(id);
                    }
                }
            }
        }),
        ("sensors[0].id", |s, c| {
            let id = format!("DE-H{c}");
            s["sensors"][0]["id"] = json!(id);
            for r in s["runs"].as_array_mut().unwrap() {
                for x in r["readings"].as_array_mut().unwrap() {
                    if x["sensor"] == "DE-H" {
                        x["sensor"] = json!(id);
                    }
                }
            }
        }),
        ("sensors[0].label", |s, c| {
            s["sensors"][0]["label"] = json!(format!("DE {c}horizontal"))
        }),
        (
            "trim.coefficients_from.machine",
            |s, c| s["trim"] = json!({"coefficients_from": {"machine": format!("P{c}1")}}),
        ),
    ];
    let url = server.url("/api/v1/sessions");
    let solve = server.url("/api/v1/solve");
    for (field, edit) in cases {
        for c in [nul, "\u{1b}"] {
            let mut s = pump();
            edit(&mut s, c);
            let (status, _, err) = post(&client, &url, &s).await;
            assert_eq!(
                (status, error_of(&err)),
                (422, ("invalid_value", Some(field))),
                "{field} {c:?}: {err}"
            );
            // The ids are the core's: a session the store refuses for its
            // ids is not solved either (it was, answering them back).
            if field.ends_with(".id") || field == "trim.coefficients_from.machine" {
                let (status, _, err) = post(&client, &solve, &json!({"session": s})).await;
                let under = format!("session.{field}");
                assert_eq!(
                    (status, error_of(&err)),
                    (422, ("invalid_value", Some(under.as_str()))),
                    "solve: {field} {c:?}: {err}"
                );
            }
        }
    }
    // Texts keep their line breaks and tabs; ids do not.
    let mut s = pump();
    s["name"] = json!("pump 3\n\tcoupling end");
    let (status, _, created) = post(&client, &url, &s).await;
    assert_eq!(status, 201, "{created}");
    let id = created["id"].as_str().unwrap();
    let (_, _, back) = send(client.get(server.url(&format!("/api/v1/sessions/{id}")))).await;
    assert_eq!(back["name"], "pump 3\n\tcoupling end");

    let runs = server.url(&format!("/api/v1/sessions/{id}/runs"));
    let mut run = pump()["runs"][1].clone();
    for bad in ["check\u{0}", "check\n"] {
        run["id"] = json!(bad);
        let (status, _, err) = post(&client, &runs, &run).await;
        assert_eq!(
            (status, error_of(&err)),
            (422, ("invalid_value", Some("id"))),
            "{bad:?}: {err}"
        );
    }

    let machines = server.url("/api/v1/machines");
    for (body, field) in [
        (json!({"id": "M", "name": "fan\u{0}"}), "name"),
        (json!({"id": "M", "notes": "a\u{0}b"}), "notes"),
        (json!({"id": "M", "notes": "bell\u{7}"}), "notes"),
    ] {
        let (status, _, err) = post(&client, &machines, &body).await;
        assert_eq!(
            (status, error_of(&err)),
            (422, ("invalid_value", Some(field))),
            "{body}: {err}"
        );
    }
    let (status, _, m) = post(
        &client,
        &machines,
        &json!({"id": "M", "name": "fan", "notes": "line 1\r\nline 2\tend"}),
    )
    .await;
    assert_eq!(status, 201, "{m}");
    let (_, _, list) = send(client.get(&url)).await;
    assert_eq!(list["total"], 1, "nothing refused was stored");
}

#[tokio::test]
async fn lookups_by_a_key_holding_a_nul_find_nothing_on_either_engine() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, m) = post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "M"}),
    )
    .await;
    assert_eq!(m["id"], "M");
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &pump()).await;
    let id = created["id"].as_str().unwrap();
    let run = pump()["runs"][1].clone();
    let mut nul_run = run.clone();
    nul_run["id"] = json!("a\u{0}b");
    let s = format!("/api/v1/sessions/{id}");
    let not_found = [
        ("GET", "/api/v1/sessions/a%00b".to_string(), Value::Null),
        ("DELETE", "/api/v1/sessions/a%00b".into(), Value::Null),
        ("POST", "/api/v1/sessions/a%00b/runs".into(), run.clone()),
        ("POST", "/api/v1/sessions/a%00b/solutions".into(), json!({})),
        (
            "GET",
            "/api/v1/sessions/a%00b/solutions".into(),
            Value::Null,
        ),
        ("GET", format!("{s}/runs/a%00b"), Value::Null),
        ("GET", format!("{s}/runs/a%00b/versions"), Value::Null),
        ("PUT", format!("{s}/runs/a%00b"), nul_run),
        ("GET", "/api/v1/machines/a%00b".into(), Value::Null),
        ("DELETE", "/api/v1/machines/a%00b".into(), Value::Null),
        (
            "GET",
            "/api/v1/machines/a%00b/coefficients".into(),
            Value::Null,
        ),
        (
            "POST",
            "/api/v1/machines/a%00b/coefficients".into(),
            json!({"sessions": [id]}),
        ),
    ];
    for (method, path, body) in not_found {
        let mut req = client.request(method.parse().unwrap(), server.url(&path));
        if !body.is_null() {
            req = req.json(&body);
        }
        let (status, _, err) = send(req).await;
        assert_eq!(
            (status, error_of(&err).0),
            (404, "not_found"),
            "{method} {path}: {err}"
        );
    }
    // A solve's `coefficients_from.machine` is held to the machine-id rule
    // before any lookup (as a trim job's): refused naming the field, on
    // either engine, never looked up.
    let from = json!({"coefficients_from": {"machine": "M\u{0}"}});
    let (status, _, err) = post(&client, &server.url(&format!("{s}/solutions")), &from).await;
    assert_eq!(
        (status, error_of(&err)),
        (422, ("invalid_value", Some("coefficients_from.machine"))),
        "{err}"
    );
    for path in ["/api/v1/solve", "/api/v1/trial-weights"] {
        let body = json!({"session": pump(), "options": from});
        let (status, _, err) = post(&client, &server.url(path), &body).await;
        assert_eq!(
            (status, error_of(&err)),
            (
                422,
                ("invalid_value", Some("options.coefficients_from.machine"))
            ),
            "{path}: {err}"
        );
    }
    let pool = json!({"sessions": ["a\u{0}b"]});
    let (status, _, err) = post(
        &client,
        &server.url("/api/v1/machines/M/coefficients"),
        &pool,
    )
    .await;
    assert_eq!(
        (status, error_of(&err)),
        (422, ("unknown_session", Some("sessions[0]"))),
        "{err}"
    );
}

#[tokio::test]
async fn what_was_stored_before_the_rules_stays_readable_and_writable() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("t.db");
    let (_, server) = start_server(&db).await;
    let client = reqwest::Client::new();
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &pump()).await;
    let id = created["id"].as_str().unwrap().to_string();
    server.shutdown().await;

    // As an earlier version stored them: ids with control characters (and a
    // NUL where the engine can hold one), a session naming such a machine.
    let old = "old\u{7}fan";
    let url = common::engine::database_url(&db).await;
    let pool = fieldbal::db::connect(&url).await.unwrap();
    let mut ids = vec![old];
    if !common::engine::postgres() {
        ids.push("nul\u{0}fan");
    }
    for m in &ids {
        sqlx::query("INSERT INTO machines (id, name) VALUES ($1, '')")
            .bind(*m)
            .execute(&pool)
            .await
            .unwrap();
    }
    let mut setup = pump();
    setup["runs"] = json!([]);
    setup["machine"] = json!(old);
    setup["sensors"][0]["label"] = json!("bell\u{7}");
    sqlx::query("UPDATE sessions SET machine = $1, setup = $2 WHERE id = $3")
        .bind(old)
        .bind(setup.to_string())
        .bind(&id)
        .execute(&pool)
        .await
        .unwrap();
    pool.close().await;

    let (_, server) = start_server(&db).await;
    for m in &ids {
        let (status, _, got) =
            send(client.get(server.url(&format!("/api/v1/machines/{}", path_segment(m))))).await;
        assert_eq!((status, got["id"].as_str()), (200, Some(*m)), "{m:?}");
    }
    let (_, _, got) =
        send(client.get(server.url(&format!("/api/v1/machines/{}", path_segment(old))))).await;
    assert_eq!(got["sessions"][0]["id"], id.as_str());
    // The session still takes a new run and a correction, and pools.
    let mut run = pump()["runs"][1].clone();
    run["id"] = json!("check");
    let (status, _, body) = post(
        &client,
        &server.url(&format!("/api/v1/sessions/{id}/runs")),
        &run,
    )
    .await;
    assert_eq!(status, 201, "{body}");
    let (status, _, body) = send(
        client
            .put(server.url(&format!("/api/v1/sessions/{id}/runs/check")))
            .json(&run),
    )
    .await;
    assert_eq!((status, &body["version"]), (200, &json!(2)), "{body}");
    let (status, _, body) = post(
        &client,
        &server.url(&format!(
            "/api/v1/machines/{}/coefficients",
            path_segment(old)
        )),
        &json!({"sessions": [id]}),
    )
    .await;
    assert_eq!((status, &body["version"]), (201, &json!(1)), "{body}");
    for m in &ids {
        let (status, _, _) =
            send(client.delete(server.url(&format!("/api/v1/machines/{}", path_segment(m))))).await;
        assert_eq!(status, 204, "{m:?}");
    }
    server.shutdown().await;
}

/// `YYYY-MM-DDTHH:MM:SS.mmmZ`: UTC, milliseconds, as both engines' defaults write it.
fn is_utc_millis(t: &Value) -> bool {
    let Some(t) = t.as_str() else {
        return false;
    };
    let b = t.as_bytes();
    let digits = |r: std::ops::Range<usize>| r.clone().all(|i| b[i].is_ascii_digit());
    b.len() == 24
        && digits(0..4)
        && b[4] == b'-'
        && digits(5..7)
        && b[7] == b'-'
        && digits(8..10)
        && b[10] == b'T'
        && digits(11..13)
        && b[13] == b':'
        && digits(14..16)
        && b[16] == b':'
        && digits(17..19)
        && b[19] == b'.'
        && digits(20..23)
        && b[23] == b'Z'
}

#[tokio::test]
async fn every_stored_timestamp_is_utc_with_milliseconds_on_either_engine() {
    let (_dir, server, client) = fresh_server().await;
    let mut s = pump();
    s["machine"] = json!("M");
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "M"}),
    )
    .await;
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &s).await;
    let id = created["id"].as_str().unwrap();
    let base = format!("/api/v1/sessions/{id}");
    let solution = common::store_solution(&client, &server, id).await;
    let (_, _, version) = post(
        &client,
        &server.url("/api/v1/machines/M/coefficients"),
        &json!({"sessions": [id]}),
    )
    .await;
    let (_, _, sessions) = send(client.get(server.url("/api/v1/sessions"))).await;
    let (_, _, machines) = send(client.get(server.url("/api/v1/machines"))).await;
    let (_, _, machine) = send(client.get(server.url("/api/v1/machines/M"))).await;
    let (_, _, versions) =
        send(client.get(server.url(&format!("{base}/runs/zero/versions")))).await;
    let (_, _, solutions) = send(client.get(server.url(&format!("{base}/solutions")))).await;
    let stamps = [
        ("solution", &solution["created_at"]),
        ("coefficient version", &version["created_at"]),
        ("session list", &sessions["sessions"][0]["created_at"]),
        ("machine list", &machines["machines"][0]["created_at"]),
        ("machine", &machine["created_at"]),
        ("machine session", &machine["sessions"][0]["created_at"]),
        (
            "machine session solved",
            &machine["sessions"][0]["solved_at"],
        ),
        ("machine version", &machine["coefficients"][0]["created_at"]),
        ("run version", &versions[0]["created_at"]),
        ("solution list", &solutions[0]["created_at"]),
    ];
    for (what, t) in stamps {
        assert!(is_utc_millis(t), "{what}: {t}");
    }
}
