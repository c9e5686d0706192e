//! A job solved more than 20 times, reopened: the service lists a session's
//! solutions a page at a time, oldest first (20 unless asked), and the form
//! took the last of the first page as the job's last solution. Solved 20
//! times, then once more after a check run, it reopened with no answer
//! (the 20th solution's runs are not the job's runs).

use serde_json::json;

use super::reopen_elsewhere;
use crate::harness::job::predicted;
use crate::harness::stand::{example_session, post, Stand};

pub async fn a_job_solved_often_reopens_with_its_last_solution(stand: &Stand) {
    let b = &stand.browser;
    let url = stand.server.url("");
    let (session, expected) = example_session("pump-two-plane-exact.json");
    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().expect("stored").to_string();
    let solutions = format!("/api/v1/sessions/{id}/solutions");
    for _ in 0..20 {
        let solved = post(stand, &solutions, json!({})).await;
        assert!(solved["solution"].is_object(), "{solved}");
    }
    let on = expected["corrections"].clone();
    let mut check = predicted(url.trim_end_matches('/'), &session, &on).await;
    check["id"] = json!("check");
    check["purpose"] = json!("check");
    let added = post(stand, &format!("/api/v1/sessions/{id}/runs"), check).await;
    assert_eq!(added["run_id"], "check", "{added}");
    let last = post(stand, &solutions, json!({})).await;
    assert!(last["solution"].is_object(), "{last}");

    reopen_elsewhere(stand, &id, "solve").await;
    b.wait_for("#step-solve table.corrections").await;
    b.wait_for("#step-solve .run-check[data-run=\"check\"]")
        .await;
}
