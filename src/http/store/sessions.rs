//! `/api/v1/sessions`: store a validated session, list, read back and delete.

use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::Json;
use serde::{Deserialize, Serialize};
use utoipa::{IntoParams, ToSchema};

use crate::balancing::model::Session;
use crate::balancing::{self, InputError};
use crate::db::idempotency;
use crate::db::ListPage;
use crate::db::{self, SessionList};
use crate::http::error::{ApiError, ErrorBody};
use crate::http::extract::JsonBody;
use crate::http::headers;
use crate::http::responses::{
    BodyRefused, MalformedJson, PageRefused, QueryRefused, StorageFull, StoreUnavailable,
};
use crate::http::store::created::CreatedAnswer;
use crate::http::work::check_blocking;
use crate::http::AppState;

/// The id of a stored session (also in the `Location` header).
#[derive(Debug, Serialize, Deserialize, ToSchema)]
pub struct Created {
    pub id: String,
}

/// Paging of the session list.
#[derive(Debug, Deserialize, IntoParams)]
#[serde(deny_unknown_fields)]
#[into_params(parameter_in = Query)]
pub struct ListParams {
    /// Sessions per page, 1 to 1000 (default 50).
    #[param(minimum = 1, maximum = 1000)]
    pub limit: Option<i64>,
    /// Sessions to skip (default 0).
    #[param(minimum = 0)]
    pub offset: Option<i64>,
    /// The previous page's `next`: the page continues after its last item,
    /// whatever was stored or deleted meanwhile (instead of `offset`).
    pub before: Option<String>,
}

impl ListParams {
    /// The page of sessions or machines asked for (limit default 50, at most
    /// 1000), or the contract's error naming the parameter.
    pub fn bounds(params: Result<Query<ListParams>, QueryRejection>) -> Result<ListPage, ApiError> {
        let Query(p) = params.map_err(headers::invalid_query)?;
        let (limit, offset) = headers::page_bounds(p.limit, p.offset, 50, 1000)?;
        let before = match p.before.as_deref() {
            None => None,
            Some(c) => match c.parse::<i64>() {
                Ok(n) if n > 0 => Some(n),
                _ => {
                    return Err(InputError::invalid(
                        "invalid_value",
                        "before",
                        "before is the `next` of a previous page",
                    )
                    .into())
                }
            },
        };
        if before.is_some() && offset != 0 {
            return Err(InputError::invalid(
                "conflicting_options",
                "offset",
                "give offset or before (the next page after a cursor), not both",
            )
            .into());
        }
        Ok(ListPage {
            limit,
            offset,
            before,
        })
    }
}

/// Validate a session to be stored. A session may be stored before any run is
/// measured (`runs: []`): its set-up is checked and runs are appended later.
pub fn validate_stored(session: &Session) -> Result<(), InputError> {
    match balancing::validate_session(session) {
        // The core checks the set-up (planes, sensors) before the runs, so when
        // the only complaint about a run-less session is the missing reference
        // run, its set-up is valid.
        Err(e) if session.runs.is_empty() && e.code == "no_reference_run" => Ok(()),
        other => other,
    }
}

#[utoipa::path(post, path = "/api/v1/sessions", tag = "sessions",
    operation_id = "create_session", summary = "Store a session",
    request_body = Session,
    params(("Idempotency-Key" = Option<String>, Header, description = "A retry with the same key and body answers the first answer again and stores nothing new")),
    responses(
        (status = 201, description = "Stored", body = Created,
         headers(("Location" = String, description = "/api/v1/sessions/{id}"),
                 ("Idempotent-Replayed" = String, description = "`true` on the answer kept for a repeated Idempotency-Key: nothing new was stored"))),
        MalformedJson,
        BodyRefused,
        (status = 422, description = "Invalid session, over the size limits (`too_large`), or an Idempotency-Key used for another request", body = ErrorBody),
        StoreUnavailable,
        (status = 507, description = "The disk is full; nothing was stored", body = ErrorBody),
    ))]
