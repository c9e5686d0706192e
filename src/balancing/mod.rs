//! The balancing core: pure functions from a recorded session to corrections.
//! No HTTP, no database, no async in here.
//!
//! Conventions (docs/method.md §1): inside the core every 1X reading is a complex
//! phasor `Y` with `x(t) = Re(Y e^{iωt})` (phase lead) and every weight angle is
//! counted with rotation, so a weight is `m e^{iθ}` and the response is
//! complex-linear in it. The session's own conventions are applied only when
//! values enter (`phasor`) and leave (`solution`).

#[macro_use]
pub mod session;
pub mod acceptance;
pub mod cancel;
pub mod conic;
pub mod fit;
pub mod job;
pub mod solve;
pub mod uncertainty;

// The modules' paths from before the grouping stay valid, so callers and
// the documentation keep naming `balancing::model`, `balancing::solution`, ...
pub use session::{error, file, limits, model, phasor, select, validate, wire};
pub use solve::{diagnostics, factor, influence, practical, report, solution};

pub use error::{from_json, ErrorKind, InputError};
pub use model::{Session, SolveOptions, SolveRequest};
pub use solution::Solution;

/// Parse and validate a session posted as JSON.
pub fn parse_session(bytes: &[u8]) -> Result<Session, InputError> {
    let session: Session = from_json(bytes)?;
    validate_session(&session)?;
    Ok(session)
}

/// A session file as `fieldbal solve` reads it: a bare session, or the
/// examples' wrapper `{"session", "options", "description", "expected"}`
/// (`session::file`), validated, a wrapped session's errors named under `session.`.
pub fn parse_session_file(bytes: &[u8]) -> Result<(Session, SolveOptions), InputError> {
    let file = file::parse(bytes)?;
    check_file(&file)?;
    Ok((file.session, file.options))
}

/// Validate a session file's session, naming a wrapped session's fields under
/// `session.`; the checked session can be solved without validating it again
/// ([`solve_checked`]). A file defines its session as a request does, so its
/// texts and the machine it names are checked first
/// (`validate::check_defined_strings`), as the service checks a posted
/// session ([`check_posted_session`]): `fieldbal` refuses what the service
/// refuses, with the same code and message.
pub fn check_file(file: &file::SessionFile) -> Result<validate::Checked<'_>, InputError> {
    validate::check_defined_strings(&file.session)
        .and_then(|()| validate::check(&file.session))
        .map_err(|e| if file.wrapped { e.under("session") } else { e })
}

/// The strings of a session a request posts within `{"session", ...}`
/// (`/solve`, `/trial-weights`, `/identify/rotor`, and their `fieldbal`
/// commands): `validate::check_defined_strings`, the store's rule for a
/// posted session, its fields named under `session.`.
pub fn check_posted_session(session: &Session) -> Result<(), InputError> {
    validate::check_defined_strings(session).map_err(|e| e.under("session"))
}

/// Check a session against the contract (everything but solvability: a stored
/// session may still lack trial runs).
pub fn validate_session(session: &Session) -> Result<(), InputError> {
    validate::check(session).map(|_| ())
}

/// Solve a session with options.
pub fn solve(session: &Session, options: &SolveOptions) -> Result<Solution, InputError> {
    limits::check_options(options, &limits::Limits::current())?;
    job::solve(session, options)
}

/// [`solve()`] of a session already validated (by [`check_file`] or `validate::check`).
pub fn solve_checked(
    checked: validate::Checked<'_>,
    options: &SolveOptions,
) -> Result<Solution, InputError> {
    limits::check_options(options, &limits::Limits::current())?;
    job::solve_checked(checked, options)
}
