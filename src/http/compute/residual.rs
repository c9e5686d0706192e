//! `POST /api/v1/residual-unbalance`: the API 617 / 684 residual-unbalance
//! check (issue 17), stateless; the core does all of it.

use axum::Json;

use crate::balancing::acceptance::{self, ResidualCheck, ResidualRequest};
use crate::http::error::{ApiError, ErrorBody};
use crate::http::extract::JsonBody;
use crate::http::responses::{BodyRefused, MalformedJson};

#[utoipa::path(post, path = "/api/v1/residual-unbalance", tag = "acceptance",
    operation_id = "residual_unbalance", summary = "API 617/684 residual-unbalance check (nothing stored)",
    request_body = ResidualRequest,
    responses(
        (status = 200, description = "The exact residual unbalance, the allowable, pass/fail and API's worksheet beside it", body = ResidualCheck),
        MalformedJson,
        BodyRefused,
        (status = 422, description = "Invalid request (fewer than 4 or more than 180 positions, positions not equally spaced, a value out of range), naming the field", body = ErrorBody),
    ))]
pub async fn check(
    JsonBody(req): JsonBody<ResidualRequest>,
) -> Result<Json<ResidualCheck>, ApiError> {
    // A handful of positions: microseconds of work, no need for a blocking thread.
    Ok(Json(acceptance::check(&req)?))
}
