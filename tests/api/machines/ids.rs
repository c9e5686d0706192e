//! A machine's id names it for good: coefficient versions are never numbered
//! twice under one id (a script pinned to `{machine, version}` never gets
//! other coefficients after the machine is deleted and created again), and an
//! id holds no control characters (refused naming the field).

use crate::common;
use crate::job_support;

use common::{fresh_server, path_segment, post, send};
use fieldbal::balancing::model::Conventions;
use job_support::*;
use serde_json::{json, Value};

fn job_session(machine: &str, seed: u64) -> Value {
    let conv = Conventions::default();
    let mut n = Noise::new(1.0, 1.0, seed);
    let mut s = session(conv, opening_runs(&Rotor::new(), conv, true, &mut n));
    s["machine"] = json!(machine);
    s
}

async fn store(client: &reqwest::Client, server: &common::Server, s: &Value) -> String {
    let (status, _, created) = post(client, &server.url("/api/v1/sessions"), s).await;
    assert_eq!(status, 201, "{created}");
    created["id"].as_str().unwrap().to_string()
}

async fn pool(client: &reqwest::Client, server: &common::Server, machine: &str, s: &str) -> Value {
    let url = server.url(&format!("/api/v1/machines/{machine}/coefficients"));
    let (status, _, body) = post(client, &url, &json!({"sessions": [s]})).await;
    assert_eq!(status, 201, "{body}");
    body
}

#[tokio::test]
async fn a_machine_deleted_and_created_again_never_numbers_a_version_twice() {
    let (_dir, server, client) = fresh_server().await;
    let machines = server.url("/api/v1/machines");
    let (status, _, _) = post(&client, &machines, &json!({"id": "P-1"})).await;
    assert_eq!(status, 201);
    let old = store(&client, &server, &job_session("P-1", 51)).await;
    assert_eq!(pool(&client, &server, "P-1", &old).await["version"], 1);
    assert_eq!(pool(&client, &server, "P-1", &old).await["version"], 2);

    let (status, _, _) = send(client.delete(server.url("/api/v1/machines/P-1"))).await;
    assert_eq!(status, 204);
    let (status, _, _) = post(&client, &machines, &json!({"id": "P-1"})).await;
    assert_eq!(status, 201);
    // A new job on the machine created again, with other readings.
    let new = store(&client, &server, &job_session("P-1", 52)).await;
    let v = pool(&client, &server, "P-1", &new).await;
    assert_eq!(
        v["version"], 3,
        "numbering goes on after the deleted versions"
    );

    // A reference pinned to a deleted version is refused, never answered
    // with the new coefficients.
    let (status, _, err) =
        send(client.get(server.url("/api/v1/machines/P-1/coefficients?version=1"))).await;
    assert_eq!(status, 404, "{err}");
    assert_eq!(err["error"]["field"], "version");
    let msg = err["error"]["message"].as_str().unwrap();
    assert!(msg.contains("deleted"), "says why: {msg}");
    let pinned = json!({"coefficients_from": {"machine": "P-1", "version": 1}});
    let (status, _, err) = post(
        &client,
        &server.url(&format!("/api/v1/sessions/{new}/solutions")),
        &pinned,
    )
    .await;
    assert_eq!(status, 422, "{err}");
    assert_eq!(err["error"]["code"], "unknown_version");
    assert_eq!(err["error"]["field"], "coefficients_from.version");

    let (_, _, latest) = send(client.get(server.url("/api/v1/machines/P-1/coefficients"))).await;
    assert_eq!(latest["version"], 3);
    assert_eq!(latest["sessions"], json!([new]));
    let (_, _, m) = send(client.get(server.url("/api/v1/machines/P-1"))).await;
    let listed: Vec<i64> = m["coefficients"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["version"].as_i64().unwrap())
        .collect();
    assert_eq!(listed, [3], "the deleted versions are gone");

    // Deleted again without a version of its own since: still no reuse.
    let (status, _, _) = send(client.delete(server.url("/api/v1/machines/P-1"))).await;
    assert_eq!(status, 204);
    post(&client, &machines, &json!({"id": "P-1"})).await;
    post(&client, &machines, &json!({"id": "p-1"})).await;
    send(client.delete(server.url("/api/v1/machines/P-1"))).await;
    post(&client, &machines, &json!({"id": "P-1"})).await;
    assert_eq!(pool(&client, &server, "P-1", &new).await["version"], 4);
    // Ids are compared exactly: another machine's numbering is its own.
    let other = store(&client, &server, &job_session("p-1", 53)).await;
    assert_eq!(pool(&client, &server, "p-1", &other).await["version"], 1);
}

