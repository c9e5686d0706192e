//! `/api/v1/machines` (v2 "Machines"): create, list, read (with sessions and
//! coefficient versions) and delete machines; pool sessions into a new
//! coefficient version and read versions back. A solve's `coefficients_from`
//! is read in `coefficients_from.rs`.

use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::Json;
use serde::{Deserialize, Serialize};
use utoipa::{IntoParams, ToSchema};

use crate::balancing::job::pool::{self, PoolOptions};
use crate::balancing::InputError;
use crate::db::machines::{
    self, MachineDetail, MachineList, Missing, NewMachine, StoredCoefficients,
};
use crate::db::{idempotency, StoreError};
use crate::http::error::{ApiError, ErrorBody};
use crate::http::extract::JsonBody;
use crate::http::headers::{self, invalid_query};
use crate::http::responses::{
    MalformedJson, PageRefused, SolverOrStoreUnavailable, StorageFull, StoreUnavailable,
};
use crate::http::runs::encode_segment;
use crate::http::sessions::ListParams;
use crate::http::work::Refused;
use crate::http::AppState;

fn invalid(field: &str, message: impl Into<String>) -> InputError {
    InputError::invalid("invalid_value", field, message)
}

/// Why version `v` of `machine` is not there any more: it was deleted with an
/// earlier machine of that id, and numbers are never given twice.
pub(crate) fn retired_version(machine: &str, v: i64, last: i64) -> String {
    format!(
        "machine '{machine}' has no coefficient version {v}: versions 1 to {last} were deleted with an earlier machine of this id, and their numbers are never given to other coefficients"
    )
}

/// 404 for a machine id in the path that names no machine.
fn no_machine(id: &str) -> ApiError {
    ApiError::not_found(format!("no machine has the id '{id}'"))
}

/// The checks of a posted machine (its rotor as in a session).
fn validate(m: &NewMachine) -> Result<(), InputError> {
    super::text::check_machine(m)?;
    if let Some(name) = &m.name {
        let n = name.chars().count();
        if name.trim().is_empty() {
            return Err(invalid(
                "name",
                "a name is not blank: give 1 to 200 characters, or leave `name` out",
            ));
        }
        if n > 200 {
            return Err(invalid(
                "name",
                format!("a name is 1 to 200 characters; this one has {n}"),
            ));
        }
    }
    if m.notes.as_ref().is_some_and(|x| x.chars().count() > 10_000) {
        return Err(invalid("notes", "at most 10000 characters"));
    }
    if let Some(r) = &m.rotor {
        crate::balancing::validate::check_rotor(r)?;
    }
    Ok(())
}

#[utoipa::path(post, path = "/api/v1/machines", tag = "machines",
    operation_id = "create_machine", summary = "Create a machine",
    request_body = NewMachine,
    responses(
        (status = 201, description = "Stored", body = machines::Machine,
         headers(("Location" = String, description = "/api/v1/machines/{id}"),
                 ("Idempotent-Replayed" = String, description = "`true` on the answer kept for a repeated Idempotency-Key: nothing new was stored"))),
        MalformedJson,
        (status = 409, description = "A machine with this id exists", body = ErrorBody),
        (status = 422, description = "Invalid machine, or an Idempotency-Key used for another request", body = ErrorBody),
        StorageFull,
        StoreUnavailable,
    ),
    params(("Idempotency-Key" = Option<String>, Header, description = "A retry with the same key and body answers the first answer again and stores nothing new")))]
pub async fn create(
    State(state): State<AppState>,
    request_headers: HeaderMap,
    JsonBody(m): JsonBody<NewMachine>,
) -> Result<Response, ApiError> {
    let idem = headers::idempotency(&request_headers, "POST", "/api/v1/machines", &m)?;
    if let Some(r) = idempotency::lookup(&state.db, idem.as_ref()).await? {
        return Ok(headers::replay(r));
    }
    validate(&m)?;
    // Percent-encoded: any id is a valid header value (a control character
    // in a raw `Location` failed the answer after the commit).
    let location = format!("/api/v1/machines/{}", encode_segment(&m.id));
    let written = machines::create(&state.db, &m, idem.as_ref(), &location).await;
    let machine = match written {
        Err(StoreError::Replayed(r)) => return Ok(headers::replay(r)),
        other => other?,
    };
    Ok((
        StatusCode::CREATED,
        [(header::LOCATION, location)],
        Json(machine),
    )
        .into_response())
}

#[utoipa::path(get, path = "/api/v1/machines", tag = "machines",
    operation_id = "list_machines", summary = "List machines, newest first",
    params(ListParams),
    responses(
        (status = 200, description = "A page of machines, newest first", body = MachineList),
        PageRefused,
        StoreUnavailable,
    ))]
