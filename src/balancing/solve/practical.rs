//! Practical forms of a correction (method §5): split over fixed places,
//! unbalance at a radius, and the ISO 21940-11 permissible residual unbalance.

use crate::balancing::phasor::wrap_deg;
use crate::balancing::solution::SplitPart;

/// Split a correction of `mass_g` at `angle_deg` over the two neighbouring of
/// `n` equally spaced places (place `p` at `360°·p/n`, same angle direction), by (5.1).
///
/// Returns the parts and whether the split is exact. With two places (opposite
/// each other) only the component along them can be fitted: the nearer place
/// gets `m·cos Δ` and the split is not exact.
pub fn split(mass_g: f64, angle_deg: f64, n: u32) -> (Vec<SplitPart>, bool) {
    let step = 360.0 / f64::from(n);
    let places: Vec<f64> = (0..n).map(|p| f64::from(p) * step).collect();
    split_places(mass_g, angle_deg, &places)
}

/// Split a correction of `mass_g` at `angle_deg` over the two places of
/// `places_deg` (any order, distinct, in `[0, 360)`, place `p` at `places_deg[p]`)
/// that enclose it, by (5.1): `m₁ = m·sin(a₂−θ)/sin(a₂−a₁)`, `m₂ = m·sin(θ−a₁)/sin(a₂−a₁)`.
///
/// When the enclosing gap is 180° or more (two opposite places, one place,
/// or a wide gap), no two non-negative weights add up to the correction: the
/// nearer place gets the component along it, `m·cos Δ` (nothing when that is
/// negative), and the split is not exact.
pub fn split_places(mass_g: f64, angle_deg: f64, places_deg: &[f64]) -> (Vec<SplitPart>, bool) {
    let theta = wrap_deg(angle_deg);
    let mut order: Vec<usize> = (0..places_deg.len()).collect();
    order.sort_by(|&a, &b| places_deg[a].total_cmp(&places_deg[b]));
    let part = |p: usize, m: f64| SplitPart {
        position: p as u32,
        angle_deg: wrap_deg(places_deg[p]),
        mass_g: m,
    };
    let Some(&first) = order.first() else {
        return (Vec::new(), false);
    };
    // The last place at or below θ, and the next one round the circle.
    let k = order.iter().rposition(|&p| places_deg[p] <= theta);
    let (lo, a1) = match k {
        Some(k) => (order[k], places_deg[order[k]]),
        None => (
            order[order.len() - 1],
            places_deg[order[order.len() - 1]] - 360.0,
        ),
    };
    let hi = match k {
        Some(k) if k + 1 < order.len() => order[k + 1],
        Some(_) => first,
        None => first,
    };
    let mut a2 = places_deg[hi];
    if a2 <= a1 || (order.len() == 1) {
        a2 += 360.0;
    }
    let gap = a2 - a1;
    if order.len() < 2 || gap >= 180.0 - 1e-9 {
        let (p, delta) = if theta - a1 <= a2 - theta {
            (lo, theta - a1)
        } else {
            (hi, a2 - theta)
        };
        let mass = mass_g * delta.to_radians().cos();
        let parts = if mass > 0.0 {
            vec![part(p, mass)]
        } else {
            Vec::new()
        };
        return (parts, delta.abs() < 1e-9);
    }
    let s = gap.to_radians().sin();
    let m1 = mass_g * (a2 - theta).to_radians().sin() / s;
    let m2 = mass_g * (theta - a1).to_radians().sin() / s;
    let tiny = 1e-12 * mass_g.max(f64::MIN_POSITIVE);
    let parts = [(lo, m1), (hi, m2)]
        .into_iter()
        .filter(|&(_, m)| m > tiny)
        .map(|(p, m)| part(p, m))
        .collect();
    (parts, true)
}

/// The grade's G value in mm/s, from its name ("G6.3" → 6.3).
pub fn grade_value(grade: &str) -> Option<f64> {
    grade.strip_prefix('G')?.parse().ok()
}

