//! Uncertainty of corrections and residuals (issue 6): calibration of the 95 %
//! regions on noisy realisations of a known rotor, the single-plane 4 % check,
//! Monte Carlo and finite differences against the linearised covariance,
//! samples instead of options, the noise side of `trial_effect_small`, and
//! invalid noise options. This file holds the generated rotor and sessions.

mod calibration;
mod dependent_planes;
mod eiv;
mod few_speeds;
mod linearisation;
mod noise_options;
mod rotor_model;
mod small_trial;
mod undetermined;

#[path = "../common/generated.rs"]
mod generated;

use fieldbal::balancing::model::{
    AngleDirection, Conventions, PhaseConvention, Reading, Run, Sample, Session, SolveOptions,
    Weight,
};
use fieldbal::balancing::phasor::{reading_out, weight_in, weight_out};
use fieldbal::balancing::uncertainty::CHI2_2_95;
use fieldbal::balancing::{self, Solution};
use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;
use rand_distr::{Distribution, Normal};

pub fn c(re: f64, im: f64) -> Complex64 {
    Complex64::new(re, im)
}

pub const LAG_AGAINST: Conventions = Conventions {
    phase: PhaseConvention::Lag,
    angle_direction: AngleDirection::AgainstRotation,
};
pub const LEAD_WITH: Conventions = Conventions {
    phase: PhaseConvention::Lead,
    angle_direction: AngleDirection::WithRotation,
};

/// A known rotor: exact influence matrix `w` (rows × planes, internal frame),
/// exact correction `c`, reference vibration `y0 = −W c + r⊥` with a part `r⊥`
/// no correction can cancel (so the least-squares residual is not zero), and
/// one trial run per plane of mass `trial[j]` at angle 0.
pub struct Rotor {
    pub w: DMatrix<Complex64>,
    pub c: DVector<Complex64>,
    pub y0: DVector<Complex64>,
    pub trial: Vec<f64>,
}

