//! A trim job (solved with a machine's stored coefficients, or with supplied
//! ones) that is not solved yet, reopened in a browser that never saw it:
//! it asked for trial runs, because what made it a trim job lived in the
//! other browser's local storage only. The session now records it (`trim`).

use serde_json::{json, Value};

use super::reopen_elsewhere;
use crate::harness::form::{self, field, type_into};
use crate::harness::stand::{example_session, get, machine_with_coefficients, post, Stand};
use crate::harness::steps::stored_id;

/// The stored solutions of session `id`, once there are `n`.
async fn solutions(stand: &Stand, id: &str, n: usize) -> Vec<Value> {
    let path = format!("/api/v1/sessions/{id}/solutions");
    for _ in 0..crate::harness::WAIT_POLLS {
        let got = get(stand, &path).await;
        if got.as_array().is_some_and(|l| l.len() == n) {
            return got.as_array().unwrap().clone();
        }
        tokio::time::sleep(std::time::Duration::from_millis(100)).await;
    }
    panic!("session {id} has not {n} solutions within 30 s");
}

/// The runs step says it is a trim job, offers Solve, asks for no trial.
async fn is_a_trim_job(stand: &Stand, words: &str) {
    let b = &stand.browser;
    b.wait_for("#step-runs td.value.amp").await;
    let lead = b.text("#step-runs p.lead").await;
    assert_eq!(
        lead,
        format!("Trim job from {words}: no trial runs are needed. Solve now."),
    );
    let enabled = crate::harness::steps::js(
        b,
        "return !document.querySelector('#step-runs button.go-solve').disabled",
    )
    .await;
    assert_eq!(enabled, json!(true), "Solve is offered without trial runs");
}

/// The trim job begun on the machine page, its zero run typed and stored,
/// then reopened elsewhere before it is solved.
pub async fn an_unsolved_trim_job_reopened_elsewhere_asks_for_no_trial_runs(stand: &Stand) {
    let b = &stand.browser;
    let session = machine_with_coefficients(stand).await;
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.click("button.trim-job").await;
    b.wait_until(
        "the set-up of the machine's last job is copied",
        "const e = document.querySelector('[data-field=\"planes[1].id\"]'); return !!e && e.value === 'outboard'",
    )
    .await;
    type_into(b, &field("name"), "PUMP-1 trim").await;
    b.click("#step-setup button.next").await;
    form::type_cells_with_tab(b, 0, &form::cells(&session, &session["runs"][0])).await;
    form::store(b).await;
    let id = stored_id(b).await;
    // The session says what the job is.
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let stored = stored.get("session").cloned().unwrap_or(stored);
    assert_eq!(
        stored["trim"],
        json!({"coefficients_from": {"machine": "PUMP-1"}}),
        "{stored}"
    );
    assert!(
        solutions(stand, &id, 0).await.is_empty(),
        "not solved before it is reopened"
    );

    reopen_elsewhere(stand, &id, "runs").await;
    is_a_trim_job(stand, "the stored coefficients of machine PUMP-1").await;
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    let said = b.text("#step-solve .coefficients-from").await;
    assert_eq!(
        said,
        "Influence coefficients: the stored ones of machine PUMP-1, version 1 (no trial runs in this job)."
    );
    let list = solutions(stand, &id, 1).await;
    assert_eq!(
        list[0]["options"]["coefficients_from"]["machine"], "PUMP-1",
        "solved with the stored coefficients: {}",
        list[0]
    );
}

/// A job stored by stand software with supplied coefficients and only its
/// zero run, opened in the form: a trim job, solved with those coefficients.
pub async fn a_job_with_supplied_coefficients_reopened_elsewhere_is_a_trim_job(stand: &Stand) {
    let b = &stand.browser;
    machine_with_coefficients(stand).await;
    let known = get(stand, "/api/v1/machines/PUMP-1/coefficients").await;
    let supplied = known["influence_coefficients"].clone();
    let n = supplied.as_array().expect("coefficients").len();
    assert_eq!(n, 8, "4 sensors × 2 planes: {known}");
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    session["name"] = json!("supplied trim");
    session["runs"] = json!([session["runs"][0].clone()]);
    session["trim"] = json!({ "influence_coefficients": supplied });
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();

    reopen_elsewhere(stand, &id, "runs").await;
    is_a_trim_job(stand, "the 8 supplied influence coefficients").await;
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve table.corrections").await;
    let list = solutions(stand, &id, 1).await;
    assert_eq!(
        list[0]["options"]["influence_coefficients"], supplied,
        "solved with the supplied coefficients: {}",
        list[0]
    );
}
