//! Command line: `fieldbal serve` runs the service, `fieldbal solve` solves a file offline,
//! `fieldbal identify` identifies model coefficients offline, `fieldbal coefficients`
//! pools session files into influence coefficients.

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
    /// API 617/684 residual-unbalance check of a file (the body of
    /// `POST /api/v1/residual-unbalance`; `-` for standard input).
    Residual { file: PathBuf },
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
    /// Identify model coefficients from a request file (the endpoint's body) and print the answer as JSON.
    Identify {
        #[arg(value_enum)]
        what: IdentifyWhat,
        /// The request JSON, as posted to `/api/v1/identify/<what>`; `-` for standard input.
        file: PathBuf,
    },
}

/// Which identification `fieldbal identify` runs.
#[derive(Debug, Clone, Copy, clap::ValueEnum)]
pub enum IdentifyWhat {
    /// `identify/rotor`: one-mass rotor from a multi-speed session.
    Rotor,
    /// `identify/free-decay`: frequency and damping from a free decay.
    FreeDecay,
    /// `identify/model`: discrete-model correction.
    Model,
}

pub fn run(cli: Cli) -> ExitCode {
    match cli.command {
        Command::Serve(args) => crate::http::serve_main(args),
        Command::Solve { file, options } => solve_file(&file, options.as_deref()),
        Command::Residual { file } => print_result(residual_file(&file)),
        Command::Coefficients { files, options } => {
            print_result(pool_files(&files, options.as_deref()))
        }
        Command::Identify { what, file } => print_result(identify_file(what, &file)),
    }
}

/// `fieldbal identify`: the same JSON as the endpoint.
fn identify_file(
    what: IdentifyWhat,
    file: &std::path::Path,
) -> Result<serde_json::Value, InputError> {
    use crate::identification as id;
    let bytes = read(file)?;
    let value = match what {
        IdentifyWhat::Rotor => {
            serde_json::to_value(id::rotor::identify(&balancing::from_json(&bytes)?)?)
        }
        IdentifyWhat::FreeDecay => {
            serde_json::to_value(id::decay::identify(&balancing::from_json(&bytes)?)?)
        }
        IdentifyWhat::Model => {
            serde_json::to_value(id::correct::correct(&balancing::from_json(&bytes)?)?)
        }
    };
    Ok(value.expect("answers serialise"))
}

/// Print an answer (exit 0) or the contract's error body (exit 2).
fn print_result(result: Result<serde_json::Value, InputError>) -> ExitCode {
    match result {
        Ok(v) => {
            println!(
                "{}",
                serde_json::to_string_pretty(&v).expect("answer serialises")
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

fn residual_file(file: &std::path::Path) -> Result<serde_json::Value, InputError> {
    let req = balancing::acceptance::parse(&read(file)?)?;
    let check = balancing::acceptance::check(&req)?;
    Ok(serde_json::to_value(check).expect("check serialises"))
}

fn solve_file(file: &std::path::Path, options: Option<&std::path::Path>) -> ExitCode {
    let (value, code) = match solve_file_inner(file, options) {
        Ok(solution) => (solution, ExitCode::SUCCESS),
        Err(err) => (err.to_json(), ExitCode::from(2)),
    };
    let text = serde_json::to_string_pretty(&value).expect("JSON values serialise");
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

/// Write `text` and a newline to standard output; unlike `println!`, a
/// closed pipe is an error to handle, not a panic.
fn print_line(text: &str) -> std::io::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())?;
    out.write_all(b"\n")?;
    out.flush()
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
