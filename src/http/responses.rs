//! The error rows of the OpenAPI document that several endpoints share,
//! declared once (`utoipa::IntoResponses`) and listed in each endpoint's
//! `responses(...)` beside its own rows: what a JSON body, a page's query
//! and the solve slots can be refused with. The document lists a status once
//! per operation, so an endpoint whose refusal reads differently (its own
//! 422, say) keeps its own row for it.

use utoipa::IntoResponses;

use super::error::ErrorBody;

/// A request body that is not JSON, or JSON with an unknown field
/// (`extract::JsonBody`).
#[derive(IntoResponses)]
#[response(
    status = 400,
    description = "Malformed JSON or unknown field; or a query parameter (`invalid_query`: no write takes one)"
)]
pub struct MalformedJson(pub ErrorBody);

/// A request body over the body limit, or without `Content-Type:
/// application/json`: the endpoints that name these themselves rather than
/// leave them to the edge's general rows (`openapi::EdgeAnswers`).
#[derive(IntoResponses)]
pub enum BodyRefused {
    #[response(status = 413, description = "Body over the limit")]
    TooLarge(ErrorBody),
    #[response(
        status = 415,
        description = "Not application/json, or a Content-Encoding other than identity"
    )]
    NotJson(ErrorBody),
}

/// A query parameter on a GET that takes none (`headers::NoParams`).
#[derive(IntoResponses)]
#[response(
    status = 400,
    description = "A query parameter: this operation takes none (`invalid_query`, naming it)"
)]
pub struct QueryRefused(pub ErrorBody);

/// A paged list's query (`limit`, `offset`) refused.
#[derive(IntoResponses)]
pub enum PageRefused {
    #[response(status = 400, description = "Unknown or malformed query parameter")]
    Malformed(ErrorBody),
    #[response(status = 422, description = "limit or offset out of range")]
    OutOfRange(ErrorBody),
}

/// Every solve slot taken (`http::work`). The edge's 503 (too many
/// connections) is added to every operation's 503 row (`openapi::EdgeAnswers`).
#[derive(IntoResponses)]
#[response(
    status = 503,
    description = "Every solver busy (`busy`): retry after `Retry-After` seconds; nothing was computed or stored"
)]
pub struct SolverBusy(pub ErrorBody);

/// The database cannot be reached or written (`StoreError::Storage`: a
/// read-only file, an I/O error, a PostgreSQL server down), for an operation
/// that reads or writes the store.
#[derive(IntoResponses)]
#[response(
    status = 503,
    description = "The database cannot be reached or written (`storage_unavailable`); nothing was stored"
)]
pub struct StoreUnavailable(pub ErrorBody);

/// [`SolverBusy`] or [`StoreUnavailable`], for a solve that reads or
/// writes the store (one row per status in the document).
#[derive(IntoResponses)]
#[response(
    status = 503,
    description = "Every solver busy (`busy`: retry after `Retry-After` seconds), or the database cannot be reached or written (`storage_unavailable`); nothing was stored"
)]
pub struct SolverOrStoreUnavailable(pub ErrorBody);

/// A write that met a full disk (`StoreError::Storage`, `db::health::is_full`).
#[derive(IntoResponses)]
#[response(
    status = 507,
    description = "The disk holding the database is full (`storage_full`); nothing was stored"
)]
pub struct StorageFull(pub ErrorBody);
