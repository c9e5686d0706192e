//! A check run that the technician renamed "trial…", reopened in another
//! browser: the form stored no check flag and counted it as a trial by its
//! name (the next trial of a two-plane job was proposed as "trial 4"). Each
//! run is now stored with its `purpose`, and a reopened job knows its check
//! runs whatever their names.

use serde_json::json;

use super::reopen_elsewhere;
use crate::harness::form::{field, value_of};
use crate::harness::job::{predicted, weights_in_editor};
use crate::harness::stand::{example_session, get, post, Stand};
use crate::harness::steps::{js, named, type_and_store};

pub async fn a_check_run_named_trial_stays_a_check_run_when_reopened(stand: &Stand) {
    let b = &stand.browser;
    let url = stand.server.url("");
    let url = url.trim_end_matches('/');
    // The zero run and a trial per plane, stored by another client (no purposes).
    let (session, _) = example_session("pump-two-plane-exact.json");
    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().expect("stored").to_string();
    reopen_elsewhere(stand, &id, "solve").await;
    b.click("#step-solve button.solve").await;
    b.click("#step-solve button.check-run").await;
    let on = weights_in_editor(b, 3).await;
    let name = "trial weights fitted";
    let check = named(predicted(url, &session, &on).await, name);
    type_and_store(b, &session, 3, &check).await;
    let run = get(
        stand,
        &format!("/api/v1/sessions/{id}/runs/trial%20weights%20fitted"),
    )
    .await;
    assert_eq!(run["purpose"], "check", "stored as what it is: {run}");

    reopen_elsewhere(stand, &id, "runs").await;
    b.wait_for("#step-runs td.value.amp").await;
    let kinds = js(
        b,
        "return [...document.querySelectorAll('#step-runs th.run')].map((t) => [t.dataset.run, t.querySelector('.run-kind')?.textContent ?? ''])",
    )
    .await;
    assert_eq!(
        kinds,
        json!([
            ["zero", ""],
            ["trial inboard", "trial run"],
            ["trial outboard", "trial run"],
            [name, "check run"]
        ])
    );
    // Two trials so far: the next is the third, whatever the check run is called.
    b.click("#step-runs button.add-trial").await;
    assert_eq!(value_of(b, &field("runs[4].id")).await, "trial 3");
    assert_eq!(value_of(b, &field("runs[4].purpose")).await, "trial");
    b.click("#step-runs button.cancel").await;
    // The trim starts from the check run, as the technician fitted it.
    b.click("#step-runs button.go-solve").await;
    b.click("details.options summary").await;
    assert_eq!(value_of(b, "select.from-run").await, name);
}
