//! Sessions and their runs in the store: round trips, corrected runs,
//! what a job and its runs are, pages read from one snapshot, stored
//! strings alike on both engines, trim jobs.

mod pages;
mod records;
mod runs;
mod sessions;
mod stored_text;
mod trim_jobs;
