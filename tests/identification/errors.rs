//! Bad input to the identification endpoints, through a real server: the
//! contract's 4xx errors naming the field (too few speeds or samples, a
//! non-square or asymmetric matrix, a shape of the wrong length, NaN, a
//! non-positive step), as a table.

use crate::common;
use crate::support;

use common::{fresh_server, post};
use serde_json::{json, Value};
use support::{free_decay_request, model_request, rotor_with, with};

#[tokio::test]
async fn bad_input_is_refused_with_the_field_named() {
    let two_speeds = rotor_with(|v| {
        for run in v["session"]["runs"].as_array_mut().unwrap() {
            run["readings"].as_array_mut().unwrap().truncate(2);
        }
    });
    let cases: Vec<(&str, &str, Value, u16, &str)> = vec![
        (
            "two speeds",
            "rotor",
            two_speeds,
            422,
            "session.runs[0].readings",
        ),
        (
            "range leaves too few speeds",
            "rotor",
            rotor_with(|v| v["options"]["speed_range_rpm"] = json!([900, 1600])),
            422,
            "options.speed_range_rpm",
        ),
        (
            "reversed range",
            "rotor",
            rotor_with(|v| v["options"]["speed_range_rpm"] = json!([3000, 1000])),
            422,
            "options.speed_range_rpm",
        ),
        (
            "unknown sensor",
            "rotor",
            rotor_with(|v| v["options"]["sensors"] = json!(["9V"])),
            422,
            "options.sensors[0]",
        ),
        (
            "negative mass",
            "rotor",
            rotor_with(|v| v["options"]["mass_kg"] = json!(-3)),
            422,
            "options.mass_kg",
        ),
        (
            "known mass, no radius",
            "rotor",
            rotor_with(|v| {
                v["options"]["mass_kg"] = json!(100);
                v["session"]["planes"][0]
                    .as_object_mut()
                    .unwrap()
                    .remove("radius_mm");
            }),
            422,
            "session.planes[0].radius_mm",
        ),
        (
            "negative amplitude",
            "rotor",
            rotor_with(|v| v["session"]["runs"][1]["readings"][0]["amplitude"] = json!(-1)),
            422,
            "session.runs[1].readings[0].amplitude",
        ),
        (
            "no trial run",
            "rotor",
            rotor_with(|v| {
                v["session"]["runs"].as_array_mut().unwrap().pop();
            }),
            422,
            "session.runs",
        ),
        // The one-mass fit's refusals named no field (review, session 20).
        (
            "a trial that changed nothing",
            "rotor",
            rotor_with(|v| {
                let reference = v["session"]["runs"][0]["readings"].clone();
                v["session"]["runs"][1]["readings"] = reference;
            }),
            422,
            "session.runs[1].readings",
        ),
        (
            "a tied cross-coupling that cancels the damping",
            "rotor",
            rotor_with(|v| v["options"]["cross_coupling_ratio"] = json!(1.0)),
            422,
            "options.cross_coupling_ratio",
        ),
        (
            "unknown option",
            "rotor",
            rotor_with(|v| v["options"]["speed_rang_rpm"] = json!([1, 2])),
            400,
            "options.speed_rang_rpm",
        ),
        (
            "seven samples",
            "free-decay",
            with(free_decay_request(), |v| {
                v["samples"].as_array_mut().unwrap().truncate(7);
            }),
            422,
            "samples",
        ),
        (
            "zero step",
            "free-decay",
            with(free_decay_request(), |v| v["dt_s"] = json!(0)),
            422,
            "dt_s",
        ),
        (
            "negative step",
            "free-decay",
            with(free_decay_request(), |v| v["dt_s"] = json!(-0.1)),
            422,
            "dt_s",
        ),
        (
            "NaN sample",
            "free-decay",
            with(free_decay_request(), |v| v["samples"][3] = json!("NaN")),
            422,
            "samples[3]",
        ),
        (
            "all zero",
            "free-decay",
            with(free_decay_request(), |v| {
                v["samples"] = json!(vec![0.0; 12])
            }),
            422,
            "samples",
        ),
        // Samples the decay models cannot fit (a constant, a lone spike, an
        // alternation at the Nyquist rate) answered `unidentifiable` naming
        // no field (review, session 20).
        (
            "constant samples",
            "free-decay",
            with(free_decay_request(), |v| {
                v["samples"] = json!(vec![1.0; 30])
            }),
            422,
            "samples",
        ),
        (
            "a lone spike, turbulent",
            "free-decay",
            with(free_decay_request(), |v| {
                let mut y = vec![0.0; 30];
                y[29] = 1.0;
                v["samples"] = json!(y);
                v["damping"] = json!("turbulent");
            }),
            422,
            "samples",
        ),
        (
            "alternating samples",
            "free-decay",
            with(free_decay_request(), |v| {
                v["samples"] = json!((0..30)
                    .map(|k| if k % 2 == 0 { 1.0 } else { -1.0 })
                    .collect::<Vec<f64>>())
            }),
            422,
            "samples",
        ),
        (
            "offset too large",
            "free-decay",
            with(free_decay_request(), |v| v["offset"] = json!(1e13)),
            422,
            "offset",
        ),
        // Pure noise was answered as a decay (review, session 21).
        (
            "pure noise",
            "free-decay",
            with(free_decay_request(), |v| {
                let mut state: u64 = 1;
                v["samples"] = json!((0..200)
                    .map(|_| {
                        state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
                        (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
                    })
                    .collect::<Vec<f64>>())
            }),
            422,
            "samples",
        ),
        (
            "unknown law",
            "free-decay",
            with(free_decay_request(), |v| v["damping"] = json!("coulomb")),
            422,
            "damping",
        ),
        (
            "non-square",
            "model",
            with(model_request(), |v| v["mass"]["fixed"][1] = json!([1.0])),
            422,
            "mass.fixed[1]",
        ),
        (
            "asymmetric",
            "model",
            with(model_request(), |v| {
                v["stiffness"]["parameters"][1][1][0] = json!(-2.0)
            }),
            422,
            "stiffness.parameters[1][1][0]",
        ),
        (
            "wrong size",
            "model",
            with(model_request(), |v| {
                v["stiffness"]["parameters"][0] = json!([[1.0]])
            }),
            422,
            "stiffness.parameters[0]",
        ),
        (
            "shape too long",
            "model",
            with(model_request(), |v| {
                v["modes"][1]["shape"] = json!([1.0, 2.0, 3.0])
            }),
            422,
            "modes[1].shape",
        ),
        (
            "NaN in a matrix",
            "model",
            with(model_request(), |v| v["mass"]["fixed"][0][0] = json!("NaN")),
            422,
            "mass.fixed[0][0]",
        ),
        (
            "zero frequency",
            "model",
            with(model_request(), |v| {
                v["modes"][0]["frequency_hz"] = json!(0)
            }),
            422,
            "modes[0].frequency_hz",
        ),
        (
            "negative weight",
            "model",
            with(model_request(), |v| v["modes"][0]["weight"] = json!(-1)),
            422,
            "modes[0].weight",
        ),
        (
            "no parameters",
            "model",
            with(model_request(), |v| {
                v["stiffness"]["parameters"] = json!([])
            }),
            422,
            "stiffness.parameters",
        ),
        (
            "initial of wrong length",
            "model",
            with(model_request(), |v| {
                v["initial"] = json!({"stiffness_parameters": [1.0]})
            }),
            422,
            "initial.stiffness_parameters",
        ),
    ];
    let (_dir, server, client) = fresh_server().await;
    for (name, what, body, want_status, want_field) in cases {
        let (status, _, answer) = post(
            &client,
            &server.url(&format!("/api/v1/identify/{what}")),
            &body,
        )
        .await;
        assert_eq!(status, want_status, "{name}: {answer}");
        assert_eq!(answer["error"]["field"], want_field, "{name}: {answer}");
        assert!(
            answer["error"]["code"].is_string() && answer["error"]["message"].is_string(),
            "{name}: {answer}"
        );
    }
    server.shutdown().await;
}

/// An empty `options.sensors` or `options.planes` answered 200 with no results
/// (session 19); a repeated id was silently merged. Both are refused as
/// `/solve` refuses them: `no_rows` / `no_planes` naming the list,
/// `duplicate_id` naming the repeat.
#[tokio::test]
async fn empty_or_repeated_selections_are_refused_like_the_solves() {
    let cases: Vec<(&str, Value, &str, &str)> = vec![
        (
            "no sensors",
            rotor_with(|v| v["options"]["sensors"] = json!([])),
            "no_rows",
            "options.sensors",
        ),
        (
            "no planes",
            rotor_with(|v| v["options"]["planes"] = json!([])),
            "no_planes",
            "options.planes",
        ),
        (
            "a sensor twice",
            rotor_with(|v| v["options"]["sensors"] = json!(["1H", "1H"])),
            "duplicate_id",
            "options.sensors[1]",
        ),
        (
            "a plane twice",
            rotor_with(|v| v["options"]["planes"] = json!(["A", "A"])),
            "duplicate_id",
            "options.planes[1]",
        ),
        (
            "unknown plane",
            rotor_with(|v| v["options"]["planes"] = json!(["A", "B"])),
            "unknown_plane",
            "options.planes[1]",
        ),
        (
            "unknown sensor",
            rotor_with(|v| v["options"]["sensors"] = json!(["9V"])),
            "unknown_sensor",
            "options.sensors[0]",
        ),
    ];
    let (_dir, server, client) = fresh_server().await;
    let url = server.url("/api/v1/identify/rotor");
    for (name, body, want_code, want_field) in cases {
        let (status, _, answer) = post(&client, &url, &body).await;
        assert_eq!(status, 422, "{name}: {answer}");
        assert_eq!(answer["error"]["code"], want_code, "{name}: {answer}");
        assert_eq!(answer["error"]["field"], want_field, "{name}: {answer}");
    }
    // The same lists without the fault are answered.
    let (status, _, answer) = post(
        &client,
        &url,
        &rotor_with(|v| v["options"] = json!({"sensors": ["1H"], "planes": ["A"]})),
    )
    .await;
    assert_eq!(status, 200, "{answer}");
    assert_eq!(
        answer["results"].as_array().map(Vec::len),
        Some(1),
        "{answer}"
    );
    server.shutdown().await;
}

/// True when `message` reads without the method's formula numbers ("(7.1)")
/// or its symbols ("e^{-2nτ}", "κ", "ω²", "Σ"), which a technician at the
/// stand cannot look up; "method §7" may stay.
fn plain_words(message: &str) -> bool {
    let formula_number = message.as_bytes().windows(5).any(|w| {
        w[0] == b'('
            && w[1].is_ascii_digit()
            && w[2] == b'.'
            && w[3].is_ascii_digit()
            && w[4] == b')'
    });
    !formula_number
        && !message.contains("e^")
        && !message.chars().any(|c| "τωζκσλχψθφΣ√²ᵢ".contains(c))
}

/// Refusals whose messages quoted the method's formulas: "(the fit (7.1)
/// gave e^{-2nτ} ≤ 0)", "of the form a0/(1 + λt) cos(ωt + ψ0)", "the
/// cross-coupling ratio κ of q = κ·b·ω", "M = M0 + Σ mᵢ Mᵢ" (session 25's
/// review). They now say it in words.
#[tokio::test]
async fn refusals_are_worded_without_formula_numbers_or_symbols() {
    let half_rate: Vec<f64> = (0..100)
        .map(|k| if k % 2 == 0 { 1.0 } else { -1.0 } * 0.99f64.powi(k))
        .collect();
    let decay = |law: &str| json!({"samples": half_rate, "dt_s": 0.01, "damping": law});
    let cases: Vec<(&str, &str, Value)> = vec![
        (
            "viscous at half the sampling rate",
            "free-decay",
            decay("viscous"),
        ),
        (
            "turbulent at half the sampling rate",
            "free-decay",
            decay("turbulent"),
        ),
        (
            "cross-coupling ratio out of range",
            "rotor",
            rotor_with(|v| v["options"]["cross_coupling_ratio"] = json!(50)),
        ),
        (
            "a negative mass",
            "model",
            with(model_request(), |v| {
                v["mass"]["fixed"] = json!([[-1.0, 0.0], [0.0, 1.0]])
            }),
        ),
    ];
    let (_dir, server, client) = fresh_server().await;
    for (name, what, body) in cases {
        let url = server.url(&format!("/api/v1/identify/{what}"));
        let (status, _, answer) = post(&client, &url, &body).await;
        assert_eq!(status, 422, "{name}: {answer}");
        let message = answer["error"]["message"].as_str().unwrap();
        assert!(plain_words(message), "{name}: {message}");
    }
    server.shutdown().await;
}
