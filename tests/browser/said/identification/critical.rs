//! A rotor read only above its critical speed (2450 rpm, read at 2800 to
//! 4400 rpm): the service still finds the critical, extrapolated, and says so
//! (`critical_outside_range`). The form left every critical outside the
//! speeds measured out ("No critical speed found inside the speeds
//! measured") and dropped the warning; it now shows the critical marked as
//! extrapolated, with the service's warning under it.
//!
//! Then the trial run is corrected in the grid to readings of a rotor whose
//! critical is 3600 rpm, inside the speeds, and solved again: the form showed
//! the first answer again (it kept the identification of a job by its id and
//! number of runs, both unchanged by a corrected run); it now asks again.

use fieldbal::balancing::model::Unit;
use serde_json::Value;

use crate::harness::form::{field, store, type_into};
use crate::harness::stand::{get, open_at_solve, post, Stand};
use crate::harness::steps::js;

use super::jeffcott;

pub async fn a_critical_outside_the_speeds_measured_is_shown_as_extrapolated(stand: &Stand) {
    let b = &stand.browser;
    let speeds = jeffcott::speeds(2800.0, 4400.0, 5);
    let (session, said) = super::identified(stand, 0.05, &speeds, 0.0, 0).await;
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
    // The table with its longest cells (the extrapolated note, the margin
    // with API 684's) and the warning row fits a tablet held upright.
    crate::harness::steps::fits_a_tablet(b, "identification").await;

    a_corrected_run_is_identified_again(stand, id, &session, &speeds).await;
}

/// Correct the trial run to `zero + (trial₂ − zero₂)` of a rotor critical at
/// 3600 rpm (its influence coefficients, over this job's zero run), solve
/// again, and compare the page with the service's answer for the stored job.
async fn a_corrected_run_is_identified_again(
    stand: &Stand,
    id: &str,
    session: &Value,
    speeds: &[f64],
) {
    let b = &stand.browser;
    let other = jeffcott::Jeffcott::with(150.0, 3600.0, 0.05);
    let other =
        serde_json::to_value(jeffcott::session(&[other], speeds, Unit::UmPp, 0.0, 0)).unwrap();
    let xy = |r: &Value| {
        let (a, p) = (
            r["amplitude"].as_f64().unwrap(),
            r["phase_deg"].as_f64().unwrap().to_radians(),
        );
        (a * p.cos(), a * p.sin())
    };
    b.click("nav [data-step=\"runs\"]").await;
    b.click("#step-runs th.run[data-run=\"trial\"] button.correct")
        .await;
    for i in 0..speeds.len() {
        let z = xy(&session["runs"][0]["readings"][i]);
        let z2 = xy(&other["runs"][0]["readings"][i]);
        let t2 = xy(&other["runs"][1]["readings"][i]);
        let (x, y) = (z.0 + t2.0 - z2.0, z.1 + t2.1 - z2.1);
        let path = format!("runs[1].readings[{i}]");
        type_into(
            b,
            &field(&format!("{path}.amplitude")),
            &format!("{:.4}", x.hypot(y)),
        )
        .await;
        let phase = y.atan2(x).to_degrees().rem_euclid(360.0);
        type_into(
            b,
            &field(&format!("{path}.phase_deg")),
            &format!("{phase:.2}"),
        )
        .await;
    }
    store(b).await;
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let stored = stored.get("session").cloned().unwrap_or(stored);
    let said = post(
        stand,
        "/api/v1/identify/rotor",
        serde_json::json!({ "session": stored }),
    )
    .await;
    let critical = said["results"][0]["critical_speed_rpm"]
        .as_f64()
        .unwrap_or_else(|| panic!("a result: {said}"));
    assert!((critical - 3600.0).abs() < 20.0, "{said}");

    b.click("nav [data-step=\"solve\"]").await;
    b.click("#step-solve button.solve").await;
    b.wait_until(
        "the identification is drawn again",
        "const x = document.querySelector('#step-solve .identification'); return !!x && !x.textContent.startsWith('Looking')",
    )
    .await;
    let shown: Value = js(
        b,
        "const r = document.querySelector('#step-solve .identification tr.ident-result'); return [r.classList.contains('outside'), r.querySelector('td.critical').textContent]",
    )
    .await;
    assert_eq!(
        shown,
        serde_json::json!([false, format!("{critical:.0}")]),
        "the corrected job's critical, as the service finds it"
    );
}

/// A critical speed and damping ratio read from noisy readings: the service
/// gives each with its 95 % half-width (`critical_speed_resolution_rpm`,
/// `damping_ratio_resolution`), as the free-decay page shows its figures. The
/// identification table showed the bare numbers ("2450", "0.050"), as if
/// known to the last digit; each now carries its "± half-width".
pub async fn a_critical_speed_is_shown_with_its_half_width(stand: &Stand) {
    let b = &stand.browser;
    let speeds = jeffcott::speeds(1800.0, 3200.0, 8);
    let (session, said) = super::identified(stand, 0.05, &speeds, 0.02, 7).await;
    let r = &said["results"][0];
    let critical = r["critical_speed_rpm"]
        .as_f64()
        .unwrap_or_else(|| panic!("a result: {said}"));
    let critical_hw = r["critical_speed_resolution_rpm"]
        .as_f64()
        .unwrap_or_else(|| panic!("a half-width: {said}"));
    assert!(
        critical_hw >= 1.0,
        "resolved to a whole rpm or worse: {said}"
    );
    assert!(
        r.get("damping_ratio_bound").is_none(),
        "a resolved damping: {said}"
    );
    let zeta = r["damping_ratio"].as_f64().unwrap();
    let zeta_hw = r["damping_ratio_resolution"].as_f64().unwrap();
    assert!(zeta_hw >= 0.001, "{said}");

    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().expect("stored");
    open_at_solve(stand, id).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .identification td.critical").await;
    let cells: Value = js(
        b,
        "const r = document.querySelector('#step-solve .identification tr.ident-result'); return [r.querySelector('td.critical').textContent, r.querySelector('td.damping').textContent]",
    )
    .await;
    // Both to the half-width's second significant digit.
    let shown = |x: f64, hw: f64| {
        let d = (1.0 - hw.log10().floor()).max(0.0) as usize;
        format!("{x:.d$} ± {hw:.d$}")
    };
    assert_eq!(
        cells[0],
        Value::from(shown(critical, critical_hw)),
        "{said}"
    );
    assert_eq!(cells[1], Value::from(shown(zeta, zeta_hw)), "{said}");
}
