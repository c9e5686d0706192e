//! Texts a client sends are held to one rule wherever they arrive: a
//! session's `name`, a sensor's `label` and its `machine` on the stateless
//! endpoints as in the store, and the residual check's `plane` id (outside
//! review, session 22).

use crate::common;
use crate::support::{error_of, pump};

use common::{fresh_server, post};
use serde_json::{json, Value};

/// A session's texts (`name`, a sensor's `label`) and the machine it names
/// are refused by the stateless endpoints that take a session (`/solve`,
/// `/trial-weights`, `/identify/rotor`) as the store refuses them: the same
/// code and message, the field named within `{"session", ...}`. `/solve`
/// answered a NUL in the name with a solution, while storing the same
/// session was refused.
#[tokio::test]
async fn stateless_endpoints_refuse_a_sessions_texts_as_the_store_does() {
    let (_dir, server, client) = fresh_server().await;
    type Edit = fn(&mut Value, &str);
    let cases: [(&str, Edit); 3] = [
        ("name", |s, c| s["name"] = json!(format!("pump{c}"))),
        ("sensors[1].label", |s, c| {
            s["sensors"][1]["label"] = json!(format!("DE {c}vertical"))
        }),
        ("machine", |s, c| s["machine"] = json!(format!("P-1{c}"))),
    ];
    let store = server.url("/api/v1/sessions");
    for (field, edit) in cases {
        for c in ["\u{0}", "\u{7}", "\u{1b}", "\u{7f}", "\u{85}"] {
            let mut s = pump();
            edit(&mut s, c);
            let (status, _, stored) = post(&client, &store, &s).await;
            assert_eq!(status, 422, "store {field} {c:?}: {stored}");
            let (code, f, message) = error_of(&stored);
            assert_eq!((code, f), ("invalid_value", Some(field)), "{stored}");
            let under = format!("session.{field}");
            for endpoint in [
                "/api/v1/solve",
                "/api/v1/trial-weights",
                "/api/v1/identify/rotor",
            ] {
                let (status, _, err) =
                    post(&client, &server.url(endpoint), &json!({"session": s})).await;
                let (got_code, got_field, got_message) = error_of(&err);
                assert_eq!(
                    (status, got_code, got_field, got_message),
                    (422, code, Some(under.as_str()), message),
                    "{endpoint}: {field} {c:?}: {err}"
                );
            }
        }
    }
    // Tabs and line breaks stay allowed in texts, on every endpoint.
    let mut s = pump();
    s["name"] = json!("pump 3\r\n\tcoupling end");
    s["sensors"][1]["label"] = json!("DE\tvertical\n(new probe)");
    for endpoint in ["/api/v1/solve", "/api/v1/trial-weights"] {
        let (status, _, body) = post(&client, &server.url(endpoint), &json!({"session": s})).await;
        assert_eq!(status, 200, "{endpoint}: {body}");
    }
    let (status, _, body) = post(&client, &store, &s).await;
    assert_eq!(status, 201, "{body}");
}

/// The residual-unbalance check's `plane` is an id, held to the id rule of
/// every other id (no control character): `"A\u0000"` was answered back
/// with its NUL.
#[tokio::test]
async fn a_residual_checks_plane_id_holds_no_control_character() {
    let (_dir, server, client) = fresh_server().await;
    let readings: Vec<Value> = (0..6)
        .map(|k| {
            let a = 60.0 * k as f64;
            json!({"angle_deg": a, "amplitude": 1.0 + 0.3 * a.to_radians().cos()})
        })
        .collect();
    let body = |plane: &str| {
        json!({"plane": plane, "speed_rpm": 9000, "trial": {"mass_g": 2.0, "radius_mm": 150},
               "journal_load_kg": 530.7, "readings": readings})
    };
    let url = server.url("/api/v1/residual-unbalance");
    for plane in ["A\u{0}", "A\n", "\u{1b}[31mA", "A\u{85}"] {
        let (status, _, err) = post(&client, &url, &body(plane)).await;
        let (code, field, message) = error_of(&err);
        assert_eq!(
            (status, code, field),
            (422, "invalid_value", Some("plane")),
            "{plane:?}: {err}"
        );
        assert!(message.contains("control"), "{message}");
    }
    let (status, _, answer) = post(&client, &url, &body("Lüfter A/2")).await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(answer["plane"], "Lüfter A/2");
}
