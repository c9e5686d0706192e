//! Session 23's outside review (qa23): the offline commands refuse what the
//! service refuses, every GET refuses a query parameter it does not take,
//! `/trial-weights` refuses the solve options it does not use, and the
//! hostile requests that found a fault.

use crate::common;

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use common::{example, fresh_server, post, send};
use serde_json::{json, Value};

fn pump() -> Value {
    example("pump-two-plane-exact.json")["session"].clone()
}

/// Machine P-1, created.
async fn machine_p1(client: &reqwest::Client, server: &common::Server) {
    let (status, _, body) = post(
        client,
        &server.url("/api/v1/machines"),
        &json!({"id": "P-1"}),
    )
    .await;
    assert_eq!(status, 201, "{body}");
}

/// The error's code, field and message.
fn error_of(body: &Value) -> (String, Option<String>, String) {
    (
        body["error"]["code"].as_str().unwrap_or("").to_string(),
        body["error"]["field"].as_str().map(str::to_string),
        body["error"]["message"].as_str().unwrap_or("").to_string(),
    )
}

/// `fieldbal ARGS…` with `stdin` on its standard input: the exit code and
/// the JSON it printed.
fn fieldbal(args: &[&str], stdin: &[u8]) -> (i32, Value) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("fieldbal runs");
    child.stdin.take().unwrap().write_all(stdin).unwrap();
    let out = child.wait_with_output().unwrap();
    let value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "fieldbal {args:?} printed no JSON ({e}): {}",
            String::from_utf8_lossy(&out.stdout)
        )
    });
    (out.status.code().unwrap_or(-1), value)
}

fn write(dir: &Path, name: &str, value: &Value) -> String {
    let path = dir.join(name);
    std::fs::write(&path, serde_json::to_vec(value).unwrap()).unwrap();
    path.to_str().unwrap().to_string()
}

/// The error `fieldbal ARGS…` printed, its field with `prefix` taken off;
/// it must exit with 2.
fn cli_error(args: &[&str], stdin: &[u8], prefix: &str) -> (String, Option<String>, String) {
    let (code, out) = fieldbal(args, stdin);
    assert_eq!(code, 2, "fieldbal {args:?}: {out}");
    let (c, f, m) = error_of(&out);
    let f = f.map(|f| {
        f.strip_prefix(prefix)
            .unwrap_or_else(|| panic!("fieldbal {args:?}: {f} is not under {prefix}"))
            .to_string()
    });
    (c, f, m)
}

/// A session's texts (`name`, a sensor's `label`) and the machine it names
/// are refused by `fieldbal solve` (a file, a wrapped file, standard
/// input), `fieldbal coefficients` and `fieldbal identify rotor` as the
/// service refuses them when the session is stored or posted: the same
/// code and message, the field where the file has it, exit status 2. The
/// commands solved a session with a NUL in its name, a bell in a label or
/// `machine: ""`, which the service refuses.
#[tokio::test]
async fn the_commands_refuse_a_sessions_texts_and_machine_as_the_service_does() {
    let (_dir, server, client) = fresh_server().await;
    let files = tempfile::tempdir().unwrap();
    type Edit = fn(&mut Value);
    let cases: [(&str, Edit); 6] = [
        ("name", |s| s["name"] = json!("pump\u{0}3")),
        ("sensors[2].label", |s| {
            s["sensors"][2]["label"] = json!("NDE \u{7}")
        }),
        ("machine", |s| s["machine"] = json!("")),
        ("machine", |s| s["machine"] = json!("   ")),
        ("machine", |s| s["machine"] = json!("P-1\u{1b}[31m")),
        ("machine", |s| s["machine"] = json!("m".repeat(65))),
    ];
    for (field, edit) in cases {
        let mut s = pump();
        edit(&mut s);
        let (status, _, stored) = post(&client, &server.url("/api/v1/sessions"), &s).await;
        assert_eq!(status, 422, "store {field}: {stored}");
        let want = error_of(&stored);
        assert_eq!(want.1.as_deref(), Some(field), "{stored}");
        let posted = json!({ "session": s });
        for endpoint in ["/api/v1/solve", "/api/v1/identify/rotor"] {
            let (status, _, body) = post(&client, &server.url(endpoint), &posted).await;
            assert_eq!(status, 422, "{endpoint}: {body}");
            let (c, f, m) = error_of(&body);
            let f = f.and_then(|f| f.strip_prefix("session.").map(str::to_string));
            assert_eq!((c, f, m), want, "{endpoint} {field}: {body}");
        }
        let bare = write(files.path(), "bare.json", &s);
        let wrapped = write(files.path(), "wrapped.json", &posted);
        let stdin = serde_json::to_vec(&s).unwrap();
        let runs: [(&[&str], &[u8], &str); 5] = [
            (&["solve", &bare], b"", ""),
            (&["solve", &wrapped], b"", "session."),
            (&["solve", "-"], &stdin, ""),
            (&["coefficients", &bare], b"", "sessions[0]."),
            (&["identify", "rotor", &wrapped], b"", "session."),
        ];
        for (args, input, prefix) in runs {
            assert_eq!(cli_error(args, input, prefix), want, "{args:?} {field}");
        }
    }
    // Tabs and line breaks stay allowed in texts offline too.
    let mut s = pump();
    s["name"] = json!("pump 3\r\n\tcoupling end");
    s["sensors"][1]["label"] = json!("DE\tvertical\n(new probe)");
    let (code, out) = fieldbal(&["solve", &write(files.path(), "ok.json", &s)], b"");
    assert_eq!(code, 0, "{out}");
}