pub async fn create(
    State(state): State<AppState>,
    request_headers: HeaderMap,
    JsonBody(session): JsonBody<Session>,
) -> Result<Response, ApiError> {
    let idem = headers::idempotency(&request_headers, "POST", "/api/v1/sessions", &session)?;
    if let Some(r) = idempotency::lookup(&state.db, idem.as_ref()).await? {
        return Ok(headers::replay(r));
    }
    super::text::check_session(&session)?;
    let readings = session.runs.iter().map(|r| r.readings.len()).sum();
    let session = check_blocking(session, readings, validate_stored).await?;
    let id = uuid::Uuid::new_v4().to_string();
    let created = CreatedAnswer {
        location: format!("/api/v1/sessions/{id}"),
        body: Created { id },
    };
    let keep = created.keep(idem.as_ref())?;
    let written = db::sessions::create(&state.db, &created.body.id, &session, keep.as_ref()).await;
    created.answer(written, ())
}

#[utoipa::path(get, path = "/api/v1/sessions", tag = "sessions",
    operation_id = "list_sessions", summary = "List stored sessions, newest first",
    params(ListParams),
    responses(
        (status = 200, description = "A page of sessions, newest first", body = SessionList),
        PageRefused,
        StoreUnavailable,
    ))]
pub async fn list(
    State(state): State<AppState>,
    params: Result<Query<ListParams>, QueryRejection>,
) -> Result<Json<SessionList>, ApiError> {
    let page = ListParams::bounds(params)?;
    Ok(Json(db::sessions::list(&state.db, page).await?))
}

#[utoipa::path(get, path = "/api/v1/sessions/{id}", tag = "sessions",
    operation_id = "get_session", summary = "Get a stored session",
    params(("id" = String, Path, description = "Session id")),
    responses(
        (status = 200, description = "The session exactly as it would be posted again", body = Session,
         headers(("ETag" = String, description = "Changes whenever the session or any of its runs changes"))),
        QueryRefused,
        (status = 404, description = "No such session", body = ErrorBody),
        StoreUnavailable,
    ))]
pub async fn get(
    State(state): State<AppState>,
    Path(id): Path<String>,
    params: Result<Query<headers::NoParams>, QueryRejection>,
) -> Result<Response, ApiError> {
    headers::NoParams::check(params)?;
    let session = db::sessions::get(&state.db, &id).await?;
    let etag = headers::etag_of(&session);
    Ok(([(header::ETAG, etag)], Json(session)).into_response())
}

#[utoipa::path(delete, path = "/api/v1/sessions/{id}", tag = "sessions",
    operation_id = "delete_session", summary = "Delete a stored session with its runs and solutions",
    params(("id" = String, Path, description = "Session id"),
           ("If-Match" = Option<String>, Header, description = "The session's ETag as read: deleted only if it has not changed since (strong comparison; `*` or no header: unconditionally)")),
    responses(
        (status = 204, description = "Deleted with its runs and solutions"),
        (status = 400, description = "An If-Match that is neither `*` nor a list of quoted entity-tags (`invalid_header`, naming `If-Match`)", body = ErrorBody),
        (status = 404, description = "No such session", body = ErrorBody),
        (status = 412, description = "The session changed since its ETag was read (or `If-Match` names no ETag of it): nothing deleted", body = ErrorBody),
        StorageFull,
        StoreUnavailable,
    ))]
pub async fn delete(
    State(state): State<AppState>,
    Path(id): Path<String>,
    request_headers: HeaderMap,
) -> Result<StatusCode, ApiError> {
    let tags = headers::if_match_tags(&request_headers)?;
    // The tag is the one `GET` gives, of the session as read in the
    // deleting transaction (so a change in between is seen).
    let unchanged = tags.map(|tags| {
        move |s: &crate::balancing::model::Session| {
            let current = headers::etag_of(s);
            tags.contains(&current)
        }
    });
    db::sessions::delete(&state.db, &id, unchanged).await?;
    Ok(StatusCode::NO_CONTENT)
}
