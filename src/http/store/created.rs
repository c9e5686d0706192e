//! The `201 Created` of a POST whose answer is known before the write (a new
//! session's id, a run's version 1): kept with the request's `Idempotency-Key`
//! in the write's own transaction (`db::idempotency::Keep`), so a retry gets
//! the same answer even after a crash between the commit and the answer.

use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, IntoResponseParts, Response};
use axum::Json;
use serde::Serialize;

use crate::db::idempotency::{Idem, Keep};
use crate::db::StoreError;
use crate::http::error::ApiError;
use crate::http::headers;

/// A `201 Created` answer: its `Location` and JSON body.
pub struct CreatedAnswer<B> {
    pub location: String,
    pub body: B,
}

impl<B: Serialize> CreatedAnswer<B> {
    /// This answer, to keep with the request's key (nothing without a key),
    /// its body as the text [`Self::answer`] sends.
    pub fn keep<'a>(&self, idem: Option<&'a Idem>) -> Result<Option<Keep<'a>>, StoreError> {
        let Some(idem) = idem else {
            return Ok(None);
        };
        Ok(Some(Keep {
            idem,
            status: 201,
            location: Some(self.location.clone()),
            body: serde_json::to_string(&self.body)?,
        }))
    }

    /// The answer once `written`: 201 with `Location`, the headers of `parts`
    /// and the body. When another request with the same key got there first
    /// (`StoreError::Replayed`), the answer that one was given; a write that
    /// failed, its error.
    pub fn answer<T>(
        self,
        written: Result<T, StoreError>,
        parts: impl IntoResponseParts,
    ) -> Result<Response, ApiError> {
        match written {
            // The kept 201, with the headers this answer adds (a run's ETag).
            Err(StoreError::Replayed(r)) => return Ok((parts, headers::replay(r)).into_response()),
            other => other?,
        };
        Ok((
            StatusCode::CREATED,
            [(header::LOCATION, self.location)],
            parts,
            Json(self.body),
        )
            .into_response())
    }
}
