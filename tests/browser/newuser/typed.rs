//! Readings shown as typed (all their digits, a decimal comma as a point),
//! answers with their unit, and a typed run kept when another job is opened
//! from a list.

use super::{confirmation, texts, ENTER};
use crate::harness::form::{choose, field, type_into, value_of};
use crate::harness::stand::Stand;

pub async fn small_readings_are_shown_as_typed_and_answers_carry_their_unit(stand: &Stand) {
    let b = &stand.browser;
    type_into(b, &field("name"), "Fan in/s").await;
    // A machine's id has 1 to 64 characters (the service refuses a longer
    // one at Store): the field takes no more, as the plane and run names.
    type_into(b, &field("machine"), &"M".repeat(70)).await;
    assert_eq!(value_of(b, &field("machine")).await, "M".repeat(64));
    type_into(b, &field("machine"), "").await;
    type_into(b, &field("speeds"), "1480").await;
    type_into(b, &field("planes[0].id"), "A").await;
    type_into(b, &field("sensors[0].id"), "1H").await;
    choose(b, &field("sensors[0].unit"), "in_s_pk").await;
    b.click("#step-setup button.next").await;
    type_into(b, &field("runs[0].readings[0].amplitude"), "0.085").await;
    type_into(
        b,
        &field("runs[0].readings[0].phase_deg"),
        &format!("212.4{ENTER}"),
    )
    .await;
    b.wait_for("#step-runs button.add-trial").await;
    b.click("#step-runs button.add-trial").await;
    // The step drawn again while a cell is typed in (what the trial-weight
    // suggestion does when its answer arrives): the typing goes on in it.
    let mass = field("runs[1].weights[0].mass_g");
    type_into(b, &mass, "2").await;
    b.client
        .execute_async(
            "const done = arguments[0]; import('/static/js/job/state.js').then((m) => { m.changed(); done(); })",
            vec![],
        )
        .await
        .unwrap();
    b.client
        .active_element()
        .await
        .unwrap()
        .send_keys("0")
        .await
        .unwrap();
    assert_eq!(value_of(b, &mass).await, "20", "typing went on in the cell");
    type_into(b, &field("runs[1].weights[0].angle_deg"), "0").await;
    type_into(b, &field("runs[1].readings[0].amplitude"), "0.06").await;
    type_into(
        b,
        &field("runs[1].readings[0].phase_deg"),
        &format!("100,25{ENTER}"),
    )
    .await;
    b.wait_until(
        "both runs stored",
        "return document.querySelectorAll('#step-runs td.value.amp').length === 2",
    )
    .await;
    // Before: "0.09" and "212" for what was typed as 0.085 and 212.4, and
    // later "100.3" for 100,25 (four significant digits); a decimal comma
    // comes back as a point.
    assert_eq!(
        texts(b, "#step-runs td.value.amp").await,
        ["0.085", "0.06"],
        "amplitudes as typed"
    );
    assert_eq!(
        texts(b, "#step-runs td.value.phase").await,
        ["212.4", "100.25"],
        "phases as typed"
    );

    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .summary").await;
    let labels = texts(b, "#step-solve .summary .big .label").await;
    assert_eq!(
        labels[..2],
        ["RMS over sensors, in/s peak", "Largest, in/s peak"],
        "the summary's figures say their unit"
    );
    // 0.085 as found, not 0.09; the residual's phases say their convention.
    assert_eq!(
        texts(b, "#step-solve table.residual td.before").await,
        ["0.085"]
    );
    let heads = texts(b, "#step-solve table.residual th").await;
    assert!(heads.contains(&"Phase, ° (lag)".to_string()), "{heads:?}");
    let summary = b.text("#step-solve .summary").await;
    assert!(summary.contains("0.085 →"), "{summary}");
}

