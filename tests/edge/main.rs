//! The service's edge: bearer tokens and the `Host` check, connections (slow
//! headers, idle and non-reading clients, the connection cap, SIGTERM), a
//! seeded fuzz run from the served OpenAPI document, compressed bodies, and the
//! headers and refusals before a handler. `scripts/test.sh` runs `access` a second time
//! with the server on PostgreSQL.

#[path = "../common/mod.rs"]
mod common;
mod support;

mod access;
mod connections;
mod encoding;
mod fuzz;
mod headers;
