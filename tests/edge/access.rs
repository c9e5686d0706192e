//! Bearer tokens with roles, and the `Host` check against DNS rebinding: who
//! may read, who may change the store, and which names the service answers to.

use crate::common;

use fieldbal::http::edge::access::Tokens;
use fieldbal::http::edge::hosts::AllowedHosts;
use fieldbal::http::edge::EdgeConfig;
use reqwest::header::{CONTENT_TYPE, HOST, WWW_AUTHENTICATE};
use reqwest::Method;
use serde_json::json;

use common::{example, send, start_server_configured};

const WRITE: &str = "write-token-for-the-stand-pc";
const READ: &str = "read-token-for-the-office";

/// (what, method, path, body, token, status, error code)
type Case<'a> = (
    &'a str,
    Method,
    String,
    Option<serde_json::Value>,
    Option<&'a str>,
    u16,
    &'a str,
);

async fn server_with_tokens(dir: &std::path::Path) -> common::Server {
    let tokens = Tokens::parse(&format!("write {WRITE}\nread {READ}\n"), "test").unwrap();
    let edge = EdgeConfig {
        tokens,
        ..EdgeConfig::default()
    };
    start_server_configured(&dir.join("t.db"), |s| s.with_edge(edge))
        .await
        .1
}

#[tokio::test]
async fn with_tokens_configured_each_request_gets_the_answer_its_role_allows() {
    let dir = tempfile::tempdir().unwrap();
    let server = server_with_tokens(dir.path()).await;
    let client = reqwest::Client::new();
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let (status, _, created) = send(
        client
            .post(server.url("/api/v1/sessions"))
            .bearer_auth(WRITE)
            .json(&session),
    )
    .await;
    assert_eq!(status, 201, "{created}");
    let id = created["id"].as_str().unwrap().to_string();
    let solve = json!({ "session": session });

    #[rustfmt::skip]
    let cases: Vec<Case> = vec![
        ("list without a token", Method::GET, "/api/v1/sessions".into(), None, None, 401, "unauthorized"),
        ("list with a wrong token", Method::GET, "/api/v1/sessions".into(), None, Some("not-a-configured-token"), 401, "unauthorized"),
        ("list with a token one character short", Method::GET, "/api/v1/sessions".into(), None, Some(&WRITE[1..]), 401, "unauthorized"),
        ("openapi without a token", Method::GET, "/api/v1/openapi.json".into(), None, None, 401, "unauthorized"),
        ("store without a token", Method::POST, "/api/v1/sessions".into(), Some(session.clone()), None, 401, "unauthorized"),
        ("store with the read token", Method::POST, "/api/v1/sessions".into(), Some(session.clone()), Some(READ), 403, "forbidden"),
        ("delete with the read token", Method::DELETE, format!("/api/v1/sessions/{id}"), None, Some(READ), 403, "forbidden"),
        ("solve and store with the read token", Method::POST, format!("/api/v1/sessions/{id}/solutions"), Some(json!({})), Some(READ), 403, "forbidden"),
        ("list with the read token", Method::GET, "/api/v1/sessions".into(), None, Some(READ), 200, ""),
        ("read back with the read token", Method::GET, format!("/api/v1/sessions/{id}"), None, Some(READ), 200, ""),
        ("stateless solve with the read token", Method::POST, "/api/v1/solve".into(), Some(solve.clone()), Some(READ), 200, ""),
        ("solve and store with the write token", Method::POST, format!("/api/v1/sessions/{id}/solutions"), Some(json!({})), Some(WRITE), 201, ""),
    ];
    for (what, method, path, body, token, want, code) in cases {
        let mut req = client.request(method, server.url(&path));
        if let Some(body) = &body {
            req = req.json(body);
        }
        if let Some(token) = token {
            req = req.bearer_auth(token);
        }
        let (status, headers, answer) = send(req).await;
        assert_eq!(status, want, "{what}: {answer}");
        if want >= 400 {
            assert_eq!(answer["error"]["code"], code, "{what}");
            assert_eq!(answer["error"]["field"], "Authorization", "{what}");
            let challenge = headers[WWW_AUTHENTICATE].to_str().unwrap();
            assert!(challenge.starts_with("Bearer"), "{what}: {challenge}");
            assert!(
                !answer.to_string().contains("token-for"),
                "{what} echoes a token"
            );
        }
    }
    // Only the write token's solve was stored.
    let (_, _, solutions) = send(
        client
            .get(server.url(&format!("/api/v1/sessions/{id}/solutions")))
            .bearer_auth(READ),
    )
    .await;
    assert_eq!(solutions.as_array().unwrap().len(), 1);
    server.shutdown().await;
}

