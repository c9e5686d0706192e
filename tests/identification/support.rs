//! Test support for identification: sessions generated from Jeffcott
//! (one-mass) rotors, and free decays integrated by RK4 with a small step.
#![allow(dead_code)] // each test binary uses a different part of this module

use fieldbal::balancing::model::{Conventions, Session, Unit};
use fieldbal::balancing::phasor::{reading_out, weight_in};
use fieldbal::identification::rotor::displacement_per_unit;
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};
use serde_json::{json, Value};

/// A Jeffcott rotor: `m z̈ + b ż + c z = D ω² e^{iωt}`, seen by a sensor
/// turned by `sensor_turn` (rad) from the reference mark.
#[derive(Debug, Clone, Copy)]
pub struct Jeffcott {
    pub mass_kg: f64,
    pub stiffness: f64,
    pub damping: f64,
    pub sensor_turn: f64,
}

impl Jeffcott {
    /// With critical speed `rpm` and damping ratio `zeta`.
    pub fn with(mass_kg: f64, rpm: f64, zeta: f64) -> Self {
        let wn = rpm * std::f64::consts::PI / 30.0;
        let stiffness = mass_kg * wn * wn;
        Jeffcott {
            mass_kg,
            stiffness,
            damping: 2.0 * zeta * (stiffness * mass_kg).sqrt(),
            sensor_turn: 0.0,
        }
    }

    pub fn critical_rpm(&self) -> f64 {
        (self.stiffness / self.mass_kg).sqrt() * 30.0 / std::f64::consts::PI
    }

    pub fn zeta(&self) -> f64 {
        self.damping / (2.0 * (self.stiffness * self.mass_kg).sqrt())
    }

    /// Displacement (m, internal frame) for the internal unbalance `u` (kg·m) at `w` (1/s).
    pub fn displacement(&self, u: Complex64, w: f64) -> Complex64 {
        u * w * w * Complex64::from_polar(1.0, -self.sensor_turn)
            / Complex64::new(self.stiffness - self.mass_kg * w * w, w * self.damping)
    }
}

/// A one-plane, one-sensor session of `rotors` (their responses add: several
/// modes) at `speeds_rpm`: the reference run with an original unbalance, and
/// one trial run of 20 g at 30° on a 200 mm radius. Amplitudes get a relative
/// complex noise of `noise` (seeded), in the sensor's `unit`.
pub fn session(
    rotors: &[Jeffcott],
    speeds_rpm: &[f64],
    unit: Unit,
    noise: f64,
    seed: u64,
) -> Session {
    session_with_weights(rotors, speeds_rpm, unit, noise, seed, 12.0, 20.0)
}

/// As [`session`], with an original unbalance of `original_g` (at 250°) and
/// a trial weight of `trial_g` (at 30°), both at 200 mm: a trial small beside
/// the original unbalance gives coefficients noisier than the readings.
pub fn session_with_weights(
    rotors: &[Jeffcott],
    speeds_rpm: &[f64],
    unit: Unit,
    noise: f64,
    seed: u64,
    original_g: f64,
    trial_g: f64,
) -> Session {
    let conv = Conventions::default();
    let radius_mm = 200.0;
    let trial = (trial_g, 30.0);
    // Original unbalance at 200 mm, 250° (session angles).
    let original = weight_in(conv, original_g, 250.0) * radius_mm * 1e-6;
    let trial_u = weight_in(conv, trial.0, trial.1) * radius_mm * 1e-6;
    let mut rng = StdRng::seed_from_u64(seed);
    let gauss = Normal::new(0.0, 1.0).unwrap();
    let mut reading = |u: Complex64, rpm: f64| {
        let w = rpm * std::f64::consts::PI / 30.0;
        let z: Complex64 = rotors.iter().map(|r| r.displacement(u, w)).sum();
        let y = z / displacement_per_unit(unit, w);
        let e =
            Complex64::new(gauss.sample(&mut rng), gauss.sample(&mut rng)) * (noise / 2f64.sqrt());
        let (amplitude, phase_deg) = reading_out(conv, y * (1.0 + e));
        json!({"speed_rpm": rpm, "sensor": "1H", "amplitude": amplitude, "phase_deg": phase_deg})
    };
    let reference: Vec<Value> = speeds_rpm.iter().map(|&s| reading(original, s)).collect();
    let trial_readings: Vec<Value> = speeds_rpm
        .iter()
        .map(|&s| reading(original + trial_u, s))
        .collect();
    // Through JSON, so that fields other helpers add to the model stay at their defaults.
    serde_json::from_value(json!({
        "name": "Jeffcott rotor on the stand",
        "conventions": conv,
        "rotor": {"mass_kg": rotors[0].mass_kg, "service_speed_rpm": 3000.0, "balance_grade": "G2.5"},
        "planes": [{"id": "A", "radius_mm": radius_mm}],
        "sensors": [{"id": "1H", "unit": unit}],
        "runs": [
            {"id": "zero", "weights": [], "readings": reference},
            {"id": "trial", "weights": [{"plane": "A", "mass_g": trial.0, "angle_deg": trial.1}], "readings": trial_readings}
        ]
    }))
    .expect("a valid session")
}

