//! Query parameters: every GET refuses one it does not take, and no write
//! takes any (outside review, session 23).

use crate::common;
use crate::support::{error_of, machine_p1, pump};

use common::{fresh_server, post, send};
use serde_json::{json, Value};

/// Every GET of the API refuses a query parameter it does not take with
/// 400 `invalid_query` naming it, as the lists and `GET
/// /api/v1/machines/{id}` did, before it looks for the resource (an
/// unknown one is still 400): `GET /api/v1/sessions/{id}`, a run's GET
/// and the OpenAPI document ignored it, so a client's misspelt
/// parameter read as if it had been applied. The OpenAPI document lists
/// the 400 on every GET of the API.
#[tokio::test]
async fn every_get_refuses_a_query_parameter_it_does_not_take() {
    let (_dir, server, client) = fresh_server().await;
    let mut s = pump();
    s["machine"] = json!("P-1");
    machine_p1(&client, &server).await;
    let (status, _, body) = post(&client, &server.url("/api/v1/sessions"), &s).await;
    assert_eq!(status, 201, "{body}");
    let id = body["id"].as_str().unwrap().to_string();
    let session = format!("/api/v1/sessions/{id}");
    let gets = [
        "/api/v1/openapi.json".to_string(),
        "/api/v1/sessions".into(),
        session.clone(),
        format!("{session}/runs/zero"),
        format!("{session}/runs/zero/versions"),
        format!("{session}/solutions"),
        "/api/v1/machines".into(),
        "/api/v1/machines/P-1".into(),
        "/api/v1/machines/P-1/coefficients".into(),
        // Not there: the query is refused first, as on machines/{id}.
        "/api/v1/sessions/no-such-session".into(),
        format!("{session}/runs/no-such-run"),
    ];
    for path in &gets {
        for query in [
            "verison=2",
            "bogus",
            "limit=1&x_y=",
            "version=1&fields=name",
        ] {
            let url = server.url(&format!("{path}?{query}"));
            let (status, _, body) = send(client.get(&url)).await;
            let (code, field, message) = error_of(&body);
            let want = query
                .split('&')
                .map(|p| p.split('=').next().unwrap())
                .find(|p| !takes(path, p))
                .unwrap();
            assert_eq!(
                (status, code, field),
                (400, "invalid_query", Some(want)),
                "GET {path}?{query}: {message}"
            );
        }
        // Without a query each answers as before: the unknown ones, and
        // the coefficients of a machine that has none yet, 404.
        let (status, _, body) = send(client.get(server.url(path))).await;
        let missing = path.contains("no-such") || path.ends_with("/coefficients");
        assert_eq!(
            status,
            if missing { 404 } else { 200 },
            "GET {path}: {body}"
        );
    }
    // The document says so: every GET's 400 is about its query parameters
    // (not only the edge's general "malformed request").
    let (_, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    for (path, item) in doc["paths"].as_object().unwrap() {
        if let Some(get) = item.get("get").filter(|_| path.starts_with("/api/v1/")) {
            let said = get["responses"]["400"]["description"]
                .as_str()
                .unwrap_or("");
            assert!(said.contains("query parameter"), "GET {path}: 400 {said:?}");
        }
    }
}

/// Whether `path` takes the query parameter `name`: `limit` on a list,
/// `version` on a machine's coefficients.
fn takes(path: &str, name: &str) -> bool {
    let paged = [
        "/api/v1/sessions",
        "/api/v1/machines",
        "/api/v1/machines/P-1",
    ]
    .contains(&path)
        || path.ends_with("/versions")
        || path.ends_with("/solutions");
    match name {
        "limit" => paged,
        "version" => path.ends_with("/coefficients"),
        _ => false,
    }
}

/// No write of the API takes a query parameter: a POST, PUT or DELETE
/// with one is refused with 400 `invalid_query` naming it, nothing done.
/// `POST /api/v1/solve?discrete=true` answered the solve without a fit,
/// `POST …/solutions?dry_run=1` stored a solution, and `DELETE
/// …/sessions/{id}?if_match=…` deleted unconditionally.
#[tokio::test]
async fn no_write_takes_a_query_parameter() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &pump()).await;
    let session = format!("/api/v1/sessions/{}", created["id"].as_str().unwrap());
    let (_, _, run) = send(client.get(server.url(&format!("{session}/runs/zero")))).await;
    let solve = json!({"session": pump()});
    let writes = [
        (
            "POST",
            "/api/v1/solve?discrete=true".to_string(),
            solve.clone(),
        ),
        ("POST", "/api/v1/trial-weights?planes=inboard".into(), solve),
        ("POST", format!("{session}/solutions?dry_run=1"), json!({})),
        ("PUT", format!("{session}/runs/zero?version=1"), run),
        ("DELETE", format!("{session}?if_match=x"), Value::Null),
        (
            "POST",
            "/api/v1/machines?upsert".into(),
            json!({"id": "P-1"}),
        ),
    ];
    for (method, path, body) in writes {
        let mut req = client.request(method.parse().unwrap(), server.url(&path));
        if !body.is_null() {
            req = req.json(&body);
        }
        let (status, _, err) = send(req).await;
        let (code, field, message) = error_of(&err);
        let want = path.split('?').nth(1).unwrap().split('=').next().unwrap();
        assert_eq!(
            (status, code, field),
            (400, "invalid_query", Some(want)),
            "{method} {path}: {message}"
        );
    }
    // Nothing was done: the session is there with no solution, no run
    // version was added, no machine made.
    let (status, _, _) = send(client.get(server.url(&session))).await;
    assert_eq!(status, 200);
    let (_, headers, _) = send(client.get(server.url(&format!("{session}/solutions")))).await;
    assert_eq!(headers["x-total-count"], "0");
    let (_, headers, _) =
        send(client.get(server.url(&format!("{session}/runs/zero/versions")))).await;
    assert_eq!(headers["x-total-count"], "1");
    let (status, _, _) = send(client.get(server.url("/api/v1/machines/P-1"))).await;
    assert_eq!(status, 404);
    // An empty query is no parameter.
    let (status, _, body) = post(
        &client,
        &server.url("/api/v1/solve?"),
        &json!({"session": pump()}),
    )
    .await;
    assert_eq!(status, 200, "{body}");
}
