//! The `machines` and `machine_coefficients` tables (v2 "Machines"): a
//! machine, its sessions (those whose `machine` is its id) with the summary of
//! each one's latest solution, and its coefficient versions. A version is
//! allocated inside the inserting transaction (one more than the machine's
//! largest) while the machine's row is locked, and `UNIQUE (machine_seq,
//! version)` keeps two from colliding. Numbers are never reused under one
//! machine id: deleting a machine keeps its last version number
//! (`machine_versions_retired`), and a machine created again under that id
//! numbers on from there.

use serde::{Deserialize, Serialize};
use sqlx::Row;
use utoipa::ToSchema;

use super::idempotency::{self, Idem};
use super::{engine, never_stored, sessions, Db, ListPage, StoreError};
use crate::balancing::model::{Rotor, Session, Unit};

/// A machine as posted.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, ToSchema)]
#[serde(remote = "Self")]
#[serde(deny_unknown_fields)]
pub struct NewMachine {
    /// 1 to 64 characters, none a control character; compared exactly (case
    /// and Unicode form matter). Never reused for other coefficients: a
    /// machine created again under a deleted one's id numbers its
    /// coefficient versions on from that one's.
    pub id: String,
    /// Optional: a machine may be known by its id alone. 1 to 200
    /// characters, not blank; no control character but tab and line breaks.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rotor: Option<Rotor>,
    /// At most 10,000 characters; no control character but tab and line breaks.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub notes: Option<String>,
}

// Objects only: a positional array is refused (see `balancing::wire`).
crate::balancing::wire::objects_only!(NewMachine);

/// A stored machine.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct Machine {
    pub id: String,
    /// Absent for a machine stored without a name.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotor: Option<Rotor>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub notes: Option<String>,
    /// UTC, RFC 3339.
    pub created_at: String,
}

/// A page of machines, newest first.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MachineList {
    pub machines: Vec<Machine>,
    pub total: i64,
    pub limit: i64,
    pub offset: i64,
    /// When more machines follow: `before` for the next page (see `SessionList`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub next: Option<String>,
}

/// One of a machine's sessions, with the before/after summary of its latest solution.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MachineSession {
    pub id: String,
    pub name: String,
    pub created_at: String,
    pub runs: i64,
    /// `summary` of the latest stored solution (rms and max before and after), if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<crate::balancing::solution::Summary>)]
    pub summary: Option<serde_json::Value>,
    /// When that solution was computed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub solved_at: Option<String>,
    /// With `summary`: the unit its figures are in, the one unit of the rows
    /// it covers (the rows the solve used); `null` when they are in more than
    /// one (then `units` names them). Beside the summary rather than in it:
    /// the summary stays the solution's own.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(value_type = Option<Unit>, nullable)]
    pub unit: Option<Option<Unit>>,
    /// With `summary`: every unit of the rows it covers, each once, in the
    /// order of the solution's `predicted_residual`; one entry exactly when
    /// `unit` is not `null`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units: Option<Vec<Unit>>,
}

/// What the machine's answer reads of a stored solution: its summary and the
/// unit of each row, whether the summary covers it. Only these are built;
/// the rest of the solution (coefficients, corrections, diagnostics) is
/// skipped over, not parsed into values.
#[derive(Deserialize)]
struct StoredSummary {
    summary: serde_json::Value,
    predicted_residual: Vec<ResidualUnit>,
}

#[derive(Deserialize)]
struct ResidualUnit {
    unit: Unit,
    used: bool,
}

impl StoredSummary {
    /// The units of the rows the summary covers, each once, in row order.
    fn units(&self) -> Vec<Unit> {
        let mut units = Vec::new();
        for row in self.predicted_residual.iter().filter(|r| r.used) {
            if !units.contains(&row.unit) {
                units.push(row.unit);
            }
        }
        units
    }
}

/// One coefficient version, without the coefficients.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct VersionSummary {
    pub version: i64,
    pub created_at: String,
    pub sessions: Vec<String>,
}

/// A machine with its sessions (oldest first) and coefficient versions.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct MachineDetail {
    #[serde(flatten)]
    pub machine: Machine,
    pub sessions: Vec<MachineSession>,
    pub coefficients: Vec<VersionSummary>,
}

/// A stored coefficient version: its identification and the pooled body.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct StoredCoefficients {
    pub machine: String,
    pub version: i64,
    pub created_at: String,
    pub sessions: Vec<String>,
    /// `conventions`, `influence_coefficients`, `excluded`, `checks`, `warnings`.
    #[serde(flatten)]
    #[schema(value_type = crate::balancing::job::pool::Pooled)]
    pub body: serde_json::Map<String, serde_json::Value>,
}

