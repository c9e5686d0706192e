//! The trim of tests/job/trim_supplied.rs: a session whose run "check" has
//! weights on, what supplied coefficients imply for that state, and readers
//! of a solution's corrections and covariances.

use crate::support::*;
use fieldbal::balancing::model::Conventions;
use fieldbal::balancing::Solution;
use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;
use serde_json::{json, Value};

/// The weights on the rotor in run "check": the exact correction fitted 40 %
/// short and 25° off, and a 5 g weight left in plane A (two weights in A).
pub fn on_weights(rotor: &Rotor, conv: Conventions) -> Weights {
    let best = rotor.optimum();
    let off = Complex64::from_polar(0.6, 25f64.to_radians());
    vec![
        typed(conv, 0, best[0] * off),
        (0, 5.0, 130.0),
        typed(conv, 1, best[1] * off),
    ]
}

/// The reference run, the trials of support.rs if `trials`, and run "check".
pub fn trim_session(rotor: &Rotor, conv: Conventions, trials: bool) -> Value {
    let mut n = Noise::none();
    let mut runs = opening_runs(rotor, conv, trials, &mut n);
    let on = on_weights(rotor, conv);
    runs.push(run(rotor, conv, "check", &on, &on, &mut n, &NO_RUNOUT));
    session(conv, runs)
}

/// What coefficients `w` imply from the state of run "check" (weights `t` on,
/// readings `Y_r = Y0 + W_rotor t`): `(C, T_r + C)` with `C = −w⁺ Y_r`.
pub fn implied(
    rotor: &Rotor,
    w: &DMatrix<Complex64>,
    t: &DVector<Complex64>,
) -> (DVector<Complex64>, DVector<Complex64>) {
    let y_r = rotor.response(t);
    let add = w.clone().svd(true, true).solve(&(-y_r), 1e-14).unwrap();
    let total = t + &add;
    (add, total)
}

/// Coefficients the rotor does not have: each scaled and turned differently.
pub fn skewed(w: &DMatrix<Complex64>) -> DMatrix<Complex64> {
    DMatrix::from_fn(w.nrows(), w.ncols(), |a, j| {
        let k = (a + 2 * j) as f64;
        w[(a, j)] * Complex64::from_polar(1.0 + 0.2 * k.sin(), 0.3 * (a as f64 - j as f64))
    })
}

pub fn near(a: Complex64, b: Complex64, scale: f64) -> bool {
    (a - b).norm() <= 1e-9 * scale
}

pub fn assert_trim(
    conv: Conventions,
    sol: &Solution,
    add: &DVector<Complex64>,
    total_: &DVector<Complex64>,
) {
    let scale = add.norm() + total_.norm();
    for (j, p) in PLANES.iter().enumerate() {
        let (c, t) = (correction(conv, sol, p), total(conv, sol, p));
        assert!(
            near(c, add[j], scale),
            "{conv:?} {p}: add {c} vs {}",
            add[j]
        );
        assert!(
            near(t, total_[j], scale),
            "{conv:?} {p}: total {t} vs {}",
            total_[j]
        );
    }
}

/// A correction as the vector `covariance_g2` describes: real axis at 0°,
/// imaginary at 90° in the session's angle direction.
pub fn vector(sol: &Solution, j: usize) -> Complex64 {
    let c = &sol.corrections[j];
    Complex64::from_polar(c.mass_g, c.angle_deg.to_radians())
}

pub fn covariance(sol: &Solution, j: usize) -> Matrix2<f64> {
    let m = sol.corrections[j]
        .uncertainty
        .as_ref()
        .expect("uncertainty given")
        .covariance_g2;
    Matrix2::new(m[0][0], m[0][1], m[1][0], m[1][1])
}

/// The trim with `list` as `influence_coefficients`.
pub fn trim_with(s: &Value, list: &Value) -> Solution {
    solve_json(
        s,
        json!({"from_run": "check", "influence_coefficients": list}),
    )
}

/// The coefficients of a stored version as a matrix (rows as support.rs's).
pub fn matrix_of(list: &Value, conv: Conventions) -> DMatrix<Complex64> {
    let mut w = DMatrix::zeros(4, 2);
    for c in list.as_array().unwrap() {
        let s = SENSORS.iter().position(|s| *s == c["sensor"]).unwrap();
        let p = SPEEDS
            .iter()
            .position(|v| *v == c["speed_rpm"].as_f64().unwrap())
            .unwrap();
        let j = PLANES.iter().position(|p| *p == c["plane"]).unwrap();
        let (amp, phase) = (
            c["amplitude_per_g"].as_f64().unwrap(),
            c["phase_deg"].as_f64().unwrap(),
        );
        w[(2 * p + s, j)] = phasor(conv, amp, phase);
    }
    w
}
