//! Every distinct vector sum one plane's kit can make at its fixed places: the
//! per-plane candidate sets that the joint search chooses from.
//!
//! Only a plane's vector sum `Σ m e^{iα}` enters the predicted vibration
//! (method 3.1), so loadings with the same sum are one candidate: per place,
//! stacks with the same total mass are one load (the one with fewer weights
//! kept), and across places, equal sums are merged (fewer weights, then less
//! mass, kept). A candidate loads at most `max_places` places; its total mass
//! keeps `max_mass_g`.

use std::collections::HashMap;

use num_complex::Complex64;

use super::places::MAX_PLACES;

/// Most candidates one plane may have; past it the fit is refused as too large.
pub const MAX_CANDIDATES: usize = 2_000_000;

/// One way to load one place: a stack of kit weights.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    pub mass_g: f64,
    /// The stacked weights, grams, heaviest first.
    pub weights: Vec<f64>,
}

/// One candidate loading of a plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Candidate {
    /// Vector sum of the loading, internal frame (method §1), grams.
    pub sum: Complex64,
    /// Total mass, grams.
    pub mass_g: f64,
    /// Number of weights.
    pub count: u32,
    /// `(place, index into the plane's loads)` of each loaded place; first `used` valid.
    pub parts: [(u16, u16); MAX_PLACES as usize],
    pub used: u8,
}

/// A plane's candidates and the loads their parts refer to.
#[derive(Debug, Clone)]
pub struct PlaneCandidates {
    pub loads: Vec<Load>,
    /// Distinct sums, ascending real part (the search's disc queries rely on it).
    pub candidates: Vec<Candidate>,
}

/// The distinct stacks of 1 to `max_per_place` kit weights, by total mass.
pub fn loads(masses_g: &[f64], max_per_place: u32) -> Vec<Load> {
    let mut sizes: Vec<f64> = masses_g.to_vec();
    sizes.sort_by(|a, b| b.total_cmp(a));
    sizes.dedup();
    let mut out: Vec<Load> = Vec::new();
    // Non-increasing index sequences are the multisets; shorter stacks come first,
    // so the first stack found for a total has the fewest weights.
    let mut stacks: Vec<Vec<usize>> = vec![Vec::new()];
    for _ in 0..max_per_place {
        let mut next = Vec::new();
        for s in &stacks {
            let from = s.last().copied().unwrap_or(0);
            for k in from..sizes.len() {
                let mut t = s.clone();
                t.push(k);
                let weights: Vec<f64> = t.iter().map(|&i| sizes[i]).collect();
                let mass_g: f64 = weights.iter().sum();
                if !out
                    .iter()
                    .any(|l| (l.mass_g - mass_g).abs() <= 1e-12 * mass_g)
                {
                    out.push(Load { mass_g, weights });
                }
                next.push(t);
            }
        }
        stacks = next;
    }
    out.sort_by(|a, b| a.mass_g.total_cmp(&b.mass_g));
    out
}

/// How many loadings (before merging) a plane has: `Σ_k C(n, k) Lᵏ`, k ≤ max_places.
pub fn count_loadings(places: usize, loads: usize, max_places: u32) -> f64 {
    let mut total = 1.0;
    let mut binom = 1.0;
    for k in 1..=max_places as usize {
        if k > places {
            break;
        }
        binom = binom * (places + 1 - k) as f64 / k as f64;
        total += binom * (loads as f64).powi(k as i32);
    }
    total
}

/// Every distinct sum of a plane: `places` the unit vectors of its places
/// (internal frame), `mass_bound` its `max_mass_g`.
pub fn plane_candidates(
    places: &[Complex64],
    loads: Vec<Load>,
    max_places: u32,
    mass_bound: Option<f64>,
) -> PlaneCandidates {
    let bound = mass_bound.map_or(f64::INFINITY, |m| m * (1.0 + 1e-12));
    let scale = loads.last().map_or(1.0, |l| l.mass_g) * 1e-10;
    let mut seen: HashMap<(i64, i64), usize> = HashMap::new();
    let mut candidates: Vec<Candidate> = Vec::new();
    let mut add = |c: Candidate| {
        let key = (
            (c.sum.re / scale).round() as i64,
            (c.sum.im / scale).round() as i64,
        );
        match seen.get(&key) {
            Some(&k) => {
                let old = &candidates[k];
                if (c.count, c.mass_g) < (old.count, old.mass_g) {
                    candidates[k] = c;
                }
            }
            None => {
                seen.insert(key, candidates.len());
                candidates.push(c);
            }
        }
    };
    let empty = Candidate {
        sum: Complex64::new(0.0, 0.0),
        mass_g: 0.0,
        count: 0,
        parts: [(0, 0); MAX_PLACES as usize],
        used: 0,
    };
    // Depth-first over increasing place numbers, at most `max_places` deep.
    let mut stack = vec![(empty, 0usize)];
    while let Some((c, from)) = stack.pop() {
        add(c);
        if u32::from(c.used) >= max_places {
            continue;
        }
        for (p, &u) in places.iter().enumerate().skip(from) {
            for (l, load) in loads.iter().enumerate() {
                let mass_g = c.mass_g + load.mass_g;
                if mass_g > bound {
                    break; // loads ascend by mass
                }
                let mut parts = c.parts;
                parts[usize::from(c.used)] = (p as u16, l as u16);
                stack.push((
                    Candidate {
                        sum: c.sum + u * load.mass_g,
                        mass_g,
                        count: c.count + load.weights.len() as u32,
                        parts,
                        used: c.used + 1,
                    },
                    p + 1,
                ));
            }
        }
    }
    candidates.sort_by(|a, b| a.sum.re.total_cmp(&b.sum.re));
    PlaneCandidates { loads, candidates }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stacks_of_equal_total_are_one_load_with_the_fewest_weights() {
        let l = loads(&[5.0, 10.0], 2);
        let masses: Vec<f64> = l.iter().map(|l| l.mass_g).collect();
        assert_eq!(masses, vec![5.0, 10.0, 15.0, 20.0]);
        assert_eq!(l[1].weights, vec![10.0]);
    }

    #[test]
    fn opposite_equal_weights_merge_with_the_empty_loading() {
        let places = [Complex64::new(1.0, 0.0), Complex64::new(-1.0, 0.0)];
        let c = plane_candidates(&places, loads(&[5.0], 1), 2, None);
        // 0, +5, −5 (and +5−5 = 0 merged into the empty loading).
        assert_eq!(c.candidates.len(), 3);
        let zero = c.candidates.iter().find(|c| c.sum.norm() < 1e-9).unwrap();
        assert_eq!(zero.count, 0);
    }

    #[test]
    fn the_count_of_loadings_matches_the_enumeration_when_nothing_merges() {
        let places: Vec<Complex64> = [0.0f64, 1.0, 2.3]
            .iter()
            .map(|&a| Complex64::from_polar(1.0, a))
            .collect();
        let l = loads(&[1.0, 2.7], 1);
        let c = plane_candidates(&places, l, 2, None);
        assert_eq!(c.candidates.len() as f64, count_loadings(3, 2, 2));
    }
}
