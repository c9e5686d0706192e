//! Solving: stateless `POST /api/v1/solve`, and solutions of stored sessions.

use axum::extract::rejection::QueryRejection;
use axum::extract::{Path, Query, State};
use axum::http::{HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::Json;

use crate::balancing::model::{Session, SolveOptions, SolveRequest};
use crate::balancing::{self, InputError, Solution};
use crate::db::idempotency;
use crate::db::{self, StoreError, StoredSolution};
use crate::http::error::{ApiError, ErrorBody};
use crate::http::extract::{JsonBody, OptionsBody};
use crate::http::headers::{self, Page};
use crate::http::responses::{
    BodyRefused, MalformedJson, PageRefused, SolverOrStoreUnavailable, StorageFull,
    StoreUnavailable,
};
use crate::http::store::coefficients_from;
use crate::http::work::Refused;
use crate::http::AppState;

/// Name a solver error's field within the body of `POST /api/v1/solve`
/// (`{"session", "options"}`): the core names options as `options.…` and the
/// session's fields from its root.
pub(crate) fn within_solve_request(e: InputError) -> InputError {
    match e.field.as_deref() {
        Some(f) if f != "options" && !f.starts_with("options.") => e.under("session"),
        _ => e,
    }
}

/// Name a solver error's field within a posted options body, or, for a fault
/// in the stored session (its runs, a trim job's `trim`), as `session.…`, the
/// path `/api/v1/solve` gives it. Such faults had no field at all.
fn within_options(mut e: InputError) -> InputError {
    e.field = e
        .field
        .take()
        .and_then(|f| match f.strip_prefix("options.") {
            Some(rest) => Some(rest.to_string()),
            None if f == "options" => None,
            None => Some(format!("session.{f}")),
        });
    e
}

/// Run the solver off the async workers in one of the service's solve slots
/// (`work`): a large session or a min-max problem must not stall other
/// requests, nor may many of them exhaust the machine. A panic in the solver
/// becomes a 500. `name_field` puts the error's field path in terms of the
/// posted body.
async fn solve_blocking(
    state: &AppState,
    session: Session,
    options: SolveOptions,
    name_field: fn(InputError) -> InputError,
) -> Result<Solution, Refused> {
    state
        .solves
        .solve(move || balancing::solve(&session, &options))
        .await?
        .map_err(|e| name_field(e).into())
}

#[utoipa::path(post, path = "/api/v1/solve", tag = "solve",
    operation_id = "solve", summary = "Correction weights for a session (nothing stored)",
    request_body = SolveRequest,
    responses(
        (status = 200, description = "The correction", body = Solution),
        MalformedJson,
        BodyRefused,
        (status = 422, description = "Invalid or unsolvable session or options, or a session over the size limits (`too_large`)", body = ErrorBody),
        SolverOrStoreUnavailable,
    ))]
pub async fn solve(
    State(state): State<AppState>,
    JsonBody(req): JsonBody<SolveRequest>,
) -> Result<Json<Solution>, Refused> {
    // `balancing::solve` validates the session first; `within_solve_request`
    // puts its field paths under `session.`.
    balancing::check_posted_session(&req.session)?;
    // Stored coefficients (v2 `coefficients_from`) are read here, not in the core.
    let options =
        coefficients_from::resolve(&state, &req.session, req.options, within_solve_request).await?;
    Ok(Json(
        solve_blocking(&state, req.session, options, within_solve_request).await?,
    ))
}

#[utoipa::path(post, path = "/api/v1/sessions/{id}/solutions", tag = "solve",
    operation_id = "create_solution", summary = "Solve a stored session and store the solution",
    params(("id" = String, Path, description = "Session id"),
           ("Idempotency-Key" = Option<String>, Header, description = "A retry with the same key and options answers the first answer again and stores nothing new")),
    request_body(content = Option<SolveOptions>, description = "Solve options; an empty body means the defaults"),
    responses(
        (status = 201, description = "Solved and stored", body = StoredSolution,
         headers(("Idempotent-Replayed" = String, description = "`true` on the answer kept for a repeated Idempotency-Key: nothing new was stored"))),
        MalformedJson,
        (status = 404, description = "No such session", body = ErrorBody),
        BodyRefused,
        (status = 422, description = "Invalid options (named without `options.`), or the session cannot be solved yet (named `session.…`; a trim job with no coefficient options is solved with its `trim`'s, a fault in them named `session.trim.…`)", body = ErrorBody),
        SolverOrStoreUnavailable,
        StorageFull,
    ))]
pub async fn create_solution(
    State(state): State<AppState>,
    Path(id): Path<String>,
    request_headers: HeaderMap,
    OptionsBody(options): OptionsBody,
) -> Result<Response, Refused> {
    let path = format!("/api/v1/sessions/{id}/solutions");
    let idem = headers::idempotency(&request_headers, "POST", &path, &options)?;
    if let Some(r) = idempotency::lookup(&state.db, idem.as_ref()).await? {
        return Ok(headers::replay(r));
    }
    let (session, solved) = db::solutions::load_for_solve(&state.db, &id).await?;
    let resolved =
        coefficients_from::resolve(&state, &session, options.clone(), within_options).await?;
    let solution = solve_blocking(&state, session, resolved, within_options).await?;
    let stored = match db::solutions::store(
        &state.db,
        &id,
        solved,
        &options,
        &solution,
        idem.as_ref(),
    )
    .await
    {
        Err(StoreError::Replayed(r)) => return Ok(headers::replay(r)),
        other => other?,
    };
    Ok((StatusCode::CREATED, Json(stored)).into_response())
}

#[utoipa::path(get, path = "/api/v1/sessions/{id}/solutions", tag = "solve",
    operation_id = "list_solutions", summary = "List a session's stored solutions, oldest first",
    params(("id" = String, Path, description = "Session id"), Page),
    responses(
        (status = 200, description = "A page of the stored solutions, oldest first (limit 1 to 100, default 20)", body = Vec<StoredSolution>,
         headers(("X-Total-Count" = i64, description = "Solutions in all"))),
        PageRefused,
        (status = 404, description = "No such session", body = ErrorBody),
        StoreUnavailable,
    ))]
pub async fn list_solutions(
    State(state): State<AppState>,
    Path(id): Path<String>,
    page: Result<Query<Page>, QueryRejection>,
) -> Result<Response, ApiError> {
    // A solution of a large session is megabytes: pages are short.
    let (limit, offset) = Page::bounds(page, 20, 100)?;
    let (list, total) = db::solutions::list(&state.db, &id, limit, offset).await?;
    Ok(headers::with_total(Json(list).into_response(), total))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solver_errors_name_fields_within_the_posted_body() {
        let opt = InputError::invalid("x", "options.planes", "m");
        let run = InputError::invalid("x", "runs", "m");
        let none = InputError::unsolvable("x", "m");
        assert_eq!(
            within_solve_request(opt.clone()).field.as_deref(),
            Some("options.planes")
        );
        assert_eq!(
            within_solve_request(run.clone()).field.as_deref(),
            Some("session.runs")
        );
        assert_eq!(within_solve_request(none).field, None);
        assert_eq!(within_options(opt).field.as_deref(), Some("planes"));
        // The stored session's fault, named as /solve names it.
        assert_eq!(within_options(run).field.as_deref(), Some("session.runs"));
        let whole = InputError::invalid("x", "options", "m");
        assert_eq!(within_options(whole).field, None);
    }
}
