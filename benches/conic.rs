//! Cone solves (issue 5): min-max and mass-bounded least squares on an
//! 11-sensor × 4-plane job and a 1,000-row × 16-plane job, and a whole min-max
//! `balancing::solve` of the small job.

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use fieldbal::balancing::conic::solve_cone;
use fieldbal::balancing::model::{Objective, SolveOptions};
use fieldbal::balancing::{self};

#[path = "support/conic_jobs.rs"]
mod conic_jobs;
use conic_jobs::{binding_bounds, job, session};

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
