//! The `runs` and `run_versions` tables: append a run, correct one while keeping
//! its earlier versions, and list those versions.

use serde::Serialize;
use sqlx::{AnyConnection, Row};
use utoipa::ToSchema;

use super::idempotency::Keep;
use super::{never_stored, sessions, Db, Engine, StoreError};
use crate::balancing::model::{Run, Session};
use crate::balancing::InputError;

/// One stored version of a run.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct RunVersion {
    /// 1 for the run as first entered, then 2, 3, … per correction.
    pub version: i64,
    /// UTC, RFC 3339.
    pub created_at: String,
    /// Whether this is the version the session uses now.
    pub current: bool,
    pub run: Run,
}

/// Checks a session with a new or changed run at `index` before it is stored.
pub type Check = fn(&Session, usize) -> Result<(), InputError>;

/// Run `check` on the blocking pool: a session of many readings takes
/// milliseconds to validate, which must not stall an async thread.
async fn check_off_async(
    session: Session,
    index: usize,
    check: Check,
) -> Result<Session, StoreError> {
    tokio::task::spawn_blocking(move || check(&session, index).map(|()| session))
        .await
        .map_err(|e| StoreError::Db(sqlx::Error::Protocol(format!("validation panicked: {e}"))))?
        .map_err(StoreError::Invalid)
}

fn no_run(id: &str, run_id: &str) -> StoreError {
    StoreError::NotFound(format!("session '{id}' has no run with the id '{run_id}'"))
}

/// Insert a run that does not exist yet, as version 1.
pub(crate) async fn insert_new(
    conn: &mut AnyConnection,
    seq: i64,
    position: i64,
    run: &Run,
) -> Result<(), StoreError> {
    sqlx::query("INSERT INTO runs (session_seq, run_id, position, version) VALUES ($1, $2, $3, 1)")
        .bind(seq)
        .bind(&run.id)
        .bind(position)
        .execute(&mut *conn)
        .await?;
    sqlx::query(
        "INSERT INTO run_versions (session_seq, run_id, version, body) VALUES ($1, $2, 1, $3)",
    )
    .bind(seq)
    .bind(&run.id)
    .bind(serde_json::to_string(run)?)
    .execute(&mut *conn)
    .await?;
    Ok(())
}

/// The current version of every run of a session, in the order they were entered.
pub(crate) async fn current(conn: &mut AnyConnection, seq: i64) -> Result<Vec<Run>, StoreError> {
    let rows = sqlx::query(
        "SELECT v.body FROM runs r
         JOIN run_versions v ON v.session_seq = r.session_seq AND v.run_id = r.run_id AND v.version = r.version
         WHERE r.session_seq = $1 ORDER BY r.position",
    )
    .bind(seq)
    .fetch_all(&mut *conn)
    .await?;
    rows.iter()
        .map(|r| Ok(serde_json::from_str(r.get("body"))?))
        .collect()
}

/// Append a run to a stored session after `check` accepts the session with it.
/// Returns the run's index in the session.
/// With `keep`, the answer is kept for its `Idempotency-Key` in the same transaction.
pub async fn append(
    db: &Db,
    id: &str,
    run: &Run,
    check: Check,
    keep: Option<&Keep<'_>>,
) -> Result<usize, StoreError> {
    let mut tx = db.begin_write().await?;
    Keep::guard(keep, &mut tx).await?;
    let (seq, mut session) = sessions::load_for_update(&mut tx, id).await?;
    if session.runs.iter().any(|r| r.id == run.id) {
        return Err(StoreError::Conflict {
            field: "id",
            message: format!(
                "the session already has a run with the id '{}'; PUT it to correct it",
                run.id
            ),
        });
    }
    let index = session.runs.len();
    session.runs.push(run.clone());
    check_off_async(session, index, check).await?;
    let position: i64 =
        sqlx::query("SELECT COALESCE(MAX(position), -1) + 1 FROM runs WHERE session_seq = $1")
            .bind(seq)
            .fetch_one(&mut *tx)
            .await?
            .get(0);
    insert_new(&mut tx, seq, position, run).await?;
    Keep::remember(keep, &mut tx).await?;
    tx.commit().await?;
    Ok(index)
}

