//! Storage of sessions, runs (with every corrected version) and solutions in
//! SQLite or PostgreSQL, through one set of queries (`sqlx::Any`, `$N`
//! placeholders, which sqlx's SQLite driver binds by number too).
//!
//! One request's writes happen in one transaction, so no request stores half
//! a session. On SQLite it is `BEGIN IMMEDIATE`, and writers of this process
//! first queue on an async mutex: SQLite allows one writer at a time anyway,
//! and its busy handler waits by sleeping (up to 100 ms a try), which under
//! load gave long tails; the busy timeout remains for writers in other
//! processes. On PostgreSQL several processes share the database, so nothing
//! process-local can make writes safe: each write transaction locks the rows
//! it builds on (`engine::lock`, `FOR UPDATE`), keys are serialised by
//! advisory locks, and unique constraints back every allocated number.

pub mod engine;
pub mod health;
pub mod idempotency;
pub mod machines;
pub mod runs;
pub mod sessions;
pub mod solutions;
pub mod watch;

use std::ops::{Deref, DerefMut};
use std::sync::Arc;

use sqlx::pool::PoolConnection;
use sqlx::{Any, AnyConnection, AnyPool};
use tokio::sync::{Mutex, OwnedMutexGuard};

use crate::balancing::InputError;

/// Which page of a newest-first list (sessions, machines): `limit` items,
/// skipping `offset`, of those stored before the cursor `before` (the
/// previous page's `next`; all when `None`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ListPage {
    pub limit: i64,
    pub offset: i64,
    pub before: Option<i64>,
}

pub use runs::RunVersion;
pub use sessions::{SessionList, SessionSummary};
pub use solutions::{StoredSolution, UsedRun};

pub use engine::{connect, connect_pool, Engine};

/// Whether no row can have `key` as its id on `engine`: PostgreSQL's text
/// holds no NUL, and a lookup by a key with one fails with an error (a 500)
/// instead of finding nothing. Such keys are answered as not found without
/// asking. SQLite may hold them (stored before the service refused NUL in
/// ids), so there they are looked up as any other.
pub(crate) fn never_stored(engine: Engine, key: &str) -> bool {
    engine == Engine::Postgres && key.contains('\0')
}

/// The pool and the queue of this process's writers.
#[derive(Debug, Clone)]
pub struct Db {
    pub pool: AnyPool,
    pub engine: Engine,
    writer: Arc<Mutex<()>>,
}

impl Db {
    pub fn new(pool: AnyPool) -> Self {
        Db {
            engine: Engine::of_pool(&pool),
            pool,
            writer: Arc::new(Mutex::new(())),
        }
    }

    /// Start a write transaction. On SQLite: wait for this process's turn to
    /// write, then hold SQLite's write lock from the first statement. On
    /// PostgreSQL: a plain (read committed) transaction, whose writes lock
    /// what they build on.
    pub(crate) async fn begin_write(&self) -> Result<WriteTx, sqlx::Error> {
        let turn = match self.engine {
            Engine::Sqlite => Some(self.writer.clone().lock_owned().await),
            Engine::Postgres => None,
        };
        let conn = self.pool.acquire().await?;
        // Held by the `WriteTx` before BEGIN is sent, so that a request cut
        // short meanwhile still rolls back (or closes) the connection.
        let mut tx = WriteTx {
            conn: Some(conn),
            turn,
        };
        let begin = match self.engine {
            Engine::Sqlite => "BEGIN IMMEDIATE",
            Engine::Postgres => "BEGIN",
        };
        sqlx::query(begin).execute(&mut *tx).await?;
        Ok(tx)
    }

    /// A read-only transaction that sees one snapshot throughout (SQLite's
    /// deferred transactions do; PostgreSQL needs repeatable read).
    pub(crate) async fn begin_read(&self) -> Result<sqlx::Transaction<'static, Any>, sqlx::Error> {
        let mut read = self.pool.begin().await?;
        if self.engine == Engine::Postgres {
            sqlx::query("SET TRANSACTION ISOLATION LEVEL REPEATABLE READ, READ ONLY")
                .execute(&mut *read)
                .await?;
        }
        Ok(read)
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
    conn: Option<PoolConnection<Any>>,
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
async fn end_failed(mut conn: PoolConnection<Any>, turn: Option<OwnedMutexGuard<()>>) {
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
    type Target = AnyConnection;
    fn deref(&self) -> &AnyConnection {
        self.conn.as_ref().expect("an open transaction")
    }
}

impl DerefMut for WriteTx {
    fn deref_mut(&mut self) -> &mut AnyConnection {
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

#[cfg(test)]
mod tests {
    use super::*;
    use sqlx::Row;

    async fn machines(conn: &mut AnyConnection) -> i64 {
        sqlx::query("SELECT COUNT(*) FROM machines")
            .fetch_one(conn)
            .await
            .expect("a count")
            .get(0)
    }

    /// What the paged lists rely on (their page and total are read in one
    /// `begin_read`): a write committed on another connection between two
    /// reads of one read transaction is in neither. The race probes of
    /// `tests/api/store/pages.rs` show the lists use it; this shows it holds.
    #[tokio::test]
    async fn a_read_transaction_sees_one_snapshot_while_another_connection_commits() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.db");
        let db = Db::new(connect(path.to_str().unwrap()).await.expect("opens"));
        let mut read = db.begin_read().await.unwrap();
        assert_eq!(machines(&mut read).await, 0);
        let mut write = db.begin_write().await.unwrap();
        sqlx::query("INSERT INTO machines (id, name) VALUES ('M', 'm')")
            .execute(&mut *write)
            .await
            .unwrap();
        write.commit().await.unwrap();
        assert_eq!(machines(&mut read).await, 0, "still the first snapshot");
        read.commit().await.unwrap();
        let mut conn = db.pool.acquire().await.unwrap();
        assert_eq!(machines(&mut conn).await, 1, "committed");
    }
}
