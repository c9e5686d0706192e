//! Uncertainty of corrections and residuals (issue 6): calibration of the 95 %
//! regions on noisy realisations of a known rotor, the single-plane 4 % check,
//! Monte Carlo against the linearised covariance, samples instead of options,
//! the noise side of `trial_effect_small`, and invalid noise options.

use fieldbal::balancing::model::{
    AngleDirection, Conventions, PhaseConvention, Plane, Reading, Run, Sample, Sensor, Session,
    SolveOptions, Unit, Weight,
};
use fieldbal::balancing::phasor::{reading_out, weight_out};
use fieldbal::balancing::uncertainty::{propagate, CHI2_2_95};
use fieldbal::balancing::{self, ErrorKind, Solution};
use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

fn c(re: f64, im: f64) -> Complex64 {
    Complex64::new(re, im)
}

const LAG_AGAINST: Conventions = Conventions {
    phase: PhaseConvention::Lag,
    angle_direction: AngleDirection::AgainstRotation,
};
const LEAD_WITH: Conventions = Conventions {
    phase: PhaseConvention::Lead,
    angle_direction: AngleDirection::WithRotation,
};

/// A known rotor: exact influence matrix `w` (rows × planes, internal frame),
/// exact correction `c`, reference vibration `y0 = −W c + r⊥` with a part `r⊥`
/// no correction can cancel (so the least-squares residual is not zero), and
/// one trial run per plane of mass `trial[j]` at angle 0.
struct Rotor {
    w: DMatrix<Complex64>,
    c: DVector<Complex64>,
    y0: DVector<Complex64>,
    trial: Vec<f64>,
}

impl Rotor {
    /// Two planes seen by four rows (two sensors at two speeds).
    fn two_plane(trial_effect: f64) -> Rotor {
        let w = DMatrix::from_row_slice(
            4,
            2,
            &[
                c(1.2, 0.8),
                c(0.3, -0.4),
                c(-0.5, 1.1),
                c(0.9, 0.2),
                c(2.0, -0.6),
                c(0.7, 0.9),
                c(0.4, 0.5),
                c(-1.3, 0.6),
            ],
        );
        let c_true = DVector::from_vec(vec![
            Complex64::from_polar(40.0, 0.5),
            Complex64::from_polar(25.0, 3.5),
        ]);
        // A part of Y0 orthogonal to W's columns: the residual of the exact fit.
        let v = DVector::from_vec(vec![c(3.0, 1.0), c(-2.0, 2.0), c(1.0, -3.0), c(2.0, 2.0)]);
        let q = w.clone().qr().q();
        let perp = &v - &q * (q.adjoint() * &v);
        let y0 = -(&w * &c_true) + perp;
        Rotor::with_trials(w, c_true, y0, trial_effect)
    }

    /// Trial masses whose largest relative change `|W_aj| m / |Y0_a|` is `effect`.
    fn with_trials(
        w: DMatrix<Complex64>,
        c: DVector<Complex64>,
        y0: DVector<Complex64>,
        effect: f64,
    ) -> Rotor {
        let trial = (0..w.ncols())
            .map(|j| {
                let per_g = (0..w.nrows())
                    .map(|a| w[(a, j)].norm() / y0[a].norm())
                    .fold(0.0, f64::max);
                effect / per_g
            })
            .collect();
        Rotor { w, c, y0, trial }
    }

    /// Exact readings, runs × rows: the reference, then one trial per plane.
    fn readings(&self) -> Vec<Vec<Complex64>> {
        let mut runs = vec![self.y0.iter().copied().collect::<Vec<_>>()];
        for (j, &m) in self.trial.iter().enumerate() {
            runs.push(
                (0..self.w.nrows())
                    .map(|a| self.y0[a] + self.w[(a, j)] * m)
                    .collect(),
            );
        }
        runs
    }

