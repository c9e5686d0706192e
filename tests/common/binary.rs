//! The real `fieldbal serve` binary in a test: start it, read the address it
//! logs, stop it with SIGTERM (bounded) or SIGKILL. The one starter that the
//! serve, edge, hardening and replica tests share. And `fieldbal solve` run
//! once for its JSON ([`solve`]).

use std::ffi::OsStr;
use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

/// `fieldbal solve ARGS…`: whether it exited with success, and the JSON it
/// printed (a panic showing the output when that is not JSON).
pub fn solve<S: AsRef<OsStr>>(args: &[S]) -> (bool, serde_json::Value) {
    let out = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .arg("solve")
        .args(args)
        .output()
        .expect("fieldbal solve runs");
    let value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "fieldbal solve printed no JSON ({e}): {}",
            String::from_utf8_lossy(&out.stdout)
        )
    });
    (out.status.success(), value)
}

/// Start `fieldbal serve ARGS…` (in `dir` if given, with `env` added and no
/// inherited DATABASE_URL or FIELDBAL_TOKENS); returns it and the address it logged.
pub fn start(dir: Option<&Path>, args: &[&str], env: &[(&str, &str)]) -> (Child, String) {
    let mut command = Command::new(env!("CARGO_BIN_EXE_fieldbal"));
    command
        .arg("serve")
        .args(args)
        .env_remove("DATABASE_URL")
        .env_remove("FIELDBAL_TOKENS")
        .envs(env.iter().copied())
        .env("NO_COLOR", "1")
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    if let Some(dir) = dir {
        command.current_dir(dir);
    }
    let mut child = command.spawn().expect("fieldbal starts");
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

/// SIGTERM, then wait (bounded: `seconds`) for the exit status.
pub fn terminate(mut child: Child, seconds: u64) -> std::process::ExitStatus {
    let sent = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
    for _ in 0..seconds * 10 {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    child.kill().unwrap();
    panic!("fieldbal did not stop within {seconds} s of SIGTERM");
}
