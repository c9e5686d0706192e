//! A trim job is solved with coefficients known before it, not from trial
//! runs, and its set-up step did not say so: it looked like any new job
//! until the runs step. It now says it is a trim job and whose coefficients
//! it is solved with: a machine's stored ones (which version), or supplied.
//! Its run checks say what they predict from: those coefficients, not "the
//! other runs"; its results CSV says what run it adds to and the total.

use serde_json::json;

use crate::harness::form::field;
use crate::harness::stand::machine_with_coefficients;
use crate::harness::stand::{example_session, get, open_at_solve, post, Stand};
use crate::harness::steps::js_async;
use crate::reopened::reopen_elsewhere;
use crate::said::answer::conventions::with_a_check_run;

/// The trim job begun on the machine page: the set-up names the machine and
/// its coefficients' version (the latest, as the solve will use).
pub async fn a_trim_job_from_a_machine_says_so_at_its_set_up(stand: &Stand) {
    let b = &stand.browser;
    machine_with_coefficients(stand).await;
    let latest = get(stand, "/api/v1/machines/PUMP-1/coefficients").await;
    let version = latest["version"].as_u64().expect("a version");
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.click("button.trim-job").await;
    b.wait_for(&field("name")).await;
    let want = format!(
        "Trim job: solved with the stored coefficients of machine PUMP-1, version {version} (the latest), instead of trial runs: a zero run is all it needs."
    );
    b.wait_until(
        "the set-up names the coefficients' version",
        &format!(
            "const e = document.querySelector('#step-setup .trim-note'); return !!e && e.textContent === {}",
            json!(want)
        ),
    )
    .await;
    // A job for the machine that is no trim job says nothing of the kind.
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    // The set-up of the trim job above is still shown while the new job's is
    // being fetched (the machine's latest session): wait for the new one,
    // which must have no note; a note that stays fails the wait.
    b.click("button.new-job").await;
    b.wait_until(
        "the new job's set-up says nothing of a trim",
        "return !!document.querySelector('#step-setup input[data-field=\"name\"]') && document.querySelectorAll('#step-setup .trim-note').length === 0",
    )
    .await;
}

/// A job stored with supplied coefficients, reopened at its (locked) set-up.
pub async fn a_trim_job_with_supplied_coefficients_says_so_at_its_set_up(stand: &Stand) {
    let b = &stand.browser;
    machine_with_coefficients(stand).await;
    let known = get(stand, "/api/v1/machines/PUMP-1/coefficients").await;
    let supplied = known["influence_coefficients"].clone();
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    session["name"] = json!("supplied trim");
    session["runs"] = json!([session["runs"][0].clone()]);
    session["trim"] = json!({ "influence_coefficients": supplied });
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    reopen_elsewhere(stand, &id, "setup").await;
    let said = b.text("#step-setup .trim-note").await;
    assert_eq!(
        said,
        "Trim job: solved with the 8 supplied influence coefficients, instead of trial runs: a zero run is all it needs."
    );
}

/// A trim job with a check run, stored with `trim` (the machine's stored
/// coefficients, or supplied ones), solved in the form: the run's check.
pub(super) async fn trim_check_words(stand: &Stand, name: &str, trim: serde_json::Value) -> String {
    let b = &stand.browser;
    let (pump, _) = example_session("pump-two-plane-exact.json");
    let checked = with_a_check_run(stand, pump).await;
    let mut session = checked.clone();
    let runs = checked["runs"].as_array().unwrap();
    session["name"] = json!(name);
    session["machine"] = json!("PUMP-1");
    session["runs"] = json!([runs[0].clone(), runs[runs.len() - 1].clone()]);
    session["trim"] = trim;
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
    b.click("#step-solve button.solve").await;
    b.text("#step-solve .run-check[data-run=\"check 1\"] p")
        .await
}