    /// The exact correction of plane `j` as `m e^{iθ}` with θ in the session's direction.
    fn correction(&self, conv: Conventions, j: usize) -> Complex64 {
        let (m, deg) = weight_out(conv, self.c[j]);
        Complex64::from_polar(m, deg.to_radians())
    }
}

/// A session of these readings (runs × rows); `samples[k][a]` optionally lists repeated readings.
fn session(
    conv: Conventions,
    trial: &[f64],
    y: &[Vec<Complex64>],
    samples: Option<&[Vec<Vec<Complex64>>]>,
) -> Session {
    let rows = y[0].len();
    let reading = |k: usize, a: usize| {
        let (amplitude, phase_deg) = reading_out(conv, y[k][a]);
        Reading {
            speed_rpm: if a < 2 { 1500.0 } else { 3000.0 },
            sensor: format!("S{}", a % 2),
            amplitude,
            phase_deg,
            samples: samples.map(|s| {
                s[k][a]
                    .iter()
                    .map(|&z| {
                        let (amplitude, phase_deg) = reading_out(conv, z);
                        Sample {
                            amplitude,
                            phase_deg,
                        }
                    })
                    .collect()
            }),
        }
    };
    let run = |k: usize| Run {
        id: format!("run {k}"),
        weights: if k == 0 {
            vec![]
        } else {
            vec![Weight {
                plane: format!("P{}", k - 1),
                mass_g: trial[k - 1],
                angle_deg: 0.0,
            }]
        },
        readings: (0..rows).map(|a| reading(k, a)).collect(),
    };
    Session {
        name: "generated".into(),
        machine: None,
        conventions: Some(conv),
        rotor: None,
        planes: (0..trial.len())
            .map(|j| Plane {
                id: format!("P{j}"),
                radius_mm: None,
                positions: None,
            })
            .collect(),
        sensors: (0..2.min(rows))
            .map(|s| Sensor {
                id: format!("S{s}"),
                unit: Unit::UmPp,
                label: None,
            })
            .collect(),
        runs: (0..y.len()).map(run).collect(),
    }
}

/// A reading with independent radial noise (`pct` % of its amplitude) and
/// tangential noise (`deg` degrees), the options' noise model.
fn noisy(y: Complex64, pct: f64, deg: f64, rng: &mut StdRng) -> Complex64 {
    let n = Normal::new(0.0, 1.0).unwrap();
    y * c(
        1.0 + pct / 100.0 * n.sample(rng),
        deg.to_radians() * n.sample(rng),
    )
}

fn solve(s: &Session, options: &SolveOptions) -> Solution {
    balancing::solve(s, options).expect("generated sessions solve")
}

/// Correction of plane `j` as `m e^{iθ}` and its covariance, session frame.
fn estimate(s: &Solution, j: usize) -> (Complex64, Matrix2<f64>) {
    let corr = &s.corrections[j];
    let u = corr
        .uncertainty
        .as_ref()
        .expect("every correction has an uncertainty");
    let k = u.covariance_g2;
    (
        Complex64::from_polar(corr.mass_g, corr.angle_deg.to_radians()),
        Matrix2::new(k[0][0], k[0][1], k[1][0], k[1][1]),
    )
}

/// Fraction of realisations whose 95 % region holds the exact correction, per plane.
fn coverage(rotor: &Rotor, conv: Conventions, realisations: usize, seed: u64) -> Vec<f64> {
    let mut rng = StdRng::seed_from_u64(seed);
    let exact = rotor.readings();
    let mut hits = vec![0usize; rotor.trial.len()];
    for _ in 0..realisations {
        let y: Vec<Vec<Complex64>> = exact
            .iter()
            .map(|run| run.iter().map(|&z| noisy(z, 2.0, 2.0, &mut rng)).collect())
            .collect();
        let sol = solve(
            &session(conv, &rotor.trial, &y, None),
            &SolveOptions::default(),
        );
        for (j, hit) in hits.iter_mut().enumerate() {
            let (z, cov) = estimate(&sol, j);
            let d = z - rotor.correction(conv, j);
            let d = nalgebra::Vector2::new(d.re, d.im);
            let inv = cov
                .try_inverse()
                .expect("a noisy solve has a regular covariance");
            if (d.transpose() * inv * d)[0] <= CHI2_2_95 {
                *hit += 1;
            }
        }
    }
    hits.iter()
        .map(|&h| h as f64 / realisations as f64)
        .collect()
}

