//! `parts` through the solve's own factorisation (`fit.factor`: QR of `A`,
//! then the SVD of the small `R`) against an SVD of the whole weighted matrix
//! `A = G W` of its own (the code before session 10): `A⁺`, `(AᴴA)⁺`, the
//! correction `−A⁺ b` against the fit's and both covariance contributions
//! (reference readings and supplied coefficients) agree to `TOL` relative
//! (Frobenius norm of the difference over that of the old answer) on every
//! example with an expected answer and on 200 seeded random supplied jobs.

use nalgebra::DMatrix;
use num_complex::Complex64;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use serde_json::{json, Value};

use super::{coefficient_part, parts, reading_part, reference_covariances, Parts, RANK_TOLERANCE};
use crate::balancing::job::supplied::resolve;
use crate::balancing::model::{Conventions, Session, SolveOptions, SuppliedCoefficient};
use crate::balancing::solve::{solve_kept, weighted_problem, Fit};
use crate::balancing::uncertainty::noise_options;
use crate::balancing::validate::check;

const TOL: f64 = 1e-12;

/// `A⁺`, `(AᴴA)⁺` and `r` as before session 10: an SVD of `A` of its own.
fn parts_by_own_svd(fit: &Fit) -> Parts {
    let sel = &fit.selection;
    let a = DMatrix::from_fn(sel.rows.len(), fit.planes.len(), |i, j| {
        fit.w[(sel.rows[i], fit.planes[j])] * sel.weights[i]
    });
    let r = nalgebra::DVector::from_fn(sel.rows.len(), |i, _| {
        fit.residual[sel.rows[i]] * sel.weights[i]
    });
    let (m, q) = a.shape();
    let mut pinv = DMatrix::zeros(q, m);
    let mut gram = DMatrix::zeros(q, q);
    let svd = a.svd(true, true);
    let (u, vt) = (svd.u.unwrap(), svd.v_t.unwrap());
    let smax = svd.singular_values.max();
    for (i, &s) in svd.singular_values.iter().enumerate() {
        if s <= RANK_TOLERANCE * smax || s == 0.0 {
            continue;
        }
        let v = vt.row(i).adjoint();
        pinv += &v * u.column(i).adjoint() / Complex64::from(s);
        gram += &v * v.adjoint() / Complex64::from(s * s);
    }
    Parts { pinv, gram, r }
}

fn rel_c(new: &DMatrix<Complex64>, old: &DMatrix<Complex64>) -> f64 {
    (new - old).norm() / old.norm().max(f64::MIN_POSITIVE)
}

fn rel_r(new: &DMatrix<f64>, old: &DMatrix<f64>) -> f64 {
    (new - old).norm() / old.norm().max(f64::MIN_POSITIVE)
}

/// The largest relative difference between the two ways over one job, and
/// the condition number of its `A`.
fn difference(session: &Session, options: &SolveOptions) -> (f64, f64) {
    let checked = check(session).expect("valid session");
    let supplied = resolve(&checked, options)
        .expect("coefficients resolve")
        .expect("coefficients supplied");
    let (_, fit) = solve_kept(session, checked, Some(&supplied), options).expect("solves");
    let new = parts(&fit);
    let old = parts_by_own_svd(&fit);
    let y0 = reference_covariances(&fit, noise_options(options).unwrap());
    let cov = |p: &Parts| reading_part(&fit, p, &y0) + coefficient_part(&fit, p, &supplied);
    let (_, b) = weighted_problem(&fit.checked, &fit.w, &fit.selection, &fit.planes);
    let c_old = -(&old.pinv * &b);
    let c = (&fit.c - &c_old).norm() / c_old.norm();
    let worst = [
        rel_c(&new.pinv, &old.pinv),
        rel_c(&new.gram, &old.gram),
        rel_r(&cov(&new), &cov(&old)),
        c,
    ]
    .into_iter()
    .fold(0.0, f64::max);
    let s = fit.factor.singular_values();
    (worst, s.max() / s.min())
}