/// ISO 21940-11 permissible residual unbalance, g·mm (5.2):
/// `U_per = 9549 · G [mm/s] · m [kg] / n [rpm]`.
pub fn permissible_unbalance_gmm(grade_mm_s: f64, mass_kg: f64, speed_rpm: f64) -> f64 {
    9549.0 * grade_mm_s * mass_kg / speed_rpm
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_split_adds_back_to_the_correction_vector() {
        for (m, theta, n) in [
            (52.4, 141.0, 12),
            (10.0, 359.0, 8),
            (3.0, 0.0, 4),
            (7.0, 200.0, 3),
        ] {
            let (parts, exact) = split(m, theta, n);
            assert!(exact);
            let (x, y) = parts.iter().fold((0.0, 0.0), |(x, y), p| {
                (
                    x + p.mass_g * p.angle_deg.to_radians().cos(),
                    y + p.mass_g * p.angle_deg.to_radians().sin(),
                )
            });
            assert!(
                (x - m * theta.to_radians().cos()).abs() < 1e-9,
                "{m} {theta} {n}"
            );
            assert!(
                (y - m * theta.to_radians().sin()).abs() < 1e-9,
                "{m} {theta} {n}"
            );
            assert!(parts.iter().all(|p| p.mass_g > 0.0));
        }
    }

    #[test]
    fn the_contract_example_splits_between_places_4_and_5() {
        let (parts, _) = split(52.4, 141.0, 12);
        assert_eq!(
            parts.iter().map(|p| p.position).collect::<Vec<_>>(),
            vec![4, 5]
        );
        assert!(
            (parts[0].angle_deg - 120.0).abs() < 1e-9 && (parts[1].angle_deg - 150.0).abs() < 1e-9
        );
    }

    #[test]
    fn two_opposite_places_take_only_the_component_along_them() {
        let (parts, exact) = split(10.0, 30.0, 2);
        assert!(!exact);
        assert_eq!(parts[0].position, 0);
        assert!((parts[0].mass_g - 10.0 * 30f64.to_radians().cos()).abs() < 1e-12);
    }

    #[test]
    fn an_irregular_split_adds_back_to_the_correction_vector() {
        let places = [200.0, 10.0, 95.0, 300.0, 140.0];
        for theta in [0.0, 5.0, 50.0, 120.0, 170.0, 250.0, 330.0, 359.5] {
            let (parts, exact) = split_places(20.0, theta, &places);
            assert!(exact, "{theta}");
            assert!(parts.len() <= 2 && parts.iter().all(|p| p.mass_g > 0.0));
            let (x, y) = parts.iter().fold((0.0, 0.0), |(x, y), p| {
                let a = places[p.position as usize].to_radians();
                (x + p.mass_g * a.cos(), y + p.mass_g * a.sin())
            });
            assert!(
                (x - 20.0 * theta.to_radians().cos()).abs() < 1e-9,
                "{theta}"
            );
            assert!(
                (y - 20.0 * theta.to_radians().sin()).abs() < 1e-9,
                "{theta}"
            );
        }
    }

    #[test]
    fn a_gap_of_more_than_half_a_turn_takes_only_the_component_along_the_nearer_place() {
        let (parts, exact) = split_places(10.0, 100.0, &[0.0, 60.0]);
        assert!(!exact);
        assert_eq!(parts[0].position, 1);
        assert!((parts[0].mass_g - 10.0 * 40f64.to_radians().cos()).abs() < 1e-12);
        let (parts, _) = split_places(10.0, 240.0, &[0.0, 60.0]);
        assert!(parts.is_empty(), "{parts:?}");
    }

    #[test]
    fn iso_tolerance_of_the_contract_rotor() {
        let g = grade_value("G6.3").unwrap();
        let u = permissible_unbalance_gmm(g, 420.0, 1480.0);
        assert!((u - 9549.0 * 6.3 * 420.0 / 1480.0).abs() < 1e-9);
        assert_eq!(grade_value("G0.4"), Some(0.4));
    }
}