/// `coefficients_from` beside `influence_coefficients`, with a version
/// below 1 or a machine id the id rule refuses, is refused by `fieldbal
/// solve` as `/api/v1/solve` refuses it (before any machine is looked up):
/// it solved with the supplied coefficients and echoed the
/// `coefficients_from` it had not read, or said the coefficients are read by
/// the service where the service refused the id (which it looked up).
#[tokio::test]
async fn the_solve_command_refuses_coefficients_from_as_the_service_does() {
    let (_dir, server, client) = fresh_server().await;
    let files = tempfile::tempdir().unwrap();
    let (_, supplied) = fieldbal(
        &[
            "coefficients",
            &write(
                files.path(),
                "pump.json",
                &example("pump-two-plane-exact.json"),
            ),
        ],
        b"",
    );
    let coefficients = supplied["influence_coefficients"].clone();
    assert!(
        coefficients.as_array().is_some_and(|c| !c.is_empty()),
        "{supplied}"
    );
    let cases = [
        json!({"coefficients_from": {"machine": "P-1"}, "influence_coefficients": coefficients}),
        json!({"coefficients_from": {"machine": "P-1", "version": 0}}),
        json!({"coefficients_from": {"machine": "P-1", "version": -3}}),
        // A machine id the id rule refuses, as a trim job's is refused.
        json!({"coefficients_from": {"machine": ""}}),
        json!({"coefficients_from": {"machine": "P-1\u{0}"}}),
        json!({"coefficients_from": {"machine": "m".repeat(65)}}),
    ];
    for options in cases {
        let body = json!({ "session": pump(), "options": options });
        let (status, _, answer) = post(&client, &server.url("/api/v1/solve"), &body).await;
        assert_eq!(status, 422, "{answer}");
        let want = error_of(&answer);
        assert_ne!(
            want.0, "unknown_machine",
            "the id is refused, not looked up: {answer}"
        );
        let wrapped = write(files.path(), "wrapped.json", &body);
        assert_eq!(cli_error(&["solve", &wrapped], b"", ""), want, "{options}");
        let bare = write(files.path(), "bare.json", &pump());
        let opts = write(files.path(), "options.json", &options);
        assert_eq!(
            cli_error(&["solve", &bare, "--options", &opts], b"", ""),
            want,
            "--options {options}"
        );
    }
}

