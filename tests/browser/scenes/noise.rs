//! The correction's estimate without the noise's pull (`corrections[].
//! uncertainty.bias_corrected`, C* of method.md 8.11, session 13) in the
//! corrections table: a short line under the 95 % figures when the readings'
//! noise is stated, nothing when it is not; and its row in the results CSV.

use serde_json::{json, Value};

use super::options::solve_now;
use crate::harness::form::{field, type_into};
use crate::harness::stand::{post, Stand};
use crate::harness::steps::js;

/// The stated noise of the example's description: 2 % and 2°.
fn noise() -> Value {
    json!({ "amplitude_noise_pct": 2.0, "phase_noise_deg": 2.0 })
}

/// Per row of the corrections table: its plane, and the `corr-unbiased` line's text and title (if any).
async fn unbiased_lines(b: &crate::harness::Browser) -> Vec<(String, Option<(String, String)>)> {
    let got = js(
        b,
        "return [...document.querySelectorAll('#step-solve table.corrections tbody tr:not(.plane-warning)')].map((tr) => { \
           const u = tr.querySelector('td.corr-uncertainty .corr-unbiased'); \
           return [tr.dataset.plane, u ? [u.textContent, u.title] : null]; })",
    )
    .await;
    serde_json::from_value(got).expect("planes and lines")
}

/// `x` as the page shows it with one decimal (`fmt(x, 1)` for 1 ≤ x < 100, `fmtAngle`).
fn one_decimal(x: f64) -> String {
    format!("{x:.1}")
}

/// The multi-speed noisy compressor, stored through the API and solved on the
/// page without, then with the noise stated.
pub async fn the_noise_pull_is_shown_beside_the_fitted_weight_only_when_the_noise_is_stated(
    stand: &Stand,
) {
    let b = &stand.browser;
    let example = crate::common::example("compressor-multispeed-noisy.json");
    let session = &example["session"];
    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().expect("a stored session");
    b.open_fresh(&stand.server.url(&format!("/#session={id}&step=solve")))
        .await;
    b.wait_until(
        "the job is open",
        "return document.querySelector('#job-title').textContent.includes('stored') && !document.querySelector('#step-solve').hidden && !!document.querySelector('#step-solve button.solve')",
    )
    .await;

    // Without noise options the service gives no estimate, and the page adds nothing.
    let plain = post(stand, "/api/v1/solve", json!({ "session": session })).await;
    let planes = plain["corrections"].as_array().expect("corrections");
    assert_eq!(planes.len(), 3, "{plain}");
    for c in planes {
        assert!(c["uncertainty"].is_object(), "{c}");
        assert!(c["uncertainty"].get("bias_corrected").is_none(), "{c}");
    }
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve table.corrections tbody tr").await;
    let shown = unbiased_lines(b).await;
    assert_eq!(shown.len(), 3, "{shown:?}");
    assert!(shown.iter().all(|(_, line)| line.is_none()), "{shown:?}");
    assert_eq!(
        js(
            b,
            "return document.querySelectorAll('#step-solve .corr-unbiased').length"
        )
        .await,
        json!(0)
    );

    // With the noise stated: the estimate per plane, as the service gives it.
    let stated = post(
        stand,
        "/api/v1/solve",
        json!({ "session": session, "options": noise() }),
    )
    .await;
    b.click("#step-solve details.options summary").await;
    type_into(b, &field("options.amplitude_noise_pct"), "2").await;
    type_into(b, &field("options.phase_noise_deg"), "2").await;
    solve_now(b).await;
    let shown = unbiased_lines(b).await;
    let want = stated["corrections"].as_array().expect("corrections");
    assert_eq!(shown.len(), want.len(), "{shown:?}");
    for (c, (plane, line)) in want.iter().zip(&shown) {
        assert_eq!(c["plane"].as_str(), Some(plane.as_str()));
        let star = &c["uncertainty"]["bias_corrected"];
        let (m, a) = (
            star["mass_g"].as_f64().expect("bias_corrected.mass_g"),
            star["angle_deg"]
                .as_f64()
                .expect("bias_corrected.angle_deg"),
        );
        // One decimal is the page's rounding for masses from 1 to 100 g.
        assert!((1.0..100.0).contains(&m), "{star}");
        // The estimate differs from the weight to fit, or the line would say nothing new.
        let fitted = (
            c["mass_g"].as_f64().unwrap(),
            c["angle_deg"].as_f64().unwrap(),
        );
        assert!(
            one_decimal(m) != one_decimal(fitted.0)
                || one_decimal(a.rem_euclid(360.0)) != one_decimal(fitted.1.rem_euclid(360.0)),
            "{c}"
        );
        let (text, title) = line.as_ref().unwrap_or_else(|| panic!("{plane}: no line"));
        assert_eq!(
            text,
            &format!(
                "without the noise's pull: {} g at {}°",
                one_decimal(m),
                one_decimal(a.rem_euclid(360.0))
            ),
            "{plane}"
        );
        assert!(
            title.contains("towards zero") && title.contains("Mass and Angle"),
            "{title}"
        );
    }
    // The weight to fit stays the least-squares one, and the 95 % figures are still shown first.
    let first = b
        .text("#step-solve table.corrections tbody tr td.corr-uncertainty")
        .await;
    assert!(first.contains(" g ± "), "{first}");
    let on_page = crate::harness::form::corrections_on_page(b).await;
    for (c, (_, mass, _)) in want.iter().zip(&on_page) {
        assert!((mass - c["mass_g"].as_f64().unwrap()).abs() <= 0.051, "{c}");
    }
    crate::harness::job::scroll_to(b, "#step-solve table.corrections").await;
    crate::harness::job::shots(b, "solution-noise-pull").await;

    // The results CSV carries each estimate as a row of its own, in the same columns.
    let csv = b
        .client
        .execute_async(
            "const [done] = arguments; import('/static/js/steps/sessions.js').then((m) => done(m.resultsCsv()));",
            vec![],
        )
        .await
        .expect("the page's module runs");
    let csv = csv.as_str().expect("CSV text");
    let header = csv.lines().next().unwrap();
    let rows: Vec<&str> = csv
        .lines()
        .filter(|l| l.starts_with("\"bias_corrected\""))
        .collect();
    assert_eq!(rows.len(), want.len(), "{csv}");
    for (c, row) in want.iter().zip(&rows) {
        assert_eq!(row.split(',').count(), header.split(',').count(), "{row}");
        let m = c["uncertainty"]["bias_corrected"]["mass_g"]
            .as_f64()
            .unwrap();
        assert!(
            row.starts_with(&format!(
                "\"bias_corrected\",\"{}\",\"\",\"{m}\",",
                c["plane"].as_str().unwrap()
            )),
            "{row}"
        );
    }
}
