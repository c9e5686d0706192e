//! What every answer carries and what the edge refuses before a handler: security
//! headers, writes that are not JSON (a cross-site "simple" request), an oversize
//! `Content-Length`, and protocol-level errors with the contract's JSON body.

use crate::common;
use crate::support;

use reqwest::header::{CONTENT_TYPE, ORIGIN};
use serde_json::json;

use common::{example, fresh_server, post, send, start_server};
use support::exchange;

#[tokio::test]
async fn api_answers_are_not_sniffed_cached_or_framed_and_the_form_allows_only_itself() {
    let (_dir, server, client) = fresh_server().await;
    for path in [
        "/api/v1/sessions",
        "/api/v1/sessions/nope",
        "/healthz",
        "/api/v1/openapi.json",
    ] {
        let res = client.get(server.url(path)).send().await.unwrap();
        let h = res.headers();
        assert_eq!(h["x-content-type-options"], "nosniff", "{path}");
        assert_eq!(h["cache-control"], "no-store", "{path}");
        assert_eq!(h["x-frame-options"], "DENY", "{path}");
        assert!(
            h["content-security-policy"]
                .to_str()
                .unwrap()
                .contains("frame-ancestors 'none'"),
            "{path}"
        );
    }
    for path in ["/", "/static/js/job/api.js"] {
        let res = client.get(server.url(path)).send().await.unwrap();
        let h = res.headers();
        assert_eq!(h["x-content-type-options"], "nosniff", "{path}");
        assert_eq!(h["x-frame-options"], "DENY", "{path}");
        let csp = h["content-security-policy"].to_str().unwrap();
        assert!(
            csp.contains("default-src 'self'") && csp.contains("frame-ancestors 'none'"),
            "{path}: {csp}"
        );
    }
    server.shutdown().await;
}

#[tokio::test]
async fn a_write_that_is_not_json_is_refused_with_415_and_changes_nothing() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &session).await;
    let id = created["id"].as_str().unwrap();
    let solutions = format!("/api/v1/sessions/{id}/solutions");
    // What a page elsewhere can send without a preflight: no body, text/plain,
    // a form encoding, multipart.
    let cases: [(&str, &str, Option<&str>, String); 5] = [
        (
            "empty solve-and-store, no content type",
            "POST",
            None,
            String::new(),
        ),
        (
            "empty solve-and-store as text",
            "POST",
            Some("text/plain"),
            String::new(),
        ),
        (
            "session as text/plain",
            "POST",
            Some("text/plain"),
            session.to_string(),
        ),
        (
            "session as a form",
            "POST",
            Some("application/x-www-form-urlencoded"),
            session.to_string(),
        ),
        (
            "session as multipart",
            "POST",
            Some("multipart/form-data; boundary=x"),
            session.to_string(),
        ),
    ];
    for (what, method, content_type, body) in cases {
        let path = if what.contains("solve") {
            solutions.clone()
        } else {
            "/api/v1/sessions".into()
        };
        let mut req = client
            .request(method.parse().unwrap(), server.url(&path))
            .header(ORIGIN, "http://evil.example")
            .body(body);
        if let Some(t) = content_type {
            req = req.header(CONTENT_TYPE, t);
        }
        let (status, _, answer) = send(req).await;
        assert_eq!(status, 415, "{what}: {answer}");
        assert_eq!(answer["error"]["code"], "unsupported_media_type", "{what}");
    }
    let (_, _, stored) = send(client.get(server.url(&solutions))).await;
    assert_eq!(stored, json!([]));
    let (_, _, list) = send(client.get(server.url("/api/v1/sessions"))).await;
    assert_eq!(list["total"], 1);
    // The same empty solve-and-store declared as JSON uses the default options.
    let (status, _, _) = send(
        client
            .post(server.url(&solutions))
            .header(CONTENT_TYPE, "application/json"),
    )
    .await;
    assert_eq!(status, 201);
    server.shutdown().await;
}

#[tokio::test]
async fn an_announced_body_over_the_limit_gets_413_before_it_is_sent() {
    let answer = support::answer_to_head(|addr| {
        format!(
            "POST /api/v1/sessions HTTP/1.1\r\nHost: {addr}\r\nContent-Type: application/json\r\n\
             Content-Length: {}\r\n\r\n{{",
            fieldbal::http::DEFAULT_BODY_LIMIT + 1
        )
    })
    .await;
    assert_eq!(answer.status, 413);
    assert_eq!(answer.json()["error"]["code"], "body_too_large");
}

