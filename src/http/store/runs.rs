//! `/api/v1/sessions/{id}/runs`: append a run, correct one (keeping the earlier
//! version), list a run's versions. Field paths in errors point into the posted run.

use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{header, HeaderMap};
use axum::response::{IntoResponse, Response};
use axum::Json;
use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::balancing::model::{Run, Session};
use crate::balancing::InputError;
use crate::db::idempotency;
use crate::db::{self, RunVersion};
use crate::http::error::{ApiError, ErrorBody};
use crate::http::extract::JsonBody;
use crate::http::headers::{self, Page};
use crate::http::responses::{
    BodyRefused, MalformedJson, PageRefused, QueryRefused, StorageFull, StoreUnavailable,
};
use crate::http::sessions::validate_stored;
use crate::http::store::created::CreatedAnswer;
use crate::http::AppState;

/// The stored version of a run.
#[derive(Debug, Serialize, Deserialize, ToSchema)]
pub struct RunStored {
    pub run_id: String,
    /// 1 when first entered, +1 per correction.
    pub version: i64,
}

/// Validate the session with the posted run at `index`, naming fields relative to
/// the posted run (`readings[3].sensor`, not `runs[4].readings[3].sensor`).
fn check_with_run(session: &Session, index: usize) -> Result<(), InputError> {
    validate_stored(session).map_err(|e| {
        if e.code == "no_reference_run" {
            return no_reference(session, index);
        }
        relative_to_run(e, index)
    })
}

/// The session has no run without weights after the posted run went in:
/// only that run can have taken the reference's place (a first run appended
/// to a set-up, or the reference run corrected), so its `weights` are at
/// fault. The service named no field (session 21).
fn no_reference(session: &Session, index: usize) -> InputError {
    let run = &session.runs[index];
    let message = if session.runs.len() == 1 {
        format!("run '{}' is the session's first run, which is the reference run (the rotor as found, no weights): store the run without weights first, then the runs with weights", run.id)
    } else {
        format!("run '{}' is the reference run (the rotor as found): it has no weights, and a session has exactly one such run; list weights only in the other runs", run.id)
    };
    InputError::invalid("no_reference_run", "weights", message)
}

fn relative_to_run(mut e: InputError, index: usize) -> InputError {
    let prefix = format!("runs[{index}]");
    e.field = e.field.take().and_then(|f| {
        let rest = f.strip_prefix(&prefix)?;
        // A fault in another run, or in the session as a whole, is not a field of
        // the posted body: the message names it.
        rest.strip_prefix('.').map(str::to_string)
    });
    e
}

/// Percent-encode a path segment (run ids may hold spaces and slashes).
pub(crate) fn encode_segment(s: &str) -> String {
    s.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' => {
                (b as char).to_string()
            }
            _ => format!("%{b:02X}"),
        })
        .collect()
}

#[utoipa::path(post, path = "/api/v1/sessions/{id}/runs", tag = "runs",
    operation_id = "append_run", summary = "Append a run to a stored session",
    params(("id" = String, Path, description = "Session id"),
           ("Idempotency-Key" = Option<String>, Header, description = "A retry with the same key and body answers the first answer again and stores nothing new")),
    request_body = Run,
    responses(
        (status = 201, description = "Appended as version 1", body = RunStored,
         headers(("Location" = String, description = "/api/v1/sessions/{id}/runs/{run_id}"),
                 ("ETag" = String, description = "The run's version; send it as If-Match with a PUT"),
                 ("Idempotent-Replayed" = String, description = "`true` on the answer kept for a repeated Idempotency-Key: nothing new was stored"))),
        MalformedJson,
        (status = 404, description = "No such session", body = ErrorBody),
        (status = 409, description = "The session already has a run with this id", body = ErrorBody),
        BodyRefused,
        (status = 422, description = "The session with this run is invalid", body = ErrorBody),
        StorageFull,
        StoreUnavailable,
    ))]
pub async fn append(
    State(state): State<AppState>,
    Path(id): Path<String>,
    request_headers: HeaderMap,
    JsonBody(run): JsonBody<Run>,
) -> Result<Response, ApiError> {
    let path = format!("/api/v1/sessions/{id}/runs");
    let idem = headers::idempotency(&request_headers, "POST", &path, &run)?;
    if let Some(r) = idempotency::lookup(&state.db, idem.as_ref()).await? {
        // An append's kept answer is its 201 of version 1, ETag included.
        return Ok(([(header::ETAG, headers::run_etag(1))], headers::replay(r)).into_response());
    }
    super::text::check_new_run(&run)?;
    let location = format!(
        "/api/v1/sessions/{}/runs/{}",
        encode_segment(&id),
        encode_segment(&run.id)
    );
    let created = CreatedAnswer {
        location,
        body: RunStored {
            run_id: run.id.clone(),
            version: 1,
        },
    };
    let keep = created.keep(idem.as_ref())?;
    let written = db::runs::append(&state.db, &id, &run, check_with_run, keep.as_ref()).await;
    created.answer(written, [(header::ETAG, headers::run_etag(1))])
}

