//! A trim job's own coefficients (session field `trim`, contract "What a job
//! and its runs are"): a job solved with coefficients known before it, a
//! machine's stored version (`coefficients_from`) or a list
//! (`influence_coefficients`). A solve whose options name no coefficients
//! takes the trim's, so that a stored trim job solves as it was recorded;
//! options that name coefficients win.

use crate::balancing::error::InputError;
use crate::balancing::model::{Session, SolveOptions};

/// The options a solve of `session` runs with when they must take the trim's
/// coefficients; `None` when they are used as given (they name coefficients
/// of their own, or the session is no trim job).
pub fn options_for(session: &Session, options: &SolveOptions) -> Option<SolveOptions> {
    let trim = session.trim.as_ref()?;
    if options.coefficients_from.is_some() || options.influence_coefficients.is_some() {
        return None;
    }
    Some(SolveOptions {
        coefficients_from: trim.coefficients_from.clone(),
        influence_coefficients: trim.influence_coefficients.clone(),
        ..options.clone()
    })
}

/// An error about coefficients that came from the trim, named where they
/// were given: `options.coefficients_from.machine` is
/// `trim.coefficients_from.machine`. Other fields are left as they are.
pub fn named_in_trim(mut e: InputError) -> InputError {
    if let Some(f) = e.field.as_deref() {
        for key in ["coefficients_from", "influence_coefficients"] {
            if let Some(rest) = f.strip_prefix("options.").and_then(|r| r.strip_prefix(key)) {
                if rest.is_empty() || rest.starts_with('.') || rest.starts_with('[') {
                    e.field = Some(format!("trim.{key}{rest}"));
                    break;
                }
            }
        }
    }
    e
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_coefficients_fields_are_renamed() {
        let name = |f: &str| {
            named_in_trim(InputError::invalid("x", f, "m"))
                .field
                .unwrap()
        };
        assert_eq!(
            name("options.coefficients_from.machine"),
            "trim.coefficients_from.machine"
        );
        assert_eq!(name("options.coefficients_from"), "trim.coefficients_from");
        assert_eq!(
            name("options.influence_coefficients[3].unit"),
            "trim.influence_coefficients[3].unit"
        );
        assert_eq!(name("options.from_run"), "options.from_run");
        assert_eq!(
            name("options.coefficients_fromage"),
            "options.coefficients_fromage"
        );
        assert_eq!(name("runs"), "runs");
    }
}
