//! Extreme numbers against stored resources: a run appended to a stored
//! session (then solved from that run) or put in place of one (then
//! solved); a stored session's solutions with rich options (bounds, row
//! weights, noise, kits, `from_run`, supplied coefficients, a machine's
//! coefficients by reference); a machine's coefficients pooled with extreme
//! options, or from a session stored with extremes and then used by reference.

use rand::rngs::StdRng;
use rand::Rng;
use serde_json::json;

use super::stateless::{coefficients, reference_only, rich_session};
use super::{mutate, Job};
use crate::common::{path_segment, post};

const MACHINE: &str = "NUMBERS-M";

/// How many run requests go to one stored session before a fresh one (a
/// session holds at most 200 runs).
const RUNS_PER_SESSION: usize = 20;

/// `requests` mutated bodies against stored resources, with the requests
/// each success leads to; 2xx answers per kind of body.
pub(super) async fn sweep(job: &Job<'_>, rng: &mut StdRng, requests: usize) -> Vec<usize> {
    let Job { server, client } = *job;
    let mut rich = rich_session();
    rich["machine"] = json!(MACHINE);
    let machine = json!({"id": MACHINE, "name": "numbers"});
    let (status, _, _) = post(client, &server.url("/api/v1/machines"), &machine).await;
    assert!(status == 201 || status == 409, "{status}");
    let full = job.store(&rich).await;
    let reference = job.store(&reference_only(&rich)).await;
    let pool = format!("/api/v1/machines/{MACHINE}/coefficients");
    let (pooled, answer) = job.send(false, &pool, &json!({"sessions": [full]})).await;
    assert!(pooled, "{answer}");
    let version = answer["version"].clone();
    let coefficients = coefficients(server, client).await;
    let solutions = |id: &str| format!("/api/v1/sessions/{id}/solutions");

    // (path, valid body) of the options and the pooling.
    let options = [
        (
            solutions(&full),
            json!({"objective": "min_max", "max_mass_g": {"inboard": 20.0, "outboard": 50.0},
                   "row_weights": [{"sensor": "DE-H", "weight": 2.0}, {"speed_rpm": 2950.0, "weight": 0.5},
                                   {"sensor": "NDE-V", "speed_rpm": 2950.0, "weight": 3.0}],
                   "speeds_rpm": [2950.0], "amplitude_noise_pct": 3.0, "phase_noise_deg": 3.0}),
        ),
        (
            solutions(&full),
            json!({"discrete": true, "fit_time_limit_ms": 20, "from_run": "trial inboard",
                   "max_mass_g": {"inboard": 40.0}, "amplitude_noise_pct": 1.0}),
        ),
        (
            solutions(&reference),
            json!({"influence_coefficients": coefficients, "discrete": true, "fit_time_limit_ms": 20}),
        ),
        (
            solutions(&reference),
            json!({"coefficients_from": {"machine": MACHINE, "version": version},
                   "objective": "min_max", "max_mass_g": {"outboard": 30.0}}),
        ),
        (
            pool.clone(),
            json!({"sessions": [full], "options": {"amplitude_noise_pct": 3.0, "phase_noise_deg": 3.0}}),
        ),
    ];
    // A trial run with two weights, appended under a fresh id; a run put in place.
    let mut appended = rich["runs"][1].clone();
    appended["weights"]
        .as_array_mut()
        .unwrap()
        .push(json!({"plane": "outboard", "mass_g": 7.0, "angle_deg": 33.0}));
    let replaced = rich["runs"][2].clone();
    let replaced_id = replaced["id"].as_str().unwrap().to_string();

    // Kinds: the options, then appended runs, replaced runs, stored sessions pooled.
    let mut ok = vec![0; options.len() + 3];
    let mut session = job.store(&rich).await;
    let mut run_requests = 0;
    for n in 0..requests {
        let kind = rng.gen_range(0..ok.len());
        if kind < options.len() {
            let (path, valid) = &options[kind];
            ok[kind] += usize::from(job.send(false, path, &mutate(valid, rng)).await.0);
            continue;
        }
        if kind < options.len() + 2 {
            run_requests += 1;
            if run_requests % RUNS_PER_SESSION == 0 {
                session = job.store(&rich).await;
            }
        }
        if kind == options.len() {
            let mut run = mutate(&appended, rng);
            let id = format!("appended {n}");
            run["id"] = json!(id);
            let path = format!("/api/v1/sessions/{session}/runs");
            if job.send(false, &path, &run).await.0 {
                ok[kind] += 1;
                job.send(false, &solutions(&session), &json!({"from_run": id}))
                    .await;
            }
        } else if kind == options.len() + 1 {
            let path = format!(
                "/api/v1/sessions/{session}/runs/{}",
                path_segment(&replaced_id)
            );
            if job.send(true, &path, &mutate(&replaced, rng)).await.0 {
                ok[kind] += 1;
                let discrete = json!({"discrete": true, "fit_time_limit_ms": 20});
                job.send(false, &solutions(&session), &discrete).await;
            }
        } else {
            // A session of the machine stored with extremes, pooled with the
            // full one, and its coefficients used by reference.
            let stored = mutate(&rich, rng);
            let (created, answer) = job.send(false, "/api/v1/sessions", &stored).await;
            if !created {
                continue;
            }
            let sessions = json!({"sessions": [full, answer["id"]]});
            let (pooled, answer) = job.send(false, &pool, &sessions).await;
            if pooled {
                ok[kind] += 1;
                let from = json!({"coefficients_from": {"machine": MACHINE, "version": answer["version"]}});
                job.send(false, &solutions(&reference), &from).await;
            }
        }
    }
    ok
}
