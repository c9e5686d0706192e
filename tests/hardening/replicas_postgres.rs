//! Replicas (issue 14): two real `fieldbal serve` processes on one PostgreSQL
//! database, concurrent writers on both. Every acknowledged write is stored
//! exactly once, run versions stay consecutive, machine coefficient versions
//! never collide, and a replica killed with SIGKILL under load loses nothing
//! it acknowledged. Needs the cluster of `scripts/test.sh`; fails without it.

use crate::common;

use std::collections::{BTreeSet, HashMap};
use std::process::Child;

use common::{binary, engine, example, send};
use serde_json::{json, Value};

/// A replica on `database`; returns it and its base URL.
fn replica(database: &str) -> (Child, String) {
    let (child, addr) = binary::start(
        None,
        &["--listen", "127.0.0.1:0", "--database", database],
        &[],
    );
    (child, format!("http://{addr}"))
}

async fn fresh_database(what: &str) -> String {
    engine::postgres_database(&format!(
        "fieldbal_{what}_{}",
        uuid::Uuid::new_v4().simple()
    ))
    .await
}

fn client() -> reqwest::Client {
    reqwest::Client::builder()
        .timeout(std::time::Duration::from_secs(60))
        .build()
        .unwrap()
}

/// A session of machine `M` that pools into coefficients.
fn machine_session() -> Value {
    let mut s = example("pump-two-plane-exact.json")["session"].clone();
    s["machine"] = json!("M");
    s
}

/// POST `body` with an Idempotency-Key; `None` when no answer came (a killed replica).
async fn post_keyed(
    c: &reqwest::Client,
    url: &str,
    key: &str,
    body: &Value,
) -> Option<(u16, Value)> {
    let res = c
        .post(url)
        .header("Idempotency-Key", key)
        .json(body)
        .send()
        .await
        .ok()?;
    let status = res.status().as_u16();
    Some((status, res.json().await.ok()?))
}

/// What one writer had acknowledged.
#[derive(Default)]
struct Acked {
    sessions: Vec<String>,
    runs: Vec<String>,
    run_versions: Vec<i64>,
    coefficient_versions: Vec<i64>,
}

