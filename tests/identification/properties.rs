//! Property tests over the identification endpoints' accepted ranges
//! (`identification::ranges`, a rotor's `speed_range_rpm` among them):
//! every accepted request answers finite numbers and frequencies within the
//! accepted range, and no refusal of an in-range request is an overflow (`not_finite`), a solver failure or a
//! range error. Before the ranges (tidy18) the model property failed (a
//! 2-mass chain answered 0 Hz) and the free-decay one (8 junk samples
//! answered 4.7e5 Hz); their seeds are kept beside this file.

use crate::support::{session, speeds, Jeffcott};

use fieldbal::balancing::model::Unit;
use fieldbal::identification::correct::correct;
use fieldbal::identification::decay::{self, DampingLaw, FreeDecayRequest, DT_S};
use fieldbal::identification::model::{Initial, MatrixFamily, Mode, ModelRequest};
use fieldbal::identification::ranges::{FREQUENCY_HZ, SPEED_RPM};
use fieldbal::identification::rotor::{self, RotorOptions, RotorRequest};
use proptest::prelude::*;
use proptest::test_runner::FileFailurePersistence;

/// `sign · 10^e` for `e` uniform in `lo..hi`.
fn magnitude(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi, any::<bool>()).prop_map(|(e, neg)| if neg { -1.0 } else { 1.0 } * 10f64.powf(e))
}

fn positive(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo..hi).prop_map(|e| 10f64.powf(e))
}

/// Spring `j` of an `n`-mass chain of stiffness `k`: ground–0, then (j−1)–j.
fn spring(n: usize, j: usize, k: f64) -> Vec<Vec<f64>> {
    let mut a = vec![vec![0.0; n]; n];
    a[j][j] = k;
    if j > 0 {
        a[j - 1][j - 1] = k;
        a[j - 1][j] = -k;
        a[j][j - 1] = -k;
    }
    a
}

fn diagonal(d: &[f64]) -> Vec<Vec<f64>> {
    (0..d.len())
        .map(|i| {
            (0..d.len())
                .map(|j| if i == j { d[i] } else { 0.0 })
                .collect()
        })
        .collect()
}

/// A model request with every number in its accepted range: 1 to 3 masses
/// (known, or one estimated too), chain springs estimated, 1 to 3 modes.
fn model_requests() -> impl Strategy<Value = ModelRequest> {
    (1usize..=3).prop_flat_map(|n| {
        let mode = (
            positive(-2.0, 5.0),
            prop::collection::vec(prop::option::weighted(0.8, magnitude(-6.0, 6.0)), n),
            prop::option::of(positive(-3.0, 3.0)),
        )
            .prop_map(|(frequency_hz, shape, weight)| Mode {
                frequency_hz,
                shape: Some(shape),
                weight,
            });
        (
            prop::collection::vec(positive(-9.0, 9.0), n),
            any::<bool>(),
            prop::collection::vec(positive(-12.0, 12.0), n),
            prop::collection::vec(mode, 1..=n),
            prop::option::of(prop::collection::vec(magnitude(-15.0, 15.0), n)),
        )
            .prop_map(move |(masses, mass_unknown, springs, modes, start)| {
                let parameters = if mass_unknown {
                    vec![diagonal(&[&[1.0], &vec![0.0; n - 1][..]].concat())]
                } else {
                    vec![]
                };
                ModelRequest {
                    mass: MatrixFamily {
                        fixed: diagonal(&masses),
                        parameters,
                    },
                    stiffness: MatrixFamily {
                        fixed: vec![vec![0.0; n]; n],
                        parameters: (0..n).map(|j| spring(n, j, springs[j])).collect(),
                    },
                    modes,
                    initial: start.map(|s| Initial {
                        mass_parameters: mass_unknown.then(|| vec![1.0]),
                        stiffness_parameters: Some(s),
                    }),
                }
            })
    })
}

/// `cases` cases, failures kept beside this file (the default would look
/// for them beside the binary's main.rs).
fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..ProptestConfig::with_cases(cases)
    }
}

fn in_range(f: f64) -> bool {
    f.is_finite() && (FREQUENCY_HZ.0..=FREQUENCY_HZ.1).contains(&f)
}

