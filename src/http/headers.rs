//! Request headers of contract v2: `Idempotency-Key` on POSTs, `ETag` and
//! `If-Match` on sessions and runs; and the paging of the shorter lists.

use axum::extract::rejection::QueryRejection;
use axum::extract::Query;
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use utoipa::IntoParams;

use super::error::ApiError;
use crate::balancing::InputError;
use crate::db::idempotency::{Idem, Replay, MAX_KEY_LEN};

pub const IDEMPOTENCY_KEY: &str = "idempotency-key";

/// The request's `Idempotency-Key` bound to its method, path and parsed body.
pub fn idempotency(
    headers: &HeaderMap,
    method: &str,
    path: &str,
    body: &impl Serialize,
) -> Result<Option<Idem>, ApiError> {
    let lines: Vec<&str> = headers
        .get_all(IDEMPOTENCY_KEY)
        .iter()
        .map(|v| v.to_str().unwrap_or(""))
        .collect();
    if lines.is_empty() {
        return Ok(None);
    }
    // Several lines are the one line a proxy may join them into (RFC 9110
    // §5.3), which the key's rule refuses: the first alone was used, so a
    // retry with its lines in another order stored the request again.
    let joined = lines.join(", ");
    let key = joined.as_str();
    if key.is_empty() || key.len() > MAX_KEY_LEN || !key.bytes().all(|b| b.is_ascii_graphic()) {
        return Err(InputError::invalid(
            "invalid_header",
            "Idempotency-Key",
            format!("an Idempotency-Key is 1 to {MAX_KEY_LEN} visible ASCII characters"),
        )
        .into());
    }
    Ok(Some(Idem::new(key, method, path, body)))
}

/// The answer kept for a repeated key, as it was first given.
pub fn replay(r: Replay) -> Response {
    let status = StatusCode::from_u16(r.status).unwrap_or(StatusCode::OK);
    let json = HeaderValue::from_static("application/json");
    let mut response = (status, [(header::CONTENT_TYPE, json)], r.body).into_response();
    if let Some(location) = r.location.and_then(|l| HeaderValue::from_str(&l).ok()) {
        response.headers_mut().insert(header::LOCATION, location);
    }
    response
        .headers_mut()
        .insert("idempotent-replayed", HeaderValue::from_static("true"));
    response
}

/// A strong entity tag for a JSON value: its SHA-256, shortened.
pub fn etag_of(value: &impl Serialize) -> String {
    let digest = Sha256::digest(serde_json::to_vec(value).unwrap_or_default());
    let hex: String = digest[..16].iter().map(|b| format!("{b:02x}")).collect();
    format!("\"{hex}\"")
}

/// The entity tag of a run's version.
pub fn run_etag(version: i64) -> String {
    format!("\"v{version}\"")
}

/// The versions `If-Match` accepts: `None` without the header or with `*`
/// (any current version), else the run versions it names; a tag that names
/// no version matches none. If-Match compares strongly (RFC 9110 §13.1.1),
/// under which a weak tag (`W/"v3"`) matches nothing, and a tag matches
/// only as the ETag was given, character for character.
pub fn if_match_versions(headers: &HeaderMap) -> Result<Option<Vec<i64>>, ApiError> {
    Ok(if_match_tags(headers)?.map(|tags| {
        tags.iter()
            .filter_map(|t| {
                let v = t.strip_prefix("\"v")?.strip_suffix('"')?.parse().ok()?;
                // Character for character: `"v01"` and `"v+1"` are not `"v1"`.
                (run_etag(v) == *t).then_some(v)
            })
            .collect()
    }))
}

/// The entity tags `If-Match` names, as given: `None` without the header
/// or with `*` (any current representation). Compared strongly (RFC 9110
/// §13.1.1): a weak tag (`W/"…"`) is kept as given and so matches no ETag
/// the service gives, all of them strong. Several `If-Match` lines are one
/// list (RFC 9110 §5.3). A value that is neither `*` nor a list of
/// entity-tags (an unquoted tag, `*` among tags, none at all) is refused
/// with 400 naming `If-Match`: taken as a tag that matches nothing, it was
/// answered 412 "changed meanwhile" even when it named the current version.
pub fn if_match_tags(headers: &HeaderMap) -> Result<Option<Vec<String>>, ApiError> {
    let mut lines = headers.get_all(header::IF_MATCH).iter().peekable();
    if lines.peek().is_none() {
        return Ok(None);
    }
    let invalid = |message: String| {
        ApiError::new(StatusCode::BAD_REQUEST, "invalid_header", message).with_field("If-Match")
    };
    let mut text = String::new();
    for (i, line) in lines.enumerate() {
        let line = line
            .to_str()
            .map_err(|_| invalid("If-Match is not ASCII".into()))?;
        if i > 0 {
            text.push(',');
        }
        text.push_str(line);
    }
    if text.trim() == "*" {
        return Ok(None);
    }
    entity_tags(&text).map(Some).ok_or_else(|| {
        let shown: String = text.chars().take(80).collect();
        invalid(format!(
            "If-Match is `*` or a comma-separated list of entity-tags, each quoted as the ETag gives it (\"v3\"); got '{shown}'"
        ))
    })
}

