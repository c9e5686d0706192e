//! Honest writes (contract v2): `Idempotency-Key` replays the first answer
//! and stores nothing new; `ETag` / `If-Match` keep two tabs from undoing each
//! other's corrections; the lists of versions and solutions are paged.

use crate::common;

use common::{example, fresh_server, post, send};
use serde_json::{json, Value};

fn two_plane() -> Value {
    example("pump-two-plane-exact.json")["session"].clone()
}

/// Store `session` (unkeyed): its id.
async fn store(client: &reqwest::Client, server: &common::Server, session: &Value) -> String {
    let (_, _, created) = post(client, &server.url("/api/v1/sessions"), session).await;
    created["id"].as_str().unwrap().to_string()
}

async fn post_keyed(
    client: &reqwest::Client,
    url: &str,
    key: &str,
    body: &Value,
) -> (u16, reqwest::header::HeaderMap, Value) {
    send(client.post(url).header("Idempotency-Key", key).json(body)).await
}

async fn total_sessions(client: &reqwest::Client, server: &common::Server) -> i64 {
    let (_, _, list) = send(client.get(server.url("/api/v1/sessions"))).await;
    list["total"].as_i64().unwrap()
}

#[tokio::test]
async fn a_repeated_idempotency_key_answers_the_first_answer_and_stores_nothing_new() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/sessions");
    let session = two_plane();

    let (s1, h1, b1) = post_keyed(&client, &url, "k-1", &session).await;
    let (s2, h2, b2) = post_keyed(&client, &url, "k-1", &session).await;
    assert_eq!((s1, s2), (201, 201));
    assert_eq!(b1, b2, "the same id again");
    assert_eq!(h1["location"], h2["location"]);
    assert_eq!(total_sessions(&client, &server).await, 1);

    // The same key with another body is refused, naming the header.
    let mut other = session.clone();
    other["name"] = json!("another");
    let (status, _, body) = post_keyed(&client, &url, "k-1", &other).await;
    assert_eq!(status, 422, "{body}");
    assert_eq!(body["error"]["code"], "idempotency_key_reused");
    assert_eq!(body["error"]["field"], "Idempotency-Key");
    // Another key stores another session.
    let (status, _, _) = post_keyed(&client, &url, "k-2", &session).await;
    assert_eq!(status, 201);
    assert_eq!(total_sessions(&client, &server).await, 2);
}

#[tokio::test]
async fn runs_and_solutions_posted_twice_with_one_key_are_stored_once() {
    let (_dir, server, client) = fresh_server().await;
    let mut session = two_plane();
    let last = session["runs"].as_array_mut().unwrap().pop().unwrap();
    let id = store(&client, &server, &session).await;

    let runs_url = server.url(&format!("/api/v1/sessions/{id}/runs"));
    let (s1, _, b1) = post_keyed(&client, &runs_url, "run-key", &last).await;
    let (s2, _, b2) = post_keyed(&client, &runs_url, "run-key", &last).await;
    assert_eq!((s1, s2), (201, 201), "{b2}");
    assert_eq!(b1, b2);

    let sol_url = server.url(&format!("/api/v1/sessions/{id}/solutions"));
    let (s1, _, b1) = post_keyed(&client, &sol_url, "sol-key", &json!({})).await;
    let (s2, h2, b2) = post_keyed(&client, &sol_url, "sol-key", &json!({})).await;
    assert_eq!((s1, s2), (201, 201));
    assert_eq!(b1["id"], b2["id"], "the stored solution's id again");
    assert_eq!(h2["idempotent-replayed"], "true");
    let (_, headers, list) = send(client.get(&sol_url)).await;
    assert_eq!(list.as_array().unwrap().len(), 1);
    assert_eq!(headers["x-total-count"], "1");
}

