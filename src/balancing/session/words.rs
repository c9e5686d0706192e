//! serde's messages for a value of the wrong type, in the words of the API's
//! readers: "expected a number, got text \"x\"" rather than Rust's
//! "invalid type: string \"x\", expected f64" (session 25's review: a
//! stand-software developer reads JSON, not Rust type names).

/// serde's data-error `message` in plain words; any other message as it is.
pub fn plain(message: &str) -> String {
    if let Some(rest) = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
    {
        if let Some(i) = rest.rfind(", expected ") {
            let (got, expected) = (&rest[..i], &rest[i + ", expected ".len()..]);
            return match expected.strip_suffix(crate::balancing::wire::NOT_AN_OBJECT) {
                // A struct posted as a positional array.
                Some("") if got == "sequence" => {
                    "expected an object of named fields, not a list".to_string()
                }
                _ => format!(
                    "expected {}, got {}",
                    expected_words(expected),
                    got_words(got)
                ),
            };
        }
    }
    if let Some(rest) = message.strip_prefix("invalid length ") {
        if let Some((n, expected)) = rest.split_once(", expected ") {
            let n = n.trim();
            let entries = if n == "1" { "entry" } else { "entries" };
            return format!("expected {}, got {n} {entries}", expected_words(expected));
        }
    }
    if let Some(rest) = message
        .strip_prefix("unknown variant ")
        .or_else(|| message.strip_prefix("unknown value "))
    {
        if let Some((got, expected)) = rest.split_once(", expected ") {
            return format!("expected {expected}, got {got}");
        }
    }
    message.to_string()
}

/// What serde says a value should have been (a Rust type or a visitor's
/// `expecting`), in plain words.
fn expected_words(expected: &str) -> String {
    let words = match expected {
        "f64" | "f32" => "a number",
        "u8" => "a whole number from 0 to 255",
        "u16" => "a whole number from 0 to 65535",
        "u32" => "a whole number from 0 to 4294967295",
        "u64" | "u128" | "usize" => "a whole number ≥ 0",
        "i8" | "i16" | "i32" | "i64" | "i128" | "isize" => "a whole number",
        "a string" | "a borrowed string" | "string" => "text",
        "a character" | "char" => "a single character",
        "a boolean" | "bool" => "true or false",
        "a sequence" => "a list",
        "a map" | "a JSON object" => "an object",
        "unit" => "null",
        _ => {
            if expected.strip_prefix("struct ").is_some() {
                return "an object".to_string();
            }
            if let Some(n) = expected
                .strip_prefix("an array of length ")
                .or_else(|| expected.strip_prefix("a tuple of size "))
            {
                return format!("a list of {n}");
            }
            if expected == crate::balancing::wire::NOT_AN_OBJECT {
                return "an object".to_string();
            }
            return expected.to_string();
        }
    };
    words.to_string()
}

/// What serde says was given (its `Unexpected`), in JSON's words.
fn got_words(got: &str) -> String {
    let inner = |prefix: &str| {
        got.strip_prefix(prefix)
            .and_then(|r| r.strip_prefix('`'))
            .and_then(|r| r.strip_suffix('`'))
            .map(str::to_string)
    };
    if let Some(text) = got.strip_prefix("string ") {
        return format!("text {text}");
    }
    if let Some(c) = inner("character ") {
        return format!("text \"{c}\"");
    }
    for prefix in ["integer ", "floating point ", "boolean "] {
        if let Some(v) = inner(prefix) {
            return v;
        }
    }
    match got {
        "map" => "an object",
        "sequence" => "a list",
        "unit value" | "null" => "null",
        other => other,
    }
    .to_string()
}

#[cfg(test)]
mod tests {
    use super::plain;

    #[test]
    fn serde_type_names_become_plain_words() {
        for (serde, words) in [
            (
                r#"invalid type: string "x", expected f64"#,
                r#"expected a number, got text "x""#,
            ),
            (
                "invalid value: integer `-1`, expected u32",
                "expected a whole number from 0 to 4294967295, got -1",
            ),
            (
                "invalid type: floating point `1.5`, expected usize",
                "expected a whole number ≥ 0, got 1.5",
            ),
            (
                "invalid type: map, expected a sequence",
                "expected a list, got an object",
            ),
            (
                "invalid type: null, expected a JSON object",
                "expected an object, got null",
            ),
            (
                "invalid type: boolean `true`, expected a string",
                "expected text, got true",
            ),
            (
                "invalid type: sequence, expected a JSON object, not an array",
                "expected an object of named fields, not a list",
            ),
            (
                "invalid length 1, expected an array of length 2",
                "expected a list of 2, got 1 entry",
            ),
            (
                "unknown variant `lagg`, expected `lag` or `lead`",
                "expected `lag` or `lead`, got `lagg`",
            ),
            // Text given may itself hold the words serde uses.
            (
                r#"invalid type: string "a, expected b", expected f64"#,
                r#"expected a number, got text "a, expected b""#,
            ),
            ("missing field `unit`", "missing field `unit`"),
        ] {
            assert_eq!(plain(serde), words, "{serde}");
        }
    }
}
