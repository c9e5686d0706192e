//! End-to-end tests of the form with sessions imported from JSON files: a
//! multi-speed job (the grid, the plots), a weak trial run (the warning in
//! plain words, its answer greyed), and the uncertainty shown in technician words.

use crate::common;

use crate::harness::stand::Stand;
use crate::harness::steps::js_async;
use crate::harness::{form, Browser};
use fantoccini::Locator;
use serde_json::{json, Value};

/// Import `file` through the sessions page, as a technician picking the file would.
async fn import(b: &Browser, dir: &tempfile::TempDir, name: &str, content: &Value) {
    let path = dir.path().join(name);
    std::fs::write(&path, serde_json::to_vec(content).unwrap()).unwrap();
    b.click("nav [data-step=\"sessions\"]").await;
    let input = b.wait_for("input.import-file").await;
    input
        .send_keys(path.to_str().unwrap())
        .await
        .expect("the file is chosen");
    // Opened: the title names it and its runs show (an earlier job's grid may still be in the page).
    let session = content.get("session").unwrap_or(content);
    let title = format!("{} · stored", session["name"].as_str().expect("a name"));
    let script = format!(
        "return document.querySelector('#job-title').textContent === {} && \
                !document.querySelector('#step-runs').hidden && \
                !!document.querySelector('#step-runs td.value.amp')",
        serde_json::to_string(&title).unwrap()
    );
    b.wait_until("the imported session is open", &script).await;
}

/// One browser for every scene of this binary (CI time); each scene gets a
/// new server and database and a freshly loaded form (`Stand::renew`).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn imported_jobs_show_their_rows_warnings_uncertainty_places_and_angles() {
    let mut stand = Stand::start().await;
    an_imported_multi_speed_job_shows_every_row_and_solves_to_the_expected_corrections(&stand)
        .await;
    stand.renew().await;
    a_weak_trial_run_is_warned_about_with_what_to_do_and_its_answer_greyed(&stand).await;
    stand.renew().await;
    a_correction_with_uncertainty_reads_as_mass_and_angle_plus_or_minus_and_a_wide_one_greys_the_summary(&stand).await;
    stand.renew().await;
    a_plane_with_fixed_places_shows_its_correction_split_over_two_places(&stand).await;
    stand.renew().await;
    crate::scenes::answer_notes::the_job_level_warning_says_whether_a_small_trial_or_alike_planes_spoil_the_figures(&stand)
        .await;
    stand.renew().await;
    crate::scenes::answer_notes::a_bound_below_the_prediction_and_an_agreeing_row_above_its_bound_are_explained(&stand).await;
    stand.renew().await;
    polar_plot_angles_run_clockwise_for_phase_lag_and_counter_clockwise_for_lead(&stand).await;
    stand.stop().await;
}

async fn an_imported_multi_speed_job_shows_every_row_and_solves_to_the_expected_corrections(
    stand: &Stand,
) {
    let b = &stand.browser;
    let example = common::example("compressor-multispeed-noisy.json");
    import(b, &stand.dir, "compressor.json", &example).await;
    let rows = b
        .client
        .find_all(Locator::Css("#step-runs table.grid tbody tr"))
        .await
        .unwrap();
    assert_eq!(rows.len(), 8 * 5, "eight speeds × five sensors");
    crate::harness::job::shots(b, "runs-multispeed").await;
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    let shown = form::corrections_on_page(b).await;
    let expected = example["expected"]["corrections"].as_array().unwrap();
    assert_eq!(shown.len(), expected.len());
    for (want, (plane, mass, angle)) in expected.iter().zip(&shown) {
        assert_eq!(want["plane"].as_str(), Some(plane.as_str()));
        assert!(
            (mass - want["mass_g"].as_f64().unwrap()).abs() <= 0.051,
            "{plane}: {mass}"
        );
        let d = (angle - want["angle_deg"].as_f64().unwrap()).rem_euclid(360.0);
        assert!(d.min(360.0 - d) <= 0.051, "{plane}: {angle}");
    }
    let plots = b
        .client
        .find_all(Locator::Css("#step-solve svg.polar"))
        .await
        .unwrap();
    // Forty plots would bury the one wanted: the filter shows one speed at first, all on request.
    assert_eq!(plots.len(), 5, "a polar plot per sensor at the first speed");
    form::choose(b, "#step-solve select.filter-speed", "").await;
    let plots = b
        .client
        .find_all(Locator::Css("#step-solve svg.polar"))
        .await
        .unwrap();
    assert_eq!(plots.len(), 40, "a polar plot per sensor and speed");
    b.client
        .execute(
            "document.querySelector('#step-solve .plots').scrollIntoView()",
            vec![],
        )
        .await
        .unwrap();
    crate::harness::job::shots(b, "solution-multispeed-plots").await;
}

