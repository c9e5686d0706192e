//! Cone solves (issue 5): min-max and mass-bounded least squares on an
//! 11-sensor × 4-plane job and a 1,000-row × 16-plane job, and a whole min-max
//! `balancing::solve` of the small job.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use fieldbal::balancing::conic::solve_cone;
use fieldbal::balancing::model::{Objective, Session, SolveOptions};
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
fn job(rows: usize, planes: usize) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let mut rng = StdRng::seed_from_u64(rows as u64 * 31 + planes as u64);
    let a = DMatrix::from_fn(rows, planes, |_, _| polar(&mut rng, 1.5));
    let b = DVector::from_fn(rows, |_, _| polar(&mut rng, 80.0));
    (a, b)
}

/// Bounds at half the unbounded least-squares mass, so that every one binds.
fn binding_bounds(a: &DMatrix<Complex64>, b: &DVector<Complex64>) -> Vec<Option<f64>> {
    let x = a.clone().svd(true, true).solve(&(-b), 1e-12).unwrap();
    x.iter().map(|z| Some(0.5 * z.norm())).collect()
}

/// The 11-sensor × 4-plane job as a session (lead / with-rotation conventions).
fn session(a: &DMatrix<Complex64>, b: &DVector<Complex64>) -> Session {
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

fn cone(c: &mut Criterion) {
    for (rows, planes) in [(11, 4), (1000, 16)] {
        let (a, b) = job(rows, planes);
        let free = vec![None; planes];
        let bounds = binding_bounds(&a, &b);
        let check = solve_cone(&a, &b, Objective::LeastSquares, &bounds).unwrap();
        assert!(
            check.bound_active.iter().any(|&x| x),
            "the bounds must bind"
        );
        c.bench_function(&format!("min_max {rows}x{planes}"), |bench| {
            bench.iter(|| {
                solve_cone(black_box(&a), black_box(&b), Objective::MinMax, &free).unwrap()
            })
        });
        c.bench_function(&format!("bounded_least_squares {rows}x{planes}"), |bench| {
            bench.iter(|| {
                solve_cone(
                    black_box(&a),
                    black_box(&b),
                    Objective::LeastSquares,
                    &bounds,
                )
                .unwrap()
            })
        });
        c.bench_function(&format!("bounded_min_max {rows}x{planes}"), |bench| {
            bench.iter(|| {
                solve_cone(black_box(&a), black_box(&b), Objective::MinMax, &bounds).unwrap()
            })
        });
    }
    let (a, b) = job(11, 4);
    let s = session(&a, &b);
    let options = SolveOptions {
        objective: Some(Objective::MinMax),
        ..SolveOptions::default()
    };
    c.bench_function("balancing::solve min_max 11x4 session", |bench| {
        bench.iter(|| balancing::solve(black_box(&s), &options).unwrap())
    });
}

criterion_group!(benches, cone);
criterion_main!(benches);
