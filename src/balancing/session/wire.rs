//! Wire structs are JSON objects only: serde's derive also accepts a struct
//! as a positional array (`["pump", null, ...]`), which the contract does not
//! allow and which would make field order part of the format.
//!
//! A struct marked `#[serde(remote = "Self")]` gets its derived code as
//! inherent functions; `objects_only!` then implements the traits, asking
//! the deserializer for a map so that an array is refused (400, naming the
//! field, see `error::classify`).

/// What serde's message says was expected where an array was given.
pub const NOT_AN_OBJECT: &str = "a JSON object, not an array";

/// Implement `Serialize` and map-only `Deserialize` for `#[serde(remote = "Self")]` structs.
macro_rules! objects_only {
    ($($t:ty),* $(,)?) => {$(
        impl<'de> serde::Deserialize<'de> for $t {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                struct Visit;
                impl<'de> serde::de::Visitor<'de> for Visit {
                    type Value = $t;
                    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                        f.write_str($crate::balancing::wire::NOT_AN_OBJECT)
                    }
                    fn visit_map<A: serde::de::MapAccess<'de>>(self, map: A) -> Result<$t, A::Error> {
                        <$t>::deserialize(serde::de::value::MapAccessDeserializer::new(map))
                    }
                }
                d.deserialize_map(Visit)
            }
        }
        impl serde::Serialize for $t {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                <$t>::serialize(self, s)
            }
        }
    )*};
}
pub(crate) use objects_only;
