//! Rotor data all or none, in the set-up and on a new machine.

use super::{message_at, ENTER};
use crate::harness::form::{choose, field, type_into, value_of};
use crate::harness::stand::{get, Stand};
use serde_json::json;

pub async fn a_rotor_given_in_part_is_marked_not_dropped(stand: &Stand) {
    let b = &stand.browser;
    let mass = field("rotor.mass_kg");
    // A rotor's mass is kilograms, not a radius.
    type_into(b, &mass, "0").await;
    assert_eq!(message_at(b, &mass).await, "rotor mass in kg, more than 0");
    type_into(b, &mass, "420").await;
    assert_eq!(message_at(b, &mass).await, "");

    type_into(b, &field("name"), "Rotor in part").await;
    type_into(b, &field("speeds"), "1480").await;
    type_into(b, &field("planes[0].id"), "A").await;
    type_into(b, &field("planes[0].radius_mm"), "250").await;
    type_into(b, &field("sensors[0].id"), "1H").await;
    // The mass without the speed and the grade: the rotor was left out unsaid.
    b.click("#step-setup button.next").await;
    let speed = field("rotor.service_speed_rpm");
    let grade = field("rotor.balance_grade");
    let said = message_at(b, &speed).await;
    assert!(
        said.starts_with("the service speed, rpm: needed"),
        "{said:?}"
    );
    let said = message_at(b, &grade).await;
    assert!(said.starts_with("the balance grade: needed"), "{said:?}");
    assert!(
        b.client
            .execute(
                "return !document.querySelector('#step-setup').hidden",
                vec![]
            )
            .await
            .unwrap()
            == json!(true),
        "the set-up stays in view"
    );
    // With the speed but no grade the service refused the session (missing_field).
    type_into(b, &speed, "1480").await;
    b.click("#step-setup button.next").await;
    let said = message_at(b, &grade).await;
    assert!(said.starts_with("the balance grade: needed"), "{said:?}");
    choose(b, &grade, "G6.3").await;
    // Enter in a field goes on to the runs, as Enter stores a run there.
    type_into(b, &mass, &format!("420{ENTER}")).await;
    type_into(b, &field("runs[0].readings[0].amplitude"), "85").await;
    type_into(
        b,
        &field("runs[0].readings[0].phase_deg"),
        &format!("50{ENTER}"),
    )
    .await;
    b.wait_for("#step-runs button.add-trial").await;
    let list = get(stand, "/api/v1/sessions").await;
    let id = list["sessions"][0]["id"]
        .as_str()
        .expect("a stored session");
    let stored = get(stand, &format!("/api/v1/sessions/{id}")).await;
    let session = stored.get("session").unwrap_or(&stored);
    assert_eq!(
        session["rotor"],
        json!({"mass_kg": 420.0, "service_speed_rpm": 1480.0, "balance_grade": "G6.3"}),
        "{stored}"
    );
}

pub async fn a_machine_is_stored_with_its_rotor(stand: &Stand) {
    let b = &stand.browser;
    b.click("nav [data-step=\"machines\"]").await;
    type_into(b, &field("machine.id"), "FAN-3").await;
    type_into(b, &field("machine.rotor.mass_kg"), "420").await;
    b.click("button.create-machine").await;
    let speed = field("machine.rotor.service_speed_rpm");
    let said = message_at(b, &speed).await;
    assert!(
        said.starts_with("the service speed, rpm: needed"),
        "{said:?}"
    );
    let banner = b.text("#step-machines .banner.error").await;
    assert!(banner.contains("Nothing was stored"), "{banner}");
    assert_eq!(get(stand, "/api/v1/machines").await["machines"], json!([]));
    type_into(b, &speed, "1480").await;
    // Mass and speed alone: the service requires the grade, and the form had no field for it.
    choose(b, &field("machine.rotor.balance_grade"), "G2.5").await;
    assert_eq!(value_of(b, &field("machine.rotor.mass_kg")).await, "420");
    b.click("button.create-machine").await;
    b.wait_for("table.machine-jobs").await;
    let machine = get(stand, "/api/v1/machines/FAN-3").await;
    assert_eq!(
        machine["rotor"],
        json!({"mass_kg": 420.0, "service_speed_rpm": 1480.0, "balance_grade": "G2.5"}),
        "{machine}"
    );
    let page = b.text("#step-machines").await;
    assert!(
        page.contains("Rotor: 420 kg, service speed 1480 rpm, balance grade G2.5"),
        "{page}"
    );
}
