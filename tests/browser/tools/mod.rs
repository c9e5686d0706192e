//! The stand-alone pages, free decay and residual check, as a technician at
//! the stand uses them: what was typed there survives a reload of the page
//! (it lived only in the page's module, while the job's steps keep their
//! drafts in this browser's storage: a reload lost a pasted record) and is
//! sent as it was typed; "Start over" asks first, then empties the page for
//! good, a reload bringing nothing back. Both pages at 1280 and 768 wide
//! (screenshots), and at 768 no target under 44 px and no sideways scroll.
//! What a spreadsheet copies is read as meant: a heading over the column is
//! passed over (it was refused as "not a number"), degree signs after the
//! residual check's angles too, and a time column copied beside the decay's
//! samples is refused at the field (it was read into the samples, times
//! and samples alternating, and fitted).

mod decay;
pub(crate) mod residual;

use serde_json::Value;

use crate::harness::stand::Stand;
use crate::harness::steps::js;
use crate::harness::Browser;

/// One browser for both pages and both checks (CI time); each scene gets a
/// new server and a freshly loaded form (`Stand::renew`), so nothing is
/// kept from the one before: what was typed survives a reload and is sent
/// as typed, and pasted columns are read as meant.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_stand_alone_pages_keep_what_was_typed_and_read_what_was_pasted() {
    let mut stand = Stand::start().await;
    decay::what_was_typed_survives_a_reload_and_is_sent_as_typed(&stand).await;
    stand.renew().await;
    residual::what_was_typed_survives_a_reload_and_is_sent_as_typed(&stand).await;
    stand.renew().await;
    decay::a_heading_is_passed_over_and_a_time_column_refused(&stand).await;
    stand.renew().await;
    residual::a_heading_and_degree_signs_are_passed_over(&stand).await;
    stand.stop().await;
}

/// Paste `text` into the textarea `css` as the browser does (a spreadsheet's
/// tabs cannot be typed: a typed Tab moves the focus): the value, then `input`.
async fn paste(b: &Browser, css: &str, text: &str) {
    js(
        b,
        &format!(
            "const t = document.querySelector({}); t.value = {}; t.dispatchEvent(new Event('input', {{ bubbles: true }})); return null",
            serde_json::to_string(css).unwrap(),
            serde_json::to_string(text).unwrap()
        ),
    )
    .await;
}

/// What `function` of the page's module `module` (under /static/js/) gives for each of `inputs`.
async fn parsed(b: &Browser, module: &str, function: &str, inputs: &[&str]) -> Vec<Value> {
    let got = crate::harness::steps::js_async(
        b,
        &format!(
            "const [done] = arguments; import('/static/js/{module}').then((m) => done({}.map((t) => m.{function}(t))));",
            serde_json::to_string(inputs).unwrap()
        ),
    )
    .await;
    got.as_array().expect("a list").clone()
}

/// The message at the field `css` (empty when it is not marked).
async fn message_at(b: &Browser, css: &str) -> String {
    let got = js(
        b,
        &format!(
            "const f = document.querySelector({}).closest('.field'); return f.classList.contains('bad') ? f.querySelector('.msg').textContent : ''",
            serde_json::to_string(css).unwrap()
        ),
    )
    .await;
    got.as_str().unwrap_or_default().to_string()
}

/// Whether the answer shown on `#step-{step}` is greyed as the answer to what
/// was typed before a change, and says so; `None` when no answer is shown.
async fn stale(b: &Browser, step: &str) -> Option<bool> {
    let got = js(
        b,
        &format!(
            "const o = document.querySelector('#step-{step} .{step}-out'); const h = o && o.querySelector('h3'); \
             if (!h) return null; \
             const said = getComputedStyle(h, '::after').content.includes('before your last change'); \
             const grey = Number(getComputedStyle(o).opacity) < 1; \
             return o.classList.contains('stale') && said && grey ? true : !o.classList.contains('stale') && !said && !grey ? false : 'mixed'"
        ),
    )
    .await;
    match got {
        Value::Null => None,
        Value::Bool(x) => Some(x),
        other => panic!("the {step} answer is half greyed: {other}"),
    }
}

/// Reload the page and wait until `step` is shown again (the address keeps it).
async fn reload(b: &Browser, step: &str) {
    b.client.refresh().await.expect("the page reloads");
    b.wait_until(
        &format!("the {step} page is back after the reload"),
        &format!(
            "const s = document.querySelector('#step-{step}'); return !!s && !s.hidden && !!s.querySelector('form')"
        ),
    )
    .await;
}

