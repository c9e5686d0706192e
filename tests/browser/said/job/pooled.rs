//! Coefficients pooled from jobs that disagree say so on the machine page.
//! Machine PUMP-1 with two solved jobs whose inboard trials moved the
//! rotor differently (the second's readings half as large again): the
//! service pools them with the warning `coefficients_disagree` naming both.
//! The form stored the version and showed the page again as if all were
//! well; a trim job from those coefficients then started from them unwarned.
//! The table of coefficient versions gave only how many jobs a version was
//! pooled from ("2"): it now names them, so that the jobs the warning names
//! can be told to be those of the version.

use serde_json::{json, Value};

use crate::harness::stand::{example_session, get, post, Stand};
use crate::harness::steps::js;

async fn solved_job(stand: &Stand, name: &str, session: &Value) -> String {
    let mut session = session.clone();
    session["name"] = json!(name);
    session["machine"] = json!("PUMP-1");
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    post(
        stand,
        &format!("/api/v1/sessions/{id}/solutions"),
        json!({}),
    )
    .await;
    id
}

pub async fn coefficients_from_jobs_that_disagree_say_so(stand: &Stand) {
    let b = &stand.browser;
    post(
        stand,
        "/api/v1/machines",
        json!({"id": "PUMP-1", "name": "pump"}),
    )
    .await;
    let (session, _) = example_session("pump-two-plane-exact.json");
    solved_job(stand, "pump in March", &session).await;
    let mut changed = session.clone();
    for r in changed["runs"][1]["readings"].as_array_mut().unwrap() {
        r["amplitude"] = json!(r["amplitude"].as_f64().unwrap() * 1.5);
    }
    solved_job(stand, "pump in June", &changed).await;

    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.click("#step-machines button.pool").await;
    b.wait_for("#step-machines .pool-warnings li").await;
    let stored = get(stand, "/api/v1/machines/PUMP-1/coefficients").await;
    let warning = &stored["warnings"][0];
    assert_eq!(warning["code"], "coefficients_disagree", "{stored}");
    let shown: Value = js(
        b,
        "return [...document.querySelectorAll('#step-machines .pool-warnings li')].map((li) => [li.dataset.code, li.textContent, (li.querySelector('.said-text') || {}).textContent || null])",
    )
    .await;
    assert_eq!(shown[0][0], "coefficients_disagree", "{shown}");
    let words = shown[0][1].as_str().unwrap();
    assert!(
        words.contains("“pump in March”") && words.contains("“pump in June”"),
        "the jobs by their names: {words}"
    );
    assert_eq!(shown[0][2], warning["message"], "{shown}");
    let heading = b.text("#step-machines .pool-warnings h4").await;
    assert!(heading.contains("version 1"), "{heading}");
    let version: Value = js(
        b,
        "return [...document.querySelectorAll('#step-machines table.coeff-versions tbody tr td')].map((td) => td.textContent)",
    )
    .await;
    assert_eq!(version[0], "1", "{version}");
    assert_eq!(
        version[2], "2: “pump in March”, “pump in June”",
        "the jobs it was pooled from, by name: {version}"
    );
}
