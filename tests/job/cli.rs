//! The CLI carries the job too: `fieldbal solve --options` with `from_run`,
//! and `fieldbal coefficients SESSION...` pooling session files.

use crate::support;

use std::process::Command;

use fieldbal::balancing::model::Conventions;
use serde_json::{json, Value};
use support::*;

fn trials(seed: u64) -> Value {
    let (rotor, conv) = (Rotor::new(), Conventions::default());
    let mut n = Noise::new(1.0, 1.0, seed);
    session(conv, first_runs(&rotor, conv, &mut n, &NO_RUNOUT, 0.0))
}

fn fieldbal(args: &[&str]) -> (i32, Value) {
    let out = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(args)
        .output()
        .expect("runs");
    let v = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    (out.status.code().unwrap_or(-1), v)
}

#[test]
fn coefficients_pools_session_files_and_solve_takes_the_new_options() {
    let dir = tempfile::tempdir().unwrap();
    let path = |n: &str| dir.path().join(n).to_str().unwrap().to_string();
    std::fs::write(path("a.json"), trials(1).to_string()).unwrap();
    std::fs::write(path("b.json"), json!({"session": trials(2)}).to_string()).unwrap();
    let (code, pooled) = fieldbal(&["coefficients", &path("a.json"), &path("b.json")]);
    assert_eq!(code, 0, "{pooled}");
    assert_eq!(pooled["sessions"], json!([path("a.json"), path("b.json")]));
    assert_eq!(
        pooled["influence_coefficients"].as_array().unwrap().len(),
        8
    );

    // Those coefficients solve a file with only its reference run, and from_run is accepted.
    let mut only_ref = trials(3);
    only_ref["runs"].as_array_mut().unwrap().truncate(1);
    std::fs::write(path("c.json"), only_ref.to_string()).unwrap();
    let options =
        json!({"influence_coefficients": pooled["influence_coefficients"], "from_run": "zero"});
    std::fs::write(path("o.json"), options.to_string()).unwrap();
    let (code, sol) = fieldbal(&["solve", &path("c.json"), "--options", &path("o.json")]);
    assert_eq!(code, 0, "{sol}");
    assert_eq!(sol["from_run"], "zero");
    assert_eq!(sol["corrections"].as_array().unwrap().len(), 2);

    std::fs::write(path("bad.json"), json!({"exclude": true}).to_string()).unwrap();
    let (code, err) = fieldbal(&[
        "coefficients",
        &path("a.json"),
        "--options",
        &path("bad.json"),
    ]);
    assert_eq!(code, 2);
    assert_eq!(err["error"]["field"], "options.exclude");
}

/// Standard input is read once: a command given `-` for its file and for
/// `--options` is refused saying so, naming `options`, before anything is
/// read (the options then read an empty input and were refused as "EOF while
/// parsing", which said nothing of the cause).
#[test]
fn standard_input_given_twice_is_refused_saying_it_is_read_once() {
    use std::io::Write;
    let session = serde_json::to_vec(&json!({"session": trials(7)})).unwrap();
    for args in [
        &["solve", "-", "--options", "-"][..],
        &["coefficients", "-", "--options", "-"],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
            .args(args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        // The command may refuse before it reads: a closed pipe is no fault here.
        let _ = child.stdin.take().unwrap().write_all(&session);
        let out = child.wait_with_output().unwrap();
        let v: Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
        assert_eq!(out.status.code(), Some(2), "{args:?}: {v}");
        assert_eq!(v["error"]["field"], "options", "{args:?}: {v}");
        let message = v["error"]["message"].as_str().unwrap();
        assert!(message.contains("standard input"), "{args:?}: {message}");
    }
}

/// One file named twice in other words (`a.json`, `./a.json`, a link to it)
/// is refused as the same name twice is: its runs were pooled twice, halving
/// the coefficients' stated variance.
#[test]
fn coefficients_refuses_one_file_named_twice_in_other_words() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a.json");
    std::fs::write(
        &file,
        serde_json::to_vec(&json!({"session": trials(11)})).unwrap(),
    )
    .unwrap();
    let link = dir.path().join("b.json");
    std::os::unix::fs::symlink(&file, &link).unwrap();
    let other = dir.path().join("c.json");
    std::fs::write(
        &other,
        serde_json::to_vec(&json!({"session": trials(12)})).unwrap(),
    )
    .unwrap();
    let spelled = format!("{}/./a.json", dir.path().display());
    for second in [spelled.as_str(), link.to_str().unwrap()] {
        let (code, v) = fieldbal(&["coefficients", file.to_str().unwrap(), second]);
        assert_eq!(code, 2, "{second}: {v}");
        assert_eq!(v["error"]["code"], "duplicate_id", "{v}");
        assert_eq!(v["error"]["field"], "sessions[1]", "{v}");
    }
    let (code, v) = fieldbal(&[
        "coefficients",
        file.to_str().unwrap(),
        other.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{v}");
}
