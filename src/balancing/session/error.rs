//! The one error type of the core: what is wrong, and which field is at fault.
//!
//! Its JSON form is the contract's error body
//! `{"error": {"code", "message", "field"}}`; the HTTP layer maps `kind` to a status.

use serde::{de::DeserializeOwned, Serialize};
use utoipa::ToSchema;

/// Broad class of a rejected input; the HTTP layer maps it to a status code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// Not JSON, or an unknown field (400).
    Malformed,
    /// JSON of the right shape whose values are wrong or that cannot be solved (422).
    Invalid,
}

/// A rejected input, naming the field at fault where there is one.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema, thiserror::Error)]
#[error("{message}")]
pub struct InputError {
    #[serde(skip)]
    pub kind: ErrorKind,
    /// Stable machine-readable code, e.g. `invalid_value`, `unknown_field`.
    pub code: &'static str,
    pub message: String,
    /// Path of the field at fault, e.g. `runs[2].readings[5].phase_deg`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub field: Option<String>,
}

impl InputError {
    /// A value error (422) at `field`.
    pub fn invalid(
        code: &'static str,
        field: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        InputError {
            kind: ErrorKind::Invalid,
            code,
            message: message.into(),
            field: Some(field.into()),
        }
    }

    /// A value error (422) that no single field is at fault for.
    pub fn unsolvable(code: &'static str, message: impl Into<String>) -> Self {
        InputError {
            kind: ErrorKind::Invalid,
            code,
            message: message.into(),
            field: None,
        }
    }

    /// Prefix the field path, e.g. `session.` for a session inside a solve request.
    pub fn under(mut self, prefix: &str) -> Self {
        self.field = Some(match self.field.take() {
            Some(f) if f.starts_with('[') => format!("{prefix}{f}"),
            Some(f) => format!("{prefix}.{f}"),
            None => prefix.to_string(),
        });
        self
    }

    /// The contract's error body.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({ "error": self })
    }
}

