//! A job whose zero run carries repeated samples per reading (`samples`, the
//! reading their mean): the runs grid showed each mean as if typed once, so
//! the technician could not tell which readings the 95 % figures take their
//! scatter from, nor that retyping one while correcting the run leaves its
//! samples out. Each such cell now says "mean of n", and in the run being
//! corrected that a retyped value replaces them.

use serde_json::{json, Value};

use crate::harness::stand::{example_session, post, Stand};
use crate::harness::steps::js;

pub async fn readings_with_samples_say_so_in_the_grid(stand: &Stand) {
    let b = &stand.browser;
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    // Three samples about the first reading of the zero run, the others plain.
    let first = &mut session["runs"][0]["readings"][0];
    let (a, p) = (
        first["amplitude"].as_f64().unwrap(),
        first["phase_deg"].as_f64().unwrap(),
    );
    first["samples"] = json!([
        { "amplitude": a * 0.99, "phase_deg": p - 0.5 },
        { "amplitude": a, "phase_deg": p },
        { "amplitude": a * 1.01, "phase_deg": p + 0.5 },
    ]);
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"]
        .as_str()
        .unwrap_or_else(|| panic!("{created}"));
    b.open_fresh(&stand.server.url(&format!("/#session={id}&step=runs")))
        .await;
    b.wait_for("#step-runs td.value.amp").await;
    let notes: Value = js(
        b,
        "return [...document.querySelectorAll('#step-runs tbody tr')].map((tr) => [...tr.querySelectorAll('td.value.amp')].map((td) => (td.querySelector('.samples') || {}).textContent || null))",
    )
    .await;
    // Row 0 (2950 rpm, DE-H): the zero run's cell says so; nothing else does.
    assert_eq!(notes[0][0], "mean of 3", "{notes}");
    let others = notes
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|r| r.as_array().unwrap().iter())
        .filter(|n| !n.is_null())
        .count();
    assert_eq!(others, 1, "{notes}");

    // Correcting the zero run: the cell being typed says what retyping does.
    b.click("#step-runs th.run[data-run=\"zero\"] button.correct")
        .await;
    b.wait_for("#step-runs td.cell input").await;
    let hint = b.text("#step-runs td.cell .samples").await;
    assert_eq!(hint, "mean of 3: a new value replaces them");
}