impl Rotor {
    /// Two planes seen by four rows (two sensors at two speeds).
    pub fn two_plane(trial_effect: f64) -> Rotor {
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
    pub fn with_trials(
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
    pub fn readings(&self) -> Vec<Vec<Complex64>> {
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
    pub fn correction(&self, conv: Conventions, j: usize) -> Complex64 {
        let (m, deg) = weight_out(conv, self.c[j]);
        Complex64::from_polar(m, deg.to_radians())
    }
}

/// Solve one realisation of `exact` (runs × rows) read with the default
/// noise model (2 %, 2°) in conventions `conv`.
pub fn solve_noisy(
    rotor: &Rotor,
    exact: &[Vec<Complex64>],
    conv: Conventions,
    rng: &mut StdRng,
) -> Solution {
    let y = noisy_runs(exact, rng);
    solve(
        &session(conv, &rotor.trial, &y, None),
        &SolveOptions::default(),
    )
}

/// A session of these readings (runs × rows); `samples[k][a]` optionally lists repeated readings.
pub fn session(
    conv: Conventions,
    trial: &[f64],
    y: &[Vec<Complex64>],
    samples: Option<&[Vec<Vec<Complex64>>]>,
) -> Session {
    let speed_rpm = |a: usize| if a < 2 { 1500.0 } else { 3000.0 };
    session_of(
        "generated",
        2.min(y[0].len()),
        speed_rpm,
        conv,
        trial,
        y,
        samples,
    )
}

/// A session named `name` of readings `y` (runs × rows): row `a` is sensor
/// `S{a % sensors}` at `speed_rpm(a)`; run 0 is the reference, run `k` has
/// trial `trial[k − 1]` at 0° in plane `P{k − 1}`; `samples[k][a]` optionally
/// lists repeated readings.
pub fn session_of(
    name: &str,
    sensors: usize,
    speed_rpm: impl Fn(usize) -> f64,
    conv: Conventions,
    trial: &[f64],
    y: &[Vec<Complex64>],
    samples: Option<&[Vec<Vec<Complex64>>]>,
) -> Session {
    let reading = |k: usize, a: usize| {
        reading_of(
            conv,
            speed_rpm(a),
            a % sensors,
            y[k][a],
            samples.map(|s| &s[k][a][..]),
        )
    };
    let run = |k: usize| Run {
        id: format!("run {k}"),
        weights: match k {
            0 => vec![],
            _ => vec![Weight {
                plane: format!("P{}", k - 1),
                mass_g: trial[k - 1],
                angle_deg: 0.0,
            }],
        },
        readings: (0..y[0].len()).map(|a| reading(k, a)).collect(),
        purpose: None,
    };
    let runs = (0..y.len()).map(run).collect();
    generated::session(name.into(), conv, trial.len(), None, sensors, runs)
}

/// The reading of sensor `S{sensor}` at `speed_rpm`: phasor `y` (internal
/// frame) and, if given, its samples, in the conventions `conv`.
pub fn reading_of(
    conv: Conventions,
    speed_rpm: f64,
    sensor: usize,
    y: Complex64,
    samples: Option<&[Complex64]>,
) -> Reading {
    Reading {
        samples: samples.map(|zs| {
            zs.iter()
                .map(|&z| {
                    let (amplitude, phase_deg) = reading_out(conv, z);
                    Sample {
                        amplitude,
                        phase_deg,
                    }
                })
                .collect()
        }),
        ..generated::reading(conv, speed_rpm, sensor, y)
    }
}

/// A reading with independent radial noise (`pct` % of its amplitude) and
/// tangential noise (`deg` degrees), the options' noise model.
pub fn noisy(y: Complex64, pct: f64, deg: f64, rng: &mut StdRng) -> Complex64 {
    let n = Normal::new(0.0, 1.0).unwrap();
    y * c(
        1.0 + pct / 100.0 * n.sample(rng),
        deg.to_radians() * n.sample(rng),
    )
}

/// Each exact reading of each run with 2 % / 2° noise (`noisy`), drawn in
/// run and row order.
pub fn noisy_runs(exact: &[Vec<Complex64>], rng: &mut StdRng) -> Vec<Vec<Complex64>> {
    exact
        .iter()
        .map(|run| run.iter().map(|&z| noisy(z, 2.0, 2.0, rng)).collect())
        .collect()
}

pub fn solve(s: &Session, options: &SolveOptions) -> Solution {
    balancing::solve(s, options).expect("generated sessions solve")
}

/// The share of `sol`'s rows whose `amplitude_95` holds the vibration that
/// really remains on the rotor (`w`, `y0`, internal frame) once its
/// corrections are fitted.
pub fn remaining_held(
    sol: &Solution,
    conv: Conventions,
    w: &DMatrix<Complex64>,
    y0: &DVector<Complex64>,
) -> f64 {
    let fitted = DVector::from_fn(sol.corrections.len(), |j, _| {
        let c = &sol.corrections[j];
        weight_in(conv, c.mass_g, c.angle_deg)
    });
    let actual = y0 + w * fitted;
    let held = sol
        .predicted_residual
        .iter()
        .enumerate()
        .filter(|(a, r)| actual[*a].norm() <= r.amplitude_95.unwrap())
        .count();
    held as f64 / sol.predicted_residual.len() as f64
}

/// Correction of plane `j` as `m e^{iθ}` and its covariance, session frame.
pub fn estimate(s: &Solution, j: usize) -> (Complex64, Matrix2<f64>) {
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
pub fn coverage(rotor: &Rotor, conv: Conventions, realisations: usize, seed: u64) -> Vec<f64> {
    let mut rng = StdRng::seed_from_u64(seed);
    let exact = rotor.readings();
    let mut hits = vec![0usize; rotor.trial.len()];
    for _ in 0..realisations {
        let sol = solve_noisy(rotor, &exact, conv, &mut rng);
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
