//! Command line: `fieldbal serve` runs the service, `fieldbal solve` solves a file offline,
//! `fieldbal coefficients` pools session files into influence coefficients.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::balancing::{self, InputError, SolveOptions};

#[derive(Debug, Parser)]
#[command(
    name = "fieldbal",
    version,
    about = "Field balancing of rotors by influence coefficients"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run the HTTP service and the web form.
    Serve(crate::http::ServeArgs),
    /// Solve a session file offline and print the solution as JSON.
    Solve {
        /// Session JSON (a bare session, or an object with `session` and optional `options`); `-` for standard input.
        file: PathBuf,
        /// Solve options JSON (overrides options inside FILE).
        #[arg(long)]
        options: Option<PathBuf>,
    },
    /// Pool the runs of several session files into one set of influence
    /// coefficients (each session against its own reference run) and print them as JSON.
    Coefficients {
        /// Session files (as for `solve`), at least one.
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// Pooling options JSON (`exclude_disagreeing`, `amplitude_noise_pct`, `phase_noise_deg`).
        #[arg(long)]
        options: Option<PathBuf>,
    },
}

pub fn run(cli: Cli) -> ExitCode {
    match cli.command {
        Command::Serve(args) => crate::http::serve_main(args),
        Command::Solve { file, options } => solve_file(&file, options.as_deref()),
        Command::Coefficients { files, options } => {
            print_result(pool_files(&files, options.as_deref()))
        }
    }
}

fn solve_file(file: &std::path::Path, options: Option<&std::path::Path>) -> ExitCode {
    print_result(solve_file_inner(file, options))
}

/// Print a result as JSON: the answer (exit 0) or the contract's error (exit 2).
fn print_result(result: Result<serde_json::Value, InputError>) -> ExitCode {
    match result {
        Ok(answer) => {
            println!(
                "{}",
                serde_json::to_string_pretty(&answer).expect("answer serialises")
            );
            ExitCode::SUCCESS
        }
        Err(err) => {
            println!(
                "{}",
                serde_json::to_string_pretty(&err.to_json()).expect("error serialises")
            );
            ExitCode::from(2)
        }
    }
}

/// The file's bytes; `-` reads standard input.
fn read(path: &std::path::Path) -> Result<Vec<u8>, InputError> {
    let bytes = if path.as_os_str() == "-" {
        let mut buf = Vec::new();
        std::io::Read::read_to_end(&mut std::io::stdin(), &mut buf).map(|_| buf)
    } else {
        std::fs::read(path)
    };
    bytes.map_err(|e| InputError {
        kind: balancing::ErrorKind::Malformed,
        code: "unreadable_file",
        message: format!("cannot read {}: {e}", path.display()),
        field: None,
    })
}

fn solve_file_inner(
    file: &std::path::Path,
    options: Option<&std::path::Path>,
) -> Result<serde_json::Value, InputError> {
    let bytes = read(file)?;
    let value: serde_json::Value = balancing::from_json(&bytes)?;
    if value.get("cases").is_some() {
        return identify_cases(&bytes);
    }
    let (session, mut opts) = balancing::parse_session_file(&bytes)?;
    if let Some(path) = options {
        opts =
            balancing::from_json::<SolveOptions>(&read(path)?).map_err(|e| e.under("options"))?;
    }
    let solution = balancing::solve(&session, &opts)?;
    Ok(serde_json::to_value(solution).expect("solution serialises"))
}

/// A file of worked identification cases (method §6): estimate each one.
fn identify_cases(bytes: &[u8]) -> Result<serde_json::Value, InputError> {
    #[derive(serde::Deserialize)]
    struct Cases {
        cases: Vec<balancing::identify::Case>,
    }
    let file: Cases = balancing::from_json(bytes)?;
    let mut out = Vec::with_capacity(file.cases.len());
    for (i, case) in file.cases.iter().enumerate() {
        let estimate = balancing::identify::estimate_case(case)
            .map_err(|e| e.under(&format!("cases[{i}]")))?;
        out.push(serde_json::json!({ "name": case.name, "estimate": estimate }));
    }
    Ok(serde_json::json!({ "cases": out }))
}

/// `fieldbal coefficients`: the sessions' pooled coefficients (v2 "Machines"),
/// each session named by its file path.
fn pool_files(
    files: &[PathBuf],
    options: Option<&std::path::Path>,
) -> Result<serde_json::Value, InputError> {
    let mut sessions = Vec::with_capacity(files.len());
    for (i, f) in files.iter().enumerate() {
        let (session, _) = balancing::parse_session_file(&read(f)?)
            .map_err(|e| e.under(&format!("sessions[{i}]")))?;
        sessions.push((f.display().to_string(), session));
    }
    let opts = match options {
        Some(path) => balancing::from_json(&read(path)?).map_err(|e| e.under("options"))?,
        None => balancing::job::pool::PoolOptions::default(),
    };
    let pooled = balancing::job::pool::pool(&sessions, &opts)?;
    Ok(serde_json::to_value(pooled).expect("coefficients serialise"))
}
