//! A machine given an id and no name in the form: the form stored the id as
//! its name. It is now stored without one, and the pages show the id once.

use serde_json::json;

use crate::harness::form::{field, type_into};
use crate::harness::stand::{get, Stand};

pub async fn a_machine_without_a_name_is_stored_without_one(stand: &Stand) {
    let b = &stand.browser;
    b.click("nav [data-step=\"machines\"]").await;
    type_into(b, &field("machine.id"), "FAN-7").await;
    b.click("button.create-machine").await;
    b.wait_until(
        "the machine's page is shown",
        "return location.hash === '#machine=FAN-7' && !!document.querySelector('#step-machines h3')",
    )
    .await;
    let stored = get(stand, "/api/v1/machines/FAN-7").await;
    assert_eq!(stored["id"], "FAN-7", "{stored}");
    assert_eq!(stored.get("name"), None, "no name stored: {stored}");
    assert_eq!(b.text("#step-machines h2").await, "Machine FAN-7");
    b.click("nav [data-step=\"machines\"]").await;
    b.wait_for("button.open-machine[data-id=\"FAN-7\"]").await;
    let row = crate::harness::steps::js(
        b,
        "const r = document.querySelector('button.open-machine[data-id=\"FAN-7\"]').closest('tr'); return [r.cells[0].textContent, r.cells[1].textContent]",
    )
    .await;
    assert_eq!(row, json!(["FAN-7", "–"]));
}
