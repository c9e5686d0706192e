//! A second job for the machine, started from its page: the set-up copied,
//! then rotor data, fixed places and kits typed in; every run read from one
//! CSV file with a column per run; the trial weight suggested before the first
//! trial; then the kit fit (kit_fit.rs) and the machine page (machine.rs).

use serde_json::{json, Value};

use super::kit_fit::kit_fit_is_drawn_where_it_goes;
use super::kit_support::{csv_column_per_run, fmt, get, post, read_csv};
use crate::harness::form::{self, field, type_into, typed, value_of};
use crate::harness::job::shots;
use crate::harness::stand::Stand;
use crate::harness::Browser;

const ROTOR: [(&str, &str); 2] = [
    ("rotor.mass_kg", "400"),
    ("rotor.service_speed_rpm", "2950"),
];
pub const GRADE: &str = "G6.3";
const INBOARD_PLACES: &str = "12";
const OUTBOARD_PLACES: &str = "0 40 100 160 220 290";
const KITS: [&str; 2] = ["5 10 20", "2 5 10"];

/// "New job for this machine" copies the set-up of its last job, name left empty.
async fn new_job_copies_the_set_up(b: &Browser, truth: &Value) {
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.click("button.new-job").await;
    b.wait_until(
        "the set-up step of the new job is shown",
        "return !document.querySelector('#step-setup').hidden && document.querySelector('#job-title').textContent === 'New balancing job'",
    )
    .await;
    let mut want = vec![
        ("name".to_string(), String::new()),
        ("machine".to_string(), "PUMP-1".to_string()),
        (
            "speeds".to_string(),
            form::speeds(truth)
                .iter()
                .map(|s| format!("{s}"))
                .collect::<Vec<_>>()
                .join(" "),
        ),
    ];
    for key in ["phase", "angle_direction"] {
        want.push((
            format!("conventions.{key}"),
            truth["conventions"][key].as_str().unwrap().to_string(),
        ));
    }
    for (i, p) in truth["planes"].as_array().unwrap().iter().enumerate() {
        want.push((
            format!("planes[{i}].id"),
            p["id"].as_str().unwrap().to_string(),
        ));
        want.push((format!("planes[{i}].radius_mm"), typed(&p["radius_mm"])));
    }
    for (i, x) in truth["sensors"].as_array().unwrap().iter().enumerate() {
        want.push((
            format!("sensors[{i}].id"),
            x["id"].as_str().unwrap().to_string(),
        ));
        want.push((
            format!("sensors[{i}].unit"),
            x["unit"].as_str().unwrap().to_string(),
        ));
    }
    for (path, value) in want {
        assert_eq!(
            value_of(b, &field(&path)).await,
            value,
            "copied set-up: {path}"
        );
    }
}