pub async fn list(
    State(state): State<AppState>,
    params: Result<Query<ListParams>, QueryRejection>,
) -> Result<Json<MachineList>, ApiError> {
    let page = ListParams::bounds(params)?;
    Ok(Json(machines::list(&state.db, page).await?))
}

/// Most sessions one page of a machine's sessions may give.
const MAX_SESSIONS_PAGE: i64 = 1000;

/// Paging of a machine's sessions (`GET /api/v1/machines/{id}`), both
/// optional: without them every session is given, as before paging was
/// added.
#[derive(Debug, Deserialize, IntoParams)]
#[serde(deny_unknown_fields)]
#[into_params(parameter_in = Query)]
pub struct SessionsPage {
    /// Sessions in the page, 1 to 1000 (default: every one from `offset` on).
    pub limit: Option<i64>,
    /// Sessions to skip, oldest first (default 0).
    pub offset: Option<i64>,
}

#[utoipa::path(get, path = "/api/v1/machines/{id}", tag = "machines",
    operation_id = "get_machine", summary = "Get a machine with its jobs and coefficient versions",
    params(("id" = String, Path, description = "Machine id"), SessionsPage),
    responses(
        (status = 200, description = "The machine, its sessions (oldest first; every one, or the page `limit` and `offset` ask for) with the summary of their latest solution, and its coefficient versions", body = MachineDetail,
         headers(("X-Total-Count" = i64, description = "The machine's sessions in all"))),
        PageRefused,
        (status = 404, description = "No such machine", body = ErrorBody),
        StoreUnavailable,
    ))]
pub async fn get(
    State(state): State<AppState>,
    Path(id): Path<String>,
    page: Result<Query<SessionsPage>, QueryRejection>,
) -> Result<Response, ApiError> {
    let Query(p) = page.map_err(invalid_query)?;
    // A page's bounds as every list's; no limit: every session.
    let (limit, offset) = headers::page_bounds(p.limit, p.offset, 1, MAX_SESSIONS_PAGE)?;
    let limit = p.limit.map(|_| limit);
    let (detail, total) = machines::get(&state.db, &id, limit, offset).await?;
    Ok(headers::with_total(Json(detail).into_response(), total))
}

#[utoipa::path(delete, path = "/api/v1/machines/{id}", tag = "machines",
    operation_id = "delete_machine", summary = "Delete a machine (never its sessions)",
    params(("id" = String, Path, description = "Machine id")),
    responses(
        (status = 204, description = "Deleted with its coefficient versions; its sessions stay"),
        (status = 404, description = "No such machine", body = ErrorBody),
        StorageFull,
        StoreUnavailable,
    ))]
pub async fn delete(
    State(state): State<AppState>,
    Path(id): Path<String>,
) -> Result<StatusCode, ApiError> {
    machines::delete(&state.db, &id).await?;
    Ok(StatusCode::NO_CONTENT)
}

/// The body of `POST /api/v1/machines/{id}/coefficients`.
#[derive(Debug, Clone, Deserialize, Serialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct PoolRequest {
    /// Ids of stored sessions of this machine, 1 to 1000 of them.
    pub sessions: Vec<String>,
    #[serde(default)]
    pub options: PoolOptions,
}

#[utoipa::path(post, path = "/api/v1/machines/{id}/coefficients", tag = "machines",
    operation_id = "pool_coefficients", summary = "Pool sessions into the machine's next coefficient version",
    params(("id" = String, Path, description = "Machine id"),
           ("Idempotency-Key" = Option<String>, Header, description = "A retry with the same key and body answers the first answer again and stores no new version")),
    request_body = PoolRequest,
    responses(
        (status = 201, headers(("Idempotent-Replayed" = String, description = "`true` on the answer kept for a repeated Idempotency-Key: nothing new was stored")), description = "A new coefficient version pooled from the sessions, with `warnings`: `coefficients_disagree` (sessions whose coefficients disagree with the others beyond their noise), `plane_undetermined` (a plane whose pooled trials moved no reading, with `plane`), `no_trial_runs` (a listed session with its reference run alone, which adds nothing)", body = StoredCoefficients),
        MalformedJson,
        (status = 404, description = "No such machine", body = ErrorBody),
        (status = 422, description = "A session unknown, of another machine, or the runs cannot be pooled", body = ErrorBody),
        SolverOrStoreUnavailable,
        StorageFull,
    ))]
