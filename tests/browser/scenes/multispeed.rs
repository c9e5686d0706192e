//! The multi-speed job's plots beyond their count: the polar plots' filter
//! narrows them as chosen, and a check run is drawn on every Bode plot beside
//! the as-found and predicted curves.

use serde_json::{json, Value};

use crate::harness::form::choose;
use crate::harness::job::{predicted, shots};
use crate::harness::stand::{open_at_solve, post, Stand};
use crate::harness::steps::js;
use crate::harness::Browser;

async fn polar_count(b: &Browser) -> Value {
    js(
        b,
        "return document.querySelectorAll('#step-solve svg.polar').length",
    )
    .await
}

/// (Item 3) The filter shows one sensor's plots, or every speed's, as chosen.
pub async fn polar_filter_narrows_the_plots(b: &Browser, session: &Value) {
    let sensors = session["sensors"].as_array().unwrap();
    let speeds = crate::harness::form::speeds(session);
    // Many plots: one speed at a time to begin with, every sensor.
    assert_eq!(polar_count(b).await, json!(sensors.len()));
    let first = sensors[0]["id"].as_str().unwrap();
    choose(b, "#step-solve select.filter-sensor", first).await;
    assert_eq!(polar_count(b).await, json!(1), "one sensor at one speed");
    choose(b, "#step-solve select.filter-speed", "").await;
    assert_eq!(
        polar_count(b).await,
        json!(speeds.len()),
        "one sensor at every speed"
    );
    let titles = js(
        b,
        "return [...document.querySelectorAll('#step-solve .polar-fig figcaption')].map((f) => f.textContent)",
    )
    .await;
    assert!(
        titles
            .as_array()
            .unwrap()
            .iter()
            .all(|t| t.as_str().unwrap().starts_with(&format!("{first} at "))),
        "{titles}"
    );
    choose(b, "#step-solve select.filter-sensor", "").await;
    choose(
        b,
        "#step-solve select.filter-speed",
        &format!("{}", speeds[0]),
    )
    .await;
    assert_eq!(polar_count(b).await, json!(sensors.len()));
}

/// (Item 3) A check run with lighter corrections on, stored through the API and
/// read back by a fresh page: each Bode plot draws it as a third curve.
pub async fn a_check_run_is_drawn_on_each_bode_plot(stand: &Stand, id: &str, session: &Value) {
    let b = &stand.browser;
    let url = stand.server.url("");
    let url = url.trim_end_matches('/');
    let solution = post(stand, "/api/v1/solve", json!({ "session": session })).await;
    let weights: Vec<Value> = solution["corrections"]
        .as_array()
        .unwrap()
        .iter()
        // The fitter had lighter weights than asked for: the check run differs from the prediction.
        .map(|c| json!({ "plane": c["plane"], "mass_g": 0.8 * c["mass_g"].as_f64().unwrap(), "angle_deg": c["angle_deg"] }))
        .collect();
    let mut check = predicted(url, session, &json!(weights)).await;
    // Named as a technician might: a check run is known by when it was
    // recorded (after every plane's trial), not by its name.
    check["id"] = json!("after balancing");
    let stored = reqwest::Client::new()
        .post(format!("{url}/api/v1/sessions/{id}/runs"))
        .json(&check)
        .send()
        .await
        .unwrap();
    assert!(
        stored.status().is_success(),
        "{}",
        stored.text().await.unwrap()
    );
    open_at_solve(stand, id).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve svg.bode").await;
    let got = js(
        b,
        "return [...document.querySelectorAll('#step-solve .bode-fig')].map((f) => \
           [f.querySelectorAll('svg.bode path.series').length, [...f.querySelectorAll('.legend li')].map((l) => l.textContent)])",
    )
    .await;
    let sensors = session["sensors"].as_array().unwrap().len();
    assert_eq!(got.as_array().unwrap().len(), sensors, "{got}");
    for fig in got.as_array().unwrap() {
        assert_eq!(
            fig[1],
            json!([
                "as found",
                "predicted after correction",
                "check run “after balancing”"
            ]),
            "{got}"
        );
        assert!(fig[0].as_u64().unwrap() >= 3, "three curves: {got}");
    }
    crate::harness::job::scroll_to(b, ".bode-plots").await;
    shots(b, "job-bode-check-run").await;
}
