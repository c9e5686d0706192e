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

/// An optional JSON object read into a map whose every key appears once
/// (`max_mass_g`), for `#[serde(default, deserialize_with = "...")]`.
/// serde's own map keeps the last of a key given twice, so
/// `{"A": 1, "A": 1000}` solved with a bound of 1000 g, while a struct's key
/// given twice is refused (session 21); the error names the key as a
/// struct's does ("duplicate field", 422 naming `<map>.<key>`).
pub(crate) fn unique_keys<'de, D, V>(
    d: D,
) -> Result<Option<std::collections::BTreeMap<String, V>>, D::Error>
where
    D: serde::Deserializer<'de>,
    V: serde::Deserialize<'de>,
{
    use serde::de::{Error, MapAccess, Visitor};
    use std::collections::BTreeMap;
    use std::marker::PhantomData;

    struct Unique<V>(BTreeMap<String, V>);
    impl<'de, V: serde::Deserialize<'de>> serde::Deserialize<'de> for Unique<V> {
        fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            struct Visit<V>(PhantomData<V>);
            impl<'de, V: serde::Deserialize<'de>> Visitor<'de> for Visit<V> {
                type Value = Unique<V>;
                fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                    f.write_str("a map")
                }
                fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Unique<V>, A::Error> {
                    let mut out = BTreeMap::new();
                    while let Some(key) = map.next_key::<String>()? {
                        let value = map.next_value::<V>()?;
                        if out.contains_key(&key) {
                            return Err(A::Error::custom(format!(
                                "duplicate field `{key}`: each key is given once"
                            )));
                        }
                        out.insert(key, value);
                    }
                    Ok(Unique(out))
                }
            }
            d.deserialize_map(Visit(PhantomData))
        }
    }
    Ok(<Option<Unique<V>> as serde::Deserialize>::deserialize(d)?.map(|u| u.0))
}
