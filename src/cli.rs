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
    #[command(after_help = SERVE_LOGGING)]
    Serve(crate::http::ServeArgs),
    /// Solve a session file offline and print the solution as JSON.
    Solve {
        /// Session JSON (a bare session, or an object with `session` and optional `options`); `-` for standard input.
        file: PathBuf,
        /// A file of solve options JSON (`{"objective": "min_max", …}`),
        /// overriding options inside FILE; `-` for standard input.
        #[arg(long, value_name = "OPTIONS_FILE")]
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
        input: FileArgs,
    },
    /// Pool the runs of several session files into one set of influence
    /// coefficients (each session against its own reference run) and print them as JSON.
    Coefficients {
        /// Session files (as for `solve`), at least one.
        #[arg(required = true)]
        files: Vec<PathBuf>,
        /// A file of pooling options JSON (`exclude_disagreeing`,
        /// `amplitude_noise_pct`, `phase_noise_deg`); `-` for standard input.
        #[arg(long, value_name = "OPTIONS_FILE")]
        options: Option<PathBuf>,
        #[command(flatten)]
        input: InputArgs,
    },
    /// Identify model coefficients from a request file (the endpoint's body) and print the answer as JSON.
    #[command(subcommand)]
    Identify(Identify),
}

/// What `fieldbal serve --help` says of logging, the one setting without a flag.
const SERVE_LOGGING: &str = "Logging: to standard error, a line per request with its x-request-id. \
The variable RUST_LOG sets how much (tracing's filter syntax): `info` (the default), \
`warn` (warnings and errors only, no request lines), `debug` (more detail, e.g. each SQL statement), \
or per module, e.g. RUST_LOG=info,tower_http=debug.";

/// `fieldbal identify WHAT FILE`: only `rotor` reads a session, so only it
/// takes the session limits (`--max-*`).
#[derive(Debug, Subcommand)]
pub enum Identify {
    /// `identify/rotor`: one-mass rotor from a multi-speed session.
    Rotor {
        /// The request JSON, as posted to `/api/v1/identify/rotor`; `-` for standard input.
        file: PathBuf,
        #[command(flatten)]
        input: InputArgs,
    },
    /// `identify/free-decay`: frequency and damping from a free decay.
    FreeDecay {
        /// The request JSON, as posted to `/api/v1/identify/free-decay`; `-` for standard input.
        file: PathBuf,
        #[command(flatten)]
        input: FileArgs,
    },
    /// `identify/model`: discrete-model correction.
    Model {
        /// The request JSON, as posted to `/api/v1/identify/model`; `-` for standard input.
        file: PathBuf,
        #[command(flatten)]
        input: FileArgs,
    },
}

/// What every file command accepts: the service's body limit, with the same
/// flag, variable and default as `fieldbal serve` (README, "Settings").
#[derive(Debug, Clone, clap::Args)]
pub struct FileArgs {
    /// Largest file read, bytes (checked before the file is parsed).
    #[arg(long, env = "FIELDBAL_BODY_LIMIT_BYTES", default_value_t = crate::http::DEFAULT_BODY_LIMIT, value_parser = crate::http::args::positive_usize)]
    pub body_limit_bytes: usize,
}

/// What a file command that reads sessions accepts: the body limit and the
/// service's session size limits, with the same flags, variables and defaults
/// as `fieldbal serve`, so a file the service refuses is refused here too,
/// and a job the service was set up to accept (limits raised) can be run
/// offline.
#[derive(Debug, Clone, clap::Args)]
pub struct InputArgs {
    #[command(flatten)]
    pub file: FileArgs,
    #[command(flatten)]
    pub session: crate::http::SessionLimitArgs,
}

impl InputArgs {
    /// Put the session limits in force for this process and return the file
    /// size limit.
    fn apply(&self) -> usize {
        crate::balancing::limits::Limits::configure(self.session.limits());
        self.file.body_limit_bytes
    }
}

/// Which identification `fieldbal identify` runs.
#[derive(Debug, Clone, Copy)]
enum IdentifyWhat {
    Rotor,
    FreeDecay,
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
            print_result(residual_file(&file, input.body_limit_bytes))
        }
        Command::Coefficients {
            files,
            options,
            input,
        } => {
            let max = input.apply();
            print_result(pool_files(&files, options.as_deref(), max))
        }
        Command::Identify(which) => {
            let (what, file, max) = match which {
                Identify::Rotor { file, input } => (IdentifyWhat::Rotor, file, input.apply()),
                Identify::FreeDecay { file, input } => {
                    (IdentifyWhat::FreeDecay, file, input.body_limit_bytes)
                }
                Identify::Model { file, input } => {
                    (IdentifyWhat::Model, file, input.body_limit_bytes)
                }
            };
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

/// One file named twice in other words (`a.json` and `./a.json`, a link to
/// it) would pool its runs twice: refused as a name given twice is. A path
/// that cannot be resolved is left to the read, which names the fault.
fn same_file_twice(files: &[PathBuf]) -> Result<(), InputError> {
    let mut seen: Vec<(PathBuf, usize)> = Vec::with_capacity(files.len());
    for (i, f) in files.iter().enumerate() {
        if f.as_os_str() == "-" {
            continue;
        }
        let Ok(real) = std::fs::canonicalize(f) else {
            continue;
        };
        if let Some((_, first)) = seen.iter().find(|(p, _)| *p == real) {
            return Err(InputError::invalid(
                "duplicate_id",
                format!("sessions[{i}]"),
                format!(
                    "{} is the file {} already given (sessions[{first}]); its runs would be pooled twice",
                    f.display(),
                    files[*first].display()
                ),
            ));
        }
        seen.push((real, i));
    }
    Ok(())
}

/// Standard input can be read once: `-` as a file and as `--options` is
/// refused before anything is read (the options read an empty input).
fn stdin_once<'a>(
    mut files: impl Iterator<Item = &'a std::path::Path>,
    options: Option<&std::path::Path>,
) -> Result<(), InputError> {
    let dash = |p: &std::path::Path| p.as_os_str() == "-";
    if options.is_some_and(dash) && files.any(dash) {
        return Err(InputError::invalid(
            "invalid_value",
            "options",
            "standard input (`-`) is read once, and it is given for the file too: give the options (or the file) as a file",
        ));
    }
    Ok(())
}

