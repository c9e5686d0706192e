//! The solve across its options, as an outside balancing engineer checks it
//! (session 20): one-plane exact jobs in every convention and both
//! objectives, the same noisy job in every convention, scale invariance,
//! the extremes of the amplitude range, selection and row weights against
//! an independent weighted least squares, and hostile numbers that reach
//! the core.

use fieldbal::balancing::model::{AngleDirection, Conventions, Run, Session, SolveOptions, Weight};
use fieldbal::balancing::phasor::{reading_in, weight_in, weight_out};
use fieldbal::balancing::{solve, Solution};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::{rngs::StdRng, Rng, SeedableRng};

use super::properties::generated;

/// A rotor in the internal frame: `w` rows × planes, the as-found vibration
/// `y0`, one trial per plane, `sensors` sensors per speed (rows are
/// speed-major, speeds 1000, 2000, … rpm).
#[derive(Clone)]
struct Rotor {
    sensors: usize,
    w: DMatrix<Complex64>,
    y0: DVector<Complex64>,
    trials: Vec<Complex64>,
}

fn polar(m: f64, deg: f64) -> Complex64 {
    Complex64::from_polar(m, deg.to_radians())
}

impl Rotor {
    /// A stand-like rotor, `noise` µm of vibration the planes cannot explain.
    fn random(seed: u64, sensors: usize, speeds: usize, planes: usize, noise: f64) -> Rotor {
        let mut rng = StdRng::seed_from_u64(seed);
        let mut c = |s: f64| polar(s * rng.gen_range(0.3..1.0), rng.gen_range(0.0..360.0));
        let rows = sensors * speeds;
        let w = DMatrix::from_fn(rows, planes, |_, _| c(1.5));
        let u = DVector::from_fn(planes, |_, _| c(40.0));
        let e = DVector::from_fn(rows, |_, _| c(noise));
        let trials = (0..planes).map(|_| c(30.0)).collect();
        Rotor {
            sensors,
            y0: &w * u + e,
            w,
            trials,
        }
    }

    /// The session a technician records in `conv`, every amplitude times
    /// `amp` and every trial mass times `mass`.
    fn session(&self, conv: Conventions, amp: f64, mass: f64) -> Session {
        let planes = self.w.ncols();
        let readings = |y: &DVector<Complex64>| {
            (0..y.len())
                .map(|a| {
                    let speed = 1000.0 * (1 + a / self.sensors) as f64;
                    generated::reading(conv, speed, a % self.sensors, y[a] * amp)
                })
                .collect()
        };
        let mut runs = vec![Run {
            id: "zero".into(),
            weights: vec![],
            readings: readings(&self.y0),
            purpose: None,
        }];
        for j in 0..planes {
            let (mass_g, angle_deg) = weight_out(conv, self.trials[j] * mass);
            let y = &self.y0 + self.w.column(j) * self.trials[j];
            runs.push(Run {
                id: format!("trial {j}"),
                weights: vec![Weight {
                    plane: format!("P{j}"),
                    mass_g,
                    angle_deg,
                }],
                readings: readings(&y),
                purpose: None,
            });
        }
        generated::session("review".into(), conv, planes, None, self.sensors, runs)
    }
}

fn internal(s: &Solution) -> Vec<Complex64> {
    s.corrections
        .iter()
        .map(|c| weight_in(s.conventions, c.mass_g, c.angle_deg))
        .collect()
}

fn residuals(s: &Solution) -> Vec<Complex64> {
    s.predicted_residual
        .iter()
        .map(|r| reading_in(s.conventions, r.amplitude, r.phase_deg))
        .collect()
}

fn options(json: serde_json::Value) -> SolveOptions {
    serde_json::from_value(json).unwrap()
}

fn objectives() -> [SolveOptions; 2] {
    [
        SolveOptions::default(),
        options(serde_json::json!({"objective": "min_max"})),
    ]
}

