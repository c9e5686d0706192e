//! The `fieldbal serve` binary: creates `fieldbal.db` in its working directory,
//! honours FIELDBAL_LISTEN, answers /healthz, stops with exit 0 on SIGTERM, and
//! the data are there when it starts again.

use crate::common;

use std::process::Child;

use common::{example, post, send};

/// Start the binary in `dir` and return it with the address it logged.
fn start(dir: &std::path::Path, args: &[&str], env: &[(&str, &str)]) -> (Child, String) {
    common::binary::start(Some(dir), args, env)
}

/// SIGTERM, then wait (bounded) for the exit status.
fn terminate(child: Child) -> std::process::ExitStatus {
    common::binary::terminate(child, 10)
}

#[tokio::test]
async fn serve_keeps_its_data_in_the_working_directory_and_stops_cleanly_on_sigterm() {
    let dir = tempfile::tempdir().unwrap();
    let client = reqwest::Client::new();
    let session = example("pump-two-plane-exact.json")["session"].clone();

    let (child, addr) = start(dir.path(), &["--listen", "127.0.0.1:0"], &[]);
    let (status, _, _) = send(client.get(format!("http://{addr}/healthz"))).await;
    assert_eq!(status, 200);
    let (status, _, created) =
        post(&client, &format!("http://{addr}/api/v1/sessions"), &session).await;
    assert_eq!(status, 201);
    assert!(terminate(child).success());
    assert!(dir.path().join("fieldbal.db").exists());

    let (child, addr) = start(dir.path(), &[], &[("FIELDBAL_LISTEN", "127.0.0.1:0")]);
    let url = format!(
        "http://{addr}/api/v1/sessions/{}",
        created["id"].as_str().unwrap()
    );
    let (status, _, back) = send(client.get(url)).await;
    assert_eq!(status, 200);
    assert_eq!(back["name"], session["name"]);
    assert!(terminate(child).success());
}

/// A `RUST_LOG` that is not a filter (a level misspelt after a module) is
/// said at start; it was dropped silently for `info`, so an operator asking
/// for debug logs got none and no reason.
#[test]
fn a_rust_log_that_does_not_parse_is_said_at_start() {
    use std::io::BufRead;
    let dir = tempfile::tempdir().unwrap();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["serve", "--listen", "127.0.0.1:0", "--database"])
        .arg(dir.path().join("t.db"))
        .env_remove("FIELDBAL_TOKENS")
        .env("RUST_LOG", "fieldbal=verbose")
        .env("NO_COLOR", "1")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut said = Vec::new();
    for line in std::io::BufReader::new(child.stderr.take().unwrap()).lines() {
        let line = line.unwrap();
        let done = line.contains("listening");
        said.push(line);
        if done {
            break;
        }
    }
    let _ = child.kill();
    let _ = child.wait();
    assert!(
        said.iter().any(|l| l.contains("RUST_LOG")
            && l.contains("fieldbal=verbose")
            && l.contains("info")),
        "{said:#?}"
    );
}

/// A `--listen` that is no address says what one looks like, and the start
/// stops before the database is opened (it created the database file first).
#[test]
fn a_listen_address_that_is_none_says_what_is_meant() {
    let dir = tempfile::tempdir().unwrap();
    let db = dir.path().join("t.db");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(["serve", "--listen", "stand-pc", "--database"])
        .arg(&db)
        .env_remove("FIELDBAL_TOKENS")
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    assert!(!out.status.success());
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(
        said.contains("--listen") && said.contains("stand-pc") && said.contains("127.0.0.1:8080"),
        "{said}"
    );
    assert!(!db.exists(), "the database was created: {said}");
}
