//! A table of bad requests against the real server: each gets its status and the
//! contract's JSON error body naming the field at fault, nothing is stored, and
//! the server still answers afterwards.

use crate::common;

use common::{example, fresh_server, post, send};
use serde_json::{json, Value};

/// A request body: JSON, or raw bytes for what JSON cannot express.
enum Body {
    Json(Value),
    Raw(Vec<u8>),
    None,
}

struct Case {
    name: &'static str,
    method: &'static str,
    /// `{id}` is replaced by a stored session's id, `{run}` by one of its run ids.
    path: &'static str,
    content_type: Option<&'static str>,
    body: Body,
    status: u16,
    code: &'static str,
    field: Option<&'static str>,
}

const JSON: Option<&str> = Some("application/json");

fn session() -> Value {
    example("pump-two-plane-exact.json")["session"].clone()
}

/// The valid session with one change.
fn with(change: impl FnOnce(&mut Value)) -> Body {
    let mut s = session();
    change(&mut s);
    Body::Json(s)
}

fn run(i: usize) -> Value {
    session()["runs"][i].clone()
}

#[rustfmt::skip]
fn cases() -> Vec<Case> {
    let c = |name, method, path, content_type, body, status, code, field| Case {
        name, method, path, content_type, body, status, code, field,
    };
    let sessions = "/api/v1/sessions";
    vec![
        // Not JSON, or JSON of the wrong shape.
        c("truncated JSON", "POST", sessions, JSON, Body::Raw(b"{\"name\": ".to_vec()), 400, "malformed_json", None),
        c("empty body", "POST", sessions, JSON, Body::Raw(Vec::new()), 400, "malformed_json", None),
        c("trailing garbage", "POST", sessions, JSON, Body::Raw(format!("{} x", session()).into_bytes()), 400, "malformed_json", None),
        c("bare NaN token", "POST", sessions, JSON, Body::Raw(br#"{"name": NaN}"#.to_vec()), 400, "malformed_json", Some("name")),
        c("an array, not a session", "POST", sessions, JSON, Body::Json(json!([])), 422, "invalid_type", None),
        c("unknown top-level field", "POST", sessions, JSON, with(|s| s["nmae"] = json!("x")), 400, "unknown_field", Some("nmae")),
        c("unknown reading field", "POST", sessions, JSON, with(|s| s["runs"][0]["readings"][0]["phase_dg"] = json!(3)), 400, "unknown_field", Some("runs[0].readings[0].phase_dg")),
        c("name is a number", "POST", sessions, JSON, with(|s| s["name"] = json!(5)), 422, "invalid_type", Some("name")),
        c("amplitude is a string", "POST", sessions, JSON, with(|s| s["runs"][0]["readings"][1]["amplitude"] = json!("88")), 422, "invalid_type", Some("runs[0].readings[1].amplitude")),
        c("NaN as a string", "POST", sessions, JSON, with(|s| s["runs"][1]["readings"][0]["phase_deg"] = json!("NaN")), 422, "invalid_type", Some("runs[1].readings[0].phase_deg")),
        c("number beyond f64", "POST", sessions, JSON, Body::Raw(session().to_string().replacen("\"amplitude\":", "\"amplitude\":1e400,\"x\":", 1).into_bytes()), 400, "malformed_json", Some("runs[0].readings[0].amplitude")),
        c("mass beyond f64 in a posted run", "POST", "/api/v1/sessions/{id}/runs", JSON, Body::Raw(run(1).to_string().replacen("\"mass_g\":30.0", "\"mass_g\":-1e999", 1).replacen("\"trial inboard\"", "\"new\"", 1).into_bytes()), 400, "malformed_json", Some("weights[0].mass_g")),
        c("a key given twice", "POST", sessions, JSON, Body::Raw(session().to_string().replacen("\"name\":", "\"name\":\"a\",\"name\":", 1).into_bytes()), 422, "invalid_type", Some("name")),
        c("a reading's key given twice", "POST", sessions, JSON, Body::Raw(session().to_string().replacen("\"phase_deg\":", "\"phase_deg\":1,\"phase_deg\":", 1).into_bytes()), 422, "invalid_type", Some("runs[0].readings[0].phase_deg")),
        c("huge amplitude", "POST", sessions, JSON, with(|s| s["runs"][0]["readings"][0]["amplitude"] = json!(1e300)), 422, "invalid_value", Some("runs[0].readings[0].amplitude")),
        c("negative amplitude", "POST", sessions, JSON, with(|s| s["runs"][0]["readings"][2]["amplitude"] = json!(-1.0)), 422, "invalid_value", Some("runs[0].readings[2].amplitude")),
        c("negative mass", "POST", sessions, JSON, with(|s| s["runs"][1]["weights"][0]["mass_g"] = json!(-30)), 422, "invalid_value", Some("runs[1].weights[0].mass_g")),
        c("mass is null", "POST", sessions, JSON, with(|s| s["runs"][1]["weights"][0]["mass_g"] = Value::Null), 422, "invalid_type", Some("runs[1].weights[0].mass_g")),
        c("missing name", "POST", sessions, JSON, with(|s| { s.as_object_mut().unwrap().remove("name"); }), 422, "missing_field", Some("name")),
        c("unknown unit", "POST", sessions, JSON, with(|s| s["sensors"][0]["unit"] = json!("furlongs")), 422, "invalid_type", Some("sensors[0].unit")),
        c("unknown phase convention", "POST", sessions, JSON, with(|s| s["conventions"]["phase"] = json!("sideways")), 422, "invalid_type", Some("conventions.phase")),
        c("missing reference run", "POST", sessions, JSON, with(|s| { s["runs"].as_array_mut().unwrap().remove(0); }), 422, "no_reference_run", Some("runs")),
        c("two reference runs", "POST", sessions, JSON, with(|s| s["runs"][1]["weights"] = json!([])), 422, "second_reference_run", Some("runs[1].weights")),
        c("duplicate run ids", "POST", sessions, JSON, with(|s| s["runs"][2]["id"] = s["runs"][1]["id"].clone()), 422, "duplicate_id", Some("runs[2].id")),
        c("unknown plane", "POST", sessions, JSON, with(|s| s["runs"][1]["weights"][0]["plane"] = json!("middle")), 422, "unknown_plane", Some("runs[1].weights[0].plane")),
        c("unknown sensor", "POST", sessions, JSON, with(|s| s["runs"][2]["readings"][3]["sensor"] = json!("XX")), 422, "unknown_sensor", Some("runs[2].readings[3].sensor")),
        c("missing trial reading", "POST", sessions, JSON, with(|s| { s["runs"][2]["readings"].as_array_mut().unwrap().pop(); }), 422, "missing_reading", Some("runs[2].readings")),
        c("empty id", "POST", sessions, JSON, with(|s| s["planes"][0]["id"] = json!("")), 422, "invalid_value", Some("planes[0].id")),
        c("balance grade unknown", "POST", sessions, JSON, with(|s| s["rotor"] = json!({"mass_kg": 100, "service_speed_rpm": 3000, "balance_grade": "G7"})), 422, "invalid_value", Some("rotor.balance_grade")),
        // A trim job's coefficients are sent back as the solve option of their name: what the option refuses cannot be stored (session 21).
        c("stored trim coefficient with a negative variance", "POST", sessions, JSON, with(|s| s["trim"] = json!({"influence_coefficients": [{"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0, "covariance": [[-1, 0], [0, 1]]}]})), 422, "invalid_value", Some("trim.influence_coefficients[0].covariance")),
        c("stored trim coefficient with an asymmetric covariance", "POST", sessions, JSON, with(|s| s["trim"] = json!({"influence_coefficients": [{"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0}, {"speed_rpm": 2950, "sensor": "DE-V", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0, "covariance": [[1, 0.5], [0.2, 1]]}]})), 422, "invalid_value", Some("trim.influence_coefficients[1].covariance")),
        c("stored trim coefficient with a covariance of 1e308", "POST", sessions, JSON, with(|s| s["trim"] = json!({"influence_coefficients": [{"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0, "covariance": [[1e308, 0], [0, 1]]}]})), 422, "invalid_value", Some("trim.influence_coefficients[0].covariance")),
        c("stored trim coefficient below 1 rpm", "POST", sessions, JSON, with(|s| s["trim"] = json!({"influence_coefficients": [{"speed_rpm": 1e-320, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0}]})), 422, "invalid_value", Some("trim.influence_coefficients[0].speed_rpm")),
        c("stored trim coefficient in another unit than its sensor", "POST", sessions, JSON, with(|s| s["trim"] = json!({"influence_coefficients": [{"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0, "unit": "mils_pp"}]})), 422, "unit_mismatch", Some("trim.influence_coefficients[0].unit")),
        // Content type and size.
        c("wrong content type", "POST", sessions, Some("text/plain"), Body::Json(session()), 415, "unsupported_media_type", None),
        c("no content type", "POST", sessions, None, Body::Raw(session().to_string().into_bytes()), 415, "unsupported_media_type", None),
        c("form content type on solve", "POST", "/api/v1/solve", Some("application/x-www-form-urlencoded"), Body::Raw(b"a=b".to_vec()), 415, "unsupported_media_type", None),
        c("body over 4 MiB", "POST", sessions, JSON, with(|s| s["name"] = json!("x".repeat(5 << 20))), 413, "body_too_large", None),
        // Unknown things.
        c("unknown session", "GET", "/api/v1/sessions/no-such-id", None, Body::None, 404, "not_found", None),
        c("delete unknown session", "DELETE", "/api/v1/sessions/no-such-id", None, Body::None, 404, "not_found", None),
        c("append to unknown session", "POST", "/api/v1/sessions/no-such-id/runs", JSON, Body::Json(run(1)), 404, "not_found", None),
        c("solve unknown session", "POST", "/api/v1/sessions/no-such-id/solutions", JSON, Body::Json(json!({})), 404, "not_found", None),
        c("correct unknown run", "PUT", "/api/v1/sessions/{id}/runs/nope", JSON, Body::Json(json!({"id": "nope", "weights": [], "readings": []})), 404, "not_found", None),
        c("versions of unknown run", "GET", "/api/v1/sessions/{id}/runs/nope/versions", None, Body::None, 404, "not_found", None),
        c("unknown route", "GET", "/api/v2/sessions", None, Body::None, 404, "not_found", None),
        c("wrong method", "PATCH", sessions, JSON, Body::Json(json!({})), 405, "method_not_allowed", None),
        // Runs entered one at a time: fields named within the posted run.
        c("duplicate run id appended", "POST", "/api/v1/sessions/{id}/runs", JSON, Body::Json(run(1)), 409, "duplicate_id", Some("id")),
        c("appended run names an unknown sensor", "POST", "/api/v1/sessions/{id}/runs", JSON, Body::Json({ let mut r = run(1); r["id"] = json!("new"); r["readings"][3]["sensor"] = json!("XX"); r }), 422, "unknown_sensor", Some("readings[3].sensor")),
        c("appended second reference run", "POST", "/api/v1/sessions/{id}/runs", JSON, Body::Json({ let mut r = run(0); r["id"] = json!("zero again"); r }), 422, "second_reference_run", Some("weights")),
        c("appended run with unknown field", "POST", "/api/v1/sessions/{id}/runs", JSON, Body::Json({ let mut r = run(1); r["id"] = json!("new"); r["weights"][0]["angle"] = json!(3); r }), 400, "unknown_field", Some("weights[0].angle")),
        c("corrected run with another id", "PUT", "/api/v1/sessions/{id}/runs/{run}", JSON, Body::Json(run(2)), 422, "id_mismatch", Some("id")),
        // The weights of the body are at fault: the service named no field (session 21).
        c("corrected reference run given weights", "PUT", "/api/v1/sessions/{id}/runs/zero", JSON, Body::Json({ let mut r = run(0); r["weights"] = json!([{"plane": "inboard", "mass_g": 5, "angle_deg": 0}]); r }), 422, "no_reference_run", Some("weights")),
        c("corrected run with negative mass", "PUT", "/api/v1/sessions/{id}/runs/{run}", JSON, Body::Json({ let mut r = run(1); r["weights"][0]["mass_g"] = json!(-1); r }), 422, "invalid_value", Some("weights[0].mass_g")),
        // Solve requests and options.
        c("solve without session", "POST", "/api/v1/solve", JSON, Body::Json(json!({"options": {}})), 422, "missing_field", Some("session")),
        c("solve with unknown option", "POST", "/api/v1/solve", JSON, Body::Json(json!({"session": session(), "options": {"objectiv": "min_max"}})), 400, "unknown_field", Some("options.objectiv")),
        c("solve with unknown plane option", "POST", "/api/v1/solve", JSON, Body::Json(json!({"session": session(), "options": {"planes": ["middle"]}})), 422, "unknown_plane", Some("options.planes[0]")),
        c("solve with an invalid session", "POST", "/api/v1/solve", JSON, Body::Json(json!({"session": with_value(|s| s["runs"][1]["weights"][0]["mass_g"] = json!(-3))})), 422, "invalid_value", Some("session.runs[1].weights[0].mass_g")),
        c("solve with a coefficient covariance of three rows", "POST", "/api/v1/solve", JSON, Body::Json(json!({"session": session(), "options": {"influence_coefficients": [{"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0, "covariance": [[1, 0], [0, 1], [0, 0]]}]}})), 422, "invalid_type", Some("options.influence_coefficients[0].covariance")),
        c("stored trim coefficient with a covariance row of three", "POST", sessions, JSON, with(|s| s["trim"] = json!({"influence_coefficients": [{"speed_rpm": 2950, "sensor": "DE-H", "plane": "inboard", "amplitude_per_g": 1, "phase_deg": 0, "covariance": [[1, 0, 0], [0, 1]]}]})), 422, "invalid_type", Some("trim.influence_coefficients[0].covariance[0]")),
        c("stored solve with unknown option", "POST", "/api/v1/sessions/{id}/solutions", JSON, Body::Json(json!({"bogus": 1})), 400, "unknown_field", Some("bogus")),
        c("stored solve with an unknown sensor option", "POST", "/api/v1/sessions/{id}/solutions", JSON, Body::Json(json!({"sensors": ["DE-H", "XX"]})), 422, "unknown_sensor", Some("sensors[1]")),
        c("stored solve with a negative mass limit", "POST", "/api/v1/sessions/{id}/solutions", JSON, Body::Json(json!({"max_mass_g": {"inboard": -5}})), 422, "invalid_value", Some("max_mass_g.inboard")),
        // serde's map kept the last of a key given twice: a bound of 1 g then 1000 g solved unbounded (session 21).
        c("solve with a mass limit given twice for one plane", "POST", "/api/v1/solve", JSON, Body::Raw(format!(r#"{{"session": {}, "options": {{"max_mass_g": {{"inboard": 1, "inboard": 1000}}}}}}"#, session()).into_bytes()), 422, "invalid_type", Some("options.max_mass_g.inboard")),
        c("stored solve with a mass limit given twice for one plane", "POST", "/api/v1/sessions/{id}/solutions", JSON, Body::Raw(br#"{"max_mass_g": {"outboard": 5, "inboard": 1, "inboard": 1}}"#.to_vec()), 422, "invalid_type", Some("max_mass_g.inboard")),
        c("solve with a mass limit on an unknown plane", "POST", "/api/v1/solve", JSON, Body::Json(json!({"session": session(), "options": {"max_mass_g": {"middle": 5}}})), 422, "unknown_plane", Some("options.max_mass_g.middle")),
        c("list with limit 0", "GET", "/api/v1/sessions?limit=0", None, Body::None, 422, "out_of_range", Some("limit")),
        c("list with a word for limit", "GET", "/api/v1/sessions?limit=many", None, Body::None, 400, "invalid_query", Some("limit")),
        c("list with limit twice", "GET", "/api/v1/sessions?limit=1&limit=2", None, Body::None, 400, "invalid_query", Some("limit")),
        c("list with an unknown parameter", "GET", "/api/v1/sessions?page=2", None, Body::None, 400, "invalid_query", Some("page")),
        c("versions with a word for offset", "GET", "/api/v1/sessions/{id}/runs/{run}/versions?offset=x", None, Body::None, 400, "invalid_query", Some("offset")),
        c("solutions with a limit beyond i64", "GET", "/api/v1/sessions/{id}/solutions?limit=99999999999999999999", None, Body::None, 400, "invalid_query", Some("limit")),
    ]
}

fn with_value(change: impl FnOnce(&mut Value)) -> Value {
    let mut s = session();
    change(&mut s);
    s
}

#[tokio::test]
async fn every_bad_request_gets_its_status_and_field_and_the_server_keeps_answering() {
    let (_dir, server, client) = fresh_server().await;
    let (status, _, created) = post(&client, &server.url("/api/v1/sessions"), &session()).await;
    assert_eq!(status, 201);
    let id = created["id"].as_str().unwrap();
    let run_id = session()["runs"][1]["id"]
        .as_str()
        .unwrap()
        .replace(' ', "%20");

    let cases = cases();
    assert!(cases.len() >= 30);
    let mut failures = Vec::new();
    for case in &cases {
        let path = case.path.replace("{id}", id).replace("{run}", &run_id);
        let method = reqwest::Method::from_bytes(case.method.as_bytes()).unwrap();
        let mut req = client.request(method, server.url(&path));
        if let Some(ct) = case.content_type {
            req = req.header("content-type", ct);
        }
        req = match &case.body {
            Body::Json(v) => req.body(v.to_string()),
            Body::Raw(b) => req.body(b.clone()),
            Body::None => req,
        };
        let (status, _, body) = send(req).await;
        let got = (
            status,
            body["error"]["code"].as_str(),
            body["error"]["field"].as_str(),
        );
        if got != (case.status, Some(case.code), case.field)
            || body["error"]["message"].as_str().is_none()
        {
            failures.push(format!(
                "{}: want {} {} {:?}, got {body}",
                case.name, case.status, case.code, case.field
            ));
        }
        let (health, _, _) = send(client.get(server.url("/healthz"))).await;
        assert_eq!(
            health, 200,
            "server stopped answering after '{}'",
            case.name
        );
    }
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );

    // Nothing was stored by the rejected requests: one session, its runs untouched,
    // one version per run, no solution.
    let (_, _, list) = send(client.get(server.url("/api/v1/sessions"))).await;
    assert_eq!(list["total"], 1);
    let (_, _, back) = send(client.get(server.url(&format!("/api/v1/sessions/{id}")))).await;
    assert_eq!(
        back,
        serde_json::to_value(
            serde_json::from_value::<fieldbal::balancing::Session>(session()).unwrap()
        )
        .unwrap()
    );
    let (_, _, versions) =
        send(client.get(server.url(&format!("/api/v1/sessions/{id}/runs/{run_id}/versions"))))
            .await;
    assert_eq!(versions.as_array().unwrap().len(), 1);
    let (_, _, solutions) =
        send(client.get(server.url(&format!("/api/v1/sessions/{id}/solutions")))).await;
    assert_eq!(solutions, json!([]));
    server.shutdown().await;
}

#[tokio::test]
async fn a_stored_session_that_cannot_be_solved_yet_gets_422_and_no_solution_is_stored() {
    let (_dir, server, client) = fresh_server().await;
    let mut only_reference = session();
    only_reference["runs"] = json!([run(0)]);
    let (status, _, created) =
        post(&client, &server.url("/api/v1/sessions"), &only_reference).await;
    assert_eq!(
        status, 201,
        "a session is stored before its trial runs: {created}"
    );
    let url = server.url(&format!(
        "/api/v1/sessions/{}/solutions",
        created["id"].as_str().unwrap()
    ));
    // An empty body means the default options; writes must say JSON (issue #9).
    let (status, _, body) =
        send(client.post(&url).header("content-type", "application/json")).await;
    assert_eq!(status, 422, "{body}");
    assert!(body["error"]["code"].is_string());
    let (_, _, solutions) = send(client.get(&url)).await;
    assert_eq!(solutions, json!([]));
    server.shutdown().await;
}

/// A number far from 1 in an error message is written in exponent form, as
/// `shown` writes it: these messages printed 1e-320 as "0.000…0001" with 320
/// digits and 1e308 with 309 (session 21), a screenful in the form's error
/// line.
#[tokio::test]
async fn error_messages_write_extreme_numbers_in_exponent_form() {
    let (_dir, server, client) = fresh_server().await;
    let solve = |s: Value, options: Value| json!({"session": s, "options": options});
    let mut ref_speed = session();
    ref_speed["runs"][0]["readings"][0]["speed_rpm"] = json!(1e-320);
    let mut trial_mass = session();
    trial_mass["runs"][1]["weights"][0]["mass_g"] = json!(1e-320);
    let mut places = session();
    places["planes"][0]["places_deg"] = json!([0, 1e-320, 90]);
    let model = json!({
        "mass": {"fixed": [[2.0, 1e308], [0.0, 1.0]], "parameters": []},
        "stiffness": {"fixed": [[0.0, 0.0], [0.0, 0.0]], "parameters": [[[1.0, 0.0], [0.0, 0.0]]]},
        "modes": [{"frequency_hz": 4.0, "shape": [0.5, 0.8]}]
    });
    let mut residual: Value = serde_json::from_slice(
        &std::fs::read(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/tests/data/residual/left-plane-12-positions.json"
        ))
        .unwrap(),
    )
    .unwrap();
    residual["readings"][1]["angle_deg"] = json!(1e-320);
    let cases = [
        (
            "reading speed",
            "/api/v1/solve",
            solve(ref_speed, json!({})),
            "1e-320",
        ),
        (
            "trial mass",
            "/api/v1/solve",
            solve(trial_mass, json!({})),
            "1e-320",
        ),
        (
            "row weight speed",
            "/api/v1/solve",
            solve(
                session(),
                json!({"row_weights": [{"speed_rpm": 1e300, "weight": 2}]}),
            ),
            "1e300",
        ),
        (
            "place angle",
            "/api/v1/solve",
            solve(places, json!({})),
            "1e-320",
        ),
        ("model matrix", "/api/v1/identify/model", model, "1e308"),
        (
            "residual position",
            "/api/v1/residual-unbalance",
            residual,
            "1e-320",
        ),
    ];
    for (name, path, body, number) in cases {
        let (status, _, answer) = post(&client, &server.url(path), &body).await;
        assert_eq!(status, 422, "{name}: {answer}");
        let message = answer["error"]["message"].as_str().unwrap();
        let longest = message
            .split(|c: char| !c.is_ascii_digit())
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(longest < 20, "{name}: {message}");
        assert!(message.contains(number), "{name}: {message}");
    }
    server.shutdown().await;
}

/// The first run appended to a set-up stored without runs is the reference
/// run: one with weights is refused naming its `weights` (no field before,
/// session 21), and nothing is stored.
#[tokio::test]
async fn a_first_run_with_weights_is_refused_naming_its_weights() {
    let (_dir, server, client) = fresh_server().await;
    let mut setup = session();
    setup["runs"] = json!([]);
    let (status, _, created) = post(&client, &server.url("/api/v1/sessions"), &setup).await;
    assert_eq!(status, 201, "{created}");
    let id = created["id"].as_str().unwrap();
    let url = server.url(&format!("/api/v1/sessions/{id}/runs"));
    let (status, _, body) = post(&client, &url, &run(1)).await;
    assert_eq!(status, 422, "{body}");
    assert_eq!(body["error"]["code"], "no_reference_run", "{body}");
    assert_eq!(body["error"]["field"], "weights", "{body}");
    let (_, _, back) = send(client.get(server.url(&format!("/api/v1/sessions/{id}")))).await;
    assert_eq!(back["runs"], json!([]), "{back}");
    server.shutdown().await;
}

/// A query the operation does not take is refused in the service's words,
/// naming the parameter and what is taken; it read "Failed to deserialize
/// query string: x: unknown field `x`, there are no fields" (axum's).
#[tokio::test]
async fn a_refused_query_says_what_the_operation_takes_in_plain_words() {
    let (_dir, server, client) = common::fresh_server().await;
    let cases = [
        (
            client.get(server.url("/api/v1/sessions?foo=1")),
            "foo",
            &["`foo`", "`limit`", "`before`"][..],
        ),
        (
            client.get(server.url("/api/v1/sessions?limit=abc")),
            "limit",
            &["`limit`", "invalid digit"][..],
        ),
        (
            client.get(server.url("/api/v1/sessions?limit=1&limit=2")),
            "limit",
            &["`limit`", "more than once"][..],
        ),
        (
            client.get(server.url("/api/v1/openapi.json?x=1")),
            "x",
            &["`x`", "takes no query parameter"][..],
        ),
        (
            client
                .post(server.url("/api/v1/solve?discrete=true"))
                .json(&serde_json::json!({})),
            "discrete",
            &["`discrete`", "takes no query parameter"][..],
        ),
    ];
    for (req, field, said) in cases {
        let (status, _, body) = common::send(req).await;
        assert_eq!(status, 400, "{body}");
        assert_eq!(body["error"]["code"], "invalid_query", "{body}");
        assert_eq!(body["error"]["field"], field, "{body}");
        let message = body["error"]["message"].as_str().unwrap();
        assert!(!message.contains("Failed to deserialize"), "{message}");
        assert!(!message.contains("there are no fields"), "{message}");
        for s in said {
            assert!(message.contains(s), "{s}: {message}");
        }
    }
    server.shutdown().await;
}
