//! The service's edge: what a request meets before any handler (protocol
//! limits, `Host`, bearer token, JSON content type on writes, an oversize
//! `Content-Length`), the headers every answer carries, and the connection
//! loop with its timeouts and cap.

pub mod access;
pub mod connections;
pub mod hosts;
mod protocol;
mod unparsed;

use std::path::PathBuf;
use std::sync::Arc;
use std::time::Duration;

use axum::extract::{Request, State};
use axum::http::{header, Method, StatusCode};
use axum::middleware::Next;
use axum::response::{IntoResponse, Response};

use crate::http::error::ApiError;

/// `fieldbal serve` arguments of the edge (flattened into `ServeArgs`).
#[derive(Debug, Clone, clap::Args)]
pub struct EdgeArgs {
    /// File of bearer tokens, one `read TOKEN` or `write TOKEN` per line (`#`
    /// comments). Tokens may also come from the variable FIELDBAL_TOKENS
    /// (entries separated by newlines or commas). None: the API is open.
    #[arg(long, env = "FIELDBAL_TOKENS_FILE")]
    pub tokens_file: Option<PathBuf>,
    /// Host names the service answers to besides localhost and address
    /// literals, comma-separated (`stand-pc`, `stand-pc:8080`); `*`: any.
    #[arg(long, env = "FIELDBAL_ALLOWED_HOSTS", default_value = "")]
    pub allowed_hosts: String,
    /// Longest time to receive a request's header, and to idle between
    /// requests on a kept-alive connection, seconds.
    #[arg(long, env = "FIELDBAL_HEADER_READ_TIMEOUT_SECS", default_value_t = connections::DEFAULT_HEADER_READ_TIMEOUT_SECS, value_parser = crate::http::args::positive_u64)]
    pub header_read_timeout_secs: u64,
    /// Longest time a write to a client may make no progress (a client that
    /// stopped reading), seconds; then the connection is closed.
    #[arg(long, env = "FIELDBAL_WRITE_TIMEOUT_SECS", default_value_t = connections::DEFAULT_WRITE_TIMEOUT_SECS, value_parser = crate::http::args::positive_u64)]
    pub write_timeout_secs: u64,
    /// Most connections open at once; more are answered 503 and closed.
    #[arg(long, env = "FIELDBAL_MAX_CONNECTIONS", default_value_t = connections::DEFAULT_MAX_CONNECTIONS, value_parser = crate::http::args::positive_usize)]
    pub max_connections: usize,
    /// On SIGTERM, longest wait for connections to finish, seconds.
    #[arg(long, env = "FIELDBAL_SHUTDOWN_GRACE_SECS", default_value_t = connections::DEFAULT_SHUTDOWN_GRACE_SECS)]
    pub shutdown_grace_secs: u64,
}

/// The edge's settings, shared by the middleware and the connection loop.
#[derive(Debug, Clone, Default)]
pub struct EdgeConfig {
    pub tokens: access::Tokens,
    pub hosts: hosts::AllowedHosts,
    pub connections: connections::Limits,
}

impl EdgeConfig {
    /// Settings from the command line; the tokens are read here (file and
    /// FIELDBAL_TOKENS), so a bad entry stops the start with its line number.
    pub fn from_args(args: &EdgeArgs) -> Result<EdgeConfig, String> {
        let var = std::env::var("FIELDBAL_TOKENS").ok();
        Ok(EdgeConfig {
            tokens: access::Tokens::load(args.tokens_file.as_deref(), var.as_deref())?,
            hosts: hosts::AllowedHosts::try_parse(&args.allowed_hosts)?,
            connections: connections::Limits {
                header_read_timeout: Duration::from_secs(args.header_read_timeout_secs.max(1)),
                write_timeout: Duration::from_secs(args.write_timeout_secs.max(1)),
                max_connections: args.max_connections.max(1),
                shutdown_grace: Duration::from_secs(args.shutdown_grace_secs),
            },
        })
    }
}

/// What the guard needs: the edge settings and the body limit.
#[derive(Debug, Clone)]
pub(crate) struct Guard {
    pub edge: Arc<EdgeConfig>,
    pub body_limit: usize,
}

