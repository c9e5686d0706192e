//! Issue 15: the restructured solve (thin SVD through QR, the propagation's
//! merged products, one validation per solve, the min-max path) gives the
//! answers of the code before it. The 40 random jobs in
//! `tests/data/perf/jobs/` (least squares plain, with row weights, with
//! repeated samples, and min-max; 2 to 8 planes, 3 to 36 rows) were solved
//! by the release `fieldbal solve` of commit feeb62d into
//! `tests/data/perf/expected/` (see `tests/data/perf/make_jobs.py`); every
//! number of every solution — corrections, their uncertainty, residuals and
//! their 95 % bounds, coefficients, diagnostics — must agree to the solver's
//! tolerance, and every warning code must be the same.

use std::path::{Path, PathBuf};

use fieldbal::balancing::{self, parse_session_file};
use serde_json::Value;

/// Least squares: the same SVD answer up to rounding in a different order
/// (QR then a small SVD), amplified by the condition number of these jobs
/// (below 10²) and by the 95 % bound's Newton stop (2·10⁻⁴ in probability):
/// 10⁻⁷ of the value, or of 1 unit (µm, g, degree) for smaller ones.
const LS_TOL: f64 = 1e-7;
/// Min-max: the interior-point optimum is known to the solver's tolerance
/// (about 10⁻⁸ of the objective); where fewer than `2n + 1` rows are active
/// the objective is flat to second order, so the correction is known to
/// about √10⁻⁸ = 10⁻⁴ of its size (as in tests/minmax_equivalence.rs).
const MINMAX_TOL: f64 = 1e-3;

fn jobs() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/perf/jobs");
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .expect("tests/data/perf/jobs")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
}

/// Walk both answers; every difference found is pushed onto `diffs`.
fn compare(path: &str, new: &Value, old: &Value, tol: f64, diffs: &mut Vec<String>) {
    match (new, old) {
        (Value::Number(a), Value::Number(b)) => {
            let (a, b) = (a.as_f64().unwrap(), b.as_f64().unwrap());
            let mut d = (a - b).abs();
            if path.contains("deg") {
                // An angle may come out as 359.99… on one side and 0.00… on the other.
                d = d.min((d - 360.0).abs());
            }
            if d > tol * (a.abs().max(b.abs()) + 1.0) {
                diffs.push(format!("{path}: {a} vs {b}"));
            }
        }
        (Value::Array(a), Value::Array(b)) => {
            if a.len() != b.len() {
                diffs.push(format!("{path}: {} vs {} entries", a.len(), b.len()));
                return;
            }
            for (i, (x, y)) in a.iter().zip(b).enumerate() {
                compare(&format!("{path}[{i}]"), x, y, tol, diffs);
            }
        }
        (Value::Object(a), Value::Object(b)) => {
            let keys = |o: &serde_json::Map<String, Value>| o.keys().cloned().collect::<Vec<_>>();
            if keys(a) != keys(b) {
                diffs.push(format!("{path}: fields {:?} vs {:?}", keys(a), keys(b)));
                return;
            }
            // A residual of zero (as many rows as planes) has no phase: 1e-14
            // of rounding points anywhere.
            let amplitude = |o: &serde_json::Map<String, Value>, k: &str| {
                o.get(k).and_then(Value::as_f64).unwrap_or(f64::INFINITY)
            };
            let no_phase = amplitude(b, "amplitude")
                <= 1e-9 * amplitude(b, "amplitude_before").clamp(1.0, 1e12);
            for (k, x) in a {
                // Messages quote rounded figures; their codes and planes are compared.
                if k != "message" && !(k == "phase_deg" && no_phase) {
                    compare(&format!("{path}.{k}"), x, &b[k], tol, diffs);
                }
            }
        }
        _ if new == old => {}
        _ => diffs.push(format!("{path}: {new} vs {old}")),
    }
}

#[test]
fn every_random_job_gets_the_answer_the_code_before_issue_15_gave() {
    let files = jobs();
    assert_eq!(files.len(), 40, "the job files of make_jobs.py");
    let mut min_max = 0;
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        let bytes = std::fs::read(file).unwrap();
        let (session, options) = parse_session_file(&bytes).unwrap();
        let solution = balancing::solve(&session, &options)
            .unwrap_or_else(|e| panic!("{name}: {}", e.message));
        let new = serde_json::to_value(solution).unwrap();
        let expected = file
            .parent()
            .unwrap()
            .parent()
            .unwrap()
            .join("expected")
            .join(&name);
        let old: Value = serde_json::from_slice(&std::fs::read(expected).unwrap()).unwrap();
        let tol = if name.contains("min_max") {
            min_max += 1;
            MINMAX_TOL
        } else {
            LS_TOL
        };
        let mut diffs = Vec::new();
        compare("", &new, &old, tol, &mut diffs);
        assert!(
            diffs.is_empty(),
            "{name}: {} differences, first {:?}",
            diffs.len(),
            &diffs[..diffs.len().min(5)]
        );
    }
    assert_eq!(min_max, 10, "min-max jobs compared");
}
