//! Driving the form like a technician: every value is typed key by key into the
//! real inputs (WebDriver send_keys), the grid is walked with the Tab key, and
//! choices are made by clicking the options.

use serde_json::Value;

use super::Browser;
use fantoccini::Locator;

const TAB: &str = "\u{e004}";

/// A JSON number as a technician would type it (shortest exact decimal).
pub fn typed(v: &Value) -> String {
    let x = v.as_f64().expect("a number");
    format!("{x}")
}

/// Clear an input and type `text` into it. The page may draw the step again
/// between finding the input and typing (an answer arriving, such as the
/// trial-weight suggestion): the input found is then stale, and the typing
/// starts again in the one now matching `css`.
pub async fn type_into(b: &Browser, css: &str, text: &str) {
    for _ in 0..50 {
        let el = b.wait_for(css).await;
        match el.clear().await {
            Ok(()) => {}
            Err(e) if e.to_string().contains("stale element") => continue,
            Err(e) => panic!("clearing {css}: {e}"),
        }
        match el.send_keys(text).await {
            Ok(()) => return,
            Err(e) if e.to_string().contains("stale element") => continue,
            Err(e) => panic!("typing into {css}: {e}"),
        }
    }
    panic!("typing into {css}: the input went stale 50 times in a row");
}

/// Choose a select's option by clicking it.
pub async fn choose(b: &Browser, select_css: &str, value: &str) {
    b.click(select_css).await;
    b.click(&format!("{select_css} option[value=\"{value}\"]"))
        .await;
}

pub fn field(path: &str) -> String {
    format!("[data-field=\"{path}\"]")
}

/// The value an input holds now (read in one script: a step drawn afresh
/// between finding the input and reading it would leave a stale element).
pub async fn value_of(b: &Browser, css: &str) -> String {
    b.wait_for(css).await;
    let script = format!(
        "const e = document.querySelector({}); return e ? String(e.value ?? '') : null",
        serde_json::to_string(css).expect("a selector")
    );
    let got = b.client.execute(&script, vec![]).await.expect("value read");
    got.as_str()
        .unwrap_or_else(|| panic!("{css} went away while being read"))
        .to_string()
}

/// Speeds of the reference run, in order of first appearance (the grid's order).
pub fn speeds(session: &Value) -> Vec<f64> {
    let reference = session["runs"]
        .as_array()
        .expect("runs")
        .iter()
        .find(|r| r["weights"].as_array().is_some_and(|w| w.is_empty()))
        .expect("a reference run");
    let mut out: Vec<f64> = Vec::new();
    for r in reference["readings"].as_array().expect("readings") {
        let s = r["speed_rpm"].as_f64().expect("speed");
        if !out.iter().any(|x| (x - s).abs() <= 0.01 * x.max(s)) {
            out.push(s);
        }
    }
    out
}

/// Type the set-up of `session` into step 1.
pub async fn type_setup(b: &Browser, session: &Value) {
    type_into(b, &field("name"), session["name"].as_str().expect("name")).await;
    if let Some(machine) = session["machine"].as_str() {
        type_into(b, &field("machine"), machine).await;
    }
    let speeds: Vec<String> = speeds(session).iter().map(|s| format!("{s}")).collect();
    type_into(b, &field("speeds"), &speeds.join(" ")).await;
    let conventions = &session["conventions"];
    choose(
        b,
        &field("conventions.phase"),
        conventions["phase"].as_str().unwrap_or("lag"),
    )
    .await;
    let direction = conventions["angle_direction"]
        .as_str()
        .unwrap_or("against_rotation");
    choose(b, &field("conventions.angle_direction"), direction).await;
    for (i, plane) in session["planes"]
        .as_array()
        .expect("planes")
        .iter()
        .enumerate()
    {
        if i > 0 {
            b.click("button.add-plane").await;
        }
        type_into(
            b,
            &field(&format!("planes[{i}].id")),
            plane["id"].as_str().expect("id"),
        )
        .await;
        if !plane["radius_mm"].is_null() {
            type_into(
                b,
                &field(&format!("planes[{i}].radius_mm")),
                &typed(&plane["radius_mm"]),
            )
            .await;
        }
        if !plane["positions"].is_null() {
            type_into(
                b,
                &field(&format!("planes[{i}].positions")),
                &typed(&plane["positions"]),
            )
            .await;
        }
    }
    for (i, sensor) in session["sensors"]
        .as_array()
        .expect("sensors")
        .iter()
        .enumerate()
    {
        if i > 0 {
            b.click("button.add-sensor").await;
        }
        type_into(
            b,
            &field(&format!("sensors[{i}].id")),
            sensor["id"].as_str().expect("id"),
        )
        .await;
        choose(
            b,
            &field(&format!("sensors[{i}].unit")),
            sensor["unit"].as_str().expect("unit"),
        )
        .await;
        if let Some(label) = sensor["label"].as_str() {
            type_into(b, &field(&format!("sensors[{i}].label")), label).await;
        }
    }
}

