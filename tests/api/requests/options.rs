//! Solve options a request may not give, or gives in a form that means the
//! same: a mass bound under the lightest weight, options `/trial-weights`
//! does not use, a speed point listed twice (outside reviews, sessions 22
//! and 23).

use crate::common;
use crate::support::{error_of, pump};

use common::{fresh_server, post};
use serde_json::json;

/// A `max_mass_g` bound is at least the lightest weight a session may give
/// (1e-6 g, as a run's `mass_g`): a bound of 5e-324 g was taken, answered a
/// correction of 5e-324 g with an empty `split` on a plane with fixed places,
/// and a warning spelling the bound with some 320 zeros.
#[tokio::test]
async fn a_mass_bound_below_the_lightest_weight_is_refused_naming_the_plane() {
    let (_dir, server, client) = fresh_server().await;
    let mut s = pump();
    s["planes"][0]["positions"] = json!(12);
    let url = server.url("/api/v1/solve");
    for bound in [5e-324, 1e-300, 1e-12, 9.9e-7] {
        for objective in ["least_squares", "min_max"] {
            let body = json!({"session": s, "options": {"objective": objective, "max_mass_g": {"inboard": bound}}});
            let (status, _, err) = post(&client, &url, &body).await;
            assert_eq!(status, 422, "{bound:e} {objective}: {err}");
            let (code, field, message) = error_of(&err);
            assert_eq!(
                (code, field),
                ("invalid_value", Some("options.max_mass_g.inboard")),
                "{err}"
            );
            assert!(message.contains("1e-6 g"), "{message}");
        }
    }
    // From the lightest weight on, the bound holds and the correction is
    // split over the plane's places.
    let body = json!({"session": s, "options": {"max_mass_g": {"inboard": 1e-6}}});
    let (status, _, solution) = post(&client, &url, &body).await;
    assert_eq!(status, 200, "{solution}");
    let c = &solution["corrections"][0];
    assert!(c["mass_g"].as_f64().unwrap() <= 1e-6 * (1.0 + 1e-9), "{c}");
    assert_eq!(c["split"].as_array().map(Vec::len), Some(2), "{c}");
}

/// `POST /api/v1/trial-weights` refuses a solve option it does not use with
/// 422 `unused_option` naming it (`options.discrete`, …): it answered the
/// same suggestions with or without them, so a client asking for
/// `"discrete": true` or `"from_run"` was not told they changed nothing.
/// The options it uses still answer, and an unknown key stays 400
/// `unknown_field` as on `/solve`.
#[tokio::test]
async fn trial_weights_refuse_the_solve_options_they_do_not_use() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/trial-weights");
    let unused = [
        ("objective", json!("min_max")),
        ("max_mass_g", json!({"inboard": 50})),
        ("drop_dependent_planes", json!(true)),
        ("amplitude_noise_pct", json!(5)),
        ("phase_noise_deg", json!(3)),
        ("from_run", json!("zero")),
        ("discrete", json!(true)),
        ("discrete", json!(false)),
        ("fit_time_limit_ms", json!(100)),
    ];
    for (key, value) in unused {
        let body = json!({"session": pump(), "options": {"planes": ["inboard"], key: value}});
        let (status, _, answer) = post(&client, &url, &body).await;
        let (code, field, message) = error_of(&answer);
        let want = format!("options.{key}");
        assert_eq!(
            (status, code, field),
            (422, "unused_option", Some(want.as_str())),
            "{key}: {answer}"
        );
        assert!(message.contains(key), "{message}");
    }
    let used = json!({
        "planes": ["inboard"],
        "sensors": ["DE-H", "NDE-H"],
        "speeds_rpm": [2950],
        "row_weights": [{"sensor": "DE-H", "weight": 2}],
    });
    let (status, _, answer) =
        post(&client, &url, &json!({"session": pump(), "options": used})).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(
        answer["suggestions"].as_array().map(Vec::len),
        Some(1),
        "{answer}"
    );
    let body = json!({"session": pump(), "options": {"discret": true}});
    let (status, _, answer) = post(&client, &url, &body).await;
    let (code, field, _) = error_of(&answer);
    assert_eq!(
        (status, code, field),
        (400, "unknown_field", Some("options.discret")),
        "{answer}"
    );
}

/// A speed point may be listed more than once in `options.speeds_rpm`
/// (stand software may send each sensor's recorded speed of one point, and
/// speeds within 1 % are one point): the selection is the same as listing
/// it once. Kept deliberately where a sensor or plane listed twice is
/// refused, since refusing would break such clients; this test holds the
/// decision.
#[tokio::test]
async fn a_speed_point_listed_twice_selects_what_listing_it_once_does() {
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/solve");
    let once = json!({"session": pump(), "options": {"speeds_rpm": [2950]}});
    let (status, _, single) = post(&client, &url, &once).await;
    assert_eq!(status, 200, "{single}");
    for speeds in [json!([2950, 2950]), json!([2950, 2960])] {
        let body = json!({"session": pump(), "options": {"speeds_rpm": speeds}});
        let (status, _, solution) = post(&client, &url, &body).await;
        assert_eq!(status, 200, "{speeds}: {solution}");
        assert_eq!(solution["corrections"], single["corrections"], "{speeds}");
    }
}
