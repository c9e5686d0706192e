//! The later scenes of the whole-job browser test: the machine page with a
//! trim from stored coefficients (its zero run read from CSV), a multi-speed
//! job's Bode plots and identification, and the page's weight.

pub mod answer_notes;
pub mod kit;
pub mod kit_fit;
pub mod kit_support;
pub mod machine;
pub mod multispeed;
pub mod names;
pub mod noise;
pub mod options;

use fantoccini::Locator;
use serde_json::{json, Value};

use crate::harness::form::{self, field, type_into, value_of};
use crate::harness::job::{scroll_to, shots};
use crate::harness::stand::{example_session, post, Stand};
use crate::harness::steps::{fits_a_tablet, js};

/// (b, i) The machine page, coefficients pooled, a trim job with only a zero run read from CSV.
pub async fn machine_page_and_trim_from_stored_coefficients(stand: &Stand, truth: &Value) {
    let b = &stand.browser;
    // The rotor as found again, as on the first day: the stored coefficients must
    // give the first answer (within what the other tab's corrected reading, 1074
    // for 1073.16, and the rounded check readings move the pooled coefficients).
    let as_found = &truth["runs"][0];
    b.click("nav [data-step=\"machines\"]").await;
    type_into(b, &field("machine.id"), "PUMP-1").await;
    type_into(b, &field("machine.name"), "Cooling water pump 1").await;
    b.click("button.create-machine").await;
    b.wait_for("table.machine-jobs button.open-session").await;
    b.click("button.pool").await;
    b.wait_for("table.coeff-versions tbody tr").await;
    b.wait_for("svg.trend").await;
    shots(b, "job-machine").await;
    fits_a_tablet(b, "machine page").await;
    b.click("button.trim-job").await;
    b.wait_until(
        "the set-up of the machine's last job is copied",
        "const e = document.querySelector('[data-field=\"planes[1].id\"]'); return !!e && e.value === 'outboard'",
    )
    .await;
    assert_eq!(value_of(b, &field("machine")).await, "PUMP-1");
    type_into(b, &field("name"), "PUMP-1 trim").await;
    b.click("#step-setup button.next").await;
    // The zero run read from a CSV file, a row per reading.
    let mut csv = String::from("sensor;speed_rpm;amplitude;phase_deg\n");
    for r in as_found["readings"].as_array().unwrap() {
        csv.push_str(&format!(
            "{};{};{};{}\n",
            r["sensor"].as_str().unwrap(),
            r["speed_rpm"],
            r["amplitude"].to_string().replace('.', ","),
            r["phase_deg"]
        ));
    }
    let path = stand.dir.path().join("as-found.csv");
    std::fs::write(&path, csv).unwrap();
    b.wait_for("input.csv-file")
        .await
        .send_keys(path.to_str().unwrap())
        .await
        .unwrap();
    let note = b.text(".banner.csv-result").await;
    assert!(
        note.starts_with("4 of 4 readings read") && note.contains("a row per reading"),
        "{note}"
    );
    let first = as_found["readings"][0]["amplitude"].as_f64().unwrap();
    let shown: f64 = value_of(b, &field("runs[0].readings[0].amplitude"))
        .await
        .parse()
        .unwrap();
    assert!((shown - first).abs() < 1e-9, "{shown} for {first}");
    shots(b, "job-csv-import").await;
    form::store(b).await;
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve table.corrections").await;
    let shown = form::corrections_on_page(b).await;
    let (_, expected) = example_session("pump-two-plane-exact.json");
    let expected = expected["corrections"].as_array().unwrap();
    assert_eq!(shown.len(), expected.len(), "{shown:?}");
    for (want, (plane, mass, angle)) in expected.iter().zip(&shown) {
        assert_eq!(want["plane"].as_str(), Some(plane.as_str()));
        let dm = (mass - want["mass_g"].as_f64().unwrap()).abs();
        assert!(dm <= 0.5, "{plane}: {mass} g from the stored coefficients");
        let d = (angle - want["angle_deg"].as_f64().unwrap()).rem_euclid(360.0);
        assert!(
            d.min(360.0 - d) <= 1.0,
            "{plane}: {angle}° from the stored coefficients"
        );
    }
    let report = js(
        b,
        "return document.querySelector('#step-report .report-coeffs').textContent",
    )
    .await;
    let report = report.as_str().unwrap();
    assert!(
        report.contains("Stored coefficients of machine PUMP-1, version 1"),
        "{report}"
    );
    shots(b, "job-trim-from-stored").await;
}

