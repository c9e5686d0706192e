//! Criterion benchmarks of the whole core solve (validation, influence
//! coefficients, SVD least squares, report): a two-plane job and a large
//! multi-speed job (16 planes, 32 sensors, 40 speeds).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use fieldbal::balancing::model::{Conventions, Reading, Run, Session, SolveOptions, Weight};
use fieldbal::balancing::phasor::weight_out;
use fieldbal::balancing::solve;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

// The session builder the tests use too, included by path (not library API).
#[path = "../tests/common/generated.rs"]
mod generated;

/// A deterministic pseudo-random number in [0, 1) (xorshift), so runs compare.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    fn phasor(&mut self, scale: f64) -> Complex64 {
        Complex64::from_polar(
            scale * (0.2 + self.next()),
            std::f64::consts::TAU * self.next(),
        )
    }
}

/// A noisy session with one removed trial per plane.
fn job(planes: usize, sensors: usize, speeds: usize) -> Session {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let conv = Conventions::default();
    let rows = sensors * speeds;
    let w = DMatrix::from_fn(rows, planes, |_, _| rng.phasor(2.0));
    let u = DVector::from_fn(planes, |_, _| rng.phasor(30.0));
    let y0 = &w * &u + DVector::from_fn(rows, |_, _| rng.phasor(1.0));
    let readings = |y: &DVector<Complex64>, rng: &mut Rng| -> Vec<Reading> {
        (0..rows)
            .map(|a| {
                let speed_rpm = 500.0 + 250.0 * (a / sensors) as f64;
                generated::reading(conv, speed_rpm, a % sensors, y[a] + rng.phasor(0.5))
            })
            .collect()
    };
    let mut runs = vec![Run {
        id: "zero".into(),
        weights: vec![],
        readings: readings(&y0, &mut rng),
        purpose: None,
    }];
    for j in 0..planes {
        let trial = rng.phasor(40.0);
        let (mass_g, angle_deg) = weight_out(conv, trial);
        let y = &y0 + w.column(j) * trial;
        runs.push(Run {
            id: format!("trial {j}"),
            weights: vec![Weight {
                plane: format!("P{j}"),
                mass_g,
                angle_deg,
            }],
            readings: readings(&y, &mut rng),
            purpose: None,
        });
    }
    let name = format!("bench {planes}x{sensors}x{speeds}");
    generated::session(name, conv, planes, Some(150.0), sensors, runs)
}

fn benches(c: &mut Criterion) {
    let options = SolveOptions::default();
    let small = job(2, 4, 1);
    c.bench_function("solve two planes, 4 sensors, 1 speed", |b| {
        b.iter(|| solve(black_box(&small), &options).unwrap())
    });
    // Stated noise: the errors-in-variables estimate iterated to its fixed
    // point, its bias map and a second propagation run too (issue 12,
    // uncertainty::bias, method 8.11 and 8.12).
    let stated = SolveOptions {
        amplitude_noise_pct: Some(2.0),
        phase_noise_deg: Some(2.0),
        ..SolveOptions::default()
    };
    c.bench_function("solve two planes, 4 sensors, 1 speed, stated noise", |b| {
        b.iter(|| solve(black_box(&small), &stated).unwrap())
    });
    // Many speeds with stated noise: the path where `amplitude_95` conditions
    // on all rows through the de-noised Gram (issue 12, method §8, session
    // 24 amp24), which one speed never takes.
    let speeds = job(3, 4, 10);
    c.bench_function("solve 3 planes, 4 sensors, 10 speeds, stated noise", |b| {
        b.iter(|| solve(black_box(&speeds), &stated).unwrap())
    });
    let large = job(16, 32, 40);
    let mut group = c.benchmark_group("large");
    group.sample_size(20);
    group.bench_function("solve 16 planes, 32 sensors, 40 speeds", |b| {
        b.iter(|| solve(black_box(&large), &options).unwrap())
    });
    group.bench_function(
        "solve 16 planes, 32 sensors, 40 speeds, stated noise",
        |b| b.iter(|| solve(black_box(&large), &stated).unwrap()),
    );
    group.bench_function("validate 16 planes, 32 sensors, 40 speeds", |b| {
        b.iter(|| {
            fieldbal::balancing::validate::check(black_box(&large))
                .unwrap()
                .rows
                .len()
        })
    });
    group.finish();
    // Issue 15: the largest job the limits accept (768 rows × 65 runs = 49,920
    // readings) and a 267 × 267 one; memory is measured on the same jobs with
    // `/usr/bin/time -v fieldbal solve benches/data/ls-*.json`.
    let mut group = c.benchmark_group("limits");
    group.sample_size(10);
    let limit = job(64, 256, 3);
    group.bench_function("solve 64 planes, 256 sensors, 3 speeds", |b| {
        b.iter(|| solve(black_box(&limit), &options).unwrap())
    });
    // 267 planes are over the default limit of 64: raise it for this job only,
    // to measure what such a job would cost if a stand allowed it.
    fieldbal::balancing::limits::Limits::configure(fieldbal::balancing::limits::Limits {
        planes: 267,
        sensors: 267,
        runs: 300,
        readings: 100_000,
        ..fieldbal::balancing::limits::Limits::DEFAULT
    });
    let square = job(267, 267, 1);
    group.bench_function("solve 267 planes, 267 sensors, 1 speed", |b| {
        b.iter(|| solve(black_box(&square), &options).unwrap())
    });
    group.finish();
}

criterion_group!(core, benches);
criterion_main!(core);