/// A number as an error message shows it: as Rust prints it where that is
/// short, in exponent form where the plain digits would run long (`1e308`
/// printed plainly is 309 digits; outside review, session 17).
pub fn shown(x: f64) -> String {
    let a = x.abs();
    if x.is_finite() && a != 0.0 && !(1e-4..1e9).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// `x` when it is finite and from `lo` to `hi`, else a value error at
/// `field` (built only then: callers name matrix entries in loops) saying
/// "`what` must be a finite number from `lo` to `hi`, got `x`" in [`shown`]'s
/// form. The one range check of the residual-unbalance request and of the
/// identification endpoints, which had a copy each differing only in how
/// they printed the numbers.
pub fn within(
    field: impl FnOnce() -> String,
    x: f64,
    (lo, hi): (f64, f64),
    what: &str,
) -> Result<f64, InputError> {
    if x.is_finite() && (lo..=hi).contains(&x) {
        Ok(x)
    } else {
        Err(InputError::invalid(
            "invalid_value",
            field(),
            format!(
                "{what} must be a finite number from {} to {}, got {}",
                shown(lo),
                shown(hi),
                shown(x)
            ),
        ))
    }
}

/// Parse JSON into `T`, turning serde's error into an [`InputError`] whose
/// `field` is the path of the offending value (for an unknown field, the path of
/// the unknown field itself, so that `phase_dg` is named).
///
/// Valid input is parsed once, without tracking the path: tracking it keeps
/// a `String` of every key and cost four times the parse on a large session
/// (issue 15, BENCHMARKS.md). Only when that parse fails is the input parsed
/// again by [`from_json_tracked`], whose error is the one returned, so errors
/// are exactly the tracked parse's. Both parses run the same `Deserialize`
/// code on the same `serde_json` reader (the tracking deserializer forwards
/// every call), so they accept the same documents and build the same value
/// (`tests/solve/parse_equivalence.rs`).
pub fn from_json<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, InputError> {
    match as_text(bytes).and_then(|text| serde_json::from_str(text).ok()) {
        Some(value) => Ok(value),
        None => from_json_tracked(bytes),
    }
}

/// The input as text when it is UTF-8, checked once for the whole document:
/// reading from a `&str` spares `serde_json` checking every string again
/// (a tenth of a large session's parse). Input that is not UTF-8 goes to the
/// slow path, whose error names it.
pub(crate) fn as_text(bytes: &[u8]) -> Option<&str> {
    std::str::from_utf8(bytes).ok()
}

/// [`from_json`]'s slow path: parse while tracking the path of the value
/// being read, so that an error names its field.
pub fn from_json_tracked<T: DeserializeOwned>(bytes: &[u8]) -> Result<T, InputError> {
    let mut de = serde_json::Deserializer::from_slice(bytes);
    let value = serde_path_to_error::deserialize(&mut de).map_err(|err| {
        let path = err.path().to_string();
        let inner = err.into_inner();
        let path = if path == "." { String::new() } else { path };
        word_given_another_value(bytes, &path, &inner).unwrap_or_else(|| classify(path, &inner))
    })?;
    // Only whitespace may follow the value: `{...} x` is not one JSON document.
    de.end().map_err(|err| classify(String::new(), &err))?;
    Ok(value)
}

/// A word field (an enum: `purpose`, `conventions.phase`, a sensor's `unit`)
/// given a number, `true`, `null` or a list: serde_json reads a word from
/// text only and stops with "expected value", as at a bare `NaN`. Where a
/// whole JSON value does start there, the input is well-formed and of the
/// wrong type: 422 `invalid_type` naming the field (the contract's rule for
/// `purpose`), not 400 `malformed_json`. `None` for anything else.
fn word_given_another_value(
    bytes: &[u8],
    path: &str,
    err: &serde_json::Error,
) -> Option<InputError> {
    if path.is_empty()
        || err.classify() != serde_json::error::Category::Syntax
        || strip_position(&err.to_string()) != "expected value"
    {
        return None;
    }
    // serde_json counts lines from 1 and columns in bytes from 1.
    let line_start = if err.line() <= 1 {
        0
    } else {
        let mut newlines = bytes.iter().enumerate().filter(|&(_, &b)| b == b'\n');
        newlines.nth(err.line() - 2)?.0 + 1
    };
    let at = line_start + err.column().checked_sub(1)?;
    let rest = bytes.get(at..)?;
    let given = serde_json::Deserializer::from_slice(rest)
        .into_iter::<serde_json::Value>()
        .next()?
        .ok()?;
    let shown = match &given {
        serde_json::Value::Array(_) => "a list".to_string(),
        serde_json::Value::Object(_) => "an object".to_string(),
        serde_json::Value::String(_) => return None,
        other => other.to_string(),
    };
    Some(InputError {
        kind: ErrorKind::Invalid,
        code: "invalid_type",
        message: format!("expected text (one of the field's words), got {shown}"),
        field: Some(path.to_string()),
    })
}

pub(crate) fn classify(path: String, err: &serde_json::Error) -> InputError {
    use serde_json::error::Category;
    let text = err.to_string();
    let message = strip_position(&text);
    match err.classify() {
        // Well-formed JSON whose number is beyond f64 (`1e400`): the reader
        // stops inside a value, so the tracked path names the field.
        Category::Syntax if message == "number out of range" && !path.is_empty() => InputError {
            kind: ErrorKind::Malformed,
            code: "malformed_json",
            message: format!(
                "the body is not valid JSON: {message} (beyond ±1.8e308, the largest 64-bit number)"
            ),
            field: Some(path),
        },
        // Well-formed JSON with a list longer than the fixed length it is
        // read into (a 2×2 `covariance` with three rows): serde_json calls
        // the entry after the last it takes "trailing characters". Text after
        // the document is checked with an empty path, so stays malformed.
        Category::Syntax if message == "trailing characters" && !path.is_empty() => InputError {
            kind: ErrorKind::Invalid,
            code: "invalid_type",
            message: "invalid length: more entries than this list takes".to_string(),
            field: Some(path),
        },
        // Not a JSON value where one goes (a bare `NaN` or `Infinity`, which
        // JSON has no words for): still malformed, but the tracked path names
        // the field the reader was in, as for `1e400`.
        Category::Syntax
            if matches!(message, "expected value" | "expected ident" | "invalid number") && !path.is_empty() =>
        {
            InputError {
            kind: ErrorKind::Malformed,
            code: "malformed_json",
            message: format!(
                "the body is not valid JSON: {text} (a value goes here; NaN and Infinity are not JSON numbers, and fieldbal takes finite numbers only)"
            ),
            field: Some(path),
            }
        }
        Category::Syntax | Category::Eof | Category::Io => InputError {
            kind: ErrorKind::Malformed,
            code: "malformed_json",
            message: format!("the body is not valid JSON: {text}"),
            field: None,
        },
        Category::Data if message.starts_with("unknown field") => {
            let name = message.split('`').nth(1).unwrap_or_default();
            // serde_path_to_error already ends the path with the unknown key.
            let field = if path.is_empty() {
                name.to_string()
            } else {
                path
            };
            InputError {
                kind: ErrorKind::Malformed,
                code: "unknown_field",
                message: message.to_string(),
                field: Some(field),
            }
        }
        Category::Data => {
            // serde names a missing or repeated key in its message; the path
            // is that of the object holding it.
            let named = |name: &str| {
                if path.is_empty() {
                    name.to_string()
                } else {
                    format!("{path}.{name}")
                }
            };
            let key = |rest: &str| rest.split('`').next().unwrap_or_default().to_string();
            // serde's wording ("invalid type: string \"x\", expected f64")
            // in plain words ("expected a number, got text \"x\""); a wire
            // struct's "a JSON object, not an array" reads "an object" when
            // a null or a number was given.
            let message = super::words::plain(message);
            let message = message.as_str();
            let (code, field) = if let Some(rest) = message.strip_prefix("missing field `") {
                ("missing_field", named(&key(rest)))
            } else if let Some(rest) = message.strip_prefix("duplicate field `") {
                ("invalid_type", named(&key(rest)))
            } else {
                ("invalid_type", path)
            };
            InputError {
                kind: ErrorKind::Invalid,
                code,
                message: message.to_string(),
                field: if field.is_empty() { None } else { Some(field) },
            }
        }
    }
}

/// serde_json appends " at line L column C"; the field path says more.
fn strip_position(text: &str) -> &str {
    match text.rfind(" at line ") {
        Some(i) => &text[..i],
        None => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::balancing::model::Session;

    #[test]
    fn an_unknown_field_is_named_by_its_full_path() {
        let body = br#"{"name":"x","planes":[],"sensors":[],"runs":[{"id":"z","weights":[],
            "readings":[{"speed_rpm":1,"sensor":"s","amplitude":1,"phase_dg":3}]}]}"#;
        let err = from_json::<Session>(body).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Malformed);
        assert_eq!(err.code, "unknown_field");
        assert_eq!(err.field.as_deref(), Some("runs[0].readings[0].phase_dg"));
    }

    #[test]
    fn a_string_where_a_number_belongs_names_the_field() {
        let body =
            br#"{"name":"x","planes":[{"id":"A","radius_mm":"NaN"}],"sensors":[],"runs":[]}"#;
        let err = from_json::<Session>(body).unwrap_err();
        assert_eq!(err.kind, ErrorKind::Invalid);
        assert_eq!(err.field.as_deref(), Some("planes[0].radius_mm"));
    }

    #[test]
    fn a_number_beyond_f64_names_the_field() {
        let body =
            br#"{"name":"x","planes":[{"id":"A","radius_mm":1e400}],"sensors":[],"runs":[]}"#;
        let err = from_json::<Session>(body).unwrap_err();
        assert_eq!(
            (err.kind, err.code),
            (ErrorKind::Malformed, "malformed_json")
        );
        assert_eq!(err.field.as_deref(), Some("planes[0].radius_mm"));
    }

    #[test]
    fn a_missing_field_is_named() {
        let body = br#"{"name":"x","planes":[],"sensors":[{"id":"s"}],"runs":[]}"#;
        let err = from_json::<Session>(body).unwrap_err();
        assert_eq!(err.code, "missing_field");
        assert_eq!(err.field.as_deref(), Some("sensors[0].unit"));
    }

    #[test]
    fn text_after_the_json_value_is_malformed() {
        let err = from_json::<serde_json::Value>(b"{} x").unwrap_err();
        assert_eq!(err.code, "malformed_json");
        assert!(from_json::<serde_json::Value>(b"{} \n").is_ok());
    }

    #[test]
    fn structs_posted_as_positional_arrays_are_refused_naming_the_field() {
        let cases: [(&[u8], Option<&str>); 4] = [
            (br#"["x", null, null, null, [], [], []]"#, None),
            (br#"{"name":"x","planes":[["A", 100]],"sensors":[],"runs":[]}"#, Some("planes[0]")),
            (br#"{"name":"x","conventions":["lag","against_rotation"],"planes":[],"sensors":[],"runs":[]}"#, Some("conventions")),
            (br#"{"name":"x","planes":[],"sensors":[],"runs":[{"id":"r","weights":[],"readings":[[1000,"s",1,2]]}]}"#, Some("runs[0].readings[0]")),
        ];
        for (body, field) in cases {
            let err = from_json::<Session>(body).unwrap_err();
            // 422 invalid_type, like any other value of the wrong type (v1).
            assert_eq!(err.kind, ErrorKind::Invalid, "{err:?}");
            assert_eq!(err.code, "invalid_type");
            assert!(err.message.ends_with("not a list"), "{}", err.message);
            assert_eq!(err.field.as_deref(), field);
        }
        let err = from_json::<crate::balancing::SolveRequest>(br#"[{}, {}]"#).unwrap_err();
        assert_eq!(err.code, "invalid_type");
    }

    /// A fixed-length list given too many entries (a coefficient's 2×2
    /// `covariance` with three rows) is well-formed JSON of the wrong shape:
    /// 422 naming the list, as one too short is. serde_json reports it as
    /// "trailing characters", a syntax error, which was answered 400
    /// `malformed_json` with no field (session 21).
    #[test]
    fn a_fixed_length_list_too_long_is_refused_naming_it() {
        let coefficient = |cov: &str| {
            format!(
                r#"{{"influence_coefficients":[{{"speed_rpm":1000,"sensor":"s","plane":"A","amplitude_per_g":1,"phase_deg":0,"covariance":{cov}}}]}}"#
            )
        };
        for (cov, field) in [
            (
                "[[1,0],[0,1],[0,0]]",
                "influence_coefficients[0].covariance",
            ),
            ("[[1,0,0],[0,1]]", "influence_coefficients[0].covariance[0]"),
            ("[[1,0]]", "influence_coefficients[0].covariance"),
        ] {
            let body = coefficient(cov);
            let err = from_json::<crate::balancing::SolveOptions>(body.as_bytes()).unwrap_err();
            assert_eq!(
                (err.kind, err.code),
                (ErrorKind::Invalid, "invalid_type"),
                "{cov}: {err:?}"
            );
            assert_eq!(err.field.as_deref(), Some(field), "{cov}");
        }
        // Text after the whole document stays malformed.
        let err = from_json::<crate::balancing::SolveOptions>(b"{} [1]").unwrap_err();
        assert_eq!(err.code, "malformed_json");
        assert_eq!(err.field, None);
    }

    /// A bare `NaN` or `Infinity` (not JSON) where a number goes is still
    /// malformed, but names the field the reader was in, as `1e400` does
    /// (it answered only a column, session 22's review).
    #[test]
    fn a_bare_nan_names_the_field_it_stands_in() {
        for (body, field) in [
            (r#"{"amplitude_noise_pct": NaN}"#, "amplitude_noise_pct"),
            (r#"{"phase_noise_deg": Infinity}"#, "phase_noise_deg"),
            (r#"{"max_mass_g": {"A": -Infinity}}"#, "max_mass_g.A"),
            (r#"{"speeds_rpm": [1000, nan]}"#, "speeds_rpm[1]"),
        ] {
            let err = from_json::<crate::balancing::SolveOptions>(body.as_bytes()).unwrap_err();
            assert_eq!(err.code, "malformed_json", "{body}: {err:?}");
            assert_eq!(err.field.as_deref(), Some(field), "{body}: {err:?}");
            assert!(err.message.contains("NaN"), "{body}: {}", err.message);
        }
        // Broken text that is not a value stays without a field.
        for body in [
            r#"{"amplitude_noise_pct" 2}"#,
            r#"{"amplitude_noise_pct":1,}"#,
            "{",
        ] {
            let err = from_json::<crate::balancing::SolveOptions>(body.as_bytes()).unwrap_err();
            assert_eq!(err.code, "malformed_json", "{body}: {err:?}");
        }
    }

    #[test]
    fn broken_json_is_malformed() {
        let err = from_json::<Session>(b"{\"name\": ").unwrap_err();
        assert_eq!(err.kind, ErrorKind::Malformed);
        assert_eq!(err.code, "malformed_json");
    }

    #[test]
    fn long_numbers_are_shown_in_exponent_form_and_short_ones_plainly() {
        assert_eq!(shown(1e308), "1e308");
        assert_eq!(shown(-2.5e-300), "-2.5e-300");
        assert_eq!(shown(1.5e-7), "1.5e-7");
        assert_eq!(shown(400.0), "400");
        assert_eq!(shown(0.25), "0.25");
        assert_eq!(shown(0.0), "0");
        assert_eq!(shown(123456789.0), "123456789");
        assert_eq!(shown(f64::INFINITY), "inf");
    }

    #[test]
    fn a_number_out_of_range_is_refused_naming_its_field_and_the_range() {
        assert_eq!(within(|| "x".into(), 2.0, (1.0, 3.0), "x"), Ok(2.0));
        for (bad, got) in [(1e-10, "1e-10"), (4e3, "4000"), (f64::NAN, "NaN")] {
            let err = within(|| "a.b[1]".into(), bad, (1e-9, 1e3), "the step").unwrap_err();
            assert_eq!(err.field.as_deref(), Some("a.b[1]"));
            let want = format!("the step must be a finite number from 1e-9 to 1000, got {got}");
            assert_eq!(err.message, want);
        }
    }
}
