//! Command line: `fieldbal serve` runs the service, `fieldbal solve` solves a file offline.

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
        /// Session JSON (a bare session, or an object with `session` and optional `options`).
        file: PathBuf,
        /// Solve options JSON (overrides options inside FILE).
        #[arg(long)]
        options: Option<PathBuf>,
    },
}

pub fn run(cli: Cli) -> ExitCode {
    match cli.command {
        Command::Serve(args) => crate::http::serve_main(args),
        Command::Solve { file, options } => solve_file(&file, options.as_deref()),
    }
}

fn solve_file(file: &std::path::Path, options: Option<&std::path::Path>) -> ExitCode {
    match solve_file_inner(file, options) {
        Ok(solution) => {
            println!(
                "{}",
                serde_json::to_string_pretty(&solution).expect("solution serialises")
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

fn read(path: &std::path::Path) -> Result<Vec<u8>, InputError> {
    std::fs::read(path).map_err(|e| InputError {
        kind: balancing::ErrorKind::Malformed,
        code: "unreadable_file",
        message: format!("cannot read {}: {e}", path.display()),
        field: None,
    })
}

fn solve_file_inner(
    file: &std::path::Path,
    options: Option<&std::path::Path>,
) -> Result<balancing::Solution, InputError> {
    let (session, mut opts) = balancing::parse_session_file(&read(file)?)?;
    if let Some(path) = options {
        opts =
            balancing::from_json::<SolveOptions>(&read(path)?).map_err(|e| e.under("options"))?;
    }
    balancing::solve(&session, &opts)
}
