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

use super::Db;

/// Set by a storage fault of any write of this process, cleared by a
/// committed probe. One database per process, so one flag.
static FAULT: AtomicBool = AtomicBool::new(false);

/// SQLite's primary result code of a database error.
fn primary_code(e: &sqlx::Error) -> Option<i64> {
    let code = e.as_database_error()?.code()?;
    code.parse::<i64>().ok().map(|c| c & 0xff)
}

/// SQLITE_FULL: no room for another page (disk full, or `max_page_count`).
pub fn is_full(e: &sqlx::Error) -> bool {
    primary_code(e) == Some(13)
}

/// Whether `e` says the database cannot be written (SQLITE_READONLY, IOERR,
/// FULL, CANTOPEN); if so, remember it until a probe succeeds.
pub fn storage_failed(e: &sqlx::Error) -> bool {
    let storage =
        matches!(primary_code(e), Some(8 | 10 | 13 | 14)) || matches!(e, sqlx::Error::Io(_));
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
        sqlx::query("INSERT INTO health_probe (id, filler) VALUES (1, zeroblob(16384))")
            .execute(&mut *tx)
            .await?;
        sqlx::query("DELETE FROM health_probe")
            .execute(&mut *tx)
            .await
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
