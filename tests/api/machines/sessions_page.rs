//! A machine's sessions, all of them by default or a page on request
//! (outside review, session 22).

use crate::common;
use crate::support::pump;

use common::{fresh_server, post};
use serde_json::{json, Value};

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
