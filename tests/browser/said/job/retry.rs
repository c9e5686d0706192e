//! A store that half-succeeds: the service takes the run but its answer, or
//! the read of the session's tag after it, is lost (the service gone a
//! moment). The form said "the run was not stored" when it was, and Store
//! pressed again said the session was "changed in another tab" (or that
//! another run had the run's name): the technician could think someone else
//! had edited the job. Now a run the service took is said to be stored; a
//! write whose answer was lost is said to be uncertain, and Store pressed
//! again (also after a reload) sees the run stored as sent and goes on; each
//! run is stored once. A new job's zero run, whose create lost its answer,
//! is looked for among the stored sessions: the job is stored once.
//!
//! How the answer is lost in a real browser: the page's `fetch` is replaced,
//! for one call, by one that lets the request reach the service and then
//! fails as a lost connection does (a `TypeError`), or that fails the read
//! after the write; it puts the real `fetch` back as it fails.

use serde_json::{json, Value};

use crate::harness::form::{cells, field, fill_run, type_cells_with_tab, type_into, type_setup};
use crate::harness::stand::{example_session, get, post, Stand};
use crate::harness::steps::js;
use crate::harness::Browser;

/// The stored session's runs.
async fn stored_runs(stand: &Stand, id: &str) -> Vec<Value> {
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let session = stored.get("session").cloned().unwrap_or(stored);
    session["runs"]
        .as_array()
        .unwrap_or_else(|| panic!("{session}"))
        .clone()
}

/// The stored session's run ids, in order.
async fn stored_ids(stand: &Stand, id: &str) -> Vec<String> {
    stored_runs(stand, id)
        .await
        .iter()
        .map(|r| r["id"].as_str().unwrap().to_string())
        .collect()
}

/// Press Store and wait until the run is stored (the draft gone, the next
/// run can be added) or an error banner speaks; the banner shown then.
async fn press_store(b: &Browser) -> String {
    b.click("#step-runs button.store").await;
    b.wait_until(
        "the run is stored or an error speaks",
        "return !!document.querySelector('#step-runs button.add-trial') || \
         !!document.querySelector('#step-runs .banner.error:not([hidden])')",
    )
    .await;
    js(
        b,
        "const e = document.querySelector('#step-runs .banner:not([hidden])'); return e ? e.className + ': ' + e.textContent : ''",
    )
    .await
    .as_str()
    .unwrap()
    .to_string()
}

/// The page's `fetch` lets the next write (`method` to a path ending in
/// `tail`) reach the service, then fails as a lost connection does.
async fn lose_the_answer_of(b: &Browser, method: &str, tail: &str) {
    js(
        b,
        &format!(
            "const real = window.fetch; \
             window.fetch = (url, init) => {{ \
               const method = (init && init.method) || 'GET'; \
               if (method === '{method}' && String(url).endsWith('{tail}')) {{ \
                 window.fetch = real; \
                 return real(url, init).then(() => {{ throw new TypeError('Failed to fetch'); }}); }} \
               return real(url, init); \
             }}; return true"
        ),
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
    let url = stand.server.url(&format!("/#session={id}&step=runs"));
    b.open_fresh(&url).await;

    // (a) The run is added, then the read of the session's tag after it fails.
    fill_run(b, &session, 1, false).await;
    js(
        b,
        "const real = window.fetch; let added = false; \
         window.fetch = (url, init) => { \
           const method = (init && init.method) || 'GET'; \
           if (added && method === 'GET') { window.fetch = real; return Promise.reject(new TypeError('Failed to fetch')); } \
           return real(url, init).then((r) => { if (method === 'POST' && String(url).endsWith('/runs')) added = true; return r; }); \
         }; return true",
    )
    .await;
    let said = press_store(b).await;
    assert!(
        said.contains("was stored") && !said.contains("not stored"),
        "the run was stored, and the page says so: {said}"
    );
    assert_eq!(stored_ids(stand, &id).await, ["zero", "trial inboard"]);

    // (b) The next run reaches the service, but its answer is lost: the page
    // cannot tell, and says so; Store again finds it stored, the same, and
    // goes on (the tag missed in (a) is no other tab's change either).
    fill_run(b, &session, 2, false).await;
    lose_the_answer_of(b, "POST", "/runs").await;
    let said = press_store(b).await;
    assert!(
        said.contains("error") && said.contains("does not answer"),
        "{said}"
    );
    assert!(
        said.contains("cannot tell whether the run was stored") && !said.contains("not stored"),
        "the service may have taken it: {said}"
    );
    let said = press_store(b).await;
    assert!(
        !said.contains("error") && !said.contains("another tab"),
        "no other tab changed the session: {said}"
    );
    assert!(said.contains("stored once"), "{said}");
    b.wait_for("#step-runs button.go-solve:not(:disabled)")
        .await;
    assert_eq!(
        stored_ids(stand, &id).await,
        ["zero", "trial inboard", "trial outboard"],
        "each run stored once"
    );

    // (c) A correction reaches the service, its answer is lost, and the page
    // is reloaded before Store is pressed again: the corrected run comes
    // back, and Store sees it stored as sent (one new version, no conflict).
    b.click("#step-runs th.run[data-run=\"trial outboard\"] button.correct")
        .await;
    type_into(b, &field("runs[2].readings[0].amplitude"), "742").await;
    lose_the_answer_of(b, "PUT", "/runs/trial%20outboard").await;
    let said = press_store(b).await;
    assert!(said.contains("cannot tell whether"), "{said}");
    b.open_fresh(&url).await;
    b.wait_for(&field("runs[2].readings[0].amplitude")).await;
    let said = press_store(b).await;
    assert!(
        !said.contains("error") && said.contains("stored once"),
        "{said}"
    );
    let runs = stored_runs(stand, &id).await;
    assert_eq!(runs[2]["readings"][0]["amplitude"], json!(742.0));
    let versions = get(
        stand,
        &format!("/api/v1/sessions/{id}/runs/trial%20outboard/versions"),
    )
    .await;
    let versions = versions.get("versions").cloned().unwrap_or(versions);
    assert_eq!(
        versions.as_array().map(Vec::len),
        Some(2),
        "the run as typed and its correction, once: {versions}"
    );

    // (d) A new job: the create that stores it with its zero run loses its
    // answer. Store again finds the job among the stored sessions.
    b.click("nav [data-step=\"sessions\"]").await;
    b.click("#step-sessions button.new-session").await;
    let mut fresh = session.clone();
    fresh["name"] = json!("a new job");
    type_setup(b, &fresh).await;
    b.click("#step-setup button.next").await;
    type_cells_with_tab(b, 0, &cells(&fresh, &fresh["runs"][0])).await;
    lose_the_answer_of(b, "POST", "/api/v1/sessions").await;
    let said = press_store(b).await;
    assert!(
        said.contains("error") && said.contains("cannot tell whether the job was stored"),
        "{said}"
    );
    let said = press_store(b).await;
    assert!(
        !said.contains("error") && said.contains("stored once"),
        "{said}"
    );
    let listed = get(stand, "/api/v1/sessions").await;
    let named = listed["sessions"]
        .as_array()
        .unwrap_or_else(|| panic!("{listed}"))
        .iter()
        .filter(|x| x["name"] == "a new job")
        .count();
    assert_eq!(named, 1, "the new job stored once: {listed}");
    let here = js(b, "return location.hash").await;
    assert!(
        here.as_str().unwrap().contains("session="),
        "the page is on the stored job: {here}"
    );
}
