//! Property tests of the balancing math on random rotors (proptest): exact
//! recovery, convention independence, kept vs removed trials, and the normal
//! condition of least squares.

use fieldbal::balancing::model::{Conventions, Reading, Run, Session, SolveOptions, Weight};
use fieldbal::balancing::phasor::{reading_in, weight_in, weight_out};
use fieldbal::balancing::{solve, Solution};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use proptest::prelude::*;
use proptest::test_runner::FileFailurePersistence;

#[path = "../common/generated.rs"]
pub(crate) mod generated;

/// A random rotor in the internal frame: influence matrix, as-found unbalance
/// (the correction is its negative), trial weights, and row layout.
#[derive(Debug, Clone)]
struct Rotor {
    sensors: usize,
    w: DMatrix<Complex64>,
    unbalance: DVector<Complex64>,
    trials: DVector<Complex64>,
    /// Extra vibration not explained by the planes (0 for exact data).
    extra: DVector<Complex64>,
}

fn polar() -> impl Strategy<Value = Complex64> {
    (0.2f64..5.0, 0.0f64..std::f64::consts::TAU).prop_map(|(r, t)| Complex64::from_polar(r, t))
}

fn rotor(exact: bool) -> impl Strategy<Value = Rotor> {
    (1usize..=4, 1usize..=4, 1usize..=3).prop_flat_map(move |(planes, sensors, speeds)| {
        let rows = sensors * speeds;
        let sensors = sensors.max(planes.div_ceil(speeds));
        let rows = rows.max(sensors * speeds);
        (
            proptest::collection::vec(polar(), rows * planes),
            proptest::collection::vec((1.0f64..60.0, 0.0f64..360.0), planes),
            proptest::collection::vec((5.0f64..80.0, 0.0f64..360.0), planes),
            proptest::collection::vec(polar(), rows),
        )
            .prop_map(move |(w, u, t, e)| Rotor {
                sensors,
                w: DMatrix::from_vec(rows, planes, w),
                unbalance: DVector::from_iterator(
                    planes,
                    u.iter()
                        .map(|&(m, a)| Complex64::from_polar(m, a.to_radians())),
                ),
                trials: DVector::from_iterator(
                    planes,
                    t.iter()
                        .map(|&(m, a)| Complex64::from_polar(m, a.to_radians())),
                ),
                extra: DVector::from_iterator(
                    rows,
                    e.iter().map(|z| {
                        if exact {
                            Complex64::new(0.0, 0.0)
                        } else {
                            z * 20.0
                        }
                    }),
                ),
            })
    })
}

/// The session a technician would record on `rotor` in conventions `conv`;
/// `kept`: each trial weight stays on for the following runs.
fn session(rotor: &Rotor, conv: Conventions, kept: bool) -> Session {
    let planes = rotor.w.ncols();
    let y0 = &rotor.w * &rotor.unbalance + &rotor.extra;
    let readings = |y: &DVector<Complex64>| -> Vec<Reading> {
        (0..y.len())
            .map(|a| {
                let speed_rpm = 1000.0 * (1 + a / rotor.sensors) as f64;
                generated::reading(conv, speed_rpm, a % rotor.sensors, y[a])
            })
            .collect()
    };
    let weight = |j: usize| {
        let (mass_g, angle_deg) = weight_out(conv, rotor.trials[j]);
        Weight {
            plane: format!("P{j}"),
            mass_g,
            angle_deg,
        }
    };
    let mut runs = vec![Run {
        id: "zero".into(),
        weights: vec![],
        readings: readings(&y0),
        purpose: None,
    }];
    for r in 0..planes {
        let on: Vec<usize> = if kept { (0..=r).collect() } else { vec![r] };
        let mut t = DVector::zeros(planes);
        for &j in &on {
            t[j] = rotor.trials[j];
        }
        runs.push(Run {
            id: format!("trial {r}"),
            weights: on.iter().map(|&j| weight(j)).collect(),
            readings: readings(&(&y0 + &rotor.w * t)),
            purpose: None,
        });
    }
    generated::session(
        "random rotor".into(),
        conv,
        planes,
        None,
        rotor.sensors,
        runs,
    )
}

