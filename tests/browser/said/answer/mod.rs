//! What a solve's answer says on the page: its mass limits, every angle's
//! convention, its date, readings with samples, every amplitude's unit and
//! every warning.

pub(super) mod bound;
pub(super) mod conventions;
pub(super) mod dates;
pub(super) mod samples;
pub(super) mod units;
pub(super) mod warnings;
