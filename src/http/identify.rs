//! Identification endpoints (`/api/v1/identify/…`): stateless, like `/solve`;
//! the work runs off the async workers.

use axum::Json;

use super::error::{ApiError, ErrorBody};
use super::extract::JsonBody;
use crate::balancing::InputError;
use crate::identification::{
    correct, decay, rotor, FreeDecay, FreeDecayRequest, ModelCorrection, ModelRequest,
    RotorIdentification, RotorRequest,
};

async fn blocking<T: Send + 'static>(
    work: impl FnOnce() -> Result<T, InputError> + Send + 'static,
) -> Result<Json<T>, ApiError> {
    let out = tokio::task::spawn_blocking(work)
        .await
        .map_err(|e| ApiError::internal(&e))??;
    Ok(Json(out))
}

#[utoipa::path(post, path = "/api/v1/identify/rotor", tag = "identification",
    request_body = RotorRequest,
    responses(
        (status = 200, description = "Per sensor and plane: critical speed, damping ratio, API 684 amplification factor and separation margin", body = RotorIdentification),
        (status = 400, description = "Malformed JSON or unknown field", body = ErrorBody),
        (status = 422, description = "Invalid session or options, too few speeds", body = ErrorBody),
    ))]
pub async fn rotor(
    JsonBody(req): JsonBody<RotorRequest>,
) -> Result<Json<RotorIdentification>, ApiError> {
    blocking(move || rotor::identify(&req)).await
}

#[utoipa::path(post, path = "/api/v1/identify/free-decay", tag = "identification",
    request_body = FreeDecayRequest,
    responses(
        (status = 200, description = "Natural frequency, damping, decrement, amplitude and phase", body = FreeDecay),
        (status = 400, description = "Malformed JSON or unknown field", body = ErrorBody),
        (status = 422, description = "Too few samples, a non-positive step, or samples that do not decay", body = ErrorBody),
    ))]
pub async fn free_decay(
    JsonBody(req): JsonBody<FreeDecayRequest>,
) -> Result<Json<FreeDecay>, ApiError> {
    blocking(move || decay::identify(&req)).await
}

#[utoipa::path(post, path = "/api/v1/identify/model", tag = "identification",
    request_body = ModelRequest,
    responses(
        (status = 200, description = "The corrected parameters and the corrected model's frequencies", body = ModelCorrection),
        (status = 400, description = "Malformed JSON or unknown field", body = ErrorBody),
        (status = 422, description = "Non-square or asymmetric matrix, a shape of the wrong length, too few modes", body = ErrorBody),
    ))]
pub async fn model(
    JsonBody(req): JsonBody<ModelRequest>,
) -> Result<Json<ModelCorrection>, ApiError> {
    blocking(move || correct::correct(&req)).await
}
