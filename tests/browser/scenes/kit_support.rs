//! Helpers of the kit-job browser scene: numbers as the page writes them,
//! the runs as one CSV file, choosing it, the angles a plane picture draws,
//! and the service asked directly.

use serde_json::Value;

pub use crate::harness::stand::{get, post};
use crate::harness::steps::js;
use crate::harness::Browser;

/// A number as the page writes it (num.js `fmt`): `digits` decimals, one more
/// below 1, at most one from 100 and none from 1000; below 0.1 two
/// significant digits, at most `digits` + 3 decimals, unless that rounds to 0.
pub fn fmt(x: f64, digits: usize) -> String {
    let a = x.abs();
    let d = if a >= 1000.0 {
        0
    } else if a >= 100.0 {
        digits.min(1)
    } else if a > 0.0 && a < 1.0 {
        digits + 1
    } else {
        digits
    };
    if a > 0.0 && a < 0.1 {
        let wanted = (1 - a.log10().floor() as i64).max(d as i64) as usize;
        let small = wanted.min(digits + 3);
        let text = format!("{x:.small$}");
        if text.parse::<f64>().is_ok_and(|v| v != 0.0) {
            return text;
        }
    }
    format!("{x:.d$}")
}

/// The readings of every run of `session` as one CSV file with a column per run.
pub fn csv_column_per_run(session: &Value) -> String {
    let runs = session["runs"].as_array().unwrap();
    let mut out = String::from("speed_rpm,sensor");
    for run in runs {
        let id = run["id"].as_str().unwrap();
        out.push_str(&format!(",{id} amplitude,{id} phase"));
    }
    out.push('\n');
    for r in runs[0]["readings"].as_array().unwrap() {
        out.push_str(&format!(
            "{},{}",
            r["speed_rpm"],
            r["sensor"].as_str().unwrap()
        ));
        for run in runs {
            let same = run["readings"]
                .as_array()
                .unwrap()
                .iter()
                .find(|x| x["sensor"] == r["sensor"] && x["speed_rpm"] == r["speed_rpm"])
                .expect("every run reads every sensor at every speed");
            out.push_str(&format!(",{},{}", same["amplitude"], same["phase_deg"]));
        }
        out.push('\n');
    }
    out
}

/// Choose `path` in the run's CSV file input and return the banner it shows.
pub async fn read_csv(b: &Browser, path: &std::path::Path) -> String {
    js(
        b,
        "document.querySelectorAll('.banner').forEach((e) => { e.textContent = ''; e.hidden = true; }); return true",
    )
    .await;
    b.wait_for("input.csv-file")
        .await
        .send_keys(path.to_str().unwrap())
        .await
        .unwrap();
    b.wait_until(
        "the CSV file is answered",
        "const e = document.querySelector('#step-runs .banner'); return !!e && e.textContent !== ''",
    )
    .await;
    b.text("#step-runs .banner").await
}

/// Angles (0–360, clockwise from the top: with rotation in the picture) of the circles `css` in plane `plane`'s picture.
pub async fn drawn_angles(b: &Browser, plane: &str, css: &str) -> Vec<f64> {
    let script = format!(
        "return [...document.querySelectorAll('#step-solve .plane-fig[data-plane=\"{plane}\"] svg circle.{css}')] \
           .map((c) => (Math.atan2(c.cx.baseVal.value - 120, 120 - c.cy.baseVal.value) * 180 / Math.PI + 360) % 360)"
    );
    let mut got: Vec<f64> = serde_json::from_value(js(b, &script).await).unwrap();
    got.sort_by(f64::total_cmp);
    got
}

pub fn assert_same_angles(got: &[f64], want: &[f64], what: &str) {
    let mut want = want.to_vec();
    want.sort_by(f64::total_cmp);
    assert_eq!(got.len(), want.len(), "{what}: {got:?} drawn for {want:?}");
    for (g, w) in got.iter().zip(&want) {
        let d = (g - w).rem_euclid(360.0);
        assert!(d.min(360.0 - d) < 0.5, "{what}: {got:?} drawn for {want:?}");
    }
}
