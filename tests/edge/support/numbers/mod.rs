//! Extreme numbers in otherwise valid requests: every numeric field of rich,
//! valid bodies replaced, one or two at a time, by values at and past the
//! edges of what the checks accept: subnormals, 1e-320 to `f64::MAX`, 0 and
//! −0, negatives, angles at 360, integers past `u32` and `u64`. The service
//! must answer every one with a 2xx, or a 4xx whose JSON error has a code and
//! a message (and, for a value refused, the field at fault): never a 5xx. A
//! 2xx answer holds no `null` (a result that overflowed is written as one).
//!
//! `stateless` posts bodies that stand alone (solve, sessions, trial weights,
//! identification, the residual-unbalance check, machines); `stored` sends
//! them against stored resources (a session's runs appended and replaced,
//! its solutions with rich options, a machine's coefficients pooled from a
//! session with extremes and used by reference).
//!
//! Found so far: in session 14 a trial mass of 1e-320 g (every influence
//! coefficient infinite) and a supplied coefficient of 1e300 unit/g (NaN
//! singular values in the SVD), both panics; in session 15 26 row weights of
//! 1e6 on one row (a panic in the SVD), a row weight of 1e-300 and a service
//! speed of 1e-320 rpm (infinite covariance and permissible unbalance,
//! answered as `null`), residual-unbalance checks with numbers past a
//! session's ranges (`null` results), `max_mass_g` of 1e50 g and more (the
//! cone solver gave up, a 422 naming no field), a kept weight at 1e6°
//! with `from_run` (a 422 naming no field), and free decays and modal models
//! whose results overflowed (`null`).

mod stateless;
mod stored;

use rand::rngs::StdRng;
use rand::Rng;
use serde_json::{json, Value};

use crate::common::{post, send, Server};

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

/// An extreme: mostly a float of [`EXTREMES`], sometimes an integer at the
/// edges of the integer fields (`positions`, `fit_time_limit_ms`, `version`).
fn extreme(rng: &mut StdRng) -> Value {
    if rng.gen_bool(0.8) {
        json!(EXTREMES[rng.gen_range(0..EXTREMES.len())])
    } else {
        [
            json!(0),
            json!(-1),
            json!(60_001),
            json!(4_294_967_296u64),
            json!(i64::MAX),
            json!(i64::MIN),
            json!(u64::MAX),
        ][rng.gen_range(0..7)]
        .clone()
    }
}

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

/// `valid` with one or two of its numbers replaced by extremes.
fn mutate(valid: &Value, rng: &mut StdRng) -> Value {
    let mut body = valid.clone();
    let mut at = Vec::new();
    numbers(&body, String::new(), &mut at);
    for _ in 0..rng.gen_range(1..=2) {
        let ptr = &at[rng.gen_range(0..at.len())];
        *body.pointer_mut(ptr).unwrap() = extreme(rng);
    }
    body
}

/// Whether `v` holds a `null` anywhere.
fn has_null(v: &Value) -> bool {
    match v {
        Value::Null => true,
        Value::Array(items) => items.iter().any(has_null),
        Value::Object(map) => map.values().any(has_null),
        _ => false,
    }
}

/// Judge one answer (module doc); panics naming `what` and the body sent.
/// Returns whether it was a 2xx.
fn judge(what: &str, status: u16, answer: &Value, body: &Value) -> bool {
    assert!(status < 500, "{status} from {what}: {answer}\nbody: {body}");
    if status < 300 {
        assert!(
            !has_null(answer),
            "{what}: a null in {answer}\nbody: {body}"
        );
        return true;
    }
    let error = &answer["error"];
    assert!(error["code"].is_string(), "{status} from {what}: {answer}");
    // A value refused names its field; what the data as a whole cannot
    // give (an identification that is not determined, a decay that does not
    // oscillate) says so in its message.
    let code = error["code"].as_str().unwrap_or_default();
    if ["invalid_value", "invalid_type", "missing_field"].contains(&code) {
        assert!(error["field"].is_string(), "{what}: {answer}\nbody: {body}");
    }
    assert!(
        error["message"].as_str().is_some_and(|m| !m.is_empty()),
        "{answer}"
    );
    false
}

/// Where a sweep's requests go; every answer is judged (`judge`).
#[derive(Clone, Copy)]
struct Job<'a> {
    server: &'a Server,
    client: &'a reqwest::Client,
}

impl Job<'_> {
    async fn store(&self, session: &Value) -> String {
        let (status, _, created) =
            post(self.client, &self.server.url("/api/v1/sessions"), session).await;
        assert_eq!(status, 201, "{created}");
        created["id"].as_str().unwrap().to_string()
    }

    /// POST (or PUT) `body` to `path`, judged; whether it was a 2xx, and the answer.
    async fn send(&self, put: bool, path: &str, body: &Value) -> (bool, Value) {
        let url = self.server.url(path);
        let req = if put {
            self.client.put(url)
        } else {
            self.client.post(url)
        };
        let (status, _, answer) = send(req.json(body)).await;
        (judge(path, status, &answer, body), answer)
    }
}

/// `requests` mutated stand-alone bodies, then `requests / 2` against stored
/// resources (module doc); panics on the first fault, naming the body, and
/// returns how many answers were 2xx per body.
pub async fn never_a_server_error(
    server: &Server,
    client: &reqwest::Client,
    rng: &mut StdRng,
    requests: usize,
) -> Vec<usize> {
    let job = Job { server, client };
    let mut ok = stateless::sweep(&job, rng, requests).await;
    ok.extend(stored::sweep(&job, rng, requests / 2).await);
    ok
}
