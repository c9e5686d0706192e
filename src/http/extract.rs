//! Request bodies: the content type is checked (415), the size is bounded (413)
//! and the JSON is parsed with `balancing::from_json`, so malformed JSON, unknown
//! fields and wrong types all get the contract's error body with a field path.

use axum::body::Bytes;
use axum::extract::rejection::BytesRejection;
use axum::extract::{FromRequest, Request};
use axum::http::{header, HeaderMap, StatusCode};
use serde::de::DeserializeOwned;

use super::error::ApiError;
use crate::balancing::{from_json, SolveOptions};

/// A JSON request body parsed into `T`.
pub struct JsonBody<T>(pub T);

impl<T, S> FromRequest<S> for JsonBody<T>
where
    T: DeserializeOwned + Send + 'static,
    S: Send + Sync,
{
    type Rejection = ApiError;

    async fn from_request(req: Request, state: &S) -> Result<Self, ApiError> {
        // Refuse a wrong content type before reading a possibly large body.
        check_content_type(req.headers())?;
        let (_, bytes) = read(req, state).await?;
        Ok(JsonBody(parse(bytes).await?))
    }
}

/// Solve options for a stored session: an empty body means the defaults.
pub struct OptionsBody(pub SolveOptions);

impl<S: Send + Sync> FromRequest<S> for OptionsBody {
    type Rejection = ApiError;

    async fn from_request(req: Request, state: &S) -> Result<Self, ApiError> {
        let (headers, bytes) = read(req, state).await?;
        if bytes.iter().all(u8::is_ascii_whitespace) {
            return Ok(OptionsBody(SolveOptions::default()));
        }
        check_content_type(&headers)?;
        Ok(OptionsBody(from_json(&bytes)?))
    }
}

/// Bodies larger than this are parsed on the blocking pool: parsing a few
/// MiB takes milliseconds, which must not stall an async thread.
const INLINE_PARSE_BYTES: usize = 64 * 1024;

async fn parse<T: DeserializeOwned + Send + 'static>(bytes: Bytes) -> Result<T, ApiError> {
    if bytes.len() <= INLINE_PARSE_BYTES {
        return Ok(from_json(&bytes)?);
    }
    tokio::task::spawn_blocking(move || from_json(&bytes))
        .await
        .map_err(|e| ApiError::internal(&e))?
        .map_err(ApiError::from)
}

/// Buffer the body; the router's `DefaultBodyLimit` bounds its size.
async fn read<S: Send + Sync>(req: Request, state: &S) -> Result<(HeaderMap, Bytes), ApiError> {
    let headers = req.headers().clone();
    let limit = req
        .extensions()
        .get::<super::edge::BodyLimit>()
        .map(|l| l.0);
    let bytes = Bytes::from_request(req, state)
        .await
        .map_err(|rejection: BytesRejection| {
            if rejection.status() == StatusCode::PAYLOAD_TOO_LARGE {
                ApiError::new(
                    StatusCode::PAYLOAD_TOO_LARGE,
                    "body_too_large",
                    match limit {
                        Some(n) => format!(
                            "the request body is larger than the server's limit of {n} bytes"
                        ),
                        None => "the request body is larger than the server's limit".to_string(),
                    },
                )
            } else {
                ApiError::new(
                    StatusCode::BAD_REQUEST,
                    "unreadable_body",
                    rejection.body_text(),
                )
            }
        })?;
    Ok((headers, bytes))
}

/// Accept `application/json` (with parameters such as `charset`) and `application/*+json`.
pub(crate) fn check_content_type(headers: &HeaderMap) -> Result<(), ApiError> {
    let value = headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .unwrap_or("");
    let essence = value
        .split(';')
        .next()
        .unwrap_or("")
        .trim()
        .to_ascii_lowercase();
    let json = essence == "application/json"
        || (essence.starts_with("application/") && essence.ends_with("+json"));
    if json {
        Ok(())
    } else {
        Err(ApiError::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "unsupported_media_type",
            format!(
                "the body must be JSON with Content-Type: application/json, not '{}'",
                if value.is_empty() { "(none)" } else { value }
            ),
        ))
    }
}