/// `fieldbal coefficients` takes the service's pool list rule: a file
/// named twice (its runs counted twice) and more than 1000 files are
/// refused as the service refuses the same list of session ids, before a
/// file is read. It pooled a file named twice, and read any number.
#[tokio::test]
async fn the_coefficients_command_takes_the_services_rule_of_a_pool_list() {
    let (_dir, server, client) = fresh_server().await;
    machine_p1(&client, &server).await;
    let pool = server.url("/api/v1/machines/P-1/coefficients");
    let files = tempfile::tempdir().unwrap();
    let one = write(
        files.path(),
        "pump.json",
        &example("pump-two-plane-exact.json"),
    );

    let (status, _, twice) = post(&client, &pool, &json!({"sessions": ["a", "b", "a"]})).await;
    assert_eq!(status, 422, "{twice}");
    let (code, field, _) = error_of(&twice);
    let (c, f, m) = cli_error(&["coefficients", &one, "x.json", &one], b"", "");
    assert_eq!((c, f), (code, field), "{m}");
    assert!(m.contains(&one), "{m}");

    let ids: Vec<String> = (0..1001).map(|i| format!("s{i}.json")).collect();
    let (status, _, many) = post(&client, &pool, &json!({ "sessions": ids })).await;
    assert_eq!(status, 422, "{many}");
    let mut args = vec!["coefficients"];
    args.extend(ids.iter().map(String::as_str));
    // None of the files exists: the list is refused before one is read.
    assert_eq!(cli_error(&args, b"", ""), error_of(&many));
}

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
                (status, code.as_str(), field.as_deref()),
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

/// `POST /api/v1/trial-weights` refuses a solve option it does not use with
/// 422 `unused_option` naming it (`options.discrete`, …): it answered the
/// same suggestions with or without them, so a client asking for
/// `"discrete": true` or `"from_run"` was not told they changed nothing.
/// The options it uses still answer, and an unknown key stays 400
/// `unknown_field` as on `/solve`.
#[tokio::test]
async fn trial_weights_refuse_the_solve_options_they_do_not_use() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/trial-weights");
    let unused = [
        ("objective", json!("min_max")),
        ("max_mass_g", json!({"inboard": 50})),
        ("drop_dependent_planes", json!(true)),
        ("amplitude_noise_pct", json!(5)),
        ("phase_noise_deg", json!(3)),
        ("from_run", json!("zero")),
        ("discrete", json!(true)),
        ("discrete", json!(false)),
        ("fit_time_limit_ms", json!(100)),
    ];
    for (key, value) in unused {
        let body = json!({"session": pump(), "options": {"planes": ["inboard"], key: value}});
        let (status, _, answer) = post(&client, &url, &body).await;
        let (code, field, message) = error_of(&answer);
        let want = format!("options.{key}");
        assert_eq!(
            (status, code.as_str(), field.as_deref()),
            (422, "unused_option", Some(want.as_str())),
            "{key}: {answer}"
        );
        assert!(message.contains(key), "{message}");
    }
    let used = json!({
        "planes": ["inboard"],
        "sensors": ["DE-H", "NDE-H"],
        "speeds_rpm": [2950],
        "row_weights": [{"sensor": "DE-H", "weight": 2}],
    });
    let (status, _, answer) =
        post(&client, &url, &json!({"session": pump(), "options": used})).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(
        answer["suggestions"].as_array().map(Vec::len),
        Some(1),
        "{answer}"
    );
    let body = json!({"session": pump(), "options": {"discret": true}});
    let (status, _, answer) = post(&client, &url, &body).await;
    let (code, field, _) = error_of(&answer);
    assert_eq!(
        (status, code.as_str(), field.as_deref()),
        (400, "unknown_field", Some("options.discret")),
        "{answer}"
    );
}

