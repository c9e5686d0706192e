//! `POST /api/v1/trial-weights`: a suggested trial weight per plane, before
//! (or instead of a repeated) trial run.

use axum::extract::State;
use axum::Json;

use serde::Serialize;
use utoipa::ToSchema;

use crate::balancing::check_posted_session;
use crate::balancing::fit::trial::{suggest, TrialRequest, TrialSuggestion};
use crate::balancing::model::Conventions;
use crate::http::error::ErrorBody;
use crate::http::extract::JsonBody;
use crate::http::responses::{BodyRefused, MalformedJson, SolverOrStoreUnavailable};
use crate::http::solve::within_solve_request;
use crate::http::store::coefficients_from;
use crate::http::work::Refused;
use crate::http::AppState;

#[utoipa::path(post, path = "/api/v1/trial-weights", tag = "solve",
    operation_id = "trial_weights", summary = "Suggest a trial weight per plane (nothing stored)",
    request_body = TrialRequest,
    description = "A trial weight per selected plane that should move the 1X vibration by about 30 % \
(the change field practice asks of a trial run, e.g. Acoem's 'Balancing How To #2: selecting a proper trial weight'). \
The session may hold only its reference run.\n\n\
basis `coefficients` (coefficients supplied in the options as `influence_coefficients`, a machine's stored ones by `coefficients_from`, or those the session's own trial runs determine): \
mass m = 0.3·‖G·Y0‖/‖G·W_j‖ over the selected rows (row weights G), so the vibration moves by 30 % \
(at least one row by 30 % or more), at the angle that lowers it most; `expected_change_pct` is that \
change in percent for the weight given.\n\n\
basis `rotor` (no coefficients known): the weight whose centrifugal force at service speed is 10 % of the \
rotor's weight share on the plane, m·r·ω² = 0.10·(M/P)·g (M rotor mass, P planes of the session, \
r the plane's radius_mm, ω from service_speed_rpm), at angle 0: the usual rule of thumb of field-balancing \
guides, a force of about a tenth of the static bearing load, large enough to read and small enough to run safely. \
Needs `rotor` and each plane's `radius_mm`.\n\n\
With a kit on the plane: the stack of kit weights (at most max_per_place) at one fixed place nearest to that weight; \
`place` and `weights` say which.",
    responses(
        (status = 200, description = "One suggestion per selected plane, and the conventions of their angles", body = TrialAnswer),
        MalformedJson,
        BodyRefused,
        (status = 422, description = "Invalid session or options, a solve option sizing does not use (`unused_option`, naming it: only `planes`, `sensors`, `speeds_rpm`, `row_weights`, `influence_coefficients` and `coefficients_from` are taken), or nothing to size a trial weight from", body = ErrorBody),
        SolverOrStoreUnavailable,
    ))]
pub async fn trial_weights(
    State(state): State<AppState>,
    JsonBody(req): JsonBody<TrialRequest>,
) -> Result<Json<TrialAnswer>, Refused> {
    check_posted_session(&req.session)?;
    // Stored coefficients (`coefficients_from`) are read here, as for a solve.
    let options =
        coefficients_from::resolve(&state, &req.session, req.options, within_solve_request).await?;
    // Validating and solving the session costs like a solve: off the async
    // threads, in one of the solve slots.
    let session = req.session;
    let conventions = session.conventions.unwrap_or_default();
    let suggestions = state
        .solves
        .solve(move || suggest(&session, &options, None).map_err(within_solve_request))
        .await??;
    Ok(Json(TrialAnswer {
        suggestions,
        conventions,
    }))
}

/// The answer of `POST /api/v1/trial-weights`: the contract's `suggestions`
/// and, added as a solution has it, the `conventions` every `angle_deg` is
/// in (the session's).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct TrialAnswer {
    pub suggestions: Vec<TrialSuggestion>,
    /// The session's conventions, which every angle of the suggestions uses.
    pub conventions: Conventions,
}
