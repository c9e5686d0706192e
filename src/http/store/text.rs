//! What a stored string may hold. Ids the client chooses (a machine's, a
//! session's planes, sensors and runs, the machine a session names) hold no
//! control characters: they go into paths, headers, file names and lists,
//! where a newline or a NUL is invisible or breaks the line. Free texts
//! (names, labels, notes) may hold tabs and line breaks but no other control
//! character; above all no NUL, which PostgreSQL's text cannot store (it
//! answered 500 where SQLite stored it).
//!
//! The rules themselves are the core's (`balancing::validate`), which
//! applies the id rule to a session's planes, sensors and runs wherever a
//! session is validated (`/api/v1/solve` too); the store adds the machine a
//! session names, texts and machines.
//!
//! The store checks only what a request defines (a posted session, an
//! appended run, a posted machine), never what is stored already: a session
//! stored before these rules with such a machine or label still takes runs
//! and corrections (one whose plane, sensor or run ids hold control
//! characters no longer validates, in the store or in the solve).

use crate::balancing::model::{Run, Session};
use crate::balancing::validate;
use crate::balancing::InputError;
use crate::db::machines::NewMachine;

/// An id the client chooses: the core's rule, the one definition of what an
/// id may hold (no control character).
pub fn check_id(field: impl FnOnce() -> String, id: &str) -> Result<(), InputError> {
    validate::check_id_chars(field, id)
}

/// A free text: tabs and line breaks, but no other control character (the
/// core's rule for texts).
pub fn check_text(field: impl FnOnce() -> String, text: &str) -> Result<(), InputError> {
    validate::check_text_chars(field, text)
}

/// The strings a posted session defines: the core's rule for them
/// (`validate::check_defined_strings`: `name`, `machine`, sensors' labels),
/// the same the stateless endpoints apply. The planes', sensors' and runs'
/// ids and `trim.coefficients_from.machine` are the core's ids: it checks
/// them when the session is validated, stored or solved.
pub fn check_session(s: &Session) -> Result<(), InputError> {
    validate::check_defined_strings(s)
}

/// The id of an appended run (its weights and readings name planes and
/// sensors of the session, checked against them).
pub fn check_new_run(r: &Run) -> Result<(), InputError> {
    check_id(|| "id".into(), &r.id)
}

/// The strings a posted machine defines.
pub fn check_machine(m: &NewMachine) -> Result<(), InputError> {
    // The core's one rule of what a machine id is (1 to 64 characters, not
    // blank, no control character), as a session's `machine` is checked.
    validate::check_machine_id(|| "id".into(), &m.id)?;
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
