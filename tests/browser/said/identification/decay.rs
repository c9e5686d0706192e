//! The free-decay page (`POST /api/v1/identify/free-decay`, method §7): a
//! decay pasted as a spreadsheet column, with decimal commas, is answered
//! with the service's frequency and damping ratio, in Hz and rpm; a sampling
//! step the service refuses is refused beside its field in the service's
//! words. The form had no page for it. A column typed to six decimals is
//! all but exact: its half-widths, offset and fit RMS read "< 0.001 Hz",
//! "0.0000", "< 0.0001", not "5.9e-8 Hz", "-2.8888e-8", "2.79e-7".

use serde_json::{json, Value};

use crate::harness::form::{choose, field, type_into};
use crate::harness::job::sideways;
use crate::harness::stand::{post, Stand};
use crate::harness::steps::js;

/// The first number of a shown cell ("10.001 Hz ± 0.002 Hz" → 10.001).
fn leading(cell: &str) -> f64 {
    cell.split_whitespace()
        .next()
        .and_then(|t| t.parse().ok())
        .unwrap_or_else(|| panic!("no number leads {cell:?}"))
}

pub async fn a_pasted_free_decay_is_answered_as_the_service_says(stand: &Stand) {
    let b = &stand.browser;
    // 10 Hz, ζ 0.02, sampled every 5 ms: 200 samples, 10 periods.
    let (f0, zeta, dt) = (10.0_f64, 0.02_f64, 0.005_f64);
    let w0 = 2.0 * std::f64::consts::PI * f0;
    let wd = w0 * (1.0 - zeta * zeta).sqrt();
    let column: Vec<String> = (0..200)
        .map(|k| {
            let t = k as f64 * dt;
            format!("{:.6}", (-zeta * w0 * t).exp() * (wd * t + 0.3).cos())
        })
        .collect();
    // What the service says of the same samples, as typed.
    let samples: Vec<f64> = column.iter().map(|s| s.parse().unwrap()).collect();
    let said = post(
        stand,
        "/api/v1/identify/free-decay",
        json!({ "samples": samples, "dt_s": dt, "damping": "viscous" }),
    )
    .await;
    let undamped = said["undamped_frequency_hz"].as_f64().expect("{said}");
    let damped = said["damped_frequency_hz"].as_f64().expect("{said}");
    let ratio = said["damping_ratio"].as_f64().expect("{said}");
    assert!(
        (undamped - f0).abs() < 0.01 && (ratio - zeta).abs() < 1e-3,
        "{said}"
    );

    b.click("nav [data-step=\"decay\"]").await;
    // A spreadsheet column, decimal commas as a European one copies it.
    let pasted = column.join("\n").replace('.', ",");
    type_into(b, "textarea[data-field=\"samples\"]", &pasted).await;
    type_into(b, &field("dt_s"), "0,005").await;
    choose(b, "select[data-field=\"damping\"]", "viscous").await;
    b.click("#step-decay button.identify").await;
    b.wait_for("#step-decay table.decay-answer").await;
    // What ± means is said (the service's resolutions are 95 % half-widths).
    let pm = b.text("#step-decay .decay-pm").await;
    assert!(pm.contains("95 % half-width"), "{pm}");
    let cell = |row: &str| {
        format!("return document.querySelector('#step-decay table.decay-answer tr.{row} td').textContent")
    };
    let shown = |row: &'static str| {
        let script = cell(row);
        async move { js(b, &script).await.as_str().unwrap().to_string() }
    };
    let hz = leading(&shown("undamped-hz").await);
    assert!(
        (hz - undamped).abs() <= 1e-4 * undamped,
        "{hz} Hz for {said}"
    );
    let rpm = leading(&shown("undamped-rpm").await);
    assert!(
        (rpm - 60.0 * undamped).abs() <= 1e-4 * 60.0 * undamped,
        "{rpm} rpm for {said}"
    );
    let hz = leading(&shown("damped-hz").await);
    assert!(
        (hz - damped).abs() <= 1e-4 * damped,
        "{hz} Hz damped for {said}"
    );
    // All but exact: no half-width reaches the decimals shown.
    let res = said["frequency_resolution_hz"].as_f64().expect("{said}");
    let zeta_res = said["damping_ratio_resolution"].as_f64().expect("{said}");
    let (offset, rms) = (
        said["offset"].as_f64().unwrap(),
        said["fit_rms"].as_f64().unwrap(),
    );
    assert!(
        res < 1e-3 / 60.0 && zeta_res < 1e-4 && offset.abs() < 5e-5 && rms < 1e-4,
        "{said}"
    );
    let mut cells = Vec::new();
    for row in ["undamped-hz", "undamped-rpm", "zeta", "offset", "fit-rms"] {
        cells.push(shown(row).await);
    }
    assert_eq!(
        cells,
        [
            format!("{undamped:.3} Hz ± < 0.001 Hz"),
            format!("{:.1} rpm ± < 0.1 rpm", 60.0 * undamped),
            format!("{ratio:.4} ± < 0.0001"),
            "0.0000".to_string(),
            "< 0.0001".to_string(),
        ],
        "{said}"
    );
    let table = b.text("#step-decay table.decay-answer").await;
    assert!(
        !table.contains("e-") && !table.contains("e+"),
        "no figure in exponent form: {table}"
    );

    // Scattered samples: each figure to its half-width's second significant
    // digit, at most the decimals above (0.001 Hz, 0.1 rpm, 0.0001 for ζ).
    let scattered: Vec<f64> = samples
        .iter()
        .enumerate()
        .map(|(k, x)| x + 0.05 * ((k * 7919 % 101) as f64 / 50.0 - 1.0))
        .collect();
    let column: Vec<String> = scattered.iter().map(|x| format!("{x:.6}")).collect();
    let scattered: Vec<f64> = column.iter().map(|s| s.parse().unwrap()).collect();
    let said = post(
        stand,
        "/api/v1/identify/free-decay",
        json!({ "samples": scattered, "dt_s": dt, "damping": "viscous" }),
    )
    .await;
    type_into(b, "textarea[data-field=\"samples\"]", &column.join("\n")).await;
    b.click("#step-decay button.identify").await;
    let before = cells[0].clone();
    b.wait_until(
        "the scattered samples' answer",
        &format!("return document.querySelector('#step-decay tr.undamped-hz td').textContent !== {before:?}"),
    )
    .await;
    let figure = |k: &str| said[k].as_f64().unwrap_or_else(|| panic!("{k}: {said}"));
    let pm = |x: f64, r: f64, most: i32, unit: &str| {
        assert!(r >= 10f64.powi(-most), "a half-width to show: {said}");
        let d = most.min((1 - r.log10().floor() as i32).max(0)) as usize;
        format!("{x:.d$}{unit} ± {r:.d$}{unit}")
    };
    let (hz, res) = (
        figure("undamped_frequency_hz"),
        figure("frequency_resolution_hz"),
    );
    let mut cells = Vec::new();
    for row in ["undamped-hz", "undamped-rpm", "zeta"] {
        cells.push(shown(row).await);
    }
    assert_eq!(
        cells,
        [
            pm(hz, res, 3, " Hz"),
            pm(60.0 * hz, 60.0 * res, 1, " rpm"),
            pm(
                figure("damping_ratio"),
                figure("damping_ratio_resolution"),
                4,
                ""
            ),
        ],
        "{said}"
    );

    // The page with its answer fits a 1024×768 screen without scrolling sideways.
    b.viewport(1024, 768).await;
    let (over, culprits) = sideways(b).await;
    assert!(
        over <= 0,
        "the free-decay page scrolls sideways by {over} px: {culprits}"
    );
    b.screenshot("free-decay-1024").await;
    b.viewport(1280, 800).await;

    // A step of 0 s: the service's refusal, beside the field it names.
    let refused = post(
        stand,
        "/api/v1/identify/free-decay",
        json!({ "samples": samples, "dt_s": 0.0, "damping": "viscous" }),
    )
    .await;
    assert_eq!(refused["error"]["field"], "dt_s", "{refused}");
    let message = refused["error"]["message"].as_str().unwrap();
    type_into(b, &field("dt_s"), "0").await;
    b.click("#step-decay button.identify").await;
    b.wait_until(
        "the refusal is shown at dt_s",
        "return !document.querySelector('#step-decay table.decay-answer') && !!document.querySelector('#step-decay .field.bad [data-field=\"dt_s\"]')",
    )
    .await;
    let at: Value = js(
        b,
        "return document.querySelector('#step-decay [data-field=\"dt_s\"]').closest('.field').querySelector('.msg').textContent",
    )
    .await;
    assert_eq!(at, Value::from(message), "{refused}");
}
