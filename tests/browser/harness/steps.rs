//! Steps of the whole-job browser test (tests/browser/job.rs) that read as
//! one sentence each: the typed-mistake rules, storing a typed run, solving,
//! the service's own trim to compare with, and the tablet-width checks.

use serde_json::{json, Value};

use super::form::{self, field, type_into};
use super::job::{message_for, sideways, small_targets};
use super::stand::{get, post, Stand};
use super::Browser;

pub const PROBE: &str = "probe";

/// The run a check run stores, with its name.
pub fn named(mut run: Value, id: &str) -> Value {
    assert_eq!(run["id"], PROBE);
    run["id"] = json!(id);
    run
}

pub async fn js(b: &Browser, script: &str) -> Value {
    b.client.execute(script, vec![]).await.expect("script runs")
}

/// The answer of an asynchronous script: one that calls `arguments[0]` (its
/// `done`) when it has finished, such as one importing the page's modules.
pub async fn js_async(b: &Browser, script: &str) -> Value {
    b.client
        .execute_async(script, vec![])
        .await
        .expect("script runs")
}

/// Every message a speed list, a phase or a decimal comma can get is the one the rule states.
pub async fn typed_mistakes_are_refused_with_the_reason(b: &Browser) {
    let speeds = field("speeds");
    let glued = message_for(b, &speeds, "1480,2950").await;
    assert!(glued.contains("ambiguous"), "{glued}");
    assert_eq!(message_for(b, &speeds, "1480, 2950").await, "");
    assert_eq!(message_for(b, &speeds, "1480;2950").await, "");
    let same = message_for(b, &speeds, "1480 1485").await;
    assert!(same.contains("within 1 %"), "{same}");
    // The rule is stated at the field, not only when it is broken.
    let rule = b.text("fieldset.job .hint.rule").await;
    assert!(rule.contains("“;”"), "{rule}");
    let decimal = b.text("fieldset.job .decimal-rule").await;
    assert!(decimal.contains("1,234 is refused"), "{decimal}");
    let got = js(
        b,
        "return import('/static/js/page/num.js').then((m) => [m.parseSpeeds('1480, 2950').value, m.parseSpeeds('1480;2950').value, m.check('370', 'phase').error, m.check('-10', 'phase').error, m.check('1,234', 'amplitude').error, m.check('2,5', 'amplitude').value])",
    )
    .await;
    assert_eq!(got[0], json!([1480, 2950]));
    assert_eq!(got[1], json!([1480, 2950]));
    assert_eq!(
        got[2],
        "phase in degrees, 0 to 360: 370° is more than a turn, the same place as 10°; type 10"
    );
    assert_eq!(
        got[3],
        "phase in degrees, 0 to 360: -10° is below 0, the same place as 350°; type 350"
    );
    assert_eq!(
        got[4],
        "1,234 could mean 1234 or 1.234: type it without the comma, or with a point"
    );
    assert_eq!(got[5], json!(2.5));
    type_into(b, &speeds, "").await;
}

/// Type the cells of `run` into run column `k` with Tab and store it.
pub async fn type_and_store(b: &Browser, session: &Value, k: usize, run: &Value) {
    type_into(
        b,
        &field(&format!("runs[{k}].id")),
        run["id"].as_str().unwrap(),
    )
    .await;
    form::type_cells_with_tab(b, k, &form::cells(session, run)).await;
    form::store(b).await;
}

pub async fn solve(b: &Browser) {
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve table.corrections").await;
}

/// The service's own trim from `from_run` of the stored session.
pub async fn service_trim(stand: &Stand, id: &str, from_run: &str) -> Value {
    let session = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let session = session.get("session").cloned().unwrap_or(session);
    post(
        stand,
        "/api/v1/solve",
        json!({ "session": session, "options": { "from_run": from_run } }),
    )
    .await
}

pub async fn stored_id(b: &Browser) -> String {
    let hash = js(b, "return location.hash").await;
    let hash = hash.as_str().unwrap();
    let id = hash
        .strip_prefix("#session=")
        .and_then(|h| h.split('&').next())
        .unwrap_or_else(|| panic!("no session in {hash}"));
    id.to_string()
}

/// The runs grid's header and the runs step's actions stay in view while scrolling.
pub async fn grid_header_and_actions_are_sticky(b: &Browser) {
    let got = js(
        b,
        "return [getComputedStyle(document.querySelector('#step-runs table.grid thead')).position, \
                 getComputedStyle(document.querySelector('#step-runs .actions.sticky')).position]",
    )
    .await;
    assert_eq!(got, json!(["sticky", "sticky"]));
}

/// Touch targets and sideways scrolling at tablet width, on the step shown now.
pub async fn fits_a_tablet(b: &Browser, what: &str) {
    b.viewport(768, 1024).await;
    assert_eq!(
        small_targets(b).await,
        json!([]),
        "{what}: targets under 44 px"
    );
    let (over, culprits) = sideways(b).await;
    assert!(
        over <= 0,
        "{what}: the page scrolls sideways by {over} px: {culprits}"
    );
    b.viewport(1280, 800).await;
}

/// The corrections step's summary is greyed, its figures plain, exactly when a
/// correction above it is (a sure answer keeps its bold figures); returns which.
pub async fn summary_follows_the_doubts(b: &Browser) -> bool {
    let got = js(
        b,
        "const s = document.querySelector('#step-solve .summary'); \
         return [s.className, [...s.querySelectorAll('.big .value')].map((e) => getComputedStyle(e).fontWeight), \
                 document.querySelectorAll('#step-solve table.corrections tr.doubtful').length > 0]",
    )
    .await;
    let doubtful = got[2] == json!(true);
    let want = if doubtful {
        json!(["summary unsure", ["400", "400", "400"], true])
    } else {
        json!(["summary", ["700", "700", "700"], false])
    };
    assert_eq!(got, want, "the summary as sure as the corrections");
    doubtful
}

/// A plane the trim leaves as it is (its words say "nothing to add") shows no
/// weight and no angle to read in the corrections table.
pub async fn a_plane_the_trim_leaves_shows_nothing_to_add(b: &Browser) {
    let nothing = js(
        b,
        "return [...document.querySelectorAll('#step-solve .trim li')].filter((l) => l.textContent.includes('nothing to add')) \
           .map((l) => document.querySelector(`#step-solve table.corrections tr[data-plane=\"${l.dataset.plane}\"]`)) \
           .map((r) => [r.className, r.querySelector('.corr-mass').textContent, r.querySelector('.corr-angle').textContent])",
    )
    .await;
    assert!(!nothing.as_array().unwrap().is_empty(), "{nothing}");
    for row in nothing.as_array().unwrap() {
        assert_eq!(row, &json!(["nothing", "nothing to add", "–"]), "{nothing}");
    }
}
