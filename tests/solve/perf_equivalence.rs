//! Issue 15: the restructured solve (thin SVD through QR, the active-set
//! min-max whose working sets a primal-dual interior-point method solves,
//! `conic/primal_dual.rs`) gives the corrections of the code before it, on
//! many seeded random jobs generated here; least squares under a binding
//! bound to the old interior point's accuracy, no worse in its objective
//! (session 20 polishes that answer to rounding).
//!
//! The old answers in `tests/data/perf/old_answers.json` were computed by the
//! release `fieldbal solve` of commit 5e3a66a (the parent of the first issue
//! 15 commit) from the job files this test writes
//! (`tests/data/perf/record_old_answers.sh`). Only corrections and the
//! min-max objective are compared, on jobs where issue 12's changes do not
//! apply: no stated noise and no repeated samples, so no errors-in-variables
//! bias is removed and least squares is the plain `−A⁺b` in both; the
//! uncertainty fields issue 12 recalibrated are left out.

use fieldbal::balancing::{self, parse_session_file};
use serde_json::{json, Value};

/// Least squares: the same SVD answer up to rounding in a different order
/// (QR then a small SVD), amplified by the condition number of these jobs
/// (below 10²): 10⁻⁹ of the largest correction.
const LS_TOL: f64 = 1e-9;
/// Min-max: the optimum value is known to the solvers' tolerance (10⁻⁸ of
/// max |b|, compared to 10⁻⁷ of itself or of 1 µm where the fit is exact);
/// where fewer than `2n + 1` rows are active the objective is flat to second
/// order, so the correction is known to about √10⁻⁸ = 10⁻⁴ of its
/// size (as in minmax/equivalence.rs).
const MINMAX_VALUE_TOL: f64 = 1e-7;
const MINMAX_TOL: f64 = 1e-4;
/// Least squares under a binding bound: the old answer is the interior
/// point's, fixed only to ~10⁻⁵ of the correction; since session 20 the
/// answer is polished to rounding on its active set (`conic/polish.rs`), so
/// it may move by that much, and its sum of squares must be no higher
/// than the old one's (to 10⁻¹²: measured 3·10⁻¹¹ to 2·10⁻⁹ lower).
const BOUNDED_LS_TOL: f64 = 1e-4;

/// A deterministic pseudo-random number in [0, 1) (xorshift), stable across
/// crate versions, so the jobs written for the old binary are the jobs here.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// A complex number of modulus `scale·(0.2..1.2)` and uniform angle.
    fn phasor(&mut self, scale: f64) -> (f64, f64) {
        let (m, a) = (
            scale * (0.2 + self.next()),
            std::f64::consts::TAU * self.next(),
        );
        (m * a.cos(), m * a.sin())
    }
}

fn mul(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}

fn add(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0 + b.0, a.1 + b.1)
}

/// Amplitude and phase of `z` in the lead convention, rounded as an
/// instrument would print them.
fn polar(z: (f64, f64)) -> (f64, f64) {
    let amp = (z.0.hypot(z.1) * 1e6).round() / 1e6;
    let deg = (z.1.atan2(z.0).to_degrees().rem_euclid(360.0) * 1e4).round() / 1e4;
    (amp, deg)
}

/// A noisy stand session: `planes` one-trial runs, `sensors × speeds` rows,
/// the true correction `−u`; returns it with `|u_j|`.
fn session(rng: &mut Rng, planes: usize, sensors: usize, speeds: usize) -> (Value, Vec<f64>) {
    let rows = sensors * speeds;
    let w: Vec<Vec<(f64, f64)>> = (0..rows)
        .map(|_| (0..planes).map(|_| rng.phasor(2.0)).collect())
        .collect();
    let u: Vec<(f64, f64)> = (0..planes).map(|_| rng.phasor(30.0)).collect();
    let y0: Vec<(f64, f64)> = (0..rows)
        .map(|a| {
            let wu = (0..planes).fold((0.0, 0.0), |s, j| add(s, mul(w[a][j], u[j])));
            add(wu, rng.phasor(1.0))
        })
        .collect();
    let readings = |y: &[(f64, f64)], rng: &mut Rng| -> Vec<Value> {
        (0..rows)
            .map(|a| {
                let (amplitude, phase_deg) = polar(add(y[a], rng.phasor(0.5)));
                json!({"speed_rpm": 500.0 + 250.0 * (a / sensors) as f64,
                       "sensor": format!("S{}", a % sensors),
                       "amplitude": amplitude, "phase_deg": phase_deg})
            })
            .collect()
    };
    let mut runs = vec![json!({"id": "zero", "weights": [], "readings": readings(&y0, rng)})];
    for j in 0..planes {
        let t = rng.phasor(40.0);
        let y: Vec<(f64, f64)> = y0
            .iter()
            .zip(&w)
            .map(|(&y, row)| add(y, mul(row[j], t)))
            .collect();
        let (mass_g, angle_deg) = polar(t);
        runs.push(json!({"id": format!("trial {j}"),
            "weights": [{"plane": format!("P{j}"), "mass_g": mass_g, "angle_deg": angle_deg}],
            "readings": readings(&y, rng)}));
    }
    let s = json!({
        "name": format!("perf {planes}x{sensors}x{speeds}"),
        "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
        "planes": (0..planes).map(|j| json!({"id": format!("P{j}"), "radius_mm": 150})).collect::<Vec<_>>(),
        "sensors": (0..sensors).map(|k| json!({"id": format!("S{k}"), "unit": "um_pp"})).collect::<Vec<_>>(),
        "runs": runs,
    });
    (s, u.iter().map(|z| z.0.hypot(z.1)).collect())
}