/// Words that read as code: with an underscore, a dot between letters, or brackets.
fn code_words(text: &str) -> Vec<String> {
    text.split_whitespace()
        .map(|w| w.trim_matches(|c: char| !c.is_alphanumeric()))
        .filter(|w| {
            w.contains('_')
                || w.contains('[')
                || w.split('.')
                    .filter(|p| p.chars().any(char::is_alphabetic))
                    .count()
                    > 1
        })
        .map(str::to_string)
        .collect()
}

async fn a_weak_trial_run_is_warned_about_with_what_to_do_and_its_answer_greyed(stand: &Stand) {
    let b = &stand.browser;
    let mut session = common::example("pump-single-plane-noisy.json")["session"].clone();
    session["name"] = json!("weak trial");
    // The trial changed the reading by 1 % and 1°: far below the 30 % / 30° field practice.
    let reference = session["runs"][0]["readings"][0].clone();
    let trial = &mut session["runs"][1]["readings"][0];
    trial["amplitude"] = json!(reference["amplitude"].as_f64().unwrap() * 1.01);
    trial["phase_deg"] = json!(reference["phase_deg"].as_f64().unwrap() + 1.0);
    import(b, &stand.dir, "weak.json", &session).await;
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    let warning = b
        .wait_for(".warnings li[data-code=\"trial_effect_small\"]")
        .await;
    let text = warning.text().await.unwrap();
    assert!(text.contains("What to do"), "{text}");
    assert!(text.contains("bigger trial weight"), "{text}");
    // The answer it spoils is greyed, not bold, and says why and what to do.
    let row = b
        .client
        .execute(
            "const r = document.querySelector('#step-solve table.corrections tbody tr');              const m = r.querySelector('td.corr-mass');              return [r.className, getComputedStyle(m).fontWeight, getComputedStyle(m).color,                      getComputedStyle(document.querySelector('#step-solve table.corrections thead th')).color]",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(row[0], "doubtful", "{row}");
    assert_eq!(row[1], "400", "not bold: {row}");
    assert_ne!(
        row[2], row[3],
        "greyed, not the ordinary text colour: {row}"
    );
    // So is what it predicts: the summary and the "after" column, greyed and plain, saying why.
    let summary = b
        .client
        .execute(
            "const s = document.querySelector('#step-solve .summary'); \
             const v = [...s.querySelectorAll('.big .value')]; const a = document.querySelector('#step-solve table.residual td.after'); \
             return [s.className, v.map((e) => getComputedStyle(e).fontWeight), v.map((e) => getComputedStyle(e).color), \
                     getComputedStyle(a).fontWeight, getComputedStyle(a).color, getComputedStyle(document.body).color, s.innerText]",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(summary[0], "summary unsure", "{summary}");
    assert_eq!(
        summary[1],
        json!(["400", "400", "400"]),
        "no bold figures: {summary}"
    );
    for colour in summary[2].as_array().unwrap().iter().chain([&summary[4]]) {
        assert_ne!(
            colour, &summary[5],
            "greyed, not the text colour: {summary}"
        );
    }
    assert_eq!(
        summary[3], "400",
        "the predicted after is not bold: {summary}"
    );
    let said = summary[6].as_str().unwrap();
    assert!(
        said.contains("Not to be trusted")
            && said.contains("bigger trial weight")
            && said.contains("about"),
        "{said}"
    );
    let doubts = b.text("#step-solve .doubts").await;
    assert!(
        doubts.contains("too small to measure its effect")
            && doubts.contains("Repeat the trial run"),
        "{doubts}"
    );
    // Plain words: no backticks, no field names or codes.
    let words = format!(
        "{}\n{doubts}\n{said}",
        b.text("#step-solve .warnings").await
    );
    let code_like = code_words(&words);
    assert!(
        !words.contains('`') && code_like.is_empty(),
        "{code_like:?} in {words}"
    );
    crate::harness::job::shots(b, "solution-warning").await;
    crate::harness::job::scroll_to(b, "#step-solve .summary").await;
    crate::harness::job::shots(b, "solution-warning-summary").await;
    // The report's first page says the same: greyed, why, and what to do.
    b.click("nav [data-step=\"report\"]").await;
    let answer = b.text("#step-report .report-answer .doubts").await;
    assert!(answer.contains("Repeat the trial run"), "{answer}");
    b.wait_for("#step-report .report-answer .summary.unsure")
        .await;
}

async fn a_correction_with_uncertainty_reads_as_mass_and_angle_plus_or_minus_and_a_wide_one_greys_the_summary(
    stand: &Stand,
) {
    let b = &stand.browser;
    // The contract's example correction, rendered by the page's own module.
    let script = r#"
        const [done] = arguments;
        import('/static/js/steps/solve.js').then((m) => {
          const c = { plane: 'A', mass_g: 52.4, angle_deg: 141.0, unbalance_gmm: 18340,
                      uncertainty: { mass_g: [48.3, 56.5], angle_deg: [136.2, 145.8],
                                     covariance_g2: [[4.1, 0.3], [0.3, 3.2]] } };
          const wrap = { plane: 'A', mass_g: 10, angle_deg: 359, uncertainty: { mass_g: [9, 11.5], angle_deg: [355, 363] } };
          const lost = { plane: 'A', mass_g: 1486, angle_deg: 119.2, uncertainty: { mass_g: [0, 10304], angle_deg: [0, 360] } };
          const table = m.residualTable({ predicted_residual: [
            { speed_rpm: 1480, sensor: '1H', unit: 'um_pp', amplitude_before: 88, amplitude: 4.1, phase_deg: 213, amplitude_95: 7.9, used: true } ] });
          // The summary of an answer with a tight correction, then with a wide one, as the page shows them.
          const look = (corr) => {
            const box = document.body.appendChild(m.summaryBox({ corrections: [corr], warnings: [], condition_number: 1,
              summary: { rms_before: 88, rms_after: 4.1, max_before: 90, max_after: 5 } }));
            const v = [...box.querySelectorAll('.big .value')].map((e) => getComputedStyle(e).fontWeight);
            box.remove();
            return [box.className, v];
          };
          done([m.uncertaintyText(c), m.uncertaintyText(wrap), m.uncertaintyText(lost), table.querySelector('td.after95').textContent,
                look(c), look(lost)]);
        });
    "#;
    let got = js_async(b, script).await;
    assert_eq!(
        got,
        json!([
            "52.4 g ± 4.1 g, 141.0° ± 4.8°",
            "10.0 g ± 1.5 g, 359.0° ± 4.0°",
            "1486 g (0 to 10304 g), angle undetermined",
            "≤ 7.9",
            ["summary", ["700", "700", "700"]],
            ["summary unsure", ["400", "400", "400"]]
        ])
    );
}

async fn a_plane_with_fixed_places_shows_its_correction_split_over_two_places(stand: &Stand) {
    let b = &stand.browser;
    let mut example = common::example("pump-two-plane-exact.json");
    example["session"]["planes"][0]["positions"] = json!(12);
    import(b, &stand.dir, "places.json", &example).await;
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    // 30 g at 255° between places 8 (240°) and 9 (270°), by method 5.1.
    let (m1, m2) = split(30.0, 255.0, 240.0, 270.0);
    let want = format!("{m1:.1} g at place 8 (240.0°) + {m2:.1} g at place 9 (270.0°)");
    let inboard = b
        .text("#step-solve tr[data-plane=\"inboard\"] .corr-split")
        .await;
    assert_eq!(inboard, want);
    let outboard = b
        .text("#step-solve tr[data-plane=\"outboard\"] .corr-split")
        .await;
    assert_eq!(
        outboard, "–",
        "a plane without fixed places takes the weight at any angle"
    );
}

/// Method 5.1: a correction `m` at `theta` between places at `a1` and `a2`.
fn split(m: f64, theta: f64, a1: f64, a2: f64) -> (f64, f64) {
    let s = |deg: f64| deg.to_radians().sin();
    (
        m * s(a2 - theta) / s(a2 - a1),
        m * s(theta - a1) / s(a2 - a1),
    )
}

/// Whether the polar plot's "90°" label sits right of the centre (clockwise from 0° at the top).
async fn ninety_is_clockwise(b: &Browser) -> bool {
    let v = b
        .client
        .execute(
            "const t = [...document.querySelectorAll('#step-solve svg.polar .angle-label')]\
               .find((e) => e.textContent === '90°');\
             return Number(t.getAttribute('x')) > 150;",
            vec![],
        )
        .await
        .expect("the label is there");
    v == json!(true)
}

async fn polar_plot_angles_run_clockwise_for_phase_lag_and_counter_clockwise_for_lead(
    stand: &Stand,
) {
    let b = &stand.browser;
    for (phase, clockwise) in [("lag", true), ("lead", false)] {
        let mut example = common::example("pump-single-plane-noisy.json");
        example["session"]["conventions"] = json!({ "phase": phase });
        example["session"]["name"] = json!(format!("phase {phase}"));
        import(b, &stand.dir, &format!("{phase}.json"), &example).await;
        b.click("#step-runs button.go-solve").await;
        b.click("#step-solve button.solve").await;
        b.wait_for("#step-solve svg.polar").await;
        assert_eq!(ninety_is_clockwise(b).await, clockwise, "phase {phase}");
    }
}