/// An `If-Match` that is not `*` or a list of entity-tags (an unquoted
/// tag, an unterminated one, a bare `W/`, `*` in a list, nothing at all) is
/// refused with 400 `invalid_header` naming `If-Match`, on a run's PUT and
/// a session's DELETE, nothing changed: it was answered 412 "changed
/// meanwhile", even when the unquoted tag named the current version, so a
/// client re-read and sent the same header for ever. Several `If-Match`
/// lines are one list (RFC 9110 §5.3): a tag on the second line matches,
/// where only the first line was read.
#[tokio::test]
async fn a_malformed_if_match_is_refused_and_its_lines_are_one_list() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &pump()).await;
    let session = server.url(&format!(
        "/api/v1/sessions/{}",
        created["id"].as_str().unwrap()
    ));
    let run = format!("{session}/runs/zero");
    let (status, headers, body) = send(client.get(&run)).await;
    assert_eq!(status, 200, "{body}");
    let tag = headers["etag"].to_str().unwrap().to_string();
    let malformed = [
        tag.trim_matches('"').to_string(),
        format!("\"{tag}"),
        tag[..tag.len() - 1].to_string(),
        "W/".into(),
        ",".into(),
        "".into(),
        format!("*, {tag}"),
        "\"v 1\"".into(),
        format!("{tag} {tag}"),
    ];
    for value in &malformed {
        let (status, _, err) = send(client.put(&run).header("If-Match", value).json(&body)).await;
        let (code, field, message) = error_of(&err);
        assert_eq!(
            (status, code.as_str(), field.as_deref()),
            (400, "invalid_header", Some("If-Match")),
            "PUT If-Match: {value}: {message}"
        );
        let (status, _, err) = send(client.delete(&session).header("If-Match", value)).await;
        let (code, field, message) = error_of(&err);
        assert_eq!(
            (status, code.as_str(), field.as_deref()),
            (400, "invalid_header", Some("If-Match")),
            "DELETE If-Match: {value}: {message}"
        );
    }
    let (_, versions, _) = send(client.get(format!("{run}/versions"))).await;
    assert_eq!(versions["x-total-count"], "1", "nothing was stored");
    // Two lines, the current tag on the second: they match as one list.
    let (status, _, answer) = send(
        client
            .put(&run)
            .header("If-Match", "\"v7\"")
            .header("If-Match", &tag)
            .json(&body),
    )
    .await;
    assert_eq!(status, 200, "{answer}");
    // The session as it is now (the same run stored again).
    let (_, headers, _) = send(client.get(&session)).await;
    let now = headers["etag"].to_str().unwrap().to_string();
    let (status, _, answer) = send(
        client
            .delete(&session)
            .header("If-Match", "W/\"x\"")
            .header("If-Match", format!("\"a,b\", {now}")),
    )
    .await;
    assert_eq!(status, 204, "{answer}");
}

/// Two `Idempotency-Key` lines are refused as the one line a proxy joins
/// them into (`a1, a2`, which holds a space) is: 422 `invalid_header`
/// naming the header, nothing stored. The first line alone was used, so a
/// retry whose lines came in the other order stored the session again.
#[tokio::test]
async fn two_idempotency_keys_are_refused_as_their_joined_line_is() {
    let (_dir, server, client) = fresh_server().await;
    let store = server.url("/api/v1/sessions");
    for keys in [["k-1", "k-2"], ["k-2", "k-1"], ["k-1", "k-1"]] {
        let (status, _, err) = send(
            client
                .post(&store)
                .header("Idempotency-Key", keys[0])
                .header("Idempotency-Key", keys[1])
                .json(&pump()),
        )
        .await;
        let joined = send(
            client
                .post(&store)
                .header("Idempotency-Key", keys.join(", "))
                .json(&pump()),
        )
        .await;
        let (code, field, _) = error_of(&err);
        assert_eq!(
            (status, code.as_str(), field.as_deref()),
            (422, "invalid_header", Some("Idempotency-Key")),
            "{keys:?}: {err}"
        );
        assert_eq!(
            (status, error_of(&err)),
            (joined.0, error_of(&joined.2)),
            "{keys:?}"
        );
    }
    let (_, _, list) = send(client.get(&store)).await;
    assert_eq!(list["total"], 0, "nothing was stored: {list}");
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
            (status, code.as_str(), field.as_deref()),
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

/// `fieldbal coefficients` pools one machine's sessions, as the service
/// does: files that name two machines are refused naming the second's
/// `machine` (they were pooled into one set of coefficients). Files that
/// name none pool with those that name one.
#[test]
fn the_coefficients_command_pools_one_machines_sessions() {
    let files = tempfile::tempdir().unwrap();
    let named = |name: &str, machine: Option<&str>| {
        let mut s = pump();
        if let Some(m) = machine {
            s["machine"] = json!(m);
        }
        write(files.path(), name, &s)
    };
    let (a, b, c) = (
        named("a.json", Some("P-1")),
        named("b.json", Some("P-2")),
        named("c.json", None),
    );
    let (code, field, message) = cli_error(&["coefficients", &c, &a, &b], b"", "");
    assert_eq!(
        (code.as_str(), field.as_deref()),
        ("other_machine", Some("sessions[2].machine")),
        "{message}"
    );
    assert!(
        message.contains("P-1") && message.contains("P-2"),
        "{message}"
    );
    let (status, pooled) = fieldbal(&["coefficients", &c, &a], b"");
    assert_eq!(status, 0, "{pooled}");
    assert!(pooled["influence_coefficients"].is_array(), "{pooled}");
}
