//! Where cone solves meet a session solve: `max_mass_g` checked against the
//! session, the choice between plain least squares and a cone program, and the
//! `mass_limit_active` warnings.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::solve_cone_conditioned;
use crate::balancing::error::InputError;
use crate::balancing::model::{Objective, Session, SolveOptions};
use crate::balancing::solution::Warning;
use crate::balancing::solve::least_squares;
use crate::balancing::validate::MIN_MASS_G;

/// Check `max_mass_g` against the session: every key a plane, every bound a
/// finite number of grams from the lightest weight a run may give
/// (`MIN_MASS_G`, 1e-6 g) on.
pub fn check_mass_bounds(options: &SolveOptions, session: &Session) -> Result<(), InputError> {
    for (id, &m) in options.max_mass_g.iter().flatten() {
        let field = format!("options.max_mass_g.{id}");
        if !session.planes.iter().any(|p| &p.id == id) {
            return Err(InputError::invalid(
                "unknown_plane",
                field,
                format!("the session has no plane '{id}'"),
            ));
        }
        if !(m.is_finite() && m > 0.0) {
            return Err(InputError::invalid(
                "invalid_value",
                field,
                "a mass bound is a finite number of grams greater than 0",
            ));
        }
        // Below the lightest weight a run may give, a bound holds the
        // correction to nothing anyone can fit (5e-324 g gave an empty
        // split and a warning spelling the bound with 320 zeros).
        if m < MIN_MASS_G {
            return Err(InputError::invalid(
                "invalid_value",
                field,
                format!(
                    "a mass bound is at least 1e-6 g, the lightest weight a run may give; got {} g (to solve without this plane, leave it out of options.planes)",
                    crate::balancing::error::shown(m)
                ),
            ));
        }
    }
    Ok(())
}

/// The correction when the options call for a cone program (min-max, or a mass
/// bound on a plane being solved for), with a warning per binding bound; `None`
/// when plain least squares is the answer. `a`, `b` are the weighted problem
/// (3.3) on `planes` (indices into `session.planes`); the masses are grams.
/// `condition` is `A`'s scaled condition number (the solve's `Factored`):
/// from [`super::NEARLY_DEPENDENT`] on, min-max picks the least-mass optimum.
#[allow(clippy::type_complexity)]
pub fn correction(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    options: &SolveOptions,
    session: &Session,
    planes: &[usize],
    condition: f64,
) -> Result<Option<(DVector<Complex64>, Vec<Warning>)>, InputError> {
    check_mass_bounds(options, session)?;
    let limits = options.max_mass_g.as_ref();
    let bounds: Vec<Option<f64>> = planes
        .iter()
        .map(|&j| limits.and_then(|l| l.get(&session.planes[j].id).copied()))
        .collect();
    let objective = options.objective.unwrap_or_default();
    // The unbounded least-squares residual, to tell a bound that costs
    // vibration from one that planes of the same effect make up for.
    let mut free_residual = None;
    if objective == Objective::LeastSquares {
        if bounds.iter().all(Option::is_none) {
            return Ok(None);
        }
        // When the unbounded least-squares answer already keeps every bound it is
        // optimal for the bounded problem too: keep the SVD's exact answer.
        let x = least_squares(a, b)?;
        let within = bounds
            .iter()
            .zip(x.iter())
            .all(|(m, xj)| m.is_none_or(|m| xj.norm() <= m));
        if within {
            return Ok(Some((x, Vec::new())));
        }
        free_residual = Some((a * &x + b).norm());
    }
    let solved = solve_cone_conditioned(condition, a, b, objective, &bounds)?;
    let what = match objective {
        Objective::LeastSquares => "least-squares",
        Objective::MinMax => "min-max",
    };
    // Binding but free: dependent planes (the same effect on every sensor)
    // take what the bounded one may not, and the residual stays the
    // unbounded one (to the polished answer's precision).
    let costs_nothing = free_residual.is_some_and(|free| {
        let bounded = (a * &solved.x + b).norm();
        bounded <= free + 1e-9 * b.norm().max(free)
    });
    let consequence = |id: &str| {
        if costs_nothing {
            "but planes with the same effect on the sensors take the rest, so the predicted vibration is the same as without the bound".to_string()
        } else {
            format!("so the predicted vibration is higher than without the bound. If the plane can take more mass (a heavier weight, or a larger radius), raising max_mass_g for {id} can lower it")
        }
    };
    let warnings = planes
        .iter()
        .zip(&bounds)
        .zip(&solved.bound_active)
        .filter(|(_, &active)| active)
        .filter_map(|((&j, m), _)| m.map(|m| (&session.planes[j].id, m)))
        .map(|(id, m)| Warning {
            code: "mass_limit_active".to_string(),
            message: format!(
                "the bound of {m} g on plane {id} is binding: the {what} correction there is held at {m} g, less than it would otherwise put there, {}",
                consequence(id)
            ),
            plane: Some(id.clone()),
        })
        .collect();
    Ok(Some((solved.x, warnings)))
}
