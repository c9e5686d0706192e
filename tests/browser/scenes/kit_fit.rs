//! The kit job's answer: the request asks for the discrete fit, each plane's
//! picture draws the kit weights where they go (mark, rotation, fixed places),
//! the words say them per place, and the rotor data give the ISO 21940-11 figure.

use serde_json::{json, Value};

use super::kit::GRADE;
use super::kit_support::{assert_same_angles, drawn_angles, fmt, get, post};
use crate::harness::job::shots;
use crate::harness::stand::Stand;
use crate::harness::steps::js;

/// (Items 2, 8) The kit fit drawn and said per plane, beside the service's own.
pub async fn kit_fit_is_drawn_where_it_goes(stand: &Stand, id: &str) {
    let b = &stand.browser;
    // Solved with the kits: the request asks for the discrete fit, and each plane's picture draws it.
    b.click("#step-runs button.go-solve").await;
    super::options::record_requests(b).await;
    super::options::solve_now(b).await;
    let sent = super::options::last_solve_request(b).await;
    assert_eq!(sent["discrete"], json!(true), "{sent}");
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let stored = stored.get("session").cloned().unwrap_or(stored);
    assert_eq!(stored["planes"][0]["positions"], json!(12), "{stored}");
    assert_eq!(
        stored["planes"][1]["places_deg"],
        json!([0.0, 40.0, 100.0, 160.0, 220.0, 290.0])
    );
    assert_eq!(
        stored["planes"][1]["kit"]["masses_g"],
        json!([2.0, 5.0, 10.0])
    );
    assert_eq!(stored["rotor"]["balance_grade"], json!(GRADE));
    let service = post(
        stand,
        "/api/v1/solve",
        json!({ "session": stored, "options": { "discrete": true } }),
    )
    .await;
    let fit = service["fit"]
        .as_array()
        .expect("the service fits the kits");
    let places = [
        (0..12).map(|k| 30.0 * k as f64).collect::<Vec<_>>(),
        vec![0.0, 40.0, 100.0, 160.0, 220.0, 290.0],
    ];
    for (p, want_places) in fit.iter().zip(&places) {
        let plane = p["plane"].as_str().unwrap();
        let figure = format!("#step-solve .plane-fig[data-plane=\"{plane}\"]");
        let caption = b.text(&format!("{figure} figcaption")).await;
        assert_eq!(caption, format!("Plane {plane}: kit weights"));
        let weights = p["weights"].as_array().unwrap();
        // Weights stacked at one place are said, and drawn, once.
        let mut stacks: Vec<(Value, f64, Vec<String>)> = Vec::new();
        for w in weights {
            let mass = format!("{} g", fmt(w["mass_g"].as_f64().unwrap(), 1));
            match stacks.iter_mut().find(|s| s.0 == w["place"]) {
                Some(s) => s.2.push(mass),
                None => stacks.push((
                    w["place"].clone(),
                    w["angle_deg"].as_f64().unwrap(),
                    vec![mass],
                )),
            }
        }
        let words: Vec<String> = stacks
            .iter()
            .map(|(place, angle, masses)| {
                format!(
                    "{} at {:.1}° (place {place})",
                    masses.join(" + "),
                    angle.rem_euclid(360.0)
                )
            })
            .collect();
        assert_eq!(
            b.text(&format!("{figure} .fit-words")).await,
            words.join("\n")
        );
        let angles: Vec<f64> = stacks.iter().map(|s| s.1).collect();
        // With rotation: the angles run clockwise in the picture, as the rotor turns.
        assert_same_angles(&drawn_angles(b, plane, "weight").await, &angles, "weights");
        assert_same_angles(
            &drawn_angles(b, plane, "place").await,
            want_places,
            "fixed places",
        );
        let marks = js(b, &format!(
            "const f = document.querySelector('{}'); return [!!f.querySelector('path.mark'), !!f.querySelector('path.rotation'), f.querySelector('svg').textContent, f.querySelector('.hint').textContent]",
            figure.replace('"', "\\\"")
        ))
        .await;
        assert_eq!(marks[0], json!(true), "the reference mark is drawn");
        assert_eq!(marks[1], json!(true), "the rotation arrow is drawn");
        let labels = marks[2].as_str().unwrap();
        assert!(
            labels.contains("mark (0°)") && labels.contains("rotation"),
            "{labels}"
        );
        assert!(
            marks[3]
                .as_str()
                .unwrap()
                .contains("Seen from the drive end"),
            "{}",
            marks[3]
        );
    }
    let fitted = b.text("#step-solve .fit-summary").await;
    let want = format!(
        "With the kit weights shown: RMS {}",
        fmt(service["fit_summary"]["rms_after"].as_f64().unwrap(), 1)
    );
    assert!(
        fitted.starts_with(&want),
        "{fitted:?} should start {want:?}"
    );
    // Rotor data: the ISO 21940-11 figure beside the answer.
    let iso = &service["iso_21940"];
    let summary = b.text("#step-solve .summary").await;
    let want = format!(
        "ISO 21940-11 {GRADE}: permissible {} g·mm per plane",
        fmt(iso["permissible_per_plane_gmm"].as_f64().unwrap(), 0)
    );
    assert!(summary.contains(&want), "{summary:?} should say {want:?}");
    crate::harness::job::scroll_to(b, ".plane-pics").await;
    shots(b, "job-kit-fit").await;
    crate::harness::steps::fits_a_tablet(b, "kit fit").await;
    report_says_the_places_and_the_iso_verdict(stand, &service).await;
}

/// (Item 6) The kit job's report: each weight's fixed place, the kit weights to
/// fit, and the result against ISO 21940-11 from the rotor data.
async fn report_says_the_places_and_the_iso_verdict(stand: &Stand, service: &Value) {
    let b = &stand.browser;
    b.click("nav [data-step=\"report\"]").await;
    b.wait_for("#step-report section.report-weights td.place")
        .await;
    let got = js(
        b,
        "return [[...document.querySelectorAll('#step-report section.report-weights tbody tr')].map((r) => [...r.cells].map((c) => c.textContent)), \
                 document.querySelector('#step-report .report-answer').innerText]",
    )
    .await;
    let rows = got[0].as_array().unwrap();
    // The trials of kit.rs: inboard (12 places) at 0°, on place 0; outboard at 120°, between its places.
    assert_eq!(rows.len(), 2, "{got}");
    assert_eq!(rows[0][1], "inboard");
    assert_eq!(rows[0][5], "0", "{got}");
    assert_eq!(rows[1][1], "outboard");
    assert_eq!(
        rows[1][5], "–",
        "120° is none of 0 40 100 160 220 290: {got}"
    );
    let answer = got[1].as_str().unwrap();
    let iso = &service["iso_21940"];
    let word = |k: &str| match iso[k].as_bool() {
        Some(true) => "pass",
        Some(false) => "fail",
        None => "–",
    };
    let want = format!(
        "ISO 21940-11 {GRADE}: {} as measured, {} once corrected (95 %)",
        word("pass"),
        word("after_correction_pass")
    );
    assert!(answer.contains(&want), "{answer:?} should say {want:?}");
    assert!(answer.contains("Weights to fit"), "{answer}");
    b.click("nav [data-step=\"solve\"]").await;
}
