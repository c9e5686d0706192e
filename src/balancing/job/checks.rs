//! Run checks (v2 `run_checks`): each run with weights whose readings the
//! other runs can predict (the other runs alone determine the influence
//! coefficients, method 2.1) is compared with that prediction,
//! `Y_0 + W_{−k} T_k`, by the χ² test of [`super::linear`] at the 99 % level,
//! with the readings' noise (the solve's `amplitude_noise_pct`,
//! `phase_noise_deg`, or the samples' scatter) and the propagated noise of the
//! prediction as the yardstick. A run that fails says `consistent: false` and
//! the warning `run_inconsistent` names it. With supplied coefficients each
//! trial run is predicted from them instead (their covariance included), and a
//! failure is `coefficients_disagree`.

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

use super::linear::{self, Data, Source, Trial};
use crate::balancing::phasor::reading_out;
use crate::balancing::solution::{RunCheck, RunCheckRow, Warning};
use crate::balancing::uncertainty::{amplitude_95, reading_covariances, Noise};
use crate::balancing::validate::Checked;

/// The session's readings as [`Data`]: columns in `checked.runs` order, every
/// trial against the reference run (column 0).
pub fn data(checked: &Checked, noise: Noise) -> Data {
    let mut data = readings(checked);
    data.cov = reading_covariances(checked, noise);
    data
}

/// [`data`] without the readings' covariances (`cov` empty): what finding the
/// estimable runs needs, before any covariance is read (issue 15).
fn readings(checked: &Checked) -> Data {
    let trials = (1..checked.runs.len())
        .map(|k| Trial {
            col: k,
            reference: 0,
            weights: DVector::from_fn(checked.t.nrows(), |j, _| checked.t[(j, k - 1)]),
        })
        .collect();
    Data {
        y: checked.y.clone(),
        cov: Vec::new(),
        trials,
        planes: checked.t.nrows(),
    }
}

/// One check in the solution's shape.
fn run_check(
    checked: &Checked,
    data: &Data,
    k: usize,
    rows: &[usize],
    t: &linear::Test,
) -> RunCheck {
    let conv = checked.conventions;
    let session = checked.session;
    let col = data.trials[k].col;
    let mut check_rows = Vec::with_capacity(rows.len());
    for (i, &a) in rows.iter().enumerate() {
        let (measured, measured_phase_deg) = reading_out(conv, data.y[(a, col)]);
        let pred = t.predicted[0][i];
        let (predicted, predicted_phase_deg) = reading_out(conv, pred);
        let row = &checked.rows[a];
        check_rows.push(RunCheckRow {
            speed_rpm: row.speed_rpm,
            sensor: session.sensors[row.sensor].id.clone(),
            measured,
            measured_phase_deg,
            predicted,
            predicted_phase_deg,
            amplitude_95: amplitude_95(pred, &t.cov[0][i]),
        });
    }
    let rms = |f: &dyn Fn(&RunCheckRow) -> f64| {
        let n = check_rows.len().max(1) as f64;
        (check_rows.iter().map(|r| f(r).powi(2)).sum::<f64>() / n).sqrt()
    };
    RunCheck {
        run: session.runs[checked.runs[col]].id.clone(),
        rms_measured: rms(&|r| r.measured),
        rms_predicted: rms(&|r| r.predicted),
        consistent: t.consistent,
        chi2: t.chi2,
        dof: t.dof,
        rows: check_rows,
    }
}

/// Leave-one-out checks of every trial run the others can predict, at `rows`.
pub fn run_checks(
    checked: &Checked,
    rows: &[usize],
    noise: Noise,
) -> (Vec<RunCheck>, Vec<Warning>) {
    // Only runs the others determine are checked: with one trial per plane
    // (the usual job) none is, and the readings' covariances, a reading noise
    // model per reading, are not needed (issue 15: a twentieth of a large solve).
    let mut data = readings(checked);
    let n = data.trials.len();
    let others = |k: usize| -> Vec<usize> { (0..n).filter(|&i| i != k).collect() };
    let checkable: Vec<usize> = (0..n)
        .filter(|&k| linear::determines(&data, &others(k)))
        .collect();
    if !checkable.is_empty() {
        data.cov = reading_covariances(checked, noise);
    }
    let mut checks = Vec::new();
    let mut warnings = Vec::new();
    for k in checkable {
        let Some(est) = linear::estimate(&data, &others(k)) else {
            continue;
        };
        let t = linear::test(&data, &[k], rows, Source::Estimated(&est));
        let check = run_check(checked, &data, k, rows, &t);
        if !check.consistent {
            warnings.push(Warning {
                code: "run_inconsistent".into(),
                message: format!(
                    "run '{}' differs from what the other runs predict for its weights by more than the readings' noise explains (χ² {:.1} for {} degrees of freedom, 99 % limit {:.1}; rms {:.3} measured, {:.3} predicted): check its weights (mass, angle, plane, a weight that fell off or was left on) and its readings; a rotor that is not linear does this too",
                    check.run, check.chi2, check.dof, linear::chi2_quantile(check.dof), check.rms_measured, check.rms_predicted
                ),
                plane: None,
            });
        }
        checks.push(check);
    }
    (checks, warnings)
}

/// Checks of every trial run against supplied coefficients `w` (covariance
/// `wcov[row][plane]`), at `rows`.
pub fn supplied_checks(
    checked: &Checked,
    rows: &[usize],
    noise: Noise,
    w: &DMatrix<Complex64>,
    wcov: &[Vec<Matrix2<f64>>],
) -> (Vec<RunCheck>, Vec<Warning>) {
    let data = data(checked, noise);
    let mut checks = Vec::new();
    for k in 0..data.trials.len() {
        let t = linear::test(&data, &[k], rows, Source::Given(w, wcov));
        checks.push(run_check(checked, &data, k, rows, &t));
    }
    let bad: Vec<&str> = checks
        .iter()
        .filter(|c| !c.consistent)
        .map(|c| c.run.as_str())
        .collect();
    let mut warnings = Vec::new();
    if !bad.is_empty() {
        warnings.push(Warning {
            code: "coefficients_disagree".into(),
            message: format!(
                "run(s) {} differ from what the job's influence coefficients (supplied with it, or stored for its machine) predict for their weights by more than the noise of the readings and of the coefficients explains: the rotor or its mounting may have changed since the coefficients were measured, or a weight or reading was typed wrong; the correction uses those coefficients",
                bad.iter().map(|r| format!("'{r}'")).collect::<Vec<_>>().join(", ")
            ),
            plane: None,
        });
    }
    (checks, warnings)
}
