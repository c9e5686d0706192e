//! Runs of a stored session: a corrected run keeps its earlier versions and the
//! session and its solutions use the newest; deleting a session removes everything.

use crate::common;

use common::{example, fresh_server, post, send};
use serde_json::{json, Value};

#[tokio::test]
async fn a_corrected_run_keeps_its_earlier_version_and_the_solution_uses_the_new_one() {
    let (_dir, server, client) = fresh_server().await;
    let ex = example("pump-two-plane-exact.json");
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
    let base = format!("/api/v1/sessions/{}", created["id"].as_str().unwrap());
    let solve = || async {
        let (status, _, s) = post(
            &client,
            &server.url(&format!("{base}/solutions")),
            &json!({}),
        )
        .await;
        assert_eq!(status, 201, "{s}");
        s["solution"].clone()
    };
    let original = ex["session"]["runs"][1].clone();
    let run_url = format!("{base}/runs/trial%20inboard");
    let before = solve().await;

    // A typo: one amplitude entered 10 times too large.
    let mut typo = original.clone();
    typo["readings"][0]["amplitude"] =
        json!(original["readings"][0]["amplitude"].as_f64().unwrap() * 10.0);
    let (status, _, body) = send(client.put(server.url(&run_url)).json(&typo)).await;
    assert_eq!(
        (status, body),
        (200, json!({"run_id": "trial inboard", "version": 2}))
    );
    let (_, _, session) = send(client.get(server.url(&base))).await;
    assert_eq!(session["runs"][1], typo_as_stored(&typo));
    let with_typo = solve().await;
    assert_ne!(with_typo["corrections"], before["corrections"]);

    // Corrected back: version 3, the same answer as before, every version listed.
    let (status, _, body) = send(client.put(server.url(&run_url)).json(&original)).await;
    assert_eq!((status, &body["version"]), (200, &json!(3)));
    assert_eq!(solve().await, before);
    let (status, _, versions) = send(client.get(server.url(&format!("{run_url}/versions")))).await;
    assert_eq!(status, 200);
    let versions = versions.as_array().unwrap();
    assert_eq!(
        versions
            .iter()
            .map(|v| v["version"].clone())
            .collect::<Vec<_>>(),
        [json!(1), json!(2), json!(3)]
    );
    assert_eq!(
        versions
            .iter()
            .map(|v| v["current"].clone())
            .collect::<Vec<_>>(),
        [json!(false), json!(false), json!(true)]
    );
    assert_eq!(versions[1]["run"], typo_as_stored(&typo));
    assert_eq!(versions[0]["run"], versions[2]["run"]);

    // Each stored solution says which run versions it used.
    let (_, _, solutions) = send(client.get(server.url(&format!("{base}/solutions")))).await;
    let used: Vec<Value> = solutions
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["runs"][1]["version"].clone())
        .collect();
    assert_eq!(used, [json!(1), json!(2), json!(3)]);
    server.shutdown().await;
}

/// Numbers read back as floats (`30` → `30.0`); compare in that form.
fn typo_as_stored(run: &Value) -> Value {
    let run: fieldbal::balancing::model::Run = serde_json::from_value(run.clone()).unwrap();
    serde_json::to_value(run).unwrap()
}

#[tokio::test]
async fn run_ids_with_spaces_and_slashes_are_reachable_at_their_location() {
    let (_dir, server, client) = fresh_server().await;
    let mut session = example("pump-two-plane-exact.json")["session"].clone();
    let mut trial = session["runs"].as_array_mut().unwrap().pop().unwrap();
    trial["id"] = json!("trial B / 40 g");
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    let url = server.url(&format!(
        "/api/v1/sessions/{}/runs",
        created["id"].as_str().unwrap()
    ));
    let (status, headers, _) = post(&client, &url, &trial).await;
    assert_eq!(status, 201);
    let location = headers["location"].to_str().unwrap().to_string();
    assert!(
        location.ends_with("/runs/trial%20B%20%2F%2040%20g"),
        "{location}"
    );
    let (status, _, versions) = send(client.get(server.url(&format!("{location}/versions")))).await;
    assert_eq!(status, 200, "{versions}");
    assert_eq!(versions[0]["run"]["id"], "trial B / 40 g");
}

