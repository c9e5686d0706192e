//! The service stops answering while a trial run is typed: Store says so in
//! plain words, and what became of the run (the banner read "Is `fieldbal
//! serve` running?", backticks and all, and not whether the run was
//! stored); nothing typed is lost (on the page, and after a reload), and
//! the run is stored once the service answers again. The page's `fetch` is
//! made to fail as it does when nothing listens (a `TypeError`), so the
//! scene needs no second server on the same origin.

use serde_json::json;

use crate::harness::form::{cells, choose, field, type_cells_with_tab, type_into, value_of};
use crate::harness::stand::{example_session, get, post, Stand};
use crate::harness::steps::js;

/// The typed trial run is on the page as it was typed.
async fn kept(b: &crate::harness::Browser, values: &[String]) {
    for (i, value) in values.iter().enumerate() {
        let kind = if i % 2 == 0 { "amplitude" } else { "phase_deg" };
        let css = field(&format!("runs[2].readings[{}].{kind}", i / 2));
        assert_eq!(&value_of(b, &css).await, value, "{css} kept");
    }
    assert_eq!(value_of(b, &field("runs[2].weights[0].mass_g")).await, "25");
}

pub async fn a_run_typed_while_the_service_is_away_is_kept_and_stored_later(stand: &Stand) {
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    let mut first = session.clone();
    first["runs"] = json!([session["runs"][0].clone(), session["runs"][1].clone()]);
    let created = post(stand, "/api/v1/sessions", first).await;
    let id = created["id"].as_str().expect("stored").to_string();
    let url = stand.server.url(&format!("/#session={id}&step=runs"));
    b.open_fresh(&url).await;
    b.click("#step-runs button.add-trial").await;
    let run = &session["runs"][2];
    choose(b, &field("runs[2].weights[0].plane"), "outboard").await;
    type_into(b, &field("runs[2].weights[0].mass_g"), "25").await;
    type_into(b, &field("runs[2].weights[0].angle_deg"), "120").await;
    let values = cells(&session, run);
    type_cells_with_tab(b, 2, &values).await;

    js(
        b,
        "window.realFetch = window.fetch; window.fetch = () => Promise.reject(new TypeError('Failed to fetch')); return true",
    )
    .await;
    b.click("#step-runs button.store").await;
    let said = b.text("#step-runs .banner.error:not([hidden])").await;
    assert!(
        said.contains("does not answer") && said.contains("the run was not stored"),
        "{said}"
    );
    assert!(!said.contains('`'), "plain words: {said}");
    kept(b, &values).await;

    // The service back (a new page has the real fetch): the reload brings
    // the typed run back, and it stores.
    b.open_fresh(&url).await;
    b.wait_for(&field("runs[2].readings[0].amplitude")).await;
    kept(b, &values).await;
    b.click("#step-runs button.store").await;
    b.wait_for("#step-runs button.go-solve:not(:disabled)")
        .await;
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let runs = stored["session"]["runs"]
        .as_array()
        .or_else(|| stored["runs"].as_array())
        .unwrap_or_else(|| panic!("{stored}"))
        .len();
    assert_eq!(runs, 3, "{stored}");
}
