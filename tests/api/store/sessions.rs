//! Sessions through the real server on a temporary SQLite file: every public
//! example round-trips and solves to its expected answer, runs entered one by
//! one equal the whole session, data survive a restart, concurrent posts all land.

use crate::common;

use common::{
    example, fresh_server, path_segment, post, send, start_server, store_solution,
    SOLVABLE_EXAMPLES,
};
use fieldbal::balancing::model::Session;
use serde_json::{json, Value};

fn as_session(v: &Value) -> Session {
    serde_json::from_value(v.clone()).expect("a session")
}

#[tokio::test]
async fn every_public_example_is_stored_read_back_identical_and_solved_to_its_expected_answer() {
    let (_dir, server, client) = fresh_server().await;
    for name in SOLVABLE_EXAMPLES {
        let ex = example(name);
        let (status, headers, created) =
            post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
        assert_eq!(status, 201, "{name}: {created}");
        let id = created["id"].as_str().unwrap();
        let location = headers["location"].to_str().unwrap();
        assert_eq!(location, format!("/api/v1/sessions/{id}"));

        let (status, _, back) = send(client.get(server.url(location))).await;
        assert_eq!(status, 200);
        // Field for field and bit for bit the same numbers as posted.
        assert_eq!(as_session(&back), as_session(&ex["session"]), "{name}");
        // And it is accepted again as it is.
        let (status, _, _) = post(&client, &server.url("/api/v1/sessions"), &back).await;
        assert_eq!(status, 201, "{name}: read-back session posted again");

        let url = server.url(&format!("{location}/solutions"));
        let (status, _, stored) = post(&client, &url, &ex["options"]).await;
        assert_eq!(status, 201, "{name}: {stored}");
        common::assert_matches_expected(name, &stored["solution"], &ex["expected"]);
        assert_eq!(stored["fieldbal_version"], env!("CARGO_PKG_VERSION"));

        let body = json!({ "session": ex["session"], "options": ex["options"] });
        let (status, _, solution) = post(&client, &server.url("/api/v1/solve"), &body).await;
        assert_eq!(status, 200, "{name}: {solution}");
        common::assert_matches_expected(name, &solution, &ex["expected"]);
        assert_eq!(
            solution, stored["solution"],
            "{name}: stateless and stored solves agree"
        );

        let (status, _, list) = send(client.get(url)).await;
        assert_eq!(status, 200);
        assert_eq!(list.as_array().unwrap().len(), 1);
        assert_eq!(list[0]["solution"], stored["solution"]);
        assert_eq!(list[0]["options"], stored["options"]);
    }
    server.shutdown().await;
}

#[tokio::test]
async fn runs_appended_one_by_one_give_the_same_session_and_solution_as_the_whole_session() {
    let (_dir, server, client) = fresh_server().await;
    for name in SOLVABLE_EXAMPLES {
        let ex = example(name);
        let whole = &ex["session"];
        let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), whole).await;
        let whole_id = created["id"].as_str().unwrap().to_string();

        let mut setup = whole.clone();
        setup["runs"] = json!([]);
        let (status, _, created) = post(&client, &server.url("/api/v1/sessions"), &setup).await;
        assert_eq!(status, 201, "{name}: set-up alone: {created}");
        let id = created["id"].as_str().unwrap().to_string();
        for run in whole["runs"].as_array().unwrap() {
            let url = server.url(&format!("/api/v1/sessions/{id}/runs"));
            let (status, headers, body) = post(&client, &url, run).await;
            assert_eq!(status, 201, "{name}: run {}: {body}", run["id"]);
            assert_eq!(body["version"], 1);
            assert!(headers.contains_key("location"));
        }
        let (_, _, back) = send(client.get(server.url(&format!("/api/v1/sessions/{id}")))).await;
        assert_eq!(as_session(&back), as_session(whole), "{name}");

        let mut solutions = Vec::new();
        for sid in [&whole_id, &id] {
            let url = server.url(&format!("/api/v1/sessions/{sid}/solutions"));
            let (status, _, stored) = post(&client, &url, &ex["options"]).await;
            assert_eq!(status, 201, "{name}: {stored}");
            solutions.push(stored["solution"].clone());
        }
        assert_eq!(solutions[0], solutions[1], "{name}");
        common::assert_matches_expected(name, &solutions[1], &ex["expected"]);
    }
    server.shutdown().await;
}

