//! End-to-end tests of the form's error handling: a bad number is marked at
//! its cell as it is typed, before anything is sent, and an error from the
//! server is shown at the field its `error.field` names.

mod browser;
mod common;

use browser::form::{self, field, type_into, type_setup};
use browser::stand::{example_session, Stand};
use fantoccini::Locator;
use serde_json::{json, Value};

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_bad_number_is_marked_before_sending_and_a_server_error_at_its_field() {
    let stand = Stand::start().await;
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;

    let cell = field("runs[0].readings[2].phase_deg");
    type_into(b, &cell, "12x").await;
    let msg = format!(".field.bad:has({cell}) .msg");
    assert_eq!(b.text(&msg).await, "not a number");
    b.click("#step-runs button.store").await;
    let banner = b.text("#step-runs .banner.error").await;
    assert!(banner.contains("Nothing was sent"), "{banner}");
    let list: Value = reqwest::get(stand.server.url("/api/v1/sessions"))
        .await
        .unwrap()
        .json()
        .await
        .unwrap();
    assert_eq!(list["total"], json!(0), "nothing may be stored: {list}");
    // A decimal comma is a number.
    type_into(b, &cell, "330,4").await;
    assert!(
        b.client.find(Locator::Css(&msg)).await.is_err(),
        "the mark goes when the number is fixed"
    );
    b.viewport(1280, 800).await;
    // A lone minus sign is a number being typed: marked only when the cell is left.
    type_into(b, &cell, "-").await;
    assert!(
        b.client.find(Locator::Css(&msg)).await.is_err(),
        "no mark while typing '-'"
    );
    b.client
        .active_element()
        .await
        .unwrap()
        .send_keys("\u{e004}")
        .await
        .unwrap();
    assert_eq!(b.text(&msg).await, "not a number");
    b.screenshot("runs-bad-cell-1280").await;
    type_into(b, &cell, "330.36690382308").await;

    // Store the zero run, then let another client take the next run's name.
    let mut zero_session = session.clone();
    zero_session["runs"] = json!([session["runs"][0]]);
    form::type_cells_with_tab(b, 0, &form::cells(&zero_session, &session["runs"][0])).await;
    // Enter in a cell stores the run, as the store button does.
    b.client
        .active_element()
        .await
        .unwrap()
        .send_keys("\u{e007}")
        .await
        .unwrap();
    b.wait_for("#step-runs button.add-trial").await;
    let list: Value = reqwest::get(stand.server.url("/api/v1/sessions"))
        .await
        .unwrap()
        .json()
        .await
        .unwrap();
    let id = list["sessions"][0]["id"].as_str().unwrap().to_string();
    let mut taken = session["runs"][1].clone();
    taken["id"] = json!("trial 1");
    let resp = reqwest::Client::new()
        .post(stand.server.url(&format!("/api/v1/sessions/{id}/runs")))
        .json(&taken)
        .send()
        .await
        .unwrap();
    assert_eq!(resp.status(), 201);
    b.click("button.add-trial").await;
    type_into(b, &field("runs[1].weights[0].mass_g"), "30").await;
    type_into(b, &field("runs[1].weights[0].angle_deg"), "0").await;
    form::type_cells_with_tab(b, 1, &form::cells(&session, &session["runs"][1])).await;
    b.click("#step-runs button.store").await;
    let at_field = format!(".field.bad:has({}) .msg", field("runs[1].id"));
    let message = b.text(&at_field).await;
    assert!(
        message.contains("already has a run"),
        "server message at the run name: {message}"
    );
    stand.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_server_error_naming_a_set_up_field_brings_the_set_up_back_with_the_field_marked() {
    let stand = Stand::start().await;
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;
    b.wait_for(&field("runs[0].readings[0].amplitude")).await;
    // The answer the service gives to a bad set-up when the zero run is posted.
    let script = r#"
        const [done] = arguments;
        import('/static/js/fields.js').then((m) => done(m.markServerError(
          { field: 'planes[1].radius_mm', message: 'the radius of 1e9 mm is beyond the plausible limit' },
          'runs[0].')));
    "#;
    let found = b.client.execute_async(script, vec![]).await.unwrap();
    assert_eq!(found, json!(true));
    let setup_shown = b
        .client
        .execute(
            "return !document.querySelector('#step-setup').hidden",
            vec![],
        )
        .await
        .unwrap();
    assert_eq!(setup_shown, json!(true));
    let msg = format!(".field.bad:has({}) .msg", field("planes[1].radius_mm"));
    assert_eq!(
        b.text(&msg).await,
        "the radius of 1e9 mm is beyond the plausible limit"
    );
    let focused = b
        .client
        .active_element()
        .await
        .unwrap()
        .attr("data-field")
        .await
        .unwrap();
    assert_eq!(focused.as_deref(), Some("planes[1].radius_mm"));
    stand.stop().await;
}
