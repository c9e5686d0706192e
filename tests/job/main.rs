//! The balancing job beyond one solve: the CLI's job options, supplied and
//! pooled coefficients, runout compensation, and the trim loop from a run's
//! state with fitted, supplied or stored coefficients. `scripts/test.sh` runs
//! this whole binary a second time with the server on PostgreSQL.

#[path = "../common/mod.rs"]
mod common;
mod support;
mod trim_support;

mod cli;
mod coefficients;
mod runout;
mod trim;
mod trim_supplied;
