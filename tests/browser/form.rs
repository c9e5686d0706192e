//! End-to-end tests of the web form in a real headless Chromium: a whole
//! balancing job typed key by key, reopening after a reload, user text that
//! looks like HTML, errors shown at their field, and the correction without
//! the noise's pull beside the fitted one (scenes/noise.rs). Screenshots go
//! to `target/screenshots/`.

use crate::harness::form::{self, field, type_run, type_setup, value_of};
use crate::harness::stand::{example_session, get, post, stored_session_id, Stand};
use crate::harness::Browser;
use fantoccini::Locator;
use serde_json::{json, Value};

/// Solve from the runs step and compare the corrections on the page with the expected ones.
async fn solve_and_compare(b: &Browser, expected: &Value) {
    b.click("#step-runs button.go-solve").await;
    solve_and_compare_here(b, expected).await;
}

/// Solve on the corrections step and compare.
async fn solve_and_compare_here(b: &Browser, expected: &Value) {
    b.click("#step-solve button.solve").await;
    b.wait_until(
        "the solve answers",
        "return !!document.querySelector('#step-solve table.corrections') && !document.querySelector('#step-solve .trim')",
    )
    .await;
    let shown = form::corrections_on_page(b).await;
    let expected = expected["corrections"]
        .as_array()
        .expect("expected corrections");
    assert_eq!(shown.len(), expected.len(), "corrections shown: {shown:?}");
    for (want, (plane, mass, angle)) in expected.iter().zip(&shown) {
        assert_eq!(want["plane"].as_str(), Some(plane.as_str()));
        // The page rounds to 0.1 g and 0.1°.
        let want_mass = want["mass_g"].as_f64().unwrap();
        assert!(
            (mass - want_mass).abs() <= 0.051,
            "{plane}: {mass} g shown, {want_mass} g expected"
        );
        let want_angle = want["angle_deg"].as_f64().unwrap();
        let diff = (angle - want_angle).rem_euclid(360.0);
        assert!(
            diff.min(360.0 - diff) <= 0.051,
            "{plane}: {angle}° shown, {want_angle}° expected"
        );
    }
}

/// The page's "mass ± g, angle ± °" and 95 % bounds, against the service's own solve of the session.
async fn uncertainty_as_the_service_gives_it(b: &Browser, stand: &Stand, session: &Value) {
    let solution = post(stand, "/api/v1/solve", json!({ "session": session })).await;
    let c = &solution["corrections"][0];
    let u = &c["uncertainty"];
    let (m, a) = (
        c["mass_g"].as_f64().unwrap(),
        c["angle_deg"].as_f64().unwrap(),
    );
    let dm = (u["mass_g"][1].as_f64().unwrap() - m).max(m - u["mass_g"][0].as_f64().unwrap());
    let arc = |x: f64, y: f64| {
        let d = (x - y).rem_euclid(360.0);
        d.min(360.0 - d)
    };
    let da = arc(u["angle_deg"][1].as_f64().unwrap(), a)
        .max(arc(a, u["angle_deg"][0].as_f64().unwrap()));
    // One decimal is the page's rounding for values from 1 to 100.
    assert!(
        (1.0..100.0).contains(&dm) && (1.0..100.0).contains(&da),
        "{u}"
    );
    let want = format!(
        "{m:.1} g ± {dm:.1} g, {:.1}° ± {da:.1}°",
        a.rem_euclid(360.0)
    );
    let shown = b
        .text("#step-solve tr[data-plane=\"inboard\"] .corr-uncertainty")
        .await;
    assert_eq!(shown, want);
    let bound = solution["predicted_residual"][0]["amplitude_95"]
        .as_f64()
        .unwrap();
    assert_eq!(
        b.text("#step-solve table.residual td.after95").await,
        format!("≤ {bound:.1}")
    );
}

/// One browser for every scene of this binary (CI time); each scene gets a
/// new server and database and a freshly loaded form (`Stand::renew`).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_job_typed_into_the_form_is_solved_stored_reopened_and_shown_safely() {
    let mut stand = Stand::start().await;
    typing_the_two_plane_pump_example_key_by_key_gives_its_corrections(&stand).await;
    stand.renew().await;
    a_trial_weight_left_in_place_is_carried_into_the_next_run_by_one_tick(&stand).await;
    stand.renew().await;
    a_stored_session_reopens_after_a_reload(&stand).await;
    stand.renew().await;
    a_session_named_like_html_is_shown_as_text_and_runs_nothing(&stand).await;
    stand.renew().await;
    crate::scenes::noise::the_noise_pull_is_shown_beside_the_fitted_weight_only_when_the_noise_is_stated(
        &stand,
    )
    .await;
    stand.stop().await;
}

