//! A page of a list and its total (`total`, `X-Total-Count`) are read from
//! one snapshot: whatever is written meanwhile, the page holds exactly
//! `min(limit, total - offset)` items, never one that a finished delete
//! removed, never one twice. They were two queries, and a write committed
//! between them gave a page its total contradicted.
//!
//! These are race probes: a writer changes the list while a reader lists it,
//! each a bounded number of times, and every page is checked. A write must
//! land between the two reads of one request to show a split snapshot, so a
//! pass does not prove there is none; a failure does prove one (each page
//! is checked only against what any single snapshot would give).

use std::collections::HashSet;
use std::future::Future;
use std::sync::{Arc, Mutex};

use crate::common;

use common::{example, fresh_server, post, send};
use serde_json::{json, Value};

/// Writes by the writer: each a chance to land inside a request's reads.
const WRITES: usize = 150;
/// Pages read at most (the writer usually finishes first).
const MAX_LISTS: usize = 3000;

/// Whether `n` items fit a page at `offset` (limit `limit`) of a list of `total`.
fn fits(n: usize, total: i64, limit: i64, offset: i64) -> Result<(), String> {
    let expected = (total - offset).clamp(0, limit);
    if n as i64 == expected {
        Ok(())
    } else {
        Err(format!(
            "{n} items at offset {offset} (limit {limit}) of a total of {total}: one snapshot gives {expected}"
        ))
    }
}

/// Read pages with `list_once` while `writer` runs (at least once, at most
/// `MAX_LISTS` times); every page must check. Returns how many were read.
async fn probe<F, Fut>(writer: tokio::task::JoinHandle<()>, mut list_once: F) -> usize
where
    F: FnMut(usize) -> Fut,
    Fut: Future<Output = Result<(), String>>,
{
    let mut lists = 0;
    let mut refused = Vec::new();
    loop {
        if let Err(e) = list_once(lists).await {
            refused.push(e);
        }
        lists += 1;
        if writer.is_finished() || lists >= MAX_LISTS {
            break;
        }
    }
    writer.await.expect("the writer finished");
    assert!(
        refused.is_empty(),
        "{} of {lists} pages contradict their total: {:?}",
        refused.len(),
        &refused[..refused.len().min(5)]
    );
    lists
}

/// Ids unique within the page, none deleted before the page was asked for.
fn consistent_ids(ids: &[String], deleted: &HashSet<String>) -> Result<(), String> {
    let mut seen = HashSet::new();
    for id in ids {
        if !seen.insert(id) {
            return Err(format!("{id} listed twice"));
        }
        if deleted.contains(id) {
            return Err(format!("{id} listed after its delete was answered"));
        }
    }
    Ok(())
}

/// Keeps up to `keep` items: creates one each step and, beyond `keep`,
/// deletes the oldest; what was deleted goes into `deleted` once answered.
async fn churn(
    client: reqwest::Client,
    create: String,
    body: impl Fn(usize) -> Value,
    item: impl Fn(&str) -> String,
    keep: usize,
    deleted: Arc<Mutex<HashSet<String>>>,
) {
    let mut alive = std::collections::VecDeque::new();
    for i in 0..WRITES {
        let (status, _, created) = post(&client, &create, &body(i)).await;
        assert_eq!(status, 201, "{created}");
        alive.push_back(created["id"].as_str().unwrap().to_string());
        if alive.len() > keep {
            let old = alive.pop_front().unwrap();
            let (status, _, _) = send(client.delete(item(&old))).await;
            assert_eq!(status, 204);
            deleted.lock().unwrap().insert(old);
        }
    }
}

fn ids_of(items: &Value) -> Vec<String> {
    items
        .as_array()
        .expect("a list")
        .iter()
        .map(|x| x["id"].as_str().expect("an id").to_string())
        .collect()
}

