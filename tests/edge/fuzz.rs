//! A seeded fuzz run driven by the served OpenAPI document: for every operation,
//! valid requests (the examples, instances of the declared schemas) and mutated
//! ones (wrong types, missing and unknown fields, extremes, NaN-ish strings,
//! positional arrays, broken JSON, no content type, odd path and query values).
//! Every answer must be declared for its operation, match the declared schema,
//! and none may be a 5xx: the document stays true to the service.

use crate::common;
use crate::support;

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use reqwest::header::CONTENT_TYPE;
use reqwest::Method;
use serde_json::{json, Value};

use common::{example, fresh_server, path_segment, post, send};
use support::schema::{mutate, Schemas};

const REQUESTS: usize = 2000;
const SEED: u64 = 20_261_122;

struct Operation {
    path: String,
    method: Method,
    spec: Value,
}

fn operations(doc: &Value) -> Vec<Operation> {
    let mut ops = Vec::new();
    for (path, item) in doc["paths"].as_object().expect("paths") {
        for (method, spec) in item.as_object().expect("path item") {
            if let Ok(method) = method.to_ascii_uppercase().parse::<Method>() {
                ops.push(Operation {
                    path: path.clone(),
                    method,
                    spec: spec.clone(),
                });
            }
        }
    }
    ops
}

fn odd_id(rng: &mut StdRng) -> String {
    let odd = [
        "no-such-id",
        "00000000-0000-0000-0000-000000000000",
        "ü",
        " ",
        "%",
        "..",
        "a/b",
    ];
    if rng.gen_bool(0.2) {
        "x".repeat(rng.gen_range(200..2000))
    } else {
        odd[rng.gen_range(0..odd.len())].to_string()
    }
}

fn query_value(param: &Value, rng: &mut StdRng) -> String {
    let s = &param["schema"];
    let lo = s["minimum"].as_i64().unwrap_or(0);
    let hi = s["maximum"].as_i64().unwrap_or(lo + 1000);
    match rng.gen_range(0..8) {
        0..=2 => rng.gen_range(lo..=hi).to_string(),
        3 => (lo - 1).to_string(),
        4 => (hi + 1).to_string(),
        5 => "99999999999999999999".into(),
        6 => "1e3".into(),
        _ => "abc".into(),
    }
}

