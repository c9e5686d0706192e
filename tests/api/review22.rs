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

/// `GET /api/v1/machines/{id}` gives every session of the machine (its
/// default answer, unchanged) and, on request, a page of them: `limit` (1
/// to 1000) and `offset` page the sessions, oldest first, with their number
/// in all in `X-Total-Count`, read from one snapshot with the page. A query
/// it does not know is refused as every list refuses one (it ignored
/// `?limit=1` and answered every session, so a client asking for a page
/// could not tell it got everything).
#[tokio::test]
async fn a_machines_sessions_can_be_paged_and_the_default_is_every_session() {
    let (_dir, server, client) = fresh_server().await;
    let (status, _, m) = post(
        &client,
        &server.url("/api/v1/machines"),
        &json!({"id": "P-7", "name": "pump 7"}),
    )
    .await;
    assert_eq!(status, 201, "{m}");
    let mut ids = Vec::new();
    for k in 0..5 {
        let mut s = pump();
        s["machine"] = json!("P-7");
        s["name"] = json!(format!("job {k}"));
        let (status, _, created) = post(&client, &server.url("/api/v1/sessions"), &s).await;
        assert_eq!(status, 201, "{created}");
        ids.push(created["id"].as_str().unwrap().to_string());
    }
    let names = |body: &Value| -> Vec<String> {
        body["sessions"]
            .as_array()
            .unwrap()
            .iter()
            .map(|s| s["id"].as_str().unwrap().to_string())
            .collect()
    };
    let get = |q: &str| {
        let url = server.url(&format!("/api/v1/machines/P-7{q}"));
        let client = client.clone();
        async move { common::send(client.get(url)).await }
    };
    let (status, headers, all) = get("").await;
    assert_eq!(status, 200, "{all}");
    assert_eq!(names(&all), ids, "every session, oldest first");
    assert_eq!(headers["x-total-count"], "5");
    // The default answer's fields, unchanged by paging (sorted by name).
    let keys: Vec<&str> = all
        .as_object()
        .unwrap()
        .keys()
        .map(|k| k.as_str())
        .collect();
    assert_eq!(
        keys,
        ["coefficients", "created_at", "id", "name", "sessions"]
    );

    let (status, headers, page) = get("?limit=2&offset=1").await;
    assert_eq!(status, 200, "{page}");
    assert_eq!(names(&page), ids[1..3]);
    assert_eq!(headers["x-total-count"], "5");
    assert_eq!(page["id"], "P-7");
    let (_, _, page) = get("?limit=2").await;
    assert_eq!(names(&page), ids[..2]);
    let (_, _, page) = get("?offset=3").await;
    assert_eq!(names(&page), ids[3..], "an offset alone: the rest");
    let (status, headers, page) = get("?offset=9").await;
    assert_eq!(status, 200, "{page}");
    assert!(names(&page).is_empty());
    assert_eq!(headers["x-total-count"], "5");

    for (q, status, code, field) in [
        ("?limit=0", 422, "out_of_range", "limit"),
        ("?limit=1001", 422, "out_of_range", "limit"),
        ("?offset=-1", 422, "out_of_range", "offset"),
        ("?limit=x", 400, "invalid_query", "limit"),
        ("?limit=1&limit=2", 400, "invalid_query", "limit"),
        ("?foo=1", 400, "invalid_query", "foo"),
    ] {
        let (got, _, err) = get(q).await;
        assert_eq!(
            (
                got,
                err["error"]["code"].as_str(),
                err["error"]["field"].as_str()
            ),
            (status, Some(code), Some(field)),
            "{q}: {err}"
        );
    }
}

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

/// `DELETE /api/v1/sessions/{id}` with `If-Match` deletes only the session
/// the client read: a session changed since (its `ETag` is another) is
/// kept and the answer is 412 naming `If-Match`, as a run's `PUT` answers.
/// It was deleted whatever `If-Match` said. Without the header, or with
/// `*`, a delete is unconditional as before.
#[tokio::test]
async fn deleting_a_session_honours_if_match() {
    let (_dir, server, client) = fresh_server().await;
    let store = server.url("/api/v1/sessions");
    let mut first = pump();
    first["runs"] = json!([pump()["runs"][0]]);
    let (_, _, created) = post(&client, &store, &first).await;
    let id = created["id"].as_str().unwrap().to_string();
    let url = server.url(&format!("/api/v1/sessions/{id}"));
    let (_, headers, _) = common::send(client.get(&url)).await;
    let read = headers["etag"].to_str().unwrap().to_string();
    // Another client appends a run: the session the first one read is gone.
    let (status, _, appended) = post(&client, &format!("{url}/runs"), &pump()["runs"][1]).await;
    assert_eq!(status, 201, "{appended}");
    let (_, headers, _) = common::send(client.get(&url)).await;
    let now = headers["etag"].to_str().unwrap().to_string();
    assert_ne!(read, now);
    for tag in [read.clone(), format!("W/{now}"), "\"bogus\"".into()] {
        let (status, _, err) =
            common::send(client.delete(&url).header("If-Match", tag.as_str())).await;
        let (code, field, _) = error_of(&err);
        assert_eq!(
            (status, code, field),
            (412, "precondition_failed", Some("If-Match")),
            "{tag}: {err}"
        );
        let (status, _, kept) = common::send(client.get(&url)).await;
        assert_eq!(status, 200, "{tag}: the session is kept: {kept}");
        assert_eq!(kept["runs"].as_array().map(Vec::len), Some(2));
    }
    // An unquoted tag is no entity-tag: 400 naming If-Match since qa23
    // (it was 412 "changed"), the session kept.
    let (status, _, err) = common::send(client.delete(&url).header("If-Match", "bogus")).await;
    let (code, field, _) = error_of(&err);
    assert_eq!(
        (status, code, field),
        (400, "invalid_header", Some("If-Match")),
        "{err}"
    );
    let (status, _, _) = common::send(
        client
            .delete(&url)
            .header("If-Match", format!("\"other\", {now}")),
    )
    .await;
    assert_eq!(status, 204, "a list holding the current tag matches");
    let (status, _, _) = common::send(client.get(&url)).await;
    assert_eq!(status, 404);
    // Unconditional deletes stay as they were.
    for tag in [None, Some("*")] {
        let (_, _, created) = post(&client, &store, &pump()).await;
        let url = server.url(&format!(
            "/api/v1/sessions/{}",
            created["id"].as_str().unwrap()
        ));
        let mut req = client.delete(&url);
        if let Some(t) = tag {
            req = req.header("If-Match", t);
        }
        let (status, _, body) = common::send(req).await;
        assert_eq!(status, 204, "{tag:?}: {body}");
    }
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
