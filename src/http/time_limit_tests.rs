//! The request time limit answers truthfully: 408 "nothing was stored" only
//! while no commit has begun; once one has, the request's real answer.

use std::time::Duration;

use axum::body::Body;
use axum::http::{Request, StatusCode};
use axum::routing::get;
use axum::Router;
use tower::ServiceExt;

const LIMIT: Duration = Duration::from_millis(20);

fn app() -> Router {
    Router::new()
        .route(
            "/committing",
            get(|| async {
                crate::db::watch::committing();
                tokio::time::sleep(Duration::from_secs(1)).await;
                StatusCode::CREATED
            }),
        )
        .route(
            "/stalled",
            get(|| async {
                tokio::time::sleep(Duration::from_secs(10)).await;
                StatusCode::CREATED
            }),
        )
        .layer(axum::middleware::from_fn_with_state(
            LIMIT,
            super::time_limit,
        ))
}

async fn status_and_body(path: &str) -> (StatusCode, String) {
    let req = Request::get(path).body(Body::empty()).unwrap();
    let res = app().oneshot(req).await.unwrap();
    let status = res.status();
    let bytes = axum::body::to_bytes(res.into_body(), 1 << 16)
        .await
        .unwrap();
    (status, String::from_utf8_lossy(&bytes).into_owned())
}

#[tokio::test]
async fn a_request_past_its_limit_before_any_commit_gets_408_saying_nothing_was_stored() {
    let (status, body) = status_and_body("/stalled").await;
    assert_eq!(status, StatusCode::REQUEST_TIMEOUT);
    assert!(body.contains("nothing was stored"), "{body}");
}

#[tokio::test]
async fn a_request_whose_commit_began_answers_its_real_result_past_the_limit() {
    let (status, _) = status_and_body("/committing").await;
    assert_eq!(status, StatusCode::CREATED);
}
