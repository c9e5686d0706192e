//! Size limits (contract v2 "Limits"): sessions over a limit are refused with
//! 422 `too_large` naming the count and the limit; the largest accepted
//! request stays within a memory budget of the real binary; solves beyond the
//! slots are refused with 503 and `Retry-After`.

use crate::common;
use crate::support;

use common::{fresh_server, post};
use serde_json::{json, Value};
use support::{client, session, Binary};

/// Peak memory the worst accepted request may cost the service (VmHWM).
const MEMORY_BUDGET_BYTES: u64 = 400 * 1024 * 1024;

/// A one-plane session with `sensors` sensors at `speeds` speeds and `runs` runs.
fn sized(sensors: usize, speeds: usize) -> Value {
    session(1, sensors, speeds)
}

fn with_samples(n: usize) -> Value {
    let mut s = sized(1, 1);
    let samples: Vec<Value> = (0..n)
        .map(|_| json!({"amplitude": 21.0, "phase_deg": 0.0}))
        .collect();
    s["runs"][0]["readings"][0]["samples"] = json!(samples);
    s
}

fn with_runs(n: usize) -> Value {
    let mut s = sized(1, 1);
    let trial = s["runs"][1].clone();
    let runs = s["runs"].as_array_mut().unwrap();
    for i in 2..n {
        let mut r = trial.clone();
        r["id"] = json!(format!("R{i}"));
        runs.push(r);
    }
    s
}

#[tokio::test]
async fn each_count_over_its_limit_is_refused_naming_the_count_and_the_limit() {
    let (_dir, server, client) = fresh_server().await;
    // (case, session, field named, limit named in the message)
    let cases: Vec<(&str, Value, &str, &str)> = vec![
        ("65 planes", session(65, 1, 1), "planes", "64"),
        ("257 sensors", sized(257, 1), "sensors", "256"),
        ("201 runs", with_runs(201), "runs", "200"),
        ("201 speed points", sized(1, 201), "runs[0].readings", "200"),
        (
            "50,200 readings",
            sized(251, 100),
            "runs[1].readings",
            "50000",
        ),
        (
            "1,001 samples",
            with_samples(1001),
            "runs[0].readings[0].samples",
            "1000",
        ),
    ];
    for (case, body, field, limit) in cases {
        for (path, body, prefix) in [
            ("/api/v1/sessions", body.clone(), ""),
            ("/api/v1/solve", json!({"session": body}), "session."),
        ] {
            let (status, _, answer) = post(&client, &server.url(path), &body).await;
            assert_eq!(status, 422, "{case} {path}: {answer}");
            assert_eq!(answer["error"]["code"], "too_large", "{case} {path}");
            assert_eq!(
                answer["error"]["field"],
                format!("{prefix}{field}"),
                "{case} {path}"
            );
            let message = answer["error"]["message"].as_str().unwrap();
            assert!(message.contains(limit), "{case}: {message}");
        }
    }
}

#[tokio::test]
async fn sessions_at_the_limits_are_accepted() {
    let (_dir, server, client) = fresh_server().await;
    for (case, body) in [
        ("64 planes", session(64, 1, 1)),
        ("256 sensors", sized(256, 1)),
        ("200 speed points", sized(1, 200)),
        ("1,000 samples", with_samples(1000)),
    ] {
        let (status, _, answer) = post(&client, &server.url("/api/v1/sessions"), &body).await;
        assert_eq!(status, 201, "{case}: {answer}");
    }
}

#[tokio::test]
async fn the_limits_are_set_by_serve_flags() {
    let dir = tempfile::tempdir().unwrap();
    let server = Binary::start(&dir.path().join("t.db"), &["--max-planes", "2"]);
    let (status, _, answer) = post(
        &client(),
        &server.url("/api/v1/sessions"),
        &session(3, 1, 1),
    )
    .await;
    assert_eq!(status, 422, "{answer}");
    assert_eq!(answer["error"]["field"], "planes");
    assert!(answer["error"]["message"]
        .as_str()
        .unwrap()
        .contains("limit is 2"));
}

