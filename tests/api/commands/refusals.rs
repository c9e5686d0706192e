//! The offline commands (`fieldbal solve`, `coefficients`, `identify
//! rotor`) refuse what the service refuses, with the same code, message and
//! field, exit status 2 (outside review, session 23).

use crate::common;
use crate::support::{error_of, machine_p1, pump};

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use common::{example, fresh_server, post};
use serde_json::{json, Value};

/// The error's code, field and message, owned (to compare the service's
/// answer with the command's).
fn owned_error(body: &Value) -> (String, Option<String>, String) {
    let (code, field, message) = error_of(body);
    (
        code.to_string(),
        field.map(str::to_string),
        message.to_string(),
    )
}

/// `fieldbal ARGS…` with `stdin` on its standard input: the exit code and
/// the JSON it printed.
fn fieldbal(args: &[&str], stdin: &[u8]) -> (i32, Value) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_fieldbal"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("fieldbal runs");
    child.stdin.take().unwrap().write_all(stdin).unwrap();
    let out = child.wait_with_output().unwrap();
    let value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "fieldbal {args:?} printed no JSON ({e}): {}",
            String::from_utf8_lossy(&out.stdout)
        )
    });
    (out.status.code().unwrap_or(-1), value)
}

fn write(dir: &Path, name: &str, value: &Value) -> String {
    let path = dir.join(name);
    std::fs::write(&path, serde_json::to_vec(value).unwrap()).unwrap();
    path.to_str().unwrap().to_string()
}

/// The error `fieldbal ARGS…` printed, its field with `prefix` taken off;
/// it must exit with 2.
fn cli_error(args: &[&str], stdin: &[u8], prefix: &str) -> (String, Option<String>, String) {
    let (code, out) = fieldbal(args, stdin);
    assert_eq!(code, 2, "fieldbal {args:?}: {out}");
    let (c, f, m) = owned_error(&out);
    let f = f.map(|f| {
        f.strip_prefix(prefix)
            .unwrap_or_else(|| panic!("fieldbal {args:?}: {f} is not under {prefix}"))
            .to_string()
    });
    (c, f, m)
}

/// A session's texts (`name`, a sensor's `label`) and the machine it names
/// are refused by `fieldbal solve` (a file, a wrapped file, standard
/// input), `fieldbal coefficients` and `fieldbal identify rotor` as the
/// service refuses them when the session is stored or posted: the same
/// code and message, the field where the file has it, exit status 2. The
/// commands solved a session with a NUL in its name, a bell in a label or
/// `machine: ""`, which the service refuses.
#[tokio::test]
async fn the_commands_refuse_a_sessions_texts_and_machine_as_the_service_does() {
    let (_dir, server, client) = fresh_server().await;
    let files = tempfile::tempdir().unwrap();
    type Edit = fn(&mut Value);
    let cases: [(&str, Edit); 6] = [
        ("name", |s| s["name"] = json!("pump\u{0}3")),
        ("sensors[2].label", |s| {
            s["sensors"][2]["label"] = json!("NDE \u{7}")
        }),
        ("machine", |s| s["machine"] = json!("")),
        ("machine", |s| s["machine"] = json!("   ")),
        ("machine", |s| s["machine"] = json!("P-1\u{1b}[31m")),
        ("machine", |s| s["machine"] = json!("m".repeat(65))),
    ];
    for (field, edit) in cases {
        let mut s = pump();
        edit(&mut s);
        let (status, _, stored) = post(&client, &server.url("/api/v1/sessions"), &s).await;
        assert_eq!(status, 422, "store {field}: {stored}");
        let want = owned_error(&stored);
        assert_eq!(want.1.as_deref(), Some(field), "{stored}");
        let posted = json!({ "session": s });
        for endpoint in ["/api/v1/solve", "/api/v1/identify/rotor"] {
            let (status, _, body) = post(&client, &server.url(endpoint), &posted).await;
            assert_eq!(status, 422, "{endpoint}: {body}");
            let (c, f, m) = owned_error(&body);
            let f = f.and_then(|f| f.strip_prefix("session.").map(str::to_string));
            assert_eq!((c, f, m), want, "{endpoint} {field}: {body}");
        }
        let bare = write(files.path(), "bare.json", &s);
        let wrapped = write(files.path(), "wrapped.json", &posted);
        let stdin = serde_json::to_vec(&s).unwrap();
        let runs: [(&[&str], &[u8], &str); 5] = [
            (&["solve", &bare], b"", ""),
            (&["solve", &wrapped], b"", "session."),
            (&["solve", "-"], &stdin, ""),
            (&["coefficients", &bare], b"", "sessions[0]."),
            (&["identify", "rotor", &wrapped], b"", "session."),
        ];
        for (args, input, prefix) in runs {
            assert_eq!(cli_error(args, input, prefix), want, "{args:?} {field}");
        }
    }
    // Tabs and line breaks stay allowed in texts offline too.
    let mut s = pump();
    s["name"] = json!("pump 3\r\n\tcoupling end");
    s["sensors"][1]["label"] = json!("DE\tvertical\n(new probe)");
    let (code, out) = fieldbal(&["solve", &write(files.path(), "ok.json", &s)], b"");
    assert_eq!(code, 0, "{out}");
}

