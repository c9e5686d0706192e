//! The free-decay page keeps its samples, step, damping law and offset, and
//! its answer, across a reload.

use serde_json::json;

use super::{
    answer_text, message_at, parsed, paste, press_and_wait, record_requests, reload,
    says_nothing_is_stored_on_the_service, sent_to, stale, starts_over, values,
};
use crate::harness::form::{choose, field, type_into};
use crate::harness::job::shots;
use crate::harness::stand::{post, Stand};
use crate::harness::steps::{fits_a_tablet, js};

const FIELDS: [&str; 4] = ["samples", "dt_s", "damping", "offset"];
const ANSWER: &str = "#step-decay .decay-result";

/// 10 Hz, ζ 0.02, sampled every 5 ms: 200 samples, as a spreadsheet's column (6 decimals).
fn decay_column() -> Vec<String> {
    let (f0, zeta, dt) = (10.0_f64, 0.02_f64, 0.005_f64);
    let w0 = 2.0 * std::f64::consts::PI * f0;
    let wd = w0 * (1.0 - zeta * zeta).sqrt();
    (0..200)
        .map(|k| {
            let t = k as f64 * dt;
            format!("{:.6}", (-zeta * w0 * t).exp() * (wd * t + 0.3).cos())
        })
        .collect()
}

pub async fn what_was_typed_survives_a_reload_and_is_sent_as_typed(stand: &Stand) {
    let b = &stand.browser;
    let here = |name: &str| format!("#step-decay {}", field(name));
    let column = decay_column();
    let samples: Vec<f64> = column.iter().map(|s| s.parse().unwrap()).collect();
    // Decimal commas, as a European spreadsheet copies a column.
    let pasted = column.join("\n").replace('.', ",");

    b.click("nav [data-step=\"decay\"]").await;
    type_into(b, &here("samples"), &pasted).await;
    type_into(b, &here("dt_s"), "0,005").await;
    type_into(b, &here("offset"), "0,01").await;
    // Not the default law: what is kept is what was chosen.
    choose(b, &here("damping"), "turbulent").await;
    press_and_wait(b, "decay", "button.identify", ".decay-result").await;
    let answered = answer_text(b, ANSWER).await;
    assert!(answered.contains("Initial decrement"), "{answered}");

    reload(b, "decay").await;
    let kept = values(b, "decay", &FIELDS).await;
    assert_eq!(
        kept[0], pasted,
        "the samples pasted are kept across a reload"
    );
    let number = |s: &str| s.replace(',', ".").parse::<f64>().ok();
    assert_eq!(number(&kept[1]), Some(0.005), "dt_s kept: {kept:?}");
    assert_eq!(kept[2], "turbulent", "the damping law kept: {kept:?}");
    assert_eq!(number(&kept[3]), Some(0.01), "the offset kept: {kept:?}");
    assert_eq!(
        answer_text(b, ANSWER).await,
        answered,
        "the answer shown before the reload is shown after it"
    );
    says_nothing_is_stored_on_the_service(b, "decay").await;

    // Sent again after the reload: the same request as typed, answered as the service answers it.
    record_requests(b).await;
    press_and_wait(b, "decay", "button.identify", ".decay-result").await;
    let sent = sent_to(b, "/identify/free-decay").await;
    let want = json!({ "samples": samples, "dt_s": 0.005, "damping": "turbulent", "offset": 0.01 });
    assert_eq!(sent, vec![want.clone()], "the request after a reload");
    let said = post(stand, "/api/v1/identify/free-decay", want).await;
    assert!(said["decrement"].is_number(), "{said}");
    assert_eq!(answer_text(b, ANSWER).await, answered, "{said}");
    let decrement = said["decrement"].as_f64().unwrap();
    let shown = js(
        b,
        "return document.querySelector('#step-decay table.decay-answer tr.decrement td').textContent",
    )
    .await;
    assert_eq!(shown, json!(format!("{decrement:.4}")), "{said}");

    js(b, "window.scrollTo(0, 0); return true").await;
    shots(b, "free-decay").await;
    fits_a_tablet(b, "free decay").await;

    // Start over: asked first; "no" keeps everything, "yes" empties the page for good.
    let emptied = ["", "", "viscous", ""];
    starts_over(b, "decay", &FIELDS, &kept, "samples", &emptied, ANSWER).await;
}

