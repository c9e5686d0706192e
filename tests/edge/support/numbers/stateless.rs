//! Stand-alone bodies rich in numbers: a session with rotor data, radii,
//! fixed places, kits, samples and runout; the same with supplied influence
//! coefficients; a trial-weight request; a free-decay record; a modal model;
//! a multi-speed session for identification; residual-unbalance checks with
//! and without phases; a machine with its rotor.

use rand::rngs::StdRng;
use rand::Rng;
use serde_json::{json, Value};

use super::{mutate, Job};
use crate::common::{example, post, Server};

/// The session of the examples with every optional number filled in.
pub(super) fn rich_session() -> Value {
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
    rich["runout"] = json!([{"sensor": "DE-H", "amplitude": 3.0, "phase_deg": 20.0}]);
    rich
}

/// The plain example's own influence coefficients, with a covariance each.
pub(super) async fn coefficients(server: &Server, client: &reqwest::Client) -> Value {
    let plain = example("pump-two-plane-exact.json")["session"].clone();
    let (status, _, solved) = post(
        client,
        &server.url("/api/v1/solve"),
        &json!({"session": plain}),
    )
    .await;
    assert_eq!(status, 200, "{solved}");
    solved["influence_coefficients"]
        .as_array()
        .expect("the solution's coefficients")
        .iter()
        .map(|c| {
            json!({"speed_rpm": c["speed_rpm"], "sensor": c["sensor"], "plane": c["plane"],
                   "amplitude_per_g": c["amplitude_per_g"], "phase_deg": c["phase_deg"],
                   "covariance": [[0.01, 0.0], [0.0, 0.01]]})
        })
        .collect()
}

/// `session` with its reference run alone.
pub(super) fn reference_only(session: &Value) -> Value {
    let mut reference = session.clone();
    reference["runs"] = json!([session["runs"][0].clone()]);
    assert!(reference["runs"][0]["weights"]
        .as_array()
        .unwrap()
        .is_empty());
    reference
}

/// The residual-unbalance check of the test data, with its optional numbers.
fn residual(phases: bool) -> Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/residual/left-plane-12-positions.json"
    );
    let mut b: Value = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    b["amplitude_noise_pct"] = json!(3.0);
    b["phase_noise_deg"] = json!(3.0);
    if !phases {
        for r in b["readings"].as_array_mut().unwrap() {
            r.as_object_mut().unwrap().remove("phase_deg");
        }
    }
    b
}

/// Valid bodies, by path, rich in numbers.
async fn bodies(server: &Server, client: &reqwest::Client) -> Vec<(&'static str, Value)> {
    let rich = rich_session();
    let coefficients = coefficients(server, client).await;
    let reference = reference_only(&rich);
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
        ("/api/v1/residual-unbalance", residual(true)),
        ("/api/v1/residual-unbalance", residual(false)),
        (
            "/api/v1/machines",
            json!({"id": "id set per request", "name": "numbers", "notes": "n",
                   "rotor": {"mass_kg": 120.0, "service_speed_rpm": 2950.0, "balance_grade": "G2.5"}}),
        ),
    ]
}

/// `requests` mutated stand-alone bodies; 2xx answers per body.
pub(super) async fn sweep(job: &Job<'_>, rng: &mut StdRng, requests: usize) -> Vec<usize> {
    let bodies = bodies(job.server, job.client).await;
    let mut ok = vec![0; bodies.len()];
    for n in 0..requests {
        let k = rng.gen_range(0..bodies.len());
        let (path, valid) = &bodies[k];
        let mut body = mutate(valid, rng);
        if *path == "/api/v1/machines" {
            body["id"] = json!(format!("NUMBERS-{n}"));
        }
        if job.send(false, path, &body).await.0 {
            ok[k] += 1;
        }
    }
    ok
}
