//! Identification endpoints (`/api/v1/identify/…`): stateless, like `/solve`;
//! the work runs off the async workers in one of the solve slots.

use axum::extract::State;
use axum::Json;

use crate::balancing::InputError;
use crate::http::error::ErrorBody;
use crate::http::extract::JsonBody;
use crate::http::responses::{MalformedJson, SolverBusy};
use crate::http::work::Refused;
use crate::http::AppState;
use crate::identification::{
    correct, decay, rotor, FreeDecay, FreeDecayRequest, ModelCorrection, ModelRequest,
    RotorIdentification, RotorRequest,
};

/// Fits and eigen-solves cost like a solve: they share its slots (503 when busy).
async fn blocking<T: Send + 'static>(
    state: &AppState,
    work: impl FnOnce() -> Result<T, InputError> + Send + 'static,
) -> Result<Json<T>, Refused> {
    Ok(Json(state.solves.solve(work).await??))
}

#[utoipa::path(post, path = "/api/v1/identify/rotor", tag = "identification",
    operation_id = "identify_rotor", summary = "One-mass rotor model from a multi-speed session",
    request_body = RotorRequest,
    responses(
        (status = 200, description = "Per sensor and plane: critical speed and its resolution (`critical_speed_resolution_rpm`, 95 %), damping ratio and its resolution, API 684 amplification factor and separation margin; a damping ratio within its resolution of zero is given as an upper bound (`damping_ratio_bound`), the factor as a lower one, with a `damping_unresolved` warning and no damping or cross-coupling coefficient; these come with their 95 % resolutions, or not at all when their split is unresolved (`damping_split_unresolved`)", body = RotorIdentification),
        MalformedJson,
        (status = 422, description = "Invalid session or options (a `speed_range_rpm` not `[lo, hi]` with lo < hi, each 1 to 1e6 rpm; an empty `sensors` or `planes`, an unknown or repeated id in them), too few speeds", body = ErrorBody),
        SolverBusy,
    ))]
pub async fn rotor(
    State(state): State<AppState>,
    JsonBody(req): JsonBody<RotorRequest>,
) -> Result<Json<RotorIdentification>, Refused> {
    // The session's texts and machine, as `/solve` and the store refuse them.
    crate::balancing::check_posted_session(&req.session)?;
    blocking(&state, move || rotor::identify(&req)).await
}

#[utoipa::path(post, path = "/api/v1/identify/free-decay", tag = "identification",
    operation_id = "identify_free_decay", summary = "Natural frequency and damping from a free decay",
    request_body = FreeDecayRequest,
    responses(
        (status = 200, description = "Natural frequency (`frequency_hz`: the undamped ω0/2π; `damped_frequency_hz` the frequency of the decaying oscillation, `undamped_frequency_hz` = `frequency_hz`), damping (`damping_ratio`, viscous only; within its resolution of zero given as the most the samples allow, `damping_ratio_bound` `upper`, with a `damping_unresolved` warning), the 95 % resolutions of both (viscous), decrement, amplitude and phase, the `offset` the record sits on (fitted, or the request's), and `warnings` (`few_samples_per_period`; `clipped`, the record flat at its largest or smallest value where the fitted decay goes on past it)", body = FreeDecay),
        MalformedJson,
        (status = 422, description = "Too few samples, a step `dt_s` outside 1e-9 to 25 s, a sample above 1e12 or all below 1e-12 in size, samples that show no decaying oscillation (less than half a period, a growing amplitude, or a fit explaining too little of the record: F ratio below 10), an `offset` above 1e12 in size, or a frequency outside 0.01 to 1e5 Hz (`frequency_out_of_range`)", body = ErrorBody),
        SolverBusy,
    ))]
pub async fn free_decay(
    State(state): State<AppState>,
    JsonBody(req): JsonBody<FreeDecayRequest>,
) -> Result<Json<FreeDecay>, Refused> {
    blocking(&state, move || decay::identify(&req)).await
}

#[utoipa::path(post, path = "/api/v1/identify/model", tag = "identification",
    operation_id = "identify_model", summary = "Correct a discrete model from measured modes",
    request_body = ModelRequest,
    responses(
        (status = 200, description = "The corrected parameters and the corrected model's frequencies", body = ModelCorrection),
        MalformedJson,
        (status = 422, description = "Non-square or asymmetric matrix, a mass or stiffness entry, measured frequency, shape entry, weight or starting parameter out of its range (docs/session-format.md, Identification), a shape of the wrong length, too few modes or more than degrees of freedom, modes that cannot settle the parameters and unmeasured shape entries (`too_few_equations`, `unidentifiable`, naming `modes`; a partly measured fit missing a measured frequency, `not_converged`, or not settling, `not_converged` naming `initial`), or a corrected model whose frequencies leave 0.01 to 1e5 Hz (`frequency_out_of_range`)", body = ErrorBody),
        SolverBusy,
    ))]
pub async fn model(
    State(state): State<AppState>,
    JsonBody(req): JsonBody<ModelRequest>,
) -> Result<Json<ModelCorrection>, Refused> {
    blocking(&state, move || correct::correct(&req)).await
}