/// The grid's cells for `run` in reading order: per speed, per sensor, amplitude then phase.
pub fn cells(session: &Value, run: &Value) -> Vec<String> {
    let mut out = Vec::new();
    for speed in speeds(session) {
        for sensor in session["sensors"].as_array().expect("sensors") {
            let reading = run["readings"]
                .as_array()
                .expect("readings")
                .iter()
                .find(|r| {
                    r["sensor"] == sensor["id"]
                        && (r["speed_rpm"].as_f64().unwrap() - speed).abs() <= 0.01 * speed
                })
                .unwrap_or_else(|| {
                    panic!(
                        "run {} has no reading for {} at {speed}",
                        run["id"], sensor["id"]
                    )
                });
            out.push(typed(&reading["amplitude"]));
            out.push(typed(&reading["phase_deg"]));
        }
    }
    out
}

/// Click the first cell of run `k`, then type every value followed by Tab:
/// this only fills the right cells if Tab walks the grid in reading order.
pub async fn type_cells_with_tab(b: &Browser, k: usize, values: &[String]) {
    let first = field(&format!("runs[{k}].readings[0].amplitude"));
    // Into the middle of the window first, as a technician scrolls to it: a
    // tall run (its name, what it is, the weights) leaves the first cell
    // below the sticky Store bar, and WebDriver clicks a cell in the window
    // where it is, under the bar.
    b.wait_for(&first).await;
    let script = format!(
        "document.querySelector({}).scrollIntoView({{ block: 'center' }})",
        serde_json::to_string(&first).unwrap()
    );
    b.client.execute(&script, vec![]).await.expect("scrolls");
    b.click(&first).await;
    for value in values {
        let active = b.client.active_element().await.expect("a focused cell");
        active
            .send_keys(&format!("{value}{TAB}"))
            .await
            .expect("typing into the focused cell");
    }
    for (i, value) in values.iter().enumerate() {
        let kind = if i % 2 == 0 { "amplitude" } else { "phase_deg" };
        let css = field(&format!("runs[{k}].readings[{}].{kind}", i / 2));
        assert_eq!(
            &value_of(b, &css).await,
            value,
            "cell {css} after typing with Tab"
        );
    }
}

/// Type run `k` of `session` (run name, weights, readings) and store it.
/// With `carry`, weights of the previous trial still on the rotor are given by the tick.
pub async fn type_run(b: &Browser, session: &Value, k: usize, carry: bool) {
    fill_run(b, session, k, carry).await;
    store(b).await;
}

