//! Command line: `fieldbal serve` runs the service, `fieldbal solve` solves a file offline,
//! `fieldbal identify` identifies model coefficients offline, `fieldbal coefficients`
//! pools session files into influence coefficients.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::balancing::{self, InputError};

pub mod pretty;
mod solve;

use solve::solve_file;

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
        #[command(flatten)]
        input: InputArgs,
    },
    /// API 617/684 residual-unbalance check of a file (the body of
    /// `POST /api/v1/residual-unbalance`; `-` for standard input).
    Residual {
        /// Request JSON, as posted to the endpoint (`speed_rpm`, `trial`, `journal_load_kg`, `readings`, …); `-` for standard input.
        file: PathBuf,
        #[command(flatten)]
        input: InputArgs,
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
        #[command(flatten)]
        input: InputArgs,
    },
    /// Identify model coefficients from a request file (the endpoint's body) and print the answer as JSON.
    Identify {
        #[arg(value_enum)]
        what: IdentifyWhat,
        /// The request JSON, as posted to `/api/v1/identify/<what>`; `-` for standard input.
        file: PathBuf,
        #[command(flatten)]
        input: InputArgs,
    },
}

/// What a file command accepts: the service's size limits, with the same
/// flags, variables and defaults as `fieldbal serve` (README, "Settings"), so
/// a file the service refuses is refused here too, and a job the service was
/// set up to accept (limits raised) can be run offline.
#[derive(Debug, Clone, clap::Args)]
pub struct InputArgs {
    /// Largest file read, bytes (checked before the file is parsed).
    #[arg(long, env = "FIELDBAL_BODY_LIMIT_BYTES", default_value_t = crate::http::DEFAULT_BODY_LIMIT)]
    pub body_limit_bytes: usize,
    #[command(flatten)]
    pub session: crate::http::SessionLimitArgs,
}

impl InputArgs {
    /// Put the session limits in force for this process and return the file
    /// size limit.
    fn apply(&self) -> usize {
        crate::balancing::limits::Limits::configure(self.session.limits());
        self.body_limit_bytes
    }
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
        Command::Solve {
            file,
            options,
            input,
        } => {
            let max = input.apply();
            solve_file(&file, options.as_deref(), max)
        }
        Command::Residual { file, input } => {
            let max = input.apply();
            print_result(residual_file(&file, max))
        }
        Command::Coefficients {
            files,
            options,
            input,
        } => {
            let max = input.apply();
            print_result(pool_files(&files, options.as_deref(), max))
        }
        Command::Identify { what, file, input } => {
            let max = input.apply();
            print_result(identify_file(what, &file, max))
        }
    }
}

/// `fieldbal identify`: the same JSON as the endpoint.
fn identify_file(
    what: IdentifyWhat,
    file: &std::path::Path,
    max: usize,
) -> Result<serde_json::Value, InputError> {
    use crate::identification as id;
    let bytes = read(file, max)?;
    let value = match what {
        IdentifyWhat::Rotor => {
            let req: id::RotorRequest = balancing::from_json(&bytes)?;
            // The session's texts and machine, as the endpoint refuses them.
            balancing::check_posted_session(&req.session)?;
            serde_json::to_value(id::rotor::identify(&req)?)
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

/// Print an answer (exit 0) or the contract's error body (exit 2), as
/// `fieldbal solve` does: a reader that has closed the pipe (`| head`) has
/// what it wanted, so the command stops quietly (`println!` panicked there).
fn print_result(result: Result<serde_json::Value, InputError>) -> ExitCode {
    let (value, code) = match result {
        Ok(v) => (v, ExitCode::SUCCESS),
        Err(err) => (err.to_json(), ExitCode::from(2)),
    };
    let text = serde_json::to_vec_pretty(&value).expect("answers serialise");
    match print_line(&text) {
        Ok(()) => code,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => code,
        Err(e) => {
            eprintln!("fieldbal: cannot write the answer: {e}");
            ExitCode::FAILURE
        }
    }
}

fn residual_file(file: &std::path::Path, max: usize) -> Result<serde_json::Value, InputError> {
    let req = balancing::acceptance::parse(&read(file, max)?)?;
    let check = balancing::acceptance::check(&req)?;
    Ok(serde_json::to_value(check).expect("check serialises"))
}

/// Write `text` and a newline to standard output; unlike `println!`, a
/// closed pipe is an error to handle, not a panic.
fn print_line(text: &[u8]) -> std::io::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(text)?;
    out.write_all(b"\n")?;
    out.flush()
}

/// The file's bytes, at most `max` of them; `-` reads standard input. A
/// longer file is refused before it is parsed (the service's 413
/// `body_too_large`): parsing costs memory in proportion to its length.
fn read(path: &std::path::Path, max: usize) -> Result<Vec<u8>, InputError> {
    use std::io::Read;
    let unreadable = |e: std::io::Error| InputError {
        kind: balancing::ErrorKind::Malformed,
        code: "unreadable_file",
        message: format!("cannot read {}: {e}", path.display()),
        field: None,
    };
    let mut buf = Vec::new();
    // One byte more than the limit tells "at the limit" from "over it".
    let cap = u64::try_from(max).unwrap_or(u64::MAX).saturating_add(1);
    if path.as_os_str() == "-" {
        std::io::stdin().take(cap).read_to_end(&mut buf)
    } else {
        std::fs::File::open(path).and_then(|f| f.take(cap).read_to_end(&mut buf))
    }
    .map_err(unreadable)?;
    if buf.len() > max {
        return Err(InputError {
            kind: balancing::ErrorKind::Malformed,
            code: "body_too_large",
            message: format!(
                "{} is larger than the limit of {max} bytes (raise it with --body-limit-bytes or FIELDBAL_BODY_LIMIT_BYTES)",
                path.display()
            ),
            field: None,
        });
    }
    Ok(buf)
}

/// `fieldbal coefficients`: the sessions' pooled coefficients (v2 "Machines"),
/// each session named by its file path.
fn pool_files(
    files: &[PathBuf],
    options: Option<&std::path::Path>,
    max: usize,
) -> Result<serde_json::Value, InputError> {
    // Each session is validated once, here, and pooled as validated. The
    // files are all read first (the checked sessions borrow them), but an
    // error is reported for the first file that fails, reading or validation,
    // as when each file was read and validated in turn.
    // The service's rule of a pool's list, the files named as given.
    let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
    balancing::job::pool::check_names(&names)?;
    let under = |i: usize| move |e: InputError| e.under(&format!("sessions[{i}]"));
    let mut parsed = Vec::with_capacity(files.len());
    let mut unreadable = None;
    for (i, f) in files.iter().enumerate() {
        match read(f, max).and_then(|bytes| balancing::file::parse(&bytes).map_err(under(i))) {
            Ok(file) => parsed.push(file),
            Err(e) => {
                unreadable = Some(e);
                break;
            }
        }
    }
    let mut checked = Vec::with_capacity(parsed.len());
    for (i, file) in parsed.iter().enumerate() {
        checked.push(balancing::check_file(file).map_err(under(i))?);
    }
    if let Some(e) = unreadable {
        return Err(e);
    }
    let opts = match options {
        Some(path) => balancing::from_json(&read(path, max)?).map_err(|e| e.under("options"))?,
        None => balancing::job::pool::PoolOptions::default(),
    };
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    let pooled = balancing::job::pool::pool_checked(&names, &checked, &opts)?;
    Ok(serde_json::to_value(pooled).expect("coefficients serialise"))
}
