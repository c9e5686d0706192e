//! What several of this binary's tests share: the public pump example's
//! session, a machine to file sessions under, and an error body's parts.

use crate::common;

use common::{example, post};
use serde_json::{json, Value};

/// The session of the public example `pump-two-plane-exact.json`.
pub fn pump() -> Value {
    example("pump-two-plane-exact.json")["session"].clone()
}

/// Machine P-1, created.
pub async fn machine_p1(client: &reqwest::Client, server: &common::Server) {
    let (status, _, body) = post(
        client,
        &server.url("/api/v1/machines"),
        &json!({"id": "P-1"}),
    )
    .await;
    assert_eq!(status, 201, "{body}");
}

/// The error's code, field and message.
pub fn error_of(body: &Value) -> (&str, Option<&str>, &str) {
    (
        body["error"]["code"].as_str().unwrap_or(""),
        body["error"]["field"].as_str(),
        body["error"]["message"].as_str().unwrap_or(""),
    )
}