/// The corrections back in the internal frame.
fn internal_corrections(s: &Solution) -> Vec<Complex64> {
    s.corrections
        .iter()
        .map(|c| weight_in(s.conventions, c.mass_g, c.angle_deg))
        .collect()
}

fn close(a: Complex64, b: Complex64, rel: f64) -> bool {
    (a - b).norm() <= rel * b.norm().max(1e-12)
}

proptest! {
    #![proptest_config(ProptestConfig {
        // Seeds in a file beside this one (the default would look for them
        // beside the binary's main.rs, in tests/proptest-regressions/).
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions"
        ))),
        ..ProptestConfig::with_cases(64)
    })]

    #[test]
    fn noise_free_readings_give_back_the_exact_correction(r in rotor(true), k in 0usize..4) {
        let conv = Conventions::ALL[k];
        let s = solve(&session(&r, conv, false), &SolveOptions::default()).unwrap();
        // Skip nearly singular rotors: their exact answer is not numerically recoverable.
        prop_assume!(s.condition_number < 1e6);
        for (got, u) in internal_corrections(&s).iter().zip(r.unbalance.iter()) {
            prop_assert!(close(*got, -u, 1e-6 * s.condition_number.max(1.0)), "{got} vs {}", -u);
        }
    }

    #[test]
    fn the_four_conventions_give_the_same_physical_correction(r in rotor(false)) {
        let answers: Vec<Vec<Complex64>> = Conventions::ALL
            .iter()
            .map(|&conv| internal_corrections(&solve(&session(&r, conv, false), &SolveOptions::default()).unwrap()))
            .collect();
        for other in &answers[1..] {
            for (a, b) in other.iter().zip(&answers[0]) {
                prop_assert!(close(*a, *b, 1e-8), "{a} vs {b}");
            }
        }
    }

    #[test]
    fn kept_and_removed_trials_give_the_same_influence_coefficients(r in rotor(false), k in 0usize..4) {
        let conv = Conventions::ALL[k];
        let removed = solve(&session(&r, conv, false), &SolveOptions::default()).unwrap();
        let kept = solve(&session(&r, conv, true), &SolveOptions::default()).unwrap();
        for (a, b) in removed.influence_coefficients.iter().zip(&kept.influence_coefficients) {
            let (za, zb) = (reading_in(conv, a.amplitude_per_g, a.phase_deg), reading_in(conv, b.amplitude_per_g, b.phase_deg));
            prop_assert!(close(za, zb, 1e-8), "{za} vs {zb}");
        }
    }

    #[test]
    fn the_least_squares_residual_is_orthogonal_to_the_influence_columns(r in rotor(false), k in 0usize..4) {
        let conv = Conventions::ALL[k];
        let s = solve(&session(&r, conv, false), &SolveOptions::default()).unwrap();
        let rows = s.predicted_residual.len();
        let planes = r.w.ncols();
        let residual: Vec<Complex64> = s.predicted_residual.iter().map(|p| reading_in(conv, p.amplitude, p.phase_deg)).collect();
        let rnorm = residual.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
        // An exact fit leaves a residual of rounding size: measure against the vibration as found.
        let y0norm = s.predicted_residual.iter().map(|p| p.amplitude_before.powi(2)).sum::<f64>().sqrt();
        let scale = rnorm + 1e-3 * y0norm;
        for j in 0..planes {
            let col: Vec<Complex64> = (0..rows).map(|a| {
                let c = &s.influence_coefficients[a * planes + j];
                reading_in(conv, c.amplitude_per_g, c.phase_deg)
            }).collect();
            let cnorm = col.iter().map(|z| z.norm_sqr()).sum::<f64>().sqrt();
            let dot: Complex64 = col.iter().zip(&residual).map(|(w, r)| w.conj() * r).sum();
            prop_assert!(dot.norm() <= 1e-9 * cnorm * scale, "plane {j}: {dot}, |col| {cnorm}, |R| {rnorm}, |Y0| {y0norm}, cond {}", s.condition_number);
        }
    }
}