#[tokio::test]
async fn health_and_the_web_form_need_no_token() {
    let dir = tempfile::tempdir().unwrap();
    let server = server_with_tokens(dir.path()).await;
    let client = reqwest::Client::new();
    for path in [
        "/healthz",
        "/",
        "/static/js/job/api.js",
        "/static/style.css",
    ] {
        let res = client.get(server.url(path)).send().await.unwrap();
        assert_eq!(res.status(), 200, "{path}");
    }
    server.shutdown().await;
}

#[tokio::test]
async fn a_request_naming_another_host_is_refused_naming_the_host_header() {
    let dir = tempfile::tempdir().unwrap();
    let edge = EdgeConfig {
        hosts: AllowedHosts::parse("stand-pc"),
        ..EdgeConfig::default()
    };
    let (addr, server) =
        start_server_configured(&dir.path().join("t.db"), |s| s.with_edge(edge)).await;
    let client = reqwest::Client::new();
    let port = addr.port();
    let table = [
        (format!("127.0.0.1:{port}"), 200),
        (format!("localhost:{port}"), 200),
        (format!("[::1]:{port}"), 200),
        (format!("stand-pc:{port}"), 200),
        (format!("evil.example:{port}"), 421),
        (format!("localhost.evil.example:{port}"), 421),
        (format!("127.0.0.1.evil.example:{port}"), 421),
        (format!("2130706433:{port}"), 421),
    ];
    for (host, want) in table {
        for path in ["/api/v1/sessions", "/healthz", "/"] {
            let (status, _, body) = if want == 200 {
                let res = client
                    .get(server.url(path))
                    .header(HOST, &host)
                    .send()
                    .await
                    .unwrap();
                (
                    res.status().as_u16(),
                    res.headers().clone(),
                    serde_json::Value::Null,
                )
            } else {
                send(client.get(server.url(path)).header(HOST, &host)).await
            };
            assert_eq!(status, want, "Host: {host} {path}");
            if want != 200 {
                assert_eq!(body["error"]["code"], "host_not_allowed");
                assert_eq!(body["error"]["field"], "Host");
            }
        }
    }
    // A rebinding page's write never reaches the store.
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let (status, _, _) = send(
        client
            .post(server.url("/api/v1/sessions"))
            .header(HOST, format!("evil.example:{port}"))
            .header(CONTENT_TYPE, "application/json")
            .body(session.to_string()),
    )
    .await;
    assert_eq!(status, 421);
    let (_, _, list) = send(client.get(server.url("/api/v1/sessions"))).await;
    assert_eq!(list["total"], 0);
    server.shutdown().await;
}

#[test]
fn the_serve_command_refuses_to_start_with_a_malformed_tokens_file() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("tokens");
    std::fs::write(
        &file,
        "# roles\nwrite a-long-enough-token-here\nadmin another-long-token-1234\n",
    )
    .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["serve", "--listen", "127.0.0.1:0", "--tokens-file"])
        .arg(&file)
        .env("DATABASE_URL", dir.path().join("t.db"))
        .env_remove("FIELDBAL_TOKENS")
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    assert!(!out.status.success());
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(log.contains("entry 3"), "{log}");
    assert!(
        !log.contains("another-long-token"),
        "the log shows a token: {log}"
    );
}