/// `fieldbal solve FILE ARGS…` with no limit variables inherited: its exit
/// code and the JSON it printed.
fn solve_file(file: &std::path::Path, args: &[&str], stdin: Option<&[u8]>) -> (i32, Value) {
    use std::io::Write;
    use std::process::{Command, Stdio};
    let mut command = Command::new(env!("CARGO_BIN_EXE_fieldbal"));
    command.arg("solve").arg(file).args(args);
    for (name, _) in std::env::vars().filter(|(n, _)| n.starts_with("FIELDBAL_")) {
        command.env_remove(name);
    }
    let mut child = command
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("fieldbal solve starts");
    let mut input = child.stdin.take().unwrap();
    if let Some(bytes) = stdin {
        // The command may stop reading at its limit: a closed pipe is fine.
        let _ = input.write_all(bytes);
    }
    drop(input);
    let out = child.wait_with_output().unwrap();
    let answer = serde_json::from_slice(&out.stdout).expect("the answer is JSON");
    (out.status.code().unwrap(), answer)
}

#[test]
fn fieldbal_solve_reads_the_service_limits_and_a_raised_limit_lets_a_larger_job_through() {
    let dir = tempfile::tempdir().unwrap();
    let small = dir.path().join("three-planes.json");
    std::fs::write(&small, session(3, 4, 1).to_string()).unwrap();
    let (code, answer) = solve_file(&small, &["--max-planes", "2"], None);
    assert_eq!(code, 2, "{answer}");
    assert_eq!(answer["error"]["code"], "too_large");
    assert_eq!(answer["error"]["field"], "planes");
    assert!(answer["error"]["message"]
        .as_str()
        .unwrap()
        .contains("limit is 2"));
    assert_eq!(solve_file(&small, &[], None).0, 0);
    // 65 planes: over the default of 64, solved once the limit is raised.
    let large = dir.path().join("65-planes.json");
    std::fs::write(&large, session(65, 2, 40).to_string()).unwrap();
    let (code, answer) = solve_file(&large, &[], None);
    assert_eq!((code, &answer["error"]["field"]), (2, &json!("planes")));
    let (code, answer) = solve_file(&large, &["--max-planes", "65"], None);
    assert_eq!(code, 0, "{answer}");
    assert_eq!(answer["corrections"].as_array().unwrap().len(), 65);
}

#[test]
fn fieldbal_solve_refuses_a_file_over_the_body_limit_before_parsing_it() {
    let dir = tempfile::tempdir().unwrap();
    // Not even JSON: refused for its size, not for its syntax, so it was not parsed.
    let junk = format!("{{{}", "x".repeat(2_000));
    let file = dir.path().join("big.json");
    std::fs::write(&file, &junk).unwrap();
    let limit = ["--body-limit-bytes", "1000"];
    for (case, path, stdin) in [
        ("file", file.as_path(), None),
        (
            "standard input",
            std::path::Path::new("-"),
            Some(junk.as_bytes()),
        ),
    ] {
        let (code, answer) = solve_file(path, &limit, stdin);
        assert_eq!(code, 2, "{case}: {answer}");
        assert_eq!(answer["error"]["code"], "body_too_large", "{case}");
        let message = answer["error"]["message"].as_str().unwrap();
        assert!(message.contains("1000 bytes"), "{case}: {message}");
    }
    // Under the limit the same junk is a syntax error.
    let (code, answer) = solve_file(&file, &[], None);
    assert_eq!(code, 2);
    assert_ne!(answer["error"]["code"], "body_too_large", "{answer}");
}

/// The attack of issue 9: 150,000 planes and many runs in under 4 MiB used to
/// allocate a planes × runs matrix of 33 GB.
fn planes_times_runs_attack() -> Vec<u8> {
    let planes: Vec<Value> = (0..150_000)
        .map(|i| json!({"id": format!("{i}")}))
        .collect();
    let runs: Vec<Value> = (0..14_000)
        .map(|i| json!({"id": format!("{i}"), "weights": [], "readings": []}))
        .collect();
    serde_json::to_vec(&json!({"name": "x", "planes": planes,
        "sensors": [{"id": "s", "unit": "um_pp"}], "runs": runs}))
    .unwrap()
}