fn not_found(id: &str) -> StoreError {
    StoreError::NotFound(format!("no machine has the id '{id}'"))
}

fn machine_from(r: &sqlx::any::AnyRow) -> Result<Machine, StoreError> {
    let rotor: Option<String> = r.get("rotor");
    Ok(Machine {
        id: r.get("id"),
        // No name is kept as "" (the column is NOT NULL) and read back as none.
        name: Some(r.get::<String, _>("name")).filter(|n| !n.is_empty()),
        rotor: rotor.map(|s| serde_json::from_str(&s)).transpose()?,
        notes: r.get("notes"),
        created_at: r.get("created_at"),
    })
}

/// Store a validated machine; `Conflict` when the id is taken. With an
/// `Idempotency-Key`, the 201 answer (with its `location`) is kept in the
/// same transaction (`Replayed` when a request with the key got there first).
pub async fn create(
    db: &Db,
    m: &NewMachine,
    idem: Option<&Idem>,
    location: &str,
) -> Result<Machine, StoreError> {
    let mut tx = db.begin_write().await?;
    idempotency::guard(&mut tx, idem).await?;
    let rotor = m.rotor.as_ref().map(serde_json::to_string).transpose()?;
    // The unique id decides, so two processes creating the same machine at
    // once get one 201 and one 409.
    let row = sqlx::query(
        "INSERT INTO machines (id, name, rotor, notes) VALUES ($1, $2, $3, $4)
         ON CONFLICT (id) DO NOTHING
         RETURNING id, name, rotor, notes, created_at",
    )
    .bind(&m.id)
    .bind(m.name.as_deref().unwrap_or(""))
    .bind(rotor)
    .bind(&m.notes)
    .fetch_optional(&mut *tx)
    .await?
    .ok_or_else(|| StoreError::Conflict {
        field: "id",
        message: format!("a machine with the id '{}' exists already", m.id),
    })?;
    let machine = machine_from(&row)?;
    idempotency::remember(&mut tx, idem, 201, Some(location), &machine).await?;
    tx.commit().await?;
    Ok(machine)
}

/// A page of machines, newest first, and how many there are in all, both
/// from one snapshot (as `sessions::list`).
pub async fn list(db: &Db, page: ListPage) -> Result<MachineList, StoreError> {
    let mut read = db.begin_read().await?;
    // One more than the page: whether a next page exists.
    let mut rows = sqlx::query(
        "SELECT seq, id, name, rotor, notes, created_at FROM machines
         WHERE seq < $1 ORDER BY seq DESC LIMIT $2 OFFSET $3",
    )
    .bind(page.before.unwrap_or(i64::MAX))
    .bind(page.limit + 1)
    .bind(page.offset)
    .fetch_all(&mut *read)
    .await?;
    let total: i64 = sqlx::query("SELECT COUNT(*) FROM machines")
        .fetch_one(&mut *read)
        .await?
        .get(0);
    read.commit().await?;
    let more = rows.len() as i64 > page.limit;
    rows.truncate(page.limit as usize);
    let next = more
        .then(|| rows.last().map(|r| r.get::<i64, _>("seq").to_string()))
        .flatten();
    Ok(MachineList {
        machines: rows.iter().map(machine_from).collect::<Result<_, _>>()?,
        total,
        limit: page.limit,
        offset: page.offset,
        next,
    })
}