/// Writer `w`: `rounds` of a session, an appended run, a correction with
/// If-Match and a coefficient version, alternating between the replicas.
async fn writer(w: usize, rounds: usize, urls: Vec<String>, hot: String) -> Acked {
    let c = client();
    let mut acked = Acked::default();
    let trial = example("pump-two-plane-exact.json")["session"]["runs"][2].clone();
    for k in 0..rounds {
        let base = &urls[(w + k) % urls.len()];
        let (status, created) = post_keyed(
            &c,
            &format!("{base}/api/v1/sessions"),
            &format!("s-{w}-{k}"),
            &machine_session(),
        )
        .await
        .expect("a live replica answers");
        assert_eq!(status, 201, "{created}");
        acked
            .sessions
            .push(created["id"].as_str().unwrap().to_string());

        let mut run = trial.clone();
        run["id"] = json!(format!("extra {w}-{k}"));
        let (status, _, body) = send(
            c.post(format!("{base}/api/v1/sessions/{hot}/runs"))
                .json(&run),
        )
        .await;
        assert_eq!(status, 201, "{body}");
        acked.runs.push(format!("extra {w}-{k}"));

        let run_url = format!("{base}/api/v1/sessions/{hot}/runs/zero");
        let (status, headers, mut zero) = send(c.get(&run_url)).await;
        assert_eq!(status, 200, "{zero}");
        let etag = headers["etag"].to_str().unwrap().to_string();
        let amplitude = zero["readings"][0]["amplitude"].as_f64().unwrap();
        zero["readings"][0]["amplitude"] = json!(amplitude * 1.001);
        let (status, _, body) = send(c.put(&run_url).header("If-Match", etag).json(&zero)).await;
        match status {
            200 => acked.run_versions.push(body["version"].as_i64().unwrap()),
            412 => assert_eq!(body["error"]["field"], "If-Match"),
            _ => panic!("PUT with If-Match: {status} {body}"),
        }

        let session = &acked.sessions[0];
        let (status, _, body) = send(
            c.post(format!("{base}/api/v1/machines/M/coefficients"))
                .json(&json!({"sessions": [session]})),
        )
        .await;
        assert_eq!(status, 201, "{body}");
        acked
            .coefficient_versions
            .push(body["version"].as_i64().unwrap());
    }
    acked
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn concurrent_writers_on_two_replicas_store_every_acknowledged_write_exactly_once() {
    let database = fresh_database("replicas").await;
    // Both start (and migrate) at once.
    let (a, b) = (replica(&database), replica(&database));
    let urls = vec![a.1.clone(), b.1.clone()];
    let c = client();
    let (status, _, m) = send(
        c.post(format!("{}/api/v1/machines", urls[0]))
            .json(&json!({"id": "M", "name": "fan"})),
    )
    .await;
    assert_eq!(status, 201, "{m}");
    let (status, _, again) = send(
        c.post(format!("{}/api/v1/machines", urls[1]))
            .json(&json!({"id": "M", "name": "fan"})),
    )
    .await;
    assert_eq!(status, 409, "the other replica sees the id taken: {again}");
    let mut hot = machine_session();
    hot["runs"].as_array_mut().unwrap().truncate(2);
    let (status, _, created) =
        send(c.post(format!("{}/api/v1/sessions", urls[1])).json(&hot)).await;
    assert_eq!(status, 201, "{created}");
    let hot = created["id"].as_str().unwrap().to_string();

    let (writers, rounds) = (6, 5);
    let tasks: Vec<_> = (0..writers)
        .map(|w| tokio::spawn(writer(w, rounds, urls.clone(), hot.clone())))
        .collect();
    let mut all = Acked::default();
    for t in tasks {
        let a = t.await.expect("writer finished");
        all.sessions.extend(a.sessions);
        all.runs.extend(a.runs);
        all.run_versions.extend(a.run_versions);
        all.coefficient_versions.extend(a.coefficient_versions);
    }

    // Sessions: every acknowledged one exactly once (the hot one besides).
    let (_, _, list) = send(c.get(format!("{}/api/v1/sessions?limit=1000", urls[0]))).await;
    let mut counts: HashMap<String, usize> = HashMap::new();
    for s in list["sessions"].as_array().unwrap() {
        *counts
            .entry(s["id"].as_str().unwrap().to_string())
            .or_default() += 1;
    }
    assert_eq!(list["total"], json!(writers * rounds + 1));
    for id in &all.sessions {
        assert_eq!(counts.get(id), Some(&1), "session {id}");
    }
    // Appended runs: each once, in consecutive positions after the two first.
    let (_, _, session) = send(c.get(format!("{}/api/v1/sessions/{hot}", urls[1]))).await;
    let ids: Vec<&str> = session["runs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["id"].as_str().unwrap())
        .collect();
    assert_eq!(ids.len(), 2 + all.runs.len());
    let stored: BTreeSet<&str> = ids[2..].iter().copied().collect();
    let acked: BTreeSet<&str> = all.runs.iter().map(String::as_str).collect();
    assert_eq!(stored, acked);
    // Corrections: versions 1..=n, consecutive, each acknowledged one once.
    let (_, _, versions) = send(c.get(format!(
        "{}/api/v1/sessions/{hot}/runs/zero/versions?limit=1000",
        urls[0]
    )))
    .await;
    let listed: Vec<i64> = versions
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["version"].as_i64().unwrap())
        .collect();
    let n = 1 + all.run_versions.len() as i64;
    assert_eq!(listed, (1..=n).collect::<Vec<_>>(), "{versions}");
    all.run_versions.sort();
    assert_eq!(all.run_versions, (2..=n).collect::<Vec<_>>());
    // Coefficient versions: never two alike, none missing.
    let (_, _, machine) = send(c.get(format!("{}/api/v1/machines/M", urls[1]))).await;
    let listed: Vec<i64> = machine["coefficients"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v["version"].as_i64().unwrap())
        .collect();
    all.coefficient_versions.sort();
    let expected: Vec<i64> = (1..=(writers * rounds) as i64).collect();
    assert_eq!(all.coefficient_versions, expected);
    assert_eq!(listed, expected);
    binary::terminate(a.0, 30);
    binary::terminate(b.0, 30);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_replica_killed_under_load_loses_nothing_it_acknowledged() {
    let database = fresh_database("kill").await;
    let (mut a, a_url) = replica(&database);
    let (b, b_url) = replica(&database);
    let (writers, rounds) = (6, 12);
    let tasks: Vec<_> = (0..writers)
        .map(|w| {
            let (a_url, b_url) = (a_url.clone(), b_url.clone());
            tokio::spawn(async move {
                let c = client();
                let mut acked = Vec::new();
                for k in 0..rounds {
                    let key = format!("k-{w}-{k}");
                    let first = if (w + k) % 2 == 0 { &a_url } else { &b_url };
                    // No answer from the killed replica: retry the same key on the live one,
                    // which stores it once or replays what the killed one stored.
                    let answer = match post_keyed(
                        &c,
                        &format!("{first}/api/v1/sessions"),
                        &key,
                        &machine_session(),
                    )
                    .await
                    {
                        Some(answer) => answer,
                        None => post_keyed(
                            &c,
                            &format!("{b_url}/api/v1/sessions"),
                            &key,
                            &machine_session(),
                        )
                        .await
                        .expect("the live replica answers"),
                    };
                    assert_eq!(answer.0, 201, "{}", answer.1);
                    acked.push(answer.1["id"].as_str().unwrap().to_string());
                }
                acked
            })
        })
        .collect();
    // Kill A once the writers are well under way (bounded wait).
    let c = client();
    for _ in 0..600 {
        let (_, _, list) = send(c.get(format!("{b_url}/api/v1/sessions?limit=1"))).await;
        if list["total"].as_i64().unwrap() >= (writers * rounds / 3) as i64 {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(20)).await;
    }
    a.kill().unwrap();
    a.wait().unwrap();
    let mut acked = BTreeSet::new();
    for t in tasks {
        for id in t.await.expect("writer finished") {
            assert!(acked.insert(id.clone()), "session {id} acknowledged twice");
        }
    }
    let (_, _, list) = send(c.get(format!("{b_url}/api/v1/sessions?limit=1000"))).await;
    let stored: Vec<String> = list["sessions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["id"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(
        stored.len(),
        writers * rounds,
        "one session per key, none lost or doubled"
    );
    assert_eq!(stored.into_iter().collect::<BTreeSet<_>>(), acked);
    binary::terminate(b, 30);
}