/// Pages of the list at `path` (items under `key`) checked while a writer
/// creates items (`body`) and deletes all but the newest six.
async fn pages_agree_while_items_come_and_go(
    path: &str,
    key: &'static str,
    body: impl Fn(usize) -> Value + Send + 'static,
) {
    let (_dir, server, client) = fresh_server().await;
    let deleted = Arc::new(Mutex::new(HashSet::new()));
    let base = server.url(path);
    let writer = tokio::spawn(churn(
        client.clone(),
        base.clone(),
        body,
        {
            let base = base.clone();
            move |id| format!("{base}/{id}")
        },
        6,
        deleted.clone(),
    ));
    probe(writer, |i| {
        let (client, base, deleted) = (client.clone(), base.clone(), deleted.clone());
        async move {
            let gone = deleted.lock().unwrap().clone();
            let (limit, offset) = [(100, 0), (100, 2), (3, 1)][i % 3];
            let url = format!("{base}?limit={limit}&offset={offset}");
            let (status, _, page) = send(client.get(url)).await;
            assert_eq!(status, 200, "{page}");
            let ids = ids_of(&page[key]);
            fits(ids.len(), page["total"].as_i64().unwrap(), limit, offset)?;
            consistent_ids(&ids, &gone)
        }
    })
    .await;
    server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_page_of_sessions_and_its_total_agree_while_sessions_come_and_go() {
    let session = example("pump-two-plane-exact.json")["session"].clone();
    pages_agree_while_items_come_and_go("/api/v1/sessions", "sessions", move |_| session.clone())
        .await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_page_of_machines_and_its_total_agree_while_machines_come_and_go() {
    pages_agree_while_items_come_and_go(
        "/api/v1/machines",
        "machines",
        |i| json!({"id": format!("M-{i}")}),
    )
    .await;
}

fn total_count(headers: &reqwest::header::HeaderMap) -> i64 {
    headers["x-total-count"].to_str().unwrap().parse().unwrap()
}

/// Numbers `1..=n` in order, as a list only ever appended to gives them.
fn from_one(numbers: &[i64], offset: i64) -> Result<(), String> {
    let expected: Vec<i64> = (offset + 1..=offset + numbers.len() as i64).collect();
    if numbers == expected {
        Ok(())
    } else {
        Err(format!("numbers {numbers:?} at offset {offset}"))
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_page_of_run_versions_and_its_total_agree_while_the_run_is_corrected() {
    let (_dir, server, client) = fresh_server().await;
    let ex = example("pump-two-plane-exact.json");
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
    let run = server.url(&format!(
        "/api/v1/sessions/{}/runs/trial%20inboard",
        created["id"].as_str().unwrap()
    ));
    let writer = tokio::spawn({
        let (client, run) = (client.clone(), run.clone());
        let body = ex["session"]["runs"][1].clone();
        async move {
            for _ in 0..WRITES {
                let (status, _, v) = send(client.put(&run).json(&body)).await;
                assert_eq!(status, 200, "{v}");
            }
        }
    });
    probe(writer, |i| {
        let (client, run) = (client.clone(), run.clone());
        async move {
            let (limit, offset) = [(1000, 0), (1000, 2), (3, 1)][i % 3];
            let url = format!("{run}/versions?limit={limit}&offset={offset}");
            let (status, headers, page) = send(client.get(url)).await;
            assert_eq!(status, 200, "{page}");
            let numbers: Vec<i64> = page
                .as_array()
                .unwrap()
                .iter()
                .map(|v| v["version"].as_i64().unwrap())
                .collect();
            fits(numbers.len(), total_count(&headers), limit, offset)?;
            from_one(&numbers, offset)
        }
    })
    .await;
    server.shutdown().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_page_of_solutions_and_its_total_agree_while_solutions_are_stored() {
    let (_dir, server, client) = fresh_server().await;
    let ex = example("pump-two-plane-exact.json");
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
    let solutions = server.url(&format!(
        "/api/v1/sessions/{}/solutions",
        created["id"].as_str().unwrap()
    ));
    let writer = tokio::spawn({
        let (client, solutions) = (client.clone(), solutions.clone());
        async move {
            for _ in 0..WRITES {
                let (status, _, s) = post(&client, &solutions, &json!({})).await;
                assert_eq!(status, 201, "{s}");
            }
        }
    });
    probe(writer, |i| {
        let (client, solutions) = (client.clone(), solutions.clone());
        async move {
            let (limit, offset) = [(100, 0), (100, 2), (3, 1)][i % 3];
            let url = format!("{solutions}?limit={limit}&offset={offset}");
            let (status, headers, page) = send(client.get(url)).await;
            assert_eq!(status, 200, "{page}");
            let ids: Vec<i64> = page
                .as_array()
                .unwrap()
                .iter()
                .map(|s| s["id"].as_i64().unwrap())
                .collect();
            fits(ids.len(), total_count(&headers), limit, offset)?;
            if ids.windows(2).all(|w| w[0] < w[1]) {
                Ok(())
            } else {
                Err(format!("solution ids out of order: {ids:?}"))
            }
        }
    })
    .await;
    server.shutdown().await;
}
