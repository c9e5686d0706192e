//! Shared support for integration tests: start the real server on 127.0.0.1:0
//! on either engine, and read the public examples.
//!
//! A test names an SQLite file; with `FIELDBAL_TEST_ENGINE=postgres`
//! (`scripts/test.sh` runs the HTTP suites a second time so) the server gets
//! a PostgreSQL database of its own on the throw-away cluster at
//! `FIELDBAL_TEST_POSTGRES_URL` instead, named after that file so that a
//! restart on the same file finds the same data.
#![allow(dead_code)] // each test binary uses a different part of this module

pub mod binary;
pub mod engine;

use std::net::SocketAddr;
use std::path::Path;

use fieldbal::http::{self, AppState};
use tokio::sync::oneshot;
use tokio::task::JoinHandle;

/// A running server; dropping it stops it (without waiting), `shutdown` stops it and waits.
pub struct Server {
    pub addr: SocketAddr,
    stop: Option<oneshot::Sender<()>>,
    task: Option<JoinHandle<std::io::Result<()>>>,
}

impl Server {
    /// `http://127.0.0.1:PORT` followed by `path`.
    pub fn url(&self, path: &str) -> String {
        format!("http://{}{path}", self.addr)
    }

    /// Stop accepting, finish requests in flight, close the database.
    pub async fn shutdown(mut self) {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
        if let Some(task) = self.task.take() {
            task.await.expect("server task").expect("server ran");
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
    }
}

/// Start the server on 127.0.0.1:0 with the SQLite file `db_path` (created if missing).
pub async fn start_server(db_path: &Path) -> (SocketAddr, Server) {
    start_server_with(db_path, http::DEFAULT_BODY_LIMIT).await
}

/// A server on a fresh database (`t.db` in a new temporary directory) and a
/// client: how most HTTP tests begin. The directory holds the database, so
/// keep it (bound to a name, not `_`) for as long as the server runs.
pub async fn fresh_server() -> (tempfile::TempDir, Server, reqwest::Client) {
    let dir = tempfile::tempdir().unwrap();
    let (_, server) = start_server(&dir.path().join("t.db")).await;
    (dir, server, reqwest::Client::new())
}

/// As [`start_server`], with another request body limit.
pub async fn start_server_with(db_path: &Path, body_limit: usize) -> (SocketAddr, Server) {
    start_server_configured(db_path, |s| s.with_body_limit(body_limit)).await
}

/// As [`start_server`], with the state's settings changed by `configure`.
pub async fn start_server_configured(
    db_path: &Path,
    configure: impl FnOnce(AppState) -> AppState,
) -> (SocketAddr, Server) {
    let url = engine::database_url(db_path).await;
    let pool = http::connect_db(&url).await.expect("database opens");
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind 127.0.0.1:0");
    let addr = listener.local_addr().expect("local addr");
    let (stop, stopped) = oneshot::channel::<()>();
    let state = configure(AppState::new(pool.clone()));
    let task = tokio::spawn(async move {
        let served = http::serve(listener, state, async {
            let _ = stopped.await;
        })
        .await;
        // Close the pool so a restart on the same file sees every commit checkpointed.
        pool.close().await;
        served
    });
    let server = Server {
        addr,
        stop: Some(stop),
        task: Some(task),
    };
    (addr, server)
}

/// An example file from `tests/data/examples` (copies of `../shared/examples`), parsed.
pub fn example(name: &str) -> serde_json::Value {
    let path = format!("{}/tests/data/examples/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The examples that carry a session and an expected answer.
pub const SOLVABLE_EXAMPLES: &[&str] = &[
    "pump-two-plane-exact.json",
    "pump-two-plane-kept-trial-exact.json",
    "pump-single-plane-noisy.json",
    "compressor-multispeed-exact.json",
    "compressor-multispeed-noisy.json",
];

/// Assert that a solution's corrections match an example's `expected` within its tolerance.
pub fn assert_matches_expected(
    name: &str,
    solution: &serde_json::Value,
    expected: &serde_json::Value,
) {
    let tol = &expected["tolerance"];
    let mass_rel = tol["mass_rel"].as_f64().expect("tolerance.mass_rel");
    let angle_tol = tol["angle_deg"].as_f64().expect("tolerance.angle_deg");
    let want = expected["corrections"]
        .as_array()
        .expect("expected.corrections");
    let got = solution["corrections"]
        .as_array()
        .unwrap_or_else(|| panic!("{name}: no corrections in {solution}"));
    assert_eq!(got.len(), want.len(), "{name}: number of corrections");
    for w in want {
        let plane = &w["plane"];
        let g = got
            .iter()
            .find(|c| &c["plane"] == plane)
            .unwrap_or_else(|| panic!("{name}: no correction for {plane}"));
        let (gm, wm) = (g["mass_g"].as_f64().unwrap(), w["mass_g"].as_f64().unwrap());
        let (ga, wa) = (
            g["angle_deg"].as_f64().unwrap(),
            w["angle_deg"].as_f64().unwrap(),
        );
        assert!(
            (gm - wm).abs() <= mass_rel * wm,
            "{name} {plane}: mass {gm} vs {wm}"
        );
        assert!(
            fieldbal::balancing::phasor::angle_diff_deg(ga, wa) <= angle_tol,
            "{name} {plane}: angle {ga} vs {wa}"
        );
    }
}

/// Percent-encode all but the unreserved characters (RFC 3986), so that an
/// odd id (spaces, slashes) stays one path segment. Written apart from the
/// service's own encoder (`http::store::runs`) on purpose: a test's URL
/// should not depend on the code under test.
pub fn path_segment(s: &str) -> String {
    let unreserved = |b: u8| b.is_ascii_alphanumeric() || b"-._~".contains(&b);
    s.bytes()
        .map(|b| {
            if unreserved(b) {
                char::from(b).to_string()
            } else {
                format!("%{b:02X}")
            }
        })
        .collect()
}

/// Solve a stored session (POST `{}` to its solutions); asserts 201 and
/// returns the stored solution's body.
pub async fn store_solution(
    client: &reqwest::Client,
    server: &Server,
    session_id: &str,
) -> serde_json::Value {
    let url = server.url(&format!("/api/v1/sessions/{session_id}/solutions"));
    let (status, _, body) = post(client, &url, &serde_json::json!({})).await;
    assert_eq!(status, 201, "{body}");
    body
}

/// POST a JSON value; returns status, headers and the parsed body (Null if empty).
pub async fn post(
    client: &reqwest::Client,
    url: &str,
    body: &serde_json::Value,
) -> (u16, reqwest::header::HeaderMap, serde_json::Value) {
    send(client.post(url).json(body)).await
}

/// Send a request; returns status, headers and the parsed body (Null if empty).
pub async fn send(
    req: reqwest::RequestBuilder,
) -> (u16, reqwest::header::HeaderMap, serde_json::Value) {
    let res = req.send().await.expect("request answered");
    let status = res.status().as_u16();
    let headers = res.headers().clone();
    let bytes = res.bytes().await.expect("body read");
    let body = if bytes.is_empty() {
        serde_json::Value::Null
    } else {
        serde_json::from_slice(&bytes).unwrap_or_else(|e| {
            panic!(
                "body is not JSON ({e}): {}",
                String::from_utf8_lossy(&bytes)
            )
        })
    };
    (status, headers, body)
}
