//! Solving: stateless `POST /api/v1/solve`, and solutions of stored sessions.

use axum::extract::{Path, State};
use axum::http::StatusCode;
use axum::Json;

use super::error::{ApiError, ErrorBody};
use super::extract::{JsonBody, OptionsBody};
use super::AppState;
use crate::balancing::model::{Session, SolveOptions, SolveRequest};
use crate::balancing::{self, InputError, Solution};
use crate::db::{self, StoredSolution};

/// Name a solver error's field within the body of `POST /api/v1/solve`
/// (`{"session", "options"}`): the core names options as `options.…` and the
/// session's fields from its root.
pub(crate) fn within_solve_request(e: InputError) -> InputError {
    match e.field.as_deref() {
        Some(f) if f != "options" && !f.starts_with("options.") => e.under("session"),
        _ => e,
    }
}

/// Name a solver error's field within a posted options body; a fault in the
/// stored session is not a field of the body (the message names it).
fn within_options(mut e: InputError) -> InputError {
    e.field = e
        .field
        .take()
        .and_then(|f| f.strip_prefix("options.").map(str::to_string));
    e
}

/// Run the solver off the async workers: a large session or a min-max problem
/// must not stall other requests. A panic in the solver becomes a 500.
/// `name_field` puts the error's field path in terms of the posted body.
async fn solve_blocking(
    session: Session,
    options: SolveOptions,
    name_field: fn(InputError) -> InputError,
) -> Result<Solution, ApiError> {
    tokio::task::spawn_blocking(move || balancing::solve(&session, &options))
        .await
        .map_err(|e| ApiError::internal(&e))?
        .map_err(|e| name_field(e).into())
}

#[utoipa::path(post, path = "/api/v1/solve", tag = "solve",
    request_body = SolveRequest,
    responses(
        (status = 200, description = "The correction", body = Solution),
        (status = 400, description = "Malformed JSON or unknown field", body = ErrorBody),
        (status = 413, description = "Body over the limit", body = ErrorBody),
        (status = 415, description = "Not application/json", body = ErrorBody),
        (status = 422, description = "Invalid or unsolvable session or options", body = ErrorBody),
    ))]
pub async fn solve(
    State(state): State<AppState>,
    JsonBody(req): JsonBody<SolveRequest>,
) -> Result<Json<Solution>, ApiError> {
    // `balancing::solve` validates the session first; `within_solve_request`
    // puts its field paths under `session.`.
    // Stored coefficients (v2 `coefficients_from`) are read here, not in the core.
    let conventions = req.session.conventions.unwrap_or_default();
    let options =
        super::machines::resolve(&state, conventions, req.options, within_solve_request).await?;
    Ok(Json(
        solve_blocking(req.session, options, within_solve_request).await?,
    ))
}

#[utoipa::path(post, path = "/api/v1/sessions/{id}/solutions", tag = "solve",
    params(("id" = String, Path, description = "Session id")),
    request_body(content = SolveOptions, description = "Solve options; an empty body means the defaults"),
    responses(
        (status = 201, description = "Solved and stored", body = StoredSolution),
        (status = 400, description = "Malformed JSON or unknown field", body = ErrorBody),
        (status = 404, description = "No such session", body = ErrorBody),
        (status = 413, description = "Body over the limit", body = ErrorBody),
        (status = 415, description = "Not application/json", body = ErrorBody),
        (status = 422, description = "Invalid options, or the session cannot be solved yet", body = ErrorBody),
    ))]
pub async fn create_solution(
    State(state): State<AppState>,
    Path(id): Path<String>,
    OptionsBody(options): OptionsBody,
) -> Result<(StatusCode, Json<StoredSolution>), ApiError> {
    let (session, solved) = db::solutions::load_for_solve(&state.db, &id).await?;
    let conventions = session.conventions.unwrap_or_default();
    let resolved =
        super::machines::resolve(&state, conventions, options.clone(), within_options).await?;
    let solution = solve_blocking(session, resolved, within_options).await?;
    let stored = db::solutions::store(&state.db, &id, solved, &options, &solution).await?;
    Ok((StatusCode::CREATED, Json(stored)))
}

#[utoipa::path(get, path = "/api/v1/sessions/{id}/solutions", tag = "solve",
    params(("id" = String, Path, description = "Session id")),
    responses(
        (status = 200, description = "Every stored solution, oldest first", body = Vec<StoredSolution>),
        (status = 404, description = "No such session", body = ErrorBody),
    ))]
pub async fn list_solutions(
    State(state): State<AppState>,
    Path(id): Path<String>,
) -> Result<Json<Vec<StoredSolution>>, ApiError> {
    Ok(Json(db::solutions::list(&state.db, &id).await?))
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
        assert_eq!(within_options(run).field, None);
    }
}
