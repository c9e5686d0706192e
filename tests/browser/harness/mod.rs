//! Support for the end-to-end tests of the web form: Debian's headless Chromium
//! driven through chromedriver (started here on a free 127.0.0.1 port, stopped
//! on drop), the example sessions, and screenshots under `target/screenshots/`.
#![allow(dead_code)] // each browser test binary uses a different part of this module

pub mod form;
pub mod job;
pub mod stand;
pub mod steps;

use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::Duration;

use fantoccini::{Client, ClientBuilder, Locator};
use hyper_util::client::legacy::connect::HttpConnector;

const CHROMIUM: &str = "/usr/bin/chromium";
const CHROMEDRIVER: &str = "/usr/bin/chromedriver";

/// Bounded waits: up to 300 polls of 100 ms (generous: the machine is shared).
pub const WAIT_POLLS: u32 = 300;

/// A headless Chromium session; dropping it stops chromedriver and its browser.
pub struct Browser {
    pub client: Client,
    driver: Child,
    _profile: tempfile::TempDir,
    /// This binary's turn to run a browser, given back when the browser is dropped.
    _turn: tokio::sync::MutexGuard<'static, ()>,
}

/// One browser at a time in this test binary. The browser tests were one
/// binary each, which cargo runs one after another; as modules of one binary
/// they run on parallel threads, and two Chromiums at once would share CI's
/// two cores. Each test keeps its own browser (a `#[tokio::test]` has its own
/// runtime, and a WebDriver client lives on the runtime that made it), so the
/// browsers take turns. A tokio mutex: it is not poisoned by a failed test.
static TURN: tokio::sync::Mutex<()> = tokio::sync::Mutex::const_new(());

fn free_port() -> u16 {
    TcpListener::bind("127.0.0.1:0")
        .and_then(|l| l.local_addr())
        .expect("a free port on 127.0.0.1")
        .port()
}

/// Fail (never skip) when the browser is missing, saying how to install it.
fn require_binaries() {
    for bin in [CHROMIUM, CHROMEDRIVER] {
        assert!(
            Path::new(bin).exists(),
            "{bin} is missing: run scripts/install-browser.sh (installs Debian's chromium and chromium-driver)"
        );
    }
}

