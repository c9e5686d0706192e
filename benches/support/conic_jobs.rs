//! The jobs of `benches/conic.rs`, shared with `examples/conic_once.rs` (which
//! runs one of them once, for callgrind's instruction counts): an 11-sensor ×
//! 4-plane and a 1,000-row × 16-plane job from fixed seeds, bounds that bind,
//! and the small job as a session.

use fieldbal::balancing::model::Session;
use fieldbal::balancing::{self};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::{rngs::StdRng, Rng, SeedableRng};
use serde_json::json;

fn polar(rng: &mut StdRng, scale: f64) -> Complex64 {
    Complex64::from_polar(
        scale * rng.gen_range(0.2..1.0),
        rng.gen_range(0.0..std::f64::consts::TAU),
    )
}

/// Influence coefficients ~1.5 µm/g and vibration ~80 µm, as on a stand.
pub fn job(rows: usize, planes: usize) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let mut rng = StdRng::seed_from_u64(rows as u64 * 31 + planes as u64);
    let a = DMatrix::from_fn(rows, planes, |_, _| polar(&mut rng, 1.5));
    let b = DVector::from_fn(rows, |_, _| polar(&mut rng, 80.0));
    (a, b)
}

/// Bounds at half the unbounded least-squares mass, so that every one binds.
pub fn binding_bounds(a: &DMatrix<Complex64>, b: &DVector<Complex64>) -> Vec<Option<f64>> {
    let x = a.clone().svd(true, true).solve(&(-b), 1e-12).unwrap();
    x.iter().map(|z| Some(0.5 * z.norm())).collect()
}

/// The 11-sensor × 4-plane job as a session (lead / with-rotation conventions).
pub fn session(a: &DMatrix<Complex64>, b: &DVector<Complex64>) -> Session {
    let reading = |i: usize, y: Complex64| {
        json!({"speed_rpm": 3000, "sensor": format!("S{i}"), "amplitude": y.norm(),
               "phase_deg": y.arg().to_degrees()})
    };
    let mut runs = vec![json!({"id": "zero", "weights": [],
        "readings": (0..a.nrows()).map(|i| reading(i, b[i])).collect::<Vec<_>>()})];
    for j in 0..a.ncols() {
        runs.push(json!({"id": format!("trial {j}"),
            "weights": [{"plane": format!("P{j}"), "mass_g": 40, "angle_deg": 0}],
            "readings": (0..a.nrows()).map(|i| reading(i, b[i] + a[(i, j)] * 40.0)).collect::<Vec<_>>()}));
    }
    let s = json!({"name": "bench", "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
        "planes": (0..a.ncols()).map(|j| json!({"id": format!("P{j}")})).collect::<Vec<_>>(),
        "sensors": (0..a.nrows()).map(|i| json!({"id": format!("S{i}"), "unit": "um_pp"})).collect::<Vec<_>>(),
        "runs": runs});
    balancing::parse_session(&serde_json::to_vec(&s).unwrap()).unwrap()
}
