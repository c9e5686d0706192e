//! Helpers of sessions.rs: the public examples, synthesised
//! rotors, and options built from JSON.

use fieldbal::balancing::model::{Session, SolveOptions};
use fieldbal::balancing::{self, Solution};
use num_complex::Complex64;
use rand::{rngs::StdRng, Rng, SeedableRng};
use serde_json::{json, Value};

pub fn example(name: &str) -> (Session, SolveOptions) {
    let path = format!("{}/tests/data/examples/{name}", env!("CARGO_MANIFEST_DIR"));
    balancing::parse_session_file(&std::fs::read(path).unwrap()).unwrap()
}

pub const BALANCING_EXAMPLES: [&str; 5] = [
    "compressor-multispeed-exact.json",
    "compressor-multispeed-noisy.json",
    "pump-single-plane-noisy.json",
    "pump-two-plane-exact.json",
    "pump-two-plane-kept-trial-exact.json",
];

/// A rotor with `sensors` sensors at `speeds` speeds and `planes` planes whose
/// readings follow (2.1) plus noise, in lead/with-rotation conventions so that a
/// reading's phase is the argument of its phasor.
pub fn rotor(seed: u64, sensors: usize, speeds: usize, planes: usize, noise: f64) -> Session {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut c = |s: f64| {
        Complex64::from_polar(
            s * rng.gen_range(0.2..1.0),
            rng.gen_range(0.0..std::f64::consts::TAU),
        )
    };
    let rows = sensors * speeds;
    let w: Vec<Vec<Complex64>> = (0..rows)
        .map(|_| (0..planes).map(|_| c(1.5)).collect())
        .collect();
    let y0: Vec<Complex64> = (0..rows).map(|_| c(80.0)).collect();
    let noise: Vec<Vec<Complex64>> = (0..=planes)
        .map(|_| (0..rows).map(|_| c(noise)).collect())
        .collect();
    let reading = |a: usize, y: Complex64| {
        json!({"speed_rpm": 1000.0 * (1 + a / sensors) as f64, "sensor": format!("S{}", a % sensors),
               "amplitude": y.norm(), "phase_deg": y.arg().to_degrees()})
    };
    let mut runs = vec![json!({"id": "zero", "weights": [],
        "readings": (0..rows).map(|a| reading(a, y0[a] + noise[0][a])).collect::<Vec<_>>()})];
    for j in 0..planes {
        runs.push(json!({"id": format!("trial {j}"),
            "weights": [{"plane": format!("P{j}"), "mass_g": 40.0, "angle_deg": 0.0}],
            "readings": (0..rows).map(|a| reading(a, y0[a] + w[a][j] * 40.0 + noise[j + 1][a])).collect::<Vec<_>>()}));
    }
    let session = json!({"name": "synthetic", "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
        "planes": (0..planes).map(|j| json!({"id": format!("P{j}")})).collect::<Vec<_>>(),
        "sensors": (0..sensors).map(|s| json!({"id": format!("S{s}"), "unit": "um_pp"})).collect::<Vec<_>>(),
        "runs": runs});
    balancing::parse_session(&serde_json::to_vec(&session).unwrap()).unwrap()
}

pub fn with(options: &SolveOptions, extra: Value) -> SolveOptions {
    let mut v = serde_json::to_value(options).unwrap();
    v.as_object_mut()
        .unwrap()
        .extend(extra.as_object().unwrap().clone());
    serde_json::from_value(v).unwrap()
}

pub fn solve(session: &Session, options: &SolveOptions) -> Solution {
    balancing::solve(session, options).unwrap()
}

pub fn mass(s: &Solution, plane: &str) -> f64 {
    s.corrections
        .iter()
        .find(|c| c.plane == plane)
        .unwrap()
        .mass_g
}

/// Used residual amplitudes of one sensor.
pub fn sensor_residuals(s: &Solution, sensor: &str) -> Vec<f64> {
    s.predicted_residual
        .iter()
        .filter(|r| r.used && r.sensor == sensor)
        .map(|r| r.amplitude)
        .collect()
}
