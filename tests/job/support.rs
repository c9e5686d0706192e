//! A rotor model for the job tests: an exact influence matrix `W` (rows =
//! sensor × speed, columns = planes) and an as-found vibration `Y0`; runs are
//! generated from method 2.1, `Y = Y0 + W T`, written in a session's conventions.
#![allow(dead_code)] // each test binary uses a different part of this module

use fieldbal::balancing::model::{Conventions, SolveOptions};
use fieldbal::balancing::phasor::{reading_in, reading_out, weight_in, weight_out};
use fieldbal::balancing::solution::Correction;
use fieldbal::balancing::{solve, Session, Solution};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};
use serde_json::{json, Value};

pub const SPEEDS: [f64; 2] = [1480.0, 2950.0];
pub const SENSORS: [&str; 2] = ["1H", "2H"];
pub const PLANES: [&str; 2] = ["A", "B"];

/// The model: 4 rows (speed-major, as the core orders them), 2 planes.
pub struct Rotor {
    pub w: DMatrix<Complex64>,
    pub y0: DVector<Complex64>,
}

fn c(a: f64, deg: f64) -> Complex64 {
    Complex64::from_polar(a, deg.to_radians())
}

impl Rotor {
    pub fn new() -> Self {
        let w = DMatrix::from_row_slice(
            4,
            2,
            &[
                c(1.9, 77.0),
                c(0.6, 150.0),
                c(0.7, 210.0),
                c(1.5, 40.0),
                c(3.1, 120.0),
                c(1.2, 260.0),
                c(1.0, 300.0),
                c(2.6, 95.0),
            ],
        );
        let y0 = DVector::from_row_slice(&[
            c(88.0, -47.0),
            c(61.5, 59.0),
            c(120.0, 10.0),
            c(95.0, 200.0),
        ]);
        Rotor { w, y0 }
    }

    /// The same rotor with every coefficient scaled by `factor` (a changed rotor).
    pub fn scaled(&self, factor: f64) -> Self {
        Rotor {
            w: self.w.map(|x| x * factor),
            y0: self.y0.clone(),
        }
    }

    /// The exact least-squares correction `C = −W⁺ Y0` (method 3.2), internal frame.
    pub fn optimum(&self) -> DVector<Complex64> {
        let svd = self.w.clone().svd(true, true);
        svd.solve(&(-&self.y0), 1e-14).unwrap()
    }

    /// Vibration with internal weights `t` on.
    pub fn response(&self, t: &DVector<Complex64>) -> DVector<Complex64> {
        &self.y0 + &self.w * t
    }
}

/// Weights as the session lists them: `[(plane index, mass, angle)]` in `conv`.
pub type Weights = Vec<(usize, f64, f64)>;

pub fn internal(conv: Conventions, weights: &Weights) -> DVector<Complex64> {
    let mut t = DVector::zeros(2);
    for &(j, m, a) in weights {
        t[j] += weight_in(conv, m, a);
    }
    t
}

/// Readings noise: relative amplitude sd `pct` %, phase sd `deg`.
pub struct Noise {
    pub pct: f64,
    pub deg: f64,
    pub rng: StdRng,
}

impl Noise {
    pub fn new(pct: f64, deg: f64, seed: u64) -> Self {
        Noise {
            pct,
            deg,
            rng: StdRng::seed_from_u64(seed),
        }
    }
    pub fn none() -> Self {
        Noise::new(0.0, 0.0, 0)
    }
    fn apply(&mut self, y: Complex64) -> Complex64 {
        if self.pct == 0.0 && self.deg == 0.0 {
            return y;
        }
        let a = Normal::new(0.0, self.pct / 100.0)
            .unwrap()
            .sample(&mut self.rng);
        let p = Normal::new(0.0, self.deg.to_radians())
            .unwrap()
            .sample(&mut self.rng);
        y * (1.0 + a) * Complex64::from_polar(1.0, p)
    }
}

/// A run of `id` with `typed` weights listed, readings from `actual` weights.
pub fn run(
    rotor: &Rotor,
    conv: Conventions,
    id: &str,
    typed: &Weights,
    actual: &Weights,
    noise: &mut Noise,
    runout: &[Complex64],
) -> Value {
    let y = rotor.response(&internal(conv, actual));
    let readings: Vec<Value> = (0..4)
        .map(|a| {
            let v = noise.apply(y[a]) + runout[a % 2];
            let (amplitude, phase) = reading_out(conv, v);
            json!({"speed_rpm": SPEEDS[a / 2], "sensor": SENSORS[a % 2],
                   "amplitude": amplitude, "phase_deg": phase})
        })
        .collect();
    let weights: Vec<Value> = typed
        .iter()
        .map(|&(j, m, a)| json!({"plane": PLANES[j], "mass_g": m, "angle_deg": a}))
        .collect();
    json!({"id": id, "weights": weights, "readings": readings})
}

