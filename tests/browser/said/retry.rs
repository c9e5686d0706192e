//! A store that half-succeeds: the service takes the run but its answer, or
//! the read of the session's tag after it, is lost (the service gone a
//! moment). The form said "the run was not stored" when it was, and Store
//! pressed again said the session was "changed in another tab" (or that
//! another run had the run's name): the technician could think someone else
//! had edited the job. The retry now sees that the run it stores is there
//! already, the same, and goes on; the run is stored once.

use serde_json::{json, Value};

use crate::harness::form::{cells, choose, field, type_cells_with_tab, type_into, typed};
use crate::harness::stand::{example_session, get, post, Stand};
use crate::harness::steps::js;
use crate::harness::Browser;

/// Type trial run `k` of `session` (weights, name, readings) without storing it.
async fn type_trial(b: &Browser, session: &Value, k: usize) {
    let run = &session["runs"][k];
    let w = &run["weights"][0];
    b.click("#step-runs button.add-trial").await;
    let path = format!("runs[{k}].weights[0]");
    choose(b, &field(&format!("{path}.plane")), w["plane"].as_str().unwrap()).await;
    type_into(b, &field(&format!("{path}.mass_g")), &typed(&w["mass_g"])).await;
    type_into(b, &field(&format!("{path}.angle_deg")), &typed(&w["angle_deg"])).await;
    type_into(b, &field(&format!("runs[{k}].id")), run["id"].as_str().unwrap()).await;
    type_cells_with_tab(b, k, &cells(session, run)).await;
}

/// The stored session's run ids, in order.
async fn stored_runs(stand: &Stand, id: &str) -> Vec<String> {
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let session = stored.get("session").cloned().unwrap_or(stored);
    session["runs"]
        .as_array()
        .unwrap_or_else(|| panic!("{session}"))
        .iter()
        .map(|r| r["id"].as_str().unwrap().to_string())
        .collect()
}

/// Press Store and wait until the run is stored (the draft gone) or a banner speaks.
async fn press_store(b: &Browser) {
    b.click("#step-runs button.store").await;
    b.wait_until(
        "the run is stored or a banner speaks",
        "return !!document.querySelector('#step-runs button.add-trial') || \
         !!document.querySelector('#step-runs .banner:not([hidden])')",
    )
    .await;
}

pub async fn a_store_that_half_succeeded_is_not_taken_for_another_tab(stand: &Stand) {
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    let mut first = session.clone();
    first["runs"] = json!([session["runs"][0].clone()]);
    let created = post(stand, "/api/v1/sessions", first).await;
    let id = created["id"].as_str().expect("stored").to_string();
    b.open_fresh(&stand.server.url(&format!("/#session={id}&step=runs")))
        .await;

    // The run is added, then the read of the session's tag after it fails.
    type_trial(b, &session, 1).await;
    js(
        b,
        "window.realFetch = window.fetch; let added = false; \
         window.fetch = (url, init) => { \
           const method = (init && init.method) || 'GET'; \
           if (added && method === 'GET') { window.fetch = window.realFetch; return Promise.reject(new TypeError('Failed to fetch')); } \
           return window.realFetch(url, init).then((r) => { if (method === 'POST' && String(url).endsWith('/runs')) added = true; return r; }); \
         }; return true",
    )
    .await;
    press_store(b).await;
    let said = b.text("#step-runs .banner:not([hidden])").await;
    assert!(
        said.contains("was stored") && !said.contains("not stored"),
        "the run was stored, and the page says so: {said}"
    );
    assert_eq!(stored_runs(stand, &id).await, ["zero", "trial inboard"]);
    assert!(
        js(b, "return !!document.querySelector('#step-runs button.add-trial')").await == json!(true),
        "the job goes on: the next run can be added"
    );

    // The next run reaches the service, but its answer is lost: Store again
    // with the service back finds it there, the same, and goes on.
    type_trial(b, &session, 2).await;
    js(
        b,
        "window.fetch = (url, init) => { \
           const method = (init && init.method) || 'GET'; \
           if (method === 'POST' && String(url).endsWith('/runs')) { \
             window.fetch = window.realFetch; \
             return window.realFetch(url, init).then(() => { throw new TypeError('Failed to fetch'); }); } \
           return window.realFetch(url, init); \
         }; return true",
    )
    .await;
    press_store(b).await;
    let said = b.text("#step-runs .banner.error:not([hidden])").await;
    assert!(said.contains("does not answer"), "{said}");
    press_store(b).await;
    let banner = js(
        b,
        "const e = document.querySelector('#step-runs .banner.error:not([hidden])'); return e ? e.textContent : ''",
    )
    .await;
    assert_eq!(banner, json!(""), "no other tab changed the session");
    b.wait_for("#step-runs button.go-solve:not(:disabled)").await;
    assert_eq!(
        stored_runs(stand, &id).await,
        ["zero", "trial inboard", "trial outboard"],
        "each run stored once"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn dev_form20b() {
    let stand = Stand::start().await;
    a_store_that_half_succeeded_is_not_taken_for_another_tab(&stand).await;
    stand.stop().await;
}