pub async fn pool_coefficients(
    State(state): State<AppState>,
    Path(id): Path<String>,
    request_headers: HeaderMap,
    JsonBody(req): JsonBody<PoolRequest>,
) -> Result<Response, Refused> {
    let path = format!("/api/v1/machines/{id}/coefficients");
    let idem = headers::idempotency(&request_headers, "POST", &path, &req)?;
    if let Some(r) = idempotency::lookup(&state.db, idem.as_ref()).await? {
        return Ok(headers::replay(r));
    }
    if !machines::exists(&state.db, &id).await? {
        return Err(no_machine(&id).into());
    }
    // The core's rule of a pool's list (1 to 1000 sessions, none twice), as
    // `fieldbal coefficients` applies it to its files.
    pool::check_names(&req.sessions)?;
    let loaded = match machines::load_sessions(&state.db, &req.sessions).await? {
        Ok(s) => s,
        Err(i) => {
            return Err(InputError::invalid(
                "unknown_session",
                format!("sessions[{i}]"),
                format!("no session has the id '{}'", req.sessions[i]),
            )
            .into())
        }
    };
    for (i, s) in loaded.iter().enumerate() {
        if s.machine.as_deref() != Some(id.as_str()) {
            let session = &req.sessions[i];
            let message = match s.machine.as_deref() {
                Some(other) => {
                    format!("session '{session}' belongs to machine '{other}', not '{id}'")
                }
                None => format!(
                    "session '{session}' names no machine: only sessions whose `machine` is '{id}' are pooled for it"
                ),
            };
            return Err(
                InputError::invalid("other_machine", format!("sessions[{i}]"), message).into(),
            );
        }
    }
    let named: Vec<(String, _)> = req.sessions.iter().cloned().zip(loaded).collect();
    let options = req.options.clone();
    // Pooling is a least-squares fit per row: CPU work, in the solve slots.
    let pooled = state
        .solves
        .solve(move || pool::pool(&named, &options))
        .await??;
    let body = match serde_json::to_value(&pooled).map_err(|e| ApiError::internal(&e))? {
        serde_json::Value::Object(mut m) => {
            m.remove("sessions");
            m
        }
        _ => return Err(ApiError::internal(&"pooled coefficients are not an object").into()),
    };
    let stored =
        machines::store_coefficients(&state.db, &id, &pooled.sessions, body, idem.as_ref()).await;
    let stored = match stored {
        Err(StoreError::Replayed(r)) => return Ok(headers::replay(r)),
        other => other?,
    };
    Ok((StatusCode::CREATED, Json(stored)).into_response())
}

/// `?version=n`.
#[derive(Debug, Deserialize, IntoParams)]
#[serde(deny_unknown_fields)]
#[into_params(parameter_in = Query)]
pub struct VersionParams {
    /// A version number; the latest when absent.
    pub version: Option<i64>,
}

#[utoipa::path(get, path = "/api/v1/machines/{id}/coefficients", tag = "machines",
    operation_id = "get_coefficients", summary = "Get a machine's stored coefficients (the latest or a version)",
    params(("id" = String, Path, description = "Machine id"), VersionParams),
    responses(
        (status = 200, description = "The coefficient version asked for, or the latest", body = StoredCoefficients),
        (status = 400, description = "An unknown query parameter, or a `version` that is not a whole number", body = ErrorBody),
        (status = 404, description = "No such machine or version", body = ErrorBody),
        (status = 422, description = "A `version` below 1 (`out_of_range`)", body = ErrorBody),
        StoreUnavailable,
    ))]
pub async fn get_coefficients(
    State(state): State<AppState>,
    Path(id): Path<String>,
    params: Result<Query<VersionParams>, QueryRejection>,
) -> Result<Json<StoredCoefficients>, ApiError> {
    let Query(params) = params.map_err(invalid_query)?;
    // Versions are numbered from 1: below that no machine could have the
    // version, a bad value (as `limit=0`), not a missing one.
    if let Some(v) = params.version.filter(|&v| v < 1) {
        return Err(InputError::invalid(
            "out_of_range",
            "version",
            crate::balancing::validate::version_below_one(v),
        )
        .into());
    }
    match machines::coefficients(&state.db, &id, params.version).await? {
        Ok(c) => Ok(Json(c)),
        Err(Missing::Machine) => Err(no_machine(&id)),
        Err(Missing::Version) => Err(ApiError::not_found(format!(
            "machine '{id}' has no coefficient version {}",
            params.version.unwrap_or_default()
        ))
        .with_field("version")),
        Err(Missing::Retired(last)) => Err(ApiError::not_found(retired_version(
            &id,
            params.version.unwrap_or_default(),
            last,
        ))
        .with_field("version")),
        Err(Missing::NoVersions) => Err(ApiError::not_found(format!(
            "machine '{id}' has no stored coefficients yet: POST /api/v1/machines/{id}/coefficients"
        ))),
    }
}

// Objects only: a positional array is refused (see `balancing::wire`).
crate::balancing::wire::objects_only!(PoolRequest);
