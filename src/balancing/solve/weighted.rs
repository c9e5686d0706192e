//! Corrections by weighted least squares over all selected sensors and speeds
//! (method §3, the Den Hartog / Goodman multi-speed method), through the SVD.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use crate::balancing::diagnostics::{significance_factors, SIGNIFICANCE_THRESHOLD};
use crate::balancing::error::InputError;
use crate::balancing::factor::{Factored, ThinSvd};
use crate::balancing::influence::influence_and_pinv;
use crate::balancing::job::supplied::Supplied;
use crate::balancing::model::{Session, SolveOptions};
use crate::balancing::report;
use crate::balancing::select::{select, Selection};
use crate::balancing::solution::{Solution, Warning};
use crate::balancing::uncertainty;
use crate::balancing::validate::{check, Checked};

/// Everything a solve computed, in the internal frame (method §1). The report
/// and the extensions (cone solves, uncertainty) read it.
#[derive(Debug, Clone)]
pub struct Fit<'a> {
    pub checked: Checked<'a>,
    /// Influence matrix `W`, all rows × all planes (method 2.1).
    pub w: DMatrix<Complex64>,
    pub selection: Selection,
    /// Darlow significance factor of each plane in `selection.planes`.
    pub factors: Vec<f64>,
    /// Planes solved for: `selection.planes` less the dropped ones.
    pub planes: Vec<usize>,
    /// Planes left out by `drop_dependent_planes`.
    pub dropped: Vec<usize>,
    /// Correction `C`, one entry per plane of `planes`: the minimiser of the
    /// objective (least squares 3.2, or the cone programs of method 4).
    pub c: DVector<Complex64>,
    /// The errors-in-variables estimate `C*` of the exact correction (method
    /// 8.3) and its bias map, where it is formed (`uncertainty::debiased`);
    /// `None` elsewhere. Reported beside `c`, never in its place: the
    /// contract's correction minimises the objective, and the options' noise
    /// is for the confidence regions only.
    pub unbiased: Option<uncertainty::Unbiased>,
    /// Predicted vibration `R = Y0 + W C` (3.1) at every row.
    pub residual: DVector<Complex64>,
    /// The weighted matrix `G W` of the used rows and `planes`, factored once
    /// for the diagnostics, the report and the uncertainty (issue 15).
    pub factor: Factored,
    /// `T⁺` (trial runs × planes) that `w` was estimated with; `None` for
    /// supplied coefficients.
    pub t_pinv: Option<DMatrix<Complex64>>,
}

/// The weighted problem `min ‖G (Y0 + W C)‖` (3.3) on the used rows and `planes`:
/// returns `(G W, G Y0)`.
pub fn weighted_problem(
    checked: &Checked,
    w: &DMatrix<Complex64>,
    selection: &Selection,
    planes: &[usize],
) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let rows = &selection.rows;
    let a = DMatrix::from_fn(rows.len(), planes.len(), |i, j| {
        w[(rows[i], planes[j])] * selection.weights[i]
    });
    let b = DVector::from_fn(rows.len(), |i, _| {
        checked.y[(rows[i], 0)] * selection.weights[i]
    });
    (a, b)
}

/// Plain least squares `C = −A⁺ b` (3.2) through the SVD of `A`, never the
/// normal equations (they square the condition number).
pub fn least_squares(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
) -> Result<DVector<Complex64>, InputError> {
    // The thin SVD through QR (`factor`): the same answer as an SVD of the
    // tall `A`, in a fraction of the time on many rows (issue 15).
    let svd = ThinSvd::of(a);
    Ok(svd.solve(&(-b), 1e-13 * svd.max()))
}

/// The correction for the weighted problem, with any warnings the method adds.
///
/// Extension point: the objective and mass bounds of `options` choose the
/// method here; plain least squares is the default. The errors-in-variables
/// estimate is formed after, by `uncertainty::debiased`, only where the noise
/// is evidenced, and reported beside this correction (issue 12).
fn correction(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    factor: &Factored,
    options: &SolveOptions,
    session: &Session,
    planes: &[usize],
) -> Result<(DVector<Complex64>, Vec<Warning>), InputError> {
    // Min-max and mass bounds are cone programs (method 4.1).
    let condition = factor.condition_number();
    if let Some(found) =
        crate::balancing::conic::wiring::correction(a, b, options, session, planes, condition)?
    {
        return Ok(found);
    }
    // `least_squares` through the solve's one factorisation.
    Ok((factor.solve(&(-b), 1e-13 * factor.max()), Vec::new()))
}

/// Solve a session: influence coefficients, corrections, predicted residual,
/// diagnostics, in the session's conventions.
pub fn solve(session: &Session, options: &SolveOptions) -> Result<Solution, InputError> {
    solve_checked(session, check(session)?, options)
}

/// [`solve`] of a session already validated (`checked` is `check(session)`):
/// validation is a large share of a small solve, so it runs once per request.
pub fn solve_checked<'a>(
    session: &'a Session,
    checked: Checked<'a>,
    options: &SolveOptions,
) -> Result<Solution, InputError> {
    let supplied = crate::balancing::job::supplied::resolve(&checked, options)?;
    solve_kept(session, checked, supplied.as_ref(), options).map(|(solution, _)| solution)
}