// 2000 realisations: the binomial sd of a 95 % coverage is 0.49 %, so the
// window 93–97 % is ±4 sd around a calibrated 95 %.
const REALISATIONS: usize = 2000;

#[test]
fn the_95_percent_regions_hold_the_exact_correction_in_95_percent_of_realisations_with_a_well_sized_trial(
) {
    let cov = coverage(&Rotor::two_plane(1.0), LAG_AGAINST, REALISATIONS, 1);
    eprintln!("well-sized trial coverage {cov:?}");
    assert!(cov.iter().all(|&p| (0.93..=0.97).contains(&p)), "{cov:?}");
}

#[test]
fn the_95_percent_regions_hold_the_exact_correction_in_95_percent_of_realisations_with_a_small_trial(
) {
    let cov = coverage(&Rotor::two_plane(0.3), LAG_AGAINST, REALISATIONS, 2);
    eprintln!("small trial coverage {cov:?}");
    assert!(cov.iter().all(|&p| (0.93..=0.97).contains(&p)), "{cov:?}");
}

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
    let p = propagate(&t, &y, &[vec![iso, iso]], &[0], &[1.0], &[0], &c_hat);
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
fn monte_carlo_covariances_agree_with_the_linearised_ones_in_either_angle_direction() {
    let rotor = Rotor::two_plane(0.8);
    let exact = rotor.readings();
    for (conv, seed) in [(LAG_AGAINST, 4), (LEAD_WITH, 5)] {
        let reference = solve(
            &session(conv, &rotor.trial, &exact, None),
            &SolveOptions::default(),
        );
        let mut rng = StdRng::seed_from_u64(seed);
        let mut cs = [Vec::new(), Vec::new()];
        let mut rs = vec![Vec::new(); 4];
        for _ in 0..3000 {
            let y: Vec<Vec<Complex64>> = exact
                .iter()
                .map(|run| run.iter().map(|&z| noisy(z, 2.0, 2.0, &mut rng)).collect())
                .collect();
            let sol = solve(
                &session(conv, &rotor.trial, &y, None),
                &SolveOptions::default(),
            );
            for (j, list) in cs.iter_mut().enumerate() {
                list.push(estimate(&sol, j).0);
            }
            for (a, list) in rs.iter_mut().enumerate() {
                list.push(sol.predicted_residual[a].amplitude);
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
        // The residual amplitudes' 95 % quantile against the reported bound.
        for (a, list) in rs.iter_mut().enumerate() {
            list.sort_by(f64::total_cmp);
            let q95 = list[(0.95 * list.len() as f64) as usize];
            let bound = reference.predicted_residual[a].amplitude_95.unwrap();
            eprintln!("{conv:?} row {a}: MC 95 % quantile {q95} bound {bound}");
            assert!(
                (q95 / bound - 1.0).abs() < 0.08,
                "{conv:?} row {a}: MC {q95} vs {bound}"
            );
        }
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
    let p = propagate(&t, &exact, &cov, &rows, &g, &[0, 1], &c0);
    // Σ J Σ_r Jᵀ with J by central differences of the LS solution and of R.
    let h = 1e-6;
    let mut full = DMatrix::<f64>::zeros(4, 4);
    let mut res = [Matrix2::<f64>::zeros(); 4];
    for a in 0..4 {
        for k in 0..4 {
            let mut jc = DMatrix::<f64>::zeros(4, 2);
            let mut jr = [Matrix2::<f64>::zeros(); 4];
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
                    let r = y.column(0) + w * &cc;
                    (cc, r)
                };
                let ((cp, rp), (cm, rm)) = (diff(1.0), diff(-1.0));
                for j in 0..2 {
                    let dc = (cp[j] - cm[j]) / (2.0 * h);
                    jc[(2 * j, col)] = dc.re;
                    jc[(2 * j + 1, col)] = dc.im;
                }
                for b in 0..4 {
                    let dr = (rp[b] - rm[b]) / (2.0 * h);
                    jr[b][(0, col)] = dr.re;
                    jr[b][(1, col)] = dr.im;
                }
            }
            full += &jc * cov[a][k] * jc.transpose();
            for (rb, jb) in res.iter_mut().zip(&jr) {
                *rb += jb * cov[a][k] * jb.transpose();
            }
        }
    }
    assert!(
        (&p.correction_full - &full).abs().max() < 1e-5 * full.abs().max(),
        "{} vs {}",
        p.correction_full,
        full
    );
    for (b, (lin, fd)) in p.residual.iter().zip(&res).enumerate() {
        assert!(
            (lin - fd).abs().max() < 1e-5 * fd.abs().max(),
            "row {b}: {lin} vs {fd}"
        );
    }
}

/// `n` samples around each exact reading, with the options' noise model at `pct` %/`deg`°,
/// recentred so that their mean is the reading.
fn with_samples(
    y: &[Vec<Complex64>],
    n: usize,
    pct: f64,
    deg: f64,
    seed: u64,
) -> Vec<Vec<Vec<Complex64>>> {
    let mut rng = StdRng::seed_from_u64(seed);
    y.iter()
        .map(|run| {
            run.iter()
                .map(|&z| {
                    let s: Vec<Complex64> = (0..n).map(|_| noisy(z, pct, deg, &mut rng)).collect();
                    let shift = z - s.iter().sum::<Complex64>() / n as f64;
                    s.into_iter().map(|x| x + shift).collect()
                })
                .collect()
        })
        .collect()
}

fn options(pct: f64, deg: f64) -> SolveOptions {
    SolveOptions {
        amplitude_noise_pct: Some(pct),
        phase_noise_deg: Some(deg),
        ..SolveOptions::default()
    }
}

#[test]
fn the_scatter_of_samples_is_used_instead_of_the_options() {
    let rotor = Rotor::two_plane(0.8);
    let y = rotor.readings();
    // 30 samples per reading scattering 10 % / 10°, far above the options' noise.
    let samples = with_samples(&y, 30, 10.0, 10.0, 7);
    let s = session(LAG_AGAINST, &rotor.trial, &y, Some(&samples));
    let var = |sol: &Solution| estimate(sol, 0).1.trace();
    let quiet_options = solve(&s, &options(0.5, 0.5));
    let loud_options = solve(&s, &options(5.0, 5.0));
    let no_samples = solve(
        &session(LAG_AGAINST, &rotor.trial, &y, None),
        &options(0.5, 0.5),
    );
    // The options change the answer only through the 2-sample prior (2 of 31 parts).
    assert!(
        (var(&loud_options) / var(&quiet_options) - 1.0).abs() < 0.2,
        "{} vs {}",
        var(&loud_options),
        var(&quiet_options)
    );
    // The samples' mean has (10 %)²/30 of variance per reading against the options' (0.5 %)²:
    // the region is wider by about (10/0.5)²/30 ≈ 13 in variance.
    let ratio = var(&quiet_options) / var(&no_samples);
    assert!((8.0..20.0).contains(&ratio), "{ratio}");
    // Twice the scatter, four times the variance.
    let doubled: Vec<Vec<Vec<Complex64>>> = samples
        .iter()
        .zip(&y)
        .map(|(run, yr)| {
            run.iter()
                .zip(yr)
                .map(|(s, &z)| s.iter().map(|&x| z + 2.0 * (x - z)).collect())
                .collect()
        })
        .collect();
    let louder = solve(
        &session(LAG_AGAINST, &rotor.trial, &y, Some(&doubled)),
        &options(0.5, 0.5),
    );
    let ratio = var(&louder) / var(&quiet_options);
    assert!((3.6..4.0).contains(&ratio), "{ratio}");
}

/// Warnings of one code and plane.
fn warnings<'s>(s: &'s Solution, code: &str, plane: &str) -> Vec<&'s str> {
    s.warnings
        .iter()
        .filter(|w| w.code == code && w.plane.as_deref() == Some(plane))
        .map(|w| w.message.as_str())
        .collect()
}

