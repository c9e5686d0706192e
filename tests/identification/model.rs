//! `identify/model` (the lecture's discrete-model correction) on a 3-mass
//! chain with known masses and stiffnesses: stiffnesses from eigenpairs
//! rounded to 3 significant digits, masses and stiffnesses together, and
//! shapes measured at some degrees of freedom only (iteration).

use fieldbal::identification::correct::correct;
use fieldbal::identification::model::{Initial, MatrixFamily, Mode, ModelRequest};
use nalgebra::{DMatrix, SymmetricEigen};

const MASSES: [f64; 3] = [2.0, 1.5, 1.0];
const SPRINGS: [f64; 3] = [3000.0, 2000.0, 1000.0];

fn rows(a: &DMatrix<f64>) -> Vec<Vec<f64>> {
    a.row_iter().map(|r| r.iter().copied().collect()).collect()
}

/// Spring `j` of the chain: ground–mass 0, then mass j−1 – mass j.
fn spring(j: usize) -> DMatrix<f64> {
    let mut k = DMatrix::zeros(3, 3);
    k[(j, j)] = 1.0;
    if j > 0 {
        k[(j - 1, j - 1)] = 1.0;
        k[(j - 1, j)] = -1.0;
        k[(j, j - 1)] = -1.0;
    }
    k
}

fn point_mass(i: usize) -> DMatrix<f64> {
    let mut m = DMatrix::zeros(3, 3);
    m[(i, i)] = 1.0;
    m
}

fn sig3(x: f64) -> f64 {
    if x == 0.0 {
        return 0.0;
    }
    let p = 10f64.powi(2 - x.abs().log10().floor() as i32);
    (x * p).round() / p
}

/// The true chain's frequencies (Hz) and mass-normalised shapes, independently
/// of the library: `M^{-1/2} K M^{-1/2}` is symmetric for a diagonal `M`.
fn true_modes() -> Vec<(f64, Vec<f64>)> {
    let k: DMatrix<f64> = (0..3)
        .map(|j| spring(j) * SPRINGS[j])
        .fold(DMatrix::zeros(3, 3), |a, b| a + b);
    let s = DMatrix::from_fn(
        3,
        3,
        |i, j| if i == j { 1.0 / MASSES[i].sqrt() } else { 0.0 },
    );
    let eig = SymmetricEigen::new(&s * k * &s);
    let mut modes: Vec<(f64, Vec<f64>)> = (0..3)
        .map(|c| {
            let phi = &s * eig.eigenvectors.column(c);
            (
                eig.eigenvalues[c].sqrt() / std::f64::consts::TAU,
                phi.iter().copied().collect(),
            )
        })
        .collect();
    modes.sort_by(|a, b| a.0.total_cmp(&b.0));
    modes
}

fn measured(round: bool, dofs: &[usize]) -> Vec<Mode> {
    let r = |x: f64| if round { sig3(x) } else { x };
    true_modes()
        .into_iter()
        .map(|(f, shape)| Mode {
            frequency_hz: r(f),
            shape: Some(
                (0..3)
                    .map(|i| dofs.contains(&i).then(|| r(shape[i])))
                    .collect(),
            ),
            weight: None,
        })
        .collect()
}

/// The chain's masses, known: a fixed diagonal mass matrix.
fn masses_known() -> MatrixFamily {
    let m0 = DMatrix::from_diagonal(&nalgebra::DVector::from_row_slice(&MASSES));
    MatrixFamily {
        fixed: rows(&m0),
        parameters: vec![],
    }
}

/// The chain's masses, unknown: one parameter a point mass.
fn masses_unknown() -> MatrixFamily {
    MatrixFamily {
        fixed: vec![vec![0.0; 3]; 3],
        parameters: (0..3).map(|i| rows(&point_mass(i))).collect(),
    }
}

fn stiffness_unknown() -> MatrixFamily {
    MatrixFamily {
        fixed: vec![vec![0.0; 3]; 3],
        parameters: (0..3).map(|j| rows(&spring(j))).collect(),
    }
}

fn rel(got: &[f64], want: &[f64]) -> f64 {
    got.iter()
        .zip(want)
        .map(|(g, w)| (g - w).abs() / w)
        .fold(0.0, f64::max)
}