/// The kinds of job: options without stated noise (module doc).
const KINDS: [&str; 5] = ["plain", "weighted", "bounded", "min_max", "bounded_min_max"];
/// (planes, sensors, speeds): square, barely over-determined, and many rows
/// per plane, where the min-max working set is a small part of the rows.
const SHAPES: [(usize, usize, usize); 12] = [
    (2, 2, 1),
    (2, 4, 1),
    (3, 4, 2),
    (4, 4, 1),
    (4, 11, 1),
    (4, 12, 3),
    (5, 8, 2),
    (6, 16, 3),
    (3, 40, 2),
    (8, 20, 4),
    (2, 60, 5),
    (12, 24, 6),
];

/// Every job as `(name, {"session", "options"})`, the same on every run.
fn jobs() -> Vec<(String, Value)> {
    let mut rng = Rng(0x15_2026_1122);
    let mut out = Vec::new();
    for kind in KINDS {
        for (planes, sensors, speeds) in SHAPES {
            let (s, u) = session(&mut rng, planes, sensors, speeds);
            let mut o = serde_json::Map::new();
            if kind == "weighted" {
                let w: Vec<Value> = (0..sensors)
                    .step_by(2)
                    .map(|k| json!({"sensor": format!("S{k}"), "weight": 0.5 + (rng.next() * 1e3).round() / 1e3}))
                    .collect();
                o.insert("row_weights".into(), json!(w));
            }
            if kind.contains("min_max") {
                o.insert("objective".into(), json!("min_max"));
            }
            if kind.starts_with("bounded") {
                // 60 % of every other plane's true unbalance: these bind.
                let bounds: serde_json::Map<String, Value> = (0..planes)
                    .step_by(2)
                    .map(|j| (format!("P{j}"), json!((600.0 * u[j]).round() / 1e3)))
                    .collect();
                o.insert("max_mass_g".into(), Value::Object(bounds));
            }
            let name = format!("{:02}-{kind}-{planes}x{sensors}x{speeds}", out.len());
            out.push((name, json!({"session": s, "options": o})));
        }
    }
    out
}

/// Corrections as phasors `(m cos θ, m sin θ)` and the largest predicted
/// residual amplitude, from a solution's JSON.
fn answer(solution: &Value) -> (Vec<(f64, f64)>, f64) {
    let c = solution["corrections"].as_array().expect("corrections");
    let phasors = c
        .iter()
        .map(|x| {
            let (m, a) = (
                x["mass_g"].as_f64().unwrap(),
                x["angle_deg"].as_f64().unwrap(),
            );
            (m * a.to_radians().cos(), m * a.to_radians().sin())
        })
        .collect();
    let worst = solution["predicted_residual"]
        .as_array()
        .expect("predicted_residual")
        .iter()
        .map(|r| r["amplitude"].as_f64().unwrap())
        .fold(0.0, f64::max);
    (phasors, worst)
}

fn old_answers() -> serde_json::Map<String, Value> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/perf/old_answers.json"
    );
    let v: Value = serde_json::from_slice(&std::fs::read(path).expect(path)).unwrap();
    v["jobs"].as_object().expect("jobs").clone()
}