/// A body sent without `Content-Length` (chunked) that runs over the limit
/// is refused as one announced over it is: 413 naming the limit, which the
/// chunked refusal did not ("larger than the server's limit").
#[tokio::test]
async fn a_chunked_body_over_the_limit_gets_413_naming_the_limit() {
    let dir = tempfile::tempdir().unwrap();
    let limit = 1000;
    let (addr, server) = common::start_server_with(&dir.path().join("t.db"), limit).await;
    let chunk = " ".repeat(limit + 1);
    let request = format!(
        "POST /api/v1/solve HTTP/1.1\r\nHost: {addr}\r\nContent-Type: application/json\r\n\
         Transfer-Encoding: chunked\r\nConnection: close\r\n\r\n{:x}\r\n{chunk}\r\n0\r\n\r\n",
        chunk.len()
    );
    let answer = exchange(addr, request.as_bytes()).await.expect("an answer");
    assert_eq!(answer.status, 413);
    let body = answer.json();
    assert_eq!(body["error"]["code"], "body_too_large", "{body}");
    let message = body["error"]["message"].as_str().unwrap();
    assert!(
        message.contains(&format!("limit of {limit} bytes")),
        "{message}"
    );
    server.shutdown().await;
}

#[tokio::test]
async fn protocol_level_errors_carry_the_contract_error_body() {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) = start_server(&dir.path().join("t.db")).await;
    let long_target = format!("/api/v1/sessions/{}", "a".repeat(10_000));
    let many_headers: String = (0..150).map(|i| format!("X-Filler-{i}: {i}\r\n")).collect();
    let big_header = format!("X-Big: {}\r\n", "b".repeat(40_000));
    // (what, request target, extra header lines, status, code, field)
    let cases = [
        (
            "a 10 kB request target",
            long_target.as_str(),
            "",
            414,
            "uri_too_long",
            None,
        ),
        (
            "150 header fields",
            "/api/v1/sessions",
            many_headers.as_str(),
            431,
            "headers_too_large",
            None,
        ),
        (
            "a 40 kB header",
            "/api/v1/sessions",
            big_header.as_str(),
            431,
            "headers_too_large",
            None,
        ),
        (
            "a session id that is not UTF-8",
            "/api/v1/sessions/%FF%FE",
            "",
            400,
            "bad_request",
            Some("id"),
        ),
        (
            "a method the path does not have",
            "/api/v1/sessions",
            "",
            405,
            "method_not_allowed",
            None,
        ),
    ];
    for (what, target, extra, status, code, field) in cases {
        let method = if status == 405 { "DELETE" } else { "GET" };
        let request = format!(
            "{method} {target} HTTP/1.1\r\nHost: {addr}\r\n{extra}Connection: close\r\n\r\n"
        );
        let answer = exchange(addr, request.as_bytes()).await.expect("an answer");
        assert_eq!(answer.status, status, "{what}");
        assert_eq!(answer.json()["error"]["code"], code, "{what}");
        assert_eq!(answer.json()["error"]["field"].as_str(), field, "{what}");
        assert!(
            answer
                .header("content-type")
                .unwrap()
                .starts_with("application/json"),
            "{what}"
        );
    }
    server.shutdown().await;
}

/// What hyper answers itself, before the service sees a request (a request it
/// cannot parse, a target beyond its 64 KiB, more header fields than it
/// reads), gets the contract's JSON body too, and the connection closes.
#[tokio::test]
async fn requests_hyper_refuses_before_the_service_get_the_contract_error_body() {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) = start_server(&dir.path().join("t.db")).await;
    let host = format!("Host: {addr}\r\n");
    let target = format!("GET /{} HTTP/1.1\r\n{host}\r\n", "a".repeat(70_000));
    let fields: String = (0..300).map(|i| format!("X-Filler-{i}: {i}\r\n")).collect();
    let fields = format!("GET /healthz HTTP/1.1\r\n{host}{fields}\r\n");
    // (what, raw request, status, code)
    let cases = [
        (
            "a control byte in the target",
            "GET /\x01bad HTTP/1.1\r\nHost: x\r\n\r\n".to_string(),
            400,
            "bad_request",
        ),
        (
            "a header line without a colon",
            format!("GET /healthz HTTP/1.1\r\n{host}Bad Header\r\n\r\n"),
            400,
            "bad_request",
        ),
        (
            "not HTTP at all",
            "GARBAGE\r\n\r\n".to_string(),
            400,
            "bad_request",
        ),
        ("a 70 kB request target", target, 414, "uri_too_long"),
        ("300 header fields", fields, 431, "headers_too_large"),
    ];
    for (what, request, status, code) in cases {
        let answer = exchange(addr, request.as_bytes()).await.expect("an answer");
        assert_eq!(answer.status, status, "{what}");
        assert_eq!(answer.header("connection"), Some("close"), "{what}");
        assert_eq!(answer.json()["error"]["code"], code, "{what}");
        assert_eq!(
            answer.header("content-type"),
            Some("application/json"),
            "{what}"
        );
    }
    server.shutdown().await;
}