/// [`solve_checked`], giving back the [`Fit`] too: the job layer's run checks
/// read its validated session and selection instead of cloning the one and
/// selecting again (issue 15). `supplied` is `job::supplied::resolve(&checked,
/// options)`, resolved by the caller so that its run checks read the same
/// coefficients without resolving them a second time.
pub fn solve_kept<'a>(
    session: &'a Session,
    checked: Checked<'a>,
    supplied: Option<&Supplied>,
    options: &SolveOptions,
) -> Result<(Solution, Fit<'a>), InputError> {
    // Supplied or stored coefficients (v2) replace the estimate from trial runs.
    let (w, t_pinv) = match supplied {
        Some(s) => (s.w.clone(), None),
        None => {
            let (w, t_pinv) = influence_and_pinv(&checked)?;
            (w, Some(t_pinv))
        }
    };
    let selection = select(&checked, options)?;
    let noise = uncertainty::noise_options(options)?;

    let (a_all, b_all) = weighted_problem(&checked, &w, &selection, &selection.planes);
    // One QR of `A` for the solve, the report and the uncertainty (issue 15).
    // The significance factors too: Gram–Schmidt of `A`'s unit columns sees
    // only their inner products, which `A = Q R` keeps (`Q` has orthonormal
    // columns), so it runs on the `q × q` `R` instead of the `rows × q` `A`.
    // Their first pivot, a tie of unit norms, is settled by plane order within
    // `PIVOT_TIE`, not by the rounding that differs between the two.
    let factor_all = Factored::of(&a_all);
    let factors = significance_factors(factor_all.small());
    let drop = options.drop_dependent_planes.unwrap_or(false);
    let (planes, dropped): (Vec<usize>, Vec<usize>) = if drop {
        let keep = |k: &usize| factors[*k] >= SIGNIFICANCE_THRESHOLD;
        let idx: Vec<usize> = (0..selection.planes.len()).collect();
        let (kept, gone): (Vec<usize>, Vec<usize>) = idx.into_iter().partition(keep);
        (
            kept.iter().map(|&k| selection.planes[k]).collect(),
            gone.iter().map(|&k| selection.planes[k]).collect(),
        )
    } else {
        (selection.planes.clone(), Vec::new())
    };
    if planes.is_empty() {
        return Err(InputError::invalid(
            "no_planes",
            "options.drop_dependent_planes",
            "every plane was found dependent and dropped: no plane is left to correct in",
        ));
    }
    if selection.rows.len() < planes.len() {
        return Err(InputError::unsolvable(
            "too_few_readings",
            format!(
                "{} correction planes need at least {} readings (sensor × speed) to balance on; {}",
                planes.len(),
                planes.len(),
                match selection.rows.len() {
                    1 => "1 is selected".to_string(),
                    n => format!("{n} are selected"),
                }
            ),
        ));
    }

    // Every plane kept (no plane dropped): the same `A` and factorisation.
    let (a, b, factor) = if planes.len() == selection.planes.len() {
        (a_all, b_all, factor_all)
    } else {
        let (a, b) = weighted_problem(&checked, &w, &selection, &planes);
        let factor = Factored::of(&a);
        (a, b, factor)
    };
    let (c, warnings) = correction(&a, &b, &factor, options, session, &planes)?;
    let cov = uncertainty::reading_covariances(&checked, noise);
    // The errors-in-variables estimate where the noise is evidenced (issue
    // 12), reported beside the correction, which stays the minimiser.
    let unbiased = match supplied {
        None => uncertainty::debiased(
            &checked,
            &cov,
            &selection.rows,
            &selection.weights,
            &planes,
            options,
            warnings.iter().any(|w| w.code == "mass_limit_active"),
            &c,
        ),
        Some(_) => None,
    };
    let w_used = DMatrix::from_fn(w.nrows(), planes.len(), |i, j| w[(i, planes[j])]);
    let residual = checked.y.column(0) + &w_used * &c;

    let fit = Fit {
        checked,
        w,
        selection,
        factors,
        planes,
        dropped,
        c,
        unbiased,
        residual,
        factor,
        t_pinv,
    };
    let mut solution = report::solution(&fit, options);
    solution.warnings.extend(warnings);
    // Confidence regions from reading noise (issue 6), after the method's warnings.
    match supplied {
        None => uncertainty::fill(&fit, options, &cov, &mut solution),
        Some(s) => crate::balancing::job::supplied::fill(&fit, s, options, noise, &mut solution),
    }
    // The ISO 21940-11 verdict reads the corrections' uncertainty (issue 17).
    crate::balancing::acceptance::iso::fill(session, &mut solution);
    // Kit weights, jointly over the planes, and the static/couple parts (issue 11).
    crate::balancing::fit::fill(&fit, options, &a, &b, &mut solution)?;
    Ok((solution, fit))
}
