//! Min-max and mass-bounded corrections (issue 5): optimality checked
//! independently of the cone solver, by SVD least squares, Goodman's bounds and
//! random feasible perturbations.

use fieldbal::balancing::conic::{objective_value, solve_cone, solve_cone_within, Limits};
use fieldbal::balancing::model::Objective;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use proptest::prelude::*;
use proptest::test_runner::FileFailurePersistence;
use rand::{rngs::StdRng, Rng, SeedableRng};

/// The least-squares correction by SVD, independent of the cone solver.
fn svd_least_squares(a: &DMatrix<Complex64>, b: &DVector<Complex64>) -> DVector<Complex64> {
    let svd = a.clone().svd(true, true);
    svd.solve(&(-b), 1e-12).expect("SVD computed with U and V")
}

fn max_abs(r: &DVector<Complex64>) -> f64 {
    r.iter().map(|z| z.norm()).fold(0.0, f64::max)
}

fn residual(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    x: &DVector<Complex64>,
) -> DVector<Complex64> {
    b + a * x
}

/// A random complex problem with entries of order `scale_a` and `scale_b`.
fn random_problem(
    seed: u64,
    rows: usize,
    planes: usize,
    scale_a: f64,
    scale_b: f64,
) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut c = |s: f64| Complex64::new(rng.gen_range(-1.0..1.0) * s, rng.gen_range(-1.0..1.0) * s);
    let a = DMatrix::from_fn(rows, planes, |_, _| c(scale_a));
    let b = DVector::from_fn(rows, |_, _| c(scale_b));
    (a, b)
}

/// `x + δ` pulled back inside the bounds, for perturbations of several sizes.
fn perturbations(
    x: &DVector<Complex64>,
    bounds: &[Option<f64>],
    seed: u64,
    count: usize,
) -> Vec<DVector<Complex64>> {
    let mut rng = StdRng::seed_from_u64(seed);
    let size = x.norm().max(1e-6);
    (0..count)
        .map(|i| {
            let step = size * 10f64.powi(-((i % 5) as i32) - 1);
            DVector::from_fn(x.len(), |j, _| {
                let mut z = x[j]
                    + Complex64::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0)) * step;
                if let Some(m) = bounds[j] {
                    if z.norm() > m {
                        z *= m / z.norm();
                    }
                }
                z
            })
        })
        .collect()
}

fn problem_strategy() -> impl Strategy<Value = (u64, usize, usize, f64, f64)> {
    // Rows ≥ planes as in balancing; units from µm to mm/s and grams to kilograms.
    (any::<u64>(), 1usize..5, 0usize..10, -3i32..3, -3i32..3).prop_map(
        |(seed, planes, extra, ea, eb)| {
            (seed, planes + extra, planes, 10f64.powi(ea), 10f64.powi(eb))
        },
    )
}

