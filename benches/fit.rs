//! The discrete fit at scale: 4 planes × 24 places × a 5-size kit × 2 per
//! place (2 places per fit), least squares, to proven optimality; and the
//! same problem through a whole solve.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use fieldbal::balancing::fit::candidates::{loads, plane_candidates};
use fieldbal::balancing::fit::search::{search, Problem};
use fieldbal::balancing::model::Objective;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

fn problem(seed: u64) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut c = || Complex64::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0));
    let a = DMatrix::from_fn(8, 4, |_, _| c() * 0.05);
    let u = DVector::from_fn(4, |_, _| c() * 50.0);
    let b = -(&a * &u) + DVector::from_fn(8, |_, _| c() * 0.05);
    (a, b)
}

fn fit(c: &mut Criterion) {
    let places: Vec<Complex64> = (0..24)
        .map(|p| Complex64::from_polar(1.0, std::f64::consts::TAU * p as f64 / 24.0))
        .collect();
    let kit = [2.0, 5.0, 10.0, 20.0, 50.0];
    c.bench_function(
        "fit::candidates 24 places x 5 sizes x 2 per place",
        |bench| bench.iter(|| plane_candidates(black_box(&places), loads(&kit, 2), 2, None)),
    );
    let sums: Vec<Complex64> = plane_candidates(&places, loads(&kit, 2), 2, None)
        .candidates
        .iter()
        .map(|k| k.sum)
        .collect();
    for objective in [Objective::LeastSquares, Objective::MinMax] {
        let (a, b) = problem(21);
        let p = Problem {
            a: &a,
            b: &b,
            sums: vec![sums.clone(); 4],
            objective,
            time_limit: Duration::from_secs(60),
            node_limit: u64::MAX,
        };
        let found = search(&p, vec![0; 4]);
        eprintln!(
            "{objective:?}: optimal {} after {} candidate evaluations",
            found.optimal, found.nodes
        );
        c.bench_function(
            &format!("fit::search 4 planes x 24 places, {objective:?}"),
            |bench| bench.iter(|| search(black_box(&p), vec![0; 4])),
        );
    }
}

criterion_group!(benches, fit);
criterion_main!(benches);
