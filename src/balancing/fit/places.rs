//! A plane's fixed places and kit: their checks (`places_deg`, `kit`) and the
//! angles of the places in the session's angle direction.

use crate::balancing::error::InputError;
use crate::balancing::model::Plane;
use crate::balancing::validate::MIN_MASS_G;

/// Most distinct weight sizes in one kit.
pub const MAX_KIT_SIZES: usize = 12;
/// Most weights stacked at one place.
pub const MAX_PER_PLACE: u32 = 4;
/// Most places one plane's fit may use.
pub const MAX_PLACES: u32 = 4;
/// Default number of places one plane's fit may use (a split over two places, method 5.1).
pub const DEFAULT_MAX_PLACES: u32 = 2;
const MAX_PLACES_LISTED: usize = 3600;
const MAX_KIT_MASS_G: f64 = 1e7;

fn invalid(field: String, message: impl Into<String>) -> InputError {
    InputError::invalid("invalid_value", field, message)
}

/// The angles of a plane's fixed places in the session's angle direction,
/// place `p` at index `p`: `places_deg` as given, or `positions` equally spaced
/// from 0. `None` when the plane has neither.
pub fn place_angles_deg(plane: &Plane) -> Option<Vec<f64>> {
    if let Some(list) = &plane.places_deg {
        return Some(list.clone());
    }
    plane.positions.map(|n| {
        (0..n)
            .map(|p| 360.0 * f64::from(p) / f64::from(n))
            .collect()
    })
}

/// Check `places_deg` and `kit` of plane `i` (the v2 "Weights that can be fitted" fields).
pub fn check_plane(i: usize, plane: &Plane) -> Result<(), InputError> {
    let f = |name: &str| format!("planes[{i}].{name}");
    if let Some(list) = &plane.places_deg {
        if plane.positions.is_some() {
            return Err(InputError::invalid(
                "conflicting_fields",
                f("places_deg"),
                "give either positions (equally spaced places) or places_deg (their angles), not both",
            ));
        }
        if list.is_empty() || list.len() > MAX_PLACES_LISTED {
            return Err(invalid(
                f("places_deg"),
                format!("1 to {MAX_PLACES_LISTED} place angles, got {}", list.len()),
            ));
        }
        for (k, &a) in list.iter().enumerate() {
            if !(a.is_finite() && (0.0..360.0).contains(&a)) {
                return Err(invalid(
                    format!("planes[{i}].places_deg[{k}]"),
                    format!(
                        "a place angle is a finite number of degrees in [0, 360), got {}",
                        crate::balancing::error::shown(a)
                    ),
                ));
            }
            if let Some(j) = list[..k].iter().position(|&b| (a - b).abs() < 1e-9) {
                return Err(InputError::invalid(
                    "duplicate_place",
                    format!("planes[{i}].places_deg[{k}]"),
                    format!(
                        "place {k} is at the same angle as place {j} ({}°)",
                        crate::balancing::error::shown(a)
                    ),
                ));
            }
        }
    }
    let Some(kit) = &plane.kit else {
        return Ok(());
    };
    if plane.positions.is_none() && plane.places_deg.is_none() {
        return Err(InputError::invalid(
            "kit_without_places",
            f("kit"),
            "a kit needs the plane's fixed places: give positions or places_deg",
        ));
    }
    if kit.masses_g.is_empty() || kit.masses_g.len() > MAX_KIT_SIZES {
        return Err(invalid(
            f("kit.masses_g"),
            format!(
                "1 to {MAX_KIT_SIZES} weight sizes, got {}",
                kit.masses_g.len()
            ),
        ));
    }
    for (k, &m) in kit.masses_g.iter().enumerate() {
        // From the lightest trial weight a session takes (1e-6 g): a kit of
        // 1e-320 g was suggested as the trial weight and fitted (session 21).
        if !(m.is_finite() && (MIN_MASS_G..=MAX_KIT_MASS_G).contains(&m)) {
            return Err(invalid(
                format!("planes[{i}].kit.masses_g[{k}]"),
                format!("a weight size is a finite number of grams from {MIN_MASS_G} to {MAX_KIT_MASS_G}, got {}", crate::balancing::error::shown(m)),
            ));
        }
    }
    if !(1..=MAX_PER_PLACE).contains(&kit.max_per_place) {
        return Err(invalid(
            f("kit.max_per_place"),
            format!(
                "1 to {MAX_PER_PLACE} weights stacked at one place, got {}",
                kit.max_per_place
            ),
        ));
    }
    if let Some(n) = kit.max_places {
        if !(1..=MAX_PLACES).contains(&n) {
            return Err(invalid(
                f("kit.max_places"),
                format!("1 to {MAX_PLACES} places per fit, got {n}"),
            ));
        }
    }
    Ok(())
}
