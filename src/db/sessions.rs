//! The `sessions` table: create, list, read back and delete whole sessions.

use serde::Serialize;
use sqlx::Row;
use utoipa::ToSchema;

use super::idempotency::Keep;
use super::{engine, never_stored, runs, Db, Engine, ListPage, StoreError};
use crate::balancing::model::Session;

/// One line of the session list.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SessionSummary {
    pub id: String,
    pub name: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub machine: Option<String>,
    /// UTC, RFC 3339.
    pub created_at: String,
    /// Number of runs (each counted once, however often it was corrected).
    pub runs: i64,
}

/// A page of the session list, newest first.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SessionList {
    pub sessions: Vec<SessionSummary>,
    /// Number of sessions stored in all.
    pub total: i64,
    pub limit: i64,
    pub offset: i64,
    /// When more sessions follow: pass it as `before` for the next page, which
    /// then neither repeats nor skips one however many are stored or deleted
    /// meanwhile (an `offset` shifts with them).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub next: Option<String>,
}

/// Store a validated session under `id` with its runs, in one transaction.
/// With `keep`, the answer is kept for its `Idempotency-Key` in the same transaction.
pub async fn create(
    db: &Db,
    id: &str,
    session: &Session,
    keep: Option<&Keep<'_>>,
) -> Result<(), StoreError> {
    let setup = Session {
        runs: Vec::new(),
        ..session.clone()
    };
    let mut tx = db.begin_write().await?;
    Keep::guard(keep, &mut tx).await?;
    let seq: i64 = sqlx::query(
        "INSERT INTO sessions (id, name, machine, setup) VALUES ($1, $2, $3, $4) RETURNING seq",
    )
    .bind(id)
    .bind(&session.name)
    .bind(&session.machine)
    .bind(serde_json::to_string(&setup)?)
    .fetch_one(&mut *tx)
    .await?
    .get(0);
    for (position, run) in session.runs.iter().enumerate() {
        runs::insert_new(&mut tx, seq, position as i64, run).await?;
    }
    Keep::remember(keep, &mut tx).await?;
    tx.commit().await?;
    Ok(())
}

/// A page of sessions, newest first, and how many there are in all, both
/// from one snapshot (two reads apart gave a page its total contradicted
/// when a session was stored or deleted between them).
pub async fn list(db: &Db, page: ListPage) -> Result<SessionList, StoreError> {
    let mut read = db.begin_read().await?;
    // One more than the page: whether a next page exists.
    let mut rows = sqlx::query(
        "SELECT s.seq, s.id, s.name, s.machine, s.created_at,
                (SELECT COUNT(*) FROM runs r WHERE r.session_seq = s.seq) AS runs
         FROM sessions s WHERE s.seq < $1 ORDER BY s.seq DESC LIMIT $2 OFFSET $3",
    )
    .bind(page.before.unwrap_or(i64::MAX))
    .bind(page.limit + 1)
    .bind(page.offset)
    .fetch_all(&mut *read)
    .await?;
    let total: i64 = sqlx::query("SELECT COUNT(*) FROM sessions")
        .fetch_one(&mut *read)
        .await?
        .get(0);
    read.commit().await?;
    let more = rows.len() as i64 > page.limit;
    rows.truncate(page.limit as usize);
    let next = more
        .then(|| rows.last().map(|r| r.get::<i64, _>("seq").to_string()))
        .flatten();
    let sessions = rows
        .into_iter()
        .map(|r| SessionSummary {
            id: r.get("id"),
            name: r.get("name"),
            machine: r.get("machine"),
            created_at: r.get("created_at"),
            runs: r.get("runs"),
        })
        .collect();
    Ok(SessionList {
        sessions,
        total,
        limit: page.limit,
        offset: page.offset,
        next,
    })
}

fn no_session(id: &str) -> StoreError {
    StoreError::NotFound(format!("no session has the id '{id}'"))
}

/// The session's internal key, or `NotFound`.
pub(crate) async fn seq_of<'e, E>(exec: E, engine: Engine, id: &str) -> Result<i64, StoreError>
where
    E: sqlx::Executor<'e, Database = sqlx::Any>,
{
    if never_stored(engine, id) {
        return Err(no_session(id));
    }
    sqlx::query("SELECT seq FROM sessions WHERE id = $1")
        .bind(id)
        .fetch_optional(exec)
        .await?
        .map(|r| r.get(0))
        .ok_or_else(|| no_session(id))
}

/// The session as it would be posted again: its set-up and the current version of each run.
pub async fn get(db: &Db, id: &str) -> Result<Session, StoreError> {
    let mut conn = db.pool.acquire().await?;
    Ok(load(&mut conn, id).await?.1)
}

/// The statement reading a session's set-up.
const SETUP: &str = "SELECT seq, setup FROM sessions WHERE id = $1";

/// Load a session inside a connection or transaction; returns its key too.
pub(crate) async fn load(
    conn: &mut sqlx::AnyConnection,
    id: &str,
) -> Result<(i64, Session), StoreError> {
    load_with(conn, id, SETUP.into()).await
}

/// [`load`] inside a write transaction that changes the session: its row
/// stays locked until the transaction ends, so writers of the same session in
/// other processes (PostgreSQL replicas) take turns.
pub(crate) async fn load_for_update(
    conn: &mut sqlx::AnyConnection,
    id: &str,
) -> Result<(i64, Session), StoreError> {
    let sql = engine::for_update(conn, SETUP);
    load_with(conn, id, sql).await
}

async fn load_with(
    conn: &mut sqlx::AnyConnection,
    id: &str,
    sql: std::borrow::Cow<'static, str>,
) -> Result<(i64, Session), StoreError> {
    if never_stored(Engine::of_conn(conn), id) {
        return Err(no_session(id));
    }
    let row = sqlx::query(&sql)
        .bind(id)
        .fetch_optional(&mut *conn)
        .await?
        .ok_or_else(|| no_session(id))?;
    let seq: i64 = row.get("seq");
    let mut session: Session = serde_json::from_str(row.get("setup"))?;
    session.runs = runs::current(&mut *conn, seq).await?;
    Ok((seq, session))
}

/// Delete a session with its runs and solutions; with `unchanged`, only
/// if it judges the session as stored unchanged (`If-Match`), else
/// `Stale` and nothing is deleted.
pub async fn delete(
    db: &Db,
    id: &str,
    unchanged: Option<impl FnOnce(&Session) -> bool>,
) -> Result<(), StoreError> {
    if never_stored(db.engine, id) {
        return Err(no_session(id));
    }
    let mut tx = db.begin_write().await?;
    // Read (and locked) in the deleting transaction: `unchanged` judges the
    // session as it is deleted, not as it was a moment before.
    if let Some(unchanged) = unchanged {
        let (_, session) = load_for_update(&mut tx, id).await?;
        if !unchanged(&session) {
            return Err(StoreError::Stale(format!(
                "session '{id}' changed since its ETag was read (or If-Match names no ETag of it): nothing was deleted; read it again"
            )));
        }
    }
    let done = sqlx::query("DELETE FROM sessions WHERE id = $1")
        .bind(id)
        .execute(&mut *tx)
        .await?;
    if done.rows_affected() == 0 {
        return Err(no_session(id));
    }
    tx.commit().await?;
    Ok(())
}
