//! Hardening of the service: crash safety under SIGKILL, size limits and the
//! memory of the largest accepted request, storage faults (a full disk, a
//! read-only database), the wire model at the edge, honest writes (idempotency
//! keys, `If-Match`, paging), and replicas on one PostgreSQL database.
//! `scripts/test.sh` runs `writes` a second time with the server on PostgreSQL.

#[path = "../common/mod.rs"]
mod common;
mod support;

mod crash;
mod limits;
mod replicas_postgres;
mod storage;
mod wire;
mod writes;
