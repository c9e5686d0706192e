//! Storage of sessions, runs (with every corrected version) and solutions in SQLite.
//!
//! One request's writes happen in one `BEGIN IMMEDIATE` transaction, so no
//! request stores half a session. Writers of this process first queue on an
//! async mutex: SQLite allows one writer at a time anyway, and its busy handler
//! waits by sleeping (up to 100 ms a try), which under load gave long tails;
//! the busy timeout remains for writers in other processes.

pub mod health;
pub mod idempotency;
pub mod machines;
pub mod runs;
pub mod sessions;
pub mod solutions;
pub mod watch;

use std::ops::{Deref, DerefMut};
use std::str::FromStr;
use std::sync::Arc;
use std::time::Duration;

use sqlx::pool::PoolConnection;
use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode, SqlitePoolOptions, SqliteSynchronous};
use sqlx::{Sqlite, SqliteConnection, SqlitePool};
use tokio::sync::{Mutex, OwnedMutexGuard};

use crate::balancing::InputError;

pub use runs::RunVersion;
pub use sessions::{SessionList, SessionSummary};
pub use solutions::{StoredSolution, UsedRun};

/// How long a connection waits for another writer before giving up.
const BUSY_TIMEOUT: Duration = Duration::from_secs(10);

/// Open (creating if missing) the database at `url` and apply the embedded migrations.
///
/// `url` is an SQLite URL (`sqlite://fieldbal.db`, `sqlite::memory:`) or a plain file path.
pub async fn connect(url: &str) -> Result<SqlitePool, sqlx::Error> {
    connect_with(options(url)?, 8).await
}

/// The connection settings of the service for the database at `url`.
pub fn options(url: &str) -> Result<SqliteConnectOptions, sqlx::Error> {
    let options = if url.starts_with("sqlite:") {
        SqliteConnectOptions::from_str(url)?
    } else {
        SqliteConnectOptions::new().filename(url)
    };
    Ok(options
        .create_if_missing(true)
        .journal_mode(SqliteJournalMode::Wal)
        // FULL fsyncs the WAL on every commit, so a session answered 201 survives
        // a power cut of the stand PC, not only a crash of the process (NORMAL's
        // guarantee). It costs about a quarter of the store rate, which stays
        // above 1,000 sessions/s (BENCHMARKS.md).
        .synchronous(SqliteSynchronous::Full)
        .busy_timeout(BUSY_TIMEOUT)
        .foreign_keys(true))
}

/// Open a pool of `connections` with `options` and apply the migrations.
pub async fn connect_with(
    options: SqliteConnectOptions,
    connections: u32,
) -> Result<SqlitePool, sqlx::Error> {
    connect_pool(
        SqlitePoolOptions::new().max_connections(connections),
        options,
    )
    .await
}

/// Open a pool with `pool` settings (tests use it to set up each connection)
/// and apply the migrations.
pub async fn connect_pool(
    pool: SqlitePoolOptions,
    options: SqliteConnectOptions,
) -> Result<SqlitePool, sqlx::Error> {
    let pool = pool.connect_with(options).await?;
    sqlx::migrate!().run(&pool).await?;
    Ok(pool)
}

/// The pool and the queue of this process's writers.
#[derive(Debug, Clone)]
pub struct Db {
    pub pool: SqlitePool,
    writer: Arc<Mutex<()>>,
}

impl Db {
    pub fn new(pool: SqlitePool) -> Self {
        Db {
            pool,
            writer: Arc::new(Mutex::new(())),
        }
    }

    /// Wait for this process's turn to write, then start a transaction holding
    /// SQLite's write lock from the first statement.
    pub(crate) async fn begin_write(&self) -> Result<WriteTx, sqlx::Error> {
        let turn = self.writer.clone().lock_owned().await;
        let conn = self.pool.acquire().await?;
        // Held by the `WriteTx` before BEGIN is sent, so that a request cut
        // short meanwhile still rolls back (or closes) the connection.
        let mut tx = WriteTx {
            conn: Some(conn),
            turn: Some(turn),
        };
        sqlx::query("BEGIN IMMEDIATE").execute(&mut *tx).await?;
        Ok(tx)
    }
}

