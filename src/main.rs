use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    fieldbal::cli::run(fieldbal::cli::Cli::parse())
}