/// Each example with an expected answer, solved against its own estimated
/// coefficients given back as supplied ones, with a correlated covariance.
#[test]
fn the_fit_factorisation_gives_the_parts_of_an_svd_of_its_own_on_the_examples() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/examples");
    let mut compared = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let bytes = std::fs::read(&path).unwrap();
        let value: Value = serde_json::from_slice(&bytes).unwrap();
        if value.get("expected").is_none() {
            continue;
        }
        let (session, mut options) = crate::balancing::parse_session_file(&bytes).unwrap();
        let estimated = crate::balancing::solve(&session, &options).unwrap();
        let mut list = serde_json::to_value(&estimated.influence_coefficients).unwrap();
        for c in list.as_array_mut().unwrap() {
            let sd = 0.03 * c["amplitude_per_g"].as_f64().unwrap();
            c["covariance"] = json!([[sd * sd, 0.3 * sd * sd], [0.3 * sd * sd, 0.5 * sd * sd]]);
        }
        options.influence_coefficients = Some(serde_json::from_value(list).unwrap());
        let (worst, cond) = difference(&session, &options);
        assert!(worst <= TOL, "{path:?}: {worst:e} (condition {cond:.1})");
        compared += 1;
    }
    assert!(compared >= 5, "{compared} examples compared");
}

/// A job of only a reference run: random sizes (1–4 planes, 1–4 sensors,
/// speeds enough for a row per plane), readings, coefficients and their
/// covariances, conventions and stated noise.
fn random_job(rng: &mut StdRng) -> (Session, SolveOptions) {
    let conv = Conventions::ALL[rng.gen_range(0..4)];
    let planes: usize = rng.gen_range(1..=4);
    let sensors: usize = rng.gen_range(1..=4);
    let speeds = rng.gen_range(1..=3usize).max(planes.div_ceil(sensors));
    let mut readings = Vec::new();
    let mut list = Vec::new();
    for p in 0..speeds {
        let speed = 1000.0 + 700.0 * p as f64;
        for s in 0..sensors {
            readings.push(json!({"speed_rpm": speed, "sensor": format!("S{s}"),
                "amplitude": rng.gen_range(20.0..150.0), "phase_deg": rng.gen_range(0.0..360.0)}));
            for j in 0..planes {
                let amp: f64 = rng.gen_range(0.2..3.0);
                let l = [0, 1, 2].map(|_| rng.gen_range(-1.0..1.0) * 0.05 * amp);
                let cov = [
                    [l[0] * l[0], l[0] * l[1]],
                    [l[0] * l[1], l[1] * l[1] + l[2] * l[2]],
                ];
                list.push(SuppliedCoefficient {
                    speed_rpm: speed,
                    sensor: format!("S{s}"),
                    plane: format!("P{j}"),
                    amplitude_per_g: amp,
                    phase_deg: rng.gen_range(0.0..360.0),
                    covariance: Some(cov),
                    unit: None,
                });
            }
        }
    }
    let session = json!({
        "name": "random", "conventions": conv,
        "planes": (0..planes).map(|j| json!({"id": format!("P{j}")})).collect::<Vec<_>>(),
        "sensors": (0..sensors).map(|s| json!({"id": format!("S{s}"), "unit": "um_pp"})).collect::<Vec<_>>(),
        "runs": [{"id": "zero", "weights": [], "readings": readings}],
    });
    let options = SolveOptions {
        influence_coefficients: Some(list),
        amplitude_noise_pct: Some(rng.gen_range(0.5..5.0)),
        phase_noise_deg: Some(rng.gen_range(0.5..5.0)),
        ..SolveOptions::default()
    };
    (serde_json::from_value(session).unwrap(), options)
}

#[test]
fn the_fit_factorisation_gives_the_parts_of_an_svd_of_its_own_on_random_supplied_jobs() {
    let mut rng = StdRng::seed_from_u64(15);
    let (mut worst, mut cond) = (0.0f64, 0.0f64);
    for k in 0..200 {
        let (session, options) = random_job(&mut rng);
        let (d, c) = difference(&session, &options);
        assert!(d <= TOL, "job {k}: {d:e} (condition {c:.1})");
        worst = worst.max(d);
        cond = cond.max(c);
    }
    eprintln!("largest relative difference {worst:e}, largest condition number {cond:.1}");
}
