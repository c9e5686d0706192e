//! Every amplitude of the answer says its unit. The pump job (µm pk-pk)
//! with kits and a check run: the run's verdict gave "RMS 41.2 measured,
//! 39.8 predicted" and the kit fit "RMS 3.21, largest 5.02 predicted after",
//! in the answer and in the report, without the unit the residual table
//! beside them gives. The results CSV had no unit for its amplitudes and
//! no convention for its phases. The machine page's jobs gave their
//! vibration before and after as bare numbers.

use serde_json::json;

use super::conventions::with_a_check_run;
use crate::harness::form::{field, type_into};
use crate::harness::stand::{
    example_session, machine_with_coefficients, open_at_solve, post, Stand,
};
use crate::harness::steps::{js, js_async};

pub async fn every_amplitude_of_the_answer_says_its_unit(stand: &Stand) {
    let b = &stand.browser;
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    for p in session["planes"].as_array_mut().unwrap() {
        p["positions"] = json!(12);
        p["kit"] = json!({ "masses_g": [1, 2, 5, 10], "max_per_place": 3 });
    }
    let session = with_a_check_run(stand, session).await;
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .run-check p").await;
    let check = b.text("#step-solve .run-check p").await;
    assert!(
        check.contains("µm pk-pk measured") && check.contains("µm pk-pk predicted"),
        "{check}"
    );
    let fitted = b.text("#step-solve .fit-summary").await;
    assert_eq!(fitted.matches("µm pk-pk").count(), 3, "{fitted}");

    b.click("nav [data-step=\"report\"]").await;
    b.wait_for("#step-report .report-fit").await;
    let fitted = b.text("#step-report .report-fit p").await;
    assert_eq!(fitted.matches("µm pk-pk").count(), 2, "{fitted}");
    let check = b.text("#step-report .run-check p").await;
    assert!(check.contains("µm pk-pk measured"), "{check}");

    // The results CSV: each residual row with its unit, the phases with their convention.
    let csv = js_async(
        b,
        "const [done] = arguments; import('/static/js/steps/sessions.js').then((m) => done(m.resultsCsv()));",
    )
    .await;
    let csv = csv.as_str().expect("CSV text");
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let unit = header
        .iter()
        .position(|h| *h == "\"unit\"")
        .unwrap_or_else(|| panic!("no unit column: {csv}"));
    assert!(
        header.contains(&"\"phase_deg (lead)\""),
        "the phases' convention: {csv}"
    );
    let residuals: Vec<Vec<&str>> = csv
        .lines()
        .filter(|l| l.starts_with("\"residual\""))
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(residuals.len(), 4, "{csv}");
    for row in residuals {
        assert_eq!(row.len(), header.len(), "{row:?}");
        assert_eq!(row[unit], "\"um_pp\"", "{row:?}");
    }
}

/// The machine page's jobs say their vibration's unit, each its own (the
/// before and after figures were bare numbers); the trend names the unit
/// only when every job on it reads in one. The units come with the machine:
/// the page fetched every solved job's whole session to read them.
pub async fn the_machine_pages_jobs_say_their_unit(stand: &Stand) {
    let b = &stand.browser;
    let mut other = machine_with_coefficients(stand).await;
    other["name"] = json!("in mils");
    for sensor in other["sensors"].as_array_mut().unwrap() {
        sensor["unit"] = json!("mils_pp");
    }
    let created = post(stand, "/api/v1/sessions", other).await;
    let id = created["id"].as_str().expect("stored");
    post(
        stand,
        &format!("/api/v1/sessions/{id}/solutions"),
        json!({}),
    )
    .await;
    // Every request the page makes from here on, by its path.
    js(
        b,
        "window.fetched = []; const fetch = window.fetch; \
         window.fetch = (url, init) => { window.fetched.push(String(url)); return fetch(url, init); }; \
         return null",
    )
    .await;
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.wait_for("table.machine-jobs td.after").await;
    let fetched = js(b, "return window.fetched").await;
    let fetched: Vec<&str> = fetched
        .as_array()
        .expect("requests")
        .iter()
        .filter_map(|u| u.as_str())
        .collect();
    assert!(
        fetched
            .iter()
            .any(|u| u.ends_with("/api/v1/machines/PUMP-1")),
        "the page's requests are seen: {fetched:?}"
    );
    assert!(
        !fetched.iter().any(|u| u.contains("/api/v1/sessions/")),
        "the units come with the machine, not a request per job: {fetched:?}"
    );
    let rows = js(
        b,
        "return [...document.querySelectorAll('table.machine-jobs tbody tr')].map((r) => \
           [r.querySelector('button.open-session').textContent, r.querySelector('td.before').textContent, r.querySelector('td.after').textContent])",
    )
    .await;
    let rows = rows.as_array().expect("rows");
    assert_eq!(rows.len(), 2, "{rows:?}");
    for row in rows {
        let unit = if row[0] == "in mils" {
            "mils pk-pk"
        } else {
            "µm pk-pk"
        };
        for cell in [&row[1], &row[2]] {
            let cell = cell.as_str().unwrap();
            assert!(cell.ends_with(&format!(" {unit}")), "{row:?}");
        }
    }
    let caption = b.text("figure.trend-fig figcaption").await;
    assert!(
        caption.starts_with("RMS vibration per job:"),
        "two units: none named for both: {caption}"
    );
}

