//! The linearised covariance against the closed single-plane form, a Monte
//! Carlo through the public solve, and finite differences of the LS fit.

use fieldbal::balancing::model::SolveOptions;
use fieldbal::balancing::uncertainty::{propagate, Problem};
use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

use fieldbal::balancing::phasor::weight_in;

use super::{c, estimate, session, solve, solve_noisy, Rotor, LAG_AGAINST, LEAD_WITH};

/// Sample covariance of complex values as (Re, Im).
fn scatter(z: &[Complex64]) -> Matrix2<f64> {
    let n = z.len() as f64;
    let m = z.iter().sum::<Complex64>() / n;
    z.iter().fold(Matrix2::zeros(), |acc, &x| {
        let d = x - m;
        acc + Matrix2::new(d.re * d.re, d.re * d.im, d.im * d.re, d.im * d.im) / (n - 1.0)
    })
}

#[test]
fn a_single_plane_correction_has_the_relative_spread_of_the_closed_form() {
    // One sensor, one plane; the trial changes the reading by −0.3·Y0, so
    // r = C/U = 1/0.3 is real and σ_C/|C| = (σ/|A|)·√(|1−r|²+|r|²) ≈ 4.07 %.
    let a = Complex64::from_polar(100.0, 0.7);
    let u = 30.0;
    let w = -0.3 * a / u;
    let y = DMatrix::from_row_slice(1, 2, &[a, a + w * u]);
    let t = DMatrix::from_element(1, 1, c(u, 0.0));
    let sigma = 0.01 * a.norm();
    let iso = Matrix2::identity() * (sigma * sigma / 2.0);
    let c_hat = DVector::from_element(1, -a / w);
    let problem = Problem {
        t: &t,
        y: &y,
        cov: &[vec![iso, iso]],
        used_rows: &[0],
        row_weights: &[1.0],
        used_planes: &[0],
    };
    let p = propagate(&problem, &c_hat, None);
    let rel = p.correction[0].trace().sqrt() / c_hat[0].norm();
    let r = c_hat[0] / u;
    let closed = sigma / a.norm() * ((1.0 - r).norm_sqr() + r.norm_sqr()).sqrt();
    assert!((rel - closed).abs() < 1e-9 * closed, "{rel} vs {closed}");
    assert!((0.039..0.042).contains(&rel), "{rel}");

    // The same noise on generated sessions through the public solve.
    let mut rng = StdRng::seed_from_u64(3);
    let n = Normal::new(0.0, sigma / 2f64.sqrt()).unwrap();
    let mut cs = Vec::new();
    for _ in 0..4000 {
        let mut noisy = |z: Complex64| z + c(n.sample(&mut rng), n.sample(&mut rng));
        let runs = vec![vec![noisy(y[(0, 0)])], vec![noisy(y[(0, 1)])]];
        let sol = solve(
            &session(LAG_AGAINST, &[u], &runs, None),
            &SolveOptions::default(),
        );
        cs.push(estimate(&sol, 0).0);
    }
    let mc = scatter(&cs).trace().sqrt() / c_hat[0].norm();
    eprintln!("single plane: linearised {rel}, closed form {closed}, Monte Carlo {mc}");
    // sd of the estimate ≈ 1.1 % relative with 4000 realisations; plus second-order effects.
    assert!(
        (mc / closed - 1.0).abs() < 0.06,
        "Monte Carlo {mc} vs {closed}"
    );
}