#[test]
fn stiffnesses_from_eigenpairs_rounded_to_three_digits_are_off_by_about_the_rounding() {
    let req = ModelRequest {
        mass: masses_known(),
        stiffness: stiffness_unknown(),
        modes: measured(true, &[0, 1, 2]),
        initial: None,
    };
    let got = correct(&req).unwrap();
    let e = rel(&got.stiffness_parameters, &SPRINGS);
    println!(
        "stiffnesses {:?}, worst error {:.3} %",
        got.stiffness_parameters,
        100.0 * e
    );
    // Three significant digits round by up to 0.5 %; the estimate stays of that order.
    assert!(e < 0.01, "{got:?}");
    assert_eq!(got.iterations, 1);
    let want_f: Vec<f64> = true_modes().iter().map(|m| m.0).collect();
    assert!(rel(&got.frequencies_hz, &want_f) < 0.005, "{got:?}");
}

#[test]
fn masses_and_stiffnesses_together_come_from_mass_normalised_rounded_shapes() {
    let req = ModelRequest {
        mass: masses_unknown(),
        stiffness: stiffness_unknown(),
        modes: measured(true, &[0, 1, 2]),
        initial: None,
    };
    let got = correct(&req).unwrap();
    let (em, ek) = (
        rel(&got.mass_parameters, &MASSES),
        rel(&got.stiffness_parameters, &SPRINGS),
    );
    println!(
        "masses {:?} ({:.3} %), stiffnesses {:?} ({:.3} %)",
        got.mass_parameters,
        100.0 * em,
        got.stiffness_parameters,
        100.0 * ek
    );
    assert!(em < 0.02 && ek < 0.02, "{got:?}");
    // Exact eigenpairs give the model back exactly.
    let exact = correct(&ModelRequest {
        modes: measured(false, &[0, 1, 2]),
        ..req
    })
    .unwrap();
    assert!(
        rel(&exact.mass_parameters, &MASSES) < 1e-9
            && rel(&exact.stiffness_parameters, &SPRINGS) < 1e-9,
        "{exact:?}"
    );
}

#[test]
fn shapes_measured_at_two_of_three_masses_are_completed_by_iteration() {
    let req = ModelRequest {
        mass: masses_known(),
        stiffness: stiffness_unknown(),
        modes: measured(false, &[0, 1]),
        initial: Some(Initial {
            mass_parameters: None,
            stiffness_parameters: Some(SPRINGS.iter().map(|k| 0.7 * k).collect()),
        }),
    };
    let got = correct(&req).unwrap();
    println!(
        "partial shapes: {:?} after {} iterations",
        got.stiffness_parameters, got.iterations
    );
    assert!(got.iterations > 1, "{got:?}");
    assert!(rel(&got.stiffness_parameters, &SPRINGS) < 1e-6, "{got:?}");
}

#[test]
fn masses_and_stiffnesses_with_partial_normalised_shapes_settle_on_the_true_model() {
    let req = ModelRequest {
        mass: masses_unknown(),
        stiffness: stiffness_unknown(),
        modes: measured(false, &[0, 2]),
        initial: Some(Initial {
            mass_parameters: Some(MASSES.iter().map(|m| 1.2 * m).collect()),
            stiffness_parameters: Some(SPRINGS.iter().map(|k| 0.8 * k).collect()),
        }),
    };
    let got = correct(&req).unwrap();
    println!("partial, masses too: {got:?}");
    assert!(
        rel(&got.mass_parameters, &MASSES) < 1e-5
            && rel(&got.stiffness_parameters, &SPRINGS) < 1e-5,
        "{got:?}"
    );
}

#[test]
fn a_start_of_zero_masses_still_gives_the_true_model() {
    // The equations were divided by the start's mean mass, here 0, floored at
    // the smallest positive number: weights near 1e305, column norms that
    // overflowed, and this well-posed request refused as unidentifiable.
    let req = ModelRequest {
        mass: masses_unknown(),
        stiffness: stiffness_unknown(),
        modes: measured(false, &[0, 1, 2]),
        initial: Some(Initial {
            mass_parameters: Some(vec![0.0; 3]),
            stiffness_parameters: None,
        }),
    };
    let got = correct(&req).unwrap();
    assert!(
        rel(&got.mass_parameters, &MASSES) < 1e-9
            && rel(&got.stiffness_parameters, &SPRINGS) < 1e-9,
        "{got:?}"
    );
}
