//! The machine page after three jobs: each job's vibration before and after,
//! in its unit (the figures were bare numbers, beside every other amplitude
//! of the form with its unit), and the trend of both.

use serde_json::json;

use super::kit_support::{fmt, get};
use crate::harness::job::shots;
use crate::harness::stand::Stand;
use crate::harness::steps::js;

/// The machine's jobs, each with its vibration before and after, and the trend of both.
pub async fn the_machine_page_shows_vibration_before_and_after_per_job(stand: &Stand) {
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
            // Every sensor of the pump's jobs reads µm pk-pk (um_pp).
            format!("{}, {} µm pk-pk", f(a), f(b))
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
    let caption = b.text("figure.trend-fig figcaption").await;
    assert!(
        caption.starts_with("RMS vibration per job, µm pk-pk:"),
        "{caption}"
    );
    trend_is_labelled_with_the_jobs_dates(b, jobs).await;
    crate::harness::job::scroll_to(b, "h3").await;
    shots(b, "job-machine-jobs").await;
    crate::harness::steps::fits_a_tablet(b, "machine jobs").await;
    a_job_worse_after_than_before_stays_inside_the_trend(b).await;
}

/// A job whose predicted vibration after is larger than before (a min-max
/// or bounded answer can leave more RMS than it found) is drawn inside the
/// plot: the trend scaled to the largest "before" only and drew such a
/// point above the figure. The page's next machine answer is given three
/// times each job's "before" as its "after" (the page's `fetch` wraps the
/// real answer once, then is put back), and every point must lie within
/// the plot's height.
async fn a_job_worse_after_than_before_stays_inside_the_trend(b: &crate::harness::Browser) {
    js(
        b,
        "const real = window.fetch; \
         window.fetch = (url, init) => { \
           const get = !init || !init.method || init.method === 'GET'; \
           if (get && /\\/api\\/v1\\/machines\\/PUMP-1(\\?|$)/.test(String(url))) { \
             window.fetch = real; \
             return real(url, init).then(async (r) => { \
               const m = await r.json(); \
               m.sessions.forEach((s) => { if (s.summary) s.summary.rms_after = 3 * s.summary.rms_before; }); \
               const h = new Headers(r.headers); h.delete('content-length'); \
               return new Response(JSON.stringify(m), { status: r.status, headers: h }); }); } \
           return real(url, init); }; \
         document.querySelector('figure.trend-fig').remove(); \
         return true",
    )
    .await;
    // The old trend is gone, so the one waited for is drawn from the answer.
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.wait_for("svg.trend circle").await;
    let inside = js(
        b,
        "const svg = document.querySelector('svg.trend'); const h = svg.viewBox.baseVal.height; \
         const ys = [...svg.querySelectorAll('circle')].map((c) => Number(c.getAttribute('cy'))); \
         return [ys.length > 0 && ys.every((y) => y >= 0 && y <= h), ys, h, typeof window.fetch]",
    )
    .await;
    assert_eq!(
        inside[0],
        json!(true),
        "every point inside the plot: {inside}"
    );
    // The real answer again, as the scenes after this one expect.
    js(
        b,
        "document.querySelector('figure.trend-fig').remove(); return true",
    )
    .await;
    b.click("nav [data-step=\"machines\"]").await;
    b.click("button.open-machine[data-id=\"PUMP-1\"]").await;
    b.wait_for("svg.trend circle").await;
}

/// Under each point of the trend, the date its job was stored (the time too
/// when jobs share a day), every label inside the plot and none over another.
async fn trend_is_labelled_with_the_jobs_dates(
    b: &crate::harness::Browser,
    jobs: &[serde_json::Value],
) {
    let mut stamps: Vec<&str> = jobs
        .iter()
        .map(|j| j["created_at"].as_str().unwrap())
        .collect();
    stamps.sort();
    let labels = js(
        b,
        "const svg = document.querySelector('svg.trend'); const box = svg.getBoundingClientRect(); \
         const dates = [...svg.querySelectorAll('text.date')]; \
         const rects = dates.map((t) => t.getBoundingClientRect()); \
         return [dates.map((t) => [...t.querySelectorAll('tspan')].map((s) => s.textContent)), \
                 rects.every((r) => r.left >= box.left && r.right <= box.right && r.bottom <= box.bottom), \
                 rects.every((r, i) => i === 0 || rects[i - 1].right <= r.left), \
                 svg.querySelector('text.axis-title').textContent]",
    )
    .await;
    let shown = labels[0].as_array().unwrap();
    assert_eq!(shown.len(), stamps.len(), "a date per job: {labels}");
    for (label, stamp) in shown.iter().zip(&stamps) {
        assert_eq!(label[0], json!(&stamp[..10]), "the day of {stamp}");
        // The three jobs are stored on one day: the time tells them apart.
        let time = label[1].as_str().expect("a time under the day");
        assert!(
            stamp[11..].starts_with(time) && time.len() >= 5,
            "{time} for {stamp}"
        );
    }
    assert_eq!(
        labels[1],
        json!(true),
        "every date inside the plot: {labels}"
    );
    assert_eq!(labels[2], json!(true), "no date over another: {labels}");
    assert!(labels[3].as_str().unwrap().contains("date"), "{labels}");
}
