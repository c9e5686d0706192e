//! The HTTP service: REST API over SQLite and the embedded web form.

pub mod assets;

use std::process::ExitCode;

/// `fieldbal serve` arguments.
#[derive(Debug, Clone, clap::Args)]
pub struct ServeArgs {
    /// Address to listen on.
    #[arg(long, env = "FIELDBAL_LISTEN", default_value = "127.0.0.1:8080")]
    pub listen: String,
    /// SQLite database URL or file path.
    #[arg(long, env = "DATABASE_URL", default_value = "sqlite://fieldbal.db")]
    pub database: String,
}

/// Run the service until SIGTERM or Ctrl-C.
pub fn serve_main(_args: ServeArgs) -> ExitCode {
    eprintln!("fieldbal serve: not built yet");
    ExitCode::FAILURE
}
