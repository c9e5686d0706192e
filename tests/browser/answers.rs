//! The answer as it is read. The test's own reader, `corrections_on_page`,
//! reads the answer of the last solve asked for, not the one before it that
//! the page still shows while the new one is out (it waited for any row of
//! corrections, so a test after a re-solve could pass on the old answer).
//! An answer that comes back after another job was opened stays with its
//! own job (it was shown as the other job's corrections), and so does a
//! refusal (its banner was shown on the other job's step).
//! The report's kit weights to fit are in grams to 0.1 g, as the answer
//! page and the report's other tables give them (it gave "10.00"), and the
//! RMS and largest the kit weights leave are to one decimal, as the summary
//! box gives the exact corrections' (the lines gave "3.21" beside its "3.2").

use serde_json::{json, Value};

use crate::harness::form::{corrections_on_page, field, type_into};
use crate::harness::stand::{example_session, open_at_solve, post, Stand};
use crate::harness::steps::js;
use crate::harness::Browser;
use crate::scenes::kit_support::fmt;

/// Store `session` and open it at its corrections step in the stand's browser.
async fn opened(stand: &Stand, session: &Value) -> String {
    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"]
        .as_str()
        .unwrap_or_else(|| panic!("stored: {created}"))
        .to_string();
    open_at_solve(stand, &id).await;
    id
}

/// From now on the page's solves are answered three seconds late (the
/// service's answer held back in the page's `fetch`), as on a slow stand PC.
async fn hold_back_solves(b: &Browser) {
    js(
        b,
        "const f = window.fetch; \
         window.fetch = (url, init) => f(url, init).then((r) => /\\/solutions$/.test(String(url)) && init && init.method === 'POST' \
           ? new Promise((ok) => setTimeout(() => ok(r), 3000)) : r); \
         return true",
    )
    .await;
}

/// Solve the open job with its answer (or refusal) held back three seconds,
/// as on a slow stand PC, and meanwhile open job `other` from the list at
/// its corrections; wait until the first job's answer is back.
async fn solve_then_open(stand: &Stand, other: &str) {
    let b = &stand.browser;
    hold_back_solves(b).await;
    b.click("#step-solve button.solve").await;
    // Meanwhile the technician opens the other job from the list, at its corrections.
    b.click("nav [data-step=\"sessions\"]").await;
    b.click(&format!(
        "#step-sessions button.open-session[data-id=\"{other}\"]"
    ))
    .await;
    b.wait_until(
        "the other job is open",
        "return document.querySelector('#job-title').textContent.startsWith('Other job')",
    )
    .await;
    b.click("nav [data-step=\"solve\"]").await;
    b.wait_until(
        "the first job's answer or refusal is back",
        "const s = document.querySelector('#step-solve'); return !!s.dataset.solves && s.dataset.solves === s.dataset.settled",
    )
    .await;
}

async fn the_corrections_read_after_a_re_solve_are_the_new_ones(stand: &Stand) {
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    opened(stand, &session).await;
    b.click("#step-solve button.solve").await;
    let first = corrections_on_page(b).await;
    let (plane, heaviest, _) = first
        .iter()
        .cloned()
        .max_by(|x, y| x.1.total_cmp(&y.1))
        .expect("corrections");
    let limit = (heaviest * 0.6).floor();
    let want = post(
        stand,
        "/api/v1/solve",
        json!({ "session": session, "options": { "max_mass_g": { plane.clone(): limit } } }),
    )
    .await;
    // The page's next answer is held back for three seconds: the old
    // one is on the page meanwhile, as on a slow stand PC.
    hold_back_solves(b).await;
    b.click("#step-solve details.options summary").await;
    let css = field(&format!("options.max_mass_g.{plane}"));
    type_into(b, &css, &format!("{limit}")).await;
    b.click("#step-solve button.solve").await;
    // While it is out the step says it is busy and Solve is off: a second
    // press stored a second solution.
    let out = js(
        b,
        "const s = document.querySelector('#step-solve'); return [s.getAttribute('aria-busy'), s.querySelector('button.solve').disabled]",
    )
    .await;
    assert_eq!(out, json!(["true", true]), "while the solve is out");
    let shown = corrections_on_page(b).await;
    let after = js(
        b,
        "const s = document.querySelector('#step-solve'); return [s.getAttribute('aria-busy'), s.querySelector('button.solve').disabled]",
    )
    .await;
    assert_eq!(after, json!([null, false]), "once the answer is in");
    let want = want["corrections"]
        .as_array()
        .unwrap_or_else(|| panic!("{want}"));
    assert_eq!(shown.len(), want.len(), "{shown:?}");
    for (w, (p, mass, angle)) in want.iter().zip(&shown) {
        assert_eq!(w["plane"].as_str(), Some(p.as_str()));
        let (m, a) = (
            w["mass_g"].as_f64().unwrap(),
            w["angle_deg"].as_f64().unwrap(),
        );
        let d = (angle - a).rem_euclid(360.0);
        assert!(
            (mass - m).abs() <= 0.051 && d.min(360.0 - d) <= 0.051,
            "{p}: {mass} g at {angle}° read, the limited answer is {m} g at {a}° (the first answer: {first:?})"
        );
    }
}

