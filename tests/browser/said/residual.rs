//! The residual-unbalance check (API 617 / API 684 test-stand acceptance,
//! `POST /api/v1/residual-unbalance`) from the form: twelve trial positions
//! pasted from a spreadsheet (tab-separated) are answered with the
//! service's residual, its 95 % interval, the angle with its convention,
//! the allowable and the verdict; a test the service refuses (three
//! positions) is refused at the readings in its words. The form had no page
//! for it: the check was reachable only through the API and the CLI.

use serde_json::{json, Value};

use crate::harness::form::{choose, field, type_into};
use crate::harness::job::sideways;
use crate::harness::stand::{post, Stand};
use crate::harness::steps::js;
use crate::tools::residual::{lines, paste, twelve_positions};

pub async fn a_residual_check_is_answered_as_the_service_says(stand: &Stand) {
    let b = &stand.browser;
    // The set-up has fields of the same names (conventions.phase): this page's.
    let here = |name: &str| format!("#step-residual {}", field(name));
    let request = twelve_positions();
    let said = post(stand, "/api/v1/residual-unbalance", request.clone()).await;
    let residual = said["residual_unbalance_gmm"]
        .as_f64()
        .unwrap_or_else(|| panic!("{said}"));
    let allowable = said["allowable_gmm"].as_f64().unwrap();
    let interval = &said["uncertainty"]["residual_unbalance_gmm"];
    assert_eq!(said["pass"], json!(true), "{said}");

    b.click("nav [data-step=\"residual\"]").await;
    paste(b, &lines(&request)).await;
    type_into(b, &here("plane"), request["plane"].as_str().unwrap()).await;
    type_into(b, &here("speed_rpm"), &request["speed_rpm"].to_string()).await;
    type_into(
        b,
        &here("journal_load_kg"),
        &request["journal_load_kg"].to_string().replace('.', ","),
    )
    .await;
    type_into(
        b,
        &here("trial.mass_g"),
        &request["trial"]["mass_g"].to_string(),
    )
    .await;
    type_into(
        b,
        &here("trial.radius_mm"),
        &request["trial"]["radius_mm"].to_string(),
    )
    .await;
    choose(
        b,
        "#step-residual select[data-field=\"conventions.phase\"]",
        "lag",
    )
    .await;
    choose(
        b,
        "#step-residual select[data-field=\"conventions.angle_direction\"]",
        "against_rotation",
    )
    .await;
    b.click("#step-residual button.check-residual").await;
    b.wait_for("#step-residual table.residual-answer").await;
    let cell = |row: &str| {
        format!("return document.querySelector('#step-residual table.residual-answer tr.{row} td').textContent")
    };
    let shown = |row: &'static str| {
        let script = cell(row);
        async move { js(b, &script).await.as_str().unwrap().to_string() }
    };
    let gmm = |x: &Value| format!("{:.0}", x.as_f64().unwrap());
    assert_eq!(
        shown("residual").await,
        format!(
            "{residual:.0} g·mm (95 %: {} to {} g·mm)",
            gmm(&interval[0]),
            gmm(&interval[1])
        ),
        "{said}"
    );
    assert_eq!(
        shown("allowable").await,
        format!("{allowable:.0} g·mm"),
        "{said}"
    );
    let verdict = shown("verdict").await;
    let pct = 100.0 * said["ratio"].as_f64().unwrap();
    assert_eq!(
        verdict,
        format!("Pass: residual {pct:.0} % of the allowable"),
        "{said}"
    );
    let angle_label: Value = js(
        b,
        "return document.querySelector('#step-residual table.residual-answer tr.angle th').textContent",
    )
    .await;
    assert!(
        angle_label.as_str().unwrap().contains("against rotation"),
        "the angle says its convention: {angle_label}"
    );
    let angle = shown("angle").await;
    let want = format!("{:.1}°", said["residual_angle_deg"].as_f64().unwrap());
    assert!(angle.starts_with(&want), "{angle} for {said}");

    // The page with its answer fits a 1024×768 screen without scrolling sideways.
    b.viewport(1024, 768).await;
    let (over, culprits) = sideways(b).await;
    assert!(
        over <= 0,
        "the residual page scrolls sideways by {over} px: {culprits}"
    );
    b.screenshot("residual-check-1024").await;
    b.viewport(1280, 800).await;

    // Three positions: the service's refusal, at the readings.
    let mut three = request.clone();
    three["readings"] = json!(request["readings"].as_array().unwrap()[..3].to_vec());
    let refused = post(stand, "/api/v1/residual-unbalance", three.clone()).await;
    let field_named = refused["error"]["field"]
        .as_str()
        .unwrap_or_else(|| panic!("{refused}"));
    assert!(field_named.starts_with("readings"), "{refused}");
    let message = refused["error"]["message"].as_str().unwrap();
    paste(b, &lines(&three)).await;
    b.click("#step-residual button.check-residual").await;
    b.wait_until(
        "the refusal is shown at the readings",
        "return !document.querySelector('#step-residual table.residual-answer') && !!document.querySelector('#step-residual .field.bad [data-field=\"readings\"]')",
    )
    .await;
    let at: Value = js(
        b,
        "return document.querySelector('#step-residual [data-field=\"readings\"]').closest('.field').querySelector('.msg').textContent",
    )
    .await;
    assert_eq!(at, Value::from(message), "{refused}");
}
