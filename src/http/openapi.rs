//! The OpenAPI document, generated from the handlers' `#[utoipa::path]` annotations.

use axum::http::Method;
use axum::Json;
use utoipa::openapi::path::{Operation, PathItem};
use utoipa::openapi::response::ResponseBuilder;
use utoipa::openapi::security::{HttpAuthScheme, HttpBuilder, SecurityRequirement, SecurityScheme};
use utoipa::openapi::{ContentBuilder, Ref, RefOr};
use utoipa::{Modify, OpenApi};

use super::{identify, machines, residual, runs, sessions, solve, trial_weights};

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
        runs::get,
        runs::versions,
        solve::create_solution,
        solve::list_solutions,
        residual::check,
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
    modifiers(&EdgeAnswers),
    tags(
        (name = "sessions", description = "Stored balancing sessions"),
        (name = "runs", description = "Runs of a stored session, entered one at a time"),
        (name = "solve", description = "Corrections"),
        (name = "machines", description = "Machines, their sessions and stored influence coefficients"),
        (name = "service", description = "Operations"),
        (name = "acceptance", description = "Test-stand acceptance: API's residual-unbalance check"),
        (name = "identification", description = "Model coefficients from stand data: one-mass rotor, free decay, discrete-model correction"),
    )
)]
pub struct ApiDoc;

#[utoipa::path(get, path = "/api/v1/openapi.json", tag = "service",
    operation_id = "openapi_document", summary = "This OpenAPI document",
    responses((status = 200, description = "This document"), super::responses::QueryRefused))]
pub async fn document(
    params: Result<
        axum::extract::Query<super::headers::NoParams>,
        axum::extract::rejection::QueryRejection,
    >,
) -> Result<Json<utoipa::openapi::OpenApi>, super::error::ApiError> {
    super::headers::NoParams::check(params)?;
    Ok(Json(ApiDoc::openapi()))
}

/// What the edge (src/http/edge) may answer to any request, before or around
/// its handler, added to every operation that does not declare it itself; and
/// the optional bearer token (`--tokens-file`), not asked for by `/healthz`.
struct EdgeAnswers;

/// Which operations an edge answer applies to.
#[derive(PartialEq)]
enum Scope {
    Every,
    /// Under `/api/` (tokens, the body limit).
    Api,
    /// Under `/api/` with a request body (POST, PUT, PATCH).
    Body,
    /// A request that changes the store (`access::is_write`): what a
    /// read-only token is refused.
    Write,
}

const EDGE_ANSWERS: &[(&str, &str, Scope)] = &[
    (
        "400",
        "Malformed request (path, query or header)",
        Scope::Every,
    ),
    (
        "401",
        "A bearer token is configured and this one is missing or not valid",
        Scope::Api,
    ),
    (
        "403",
        "A read-only token on a request that changes the store",
        Scope::Write,
    ),
    (
        "408",
        "The request took longer than the request time limit",
        Scope::Every,
    ),
    (
        "413",
        "Body (or its announced Content-Length) over the limit",
        Scope::Api,
    ),
    ("414", "Request target over 8 KiB", Scope::Every),
    (
        "415",
        "A request body without Content-Type: application/json, or with a Content-Encoding other than identity (bodies are not decompressed)",
        Scope::Body,
    ),
    (
        "421",
        "The Host header is not a name this service answers to",
        Scope::Every,
    ),
    (
        "431",
        "More than 100 header fields or 32 KiB of them",
        Scope::Every,
    ),
    (
        "500",
        "Internal error; the server log has the details",
        Scope::Every,
    ),
    (
        "503",
        TOO_MANY_CONNECTIONS,
        Scope::Every,
    ),
];

/// The edge's 503, which any operation may answer: added to an operation's
/// own 503 row, or the row itself where the handler sends no 503.
const TOO_MANY_CONNECTIONS: &str =
    "Too many open connections (`too_many_connections`): retry after `Retry-After` seconds";

impl Modify for EdgeAnswers {
    fn modify(&self, openapi: &mut utoipa::openapi::OpenApi) {
        let components = openapi.components.get_or_insert_with(Default::default);
        components.add_security_scheme(
            "bearer",
            SecurityScheme::Http(HttpBuilder::new().scheme(HttpAuthScheme::Bearer).build()),
        );
        // A token only when the service is configured with some: either is valid.
        openapi.security = Some(vec![
            SecurityRequirement::new("bearer", Vec::<String>::new()),
            SecurityRequirement::default(),
        ]);
        for (path, item) in openapi.paths.paths.iter_mut() {
            let api = path.starts_with("/api/");
            for (method, op) in operations(item) {
                if !api {
                    op.security = Some(Vec::new());
                }
                let body = [Method::POST, Method::PUT, Method::PATCH].contains(&method);
                for (status, description, scope) in EDGE_ANSWERS {
                    let applies = match scope {
                        Scope::Every => true,
                        Scope::Api => api,
                        Scope::Body => api && body,
                        Scope::Write => api && super::edge::access::is_write(&method, path),
                    };
                    if !applies {
                        continue;
                    }
                    match op.responses.responses.entry(status.to_string()) {
                        std::collections::btree_map::Entry::Vacant(v) => {
                            v.insert(RefOr::T(error_response(description)));
                        }
                        // The handler's own 503s, and the edge's beside them.
                        std::collections::btree_map::Entry::Occupied(mut o) if *status == "503" => {
                            if let RefOr::T(own) = o.get_mut() {
                                let edge = description.replacen("Too", "too", 1);
                                own.description = format!("{}; or {edge}", own.description);
                            }
                        }
                        std::collections::btree_map::Entry::Occupied(_) => {}
                    }
                }
            }
        }
    }
}

/// Each operation of a path with its method.
fn operations(item: &mut PathItem) -> impl Iterator<Item = (Method, &mut Operation)> {
    [
        (Method::GET, item.get.as_mut()),
        (Method::POST, item.post.as_mut()),
        (Method::PUT, item.put.as_mut()),
        (Method::PATCH, item.patch.as_mut()),
        (Method::DELETE, item.delete.as_mut()),
    ]
    .into_iter()
    .filter_map(|(method, op)| op.map(|op| (method, op)))
}

fn error_response(description: &str) -> utoipa::openapi::Response {
    ResponseBuilder::new()
        .description(description)
        .content(
            "application/json",
            ContentBuilder::new()
                .schema(Some(Ref::from_schema_name("ErrorBody")))
                .build(),
        )
        .build()
}