pub async fn a_heading_is_passed_over_and_a_time_column_refused(stand: &Stand) {
    let b = &stand.browser;
    let here = |name: &str| format!("#step-decay {}", field(name));
    b.click("nav [data-step=\"decay\"]").await;
    let got = parsed(
        b,
        "steps/decay.js",
        "parseSamples",
        &[
            "Amplitude, mm/s\n0,95\n0,81\n-0,2",
            "t\tx\n0.000\t0.95\n0.005\t0.81\n0.010\t0.59",
            "0.95 0.31 -0.62",
            "0.1, 0.2, 0.3, 0.4, 0.5\n0.6, 0.7",
            "0.000\t0.95\n0.005\t0.81\n0.010\t0.59",
        ],
    )
    .await;
    assert_eq!(
        got[0],
        json!({ "values": [0.95, 0.81, -0.2] }),
        "a heading: {got:?}"
    );
    let refused = got[1]["error"].as_str().unwrap_or_default();
    assert!(
        refused.starts_with("2 columns pasted (line 2: 0.000\t0.95)")
            && refused.contains("paste the samples' column alone"),
        "a time column beside the samples: {got:?}"
    );
    assert_eq!(
        got[2],
        json!({ "values": [0.95, 0.31, -0.62] }),
        "a row: {got:?}"
    );
    // Without a heading it was read as samples, times and samples alternating.
    let refused = got[4]["error"].as_str().unwrap_or_default();
    assert!(
        refused.starts_with("2 columns pasted (line 1: 0.000\t0.95)"),
        "a time column beside the samples, no heading: {got:?}"
    );
    assert_eq!(
        got[3],
        json!({ "values": [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7] }),
        "a row wrapped over lines: {got:?}"
    );

    // Through the page: the times copied beside the samples are refused at the field, nothing sent.
    let column = decay_column();
    let samples: Vec<f64> = column.iter().map(|s| s.parse().unwrap()).collect();
    let two: Vec<String> = column
        .iter()
        .enumerate()
        .map(|(k, x)| format!("{:.3}\t{x}", k as f64 * 0.005))
        .collect();
    record_requests(b).await;
    paste(
        b,
        &here("samples"),
        &format!("Time, s\tVelocity\n{}", two.join("\n")),
    )
    .await;
    type_into(b, &here("dt_s"), "0.005").await;
    b.click("#step-decay button.identify").await;
    b.wait_until(
        "the samples are marked",
        "return document.querySelector('#step-decay .samples-field').classList.contains('bad')",
    )
    .await;
    let said = message_at(b, &here("samples")).await;
    assert!(
        said.starts_with("2 columns pasted (line 2: 0.000"),
        "{said}"
    );
    assert_eq!(sent_to(b, "/identify/free-decay").await.len(), 0);

    // The column under its heading: read, sent, answered; ± said only where a figure has one.
    paste(
        b,
        &here("samples"),
        &format!("Velocity, mm/s\n{}", column.join("\n")),
    )
    .await;
    choose(b, &here("damping"), "turbulent").await;
    press_and_wait(b, "decay", "button.identify", ".decay-result").await;
    let sent = sent_to(b, "/identify/free-decay").await;
    assert_eq!(sent.len(), 1, "{sent:?}");
    assert_eq!(sent[0]["samples"], json!(samples));
    let shown = answer_text(b, ANSWER).await;
    assert!(
        !shown.contains('±') && !shown.contains("half-width"),
        "no figure has a ±, and none is explained: {shown}"
    );
    choose(b, &here("damping"), "viscous").await;
    press_and_wait(b, "decay", "button.identify", ".decay-result").await;
    let shown = answer_text(b, ANSWER).await;
    assert!(
        shown.contains('±') && shown.contains("95 % half-width"),
        "{shown}"
    );

    // A field changed after the answer: the answer is greyed as the one to the
    // input before, across a reload too, until it is sent again.
    assert_eq!(stale(b, "decay").await, Some(false));
    type_into(b, &here("offset"), "0,02").await;
    assert_eq!(stale(b, "decay").await, Some(true), "after a change");
    reload(b, "decay").await;
    assert_eq!(stale(b, "decay").await, Some(true), "after a reload");
    press_and_wait(b, "decay", "button.identify", ".decay-result").await;
    assert_eq!(stale(b, "decay").await, Some(false), "sent again");
}