/// The machine, its sessions (oldest first: `limit` of them from `offset`,
/// every one from `offset` on without a limit) and its coefficient
/// versions, with the number of its sessions in all, from one snapshot.
pub async fn get(
    db: &Db,
    id: &str,
    limit: Option<i64>,
    offset: i64,
) -> Result<(MachineDetail, i64), StoreError> {
    if never_stored(db.engine, id) {
        return Err(not_found(id));
    }
    let mut read = db.begin_read().await?;
    let row =
        sqlx::query("SELECT seq, id, name, rotor, notes, created_at FROM machines WHERE id = $1")
            .bind(id)
            .fetch_optional(&mut *read)
            .await?
            .ok_or_else(|| not_found(id))?;
    let seq: i64 = row.get("seq");
    let machine = machine_from(&row)?;
    let rows = sqlx::query(
        "SELECT s.id, s.name, s.created_at,
                (SELECT COUNT(*) FROM runs r WHERE r.session_seq = s.seq) AS runs,
                (SELECT solution FROM solutions o WHERE o.session_seq = s.seq ORDER BY o.seq DESC LIMIT 1) AS solution,
                (SELECT created_at FROM solutions o WHERE o.session_seq = s.seq ORDER BY o.seq DESC LIMIT 1) AS solved_at
         FROM sessions s WHERE s.machine = $1 ORDER BY s.seq LIMIT $2 OFFSET $3",
    )
    .bind(id)
    .bind(limit.unwrap_or(i64::MAX))
    .bind(offset)
    .fetch_all(&mut *read)
    .await?;
    let total: i64 = sqlx::query("SELECT COUNT(*) FROM sessions WHERE machine = $1")
        .bind(id)
        .fetch_one(&mut *read)
        .await?
        .get(0);
    let mut sessions = Vec::with_capacity(rows.len());
    for r in &rows {
        let solution: Option<String> = r.get("solution");
        let stored = solution
            .map(|s| serde_json::from_str::<StoredSummary>(&s))
            .transpose()?;
        let units = stored.as_ref().map(StoredSummary::units);
        sessions.push(MachineSession {
            id: r.get("id"),
            name: r.get("name"),
            created_at: r.get("created_at"),
            runs: r.get("runs"),
            unit: units
                .as_ref()
                .map(|u| if u.len() == 1 { Some(u[0]) } else { None }),
            units,
            summary: stored.map(|s| s.summary),
            solved_at: r.get("solved_at"),
        });
    }
    let versions = sqlx::query(
        "SELECT version, created_at, sessions FROM machine_coefficients WHERE machine_seq = $1 ORDER BY version",
    )
    .bind(seq)
    .fetch_all(&mut *read)
    .await?;
    let coefficients = versions
        .iter()
        .map(|r| {
            Ok(VersionSummary {
                version: r.get("version"),
                created_at: r.get("created_at"),
                sessions: serde_json::from_str(r.get("sessions"))?,
            })
        })
        .collect::<Result<_, StoreError>>()?;
    read.commit().await?;
    Ok((
        MachineDetail {
            machine,
            sessions,
            coefficients,
        },
        total,
    ))
}

/// Delete a machine and its coefficient versions (never its sessions),
/// keeping the id's last version number so that none is numbered twice.
pub async fn delete(db: &Db, id: &str) -> Result<(), StoreError> {
    if never_stored(db.engine, id) {
        return Err(not_found(id));
    }
    let mut tx = db.begin_write().await?;
    // Locked first: a version being stored by another replica is either
    // counted here or refused (its machine gone), never numbered again later.
    let lock = engine::for_update(&tx, "SELECT seq FROM machines WHERE id = $1");
    let seq: i64 = sqlx::query(&lock)
        .bind(id)
        .fetch_optional(&mut *tx)
        .await?
        .ok_or_else(|| not_found(id))?
        .get(0);
    let last: Option<i64> =
        sqlx::query("SELECT MAX(version) FROM machine_coefficients WHERE machine_seq = $1")
            .bind(seq)
            .fetch_one(&mut *tx)
            .await?
            .get(0);
    if let Some(last) = last {
        sqlx::query(
            "INSERT INTO machine_versions_retired (machine_id, last_version) VALUES ($1, $2)
             ON CONFLICT (machine_id) DO UPDATE SET last_version =
                 CASE WHEN excluded.last_version > machine_versions_retired.last_version
                      THEN excluded.last_version ELSE machine_versions_retired.last_version END",
        )
        .bind(id)
        .bind(last)
        .execute(&mut *tx)
        .await?;
    }
    sqlx::query("DELETE FROM machines WHERE seq = $1")
        .bind(seq)
        .execute(&mut *tx)
        .await?;
    tx.commit().await?;
    Ok(())
}

/// Whether the machine exists.
pub async fn exists(db: &Db, id: &str) -> Result<bool, StoreError> {
    if never_stored(db.engine, id) {
        return Ok(false);
    }
    Ok(sqlx::query("SELECT 1 FROM machines WHERE id = $1")
        .bind(id)
        .fetch_optional(&db.pool)
        .await?
        .is_some())
}

/// The listed sessions, from one snapshot; `Err(i)` names the first listed
/// session that does not exist.
pub async fn load_sessions(
    db: &Db,
    ids: &[String],
) -> Result<Result<Vec<Session>, usize>, StoreError> {
    let mut read = db.begin_read().await?;
    let mut out = Vec::with_capacity(ids.len());
    for (i, id) in ids.iter().enumerate() {
        match sessions::load(&mut read, id).await {
            Ok((_, s)) => out.push(s),
            Err(StoreError::NotFound(_)) => return Ok(Err(i)),
            Err(e) => return Err(e),
        }
    }
    read.commit().await?;
    Ok(Ok(out))
}

