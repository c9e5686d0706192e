//! End-to-end tests of the form's error handling: a bad number is marked at
//! its cell as it is typed, before anything is sent, and an error from the
//! server is shown at the field its `error.field` names.

use crate::harness::form::{self, field, type_into, type_setup};
use crate::harness::stand::{example_session, get, stored_session_id, Stand};
use fantoccini::Locator;
use serde_json::{json, Value};

/// One browser for every scene of this binary (CI time); each scene gets a
/// new server and database and a freshly loaded form (`Stand::renew`).
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_form_marks_each_mistake_at_its_field_and_loses_nothing() {
    let mut stand = Stand::start().await;
    a_bad_number_is_marked_before_sending_and_a_server_error_at_its_field(&stand).await;
    stand.renew().await;
    a_server_error_naming_a_set_up_field_brings_the_set_up_back_with_the_field_marked(&stand).await;
    stand.renew().await;
    a_mistyped_run_is_corrected_in_place_and_stored_as_a_new_version(&stand).await;
    stand.renew().await;
    typed_numbers_are_accepted_or_refused_as_the_table_says(&stand).await;
    stand.renew().await;
    changing_the_sensors_keeps_each_typed_cell_with_its_sensor(&stand).await;
    stand.stop().await;
}

async fn a_bad_number_is_marked_before_sending_and_a_server_error_at_its_field(stand: &Stand) {
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
    let list = get(stand, "/api/v1/sessions").await;
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
    crate::harness::job::shots(b, "runs-bad-cell").await;
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
    let id = stored_session_id(stand).await;
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
    // The other client changed the session: said first, the typed run kept.
    b.wait_until(
        "the change made elsewhere is reported",
        "const e = document.querySelector('#step-runs .banner.error'); return !!e && e.textContent.includes('changed in another tab')",
    )
    .await;
    b.click("#step-runs button.reload-session").await;
    b.wait_for("#step-runs th.run[data-run=\"trial 1\"]").await;
    b.click("#step-runs button.store").await;
    // Its run now has the name this one was given: the clash is marked at the name.
    let at_field = format!(".field.bad:has({}) .msg", field("runs[2].id"));
    let message = b.text(&at_field).await;
    assert!(
        message.contains("already has"),
        "the name clash at the run name: {message}"
    );
}

async fn a_server_error_naming_a_set_up_field_brings_the_set_up_back_with_the_field_marked(
    stand: &Stand,
) {
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;
    b.wait_for(&field("runs[0].readings[0].amplitude")).await;
    // The answer the service gives to a bad set-up when the zero run is posted.
    let script = r#"
        const [done] = arguments;
        import('/static/js/page/fields.js').then((m) => done(m.markServerError(
          { field: 'planes[1].radius_mm', message: 'the radius of 1e9 mm is beyond the plausible limit' },
          'runs[0].')));
    "#;
    let found = crate::harness::steps::js_async(b, script).await;
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
}

async fn a_mistyped_run_is_corrected_in_place_and_stored_as_a_new_version(stand: &Stand) {
    let b = &stand.browser;
    let (session, expected) = example_session("pump-two-plane-exact.json");
    let right = form::typed(&session["runs"][1]["readings"][0]["amplitude"]);
    let mut mistyped = session.clone();
    mistyped["runs"][1]["readings"][0]["amplitude"] = json!(1037.1644583458099);
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;
    form::type_run(b, &mistyped, 0, false).await;
    form::type_run(b, &mistyped, 1, false).await;

    let corrects = b
        .client
        .find_all(Locator::Css("#step-runs button.correct"))
        .await
        .unwrap();
    corrects[1].click().await.unwrap();
    let cell = field("runs[1].readings[0].amplitude");
    assert_eq!(form::value_of(b, &cell).await, "1037.1644583458099");
    type_into(b, &cell, &right).await;
    form::store(b).await;

    let id = stored_session_id(stand).await;
    let versions = get(
        stand,
        &format!("/api/v1/sessions/{id}/runs/trial%20inboard/versions"),
    )
    .await;
    assert_eq!(versions.as_array().map(Vec::len), Some(2), "{versions}");
    assert_eq!(versions[1]["current"], json!(true));
    assert_eq!(
        form::typed(&versions[1]["run"]["readings"][0]["amplitude"]),
        right
    );

    form::type_run(b, &session, 2, false).await;
    b.click("#step-runs button.go-solve").await;
    b.click("#step-solve button.solve").await;
    let shown = form::corrections_on_page(b).await;
    for (want, (plane, mass, _)) in expected["corrections"]
        .as_array()
        .unwrap()
        .iter()
        .zip(&shown)
    {
        let want_mass = want["mass_g"].as_f64().unwrap();
        assert!(
            (mass - want_mass).abs() <= 0.051,
            "{plane}: {mass} g, {want_mass} g expected"
        );
    }
}

