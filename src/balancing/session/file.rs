//! Session files as `fieldbal solve` and `fieldbal coefficients` read them:
//! a bare session, or the examples' wrapper
//! `{"session", "options", "description", "expected"}`, parsed in one pass.
//!
//! Which of the two a file is was once decided by parsing the whole document
//! into a `serde_json::Value` and asking for a `session` key; on a 1.7 MB job
//! that cost three times the typed parse (issue 15). Here the first key
//! decides: the two structs' keys are disjoint and both deny unknown keys, so
//! when the typed parse of the one the first key names succeeds, the file is
//! that one. When it fails, [`parse_tracked`] does what the old code did, in
//! the same order, so every error is exactly the old one.

use serde::de::{self, DeserializeSeed, IntoDeserializer, MapAccess, Visitor};
use serde::{Deserialize, Deserializer};

use super::error::{as_text, from_json_tracked, InputError};
use super::model::{Session, SolveOptions};

/// A session file's content, parsed but not yet validated.
#[derive(Debug, Clone, PartialEq)]
pub struct SessionFile {
    pub session: Session,
    pub options: SolveOptions,
    /// The session came inside the wrapper, so its errors are named under `session.`.
    pub wrapped: bool,
}

/// The examples' wrapper around a session.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Wrapper {
    session: Session,
    #[serde(default)]
    options: SolveOptions,
    #[serde(default, rename = "description")]
    _description: Option<String>,
    #[serde(default, rename = "expected")]
    _expected: Option<serde_json::Value>,
}

/// The wrapper's keys; a bare session has none of them.
const WRAPPER_KEYS: [&str; 4] = ["session", "options", "description", "expected"];

impl From<Wrapper> for SessionFile {
    fn from(w: Wrapper) -> Self {
        SessionFile {
            session: w.session,
            options: w.options,
            wrapped: true,
        }
    }
}

impl From<Session> for SessionFile {
    fn from(session: Session) -> Self {
        SessionFile {
            session,
            options: SolveOptions::default(),
            wrapped: false,
        }
    }
}

/// Parse a session file (wrapped or bare) without validating it: one typed
/// parse when the file is well formed, the old two-step parse (and its
/// error) when it is not.
pub fn parse(bytes: &[u8]) -> Result<SessionFile, InputError> {
    match parse_fast(bytes) {
        Some(file) => Ok(file),
        None => parse_tracked(bytes, &crate::balancing::from_json(bytes)?),
    }
}

/// The one-pass parse; `None` for anything it does not accept (the caller
/// then takes the slow path for the error, or for a file that is not a
/// session file, such as `fieldbal solve`'s worked cases).
pub fn parse_fast(bytes: &[u8]) -> Option<SessionFile> {
    let mut de = serde_json::Deserializer::from_str(as_text(bytes)?);
    let file = de.deserialize_map(FileVisitor).ok()?;
    de.end().ok()?;
    Some(file)
}

/// The old parse, given the document already read as a `Value`: a wrapper
/// when it has a `session` key, a bare session otherwise; errors name their
/// field through the tracked parse.
pub fn parse_tracked(bytes: &[u8], value: &serde_json::Value) -> Result<SessionFile, InputError> {
    if value.get("session").is_some() {
        from_json_tracked::<Wrapper>(bytes).map(SessionFile::from)
    } else {
        from_json_tracked::<Session>(bytes).map(SessionFile::from)
    }
}

/// Reads the first key, then hands the whole map, that key replayed first,
/// to the derived code of the struct it belongs to.
struct FileVisitor;

impl<'de> Visitor<'de> for FileVisitor {
    type Value = SessionFile;

    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a session, or an object with `session`")
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<SessionFile, A::Error> {
        let Some(first) = map.next_key::<String>()? else {
            return Err(de::Error::custom("an empty object is not a session"));
        };
        let wrapped = WRAPPER_KEYS.contains(&first.as_str());
        let rest = de::value::MapAccessDeserializer::new(Replay {
            first: Some(first),
            map,
        });
        if wrapped {
            Wrapper::deserialize(rest).map(SessionFile::from)
        } else {
            Session::deserialize(rest).map(SessionFile::from)
        }
    }
}

/// A map whose first key has already been read: it gives that key again,
/// then the rest of the map.
struct Replay<A> {
    first: Option<String>,
    map: A,
}

impl<'de, A: MapAccess<'de>> MapAccess<'de> for Replay<A> {
    type Error = A::Error;

    fn next_key_seed<K: DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, A::Error> {
        match self.first.take() {
            Some(key) => seed.deserialize(key.into_deserializer()).map(Some),
            None => self.map.next_key_seed(seed),
        }
    }

    fn next_value_seed<V: DeserializeSeed<'de>>(&mut self, seed: V) -> Result<V::Value, A::Error> {
        self.map.next_value_seed(seed)
    }

    fn size_hint(&self) -> Option<usize> {
        self.map
            .size_hint()
            .map(|n| n + usize::from(self.first.is_some()))
    }
}
