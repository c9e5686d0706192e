//! A stand for one browser test: a real server on a temporary SQLite file and
//! a headless Chromium showing the form.

use serde_json::{json, Value};

use super::Browser;

/// The server (on a file in `dir`) and the browser, with the form loaded.
pub struct Stand {
    pub dir: tempfile::TempDir,
    pub server: crate::common::Server,
    pub browser: Browser,
}

impl Stand {
    pub async fn start() -> Stand {
        let (dir, server) = serve().await;
        let browser = Browser::start().await;
        browser
            .client
            .goto(&server.url("/"))
            .await
            .expect("the form loads");
        browser.wait_for("[data-field=\"name\"]").await;
        Stand {
            dir,
            server,
            browser,
        }
    }

    /// Ready the stand for the next scene of a test binary that shares one
    /// browser (CI time): a new server on a new database, so the scene sees no
    /// other scene's sessions, and the form loaded fresh from it. The new
    /// port is a new origin, so the form's saved draft (`localStorage`) is
    /// empty too; the window is back at 1280×800, on screen, not in print.
    pub async fn renew(&mut self) {
        let (dir, server) = serve().await;
        std::mem::replace(&mut self.server, server).shutdown().await;
        self.dir = dir;
        let b = &self.browser;
        b.emulate_print(false).await;
        b.client
            .set_window_size(1280, 800)
            .await
            .expect("window resizes");
        b.open_fresh(&self.server.url("/")).await;
        b.wait_for("[data-field=\"name\"]").await;
    }

    pub async fn stop(self) {
        self.browser.close().await;
        self.server.shutdown().await;
    }
}

/// A server on a new SQLite file in a new temporary directory.
async fn serve() -> (tempfile::TempDir, crate::common::Server) {
    let dir = tempfile::tempdir().expect("temporary directory");
    let (_, server) = crate::common::start_server(&dir.path().join("form.db")).await;
    (dir, server)
}

/// The service's JSON answer to `body` posted at `path`.
pub async fn post(stand: &Stand, path: &str, body: Value) -> Value {
    reqwest::Client::new()
        .post(stand.server.url(path))
        .json(&body)
        .send()
        .await
        .unwrap()
        .json()
        .await
        .unwrap()
}

/// The service's JSON answer at `path`.
pub async fn get(stand: &Stand, path: &str) -> Value {
    reqwest::get(stand.server.url(path))
        .await
        .unwrap()
        .json()
        .await
        .unwrap()
}

/// Open the stored job `id` at its solve step in a fresh page and wait until
/// it can be solved.
pub async fn open_at_solve(stand: &Stand, id: &str) {
    stand
        .browser
        .open_fresh(&stand.server.url(&format!("/#session={id}&step=solve")))
        .await;
    stand
        .browser
        .wait_until(
            "the job is open",
            "return !document.querySelector('#step-solve').hidden && !!document.querySelector('#step-solve button.solve')",
        )
        .await;
}

/// The id of the first session the service lists (the one a test stored).
pub async fn stored_session_id(stand: &Stand) -> String {
    let list = get(stand, "/api/v1/sessions").await;
    list["sessions"][0]["id"]
        .as_str()
        .unwrap_or_else(|| panic!("a stored session: {list}"))
        .to_string()
}

/// The session and the expected answer of a public example.
pub fn example_session(name: &str) -> (Value, Value) {
    let example = crate::common::example(name);
    (example["session"].clone(), example["expected"].clone())
}

/// Machine PUMP-1 with coefficients (version 1) pooled from one solved job
/// (the pump example), all through the API as another stand PC would store
/// them; the job's session is returned.
pub async fn machine_with_coefficients(stand: &Stand) -> Value {
    let machine = post(
        stand,
        "/api/v1/machines",
        json!({"id": "PUMP-1", "name": "pump"}),
    )
    .await;
    assert_eq!(machine["id"], "PUMP-1", "{machine}");
    let (mut session, _) = example_session("pump-two-plane-exact.json");
    session["machine"] = json!("PUMP-1");
    let job = post(stand, "/api/v1/sessions", session.clone()).await;
    let job = job["id"].as_str().expect("stored").to_string();
    post(
        stand,
        &format!("/api/v1/sessions/{job}/solutions"),
        json!({}),
    )
    .await;
    let pooled = post(
        stand,
        "/api/v1/machines/PUMP-1/coefficients",
        json!({"sessions": [job]}),
    )
    .await;
    assert_eq!(pooled["version"], 1, "{pooled}");
    session
}
