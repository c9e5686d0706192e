//! The residual-check page keeps its readings, plane, speed, load, trial
//! weight and conventions, and its answer, across a reload.

use serde_json::{json, Value};

use super::{
    answer_text, parsed, press_and_wait, record_requests, reload,
    says_nothing_is_stored_on_the_service, sent_to, stale, starts_over, values,
};
use crate::harness::form::{choose, field, type_into};
use crate::harness::job::shots;
use crate::harness::stand::{post, Stand};
use crate::harness::steps::{fits_a_tablet, js};

const FIELDS: [&str; 8] = [
    "readings",
    "plane",
    "speed_rpm",
    "journal_load_kg",
    "trial.mass_g",
    "trial.radius_mm",
    "conventions.phase",
    "conventions.angle_direction",
];
const ANSWER: &str = "#step-residual .residual-result";

/// Paste `text` into the readings (a spreadsheet's tabs cannot be typed: a
/// typed Tab moves the focus).
pub(crate) async fn paste(b: &crate::harness::Browser, text: &str) {
    super::paste(b, "#step-residual textarea[data-field=\"readings\"]", text).await;
}

/// The request of tests/data/residual: twelve positions of plane "left".
pub(crate) fn twelve_positions() -> Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/residual/left-plane-12-positions.json"
    );
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// The request's readings as a spreadsheet copies them: a line each,
/// position angle, amplitude and phase separated by tabs.
pub(crate) fn lines(request: &Value) -> String {
    let lines: Vec<String> = request["readings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| format!("{}\t{}\t{}", r["angle_deg"], r["amplitude"], r["phase_deg"]))
        .collect();
    lines.join("\n")
}

pub async fn what_was_typed_survives_a_reload_and_is_sent_as_typed(stand: &Stand) {
    let b = &stand.browser;
    let here = |name: &str| format!("#step-residual {}", field(name));
    let mut request = twelve_positions();
    // Not the defaults: what is kept is what was chosen.
    request["conventions"] = json!({ "phase": "lead", "angle_direction": "with_rotation" });
    let pasted = lines(&request);

    b.click("nav [data-step=\"residual\"]").await;
    paste(b, &pasted).await;
    type_into(b, &here("plane"), request["plane"].as_str().unwrap()).await;
    type_into(b, &here("speed_rpm"), &request["speed_rpm"].to_string()).await;
    let load = request["journal_load_kg"].to_string().replace('.', ",");
    type_into(b, &here("journal_load_kg"), &load).await;
    let mass = request["trial"]["mass_g"].to_string();
    type_into(b, &here("trial.mass_g"), &mass).await;
    let radius = request["trial"]["radius_mm"].to_string();
    type_into(b, &here("trial.radius_mm"), &radius).await;
    choose(b, &here("conventions.phase"), "lead").await;
    choose(b, &here("conventions.angle_direction"), "with_rotation").await;
    press_and_wait(b, "residual", "button.check-residual", ".residual-result").await;
    let answered = answer_text(b, ANSWER).await;
    assert!(answered.contains("with rotation"), "{answered}");

    reload(b, "residual").await;
    let kept = values(b, "residual", &FIELDS).await;
    assert_eq!(
        kept[0], pasted,
        "the readings pasted are kept across a reload"
    );
    let number = |s: &str| s.replace(',', ".").parse::<f64>().ok();
    assert_eq!(kept[1], request["plane"].as_str().unwrap(), "{kept:?}");
    for (k, want) in [
        (2, &request["speed_rpm"]),
        (3, &request["journal_load_kg"]),
        (4, &request["trial"]["mass_g"]),
        (5, &request["trial"]["radius_mm"]),
    ] {
        assert_eq!(
            number(&kept[k]),
            want.as_f64(),
            "{} kept: {kept:?}",
            FIELDS[k]
        );
    }
    assert_eq!(kept[6..], ["lead", "with_rotation"], "{kept:?}");
    assert_eq!(
        answer_text(b, ANSWER).await,
        answered,
        "the answer shown before the reload is shown after it"
    );
    says_nothing_is_stored_on_the_service(b, "residual").await;

    // Sent again after the reload: the same request, answered as the service answers it.
    record_requests(b).await;
    press_and_wait(b, "residual", "button.check-residual", ".residual-result").await;
    let sent = sent_to(b, "/residual-unbalance").await;
    assert_eq!(sent.len(), 1, "{sent:?}");
    let number_at = |v: &Value, k: &str| v[k].as_f64();
    let got = &sent[0];
    assert_eq!(got["plane"], request["plane"], "{got}");
    for k in ["speed_rpm", "journal_load_kg"] {
        assert_eq!(number_at(got, k), number_at(&request, k), "{k}: {got}");
    }
    for k in ["mass_g", "radius_mm"] {
        assert_eq!(
            number_at(&got["trial"], k),
            number_at(&request["trial"], k),
            "trial.{k}: {got}"
        );
    }
    assert_eq!(got["conventions"], request["conventions"], "{got}");
    assert_eq!(
        positions(&got["readings"]),
        positions(&request["readings"]),
        "the readings sent after a reload"
    );
    assert_eq!(answer_text(b, ANSWER).await, answered);
    let said = post(stand, "/api/v1/residual-unbalance", request.clone()).await;
    let residual = said["residual_unbalance_gmm"]
        .as_f64()
        .unwrap_or_else(|| panic!("{said}"));
    assert!(
        answered.contains(&format!("{residual:.0} g·mm")),
        "{answered} for {said}"
    );

    js(b, "window.scrollTo(0, 0); return true").await;
    shots(b, "residual-check").await;
    fits_a_tablet(b, "residual check").await;

    // Start over: asked first; "no" keeps everything, "yes" empties the page for good.
    let emptied = ["", "", "", "", "", "", "lag", "against_rotation"];
    starts_over(b, "residual", &FIELDS, &kept, "readings", &emptied, ANSWER).await;
}

/// Each reading's angle, amplitude and phase.
fn positions(readings: &Value) -> Vec<[Option<f64>; 3]> {
    readings
        .as_array()
        .expect("readings")
        .iter()
        .map(|r| {
            [
                r["angle_deg"].as_f64(),
                r["amplitude"].as_f64(),
                r["phase_deg"].as_f64(),
            ]
        })
        .collect()
}

pub async fn a_heading_and_degree_signs_are_passed_over(stand: &Stand) {
    let b = &stand.browser;
    let here = |name: &str| format!("#step-residual {}", field(name));
    b.click("nav [data-step=\"residual\"]").await;
    let got = parsed(
        b,
        "steps/residual.js",
        "parsePositions",
        &[
            "Angle\tAmplitude\tPhase\n0°\t2.453\t335.7°\n30°\t2,59\t356.3°",
            "0 2.453 335.7\n30 2.59 356.3",
            "0 2.453 335.7\n\n30 2.59\n60 2.618 15.5",
        ],
    )
    .await;
    assert_eq!(got[0]["readings"], got[1]["readings"], "{got:?}");
    assert_eq!(
        got[1]["readings"],
        json!([
            { "angle_deg": 0, "amplitude": 2.453, "phase_deg": 335.7 },
            { "angle_deg": 30, "amplitude": 2.59, "phase_deg": 356.3 },
        ])
    );
    // A phase missing on one line: which line, counted as pasted (the empty line too).
    assert_eq!(
        got[2]["error"],
        json!("line 3 has no phase, line 1 has one: a phase on every line or none"),
        "{got:?}"
    );

    // Through the page: the twelve positions under a heading, angles and phases with their sign.
    let request = twelve_positions();
    let lines: Vec<String> = request["readings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            format!(
                "{}°\t{}\t{}°",
                r["angle_deg"], r["amplitude"], r["phase_deg"]
            )
        })
        .collect();
    paste(
        b,
        &format!("Trial angle\tAmplitude, µm\tPhase\n{}", lines.join("\n")),
    )
    .await;
    type_into(b, &here("speed_rpm"), &request["speed_rpm"].to_string()).await;
    let load = request["journal_load_kg"].to_string();
    type_into(b, &here("journal_load_kg"), &load).await;
    let mass = request["trial"]["mass_g"].to_string();
    type_into(b, &here("trial.mass_g"), &mass).await;
    let radius = request["trial"]["radius_mm"].to_string();
    type_into(b, &here("trial.radius_mm"), &radius).await;
    record_requests(b).await;
    press_and_wait(b, "residual", "button.check-residual", ".residual-result").await;
    let sent = sent_to(b, "/residual-unbalance").await;
    assert_eq!(sent.len(), 1, "{sent:?}");
    assert_eq!(
        positions(&sent[0]["readings"]),
        positions(&request["readings"])
    );
    let said = post(stand, "/api/v1/residual-unbalance", request.clone()).await;
    let residual = said["residual_unbalance_gmm"]
        .as_f64()
        .unwrap_or_else(|| panic!("{said}"));
    let shown = answer_text(b, ANSWER).await;
    assert!(
        shown.contains(&format!("{residual:.0} g·mm")),
        "{shown} for {said}"
    );
    assert_eq!(stale(b, "residual").await, Some(false));
    type_into(b, &here("plane"), "left").await;
    assert_eq!(
        stale(b, "residual").await,
        Some(true),
        "a field changed after the answer"
    );

    // A refusal names the line a reading was pasted on, not its index from 0.
    let mut gap = request.clone();
    gap["readings"].as_array_mut().unwrap().remove(5);
    let refused = post(stand, "/api/v1/residual-unbalance", gap).await;
    let message = refused["error"]["message"]
        .as_str()
        .unwrap_or_else(|| panic!("{refused}"));
    assert!(message.contains("readings[0]"), "{refused}");
    let mut lines = lines.clone();
    lines.remove(5);
    paste(b, &lines.join("\n")).await;
    b.click("#step-residual button.check-residual").await;
    b.wait_until(
        "the refusal is at the readings",
        "return document.querySelector('#step-residual .readings-field').classList.contains('bad')",
    )
    .await;
    let shown = super::message_at(b, "#step-residual [data-field=\"readings\"]").await;
    let mut want = message.to_string();
    for i in (0..11).rev() {
        want = want.replace(&format!("readings[{i}]"), &format!("line {}", i + 1));
    }
    assert_eq!(shown, want, "the service said: {message}");
}
