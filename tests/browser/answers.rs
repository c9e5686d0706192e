//! The answer as it is read. The test's own reader, `corrections_on_page`,
//! reads the answer of the last solve asked for, not the one before it that
//! the page still shows while the new one is out (it waited for any row of
//! corrections, so a test after a re-solve could pass on the old answer).

use serde_json::{json, Value};

use crate::harness::form::{corrections_on_page, field, type_into};
use crate::harness::stand::{example_session, open_at_solve, post, Stand};
use crate::harness::steps::js;

/// Store `session` and open it at its corrections step in the stand's browser.
async fn opened(stand: &Stand, session: &Value) -> String {
    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"]
        .as_str()
        .unwrap_or_else(|| panic!("stored: {created}"))
        .to_string();
    open_at_solve(stand, &id).await;
    id
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_corrections_read_after_a_re_solve_are_the_new_ones() {
    let stand = Stand::start().await;
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    opened(&stand, &session).await;
    b.click("#step-solve button.solve").await;
    let first = corrections_on_page(b).await;
    let (plane, heaviest, _) = first
        .iter()
        .cloned()
        .max_by(|x, y| x.1.total_cmp(&y.1))
        .expect("corrections");
    let limit = (heaviest * 0.6).floor();
    let want = post(
        &stand,
        "/api/v1/solve",
        json!({ "session": session, "options": { "max_mass_g": { plane.clone(): limit } } }),
    )
    .await;
    // The page's next answer is held back for a second and a half: the old
    // one is on the page meanwhile, as on a slow stand PC.
    js(
        b,
        "const f = window.fetch; \
         window.fetch = (url, init) => f(url, init).then((r) => /\\/solutions$/.test(String(url)) && init && init.method === 'POST' \
           ? new Promise((ok) => setTimeout(() => ok(r), 1500)) : r); \
         return true",
    )
    .await;
    b.click("#step-solve details.options summary").await;
    let css = field(&format!("options.max_mass_g.{plane}"));
    type_into(b, &css, &format!("{limit}")).await;
    b.click("#step-solve button.solve").await;
    let shown = corrections_on_page(b).await;
    let want = want["corrections"]
        .as_array()
        .unwrap_or_else(|| panic!("{want}"));
    assert_eq!(shown.len(), want.len(), "{shown:?}");
    for (w, (p, mass, angle)) in want.iter().zip(&shown) {
        assert_eq!(w["plane"].as_str(), Some(p.as_str()));
        let (m, a) = (
            w["mass_g"].as_f64().unwrap(),
            w["angle_deg"].as_f64().unwrap(),
        );
        let d = (angle - a).rem_euclid(360.0);
        assert!(
            (mass - m).abs() <= 0.051 && d.min(360.0 - d) <= 0.051,
            "{p}: {mass} g at {angle}° read, the limited answer is {m} g at {a}° (the first answer: {first:?})"
        );
    }
    stand.stop().await;
}