/// The request body for `op`, valid or not, as text.
fn body(
    op: &Operation,
    schemas: &Schemas,
    run_id: &str,
    n: usize,
    rng: &mut StdRng,
) -> Option<String> {
    let schema = op.spec["requestBody"]["content"]["application/json"]["schema"].clone();
    if schema.is_null() {
        return None;
    }
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let name = schema["$ref"]
        .as_str()
        .unwrap_or("")
        .rsplit('/')
        .next()
        .unwrap_or("");
    let mut value = match name {
        "Session" => session.clone(),
        "Run" => {
            let mut run = session["runs"][1].clone();
            let id = if op.method == Method::PUT {
                run_id.to_string()
            } else {
                format!("fuzz {n}")
            };
            run["id"] = json!(id);
            run
        }
        "SolveRequest" | "TrialRequest" => json!({ "session": session }),
        "SolveOptions" => json!({}),
        _ => schemas.instance(&schema, rng, 6),
    };
    match rng.gen_range(0..20) {
        0..=5 => {}
        6..=7 => value = schemas.instance(&schema, rng, 6),
        8 => {
            return Some(
                ["", "{", "[1,2", "nul", "{\"a\":1e999}", "\u{feff}{}"][rng.gen_range(0..6)].into(),
            )
        }
        9 => {
            return Some(
                value
                    .to_string()
                    .replacen(|c: char| c.is_ascii_digit(), "NaN", 1),
            )
        }
        10 => value = json!([value]),
        _ => {
            for _ in 0..rng.gen_range(1..=3) {
                mutate(&mut value, rng);
            }
        }
    }
    Some(value.to_string())
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn generated_requests_get_only_declared_answers_with_declared_bodies() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    let schemas = Schemas { doc: &doc };
    // The checker itself finds what it must (or this test could not fail).
    let error_body = json!({ "$ref": "#/components/schemas/ErrorBody" });
    for wrong in [
        json!({}),
        json!({"error": {"code": 1, "message": "m"}}),
        json!([]),
    ] {
        let mut v = Vec::new();
        schemas.violations(&error_body, &wrong, "body", &mut v);
        assert!(!v.is_empty(), "{wrong} passes as an error body");
    }
    let ops = operations(&doc);
    assert!(
        ops.len() >= 12,
        "the document lists {} operations",
        ops.len()
    );

    let session = example("pump-two-plane-exact.json")["session"].clone();
    // `{id}` is a stored session's id, or under /api/v1/machines the id of a
    // machine that owns the session and has a coefficient version pooled from
    // it, so that every kind of resource can be reached.
    const MACHINE: &str = "FUZZ-M1";
    let mut session = session;
    session["machine"] = json!(MACHINE);
    let store = || async {
        let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &session).await;
        let id = created["id"].as_str().expect("stored").to_string();
        let machine = json!({"id": MACHINE, "name": "fuzzed machine"});
        let (status, _, _) = post(&client, &server.url("/api/v1/machines"), &machine).await;
        assert!(
            status == 201 || status == 409,
            "the machine is stored: {status}"
        );
        let pool = json!({"sessions": [id]});
        let url = server.url(&format!("/api/v1/machines/{MACHINE}/coefficients"));
        let (status, _, answer) = post(&client, &url, &pool).await;
        assert_eq!(status, 201, "coefficients pooled: {answer}");
        id
    };
    let mut id = store().await;
    let run_ids: Vec<String> = session["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["id"].as_str().unwrap().to_string())
        .collect();

    let mut rng = StdRng::seed_from_u64(SEED);
    let mut violations = Vec::new();
    let mut succeeded = vec![0usize; ops.len()];
    let mut seen = std::collections::BTreeMap::<u16, usize>::new();
    for n in 0..REQUESTS {
        let k = n % ops.len();
        let op = &ops[k];
        let real = rng.gen_bool(0.7);
        let run_id = run_ids[rng.gen_range(0..run_ids.len())].clone();
        let path = op
            .path
            .replace(
                "{id}",
                &path_segment(&if !real {
                    odd_id(&mut rng)
                } else if op.path.starts_with("/api/v1/machines/") {
                    MACHINE.to_string()
                } else {
                    id.clone()
                }),
            )
            .replace(
                "{run_id}",
                &path_segment(&if rng.gen_bool(0.8) {
                    run_id.clone()
                } else {
                    odd_id(&mut rng)
                }),
            );
        let mut query = Vec::new();
        for param in op.spec["parameters"].as_array().into_iter().flatten() {
            if param["in"] == "query" && rng.gen_bool(0.5) {
                query.push(format!(
                    "{}={}",
                    param["name"].as_str().unwrap(),
                    query_value(param, &mut rng)
                ));
            }
        }
        if rng.gen_bool(0.03) {
            query.push("bogus=1".into());
        }
        let url = if query.is_empty() {
            server.url(&path)
        } else {
            server.url(&format!("{path}?{}", query.join("&")))
        };
        let mut req = client.request(op.method.clone(), &url);
        if let Some(text) = body(op, &schemas, &run_id, n, &mut rng) {
            if rng.gen_bool(0.95) {
                req = req.header(CONTENT_TYPE, "application/json");
            }
            req = req.body(text);
        }
        let res = req.send().await.expect("answered");
        let status = res.status().as_u16();
        let bytes = res.bytes().await.expect("body");
        let what = format!("#{n} {} {url}", op.method);
        let declared = &op.spec["responses"][status.to_string()];
        if status >= 500 {
            violations.push(format!(
                "{what}: {status} {}",
                String::from_utf8_lossy(&bytes)
            ));
        } else if declared.is_null() {
            violations.push(format!("{what}: {status} is not declared"));
        } else if let Some(schema) = declared["content"]["application/json"].get("schema") {
            match serde_json::from_slice::<Value>(&bytes) {
                Ok(value) => {
                    let mut v = Vec::new();
                    schemas.violations(schema, &value, "body", &mut v);
                    violations.extend(v.into_iter().map(|v| format!("{what}: {status} {v}")));
                }
                Err(e) => violations.push(format!("{what}: {status} body is not JSON: {e}")),
            }
        }
        *seen.entry(status).or_default() += 1;
        if status < 300 {
            succeeded[k] += 1;
        }
        if op.method == Method::DELETE && status == 204 && real {
            id = store().await;
        }
    }
    eprintln!("answers by status: {seen:?}");
    assert!(
        violations.is_empty(),
        "{} violations, e.g.:\n{}",
        violations.len(),
        violations[..violations.len().min(20)].join("\n")
    );
    // Where a valid body is known (the examples), some request must succeed.
    let known = [
        "Session",
        "Run",
        "SolveRequest",
        "TrialRequest",
        "SolveOptions",
    ];
    for (op, ok) in ops.iter().zip(&succeeded) {
        let body = &op.spec["requestBody"]["content"]["application/json"]["schema"]["$ref"];
        let name = body.as_str().map(|r| r.rsplit('/').next().unwrap_or(""));
        if name.is_some_and(|n| !known.contains(&n)) {
            continue;
        }
        assert!(
            *ok > 0,
            "{} {}: no valid request was generated",
            op.method,
            op.path
        );
    }
    // The same server: every number of rich, valid bodies pushed to extremes
    // (support::numbers). Each body must also get through unharmed
    // somewhere, or the mutations would only ever meet the first check.
    let ok = support::numbers::never_a_server_error(&server, &client, &mut rng, 1500).await;
    eprintln!("2xx answers per rich body: {ok:?}");
    assert!(ok.iter().all(|&n| n > 0), "{ok:?}");
    server.shutdown().await;
}
