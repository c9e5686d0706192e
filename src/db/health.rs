//! Whether the database can be written: storage faults (a full disk, a
//! read-only file, I/O errors) are recognised, remembered, and probed for
//! `/healthz` and at start.
//!
//! The probe writes a 16 KiB blob inside a transaction: that allocates
//! pages, which fails on a read-only database or when no page may be added.
//! It is rolled back, so it costs no fsync, except after a storage fault:
//! then it is committed, because a full disk refuses only the commit's write
//! to the WAL, and a committed probe is what shows the space is back.

use std::sync::atomic::{AtomicBool, Ordering};

use super::{Db, Engine};

/// Set by a storage fault of any write of this process, cleared by a
/// committed probe. One database per process, so one flag.
static FAULT: AtomicBool = AtomicBool::new(false);

/// SQLite's primary result code of a database error.
fn primary_code(e: &sqlx::Error) -> Option<i64> {
    let db = e.as_database_error()?;
    db.try_downcast_ref::<sqlx::sqlite::SqliteError>()?;
    db.code()?.parse::<i64>().ok().map(|c| c & 0xff)
}

/// PostgreSQL's SQLSTATE of a database error.
fn sqlstate(e: &sqlx::Error) -> Option<String> {
    let db = e.as_database_error()?;
    Some(
        db.try_downcast_ref::<sqlx::postgres::PgDatabaseError>()?
            .code()
            .to_string(),
    )
}

/// No room for another page: SQLITE_FULL (disk full, or `max_page_count`),
/// PostgreSQL's disk_full (53100).
pub fn is_full(e: &sqlx::Error) -> bool {
    primary_code(e) == Some(13) || sqlstate(e).as_deref() == Some("53100")
}

/// Whether `e` says the database cannot be written (SQLite: READONLY, IOERR,
/// FULL, CANTOPEN; PostgreSQL: insufficient resources (53…), a read-only
/// transaction (a standby, 25006), an I/O error (58030), the server shutting
/// down or the connection lost (57P…, 08…); either: no connection at all);
/// if so, remember it until a probe succeeds.
pub fn storage_failed(e: &sqlx::Error) -> bool {
    let pg = sqlstate(e).is_some_and(|c| {
        c.starts_with("53")
            || c.starts_with("08")
            || c.starts_with("57P")
            || c == "25006"
            || c == "58030"
    });
    let storage = pg
        || matches!(primary_code(e), Some(8 | 10 | 13 | 14))
        || matches!(e, sqlx::Error::Io(_) | sqlx::Error::PoolTimedOut);
    if storage {
        FAULT.store(true, Ordering::Release);
    }
    storage
}

/// Write (and roll back, or after a fault commit) a probe row.
pub async fn probe(db: &Db) -> Result<(), sqlx::Error> {
    let mut tx = db.begin_write().await.inspect_err(|e| {
        storage_failed(e);
    })?;
    let wrote = async {
        // Each PostgreSQL session probes its own row, so replicas' probes never wait on each other.
        let insert = match db.engine {
            Engine::Sqlite => "INSERT INTO health_probe (id, filler) VALUES (1, zeroblob(16384))",
            Engine::Postgres => {
                "INSERT INTO health_probe (id, filler)
                 VALUES (pg_backend_pid(), decode(repeat('00', 16384), 'hex'))"
            }
        };
        sqlx::query(insert).execute(&mut *tx).await?;
        let delete = match db.engine {
            Engine::Sqlite => "DELETE FROM health_probe",
            Engine::Postgres => "DELETE FROM health_probe WHERE id = pg_backend_pid()",
        };
        sqlx::query(delete).execute(&mut *tx).await
    }
    .await;
    if let Err(e) = wrote {
        storage_failed(&e);
        tx.rollback().await;
        return Err(e);
    }
    if FAULT.load(Ordering::Acquire) {
        tx.commit().await?;
        FAULT.store(false, Ordering::Release);
    } else {
        tx.rollback().await;
    }
    Ok(())
}
