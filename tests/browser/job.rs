//! A whole job at the stand in a real headless Chromium, typed key by key: the
//! rules that stop silent mistakes (speed lists, phases, decimal commas), a
//! reload before and during a run, Back/Forward between steps, a second trial
//! in a tried plane questioned, the three-stage trim loop (each check run
//! beside its prediction) until within tolerance, the printed report with the
//! answer on its first page, two tabs on one session, the machine page with a
//! trim from stored coefficients and a CSV import, a multi-speed job's Bode
//! plots and each solve option reaching the request, a second job for the
//! machine with rotor data, fixed places and kits (the trial weight suggested,
//! the kit fit drawn per plane), touch targets and page weight. One browser and one server for all
//! (CI time); screenshots of every step at 1280 and 768 wide go to
//! `target/screenshots/`.

use crate::harness::form::{self, field, type_into, type_run, type_setup, value_of};
use crate::harness::job::{message_for, predicted, scroll_to, shots};
use crate::harness::stand::{example_session, get, Stand};
use crate::harness::steps::{
    a_plane_the_trim_leaves_shows_nothing_to_add, fits_a_tablet,
    grid_header_and_actions_are_sticky, js, named, service_trim, solve, stored_id,
    summary_follows_the_doubts, type_and_store, typed_mistakes_are_refused_with_the_reason,
};
use crate::scenes::kit::new_job_with_rotor_places_and_kits;
use crate::scenes::{
    machine_page_and_trim_from_stored_coefficients, multi_speed_job_shows_bode_plots,
    the_form_weighs_little_and_asks_nothing_of_other_hosts,
};
use serde_json::json;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_whole_job_runs_in_the_browser_from_set_up_to_a_signed_report() {
    let stand = Stand::start().await;
    let b = &stand.browser;
    let url = stand.server.url("");
    let url = url.trim_end_matches('/');
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    session["machine"] = json!("PUMP-1");
    let truth = session.clone();

    // (a) Rules, then the set-up typed and kept across a reload before any run is stored.
    typed_mistakes_are_refused_with_the_reason(b).await;
    type_setup(b, &session).await;
    shots(b, "job-setup").await;
    fits_a_tablet(b, "set-up").await;
    b.client.refresh().await.unwrap();
    b.wait_for(&field("name")).await;
    assert_eq!(
        value_of(b, &field("name")).await,
        "pump-two-plane-exact",
        "the set-up survives a reload"
    );
    assert_eq!(value_of(b, &field("planes[1].radius_mm")).await, "160");
    assert_eq!(value_of(b, &field("speeds")).await, "2950");
    b.click("#step-setup button.next").await;
    let phase = field("runs[0].readings[0].phase_deg");
    let refused = message_for(b, &phase, "370").await;
    assert!(refused.contains("the same place as 10°"), "{refused}");
    type_run(b, &session, 0, false).await;

    // A reload in the middle of a trial run keeps what was typed.
    b.click("button.add-trial").await;
    let w = &session["runs"][1]["weights"][0];
    form::choose(b, &field("runs[1].weights[0].plane"), "inboard").await;
    type_into(
        b,
        &field("runs[1].weights[0].mass_g"),
        &form::typed(&w["mass_g"]),
    )
    .await;
    type_into(
        b,
        &field("runs[1].weights[0].angle_deg"),
        &form::typed(&w["angle_deg"]),
    )
    .await;
    let cells = form::cells(&session, &session["runs"][1]);
    form::type_cells_with_tab(b, 1, &cells[..3]).await;
    shots(b, "job-trial-typing").await;
    b.client.refresh().await.unwrap();
    b.wait_for(&field("runs[1].readings[1].amplitude")).await;
    assert_eq!(
        value_of(b, &field("runs[1].weights[0].mass_g")).await,
        form::typed(&w["mass_g"])
    );
    assert_eq!(
        value_of(b, &field("runs[1].readings[0].amplitude")).await,
        cells[0]
    );
    assert_eq!(
        value_of(b, &field("runs[1].readings[1].amplitude")).await,
        cells[2]
    );
    type_into(b, &field("runs[1].id"), "trial inboard").await;
    // Go on from the first empty cell, Tab after Tab.
    b.click(&field("runs[1].readings[1].phase_deg")).await;
    for value in &cells[3..] {
        let active = b.client.active_element().await.unwrap();
        active.send_keys(&format!("{value}\u{e004}")).await.unwrap();
    }
    for (i, value) in cells.iter().enumerate() {
        let kind = if i % 2 == 0 { "amplitude" } else { "phase_deg" };
        let css = field(&format!("runs[1].readings[{}].{kind}", i / 2));
        assert_eq!(&value_of(b, &css).await, value, "{css}");
    }
    form::store(b).await;

    // A second trial in the plane already tried is questioned before it is stored.
    b.click("button.add-trial").await;
    let w2 = &session["runs"][2]["weights"][0];
    type_into(
        b,
        &field("runs[2].weights[0].mass_g"),
        &form::typed(&w2["mass_g"]),
    )
    .await;
    type_into(
        b,
        &field("runs[2].weights[0].angle_deg"),
        &form::typed(&w2["angle_deg"]),
    )
    .await;
    form::choose(b, &field("runs[2].weights[0].plane"), "inboard").await;
    type_into(b, &field("runs[2].id"), "trial outboard").await;
    form::type_cells_with_tab(b, 2, &form::cells(&session, &session["runs"][2])).await;
    b.click("#step-runs button.store").await;
    let question = b.text(".question").await;
    assert!(
        question.contains("Plane inboard already had a trial weight")
            && question.contains("outboard has none yet"),
        "{question}"
    );
    shots(b, "job-second-trial-question").await;
    b.click(".question button.no").await;
    form::choose(b, &field("runs[2].weights[0].plane"), "outboard").await;
    form::store(b).await;
    let id = stored_id(b).await;
    shots(b, "job-runs").await;
    grid_header_and_actions_are_sticky(b).await;
    fits_a_tablet(b, "runs").await;

    // Back and Forward move between the steps.
    solve(b).await;
    b.click("nav [data-step=\"report\"]").await;
    b.client.back().await.unwrap();
    b.wait_until(
        "Back shows the corrections",
        "return !document.querySelector('#step-solve').hidden",
    )
    .await;
    b.client.back().await.unwrap();
    b.wait_until(
        "Back again shows the runs",
        "return !document.querySelector('#step-runs').hidden",
    )
    .await;
    b.client.forward().await.unwrap();
    b.wait_until(
        "Forward shows the corrections",
        "return !document.querySelector('#step-solve').hidden",
    )
    .await;
    b.wait_for("#step-solve table.corrections").await;
    shots(b, "job-corrections").await;
    // A correction greyed for wide 95 % figures greys what it predicts too.
    summary_follows_the_doubts(b).await;
    scroll_to(b, ".plane-pics").await;
    shots(b, "job-plane-pictures").await;
    fits_a_tablet(b, "corrections").await;

    // (b) Check run 1: the fitter put 28 g at 250° instead of 30 g at 255°.
    b.click("#step-solve button.check-run").await;
    type_into(b, &field("runs[3].weights[0].mass_g"), "28").await;
    type_into(b, &field("runs[3].weights[0].angle_deg"), "250").await;
    let on = crate::harness::job::weights_in_editor(b, 3).await;
    let check = named(predicted(url, &truth, &on).await, "check");
    shots(b, "job-check-run").await;
    type_and_store(b, &session, 3, &check).await;
    solve(b).await;
    let trim = service_trim(&stand, &id, "check").await;
    let c = &trim["corrections"][0];
    let words = b.text(".trim li[data-plane=\"inboard\"]").await;
    let want = format!(
        "add {:.1} g at {:.1}° to what is on now, or replace the weights in this plane by one weight of {:.1} g at {:.1}°",
        c["mass_g"].as_f64().unwrap(),
        c["angle_deg"].as_f64().unwrap().rem_euclid(360.0),
        c["total"]["mass_g"].as_f64().unwrap(),
        c["total"]["angle_deg"].as_f64().unwrap().rem_euclid(360.0)
    );
    assert!(words.contains(&want), "{words:?} should say {want:?}");
    // The check run beside its prediction.
    b.wait_for(".run-check[data-run=\"check\"] td.predicted")
        .await;
    shots(b, "job-trim").await;
    scroll_to(b, ".run-checks").await;
    shots(b, "job-check-beside-prediction").await;

    // Check run 2 with the trim added; then within tolerance.
    b.click("#step-solve button.check-run").await;
    let on = crate::harness::job::weights_in_editor(b, 4).await;
    assert_eq!(
        on.as_array().unwrap().len(),
        3,
        "check 2 lists what is on: {on}"
    );
    let check2 = named(predicted(url, &truth, &on).await, "check 2");
    type_and_store(b, &session, 4, &check2).await;
    // Check runs carry weights but are no trials: the count is of planes tried.
    let lead = b.text("#step-runs p.lead").await;
    assert!(lead.contains("(2 of 2)"), "{lead}");
    crate::scenes::names::a_trial_after_check_runs_is_numbered_by_trials(b).await;
    b.click("#step-runs button.go-solve").await;
    b.click("details.options summary").await;
    type_into(b, &field("options.limit"), "5").await;
    shots(b, "job-options").await;
    b.click("#step-solve button.solve").await;
    let verdict = b.text(".verdict").await;
    assert!(verdict.starts_with("Within tolerance"), "{verdict}");
    a_plane_the_trim_leaves_shows_nothing_to_add(b).await;
    // Sure or greyed, the summary follows the corrections (both cases fixed: import.rs).
    summary_follows_the_doubts(b).await;
    shots(b, "job-within-tolerance").await;

    // (g) The report: the answer on its first page, then what ISO 21940-13 asks.
    b.click("nav [data-step=\"report\"]").await;
    type_into(b, "input.report-reason", "1X alarm after impeller repair").await;
    type_into(b, "input.report-by", "A. Fitter").await;
    // The reason and the signer are kept across a reload, as the runs are.
    b.client.refresh().await.unwrap();
    b.wait_for("input.report-reason").await;
    b.wait_until(
        "the report step is back",
        "return !document.querySelector('#step-report').hidden",
    )
    .await;
    assert_eq!(
        value_of(b, "input.report-reason").await,
        "1X alarm after impeller repair"
    );
    assert_eq!(value_of(b, "input.report-by").await, "A. Fitter");
    b.wait_for("#step-report .verdict").await;
    shots(b, "job-report").await;
    fits_a_tablet(b, "report").await;
    b.emulate_print(true).await;
    b.viewport(794, 1123).await;
    let layout = js(
        b,
        "const art = document.querySelector('article.report'); const a = art.querySelector('section'); \
         return [a.className, a.getBoundingClientRect().bottom - art.getBoundingClientRect().top, \
                 getComputedStyle(a).breakAfter, art.innerText]",
    )
    .await;
    assert_eq!(
        layout[0], "report-answer",
        "the answer is the report's first section"
    );
    assert!(
        layout[1].as_f64().unwrap() < 1000.0,
        "the answer fits the first A4 page: {}",
        layout[1]
    );
    assert_eq!(layout[2], "page");
    let text = layout[3].as_str().unwrap();
    for needed in [
        "Machine: PUMP-1",
        "1X alarm after impeller repair",
        "Within tolerance",
        "Phase reference",
        "phase lead, weight angles with rotation",
        "µm pk-pk",
        "Trial and correction weights",
        "Influence coefficients used",
        "Balanced by: A. Fitter",
        "Accepted for the customer",
    ] {
        assert!(text.contains(needed), "the printed report lacks {needed:?}");
    }
    let plots = js(
        b,
        "return document.querySelectorAll('article.report .report-plots svg').length",
    )
    .await;
    assert!(plots.as_u64().unwrap() >= 3, "plots in the report: {plots}");
    b.screenshot("job-report-print-794").await;
    b.emulate_print(false).await;
    b.viewport(1280, 800).await;

    // (a) Two tabs on one session: the second stores, the first is told, nothing lost.
    b.click("nav [data-step=\"runs\"]").await;
    b.click("#step-runs th.run[data-run=\"trial inboard\"] button.correct")
        .await;
    let first = b.client.window().await.unwrap();
    let second = b.client.new_window(true).await.unwrap().handle;
    b.client.switch_to_window(second.clone()).await.unwrap();
    b.client
        .goto(&stand.server.url(&format!("/#session={id}&step=runs")))
        .await
        .unwrap();
    b.click("#step-runs th.run[data-run=\"trial inboard\"] button.correct")
        .await;
    type_into(b, &field("runs[1].readings[0].amplitude"), "1074").await;
    form::store(b).await;
    b.client.close_window().await.unwrap();
    b.client.switch_to_window(first).await.unwrap();
    type_into(b, &field("runs[1].readings[0].amplitude"), "1075").await;
    b.click("#step-runs button.store").await;
    b.wait_until(
        "the first tab answers its store",
        "const e = document.querySelector('#step-runs .banner'); return !!e && !e.hidden && e.textContent !== ''",
    )
    .await;
    let banner = b.text("#step-runs .banner").await;
    assert!(banner.contains("changed in another tab"), "{banner}");
    assert_eq!(
        value_of(b, &field("runs[1].readings[0].amplitude")).await,
        "1075"
    );
    shots(b, "job-two-tabs").await;
    let versions = get(
        &stand,
        &format!("/api/v1/sessions/{id}/runs/trial%20inboard/versions"),
    )
    .await;
    let versions = versions.get("versions").cloned().unwrap_or(versions);
    assert_eq!(
        versions.as_array().map(Vec::len),
        Some(2),
        "only the other tab's correction is stored"
    );
    b.click("#step-runs button.cancel").await;

    machine_page_and_trim_from_stored_coefficients(&stand, &truth).await;
    new_job_with_rotor_places_and_kits(&stand, &truth).await;
    multi_speed_job_shows_bode_plots(&stand).await;
    the_form_weighs_little_and_asks_nothing_of_other_hosts(&stand).await;
    stand.stop().await;
}
