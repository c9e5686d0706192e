//! Min-max optima known in closed form, asserted to 1e-9 relative: the
//! interior point alone fixes a min-max correction only to about the square
//! root of its duality gap where the peak is flat to second order along the
//! optimal set's tangent (about 1e-5), so a technician comparing digits with
//! another tool saw them differ (session 20).

use fieldbal::balancing::conic::{solve_cone_with, Limits, Strategy};
use fieldbal::balancing::model::Objective;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

fn c(re: f64, im: f64) -> Complex64 {
    Complex64::new(re, im)
}

/// One plane, two sensors: `|r_a| = |a_a| |x − u_a|` with `u_a = −b_a/a_a`,
/// so the largest residual is a weighted distance to two points, least on
/// the segment between them where the two are equal:
/// `x = u₁ + (u₂ − u₁) |a₂| / (|a₁| + |a₂|)`, peak `|a₁||a₂||u₂ − u₁| / (|a₁| + |a₂|)`.
fn one_plane_two_sensors(a: [Complex64; 2], b: [Complex64; 2]) -> (Complex64, f64) {
    let u = [-b[0] / a[0], -b[1] / a[1]];
    let (w1, w2) = (a[0].norm(), a[1].norm());
    let x = u[0] + (u[1] - u[0]) * (w2 / (w1 + w2));
    let peak = w1 * w2 * (u[1] - u[0]).norm() / (w1 + w2);
    (x, peak)
}

#[test]
fn one_plane_two_sensors_gives_the_equalising_correction_to_1e_9() {
    let cases = [
        ([c(1.5, 0.4), c(-0.3, 0.9)], [c(80.0, -20.0), c(12.0, 45.0)]),
        ([c(0.02, 0.0), c(0.0, 3.0)], [c(1.0, 1.0), c(-250.0, 7.0)]),
        (
            [c(2.0, -1.0), c(2.1, -0.9)],
            [c(465.0, 28.0), c(-173.0, 66.0)],
        ),
    ];
    for (a, b) in cases {
        let (want, peak) = one_plane_two_sensors(a, b);
        let am = DMatrix::from_column_slice(2, 1, &a);
        let bv = DVector::from_column_slice(&b);
        for strategy in [Strategy::ActiveSet, Strategy::Full] {
            let got = solve_cone_with(
                &am,
                &bv,
                Objective::MinMax,
                &[None],
                Limits::default(),
                strategy,
                false,
            )
            .unwrap();
            let what = format!("{a:?} {b:?} {strategy:?}");
            assert!(
                (got.x[0] - want).norm() <= 1e-9 * want.norm(),
                "{what}: {} vs {want}, {:.2e} relative",
                got.x[0],
                (got.x[0] - want).norm() / want.norm()
            );
            assert!((got.value - peak).abs() <= 1e-9 * peak, "{what}");
        }
    }
}

/// A min-max job built from its optimality conditions, so its optimum `x*`
/// is known: `n + 1` rows at the peak `t` whose residuals `r_a = t v_a/|v_a|`
/// come from a `v` with `Σ_a conj(A_ak) v_a = −c x*_0 δ_k0` (`v` in the null
/// space of the active rows' `Aᴴ`, shifted by the bound's pull when plane 0
/// is bounded at `|x*_0|`), multipliers `|v_a| > 0`; the other rows well
/// below the peak. Convex, so these conditions make `x*` optimal; unique,
/// as the active rows have full column rank.
/// A built job: `A`, `b`, the optimum `x*`, its peak `t`, the bounds.
type Built = (
    DMatrix<Complex64>,
    DVector<Complex64>,
    DVector<Complex64>,
    f64,
    Vec<Option<f64>>,
);

fn built(seed: u64, n: usize, rows: usize, bounded: bool, t: f64) -> Built {
    use rand::{rngs::StdRng, Rng, SeedableRng};
    let mut rng = StdRng::seed_from_u64(seed);
    let mut polar = |s: f64| {
        Complex64::from_polar(
            s * rng.gen_range(0.3..1.0),
            rng.gen_range(0.0..std::f64::consts::TAU),
        )
    };
    let a = DMatrix::from_fn(rows, n, |_, _| polar(1.5));
    let x = DVector::from_fn(n, |_, _| polar(40.0));
    let p = n + 1;
    let act = a.rows(0, p).clone_owned();
    // v = v_pull + z·null: A_actᴴ v = −c x0 e_0 (c = 0 when unbounded).
    let mut rhs = DVector::zeros(n);
    if bounded {
        rhs[0] = -x[0] * 0.02;
    }
    let svd = act.adjoint().svd(true, true);
    let pull = svd.solve(&rhs, 1e-14).unwrap();
    // The null vector: the right singular vector of the zero singular value
    // (the padded (n+1)-th), through the full SVD of the (n+1) × (n+1) matrix.
    let square = act.adjoint().resize_vertically(p, Complex64::new(0.0, 0.0));
    let sq = square.svd(false, true);
    let k = (0..p)
        .min_by(|&i, &j| sq.singular_values[i].total_cmp(&sq.singular_values[j]))
        .unwrap();
    let null = sq.v_t.unwrap().row(k).adjoint();
    let v = pull + null * Complex64::new(0.8, 0.3);
    assert!(v.iter().all(|z| z.norm() > 0.05), "{v}");
    let r = DVector::from_fn(rows, |i, _| {
        if i < p {
            v[i] / v[i].norm() * t
        } else {
            polar(0.7 * t)
        }
    });
    let b = &r - &a * &x;
    let mut bounds = vec![None; n];
    if bounded {
        bounds[0] = Some(x[0].norm());
    }
    (a, b, x, t, bounds)
}

