//! An id (a sensor's, a plane's) that many entries of one solution repeat,
//! shared instead of copied: the influence coefficients of a 16-plane,
//! 1280-row job named their sensor and plane 20,480 times each, and copying
//! those strings was half of building the report (issue 15). It reads and
//! writes as a plain JSON string.

use std::fmt;
use std::ops::Deref;
use std::sync::Arc;

use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A shared, immutable id; compares and prints as its text.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SharedId(Arc<str>);

impl Deref for SharedId {
    type Target = str;
    fn deref(&self) -> &str {
        &self.0
    }
}

impl fmt::Debug for SharedId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&*self.0, f)
    }
}

impl fmt::Display for SharedId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl From<&str> for SharedId {
    fn from(s: &str) -> Self {
        SharedId(Arc::from(s))
    }
}

impl From<String> for SharedId {
    fn from(s: String) -> Self {
        SharedId(Arc::from(s))
    }
}

impl PartialEq<str> for SharedId {
    fn eq(&self, other: &str) -> bool {
        *self.0 == *other
    }
}

impl PartialEq<&str> for SharedId {
    fn eq(&self, other: &&str) -> bool {
        *self.0 == **other
    }
}

impl PartialEq<String> for SharedId {
    fn eq(&self, other: &String) -> bool {
        *self.0 == **other
    }
}

impl Serialize for SharedId {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(&self.0)
    }
}

impl<'de> Deserialize<'de> for SharedId {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        String::deserialize(deserializer).map(SharedId::from)
    }
}

#[cfg(test)]
mod tests {
    use super::SharedId;

    #[test]
    fn a_shared_id_reads_and_writes_as_a_plain_string() {
        let id = SharedId::from("S1");
        assert_eq!(serde_json::to_string(&id).unwrap(), "\"S1\"");
        let back: SharedId = serde_json::from_str("\"P0\"").unwrap();
        assert_eq!(back, "P0");
        assert_eq!(format!("{id} {id:?}"), "S1 \"S1\"");
    }
}
