//! `decay` on exact records: the parameters come back; a ramp, a growing
//! oscillation and a step out of range are refused naming their field.

use super::*;

#[test]
fn an_exact_viscous_decay_gives_back_its_parameters() {
    let (w0, zeta, tau) = (5.0_f64, 0.03, 0.1);
    let n = zeta * w0;
    let wd = (w0 * w0 - n * n).sqrt();
    let samples: Vec<f64> = (0..30)
        .map(|k| {
            let t = k as f64 * tau;
            2.0 * (-n * t).exp() * (wd * t + 0.4).cos()
        })
        .collect();
    let got = identify(&FreeDecayRequest {
        samples,
        dt_s: tau,
        damping: DampingLaw::Viscous,
        offset: None,
    })
    .unwrap();
    assert!((got.c_over_m - w0 * w0).abs() < 1e-9 * w0 * w0);
    assert!((got.b_over_m - 2.0 * n).abs() < 1e-9);
    assert!((got.amplitude - 2.0).abs() < 1e-9);
    assert!((got.phase_deg - 0.4_f64.to_degrees()).abs() < 1e-7);
    assert!(got.fit_rms < 1e-10);
}

fn request(samples: Vec<f64>, dt_s: f64, damping: DampingLaw) -> FreeDecayRequest {
    FreeDecayRequest {
        samples,
        dt_s,
        damping,
        offset: None,
    }
}

/// `e^{rate·k} cos(0.7k + 0.3)`, 30 samples.
fn oscillation(rate: f64) -> Vec<f64> {
    (0..30)
        .map(|k| (rate * k as f64).exp() * (0.7 * k as f64 + 0.3).cos())
        .collect()
}

#[test]
fn a_ramp_or_a_growing_oscillation_is_refused_naming_the_samples() {
    // The ramp was answered 200 with 5.8e-9 Hz and a negative decrement
    // (review, session 17); a growth of 5 % a step with a decrement of -0.45.
    let ramp: Vec<f64> = (1..=8).map(f64::from).collect();
    for law in [DampingLaw::Viscous, DampingLaw::Turbulent] {
        for (samples, code) in [
            (ramp.clone(), "not_oscillatory"),
            (oscillation(0.05), "not_decaying"),
        ] {
            let err = identify(&request(samples, 1.0, law)).unwrap_err();
            assert_eq!(err.code, code, "{law:?}: {err:?}");
            assert_eq!(err.field.as_deref(), Some("samples"), "{law:?}");
            assert!(err.message.starts_with("no decaying oscillation found"));
        }
    }
}

#[test]
fn an_undamped_record_is_still_identified() {
    // Rounding must not make an exact constant amplitude "grow".
    let got = identify(&request(oscillation(0.0), 0.1, DampingLaw::Viscous)).unwrap();
    assert!((got.c_over_m - 49.0).abs() < 1e-9, "{got:?}");
    assert!(got.decrement.abs() < 1e-9, "{got:?}");
}

#[test]
fn a_step_outside_its_range_is_refused_naming_dt_s() {
    // 1e300 answered 0 Hz; 1e-300 a not_finite with no field (review, session 17).
    for dt_s in [1e300, 1e-300, 0.0, -0.1, 0.99e-9, 25.1, 1e3] {
        let err = identify(&request(oscillation(-0.05), dt_s, DampingLaw::Viscous)).unwrap_err();
        assert_eq!(err.field.as_deref(), Some("dt_s"), "{dt_s}: {err:?}");
        assert!(err.message.contains("from 1e-9 to 25,"), "{}", err.message);
    }
    // At either end, an oscillation of a frequency in range: 1e5 Hz at
    // 1e-9 s (two periods in 20 000 samples), 0.0127 Hz at 25 s.
    for (dt_s, theta, n) in [(DT_S.0, 6e-4, 20_000), (DT_S.1, 2.0, 30)] {
        let a = 0.05 * theta / 0.7;
        let samples = (0..n)
            .map(|k| (-a * k as f64).exp() * (theta * k as f64 + 0.3).cos())
            .collect();
        let got = identify(&request(samples, dt_s, DampingLaw::Viscous)).unwrap();
        let want = theta * theta + a * a;
        assert!(
            (got.c_over_m * dt_s * dt_s - want).abs() < 1e-6 * want,
            "{dt_s}: {got:?}"
        );
    }
}

#[test]
fn a_frequency_out_of_range_is_refused_naming_samples_and_dt_s() {
    // 0.7 rad a step at 25 s is 4.5e-3 Hz, at 1e-9 s 1.1e8 Hz.
    for dt_s in [DT_S.1, DT_S.0] {
        let err = identify(&request(oscillation(-0.05), dt_s, DampingLaw::Viscous)).unwrap_err();
        assert_eq!(err.code, "frequency_out_of_range", "{dt_s}: {err:?}");
        assert!(
            err.message
                .starts_with("the samples at this dt_s give a natural frequency of"),
            "{}",
            err.message
        );
    }
}

#[test]
fn a_nearly_undamped_record_that_fits_as_slightly_growing_is_still_answered() {
    // 1.5 % growth over the record: what noise can make of a lightly damped
    // decay. Its frequency is measured; the decrement says no damping is.
    let samples = oscillation(0.0005);
    let got = identify(&request(samples, 1.0, DampingLaw::Viscous)).expect("answered");
    assert!(got.decrement < 0.0 && got.decrement > -0.01, "{got:?}");
    let want = 0.7 / std::f64::consts::TAU;
    assert!((got.frequency_hz - want).abs() < 1e-6 * want, "{got:?}");
}
