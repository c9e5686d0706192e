//! The fast parse (one typed pass, no path tracking, no `Value` first) agrees
//! with the path-tracking parse it replaced on every document: a document the
//! fast parse accepts is accepted by the tracked parse as the same session,
//! and every document gets the same answer or the same error as before.
//!
//! Documents are the examples and a session using every wire struct,
//! rewritten at random: keys in any order or repeated, values replaced by
//! other JSON, objects turned into arrays, unknown keys, and bytes cut,
//! inserted or changed.

use fieldbal::balancing::error::{from_json_tracked, InputError};
use fieldbal::balancing::file::{self, SessionFile};
use fieldbal::balancing::model::{Session, SolveRequest};
use fieldbal::balancing::{from_json, parse_session_file};
use proptest::prelude::*;
use serde_json::{json, Value};

/// The session-file parse as it was: the whole document as a `Value`
/// first, then the wrapper or the bare session, both tracking the path.
fn old_session_file(bytes: &[u8]) -> Result<SessionFile, InputError> {
    let value: Value = from_json_tracked(bytes)?;
    file::parse_tracked(bytes, &value)
}

/// Every parse the fast paths replaced agrees with the old one on `bytes`.
fn assert_agree(bytes: &[u8]) {
    let text = String::from_utf8_lossy(bytes);
    let old = old_session_file(bytes);
    if let Some(fast) = file::parse_fast(bytes) {
        assert_eq!(Ok(&fast), old.as_ref(), "fast file parse accepted {text}");
    }
    assert_eq!(file::parse(bytes), old, "{text}");

    let tracked = from_json_tracked::<Session>(bytes);
    if let Ok(fast) = serde_json::from_slice::<Session>(bytes) {
        assert_eq!(Ok(&fast), tracked.as_ref(), "fast parse accepted {text}");
    }
    assert_eq!(from_json::<Session>(bytes), tracked, "{text}");
    assert_eq!(
        from_json::<SolveRequest>(bytes),
        from_json_tracked::<SolveRequest>(bytes),
        "{text}"
    );
    assert_eq!(
        from_json::<Value>(bytes),
        from_json_tracked::<Value>(bytes),
        "{text}"
    );
}

/// A bare session with every wire struct and optional field in it.
fn full_session() -> Value {
    json!({
        "name": "full", "machine": "m1",
        "conventions": {"phase": "lag", "angle_direction": "against_rotation"},
        "rotor": {"mass_kg": 120.0, "service_speed_rpm": 3000, "balance_grade": "G2.5"},
        "planes": [
            {"id": "A", "radius_mm": 150, "positions": 12,
             "kit": {"masses_g": [1, 2.5], "max_per_place": 2, "max_places": 2}},
            {"id": "B", "places_deg": [0, 90.5, 200]}
        ],
        "sensors": [{"id": "s1", "unit": "um_pp", "label": "inboard"}, {"id": "s2", "unit": "mm_s_rms"}],
        "runs": [
            {"id": "ref", "weights": [], "readings": [
                {"speed_rpm": 3000, "sensor": "s1", "amplitude": 50.5, "phase_deg": 30,
                 "samples": [{"amplitude": 50, "phase_deg": 29}, {"amplitude": 51, "phase_deg": 31}]},
                {"speed_rpm": 3000, "sensor": "s2", "amplitude": 4.25e0, "phase_deg": -12.5}
            ]},
            {"id": "t1", "weights": [{"plane": "A", "mass_g": 20, "angle_deg": 0}], "readings": [
                {"speed_rpm": 3000, "sensor": "s1", "amplitude": 60, "phase_deg": 45},
                {"speed_rpm": 3000, "sensor": "s2", "amplitude": 5, "phase_deg": 10}
            ]}
        ],
        "runout": [{"sensor": "s1", "amplitude": 2, "phase_deg": 5}]
    })
}

