//! The HTTP layer's one error type: a status and the contract's JSON error body.
//!
//! Internal causes (database, a panic) are logged with the request's span and
//! answered with a generic 500 body; bad input never reaches that arm.

use axum::http::StatusCode;
use axum::response::{IntoResponse, Response};
use axum::Json;
use serde::Serialize;
use utoipa::ToSchema;

use crate::balancing::{ErrorKind, InputError};
use crate::db::StoreError;

/// The contract's error body: `{"error": {"code", "message", "field"}}`.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ErrorBody {
    pub error: ErrorDetail,
}

/// What went wrong, and the path of the field at fault where one field is.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ErrorDetail {
    /// Stable machine-readable code, e.g. `unknown_field`, `not_found`, `body_too_large`.
    pub code: String,
    pub message: String,
    /// E.g. `runs[2].readings[5].phase_deg`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub field: Option<String>,
}

/// A rejected or failed request.
#[derive(Debug)]
pub struct ApiError {
    pub status: StatusCode,
    pub detail: ErrorDetail,
}

impl ApiError {
    pub fn new(status: StatusCode, code: &str, message: impl Into<String>) -> Self {
        ApiError {
            status,
            detail: ErrorDetail {
                code: code.to_string(),
                message: message.into(),
                field: None,
            },
        }
    }

    pub fn with_field(mut self, field: impl Into<String>) -> Self {
        self.detail.field = Some(field.into());
        self
    }

    pub fn not_found(message: impl Into<String>) -> Self {
        Self::new(StatusCode::NOT_FOUND, "not_found", message)
    }

    /// Log the cause and answer a generic 500: the client learns nothing internal.
    pub fn internal(cause: &dyn std::fmt::Display) -> Self {
        tracing::error!(error = %cause, "internal error");
        Self::new(
            StatusCode::INTERNAL_SERVER_ERROR,
            "internal",
            "internal error; the server log has the details",
        )
    }
}

impl From<InputError> for ApiError {
    fn from(e: InputError) -> Self {
        let status = match e.kind {
            ErrorKind::Malformed => StatusCode::BAD_REQUEST,
            ErrorKind::Invalid => StatusCode::UNPROCESSABLE_ENTITY,
        };
        ApiError {
            status,
            detail: ErrorDetail {
                code: e.code.to_string(),
                message: e.message,
                field: e.field,
            },
        }
    }
}

impl From<StoreError> for ApiError {
    fn from(e: StoreError) -> Self {
        match e {
            StoreError::NotFound(message) => ApiError::not_found(message),
            StoreError::Conflict { field, message } => {
                ApiError::new(StatusCode::CONFLICT, "duplicate_id", message).with_field(field)
            }
            StoreError::Invalid(input) => input.into(),
            StoreError::KeyReused => ApiError::new(
                StatusCode::UNPROCESSABLE_ENTITY,
                "idempotency_key_reused",
                "this Idempotency-Key was used for a different request (method, path or body); use a new key",
            )
            .with_field("Idempotency-Key"),
            StoreError::Stale(message) => {
                ApiError::new(StatusCode::PRECONDITION_FAILED, "precondition_failed", message)
                    .with_field("If-Match")
            }
            // Handlers answer a replay themselves; reaching here is a bug.
            StoreError::Replayed(_) => ApiError::internal(&e),
            // Storage faults are not bugs: say what happened, log the cause.
            StoreError::Storage(cause) => {
                tracing::error!(error = %cause, "the database cannot be written");
                if crate::db::health::is_full(&cause) {
                    ApiError::new(
                        StatusCode::INSUFFICIENT_STORAGE,
                        "storage_full",
                        "the disk holding the database is full; nothing was stored",
                    )
                } else {
                    ApiError::new(
                        StatusCode::SERVICE_UNAVAILABLE,
                        "storage_unavailable",
                        "the database cannot be written; nothing was stored",
                    )
                }
            }
            StoreError::Db(_) | StoreError::Corrupt(_) => ApiError::internal(&e),
        }
    }
}

impl IntoResponse for ApiError {
    fn into_response(self) -> Response {
        (self.status, Json(ErrorBody { error: self.detail })).into_response()
    }
}