/// No runout at either sensor.
pub const NO_RUNOUT: [Complex64; 2] = [Complex64::new(0.0, 0.0), Complex64::new(0.0, 0.0)];

/// The zero run and one trial per plane: 40 g at 0° in A, and 40 g typed at
/// 90° in B but put at `90 + typo`.
pub fn first_runs(
    rotor: &Rotor,
    conv: Conventions,
    noise: &mut Noise,
    runout: &[Complex64],
    typo: f64,
) -> Vec<Value> {
    vec![
        run(rotor, conv, "zero", &vec![], &vec![], noise, runout),
        run(
            rotor,
            conv,
            "trial A",
            &vec![(0, 40.0, 0.0)],
            &vec![(0, 40.0, 0.0)],
            noise,
            runout,
        ),
        run(
            rotor,
            conv,
            "trial B",
            &vec![(1, 40.0, 90.0)],
            &vec![(1, 40.0, 90.0 + typo)],
            noise,
            runout,
        ),
    ]
}

pub fn session(conv: Conventions, runs: Vec<Value>) -> Value {
    json!({
        "name": "job", "machine": "ID-FAN-3", "conventions": conv,
        "planes": [{"id": "A", "radius_mm": 350}, {"id": "B", "radius_mm": 350}],
        "sensors": [{"id": "1H", "unit": "um_pp"}, {"id": "2H", "unit": "um_pp"}],
        "runs": runs,
    })
}

pub fn solve_json(session: &Value, options: Value) -> Solution {
    let s: Session = serde_json::from_value(session.clone()).expect("session parses");
    let o: SolveOptions = serde_json::from_value(options).expect("options parse");
    solve(&s, &o).unwrap_or_else(|e| panic!("solve failed: {e:?}"))
}

/// The solution's correction in `plane`.
fn corrected<'a>(s: &'a Solution, plane: &str) -> &'a Correction {
    s.corrections
        .iter()
        .find(|c| c.plane == plane)
        .expect("plane corrected")
}

/// A correction of the solution as an internal weight.
pub fn correction(conv: Conventions, s: &Solution, plane: &str) -> Complex64 {
    let c = corrected(s, plane);
    weight_in(conv, c.mass_g, c.angle_deg)
}

/// A correction's `total` as an internal weight.
pub fn total(conv: Conventions, s: &Solution, plane: &str) -> Complex64 {
    let t = corrected(s, plane)
        .total
        .as_ref()
        .expect("total given with from_run");
    weight_in(conv, t.mass_g, t.angle_deg)
}

/// An internal weight as a typed `(plane, mass, angle)`.
pub fn typed(conv: Conventions, j: usize, w: Complex64) -> (usize, f64, f64) {
    let (m, a) = weight_out(conv, w);
    (j, m, a)
}

pub fn phasor(conv: Conventions, amplitude: f64, phase: f64) -> Complex64 {
    reading_in(conv, amplitude, phase)
}

/// Coefficients `w` (rows × planes, internal frame) as the option
/// `influence_coefficients` lists them, in `conv`; `cov(row, plane)` gives a
/// coefficient's covariance (wire frame, (unit/g)²) or none.
pub fn supplied(
    w: &DMatrix<Complex64>,
    conv: Conventions,
    cov: impl Fn(usize, usize) -> Option<[[f64; 2]; 2]>,
) -> Value {
    let mut out = Vec::new();
    for a in 0..w.nrows() {
        for (j, p) in PLANES.iter().enumerate() {
            let (amp, phase) = reading_out(conv, w[(a, j)]);
            let mut c = json!({"speed_rpm": SPEEDS[a / 2], "sensor": SENSORS[a % 2], "plane": p,
                               "amplitude_per_g": amp, "phase_deg": phase});
            if let Some(m) = cov(a, j) {
                c["covariance"] = json!(m);
            }
            out.push(c);
        }
    }
    Value::Array(out)
}

/// The zero run and, if `trials`, one trial per plane ([`first_runs`], no typo).
pub fn opening_runs(
    rotor: &Rotor,
    conv: Conventions,
    trials: bool,
    noise: &mut Noise,
) -> Vec<Value> {
    if trials {
        return first_runs(rotor, conv, noise, &NO_RUNOUT, 0.0);
    }
    vec![run(
        rotor,
        conv,
        "zero",
        &vec![],
        &vec![],
        noise,
        &NO_RUNOUT,
    )]
}