/// The body limit in force, for the extractors' 413 (a request extension).
#[derive(Debug, Clone, Copy)]
pub(crate) struct BodyLimit(pub usize);

/// The middleware in front of every route.
pub(crate) async fn guard(State(guard): State<Guard>, mut req: Request, next: Next) -> Response {
    let form = is_form_file(req.uri().path());
    let mut resp = match refusal(&guard, &req) {
        None => {
            // A body read past the limit (sent chunked) is refused naming it.
            req.extensions_mut().insert(BodyLimit(guard.body_limit));
            next.run(req).await
        }
        Some(refused) => refused,
    };
    if resp.status().is_client_error() || resp.status().is_server_error() {
        resp = protocol::json_error_body(resp).await;
    }
    protocol::security_headers(&mut resp, form);
    resp
}

/// The web form's own files: no token, their own cache and CSP headers.
fn is_form_file(path: &str) -> bool {
    path == "/" || path.starts_with("/static/")
}

/// The answer to a request refused at the edge, in the order: protocol limits,
/// `Host`, token, content type and encoding, announced length.
fn refusal(guard: &Guard, req: &Request) -> Option<Response> {
    let path = req.uri().path();
    let api = path.starts_with("/api/");
    let checked =
        protocol::check_size(req).and_then(|()| guard.edge.hosts.check(req.headers(), req.uri()));
    if let Err(e) = checked {
        return Some(e.into_response());
    }
    if !api {
        return None;
    }
    if let Some(refused) = access::refusal(&guard.edge.tokens, req.headers(), req.method(), path) {
        return Some(refused);
    }
    let headers = req.headers();
    // A cross-site page can send a "simple" request (no preflight) only as
    // text/plain, a form encoding or without a body: requiring JSON here
    // means no page elsewhere can change the store through a visitor's browser.
    // DELETE is never simple, so the browser asks first and gets no CORS answer.
    if matches!(*req.method(), Method::POST | Method::PUT | Method::PATCH) {
        if let Err(e) = crate::http::extract::check_content_type(headers) {
            return Some(e.into_response());
        }
        if let Some(refused) = encoding_refusal(headers) {
            return Some(refused);
        }
    }
    announced_length(guard, headers)
        .err()
        .map(IntoResponse::into_response)
}

/// Refuse a body announced over the limit now, not after reading it.
fn announced_length(guard: &Guard, headers: &header::HeaderMap) -> Result<(), ApiError> {
    let declared = headers
        .get(header::CONTENT_LENGTH)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.trim().parse::<u64>().ok());
    if declared.is_some_and(|n| n > guard.body_limit as u64) {
        return Err(ApiError::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            "body_too_large",
            format!(
                "the request body ({} bytes) is larger than the server's limit of {} bytes",
                declared.unwrap_or_default(),
                guard.body_limit
            ),
        ));
    }
    Ok(())
}

/// Bodies are read as sent: the service decompresses none (tower-http's
/// `decompression-gzip` needs crates that are not in `Cargo.lock`). A gzip
/// body used to be read as JSON and refused as malformed, naming no cause;
/// now any coding but `identity` is refused with 415 naming
/// `Content-Encoding`, with `Accept-Encoding: identity` as RFC 7694 asks,
/// before the body is read.
fn encoding_refusal(headers: &header::HeaderMap) -> Option<Response> {
    for value in headers.get_all(header::CONTENT_ENCODING) {
        let text = value.to_str().unwrap_or("(not ASCII)");
        let identity = text
            .split(',')
            .map(str::trim)
            .all(|coding| coding.is_empty() || coding.eq_ignore_ascii_case("identity"));
        if identity {
            continue;
        }
        // Visible ASCII: any byte is a character boundary.
        let shown = &text[..text.len().min(64)];
        let mut refused = ApiError::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "unsupported_media_type",
            format!(
                "the body must be sent uncompressed: Content-Encoding '{shown}' is not accepted (leave the header out, or send identity)"
            ),
        )
        .with_field("Content-Encoding")
        .into_response();
        refused.headers_mut().insert(
            header::ACCEPT_ENCODING,
            header::HeaderValue::from_static("identity"),
        );
        return Some(refused);
    }
    None
}