#[test]
fn monte_carlo_covariances_agree_with_the_linearised_ones_and_residual_bounds_hold_at_least_95_percent(
) {
    let rotor = Rotor::two_plane(0.8);
    let exact = rotor.readings();
    for (conv, seed) in [(LAG_AGAINST, 4), (LEAD_WITH, 5)] {
        let reference = solve(
            &session(conv, &rotor.trial, &exact, None),
            &SolveOptions::default(),
        );
        let mut rng = StdRng::seed_from_u64(seed);
        let mut cs = [Vec::new(), Vec::new()];
        let mut held = [0usize; 4];
        let realisations = 3000;
        for _ in 0..realisations {
            let sol = solve_noisy(&rotor, &exact, conv, &mut rng);
            for (j, list) in cs.iter_mut().enumerate() {
                list.push(estimate(&sol, j).0);
            }
            // The vibration that would really remain with this correction fitted.
            let fitted = DVector::from_fn(2, |j, _| {
                let corr = &sol.corrections[j];
                weight_in(conv, corr.mass_g, corr.angle_deg)
            });
            let actual = &rotor.y0 + &rotor.w * fitted;
            for (a, h) in held.iter_mut().enumerate() {
                if actual[a].norm() <= sol.predicted_residual[a].amplitude_95.unwrap() {
                    *h += 1;
                }
            }
        }
        for (j, list) in cs.iter().enumerate() {
            let (_, lin) = estimate(&reference, j);
            let mc = scatter(list);
            // Elements compared on the scale of the ellipse: the MC estimate of a
            // covariance from 3000 draws is within a few % of it.
            let scale = (lin[(0, 0)] * lin[(1, 1)]).sqrt();
            eprintln!("{conv:?} plane {j}: MC {mc:?} linearised {lin:?}");
            assert!(
                (mc - lin).abs().max() < 0.1 * scale,
                "{conv:?} plane {j}: MC {mc} vs linearised {lin}"
            );
        }
        // The bounds hold the really remaining vibration in 93–97 % of
        // realisations over the rows (uncertainty::remaining). Row by row
        // they are calibrated only together: the weight given to the
        // predictions is estimated from the job's rows (empirical Bayes), here
        // from two complex degrees of freedom, and one row of this rotor, with
        // |r| about its noise, holds 90.1–90.9 % in the two conventions (3000
        // realisations, sd 0.5 %; measured with the all-rows conditioning of
        // session 11, 89.9–90.8 % before it; 91.6–91.8 % with the form before
        // that, which over-covered elsewhere). Every row must hold at least 88 %.
        let held = held.map(|h| h as f64 / realisations as f64);
        eprintln!("{conv:?}: residual bounds hold in {held:?}");
        let pooled = held.iter().sum::<f64>() / held.len() as f64;
        assert!((0.93..=0.97).contains(&pooled), "{conv:?}: {held:?}");
        assert!(held.iter().all(|&p| p >= 0.88), "{conv:?}: {held:?}");
    }
}

/// Least-squares correction of the used rows/planes, computed here by SVD.
fn ls(
    t: &DMatrix<Complex64>,
    y: &DMatrix<Complex64>,
    rows: &[usize],
    g: &[f64],
) -> DVector<Complex64> {
    let t_pinv = t.clone().pseudo_inverse(1e-12).unwrap();
    let y0 = y.column(0).clone_owned();
    let mut dy = y.columns(1, y.ncols() - 1).clone_owned();
    for mut col in dy.column_iter_mut() {
        col -= &y0;
    }
    let w = dy * t_pinv;
    let a = DMatrix::from_fn(rows.len(), w.ncols(), |i, j| w[(rows[i], j)] * g[i]);
    let b = DVector::from_fn(rows.len(), |i, _| -y0[rows[i]] * g[i]);
    a.svd(true, true).solve(&b, 1e-12).unwrap()
}

