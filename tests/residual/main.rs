//! The residual-unbalance check (issue 17): on a generated linear rotor, and
//! through the real server and the command line. `scripts/test.sh` runs `api`
//! a second time with the server on PostgreSQL.

#[path = "../common/mod.rs"]
mod common;
mod support;

mod api;
mod unbalance;
