//! A second job for the machine, started from its page: the set-up copied,
//! then rotor data, fixed places and kits typed in; every run read from one
//! CSV file with a column per run; the trial weight suggested before the first
//! trial; the kit fit drawn per plane where it goes; the ISO 21940-11 figure;
//! and the machine page's vibration before and after per job.

use serde_json::{json, Value};

use super::form::{self, field, type_into, typed, value_of};
use super::job::shots;
use super::stand::Stand;
use super::steps::js;
use super::Browser;

const ROTOR: [(&str, &str); 2] = [
    ("rotor.mass_kg", "400"),
    ("rotor.service_speed_rpm", "2950"),
];
const GRADE: &str = "G6.3";
const INBOARD_PLACES: &str = "12";
const OUTBOARD_PLACES: &str = "0 40 100 160 220 290";
const KITS: [&str; 2] = ["5 10 20", "2 5 10"];

/// A number as the page writes it (num.js `fmt`): `digits` decimals, one more
/// below 1, at most one from 100 and none from 1000.
fn fmt(x: f64, digits: usize) -> String {
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
    format!("{x:.d$}")
}

/// The readings of every run of `session` as one CSV file with a column per run.
fn csv_column_per_run(session: &Value) -> String {
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
async fn read_csv(b: &Browser, path: &std::path::Path) -> String {
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
async fn drawn_angles(b: &Browser, plane: &str, css: &str) -> Vec<f64> {
    let script = format!(
        "return [...document.querySelectorAll('#step-solve .plane-fig[data-plane=\"{plane}\"] svg circle.{css}')] \
           .map((c) => (Math.atan2(c.cx.baseVal.value - 120, 120 - c.cy.baseVal.value) * 180 / Math.PI + 360) % 360)"
    );
    let mut got: Vec<f64> = serde_json::from_value(js(b, &script).await).unwrap();
    got.sort_by(f64::total_cmp);
    got
}

fn assert_same_angles(got: &[f64], want: &[f64], what: &str) {
    let mut want = want.to_vec();
    want.sort_by(f64::total_cmp);
    assert_eq!(got.len(), want.len(), "{what}: {got:?} drawn for {want:?}");
    for (g, w) in got.iter().zip(&want) {
        let d = (g - w).rem_euclid(360.0);
        assert!(d.min(360.0 - d) < 0.5, "{what}: {got:?} drawn for {want:?}");
    }
}

async fn post(stand: &Stand, path: &str, body: Value) -> Value {
    reqwest::Client::new()
        .post(stand.server.url(path))
        .json(&body)
        .send()
        .await
        .unwrap()
        .json()
        .await
        .unwrap()
}

async fn get(stand: &Stand, path: &str) -> Value {
    reqwest::get(stand.server.url(path))
        .await
        .unwrap()
        .json()
        .await
        .unwrap()
}

/// "New job for this machine" copies the set-up of its last job, name left empty.
async fn new_job_copies_the_set_up(b: &Browser, truth: &Value) {
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.click("button.new-job").await;
    b.wait_until(
        "the set-up step of the new job is shown",
        "return !document.querySelector('#step-setup').hidden && document.querySelector('#job-title').textContent === 'New balancing job'",
    )
    .await;
    let mut want = vec![
        ("name".to_string(), String::new()),
        ("machine".to_string(), "PUMP-1".to_string()),
        (
            "speeds".to_string(),
            form::speeds(truth)
                .iter()
                .map(|s| format!("{s}"))
                .collect::<Vec<_>>()
                .join(" "),
        ),
    ];
    for key in ["phase", "angle_direction"] {
        want.push((
            format!("conventions.{key}"),
            truth["conventions"][key].as_str().unwrap().to_string(),
        ));
    }
    for (i, p) in truth["planes"].as_array().unwrap().iter().enumerate() {
        want.push((
            format!("planes[{i}].id"),
            p["id"].as_str().unwrap().to_string(),
        ));
        want.push((format!("planes[{i}].radius_mm"), typed(&p["radius_mm"])));
    }
    for (i, x) in truth["sensors"].as_array().unwrap().iter().enumerate() {
        want.push((
            format!("sensors[{i}].id"),
            x["id"].as_str().unwrap().to_string(),
        ));
        want.push((
            format!("sensors[{i}].unit"),
            x["unit"].as_str().unwrap().to_string(),
        ));
    }
    for (path, value) in want {
        assert_eq!(
            value_of(b, &field(&path)).await,
            value,
            "copied set-up: {path}"
        );
    }
}

/// (Items 1, 2, 8, 9) A second job for the machine with rotor data, fixed places and kits.
pub async fn new_job_with_rotor_places_and_kits(stand: &Stand, truth: &Value) {
    let b = &stand.browser;
    new_job_copies_the_set_up(b, truth).await;
    type_into(b, &field("name"), "PUMP-1 kit job").await;
    for (path, value) in ROTOR {
        type_into(b, &field(path), value).await;
    }
    form::choose(b, &field("rotor.balance_grade"), GRADE).await;
    type_into(b, &field("planes[0].positions"), INBOARD_PLACES).await;
    type_into(b, &field("planes[0].kit.masses_g"), KITS[0]).await;
    type_into(b, &field("planes[1].places_deg"), OUTBOARD_PLACES).await;
    type_into(b, &field("planes[1].kit.masses_g"), KITS[1]).await;
    super::job::scroll_to(b, "fieldset.planes").await;
    shots(b, "job-kit-setup").await;
    super::steps::fits_a_tablet(b, "kit setup").await;
    b.click("#step-setup button.next").await;

    // The shapes a CSV file may have are said at the grid, before any file is chosen.
    let shapes = b.text("#step-runs .csv-shapes").await;
    assert!(
        shapes.contains("a row per reading") && shapes.contains("a column per run"),
        "{shapes}"
    );
    let path = stand.dir.path().join("pump-runs.csv");
    std::fs::write(&path, csv_column_per_run(truth)).unwrap();
    let note = read_csv(b, &path).await;
    assert!(
        note.starts_with("4 of 4 readings read") && note.contains("(a column per run)"),
        "{note}"
    );
    for (i, r) in truth["runs"][0]["readings"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
    {
        let shown = value_of(b, &field(&format!("runs[0].readings[{i}].phase_deg"))).await;
        assert_eq!(
            shown.parse::<f64>().unwrap(),
            r["phase_deg"].as_f64().unwrap()
        );
    }
    form::store(b).await;
    let id = super::steps::stored_id(b).await;

    // Before the first trial: the trial weight the service suggests from the rotor data.
    b.click("button.add-trial").await;
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let stored = stored.get("session").cloned().unwrap_or(stored);
    let suggested = post(stand, "/api/v1/trial-weights", json!({ "session": stored })).await;
    let suggestions = suggested["suggestions"].as_array().expect("suggestions");
    assert_eq!(suggestions.len(), 2, "{suggested}");
    for s in suggestions {
        let plane = s["plane"].as_str().unwrap();
        let text = b
            .text(&format!(".suggestion li[data-plane=\"{plane}\"]"))
            .await;
        let want = format!(
            "Plane {plane}: {} g at {:.1}°",
            fmt(s["mass_g"].as_f64().unwrap(), 1),
            s["angle_deg"].as_f64().unwrap().rem_euclid(360.0)
        );
        assert!(text.contains(&want), "{text:?} should say {want:?}");
    }
    shots(b, "job-trial-suggestion").await;
    super::steps::fits_a_tablet(b, "trial suggestion").await;
    b.click(".suggestion li[data-plane=\"inboard\"] button.use-suggestion")
        .await;
    let used: f64 = value_of(b, &field("runs[1].weights[0].mass_g"))
        .await
        .parse()
        .unwrap();
    assert!(
        (used - suggestions[0]["mass_g"].as_f64().unwrap()).abs() <= 0.05 + 1e-9,
        "{used}"
    );

    // The trials: the fitter used the example's weights; the readings from the same file.
    for (k, name) in [(1usize, "trial inboard"), (2, "trial outboard")] {
        if k == 2 {
            b.click("button.add-trial").await;
        }
        let w = &truth["runs"][k]["weights"][0];
        form::choose(
            b,
            &field(&format!("runs[{k}].weights[0].plane")),
            w["plane"].as_str().unwrap(),
        )
        .await;
        type_into(
            b,
            &field(&format!("runs[{k}].weights[0].mass_g")),
            &typed(&w["mass_g"]),
        )
        .await;
        type_into(
            b,
            &field(&format!("runs[{k}].weights[0].angle_deg")),
            &typed(&w["angle_deg"]),
        )
        .await;
        if k == 1 {
            // A file of several runs is read into the run of the same name, and says so.
            let refused = read_csv(b, &path).await;
            assert!(
                refused.contains("none called “trial 1”: name the run as in the file"),
                "{refused}"
            );
        }
        type_into(b, &field(&format!("runs[{k}].id")), name).await;
        let note = read_csv(b, &path).await;
        assert!(note.starts_with("4 of 4 readings read"), "{note}");
        form::store(b).await;
    }
    let lead = b.text("#step-runs p.lead").await;
    assert!(lead.contains("2 of 2"), "{lead}");

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
        fmt(service["fit_summary"]["rms_after"].as_f64().unwrap(), 2)
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
    super::job::scroll_to(b, ".plane-pics").await;
    shots(b, "job-kit-fit").await;
    super::steps::fits_a_tablet(b, "kit fit").await;

    the_machine_page_shows_vibration_before_and_after_per_job(stand).await;
}

/// The machine's jobs, each with its vibration before and after, and the trend of both.
async fn the_machine_page_shows_vibration_before_and_after_per_job(stand: &Stand) {
    let b = &stand.browser;
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.wait_for("table.machine-jobs td.after").await;
    let machine = get(stand, "/api/v1/machines/PUMP-1").await;
    let jobs = machine["sessions"].as_array().unwrap();
    assert_eq!(jobs.len(), 3, "the first job, the trim job and the kit job");
    for job in jobs {
        let name = job["name"].as_str().unwrap();
        let sm = &job["summary"];
        let row = js(b, &format!(
            "const r = [...document.querySelectorAll('table.machine-jobs tbody tr')].find((r) => r.querySelector('button.open-session').textContent === {}); \
             return [r.querySelector('td.before').textContent, r.querySelector('td.after').textContent]",
            serde_json::to_string(name).unwrap()
        ))
        .await;
        let pair = |a: &str, b: &str| {
            let f = |k: &str| fmt(sm[k].as_f64().unwrap(), 1);
            format!("{}, {}", f(a), f(b))
        };
        assert_eq!(
            row[0],
            json!(pair("rms_before", "max_before")),
            "{name}: before"
        );
        assert_eq!(
            row[1],
            json!(pair("rms_after", "max_after")),
            "{name}: after"
        );
    }
    let points = js(b, "return [document.querySelectorAll('svg.trend path.series').length, document.querySelectorAll('svg.trend circle').length]").await;
    assert_eq!(
        points,
        json!([2, 2 * jobs.len()]),
        "before and after, a point per job"
    );
    super::job::scroll_to(b, "h3").await;
    shots(b, "job-machine-jobs").await;
    super::steps::fits_a_tablet(b, "machine jobs").await;
}
