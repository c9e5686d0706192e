//! Service behaviour around the API: request ids, a configured body limit,
//! content-type parameters, a stalled client's time limit, and racing appends of one run.

use crate::common;

use std::time::Duration;

use common::{example, fresh_server, post, send, start_server_configured, start_server_with};
use serde_json::json;
use tokio::io::{AsyncReadExt, AsyncWriteExt};

#[tokio::test]
async fn a_request_id_is_generated_or_echoed() {
    let (_dir, server, client) = fresh_server().await;
    let res = client.get(server.url("/healthz")).send().await.unwrap();
    let generated = res.headers()["x-request-id"].to_str().unwrap().to_string();
    assert_eq!(generated.len(), 36, "a uuid: {generated}");
    let res = client
        .get(server.url("/api/v1/sessions/none"))
        .header("x-request-id", "stand-42")
        .send()
        .await
        .unwrap();
    assert_eq!(res.status(), 404);
    assert_eq!(res.headers()["x-request-id"], "stand-42");
    server.shutdown().await;
}

#[tokio::test]
async fn the_body_limit_is_configurable_and_answered_with_413_json() {
    let dir = tempfile::tempdir().unwrap();
    let (_, server) = start_server_with(&dir.path().join("t.db"), 1024).await;
    let client = reqwest::Client::new();
    let session = example("pump-two-plane-exact.json")["session"].clone();
    assert!(session.to_string().len() > 1024);
    let (status, _, body) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    assert_eq!(
        (status, body["error"]["code"].as_str()),
        (413, Some("body_too_large"))
    );
    let mut small = session.clone();
    small["runs"] = json!([]);
    let (status, _, body) = post(&client, &server.url("/api/v1/sessions"), &small).await;
    assert_eq!(status, 201, "{body}");
    server.shutdown().await;
}

#[tokio::test]
async fn json_with_a_charset_parameter_is_accepted() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let req = client
        .post(server.url("/api/v1/sessions"))
        .header("content-type", "application/json; charset=utf-8")
        .body(session.to_string());
    let (status, _, body) = send(req).await;
    assert_eq!(status, 201, "{body}");
    server.shutdown().await;
}

#[tokio::test]
async fn of_ten_racing_appends_of_one_run_exactly_one_is_stored() {
    let (_dir, server, client) = fresh_server().await;
    let mut session = example("pump-two-plane-exact.json")["session"].clone();
    let run = session["runs"].as_array_mut().unwrap().pop().unwrap();
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    let base = format!("/api/v1/sessions/{}", created["id"].as_str().unwrap());
    let tasks: Vec<_> = (0..10)
        .map(|_| {
            let (client, url, run) = (
                client.clone(),
                server.url(&format!("{base}/runs")),
                run.clone(),
            );
            tokio::spawn(async move { post(&client, &url, &run).await.0 })
        })
        .collect();
    let mut statuses = Vec::new();
    for task in tasks {
        statuses.push(task.await.unwrap());
    }
    statuses.sort_unstable();
    assert_eq!(statuses, [201, 409, 409, 409, 409, 409, 409, 409, 409, 409]);
    let (_, _, back) = send(client.get(server.url(&base))).await;
    assert_eq!(back["runs"].as_array().unwrap().len(), 3);
    server.shutdown().await;
}

#[tokio::test]
async fn a_client_that_stalls_mid_body_gets_a_json_408_and_nothing_is_stored() {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) = start_server_configured(&dir.path().join("t.db"), |s| {
        s.with_request_timeout(Duration::from_millis(300))
    })
    .await;
    let mut stream = tokio::net::TcpStream::connect(addr).await.unwrap();
    let head = format!(
        "POST /api/v1/sessions HTTP/1.1\r\nhost: {addr}\r\ncontent-type: application/json\r\ncontent-length: 1000\r\n\r\n{{\"name\": "
    );
    stream.write_all(head.as_bytes()).await.unwrap();
    let mut answer = Vec::new();
    tokio::time::timeout(Duration::from_secs(10), stream.read_to_end(&mut answer))
        .await
        .expect("the server answers within its time limit")
        .unwrap();
    let answer = String::from_utf8_lossy(&answer);
    assert!(answer.starts_with("HTTP/1.1 408"), "{answer}");
    assert!(answer.contains("\"code\":\"request_timeout\""), "{answer}");
    let client = reqwest::Client::new();
    let (status, _, list) = send(client.get(server.url("/api/v1/sessions"))).await;
    assert_eq!((status, &list["total"]), (200, &json!(0)), "{list}");
    server.shutdown().await;
}
