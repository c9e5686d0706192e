//! `regions_unreliable` beside a small trial (issue 12, session 18;
//! uncertainty/hidden.rs): the planes are solved together, so where one
//! plane's trial is `trial_effect_small` the others' intervals share its
//! error, and on simulated rotors at one to four speeds the planes with no
//! warning of their own beside such a plane held 69–90 % instead of 95 %
//! (scripts/issue12_layouts.py, method §8 "Session 18"). The job then says
//! so; a job whose trials are all large enough does not.

use fieldbal::balancing::model::SolveOptions;
use fieldbal::balancing::uncertainty::CHI2_2_95;
use nalgebra::Vector2;
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::SeedableRng;

use super::rotor_model::{rotor, rotor_with_planes, session};
use super::{estimate, noisy_runs, session_of, solve, LEAD_WITH};

const SPEEDS: [f64; 4] = [1500.0, 2500.0, 3500.0, 4500.0];

/// The warnings of the exact readings of the calibration rotor's planes at
/// nodes 0, 3, 6 over four speeds, trial effects `effects` per plane, the
/// noise stated as 2 %/2°.
fn warnings(effects: [f64; 3]) -> Vec<(String, Option<String>, String)> {
    let r = rotor_with_planes(&SPEEDS, &[0, 3, 6], 1.0);
    let trial: Vec<f64> = r.trial.iter().zip(effects).map(|(t, e)| t * e).collect();
    let y: Vec<Vec<Complex64>> = std::iter::once(r.y0.iter().copied().collect())
        .chain((0..3).map(|j| {
            (0..r.y0.len())
                .map(|a| r.y0[a] + r.w[(a, j)] * trial[j])
                .collect()
        }))
        .collect();
    let session = session_of(
        "small trial",
        4,
        |a| SPEEDS[a / 4],
        LEAD_WITH,
        &trial,
        &y,
        None,
    );
    let options = SolveOptions {
        amplitude_noise_pct: Some(2.0),
        phase_noise_deg: Some(2.0),
        ..SolveOptions::default()
    };
    solve(&session, &options)
        .warnings
        .into_iter()
        .map(|w| (w.code, w.plane, w.message))
        .collect()
}

#[test]
fn a_small_trial_in_one_plane_makes_the_whole_jobs_intervals_unreliable() {
    let got = warnings([0.05, 1.0, 1.0]);
    let small: Vec<_> = got
        .iter()
        .filter(|w| w.0 == "trial_effect_small")
        .map(|w| w.1.as_deref())
        .collect();
    assert_eq!(small, [Some("P0")], "{got:#?}");
    let job = got
        .iter()
        .find(|w| w.0 == "regions_unreliable")
        .unwrap_or_else(|| panic!("no regions_unreliable: {got:#?}"));
    assert_eq!(job.1, None, "{job:?}");
    assert!(
        job.2
            .contains("plane(s) P0 changed the vibration too little")
            && job
                .2
                .contains("the other planes' corrections share that error"),
        "{}",
        job.2
    );
}

#[test]
fn with_every_trial_large_enough_the_job_carries_no_such_warning() {
    let got = warnings([1.0, 1.0, 1.0]);
    assert!(
        got.iter()
            .all(|w| w.0 != "regions_unreliable" && w.0 != "trial_effect_small"),
        "{got:#?}"
    );
}

/// The calibration rotor's ten speeds (tests/uncertainty/eiv.rs).
const TEN_SPEEDS: [f64; 10] = [
    1200.0, 1700.0, 2200.0, 2700.0, 3200.0, 3700.0, 4200.0, 4700.0, 5200.0, 5700.0,
];

/// Noisy jobs for the unwarned planes' test below (its doc).
const REALISATIONS: usize = 3000;

