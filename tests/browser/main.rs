//! End-to-end tests of the web form in Debian's headless Chromium, typed key
//! by key: the answer as read (`answers`), errors at their field, exports, the form, imported sessions, a
//! whole job at the stand, what a new user met (`newuser`), a job reopened elsewhere and
//! one typed from the keyboard alone (`reopened`), bearer tokens, and the stand-alone free-decay and residual pages kept across a reload (`tools`). `harness/` starts and drives the
//! browser (one at a time in this binary, see `harness::Browser::start`);
//! `scenes/` holds the longer scenes the tests go through. Screenshots go to
//! `target/screenshots/`.

#[path = "../common/mod.rs"]
mod common;
mod harness;
mod scenes;

mod answers;
mod errors;
mod export;
mod form;
mod import;
mod job;
mod newuser;
mod reopened;
mod said;
mod token;
mod tools;
