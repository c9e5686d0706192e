//! A rotor without damping, read at 9 speeds about its critical: the service
//! answers the damping ratio as an upper bound and the amplification factor
//! as a lower one (`*_bound`), since the readings cannot tell the damping
//! from zero. The form showed both as plain numbers (an amplification factor
//! of some thousands as if measured), then the bounds with a note in its own
//! words: the service's `damping_unresolved` warning, with the fitted ratio
//! and its resolution, is now shown as said, under the result it concerns.

use serde_json::Value;

use crate::harness::stand::{open_at_solve, post, Stand};
use crate::harness::steps::js;

use super::jeffcott;

pub async fn an_unresolved_damping_is_shown_as_a_bound(stand: &Stand) {
    let b = &stand.browser;
    // As tests/identification/rotor.rs: 2450 rpm, between the speeds of the grid.
    let speeds = jeffcott::speeds(1200.0, 3600.0, 9);
    let (session, said) = super::identified(stand, 0.0, &speeds, 0.0, 0).await;
    let r = &said["results"][0];
    assert_eq!(r["damping_ratio_bound"], "upper", "{said}");
    assert_eq!(r["amplification_factor_bound"], "lower", "{said}");
    let zeta = r["damping_ratio"].as_f64().unwrap();
    let factor = r["amplification_factor"].as_f64().unwrap();
    let warned = said["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| w["code"] == "damping_unresolved")
        .unwrap_or_else(|| panic!("a damping_unresolved warning: {said}"));
    let message = warned["message"].as_str().unwrap();

    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().expect("stored");
    open_at_solve(stand, id).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .identification td.critical").await;
    let row: Value = js(
        b,
        "return [...document.querySelectorAll('#step-solve .identification tbody tr.ident-result td')].map((t) => t.textContent)",
    )
    .await;
    let cells: Vec<&str> = row
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert_eq!(&cells[..3], &["1H", "A", "2450"], "{row}");
    let number = |cell: &str, sign: &str| -> f64 {
        let rest = cell
            .strip_prefix(sign)
            .unwrap_or_else(|| panic!("{cell:?} is not given as “{sign}…”: {row}"));
        rest.trim().parse().unwrap_or_else(|_| panic!("{cell:?}"))
    };
    let shown = number(cells[3], "≤ ");
    assert!((shown - zeta).abs() <= 0.05 * zeta, "ζ {shown} for {zeta}");
    let shown = number(cells[4], "≥ ");
    assert!(
        (shown - factor).abs() <= 0.5 + 1e-3 * factor,
        "AF {shown} for {factor}"
    );
    // The service's own words, in the row right under the result.
    let note: Value = js(
        b,
        "const r = document.querySelector('#step-solve .identification tr.ident-result'); const n = r.nextElementSibling; return n && n.matches('.ident-warning.damping-unresolved') ? n.textContent : null",
    )
    .await;
    assert_eq!(note, Value::from(format!("⚠ {message}")), "{said}");
}