#[tokio::test]
async fn the_largest_requests_stay_within_the_memory_budget() {
    let dir = tempfile::tempdir().unwrap();
    let server = Binary::start(&dir.path().join("t.db"), &[]);
    let client = client();

    let attack = planes_times_runs_attack();
    assert!(attack.len() < 4 * 1024 * 1024, "{} bytes", attack.len());
    let res = client
        .post(server.url("/api/v1/sessions"))
        .header("content-type", "application/json")
        .body(attack)
        .send()
        .await
        .unwrap();
    assert_eq!(res.status(), 422);

    // The worst accepted session: 64 planes, 65 runs of 768 readings each
    // (49,920 readings), every plane's uncertainty propagated.
    let worst = session(64, 256, 3);
    let bytes = serde_json::to_vec(&worst).unwrap().len();
    assert!(bytes < 4 * 1024 * 1024, "{bytes} bytes");
    for objective in ["least_squares", "min_max"] {
        let body = json!({"session": worst, "options": {"objective": objective}});
        let (status, _, answer) = post(&client, &server.url("/api/v1/solve"), &body).await;
        assert_eq!(status, 200, "{objective}: {}", answer["error"]);
    }
    let (status, _, created) = post(&client, &server.url("/api/v1/sessions"), &worst).await;
    assert_eq!(status, 201, "{created}");
    let id = created["id"].as_str().unwrap();
    let (status, _, _) = common::send(
        client
            .post(server.url(&format!("/api/v1/sessions/{id}/solutions")))
            .header("content-type", "application/json"),
    )
    .await;
    assert_eq!(status, 201);

    let peak = server.peak_rss_bytes();
    eprintln!(
        "peak RSS after the worst requests ({bytes} bytes): {} MiB",
        peak >> 20
    );
    assert!(
        peak < MEMORY_BUDGET_BYTES,
        "peak RSS {} MiB is over the budget of {} MiB",
        peak >> 20,
        MEMORY_BUDGET_BYTES >> 20
    );
}

#[tokio::test]
async fn solves_beyond_the_slots_are_refused_with_retry_after() {
    let dir = tempfile::tempdir().unwrap();
    let server = Binary::start(
        &dir.path().join("t.db"),
        &["--solve-slots", "1", "--solve-queue-ms", "0"],
    );
    let client = client();
    let body = json!({"session": session(16, 64, 3), "options": {"objective": "min_max"}});
    let url = server.url("/api/v1/solve");
    let answers = futures_join(&client, &url, &body, 8).await;
    let busy: Vec<&(u16, Option<String>, Value)> =
        answers.iter().filter(|(s, _, _)| *s == 503).collect();
    let statuses: Vec<(u16, &Value)> = answers.iter().map(|(s, _, b)| (*s, &b["error"])).collect();
    assert!(
        answers.iter().any(|(s, _, _)| *s == 200),
        "one solve runs: {statuses:?}"
    );
    assert!(
        !busy.is_empty(),
        "with one slot and no queue, some of 8 are refused"
    );
    for (_, retry_after, body) in busy {
        assert!(retry_after.is_some(), "503 carries Retry-After");
        assert_eq!(body["error"]["code"], "busy");
    }
}

/// Post `body` `n` times at once; status, `Retry-After` and body of each.
async fn futures_join(
    client: &reqwest::Client,
    url: &str,
    body: &Value,
    n: usize,
) -> Vec<(u16, Option<String>, Value)> {
    let tasks: Vec<_> = (0..n)
        .map(|_| {
            let (client, url, body) = (client.clone(), url.to_string(), body.clone());
            tokio::spawn(async move {
                let (status, headers, answer) = post(&client, &url, &body).await;
                let retry = headers
                    .get("retry-after")
                    .map(|v| v.to_str().unwrap().to_string());
                (status, retry, answer)
            })
        })
        .collect();
    let mut out = Vec::new();
    for t in tasks {
        out.push(t.await.unwrap());
    }
    out
}