/// The documents mutated: each example as it is (wrapped) and bare, and the
/// full session bare, wrapped with options, and as a solve request.
fn bases() -> &'static [Value] {
    static BASES: std::sync::OnceLock<Vec<Value>> = std::sync::OnceLock::new();
    BASES.get_or_init(read_bases)
}

fn read_bases() -> Vec<Value> {
    let mut out = vec![
        full_session(),
        json!({"session": full_session(), "options": {"objective": "min_max", "speeds_rpm": [3000],
               "row_weights": [{"sensor": "s1", "weight": 2}], "max_mass_g": {"A": 50}},
               "description": "d", "expected": {"anything": [1, {"goes": null}]}}),
    ];
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/examples");
    let mut names: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    names.sort();
    for path in names {
        let example: Value = serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
        if let Some(session) = example.get("session") {
            out.push(session.clone());
        }
        out.push(example);
    }
    out
}

/// xorshift, so a proptest seed replays the same document.
struct Rng(u64);
impl Rng {
    fn below(&mut self, n: usize) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n.max(1) as u64) as usize
    }
}

/// Values put in place of others.
fn replacement(rng: &mut Rng) -> Value {
    let pool = [
        Value::Null,
        json!(0),
        json!(-1.5),
        json!(4294967296u64),
        json!("x"),
        json!("NaN"),
        json!(true),
        json!([]),
        json!({}),
        json!([1, "a"]),
        json!({"id": "z"}),
    ];
    pool[rng.below(pool.len())].clone()
}

/// Change one node of `v`, chosen by walking down at random.
fn mutate(v: &mut Value, rng: &mut Rng) {
    let descend = rng.below(4) != 0;
    match v {
        Value::Object(map) if descend && !map.is_empty() => {
            let key = map.keys().nth(rng.below(map.len())).unwrap().clone();
            mutate(map.get_mut(&key).unwrap(), rng);
        }
        Value::Array(items) if descend && !items.is_empty() => {
            let i = rng.below(items.len());
            mutate(&mut items[i], rng);
        }
        Value::Object(map) => match rng.below(5) {
            0 if !map.is_empty() => {
                let key = map.keys().nth(rng.below(map.len())).unwrap().clone();
                map.remove(&key);
            }
            1 => {
                let key = ["phase_dg", "session", "options", "cases", "extra"][rng.below(5)];
                map.insert(key.into(), replacement(rng));
            }
            2 => *v = Value::Array(map.values().cloned().collect()),
            _ => *v = replacement(rng),
        },
        _ => *v = replacement(rng),
    }
}

/// JSON text of `v` with each object's keys in a random order, and now and
/// then one key written twice.
fn write(v: &Value, rng: &mut Rng, out: &mut String) {
    match v {
        Value::Object(map) => {
            let mut entries: Vec<_> = map.iter().collect();
            for i in (1..entries.len()).rev() {
                entries.swap(i, rng.below(i + 1));
            }
            if !entries.is_empty() && rng.below(40) == 0 {
                entries.push(entries[rng.below(entries.len())]);
            }
            out.push('{');
            for (i, (k, val)) in entries.into_iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                out.push_str(&serde_json::to_string(k).unwrap());
                out.push(':');
                write(val, rng, out);
            }
            out.push('}');
        }
        Value::Array(items) => {
            out.push('[');
            for (i, item) in items.iter().enumerate() {
                if i > 0 {
                    out.push(',');
                }
                write(item, rng, out);
            }
            out.push(']');
        }
        other => out.push_str(&other.to_string()),
    }
}

