//! Support for the whole-job browser test: screenshots at both widths, the
//! readings a run with given weights would show (from the service's own run
//! check of a probe run, so the test data follow the rotor's linear model
//! without a second implementation of it), and measurements of the page.

use serde_json::{json, Value};

use super::form::{field, type_into, value_of};
use super::Browser;

/// Screenshots of the page as it is now at 1280 and 768 wide, `NAME-1280.png` and `NAME-768.png`.
pub async fn shots(b: &Browser, name: &str) {
    for (w, h) in [(1280, 800), (768, 1024)] {
        b.viewport(w, h).await;
        b.screenshot(&format!("{name}-{w}")).await;
    }
    b.viewport(1280, 800).await;
}

/// Scroll so that the first element matching `css` is at the top.
pub async fn scroll_to(b: &Browser, css: &str) {
    b.wait_for(css).await;
    let script = format!(
        "document.querySelector({}).scrollIntoView()",
        serde_json::to_string(css).unwrap()
    );
    b.client.execute(&script, vec![]).await.expect("scrolls");
}

/// The readings of a run with `weights` on, as the rotor of `session` (its
/// zero and trial runs) would show them: the service's prediction for a probe run.
pub async fn predicted(url: &str, session: &Value, weights: &Value) -> Value {
    let mut probe = session.clone();
    let reference = session["runs"][0]["readings"].clone();
    probe["runs"]
        .as_array_mut()
        .unwrap()
        .push(json!({ "id": "probe", "weights": weights, "readings": reference }));
    let solution: Value = reqwest::Client::new()
        .post(format!("{url}/api/v1/solve"))
        .json(&json!({ "session": probe }))
        .send()
        .await
        .expect("the service answers")
        .json()
        .await
        .expect("a solution");
    let check = solution["run_checks"]
        .as_array()
        .expect("run checks")
        .iter()
        .find(|c| c["run"] == "probe")
        .expect("the probe run is predicted");
    let readings: Vec<Value> = check["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let amp = (r["predicted"].as_f64().unwrap() * 1000.0).round() / 1000.0;
            let phase = (r["predicted_phase_deg"].as_f64().unwrap().rem_euclid(360.0) * 100.0)
                .round()
                / 100.0;
            json!({ "speed_rpm": r["speed_rpm"], "sensor": r["sensor"], "amplitude": amp,
                    "phase_deg": if phase >= 360.0 { 0.0 } else { phase } })
        })
        .collect();
    json!({ "id": "probe", "weights": weights, "readings": readings })
}

/// The weights of run `k`'s editor as (plane, mass, angle).
pub async fn weights_in_editor(b: &Browser, k: usize) -> Value {
    let mut out = Vec::new();
    for j in 0..16 {
        let mass = field(&format!("runs[{k}].weights[{j}].mass_g"));
        if b.client
            .find(fantoccini::Locator::Css(&mass))
            .await
            .is_err()
        {
            break;
        }
        let plane = value_of(b, &field(&format!("runs[{k}].weights[{j}].plane"))).await;
        let m: f64 = value_of(b, &mass).await.parse().expect("a mass");
        let a: f64 = value_of(b, &field(&format!("runs[{k}].weights[{j}].angle_deg")))
            .await
            .parse()
            .expect("an angle");
        out.push(json!({ "plane": plane, "mass_g": m, "angle_deg": a }));
    }
    Value::Array(out)
}

/// Type `text` into a field and return the message shown next to it.
pub async fn message_for(b: &Browser, css: &str, text: &str) -> String {
    type_into(b, css, text).await;
    let script = format!(
        "const f = document.querySelector({}).closest('.field'); return f.querySelector('.msg').textContent",
        serde_json::to_string(css).unwrap()
    );
    b.client
        .execute(&script, vec![])
        .await
        .expect("message")
        .as_str()
        .unwrap_or_default()
        .to_string()
}

/// Elements shown now whose touch target is under 44 px high (a checkbox counts its label).
pub async fn small_targets(b: &Browser) -> Value {
    b.client
        .execute(
            r#"return [...document.querySelectorAll('button, select, input, summary, label.button')]
                .filter((e) => e.getClientRects().length > 0 && !e.closest('[hidden]') && getComputedStyle(e).visibility !== 'hidden')
                .filter((e) => !(e.type === 'file'))
                .map((e) => [e, e.type === 'checkbox' ? (e.closest('label') || e) : e])
                .filter(([, t]) => t.getBoundingClientRect().height < 44)
                .map(([e, t]) => `${e.tagName} ${e.className || e.type} ${e.textContent.trim().slice(0, 30)}: ${t.getBoundingClientRect().height.toFixed(1)} px`)"#,
            vec![],
        )
        .await
        .expect("measured")
}

/// The page's width beyond the viewport (0 when nothing scrolls sideways),
/// with the elements that stick out (outside the tables' own scroll boxes).
pub async fn sideways(b: &Browser) -> (i64, Value) {
    let got = b
        .client
        .execute(
            // clientWidth, not innerWidth: the vertical scroll bar takes its
            // width from the page, and a page that fits under it still scrolls sideways.
            "const w = document.documentElement.clientWidth; \
             return [document.documentElement.scrollWidth - w, \
                     [...document.querySelectorAll('body *')].filter((e) => e.getBoundingClientRect().right > w + 1 && !e.closest('.scroll')) \
                       .slice(0, 6).map((e) => `${e.tagName}.${e.className.baseVal ?? e.className} ${Math.round(e.getBoundingClientRect().right)}`)]",
            vec![],
        )
        .await
        .expect("measured");
    (got[0].as_i64().expect("a number"), got[1].clone())
}
