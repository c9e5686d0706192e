//! The discrete fit through a whole solve: what it reports is what its
//! weights do, it beats rounding each plane on its own, it stops at its bound
//! with a valid answer, and the static/couple parts add up.

use crate::support;

use std::time::Duration;

use fieldbal::balancing::fit::candidates::{loads, plane_candidates};
use fieldbal::balancing::fit::search::{objective, search, Found, Problem};
use fieldbal::balancing::model::{Objective, Session, SolveOptions};
use fieldbal::balancing::{self, Solution};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use serde_json::{json, Value};

use support::{rotor, weight};

fn solve(session: &Value, options: Value) -> Solution {
    let s: Session = serde_json::from_value(session.clone()).unwrap();
    let o: SolveOptions = serde_json::from_value(options).unwrap();
    balancing::solve(&s, &o).unwrap()
}

/// The vibration a set of weights leaves, from the solution's own coefficients
/// and predicted residual (lag, against rotation), over every row: (rms, max).
fn predicted(sol: &Solution, weights: &[(String, Complex64)]) -> (f64, f64) {
    let rows = &sol.predicted_residual;
    let mut sq = 0.0;
    let mut max: f64 = 0.0;
    for r in rows {
        // R = Y0 + W C (3.1): take the continuous correction off, put the weights on.
        let mut y = Complex64::from_polar(r.amplitude, -r.phase_deg.to_radians());
        for c in &sol.corrections {
            let k = sol
                .influence_coefficients
                .iter()
                .find(|k| k.speed_rpm == r.speed_rpm && k.sensor == r.sensor && k.plane == c.plane)
                .unwrap();
            let w = Complex64::from_polar(k.amplitude_per_g, -k.phase_deg.to_radians());
            let added: Complex64 = weights
                .iter()
                .filter(|(p, _)| p == &c.plane)
                .map(|(_, m)| m)
                .sum();
            y += w * (added - weight(c.mass_g, c.angle_deg));
        }
        sq += y.norm_sqr();
        max = max.max(y.norm());
    }
    ((sq / rows.len() as f64).sqrt(), max)
}

fn fitted(sol: &Solution) -> Vec<(String, Complex64)> {
    sol.fit
        .as_ref()
        .unwrap()
        .iter()
        .flat_map(|p| {
            p.weights
                .iter()
                .map(|w| (p.plane.clone(), weight(w.mass_g, w.angle_deg)))
        })
        .collect()
}

fn kit_plane(positions: u32, sizes: &[f64]) -> Value {
    json!({"radius_mm": 300, "positions": positions, "kit": {"masses_g": sizes, "max_per_place": 2}})
}

#[test]
fn the_fit_summary_is_the_vibration_its_weights_leave() {
    let mut rng = StdRng::seed_from_u64(3);
    for objective in ["least_squares", "min_max"] {
        let (w, y0) = rotor(&mut rng, 6, 3);
        let planes = vec![
            kit_plane(12, &[5.0, 10.0, 20.0]),
            json!({"places_deg": [0, 40, 95, 180, 250, 300], "kit": {"masses_g": [4, 9], "max_per_place": 2, "max_places": 3}}),
            kit_plane(8, &[7.5, 15.0]),
        ];
        let s = support::session(&w, &y0, planes);
        let sol = solve(
            &s,
            json!({"discrete": true, "objective": objective, "max_mass_g": {"P1": 40}}),
        );
        let summary = sol.fit_summary.as_ref().unwrap();
        assert!(summary.optimal, "{objective}");
        let (rms, max) = predicted(&sol, &fitted(&sol));
        assert!(
            (rms - summary.rms_after).abs() < 1e-6 * rms.max(1.0),
            "{objective}: {rms} vs {}",
            summary.rms_after
        );
        assert!(
            (max - summary.max_after).abs() < 1e-6 * max.max(1.0),
            "{objective}"
        );
        let p1: f64 = sol.fit.as_ref().unwrap()[1]
            .weights
            .iter()
            .map(|w| w.mass_g)
            .sum();
        assert!(p1 <= 40.0 + 1e-9, "max_mass_g kept: {p1}");
        for p in sol.fit.as_ref().unwrap() {
            let mut per_place = std::collections::HashMap::new();
            for w in &p.weights {
                *per_place.entry(w.place).or_insert(0) += 1;
            }
            assert!(per_place.values().all(|&n| n <= 2), "max_per_place kept");
        }
    }
}

