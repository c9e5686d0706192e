//! The web form's files, embedded in the binary so `fieldbal serve` shows it from any directory.

use axum::{response::Html, routing::get, Router};

/// Routes for `/` and the form's static files.
pub fn router<S: Clone + Send + Sync + 'static>() -> Router<S> {
    Router::new().route(
        "/",
        get(|| async { Html("<!doctype html><title>fieldbal</title>") }),
    )
}