#[tokio::test]
async fn deleting_a_session_removes_it_with_its_runs_and_solutions() {
    let (_dir, server, client) = fresh_server().await;
    let ex = example("pump-two-plane-exact.json");
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
    let base = format!("/api/v1/sessions/{}", created["id"].as_str().unwrap());
    let (status, _, _) = post(
        &client,
        &server.url(&format!("{base}/solutions")),
        &json!({}),
    )
    .await;
    assert_eq!(status, 201);

    let (status, _, body) = send(client.delete(server.url(&base))).await;
    assert_eq!((status, body), (204, Value::Null));
    for path in [
        base.clone(),
        format!("{base}/solutions"),
        format!("{base}/runs/zero/versions"),
    ] {
        let (status, _, body) = send(client.get(server.url(&path))).await;
        assert_eq!(
            (status, body["error"]["code"].as_str()),
            (404, Some("not_found")),
            "{path}"
        );
    }
    let (_, _, list) = send(client.get(server.url("/api/v1/sessions"))).await;
    assert_eq!(list["total"], 0);
    server.shutdown().await;
}

#[tokio::test]
async fn if_match_compares_strongly_so_a_weak_tag_never_matches() {
    let (_dir, server, client) = fresh_server().await;
    let ex = example("pump-two-plane-exact.json");
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
    let run_url = server.url(&format!(
        "/api/v1/sessions/{}/runs/trial%20inboard",
        created["id"].as_str().unwrap()
    ));
    let (status, headers, run) = send(client.get(&run_url)).await;
    assert_eq!(status, 200);
    let tag = headers["etag"].to_str().unwrap().to_string();
    assert!(tag.starts_with('"'), "a strong tag: {tag}");
    // RFC 9110 §13.1.1: If-Match uses the strong comparison, under which a
    // weak tag matches nothing, not even the current version's (it was
    // taken as that version). Alone or in a list: 412, nothing stored.
    // Nor does a tag spelled otherwise than the ETag (`"v01"` for `"v1"`).
    assert_eq!(tag, "\"v1\"");
    for weak in [
        format!("W/{tag}"),
        format!("W/{tag}, \"v99\""),
        "\"v01\"".into(),
        "\"v+1\"".into(),
    ] {
        let (status, _, body) =
            send(client.put(&run_url).header("If-Match", &weak).json(&run)).await;
        assert_eq!(status, 412, "{weak}: {body}");
        assert_eq!(body["error"]["code"], "precondition_failed", "{body}");
        assert_eq!(body["error"]["field"], "If-Match", "{body}");
    }
    let (_, versions, _) = send(client.get(format!("{run_url}/versions"))).await;
    assert_eq!(versions["x-total-count"], "1", "nothing was stored");
    // The strong tag, alone or beside a weak one, still matches.
    let (status, headers, body) = send(
        client
            .put(&run_url)
            .header("If-Match", format!("W/\"v7\", {tag}"))
            .json(&run),
    )
    .await;
    assert_eq!(status, 200, "{body}");
    let tag = headers["etag"].to_str().unwrap().to_string();
    let (status, _, body) = send(client.put(&run_url).header("If-Match", &tag).json(&run)).await;
    assert_eq!(status, 200, "{body}");
}

/// A retried append (the same `Idempotency-Key`, the first answer lost)
/// answers as the first did, `ETag` included: the replay carried no `ETag`,
/// so a client that lost the first answer had none to send as `If-Match`.
/// The document declares both headers of that answer.
#[tokio::test]
async fn a_replayed_append_carries_the_runs_etag_as_the_first_answer_did() {
    let (_dir, server, client) = fresh_server().await;
    let ex = example("pump-two-plane-exact.json");
    let session = ex.get("session").cloned().unwrap_or(ex);
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    let url = server.url(&format!(
        "/api/v1/sessions/{}/runs",
        created["id"].as_str().unwrap()
    ));
    let mut run = session["runs"][1].clone();
    run["id"] = json!("check");
    let append = || {
        client
            .post(&url)
            .header("Idempotency-Key", "append-check-1")
            .json(&run)
    };
    let (first, first_headers, _) = send(append()).await;
    let (again, again_headers, body) = send(append()).await;
    assert_eq!((first, again), (201, 201), "{body}");
    assert_eq!(again_headers.get("idempotent-replayed").unwrap(), "true");
    assert_eq!(
        again_headers.get("etag"),
        first_headers.get("etag"),
        "the replay's ETag"
    );
    let (_, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    for (path, method) in [
        ("/api/v1/sessions/{id}/runs", "post"),
        ("/api/v1/sessions", "post"),
        ("/api/v1/sessions/{id}/solutions", "post"),
        ("/api/v1/machines", "post"),
        ("/api/v1/machines/{id}/coefficients", "post"),
    ] {
        let headers = &doc["paths"][path][method]["responses"]["201"]["headers"];
        assert!(
            headers.get("Idempotent-Replayed").is_some(),
            "{method} {path}: {headers}"
        );
    }
    server.shutdown().await;
}
