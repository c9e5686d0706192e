//! Issue 12, item 1, nearly dependent planes at one speed: the flexible rotor
//! of `rotor_model` read at 3000 rpm by four sensors, with corrections at
//! nodes where two planes look nearly alike to the sensors. Noise stated
//! (2 %, 2°), 400 realisations per trial effect (30 % and 100 %); measured
//! per plane: the share of 95 % ellipses holding the exact correction and the
//! mean squared Mahalanobis distance of the error in the reported covariance
//! (2 when calibrated; less when too wide, more when too narrow).
//!
//! Two fixtures, both with condition number 30–50, and opposite failures
//! (measured at main 43a89b6, per plane):
//!
//! - nodes 0, 1, 6 (P0, P1 adjacent; condition 33.8, residual 0.9 % of the
//!   vibration): 98.5–99.8 % in P0, P1 (Mahalanobis² 0.55–1.14), 96.5–98.8 %
//!   in P2: over-cautious, like planes P0, P2 of the held-out rotor of
//!   scripts/coverage_heldout.py (99.3–100 %, residual exactly 0 there);
//! - nodes 1, 2, 4 (condition 32.5, residual 5.1 %): 61–83 % over two seeds
//!   (Mahalanobis² 3.1–6.7): too narrow; nodes 0, 3, 4 (27.9, 3.8 %) 75–88 %.
//!
//! So the first-order ellipse fails both ways along the weak direction of
//! `A`, and the residual decides which: method 8.4, "Nearly dependent
//! planes", gives the diagnosis and why replacing the fitted residual in the
//! second term of (8.2) is not the fix.
//!
//! Session 9 (method §8, same paragraph; scripts/issue12_weak_direction.py)
//! inverted tests instead: Kleibergen's K statistic holds 93–97 % per plane
//! on both fixtures and the held-out rotor, but its regions, like the score's
//! and the profile likelihood ratio's, are unbounded in most realisations
//! (Gleser & Hwang 1987), and the factor the ellipse itself would need
//! (0.23–0.87 here, 1.3–3.7 on the large-residual fixture) cannot be read
//! from the readings at 30 % trials. So no ellipse is calibrated on both
//! fixtures at once; the window test stays ignored as the open target.
//!
//! Measurement mode until the fix lands: what holds today and must keep
//! holding is asserted (the fixture is what it says; with the small residual
//! no plane falls below 93 %); the full 93–97 % window on both fixtures is the
//! ignored test, which fails today (`cargo test --release --test uncertainty
//! dependent -- --nocapture --include-ignored` prints the figures).

use fieldbal::balancing::model::SolveOptions;
use fieldbal::balancing::uncertainty::CHI2_2_95;
use nalgebra::Vector2;
use rand::rngs::StdRng;
use rand::SeedableRng;

use super::rotor_model::{rotor_with_planes, session};
use super::{estimate, noisy_runs, solve, Rotor, LEAD_WITH};
use fieldbal::balancing::Solution;

const SPEED: [f64; 1] = [3000.0];
/// Correction planes at nodes 0, 1, 6: small residual (module doc).
const SMALL_RESIDUAL: [usize; 3] = [0, 1, 6];
/// Correction planes at nodes 1, 2, 4: a residual of 5 % (module doc).
const LARGE_RESIDUAL: [usize; 3] = [1, 2, 4];
const REALISATIONS: usize = 400;

/// Solve `REALISATIONS` noisy jobs of the planes at `nodes` with trials of
/// `effect` (2 %/2° stated), handing each answer to `f` with the rotor.
fn each_job(nodes: &[usize], effect: f64, seed: u64, mut f: impl FnMut(&Rotor, &Solution)) {
    let rotor = rotor_with_planes(&SPEED, nodes, effect);
    let exact = rotor.readings();
    let mut rng = StdRng::seed_from_u64(seed);
    let options = SolveOptions {
        amplitude_noise_pct: Some(2.0),
        phase_noise_deg: Some(2.0),
        ..SolveOptions::default()
    };
    for _ in 0..REALISATIONS {
        let y = noisy_runs(&exact, &mut rng);
        let sol = solve(
            &session(LEAD_WITH, &SPEED, &rotor.trial, &y, None),
            &options,
        );
        f(&rotor, &sol);
    }
}