/// (Items 1, 2, 8, 9) A second job for the machine with rotor data, fixed places and kits.
pub async fn new_job_with_rotor_places_and_kits(stand: &Stand, truth: &Value) {
    let b = &stand.browser;
    new_job_copies_the_set_up(b, truth).await;
    type_into(b, &field("name"), "PUMP-1 kit job").await;
    for (path, value) in ROTOR {
        type_into(b, &field(path), value).await;
    }
    form::choose(b, &field("rotor.balance_grade"), GRADE).await;
    type_into(b, &field("planes[0].positions"), INBOARD_PLACES).await;
    type_into(b, &field("planes[0].kit.masses_g"), KITS[0]).await;
    type_into(b, &field("planes[1].places_deg"), OUTBOARD_PLACES).await;
    type_into(b, &field("planes[1].kit.masses_g"), KITS[1]).await;
    crate::harness::job::scroll_to(b, "fieldset.planes").await;
    shots(b, "job-kit-setup").await;
    crate::harness::steps::fits_a_tablet(b, "kit setup").await;
    b.click("#step-setup button.next").await;

    // The shapes a CSV file may have are said at the grid, before any file is chosen.
    let shapes = b.text("#step-runs .csv-shapes").await;
    assert!(
        shapes.contains("a row per reading") && shapes.contains("a column per run"),
        "{shapes}"
    );
    let path = stand.dir.path().join("pump-runs.csv");
    std::fs::write(&path, csv_column_per_run(truth)).unwrap();
    let note = read_csv(b, &path).await;
    assert!(
        note.starts_with("4 of 4 readings read") && note.contains("(a column per run)"),
        "{note}"
    );
    for (i, r) in truth["runs"][0]["readings"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
    {
        let shown = value_of(b, &field(&format!("runs[0].readings[{i}].phase_deg"))).await;
        assert_eq!(
            shown.parse::<f64>().unwrap(),
            r["phase_deg"].as_f64().unwrap()
        );
    }
    form::store(b).await;
    let id = crate::harness::steps::stored_id(b).await;

    // Before the first trial: the trial weight the service suggests from the rotor data.
    b.click("button.add-trial").await;
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let stored = stored.get("session").cloned().unwrap_or(stored);
    let suggested = post(stand, "/api/v1/trial-weights", json!({ "session": stored })).await;
    let suggestions = suggested["suggestions"].as_array().expect("suggestions");
    assert_eq!(suggestions.len(), 2, "{suggested}");
    for s in suggestions {
        let plane = s["plane"].as_str().unwrap();
        let text = b
            .text(&format!(".suggestion li[data-plane=\"{plane}\"]"))
            .await;
        let want = format!(
            "Plane {plane}: {} g at {:.1}°",
            fmt(s["mass_g"].as_f64().unwrap(), 1),
            s["angle_deg"].as_f64().unwrap().rem_euclid(360.0)
        );
        assert!(text.contains(&want), "{text:?} should say {want:?}");
    }
    shots(b, "job-trial-suggestion").await;
    crate::harness::steps::fits_a_tablet(b, "trial suggestion").await;
    use_it_enters_each_kit_weight(b, suggestions).await;

    // The trials: the fitter used the example's weights; the readings from the same file.
    for (k, name) in [(1usize, "trial inboard"), (2, "trial outboard")] {
        if k == 2 {
            b.click("button.add-trial").await;
        }
        let w = &truth["runs"][k]["weights"][0];
        form::choose(
            b,
            &field(&format!("runs[{k}].weights[0].plane")),
            w["plane"].as_str().unwrap(),
        )
        .await;
        type_into(
            b,
            &field(&format!("runs[{k}].weights[0].mass_g")),
            &typed(&w["mass_g"]),
        )
        .await;
        type_into(
            b,
            &field(&format!("runs[{k}].weights[0].angle_deg")),
            &typed(&w["angle_deg"]),
        )
        .await;
        if k == 1 {
            // A file of several runs is read into the run of the same name, and says so.
            let refused = read_csv(b, &path).await;
            assert!(
                refused.contains("none called “trial 1”: name the run as in the file"),
                "{refused}"
            );
        }
        type_into(b, &field(&format!("runs[{k}].id")), name).await;
        // The grid's column says the name as it is typed.
        assert_eq!(b.text("#step-runs th.run.editing .run-name").await, name);
        let note = read_csv(b, &path).await;
        assert!(note.starts_with("4 of 4 readings read"), "{note}");
        form::store(b).await;
    }
    let lead = b.text("#step-runs p.lead").await;
    assert!(lead.contains("2 of 2"), "{lead}");

    kit_fit_is_drawn_where_it_goes(stand, &id).await;
    super::machine::the_machine_page_shows_vibration_before_and_after_per_job(stand).await;
}

/// "Use it" on a stack of kit weights enters each weight the fitter bolts on,
/// all at the place's angle, not one weight of their sum; the extra rows are
/// then removed, as the trials below use the example's own weights.
async fn use_it_enters_each_kit_weight(b: &Browser, suggestions: &[Value]) {
    let stack = suggestions
        .iter()
        .find(|s| s["weights"].as_array().is_some_and(|w| w.len() >= 2))
        .unwrap_or_else(|| panic!("a suggestion of two kit weights or more: {suggestions:?}"));
    let plane = stack["plane"].as_str().unwrap();
    let text = b
        .text(&format!(".suggestion li[data-plane=\"{plane}\"]"))
        .await;
    let parts: Vec<String> = stack["weights"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| format!("{} g", fmt(m.as_f64().unwrap(), 1)))
        .collect();
    assert!(
        text.contains(&format!(
            "{} stacked at place {}",
            parts.join(" + "),
            stack["place"]
        )),
        "{text:?} names the parts {parts:?}"
    );
    b.click(&format!(
        ".suggestion li[data-plane=\"{plane}\"] button.use-suggestion"
    ))
    .await;
    let entered = crate::harness::job::weights_in_editor(b, 1).await;
    let angle: f64 = format!(
        "{:.1}",
        stack["angle_deg"].as_f64().unwrap().rem_euclid(360.0)
    )
    .parse()
    .unwrap();
    let want: Vec<Value> = stack["weights"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| json!({ "plane": plane, "mass_g": m, "angle_deg": angle }))
        .collect();
    assert_eq!(entered, json!(want), "each kit weight on its own row");
    shots(b, "job-trial-suggestion-used").await;
    let rows = want.len();
    for _ in 1..rows {
        b.click("#step-runs .weights tbody tr:last-child button.remove-weight")
            .await;
    }
    b.wait_until(
        "the extra rows are removed",
        "return document.querySelectorAll('#step-runs .weights tbody tr').length === 1",
    )
    .await;
}
