//! Experimental influence coefficients from any run sequence (method §2):
//! `ΔY = W T`, so `W = ΔY T⁺`, through the SVD of `T`.

use nalgebra::DMatrix;
use num_complex::Complex64;

use crate::balancing::error::InputError;
use crate::balancing::factor::cmul;
use crate::balancing::validate::Checked;

/// Relative singular value below which the trial weights count as dependent.
const RANK_TOLERANCE: f64 = 1e-9;

/// `ΔY = Y_r − Y_0 1ᵀ` (method 2.1), rows × trial runs.
///
/// Through the storage slices, written once (issue 15, session 9: copying
/// `Y` then subtracting through nalgebra's column iterators took 39
/// instructions an entry); the same differences, bit for bit.
pub fn changes(checked: &Checked) -> DMatrix<Complex64> {
    let (n, runs) = checked.y.shape();
    if n == 0 || runs == 0 {
        return DMatrix::zeros(n, runs.saturating_sub(1));
    }
    let (y0, trials) = checked.y.as_slice().split_at(n);
    let mut data = Vec::with_capacity(trials.len());
    for col in trials.chunks_exact(n) {
        data.extend(col.iter().zip(y0).map(|(y, y0)| y - y0));
    }
    DMatrix::from_vec(n, runs - 1, data)
}

/// The influence matrix `W` (rows × planes, vibration per gram at angle 0 in the
/// internal frame), or an error saying which planes lack an independent trial.
pub fn influence_matrix(checked: &Checked) -> Result<DMatrix<Complex64>, InputError> {
    influence_and_pinv(checked).map(|(w, _)| w)
}

/// [`influence_matrix`] and the `T⁺` it was formed with (trial runs × planes),
/// which the uncertainty propagation needs too (issue 15: one SVD of `T`,
/// a full complex SVD for a square many-plane job).
pub fn influence_and_pinv(
    checked: &Checked,
) -> Result<(DMatrix<Complex64>, DMatrix<Complex64>), InputError> {
    let session = checked.session;
    let t = &checked.t;
    let (planes, trials) = t.shape();
    if trials < planes {
        return Err(InputError::invalid(
            "too_few_trial_runs",
            "runs",
            format!(
                "{planes} correction planes need at least {planes} trial runs, one independent trial per plane; the session has {trials}"
            ),
        ));
    }
    let svd = t.clone().svd(true, true);
    let smax = svd.singular_values.max();
    let weak: Vec<usize> = (0..planes)
        .filter(|&k| svd.singular_values[k] <= RANK_TOLERANCE * smax)
        .collect();
    if smax == 0.0 || !weak.is_empty() {
        // Left singular vectors of the zero singular values show the planes whose
        // trials cannot be told apart.
        let u = svd.u.as_ref().expect("SVD computed with U");
        let mut involved: Vec<&str> = (0..planes)
            .filter(|&j| weak.iter().any(|&k| u[(j, k)].norm() > 1e-6) || smax == 0.0)
            .map(|j| session.planes[j].id.as_str())
            .collect();
        involved.dedup();
        return Err(InputError::invalid(
            "dependent_trials",
            "runs",
            format!(
                "the trial weights do not give every plane an independent trial: plane(s) {} cannot be told apart; add a run with a trial weight in one of them alone",
                involved.join(", ")
            ),
        ));
    }
    let t_pinv = svd
        .pseudo_inverse(0.0)
        .map_err(|e| InputError::unsolvable("solver_failed", e.to_string()))?;
    // Four real products (`factor::cmul`, issue 15): `W` is rounded in another
    // order than nalgebra's complex product; the significance factors' first
    // pivot, a tie of unit norms, is settled by plane order, not by rounding.
    Ok((cmul(&changes(checked), &t_pinv), t_pinv))
}
