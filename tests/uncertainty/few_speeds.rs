//! `amplitude_95` at a few speeds, one of them far below the others (issue
//! 12, session 15): the low speed's readings are small and, the noise being
//! relative, precise, so the all-rows conditioning (method 8.8) recovers
//! the correction's error, bias included, from the predictions, and the
//! bias move (8.12) must not be added on top of it (remaining/fitted.rs).
//! Before session 15 the bound held 88.2 % and 89.0 % here at 10 % and 30 %
//! trials (96.2 % at 100 %), and 78–86 % on the held-out rotor of
//! scripts/coverage_heldout.py at 1000/2750/4500 rpm. Now the bound is the
//! larger of the moved and the unmoved one, and it errs the other way here:
//! 97.9–98.4 %. The test holds the side that is false precision: never
//! below the window (93 % less three cluster standard errors, as eiv.rs);
//! the over-coverage was stated, not held (method §8, session 15). Since
//! session 24 (the de-noised conditioning, remaining/denoise.rs) it was
//! 98.8, 97.9 and 96.0 %, and since session 25 (Fuller's small-sample
//! modification there) 97.3, 97.3 and 95.9 %; the upper side is held at 10
//! and 100 % trials.
//!
//! The rotor is a third one, modal like the held-out rotor but not it:
//! three modes (1200, 3100, 6000, damping 4–7 %), sensors near each end in
//! two directions of different stiffness, planes at 0.15, 0.5, 0.85 of the
//! length, unbalance at the planes and between them. Three modes and three
//! planes: the exact correction leaves no residual. Speeds 600, 2200 and
//! 3800 (the vibration 7.7, 153 and 958 over the four sensors), trials of
//! 10, 30 and 100 % of the vibration (masses at angle 0), 2 %/2° stated,
//! 400 realisations. A correct bound (true coverage 93 % or more) fails
//! with probability below 0.14 %; the old one (88–89 %, cluster sd 0.7–0.8
//! %) fails with certainty. The ellipses are printed, not held: 91.1–99.3 %
//! here (method §8, session 15, "few speeds").

use fieldbal::balancing::model::SolveOptions;
use fieldbal::balancing::uncertainty::CHI2_2_95;
use nalgebra::{DMatrix, DVector, Vector2};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;

use super::eiv::{coverage, in_window};
use super::{estimate, noisy_runs, remaining_held, session_of, solve, LEAD_WITH};

const SPEEDS: [f64; 3] = [600.0, 2200.0, 3800.0];
const REALISATIONS: usize = 400;
/// Sensor stations (fraction of the length) and the stiffness factor of each direction.
const SENSORS: [(f64, f64); 4] = [(0.1, 1.0), (0.1, 1.25), (0.9, 1.0), (0.9, 1.15)];
/// Modes: natural frequency (in the speeds' unit) and damping ratio.
const MODES: [(f64, f64); 3] = [(1200.0, 0.04), (3100.0, 0.06), (6000.0, 0.07)];
const PLANES: [f64; 3] = [0.15, 0.5, 0.85];

fn shape(k: usize, z: f64) -> f64 {
    ((k + 1) as f64 * std::f64::consts::PI * (z + 0.15) / 1.3).sin()
}

/// Response at each sensor and speed (rows speed-major) to a unit unbalance at `z`.
fn column(z: f64) -> Vec<Complex64> {
    let mut out = Vec::new();
    for &speed in &SPEEDS {
        for &(zs, stiff) in &SENSORS {
            out.push(
                MODES
                    .iter()
                    .enumerate()
                    .map(|(k, &(f, damping))| {
                        let w = f * stiff;
                        let den = Complex64::new(w * w - speed * speed, 2.0 * damping * w * speed);
                        shape(k, zs) * shape(k, z) * speed * speed / den
                    })
                    .sum(),
            );
        }
    }
    out
}

/// The exact coefficients, the reference vibration and the trial masses for `effect`.
fn rotor(effect: f64) -> (DMatrix<Complex64>, DVector<Complex64>, Vec<f64>) {
    let cols: Vec<Vec<Complex64>> = PLANES.iter().map(|&z| column(z)).collect();
    let rows = cols[0].len();
    let w = DMatrix::from_fn(rows, PLANES.len(), |a, j| cols[j][a]);
    let at =
        |z: f64, m: f64, phase: f64| DVector::from_vec(column(z)) * Complex64::from_polar(m, phase);
    let y0 = at(0.15, 40.0, 0.7)
        + at(0.5, 40.0, 2.9)
        + at(0.85, 40.0, 5.1)
        + at(0.3, 20.0, 1.9)
        + at(0.7, 20.0, 4.4);
    let trial = (0..PLANES.len())
        .map(|j| effect * y0.norm() / w.column(j).norm())
        .collect();
    (w, y0, trial)
}

