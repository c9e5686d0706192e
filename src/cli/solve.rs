//! `fieldbal solve FILE`: one typed parse of the file, one validation, the
//! solve, and the answer written straight from the solution (issue 15).

use std::process::ExitCode;

use super::{pretty, print_line, read};
use crate::balancing::{self, InputError, SolveOptions};

pub(super) fn solve_file(
    file: &std::path::Path,
    options: Option<&std::path::Path>,
    max: usize,
) -> ExitCode {
    // The solution is written straight from its struct: building a
    // `serde_json::Value` of it first cost more than the writing (issue 15).
    let (text, code) = match solve_file_inner(file, options, max) {
        Ok(Answer::Solution(s)) => (pretty::to_vec_pretty(&s), ExitCode::SUCCESS),
        Ok(Answer::Cases(v)) => (pretty::to_vec_pretty(&v), ExitCode::SUCCESS),
        Err(err) => (pretty::to_vec_pretty(&err.to_json()), ExitCode::from(2)),
    };
    let text = text.expect("answers serialise");
    match print_line(&text) {
        Ok(()) => code,
        // `fieldbal solve FILE | head`: the reader has what it wanted; stop quietly.
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => code,
        Err(e) => {
            eprintln!("fieldbal solve: cannot write the answer: {e}");
            ExitCode::FAILURE
        }
    }
}

/// What `fieldbal solve` prints: a solution, or the estimates of a file of
/// worked identification cases.
enum Answer {
    Solution(Box<balancing::Solution>),
    Cases(serde_json::Value),
}

fn solve_file_inner(
    file: &std::path::Path,
    options: Option<&std::path::Path>,
    max: usize,
) -> Result<Answer, InputError> {
    super::stdin_once(std::iter::once(file), options)?;
    let bytes = read(file, max)?;
    // One typed parse for a well-formed session file; otherwise the document
    // is read as a `Value` first, as it always was, so that a file of cases
    // is recognised and every error is the one it always was.
    let file = match balancing::file::parse_fast(&bytes) {
        Some(file) => file,
        None => {
            let value: serde_json::Value = balancing::from_json(&bytes)?;
            if value.get("cases").is_some() {
                return identify_cases(&bytes).map(Answer::Cases);
            }
            balancing::file::parse_tracked(&bytes, &value)?
        }
    };
    // Validated once, here (before the options file is read, as before), and
    // not again by the solve.
    let checked = balancing::check_file(&file)?;
    let opts = match options {
        Some(path) => balancing::from_json::<SolveOptions>(&read(path, max)?)
            .map_err(|e| e.under("options"))?,
        None => file.options.clone(),
    };
    // The service's rule of `coefficients_from` (not beside
    // `influence_coefficients`, a version from 1) before the solve says
    // that offline it cannot be read.
    balancing::job::check_coefficients_from(&opts)?;
    let solution = balancing::solve_checked(checked, &opts)?;
    Ok(Answer::Solution(Box::new(solution)))
}

/// A file of worked identification cases (method §6): estimate each one.
fn identify_cases(bytes: &[u8]) -> Result<serde_json::Value, InputError> {
    #[derive(serde::Deserialize)]
    struct Cases {
        cases: Vec<crate::identification::textbook::Case>,
    }
    let file: Cases = balancing::from_json(bytes)?;
    let mut out = Vec::with_capacity(file.cases.len());
    for (i, case) in file.cases.iter().enumerate() {
        let estimate = crate::identification::textbook::estimate_case(case)
            .map_err(|e| e.under(&format!("cases[{i}]")))?;
        out.push(serde_json::json!({ "name": case.name, "estimate": estimate }));
    }
    Ok(serde_json::json!({ "cases": out }))
}