/// Store a new coefficient version; returns it. With an `Idempotency-Key`,
/// the 201 answer is kept in the same transaction (`Replayed` when a request
/// with the key got there first).
pub async fn store_coefficients(
    db: &Db,
    machine: &str,
    sessions: &[String],
    body: serde_json::Map<String, serde_json::Value>,
    idem: Option<&Idem>,
) -> Result<StoredCoefficients, StoreError> {
    if never_stored(db.engine, machine) {
        return Err(not_found(machine));
    }
    let mut tx = db.begin_write().await?;
    idempotency::guard(&mut tx, idem).await?;
    // Lock the machine so that concurrent versions (other replicas) are
    // allocated one after the other; UNIQUE (machine_seq, version) backs it.
    let lock = engine::for_update(&tx, "SELECT seq FROM machines WHERE id = $1");
    sqlx::query(&lock)
        .bind(machine)
        .fetch_optional(&mut *tx)
        .await?
        .ok_or_else(|| not_found(machine))?;
    // After the machine's own versions, or else after those of a deleted
    // machine of the same id (every own version is above those).
    let row = sqlx::query(
        "INSERT INTO machine_coefficients (machine_seq, version, sessions, body)
         SELECT m.seq,
                COALESCE((SELECT MAX(c.version) FROM machine_coefficients c WHERE c.machine_seq = m.seq),
                         (SELECT r.last_version FROM machine_versions_retired r WHERE r.machine_id = m.id),
                         0) + 1,
                $1, $2
         FROM machines m WHERE m.id = $3
         RETURNING version, created_at",
    )
    .bind(serde_json::to_string(sessions)?)
    .bind(serde_json::to_string(&body)?)
    .bind(machine)
    .fetch_optional(&mut *tx)
    .await?
    .ok_or_else(|| not_found(machine))?;
    let stored = StoredCoefficients {
        machine: machine.to_string(),
        version: row.get("version"),
        created_at: row.get("created_at"),
        sessions: sessions.to_vec(),
        body,
    };
    idempotency::remember(&mut tx, idem, 201, None, &stored).await?;
    tx.commit().await?;
    Ok(stored)
}

/// Why stored coefficients could not be read.
#[derive(Debug)]
pub enum Missing {
    Machine,
    Version,
    /// The version was deleted with an earlier machine of this id, whose
    /// versions went up to this one; it is never numbered again.
    Retired(i64),
    NoVersions,
}

/// A machine's coefficients: `version`, or the latest.
pub async fn coefficients(
    db: &Db,
    machine: &str,
    version: Option<i64>,
) -> Result<Result<StoredCoefficients, Missing>, StoreError> {
    if never_stored(db.engine, machine) {
        return Ok(Err(Missing::Machine));
    }
    let mut read = db.begin_read().await?;
    let Some(m) = sqlx::query("SELECT seq FROM machines WHERE id = $1")
        .bind(machine)
        .fetch_optional(&mut *read)
        .await?
    else {
        return Ok(Err(Missing::Machine));
    };
    let seq: i64 = m.get(0);
    let row = sqlx::query(
        "SELECT version, created_at, sessions, body FROM machine_coefficients
         WHERE machine_seq = $1 AND ($2 IS NULL OR version = $3) ORDER BY version DESC LIMIT 1",
    )
    .bind(seq)
    .bind(version)
    .bind(version)
    .fetch_optional(&mut *read)
    .await?;
    let Some(r) = row else {
        let Some(v) = version else {
            return Ok(Err(Missing::NoVersions));
        };
        let retired: Option<i64> =
            sqlx::query("SELECT last_version FROM machine_versions_retired WHERE machine_id = $1")
                .bind(machine)
                .fetch_optional(&mut *read)
                .await?
                .map(|r| r.get(0));
        read.commit().await?;
        return Ok(Err(match retired {
            Some(last) if (1..=last).contains(&v) => Missing::Retired(last),
            _ => Missing::Version,
        }));
    };
    read.commit().await?;
    Ok(Ok(StoredCoefficients {
        machine: machine.to_string(),
        version: r.get("version"),
        created_at: r.get("created_at"),
        sessions: serde_json::from_str(r.get("sessions"))?,
        body: serde_json::from_str(r.get("body"))?,
    }))
}