/// The pump job with a kit of 1, 2, 5 and 10 g weights on twelve places a
/// plane, solved on the page until `shown` is there; what the service
/// answers it with the kits fitted (`discrete`).
async fn kit_job_solved(stand: &Stand, shown: &str) -> Value {
    let b = &stand.browser;
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    for p in session["planes"].as_array_mut().unwrap() {
        p["positions"] = json!(12);
        p["kit"] = json!({ "masses_g": [1, 2, 5, 10], "max_per_place": 3 });
    }
    opened(stand, &session).await;
    b.click("#step-solve button.solve").await;
    b.wait_for(shown).await;
    post(
        stand,
        "/api/v1/solve",
        json!({ "session": session, "options": { "discrete": true } }),
    )
    .await
}

async fn the_reports_kit_weights_are_in_grams_to_a_tenth(stand: &Stand) {
    let b = &stand.browser;
    let service = kit_job_solved(stand, "#step-solve .plane-fig .fit-words").await;
    let fit = service["fit"]
        .as_array()
        .unwrap_or_else(|| panic!("the service fits the kits: {service}"));
    // [plane, place, angle, mass] a row, as the report's table has them.
    let mut want: Vec<[String; 4]> = Vec::new();
    for p in fit {
        let plane = p["plane"].as_str().unwrap().to_string();
        if p["weights"].as_array().unwrap().is_empty() {
            want.push([plane.clone(), "none".into(), "–".into(), "–".into()]);
        }
        for (i, w) in p["weights"].as_array().unwrap().iter().enumerate() {
            want.push([
                if i == 0 { plane.clone() } else { String::new() },
                w["place"].to_string(),
                fmt(w["angle_deg"].as_f64().unwrap(), 1),
                fmt(w["mass_g"].as_f64().unwrap(), 1),
            ]);
        }
    }
    b.click("nav [data-step=\"report\"]").await;
    b.wait_for("#step-report .report-fit table tbody tr").await;
    let rows: Vec<[String; 4]> = serde_json::from_value(
        js(
            b,
            "return [...document.querySelectorAll('#step-report .report-fit table tbody tr')].map((r) => [...r.cells].map((c) => c.textContent))",
        )
        .await,
    )
    .expect("rows of four cells");
    assert_eq!(rows, want, "the report's weights to fit, in g to 0.1 g");
    // The same figures as the answer page's words for each plane.
    b.click("nav [data-step=\"solve\"]").await;
    let words = js(
        b,
        "return [...document.querySelectorAll('#step-solve .plane-fig .fit-words li')].map((e) => e.textContent).join('\\n')",
    )
    .await;
    let words = words.as_str().unwrap();
    for row in &want {
        assert!(
            words.contains(&format!("{} g", row[3])),
            "{} g is not said on the answer page: {words}",
            row[3]
        );
    }
}