/// Angles in degrees the same to `tol`, across 0/360.
fn same_angle(a: f64, b: f64, tol: f64) -> bool {
    let d = (a - b).rem_euclid(360.0);
    d.min(360.0 - d) <= tol
}

#[test]
fn a_one_plane_one_sensor_job_is_exact_in_every_convention_and_objective() {
    // 52.4 g at 141° with rotation is the correction; against rotation the
    // same place is 219°.
    let correction = polar(52.4, 141.0);
    let w = DMatrix::from_element(1, 1, polar(1.9, 40.0));
    let rotor = Rotor {
        sensors: 1,
        y0: -&w * DVector::from_element(1, correction),
        w,
        trials: vec![polar(30.0, 20.0)],
    };
    for conv in Conventions::ALL {
        let want_deg = weight_out(conv, correction).1;
        for opts in objectives() {
            let s = solve(&rotor.session(conv, 1.0, 1.0), &opts).unwrap();
            let c = &s.corrections[0];
            assert!((c.mass_g - 52.4).abs() <= 1e-9 * 52.4, "{conv:?}: {c:?}");
            assert!(same_angle(c.angle_deg, want_deg, 1e-9), "{conv:?}: {c:?}");
            assert!(s.summary.max_after <= 1e-9 * s.summary.max_before);
        }
    }
    // The two directions give the two angles a technician would mark.
    for conv in Conventions::ALL {
        let want = match conv.angle_direction {
            AngleDirection::WithRotation => 141.0,
            AngleDirection::AgainstRotation => 219.0,
        };
        let s = solve(&rotor.session(conv, 1.0, 1.0), &SolveOptions::default()).unwrap();
        assert!(
            same_angle(s.corrections[0].angle_deg, want, 1e-9),
            "{conv:?}: {:?}",
            s.corrections
        );
    }
}

