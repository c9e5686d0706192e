//! The OpenAPI document, generated from the handlers' `#[utoipa::path]` annotations.

use axum::Json;
use utoipa::OpenApi;

use super::{identify, machines, runs, sessions, solve, trial_weights};

#[derive(OpenApi)]
#[openapi(
    info(title = "fieldbal", description = "Field balancing of rotors by influence coefficients (docs/session-format.md). Every angle uses the session's conventions."),
    paths(
        super::healthz,
        solve::solve,
        sessions::create,
        sessions::list,
        sessions::get,
        sessions::delete,
        runs::append,
        runs::replace,
        runs::versions,
        solve::create_solution,
        solve::list_solutions,
        machines::create,
        machines::list,
        machines::get,
        machines::delete,
        machines::pool_coefficients,
        machines::get_coefficients,
        identify::rotor,
        identify::free_decay,
        identify::model,
        trial_weights::trial_weights,
        document,
    ),
    tags(
        (name = "sessions", description = "Stored balancing sessions"),
        (name = "runs", description = "Runs of a stored session, entered one at a time"),
        (name = "solve", description = "Corrections"),
        (name = "machines", description = "Machines, their sessions and stored influence coefficients"),
        (name = "service", description = "Operations"),
        (name = "identification", description = "Model coefficients from stand data: one-mass rotor, free decay, discrete-model correction"),
    )
)]
pub struct ApiDoc;

#[utoipa::path(get, path = "/api/v1/openapi.json", tag = "service",
    responses((status = 200, description = "This document")))]
pub async fn document() -> Json<utoipa::openapi::OpenApi> {
    Json(ApiDoc::openapi())
}
