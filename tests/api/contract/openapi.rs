//! The OpenAPI document served at /api/v1/openapi.json lists every endpoint of
//! the contract, with the contract's error body.

use crate::common;

use common::{fresh_server, send};

#[tokio::test]
async fn the_openapi_document_lists_every_endpoint_and_the_error_body() {
    let (_dir, server, client) = fresh_server().await;
    let (status, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    assert_eq!(status, 200);
    assert!(doc["openapi"].as_str().unwrap().starts_with("3."));

    let expected = [
        ("/healthz", "get"),
        ("/api/v1/openapi.json", "get"),
        ("/api/v1/solve", "post"),
        ("/api/v1/trial-weights", "post"),
        ("/api/v1/sessions", "post"),
        ("/api/v1/sessions", "get"),
        ("/api/v1/sessions/{id}", "get"),
        ("/api/v1/sessions/{id}", "delete"),
        ("/api/v1/sessions/{id}/runs", "post"),
        ("/api/v1/sessions/{id}/runs/{run_id}", "get"),
        ("/api/v1/sessions/{id}/runs/{run_id}", "put"),
        ("/api/v1/sessions/{id}/runs/{run_id}/versions", "get"),
        ("/api/v1/sessions/{id}/solutions", "post"),
        ("/api/v1/sessions/{id}/solutions", "get"),
        ("/api/v1/residual-unbalance", "post"),
        ("/api/v1/machines", "post"),
        ("/api/v1/machines", "get"),
        ("/api/v1/machines/{id}", "get"),
        ("/api/v1/machines/{id}", "delete"),
        ("/api/v1/machines/{id}/coefficients", "post"),
        ("/api/v1/machines/{id}/coefficients", "get"),
        ("/api/v1/identify/rotor", "post"),
        ("/api/v1/identify/free-decay", "post"),
        ("/api/v1/identify/model", "post"),
    ];
    let mut listed: Vec<(String, String)> = doc["paths"]
        .as_object()
        .unwrap()
        .iter()
        .flat_map(|(path, item)| {
            item.as_object()
                .unwrap()
                .keys()
                .filter(|k| ["get", "post", "put", "delete", "patch"].contains(&k.as_str()))
                .map(move |m| (path.clone(), m.clone()))
        })
        .collect();
    listed.sort();
    let mut want: Vec<(String, String)> = expected
        .iter()
        .map(|(p, m)| (p.to_string(), m.to_string()))
        .collect();
    want.sort();
    assert_eq!(listed, want);

    let schemas = doc["components"]["schemas"].as_object().unwrap();
    for name in [
        "Session",
        "Run",
        "SolveRequest",
        "SolveOptions",
        "Solution",
        "ErrorBody",
        "StoredSolution",
        "SessionList",
    ] {
        assert!(schemas.contains_key(name), "schema {name} missing");
    }
    let detail = &schemas["ErrorDetail"]["properties"];
    for field in ["code", "message", "field"] {
        assert!(detail.get(field).is_some(), "error detail lacks {field}");
    }
    // Every 4xx response of the session post names the error body.
    let responses = &doc["paths"]["/api/v1/sessions"]["post"]["responses"];
    for status in ["400", "413", "415", "422"] {
        let schema = &responses[status]["content"]["application/json"]["schema"]["$ref"];
        assert_eq!(schema, "#/components/schemas/ErrorBody", "{status}");
    }
    server.shutdown().await;
}

/// Every operation, as a client generator and a reader of the document see
/// it: a one-line `summary`, an `operationId` no other operation has (a
/// generator names its methods by them: `list` twice, for sessions and
/// machines, made two methods of one name), a 503 row naming every 503 the
/// service sends there, and a 403 row only where a read-only token is
/// refused (a store write; `access::is_write`).
#[tokio::test]
async fn every_operation_has_a_summary_a_unique_id_and_its_real_refusals() {
    let (_dir, server, client) = fresh_server().await;
    let (status, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    assert_eq!(status, 200);
    let mut ids = std::collections::BTreeMap::new();
    let mut faults = Vec::new();
    for (path, item) in doc["paths"].as_object().unwrap() {
        for (method, op) in item.as_object().unwrap() {
            let what = format!("{} {path}", method.to_uppercase());
            let summary = op["summary"].as_str().unwrap_or_default();
            if summary.trim().is_empty() || summary.len() > 80 || summary.contains('\n') {
                faults.push(format!("{what}: summary {summary:?}"));
            }
            let id = op["operationId"].as_str().unwrap_or_default().to_string();
            if let Some(other) = ids.insert(id.clone(), what.clone()) {
                faults.push(format!("{what}: operationId {id:?} also {other}"));
            }
            let unavailable = op["responses"]["503"]["description"]
                .as_str()
                .unwrap_or_default();
            let store = path.starts_with("/api/v1/sessions")
                || path.starts_with("/api/v1/machines")
                // `coefficients_from` reads a machine's stored coefficients.
                || path == "/api/v1/solve"
                || path == "/api/v1/trial-weights";
            let solver = [
                "/api/v1/solve",
                "/api/v1/trial-weights",
                "/api/v1/identify/",
            ]
            .iter()
            .any(|p| path.starts_with(p))
                || (method == "post" && path.ends_with("/solutions"))
                || (method == "post" && path.ends_with("/coefficients"));
            let mut codes = vec!["too_many_connections"];
            if store {
                codes.push("storage_unavailable");
            }
            if solver {
                codes.push("`busy`");
            }
            if path == "/healthz" {
                codes.push("not_ready");
            }
            for code in codes {
                if !unavailable.contains(code) {
                    faults.push(format!("{what}: 503 does not name {code}: {unavailable:?}"));
                }
            }
            let write = method != "get"
                && ![
                    "/api/v1/solve",
                    "/api/v1/trial-weights",
                    "/api/v1/residual-unbalance",
                ]
                .contains(&path.as_str())
                && !path.starts_with("/api/v1/identify/");
            if op["responses"].get("403").is_some() != write {
                faults.push(format!("{what}: 403 declared: {}", !write));
            }
        }
    }
    assert!(faults.is_empty(), "{faults:#?}");
}

/// The headers the service's answers carry for a client to use (`ETag`,
/// `Location`, `X-Total-Count`) are declared on the answer that carries
/// them: a stored or corrected run's `ETag` (to send as `If-Match` with the
/// next `PUT`) was sent but not declared.
#[tokio::test]
async fn the_headers_answers_carry_are_declared_in_the_document() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    let session = common::example("pump-two-plane-exact.json");
    let session = session.get("session").cloned().unwrap_or(session);
    let (status, _, created) =
        common::post(&client, &server.url("/api/v1/sessions"), &session).await;
    assert_eq!(status, 201, "{created}");
    let id = created["id"].as_str().unwrap().to_string();
    let mut run = session["runs"][1].clone();
    run["id"] = serde_json::json!("check");
    let runs = format!("/api/v1/sessions/{id}/runs");
    let one = format!("/api/v1/sessions/{id}/runs/check");
    let answers = [
        (
            "post",
            "/api/v1/sessions/{id}/runs",
            client.post(server.url(&runs)).json(&run),
        ),
        (
            "put",
            "/api/v1/sessions/{id}/runs/{run_id}",
            client.put(server.url(&one)).json(&run),
        ),
        (
            "get",
            "/api/v1/sessions/{id}/runs/{run_id}",
            client.get(server.url(&one)),
        ),
        (
            "get",
            "/api/v1/sessions/{id}",
            client.get(server.url(&format!("/api/v1/sessions/{id}"))),
        ),
        (
            "get",
            "/api/v1/sessions/{id}/runs/{run_id}/versions",
            client.get(server.url(&format!("{one}/versions"))),
        ),
    ];
    let mut undeclared = Vec::new();
    for (method, template, req) in answers {
        let (status, headers, body) = send(req).await;
        assert!(status < 300, "{method} {template}: {status} {body}");
        let declared = &doc["paths"][template][method]["responses"][status.to_string()]["headers"];
        for name in ["etag", "location", "x-total-count"] {
            let said = declared
                .as_object()
                .is_some_and(|h| h.keys().any(|k| k.eq_ignore_ascii_case(name)));
            if headers.contains_key(name) && !said {
                undeclared.push(format!("{method} {template} {status}: {name}"));
            }
        }
    }
    assert!(undeclared.is_empty(), "{undeclared:#?}");
    server.shutdown().await;
}

/// `POST …/solutions` takes an empty body (the default options), and the
/// document says so: it declared the body required, so a generated client
/// could not send none.
#[tokio::test]
async fn the_solutions_body_is_declared_optional_as_it_is() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    let body = &doc["paths"]["/api/v1/sessions/{id}/solutions"]["post"]["requestBody"];
    assert_ne!(body["required"], true, "{body}");
    let session = common::example("pump-two-plane-exact.json");
    let session = session.get("session").cloned().unwrap_or(session);
    let (_, _, created) = common::post(&client, &server.url("/api/v1/sessions"), &session).await;
    let url = server.url(&format!(
        "/api/v1/sessions/{}/solutions",
        created["id"].as_str().unwrap()
    ));
    let (status, _, solved) =
        send(client.post(url).header("content-type", "application/json")).await;
    assert_eq!(status, 201, "{solved}");
    server.shutdown().await;
}