/// Per realisation of the job (`w`, `y0`, `trial` at `speeds`, rows
/// speed-major over [`SENSORS`]), the share of rows whose bound held and of
/// planes whose ellipse did.
fn run(
    job: (DMatrix<Complex64>, DVector<Complex64>, Vec<f64>),
    speeds: &[f64],
    seed: u64,
) -> (Vec<f64>, Vec<f64>) {
    run_n(job, speeds, seed, REALISATIONS)
}

/// [`run`] with `realisations` noisy jobs.
fn run_n(
    (w, y0, trial): (DMatrix<Complex64>, DVector<Complex64>, Vec<f64>),
    speeds: &[f64],
    seed: u64,
    realisations: usize,
) -> (Vec<f64>, Vec<f64>) {
    let c = -(w.clone().svd(true, true).solve(&y0, 1e-14).unwrap());
    let exact: Vec<Vec<Complex64>> = std::iter::once(y0.iter().copied().collect())
        .chain((0..trial.len()).map(|j| {
            (0..y0.len())
                .map(|a| y0[a] + w[(a, j)] * trial[j])
                .collect()
        }))
        .collect();
    let options = SolveOptions {
        amplitude_noise_pct: Some(2.0),
        phase_noise_deg: Some(2.0),
        ..SolveOptions::default()
    };
    let mut rng = StdRng::seed_from_u64(seed);
    let (mut rows, mut planes) = (Vec::new(), Vec::new());
    for _ in 0..realisations {
        let y = noisy_runs(&exact, &mut rng);
        let speed = |a: usize| speeds[a / SENSORS.len()];
        let session = session_of(
            "few speeds",
            SENSORS.len(),
            speed,
            LEAD_WITH,
            &trial,
            &y,
            None,
        );
        let sol = solve(&session, &options);
        rows.push(remaining_held(&sol, LEAD_WITH, &w, &y0));
        let inside = (0..trial.len())
            .filter(|&j| {
                let (z, cov) = estimate(&sol, j);
                let (m, deg) = fieldbal::balancing::phasor::weight_out(LEAD_WITH, c[j]);
                let d = z - Complex64::from_polar(m, deg.to_radians());
                let v = Vector2::new(d.re, d.im);
                cov.try_inverse()
                    .is_some_and(|inv| (v.transpose() * inv * v)[0] <= CHI2_2_95)
            })
            .count();
        planes.push(inside as f64 / trial.len() as f64);
    }
    (rows, planes)
}