/// The entity-tags of a list (RFC 9110 §8.8.3, `#entity-tag`): each
/// `"…"` or `W/"…"` of visible characters but `"`, separated by commas
/// (empty elements allowed), as written; `None` when it is not such a list
/// or names no tag.
fn entity_tags(text: &str) -> Option<Vec<String>> {
    let mut tags = Vec::new();
    let mut rest = text;
    loop {
        rest = rest.trim_start_matches([' ', '\t', ',']);
        if rest.is_empty() {
            break;
        }
        let opaque = rest.strip_prefix("W/").unwrap_or(rest).strip_prefix('"')?;
        let end = opaque.find('"')?;
        if !opaque[..end]
            .bytes()
            .all(|b| b == 0x21 || (0x23..=0x7e).contains(&b))
        {
            return None;
        }
        let len = rest.len() - opaque.len() + end + 1;
        tags.push(rest[..len].to_string());
        rest = rest[len..].trim_start_matches([' ', '\t']);
        if !rest.is_empty() {
            rest = rest.strip_prefix(',')?;
        }
    }
    (!tags.is_empty()).then_some(tags)
}

/// Paging of a list: `limit` 1 to `max` (default `default`), `offset` 0 or more.
#[derive(Debug, Deserialize, IntoParams)]
#[serde(deny_unknown_fields)]
#[into_params(parameter_in = Query)]
pub struct Page {
    /// Items per page.
    pub limit: Option<i64>,
    /// Items to skip (default 0).
    pub offset: Option<i64>,
}

impl Page {
    /// `(limit, offset)` within the bounds, or the contract's error naming the parameter.
    pub fn bounds(
        params: Result<Query<Page>, QueryRejection>,
        default: i64,
        max: i64,
    ) -> Result<(i64, i64), ApiError> {
        let Query(p) = params.map_err(invalid_query)?;
        page_bounds(p.limit, p.offset, default, max)
    }
}

/// The query of a GET that takes no parameter (a session, a run, the
/// OpenAPI document): any parameter is refused with 400 `invalid_query`
/// naming it, as the lists and `GET /api/v1/machines/{id}` refuse one they
/// do not take; ignored, a misspelt parameter read as if it were applied.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NoParams {}

impl NoParams {
    /// `Ok` for an empty query (or none), else the contract's 400.
    pub fn check(params: Result<Query<NoParams>, QueryRejection>) -> Result<(), ApiError> {
        params.map(drop).map_err(invalid_query)
    }
}

/// A query string that does not parse: 400 with the contract's body,
/// naming the parameter at fault when axum's message does.
pub fn invalid_query(r: QueryRejection) -> ApiError {
    let text = r.body_text();
    let field = query_field(&text);
    let message = query_message(&text, field.as_deref());
    let error = ApiError::new(StatusCode::BAD_REQUEST, "invalid_query", message);
    match field {
        Some(field) => error.with_field(field),
        None => error,
    }
}

/// axum's query message ("Failed to deserialize query string: foo: unknown
/// field `foo`, there are no fields") in the service's words, naming the
/// parameter and what the operation takes.
fn query_message(text: &str, field: Option<&str>) -> String {
    let Some(rest) = text.strip_prefix("Failed to deserialize query string: ") else {
        return text.to_string();
    };
    let Some(name) = field else {
        return format!("the query string does not parse: {rest}");
    };
    if rest.starts_with("duplicate field") {
        return format!("query parameter `{name}` is given more than once");
    }
    let cause = rest.split_once(": ").map_or(rest, |(_, cause)| cause);
    if cause.starts_with("unknown field") {
        return match cause.split_once(", expected ") {
            Some((_, taken)) => format!(
                "`{name}` is not a query parameter of this operation, which takes {}",
                taken.trim_start_matches("one of ")
            ),
            None => format!(
                "`{name}` is not a query parameter of this operation, which takes no query parameter"
            ),
        };
    }
    format!("query parameter `{name}`: {cause}")
}

/// The parameter axum's query message names: its `serde_path_to_error`
/// prefix (`limit: invalid digit found in string`), or the name in
/// `duplicate field `limit``. Query parameters are plain names.
fn query_field(text: &str) -> Option<String> {
    let rest = text.strip_prefix("Failed to deserialize query string: ")?;
    let name = match rest.split_once(": ") {
        Some((path, _)) => path,
        None => rest.strip_prefix("duplicate field `")?.split('`').next()?,
    };
    let plain = !name.is_empty()
        && name.len() <= 64
        && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_');
    plain.then(|| name.to_string())
}

/// `limit` 1 to `max` (default `default`) and `offset` 0 or more (default 0),
/// or the contract's error naming the parameter: the one rule of every paged list.
pub fn page_bounds(
    limit: Option<i64>,
    offset: Option<i64>,
    default: i64,
    max: i64,
) -> Result<(i64, i64), ApiError> {
    let limit = limit.unwrap_or(default);
    if !(1..=max).contains(&limit) {
        return Err(InputError::invalid(
            "out_of_range",
            "limit",
            format!("limit must be 1 to {max}"),
        )
        .into());
    }
    let offset = offset.unwrap_or(0);
    if offset < 0 {
        return Err(
            InputError::invalid("out_of_range", "offset", "offset must be 0 or more").into(),
        );
    }
    Ok((limit, offset))
}

/// `X-Total-Count`: how many items the paged list has in all.
pub fn with_total(mut response: Response, total: i64) -> Response {
    response
        .headers_mut()
        .insert("x-total-count", HeaderValue::from(total));
    response
}
