//! Extreme numbers in otherwise valid requests: every numeric field of rich,
//! valid bodies (a session with rotor data, radii, fixed places, kits and
//! samples; the same with supplied influence coefficients; a trial-weight
//! request; a free-decay record; a modal model; a multi-speed session for
//! identification) replaced, one or two at a time, by values at and past the
//! edges of what the checks accept: subnormals, 1e-320 to `f64::MAX`, 0 and
//! −0, negatives, angles at 360. The service must answer every one with a
//! 2xx, or a 4xx whose JSON error has a code and a message (and, for a
//! value refused, the field at fault): never a 5xx. Fuzzing this way found two panics in session 14, a
//! trial mass of 1e-320 g (every influence coefficient infinite) and a
//! supplied coefficient of 1e300 unit/g (NaN singular values in the SVD).

use rand::rngs::StdRng;
use rand::Rng;
use serde_json::{json, Value};

use crate::common::{example, post, Server};

/// The values put in place of a number.
const EXTREMES: [f64; 24] = [
    0.0,
    -0.0,
    5e-324,
    1e-320,
    1e-300,
    1e-12,
    1e-9,
    1e-7,
    1e-6,
    1e-3,
    0.5,
    1.0,
    3.0,
    360.0,
    -360.0,
    -1.0,
    -1e-9,
    1e6,
    1e7,
    1e9,
    1e15,
    1e300,
    f64::MAX,
    9_007_199_254_740_992.0,
];

/// JSON pointers of every number inside `v`.
fn numbers(v: &Value, at: String, out: &mut Vec<String>) {
    match v {
        Value::Number(_) => out.push(at),
        Value::Array(items) => {
            for (i, x) in items.iter().enumerate() {
                numbers(x, format!("{at}/{i}"), out);
            }
        }
        Value::Object(map) => {
            for (k, x) in map {
                numbers(
                    x,
                    format!("{at}/{}", k.replace('~', "~0").replace('/', "~1")),
                    out,
                );
            }
        }
        _ => {}
    }
}

/// Valid bodies, by path, rich in numbers.
async fn bodies(server: &Server, client: &reqwest::Client) -> Vec<(&'static str, Value)> {
    let plain = example("pump-two-plane-exact.json")["session"].clone();
    let mut rich = plain.clone();
    rich["rotor"] = json!({"mass_kg": 120.0, "service_speed_rpm": 2950.0, "balance_grade": "G2.5"});
    for p in rich["planes"].as_array_mut().unwrap() {
        p["radius_mm"] = json!(150.0);
        p["positions"] = json!(12);
        p["kit"] = json!({"masses_g": [1.0, 2.0, 5.0, 10.0], "max_per_place": 2});
    }
    for run in rich["runs"].as_array_mut().unwrap() {
        for r in run["readings"].as_array_mut().unwrap().iter_mut().take(2) {
            let (a, ph) = (
                r["amplitude"].as_f64().unwrap(),
                r["phase_deg"].as_f64().unwrap(),
            );
            r["samples"] = json!([
                {"amplitude": a * 0.99, "phase_deg": ph - 1.0},
                {"amplitude": a, "phase_deg": ph},
                {"amplitude": a * 1.01, "phase_deg": ph + 1.0}
            ]);
        }
    }
    // Supplied coefficients: the plain session's own, with only its reference run.
    let (status, _, solved) = post(
        client,
        &server.url("/api/v1/solve"),
        &json!({"session": plain}),
    )
    .await;
    assert_eq!(status, 200, "{solved}");
    let coefficients: Vec<Value> = solved["influence_coefficients"]
        .as_array()
        .expect("the solution's coefficients")
        .iter()
        .map(|c| {
            json!({"speed_rpm": c["speed_rpm"], "sensor": c["sensor"], "plane": c["plane"],
                   "amplitude_per_g": c["amplitude_per_g"], "phase_deg": c["phase_deg"],
                   "covariance": [[0.01, 0.0], [0.0, 0.01]]})
        })
        .collect();
    let mut reference = rich.clone();
    reference["runs"] = json!([rich["runs"][0].clone()]);
    assert!(reference["runs"][0]["weights"]
        .as_array()
        .unwrap()
        .is_empty());
    let decay: Vec<f64> = (0..30)
        .map(|k| (-0.05 * k as f64).exp() * (0.7 * k as f64 + 0.3).cos())
        .collect();
    vec![
        (
            "/api/v1/solve",
            json!({"session": rich, "options": {"objective": "min_max", "max_mass_g": {"inboard": 20.0}}}),
        ),
        (
            "/api/v1/solve",
            json!({"session": rich, "options": {"amplitude_noise_pct": 3.0, "phase_noise_deg": 3.0, "discrete": true, "fit_time_limit_ms": 20}}),
        ),
        (
            "/api/v1/solve",
            json!({"session": reference, "options": {"influence_coefficients": coefficients}}),
        ),
        ("/api/v1/sessions", rich.clone()),
        ("/api/v1/trial-weights", json!({"session": reference})),
        (
            "/api/v1/identify/free-decay",
            json!({"samples": decay, "dt_s": 0.05, "damping": "viscous"}),
        ),
        (
            "/api/v1/identify/model",
            json!({
                "mass": {"fixed": [[2.0, 0.0], [0.0, 1.0]]},
                "stiffness": {"fixed": [[0.0, 0.0], [0.0, 0.0]], "parameters": [[[1.0, 0.0], [0.0, 0.0]], [[1.0, -1.0], [-1.0, 1.0]]]},
                "modes": [{"frequency_hz": 4.11, "shape": [0.4, 0.93]}, {"frequency_hz": 10.3, "shape": [0.66, -0.61]}]
            }),
        ),
        (
            "/api/v1/identify/rotor",
            json!({"session": example("compressor-multispeed-exact.json")["session"]}),
        ),
    ]
}

/// `requests` mutated bodies (module doc); panics on the first 5xx, naming
/// the body, and returns how many answers were 2xx per body.
pub async fn never_a_server_error(
    server: &Server,
    client: &reqwest::Client,
    rng: &mut StdRng,
    requests: usize,
) -> Vec<usize> {
    let bodies = bodies(server, client).await;
    let mut ok = vec![0; bodies.len()];
    for _ in 0..requests {
        let k = rng.gen_range(0..bodies.len());
        let (path, valid) = &bodies[k];
        let mut body = valid.clone();
        let mut at = Vec::new();
        numbers(&body, String::new(), &mut at);
        for _ in 0..rng.gen_range(1..=2) {
            let ptr = &at[rng.gen_range(0..at.len())];
            *body.pointer_mut(ptr).unwrap() = json!(EXTREMES[rng.gen_range(0..EXTREMES.len())]);
        }
        let (status, _, answer) = post(client, &server.url(path), &body).await;
        assert!(status < 500, "{status} from {path}: {answer}\nbody: {body}");
        if status < 300 {
            ok[k] += 1;
        } else {
            let error = &answer["error"];
            assert!(error["code"].is_string(), "{status} from {path}: {answer}");
            // A value refused names its field; what the data as a whole
            // cannot give (an identification that is not determined, a
            // decay that does not oscillate) says so in its message.
            let code = error["code"].as_str().unwrap_or_default();
            if ["invalid_value", "invalid_type", "missing_field"].contains(&code) {
                assert!(error["field"].is_string(), "{path}: {answer}\nbody: {body}");
            }
            assert!(
                error["message"].as_str().is_some_and(|m| !m.is_empty()),
                "{answer}"
            );
        }
    }
    ok
}