#[test]
fn the_linearised_covariance_is_the_finite_difference_jacobian_of_the_least_squares_fit() {
    // Two trial runs with both planes' weights (T not diagonal), one unused row,
    // weighted rows and a residual that is not zero: every term of dC matters.
    let rotor = Rotor::two_plane(1.0);
    let t = DMatrix::from_row_slice(
        2,
        3,
        &[
            c(10.0, 0.0),
            c(8.0, 6.0),
            c(0.0, 0.0),
            c(0.0, 0.0),
            c(5.0, -5.0),
            c(0.0, 12.0),
        ],
    );
    let exact = DMatrix::from_fn(4, 4, |a, k| {
        if k == 0 {
            rotor.y0[a]
        } else {
            rotor.y0[a] + (rotor.w.row(a) * t.column(k - 1))[0]
        }
    });
    let rows = [0, 1, 3];
    let g = [1.0, 2.5, 0.7];
    let c0 = ls(&t, &exact, &rows, &g);
    let mut rng = StdRng::seed_from_u64(6);
    let cov: Vec<Vec<Matrix2<f64>>> = (0..4)
        .map(|_| {
            (0..4)
                .map(|_| {
                    let l =
                        Matrix2::from_fn(|_, _| Normal::new(0.0, 0.3).unwrap().sample(&mut rng));
                    l * l.transpose()
                })
                .collect()
        })
        .collect();
    let problem = Problem {
        t: &t,
        y: &exact,
        cov: &cov,
        used_rows: &rows,
        row_weights: &g,
        used_planes: &[0, 1],
    };
    let p = propagate(&problem, &c0, None);
    // Σ J Σ_r Jᵀ with J by central differences of the LS solution, of the
    // prediction R̂ = Y0 + W C, and of Y0 + W C0 with the fitted C0 held fixed.
    let h = 1e-6;
    let mut full = DMatrix::<f64>::zeros(4, 4);
    let mut res = [Matrix2::<f64>::zeros(); 4];
    let mut fixed = [Matrix2::<f64>::zeros(); 4];
    for a in 0..4 {
        for k in 0..4 {
            let mut jc = DMatrix::<f64>::zeros(4, 2);
            let mut jr = [Matrix2::<f64>::zeros(); 4];
            let mut jf = [Matrix2::<f64>::zeros(); 4];
            for (col, d) in [c(h, 0.0), c(0.0, h)].into_iter().enumerate() {
                let diff = |s: f64| {
                    let mut y = exact.clone();
                    y[(a, k)] += d * s;
                    let cc = ls(&t, &y, &rows, &g);
                    let w = DMatrix::from_fn(4, 2, |b, j| {
                        (1..4)
                            .map(|kk| {
                                (y[(b, kk)] - y[(b, 0)])
                                    * t.clone().pseudo_inverse(1e-12).unwrap()[(kk - 1, j)]
                            })
                            .sum::<Complex64>()
                    });
                    let r = y.column(0) + &w * &cc;
                    let f = y.column(0) + &w * &c0;
                    (cc, r, f)
                };
                let ((cp, rp, fp), (cm, rm, fm)) = (diff(1.0), diff(-1.0));
                for j in 0..2 {
                    let dc = (cp[j] - cm[j]) / (2.0 * h);
                    jc[(2 * j, col)] = dc.re;
                    jc[(2 * j + 1, col)] = dc.im;
                }
                for b in 0..4 {
                    let dr = (rp[b] - rm[b]) / (2.0 * h);
                    jr[b][(0, col)] = dr.re;
                    jr[b][(1, col)] = dr.im;
                    let df = (fp[b] - fm[b]) / (2.0 * h);
                    jf[b][(0, col)] = df.re;
                    jf[b][(1, col)] = df.im;
                }
            }
            full += &jc * cov[a][k] * jc.transpose();
            for (rb, jb) in res.iter_mut().zip(&jr) {
                *rb += jb * cov[a][k] * jb.transpose();
            }
            for (fb, jb) in fixed.iter_mut().zip(&jf) {
                *fb += jb * cov[a][k] * jb.transpose();
            }
        }
    }
    assert!(
        (&p.correction_full - &full).abs().max() < 1e-5 * full.abs().max(),
        "{} vs {}",
        p.correction_full,
        full
    );
    for (b, (lin, fd)) in p.prediction.iter().zip(&res).enumerate() {
        assert!(
            (lin - fd).abs().max() < 1e-5 * fd.abs().max(),
            "prediction, row {b}: {lin} vs {fd}"
        );
    }
    for (b, (lin, fd)) in p.residual.iter().zip(&fixed).enumerate() {
        assert!(
            (lin - fd).abs().max() < 1e-5 * fd.abs().max(),
            "residual with C fixed, row {b}: {lin} vs {fd}"
        );
    }
}

#[test]
fn with_as_many_rows_as_planes_the_residual_bound_holds_the_remaining_vibration_in_95_percent_of_realisations(
) {
    // Two rows, two planes: the prediction is always 0, and all of the really
    // remaining vibration comes from the reading errors with the correction fixed.
    let full = Rotor::two_plane(0.8);
    let w = full.w.rows(0, 2).into_owned();
    let y0 = -(&w * &full.c);
    let rotor = Rotor::with_trials(w, full.c.clone(), y0, 0.8);
    let exact = rotor.readings();
    let mut rng = StdRng::seed_from_u64(8);
    let mut held = [0usize; 2];
    let realisations = 3000;
    for _ in 0..realisations {
        let sol = solve_noisy(&rotor, &exact, LAG_AGAINST, &mut rng);
        let fitted = DVector::from_fn(2, |j, _| {
            let corr = &sol.corrections[j];
            weight_in(LAG_AGAINST, corr.mass_g, corr.angle_deg)
        });
        let actual = &rotor.y0 + &rotor.w * fitted;
        for (a, h) in held.iter_mut().enumerate() {
            assert!(sol.predicted_residual[a].amplitude < 1e-6 * y0_scale(&rotor));
            if actual[a].norm() <= sol.predicted_residual[a].amplitude_95.unwrap() {
                *h += 1;
            }
        }
    }
    let held = held.map(|h| h as f64 / realisations as f64);
    eprintln!("square system: residual bounds hold in {held:?}");
    assert!(held.iter().all(|p| (0.93..=0.97).contains(p)), "{held:?}");
}

fn y0_scale(rotor: &Rotor) -> f64 {
    rotor.y0.iter().map(|z| z.norm()).fold(0.0, f64::max)
}