/// `fieldbal coefficients`: the sessions' pooled coefficients (v2 "Machines"),
/// each session named by its file path.
fn pool_files(
    files: &[PathBuf],
    options: Option<&std::path::Path>,
    max: usize,
) -> Result<serde_json::Value, InputError> {
    stdin_once(files.iter().map(PathBuf::as_path), options)?;
    // Each session is validated once, here, and pooled as validated. The
    // files are all read first (the checked sessions borrow them), but an
    // error is reported for the first file that fails, reading or validation,
    // as when each file was read and validated in turn.
    // The service's rule of a pool's list, the files named as given.
    let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
    balancing::job::pool::check_names(&names)?;
    same_file_twice(files)?;
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

#[cfg(test)]
mod tests {
    use clap::{CommandFactory, Parser};

    use super::Cli;

    fn parse(args: &[&str]) -> Result<Cli, String> {
        let mut all = vec!["fieldbal"];
        all.extend_from_slice(args);
        Cli::try_parse_from(all).map_err(|e| e.to_string())
    }

    fn long_help(path: &[&str]) -> String {
        let mut cmd = Cli::command();
        let mut sub = &mut cmd;
        for name in path {
            sub = sub.find_subcommand_mut(name).expect("a subcommand");
        }
        sub.render_long_help().to_string()
    }

    /// An operator who wants more (or less) logging reads `serve --help`:
    /// the log filter is the one setting without a flag.
    /// Where the default database lands and what an address looks like are
    /// in `serve --help`, not only in the README.
    #[test]
    fn serve_help_says_where_the_database_is_and_what_listen_takes() {
        let help = long_help(&["serve"]);
        assert!(help.contains("working directory"), "{help}");
        assert!(help.contains("0.0.0.0:8080"), "{help}");
    }

    /// `--options` takes a file, not the JSON itself: the help said "Solve
    /// options JSON", and `--options '{"objective": "min_max"}'` was then
    /// answered "cannot read {…}: No such file or directory".
    #[test]
    fn the_options_flag_says_it_takes_a_file() {
        for cmd in ["solve", "coefficients"] {
            let help = long_help(&[cmd]);
            assert!(help.contains("--options <OPTIONS_FILE>"), "{help}");
            assert!(help.contains("A file of"), "{help}");
        }
    }

    #[test]
    fn serve_help_says_how_to_set_the_log_level() {
        let help = long_help(&["serve"]);
        assert!(help.contains("RUST_LOG"), "{help}");
        assert!(help.contains("debug"), "{help}");
    }

    /// Each file command takes the limits it applies, and no others: the
    /// residual check reads no session, identify's free decay and model
    /// correction none either; only `identify rotor`, `solve` and
    /// `coefficients` validate sessions against the `--max-*` limits.
    #[test]
    fn each_file_command_takes_only_the_limits_it_applies() {
        let limit = ["--max-planes", "2"];
        let ok = |args: &[&str]| {
            let mut all = args.to_vec();
            all.extend_from_slice(&limit);
            parse(&all).map(|_| ())
        };
        for args in [
            &["solve", "f.json"][..],
            &["coefficients", "a.json", "b.json"],
            &["identify", "rotor", "f.json"],
        ] {
            assert!(ok(args).is_ok(), "{args:?} --max-planes refused");
        }
        for args in [
            &["residual", "f.json"][..],
            &["identify", "free-decay", "f.json"],
            &["identify", "model", "f.json"],
        ] {
            let err = ok(args).expect_err("a limit it does not apply accepted");
            assert!(err.contains("--max-planes"), "{args:?}: {err}");
        }
        for path in [
            &["residual"][..],
            &["identify", "free-decay"],
            &["identify", "model"],
        ] {
            let help = long_help(path);
            assert!(!help.contains("--max-"), "{path:?}: {help}");
            assert!(help.contains("--body-limit-bytes"), "{path:?}: {help}");
        }
        // Every documented invocation still parses.
        for args in [
            &["residual", "-"][..],
            &["identify", "rotor", "-"],
            &["identify", "free-decay", "-"],
            &["identify", "model", "f.json", "--body-limit-bytes", "10"],
            &["coefficients", "a.json", "--options", "o.json"],
            &[
                "solve",
                "big.json",
                "--max-planes",
                "267",
                "--max-sensors",
                "267",
                "--body-limit-bytes",
                "8000000",
            ],
        ] {
            assert!(parse(args).is_ok(), "{args:?}: {:?}", parse(args).err());
        }
    }

    /// A body limit of 0 refuses every file; the file commands refuse it at
    /// once, naming the flag, as `fieldbal serve` does.
    #[test]
    fn a_zero_body_limit_is_refused_naming_the_flag() {
        for args in [
            &["solve", "f.json"][..],
            &["residual", "f.json"],
            &["coefficients", "a.json"],
            &["identify", "free-decay", "f.json"],
        ] {
            let mut all = args.to_vec();
            all.extend_from_slice(&["--body-limit-bytes", "0"]);
            let err = parse(&all).expect_err("0 accepted");
            assert!(
                err.contains("--body-limit-bytes") && err.contains("at least 1"),
                "{args:?}: {err}"
            );
        }
    }
}
