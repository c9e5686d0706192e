//! The active-set min-max (issue 15) against the full one-cone-per-row
//! program: on many random jobs, with and without mass bounds, the same
//! objective and the same correction to the solver's tolerance; and limits
//! still end a large solve with a 422.

use fieldbal::balancing::conic::{solve_cone_with, Limits, Strategy};
use fieldbal::balancing::model::Objective;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::{rngs::StdRng, Rng, SeedableRng};

fn polar(rng: &mut StdRng, scale: f64) -> Complex64 {
    Complex64::from_polar(
        scale * rng.gen_range(0.2..1.0),
        rng.gen_range(0.0..std::f64::consts::TAU),
    )
}

/// A stand-like job: coefficients ~1.5 units/g, vibration ~80 units.
fn job(seed: u64, rows: usize, planes: usize) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let mut rng = StdRng::seed_from_u64(seed);
    let a = DMatrix::from_fn(rows, planes, |_, _| polar(&mut rng, 1.5));
    let b = DVector::from_fn(rows, |_, _| polar(&mut rng, 80.0));
    (a, b)
}

fn max_abs(r: &DVector<Complex64>) -> f64 {
    r.iter().map(|z| z.norm()).fold(0.0, f64::max)
}

#[test]
fn the_active_set_answer_equals_the_full_programs_on_many_random_jobs() {
    let shapes = [(30, 2), (60, 3), (120, 4), (200, 6), (400, 8), (1000, 16)];
    let mut jobs = 0;
    let mut worst: f64 = 0.0;
    for (s, &(rows, planes)) in shapes.iter().enumerate() {
        let seeds = if rows >= 400 { 3 } else { 8 };
        for seed in 0..seeds {
            let (a, b) = job(1000 * s as u64 + seed, rows, planes);
            let free = vec![None; planes];
            // Bounds at 60 % of the unbounded min-max mass on every other plane.
            let unbounded = solve_cone_with(
                &a,
                &b,
                Objective::MinMax,
                &free,
                Limits::default(),
                Strategy::Full,
                false,
            )
            .unwrap();
            let bounded: Vec<Option<f64>> = (0..planes)
                .map(|j| (j % 2 == 0).then(|| 0.6 * unbounded.x[j].norm()))
                .collect();
            for bounds in [&free, &bounded] {
                let full = solve_cone_with(
                    &a,
                    &b,
                    Objective::MinMax,
                    bounds,
                    Limits::default(),
                    Strategy::Full,
                    false,
                )
                .unwrap();
                let act = solve_cone_with(
                    &a,
                    &b,
                    Objective::MinMax,
                    bounds,
                    Limits::default(),
                    Strategy::ActiveSet,
                    false,
                )
                .unwrap();
                let scale = max_abs(&b);
                let what = format!(
                    "{rows}x{planes} seed {seed} bounded {}",
                    bounds.iter().any(Option::is_some)
                );
                // The values: both optimal to rounding (polished, session 20;
                // before, to the solver's tolerance, 1e-8 of max |b|).
                assert!(
                    (act.value - full.value).abs() <= 1e-12 * scale,
                    "{what}: {} vs {}",
                    act.value,
                    full.value
                );
                assert!((max_abs(&(&b + &a * &act.x)) - act.value).abs() <= 1e-12 * scale);
                // The corrections: the optimum of a generic job is unique, but
                // where fewer than 2n + 1 rows are active the objective is flat
                // to second order along their cones, so a value known to 1e-8
                // fixed x only to about √1e-8 = 1e-4 of its size; both answers
                // are now polished to rounding on their active set
                // (`conic/polish.rs`): measured 1.6e-14 apart at most.
                let dx = (&act.x - &full.x).norm() / full.x.norm().max(1e-9);
                worst = worst.max(dx);
                assert!(dx <= 1e-9, "{what}: |Δx|/|x| = {dx}");
                for (j, m) in bounds.iter().enumerate() {
                    if let Some(m) = m {
                        assert!(act.x[j].norm() <= *m, "{what}: plane {j} over its bound");
                    }
                }
                assert_eq!(act.bound_active, full.bound_active, "{what}");
                jobs += 1;
            }
        }
    }
    assert!(jobs >= 60, "{jobs} jobs compared");
    eprintln!("{jobs} jobs, largest |Δx|/|x| {worst:.1e}");
}

#[test]
fn a_large_active_set_solve_cut_off_by_its_limits_is_a_422_not_a_hang() {
    let (a, b) = job(7, 1000, 16);
    let free = vec![None; 16];
    for limits in [
        Limits {
            max_iter: 2,
            time_limit_s: 5.0,
        },
        Limits {
            max_iter: 200,
            time_limit_s: 1e-9,
        },
    ] {
        let err = solve_cone_with(
            &a,
            &b,
            Objective::MinMax,
            &free,
            limits,
            Strategy::ActiveSet,
            false,
        )
        .unwrap_err();
        assert_eq!(err.code, "solver_failed", "{limits:?}: {}", err.message);
    }
}