/// `coefficients_from` beside `influence_coefficients`, with a version
/// below 1 or a machine id the id rule refuses, is refused by `fieldbal
/// solve` as `/api/v1/solve` refuses it (before any machine is looked up):
/// it solved with the supplied coefficients and echoed the
/// `coefficients_from` it had not read, or said the coefficients are read by
/// the service where the service refused the id (which it looked up).
#[tokio::test]
async fn the_solve_command_refuses_coefficients_from_as_the_service_does() {
    let (_dir, server, client) = fresh_server().await;
    let files = tempfile::tempdir().unwrap();
    let (_, supplied) = fieldbal(
        &[
            "coefficients",
            &write(
                files.path(),
                "pump.json",
                &example("pump-two-plane-exact.json"),
            ),
        ],
        b"",
    );
    let coefficients = supplied["influence_coefficients"].clone();
    assert!(
        coefficients.as_array().is_some_and(|c| !c.is_empty()),
        "{supplied}"
    );
    let cases = [
        json!({"coefficients_from": {"machine": "P-1"}, "influence_coefficients": coefficients}),
        json!({"coefficients_from": {"machine": "P-1", "version": 0}}),
        json!({"coefficients_from": {"machine": "P-1", "version": -3}}),
        // A machine id the id rule refuses, as a trim job's is refused.
        json!({"coefficients_from": {"machine": ""}}),
        json!({"coefficients_from": {"machine": "P-1\u{0}"}}),
        json!({"coefficients_from": {"machine": "m".repeat(65)}}),
    ];
    for options in cases {
        let body = json!({ "session": pump(), "options": options });
        let (status, _, answer) = post(&client, &server.url("/api/v1/solve"), &body).await;
        assert_eq!(status, 422, "{answer}");
        let want = owned_error(&answer);
        assert_ne!(
            want.0, "unknown_machine",
            "the id is refused, not looked up: {answer}"
        );
        let wrapped = write(files.path(), "wrapped.json", &body);
        assert_eq!(cli_error(&["solve", &wrapped], b"", ""), want, "{options}");
        let bare = write(files.path(), "bare.json", &pump());
        let opts = write(files.path(), "options.json", &options);
        assert_eq!(
            cli_error(&["solve", &bare, "--options", &opts], b"", ""),
            want,
            "--options {options}"
        );
    }
}

/// `fieldbal coefficients` takes the service's pool list rule: a file
/// named twice (its runs counted twice) and more than 1000 files are
/// refused as the service refuses the same list of session ids, before a
/// file is read. It pooled a file named twice, and read any number.
#[tokio::test]
async fn the_coefficients_command_takes_the_services_rule_of_a_pool_list() {
    let (_dir, server, client) = fresh_server().await;
    machine_p1(&client, &server).await;
    let pool = server.url("/api/v1/machines/P-1/coefficients");
    let files = tempfile::tempdir().unwrap();
    let one = write(
        files.path(),
        "pump.json",
        &example("pump-two-plane-exact.json"),
    );

    let (status, _, twice) = post(&client, &pool, &json!({"sessions": ["a", "b", "a"]})).await;
    assert_eq!(status, 422, "{twice}");
    let (code, field, _) = owned_error(&twice);
    let (c, f, m) = cli_error(&["coefficients", &one, "x.json", &one], b"", "");
    assert_eq!((c, f), (code, field), "{m}");
    assert!(m.contains(&one), "{m}");

    let ids: Vec<String> = (0..1001).map(|i| format!("s{i}.json")).collect();
    let (status, _, many) = post(&client, &pool, &json!({ "sessions": ids })).await;
    assert_eq!(status, 422, "{many}");
    let mut args = vec!["coefficients"];
    args.extend(ids.iter().map(String::as_str));
    // None of the files exists: the list is refused before one is read.
    assert_eq!(cli_error(&args, b"", ""), owned_error(&many));
}

/// `fieldbal coefficients` pools one machine's sessions, as the service
/// does: files that name two machines are refused naming the second's
/// `machine` (they were pooled into one set of coefficients). Files that
/// name none pool with those that name one.
#[test]
fn the_coefficients_command_pools_one_machines_sessions() {
    let files = tempfile::tempdir().unwrap();
    let named = |name: &str, machine: Option<&str>| {
        let mut s = pump();
        if let Some(m) = machine {
            s["machine"] = json!(m);
        }
        write(files.path(), name, &s)
    };
    let (a, b, c) = (
        named("a.json", Some("P-1")),
        named("b.json", Some("P-2")),
        named("c.json", None),
    );
    let (code, field, message) = cli_error(&["coefficients", &c, &a, &b], b"", "");
    assert_eq!(
        (code.as_str(), field.as_deref()),
        ("other_machine", Some("sessions[2].machine")),
        "{message}"
    );
    assert!(
        message.contains("P-1") && message.contains("P-2"),
        "{message}"
    );
    let (status, pooled) = fieldbal(&["coefficients", &c, &a], b"");
    assert_eq!(status, 0, "{pooled}");
    assert!(pooled["influence_coefficients"].is_array(), "{pooled}");
}