#[utoipa::path(put, path = "/api/v1/sessions/{id}/runs/{run_id}", tag = "runs",
    operation_id = "replace_run", summary = "Store a corrected version of a run (the old one is kept)",
    params(("id" = String, Path, description = "Session id"),
           ("run_id" = String, Path, description = "Run id"),
           ("If-Match" = Option<String>, Header, description = "The run's ETag: refuse (412) if the run changed since (compared strongly: a weak tag `W/\"…\"` never matches; a value that is neither `*` nor a list of quoted entity-tags is refused with 400 `invalid_header`)")),
    request_body = Run,
    responses(
        (status = 200, description = "Stored as a new version; the earlier ones are kept", body = RunStored,
         headers(("ETag" = String, description = "The run's new version; send it as If-Match with the next PUT"))),
        MalformedJson,
        (status = 404, description = "No such session or run", body = ErrorBody),
        BodyRefused,
        (status = 412, description = "If-Match names a version that is no longer the run's current one", body = ErrorBody),
        (status = 422, description = "Invalid, or the body's id differs from the path's", body = ErrorBody),
        StorageFull,
        StoreUnavailable,
    ))]
pub async fn replace(
    State(state): State<AppState>,
    Path((id, run_id)): Path<(String, String)>,
    request_headers: HeaderMap,
    JsonBody(run): JsonBody<Run>,
) -> Result<Response, ApiError> {
    let if_match = headers::if_match_versions(&request_headers)?;
    if run.id != run_id {
        return Err(InputError::invalid(
            "id_mismatch",
            "id",
            format!(
                "the body's run id '{}' differs from the path's '{run_id}'",
                run.id
            ),
        )
        .into());
    }
    let version =
        db::runs::replace(&state.db, &id, &run, check_with_run, if_match.as_deref()).await?;
    Ok((
        [(header::ETAG, headers::run_etag(version))],
        Json(RunStored { run_id, version }),
    )
        .into_response())
}

#[utoipa::path(get, path = "/api/v1/sessions/{id}/runs/{run_id}", tag = "runs",
    operation_id = "get_run", summary = "Get a run's current version",
    params(("id" = String, Path, description = "Session id"),
           ("run_id" = String, Path, description = "Run id")),
    responses(
        (status = 200, description = "The run's current version, as it would be PUT again", body = Run,
         headers(("ETag" = String, description = "The run's version; send it as If-Match with a PUT"))),
        QueryRefused,
        (status = 404, description = "No such session or run", body = ErrorBody),
        StoreUnavailable,
    ))]
pub async fn get(
    State(state): State<AppState>,
    Path((id, run_id)): Path<(String, String)>,
    params: Result<Query<headers::NoParams>, QueryRejection>,
) -> Result<Response, ApiError> {
    headers::NoParams::check(params)?;
    let (run, version) = db::runs::get(&state.db, &id, &run_id).await?;
    Ok(([(header::ETAG, headers::run_etag(version))], Json(run)).into_response())
}

#[utoipa::path(get, path = "/api/v1/sessions/{id}/runs/{run_id}/versions", tag = "runs",
    operation_id = "list_run_versions", summary = "List every version of a run, oldest first",
    params(("id" = String, Path, description = "Session id"),
           ("run_id" = String, Path, description = "Run id"), Page),
    responses(
        (status = 200, description = "A page of the run's versions, oldest first (limit 1 to 1000, default 1000)", body = Vec<RunVersion>,
         headers(("X-Total-Count" = i64, description = "Versions in all"))),
        PageRefused,
        (status = 404, description = "No such session or run", body = ErrorBody),
        StoreUnavailable,
    ))]
pub async fn versions(
    State(state): State<AppState>,
    Path((id, run_id)): Path<(String, String)>,
    page: Result<Query<Page>, QueryRejection>,
) -> Result<Response, ApiError> {
    let (limit, offset) = Page::bounds(page, 1000, 1000)?;
    let (list, total) = db::runs::versions(&state.db, &id, &run_id, limit, offset).await?;
    Ok(headers::with_total(Json(list).into_response(), total))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fault_in_the_posted_run_is_named_relative_to_it() {
        let e = InputError::invalid("x", "runs[4].readings[3].sensor", "m");
        assert_eq!(
            relative_to_run(e, 4).field.as_deref(),
            Some("readings[3].sensor")
        );
    }

    #[test]
    fn a_fault_in_another_run_names_no_field_of_the_body() {
        let e = InputError::invalid("x", "runs[14].readings", "m");
        assert_eq!(relative_to_run(e, 1).field, None);
    }

    #[test]
    fn run_ids_are_percent_encoded_in_locations() {
        assert_eq!(encode_segment("trial A/2"), "trial%20A%2F2");
    }
}