/// Per plane: (coverage of the ellipse, mean Mahalanobis² of the error).
fn measure(nodes: &[usize], effect: f64, seed: u64) -> Vec<(f64, f64)> {
    let mut sums = vec![(0.0, 0.0); nodes.len()];
    each_job(nodes, effect, seed, |rotor, sol| {
        for (j, sum) in sums.iter_mut().enumerate() {
            let (z, cov) = estimate(sol, j);
            let d = z - rotor.correction(LEAD_WITH, j);
            let v = Vector2::new(d.re, d.im);
            let inv = cov
                .try_inverse()
                .expect("a noisy solve has a regular covariance");
            let m2 = (v.transpose() * inv * v)[0];
            sum.0 += f64::from(u8::from(m2 <= CHI2_2_95));
            sum.1 += m2;
        }
    });
    let r = REALISATIONS as f64;
    sums.iter().map(|&(h, m)| (h / r, m / r)).collect()
}

/// Condition number of `W` and the exact fit's residual beside the vibration.
fn fixture(nodes: &[usize]) -> (f64, f64) {
    let rotor = rotor_with_planes(&SPEED, nodes, 1.0);
    let sv = rotor.w.clone().singular_values();
    let residual = (&rotor.y0 + &rotor.w * &rotor.c).norm() / rotor.y0.norm();
    (sv.max() / sv.min(), residual)
}

/// Per trial effect (30 %, 100 %), the planes' (coverage, mean Mahalanobis²), printed.
fn cases(nodes: &[usize], seed: u64) -> Vec<(f64, Vec<(f64, f64)>)> {
    [0.3, 1.0]
        .into_iter()
        .enumerate()
        .map(|(case, effect)| {
            let per_plane = measure(nodes, effect, seed + case as u64);
            eprintln!(
                "planes at nodes {nodes:?}, 1 speed, trial {:.0} %: coverage {:.3?}, mean Mahalanobis² {:.2?}",
                effect * 100.0,
                per_plane.iter().map(|p| p.0).collect::<Vec<_>>(),
                per_plane.iter().map(|p| p.1).collect::<Vec<_>>(),
            );
            (effect, per_plane)
        })
        .collect()
}

/// 3 binomial sd of 400 checks at 95 %: 3.3 %.
fn sd3() -> f64 {
    3.0 * (0.95 * 0.05 / REALISATIONS as f64).sqrt()
}

/// The planes whose coverage lies outside `window`.
fn outside(cases: &[(f64, Vec<(f64, f64)>)], window: std::ops::RangeInclusive<f64>) -> Vec<String> {
    cases
        .iter()
        .flat_map(|(effect, per_plane)| {
            per_plane
                .iter()
                .enumerate()
                .filter(|(_, p)| !window.contains(&p.0))
                .map(move |(j, p)| format!("trial {effect}: P{j} {:.3}", p.0))
        })
        .collect()
}

#[test]
fn both_dependent_plane_fixtures_are_ill_conditioned_and_leave_a_residual() {
    for (nodes, least) in [(SMALL_RESIDUAL, 0.005), (LARGE_RESIDUAL, 0.03)] {
        let (cond, residual) = fixture(&nodes);
        assert!((30.0..=50.0).contains(&cond), "{nodes:?}: condition {cond}");
        assert!(residual > least, "{nodes:?}: residual {residual}");
    }
}

#[test]
fn with_two_nearly_dependent_planes_and_a_small_residual_no_ellipse_holds_less_than_93_percent() {
    let low = outside(&cases(&SMALL_RESIDUAL, 300), 0.93 - sd3()..=1.0);
    assert!(low.is_empty(), "{low:?}");
}

#[test]
#[ignore = "issue 12 item 1 open: 98.5-99.8 % and 61-83 % measured (module doc)"]
fn with_two_nearly_dependent_planes_at_one_speed_the_ellipses_hold_93_to_97_percent() {
    let mut wrong = outside(&cases(&SMALL_RESIDUAL, 300), 0.93 - sd3()..=0.97 + sd3());
    wrong.extend(outside(
        &cases(&LARGE_RESIDUAL, 400),
        0.93 - sd3()..=0.97 + sd3(),
    ));
    assert!(wrong.is_empty(), "{wrong:?}");
}

