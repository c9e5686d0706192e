//! How often `identify/rotor`'s `b_over_m` and `q_over_m` hold the truth
//! within their 95 % half-widths when they are given, with the
//! cross-coupling estimated (the default).

use crate::support;

use fieldbal::balancing::model::Unit;
use fieldbal::identification::rotor::{identify, RotorOptions, RotorRequest};
use support::{session, speeds, Jeffcott};

/// The most misses among `given` answers that a 95 % interval leaves with
/// probability over 1e-3 (binomial, p = 0.05): a calibrated interval fails
/// this test once in a thousand runs.
fn allowed_misses(given: usize) -> usize {
    let p: f64 = 0.05;
    let mut term = (1.0 - p).powi(given as i32);
    let mut cdf = term;
    let mut k = 0;
    while 1.0 - cdf > 1e-3 && k < given {
        term *= (given - k) as f64 / (k + 1) as f64 * p / (1.0 - p);
        cdf += term;
        k += 1;
    }
    k
}

/// Over `seeds` noisy sessions of `rotor` (q = 0) read at `grid` with
/// relative reading noise `noise`: (given, missed) of `b_over_m`/`q_over_m`.
fn tally(rotor: Jeffcott, grid: &[f64], noise: f64, seeds: u64) -> (usize, usize) {
    let b_true = rotor.damping / rotor.mass_kg;
    let (mut given, mut missed) = (0, 0);
    for seed in 1..=seeds {
        let out = identify(&RotorRequest {
            session: session(&[rotor], grid, Unit::UmPp, noise, seed),
            options: RotorOptions::default(),
        })
        .unwrap();
        let r = serde_json::to_value(&out.results[0]).unwrap();
        let Some(b) = r["b_over_m"].as_f64() else {
            continue;
        };
        given += 1;
        let rb = r["b_over_m_resolution"].as_f64().unwrap();
        let (q, rq) = (
            r["q_over_m"].as_f64().unwrap(),
            r["q_over_m_resolution"].as_f64().unwrap(),
        );
        missed += usize::from((b - b_true).abs() > rb || q.abs() > rq);
    }
    (given, missed)
}

/// Synchronous readings fix `ωb − q` near the critical and split it into
/// direct damping and cross-coupling only through the few per cent the speed
/// changes across the resonance. b/m and q/m were given whenever b/m cleared
/// its 95 % half-width, a test at 5 % that, where the split is not resolved
/// (nearly always), passes the records whose noise pushed b/m far up: the few
/// given were mostly misses (session 23, scripts/ident_rotor_coverage.py:
/// 12 of 47 held the truth at 3 to 40 speeds; at three speeds, one degree of
/// freedom, one was given with a half-width of 1.5 1/s against an error of
/// 172). Given now, they hold it about 95 % of the time; a split resolved
/// is still given.
#[test]
fn b_over_m_and_q_over_m_hold_the_truth_about_95_percent_of_the_times_they_are_given() {
    let turned = |zeta| Jeffcott {
        sensor_turn: -0.4,
        ..Jeffcott::with(150.0, 2450.0, zeta)
    };
    // The split barely resolved if at all: three speeds (one degree of
    // freedom), four, and eight across the critical (the old gate: 10 of 14,
    // 6 of 8 and 2 of 72 given missed). A record given where the split is
    // unresolved misses whatever the gate (noise pushed b/m up to pass it);
    // a gate can only make such records rare: under 1 % of them.
    let mut misses = 0;
    for (grid, noise) in [
        (vec![2000.0, 2400.0, 2800.0], 0.02),
        (vec![2000.0, 2300.0, 2600.0, 2900.0], 0.02),
        (speeds(1715.0, 3185.0, 8), 0.01),
    ] {
        let (given, missed) = tally(turned(0.05), &grid, noise, 300);
        println!("{} speeds: {missed} of {given} given missed", grid.len());
        assert!(
            missed <= allowed_misses(given),
            "{} speeds: {missed} of {given} given missed",
            grid.len()
        );
        misses += missed;
    }
    assert!(
        misses <= 9,
        "{misses} of 900 records were given a b/m or q/m that missed"
    );
    // Resolved: ζ 0.2 read at 25 speeds from 0.3 to 1.7 times the critical
    // with 0.5 % noise. Given most times, and right.
    let grid = speeds(735.0, 4165.0, 25);
    let (given, missed) = tally(turned(0.2), &grid, 0.005, 100);
    println!("resolved: {missed} of {given} given missed");
    assert!(given >= 50, "only {given} of 100 given");
    assert!(
        missed <= allowed_misses(given),
        "{missed} of {given} given missed"
    );
}
