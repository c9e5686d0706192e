//! The server starts on a temporary SQLite file, answers health checks and stops.

mod common;

#[tokio::test]
async fn the_server_answers_healthz_and_stops_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let (addr, server) = common::start_server(&dir.path().join("t.db")).await;
    let res = reqwest::get(format!("http://{addr}/healthz"))
        .await
        .unwrap();
    assert_eq!(res.status(), 200);
    assert!(res.headers().contains_key("x-request-id"));
    server.shutdown().await;
    assert!(reqwest::get(format!("http://{addr}/healthz"))
        .await
        .is_err());
}
