//! Pretty JSON output of `fieldbal solve`, byte for byte `serde_json`'s
//! `to_string_pretty`, with each line's break and indent written at once.
//!
//! A large job's solution is about 3.7 MB over some 400,000 lines; the
//! standard formatter writes a line's indent one level at a time (a copy per
//! level), which was a fifth of writing the answer (issue 15).

use std::io::{self, Write};

use serde::Serialize;
use serde_json::ser::{Formatter, Serializer};

/// `value` as `serde_json::to_string_pretty` would write it (two-space indent).
pub fn to_vec_pretty<T: Serialize + ?Sized>(value: &T) -> serde_json::Result<Vec<u8>> {
    let mut out = Vec::with_capacity(4096);
    value.serialize(&mut Serializer::with_formatter(&mut out, Pretty::default()))?;
    Ok(out)
}

/// A comma, a line break and the indent of the deepest level written at once.
const BREAK: &[u8; 2 + 2 * DEEPEST] = &{
    let mut b = [b' '; 2 + 2 * DEEPEST];
    b[0] = b',';
    b[1] = b'\n';
    b
};
/// Levels indented by one copy; deeper ones (never in a solution) by several.
const DEEPEST: usize = 32;

#[derive(Default)]
struct Pretty {
    depth: usize,
    has_value: bool,
}

impl Pretty {
    /// `,` unless `first`, then a line break and the current indent.
    fn new_line<W: ?Sized + Write>(&self, w: &mut W, first: bool) -> io::Result<()> {
        let from = usize::from(first);
        if self.depth <= DEEPEST {
            return w.write_all(&BREAK[from..2 + 2 * self.depth]);
        }
        w.write_all(&BREAK[from..2 + 2 * DEEPEST])?;
        (DEEPEST..self.depth).try_for_each(|_| w.write_all(b"  "))
    }

    fn open<W: ?Sized + Write>(&mut self, w: &mut W, bracket: &[u8]) -> io::Result<()> {
        self.depth += 1;
        self.has_value = false;
        w.write_all(bracket)
    }

    fn close<W: ?Sized + Write>(&mut self, w: &mut W, bracket: &[u8]) -> io::Result<()> {
        self.depth -= 1;
        if self.has_value {
            self.new_line(w, true)?;
        }
        w.write_all(bracket)
    }
}

impl Formatter for Pretty {
    fn begin_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.open(w, b"[")
    }

    fn end_array<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.close(w, b"]")
    }

    fn begin_array_value<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        self.new_line(w, first)
    }

    fn end_array_value<W: ?Sized + Write>(&mut self, _w: &mut W) -> io::Result<()> {
        self.has_value = true;
        Ok(())
    }

    fn begin_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.open(w, b"{")
    }

    fn end_object<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        self.close(w, b"}")
    }

    fn begin_object_key<W: ?Sized + Write>(&mut self, w: &mut W, first: bool) -> io::Result<()> {
        self.new_line(w, first)
    }

    fn begin_object_value<W: ?Sized + Write>(&mut self, w: &mut W) -> io::Result<()> {
        w.write_all(b": ")
    }

    fn end_object_value<W: ?Sized + Write>(&mut self, _w: &mut W) -> io::Result<()> {
        self.has_value = true;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn output_is_byte_for_byte_serde_jsons_pretty_form() {
        // Empty and nested containers, escapes, numbers, and nesting deeper
        // than one copy of the indent covers.
        let mut deep = json!("bottom");
        for i in 0..(DEEPEST + 5) {
            deep = if i % 2 == 0 {
                json!([deep, i])
            } else {
                json!({ "k": deep, "e": {}, "a": [] })
            };
        }
        let cases = [
            json!(null),
            json!([]),
            json!({}),
            json!({"a": [1, 2.5, -3e-7, {"b": "x\"\n\u{1}"}], "c": [[]], "d": {"e": {}}}),
            json!([{"x": true}, [null, false], "é"]),
            deep,
        ];
        for v in cases {
            assert_eq!(
                String::from_utf8(to_vec_pretty(&v).unwrap()).unwrap(),
                serde_json::to_string_pretty(&v).unwrap()
            );
        }
    }
}
