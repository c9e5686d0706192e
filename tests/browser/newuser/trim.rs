//! A trim job from stored coefficients, reopened in a browser that never saw it.

use crate::harness::stand::{get, machine_with_coefficients, post, Stand};
use serde_json::json;

pub async fn a_trim_job_reopened_elsewhere_still_uses_the_stored_coefficients(stand: &Stand) {
    let b = &stand.browser;
    // A solved job for the machine, its coefficients pooled, then a trim job
    // with only its reference run solved from them: all through the API, as
    // another stand PC would have stored them.
    let mut session = machine_with_coefficients(stand).await;
    session["name"] = json!("PUMP-1 trim");
    session["runs"] = json!([session["runs"][0].clone()]);
    let trim = post(stand, "/api/v1/sessions", session).await;
    let trim = trim["id"].as_str().expect("stored").to_string();
    let solved = post(
        stand,
        &format!("/api/v1/sessions/{trim}/solutions"),
        json!({"coefficients_from": {"machine": "PUMP-1"}}),
    )
    .await;
    assert!(solved.to_string().contains("coefficients_from"), "{solved}");

    // This browser never saw the job: its local storage holds nothing of it.
    b.open_fresh(&stand.server.url(&format!("/#session={trim}&step=runs")))
        .await;
    b.wait_for("#step-runs td.value.amp").await;
    let lead = b.text("#step-runs p.lead").await;
    assert!(
        lead.starts_with("Trim job from the stored coefficients of machine PUMP-1"),
        "{lead}"
    );
    b.click("#step-runs button.go-solve").await;
    let said = b.text("#step-solve .coefficients-from").await;
    assert_eq!(
        said,
        "Influence coefficients: the stored ones of machine PUMP-1, version 1 (no trial runs in this job)."
    );
    assert!(!b.text("#step-solve .warnings").await.contains("trial runs"));
    // Solving again asks for the same coefficients, and is answered.
    b.click("#step-solve button.solve").await;
    let path = format!("/api/v1/sessions/{trim}/solutions");
    let mut solutions = get(stand, &path).await;
    for _ in 0..crate::harness::WAIT_POLLS {
        if solutions.as_array().is_some_and(|l| l.len() == 2) {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(100)).await;
        solutions = get(stand, &path).await;
    }
    let list = solutions.as_array().expect("a list");
    assert_eq!(list.len(), 2, "solved again: {solutions}");
    assert_eq!(
        list[1]["solution"]["coefficients_from"]["machine"], "PUMP-1",
        "{solutions}"
    );
    assert!(
        b.client
            .find(fantoccini::Locator::Css(
                "#step-solve .banner.error:not([hidden])"
            ))
            .await
            .is_err(),
        "no error shown"
    );
}
