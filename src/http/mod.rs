//! The HTTP service: REST API over SQLite and the embedded web form.
//!
//! Tests and `fieldbal serve` start it the same way: [`connect_db`], then
//! [`serve`] on a bound listener with a shutdown future.

pub mod args;
pub mod assets;
pub mod compute;
pub mod edge;
pub mod error;
pub mod extract;
pub mod headers;
pub mod openapi;
pub mod responses;
pub mod store;
#[cfg(test)]
mod time_limit_tests;
pub mod work;

// Paths from before the grouping stay valid for callers and tests.
pub use compute::{identify, residual, solve, trial_weights};
pub use store::{machines, runs, sessions};

use std::future::Future;
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Duration;

use axum::extract::{DefaultBodyLimit, State};
use axum::http::{Request, StatusCode};
use axum::routing::{get, post, put};
use axum::{Json, Router};
use sqlx::AnyPool;
use tower_http::catch_panic::CatchPanicLayer;
use tower_http::request_id::{MakeRequestUuid, PropagateRequestIdLayer, SetRequestIdLayer};
use tower_http::trace::{DefaultOnResponse, TraceLayer};
use tracing::Level;

use crate::balancing::limits::Limits;
use error::ApiError;

/// Default request body limit: 4 MiB.
pub const DEFAULT_BODY_LIMIT: usize = 4 * 1024 * 1024;
/// Default time a request may take, body included, seconds.
pub const DEFAULT_REQUEST_TIMEOUT_SECS: u64 = 30;

