//! A whole job at a 1024×768 window with the keyboard alone: the set-up, the
//! zero run, two trials, solve, the corrections bolted on and a check run,
//! and the trim from it. No click, no element picked: keys go to whatever
//! has the focus. What it found, each failing on the old form:
//!
//! - after a step was shown by a button (Next, Solve →, "record a check
//!   run"), a run stored or a solve, the focus was left on the page's body:
//!   Tab started again from the tabs (21 presses to a check run's first
//!   cell). The focus now goes on: to the first empty cell (app.js
//!   focusStep), to "+ Add trial run" or "Solve →" (runs.js store), back to
//!   "Solve again" (solve.js);
//! - Enter in a run's name or weight did nothing: it goes on to the first
//!   empty cell (or stores a run fully typed);
//! - a check run offered "Weights of “trial 2” are still on the rotor", whose
//!   tick would add the trial weight to a run that lists every weight on;
//! - after a check run was stored the runs step still said "Every plane has
//!   had its trial weight … Solve, or add a run": it now says to solve again.

use serde_json::json;

use super::keys::{focus_in_view, focus_is, focused, press, tab_to, DOWN, ENTER, TAB};
use crate::harness::form::{self, field, value_of};
use crate::harness::job::{predicted, sideways, weights_in_editor};
use crate::harness::stand::{example_session, Stand};
use crate::harness::steps::js;
use crate::harness::Browser;

fn keys(parts: &[&str]) -> String {
    parts.join(&TAB.to_string())
}

/// The focus is on `css`, or the scene fails naming where it is.
async fn focus_on(b: &Browser, css: &str, when: &str) {
    assert!(
        focus_is(b, css).await,
        "{when}: the focus should be on {css}, is on {}",
        focused(b).await
    );
}

/// Type `cells` from the focused first cell of run `k`, Tab between them,
/// each cell in full view as it is typed into; Enter stores the run.
async fn type_cells_and_enter(b: &Browser, k: usize, cells: &[String]) {
    focus_on(
        b,
        &field(&format!("runs[{k}].readings[0].amplitude")),
        "first cell",
    )
    .await;
    for (i, v) in cells.iter().enumerate() {
        if i > 0 {
            press(b, &TAB.to_string()).await;
        }
        assert_eq!(
            focus_in_view(b).await,
            json!(true),
            "{} is hidden at 1024×768",
            focused(b).await
        );
        press(b, v).await;
    }
    press(b, &ENTER.to_string()).await;
    b.wait_until(
        "the run is stored",
        &format!("return document.querySelectorAll('#step-runs th.run').length === {} && !document.querySelector('#step-runs .draft')", k + 1),
    )
    .await;
}

async fn fits(b: &Browser, what: &str) {
    let (over, culprits) = sideways(b).await;
    assert!(
        over <= 0,
        "{what}: sideways by {over} px at 1024: {culprits}"
    );
}

