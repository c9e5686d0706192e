//! Conditional and idempotent writes: `If-Match` on a session's DELETE, a
//! malformed `If-Match`, its lines as one list, and two `Idempotency-Key`
//! lines (outside reviews, sessions 22 and 23).

use crate::common;
use crate::support::{error_of, pump};

use common::{fresh_server, post, send};
use serde_json::json;

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

/// An `If-Match` that is not `*` or a list of entity-tags (an unquoted
/// tag, an unterminated one, a bare `W/`, `*` in a list, nothing at all) is
/// refused with 400 `invalid_header` naming `If-Match`, on a run's PUT and
/// a session's DELETE, nothing changed: it was answered 412 "changed
/// meanwhile", even when the unquoted tag named the current version, so a
/// client re-read and sent the same header for ever. Several `If-Match`
/// lines are one list (RFC 9110 §5.3): a tag on the second line matches,
/// where only the first line was read.
#[tokio::test]
async fn a_malformed_if_match_is_refused_and_its_lines_are_one_list() {
    let (_dir, server, client) = fresh_server().await;
    let (_, _, created) = post(&client, &server.url("/api/v1/sessions"), &pump()).await;
    let session = server.url(&format!(
        "/api/v1/sessions/{}",
        created["id"].as_str().unwrap()
    ));
    let run = format!("{session}/runs/zero");
    let (status, headers, body) = send(client.get(&run)).await;
    assert_eq!(status, 200, "{body}");
    let tag = headers["etag"].to_str().unwrap().to_string();
    let malformed = [
        tag.trim_matches('"').to_string(),
        format!("\"{tag}"),
        tag[..tag.len() - 1].to_string(),
        "W/".into(),
        ",".into(),
        "".into(),
        format!("*, {tag}"),
        "\"v 1\"".into(),
        format!("{tag} {tag}"),
    ];
    for value in &malformed {
        let (status, _, err) = send(client.put(&run).header("If-Match", value).json(&body)).await;
        let (code, field, message) = error_of(&err);
        assert_eq!(
            (status, code, field),
            (400, "invalid_header", Some("If-Match")),
            "PUT If-Match: {value}: {message}"
        );
        let (status, _, err) = send(client.delete(&session).header("If-Match", value)).await;
        let (code, field, message) = error_of(&err);
        assert_eq!(
            (status, code, field),
            (400, "invalid_header", Some("If-Match")),
            "DELETE If-Match: {value}: {message}"
        );
    }
    let (_, versions, _) = send(client.get(format!("{run}/versions"))).await;
    assert_eq!(versions["x-total-count"], "1", "nothing was stored");
    // Two lines, the current tag on the second: they match as one list.
    let (status, _, answer) = send(
        client
            .put(&run)
            .header("If-Match", "\"v7\"")
            .header("If-Match", &tag)
            .json(&body),
    )
    .await;
    assert_eq!(status, 200, "{answer}");
    // The session as it is now (the same run stored again).
    let (_, headers, _) = send(client.get(&session)).await;
    let now = headers["etag"].to_str().unwrap().to_string();
    let (status, _, answer) = send(
        client
            .delete(&session)
            .header("If-Match", "W/\"x\"")
            .header("If-Match", format!("\"a,b\", {now}")),
    )
    .await;
    assert_eq!(status, 204, "{answer}");
}

/// Two `Idempotency-Key` lines are refused as the one line a proxy joins
/// them into (`a1, a2`, which holds a space) is: 422 `invalid_header`
/// naming the header, nothing stored. The first line alone was used, so a
/// retry whose lines came in the other order stored the session again.
#[tokio::test]
async fn two_idempotency_keys_are_refused_as_their_joined_line_is() {
    let (_dir, server, client) = fresh_server().await;
    let store = server.url("/api/v1/sessions");
    for keys in [["k-1", "k-2"], ["k-2", "k-1"], ["k-1", "k-1"]] {
        let (status, _, err) = send(
            client
                .post(&store)
                .header("Idempotency-Key", keys[0])
                .header("Idempotency-Key", keys[1])
                .json(&pump()),
        )
        .await;
        let joined = send(
            client
                .post(&store)
                .header("Idempotency-Key", keys.join(", "))
                .json(&pump()),
        )
        .await;
        let (code, field, _) = error_of(&err);
        assert_eq!(
            (status, code, field),
            (422, "invalid_header", Some("Idempotency-Key")),
            "{keys:?}: {err}"
        );
        assert_eq!(
            (status, error_of(&err)),
            (joined.0, error_of(&joined.2)),
            "{keys:?}"
        );
    }
    let (_, _, list) = send(client.get(&store)).await;
    assert_eq!(list["total"], 0, "nothing was stored: {list}");
}