/// A trim job checks its runs against the coefficients it is solved with,
/// not against its other runs (it has none to predict from): the run-check
/// words said "what the other runs predict" in a trim job.
pub async fn a_trim_jobs_run_check_names_its_coefficients(stand: &Stand) {
    machine_with_coefficients(stand).await;
    let said = trim_check_words(
        stand,
        "stored trim",
        json!({ "coefficients_from": { "machine": "PUMP-1" } }),
    )
    .await;
    assert!(
        said.contains("what the stored coefficients of machine PUMP-1 (version")
            && said.contains("predict for its weights"),
        "{said}"
    );
    assert!(!said.contains("other runs"), "{said}");

    let known = get(stand, "/api/v1/machines/PUMP-1/coefficients").await;
    let supplied = known["influence_coefficients"].clone();
    let n = supplied.as_array().expect("coefficients").len();
    let said = trim_check_words(
        stand,
        "supplied trim",
        json!({ "influence_coefficients": supplied }),
    )
    .await;
    assert!(
        said.contains(&format!(
            "what the {n} supplied influence coefficients predict for its weights"
        )),
        "{said}"
    );
    assert!(!said.contains("other runs"), "{said}");
    // It had no trial runs to be clear, and did not estimate its coefficients.
    let b = &stand.browser;
    let none = b.text("#step-solve .warnings.none").await;
    assert_eq!(none, "No warnings.");
    let source = b.text("#step-solve p.coefficients-from").await;
    assert_eq!(
        source,
        format!(
            "Influence coefficients: the {n} supplied with the job (no trial runs in this job)."
        )
    );
    b.click("nav [data-step=\"report\"]").await;
    let source = b.text("#step-report p.coefficients-source").await;
    assert_eq!(
        source,
        format!("Supplied with the job ({n} coefficients), not estimated from its runs.")
    );
}

/// A trim's results CSV says which run's state its corrections add to
/// (`from_run`) and each plane's one replacing weight (`total`), after the
/// columns it had (`unit`, `note` unmoved): the file of a trim did not say
/// that its weights were to be added to those on the rotor.
pub async fn a_trims_results_csv_says_from_run_and_total(stand: &Stand) {
    let b = &stand.browser;
    machine_with_coefficients(stand).await;
    trim_check_words(
        stand,
        "stored trim",
        json!({ "coefficients_from": { "machine": "PUMP-1" } }),
    )
    .await;
    let got = js_async(
        b,
        "const [done] = arguments; \
         Promise.all([import('/static/js/steps/sessions.js'), import('/static/js/job/state.js')]).then(([m, s]) => { \
           const sol = s.state.solution; \
           done({ csv: m.resultsCsv(), from: sol.from_run, totals: sol.corrections.map((c) => [c.plane, String(c.total.mass_g), String(c.total.angle_deg)]) }); })",
    )
    .await;
    let csv = got["csv"].as_str().expect("CSV text");
    let from = got["from"].as_str().expect("a trim from a run");
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    assert_eq!(
        header[header.len() - 5..],
        [
            "\"unit\"",
            "\"note\"",
            "\"from_run\"",
            "\"total_mass_g\"",
            "\"total_angle_deg (with_rotation)\""
        ],
        "{csv}"
    );
    let corrections: Vec<Vec<&str>> = csv
        .lines()
        .filter(|l| l.starts_with("\"correction\""))
        .map(|l| l.split(',').collect())
        .collect();
    let totals = got["totals"].as_array().unwrap();
    assert_eq!(corrections.len(), totals.len(), "{csv}");
    for (row, total) in corrections.iter().zip(totals) {
        assert_eq!(row.len(), header.len(), "{row:?}");
        assert_eq!(row[1], format!("\"{}\"", total[0].as_str().unwrap()));
        assert_eq!(
            row[row.len() - 3..],
            [
                format!("\"{from}\""),
                format!("\"{}\"", total[1].as_str().unwrap()),
                format!("\"{}\"", total[2].as_str().unwrap())
            ],
            "{csv}"
        );
    }
    for row in csv.lines().filter(|l| l.starts_with("\"residual\"")) {
        assert!(row.ends_with(&format!("\"{from}\",\"\",\"\"")), "{row}");
    }
}
