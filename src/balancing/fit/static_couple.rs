//! Static and couple parts of a two-plane correction: static `(C₁ + C₂)/2` in
//! each plane, couple `±(C₁ − C₂)/2` (the `StaticCouple` field docs give the
//! convention), for fitters of narrow and overhung rotors who think in them.

use num_complex::Complex64;

use crate::balancing::model::Conventions;
use crate::balancing::phasor::weight_out;
use crate::balancing::solution::{PlaneWeight, StaticCouple};
use crate::balancing::solve::Fit;

/// The decomposition of `c1`, `c2` (internal frame, grams) for planes `ids`.
pub fn split(conv: Conventions, ids: [&str; 2], c1: Complex64, c2: Complex64) -> StaticCouple {
    let s = (c1 + c2) / 2.0;
    let k = (c1 - c2) / 2.0;
    let weight = |id: &str, w: Complex64| {
        let (mass_g, angle_deg) = weight_out(conv, w);
        PlaneWeight {
            plane: id.to_string(),
            mass_g,
            angle_deg,
        }
    };
    StaticCouple {
        static_part: vec![weight(ids[0], s), weight(ids[1], s)],
        couple: vec![weight(ids[0], k), weight(ids[1], -k)],
    }
}

/// The decomposition of a solve's correction when it has exactly two planes.
pub fn of(fit: &Fit) -> Option<StaticCouple> {
    if fit.planes.len() != 2 {
        return None;
    }
    let session = fit.checked.session;
    let ids = [
        session.planes[fit.planes[0]].id.as_str(),
        session.planes[fit.planes[1]].id.as_str(),
    ];
    Some(split(fit.checked.conventions, ids, fit.c[0], fit.c[1]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::balancing::phasor::weight_in;

    #[test]
    fn static_plus_couple_gives_each_plane_its_correction() {
        for conv in Conventions::ALL {
            let (c1, c2) = (weight_in(conv, 30.0, 40.0), weight_in(conv, 12.0, 250.0));
            let sc = split(conv, ["A", "B"], c1, c2);
            for (k, c) in [c1, c2].into_iter().enumerate() {
                let s = &sc.static_part[k];
                let m = &sc.couple[k];
                let sum =
                    weight_in(conv, s.mass_g, s.angle_deg) + weight_in(conv, m.mass_g, m.angle_deg);
                assert!((sum - c).norm() < 1e-9, "{conv:?} plane {k}");
            }
            assert!((sc.couple[0].mass_g - sc.couple[1].mass_g).abs() < 1e-12);
        }
    }
}
