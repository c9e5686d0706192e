//! Protocol-level answers in the contract's shape: the request-line and header
//! limits checked here (414/431 with the JSON error, below hyper's own harder
//! limits, whose bare answers `unparsed.rs` completes), a JSON body for any error answered
//! without one, and the security headers of every response.

use axum::body::Body;
use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};

use crate::http::error::ApiError;

/// Longest request target answered (hyper refuses over 65,534 bytes itself: `unparsed.rs`).
pub const MAX_URI_BYTES: usize = 8 * 1024;
/// Most header fields answered (hyper's own limit is set to twice this).
pub const MAX_HEADERS: usize = 100;
/// Largest header section answered, bytes (hyper's is its read buffer, about 400 KiB).
pub const MAX_HEADER_BYTES: usize = 32 * 1024;

/// 414 / 431 with the contract's error body.
pub fn check_size<B>(req: &axum::http::Request<B>) -> Result<(), ApiError> {
    let target = req.uri().path_and_query().map_or(0, |p| p.as_str().len());
    if target > MAX_URI_BYTES {
        return Err(ApiError::new(
            StatusCode::URI_TOO_LONG,
            "uri_too_long",
            format!("the request target is longer than {MAX_URI_BYTES} bytes"),
        ));
    }
    let headers = req.headers();
    let bytes: usize = headers
        .iter()
        .map(|(name, value)| name.as_str().len() + value.len() + 4)
        .sum();
    if headers.len() > MAX_HEADERS || bytes > MAX_HEADER_BYTES {
        return Err(ApiError::new(
            StatusCode::REQUEST_HEADER_FIELDS_TOO_LARGE,
            "headers_too_large",
            format!(
                "the request has more than {MAX_HEADERS} header fields or {MAX_HEADER_BYTES} bytes of them"
            ),
        ));
    }
    Ok(())
}

/// An error answered without the JSON body (an extractor's plain-text
/// rejection, an empty status) gets one, keeping its status and headers.
pub async fn json_error_body(resp: Response) -> Response {
    let is_json = resp
        .headers()
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .is_some_and(|v| v.contains("json"));
    if is_json {
        return resp;
    }
    let (mut parts, body) = resp.into_parts();
    // Such bodies are a short sentence; anything longer is not repeated.
    let text = axum::body::to_bytes(body, 4096)
        .await
        .ok()
        .and_then(|b| String::from_utf8(b.to_vec()).ok())
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty() && s.len() <= 500);
    let status = parts.status;
    let (code, default) = describe(status);
    let field = text.as_deref().and_then(path_parameter);
    let mut error = ApiError::new(status, code, text.unwrap_or_else(|| default.to_string()));
    if let Some(field) = field {
        error = error.with_field(field);
    }
    let json = error.into_response();
    let (json_parts, json_body) = json.into_parts();
    parts.headers.remove(header::CONTENT_LENGTH);
    for (name, value) in json_parts.headers.iter() {
        parts.headers.insert(name.clone(), value.clone());
    }
    Response::from_parts(parts, Body::new(json_body))
}

/// The path parameter a path's rejection names ("Invalid URL: Invalid UTF-8
/// in `id`"), which is the field at fault.
fn path_parameter(text: &str) -> Option<String> {
    let rest = text.strip_prefix("Invalid URL: ")?;
    let name = rest.split_once(" in `")?.1.split_once('`')?.0;
    let plain = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
    plain.then(|| name.to_string())
}

/// The contract's code and a default message for a bare status.
fn describe(status: StatusCode) -> (&'static str, &'static str) {
    match status.as_u16() {
        400 => ("bad_request", "the request is malformed"),
        401 => ("unauthorized", "this service needs a bearer token"),
        403 => ("forbidden", "not allowed"),
        404 => ("not_found", "no such resource"),
        405 => (
            "method_not_allowed",
            "this resource does not accept that method",
        ),
        408 => ("request_timeout", "the request took too long"),
        413 => (
            "body_too_large",
            "the request body is larger than the server's limit",
        ),
        414 => ("uri_too_long", "the request target is too long"),
        415 => (
            "unsupported_media_type",
            "the body must be application/json",
        ),
        431 => (
            "headers_too_large",
            "the request's header fields are too large",
        ),
        503 => ("unavailable", "the service is busy; try again"),
        500..=599 => ("internal", "internal error; the server log has the details"),
        _ => ("bad_request", "the request cannot be answered"),
    }
}

/// No sniffing, no framing, no referrer anywhere; API answers are never
/// cached and may load nothing. The form's files keep their own CSP and cache rule.
pub fn security_headers(resp: &mut Response, form: bool) {
    let headers = resp.headers_mut();
    let mut set = |name: header::HeaderName, value: &'static str| {
        headers
            .entry(name)
            .or_insert_with(|| HeaderValue::from_static(value));
    };
    set(header::X_CONTENT_TYPE_OPTIONS, "nosniff");
    set(header::X_FRAME_OPTIONS, "DENY");
    set(header::REFERRER_POLICY, "no-referrer");
    if !form {
        set(header::CACHE_CONTROL, "no-store");
        set(
            header::CONTENT_SECURITY_POLICY,
            "default-src 'none'; frame-ancestors 'none'",
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[tokio::test]
    async fn a_bare_status_gets_the_contract_error_body_and_keeps_its_headers() {
        let mut bare =
            (StatusCode::BAD_REQUEST, "Invalid URL: bad percent-encoding").into_response();
        bare.headers_mut()
            .insert("x-request-id", HeaderValue::from_static("abc"));
        let resp = json_error_body(bare).await;
        assert_eq!(resp.status(), StatusCode::BAD_REQUEST);
        assert_eq!(resp.headers()["x-request-id"], "abc");
        assert_eq!(resp.headers()[header::CONTENT_TYPE], "application/json");
        let body = axum::body::to_bytes(resp.into_body(), 4096).await.unwrap();
        let value: serde_json::Value = serde_json::from_slice(&body).unwrap();
        assert_eq!(value["error"]["code"], "bad_request");
        assert_eq!(
            value["error"]["message"],
            "Invalid URL: bad percent-encoding"
        );
        assert!(value["error"].get("field").is_none());
    }

    #[test]
    fn a_path_rejection_names_its_parameter_as_the_field() {
        assert_eq!(
            path_parameter("Invalid URL: Invalid UTF-8 in `run_id`").as_deref(),
            Some("run_id")
        );
        assert_eq!(path_parameter("Invalid UTF-8 in `id`"), None);
        assert_eq!(path_parameter("Invalid URL: in `a b`"), None);
    }
}