/// `fieldbal serve` arguments.
#[derive(Debug, Clone, clap::Args)]
pub struct ServeArgs {
    /// Address to listen on, HOST:PORT (0.0.0.0:8080 for every interface).
    #[arg(long, env = "FIELDBAL_LISTEN", default_value = "127.0.0.1:8080")]
    pub listen: String,
    /// Database: `postgres://user:password@host/db` (PostgreSQL, for several
    /// replicas), or an SQLite URL (`sqlite://fieldbal.db`, `sqlite:///var/lib/fieldbal/fieldbal.db`)
    /// or file path; a relative one is in the working directory (the start log names the file).
    #[arg(long, env = "DATABASE_URL", default_value = "sqlite://fieldbal.db")]
    pub database: String,
    /// Largest accepted request body, bytes.
    #[arg(long, env = "FIELDBAL_BODY_LIMIT_BYTES", default_value_t = DEFAULT_BODY_LIMIT, value_parser = args::positive_usize)]
    pub body_limit_bytes: usize,
    /// Longest time a request may take, body included, seconds (then 408).
    #[arg(long, env = "FIELDBAL_REQUEST_TIMEOUT_SECS", default_value_t = DEFAULT_REQUEST_TIMEOUT_SECS, value_parser = args::positive_u64)]
    pub request_timeout_secs: u64,
    #[command(flatten)]
    pub edge: edge::EdgeArgs,
    /// Size limits of a session (422 `too_large` beyond them) and solve slots.
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// `fieldbal serve` size limits and solve concurrency (README, "Settings").
#[derive(Debug, Clone, clap::Args)]
pub struct LimitArgs {
    #[command(flatten)]
    pub session: SessionLimitArgs,
    /// Solves that run at once (default: the number of CPUs).
    #[arg(long, env = "FIELDBAL_SOLVE_SLOTS", value_parser = args::positive_usize)]
    pub solve_slots: Option<usize>,
    /// How long a solve waits for a free slot before 503 with Retry-After, ms.
    #[arg(long, env = "FIELDBAL_SOLVE_QUEUE_MS", default_value_t = work::DEFAULT_SOLVE_QUEUE_MS)]
    pub solve_queue_ms: u64,
}

/// The size limits of one session (422 `too_large` beyond them), read by
/// `fieldbal serve` and by the commands that read a session file, so a job
/// the service was set up to accept can be run offline too.
#[derive(Debug, Clone, clap::Args)]
pub struct SessionLimitArgs {
    /// Most correction planes in a session.
    #[arg(long, env = "FIELDBAL_MAX_PLANES", default_value_t = Limits::DEFAULT.planes, value_parser = args::positive_usize)]
    pub max_planes: usize,
    /// Most sensors in a session.
    #[arg(long, env = "FIELDBAL_MAX_SENSORS", default_value_t = Limits::DEFAULT.sensors, value_parser = args::positive_usize)]
    pub max_sensors: usize,
    /// Most speed points (speeds more than 1 % apart) in a session's reference run.
    #[arg(long, env = "FIELDBAL_MAX_SPEED_POINTS", default_value_t = Limits::DEFAULT.speed_points, value_parser = args::positive_usize)]
    pub max_speed_points: usize,
    /// Most runs in a session.
    #[arg(long, env = "FIELDBAL_MAX_RUNS", default_value_t = Limits::DEFAULT.runs, value_parser = args::positive_usize)]
    pub max_runs: usize,
    /// Most readings over all runs of a session.
    #[arg(long, env = "FIELDBAL_MAX_READINGS", default_value_t = Limits::DEFAULT.readings, value_parser = args::positive_usize)]
    pub max_readings: usize,
}

impl SessionLimitArgs {
    /// The limits these arguments set (the others keep their defaults).
    pub fn limits(&self) -> Limits {
        Limits {
            planes: self.max_planes,
            sensors: self.max_sensors,
            speed_points: self.max_speed_points,
            runs: self.max_runs,
            readings: self.max_readings,
            ..Limits::DEFAULT
        }
    }
}

/// Settings the handlers need.
#[derive(Debug, Clone)]
pub struct Config {
    pub body_limit_bytes: usize,
    pub request_timeout: Duration,
}

/// Shared state of the handlers.
#[derive(Debug, Clone)]
pub struct AppState {
    pub pool: AnyPool,
    pub config: Arc<Config>,
    /// The pool with this process's queue of writers (see `db`).
    pub(crate) db: crate::db::Db,
    /// Tokens, allowed hosts, connection limits (see `edge`).
    pub edge: Arc<edge::EdgeConfig>,
    /// Bounded concurrency of solves (see `work`).
    pub solves: work::Slots,
}

impl AppState {
    /// State with the default settings.
    pub fn new(pool: AnyPool) -> Self {
        AppState {
            db: crate::db::Db::new(pool.clone()),
            solves: work::Slots::new(
                work::default_solve_slots(),
                Duration::from_millis(work::DEFAULT_SOLVE_QUEUE_MS),
            ),
            pool,
            config: Arc::new(Config {
                body_limit_bytes: DEFAULT_BODY_LIMIT,
                request_timeout: Duration::from_secs(DEFAULT_REQUEST_TIMEOUT_SECS),
            }),
            edge: Arc::new(edge::EdgeConfig::default()),
        }
    }

    /// The same state with other edge settings (tokens, hosts, connections).
    pub fn with_edge(mut self, edge: edge::EdgeConfig) -> Self {
        self.edge = Arc::new(edge);
        self
    }

    /// The same state with another body limit.
    pub fn with_body_limit(mut self, bytes: usize) -> Self {
        Arc::make_mut(&mut self.config).body_limit_bytes = bytes;
        self
    }

    /// The same state with `count` solve slots, each waited for at most `wait`.
    pub fn with_solve_slots(mut self, count: usize, wait: Duration) -> Self {
        self.solves = work::Slots::new(count, wait);
        self
    }

