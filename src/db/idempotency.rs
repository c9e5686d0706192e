//! `Idempotency-Key` (contract v2): the answer to a POST that stored
//! something is kept with its key, in the same transaction as what it stored,
//! so a retry with the same key and body gets that answer again and stores
//! nothing new, even after a crash between the commit and the answer.
//!
//! A key is bound to the request's method, path and parsed body (their
//! SHA-256, the fingerprint); the same key with anything else is refused.

use serde::Serialize;
use sha2::{Digest, Sha256};
use sqlx::{AnyConnection, Row};

use super::StoreError;

/// The longest key accepted (a UUID is 36).
pub const MAX_KEY_LEN: usize = 255;

/// A request's key and fingerprint.
#[derive(Debug, Clone)]
pub struct Idem {
    key: String,
    fingerprint: String,
}

impl Idem {
    /// The key of `method path` with the parsed `body`.
    pub fn new(key: &str, method: &str, path: &str, body: &impl Serialize) -> Idem {
        let mut hash = Sha256::new();
        hash.update(method.as_bytes());
        hash.update(b" ");
        hash.update(path.as_bytes());
        hash.update(b"\n");
        hash.update(serde_json::to_vec(body).unwrap_or_default());
        let fingerprint = hash.finalize().iter().map(|b| format!("{b:02x}")).collect();
        Idem {
            key: key.to_string(),
            fingerprint,
        }
    }
}

/// An answer kept for a key: `body` is the JSON text first answered, kept
/// as text so a retry gets the same document byte for byte (parsed into a
/// `serde_json::Value` its keys came back sorted).
#[derive(Debug, Clone)]
pub struct Replay {
    pub status: u16,
    pub location: Option<String>,
    pub body: String,
}

/// The answer kept for `idem`'s key, if any; `KeyReused` if the key was
/// used for another request.
pub(crate) async fn find(
    conn: &mut AnyConnection,
    idem: &Idem,
) -> Result<Option<Replay>, StoreError> {
    let Some(row) =
        sqlx::query("SELECT fingerprint, status, location, body FROM idempotency WHERE key = $1")
            .bind(&idem.key)
            .fetch_optional(&mut *conn)
            .await?
    else {
        return Ok(None);
    };
    if row.get::<String, _>("fingerprint") != idem.fingerprint {
        return Err(StoreError::KeyReused);
    }
    Ok(Some(Replay {
        status: row.get::<i64, _>("status") as u16,
        location: row.get("location"),
        body: row.get("body"),
    }))
}

/// Look the key up outside a transaction (before doing the work).
pub async fn lookup(db: &super::Db, idem: Option<&Idem>) -> Result<Option<Replay>, StoreError> {
    match idem {
        Some(idem) => find(&mut *db.pool.acquire().await?, idem).await,
        None => Ok(None),
    }
}

/// Inside the write transaction, before writing: stop with `Replayed` if
/// another request with this key got there first.
pub(crate) async fn guard(conn: &mut AnyConnection, idem: Option<&Idem>) -> Result<(), StoreError> {
    if let Some(idem) = idem {
        super::engine::lock_key(conn, &idem.key).await?;
        if let Some(r) = find(conn, idem).await? {
            return Err(StoreError::Replayed(r));
        }
    }
    Ok(())
}

/// An answer known before the write (a new session's id, a run's version 1), to keep with its key.
#[derive(Debug, Clone)]
pub struct Keep<'a> {
    pub idem: &'a Idem,
    pub status: u16,
    pub location: Option<String>,
    /// The answer's JSON text, as it is answered.
    pub body: String,
}

impl Keep<'_> {
    /// Guard and remember in one step, for writes whose answer is known beforehand.
    pub(crate) async fn guard(
        keep: Option<&Self>,
        conn: &mut AnyConnection,
    ) -> Result<(), StoreError> {
        guard(conn, keep.map(|k| k.idem)).await
    }

    pub(crate) async fn remember(
        keep: Option<&Self>,
        conn: &mut AnyConnection,
    ) -> Result<(), StoreError> {
        match keep {
            Some(k) => remember_text(conn, k.idem, k.status, k.location.as_deref(), &k.body).await,
            None => Ok(()),
        }
    }
}

/// Keep the answer for `idem` inside the write transaction that stored it.
pub(crate) async fn remember(
    conn: &mut AnyConnection,
    idem: Option<&Idem>,
    status: u16,
    location: Option<&str>,
    body: &impl Serialize,
) -> Result<(), StoreError> {
    match idem {
        Some(idem) => {
            remember_text(conn, idem, status, location, &serde_json::to_string(body)?).await
        }
        None => Ok(()),
    }
}

/// [`remember`] with the answer's JSON text.
async fn remember_text(
    conn: &mut AnyConnection,
    idem: &Idem,
    status: u16,
    location: Option<&str>,
    body: &str,
) -> Result<(), StoreError> {
    sqlx::query(
        "INSERT INTO idempotency (key, fingerprint, status, location, body) VALUES ($1, $2, $3, $4, $5)",
    )
    .bind(&idem.key)
    .bind(&idem.fingerprint)
    .bind(i64::from(status))
    .bind(location)
    .bind(body)
    .execute(&mut *conn)
    .await?;
    Ok(())
}
