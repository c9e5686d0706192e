//! The job goes on (v2): runout, corrections from the rotor as it is
//! (`from_run`, with `total` per plane), run checks, and supplied or pooled
//! influence coefficients. This module wraps the one-shot solve of `solve/weighted.rs`.
//!
//! `from_run`: the rotor as it was in run `r`, its weights `T_r` still on. The
//! session is re-referenced to that run (method 2.1 holds for any reference:
//! `Y_k − Y_r = W (T_k − T_r)`), so the correction minimises the vibration
//! predicted from the run's own readings, `Y_r + W C` (3.1), and `C` is what to
//! add. The one weight per plane that replaces everything in it is then
//! `T_r + C`, relative to the reference state.

pub mod checks;
pub mod linear;
pub mod pool;
pub mod runout;
pub mod supplied;
pub mod trim;

use crate::balancing::error::InputError;
use crate::balancing::model::{Session, SolveOptions, Weight};
use crate::balancing::phasor::{weight_in, weight_out};
use crate::balancing::select::select;
use crate::balancing::solution::{Solution, TotalWeight};
use crate::balancing::solve as one_shot;
use crate::balancing::uncertainty::noise_options;
use crate::balancing::validate::{check, Checked, MAX_ANGLE_DEG};

/// Solve with the v2 options: `from_run`, `influence_coefficients`, and the
/// run checks; without them, exactly the v1 solve plus `run_checks`.
pub fn solve(session: &Session, options: &SolveOptions) -> Result<Solution, InputError> {
    solve_checked(check(session)?, options)
}

/// What a request's `coefficients_from` must be before any store is asked
/// for it: not beside `influence_coefficients` (the one or the other), a
/// `machine` that is a machine id (`validate::check_machine_id`) and a
/// `version` from 1. The one rule of the service (which then reads the
/// machine's coefficients into `influence_coefficients`) and of `fieldbal
/// solve` (which cannot read them, and says so when solving); errors name
/// `options.…`.
pub fn check_coefficients_from(options: &SolveOptions) -> Result<(), InputError> {
    let Some(from) = &options.coefficients_from else {
        return Ok(());
    };
    if options.influence_coefficients.is_some() {
        return Err(InputError::invalid(
            "conflicting_options",
            "options.influence_coefficients",
            "give influence_coefficients or coefficients_from, not both",
        ));
    }
    // The id rule, as for a trim job's `coefficients_from`: an id no
    // machine can have is a bad value, not one to look up.
    crate::balancing::validate::check_machine_id(
        || "options.coefficients_from.machine".into(),
        &from.machine,
    )?;
    // Below 1 no machine could have the version: a bad value, said as a
    // machine's coefficients and a trim job say it.
    if let Some(v) = from.version.filter(|&v| v < 1) {
        return Err(InputError::invalid(
            "out_of_range",
            "options.coefficients_from.version",
            crate::balancing::validate::version_below_one(v),
        ));
    }
    Ok(())
}

/// [`solve`] of a session its caller has already validated (`fieldbal solve`
/// validates a file first, to name errors under `session.` when it is wrapped).
pub fn solve_checked(checked: Checked<'_>, options: &SolveOptions) -> Result<Solution, InputError> {
    let session = checked.session;
    // A trim job whose options name no coefficients: the trim's.
    if let Some(with_trim) = trim::options_for(session, options) {
        return solve_checked(checked, &with_trim).map_err(trim::named_in_trim);
    }
    if options.coefficients_from.is_some() && options.influence_coefficients.is_none() {
        return Err(InputError::invalid(
            "coefficients_unavailable",
            "options.coefficients_from",
            "a machine's stored coefficients are read by the service (POST /api/v1/solve or a stored session's solutions); offline, give them as influence_coefficients",
        ));
    }
    let from = match &options.from_run {
        None => None,
        Some(id) => Some(
            session
                .runs
                .iter()
                .position(|r| &r.id == id)
                .ok_or_else(|| {
                    InputError::invalid(
                        "unknown_run",
                        "options.from_run",
                        format!("the session has no run '{id}'"),
                    )
                })?,
        ),
    };
    // The run checks read the posted session's rows as the solve selected
    // them, with the supplied coefficients it used: without `from_run` the
    // solve's own (no clone, no second selection, one resolution of the
    // coefficients: issue 15); with it the solve ran on the rebased session,
    // whose reference is run `r` (its rows and speeds), so the posted one is
    // selected and its coefficients resolved here.
    let (fit, selection, resolved);
    let (mut solution, checked, rows) = match from {
        // The session as posted is validated once, above.
        None => {
            resolved = supplied::resolve(&checked, options)?;
            let solution;
            (solution, fit) = one_shot::solve_kept(session, checked, resolved.as_ref(), options)?;
            (solution, &fit.checked, &fit.selection.rows)
        }
        Some(r) => {
            let solution = one_shot::solve(&rebase(session, r), options)?;
            selection = select(&checked, options)?;
            resolved = supplied::resolve(&checked, options)?;
            (solution, &checked, &selection.rows)
        }
    };

    if let Some(r) = from {
        let conv = checked.conventions;
        for corr in &mut solution.corrections {
            let on: num_complex::Complex64 = session.runs[r]
                .weights
                .iter()
                .filter(|w| w.plane == corr.plane)
                .map(|w| weight_in(conv, w.mass_g, w.angle_deg))
                .sum();
            let (mass_g, angle_deg) =
                weight_out(conv, on + weight_in(conv, corr.mass_g, corr.angle_deg));
            corr.total = Some(TotalWeight { mass_g, angle_deg });
        }
        solution.from_run = options.from_run.clone();
    }

    let noise = noise_options(options)?;
    let (run_checks, warnings) = match &resolved {
        Some(s) => {
            // Trials do not estimate W here: their small effect says nothing.
            solution.warnings.retain(|w| w.code != "trial_effect_small");
            checks::supplied_checks(checked, rows, noise, &s.w, &s.cov)
        }
        None => checks::run_checks(checked, rows, noise),
    };
    solution.warnings.extend(warnings);
    if !run_checks.is_empty() {
        solution.run_checks = Some(run_checks);
    }
    solution.runout = session.runout.clone();
    solution.coefficients_from = options.coefficients_from.clone();
    Ok(solution)
}

/// The session re-referenced to run `r`: that run's weights become the
/// reference state, so every run lists its weights minus run `r`'s (a weight
/// taken off is the same weight at the opposite angle). Run order is kept, so
/// field paths of errors still name the posted runs.
pub fn rebase(session: &Session, r: usize) -> Session {
    let off: Vec<Weight> = session.runs[r]
        .weights
        .iter()
        .map(|w| Weight {
            // Turned the way that stays within the angles a session allows:
            // a weight at 1e6° became 1e6 + 180°, which the rebased session's
            // check refused with a 422 naming no field of the request
            // (fuzzing, session 15).
            angle_deg: if w.angle_deg + 180.0 > MAX_ANGLE_DEG {
                w.angle_deg - 180.0
            } else {
                w.angle_deg + 180.0
            },
            ..w.clone()
        })
        .collect();
    let mut out = session.clone();
    for (i, run) in out.runs.iter_mut().enumerate() {
        if i == r {
            run.weights.clear();
            // Now the reference run: neither a trial nor a check (a purpose
            // on it would be refused by the rebased session's check).
            run.purpose = None;
        } else {
            run.weights.extend(off.iter().cloned());
        }
    }
    out
}