    /// The same state with another request time limit.
    pub fn with_request_timeout(mut self, timeout: Duration) -> Self {
        Arc::make_mut(&mut self.config).request_timeout = timeout;
        self
    }
}

/// Open (creating and migrating) the database at `url`: `postgres://…`, or
/// SQLite's (URL or file path).
pub async fn connect_db(url: &str) -> Result<AnyPool, sqlx::Error> {
    crate::db::connect(url).await
}

/// The whole service: API, OpenAPI document, web form, JSON 404/405, request ids and logs.
pub fn app(state: AppState) -> Router {
    let limit = state.config.body_limit_bytes;
    let timeout = state.config.request_timeout;
    let guard = edge::Guard {
        edge: state.edge.clone(),
        body_limit: limit,
    };
    let api = Router::new()
        .route("/healthz", get(healthz))
        .route("/api/v1/openapi.json", get(openapi::document))
        .route("/api/v1/solve", post(solve::solve))
        .route("/api/v1/residual-unbalance", post(residual::check))
        .route("/api/v1/identify/rotor", post(identify::rotor))
        .route("/api/v1/identify/free-decay", post(identify::free_decay))
        .route("/api/v1/identify/model", post(identify::model))
        .route("/api/v1/trial-weights", post(trial_weights::trial_weights))
        .route(
            "/api/v1/sessions",
            post(sessions::create).get(sessions::list),
        )
        .route(
            "/api/v1/sessions/{id}",
            get(sessions::get).delete(sessions::delete),
        )
        .route("/api/v1/sessions/{id}/runs", post(runs::append))
        .route(
            "/api/v1/sessions/{id}/runs/{run_id}",
            put(runs::replace).get(runs::get),
        )
        .route(
            "/api/v1/sessions/{id}/runs/{run_id}/versions",
            get(runs::versions),
        )
        .route(
            "/api/v1/sessions/{id}/solutions",
            post(solve::create_solution).get(solve::list_solutions),
        )
        .route(
            "/api/v1/machines",
            post(machines::create).get(machines::list),
        )
        .route(
            "/api/v1/machines/{id}",
            get(machines::get).delete(machines::delete),
        )
        .route(
            "/api/v1/machines/{id}/coefficients",
            post(machines::pool_coefficients).get(machines::get_coefficients),
        )
        .route_layer(axum::middleware::from_fn(no_query_on_writes))
        .with_state(state);
    Router::new()
        .merge(api)
        .merge(assets::router())
        .fallback(not_found)
        .method_not_allowed_fallback(method_not_allowed)
        .layer(DefaultBodyLimit::max(limit))
        .layer(axum::middleware::from_fn_with_state(timeout, time_limit))
        .layer(CatchPanicLayer::custom(|panic: Box<dyn std::any::Any + Send>| {
            let what = panic
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            let cause = format!("handler panicked: {what}");
            axum::response::IntoResponse::into_response(ApiError::internal(&cause))
        }))
        .layer(axum::middleware::from_fn_with_state(guard, edge::guard))
        .layer(PropagateRequestIdLayer::x_request_id())
        .layer(
            TraceLayer::new_for_http()
                .make_span_with(|req: &Request<_>| {
                    let id = req
                        .headers()
                        .get("x-request-id")
                        .and_then(|v| v.to_str().ok())
                        .unwrap_or("-");
                    tracing::info_span!("request", request_id = %id, method = %req.method(), uri = %req.uri())
                })
                .on_response(DefaultOnResponse::new().level(Level::INFO)),
        )
        .layer(SetRequestIdLayer::x_request_id(MakeRequestUuid))
}

/// Serve `app(state)` on `listener` until `shutdown` completes, then finish the
/// requests in flight (within the edge's grace period).
pub async fn serve(
    listener: tokio::net::TcpListener,
    state: AppState,
    shutdown: impl Future<Output = ()> + Send + 'static,
) -> std::io::Result<()> {
    let limits = state.edge.connections.clone();
    edge::connections::serve(listener, app(state), limits, shutdown).await
}

#[utoipa::path(get, path = "/healthz", tag = "service",
    operation_id = "healthz", summary = "Readiness: whether the database can be written",
    responses((status = 200, description = "Ready: the database can be written"),
              (status = 503, description = "Not ready: the database cannot be written (`not_ready`: read-only, full disk)", body = error::ErrorBody)))]
async fn healthz(State(state): State<AppState>) -> Result<Json<serde_json::Value>, ApiError> {
    crate::db::health::probe(&state.db).await.map_err(|e| {
        tracing::error!(error = %e, "health probe: the database cannot be written");
        ApiError::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "not_ready",
            "the database cannot be written (read-only, or the disk is full)",
        )
    })?;
    Ok(Json(serde_json::json!({ "status": "ok" })))
}