async fn typing_the_two_plane_pump_example_key_by_key_gives_its_corrections(stand: &Stand) {
    let b = &stand.browser;
    let (session, expected) = example_session("pump-two-plane-exact.json");
    type_setup(b, &session).await;
    b.viewport(1280, 800).await;
    b.client
        .execute("window.scrollTo(0, 0)", vec![])
        .await
        .expect("scrolls");
    b.screenshot("setup-1280").await;
    b.client
        .execute(
            "document.querySelector('fieldset.planes').scrollIntoView()",
            vec![],
        )
        .await
        .expect("scrolls");
    crate::harness::job::shots(b, "setup-planes").await;
    b.viewport(768, 1024).await;
    b.client
        .execute("window.scrollTo(0, 0)", vec![])
        .await
        .expect("scrolls");
    b.screenshot("setup-768").await;
    b.viewport(1280, 800).await;
    b.click("#step-setup button.next").await;
    for k in 0..session["runs"].as_array().unwrap().len() {
        type_run(b, &session, k, false).await;
    }
    b.screenshot("runs-1280").await;
    b.viewport(768, 1024).await;
    b.screenshot("runs-768").await;
    b.viewport(1280, 800).await;
    solve_and_compare(b, &expected).await;
    uncertainty_as_the_service_gives_it(b, stand, &session).await;
    b.screenshot("solution-1280").await;
    b.client
        .execute("document.querySelector('.plots').scrollIntoView()", vec![])
        .await
        .expect("scrolls");
    crate::harness::job::shots(b, "solution-plots").await;
    b.viewport(768, 1024).await;
    b.client
        .execute("window.scrollTo(0, 0)", vec![])
        .await
        .expect("scrolls");
    b.screenshot("solution-768").await;
    b.client
        .find(Locator::Css("nav [data-step=\"report\"]"))
        .await
        .unwrap()
        .click()
        .await
        .unwrap();
    let title = b.text(".report-title").await;
    assert!(
        title.contains("pump-two-plane-exact"),
        "report title: {title}"
    );
    crate::harness::job::shots(b, "report").await;
    // On paper only the report shows: no navigation, no print button.
    b.emulate_print(true).await;
    let shown = b
        .client
        .execute(
            "return ['nav.steps', 'header.top', '#step-report .print', '#step-report article']\
               .map((css) => document.querySelector(css).getClientRects().length > 0)",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(shown, json!([false, false, false, true]));
    b.viewport(1280, 800).await;
    b.screenshot("report-print-1280").await;
    b.emulate_print(false).await;

    // The check run starts with the corrections as its weights; readings at the
    // predicted residual (zero for exact data) leave the corrections unchanged.
    b.viewport(1280, 800).await;
    b.click("nav [data-step=\"solve\"]").await;
    b.click("#step-solve button.check-run").await;
    assert_eq!(value_of(b, &field("runs[3].weights[0].mass_g")).await, "30");
    assert_eq!(
        value_of(b, &field("runs[3].weights[0].angle_deg")).await,
        "255"
    );
    assert_eq!(value_of(b, &field("runs[3].weights[1].mass_g")).await, "22");
    assert_eq!(
        value_of(b, &field("runs[3].weights[1].angle_deg")).await,
        "120"
    );
    form::type_cells_with_tab(b, 3, &vec!["0".to_string(); 8]).await;
    b.client
        .execute("window.scrollTo(0, 0)", vec![])
        .await
        .expect("scrolls");
    crate::harness::job::shots(b, "runs-check-entry").await;
    form::store(b).await;
    // After the check run the solve starts from it: nothing to add, and the
    // one weight per plane that replaces what is on is the first answer.
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    for want in expected["corrections"].as_array().unwrap() {
        let plane = want["plane"].as_str().unwrap();
        let words = b.text(&format!(".trim li[data-plane=\"{plane}\"]")).await;
        let total = format!(
            "one weight of {:.1} g at {:.1}°",
            want["mass_g"].as_f64().unwrap(),
            want["angle_deg"].as_f64().unwrap().rem_euclid(360.0)
        );
        assert!(
            words.contains("nothing to add") && words.contains(&total),
            "{words}"
        );
    }
    // Corrected from the zero run instead, the first answer again.
    b.click("details.options summary").await;
    form::choose(b, "#step-solve select.from-run", "").await;
    solve_and_compare_here(b, &expected).await;
}

async fn a_trial_weight_left_in_place_is_carried_into_the_next_run_by_one_tick(stand: &Stand) {
    let b = &stand.browser;
    let (session, expected) = example_session("pump-two-plane-kept-trial-exact.json");
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;
    for k in 0..session["runs"].as_array().unwrap().len() {
        type_run(b, &session, k, true).await;
    }
    // The stored run lists both weights although only the second was typed.
    let id = stored_session_id(stand).await;
    let got = get(stand, &format!("/api/v1/sessions/{id}")).await;
    assert_eq!(got["runs"][2]["weights"], session["runs"][2]["weights"]);
    solve_and_compare(b, &expected).await;
}

async fn a_stored_session_reopens_after_a_reload(stand: &Stand) {
    let b = &stand.browser;
    let (session, expected) = example_session("pump-two-plane-exact.json");
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;
    type_run(b, &session, 0, false).await;
    type_run(b, &session, 1, false).await;

    // A reload keeps the session (its id is in the address).
    b.client.refresh().await.expect("reloads");
    b.wait_for("#step-runs td.value.amp").await;
    let amps: Vec<String> = {
        let mut out = Vec::new();
        for el in b
            .client
            .find_all(Locator::Css("#step-runs td.value.amp"))
            .await
            .unwrap()
        {
            out.push(el.text().await.unwrap());
        }
        out
    };
    assert_eq!(amps.len(), 8, "two runs × four sensors: {amps:?}");
    // What was typed (465.37419496698874), to six significant digits.
    assert_eq!(amps[0], "465.374", "zero run, DE-H");
    assert_eq!(amps[1], "1073.16", "trial inboard, DE-H");

    // A fresh start at `/` lists it; opening it restores set-up and runs.
    b.client.goto(&stand.server.url("/")).await.unwrap();
    b.click("nav [data-step=\"sessions\"]").await;
    b.wait_for("button.open-session").await;
    crate::harness::job::shots(b, "sessions").await;
    b.click("button.open-session").await;
    b.wait_for("#step-runs td.value.amp").await;
    assert_eq!(b.text("#job-title").await, "pump-two-plane-exact · stored");
    b.click("nav [data-step=\"setup\"]").await;
    assert_eq!(value_of(b, &field("planes[1].id")).await, "outboard");
    assert_eq!(value_of(b, &field("planes[1].radius_mm")).await, "160");
    assert_eq!(value_of(b, &field("sensors[3].id")).await, "NDE-V");
    assert_eq!(value_of(b, &field("speeds")).await, "2950");
    b.click("#step-setup button.next").await;
    // The job goes on where it stopped.
    type_run(b, &session, 2, false).await;
    solve_and_compare(b, &expected).await;
}

async fn a_session_named_like_html_is_shown_as_text_and_runs_nothing(stand: &Stand) {
    let b = &stand.browser;
    let name = "<img src=x onerror=alert(1)>";
    let (mut session, _) = example_session("pump-single-plane-noisy.json");
    session["name"] = json!(name);
    session["sensors"][0]["label"] = json!("<b>bold</b>");
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;
    type_run(b, &session, 0, false).await;
    b.click("nav [data-step=\"sessions\"]").await;
    b.wait_for("button.open-session").await;
    assert_eq!(b.text("button.open-session").await, name);
    assert_eq!(b.text("#job-title").await, format!("{name} · stored"));
    b.click("nav [data-step=\"report\"]").await;
    assert_eq!(
        b.text(".report-title").await,
        format!("Balancing report — {name}")
    );
    // Had the name been parsed as HTML anywhere, there would be an <img> or a <b>.
    let parsed = b
        .client
        .execute("return document.querySelectorAll('img, b').length", vec![])
        .await
        .unwrap();
    assert_eq!(parsed, json!(0));
    assert!(b.client.get_alert_text().await.is_err(), "an alert is open");
}
