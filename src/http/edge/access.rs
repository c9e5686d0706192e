//! Optional bearer tokens with a role: who may read and who may change the store.
//!
//! Format (file `--tokens-file` / `FIELDBAL_TOKENS_FILE`, or the variable
//! `FIELDBAL_TOKENS`): one `ROLE TOKEN` entry per line (the variable may also
//! separate entries with `,`), `ROLE` being `read` or `write`; `#` starts a
//! comment. A token is 16 to 256 visible ASCII characters without `,`.
//! No entry at all means the API is open, as before.

use axum::http::{header, HeaderMap, HeaderValue, Method, StatusCode};
use axum::response::{IntoResponse, Response};

use crate::http::error::ApiError;

/// What a token allows. `Write` includes reading.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Role {
    Read,
    Write,
}

/// The configured tokens; empty means no token is asked for.
#[derive(Clone, Default)]
pub struct Tokens {
    entries: Vec<(Vec<u8>, Role)>,
}

// Never print a token, not even in a debug dump of the settings.
impl std::fmt::Debug for Tokens {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Tokens({} configured)", self.entries.len())
    }
}

const MIN_LEN: usize = 16;
const MAX_LEN: usize = 256;

impl Tokens {
    /// Parse entries; the error names the entry (by line) but never the token.
    pub fn parse(text: &str, source: &str) -> Result<Tokens, String> {
        let mut entries = Vec::new();
        let lines = text.split(['\n', ',']).enumerate();
        for (n, raw) in lines {
            let line = raw.split('#').next().unwrap_or("").trim();
            if line.is_empty() {
                continue;
            }
            let at = format!("{source}, entry {}", n + 1);
            let mut words = line.split_whitespace();
            let role = match words.next() {
                Some("read") => Role::Read,
                Some("write") => Role::Write,
                _ => return Err(format!("{at}: the role must be `read` or `write`")),
            };
            let token = words
                .next()
                .ok_or_else(|| format!("{at}: a role without a token"))?;
            if words.next().is_some() {
                return Err(format!("{at}: expected `ROLE TOKEN`, found more words"));
            }
            if !(MIN_LEN..=MAX_LEN).contains(&token.len())
                || !token.bytes().all(|b| b.is_ascii_graphic())
            {
                return Err(format!(
                    "{at}: a token must be {MIN_LEN} to {MAX_LEN} visible ASCII characters"
                ));
            }
            entries.push((token.as_bytes().to_vec(), role));
        }
        Ok(Tokens { entries })
    }

    /// Tokens from an optional file and an optional variable's text, together.
    pub fn load(file: Option<&std::path::Path>, var: Option<&str>) -> Result<Tokens, String> {
        let mut all = Tokens::default();
        if let Some(path) = file {
            let text = std::fs::read_to_string(path)
                .map_err(|e| format!("tokens file {}: {e}", path.display()))?;
            all.entries
                .extend(Tokens::parse(&text, &path.display().to_string())?.entries);
        }
        if let Some(text) = var {
            all.entries
                .extend(Tokens::parse(text, "FIELDBAL_TOKENS")?.entries);
        }
        Ok(all)
    }

    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// The role of `presented`, comparing against every entry in constant time
    /// (no early exit, no length-dependent branch), so timing tells nothing.
    fn role_of(&self, presented: &[u8]) -> Option<Role> {
        let mut found: Option<Role> = None;
        for (token, role) in &self.entries {
            if constant_time_eq(token, presented) {
                found = found.max(Some(*role));
            }
        }
        found
    }
}

fn constant_time_eq(a: &[u8], b: &[u8]) -> bool {
    let mut diff = (a.len() != b.len()) as u8;
    // Walk the stored token's length whatever was presented.
    for (i, x) in a.iter().enumerate() {
        let y = b.get(i).copied().unwrap_or(0);
        diff |= std::hint::black_box(x ^ y);
    }
    diff == 0
}

/// Stateless computations: a POST that stores nothing, open to read tokens.
const COMPUTE_ONLY: &[&str] = &[
    "/api/v1/solve",
    "/api/v1/trial-weights",
    "/api/v1/identify/rotor",
    "/api/v1/identify/free-decay",
    "/api/v1/identify/model",
    "/api/v1/residual-unbalance",
];

