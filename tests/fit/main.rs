//! The discrete fit of kit weights and trial-weight suggestions: against
//! brute force, through a whole solve, over HTTP (`scripts/test.sh` runs
//! `http` a second time with the server on PostgreSQL), and the suggested
//! trial weights on generated rotors.

#[path = "../common/mod.rs"]
mod common;
mod support;

mod brute;
mod http;
mod solve;
mod trial;