/// Answer 408 with the contract's body when a request (a slow body, say) takes
/// longer than the limit, so a stalled client holds no connection or shutdown
/// forever. A request cut short before any commit began stored nothing (its
/// transaction is rolled back); one whose commit has begun is left to finish
/// and answers its real result, so a 408 never hides a stored write.
async fn time_limit(
    State(limit): State<Duration>,
    req: axum::extract::Request,
    next: axum::middleware::Next,
) -> axum::response::Response {
    let watch = Arc::new(crate::db::watch::WriteWatch::default());
    let request = crate::db::watch::watched(watch.clone(), next.run(req));
    tokio::pin!(request);
    tokio::select! {
        response = &mut request => response,
        () = tokio::time::sleep(limit) => {
            if watch.committing() {
                return request.await;
            }
            axum::response::IntoResponse::into_response(ApiError::new(
                StatusCode::REQUEST_TIMEOUT,
                "request_timeout",
                format!(
                    "the request took longer than {} s; nothing was stored",
                    limit.as_secs_f64()
                ),
            ))
        }
    }
}

async fn not_found() -> ApiError {
    ApiError::not_found("no such resource")
}

/// No write of the API (POST, PUT, DELETE) takes a query parameter: one is
/// refused with 400 `invalid_query` naming it, before anything is done, as a
/// GET refuses one it does not take (`headers::NoParams`). Ignored, `POST
/// /api/v1/solve?discrete=true` answered a solve without the fit it asked for.
async fn no_query_on_writes(
    req: axum::extract::Request,
    next: axum::middleware::Next,
) -> axum::response::Response {
    use axum::response::IntoResponse;
    let read = matches!(
        *req.method(),
        axum::http::Method::GET | axum::http::Method::HEAD
    );
    if !read {
        if let Err(e) = headers::NoParams::check(axum::extract::Query::try_from_uri(req.uri())) {
            return e.into_response();
        }
    }
    next.run(req).await
}

async fn method_not_allowed() -> ApiError {
    ApiError::new(
        StatusCode::METHOD_NOT_ALLOWED,
        "method_not_allowed",
        "this resource does not accept that method",
    )
}

/// Resolves on Ctrl-C or SIGTERM.
async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! {
        () = ctrl_c => {},
        () = term => {},
    }
    tracing::info!("shutdown signal received; finishing requests in flight");
}