proptest! {
    #![proptest_config(ProptestConfig {
        // Seeds in a file beside this one (the default would look for them
        // beside the binary's main.rs, in tests/proptest-regressions/).
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions"
        ))),
        ..ProptestConfig::with_cases(48)
    })]

    #[test]
    fn no_random_perturbation_beats_the_min_max_answer((seed, rows, planes, sa, sb) in problem_strategy()) {
        let (a, b) = random_problem(seed, rows, planes, sa, sb);
        let free = vec![None; planes];
        let sol = solve_cone(&a, &b, Objective::MinMax, &free).unwrap();
        let best = max_abs(&residual(&a, &b, &sol.x));
        for x in perturbations(&sol.x, &free, seed ^ 1, 200) {
            prop_assert!(best <= max_abs(&residual(&a, &b, &x)) * (1.0 + 1e-6) + 1e-9 * sb);
        }
    }

    #[test]
    fn the_min_max_value_lies_between_the_least_squares_rms_and_maximum((seed, rows, planes, sa, sb) in problem_strategy()) {
        let (a, b) = random_problem(seed, rows, planes, sa, sb);
        let sol = solve_cone(&a, &b, Objective::MinMax, &vec![None; planes]).unwrap();
        let r_ls = residual(&a, &b, &svd_least_squares(&a, &b));
        let rms = r_ls.norm() / (rows as f64).sqrt();
        let tol = 1e-6 * sb;
        // Goodman (1964): no correction can push every row below the LS RMS.
        prop_assert!(sol.value >= rms - tol, "min-max {} below LS rms {}", sol.value, rms);
        prop_assert!(sol.value <= max_abs(&r_ls) + tol, "min-max {} above LS max {}", sol.value, max_abs(&r_ls));
    }

    #[test]
    fn unbounded_cone_least_squares_matches_the_svd_solution((seed, rows, planes, sa, sb) in problem_strategy()) {
        let (a, b) = random_problem(seed, rows, planes, sa, sb);
        let sol = solve_cone(&a, &b, Objective::LeastSquares, &vec![None; planes]).unwrap();
        let x_ls = svd_least_squares(&a, &b);
        let ls_norm = residual(&a, &b, &x_ls).norm();
        prop_assert!((sol.value - ls_norm).abs() <= 1e-7 * sb * (rows as f64).sqrt() + 1e-7 * ls_norm);
    }

    #[test]
    fn bounded_solutions_respect_every_bound_and_are_not_beaten_inside_them(
        (seed, rows, planes, sa, sb) in problem_strategy(), ls in any::<bool>(), frac in 0.05f64..1.5,
    ) {
        let (a, b) = random_problem(seed, rows, planes, sa, sb);
        let objective = if ls { Objective::LeastSquares } else { Objective::MinMax };
        let free = solve_cone(&a, &b, objective, &vec![None; planes]).unwrap();
        // Bound every other plane at a fraction of its unbounded mass.
        let bounds: Vec<Option<f64>> = (0..planes)
            .map(|j| (j % 2 == 0).then(|| (free.x[j].norm() * frac).max(1e-6 * sb / sa)))
            .collect();
        let sol = solve_cone(&a, &b, objective, &bounds).unwrap();
        for (j, m) in bounds.iter().enumerate() {
            if let Some(m) = m {
                prop_assert!(sol.x[j].norm() <= *m, "plane {j}: {} > bound {m}", sol.x[j].norm());
            }
        }
        prop_assert!(sol.value >= free.value * (1.0 - 1e-7) - 1e-9 * sb);
        for x in perturbations(&sol.x, &bounds, seed ^ 2, 200) {
            let v = objective_value(&a, &b, &x, objective);
            prop_assert!(sol.value <= v * (1.0 + 1e-6) + 1e-9 * sb, "{} beaten by {} (free {}, active {:?})", sol.value, v, free.value, sol.bound_active);
        }
    }

    #[test]
    fn loose_bounds_give_the_unbounded_answer((seed, rows, planes, sa, sb) in problem_strategy(), ls in any::<bool>()) {
        let (a, b) = random_problem(seed, rows, planes, sa, sb);
        let objective = if ls { Objective::LeastSquares } else { Objective::MinMax };
        let x_ls = svd_least_squares(&a, &b);
        let free = solve_cone(&a, &b, objective, &vec![None; planes]).unwrap();
        let loose: Vec<Option<f64>> = (0..planes)
            .map(|j| Some(10.0 * x_ls[j].norm().max(free.x[j].norm()) + sb / sa))
            .collect();
        let sol = solve_cone(&a, &b, objective, &loose).unwrap();
        prop_assert!(sol.bound_active.iter().all(|&active| !active));
        // Interior-point accuracy is relative to the data (tolerance 1e-8 of max|b|),
        // which matters where the optimum is an exact zero.
        prop_assert!((sol.value - free.value).abs() <= 1e-6 * free.value + 1e-7 * sb, "{} vs {}", sol.value, free.value);
        if ls {
            // Least squares has a unique answer: the SVD one.
            let err = (&sol.x - &x_ls).norm();
            prop_assert!(err <= 1e-5 * x_ls.norm() + 1e-9 * sb / sa, "x differs from SVD by {err}");
        }
    }
}