async fn typed_numbers_are_accepted_or_refused_as_the_table_says(stand: &Stand) {
    let b = &stand.browser;
    // (typed text, kind of field, the number it gives or the message shown)
    let table: &[(&str, &str, Result<f64, &str>)] = &[
        ("12.5", "amplitude", Ok(12.5)),
        ("12,5", "amplitude", Ok(12.5)),
        (" 7 ", "phase", Ok(7.0)),
        ("1e3", "amplitude", Ok(1000.0)),
        (".5", "mass", Ok(0.5)),
        ("0", "amplitude", Ok(0.0)),
        ("12", "positions", Ok(12.0)),
        ("", "amplitude", Err("required")),
        ("12x", "amplitude", Err("not a number")),
        ("1.2.3", "phase", Err("not a number")),
        ("Infinity", "amplitude", Err("not a number")),
        ("NaN", "phase", Err("not a number")),
        ("1e400", "amplitude", Err("number too large")),
        ("-1", "amplitude", Err("amplitude must be 0 or more")),
        (
            "720",
            "phase",
            Err("phase in degrees, 0 to 360: 720° is more than a turn, the same place as 0°; type 0"),
        ),
        ("0", "mass", Err("mass in grams, more than 0")),
        ("-5", "radius", Err("radius in mm, more than 0")),
        (
            "2.5",
            "positions",
            Err("a whole number of places, 2 to 360"),
        ),
        ("1", "positions", Err("a whole number of places, 2 to 360")),
        ("361", "positions", Err("a whole number of places, 2 to 360")),
        ("0", "speed", Err("speed in rpm, more than 0")),
        // Over the top of a range the message says the top, not the bottom.
        (
            "2e6",
            "amplitude",
            Err("amplitude must be less than 1000000 (check the unit)"),
        ),
        ("2e6", "mass", Err("mass in grams, less than 1000000")),
        ("2e6", "speed", Err("speed in rpm, less than 1000000")),
        ("0", "rotor_mass", Err("rotor mass in kg, more than 0")),
        ("500", "rotor_mass", Ok(500.0)),
    ];
    let cases: Vec<Value> = table
        .iter()
        .map(|(text, kind, _)| json!([text, kind]))
        .collect();
    let script = r#"
        const [cases, done] = arguments;
        import('/static/js/page/num.js').then((m) => done(cases.map(([text, kind]) => m.check(text, kind))));
    "#;
    let got = b
        .client
        .execute_async(script, vec![json!(cases)])
        .await
        .unwrap();
    for ((text, kind, want), got) in table.iter().zip(got.as_array().unwrap()) {
        match want {
            Ok(x) => assert_eq!(got["value"].as_f64(), Some(*x), "{text:?} as {kind}: {got}"),
            Err(msg) => assert_eq!(
                got["error"].as_str(),
                Some(*msg),
                "{text:?} as {kind}: {got}"
            ),
        }
    }
}

async fn changing_the_sensors_keeps_each_typed_cell_with_its_sensor(stand: &Stand) {
    let b = &stand.browser;
    let (session, _) = example_session("pump-two-plane-exact.json");
    type_setup(b, &session).await;
    b.click("#step-setup button.next").await;
    type_into(b, &field("runs[0].readings[1].amplitude"), "185.4").await;
    type_into(b, &field("runs[0].readings[1].phase_deg"), "159").await;

    // Taking DE-H out moves DE-V's row up: the typed values must move with it.
    b.click("nav [data-step=\"setup\"]").await;
    b.click("button[aria-label=\"Remove sensor 1\"]").await;
    b.click("button.add-sensor").await;
    type_into(b, &field("sensors[3].id"), "AX").await;
    b.click("#step-setup button.next").await;
    assert_eq!(
        form::value_of(b, &field("runs[0].readings[0].amplitude")).await,
        "185.4"
    );
    assert_eq!(
        form::value_of(b, &field("runs[0].readings[0].phase_deg")).await,
        "159"
    );
    assert_eq!(
        form::value_of(b, &field("runs[0].readings[1].amplitude")).await,
        ""
    );
    assert_eq!(
        form::value_of(b, &field("runs[0].readings[3].amplitude")).await,
        ""
    );
}