async fn an_answer_that_comes_back_after_another_job_is_opened_stays_with_its_job(stand: &Stand) {
    let b = &stand.browser;
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    session["name"] = json!("Other job");
    let other = post(stand, "/api/v1/sessions", session.clone()).await;
    let other = other["id"].as_str().expect("stored").to_string();
    session["name"] = json!("Solved job");
    opened(stand, &session).await;
    solve_then_open(stand, &other).await;
    let shown = js(
        b,
        "const s = document.querySelector('#step-solve'); return [document.querySelector('#job-title').textContent, !!s.querySelector('table.corrections'), s.querySelector('button.solve').disabled]",
    )
    .await;
    assert_eq!(
        shown,
        json!(["Other job · stored", false, false]),
        "the other job shows no answer of the first, and can be solved"
    );
}

async fn a_refusal_that_comes_back_after_another_job_is_opened_stays_with_its_job(stand: &Stand) {
    let b = &stand.browser;
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    session["name"] = json!("Other job");
    let other = post(stand, "/api/v1/sessions", session.clone()).await;
    let other = other["id"].as_str().expect("stored").to_string();
    // The zero run alone: the service refuses to solve it (too few trial runs).
    session["name"] = json!("Refused job");
    session["runs"] = json!([session["runs"][0].clone()]);
    let refused = post(stand, "/api/v1/solve", json!({ "session": session })).await;
    assert!(refused["error"]["message"].is_string(), "{refused}");
    opened(stand, &session).await;
    solve_then_open(stand, &other).await;
    let shown = js(
        b,
        "const s = document.querySelector('#step-solve'), e = s.querySelector('.banner.error'); \
         return [document.querySelector('#job-title').textContent, e && !e.hidden ? e.textContent : null, document.querySelectorAll('.field.bad').length, s.querySelector('button.solve').disabled]",
    )
    .await;
    assert_eq!(
        shown,
        json!(["Other job · stored", null, 0, false]),
        "the other job shows no refusal of the first ({refused}), and can be solved"
    );
}

async fn the_kit_fits_rms_reads_to_the_decimals_of_the_summary_box(stand: &Stand) {
    let b = &stand.browser;
    let service = kit_job_solved(stand, "#step-solve .fit-summary").await;
    let figure = |k: &str| fmt(service["fit_summary"][k].as_f64().unwrap(), 1);
    let (rms, max) = (figure("rms_after"), figure("max_after"));
    // The summary box's RMS after the exact corrections, as it shows it.
    let boxed = b.text("#step-solve .summary .big .value").await;
    let exact = boxed.rsplit(' ').next().unwrap().to_string();
    assert_eq!(
        exact,
        fmt(service["summary"]["rms_after"].as_f64().unwrap(), 1),
        "{boxed}"
    );
    let said = b.text("#step-solve .fit-summary").await;
    let want = format!(
        "With the kit weights shown: RMS {rms} µm pk-pk, largest {max} µm pk-pk predicted after (the exact corrections above: RMS {exact} µm pk-pk)."
    );
    assert!(said.starts_with(&want), "{said:?} should start {want:?}");
    b.click("nav [data-step=\"report\"]").await;
    b.wait_for("#step-report .report-fit p").await;
    let said = b.text("#step-report .report-fit p").await;
    let want = format!("With these weights: RMS {rms} µm pk-pk, max {max} µm pk-pk");
    assert!(said.starts_with(&want), "{said:?} should start {want:?}");
}

/// One browser for every scene (CI time); each scene gets a new server and
/// database and a freshly loaded form (`Stand::renew`).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_answer_is_read_as_it_is_meant() {
    let mut stand = Stand::start().await;
    the_corrections_read_after_a_re_solve_are_the_new_ones(&stand).await;
    stand.renew().await;
    the_reports_kit_weights_are_in_grams_to_a_tenth(&stand).await;
    stand.renew().await;
    an_answer_that_comes_back_after_another_job_is_opened_stays_with_its_job(&stand).await;
    stand.renew().await;
    a_refusal_that_comes_back_after_another_job_is_opened_stays_with_its_job(&stand).await;
    stand.renew().await;
    the_kit_fits_rms_reads_to_the_decimals_of_the_summary_box(&stand).await;
    stand.stop().await;
}