/// Over `REALISATIONS` jobs of the planes at `nodes` with trials of
/// `effect`: the share of jobs carrying the job-level `regions_unreliable`,
/// and the ellipse checks of the planes under no warning at all (neither
/// their own `trial_effect_small` or `ill_conditioned` nor the job's):
/// (held, checked).
fn unwarned(nodes: &[usize], effect: f64, seed: u64) -> (f64, (usize, usize)) {
    let (mut flagged_jobs, mut held, mut checked) = (0, 0, 0);
    each_job(nodes, effect, seed, |rotor, sol| {
        if sol.warnings.iter().any(|w| w.code == "regions_unreliable") {
            flagged_jobs += 1;
            return;
        }
        for (j, corr) in sol.corrections.iter().enumerate() {
            let own = sol.warnings.iter().any(|w| {
                matches!(w.code.as_str(), "trial_effect_small" | "ill_conditioned")
                    && w.plane.as_deref() == Some(corr.plane.as_str())
            });
            if own {
                continue;
            }
            let (z, cov) = estimate(sol, j);
            let d = z - rotor.correction(LEAD_WITH, j);
            let v = Vector2::new(d.re, d.im);
            let inside = cov
                .try_inverse()
                .is_some_and(|inv| (v.transpose() * inv * v)[0] <= CHI2_2_95);
            held += usize::from(inside);
            checked += 1;
        }
    });
    (flagged_jobs as f64 / REALISATIONS as f64, (held, checked))
}

/// Where a residual hides along the weak direction (the large-residual
/// fixture, 100 % trials) the planes with no warning of their own held 71 %
/// before session 15 (205 of 287 checks, 400 realisations): the answer now
/// flags the whole job (`regions_unreliable`, uncertainty/hidden.rs) wherever
/// a plane is `ill_conditioned`, which is every job here; no plane is then
/// left looking trustworthy.
///
/// With 30 % trials the coefficients' noise makes the planes look less alike
/// than they are, and before session 17 16 % of these jobs carried no flag,
/// their unwarned planes missing nearly always (scripts/
/// issue12_hidden_residual.py: 21 of 23 checks). The flag now also fires
/// where a plane's own share is below the threshold once its noise is taken
/// out (hidden.rs): here in 94 % of the jobs (1 in 10 still escapes, and its
/// planes still miss; method §8, "Session 17").
///
/// On eiv.rs's well-conditioned rotor at one speed with 100 % trials the
/// true own share of P0 is 0.218, just above the threshold 0.2, so the
/// noise-free estimate falls below it in about 30 % of the jobs (Darlow's
/// factor of the noisy readings alone, `ill_conditioned`: 15 %); the planes
/// left unflagged hold their 95 % (94.1 % of 846 checks).
#[test]
fn where_nearly_alike_planes_can_hide_a_residual_no_plane_is_left_unwarned() {
    let (share, (held, checked)) = unwarned(&LARGE_RESIDUAL, 1.0, 500);
    eprintln!("nodes {LARGE_RESIDUAL:?}, 100 %: regions_unreliable in {share:.3} of jobs, unwarned planes held {held} of {checked}");
    assert!(share >= 0.9, "regions_unreliable in {share} of jobs");
    // Fewer than 1 % of the plane checks left without any warning.
    assert!(
        checked * 100 < 3 * REALISATIONS,
        "{checked} unwarned plane checks"
    );

    let (share, (held, checked)) = unwarned(&LARGE_RESIDUAL, 0.3, 502);
    eprintln!("nodes {LARGE_RESIDUAL:?}, 30 %: regions_unreliable in {share:.3} of jobs, unwarned planes held {held} of {checked}");
    assert!(
        share >= 0.9,
        "regions_unreliable in {share} of jobs at 30 %"
    );

    let (share, (held, checked)) = unwarned(&[0, 3, 6], 1.0, 501);
    let p = held as f64 / checked as f64;
    eprintln!("nodes [0, 3, 6], 100 %: regions_unreliable in {share:.3} of jobs, unwarned planes held {p:.3} ({checked})");
    assert!(
        share <= 0.4,
        "regions_unreliable in {share} of well-conditioned jobs"
    );
    // eiv.rs's window, lower edge: 93 % less 3 binomial sd of these checks.
    let sd = (0.95 * 0.05 / checked as f64).sqrt();
    assert!(p >= 0.93 - 3.0 * sd, "unwarned planes held {p}");
}