#[test]
fn a_trial_effect_within_three_times_its_noise_is_flagged_even_above_thirty_percent() {
    let rotor = Rotor::two_plane(0.35);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let quiet = solve(&s, &SolveOptions::default());
    assert!(
        quiet
            .warnings
            .iter()
            .all(|w| w.code != "trial_effect_small"),
        "{:?}",
        quiet.warnings
    );
    assert!(
        quiet
            .planes
            .iter()
            .all(|p| p.trial_effect_snr.unwrap() > 3.0),
        "{:?}",
        quiet.planes
    );
    // A noisy instrument: 15 % and 15° make a 35 % change indistinguishable from noise.
    let noisy = solve(&s, &options(15.0, 15.0));
    for p in &noisy.planes {
        let snr = p.trial_effect_snr.unwrap();
        assert!(snr < 3.0, "{} {snr}", p.plane);
        let w = warnings(&noisy, "trial_effect_small", &p.plane);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].contains("measurement noise"), "{}", w[0]);
    }
}

#[test]
fn a_trial_too_small_by_both_tests_gets_one_warning_that_says_both() {
    let rotor = Rotor::two_plane(0.05);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let sol = solve(&s, &SolveOptions::default());
    let w = warnings(&sol, "trial_effect_small", "P0");
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(
        w[0].contains("30 %") && w[0].contains("measurement noise"),
        "{}",
        w[0]
    );
}

