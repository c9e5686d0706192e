//! What a technician read walking a job through the form (new job, runs,
//! solve, check run, trim, report, machine, a trim job): a trim's residual
//! table called the check run's readings "As found"; a trim job with no
//! trial runs was told to fit its weights "all trial weights removed"; the
//! polar plots' titles ran the speed into the unit ("2950 rpm µm pk-pk");
//! the report's print time was in the browser's own format, unlike every
//! other time of the form; the set-up's fixed places gave angles with no
//! word of where they are counted from or which way; the acceptable
//! vibration was asked in "sensor units" when every sensor reads in one; a
//! trim job's check run was to be typed "with every trial weight off", to
//! "sharpen the influence coefficients", and its trim offered "the zero run
//! (all trial weights off)".

use serde_json::json;

use crate::harness::stand::{
    example_session, machine_with_coefficients, open_at_solve, post, Stand,
};
use crate::harness::steps::js;
use crate::said::answer::conventions::with_a_check_run;

/// The header cells of the first table matching `css`.
async fn headers(b: &crate::harness::Browser, css: &str) -> Vec<String> {
    let got = js(
        b,
        &format!(
            "const t = document.querySelector({}); return t ? [...t.querySelectorAll('thead th')].map((th) => th.textContent) : []",
            json!(css)
        ),
    )
    .await;
    serde_json::from_value(got).expect("header texts")
}

pub async fn what_a_technician_reads_walking_a_job(stand: &Stand) {
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    let session = with_a_check_run(stand, session).await;
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .trim li").await;

    // The trim adds to the check run: its readings are no "as found".
    let residual = headers(b, "#step-solve table.residual").await;
    assert_eq!(residual[2], "In run “check 1”", "{residual:?}");
    // In the options (folded: their text, not what is drawn).
    let limit = js(b, "return document.querySelector('#step-solve details.options label:has(input[data-field=\"options.limit\"]) span').textContent").await;
    assert_eq!(limit, "Acceptable vibration (largest reading, µm pk-pk)");
    let title = b.text("#step-solve .polar-fig figcaption").await;
    assert_eq!(title, "DE-H at 2950 rpm, µm pk-pk, phase lead");

    b.click("nav [data-step=\"report\"]").await;
    b.wait_for("#step-report article.report .report-runs").await;
    let residual = headers(b, "#step-report table.residual").await;
    assert_eq!(residual[2], "In run “check 1”", "{residual:?}");
    let header = b.text("#step-report article.report header p").await;
    let today = js(b, "return new Date().toISOString().slice(0, 10)").await;
    assert!(
        header.contains(&format!("printed {} ", today.as_str().unwrap()))
            && header.contains(" UTC"),
        "the print time as every other time of the form: {header}"
    );

    // The set-up's fixed places: angles from the mark, counted as the weights'.
    b.click("nav [data-step=\"setup\"]").await;
    let planes = headers(b, "#step-setup fieldset.planes table").await;
    assert!(
        planes.contains(&"or places at, ° from the mark".to_string()),
        "{planes:?}"
    );
    let hint = b.text("#step-setup fieldset.planes p.hint").await;
    assert!(hint.contains("counted like the weight angles"), "{hint}");

    // A trim job with only its zero run had no trial weights to remove.
    machine_with_coefficients(stand).await;
    let (mut trim, _) = example_session("pump-two-plane-exact.json");
    trim["name"] = json!("trim, zero run only");
    trim["machine"] = json!("PUMP-1");
    trim["runs"] = json!([trim["runs"][0].clone()]);
    trim["trim"] = json!({ "coefficients_from": { "machine": "PUMP-1" } });
    let created = post(stand, "/api/v1/sessions", trim).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve table.corrections").await;
    let fit = js(
        b,
        "return [...document.querySelectorAll('#step-solve h3')].map((e) => e.textContent).find((t) => t.startsWith('Fit these weights')) || ''",
    )
    .await;
    assert_eq!(fit, json!("Fit these weights to the rotor as found"));
    let residual = headers(b, "#step-solve table.residual").await;
    assert_eq!(residual[2], "As found", "{residual:?}");
    b.click("#step-solve button.check-run").await;
    let lead = b.text("#step-runs p.lead").await;
    assert!(
        !lead.contains("trial weight")
            && lead.contains("whether the stored coefficients of machine PUMP-1 still hold"),
        "{lead}"
    );
    b.click("#step-runs button.cancel").await;

    // A trim job with a check run: its trim may start from the zero run as found.
    super::trim::trim_check_words(
        stand,
        "trim with a check run",
        json!({ "coefficients_from": { "machine": "PUMP-1" } }),
    )
    .await;
    let zero = js(b, "return document.querySelector('#step-solve select.from-run option[value=\"\"]').textContent").await;
    assert_eq!(zero, "the zero run (as found)");
}