/// Refusals an in-range request may get: what the data cannot give.
const NOT_FOR_IN_RANGE: [&str; 3] = ["not_finite", "solver_failed", "invalid_value"];

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn an_in_range_model_request_answers_finite_in_range_numbers_or_says_why_not(req in model_requests()) {
        match correct(&req) {
            Ok(c) => {
                prop_assert!(c.residual.is_finite(), "{c:?}");
                prop_assert!(c.mass_parameters.iter().chain(&c.stiffness_parameters).all(|x| x.is_finite()), "{c:?}");
                prop_assert!(c.frequencies_hz.iter().all(|&f| in_range(f)), "{c:?}");
            }
            Err(e) => prop_assert!(!NOT_FOR_IN_RANGE.contains(&e.code), "{e:?}"),
        }
    }

    #[test]
    fn an_in_range_free_decay_answers_finite_in_range_numbers_or_says_why_not(
        f in positive(-2.0, 5.0),
        theta in 0.05f64..3.0,
        zeta in positive(-5.0, -0.5),
        amplitude in positive(-11.0, 11.0),
        n in 8usize..400,
        junk in prop::collection::vec(magnitude(-12.0, 12.0), 8..40),
        law in prop::sample::select(vec![DampingLaw::Viscous, DampingLaw::Turbulent]),
    ) {
        let w = std::f64::consts::TAU * f;
        let dt_s = (theta / w).clamp(DT_S.0, DT_S.1);
        let decay: Vec<f64> = (0..n)
            .map(|k| {
                let t = k as f64 * dt_s;
                amplitude * (-zeta * w * t).exp() * (w * t + 0.3).cos()
            })
            .collect();
        for samples in [decay, junk] {
            let req = FreeDecayRequest { samples, dt_s, damping: law, offset: None };
            match decay::identify(&req) {
                Ok(d) => {
                    let all = [d.frequency_hz, d.c_over_m, d.b_over_m, d.decrement, d.amplitude, d.phase_deg, d.fit_rms];
                    prop_assert!(all.iter().all(|x| x.is_finite()), "{d:?}");
                    prop_assert!(in_range(d.frequency_hz), "{d:?}");
                }
                Err(e) => prop_assert!(!NOT_FOR_IN_RANGE.contains(&e.code), "{e:?}"),
            }
        }
    }
}

proptest! {
    #![proptest_config(config(32))]

    #[test]
    fn a_rotor_with_an_in_range_mass_and_cross_coupling_answers_finite_numbers(
        mass_kg in prop::option::of(positive(-9.0, 9.0)),
        kappa in prop::option::of(-10.0f64..10.0),
        rpm in 600.0f64..20_000.0,
        range in prop::option::of((0.0f64..6.0, 0.0f64..6.0)),
    ) {
        let rotor = Jeffcott::with(100.0, rpm, 0.05);
        // Any [lo, hi] within SPEED_RPM, lo < hi (log-uniform).
        let speed_range_rpm = range
            .map(|(a, b)| (10f64.powf(a.min(b)), 10f64.powf(a.max(b))))
            .filter(|(lo, hi)| lo < hi && SPEED_RPM.0 <= *lo && *hi <= SPEED_RPM.1)
            .map(|(lo, hi)| vec![lo, hi]);
        let req = RotorRequest {
            session: session(&[rotor], &speeds(0.5 * rpm, 1.5 * rpm, 7), Unit::UmPp, 0.01, 7),
            options: RotorOptions { mass_kg, cross_coupling_ratio: kappa, speed_range_rpm, ..RotorOptions::default() },
        };
        match rotor::identify(&req) {
            Ok(out) => {
                for r in &out.results {
                    let json = serde_json::to_value(r).unwrap();
                    let numbers = json.as_object().unwrap().values().filter(|v| !v.is_string());
                    for v in numbers {
                        prop_assert!(v.is_number(), "{r:?}");
                    }
                    prop_assert!(r.critical_speed_rpm > 0.0, "{r:?}");
                }
            }
            Err(e) => prop_assert!(!NOT_FOR_IN_RANGE.contains(&e.code), "{e:?}"),
        }
    }
}
