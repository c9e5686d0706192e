//! A linear rotor on a balancing machine with a known residual unbalance, read
//! with the trial weight at equally spaced positions (issue 17 tests).
#![allow(dead_code)] // each test binary uses a different part

use fieldbal::balancing::acceptance::{PositionReading, ResidualRequest, TrialWeight};
use fieldbal::balancing::model::Conventions;
use fieldbal::balancing::phasor::{reading_out, weight_in};
use num_complex::Complex64;
use rand::{rngs::StdRng, SeedableRng};
use rand_distr::{Distribution, Normal};

/// The rotor: residual `residual_gmm` at `angle_deg` (session direction),
/// machine sensitivity `h` (reading per g·mm, internal frame).
#[derive(Debug, Clone, Copy)]
pub struct Rotor {
    pub residual_gmm: f64,
    pub angle_deg: f64,
    pub h: Complex64,
    pub conv: Conventions,
}

impl Rotor {
    pub fn new(residual_gmm: f64, angle_deg: f64, conv: Conventions) -> Self {
        Rotor {
            residual_gmm,
            angle_deg,
            h: Complex64::from_polar(0.004, 0.7),
            conv,
        }
    }

    /// The internal residual unbalance vector.
    pub fn u(&self) -> Complex64 {
        weight_in(self.conv, self.residual_gmm, self.angle_deg)
    }
}

/// What the journal load and speed give: 6350·530.7/9000 ≈ 374.4 g·mm allowable.
pub const LOAD_KG: f64 = 530.7;
pub const SPEED_RPM: f64 = 9000.0;
pub const RADIUS_MM: f64 = 150.0;

pub fn allowable() -> f64 {
    6350.0 * LOAD_KG / SPEED_RPM
}

/// Readings with the trial unbalance `trial_gmm` at `n` positions from 0°,
/// with phases or not, and optionally 2 % / 2° reading noise from `seed`.
pub fn request(
    rotor: &Rotor,
    trial_gmm: f64,
    n: usize,
    phases: bool,
    noise_seed: Option<u64>,
) -> ResidualRequest {
    let mut rng = noise_seed.map(StdRng::seed_from_u64);
    let normal = Normal::new(0.0, 1.0).unwrap();
    let readings = (0..n)
        .map(|k| {
            let angle = 360.0 * k as f64 / n as f64;
            let v = rotor.h * (rotor.u() + weight_in(rotor.conv, trial_gmm, angle));
            let (mut a, mut p) = reading_out(rotor.conv, v);
            if let Some(rng) = rng.as_mut() {
                a *= 1.0 + 0.02 * normal.sample(rng);
                p += 2.0 * normal.sample(rng);
            }
            PositionReading {
                angle_deg: angle,
                amplitude: a,
                phase_deg: phases.then_some(p),
            }
        })
        .collect();
    ResidualRequest {
        plane: Some("A".into()),
        speed_rpm: SPEED_RPM,
        trial: TrialWeight {
            mass_g: trial_gmm / RADIUS_MM,
            radius_mm: RADIUS_MM,
        },
        journal_load_kg: LOAD_KG,
        readings,
        conventions: Some(rotor.conv),
        amplitude_noise_pct: None,
        phase_noise_deg: None,
    }
}