/// A write transaction on a connection of the pool; the next writer's turn
/// comes when it is committed or dropped.
///
/// The transaction is begun and ended by hand rather than with sqlx's
/// `Transaction`: when SQLite rolls a transaction back by itself (a full
/// disk), sqlx's own rollback then fails and its connection stays marked as
/// inside a transaction, so every later write on it failed until restart.
/// Here a connection whose rollback fails is closed instead of returned.
pub(crate) struct WriteTx {
    conn: Option<PoolConnection<Sqlite>>,
    turn: Option<OwnedMutexGuard<()>>,
}

impl WriteTx {
    /// Commit. From here on the write may be stored even if the request is
    /// cut short, so the request's time limit lets it finish (`watch`).
    pub(crate) async fn commit(mut self) -> Result<(), sqlx::Error> {
        watch::committing();
        // The connection stays in `self` until COMMIT is answered: if this
        // future is dropped meanwhile, `drop` still ends the transaction.
        let done = sqlx::query("COMMIT").execute(&mut *self).await;
        let conn = self.conn.take().expect("an open transaction");
        let turn = self.turn.take();
        match done {
            Ok(_) => Ok(()),
            Err(e) => {
                health::storage_failed(&e);
                end_failed(conn, turn).await;
                Err(e)
            }
        }
    }
}

impl WriteTx {
    /// Roll back (closing the connection if that fails).
    pub(crate) async fn rollback(mut self) {
        if let Some(conn) = self.conn.take() {
            end_failed(conn, self.turn.take()).await;
        }
    }
}

/// Roll back a transaction that will not be committed; close the connection
/// if even that fails, so the pool never hands out one left in a transaction.
async fn end_failed(mut conn: PoolConnection<Sqlite>, turn: Option<OwnedMutexGuard<()>>) {
    if let Err(e) = sqlx::query("ROLLBACK").execute(&mut *conn).await {
        tracing::warn!(error = %e, "rollback failed; closing the connection");
        drop(conn.detach());
    }
    drop(turn);
}

impl Drop for WriteTx {
    fn drop(&mut self) {
        let Some(conn) = self.conn.take() else {
            return;
        };
        let turn = self.turn.take();
        // An error or a cancelled request left the transaction open: end it
        // before the next writer's turn. Without a runtime, closing the
        // connection rolls the transaction back.
        match tokio::runtime::Handle::try_current() {
            Ok(rt) => {
                rt.spawn(end_failed(conn, turn));
            }
            Err(_) => drop(conn.detach()),
        }
    }
}

impl Deref for WriteTx {
    type Target = SqliteConnection;
    fn deref(&self) -> &SqliteConnection {
        self.conn.as_ref().expect("an open transaction")
    }
}

impl DerefMut for WriteTx {
    fn deref_mut(&mut self) -> &mut SqliteConnection {
        self.conn.as_mut().expect("an open transaction")
    }
}

/// Why a storage operation did not happen.
#[derive(Debug, thiserror::Error)]
pub enum StoreError {
    /// No such session (or run): the message says which.
    #[error("{0}")]
    NotFound(String),
    /// The id is taken: the message says which.
    #[error("{field}: {message}")]
    Conflict {
        field: &'static str,
        message: String,
    },
    /// The change would make the session invalid; nothing was stored.
    #[error(transparent)]
    Invalid(InputError),
    /// The request's `Idempotency-Key` was used before for another request.
    #[error("the Idempotency-Key was used for another request")]
    KeyReused,
    /// The request's `Idempotency-Key` was used for this same request, whose
    /// answer is this: nothing new was stored.
    #[error("replayed")]
    Replayed(idempotency::Replay),
    /// `If-Match` named a version that is no longer the current one.
    #[error("{0}")]
    Stale(String),
    /// The database cannot be written (full disk, read-only file, I/O error);
    /// nothing was stored.
    #[error("storage: {0}")]
    Storage(sqlx::Error),
    /// The database failed.
    #[error(transparent)]
    Db(sqlx::Error),
    /// A stored JSON column did not parse (only a bug or a hand-edited database does this).
    #[error("stored data unreadable: {0}")]
    Corrupt(#[from] serde_json::Error),
}

impl From<sqlx::Error> for StoreError {
    fn from(e: sqlx::Error) -> Self {
        if health::storage_failed(&e) {
            StoreError::Storage(e)
        } else {
            StoreError::Db(e)
        }
    }
}