/// Damage the text: cut it, or insert or change one byte.
fn damage(bytes: &mut Vec<u8>, rng: &mut Rng) {
    let noise = [
        b'x', b'"', b',', b'}', b']', b'{', b'\\', 0x01, 0xff, b'N', b' ', b'1',
    ];
    let at = rng.below(bytes.len() + 1);
    match rng.below(3) {
        0 => bytes.truncate(at),
        1 => bytes.insert(at, noise[rng.below(noise.len())]),
        _ if at < bytes.len() => bytes[at] = noise[rng.below(noise.len())],
        _ => bytes.extend_from_slice(b" x"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn fast_and_tracked_parses_agree_on_rewritten_documents(
        base in 0usize..64, seed in 1u64.., edits in 0usize..4, damaged in any::<bool>(),
    ) {
        let bases = bases();
        let mut rng = Rng(seed);
        let mut doc = bases[base % bases.len()].clone();
        for _ in 0..edits {
            mutate(&mut doc, &mut rng);
        }
        let mut text = String::new();
        write(&doc, &mut rng, &mut text);
        let mut bytes = text.into_bytes();
        if damaged {
            damage(&mut bytes, &mut rng);
        }
        assert_agree(&bytes);
    }
}

#[test]
fn every_base_session_file_parses_the_same_fast_as_tracked() {
    for doc in bases() {
        let doc = doc.clone();
        let bytes = serde_json::to_vec(&doc).unwrap();
        // The worked cases (`textbook-regression.json`) are not a session file.
        match file::parse_fast(&bytes) {
            Some(fast) => assert_eq!(Ok(fast), old_session_file(&bytes)),
            None => assert!(doc.get("cases").is_some(), "{doc}"),
        }
        assert_agree(&bytes);
    }
}

#[test]
fn documents_at_the_edges_of_the_fast_path_agree() {
    let full = full_session().to_string();
    let wrapped_last = format!(r#"{{"description":"d","options":{{}},"session":{full}}}"#);
    let bare_then_session = format!(r#"{{"name":"x","session":{full}}}"#);
    let cases: Vec<(&str, String)> = vec![
        ("session key last", wrapped_last),
        ("session after a session field", bare_then_session),
        ("options without session", r#"{"options":{}}"#.into()),
        ("session null", r#"{"session":null}"#.into()),
        ("empty object", "{}".into()),
        ("top-level array", "[]".into()),
        ("wrapper as an array", format!("[{full}]")),
        ("cases file", r#"{"cases":[]}"#.into()),
        ("trailing text", format!("{full} x")),
        ("trailing whitespace", format!("{full} \n\t")),
        (
            "duplicate name",
            full.replacen(r#""name":"full""#, r#""name":"a","name":"b""#, 1),
        ),
        (
            "NaN",
            full.replacen(r#""radius_mm":150"#, r#""radius_mm":NaN"#, 1),
        ),
        (
            "huge number",
            full.replacen(r#""radius_mm":150"#, r#""radius_mm":1e400"#, 1),
        ),
        ("not JSON", "name: x".into()),
        ("empty", String::new()),
    ];
    for (what, doc) in cases {
        let bytes = doc.as_bytes();
        assert_agree(bytes);
        // Only the two well-formed files take the fast path.
        let well_formed = ["session key last", "trailing whitespace"].contains(&what);
        assert_eq!(file::parse_fast(bytes).is_some(), well_formed, "{what}");
    }
    // Not UTF-8 inside a string, and a byte-order mark: the tracked parse decides.
    let mut latin1 = full.clone().into_bytes();
    let at = full.find("full").unwrap();
    latin1[at] = 0xe9;
    assert_agree(&latin1);
    assert_agree(&[b"\xef\xbb\xbf".as_slice(), full.as_bytes()].concat());
}

#[test]
fn a_wrapped_sessions_errors_are_named_under_session_and_a_bare_ones_are_not() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/examples/pump-two-plane-exact.json"
    );
    let example: Value = serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
    let mut bad = example["session"].clone();
    bad["planes"][0]["radius_mm"] = json!(-1);
    let bare = parse_session_file(&serde_json::to_vec(&bad).unwrap()).unwrap_err();
    let wrapped =
        parse_session_file(&serde_json::to_vec(&json!({ "session": bad })).unwrap()).unwrap_err();
    assert_eq!(bare.field.as_deref(), Some("planes[0].radius_mm"));
    assert_eq!(
        wrapped.field.as_deref(),
        Some("session.planes[0].radius_mm")
    );
    assert_eq!((bare.code, &bare.message), (wrapped.code, &wrapped.message));
}
