//! Every warning of a solve is shown with the service's own message, and one
//! that names a plane also under that plane's correction. The pump job with
//! a trial in plane "outboard" that moved the readings by 5 % and 1°
//! (`trial_effect_small`) and a mass limit at half the heaviest correction
//! (`mass_limit_active`): the form said each in its own words only, dropping
//! the figures the service gives (the trial's effect in %, how much heavier
//! to make it, the bound) and, for some codes, the plane; and a warning that
//! names a plane was only in the box above the answer, not beside the weight
//! read off the table. The results CSV left the warnings out.

use serde_json::{json, Value};

use crate::harness::form::{field, type_into};
use crate::harness::stand::{example_session, get, open_at_solve, post, Stand};
use crate::harness::steps::{js, js_async};

pub async fn every_solve_warning_is_shown_with_its_message_beside_its_plane(stand: &Stand) {
    let b = &stand.browser;
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    let reference = session["runs"][0]["readings"].clone();
    for (k, r) in session["runs"][2]["readings"]
        .as_array_mut()
        .unwrap()
        .iter_mut()
        .enumerate()
    {
        r["amplitude"] = json!(reference[k]["amplitude"].as_f64().unwrap() * 1.05);
        r["phase_deg"] = json!((reference[k]["phase_deg"].as_f64().unwrap() + 1.0) % 360.0);
    }
    // A mass limit at half the heaviest correction the service gives without one.
    let free = post(
        stand,
        "/api/v1/solve",
        json!({ "session": session.clone(), "options": {} }),
    )
    .await;
    let (heavy, mass) = free["corrections"]
        .as_array()
        .unwrap_or_else(|| panic!("{free}"))
        .iter()
        .map(|c| {
            (
                c["plane"].as_str().unwrap().to_string(),
                c["mass_g"].as_f64().unwrap(),
            )
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    let limit = format!("{:.1}", mass / 2.0);
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
    b.click("#step-solve details.options summary").await;
    type_into(b, &field(&format!("options.max_mass_g.{heavy}")), &limit).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve table.corrections").await;

    // What the service answered, as it stored it.
    let solutions = get(stand, &format!("/api/v1/sessions/{id}/solutions")).await;
    let warnings = solutions[0]["solution"]["warnings"]
        .as_array()
        .unwrap_or_else(|| panic!("a stored solution: {solutions}"))
        .clone();
    let has = |code: &str, plane: &str| {
        warnings
            .iter()
            .any(|w| w["code"] == code && w["plane"] == plane)
    };
    assert!(
        has("trial_effect_small", "outboard") && has("mass_limit_active", &heavy),
        "the job is not the one meant: {warnings:?}"
    );

    // The box: one item per warning, in order, each with the service's message.
    let shown: Value = js(
        b,
        "return [...document.querySelectorAll('#step-solve .warnings > ul > li')].map((li) => [li.dataset.code, li.dataset.plane, (li.querySelector('.said-text') || {}).textContent || null])",
    )
    .await;
    let shown = shown.as_array().unwrap();
    assert_eq!(shown.len(), warnings.len(), "{shown:?} for {warnings:?}");
    for (w, s) in warnings.iter().zip(shown) {
        assert_eq!(s[0], w["code"], "{s} for {w}");
        assert_eq!(
            s[1],
            w.get("plane").cloned().unwrap_or(json!("")),
            "{s} for {w}"
        );
        assert_eq!(s[2], w["message"], "the service's words: {s} for {w}");
    }
    // One click shows them.
    b.click("#step-solve .warnings li[data-code=\"trial_effect_small\"] details.said summary")
        .await;
    let said = b
        .text("#step-solve .warnings li[data-code=\"trial_effect_small\"] .said-text")
        .await;
    assert!(said.contains("changed the vibration by at most"), "{said}");

    // The results CSV carries each warning, in the service's words.
    let csv = js_async(
        b,
        "const [done] = arguments; import('/static/js/steps/sessions.js').then((m) => done(m.resultsCsv()));",
    )
    .await;
    let csv = csv.as_str().expect("CSV text");
    let header = csv.lines().next().unwrap();
    let rows: Vec<&str> = csv
        .lines()
        .filter(|l| l.starts_with("\"warning\""))
        .collect();
    assert_eq!(rows.len(), warnings.len(), "{csv}");
    for (w, row) in warnings.iter().zip(&rows) {
        let plane = w["plane"].as_str().unwrap_or("");
        assert!(
            row.starts_with(&format!("\"warning\",\"{plane}\",")),
            "{row}"
        );
        let message = w["message"].as_str().unwrap().replace('"', "\"\"");
        // The columns after `note` (a trim's from_run and total) are empty.
        let fields: Vec<&str> = header.split(',').collect();
        let note = fields
            .iter()
            .position(|f| *f == "\"note\"")
            .expect("a note column");
        let after = ",\"\"".repeat(fields.len() - 1 - note);
        assert!(
            row.ends_with(&format!(
                "\"{}: {message}\"{after}",
                w["code"].as_str().unwrap()
            )),
            "{row}"
        );
    }

    // Beside the plane: the rows right under each plane's correction.
    for plane in ["inboard", "outboard"] {
        let under: Value = js(
            b,
            &format!(
                "const out = []; let r = document.querySelector('#step-solve table.corrections tbody tr[data-plane=\"{plane}\"]:not(.plane-warning)').nextElementSibling; \
                 while (r && r.matches('.plane-warning')) {{ out.push([r.dataset.code, r.textContent]); r = r.nextElementSibling; }} return out"
            ),
        )
        .await;
        let meant: Vec<&Value> = warnings.iter().filter(|w| w["plane"] == plane).collect();
        let under = under.as_array().unwrap();
        assert_eq!(under.len(), meant.len(), "{plane}: {under:?} for {meant:?}");
        for (w, u) in meant.iter().zip(under) {
            assert_eq!(u[0], w["code"], "{plane}: {u}");
            let text = u[1].as_str().unwrap();
            assert!(text.starts_with(&format!("⚠ Plane {plane}: ")), "{text}");
        }
    }

    // On paper the plain words stand; the service's words (a click on
    // screen) are left off, so the answer keeps to its first page.
    b.click("nav [data-step=\"report\"]").await;
    b.wait_for("#step-report .report-answer .warnings li").await;
    b.emulate_print(true).await;
    let printed: Value = js(
        b,
        "const li = document.querySelector('#step-report .report-answer .warnings li'); \
         return [getComputedStyle(li).display, getComputedStyle(li.querySelector('details.said')).display]",
    )
    .await;
    b.emulate_print(false).await;
    assert_eq!(printed, json!(["list-item", "none"]), "in print");
}