/// (f) A job over many speeds: a Bode and a polar plot per sensor, the polar
/// filter; then each solve option on it.
pub async fn multi_speed_job_shows_bode_plots(stand: &Stand) {
    let b = &stand.browser;
    let example = crate::common::example("compressor-multispeed-noisy.json");
    let session = &example["session"];
    let created = post(stand, "/api/v1/sessions", session.clone()).await;
    let id = created["id"].as_str().unwrap();
    b.open_fresh(&stand.server.url(&format!("/#session={id}&step=solve")))
        .await;
    b.wait_until(
        "the multi-speed job is open",
        "return document.querySelector('#job-title').textContent.includes('stored') && !document.querySelector('#step-solve').hidden",
    )
    .await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve svg.bode").await;
    let sensors = session["sensors"].as_array().unwrap().len();
    let counts = js(
        b,
        "return [document.querySelectorAll('#step-solve svg.bode').length, document.querySelectorAll('#step-solve svg.nyquist').length, document.querySelectorAll('#step-solve svg.polar').length, document.querySelectorAll('#step-solve .identification').length]",
    )
    .await;
    assert_eq!(counts[0], json!(sensors), "a Bode plot per sensor");
    assert_eq!(
        counts[1],
        json!(sensors),
        "a polar plot across speeds per sensor"
    );
    assert_eq!(counts[3], json!(1), "identification beside them");
    // The compressor passes a critical speed between 1200 and 9600 rpm.
    b.wait_for("#step-solve .identification td.critical").await;
    // Without rotor data no margin: said as a fact, not as advice to change a
    // set-up that is locked once stored (it said "give the service speed in the set-up").
    let margin = b
        .text("#step-solve .identification tbody tr td:last-child")
        .await;
    assert_eq!(margin, "no service speed in this job's rotor data");
    // The polar plots per speed are filtered to one speed at a time.
    assert_eq!(counts[2], json!(sensors));
    self::multispeed::polar_filter_narrows_the_plots(b, session).await;
    scroll_to(b, ".bode-plots").await;
    shots(b, "job-bode").await;
    fits_a_tablet(b, "multi-speed corrections").await;
    self::options::each_option_reaches_the_request_and_changes_the_answer(b, session).await;
    self::multispeed::a_check_run_is_drawn_on_each_bode_plot(stand, id, session).await;
}

/// The page weighs little and asks nothing of any other host, measured on a
/// fresh load: every file of `static/` is loaded (none lazily, so the sum is
/// the whole form), under 120 kB on the wire (the service sends the files
/// gzip-compressed) and under 300 kB inflated, no request leaves the
/// service, no file names another host, and the service's
/// Content-Security-Policy forbids the browser to try.
pub async fn the_form_weighs_little_and_asks_nothing_of_other_hosts(stand: &Stand) {
    let b = &stand.browser;
    b.open_fresh(&stand.server.url("/")).await;
    b.wait_for("nav [data-step=\"setup\"]").await;
    let got = js(
        b,
        "const all = performance.getEntriesByType('resource'); \
         const nav = performance.getEntriesByType('navigation')[0]; \
         const files = all.filter((e) => e.initiatorType !== 'fetch' && e.initiatorType !== 'xmlhttprequest'); \
         return [all.filter((e) => !e.name.startsWith(location.origin + '/')).map((e) => e.name), \
                 files.reduce((s, e) => s + e.decodedBodySize, nav.decodedBodySize), \
                 files.map((e) => new URL(e.name).pathname).sort(), \
                 files.reduce((s, e) => s + e.encodedBodySize, nav.encodedBodySize)]",
    )
    .await;
    assert_eq!(got[0], json!([]), "requests outside the service");
    let bytes = got[1].as_u64().expect("bytes");
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("static");
    let mut files = Vec::new();
    let mut on_disk = 0;
    // Every folder under static/ (static/js/ has subfolders: page/, job/, steps/, …).
    let mut dirs = vec![root.clone()];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                dirs.push(path);
            } else if path.is_file() {
                let text = std::fs::read_to_string(&path).unwrap();
                on_disk += text.len() as u64;
                let other = text
                    .match_indices("//")
                    .filter(|(i, _)| {
                        text[..*i].ends_with("http:") || text[..*i].ends_with("https:")
                    })
                    .map(|(i, _)| &text[i.saturating_sub(6)..(i + 40).min(text.len())])
                    .find(|u| !u.contains("www.w3.org/2000/svg"));
                assert_eq!(other, None, "{} names another host", path.display());
                let rel = path
                    .strip_prefix(&root)
                    .unwrap()
                    .to_str()
                    .unwrap()
                    .replace('\\', "/");
                if rel != "index.html" {
                    files.push(format!("/static/{rel}"));
                }
            }
        }
    }
    files.sort();
    assert_eq!(got[2], json!(files), "the page loads every file of static/");
    println!(
        "page weight: {bytes} bytes in {} files and the page ({on_disk} bytes on disk)",
        files.len()
    );
    let sent = got[3].as_u64().expect("bytes sent");
    println!("page weight on the wire: {sent} bytes");
    assert!(sent < 120_000, "page weight on the wire {sent} bytes");
    assert!(bytes < 300_000, "page weight {bytes} bytes");
    let page = reqwest::get(stand.server.url("/")).await.unwrap();
    let csp = page.headers()["content-security-policy"]
        .to_str()
        .unwrap()
        .to_string();
    for rule in [
        "default-src 'self'",
        "connect-src 'self'",
        "script-src 'self'",
        "style-src 'self'",
    ] {
        assert!(csp.contains(rule), "{csp} lacks {rule}");
    }
    b.client
        .find(Locator::Css("body"))
        .await
        .expect("the page is still there");
}