/// Replace the current version of a run by a new one, keeping the old; returns the new version number.
/// With `if_match`, only while the run's current version is one of those (else `Stale`).
pub async fn replace(
    db: &Db,
    id: &str,
    run: &Run,
    check: Check,
    if_match: Option<&[i64]>,
) -> Result<i64, StoreError> {
    let mut tx = db.begin_write().await?;
    let (seq, mut session) = sessions::load_for_update(&mut tx, id).await?;
    if never_stored(Engine::of_conn(&tx), &run.id) {
        return Err(no_run(id, &run.id));
    }
    if let Some(wanted) = if_match {
        let current = current_version(&mut tx, seq, &run.id).await?;
        if current.is_some_and(|v| !wanted.contains(&v)) {
            return Err(StoreError::Stale(format!(
                "run '{}' changed meanwhile: its current version is {}; read it again and reapply the correction",
                run.id,
                current.unwrap_or_default()
            )));
        }
    }
    let index = session
        .runs
        .iter()
        .position(|r| r.id == run.id)
        .ok_or_else(|| no_run(id, &run.id))?;
    session.runs[index] = run.clone();
    check_off_async(session, index, check).await?;
    let version: i64 = sqlx::query(
        "UPDATE runs SET version = (SELECT MAX(version) + 1 FROM run_versions WHERE session_seq = $1 AND run_id = $2)
         WHERE session_seq = $1 AND run_id = $2 RETURNING version",
    )
    .bind(seq)
    .bind(&run.id)
    .fetch_one(&mut *tx)
    .await?
    .get(0);
    sqlx::query(
        "INSERT INTO run_versions (session_seq, run_id, version, body) VALUES ($1, $2, $3, $4)",
    )
    .bind(seq)
    .bind(&run.id)
    .bind(version)
    .bind(serde_json::to_string(run)?)
    .execute(&mut *tx)
    .await?;
    tx.commit().await?;
    Ok(version)
}

/// A page of a run's versions, oldest first, and how many there are in all,
/// from one snapshot (as `sessions::list`).
pub async fn versions(
    db: &Db,
    id: &str,
    run_id: &str,
    limit: i64,
    offset: i64,
) -> Result<(Vec<RunVersion>, i64), StoreError> {
    let mut read = db.begin_read().await?;
    let seq = sessions::seq_of(&mut *read, db.engine, id).await?;
    if never_stored(db.engine, run_id) {
        return Err(no_run(id, run_id));
    }
    let rows = sqlx::query(
        "SELECT v.version, v.created_at, v.body, r.version AS current
         FROM run_versions v JOIN runs r ON r.session_seq = v.session_seq AND r.run_id = v.run_id
         WHERE v.session_seq = $1 AND v.run_id = $2 ORDER BY v.version LIMIT $3 OFFSET $4",
    )
    .bind(seq)
    .bind(run_id)
    .bind(limit)
    .bind(offset)
    .fetch_all(&mut *read)
    .await?;
    let total: i64 =
        sqlx::query("SELECT COUNT(*) FROM run_versions WHERE session_seq = $1 AND run_id = $2")
            .bind(seq)
            .bind(run_id)
            .fetch_one(&mut *read)
            .await?
            .get(0);
    read.commit().await?;
    if total == 0 {
        return Err(no_run(id, run_id));
    }
    let page = rows
        .iter()
        .map(|r| {
            Ok(RunVersion {
                version: r.get("version"),
                created_at: r.get("created_at"),
                // Compared here: `sqlx::Any` reads SQLite's 0/1 as a number, not a bool.
                current: r.get::<i64, _>("current") == r.get::<i64, _>("version"),
                run: serde_json::from_str(r.get("body"))?,
            })
        })
        .collect::<Result<_, StoreError>>()?;
    Ok((page, total))
}

/// The current version number of a run, if the session has it.
async fn current_version(
    conn: &mut AnyConnection,
    seq: i64,
    run_id: &str,
) -> Result<Option<i64>, StoreError> {
    Ok(
        sqlx::query("SELECT version FROM runs WHERE session_seq = $1 AND run_id = $2")
            .bind(seq)
            .bind(run_id)
            .fetch_optional(&mut *conn)
            .await?
            .map(|r| r.get(0)),
    )
}

/// The current version of one run and its number.
pub async fn get(db: &Db, id: &str, run_id: &str) -> Result<(Run, i64), StoreError> {
    let mut conn = db.pool.acquire().await?;
    let seq = sessions::seq_of(&mut *conn, db.engine, id).await?;
    if never_stored(db.engine, run_id) {
        return Err(no_run(id, run_id));
    }
    let row = sqlx::query(
        "SELECT v.body, r.version FROM runs r
         JOIN run_versions v ON v.session_seq = r.session_seq AND v.run_id = r.run_id AND v.version = r.version
         WHERE r.session_seq = $1 AND r.run_id = $2",
    )
    .bind(seq)
    .bind(run_id)
    .fetch_optional(&mut *conn)
    .await?
    .ok_or_else(|| no_run(id, run_id))?;
    Ok((serde_json::from_str(row.get("body"))?, row.get("version")))
}