#[test]
fn the_same_noisy_job_in_every_convention_gives_the_same_physical_answer_for_both_objectives() {
    let rotor = Rotor::random(7, 3, 2, 2, 6.0);
    for opts in objectives() {
        let answers: Vec<(Vec<Complex64>, Vec<Complex64>)> = Conventions::ALL
            .iter()
            .map(|&conv| {
                let s = solve(&rotor.session(conv, 1.0, 1.0), &opts).unwrap();
                (internal(&s), residuals(&s))
            })
            .collect();
        for (x, r) in &answers[1..] {
            for (a, b) in x.iter().zip(&answers[0].0) {
                assert!((a - b).norm() <= 1e-9 * b.norm(), "{opts:?}: {a} vs {b}");
            }
            for (a, b) in r.iter().zip(&answers[0].1) {
                assert!((a - b).norm() <= 1e-9 * 100.0, "{opts:?}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn scaling_amplitudes_and_trial_masses_by_1000_scales_the_corrections_and_keeps_their_angles() {
    let rotor = Rotor::random(11, 4, 2, 3, 5.0);
    let conv = Conventions::ALL[0];
    for opts in objectives() {
        let base = solve(&rotor.session(conv, 1.0, 1.0), &opts).unwrap();
        // Amplitudes alone: the same coefficients per gram times 1000, the
        // same correction, 1000 times the vibration left.
        let amp = solve(&rotor.session(conv, 1000.0, 1.0), &opts).unwrap();
        // Amplitudes and trial masses: the same coefficients, 1000 times the
        // correction.
        let both = solve(&rotor.session(conv, 1000.0, 1000.0), &opts).unwrap();
        for ((b, a), m) in base
            .corrections
            .iter()
            .zip(&amp.corrections)
            .zip(&both.corrections)
        {
            assert!(
                (a.mass_g - b.mass_g).abs() <= 1e-9 * b.mass_g,
                "{opts:?}: {a:?} {b:?}"
            );
            assert!(
                (m.mass_g - 1000.0 * b.mass_g).abs() <= 1e-9 * 1000.0 * b.mass_g,
                "{opts:?}: {m:?} {b:?}"
            );
            assert!(
                same_angle(a.angle_deg, b.angle_deg, 1e-7),
                "{opts:?}: {a:?} {b:?}"
            );
            assert!(
                same_angle(m.angle_deg, b.angle_deg, 1e-7),
                "{opts:?}: {m:?} {b:?}"
            );
        }
        for s in [&amp, &both] {
            let want = 1000.0 * base.summary.max_after;
            assert!(
                (s.summary.max_after - want).abs() <= 1e-9 * want,
                "{opts:?}"
            );
        }
    }
}

#[test]
fn the_ends_of_the_amplitude_range_give_exact_answers() {
    // 1e-9 and 1e9 of the unit are the limits a reading may take: an exact
    // two-plane job scaled to each end gives back its correction.
    let exact = Rotor::random(3, 3, 1, 2, 0.0);
    let conv = Conventions::ALL[3];
    let base = solve(&exact.session(conv, 1.0, 1.0), &SolveOptions::default()).unwrap();
    let biggest = (0..exact.y0.len())
        .flat_map(|a| {
            let mut v = vec![exact.y0[a].norm()];
            for j in 0..exact.w.ncols() {
                v.push((exact.y0[a] + exact.w[(a, j)] * exact.trials[j]).norm());
            }
            v
        })
        .fold(0.0, f64::max);
    let smallest = (0..exact.y0.len())
        .map(|a| exact.y0[a].norm())
        .fold(f64::INFINITY, f64::min);
    for (amp, mass) in [
        (1e9 / biggest, 1.0),
        (1.001e-9 / smallest, 1.0),
        (1e9 / biggest, 1e3),
    ] {
        for opts in objectives() {
            let s = solve(&exact.session(conv, amp, mass), &opts)
                .unwrap_or_else(|e| panic!("×{amp:e}: {e:?}"));
            // Amplitudes alone scale the coefficients, not the correction;
            // trial masses too scale the correction.
            for (got, b) in internal(&s).iter().zip(internal(&base)) {
                let want = b * mass;
                assert!(
                    (got - want).norm() <= 1e-8 * want.norm(),
                    "×{amp:e} {opts:?}: {got} vs {want}"
                );
            }
        }
    }
}

/// The weighted least-squares correction from the readings alone (one
/// trial per plane, so `W = (Y_j − Y_0)/T_j`), by SVD: an independent check
/// of selection and row weights.
fn independent(s: &Session, rows: &[(usize, f64)], planes: &[usize]) -> Vec<Complex64> {
    let conv = s.conventions.unwrap();
    let y = |run: usize, a: usize| {
        let r = &s.runs[run].readings[a];
        reading_in(conv, r.amplitude, r.phase_deg)
    };
    let a = DMatrix::from_fn(rows.len(), planes.len(), |i, k| {
        let (row, g) = rows[i];
        let j = planes[k];
        let t = &s.runs[j + 1].weights[0];
        (y(j + 1, row) - y(0, row)) / weight_in(conv, t.mass_g, t.angle_deg) * g
    });
    let b = DVector::from_fn(rows.len(), |i, _| y(0, rows[i].0) * rows[i].1);
    let x = a.svd(true, true).solve(&(-b), 1e-14).unwrap();
    x.iter().copied().collect()
}

#[test]
fn sensor_selection_row_weights_and_excluded_planes_match_an_independent_weighted_fit() {
    // Two speeds × 3 sensors, 3 planes; rows speed-major (S0..S2 at 1000 rpm,
    // then at 2000 rpm).
    let rotor = Rotor::random(5, 3, 2, 3, 8.0);
    let conv = Conventions::ALL[1];
    let s = rotor.session(conv, 1.0, 1.0);
    // (options, used rows with their weights, planes solved for)
    type Case = (serde_json::Value, Vec<(usize, f64)>, Vec<usize>);
    let cases: Vec<Case> = vec![
        (
            serde_json::json!({}),
            (0..6).map(|a| (a, 1.0)).collect(),
            vec![0, 1, 2],
        ),
        (
            serde_json::json!({"sensors": ["S0", "S2"]}),
            vec![(0, 1.0), (2, 1.0), (3, 1.0), (5, 1.0)],
            vec![0, 1, 2],
        ),
        (
            serde_json::json!({"speeds_rpm": [2000], "planes": ["P0", "P2"]}),
            vec![(3, 1.0), (4, 1.0), (5, 1.0)],
            vec![0, 2],
        ),
        (
            serde_json::json!({"row_weights": [{"sensor": "S1", "weight": 3.0},
                                               {"speed_rpm": 2000, "weight": 0.5},
                                               {"sensor": "S2", "speed_rpm": 1000, "weight": 2.0}]}),
            vec![(0, 1.0), (1, 3.0), (2, 2.0), (3, 0.5), (4, 1.5), (5, 0.5)],
            vec![0, 1, 2],
        ),
    ];
    for (json, rows, planes) in cases {
        let got = solve(&s, &options(json.clone())).unwrap_or_else(|e| panic!("{json}: {e:?}"));
        let want = independent(&s, &rows, &planes);
        assert_eq!(got.corrections.len(), planes.len(), "{json}");
        for (g, w) in internal(&got).iter().zip(&want) {
            assert!((g - w).norm() <= 1e-9 * w.norm(), "{json}: {g} vs {w}");
        }
    }
}

/// A one-plane job on sensors `S0…` whose readings of the zero and trial runs
/// are taken at the given speeds (one per sensor).
fn paired_job(zero: &[f64], trial: &[f64]) -> Result<Solution, fieldbal::balancing::InputError> {
    let reading = |s: usize, rpm: f64, amp: f64, ph: f64| serde_json::json!({"speed_rpm": rpm, "sensor": format!("S{s}"), "amplitude": amp, "phase_deg": ph});
    let session = serde_json::json!({
        "name": "pairing",
        "planes": [{"id": "P0"}],
        "sensors": (0..zero.len()).map(|s| serde_json::json!({"id": format!("S{s}"), "unit": "um_pp"})).collect::<Vec<_>>(),
        "runs": [
            {"id": "zero", "weights": [],
             "readings": zero.iter().enumerate().map(|(s, &v)| reading(s, v, 80.0 + s as f64, 30.0 * s as f64)).collect::<Vec<_>>()},
            {"id": "trial", "weights": [{"plane": "P0", "mass_g": 20.0, "angle_deg": 0.0}],
             "readings": trial.iter().enumerate().map(|(s, &v)| reading(s, v, 50.0 + s as f64, 100.0 + 30.0 * s as f64)).collect::<Vec<_>>()},
        ]
    });
    let session = fieldbal::balancing::parse_session(&serde_json::to_vec(&session).unwrap())?;
    solve(
        &session,
        &options(serde_json::json!({"speeds_rpm": [1000.0]})),
    )
}

/// The sensors in the speed point of 1000 rpm (the job's selection).
fn at_1000(s: &Solution) -> Vec<&str> {
    s.predicted_residual
        .iter()
        .filter(|r| r.used)
        .map(|r| r.sensor.as_str())
        .collect()
}

#[test]
fn speeds_1_percent_apart_pair_and_2_01_percent_apart_do_not_even_through_a_third_sensor() {
    // 1 % apart, either way round, in one run or across runs: one speed
    // point. (Not both ways at once: 990.1 and 1010 rpm would make one point
    // span 2 %, rejected by name.)
    for (zero, trial) in [
        (vec![1000.0, 1010.0], vec![1010.0, 1000.0]),
        (vec![1000.0, 1000.0], vec![1010.0, 1000.0]),
        (vec![1000.0, 1000.0], vec![990.1, 1000.0]),
    ] {
        let s = paired_job(&zero, &trial).unwrap_or_else(|e| panic!("{zero:?} {trial:?}: {e:?}"));
        assert_eq!(at_1000(&s), ["S0", "S1"], "{zero:?} {trial:?}");
    }
    // 2.01 % apart in the reference: two speed points, each sensor at its own.
    let s = paired_job(&[1000.0, 1020.1], &[1000.0, 1020.1]).unwrap();
    assert_eq!(at_1000(&s), ["S0"], "{:?}", s.predicted_residual);
    // A trial reading 2.01 % from its own reference is not that reading.
    let e = paired_job(&[1000.0, 1000.0], &[1000.0, 1020.1]).unwrap_err();
    assert_eq!(
        e.field.as_deref(),
        Some("runs[1].readings[1].speed_rpm"),
        "{e:?}"
    );
    // A third sensor 1 % from each does not bridge them: S0 at 1000 and S2 at
    // 1020.1 stay apart however S1 at 1010 sits between them ...
    let s = paired_job(&[1000.0, 1010.0, 1020.1], &[1000.0, 1010.0, 1020.1]).unwrap();
    assert_eq!(at_1000(&s), ["S0", "S1"], "{:?}", s.predicted_residual);
    // ... and S0's trial reading 1.05 % from its own reference, 0.05 % from
    // S1's, is not paired with S0's reference through S1.
    let e = paired_job(&[1000.0, 1010.0, 1020.1], &[1010.5, 1010.0, 1020.1]).unwrap_err();
    assert_eq!(
        e.field.as_deref(),
        Some("runs[1].readings[0].speed_rpm"),
        "{e:?}"
    );
}

#[test]
fn hostile_numbers_reaching_the_core_give_an_answer_or_a_named_4xx_never_a_panic() {
    // The largest trial mass (1e7 g) moving the readings by the smallest
    // amplitudes, the smallest (1e-6 g) moving them by the largest, and
    // subnormal amplitudes: an answer with finite numbers, or an error that
    // names a field or says why.
    let rotor = Rotor::random(9, 2, 1, 1, 3.0);
    let conv = Conventions::ALL[2];
    let mut cases = Vec::new();
    // Trial 1e7 g with the trial's effect 1e-9 of the readings.
    let mut heavy = rotor.clone();
    heavy.trials = vec![polar(1e7, 33.0)];
    heavy.w *= Complex64::from(1e-9 * rotor.y0.norm() / 1e7);
    cases.push(("heavy trial, tiny effect", heavy.session(conv, 1.0, 1.0)));
    // Trial 1e-6 g moving the readings by 1e8.
    let mut light = rotor.clone();
    light.trials = vec![polar(1e-6, 33.0)];
    light.w *= Complex64::from(1e8 / 1e-6);
    cases.push(("light trial, huge effect", light.session(conv, 1.0, 1.0)));
    // Subnormal amplitudes.
    let mut sub = rotor.session(conv, 1.0, 1.0);
    sub.runs[0].readings[0].amplitude = 1e-310;
    cases.push(("subnormal amplitude", sub));
    for (what, session) in cases {
        for opts in objectives() {
            let opts_bounded = {
                let mut o = opts.clone();
                o.max_mass_g = Some([("P0".to_string(), 1e-3)].into_iter().collect());
                o
            };
            for o in [&opts, &opts_bounded] {
                match std::panic::catch_unwind(|| {
                    fieldbal::balancing::validate_session(&session).and_then(|_| solve(&session, o))
                }) {
                    Err(_) => panic!("{what}: panicked"),
                    Ok(Ok(s)) => {
                        for c in &s.corrections {
                            assert!(
                                c.mass_g.is_finite() && c.angle_deg.is_finite(),
                                "{what}: {c:?}"
                            );
                        }
                        assert!(s.summary.max_after.is_finite(), "{what}");
                    }
                    Ok(Err(e)) => {
                        assert_eq!(
                            e.kind,
                            fieldbal::balancing::ErrorKind::Invalid,
                            "{what}: {e:?}"
                        );
                        assert!(!e.message.is_empty(), "{what}: {e:?}");
                        println!("{what}: {} {:?} {}", e.code, e.field, e.message);
                    }
                }
            }
        }
    }
}