/// Record the body of every request the page sends from now on (until it is reloaded).
async fn record_requests(b: &Browser) {
    js(
        b,
        "window.sentBodies = []; const f = window.fetch; \
         window.fetch = (url, init) => { if (init && init.body) window.sentBodies.push({ url: String(url), body: JSON.parse(init.body) }); return f(url, init); }; \
         return true",
    )
    .await;
}

/// The bodies the page sent to a URL ending in `path` since `record_requests`.
async fn sent_to(b: &Browser, path: &str) -> Vec<Value> {
    let got = js(
        b,
        &format!(
            "return window.sentBodies.filter((x) => x.url.endsWith({})).map((x) => x.body)",
            serde_json::to_string(path).unwrap()
        ),
    )
    .await;
    got.as_array().expect("a list").clone()
}

/// Press `button` in `#step-{step}` and wait until `result` (a selector) is
/// one drawn after the press (the one shown before is marked first).
async fn press_and_wait(b: &Browser, step: &str, button: &str, result: &str) {
    let css = format!("#step-{step} {result}");
    js(
        b,
        &format!(
            "const r = document.querySelector({}); if (r) r.dataset.old = 'yes'; return true",
            serde_json::to_string(&css).unwrap()
        ),
    )
    .await;
    b.click(&format!("#step-{step} {button}")).await;
    b.wait_until(
        "a new answer is shown",
        &format!(
            "const r = document.querySelector({}); return !!r && r.dataset.old !== 'yes'",
            serde_json::to_string(&css).unwrap()
        ),
    )
    .await;
}

/// The value of each field of `#step-{step}` named in `fields` (`data-field`).
async fn values(b: &Browser, step: &str, fields: &[&str]) -> Vec<String> {
    let got = js(
        b,
        &format!(
            "return {}.map((f) => {{ const e = document.querySelector(`#step-{step} [data-field=\"${{f}}\"]`); return e ? e.value : null; }})",
            serde_json::to_string(fields).unwrap()
        ),
    )
    .await;
    got.as_array()
        .expect("a list")
        .iter()
        .map(|v| {
            v.as_str()
                .unwrap_or_else(|| panic!("a field of {fields:?} is missing: {got}"))
                .to_string()
        })
        .collect()
}

/// The text the page shows as its answer, or "" when it shows none.
async fn answer_text(b: &Browser, css: &str) -> String {
    let got = js(
        b,
        &format!(
            "const r = document.querySelector({}); return r ? r.innerText : ''",
            serde_json::to_string(css).unwrap()
        ),
    )
    .await;
    got.as_str().unwrap_or_default().to_string()
}

/// "Start over" asks first: dismissed, the page keeps what was typed (checked
/// by the caller); accepted, every field is empty or back at its default, no
/// answer is shown, and a reload brings nothing back.
async fn start_over(b: &Browser, step: &str) -> String {
    let button = format!("#step-{step} button.start-over");
    b.click(&button).await;
    let asked = crate::newuser::confirmation(b).await;
    b.client.dismiss_alert().await.unwrap();
    asked
}

/// Press "Start over" and accept its question.
async fn start_over_accepted(b: &Browser, step: &str) {
    b.click(&format!("#step-{step} button.start-over")).await;
    crate::newuser::confirmation(b).await;
    b.client.accept_alert().await.unwrap();
}

/// The page's note says that what is typed is kept in this browser only:
/// "nothing is stored on the service" (it said "nothing is stored").
async fn says_nothing_is_stored_on_the_service(b: &Browser, step: &str) {
    let note = js(
        b,
        &format!("return document.querySelector('#step-{step} p.note').textContent"),
    )
    .await;
    assert!(
        note.as_str()
            .unwrap()
            .to_lowercase()
            .contains("nothing is stored on the service."),
        "{note}"
    );
}

/// Start over on `step`: the question names `word` and "no" keeps the
/// `fields` as they were (`kept`); "yes" leaves them `emptied` and no answer
/// at `answer`, and a reload brings nothing back.
async fn starts_over(
    b: &Browser,
    step: &str,
    fields: &[&str],
    kept: &[String],
    word: &str,
    emptied: &[&str],
    answer: &str,
) {
    let asked = start_over(b, step).await;
    assert!(asked.contains(word), "{asked}");
    assert_eq!(values(b, step, fields).await, kept);
    start_over_accepted(b, step).await;
    assert_eq!(values(b, step, fields).await, emptied);
    assert_eq!(answer_text(b, answer).await, "");
    reload(b, step).await;
    assert_eq!(
        values(b, step, fields).await,
        emptied,
        "nothing comes back after starting over"
    );
    assert_eq!(answer_text(b, answer).await, "");
}