#[test]
fn without_noise_the_regions_shrink_to_the_correction() {
    let rotor = Rotor::two_plane(1.0);
    let sol = solve(
        &session(LEAD_WITH, &rotor.trial, &rotor.readings(), None),
        &options(0.0, 0.0),
    );
    for corr in &sol.corrections {
        let u = corr.uncertainty.as_ref().unwrap();
        assert_eq!(u.covariance_g2, [[0.0; 2]; 2]);
        assert!(
            (u.mass_g[0] - corr.mass_g).abs() < 1e-9 && (u.mass_g[1] - corr.mass_g).abs() < 1e-9
        );
    }
    for r in &sol.predicted_residual {
        assert!((r.amplitude_95.unwrap() - r.amplitude).abs() < 1e-9);
    }
    assert!(sol.planes.iter().all(|p| p.trial_effect_snr.is_none()));
}

#[test]
fn invalid_noise_options_are_rejected_naming_the_option() {
    let rotor = Rotor::two_plane(1.0);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let cases: [(&str, Option<f64>, Option<f64>, &str); 7] = [
        (
            "negative amplitude noise",
            Some(-1.0),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "NaN amplitude noise",
            Some(f64::NAN),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "infinite amplitude noise",
            Some(f64::INFINITY),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "amplitude noise above 100 %",
            Some(150.0),
            None,
            "options.amplitude_noise_pct",
        ),
        (
            "negative phase noise",
            None,
            Some(-0.5),
            "options.phase_noise_deg",
        ),
        (
            "phase noise above 90°",
            None,
            Some(360.0),
            "options.phase_noise_deg",
        ),
        (
            "NaN phase noise",
            None,
            Some(f64::NAN),
            "options.phase_noise_deg",
        ),
    ];
    for (what, pct, deg, field) in cases {
        let o = SolveOptions {
            amplitude_noise_pct: pct,
            phase_noise_deg: deg,
            ..SolveOptions::default()
        };
        let err = balancing::solve(&s, &o).expect_err(what);
        assert_eq!(err.kind, ErrorKind::Invalid, "{what}");
        assert_eq!(err.field.as_deref(), Some(field), "{what}");
    }
}