impl Browser {
    /// Start chromedriver and a fresh headless Chromium with a 1280×800 window.
    pub async fn start() -> Browser {
        require_binaries();
        let turn = TURN.lock().await;
        let port = free_port();
        let profile = tempfile::tempdir().expect("temporary profile directory");
        let mut command = Command::new(CHROMEDRIVER);
        command
            .arg(format!("--port={port}"))
            .arg("--allowed-ips=127.0.0.1")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null());
        // Its own process group, so that the browser it starts can be stopped with it.
        std::os::unix::process::CommandExt::process_group(&mut command, 0);
        let driver = command.spawn().expect("chromedriver starts");
        let url = format!("http://127.0.0.1:{port}");
        let mut ready = false;
        for _ in 0..WAIT_POLLS {
            if std::net::TcpStream::connect(("127.0.0.1", port)).is_ok() {
                ready = true;
                break;
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
        let mut guard = DriverGuard(Some(driver));
        assert!(ready, "chromedriver did not listen on {url} within 30 s");
        let args = [
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--disable-dev-shm-usage",
            "--window-size=1280,800",
            "--lang=en-GB",
        ]
        .iter()
        .map(|a| a.to_string())
        .chain([format!("--user-data-dir={}", profile.path().display())])
        .collect::<Vec<_>>();
        let mut caps = serde_json::Map::new();
        caps.insert("browserName".into(), "chrome".into());
        caps.insert(
            "goog:chromeOptions".into(),
            serde_json::json!({
                "binary": CHROMIUM,
                "args": args,
                "prefs": {
                    "download.default_directory": profile.path().join("downloads"),
                    "download.prompt_for_download": false,
                },
            }),
        );
        let client = ClientBuilder::new(HttpConnector::new())
            .capabilities(caps)
            .connect(&url)
            .await
            .expect("a Chromium session through chromedriver");
        Browser {
            client,
            driver: guard.0.take().expect("driver"),
            _profile: profile,
            _turn: turn,
        }
    }

    /// Close the browser session, then stop chromedriver.
    pub async fn close(self) {
        let client = self.client.clone();
        let _ = client.close().await;
        drop(self);
    }

    /// Wait (bounded) for a finished download named `name` and return its bytes.
    pub async fn downloaded(&self, name: &str) -> Vec<u8> {
        let path = self._profile.path().join("downloads").join(name);
        for _ in 0..WAIT_POLLS {
            if let Ok(bytes) = std::fs::read(&path) {
                if !bytes.is_empty() {
                    return bytes;
                }
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
        panic!("{} was not downloaded within 30 s", path.display());
    }

    /// Resize the window so that the page's viewport is `width` × `height`.
    /// The page may report its old size for a moment after a resize: wait
    /// (bounded) for the size to settle before correcting for the window's frame.
    pub async fn viewport(&self, width: u32, height: u32) {
        let want = (width as i64, height as i64);
        self.client
            .set_window_size(width, height)
            .await
            .expect("window resizes");
        let inner = self.settled_inner(want).await;
        let (dw, dh) = (want.0 - inner.0, want.1 - inner.1);
        if dw != 0 || dh != 0 {
            self.client
                .set_window_size((want.0 + dw) as u32, (want.1 + dh) as u32)
                .await
                .expect("window resizes");
            self.settled_inner(want).await;
        }
    }

    /// The page's inner size once it is `want`, or has stayed the same for a few polls.
    async fn settled_inner(&self, want: (i64, i64)) -> (i64, i64) {
        let mut last = (-1, -1);
        let mut same = 0;
        for _ in 0..40 {
            let got: (i64, i64) = serde_json::from_value(
                self.client
                    .execute("return [innerWidth, innerHeight]", vec![])
                    .await
                    .expect("inner size"),
            )
            .expect("two numbers");
            if got == want {
                return got;
            }
            same = if got == last { same + 1 } else { 0 };
            if same >= 4 {
                return got;
            }
            last = got;
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
        last
    }

    /// Show the page as it prints (CSS `@media print`), or back as on screen.
    pub async fn emulate_print(&self, print: bool) {
        let media = if print { "print" } else { "" };
        self.client
            .issue_cmd(Cdp(serde_json::json!({
                "cmd": "Emulation.setEmulatedMedia",
                "params": { "media": media },
            })))
            .await
            .expect("chromedriver runs the DevTools command");
    }

    /// Save a PNG of the viewport as `target/screenshots/NAME.png`.
    pub async fn screenshot(&self, name: &str) -> PathBuf {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/screenshots");
        std::fs::create_dir_all(&dir).expect("screenshot directory");
        let png = self.client.screenshot().await.expect("screenshot");
        let path = dir.join(format!("{name}.png"));
        std::fs::write(&path, png).expect("screenshot written");
        path
    }

    /// Wait (bounded) until an element matching `css` exists and return it.
    pub async fn wait_for(&self, css: &str) -> fantoccini::elements::Element {
        for _ in 0..WAIT_POLLS {
            if let Ok(el) = self.client.find(Locator::Css(css)).await {
                return el;
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
        panic!("no element matches {css} within 30 s");
    }

    /// Wait (bounded) until `script` returns true.
    pub async fn wait_until(&self, what: &str, script: &str) {
        for _ in 0..WAIT_POLLS {
            let v = self
                .client
                .execute(script, vec![])
                .await
                .expect("script runs");
            if v == serde_json::Value::Bool(true) {
                return;
            }
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
        panic!("{what}: not true within 30 s ({script})");
    }

    pub async fn click(&self, css: &str) {
        // The page may render again between finding the element and clicking
        // it (a reload of the session, an answer arriving): the element found
        // is then stale, and the click goes to the one now matching `css`.
        for _ in 0..50 {
            match self.wait_for(css).await.click().await {
                Ok(()) => return,
                Err(e) if e.to_string().contains("stale element") => {
                    tokio::time::sleep(Duration::from_millis(50)).await
                }
                Err(e) => panic!("click {css}: {e}"),
            }
        }
        panic!("click {css}: the element went stale 50 times in a row");
    }

    /// Load `url` as a fresh page: a new address that differs only in its
    /// hash would keep the page as it is.
    pub async fn open_fresh(&self, url: &str) {
        self.client.goto("about:blank").await.unwrap();
        self.client.goto(url).await.unwrap();
    }

    /// The visible text of the first element matching `css`.
    pub async fn text(&self, css: &str) -> String {
        self.wait_for(css).await.text().await.expect("element text")
    }
}

/// A Chrome DevTools command sent through chromedriver's `goog/cdp/execute`.
#[derive(Debug)]
struct Cdp(serde_json::Value);

impl fantoccini::wd::WebDriverCompatibleCommand for Cdp {
    fn endpoint(
        &self,
        base: &url::Url,
        session: Option<&str>,
    ) -> Result<url::Url, url::ParseError> {
        base.join(&format!(
            "session/{}/goog/cdp/execute",
            session.unwrap_or_default()
        ))
    }

    fn method_and_body(&self, _url: &url::Url) -> (http::Method, Option<String>) {
        (http::Method::POST, Some(self.0.to_string()))
    }
}

/// Stops chromedriver's process group (the driver and the browser it started).
struct DriverGuard(Option<Child>);

impl Drop for DriverGuard {
    fn drop(&mut self) {
        if let Some(child) = self.0.as_mut() {
            stop_group(child);
        }
    }
}

fn stop_group(child: &mut Child) {
    let pgid = child.id();
    let _ = Command::new("kill")
        .args(["-KILL", "--", &format!("-{pgid}")])
        .stderr(Stdio::null())
        .status();
    let _ = child.kill();
    let _ = child.wait();
}

impl Drop for Browser {
    fn drop(&mut self) {
        stop_group(&mut self.driver);
    }
}