#[test]
fn at_three_speeds_one_far_below_the_others_amplitude_95_holds_at_least_95_percent() {
    let mut failures = Vec::new();
    for (case, effect) in [0.1, 0.3, 1.0].into_iter().enumerate() {
        let (rows, planes) = run(rotor(effect), &SPEEDS, 300 + case as u64);
        let a = coverage(&rows, SENSORS.len() * SPEEDS.len());
        let e = coverage(&planes, PLANES.len());
        eprintln!(
            "3 speeds, trial {:.0} %: amplitude_95 {:.3} ± {:.3}, ellipse {:.3} ± {:.3} (not held)",
            effect * 100.0,
            a.0,
            a.1,
            e.0,
            e.1
        );
        // Not below the window: `in_window`'s lower edge, 93 % − 3 sd.
        if a.0 < 0.93 - 3.0 * a.1 {
            failures.push(format!("trial {effect}: amplitude_95 {a:?}"));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The upper side at 100 % trials, where the trial runs carry as much
/// vibration as the rotor: the bound must not be wider than the window
/// allows (`in_window`'s upper edge, 97 % + 3 sd). The bound before
/// session 24's de-noised conditioning (the larger of the moved and the
/// unmoved one) held 98.4 ± 0.3 % here; the de-noised conditioning with
/// the product term split along the row's own error (remaining/denoise.rs;
/// method §8, session 24, amp24b's form (7)) holds 96.0 ± 0.5 %. The same
/// realisations as the 100 % case above (seed 302).
#[test]
fn at_three_speeds_with_full_size_trials_amplitude_95_is_not_wider_than_the_window() {
    let (rows, _) = run(rotor(1.0), &SPEEDS, 302);
    let a = coverage(&rows, SENSORS.len() * SPEEDS.len());
    eprintln!(
        "3 speeds, trial 100 %: amplitude_95 {:.3} ± {:.3}",
        a.0, a.1
    );
    assert!(a.0 <= 0.97 + 3.0 * a.1, "amplitude_95 {a:?}");
}

/// The upper side at 10 % trials, where the coefficients are noisiest: the
/// bound must not be wider than the window allows (97 % + 3 sd, about
/// 97.9 %). The de-noised conditioning of session 24 held 98.8 ± 0.3 % here:
/// Fuller's corrected estimator has no finite moments where the de-noised
/// Gram `G − N` is near singular, and where it is not positive definite the
/// bound fell back to the conditioning with `Ŵ` known and the larger of the
/// moved and unmoved bound. With Fuller's small-sample modification
/// (remaining/denoise.rs; method §8, session 25, amp25) 97.3 ± 0.3 %. The
/// same realisations as the 10 % case above (seed 300).
#[test]
fn at_three_speeds_with_small_trials_amplitude_95_is_not_wider_than_the_window() {
    let (rows, _) = run(rotor(0.1), &SPEEDS, 300);
    let a = coverage(&rows, SENSORS.len() * SPEEDS.len());
    eprintln!("3 speeds, trial 10 %: amplitude_95 {:.3} ± {:.3}", a.0, a.1);
    assert!(a.0 <= 0.97 + 3.0 * a.1, "amplitude_95 {a:?}");
}

/// The ellipses at few speeds on the calibration rotor of eiv.rs
/// (tests/uncertainty/rotor_model.rs, four sensors as here), trials of 10 %
/// and 30 %, held in eiv.rs's window (93–97 % widened by three cluster
/// standard errors) on both sides. At four speeds 1500–4500 rpm with 10 %
/// trials the errors-in-variables estimate `C*` is itself 0.75–0.89 sd short
/// (the fixed point of 8.3 does not contract: `‖B‖₂` 0.5–2.2). The region
/// (8.11) through the bias map held 82.5 % here before session 15 and 93.0 %
/// with the simpler form where `‖B‖₂` reached the contraction limit (three
/// speeds 91.5 % and 94.5 %, four at 30 % 91.7 %: the lower side only was
/// held then). Since session 18 the simpler form is the only one
/// (bias/region.rs): three speeds 94.0 % and 95.3 %, four 95.0 % and 95.2 %.
#[test]
fn at_three_and_four_speeds_the_ellipses_hold_95_percent() {
    let mut failures = Vec::new();
    let sets: [&[f64]; 2] = [&[1500.0, 3000.0, 4500.0], &[1500.0, 2500.0, 3500.0, 4500.0]];
    for (k, speeds) in sets.into_iter().enumerate() {
        for (case, effect) in [0.1, 0.3].into_iter().enumerate() {
            let r = super::rotor_model::rotor(speeds, effect);
            let seed = 400 + 10 * k as u64 + case as u64;
            let (_, planes) = run((r.w, r.y0, r.trial), speeds, seed);
            let e = coverage(&planes, 3);
            eprintln!(
                "{} speeds, trial {:.0} %: ellipse {:.3} ± {:.3}",
                speeds.len(),
                effect * 100.0,
                e.0,
                e.1
            );
            if !in_window(e) {
                failures.push(format!(
                    "{} speeds, trial {effect}: ellipse {e:?}",
                    speeds.len()
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}

/// The ellipses at four speeds (1500–4500 rpm) on three plane layouts of
/// the calibration rotor where the sensors see the planes partly alike (own
/// shares 0.19–0.48): planes at nodes 1, 3, 5 with 100 % trials, at 1, 4, 6
/// with 50 % and at 0, 3, 6 with 50 %, 1,000 realisations each. Pooled over
/// the three cases they must lie in eiv.rs's window widened by three pooled
/// standard errors, and each case above 93 % less three of its own. The
/// region through the bias map (8.11, sessions 13–17) held 92.7 ± 0.7, 90.1
/// ± 0.8 and 93.5 ± 0.6 % here (scripts/issue12_layouts.py, 200
/// realisations: 88.5–90.5, 89.5–92.5 and 90–92.5 % per plane, no warning
/// on a quarter to a third of the first case's planes), and fails the
/// second case (floor 90.5 %). Since session 18 the region is `(1 + κ)
/// Σ(C*) + b̂ b̂ᵀ` at every job (bias/region.rs): 95.6, 94.3 and 95.6 %,
/// pooled 95.1 ± 0.3 %.
#[test]
fn at_four_speeds_on_planes_seen_partly_alike_the_ellipses_hold_95_percent() {
    const N: usize = 1000;
    let speeds = [1500.0, 2500.0, 3500.0, 4500.0];
    let cases = [([1, 3, 5], 1.0), ([1, 4, 6], 0.5), ([0, 3, 6], 0.5)];
    let mut failures = Vec::new();
    let mut pooled = (0.0, 0.0);
    for (case, (planes, effect)) in cases.into_iter().enumerate() {
        let r = super::rotor_model::rotor_with_planes(&speeds, &planes, effect);
        let (_, held) = run_n((r.w, r.y0, r.trial), &speeds, 450 + case as u64, N);
        let e = coverage(&held, 3);
        eprintln!(
            "planes at nodes {planes:?}, trial {effect}: ellipse {:.3} ± {:.3}",
            e.0, e.1
        );
        if e.0 < 0.93 - 3.0 * e.1 {
            failures.push(format!("nodes {planes:?}, trial {effect}: ellipse {e:?}"));
        }
        pooled.0 += e.0 / cases.len() as f64;
        pooled.1 += (e.1 / cases.len() as f64).powi(2);
    }
    let pooled = (pooled.0, pooled.1.sqrt());
    eprintln!("pooled: ellipse {:.4} ± {:.4}", pooled.0, pooled.1);
    if !in_window(pooled) {
        failures.push(format!("pooled: ellipse {pooled:?}"));
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