#[tokio::test]
async fn sessions_runs_versions_and_solutions_survive_a_restart_on_the_same_file() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("t.db");
    let ex = example("pump-two-plane-exact.json");
    let client = reqwest::Client::new();

    let (_, server) = start_server(&db).await;
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
    let id = created["id"].as_str().unwrap().to_string();
    // Correct the last run with the same values: a second version is kept.
    let run = ex["session"]["runs"]
        .as_array()
        .unwrap()
        .last()
        .unwrap()
        .clone();
    let run_url = format!(
        "/api/v1/sessions/{id}/runs/{}",
        path_segment(run["id"].as_str().unwrap())
    );
    let (status, _, body) = send(client.put(server.url(&run_url)).json(&run)).await;
    assert_eq!((status, &body["version"]), (200, &json!(2)), "{body}");
    let stored = store_solution(&client, &server, &id).await;
    server.shutdown().await;

    let (_, server) = start_server(&db).await;
    let (status, _, back) = send(client.get(server.url(&format!("/api/v1/sessions/{id}")))).await;
    assert_eq!(status, 200);
    assert_eq!(as_session(&back), as_session(&ex["session"]));
    let (_, _, list) = send(client.get(server.url("/api/v1/sessions"))).await;
    assert_eq!(list["total"], 1);
    assert_eq!(list["sessions"][0]["id"], json!(id));
    assert_eq!(
        list["sessions"][0]["runs"],
        json!(ex["session"]["runs"].as_array().unwrap().len())
    );
    let (_, _, versions) = send(client.get(server.url(&format!("{run_url}/versions")))).await;
    assert_eq!(versions.as_array().unwrap().len(), 2);
    let (_, _, solutions) =
        send(client.get(server.url(&format!("/api/v1/sessions/{id}/solutions")))).await;
    assert_eq!(solutions[0]["solution"], stored["solution"]);
    assert_eq!(solutions[0]["runs"], stored["runs"]);
    server.shutdown().await;
}

#[tokio::test]
async fn fifty_concurrent_posts_are_all_stored_and_listed() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let tasks: Vec<_> = (0..50)
        .map(|i| {
            let (client, url) = (client.clone(), server.url("/api/v1/sessions"));
            let mut session = session.clone();
            session["name"] = json!(format!("concurrent {i}"));
            tokio::spawn(async move { (i, post(&client, &url, &session).await) })
        })
        .collect();
    let mut ids = std::collections::BTreeMap::new();
    for task in tasks {
        let (i, (status, _, body)) = task.await.unwrap();
        assert_eq!(status, 201, "post {i}: {body}");
        ids.insert(
            body["id"].as_str().unwrap().to_string(),
            format!("concurrent {i}"),
        );
    }
    assert_eq!(ids.len(), 50, "fifty distinct ids");

    let (_, _, list) = send(client.get(server.url("/api/v1/sessions?limit=1000"))).await;
    assert_eq!(list["total"], 50);
    let listed: std::collections::BTreeMap<String, String> = list["sessions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            (
                s["id"].as_str().unwrap().to_string(),
                s["name"].as_str().unwrap().to_string(),
            )
        })
        .collect();
    assert_eq!(listed, ids);
    // Paging covers the same sessions, newest first, without overlap.
    let mut paged = Vec::new();
    for offset in (0..50).step_by(20) {
        let (_, _, page) =
            send(client.get(server.url(&format!("/api/v1/sessions?limit=20&offset={offset}"))))
                .await;
        paged.extend(
            page["sessions"]
                .as_array()
                .unwrap()
                .iter()
                .map(|s| s["id"].clone()),
        );
    }
    let all: Vec<Value> = list["sessions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["id"].clone())
        .collect();
    assert_eq!(paged, all);
    server.shutdown().await;
}

