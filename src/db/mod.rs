//! Storage of sessions, runs (with every corrected version) and solutions in SQLite.
//!
//! One request's writes happen in one `BEGIN IMMEDIATE` transaction, so no
//! request stores half a session. Writers of this process first queue on an
//! async mutex: SQLite allows one writer at a time anyway, and its busy handler
//! waits by sleeping (up to 100 ms a try), which under load gave long tails;
//! the busy timeout remains for writers in other processes.

pub mod machines;
pub mod runs;
pub mod sessions;
pub mod solutions;

use std::ops::{Deref, DerefMut};
use std::str::FromStr;
use std::sync::Arc;
use std::time::Duration;

use sqlx::sqlite::{SqliteConnectOptions, SqliteJournalMode, SqlitePoolOptions, SqliteSynchronous};
use sqlx::{Sqlite, SqliteConnection, SqlitePool, Transaction};
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
    let options = if url.starts_with("sqlite:") {
        SqliteConnectOptions::from_str(url)?
    } else {
        SqliteConnectOptions::new().filename(url)
    };
    let options = options
        .create_if_missing(true)
        .journal_mode(SqliteJournalMode::Wal)
        // FULL fsyncs the WAL on every commit, so a session answered 201 survives
        // a power cut of the stand PC, not only a crash of the process (NORMAL's
        // guarantee). It costs about a quarter of the store rate, which stays
        // above 1,000 sessions/s (BENCHMARKS.md).
        .synchronous(SqliteSynchronous::Full)
        .busy_timeout(BUSY_TIMEOUT)
        .foreign_keys(true);
    let pool = SqlitePoolOptions::new()
        .max_connections(8)
        .connect_with(options)
        .await?;
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
        let tx = self.pool.begin_with("BEGIN IMMEDIATE").await?;
        Ok(WriteTx { tx, _turn: turn })
    }
}

/// A write transaction; the next writer's turn comes when it is committed or dropped.
pub(crate) struct WriteTx {
    tx: Transaction<'static, Sqlite>,
    _turn: OwnedMutexGuard<()>,
}

impl WriteTx {
    pub(crate) async fn commit(self) -> Result<(), sqlx::Error> {
        self.tx.commit().await
    }
}

impl Deref for WriteTx {
    type Target = SqliteConnection;
    fn deref(&self) -> &SqliteConnection {
        &self.tx
    }
}

impl DerefMut for WriteTx {
    fn deref_mut(&mut self) -> &mut SqliteConnection {
        &mut self.tx
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
    /// The database failed.
    #[error(transparent)]
    Db(#[from] sqlx::Error),
    /// A stored JSON column did not parse (only a bug or a hand-edited database does this).
    #[error("stored data unreadable: {0}")]
    Corrupt(#[from] serde_json::Error),
}