/// Whether a request may change the store (any other method than a read,
/// unless the path only computes).
pub fn is_write(method: &Method, path: &str) -> bool {
    !matches!(*method, Method::GET | Method::HEAD | Method::OPTIONS)
        && !COMPUTE_ONLY.contains(&path)
}

/// Check the `Authorization` header of an `/api/` request: `Some` is the 401 or 403.
pub fn refusal(
    tokens: &Tokens,
    headers: &HeaderMap,
    method: &Method,
    path: &str,
) -> Option<Response> {
    if tokens.is_empty() {
        return None;
    }
    let presented = headers
        .get(header::AUTHORIZATION)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| {
            let (scheme, token) = v.trim().split_once(' ')?;
            scheme.eq_ignore_ascii_case("bearer").then(|| token.trim())
        });
    let Some(presented) = presented else {
        return Some(refuse(
            StatusCode::UNAUTHORIZED,
            "unauthorized",
            "this service needs `Authorization: Bearer <token>`",
            r#"Bearer realm="fieldbal""#,
        ));
    };
    match tokens.role_of(presented.as_bytes()) {
        None => Some(refuse(
            StatusCode::UNAUTHORIZED,
            "unauthorized",
            "the bearer token is not valid here",
            r#"Bearer realm="fieldbal", error="invalid_token""#,
        )),
        Some(Role::Read) if is_write(method, path) => Some(refuse(
            StatusCode::FORBIDDEN,
            "forbidden",
            "this token may read but not change the store",
            r#"Bearer realm="fieldbal", error="insufficient_scope""#,
        )),
        Some(_) => None,
    }
}

fn refuse(status: StatusCode, code: &str, message: &str, challenge: &'static str) -> Response {
    let mut resp = ApiError::new(status, code, message)
        .with_field("Authorization")
        .into_response();
    resp.headers_mut().insert(
        header::WWW_AUTHENTICATE,
        HeaderValue::from_static(challenge),
    );
    resp
}

#[cfg(test)]
mod tests {
    use super::*;

    const W: &str = "write-token-0123456789";
    const R: &str = "read-token-0123456789";

    #[test]
    fn entries_are_read_from_lines_and_commas_with_comments() {
        let text = format!("# stand PC\nwrite {W}  # the form\n\n read {R} ,");
        let tokens = Tokens::parse(&text, "t").unwrap();
        assert_eq!(tokens.len(), 2);
        assert_eq!(tokens.role_of(W.as_bytes()), Some(Role::Write));
        assert_eq!(tokens.role_of(R.as_bytes()), Some(Role::Read));
        assert_eq!(tokens.role_of(b"write-token-012345678"), None);
        assert_eq!(tokens.role_of(b""), None);
    }

    #[test]
    fn bad_entries_are_refused_without_echoing_the_token() {
        let cases = [
            ("admin write-token-0123456789", "role"),
            ("write", "without a token"),
            ("write short", "16 to 256"),
            ("write write-token-0123456789 extra", "more words"),
        ];
        for (text, says) in cases {
            let err = Tokens::parse(text, "t").unwrap_err();
            assert!(err.contains(says), "{text}: {err}");
            assert!(!err.contains("0123456789"), "{err} shows the token");
        }
    }

    #[test]
    fn only_a_different_string_of_any_length_fails_the_comparison() {
        assert!(constant_time_eq(b"abc", b"abc"));
        assert!(!constant_time_eq(b"abc", b"abd"));
        assert!(!constant_time_eq(b"abc", b"ab"));
        assert!(!constant_time_eq(b"abc", b"abcd"));
    }

    #[test]
    fn stateless_computations_are_reads_and_stored_changes_are_writes() {
        assert!(!is_write(&Method::POST, "/api/v1/solve"));
        assert!(!is_write(&Method::POST, "/api/v1/trial-weights"));
        assert!(!is_write(&Method::GET, "/api/v1/sessions"));
        assert!(is_write(&Method::POST, "/api/v1/sessions"));
        assert!(is_write(&Method::DELETE, "/api/v1/sessions/x"));
        assert!(is_write(&Method::PUT, "/api/v1/sessions/x/runs/r"));
    }
}
