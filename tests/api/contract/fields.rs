//! docs/session-format.md is the contract clients code against: every
//! request and response field the served OpenAPI document names must be
//! named there too, or a client coding against the contract cannot find it.
//! (An outside review found over forty fields the README and the OpenAPI
//! described and the contract did not: `iso_21940`, `static_couple`, the
//! plane diagnostics, `fit_time_limit_ms`, a run check's `chi2`/`dof`, ...)

use std::collections::{BTreeMap, BTreeSet};

use crate::common;

use common::{fresh_server, send};

/// Property names that are in the OpenAPI document but need no word in the
/// contract because no client sees them as a field. Empty: every property the
/// document names is one a client sends or reads. A name goes here only with
/// a comment saying why it is internal.
const INTERNAL: &[&str] = &[];

/// The identifiers the contract writes as code: inside `inline code` or a
/// fenced block. A field counts as named only there, so that a word of the
/// prose (`used`, `holds`, `static`) does not pass for the field.
fn code_identifiers(contract: &str) -> BTreeSet<String> {
    let mut code = Vec::new();
    for (i, part) in contract.split("```").enumerate() {
        if i % 2 == 1 {
            code.push(part);
        } else {
            // Inline spans: the text between a backtick and the next.
            code.extend(part.split('`').skip(1).step_by(2));
        }
    }
    // A header's name has hyphens (`If-Match`): a hyphenated word counts
    // whole and by its parts.
    let words = code
        .iter()
        .flat_map(|c| c.split(|ch: char| !(ch.is_ascii_alphanumeric() || ch == '_' || ch == '-')));
    words
        .flat_map(|w| std::iter::once(w).chain(w.split('-')))
        .map(|w| w.trim_matches('-'))
        .filter(|w| !w.is_empty())
        .map(str::to_string)
        .collect()
}

/// Every property name under `node` (an object schema's `properties`, at any
/// depth: inline schemas, `items`, `oneOf`) and every operation parameter's
/// name, with where it was found.
fn collect_properties(
    node: &serde_json::Value,
    place: &str,
    out: &mut BTreeMap<String, BTreeSet<String>>,
) {
    match node {
        serde_json::Value::Object(map) => {
            if let Some(serde_json::Value::Object(props)) = map.get("properties") {
                for name in props.keys() {
                    out.entry(name.clone())
                        .or_default()
                        .insert(place.to_string());
                }
            }
            // An operation's parameters (query, path, header) are fields too.
            if let Some(serde_json::Value::Array(params)) = map.get("parameters") {
                for name in params.iter().filter_map(|p| p["name"].as_str()) {
                    out.entry(name.to_string())
                        .or_default()
                        .insert(place.to_string());
                }
            }
            for value in map.values() {
                collect_properties(value, place, out);
            }
        }
        serde_json::Value::Array(items) => {
            for value in items {
                collect_properties(value, place, out);
            }
        }
        _ => {}
    }
}

#[test]
fn code_identifiers_are_read_from_code_only() {
    let ids = code_identifiers(
        "prose used here, `a.b_c` and\n```json\n{\"d\": 1}\n```\nholds `e` `If-Match`",
    );
    let want: BTreeSet<String> = ["a", "b_c", "d", "1", "e", "json", "If-Match", "If", "Match"]
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(ids, want);
}

#[tokio::test]
async fn every_field_the_openapi_names_is_in_the_contract() {
    let (_dir, server, client) = fresh_server().await;
    let (status, _, doc) = send(client.get(server.url("/api/v1/openapi.json"))).await;
    assert_eq!(status, 200);

    let mut names = BTreeMap::new();
    let schemas = doc["components"]["schemas"].as_object().unwrap();
    for (schema, body) in schemas {
        collect_properties(body, schema, &mut names);
    }
    for (path, item) in doc["paths"].as_object().unwrap() {
        collect_properties(item, path, &mut names);
    }
    // The walk must reach the document's fields, or the test passes on nothing.
    for known in [
        "corrections",
        "iso_21940",
        "residual_unbalance_gmm",
        "before",
    ] {
        assert!(names.contains_key(known), "the walk missed {known}");
    }

    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/session-format.md");
    let contract = std::fs::read_to_string(path).expect("docs/session-format.md read");
    let named = code_identifiers(&contract);

    let missing: Vec<String> = names
        .iter()
        .filter(|(name, _)| !named.contains(*name) && !INTERNAL.contains(&name.as_str()))
        .map(|(name, places)| {
            let places: Vec<&str> = places.iter().map(String::as_str).collect();
            format!("{name} ({})", places.join(", "))
        })
        .collect();
    assert!(
        missing.is_empty(),
        "{} field(s) of the served OpenAPI are not named (as code) in docs/session-format.md:\n  {}",
        missing.len(),
        missing.join("\n  ")
    );
}
