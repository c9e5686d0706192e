//! The library's solve against its contract: the public examples and the
//! textbook's worked checks, invalid sessions, the solution's diagnostics and
//! practical forms, property tests, the fast parse and the restructured solve
//! against the code they replaced, and the min-max and mass-bounded
//! corrections. Proptest keeps its failure seeds next to each test file
//! (`*.proptest-regressions`).

#[path = "../common/mod.rs"]
mod common;

mod across_options;
mod examples;
mod invalid_sessions;
mod parse_equivalence;
mod perf_equivalence;
mod properties;
mod solution_forms;
mod textbook;

/// Min-max and mass-bounded corrections (issues 5 and 15).
mod minmax {
    mod dependent;
    mod equivalence;
    mod exact;
    mod optimality;
    mod sessions;
    mod support;
}
