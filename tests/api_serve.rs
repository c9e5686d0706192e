//! The `fieldbal serve` binary: creates `fieldbal.db` in its working directory,
//! honours FIELDBAL_LISTEN, answers /healthz, stops with exit 0 on SIGTERM, and
//! the data are there when it starts again.

mod common;

use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Stdio};
use std::time::Duration;

use common::{example, post, send};

/// Start the binary in `dir` and return it with the address it logged.
fn start(dir: &std::path::Path, args: &[&str], env: &[(&str, &str)]) -> (Child, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .arg("serve")
        .args(args)
        .envs(env.iter().copied())
        .env_remove("DATABASE_URL")
        .env("NO_COLOR", "1")
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("fieldbal starts");
    let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
    let addr = loop {
        let line = lines
            .next()
            .expect("the server logs its address before exiting")
            .unwrap();
        if let Some(rest) = line.split("addr=").nth(1) {
            break rest.split_whitespace().next().unwrap().to_string();
        }
    };
    // Keep draining the log so the server never blocks on a full pipe.
    std::thread::spawn(move || lines.for_each(drop));
    (child, addr)
}

/// SIGTERM, then wait (bounded) for the exit status.
fn terminate(mut child: Child) -> std::process::ExitStatus {
    let status = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(status.success());
    for _ in 0..100 {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    child.kill().unwrap();
    panic!("fieldbal did not stop within 10 s of SIGTERM");
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