/// Issue 12, points 1 and 4 (method §8, "Session 24"): with 15 % trials at
/// ten speeds the trials sit at the limit of `trial_effect_small` (true `κ`
/// 0.15–0.16 here), and a fifth of the jobs escape the warning with every
/// plane's `κ̂` just under it. The noise that makes a trial look strong
/// (and so passes the test) is the noise that makes the correction and its
/// errors-in-variables estimate short and the ellipse small (session 16's
/// anti-selection): those planes held 91–93 % here (88.5 % on the same
/// rotor in scripts/issue12_table.py). The region of a plane that passed
/// now takes the selection's mean out of its own energy
/// (uncertainty/trust.rs, `selection_stretch`), so the planes that carry
/// no warning hold 95 %.
///
/// Binomial tolerance: a job's three planes err together, so the standard
/// error of the unwarned planes' coverage is the cluster one over jobs
/// (ratio estimator, `sd² = R/(R−1) Σ_r (h_r − p n_r)² / n²`, `h_r`, `n_r`
/// the unwarned hits and checks of job `r`, `n = Σ n_r`), never below the
/// independent-checks binomial `√(0.95·0.05 / n)`. The unwarned checks
/// must hold at least 95 % − 3 sd. About 1,600–1,800 of the 9,000 checks
/// carry no warning and the sd is about 0.7 %: the bar is near 92.9 %.
/// Before session 24 they held 91.3 % (this seed; 91.3–93.0 % over five
/// seeds, failing with each); now 93.7 % (93.7–94.1 % over three). A method
/// whose unwarned planes hold 95 % fails with probability about 0.1 %.
#[test]
fn with_trials_at_the_limit_the_planes_without_a_warning_hold_95_percent() {
    let r = rotor(&TEN_SPEEDS, 0.15);
    let exact = r.readings();
    let options = SolveOptions {
        amplitude_noise_pct: Some(2.0),
        phase_noise_deg: Some(2.0),
        ..SolveOptions::default()
    };
    let mut rng = StdRng::seed_from_u64(1);
    // Per job: (unwarned hits, unwarned checks).
    let mut jobs = Vec::with_capacity(REALISATIONS);
    let mut warned = 0;
    for _ in 0..REALISATIONS {
        let y = noisy_runs(&exact, &mut rng);
        let sol = solve(
            &session(LEAD_WITH, &TEN_SPEEDS, &r.trial, &y, None),
            &options,
        );
        let job_wide = sol.warnings.iter().any(|w| w.code == "regions_unreliable");
        let (mut hits, mut checks) = (0usize, 0usize);
        for j in 0..r.trial.len() {
            let plane = format!("P{j}");
            let named = sol
                .warnings
                .iter()
                .any(|w| w.plane.as_deref() == Some(plane.as_str()));
            if job_wide || named {
                warned += 1;
                continue;
            }
            let (z, cov) = estimate(&sol, j);
            let d = z - r.correction(LEAD_WITH, j);
            let v = Vector2::new(d.re, d.im);
            let inside = cov
                .try_inverse()
                .is_some_and(|inv| (v.transpose() * inv * v)[0] <= CHI2_2_95);
            hits += usize::from(inside);
            checks += 1;
        }
        jobs.push((hits as f64, checks as f64));
    }
    let n: f64 = jobs.iter().map(|j| j.1).sum();
    let held: f64 = jobs.iter().map(|j| j.0).sum();
    eprintln!("unwarned plane-checks {n} holding {held}, warned {warned}");
    if n == 0.0 {
        return;
    }
    let p = held / n;
    let cluster = (jobs.iter().map(|(h, c)| (h - p * c).powi(2)).sum::<f64>()
        * REALISATIONS as f64
        / (REALISATIONS - 1) as f64)
        .sqrt()
        / n;
    let sd = cluster.max((0.95 * 0.05 / n).sqrt());
    assert!(
        p >= 0.95 - 3.0 * sd,
        "the {n} plane-checks without a warning held {:.1} % (sd {:.1} %), {warned} warned",
        100.0 * p,
        100.0 * sd
    );
}
