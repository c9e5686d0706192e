//! The subset of JSON Schema that utoipa emits (`$ref`, `type` (one or a list,
//! `null` included), `properties`, `required`, `additionalProperties`, `items`,
//! `enum`, `oneOf`/`anyOf`/`allOf`, `minimum`/`maximum`): a checker for
//! answers and a generator of instances and their mutations for requests.

use rand::rngs::StdRng;
use rand::Rng;
use serde_json::{json, Map, Value};

/// A document's schemas, resolving `#/components/schemas/NAME`.
pub struct Schemas<'a> {
    pub doc: &'a Value,
}

impl<'a> Schemas<'a> {
    pub fn resolve(&self, schema: &'a Value) -> &'a Value {
        let mut s = schema;
        for _ in 0..16 {
            match s.get("$ref").and_then(Value::as_str) {
                Some(r) => {
                    let name = r.trim_start_matches("#/components/schemas/");
                    s = &self.doc["components"]["schemas"][name];
                }
                None => return s,
            }
        }
        panic!("$ref cycle at {schema}");
    }

    /// Where `value` breaks `schema`, as `path: why`.
    pub fn violations(&self, schema: &Value, value: &Value, path: &str, out: &mut Vec<String>) {
        let s = self.resolve(schema);
        if let Some(all) = s.get("allOf").and_then(Value::as_array) {
            for sub in all {
                self.violations(sub, value, path, out);
            }
        }
        for key in ["oneOf", "anyOf"] {
            if let Some(alts) = s.get(key).and_then(Value::as_array) {
                let fits = alts.iter().any(|alt| {
                    let mut v = Vec::new();
                    self.violations(alt, value, path, &mut v);
                    v.is_empty()
                });
                if !fits {
                    out.push(format!("{path}: fits none of {key}"));
                }
            }
        }
        if let Some(allowed) = s.get("enum").and_then(Value::as_array) {
            if !allowed.contains(value) {
                out.push(format!("{path}: {value} not in the enum"));
            }
        }
        let types = types_of(s);
        if !types.is_empty() && !types.iter().any(|t| is_type(value, t)) {
            out.push(format!("{path}: {value} is not {types:?}"));
            return;
        }
        if let Some(n) = value.as_f64() {
            if s.get("minimum")
                .and_then(Value::as_f64)
                .is_some_and(|m| n < m)
            {
                out.push(format!("{path}: {n} below the minimum"));
            }
            if s.get("maximum")
                .and_then(Value::as_f64)
                .is_some_and(|m| n > m)
            {
                out.push(format!("{path}: {n} above the maximum"));
            }
        }
        if let Some(obj) = value.as_object() {
            let props = s.get("properties").and_then(Value::as_object);
            for name in s
                .get("required")
                .and_then(Value::as_array)
                .into_iter()
                .flatten()
            {
                let name = name.as_str().unwrap_or_default();
                if !obj.contains_key(name) {
                    out.push(format!("{path}.{name}: required, missing"));
                }
            }
            for (k, v) in obj {
                match props.and_then(|p| p.get(k)) {
                    Some(sub) => self.violations(sub, v, &format!("{path}.{k}"), out),
                    None => match s.get("additionalProperties") {
                        Some(Value::Bool(false)) => out.push(format!("{path}.{k}: not declared")),
                        Some(extra @ Value::Object(_)) => {
                            self.violations(extra, v, &format!("{path}.{k}"), out)
                        }
                        _ => {}
                    },
                }
            }
        }
        if let (Some(items), Some(arr)) = (s.get("items"), value.as_array()) {
            for (i, v) in arr.iter().enumerate() {
                self.violations(items, v, &format!("{path}[{i}]"), out);
            }
        }
    }

    /// A value shaped by `schema` (within its bounds), `depth` bounding recursion.
    pub fn instance(&self, schema: &Value, rng: &mut StdRng, depth: u32) -> Value {
        let s = self.resolve(schema);
        if let Some(alts) = s.get("oneOf").or(s.get("anyOf")).and_then(Value::as_array) {
            if !alts.is_empty() {
                return self.instance(&alts[rng.gen_range(0..alts.len())], rng, depth);
            }
        }
        if let Some(all) = s.get("allOf").and_then(Value::as_array) {
            let mut merged = Map::new();
            for sub in all {
                if let Value::Object(o) = self.instance(sub, rng, depth) {
                    merged.extend(o);
                }
            }
            return Value::Object(merged);
        }
        if let Some(allowed) = s.get("enum").and_then(Value::as_array) {
            if !allowed.is_empty() {
                return allowed[rng.gen_range(0..allowed.len())].clone();
            }
        }
        let types = types_of(s);
        let non_null: Vec<&str> = types.iter().copied().filter(|t| *t != "null").collect();
        let ty = if non_null.is_empty() {
            if s.get("properties").is_some() {
                "object"
            } else {
                "string"
            }
        } else {
            non_null[rng.gen_range(0..non_null.len())]
        };
        let lo = s.get("minimum").and_then(Value::as_f64).unwrap_or(0.0);
        let hi = s
            .get("maximum")
            .and_then(Value::as_f64)
            .unwrap_or(lo + 100.0);
        match ty {
            "object" if depth > 0 => {
                let mut obj = Map::new();
                let required: Vec<&str> = s
                    .get("required")
                    .and_then(Value::as_array)
                    .map(|r| r.iter().filter_map(Value::as_str).collect())
                    .unwrap_or_default();
                for (k, sub) in s
                    .get("properties")
                    .and_then(Value::as_object)
                    .into_iter()
                    .flatten()
                {
                    if required.contains(&k.as_str()) || rng.gen_bool(0.5) {
                        obj.insert(k.clone(), self.instance(sub, rng, depth - 1));
                    }
                }
                Value::Object(obj)
            }
            "array" if depth > 0 => {
                let n = rng.gen_range(0..3);
                let items = s.get("items").cloned().unwrap_or(json!({}));
                Value::Array(
                    (0..n)
                        .map(|_| self.instance(&items, rng, depth - 1))
                        .collect(),
                )
            }
            "integer" => json!(rng.gen_range(lo as i64..=hi as i64)),
            "number" => json!(rng.gen_range(lo..=hi)),
            "boolean" => json!(rng.gen_bool(0.5)),
            "string" => json!(format!("s{}", rng.gen_range(0..1000))),
            "object" => json!({}),
            _ => json!([]),
        }
    }
}

fn types_of(s: &Value) -> Vec<&str> {
    match s.get("type") {
        Some(Value::String(t)) => vec![t.as_str()],
        Some(Value::Array(ts)) => ts.iter().filter_map(Value::as_str).collect(),
        _ => Vec::new(),
    }
}

fn is_type(value: &Value, ty: &str) -> bool {
    match ty {
        "null" => value.is_null(),
        "boolean" => value.is_boolean(),
        "integer" => value.is_i64() || value.is_u64(),
        "number" => value.is_number(),
        "string" => value.is_string(),
        "array" => value.is_array(),
        "object" => value.is_object(),
        _ => true,
    }
}

/// Awkward values: wrong types, extremes, NaN-ish strings, long text.
pub fn awkward(rng: &mut StdRng) -> Value {
    let choices = [
        json!(null),
        json!(true),
        json!("NaN"),
        json!("Infinity"),
        json!("-inf"),
        json!(""),
        json!("x".repeat(10_000)),
        json!("ü\u{0}😀"),
        json!(0),
        json!(-1),
        json!(1e308),
        json!(-1e308),
        json!(5e-324),
        json!(u64::MAX),
        json!(i64::MIN),
        json!([]),
        json!([1, 2, 3]),
        json!({}),
        json!({"unknown": 1}),
    ];
    choices[rng.gen_range(0..choices.len())].clone()
}

/// `value` with one mutation somewhere inside it.
pub fn mutate(value: &mut Value, rng: &mut StdRng) {
    // Walk down a random branch, then change what is there.
    let deeper = rng.gen_bool(0.7);
    match value {
        Value::Object(o) if deeper && !o.is_empty() => {
            let k = o.keys().nth(rng.gen_range(0..o.len())).unwrap().clone();
            return mutate(o.get_mut(&k).unwrap(), rng);
        }
        Value::Array(a) if deeper && !a.is_empty() => {
            let i = rng.gen_range(0..a.len());
            return mutate(&mut a[i], rng);
        }
        _ => {}
    }
    match value {
        Value::Object(o) if !o.is_empty() && rng.gen_bool(0.4) => {
            let k = o.keys().nth(rng.gen_range(0..o.len())).unwrap().clone();
            o.remove(&k);
        }
        Value::Object(o) if rng.gen_bool(0.5) => {
            o.insert("unexpected_field".into(), awkward(rng));
        }
        Value::Object(o) => {
            // An object written as a positional array of its values.
            let values = o.values().cloned().collect();
            *value = Value::Array(values);
        }
        Value::Array(a) if !a.is_empty() && rng.gen_bool(0.5) => {
            let copy = a[0].clone();
            a.extend(std::iter::repeat_n(copy, 3));
        }
        other => *other = awkward(rng),
    }
}