#[test]
fn every_random_job_gets_the_corrections_the_code_before_issue_15_gave() {
    let old = old_answers();
    let jobs = jobs();
    assert_eq!(old.len(), jobs.len(), "one stored answer per job");
    let mut failures = Vec::new();
    let (mut worst_ls, mut worst_mm) = (0.0f64, 0.0f64);
    for (name, job) in &jobs {
        let bytes = serde_json::to_vec(job).unwrap();
        let (session, options) = parse_session_file(&bytes).unwrap();
        let solution = balancing::solve(&session, &options)
            .unwrap_or_else(|e| panic!("{name}: {}", e.message));
        let new_json = serde_json::to_value(solution).unwrap();
        let (new_c, new_worst) = answer(&new_json);
        let stored = old
            .get(name)
            .unwrap_or_else(|| panic!("{name}: no stored answer"));
        let (old_c, old_worst) = answer(stored);
        assert_eq!(new_c.len(), old_c.len(), "{name}: planes");
        let size = old_c.iter().map(|z| z.0.hypot(z.1)).fold(0.0, f64::max);
        let min_max = name.contains("min_max");
        let bounded_ls = !min_max && name.contains("bounded");
        let tol = if min_max {
            MINMAX_TOL
        } else if bounded_ls {
            BOUNDED_LS_TOL
        } else {
            LS_TOL
        };
        let squares = |v: &Value| -> f64 {
            let rows = v["predicted_residual"]
                .as_array()
                .expect("predicted_residual");
            rows.iter()
                .map(|r| r["amplitude"].as_f64().unwrap().powi(2))
                .sum()
        };
        if bounded_ls && squares(&new_json) > squares(stored) * (1.0 + 1e-12) {
            failures.push(format!(
                "{name}: sum of squares {} above the old {}",
                squares(&new_json),
                squares(stored)
            ));
        }
        let moved = new_c
            .iter()
            .zip(&old_c)
            .map(|(a, b)| (a.0 - b.0).hypot(a.1 - b.1))
            .fold(0.0, f64::max);
        let worst = if min_max {
            &mut worst_mm
        } else {
            &mut worst_ls
        };
        *worst = worst.max(moved / size);
        if moved > tol * size {
            failures.push(format!(
                "{name}: a correction moved by {moved:.3e} g of {size:.3} g"
            ));
        }
        // The min-max objective itself, to the solvers' tolerance.
        if min_max && (new_worst - old_worst).abs() > MINMAX_VALUE_TOL * old_worst.max(1.0) {
            failures.push(format!(
                "{name}: largest residual {new_worst} vs {old_worst}"
            ));
        }
    }
    eprintln!("largest relative move: least squares {worst_ls:.1e}, min-max {worst_mm:.1e}");
    assert!(
        failures.is_empty(),
        "{} of {} jobs differ: {failures:#?}",
        failures.len(),
        jobs.len()
    );
}

#[test]
fn the_stored_answers_are_of_these_jobs_and_bounds_bind_where_set() {
    // A changed generator would compare new answers with other jobs' old ones.
    let old = old_answers();
    for (name, job) in jobs() {
        let stored = &old[&name];
        assert_eq!(stored["name"], job["session"]["name"], "{name}");
        let planes = job["session"]["planes"].as_array().unwrap().len();
        assert_eq!(
            stored["corrections"].as_array().unwrap().len(),
            planes,
            "{name}"
        );
        // The bounded jobs test the bounded programs only if a bound binds.
        if name.contains("bounded") {
            let warned = stored["warnings"].as_array().unwrap();
            assert!(
                warned.iter().any(|w| w == "mass_limit_active"),
                "{name}: no bound binds"
            );
        }
    }
}

/// Writes every job to `$FIELDBAL_PERF_JOBS_DIR/<name>.json` for the old
/// binary (record_old_answers.sh), or to a temporary directory, and checks
/// each file parses back to the session solved above.
#[test]
fn the_jobs_written_for_the_old_binary_parse_back_to_the_same_sessions() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = std::env::var_os("FIELDBAL_PERF_JOBS_DIR")
        .map(std::path::PathBuf::from)
        .unwrap_or_else(|| tmp.path().to_path_buf());
    for (name, job) in jobs() {
        let path = dir.join(format!("{name}.json"));
        std::fs::write(&path, serde_json::to_vec(&job).unwrap()).unwrap();
        let back = parse_session_file(&std::fs::read(&path).unwrap()).unwrap();
        let here = parse_session_file(&serde_json::to_vec(&job).unwrap()).unwrap();
        assert_eq!(back, here, "{name}");
    }
}