#[tokio::test]
async fn machines_and_coefficient_versions_posted_twice_with_one_key_are_stored_once() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/machines");
    let machine = json!({"id": "P-1", "name": "pump 1"});
    let (s1, h1, b1) = post_keyed(&client, &url, "m-key", &machine).await;
    let (s2, h2, b2) = post_keyed(&client, &url, "m-key", &machine).await;
    assert_eq!((s1, s2), (201, 201), "{b2}");
    assert_eq!(b1, b2, "the first answer again");
    assert_eq!(h1["location"], h2["location"]);
    assert_eq!(h2["idempotent-replayed"], "true");
    let (status, _, body) =
        post_keyed(&client, &url, "m-key", &json!({"id": "P-2", "name": "x"})).await;
    assert_eq!(status, 422, "{body}");
    assert_eq!(body["error"]["code"], "idempotency_key_reused");
    assert_eq!(body["error"]["field"], "Idempotency-Key");

    let mut session = two_plane();
    session["machine"] = json!("P-1");
    let id = store(&client, &server, &session).await;
    let pool_url = server.url("/api/v1/machines/P-1/coefficients");
    let pool = json!({"sessions": [id]});
    let (s1, _, b1) = post_keyed(&client, &pool_url, "c-key", &pool).await;
    let (s2, h2, b2) = post_keyed(&client, &pool_url, "c-key", &pool).await;
    assert_eq!((s1, s2), (201, 201), "{b2}");
    assert_eq!(b1["version"], 1);
    assert_eq!(b1, b2, "version 1 again, not a version 2");
    assert_eq!(h2["idempotent-replayed"], "true");
    let (_, _, detail) = send(client.get(server.url("/api/v1/machines/P-1"))).await;
    assert_eq!(
        detail["coefficients"].as_array().unwrap().len(),
        1,
        "{detail}"
    );
}

#[tokio::test]
async fn a_machine_id_no_header_can_carry_raw_is_answered_201_with_an_encoded_location() {
    // A raw control character in `Location` made the answer a 500 after the
    // machine was stored: a refusal that stored something. Control
    // characters are refused in ids now (422, nothing stored); spaces,
    // slashes and letters beyond ASCII still need the encoding.
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/machines");
    let (status, _, body) = post(&client, &url, &json!({"id": "a\nb", "name": "x"})).await;
    assert_eq!(
        (status, &body["error"]["field"]),
        (422, &json!("id")),
        "{body}"
    );
    let (status, _, _) = send(client.get(server.url("/api/v1/machines/a%0Ab"))).await;
    assert_eq!(status, 404, "nothing stored");
    let id = "pump 1/\u{fc}";
    let (status, headers, body) = post(&client, &url, &json!({"id": id, "name": "x"})).await;
    assert_eq!(status, 201, "{body}");
    assert_eq!(headers["location"], "/api/v1/machines/pump%201%2F%C3%BC");
    assert_eq!(body["id"], id);
    let (status, _, got) = send(client.get(server.url("/api/v1/machines/pump%201%2F%C3%BC"))).await;
    assert_eq!((status, &got["id"]), (200, &json!(id)));
}

#[tokio::test]
async fn a_put_with_a_stale_if_match_is_refused_with_412() {
    let (_dir, server, client) = fresh_server().await;
    let session = two_plane();
    let id = store(&client, &server, &session).await;
    let run_id = session["runs"][1]["id"].as_str().unwrap();
    let run_url = server.url(&format!("/api/v1/sessions/{id}/runs/{run_id}"));

    let (status, headers, run) = send(client.get(&run_url)).await;
    assert_eq!(status, 200);
    let as_run = |v: &Value| -> fieldbal::balancing::model::Run {
        serde_json::from_value(v.clone()).unwrap()
    };
    assert_eq!(as_run(&run), as_run(&session["runs"][1]));
    let tag = headers["etag"].to_str().unwrap().to_string();

    // Tab 1 corrects the run with the tag it read: accepted, new tag.
    let mut corrected = run.clone();
    corrected["readings"][0]["amplitude"] = json!(99.0);
    let (status, headers, _) = send(
        client
            .put(&run_url)
            .header("If-Match", &tag)
            .json(&corrected),
    )
    .await;
    assert_eq!(status, 200);
    assert_ne!(headers["etag"].to_str().unwrap(), tag);
    // Tab 2 still holds the first tag: refused, the correction of tab 1 kept.
    let (status, _, body) = send(client.put(&run_url).header("If-Match", &tag).json(&run)).await;
    assert_eq!(status, 412, "{body}");
    assert_eq!(body["error"]["code"], "precondition_failed");
    assert_eq!(body["error"]["field"], "If-Match");
    let (_, _, now) = send(client.get(&run_url)).await;
    assert_eq!(now["readings"][0]["amplitude"], 99.0);
    // Without If-Match a PUT still corrects (v1).
    let (status, _, _) = send(client.put(&run_url).json(&run)).await;
    assert_eq!(status, 200);
}

