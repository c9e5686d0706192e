//! A flexible rotor of the tests' own for the calibration of issue 12: seven
//! lumped masses on a shaft with bending stiffness (second differences), on
//! two bearings of different stiffness and damping, light structural damping.
//! Influence coefficients come from the direct complex-stiffness solve
//! `(K(1 + iη) + iωC − ω²M) x = ω² u` at each speed: two rigid-body modes on
//! the bearings and the first bending mode lie in the speed range, so the
//! coefficients change in size and phase from speed to speed. Unbalance sits at
//! every mass, corrections only in three planes: the exact least-squares
//! correction leaves a residual over several speeds and sensors.

use fieldbal::balancing::model::{Conventions, Session};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::Rotor;

const NODES: usize = 7;
/// Correction planes: both ends and the middle.
const PLANES: [usize; 3] = [0, 3, 6];
/// Sensors: at the bearings and between.
const SENSORS: [usize; 4] = [1, 2, 4, 5];
/// Bearings (node, stiffness N/m, damping N·s/m): different stiffness.
const BEARINGS: [(usize, f64, f64); 2] = [(1, 8.0e6, 2.5e3), (5, 3.0e6, 1.5e3)];
const MASS_KG: f64 = 15.0;
const BENDING: f64 = 2.7e7;
const STRUCTURAL_LOSS: f64 = 0.02;
const RADIUS_M: f64 = 0.1;

/// Exact influence coefficients (µm per gram at angle 0 in the internal frame),
/// rows speed-major × sensors, and the reference vibration of the rotor's own
/// unbalance, at each of `speeds_rpm`.
fn response(speeds_rpm: &[f64], planes: &[usize]) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let mut k = DMatrix::<f64>::zeros(NODES, NODES);
    for i in 0..NODES - 2 {
        let d = [(i, 1.0), (i + 1, -2.0), (i + 2, 1.0)];
        for &(a, x) in &d {
            for &(b, y) in &d {
                k[(a, b)] += BENDING * x * y;
            }
        }
    }
    // The rotor's unbalance, g·mm at every mass, in no plane's pattern.
    let u0: Vec<Complex64> = [
        (60.0, 0.3),
        (25.0, 2.0),
        (40.0, 4.1),
        (80.0, 1.1),
        (30.0, 5.5),
        (45.0, 3.0),
        (70.0, 0.9),
    ]
    .iter()
    .map(|&(m, a)| Complex64::from_polar(m, a))
    .collect();
    let rows = speeds_rpm.len() * SENSORS.len();
    let mut w = DMatrix::zeros(rows, planes.len());
    let mut y0 = DVector::zeros(rows);
    for (p, &rpm) in speeds_rpm.iter().enumerate() {
        let om = rpm * std::f64::consts::TAU / 60.0;
        let z = DMatrix::from_fn(NODES, NODES, |a, b| {
            let mut v = Complex64::new(k[(a, b)], k[(a, b)] * STRUCTURAL_LOSS);
            if a == b {
                v -= om * om * MASS_KG;
                for &(node, kb, cb) in &BEARINGS {
                    if node == a {
                        v += Complex64::new(kb, om * cb);
                    }
                }
            }
            v
        });
        let lu = z.lu();
        // µm from a force of ω² × (kg·m) of unbalance.
        let solve = |u_kgm: DVector<Complex64>| {
            lu.solve(&(u_kgm * Complex64::from(om * om))).unwrap() * Complex64::from(1e6)
        };
        let x0 = solve(DVector::from_fn(NODES, |i, _| u0[i] * 1e-9));
        for (s, &node) in SENSORS.iter().enumerate() {
            y0[p * SENSORS.len() + s] = x0[node];
        }
        for (j, &plane) in planes.iter().enumerate() {
            let x = solve(DVector::from_fn(NODES, |i, _| {
                Complex64::from(if i == plane { 1e-3 * RADIUS_M } else { 0.0 })
            }));
            for (s, &node) in SENSORS.iter().enumerate() {
                w[(p * SENSORS.len() + s, j)] = x[node];
            }
        }
    }
    (w, y0)
}

/// The rotor at `speeds_rpm` with trials whose effect is `effect` of the
/// vibration: `‖W_:j‖ m_j = effect · ‖Y0‖`, the change over all sensors and
/// speeds beside the vibration there (root mean square over the rows).
///
/// Not the largest change at any one row (`Rotor::with_trials`): over ten
/// speeds through two resonances that is reached where the rotor hardly
/// vibrates, and a "10 %" trial then changed the median row by 1.2 % — a
/// trial far smaller than it was called, which is why the ten-speed cases
/// looked so much worse than one speed (coverage 14–76 %).
pub fn rotor(speeds_rpm: &[f64], effect: f64) -> Rotor {
    rotor_with_planes(speeds_rpm, &PLANES, effect)
}

/// [`rotor`] with corrections in the planes at the nodes `planes` (0–6)
/// instead of both ends and the middle.
pub fn rotor_with_planes(speeds_rpm: &[f64], planes: &[usize], effect: f64) -> Rotor {
    let (w, y0) = response(speeds_rpm, planes);
    let c = -(w.clone().svd(true, true).solve(&y0, 1e-14).unwrap());
    let trial = (0..w.ncols())
        .map(|j| effect * y0.norm() / w.column(j).norm())
        .collect();
    Rotor { w, c, y0, trial }
}

/// A session of readings `y` (runs × rows, rows speed-major as [`rotor`]),
/// with optional samples `samples[k][a]`.
pub fn session(
    conv: Conventions,
    speeds_rpm: &[f64],
    trial: &[f64],
    y: &[Vec<Complex64>],
    samples: Option<&[Vec<Vec<Complex64>>]>,
) -> Session {
    let n = SENSORS.len();
    let speed_rpm = |a: usize| speeds_rpm[a / n];
    super::session_of("flexible rotor", n, speed_rpm, conv, trial, y, samples)
}