pub async fn a_typed_run_is_not_dropped_by_opening_another_job(stand: &Stand) {
    let b = &stand.browser;
    type_into(b, &field("name"), "Typed").await;
    type_into(b, &field("speeds"), "1480").await;
    type_into(b, &field("planes[0].id"), "A").await;
    type_into(b, &field("sensors[0].id"), "1H").await;
    b.click("#step-setup button.next").await;
    let cell = field("runs[0].readings[0].amplitude");
    type_into(b, &cell, "85").await;
    b.click("nav [data-step=\"sessions\"]").await;
    b.click("#step-sessions button.new-session").await;
    let asked = confirmation(b).await;
    assert!(
        asked.starts_with("The run “zero” is typed but not stored."),
        "{asked}"
    );
    b.client.dismiss_alert().await.unwrap();
    b.click("nav [data-step=\"runs\"]").await;
    assert_eq!(
        value_of(b, &cell).await,
        "85",
        "the typed run is still there"
    );
    b.click("nav [data-step=\"sessions\"]").await;
    b.click("#step-sessions button.new-session").await;
    confirmation(b).await;
    b.client.accept_alert().await.unwrap();
    b.wait_until(
        "a new job's set-up",
        "return !document.querySelector('#step-setup').hidden && document.querySelector('[data-field=\"name\"]').value === ''",
    )
    .await;
}

/// A spreadsheet row pasted into the grid (cells split by tabs, rows by line
/// breaks, decimal commas, a trailing line break as spreadsheets copy it):
/// every value lands in its own cell, in Tab order. WebDriver cannot reach
/// the system clipboard in headless Chromium, so the paste is the event the
/// page gets, carrying the clipboard's text. It landed whole in the first cell.
pub async fn a_pasted_spreadsheet_block_fills_the_cells_in_tab_order(stand: &Stand) {
    let b = &stand.browser;
    type_into(b, &field("name"), "Pasted").await;
    type_into(b, &field("speeds"), "1480").await;
    type_into(b, &field("planes[0].id"), "A").await;
    type_into(b, &field("sensors[0].id"), "1H").await;
    b.click("button.add-sensor").await;
    type_into(b, &field("sensors[1].id"), "1V").await;
    b.click("#step-setup button.next").await;
    let first = field("runs[0].readings[0].amplitude");
    b.wait_for(&first).await;
    let paste = format!(
        "const cell = document.querySelector({}); cell.focus(); \
         const data = new DataTransfer(); data.setData('text/plain', '85,5\\t212.4\\r\\n61.25\\t100,25\\r\\n'); \
         cell.dispatchEvent(new ClipboardEvent('paste', {{ clipboardData: data, bubbles: true, cancelable: true }}));",
        serde_json::to_string(&first).unwrap()
    );
    b.client.execute(&paste, vec![]).await.unwrap();
    let mut cells = Vec::new();
    for f in [
        "readings[0].amplitude",
        "readings[0].phase_deg",
        "readings[1].amplitude",
        "readings[1].phase_deg",
    ] {
        cells.push(value_of(b, &field(&format!("runs[0].{f}"))).await);
    }
    assert_eq!(
        cells,
        ["85,5", "212.4", "61.25", "100,25"],
        "one value a cell"
    );
    // A value more than the run has cells left is said, not dropped unseen.
    let second = field("runs[0].readings[1].amplitude");
    let again = format!(
        "const cell = document.querySelector({}); cell.focus(); \
         const data = new DataTransfer(); data.setData('text/plain', '61.25\\t100,25\\t0.5'); \
         cell.dispatchEvent(new ClipboardEvent('paste', {{ clipboardData: data, bubbles: true, cancelable: true }}));",
        serde_json::to_string(&second).unwrap()
    );
    b.client.execute(&again, vec![]).await.unwrap();
    assert_eq!(
        b.text("#step-runs .banner.error").await,
        "3 values were pasted and 2 cells of this run were left from the one pasted into: \
         the last value (0.5) was not used. Check that the block was copied from the right place."
    );
    // Stored as typed: the grid shows what was pasted (a decimal comma as a point).
    b.click("#step-runs button.store").await;
    b.wait_for("#step-runs button.add-trial").await;
    assert_eq!(texts(b, "#step-runs td.value.amp").await, ["85.5", "61.25"]);
    assert_eq!(
        texts(b, "#step-runs td.value.phase").await,
        ["212.4", "100.25"]
    );
}