/// Every path parameter is a `{name}` of its path and every `{name}` is a
/// path parameter; `limit`, `offset` and `version` are query parameters.
/// They were declared `in: path` (utoipa's default without
/// `parameter_in = Query`), which an OpenAPI validator refuses and a
/// generated client puts in the path.
#[tokio::test]
async fn path_parameters_are_the_paths_own_and_the_rest_are_queries() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    let mut faults = Vec::new();
    for (path, item) in doc["paths"].as_object().unwrap() {
        let mut templated: Vec<&str> = path
            .split('/')
            .filter_map(|s| s.strip_prefix('{')?.strip_suffix('}'))
            .collect();
        templated.sort();
        for (method, op) in item.as_object().unwrap() {
            let params = op["parameters"].as_array().cloned().unwrap_or_default();
            let mut in_path: Vec<&str> = params
                .iter()
                .filter(|p| p["in"] == "path")
                .map(|p| p["name"].as_str().unwrap())
                .collect();
            in_path.sort();
            if in_path != templated {
                faults.push(format!("{method} {path}: path parameters {in_path:?}"));
            }
            for p in &params {
                let name = p["name"].as_str().unwrap();
                if ["limit", "offset", "before", "version"].contains(&name) && p["in"] != "query" {
                    faults.push(format!("{method} {path}: {name} in {}", p["in"]));
                }
            }
        }
    }
    assert!(faults.is_empty(), "{faults:#?}");
    server.shutdown().await;
}
