//! Every stored session and machine reachable from its list, a page at a time;
//! a machine stored without a name shows its id once, and both lists give the
//! time each was stored in one format.

use super::texts;
use crate::harness::form::{field, type_into};
use crate::harness::stand::{example_session, get, post, Stand};
use crate::harness::steps::js;
use serde_json::{json, Value};

pub async fn every_stored_session_can_be_reached_from_the_list(stand: &Stand) {
    let b = &stand.browser;
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    for i in 0..53 {
        session["name"] = json!(format!("job {i:02}"));
        let stored = post(stand, "/api/v1/sessions", session.clone()).await;
        assert!(stored["id"].is_string(), "{stored}");
    }
    b.click("nav [data-step=\"sessions\"]").await;
    b.wait_for("#step-sessions button.more-sessions").await;
    let names = texts(b, "#step-sessions button.open-session").await;
    assert_eq!(names.len(), 50, "a page at a time");
    assert_eq!(names[0], "job 52", "newest first");
    let note = b.text("#step-sessions p.more").await;
    assert_eq!(note, "The 50 newest of 53 stored sessions. Show 3 more");
    b.click("#step-sessions button.more-sessions").await;
    b.wait_until(
        "the older sessions listed",
        "return document.querySelectorAll('#step-sessions button.open-session').length === 53",
    )
    .await;
    let names = texts(b, "#step-sessions button.open-session").await;
    assert_eq!(names[52], "job 00", "the oldest is reachable");
    assert_eq!(
        b.text("#step-sessions p.more").await,
        "",
        "nothing more to show"
    );
    // And it opens.
    b.client
        .execute(
            "[...document.querySelectorAll('#step-sessions button.open-session')].pop().click()",
            vec![],
        )
        .await
        .unwrap();
    b.wait_until(
        "the oldest session opened",
        "return document.querySelector('#job-title').textContent === 'job 00 · stored'",
    )
    .await;

    // Machines the same way (a fleet on one database), 100 at a time.
    for i in 0..102 {
        let id = format!("M-{i:03}");
        let stored = post(stand, "/api/v1/machines", json!({"id": id, "name": id})).await;
        assert_eq!(stored["id"], json!(id), "{stored}");
    }
    b.click("nav [data-step=\"machines\"]").await;
    b.wait_for("#step-machines button.more-machines").await;
    assert_eq!(
        texts(b, "#step-machines button.open-machine").await.len(),
        100
    );
    let note = b.text("#step-machines p.more").await;
    assert_eq!(note, "The 100 newest of 102 machines. Show 2 more");
    b.click("#step-machines button.more-machines").await;
    b.wait_until(
        "the older machines listed",
        "return document.querySelectorAll('#step-machines button.open-machine').length === 102",
    )
    .await;
    let ids = texts(b, "#step-machines button.open-machine").await;
    assert_eq!(ids[101], "M-000", "the oldest is reachable");
    a_machine_without_a_name_shows_its_id_once(stand).await;
    both_lists_show_when_stored_alike(stand).await;
}

/// The form stored the id as the name when none was typed (as the machines
/// above were stored): the id was then shown twice, in the list's Machine and
/// Name columns and in the page's heading ("Machine FAN-2 · FAN-2"). Fails
/// without the fix in static/js/steps/machines.js. A machine given no name is
/// now stored without one (session 19, tests/browser/reopened/machine.rs).
async fn a_machine_without_a_name_shows_its_id_once(stand: &Stand) {
    let b = &stand.browser;
    let row = js(b, "const r = document.querySelector('#step-machines button.open-machine[data-id=\"M-000\"]').closest('tr'); return [r.children[0].textContent, r.children[1].textContent]").await;
    assert_eq!(row, json!(["M-000", "–"]), "the id once, no name");
    // Stored from the form with the name left empty.
    type_into(b, &field("machine.id"), "FAN-2").await;
    b.click("button.create-machine").await;
    b.wait_until(
        "the new machine's page",
        "const e = document.querySelector('#step-machines h2'); return !!e && e.textContent.includes('FAN-2') && !!document.querySelector('#step-machines table.machine-jobs')",
    )
    .await;
    assert_eq!(get(stand, "/api/v1/machines/FAN-2").await.get("name"), None);
    assert_eq!(b.text("#step-machines h2").await, "Machine FAN-2");
}

/// The Sessions page gave the browser's local time in its own format
/// ("11/24/2026, 7:25:39 AM"), the Machines page "2026-11-24 06:25 UTC": now
/// both the latter, from the stored RFC 3339 time in UTC (unchanged in the
/// store). Fails without the fix in static/js/steps/sessions.js.
async fn both_lists_show_when_stored_alike(stand: &Stand) {
    let b = &stand.browser;
    let shown = |t: &Value| {
        let t = t.as_str().unwrap();
        assert!(t.ends_with('Z'), "stored in UTC: {t}");
        format!("{} {} UTC", &t[..10], &t[11..16])
    };
    b.click("nav [data-step=\"machines\"]").await;
    b.wait_for("#step-machines button.open-machine[data-id=\"FAN-2\"]")
        .await;
    let machines = get(stand, "/api/v1/machines?limit=5").await;
    for m in machines["machines"].as_array().unwrap() {
        let cell = js(b, &format!("return document.querySelector('#step-machines button.open-machine[data-id={}]').closest('tr').children[2].textContent", serde_json::to_string(m["id"].as_str().unwrap()).unwrap())).await;
        assert_eq!(cell, json!(shown(&m["created_at"])), "machine {}", m["id"]);
    }
    b.click("nav [data-step=\"sessions\"]").await;
    b.wait_for("#step-sessions button.open-session").await;
    let sessions = get(stand, "/api/v1/sessions?limit=5").await;
    for x in sessions["sessions"].as_array().unwrap() {
        let cell = js(b, &format!("return document.querySelector('#step-sessions button.open-session[data-id={}]').closest('tr').children[2].firstChild.textContent", serde_json::to_string(x["id"].as_str().unwrap()).unwrap())).await;
        assert_eq!(cell, json!(shown(&x["created_at"])), "session {}", x["id"]);
    }
}
