//! The HTTP API against the real server, grouped by what it holds:
//! `requests` (bad requests and their error bodies, texts, solve options,
//! query parameters, the conditional and idempotent writes' headers),
//! `store` (sessions, runs, what a job and its runs are, pages from one
//! snapshot, strings alike on both engines, trim jobs), `machines` (their
//! coefficient versions, ids never reused, their sessions), `contract` (the
//! OpenAPI document and the contract's field names), `service` (the `fieldbal
//! serve` binary, request ids, limits) and `commands` (the offline commands
//! refuse what the service refuses). `scripts/test.sh` runs this whole
//! binary a second time with the server on PostgreSQL.

#[path = "../common/mod.rs"]
mod common;
/// The job tests' rotor model (machines solve new jobs from it).
#[path = "../job/support.rs"]
mod job_support;

mod support;

mod commands;
mod contract;
mod machines;
mod requests;
mod service;
mod store;
