//! Every angle the answer and the report show says its convention. The pump
//! job (phase lead, weight angles with rotation) with a check run fitted
//! short of the correction: the trim's "add 4.1 g at 255.0°, or replace …
//! by one weight of … at …°" came above the table whose header says the
//! direction, without it; the report's tables of weights to fit, weights,
//! readings and coefficients headed their columns "Angle" and "Phase, °"
//! only; the suggested trial weight ("20.0 g at 0.0°") said neither; nor
//! did each run's weights ("inboard: 30.0 g at 0.0°") in the runs grid, the
//! report's runs table and the readings CSV.

use serde_json::{json, Value};

use crate::harness::job::predicted;
use crate::harness::stand::{example_session, open_at_solve, post, Stand};
use crate::harness::steps::{js, named};

/// Header cells under `css` that speak of an angle or a phase but say no convention.
async fn headers_without_convention(b: &crate::harness::Browser, css: &str) -> Value {
    js(
        b,
        &format!(
            "return [...document.querySelectorAll('{css} th')].map((t) => t.textContent) \
               .filter((t) => /angle|phase/i.test(t) && !/\\b(lag|lead|with rotation|against rotation)\\b/.test(t))"
        ),
    )
    .await
}

/// `session` with a check run "check 1" fitted with 80 % of each correction
/// the service gives, so that a trim is left to add.
pub async fn with_a_check_run(stand: &Stand, mut session: Value) -> Value {
    let url = stand.server.url("");
    let url = url.trim_end_matches('/');
    let free = post(
        stand,
        "/api/v1/solve",
        json!({ "session": session.clone() }),
    )
    .await;
    let on: Vec<Value> = free["corrections"]
        .as_array()
        .unwrap_or_else(|| panic!("{free}"))
        .iter()
        .map(|c| json!({ "plane": c["plane"], "mass_g": (c["mass_g"].as_f64().unwrap() * 8.0).round() / 10.0, "angle_deg": (c["angle_deg"].as_f64().unwrap() * 10.0).round() / 10.0 }))
        .collect();
    let mut check = named(predicted(url, &session, &json!(on)).await, "check 1");
    check["purpose"] = json!("check");
    session["runs"].as_array_mut().unwrap().push(check);
    session
}

pub async fn every_angle_of_the_answer_and_report_says_its_convention(stand: &Stand) {
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    assert_eq!(session["conventions"]["angle_direction"], "with_rotation");
    assert_eq!(session["conventions"]["phase"], "lead");
    let session = with_a_check_run(stand, session).await;
    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .trim li").await;
    let trim = b.text("#step-solve .trim h3").await;
    assert!(trim.contains("with rotation"), "{trim}");
    let bare = headers_without_convention(b, "#step-solve").await;
    assert_eq!(bare, json!([]), "at the answer");

    b.click("nav [data-step=\"report\"]").await;
    b.wait_for("#step-report article.report .report-runs").await;
    let trim = b.text("#step-report .trim h3").await;
    assert!(trim.contains("with rotation"), "{trim}");
    let bare = headers_without_convention(b, "#step-report").await;
    assert_eq!(bare, json!([]), "in the report");

    // The runs: each run's weights in the grid's headers, in the report and
    // in the readings CSV.
    let weights_header: serde_json::Value = js(
        b,
        "return [...document.querySelectorAll('#step-report th')].map((t) => t.textContent).filter((t) => /^Weights/.test(t))",
    )
    .await;
    assert_eq!(weights_header, json!(["Weights (angles with rotation)"]));
    let csv = crate::harness::steps::js_async(
        b,
        "const [done] = arguments; import('/static/js/steps/sessions.js').then((m) => done(m.readingsCsv()));",
    )
    .await;
    let header = csv.as_str().unwrap().lines().next().unwrap().to_string();
    assert!(
        header.starts_with("\"run\",\"weights (angles with_rotation)\","),
        "{header}"
    );
    b.click("nav [data-step=\"runs\"]").await;
    let caption = b.text("#step-runs table.grid caption").await;
    assert_eq!(
        caption,
        "Weight angles with rotation from the mark; phases lead."
    );

    // A new job's suggested trial weight, from the rotor's data.
    let (mut fresh, _) = example_session("pump-two-plane-exact.json");
    fresh["name"] = json!("pump, first trial");
    fresh["runs"] = json!([fresh["runs"][0].clone()]);
    fresh["rotor"] = json!({ "mass_kg": 400, "service_speed_rpm": 2950, "balance_grade": "G2.5" });
    let created = post(stand, "/api/v1/sessions", fresh).await;
    let id = created["id"].as_str().expect("stored").to_string();
    b.open_fresh(&stand.server.url(&format!("/#session={id}&step=runs")))
        .await;
    b.click("#step-runs button.add-trial").await;
    b.wait_for("#step-runs .suggestion li").await;
    let said = b.text("#step-runs .suggestion h4").await;
    assert!(said.contains("with rotation"), "{said}");
}