/// A job whose sensors read in two units (proximity probes in µm pk-pk
/// beside others in mils pk-pk): the summary's RMS and largest figures,
/// taken over all of them, were shown bare, as if in no unit at all, and
/// read as µm. They now name the units they mix.
pub async fn figures_over_mixed_units_say_so(stand: &Stand) {
    let b = &stand.browser;
    open_mixed_units_at_solve(stand).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .summary").await;
    let labels = js(
        b,
        "return [...document.querySelectorAll('#step-solve .summary .big .label')].map((e) => e.textContent)",
    )
    .await;
    assert_eq!(
        labels[0], "RMS over sensors, mixed units: µm pk-pk, mils pk-pk",
        "{labels}"
    );
    assert_eq!(
        labels[1], "Largest, mixed units: µm pk-pk, mils pk-pk",
        "{labels}"
    );
}

/// The pump job with its vertical sensors in mils pk-pk, the others in µm
/// pk-pk, stored and opened at the solve step.
async fn open_mixed_units_at_solve(stand: &Stand) {
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    for s in session["sensors"].as_array_mut().unwrap() {
        if s["id"].as_str().unwrap().ends_with("-V") {
            s["unit"] = json!("mils_pp");
        }
    }
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
}

/// Sensors in two units take an acceptable vibration per unit, and the
/// verdict weighs each unit's largest reading against its own limit. There
/// was one field labelled "sensor units", compared with the largest reading
/// whatever its unit: 50 could not mean both 50 µm and 50 mils.
pub async fn a_limit_per_unit_when_sensors_mix_units(stand: &Stand) {
    let b = &stand.browser;
    open_mixed_units_at_solve(stand).await;
    b.click("details.options summary").await;
    let labels = js(
        b,
        "return [...document.querySelectorAll('details.options input[data-field^=\"options.limit\"]')].map((e) => e.dataset.field)",
    )
    .await;
    assert_eq!(
        labels,
        json!(["options.limit.um_pp", "options.limit.mils_pp"]),
        "one limit per unit"
    );
    // The zero run's largest: 465.4 µm pk-pk (DE-H), 490.8 mils pk-pk (NDE-V).
    type_into(b, &field("options.limit.um_pp"), "500").await;
    type_into(b, &field("options.limit.mils_pp"), "400").await;
    b.click("#step-solve button.solve").await;
    b.wait_for(".verdict").await;
    let verdict = b.text(".verdict").await;
    assert_eq!(
        verdict,
        "Not yet within tolerance: the largest vibration in run “zero” is 465.4 µm pk-pk at or below the limit of 500.0 µm pk-pk; 490.8 mils pk-pk above the limit of 400.0 mils pk-pk. Fit the weights below and do a check run."
    );
    type_into(b, &field("options.limit.mils_pp"), "491").await;
    b.click("#step-solve button.solve").await;
    b.wait_until(
        "the verdict weighs the new limit",
        "const v = document.querySelector('.verdict'); return !!v && v.textContent.startsWith('Within tolerance')",
    )
    .await;
    let verdict = b.text(".verdict").await;
    assert!(
        verdict.contains("490.8 mils pk-pk at or below the limit of 491.0 mils pk-pk"),
        "{verdict}"
    );
}