/// `count` speeds evenly from `lo` to `hi` rpm.
pub fn speeds(lo: f64, hi: f64, count: usize) -> Vec<f64> {
    (0..count)
        .map(|i| lo + (hi - lo) * i as f64 / (count - 1) as f64)
        .collect()
}

/// `y'' = f(y, y')` from `(y0, v0)` by classical RK4 with step `h`, sampled
/// every `every` steps, `samples` samples (the first at t = 0).
pub fn rk4_samples(
    f: impl Fn(f64, f64) -> f64,
    y0: f64,
    v0: f64,
    h: f64,
    every: usize,
    samples: usize,
) -> Vec<f64> {
    let (mut y, mut v) = (y0, v0);
    let mut out = Vec::with_capacity(samples);
    out.push(y);
    while out.len() < samples {
        for _ in 0..every {
            let (k1y, k1v) = (v, f(y, v));
            let (k2y, k2v) = (v + 0.5 * h * k1v, f(y + 0.5 * h * k1y, v + 0.5 * h * k1v));
            let (k3y, k3v) = (v + 0.5 * h * k2v, f(y + 0.5 * h * k2y, v + 0.5 * h * k2v));
            let (k4y, k4v) = (v + h * k3v, f(y + h * k3y, v + h * k3v));
            y += h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
            v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        }
        out.push(y);
    }
    out
}

/// Round to `decimals` decimal places.
pub fn round_to(x: f64, decimals: i32) -> f64 {
    let s = 10f64.powi(decimals);
    (x * s).round() / s
}

/// A valid `identify/free-decay` request: a viscous decay, 30 samples.
pub fn free_decay_request() -> Value {
    let samples: Vec<f64> = (0..30)
        .map(|k| (-0.05 * k as f64).exp() * (0.7 * k as f64 + 0.3).cos())
        .collect();
    json!({"samples": samples, "dt_s": 0.05, "damping": "viscous"})
}

/// A valid `identify/model` request: a 2-mass chain, masses known.
pub fn model_request() -> Value {
    json!({
        "mass": {"fixed": [[2.0, 0.0], [0.0, 1.0]]},
        "stiffness": {"fixed": [[0.0, 0.0], [0.0, 0.0]], "parameters": [[[1.0, 0.0], [0.0, 0.0]], [[1.0, -1.0], [-1.0, 1.0]]]},
        "modes": [{"frequency_hz": 4.11, "shape": [0.4, 0.93]}, {"frequency_hz": 10.3, "shape": [0.66, -0.61]}]
    })
}

/// `v` with `change` applied to it.
pub fn with(mut v: Value, change: impl FnOnce(&mut Value)) -> Value {
    change(&mut v);
    v
}

/// A valid `identify/rotor` request (a Jeffcott rotor at 5 speeds, no noise)
/// with `change` applied to it.
pub fn rotor_with(change: impl FnOnce(&mut Value)) -> Value {
    let rotor = Jeffcott::with(100.0, 2000.0, 0.05);
    let s = session(&[rotor], &speeds(1000.0, 3000.0, 5), Unit::UmPp, 0.0, 0);
    with(json!({"session": s, "options": {}}), change)
}
