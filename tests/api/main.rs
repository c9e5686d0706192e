//! The HTTP API against the real server: bad requests and their error bodies,
//! machines and their coefficient versions (numbers never reused under an
//! id), the strings and timestamps stored alike on both engines
//! (`stored_text`), the OpenAPI document, runs of a
//! stored session, what a job and its runs are (`records`), a page and its
//! total from one snapshot (`pages`), the `fieldbal serve` binary, service behaviour (request ids,
//! body limits, time limits) and sessions. `scripts/test.sh` runs this whole
//! binary a second time with the server on PostgreSQL.

#[path = "../common/mod.rs"]
mod common;
/// The job tests' rotor model (machines solve new jobs from it).
#[path = "../job/support.rs"]
mod job_support;

mod contract_fields;
mod errors;
mod machine_ids;
mod machines;
mod openapi;
mod pages;
mod records;
mod review22;
mod review23;
mod runs;
mod serve;
mod service;
mod sessions;
mod stored_text;
mod trim_jobs;
