//! The textbook's worked estimation checks (examples/textbook-regression.json,
//! method §6) reproduced by the library and by `fieldbal solve`.

use std::path::PathBuf;

use crate::common::binary;
use fieldbal::identification::textbook::{estimate_case, Case};
use serde_json::Value;

fn file() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/examples/textbook-regression.json")
}

/// The published estimate's two values, in the file's order (c first, then damping).
fn published(case: &Value) -> (f64, f64) {
    let p = case["published_estimate"].as_object().unwrap();
    let damping = p.iter().find(|(k, _)| k.as_str() != "c").unwrap().1;
    (p["c"].as_f64().unwrap(), damping.as_f64().unwrap())
}

/// Published values are given to four or five significant digits.
fn agrees(got: f64, published: f64) -> bool {
    (got - published).abs() <= 5e-5 * published.abs()
}

#[test]
fn the_library_reproduces_every_published_estimate() {
    let value: Value = serde_json::from_slice(&std::fs::read(file()).unwrap()).unwrap();
    let cases = value["cases"].as_array().unwrap();
    assert_eq!(cases.len(), 2);
    for case in cases {
        let parsed: Case = serde_json::from_value(case.clone()).unwrap();
        let est = estimate_case(&parsed).unwrap();
        let (c, d) = published(case);
        assert!(agrees(est.c, c), "{}: c = {} vs {c}", parsed.name, est.c);
        assert!(
            agrees(est.b, d),
            "{}: damping = {} vs {d}",
            parsed.name,
            est.b
        );
    }
}

#[test]
fn the_command_line_reproduces_every_published_estimate() {
    let (ok, got) = binary::solve(&[file()]);
    assert!(ok, "{got}");
    let want: Value = serde_json::from_slice(&std::fs::read(file()).unwrap()).unwrap();
    for (g, w) in got["cases"]
        .as_array()
        .unwrap()
        .iter()
        .zip(want["cases"].as_array().unwrap())
    {
        let (c, d) = published(w);
        assert!(agrees(g["estimate"]["c"].as_f64().unwrap(), c), "{g}");
        assert!(agrees(g["estimate"]["b"].as_f64().unwrap(), d), "{g}");
    }
}
