//! The discrete fit against brute force: on many small random problems the
//! search's objective equals the exhaustive optimum over every loading the
//! kits allow, and the search says it is proven optimal.

use crate::support;

use fieldbal::balancing::fit::candidates::{loads, plane_candidates};
use fieldbal::balancing::fit::search::{objective, search, Problem};
use fieldbal::balancing::model::Objective;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use std::time::Duration;

/// One plane of a random problem.
struct PlaneSpec {
    places: Vec<Complex64>,
    sizes: Vec<f64>,
    max_per_place: u32,
    max_places: u32,
    bound: Option<f64>,
}

/// Every loading's sum, by plain enumeration: each place gets a multiset of
/// 0 to `max_per_place` sizes, at most `max_places` places loaded, total mass
/// within the bound. No merging: an independent count of the choices.
fn all_sums(p: &PlaneSpec) -> Vec<Complex64> {
    let mut stacks: Vec<f64> = Vec::new(); // total masses of every non-empty multiset
    fn multisets(sizes: &[f64], from: usize, left: u32, acc: f64, out: &mut Vec<f64>) {
        for k in from..sizes.len() {
            out.push(acc + sizes[k]);
            if left > 1 {
                multisets(sizes, k, left - 1, acc + sizes[k], out);
            }
        }
    }
    multisets(&p.sizes, 0, p.max_per_place, 0.0, &mut stacks);
    let mut out = Vec::new();
    fn go(
        p: &PlaneSpec,
        stacks: &[f64],
        place: usize,
        used: u32,
        sum: Complex64,
        mass: f64,
        out: &mut Vec<Complex64>,
    ) {
        if place == p.places.len() {
            if p.bound.is_none_or(|b| mass <= b * (1.0 + 1e-12)) {
                out.push(sum);
            }
            return;
        }
        go(p, stacks, place + 1, used, sum, mass, out);
        if used < p.max_places {
            for &m in stacks {
                go(
                    p,
                    stacks,
                    place + 1,
                    used + 1,
                    sum + p.places[place] * m,
                    mass + m,
                    out,
                );
            }
        }
    }
    go(p, &stacks, 0, 0, Complex64::new(0.0, 0.0), 0.0, &mut out);
    out
}

fn brute(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    sums: &[Vec<Complex64>],
    obj: Objective,
) -> f64 {
    fn go(
        a: &DMatrix<Complex64>,
        r: DVector<Complex64>,
        sums: &[Vec<Complex64>],
        j: usize,
        obj: Objective,
    ) -> f64 {
        if j == sums.len() {
            return match obj {
                Objective::LeastSquares => r.norm_squared(),
                Objective::MinMax => r.iter().map(|x| x.norm()).fold(0.0, f64::max),
            };
        }
        let col = a.column(j);
        sums[j]
            .iter()
            .map(|&s| go(a, &r + col * s, sums, j + 1, obj))
            .fold(f64::INFINITY, f64::min)
    }
    go(a, b.clone(), sums, 0, obj)
}

fn random_plane(rng: &mut StdRng) -> PlaneSpec {
    let n = rng.gen_range(1..=8);
    let places = if rng.gen_bool(0.5) {
        (0..n)
            .map(|p| Complex64::from_polar(1.0, std::f64::consts::TAU * p as f64 / n as f64))
            .collect()
    } else {
        (0..n)
            .map(|_| Complex64::from_polar(1.0, rng.gen_range(0.0..std::f64::consts::TAU)))
            .collect()
    };
    let k = rng.gen_range(2..=3);
    let sizes = (0..k)
        .map(|_| f64::from(rng.gen_range(2..=40)) * 0.5 + 1.0)
        .collect();
    PlaneSpec {
        places,
        sizes,
        max_per_place: rng.gen_range(1..=2),
        max_places: rng.gen_range(1..=2),
        bound: rng.gen_bool(0.3).then(|| rng.gen_range(10.0..60.0)),
    }
}

fn check_many(obj: Objective, seed: u64) {
    let mut rng = StdRng::seed_from_u64(seed);
    let mut cases = 0;
    while cases < 60 {
        let planes: usize = rng.gen_range(1..=3);
        let rows = 2 * rng.gen_range(1..=3usize).max(planes.div_ceil(2));
        let specs: Vec<PlaneSpec> = (0..planes).map(|_| random_plane(&mut rng)).collect();
        let raw: Vec<Vec<Complex64>> = specs.iter().map(all_sums).collect();
        let product: f64 = raw.iter().map(|s| s.len() as f64).product();
        if product > 3e5 {
            continue; // too many for the brute force; draw another
        }
        cases += 1;
        let (a, b) = support::rotor(&mut rng, rows, planes);
        let sums: Vec<Vec<Complex64>> = specs
            .iter()
            .map(|p| {
                let c = plane_candidates(
                    &p.places,
                    loads(&p.sizes, p.max_per_place),
                    p.max_places,
                    p.bound,
                );
                c.candidates.iter().map(|k| k.sum).collect()
            })
            .collect();
        let problem = Problem {
            a: &a,
            b: &b,
            sums,
            objective: obj,
            time_limit: Duration::from_secs(600),
            node_limit: u64::MAX,
        };
        let found = search(&problem, vec![0; planes]);
        let best = brute(&a, &b, &raw, obj);
        assert!(found.optimal, "case {cases}");
        assert!(
            (found.value - best).abs() <= 1e-9 * best + 1e-12,
            "case {cases} ({obj:?}): search {} vs exhaustive {best}",
            found.value
        );
        assert!(
            (objective(&problem, &found.choice) - found.value).abs()
                <= 1e-12 * found.value.max(1.0)
        );
    }
}

#[test]
fn least_squares_fits_equal_the_exhaustive_optimum_on_random_problems() {
    check_many(Objective::LeastSquares, 11);
}

#[test]
fn min_max_fits_equal_the_exhaustive_optimum_on_random_problems() {
    check_many(Objective::MinMax, 12);
}