#[test]
fn a_tight_bound_is_reported_binding_and_held_exactly() {
    let (a, b) = random_problem(7, 11, 4, 0.5, 80.0);
    let x_ls = svd_least_squares(&a, &b);
    for objective in [Objective::LeastSquares, Objective::MinMax] {
        let m = 0.3 * x_ls[2].norm();
        let bounds = vec![None, None, Some(m), None];
        let sol = solve_cone(&a, &b, objective, &bounds).unwrap();
        assert!(
            sol.bound_active[2],
            "{objective:?}: bound on plane 2 should bind"
        );
        assert!(!sol.bound_active[0] && !sol.bound_active[1] && !sol.bound_active[3]);
        assert!(sol.x[2].norm() <= m && sol.x[2].norm() >= m * (1.0 - 1e-5));
    }
}

#[test]
fn exact_data_are_balanced_to_zero_by_both_objectives() {
    // A square, noise-free job: some correction cancels the vibration exactly,
    // where the cone optimum sits at its apex.
    let (a, _) = random_problem(3, 4, 4, 2.0, 1.0);
    let truth = DVector::from_fn(4, |j, _| Complex64::from_polar(10.0 + j as f64, j as f64));
    let b = -(&a * &truth);
    for objective in [Objective::LeastSquares, Objective::MinMax] {
        let sol = solve_cone(&a, &b, objective, &[None; 4]).unwrap();
        assert!(
            sol.value <= 1e-6 * b.norm(),
            "{objective:?} left {}",
            sol.value
        );
        assert!((&sol.x - &truth).norm() <= 1e-5 * truth.norm());
    }
}

#[test]
fn the_answer_does_not_depend_on_the_units() {
    // Same rotor in µm and g versus mm and kg: corrections scale, residuals scale.
    let (a, b) = random_problem(11, 9, 3, 1.0, 1.0);
    let (ka, kb) = (1e-6, 1e3);
    let a2 = a.map(|z| z * ka);
    let b2 = b.map(|z| z * kb);
    for objective in [Objective::LeastSquares, Objective::MinMax] {
        let s1 = solve_cone(&a, &b, objective, &[Some(0.8), None, None]).unwrap();
        let s2 = solve_cone(&a2, &b2, objective, &[Some(0.8 * kb / ka), None, None]).unwrap();
        assert!((s2.value / kb - s1.value).abs() <= 1e-6 * s1.value);
        assert_eq!(s1.bound_active, s2.bound_active);
    }
}

#[test]
fn a_plane_no_sensor_sees_gets_no_correction() {
    let (mut a, b) = random_problem(5, 6, 3, 1.0, 1.0);
    a.column_mut(1).fill(Complex64::new(0.0, 0.0));
    for objective in [Objective::LeastSquares, Objective::MinMax] {
        let sol = solve_cone(&a, &b, objective, &[None, Some(1.0), None]).unwrap();
        assert_eq!(sol.x[1], Complex64::new(0.0, 0.0));
        assert!(!sol.bound_active[1]);
    }
}

/// What is wrong, A, b, bounds, expected error code.
type BadCase = (
    &'static str,
    DMatrix<Complex64>,
    DVector<Complex64>,
    Vec<Option<f64>>,
    &'static str,
);