#[test]
fn min_max_optima_built_from_their_optimality_conditions_come_back_to_1e_9() {
    let mut worst: f64 = 0.0;
    for (seed, &(n, rows)) in [(2, 6), (2, 40), (3, 12), (4, 60)].iter().enumerate() {
        for bounded in [false, true] {
            let (a, b, x, t, bounds) = built(seed as u64, n, rows, bounded, 7.5);
            for strategy in [Strategy::ActiveSet, Strategy::Full] {
                let got = solve_cone_with(
                    &a,
                    &b,
                    Objective::MinMax,
                    &bounds,
                    Limits::default(),
                    strategy,
                    false,
                )
                .unwrap();
                let what = format!("{n} planes, {rows} rows, bounded {bounded}, {strategy:?}");
                let err = (&got.x - &x).norm() / x.norm();
                worst = worst.max(err);
                assert!(err <= 1e-9, "{what}: {:.2e} relative", err);
                assert!(
                    (got.value - t).abs() <= 1e-9 * t,
                    "{what}: {} vs {t}",
                    got.value
                );
                assert_eq!(got.bound_active[0], bounded, "{what}");
            }
        }
    }
    println!("worst relative error {worst:.2e}");
}

#[test]
fn bounded_least_squares_on_one_plane_is_the_radial_projection_to_1e_9() {
    // With one plane, ‖b + a x‖² = ‖a‖² |x − x_ls|² + const: the bounded
    // optimum is x_ls pulled back radially onto the bound.
    use rand::{rngs::StdRng, Rng, SeedableRng};
    let mut rng = StdRng::seed_from_u64(4);
    let mut worst: f64 = 0.0;
    for rows in [1, 2, 5, 40] {
        let mut polar = |s: f64| {
            Complex64::from_polar(
                s * rng.gen_range(0.3..1.0),
                rng.gen_range(0.0..std::f64::consts::TAU),
            )
        };
        let a = DMatrix::from_fn(rows, 1, |_, _| polar(1.5));
        let b = DVector::from_fn(rows, |_, _| polar(80.0));
        let x_ls = -(a.adjoint() * &b)[0] / a.norm_squared();
        for share in [0.9, 0.5, 1e-3] {
            let m = share * x_ls.norm();
            let want = x_ls * share;
            let objective = Objective::LeastSquares;
            let got =
                fieldbal::balancing::conic::solve_cone(&a, &b, objective, &[Some(m)]).unwrap();
            let err = (got.x[0] - want).norm() / want.norm();
            worst = worst.max(err);
            assert!(
                err <= 1e-9,
                "{rows} rows, share {share}: {} vs {want}, {err:.2e}",
                got.x[0]
            );
            assert!(got.bound_active[0]);
        }
    }
    println!("worst relative error {worst:.2e}");
}

#[test]
fn the_noise_free_examples_come_back_exact_to_1e_9_with_min_max() {
    // Exact readings: the min-max optimum leaves nothing, the correction is
    // the examples' own to rounding, as least squares gives it.
    use super::support::{example, solve, with};
    for name in [
        "pump-two-plane-exact.json",
        "compressor-multispeed-exact.json",
        "pump-two-plane-kept-trial-exact.json",
    ] {
        let (session, options) = example(name);
        let ls = solve(&session, &options);
        let mm = solve(
            &session,
            &with(&options, serde_json::json!({"objective": "min_max"})),
        );
        for (m, l) in mm.corrections.iter().zip(&ls.corrections) {
            assert!(
                (m.mass_g - l.mass_g).abs() <= 1e-9 * l.mass_g,
                "{name}: {m:?} vs {l:?}"
            );
            let d = (m.angle_deg - l.angle_deg).rem_euclid(360.0);
            assert!(d.min(360.0 - d) <= 1e-7, "{name}: {m:?} vs {l:?}");
        }
    }
}

#[test]
fn a_min_max_optimum_a_hair_above_zero_comes_back_to_1e_9() {
    // A peak of 1e-5 µm beside readings of ~60 µm (nearly exact data):
    // below `polish`'s near-zero threshold, where the least-squares answer
    // is not the min-max one, Newton still polishes.
    for (seed, &(n, rows)) in [(2, 6), (3, 12), (2, 40)].iter().enumerate() {
        let (a, b, x, t, bounds) = built(10 + seed as u64, n, rows, false, 1e-5);
        let got = solve_cone_with(
            &a,
            &b,
            Objective::MinMax,
            &bounds,
            Limits::default(),
            Strategy::ActiveSet,
            false,
        )
        .unwrap();
        let err = (&got.x - &x).norm() / x.norm();
        assert!(err <= 1e-9, "{n} planes, {rows} rows: {err:.2e} relative");
        assert!((got.value - t).abs() <= 1e-6 * t, "{} vs {t}", got.value);
    }
}
