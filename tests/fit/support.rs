//! Shared support for the fit tests: generated rotors (an influence matrix and
//! a vibration as found) written as sessions whose trial runs determine the
//! influence coefficients exactly.
#![allow(dead_code)] // each test binary uses a different part

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::Rng;
use serde_json::{json, Value};

/// A complex number with both parts uniform in `[-1, 1]`.
pub fn c(rng: &mut StdRng) -> Complex64 {
    Complex64::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0))
}

/// A generated rotor: `w` (rows × planes, vibration per gram, internal frame)
/// and the vibration as found `y0 = −w u` for an unbalance `u` of 20 to 80 g
/// per plane, plus a little that no correction removes.
pub fn rotor(
    rng: &mut StdRng,
    rows: usize,
    planes: usize,
) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let w = DMatrix::from_fn(rows, planes, |_, _| c(rng) * 0.05);
    let u = DVector::from_fn(planes, |_, _| {
        Complex64::from_polar(
            rng.gen_range(20.0..80.0),
            rng.gen_range(0.0..std::f64::consts::TAU),
        )
    });
    let y0 = -(&w * &u) + DVector::from_fn(rows, |_, _| c(rng) * 0.05);
    (w, y0)
}

/// A reading of internal phasor `y` in the lag convention.
fn reading(speed: f64, sensor: &str, y: Complex64) -> Value {
    json!({"speed_rpm": speed, "sensor": sensor, "amplitude": y.norm(), "phase_deg": (-y.arg().to_degrees()).rem_euclid(360.0)})
}

/// Rows are `sensors × speeds` in the order the core sorts them (speed, then sensor).
pub fn row_ids(rows: usize) -> Vec<(f64, String)> {
    (0..rows)
        .map(|a| (1000.0 * (1 + a / 2) as f64, format!("S{}", a % 2)))
        .collect()
}

/// A session (lag, against rotation) for `w`, `y0` (rows even: 2 sensors ×
/// rows/2 speeds), with `planes` the JSON of each plane (its `id` is set here),
/// a reference run and one 10 g trial at angle 0 per plane.
pub fn session(w: &DMatrix<Complex64>, y0: &DVector<Complex64>, planes: Vec<Value>) -> Value {
    let ids = row_ids(w.nrows());
    let mut runs = vec![json!({"id": "zero", "weights": [],
        "readings": ids.iter().enumerate().map(|(a, (s, n))| reading(*s, n, y0[a])).collect::<Vec<_>>()})];
    for j in 0..w.ncols() {
        runs.push(json!({"id": format!("trial {j}"),
            "weights": [{"plane": format!("P{j}"), "mass_g": 10.0, "angle_deg": 0.0}],
            "readings": ids.iter().enumerate().map(|(a, (s, n))| reading(*s, n, y0[a] + w[(a, j)] * 10.0)).collect::<Vec<_>>()}));
    }
    let planes: Vec<Value> = planes
        .into_iter()
        .enumerate()
        .map(|(j, mut p)| {
            p["id"] = json!(format!("P{j}"));
            p
        })
        .collect();
    json!({
        "name": "generated",
        "rotor": {"mass_kg": 400.0, "service_speed_rpm": 1500.0, "balance_grade": "G6.3"},
        "planes": planes,
        "sensors": [{"id": "S0", "unit": "um_pp"}, {"id": "S1", "unit": "um_pp"}],
        "runs": runs,
    })
}

/// Internal weight of `mass_g` at `deg` against rotation.
pub fn weight(mass_g: f64, deg: f64) -> Complex64 {
    Complex64::from_polar(mass_g, -deg.to_radians())
}