#[test]
fn unsolvable_cone_problems_are_rejected_with_422_codes() {
    let (a, b) = random_problem(1, 5, 2, 1.0, 1.0);
    let nan = Complex64::new(f64::NAN, 0.0);
    let mut a_nan = a.clone();
    a_nan[(0, 0)] = nan;
    let cases: Vec<BadCase> = vec![
        (
            "every plane excluded",
            DMatrix::zeros(5, 0),
            b.clone(),
            vec![],
            "no_planes",
        ),
        (
            "no rows",
            DMatrix::zeros(0, 2),
            DVector::zeros(0),
            vec![None, None],
            "no_rows",
        ),
        (
            "negative bound",
            a.clone(),
            b.clone(),
            vec![Some(-1.0), None],
            "infeasible",
        ),
        (
            "zero bound",
            a.clone(),
            b.clone(),
            vec![None, Some(0.0)],
            "infeasible",
        ),
        (
            "infinite bound",
            a.clone(),
            b.clone(),
            vec![Some(f64::INFINITY), None],
            "infeasible",
        ),
        (
            "NaN in the matrix",
            a_nan,
            b.clone(),
            vec![None, None],
            "solver_failed",
        ),
    ];
    for (what, a, b, bounds, code) in cases {
        for objective in [Objective::LeastSquares, Objective::MinMax] {
            let err = solve_cone(&a, &b, objective, &bounds).unwrap_err();
            assert_eq!(err.kind, fieldbal::balancing::ErrorKind::Invalid, "{what}");
            assert_eq!(err.code, code, "{what}");
        }
    }
}

#[test]
fn a_solve_cut_off_by_its_limits_is_a_422_not_a_hang() {
    let (a, b) = random_problem(13, 11, 4, 1.0, 80.0);
    let cut_offs = [
        (
            "two iterations",
            Limits {
                max_iter: 2,
                time_limit_s: 5.0,
            },
        ),
        (
            "a nanosecond",
            Limits {
                max_iter: 200,
                time_limit_s: 1e-9,
            },
        ),
    ];
    for (what, limits) in cut_offs {
        for objective in [Objective::LeastSquares, Objective::MinMax] {
            let bounds = [Some(1.0), None, None, None];
            let err = solve_cone_within(&a, &b, objective, &bounds, limits).unwrap_err();
            assert_eq!(err.kind, fieldbal::balancing::ErrorKind::Invalid, "{what}");
            assert_eq!(err.code, "solver_failed", "{what}: {}", err.message);
        }
    }
    // The same problem within the default limits solves.
    assert!(solve_cone_within(&a, &b, Objective::MinMax, &[None; 4], Limits::default()).is_ok());
}

#[test]
fn two_planes_that_act_alike_still_get_an_optimal_bounded_answer() {
    // Plane 2 moves every sensor exactly as plane 0 does, turned by 90°: the
    // problem is rank-deficient, its optimum value unique, its x not.
    let (mut a, b) = random_problem(17, 8, 3, 1.0, 50.0);
    let turned = a.column(0) * Complex64::new(0.0, 1.0);
    a.set_column(2, &turned);
    let ls_value = residual(&a, &b, &svd_least_squares(&a, &b)).norm();
    for objective in [Objective::LeastSquares, Objective::MinMax] {
        let free = solve_cone(&a, &b, objective, &[None; 3]).unwrap();
        let bounds = [Some(1e3), Some(1e3), Some(1e3)];
        let loose = solve_cone(&a, &b, objective, &bounds).unwrap();
        assert!(
            (loose.value - free.value).abs() <= 1e-6 * free.value,
            "{objective:?}"
        );
        if objective == Objective::LeastSquares {
            assert!((free.value - ls_value).abs() <= 1e-6 * ls_value);
        }
        let tight = [
            Some(0.2 * free.x[0].norm()),
            None,
            Some(0.2 * free.x[2].norm()),
        ];
        let sol = solve_cone(&a, &b, objective, &tight).unwrap();
        assert!(sol.x[0].norm() <= tight[0].unwrap() && sol.x[2].norm() <= tight[2].unwrap());
        for x in perturbations(&sol.x, &tight, 23, 300) {
            assert!(sol.value <= objective_value(&a, &b, &x, objective) * (1.0 + 1e-6));
        }
    }
}
