//! Session 22's outside review of the API (qa22): what a hostile client
//! found that earlier reviews left.

use crate::common;

use common::{example, fresh_server, post};
use serde_json::{json, Value};

fn pump() -> Value {
    example("pump-two-plane-exact.json")["session"].clone()
}

/// The error's code, field and message.
fn error_of(body: &Value) -> (&str, Option<&str>, &str) {
    (
        body["error"]["code"].as_str().unwrap_or(""),
        body["error"]["field"].as_str(),
        body["error"]["message"].as_str().unwrap_or(""),
    )
}

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
