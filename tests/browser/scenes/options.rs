//! The solve options of the form, each set as a technician would and followed
//! to the request the page sends (recorded by wrapping the page's `fetch`) and
//! to the answer shown, which must change: what to minimise, a mass limit,
//! sensors and speeds left out, and the readings' repeatability (the rotor
//! data, fixed places and kits are set-up fields: see kit.rs).

use serde_json::{json, Value};

use crate::harness::form::{corrections_on_page, field, type_into};
use crate::harness::job::shots;
use crate::harness::steps::js;
use crate::harness::Browser;

/// Keep the body of every request the page sends from now on (until it is reloaded).
pub async fn record_requests(b: &Browser) {
    js(
        b,
        "if (!window.sentBodies) { window.sentBodies = []; const f = window.fetch; \
           window.fetch = (url, init) => { if (init && init.body) window.sentBodies.push({ url: String(url), body: JSON.parse(init.body) }); return f(url, init); }; } \
         return true",
    )
    .await;
}

/// The options of the last solve the page asked the service for.
pub async fn last_solve_request(b: &Browser) -> Value {
    js(
        b,
        "const s = window.sentBodies.filter((x) => /\\/solutions$/.test(x.url)); return s.length ? s[s.length - 1].body : null",
    )
    .await
}

/// Press Solve and wait until the answer shown is the new one.
pub async fn solve_now(b: &Browser) {
    js(
        b,
        "const t = document.querySelector('#step-solve table.corrections'); if (t) t.dataset.old = 'yes'; return true",
    )
    .await;
    b.click("#step-solve button.solve").await;
    b.wait_until(
        "the new answer is shown",
        "const t = document.querySelector('#step-solve table.corrections'); return !!t && t.dataset.old !== 'yes'",
    )
    .await;
}

/// Empty a typed field with the keyboard, so that the page hears it emptied.
async fn empty(b: &Browser, css: &str) {
    let el = b.wait_for(css).await;
    let n = el
        .prop("value")
        .await
        .unwrap()
        .unwrap_or_default()
        .chars()
        .count();
    el.click().await.unwrap();
    el.send_keys("\u{e010}").await.unwrap(); // End
    el.send_keys(&"\u{e003}".repeat(n)).await.unwrap(); // Backspace
}

/// A tick box of the options' "leave out" lists, clicked by its label.
async fn tick(b: &Browser, list: &str, value: &str) {
    b.click(&format!(
        "#step-solve fieldset.leave.{list} input[value=\"{value}\"]"
    ))
    .await;
}

/// The corrections and their 95 % figures as shown.
async fn answer_shown(b: &Browser) -> (Vec<(String, f64, f64)>, Value) {
    let uncertainty = js(
        b,
        "return [...document.querySelectorAll('#step-solve td.corr-uncertainty')].map((e) => e.textContent)",
    )
    .await;
    (corrections_on_page(b).await, uncertainty)
}

fn moved(a: &[(String, f64, f64)], b: &[(String, f64, f64)]) -> bool {
    a.len() != b.len()
        || a.iter().zip(b).any(|(x, y)| {
            let d = (x.2 - y.2).rem_euclid(360.0);
            x.0 != y.0 || (x.1 - y.1).abs() > 0.05 || d.min(360.0 - d) > 0.05
        })
}

/// (Item 8) Each option reaches the request and changes the answer; the
/// multi-speed job with five sensors is open and solved with the defaults.
pub async fn each_option_reaches_the_request_and_changes_the_answer(b: &Browser, session: &Value) {
    record_requests(b).await;
    let (base, base_uncertainty) = answer_shown(b).await;
    b.click("#step-solve details.options summary").await;

    // What to minimise.
    crate::harness::form::choose(b, "#step-solve select.objective", "min_max").await;
    solve_now(b).await;
    assert_eq!(last_solve_request(b).await["objective"], json!("min_max"));
    assert!(
        moved(&answer_shown(b).await.0, &base),
        "min-max gives other weights"
    );
    shots(b, "job-option-objective").await;
    crate::harness::steps::fits_a_tablet(b, "options open").await;
    crate::harness::form::choose(b, "#step-solve select.objective", "least_squares").await;

    // A mass limit below the heaviest correction.
    let (plane, heaviest, _) = base
        .iter()
        .cloned()
        .max_by(|x, y| x.1.total_cmp(&y.1))
        .unwrap();
    let limit = (heaviest * 0.6).floor();
    let css = field(&format!("options.max_mass_g.{plane}"));
    type_into(b, &css, &format!("{limit}")).await;
    solve_now(b).await;
    let sent = last_solve_request(b).await;
    let limits = sent["max_mass_g"].as_object().expect("mass limits sent");
    assert_eq!(limits.len(), 1, "{sent}");
    assert_eq!(limits[&plane].as_f64(), Some(limit), "{sent}");
    let limited = answer_shown(b).await.0;
    let m = limited.iter().find(|c| c.0 == plane).unwrap().1;
    assert!(
        m <= limit + 0.05,
        "{plane}: {m} g over the limit of {limit} g"
    );
    let words = b
        .text("#step-solve .warnings li[data-code=\"mass_limit_active\"]")
        .await;
    assert!(words.contains("reached the mass limit you set"), "{words}");
    empty(b, &css).await;

    // A sensor left out, then a speed left out.
    let sensors: Vec<&str> = session["sensors"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x["id"].as_str().unwrap())
        .collect();
    let left = sensors[sensors.len() - 1];
    tick(b, "sensors", left).await;
    solve_now(b).await;
    let sent = last_solve_request(b).await;
    assert_eq!(
        sent["sensors"],
        json!(sensors[..sensors.len() - 1]),
        "{sent}"
    );
    assert!(moved(&answer_shown(b).await.0, &base), "without {left}");
    tick(b, "sensors", left).await;
    let speeds = crate::harness::form::speeds(session);
    tick(b, "speeds", &format!("{}", speeds[0])).await;
    solve_now(b).await;
    let sent = last_solve_request(b).await;
    let sent_speeds: Vec<f64> =
        serde_json::from_value(sent["speeds_rpm"].clone()).expect("speeds sent");
    assert_eq!(sent_speeds, speeds[1..], "{sent}");
    assert!(
        moved(&answer_shown(b).await.0, &base),
        "without {} rpm",
        speeds[0]
    );
    tick(b, "speeds", &format!("{}", speeds[0])).await;

    // Noisier readings: other 95 % figures.
    type_into(b, &field("options.amplitude_noise_pct"), "10").await;
    type_into(b, &field("options.phase_noise_deg"), "10").await;
    solve_now(b).await;
    let sent = last_solve_request(b).await;
    assert_eq!(
        (
            sent["amplitude_noise_pct"].as_f64(),
            sent["phase_noise_deg"].as_f64()
        ),
        (Some(10.0), Some(10.0)),
        "{sent}"
    );
    let (_, noisy_uncertainty) = answer_shown(b).await;
    assert_ne!(
        noisy_uncertainty, base_uncertainty,
        "other 95 % figures with noisier readings"
    );
    empty(b, &field("options.amplitude_noise_pct")).await;
    empty(b, &field("options.phase_noise_deg")).await;

    // All back as they were: the request carries the defaults only.
    solve_now(b).await;
    let sent = last_solve_request(b).await;
    assert_eq!(sent, json!({ "objective": "least_squares" }), "{sent}");
    assert!(!moved(&answer_shown(b).await.0, &base));
}
