//! Practical forms of a correction (method §5): split over fixed places,
//! unbalance at a radius, and the ISO 21940-11 permissible residual unbalance.

use super::phasor::wrap_deg;
use super::solution::SplitPart;

/// Split a correction of `mass_g` at `angle_deg` over the two neighbouring of
/// `n` equally spaced places (place `p` at `360°·p/n`, same angle direction), by (5.1).
///
/// Returns the parts and whether the split is exact. With two places (opposite
/// each other) only the component along them can be fitted: the nearer place
/// gets `m·cos Δ` and the split is not exact.
pub fn split(mass_g: f64, angle_deg: f64, n: u32) -> (Vec<SplitPart>, bool) {
    let step = 360.0 / f64::from(n);
    let theta = wrap_deg(angle_deg);
    let lower = ((theta / step).floor() as u32).min(n - 1);
    let a1 = f64::from(lower) * step;
    let a2 = a1 + step;
    let place = |p: u32| SplitPart {
        position: p % n,
        angle_deg: wrap_deg(f64::from(p % n) * step),
        mass_g: 0.0,
    };
    if n == 2 {
        let (p, delta) = if theta - a1 <= a2 - theta {
            (lower, theta - a1)
        } else {
            (lower + 1, a2 - theta)
        };
        let mass = mass_g * delta.to_radians().cos();
        return (
            vec![SplitPart {
                mass_g: mass,
                ..place(p)
            }],
            delta.abs() < 1e-9,
        );
    }
    let s = step.to_radians().sin();
    let m1 = mass_g * (a2 - theta).to_radians().sin() / s;
    let m2 = mass_g * (theta - a1).to_radians().sin() / s;
    let tiny = 1e-12 * mass_g.max(f64::MIN_POSITIVE);
    let parts = [(lower, m1), (lower + 1, m2)]
        .into_iter()
        .filter(|&(_, m)| m > tiny)
        .map(|(p, m)| SplitPart {
            mass_g: m,
            ..place(p)
        })
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
    fn iso_tolerance_of_the_contract_rotor() {
        let g = grade_value("G6.3").unwrap();
        let u = permissible_unbalance_gmm(g, 420.0, 1480.0);
        assert!((u - 9549.0 * 6.3 * 420.0 / 1480.0).abs() < 1e-9);
        assert_eq!(grade_value("G0.4"), Some(0.4));
    }
}