/// Run the service until SIGTERM or Ctrl-C.
pub fn serve_main(args: ServeArgs) -> ExitCode {
    // Logs go to standard error (journald and container runtimes collect it),
    // coloured only on a terminal.
    let (filter, unparsed) = match tracing_subscriber::EnvFilter::try_from_default_env() {
        Ok(filter) => (filter, None),
        // Unset: the default. Set but not a filter: the default, said once
        // the logger is up (`fieldbal=verbose` fell back silently).
        Err(e) => (
            "info".into(),
            std::env::var("RUST_LOG").ok().map(|v| (v, e.to_string())),
        ),
    };
    tracing_subscriber::fmt()
        .with_writer(std::io::stderr)
        .with_ansi(std::io::IsTerminal::is_terminal(&std::io::stderr()))
        .with_env_filter(filter)
        .init();
    if let Some((value, e)) = unparsed {
        tracing::warn!("RUST_LOG={value:?} is not a log filter ({e}); logging at info (e.g. RUST_LOG=debug or RUST_LOG=info,fieldbal=debug)");
    }
    let runtime = match tokio::runtime::Runtime::new() {
        Ok(rt) => rt,
        Err(e) => {
            eprintln!("fieldbal serve: cannot start the runtime: {e}");
            return ExitCode::FAILURE;
        }
    };
    match runtime.block_on(run(args)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            tracing::error!("fieldbal serve: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The start-up error for a database that cannot be opened or written.
fn cannot_write(database: &str, e: &sqlx::Error) -> String {
    let file = crate::db::engine::sqlite_file(database);
    // SQLite creates the file, never its directory.
    let missing = file
        .as_deref()
        .and_then(std::path::Path::parent)
        .filter(|dir| !dir.as_os_str().is_empty() && !dir.exists())
        .map(|dir| format!(" (the directory {} does not exist)", dir.display()))
        .unwrap_or_default();
    let database = match file {
        Some(file) if file.as_os_str() != database => format!("{database} ({})", file.display()),
        _ => crate::db::engine::redacted(database),
    };
    let text = format!("{e}{missing}");
    if text.contains("readonly") || text.contains("read-only") {
        format!("database {database} is read-only ({text}): fieldbal needs to write the file and its directory (for the -wal and -shm files); fix the permissions or the mount, or point --database elsewhere")
    } else {
        format!("database {database} cannot be opened and written: {text}")
    }
}

async fn run(args: ServeArgs) -> Result<(), String> {
    let edge = edge::EdgeConfig::from_args(&args.edge)?;
    if edge.tokens.is_empty() {
        tracing::warn!("no bearer tokens configured: anyone who reaches the port may read and change the store");
    } else {
        tracing::info!(
            tokens = edge.tokens.len(),
            "bearer tokens required on /api/"
        );
    }
    // The address first: a start that cannot listen creates no database.
    let listener = tokio::net::TcpListener::bind(&args.listen)
        .await
        .map_err(|e| {
            format!(
                "cannot listen on {} ({e}): --listen (FIELDBAL_LISTEN) takes HOST:PORT, e.g. 127.0.0.1:8080, or 0.0.0.0:8080 for every interface",
                args.listen
            )
        })?;
    let pool = connect_db(&args.database)
        .await
        .map_err(|e| cannot_write(&args.database, &e))?;
    // Refuse to start on a database that cannot be written, rather than
    // answer every write with an error.
    crate::db::health::probe(&crate::db::Db::new(pool.clone()))
        .await
        .map_err(|e| cannot_write(&args.database, &e))?;
    let addr = listener.local_addr().map_err(|e| e.to_string())?;
    match crate::db::engine::sqlite_file(&args.database) {
        Some(file) => {
            tracing::info!(%addr, database = %args.database, file = %file.display(), "fieldbal serve listening")
        }
        None => {
            tracing::info!(%addr, database = %crate::db::engine::redacted(&args.database), "fieldbal serve listening")
        }
    }
    let l = &args.limits;
    Limits::configure(l.session.limits());
    let state = AppState::new(pool.clone())
        .with_solve_slots(
            l.solve_slots.unwrap_or_else(work::default_solve_slots),
            Duration::from_millis(l.solve_queue_ms),
        )
        .with_body_limit(args.body_limit_bytes)
        .with_request_timeout(Duration::from_secs(args.request_timeout_secs))
        .with_edge(edge);
    serve(listener, state, shutdown_signal())
        .await
        .map_err(|e| e.to_string())?;
    pool.close().await;
    tracing::info!("stopped");
    Ok(())
}

#[cfg(test)]
mod start_tests {
    use super::cannot_write;

    fn fault() -> sqlx::Error {
        sqlx::Error::Configuration("unable to open database file".into())
    }

    /// An SQLite file in a directory that does not exist: the start error
    /// says which directory, not only SQLite's "unable to open database file";
    /// a file path given as it is is named once.
    #[test]
    fn a_missing_directory_is_named_at_start() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("no such dir");
        let file = missing.join("f.db");
        let e = cannot_write(file.to_str().unwrap(), &fault());
        assert!(
            e.contains(&format!(
                "the directory {} does not exist",
                missing.display()
            )),
            "{e}"
        );
        assert_eq!(e.matches(file.to_str().unwrap()).count(), 1, "{e}");
        // Its directory exists: nothing said of it.
        let e = cannot_write(dir.path().join("f.db").to_str().unwrap(), &fault());
        assert!(!e.contains("does not exist"), "{e}");
    }

    #[test]
    fn a_password_in_a_refused_url_is_not_shown() {
        let e = cannot_write("mysql://u:secret@h/db", &fault());
        assert!(!e.contains("secret"), "{e}");
    }
}