#[tokio::test]
async fn machine_ids_with_control_characters_are_refused_naming_the_field() {
    let (_dir, server, client) = fresh_server().await;
    let machines = server.url("/api/v1/machines");
    for id in [
        "a\u{0}b",
        "a\nb",
        "tab\there",
        "\u{7}",
        "a\u{7f}",
        "a\u{85}b",
        "end\r",
        // Blank: a machine no one can tell from no machine (a blank name
        // was refused, a blank id stored).
        " ",
        "   ",
        "\u{a0}",
    ] {
        let (status, _, err) = post(&client, &machines, &json!({"id": id})).await;
        assert_eq!(status, 422, "{id:?}: {err}");
        assert_eq!(err["error"]["code"], "invalid_value", "{id:?}");
        assert_eq!(err["error"]["field"], "id", "{id:?}");
    }
    let (_, _, list) = send(client.get(&machines)).await;
    assert_eq!(list["total"], 0, "nothing stored");
    // Printable ids of every script stay valid, and readable by their path.
    for id in ["ID-FAN-3", "pump 1/2", "Gebläse \u{e9}", "\u{6c34}\u{6cf5}"] {
        let (status, _, body) = post(&client, &machines, &json!({"id": id})).await;
        assert_eq!(status, 201, "{id}: {body}");
        let (status, _, got) =
            send(client.get(server.url(&format!("/api/v1/machines/{}", path_segment(id))))).await;
        assert_eq!((status, got["id"].as_str()), (200, Some(id)));
    }
}

#[tokio::test]
async fn versions_pooled_while_the_machine_is_deleted_and_created_again_never_repeat_a_number() {
    let (_dir, server, client) = fresh_server().await;
    let machines = server.url("/api/v1/machines");
    post(&client, &machines, &json!({"id": "R"})).await;
    let s = store(&client, &server, &job_session("R", 54)).await;
    let url = server.url("/api/v1/machines/R/coefficients");
    let poolers: Vec<_> = (0..3)
        .map(|_| {
            let (client, url, s) = (client.clone(), url.clone(), s.clone());
            tokio::spawn(async move {
                let mut got = Vec::new();
                for _ in 0..6 {
                    let (status, _, body) = post(&client, &url, &json!({"sessions": [s]})).await;
                    // 404 while the machine is deleted; nothing else.
                    assert!(status == 201 || status == 404, "{status}: {body}");
                    if status == 201 {
                        got.push(body["version"].as_i64().unwrap());
                    }
                }
                got
            })
        })
        .collect();
    for _ in 0..6 {
        send(client.delete(server.url("/api/v1/machines/R"))).await;
        post(&client, &machines, &json!({"id": "R"})).await;
    }
    let mut versions = Vec::new();
    for p in poolers {
        versions.extend(p.await.unwrap());
    }
    versions.push(
        pool(&client, &server, "R", &s).await["version"]
            .as_i64()
            .unwrap(),
    );
    let n = versions.len();
    versions.sort_unstable();
    versions.dedup();
    assert_eq!(versions.len(), n, "a number given twice: {versions:?}");
}

#[tokio::test]
async fn a_stored_sessions_machine_is_refused_when_no_machine_could_have_that_id() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/sessions");
    let stateless = ["/api/v1/solve", "/api/v1/trial-weights"].map(|p| server.url(p));
    // Too long, empty or with a control character: a machine id has 1 to 64
    // characters, none a control character. The solve (and the trial
    // weights) refuse the session as the store does (they answered it).
    for bad in [
        "M".repeat(65),
        String::new(),
        "M\u{0}".into(),
        "M\n1".into(),
        " ".into(),
    ] {
        let s = job_session(&bad, 55);
        let (status, _, err) = post(&client, &url, &s).await;
        assert_eq!(status, 422, "{bad:?}: {err}");
        assert_eq!(err["error"]["field"], "machine", "{bad:?}: {err}");
        for u in &stateless {
            let (status, _, err) = post(&client, u, &json!({"session": s})).await;
            let got = (status, &err["error"]["code"], &err["error"]["field"]);
            assert_eq!(
                got,
                (422, &json!("invalid_value"), &json!("session.machine")),
                "{u} {bad:?}: {err}"
            );
        }
    }
    let (_, _, list) = send(client.get(&url)).await;
    assert_eq!(list["total"], 0, "nothing stored");
    let longest = "\u{e9}".repeat(64);
    let (status, _, body) = post(&client, &url, &job_session(&longest, 55)).await;
    assert_eq!(status, 201, "64 characters are an id: {body}");
    let s = job_session(&longest, 55);
    for u in &stateless {
        let (status, _, body) = post(&client, u, &json!({"session": s})).await;
        assert_eq!(status, 200, "{u} answers it too: {body}");
    }
}

