//! Solving: stateless `POST /api/v1/solve`, and solutions of stored sessions.

use axum::extract::{Path, State};
use axum::http::StatusCode;
use axum::Json;

use super::error::{ApiError, ErrorBody};
use super::extract::{JsonBody, OptionsBody};
use super::AppState;
use crate::balancing::model::{Session, SolveOptions, SolveRequest};
use crate::balancing::{self, Solution};
use crate::db::{self, StoredSolution};

/// Run the solver off the async workers: a large session or a min-max problem
/// must not stall other requests. A panic in the solver becomes a 500.
async fn solve_blocking(session: Session, options: SolveOptions) -> Result<Solution, ApiError> {
    tokio::task::spawn_blocking(move || balancing::solve(&session, &options))
        .await
        .map_err(|e| ApiError::internal(&e))?
        .map_err(ApiError::from)
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
pub async fn solve(JsonBody(req): JsonBody<SolveRequest>) -> Result<Json<Solution>, ApiError> {
    balancing::validate_session(&req.session).map_err(|e| e.under("session"))?;
    Ok(Json(solve_blocking(req.session, req.options).await?))
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
    let stored = db::solutions::solve_and_store(&state.pool, &id, &options, |session| {
        balancing::solve(session, &options)
    })
    .await?;
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
    Ok(Json(db::solutions::list(&state.pool, &id).await?))
}
