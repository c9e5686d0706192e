//! A stand for one browser test: a real server on a temporary SQLite file and
//! a headless Chromium showing the form.

use serde_json::Value;

use super::Browser;

/// The server (on a file in `dir`) and the browser, with the form loaded.
pub struct Stand {
    pub dir: tempfile::TempDir,
    pub server: crate::common::Server,
    pub browser: Browser,
}

impl Stand {
    pub async fn start() -> Stand {
        let dir = tempfile::tempdir().expect("temporary directory");
        let (_, server) = crate::common::start_server(&dir.path().join("form.db")).await;
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

    pub async fn stop(self) {
        self.browser.close().await;
        self.server.shutdown().await;
    }
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

/// The session and the expected answer of a public example.
pub fn example_session(name: &str) -> (Value, Value) {
    let example = crate::common::example(name);
    (example["session"].clone(), example["expected"].clone())
}