/// Every id of the list at `path` (`sessions` or `machines`), walked a page of
/// `limit` at a time by the `next` cursor, with `between(seen so far)` run
/// between pages (a writer at a stand storing or deleting meanwhile).
async fn walk(
    server: &common::Server,
    client: &reqwest::Client,
    path: &str,
    key: &str,
    limit: usize,
    mut between: impl FnMut(&[String]) -> Option<(reqwest::Method, String, Value)>,
) -> Vec<String> {
    let mut seen = Vec::new();
    let mut query = format!("limit={limit}");
    loop {
        let (status, _, page) = send(client.get(server.url(&format!("{path}?{query}")))).await;
        assert_eq!(status, 200, "{page}");
        let items = page[key].as_array().unwrap();
        assert!(items.len() <= limit);
        seen.extend(items.iter().map(|s| s["id"].as_str().unwrap().to_string()));
        if let Some((method, url, body)) = between(&seen) {
            let (status, _, b) = send(client.request(method, server.url(&url)).json(&body)).await;
            assert!((200..300).contains(&status), "{url}: {status} {b}");
        }
        match page["next"].as_str() {
            Some(next) => query = format!("limit={limit}&before={next}"),
            None => break,
        }
    }
    seen
}

#[tokio::test]
async fn paging_by_the_next_cursor_neither_repeats_nor_loses_items_while_others_write() {
    // Offset paging of a newest-first list repeats the last item of a page
    // when a session is stored between two pages, and skips one when a
    // session is deleted. The `next` cursor continues after the last item seen.
    let (_dir, server, client) = fresh_server().await;
    let ex = example(SOLVABLE_EXAMPLES[0]);
    let mut ids = Vec::new();
    for _ in 0..7 {
        let (status, _, created) =
            post(&client, &server.url("/api/v1/sessions"), &ex["session"]).await;
        assert_eq!(status, 201);
        ids.push(created["id"].as_str().unwrap().to_string());
    }
    let newest_first: Vec<String> = ids.iter().rev().cloned().collect();
    let sessions = "/api/v1/sessions";
    let seen = walk(&server, &client, sessions, "sessions", 3, |_| {
        Some((
            reqwest::Method::POST,
            sessions.to_string(),
            ex["session"].clone(),
        ))
    })
    .await;
    assert_eq!(seen, newest_first, "a session stored between pages");
    // Deleting a session already seen loses none of the rest.
    let seen = walk(&server, &client, sessions, "sessions", 3, |seen| {
        (seen.len() == 3).then(|| {
            (
                reqwest::Method::DELETE,
                format!("{sessions}/{}", seen[0]),
                json!(null),
            )
        })
    })
    .await;
    assert_eq!(seen.len(), 10, "{seen:?}");
    assert_eq!(
        seen[3..],
        newest_first[..],
        "a session deleted between pages"
    );
    // The last page says there is no next; a bad cursor is named.
    let (_, _, all) = send(client.get(server.url("/api/v1/sessions?limit=1000"))).await;
    assert!(all.get("next").is_none(), "{all}");
    for bad in ["x", "0", "-3", "1.5"] {
        let (status, _, err) =
            send(client.get(server.url(&format!("/api/v1/sessions?before={bad}")))).await;
        assert_eq!(
            (status, &err["error"]["field"]),
            (422, &json!("before")),
            "{bad}: {err}"
        );
    }
    let (status, _, err) = send(client.get(server.url("/api/v1/sessions?before=5&offset=2"))).await;
    assert_eq!(
        (status, &err["error"]["field"]),
        (422, &json!("offset")),
        "{err}"
    );

    // Machines page the same way.
    let machines = "/api/v1/machines";
    for k in 0..5 {
        let (status, _, _) = post(
            &client,
            &server.url(machines),
            &json!({"id": format!("M{k}"), "name": "pump"}),
        )
        .await;
        assert_eq!(status, 201);
    }
    let mut k = 5;
    let seen = walk(&server, &client, machines, "machines", 2, |_| {
        k += 1;
        Some((
            reqwest::Method::POST,
            machines.to_string(),
            json!({"id": format!("M{k}"), "name": "pump"}),
        ))
    })
    .await;
    assert_eq!(seen, ["M4", "M3", "M2", "M1", "M0"]);
    server.shutdown().await;
}
