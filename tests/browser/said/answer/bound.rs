//! A mass limit that binds on a plane whose twin (the same effect on every
//! sensor) takes the rest costs no vibration: the service says so (session
//! 20), and the form's own words did not ("the vibration left will be
//! larger than without the limit").

use serde_json::json;

use crate::harness::form::{field, type_into};
use crate::harness::stand::{example_session, open_at_solve, post, Stand};

pub async fn a_limit_a_twin_plane_makes_up_for_is_not_called_costly(stand: &Stand) {
    let b = &stand.browser;
    // The pump with its outboard trial a copy of the inboard one.
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    session["runs"][2]["weights"] = session["runs"][1]["weights"].clone();
    session["runs"][2]["weights"][0]["plane"] = json!("outboard");
    session["runs"][2]["readings"] = session["runs"][1]["readings"].clone();
    let free = post(
        stand,
        "/api/v1/solve",
        json!({ "session": session.clone(), "options": {} }),
    )
    .await;
    let total: f64 = free["corrections"]
        .as_array()
        .unwrap_or_else(|| panic!("{free}"))
        .iter()
        .map(|c| c["mass_g"].as_f64().unwrap())
        .sum();
    let limit = format!("{:.1}", total / 4.0);
    let created = post(stand, "/api/v1/sessions", session).await;
    let id = created["id"].as_str().expect("stored").to_string();
    open_at_solve(stand, &id).await;
    b.click("#step-solve details.options summary").await;
    type_into(b, &field("options.max_mass_g.inboard"), &limit).await;
    b.click("#step-solve button.solve").await;
    b.wait_for("#step-solve .warnings li[data-code=\"mass_limit_active\"]")
        .await;
    let words = b
        .text("#step-solve .warnings li[data-code=\"mass_limit_active\"]")
        .await;
    assert!(
        words.contains("reached the mass limit you set")
            && words.contains("the same as without the limit")
            && !words.contains("larger"),
        "{words}"
    );
}
