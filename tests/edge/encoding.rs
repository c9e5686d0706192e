//! Compressed request bodies (`Content-Encoding`): the service decompresses
//! none, so a body sent as gzip (stand software compressing a big session) is
//! refused with 415 naming `Content-Encoding`, before its body is read, and
//! nothing is stored. Before this refusal the header was ignored and the gzip
//! bytes were parsed as JSON: a 400 `malformed_json` that named no cause.

use crate::common;
use crate::support;

use reqwest::header::{CONTENT_ENCODING, CONTENT_TYPE};
use serde_json::Value;

use common::{example, fresh_server, send};

/// CRC-32 (IEEE, reflected), for the gzip trailer.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

/// A valid gzip member (RFC 1952) holding `data` in stored deflate blocks
/// (RFC 1951 §3.2.4): what `gzip` sends, without a compressor in the tests.
fn gzip(data: &[u8]) -> Vec<u8> {
    let mut out = vec![0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 0xff];
    let mut chunks = data.chunks(0xffff).peekable();
    if chunks.peek().is_none() {
        out.extend_from_slice(&[1, 0, 0, 0xff, 0xff]);
    }
    while let Some(chunk) = chunks.next() {
        let last = u8::from(chunks.peek().is_none());
        let len = chunk.len() as u16;
        out.push(last);
        out.extend_from_slice(&len.to_le_bytes());
        out.extend_from_slice(&(!len).to_le_bytes());
        out.extend_from_slice(chunk);
    }
    out.extend_from_slice(&crc32(data).to_le_bytes());
    out.extend_from_slice(&(data.len() as u32).to_le_bytes());
    out
}

#[test]
fn the_test_gzip_is_gzip() {
    // The check value of CRC-32 (IEEE) and the empty member's known bytes.
    assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    assert_eq!(
        gzip(b""),
        [0x1f, 0x8b, 8, 0, 0, 0, 0, 0, 0, 0xff, 1, 0, 0, 0xff, 0xff, 0, 0, 0, 0, 0, 0, 0, 0]
    );
}

fn assert_refused(status: u16, headers: &reqwest::header::HeaderMap, answer: &Value, what: &str) {
    assert_eq!(status, 415, "{what}: {answer}");
    assert_eq!(answer["error"]["code"], "unsupported_media_type", "{what}");
    assert_eq!(answer["error"]["field"], "Content-Encoding", "{what}");
    assert!(
        answer["error"]["message"]
            .as_str()
            .is_some_and(|m| m.contains("uncompressed")),
        "{what}: {answer}"
    );
    assert_eq!(headers["accept-encoding"], "identity", "{what}");
}

#[tokio::test]
async fn a_gzip_body_is_refused_with_415_naming_content_encoding_and_nothing_is_stored() {
    let (_dir, server, client) = fresh_server().await;
    let session = example("pump-two-plane-exact.json")["session"].clone();
    let json = serde_json::to_vec(&session).unwrap();
    let sessions = server.url("/api/v1/sessions");
    // The message shows at most 64 characters of the header; the check reads all of it.
    let long = format!("{}gzip", "identity, ".repeat(10));
    for (what, coding) in [
        ("gzip", "gzip"),
        ("GZIP in capitals", "GZIP"),
        ("x-gzip", "x-gzip"),
        ("gzip after identity", "identity, gzip"),
        ("gzip after 64 characters", long.as_str()),
        ("deflate", "deflate"),
        ("br", "br"),
    ] {
        let (status, headers, answer) = send(
            client
                .post(&sessions)
                .header(CONTENT_TYPE, "application/json")
                .header(CONTENT_ENCODING, coding)
                .body(gzip(&json)),
        )
        .await;
        assert_refused(status, &headers, &answer, what);
    }
    // A stateless solve too: every body is read the same way.
    let solve = serde_json::to_vec(&serde_json::json!({ "session": session })).unwrap();
    let (status, headers, answer) = send(
        client
            .post(server.url("/api/v1/solve"))
            .header(CONTENT_TYPE, "application/json")
            .header(CONTENT_ENCODING, "gzip")
            .body(gzip(&solve)),
    )
    .await;
    assert_refused(status, &headers, &answer, "solve");
    let (_, _, list) = send(client.get(&sessions)).await;
    assert_eq!(list["total"], 0, "nothing stored: {list}");

    // `identity` (or no header) is the body as it is, and is accepted, however
    // often it is said.
    let identity = format!("{}identity", "identity, ".repeat(10));
    let (status, _, answer) = send(
        client
            .post(&sessions)
            .header(CONTENT_TYPE, "application/json")
            .header(CONTENT_ENCODING, identity)
            .body(json.clone()),
    )
    .await;
    assert_eq!(status, 201, "identity: {answer}");
    // A GET has no body to decode: the header changes nothing there.
    let (status, _, list) = send(client.get(&sessions).header(CONTENT_ENCODING, "gzip")).await;
    assert_eq!(status, 200, "{list}");
    assert_eq!(list["total"], 1);
    server.shutdown().await;
}

#[tokio::test]
async fn a_gzip_bomb_is_refused_before_its_body_is_read() {
    // Announced within the body limit; it would inflate far beyond it, but
    // only its head is sent: the answer cannot depend on reading it.
    let answer = support::answer_to_head(|addr| {
        format!(
            "POST /api/v1/sessions HTTP/1.1\r\nHost: {addr}\r\nContent-Type: application/json\r\n\
             Content-Encoding: gzip\r\nContent-Length: 1000000\r\n\r\n"
        )
    })
    .await;
    assert_eq!(answer.status, 415, "{:?}", answer.json());
    assert_eq!(answer.json()["error"]["field"], "Content-Encoding");
    assert_eq!(answer.header("accept-encoding"), Some("identity"));
}
