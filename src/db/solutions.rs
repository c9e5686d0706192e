//! The `solutions` table: each solve of a stored session, with its options, the
//! run versions it used and the fieldbal version that computed it.

use serde::{Deserialize, Serialize};
use sqlx::Row;
use utoipa::ToSchema;

use super::idempotency::{self, Idem};
use super::{sessions, Db, StoreError};
use crate::balancing::model::{Session, SolveOptions};
use crate::balancing::Solution;

/// A run and the version of it that a solution used.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
pub struct UsedRun {
    pub run_id: String,
    pub version: i64,
}

/// A stored solution.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct StoredSolution {
    pub id: i64,
    /// UTC, RFC 3339.
    pub created_at: String,
    /// Version of fieldbal that computed it.
    pub fieldbal_version: String,
    pub options: SolveOptions,
    /// The runs (and their versions) the solution was computed from.
    pub runs: Vec<UsedRun>,
    #[schema(value_type = Solution)]
    pub solution: serde_json::Value,
}

/// Which stored session, and which versions of its runs, a solve used.
pub struct Solved {
    seq: i64,
    pub runs: Vec<UsedRun>,
}

/// Read the session and its run versions from one snapshot, so the solution
/// records exactly which versions it used.
pub async fn load_for_solve(db: &Db, id: &str) -> Result<(Session, Solved), StoreError> {
    let mut read = db.begin_read().await?;
    let (seq, session) = sessions::load(&mut read, id).await?;
    let runs: Vec<UsedRun> =
        sqlx::query("SELECT run_id, version FROM runs WHERE session_seq = $1 ORDER BY position")
            .bind(seq)
            .fetch_all(&mut *read)
            .await?
            .iter()
            .map(|r| UsedRun {
                run_id: r.get("run_id"),
                version: r.get("version"),
            })
            .collect();
    read.commit().await?;
    Ok((session, Solved { seq, runs }))
}

/// Store a solution of a session loaded by [`load_for_solve`].
pub async fn store(
    db: &Db,
    id: &str,
    solved: Solved,
    options: &SolveOptions,
    solution: &Solution,
    idem: Option<&Idem>,
) -> Result<StoredSolution, StoreError> {
    let solution = serde_json::to_value(solution)?;
    let fieldbal_version = env!("CARGO_PKG_VERSION").to_string();
    let mut tx = db.begin_write().await?;
    idempotency::guard(&mut tx, idem).await?;
    if super::Engine::of_conn(&tx) == super::Engine::Postgres {
        // Keep another replica from deleting the session between this insert
        // and its foreign-key check (SQLite's writers take turns already).
        let lock = super::engine::for_update(&tx, "SELECT seq FROM sessions WHERE seq = $1");
        sqlx::query(&lock)
            .bind(solved.seq)
            .fetch_optional(&mut *tx)
            .await?;
    }
    // The session may have been deleted meanwhile: then nothing is inserted.
    let row = sqlx::query(
        "INSERT INTO solutions (session_seq, options, run_versions, solution, fieldbal_version)
         SELECT seq, $1, $2, $3, $4 FROM sessions WHERE seq = $5
         RETURNING seq, created_at",
    )
    .bind(serde_json::to_string(options)?)
    .bind(serde_json::to_string(&solved.runs)?)
    .bind(serde_json::to_string(&solution)?)
    .bind(&fieldbal_version)
    .bind(solved.seq)
    .fetch_optional(&mut *tx)
    .await?
    .ok_or_else(|| StoreError::NotFound(format!("no session has the id '{id}'")))?;
    let stored = StoredSolution {
        id: row.get("seq"),
        created_at: row.get("created_at"),
        fieldbal_version,
        options: options.clone(),
        runs: solved.runs,
        solution,
    };
    idempotency::remember(&mut tx, idem, 201, None, &stored).await?;
    tx.commit().await?;
    Ok(stored)
}

/// A page of a session's stored solutions, oldest first, and how many there
/// are in all, from one snapshot (as `sessions::list`).
pub async fn list(
    db: &Db,
    id: &str,
    limit: i64,
    offset: i64,
) -> Result<(Vec<StoredSolution>, i64), StoreError> {
    let mut read = db.begin_read().await?;
    let seq = sessions::seq_of(&mut *read, db.engine, id).await?;
    let rows = sqlx::query(
        "SELECT seq, created_at, fieldbal_version, options, run_versions, solution
         FROM solutions WHERE session_seq = $1 ORDER BY seq LIMIT $2 OFFSET $3",
    )
    .bind(seq)
    .bind(limit)
    .bind(offset)
    .fetch_all(&mut *read)
    .await?;
    let total: i64 = sqlx::query("SELECT COUNT(*) FROM solutions WHERE session_seq = $1")
        .bind(seq)
        .fetch_one(&mut *read)
        .await?
        .get(0);
    read.commit().await?;
    let page = rows
        .iter()
        .map(|r| {
            Ok(StoredSolution {
                id: r.get("seq"),
                created_at: r.get("created_at"),
                fieldbal_version: r.get("fieldbal_version"),
                options: serde_json::from_str(r.get("options"))?,
                runs: serde_json::from_str(r.get("run_versions"))?,
                solution: serde_json::from_str(r.get("solution"))?,
            })
        })
        .collect::<Result<_, StoreError>>()?;
    Ok((page, total))
}