#[tokio::test]
async fn a_session_etag_changes_when_a_run_is_corrected() {
    let (_dir, server, client) = fresh_server().await;
    let session = two_plane();
    let id = store(&client, &server, &session).await;
    let url = server.url(&format!("/api/v1/sessions/{id}"));
    let (_, h1, _) = send(client.get(&url)).await;
    let (_, h2, _) = send(client.get(&url)).await;
    assert_eq!(h1["etag"], h2["etag"], "stable while nothing changes");
    let mut run = session["runs"][1].clone();
    run["readings"][0]["amplitude"] = json!(98.0);
    let run_url = format!("{url}/runs/{}", run["id"].as_str().unwrap());
    send(client.put(&run_url).json(&run)).await;
    let (_, h3, _) = send(client.get(&url)).await;
    assert_ne!(h1["etag"], h3["etag"]);
}

#[tokio::test]
async fn versions_and_solutions_are_paged_within_bounds() {
    let (_dir, server, client) = fresh_server().await;
    let session = two_plane();
    let id = store(&client, &server, &session).await;
    let run = session["runs"][1].clone();
    let run_url = server.url(&format!(
        "/api/v1/sessions/{id}/runs/{}",
        run["id"].as_str().unwrap()
    ));
    for _ in 0..3 {
        send(client.put(&run_url).json(&run)).await;
    }
    let (status, headers, page) =
        send(client.get(format!("{run_url}/versions?limit=2&offset=1"))).await;
    assert_eq!(status, 200);
    assert_eq!(headers["x-total-count"], "4");
    let versions: Vec<i64> = page
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["version"].as_i64().unwrap())
        .collect();
    assert_eq!(versions, [2, 3]);
    let cases = [
        ("versions?limit=0", "limit"),
        ("versions?limit=1001", "limit"),
        ("versions?offset=-1", "offset"),
    ];
    for (query, field) in cases {
        let (status, _, body) = send(client.get(format!("{run_url}/{query}"))).await;
        assert_eq!(status, 422, "{query}");
        assert_eq!(body["error"]["field"], field, "{query}");
    }
    let sol_url = server.url(&format!("/api/v1/sessions/{id}/solutions"));
    let (status, _, body) = send(client.get(format!("{sol_url}?limit=101"))).await;
    assert_eq!(status, 422, "{body}");
    assert_eq!(body["error"]["field"], "limit");
}

/// The text of a keyed POST's answer and whether it was a replay.
async fn post_keyed_text(
    client: &reqwest::Client,
    url: &str,
    key: &str,
    body: &Value,
) -> (u16, bool, String) {
    let response = client
        .post(url)
        .header("Idempotency-Key", key)
        .json(body)
        .send()
        .await
        .unwrap();
    let status = response.status().as_u16();
    let replayed = response.headers().get("idempotent-replayed").is_some();
    (status, replayed, response.text().await.unwrap())
}

#[tokio::test]
async fn a_replayed_answer_is_the_first_answer_byte_for_byte() {
    // The kept answer was parsed back into a JSON value, whose keys are
    // sorted: a client comparing or hashing the retry's text saw another
    // document (a stored solution's `id` after its `correction`, say).
    let (_dir, server, client) = fresh_server().await;
    let id = store(&client, &server, &two_plane()).await;
    let url = server.url(&format!("/api/v1/sessions/{id}/solutions"));
    let (s1, r1, first) = post_keyed_text(&client, &url, "text-key", &json!({})).await;
    let (s2, r2, again) = post_keyed_text(&client, &url, "text-key", &json!({})).await;
    assert_eq!((s1, r1, s2, r2), (201, false, 201, true));
    assert_eq!(
        first, again,
        "the replay's text differs from the first answer's"
    );
}
