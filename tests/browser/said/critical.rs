//! A rotor read only above its critical speed (2450 rpm, read at 2800 to
//! 4400 rpm): the service still finds the critical, extrapolated, and says so
//! (`critical_outside_range`). The form left every critical outside the
//! speeds measured out ("No critical speed found inside the speeds
//! measured") and dropped the warning; it now shows the critical marked as
//! extrapolated, with the service's warning under it.

use fieldbal::balancing::model::Unit;
use serde_json::Value;

use crate::harness::stand::{open_at_solve, post, Stand};
use crate::harness::steps::js;

use super::jeffcott;

pub async fn a_critical_outside_the_speeds_measured_is_shown_as_extrapolated(stand: &Stand) {
    let b = &stand.browser;
    let rotor = jeffcott::Jeffcott::with(150.0, 2450.0, 0.05);
    let speeds = jeffcott::speeds(2800.0, 4400.0, 5);
    let session =
        serde_json::to_value(jeffcott::session(&[rotor], &speeds, Unit::UmPp, 0.0, 0)).unwrap();
    let said = post(
        stand,
        "/api/v1/identify/rotor",
        serde_json::json!({ "session": session }),
    )
    .await;
    let critical = said["results"][0]["critical_speed_rpm"]
        .as_f64()
        .unwrap_or_else(|| panic!("a result: {said}"));
    assert!((critical - 2450.0).abs() < 5.0, "{said}");
    let warned = said["warnings"]
        .as_array()
        .unwrap_or_else(|| panic!("warnings: {said}"))
        .iter()
        .find(|w| w["code"] == "critical_outside_range")
        .unwrap_or_else(|| panic!("a critical_outside_range warning: {said}"));
    let message = warned["message"].as_str().unwrap();

    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().expect("stored");
    open_at_solve(stand, id).await;
    b.click("#step-solve button.solve").await;
    b.wait_until(
        "the identification is drawn",
        "const x = document.querySelector('#step-solve .identification'); return !!x && !x.textContent.startsWith('Looking')",
    )
    .await;
    let shown: Value = js(
        b,
        "const r = document.querySelector('#step-solve .identification tr.ident-result'); if (!r) return document.querySelector('#step-solve .identification').textContent; const n = r.nextElementSibling; return [r.classList.contains('outside'), r.querySelector('td.critical').textContent, n && n.matches('.ident-warning') ? n.dataset.code : null, n ? n.textContent : null]",
    )
    .await;
    assert_eq!(shown[0], true, "the row is not marked outside: {shown}");
    assert_eq!(
        shown[1], "2450 outside the 2800–4400 rpm measured: extrapolated",
        "{shown}"
    );
    assert_eq!(shown[2], "critical_outside_range", "{shown}");
    assert_eq!(shown[3], Value::from(format!("⚠ {message}")), "{shown}");
}
