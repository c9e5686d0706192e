//! What a stored string may hold. Ids the client chooses (a machine's, a
//! session's planes, sensors and runs, the machine a session names) hold no
//! control characters: they go into paths, headers, file names and lists,
//! where a newline or a NUL is invisible or breaks the line. Free texts
//! (names, labels, notes) may hold tabs and line breaks but no other control
//! character; above all no NUL, which PostgreSQL's text cannot store (it
//! answered 500 where SQLite stored it).
//!
//! Only what a request defines is checked (a posted session, an appended
//! run, a posted machine), never what is stored already: a session stored
//! before these rules still takes runs and corrections.

use crate::balancing::model::{Run, Session};
use crate::balancing::InputError;
use crate::db::machines::NewMachine;

/// The first character of `s` that `bad` refuses, with its position (from 1).
fn first(s: &str, bad: impl Fn(char) -> bool) -> Option<(usize, char)> {
    s.chars()
        .enumerate()
        .find(|&(_, c)| bad(c))
        .map(|(i, c)| (i + 1, c))
}

fn refused(field: impl Into<String>, what: &str, at: usize, c: char) -> InputError {
    InputError::invalid(
        "invalid_value",
        field,
        format!(
            "{what}; this one has U+{:04X} at character {at}",
            u32::from(c)
        ),
    )
}

/// An id the client chooses: no control character (Unicode Cc: U+0000 to
/// U+001F, U+007F to U+009F).
pub fn check_id(field: impl FnOnce() -> String, id: &str) -> Result<(), InputError> {
    match first(id, char::is_control) {
        None => Ok(()),
        Some((at, c)) => Err(refused(
            field(),
            "an id holds no control characters (U+0000 to U+001F, U+007F to U+009F)",
            at,
            c,
        )),
    }
}

/// A free text: tabs and line breaks, but no other control character.
pub fn check_text(field: impl FnOnce() -> String, text: &str) -> Result<(), InputError> {
    match first(text, |c| c.is_control() && !matches!(c, '\t' | '\n' | '\r')) {
        None => Ok(()),
        Some((at, c)) => Err(refused(
            field(),
            "a text holds no control characters but tabs and line breaks",
            at,
            c,
        )),
    }
}

/// The strings a posted session defines.
pub fn check_session(s: &Session) -> Result<(), InputError> {
    check_text(|| "name".into(), &s.name)?;
    if let Some(m) = &s.machine {
        check_id(|| "machine".into(), m)?;
        // The core allows any short text; a stored session's machine is
        // looked up as a machine's id, which has at most 64 characters.
        let n = m.chars().count();
        if n > 64 {
            return Err(InputError::invalid(
                "invalid_value",
                "machine",
                format!("a machine id has 1 to 64 characters; this one has {n}"),
            ));
        }
    }
    for (i, p) in s.planes.iter().enumerate() {
        check_id(|| format!("planes[{i}].id"), &p.id)?;
    }
    for (i, x) in s.sensors.iter().enumerate() {
        check_id(|| format!("sensors[{i}].id"), &x.id)?;
        if let Some(l) = &x.label {
            check_text(|| format!("sensors[{i}].label"), l)?;
        }
    }
    for (i, r) in s.runs.iter().enumerate() {
        check_id(|| format!("runs[{i}].id"), &r.id)?;
    }
    if let Some(from) = s.trim.as_ref().and_then(|t| t.coefficients_from.as_ref()) {
        check_id(|| "trim.coefficients_from.machine".into(), &from.machine)?;
    }
    Ok(())
}

/// The id of an appended run (its weights and readings name planes and
/// sensors of the session, checked against them).
pub fn check_new_run(r: &Run) -> Result<(), InputError> {
    check_id(|| "id".into(), &r.id)
}

/// The strings a posted machine defines.
pub fn check_machine(m: &NewMachine) -> Result<(), InputError> {
    check_id(|| "id".into(), &m.id)?;
    if let Some(n) = &m.name {
        check_text(|| "name".into(), n)?;
    }
    if let Some(n) = &m.notes {
        check_text(|| "notes".into(), n)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_refuse_every_control_character_and_say_which() {
        for id in ["a\u{0}", "\n", "a\tb", "\u{1b}[31m", "x\u{7f}", "\u{9f}"] {
            assert!(check_id(|| "id".into(), id).is_err(), "{id:?}");
        }
        let e = check_id(|| "id".into(), "ab\ncd").unwrap_err();
        assert!(e.message.contains("U+000A at character 3"), "{}", e.message);
        for id in [
            "ID-FAN-3",
            "trial A/2",
            "Lüfter 3",
            "\u{6c34}",
            "a\u{200b}b",
        ] {
            assert!(check_id(|| "id".into(), id).is_ok(), "{id:?}");
        }
    }

    #[test]
    fn texts_keep_tabs_and_line_breaks_but_no_nul() {
        assert!(check_text(|| "notes".into(), "line 1\r\n\tline 2").is_ok());
        for t in ["a\u{0}b", "bell\u{7}", "\u{85}"] {
            assert!(check_text(|| "notes".into(), t).is_err(), "{t:?}");
        }
    }
}