/// Type run `k` of `session` (run name, weights, readings) without storing it.
pub async fn fill_run(b: &Browser, session: &Value, k: usize, carry: bool) {
    let runs = session["runs"].as_array().expect("runs");
    let run = &runs[k];
    let weights = run["weights"].as_array().expect("weights");
    if k > 0 {
        b.click("button.add-trial").await;
        let previous = runs[..k]
            .iter()
            .rev()
            .find(|r| !r["weights"].as_array().unwrap().is_empty());
        let mut own: &[Value] = weights;
        if let Some(prev) = previous.filter(|_| carry) {
            let kept = prev["weights"].as_array().unwrap();
            if weights.len() >= kept.len() && &weights[..kept.len()] == kept.as_slice() {
                b.click("input.carry-tick").await;
                own = &weights[kept.len()..];
            }
        }
        // The new run starts with one weight row.
        if own.is_empty() {
            b.click(".weights button.small").await;
        }
        for _ in 1..own.len() {
            b.click("button.add-weight").await;
        }
        for (j, w) in own.iter().enumerate() {
            let path = format!("runs[{k}].weights[{j}]");
            choose(
                b,
                &field(&format!("{path}.plane")),
                w["plane"].as_str().unwrap(),
            )
            .await;
            type_into(b, &field(&format!("{path}.mass_g")), &typed(&w["mass_g"])).await;
            type_into(
                b,
                &field(&format!("{path}.angle_deg")),
                &typed(&w["angle_deg"]),
            )
            .await;
        }
    }
    type_into(
        b,
        &field(&format!("runs[{k}].id")),
        run["id"].as_str().expect("run id"),
    )
    .await;
    type_cells_with_tab(b, k, &cells(session, run)).await;
}

/// Press the store button and wait until the run is stored (or fail with the page's message).
pub async fn store(b: &Browser) {
    b.click("#step-runs button.store").await;
    b.wait_until(
        "the run is stored or refused",
        "return !!document.querySelector('#step-runs button.add-trial') || \
         !!document.querySelector('#step-runs .banner.error:not([hidden])')",
    )
    .await;
    if let Ok(banner) = b
        .client
        .find(Locator::Css("#step-runs .banner.error:not([hidden])"))
        .await
    {
        panic!(
            "the form refused the run: {}",
            banner.text().await.unwrap_or_default()
        );
    }
}

/// The corrections as the page shows them: (plane, mass in g, angle in
/// degrees), read once the answer of the last solve asked for is drawn. The
/// corrections step counts the solves it asks for (`data-solves`) and says
/// which has come back (`data-settled`); while a re-solve is out the page
/// still shows the answer before it, which waiting for any row would read.
/// A refused solve fails here with the page's message.
pub async fn corrections_on_page(b: &Browser) -> Vec<(String, f64, f64)> {
    b.wait_until(
        "the answer of the last solve is shown, or refused",
        "const s = document.querySelector('#step-solve'); \
         return (s.dataset.solves || '0') === (s.dataset.settled || '0') && \
           (!!s.querySelector('table.corrections tbody tr') || !!s.querySelector('.banner.error:not([hidden])'))",
    )
    .await;
    // Read in one script: the step drawn again between two reads would leave stale rows.
    let got = b
        .client
        .execute(
            "const s = document.querySelector('#step-solve'); \
             const refused = s.querySelector('.banner.error:not([hidden])'); \
             if (refused) return { refused: refused.textContent }; \
             return { rows: [...s.querySelectorAll('table.corrections tbody tr:not(.plane-warning)')] \
               .map((r) => ['.corr-plane', '.corr-mass', '.corr-angle'].map((c) => r.querySelector(c).textContent)) }",
            vec![],
        )
        .await
        .expect("the corrections read");
    if let Some(refused) = got.get("refused") {
        panic!("the solve was refused: {refused}");
    }
    let number = |s: &str| -> f64 {
        s.trim_end_matches(|c: char| !c.is_ascii_digit())
            .parse()
            .unwrap_or_else(|_| panic!("not a number on the page: {s:?}"))
    };
    // Not the rows of warnings under a plane's correction (left out above).
    got["rows"]
        .as_array()
        .expect("rows")
        .iter()
        .map(|r| {
            let cell = |k: usize| r[k].as_str().expect("a cell's text").to_string();
            (cell(0), number(&cell(1)), number(&cell(2)))
        })
        .collect()
}