pub async fn a_whole_job_at_1024_by_768_with_the_keyboard_alone(stand: &Stand) {
    let b = &stand.browser;
    b.viewport(1024, 768).await;
    let (session, _) = example_session("pump-two-plane-exact.json");
    let url = stand.server.url("");
    let url = url.trim_end_matches('/');

    // The set-up: text, selects by arrow key, planes and sensors added by Enter.
    tab_to(b, &field("name"), 10).await;
    press(b, &keys(&["pump job", "PUMP-1", "2950", ""])).await;
    press(b, &format!("{DOWN}{TAB}{DOWN}")).await;
    assert_eq!(value_of(b, &field("conventions.phase")).await, "lead");
    assert_eq!(
        value_of(b, &field("conventions.angle_direction")).await,
        "with_rotation"
    );
    tab_to(b, &field("planes[0].id"), 5).await;
    press(b, &keys(&["inboard", "180"])).await;
    tab_to(b, "button.add-plane", 5).await;
    press(b, &ENTER.to_string()).await;
    focus_on(b, &field("planes[1].id"), "a plane added").await;
    press(b, &keys(&["outboard", "160"])).await;
    tab_to(b, &field("sensors[0].id"), 8).await;
    for (i, s) in session["sensors"].as_array().unwrap().iter().enumerate() {
        if i > 0 {
            tab_to(b, "button.add-sensor", 5).await;
            press(b, &ENTER.to_string()).await;
        }
        press(b, s["id"].as_str().unwrap()).await;
    }
    fits(b, "set-up").await;
    press(b, &ENTER.to_string()).await;

    // The zero run: the focus is in its first cell.
    b.wait_for("#step-runs table.grid").await;
    let zero = form::cells(&session, &session["runs"][0]);
    type_cells_and_enter(b, 0, &zero).await;
    focus_on(b, "#step-runs button.add-trial", "the zero run stored").await;

    // Two trials: Enter adds one, the plane is proposed, Enter after the
    // weight goes on to the readings.
    for k in 1..=2 {
        press(b, &ENTER.to_string()).await;
        let w = &session["runs"][k]["weights"][0];
        focus_on(
            b,
            &field(&format!("runs[{k}].weights[0].mass_g")),
            "a trial added",
        )
        .await;
        assert_eq!(
            value_of(b, &field(&format!("runs[{k}].weights[0].plane"))).await,
            w["plane"].as_str().unwrap(),
            "the untried plane is proposed"
        );
        press(b, &format!("{}{TAB}{}{ENTER}", w["mass_g"], w["angle_deg"])).await;
        let cells = form::cells(&session, &session["runs"][k]);
        type_cells_and_enter(b, k, &cells).await;
        let next = if k == 1 {
            "button.add-trial"
        } else {
            "button.go-solve"
        };
        focus_on(b, &format!("#step-runs {next}"), "a trial stored").await;
    }
    fits(b, "runs").await;

    // Solve: the step's heading has the focus; Solve is a Tab or two away.
    press(b, &ENTER.to_string()).await;
    b.wait_for("#step-solve button.solve").await;
    focus_on(b, "#step-solve h2", "the corrections step shown").await;
    tab_to(b, "#step-solve button.solve", 3).await;
    press(b, &ENTER.to_string()).await;
    b.wait_for("#step-solve table.corrections").await;
    focus_on(b, "#step-solve button.solve", "solved").await;
    assert_eq!(b.text("#step-solve button.solve").await, "Solve again");
    fits(b, "corrections").await;

    // The corrections bolted on, a check run: its first cell has the focus,
    // its weights are the corrections, and no trial weight is offered to add.
    tab_to(b, "#step-solve button.check-run", 40).await;
    press(b, &ENTER.to_string()).await;
    b.wait_for(&field("runs[3].readings[0].amplitude")).await;
    let carry = js(
        b,
        "return !!document.querySelector('#step-runs input.carry-tick')",
    )
    .await;
    assert_eq!(carry, json!(false), "a check run lists every weight on");
    assert_eq!(value_of(b, &field("runs[3].purpose")).await, "check");
    let on = weights_in_editor(b, 3).await;
    let check = predicted(url, &session, &on).await;
    type_cells_and_enter(b, 3, &form::cells(&session, &check)).await;
    focus_on(b, "#step-runs button.go-solve", "the check run stored").await;
    let lead = b.text("#step-runs p.lead").await;
    assert!(
        lead.starts_with("Check run “check” stored: solve again"),
        "{lead}"
    );

    // The trim from the check run, its options opened from the keyboard.
    press(b, &ENTER.to_string()).await;
    b.wait_for("#step-solve button.solve").await;
    tab_to(b, "#step-solve details.options summary", 3).await;
    press(b, &ENTER.to_string()).await;
    tab_to(b, "#step-solve select.from-run", 5).await;
    assert_eq!(value_of(b, "select.from-run").await, "check");
    tab_to(b, "#step-solve button.solve", 20).await;
    press(b, &ENTER.to_string()).await;
    let words = b.text(".trim li[data-plane=\"inboard\"]").await;
    assert!(words.contains("nothing to add"), "{words}");
    b.viewport(1280, 800).await;
}