#[test]
fn the_joint_fit_beats_rounding_each_plane_on_its_own() {
    // Two planes that the sensors see almost alike (a flexible rotor's two
    // ends near a mode): the continuous corrections are large and cancelling,
    // so rounding each on its own leaves errors that no longer cancel.
    let mut rng = StdRng::seed_from_u64(5);
    let base = DVector::from_fn(4, |_, _| support::c(&mut rng) * 0.05);
    let w = DMatrix::from_fn(4, 2, |a, j| {
        base[a] * if j == 0 { 1.0 } else { -0.9 } + support::c(&mut rng) * 0.004
    });
    let u = DVector::from_vec(vec![weight(60.0, 30.0), weight(50.0, 200.0)]);
    let y0 = -(&w * &u);
    let sizes = [5.0, 10.0, 20.0];
    let s = support::session(&w, &y0, vec![kit_plane(12, &sizes), kit_plane(12, &sizes)]);
    let sol = solve(&s, json!({"discrete": true}));
    let joint = sol.fit_summary.as_ref().unwrap().rms_after;

    // Rounding on its own: each plane's split over its two neighbouring places
    // (method 5.1), each part rounded to the nearest stack of at most 2 kit weights.
    let stacks = loads(&sizes, 2);
    let mut rounded = Vec::new();
    for c in &sol.corrections {
        for part in c.split.as_ref().unwrap() {
            let m = std::iter::once(0.0)
                .chain(stacks.iter().map(|l| l.mass_g))
                .min_by(|a, b| (a - part.mass_g).abs().total_cmp(&(b - part.mass_g).abs()))
                .unwrap();
            rounded.push((c.plane.clone(), weight(m, part.angle_deg)));
        }
    }
    let (alone, _) = predicted(&sol, &rounded);
    println!("rms before {:.3}, continuous {:.3}, rounded plane by plane {alone:.3}, joint fit {joint:.3}",
        sol.summary.rms_before, sol.summary.rms_after);
    assert!(sol.fit_summary.as_ref().unwrap().optimal);
    assert!(
        alone > 2.0 * joint,
        "rounded alone {alone} vs joint {joint}"
    );
}

fn big_problem(seed: u64) -> (DMatrix<Complex64>, DVector<Complex64>, Vec<Vec<Complex64>>) {
    let mut rng = StdRng::seed_from_u64(seed);
    let (a, b) = rotor(&mut rng, 8, 4);
    let places: Vec<Complex64> = (0..24)
        .map(|p| Complex64::from_polar(1.0, std::f64::consts::TAU * p as f64 / 24.0))
        .collect();
    let sums = (0..4)
        .map(|_| {
            let c = plane_candidates(&places, loads(&[2.0, 5.0, 10.0, 20.0, 50.0], 2), 2, None);
            c.candidates.iter().map(|k| k.sum).collect()
        })
        .collect();
    (a, b, sums)
}

/// The job of four planes of 24 places and a 5-size kit, searched to its
/// proof unless the request it serves has `ended` (`balancing::cancel`).
fn search_four_planes(ended: bool) -> Found {
    let (a, b, sums) = big_problem(21);
    let p = Problem {
        a: &a,
        b: &b,
        sums,
        objective: Objective::LeastSquares,
        time_limit: Duration::from_secs(600),
        node_limit: u64::MAX,
    };
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(ended));
    fieldbal::balancing::cancel::scope(flag, || search(&p, vec![0; 4]))
}

#[test]
fn four_planes_of_24_places_with_a_5_size_kit_are_solved_to_proven_optimality() {
    let found = search_four_planes(false);
    assert!(found.optimal);
    println!("{} candidate evaluations", found.nodes);
}

#[test]
fn a_search_stopped_by_its_bound_says_so_and_gives_a_valid_fit_no_worse_than_its_start() {
    let (a, b, sums) = big_problem(22);
    let sizes: Vec<usize> = sums.iter().map(Vec::len).collect();
    let mut rng = StdRng::seed_from_u64(1);
    let start: Vec<usize> = sizes.iter().map(|&n| rng.gen_range(0..n)).collect();
    for objective in [Objective::LeastSquares, Objective::MinMax] {
        let p = Problem {
            a: &a,
            b: &b,
            sums: sums.clone(),
            objective,
            time_limit: Duration::from_secs(600),
            node_limit: 50,
        };
        let found = search(&p, start.clone());
        assert!(!found.optimal, "{objective:?}");
        assert!(found.choice.iter().zip(&sizes).all(|(&k, &n)| k < n));
        assert!((objective_of(&p, &found.choice) - found.value).abs() <= 1e-12 * found.value);
        assert!(found.value <= objective_of(&p, &start));
    }
}

#[test]
fn a_search_whose_request_ended_stops_at_its_next_checkpoint() {
    let whole = search_four_planes(false);
    let found = search_four_planes(true);
    assert!(whole.optimal && !found.optimal);
    assert!(
        found.nodes * 2 < whole.nodes,
        "{} of {} nodes",
        found.nodes,
        whole.nodes
    );
}

fn objective_of(p: &Problem, choice: &[usize]) -> f64 {
    objective(p, choice)
}

#[test]
fn a_two_plane_solution_has_static_and_couple_parts_that_add_up_to_each_correction() {
    let mut rng = StdRng::seed_from_u64(9);
    let (w, y0) = rotor(&mut rng, 4, 2);
    let s = support::session(&w, &y0, vec![json!({}), json!({})]);
    let sol = solve(&s, json!({}));
    let sc = sol.static_couple.as_ref().unwrap();
    for (k, c) in sol.corrections.iter().enumerate() {
        let sum = weight(sc.static_part[k].mass_g, sc.static_part[k].angle_deg)
            + weight(sc.couple[k].mass_g, sc.couple[k].angle_deg);
        assert!((sum - weight(c.mass_g, c.angle_deg)).norm() < 1e-9 * c.mass_g.max(1.0));
    }
    let (w3, y3) = rotor(&mut rng, 4, 3);
    let three = solve(
        &support::session(&w3, &y3, vec![json!({}), json!({}), json!({})]),
        json!({}),
    );
    assert!(three.static_couple.is_none() && three.fit.is_none());
}