#[tokio::test]
async fn a_pool_listing_more_sessions_than_the_limit_is_refused_before_any_is_read() {
    // Each listed id was compared with every one before it, on the request's
    // thread: 60,000 ids (a 0.6 MB body) held it for half a minute.
    let (_dir, server, client) = fresh_server().await;
    post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "M"}),
    )
    .await;
    let url = server.url("/api/v1/machines/M/coefficients");
    let many: Vec<String> = (0..=1000).map(|i| format!("s{i}")).collect();
    let (status, _, err) = post(&client, &url, &json!({"sessions": many})).await;
    assert_eq!(status, 422, "{err}");
    assert_eq!(err["error"]["code"], "too_large");
    assert_eq!(err["error"]["field"], "sessions");
    // At the limit the list is read: its first unknown id is named.
    let (status, _, err) = post(&client, &url, &json!({"sessions": &many[..1000]})).await;
    assert_eq!(status, 422, "{err}");
    assert_eq!(err["error"]["field"], "sessions[0]");
    // A repeat is still found wherever it is.
    let mut repeated = many[..1000].to_vec();
    repeated[999] = "s3".into();
    let (_, _, err) = post(&client, &url, &json!({"sessions": repeated})).await;
    assert_eq!(
        (
            err["error"]["code"].as_str(),
            err["error"]["field"].as_str()
        ),
        (Some("duplicate_id"), Some("sessions[999]"))
    );
}

#[tokio::test]
async fn a_version_no_machine_could_have_is_a_bad_value_not_a_missing_one() {
    let (_dir, server, client) = fresh_server().await;
    let (status, _, _) = post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "V-1"}),
    )
    .await;
    assert_eq!(status, 201);
    let s = store(&client, &server, &job_session("V-1", 61)).await;
    assert_eq!(pool(&client, &server, "V-1", &s).await["version"], 1);
    let url = |q: &str| server.url(&format!("/api/v1/machines/V-1/coefficients{q}"));
    // Versions are numbered from 1: 0 or below is never a version (it was
    // answered 404 as if it might have been one), whether the machine
    // exists or not.
    for q in ["?version=0", "?version=-1", "?version=-9223372036854775808"] {
        for u in [
            url(q),
            server.url(&format!("/api/v1/machines/NOPE/coefficients{q}")),
        ] {
            let (status, _, err) = send(client.get(&u)).await;
            assert_eq!(status, 422, "{u}: {err}");
            assert_eq!(err["error"]["code"], "out_of_range", "{u}: {err}");
            assert_eq!(err["error"]["field"], "version", "{u}: {err}");
        }
    }
    // The same version asked of a solve (`coefficients_from`) or named by a
    // stored trim job is the same bad value, said with the same code (it was
    // `unknown_version` in a solve and `invalid_value` in a trim).
    let mut session = job_session("V-1", 62);
    let solve = json!({"session": session.clone(),
        "options": {"coefficients_from": {"machine": "V-1", "version": 0}}});
    let (status, _, err) = post(&client, &server.url("/api/v1/solve"), &solve).await;
    assert_eq!(status, 422, "{err}");
    assert_eq!(err["error"]["code"], "out_of_range", "{err}");
    assert_eq!(
        err["error"]["field"], "options.coefficients_from.version",
        "{err}"
    );
    session["trim"] = json!({"coefficients_from": {"machine": "V-1", "version": -3}});
    let (status, _, err) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    assert_eq!(status, 422, "{err}");
    assert_eq!(err["error"]["code"], "out_of_range", "{err}");
    assert_eq!(
        err["error"]["field"], "trim.coefficients_from.version",
        "{err}"
    );
    // Not a number at all: the query's syntax (as `limit=many`), 400.
    for q in ["?version=1.5", "?version=x", "?version="] {
        let (status, _, err) = send(client.get(url(q))).await;
        assert_eq!(status, 400, "{q}: {err}");
        assert_eq!(err["error"]["field"], "version", "{q}: {err}");
    }
    // A version that could exist but does not stays 404 naming it.
    let (status, _, err) = send(client.get(url("?version=2"))).await;
    assert_eq!(status, 404, "{err}");
    assert_eq!(err["error"]["field"], "version", "{err}");
    let (status, _, got) = send(client.get(url("?version=1"))).await;
    assert_eq!((status, &got["version"]), (200, &json!(1)), "{got}");
}
