//! Identification (method §7): free decays, the discrete-model correction,
//! rotors from sessions of generated Jeffcott rotors, and the endpoints through
//! a real server with their errors. `scripts/test.sh` runs `api` a second time
//! with the server on PostgreSQL.

#[path = "../common/mod.rs"]
mod common;
mod support;

mod api;
mod decay;
mod errors;
mod model;
mod partial;
mod properties;
mod ranges;
mod rotor;
mod split;
