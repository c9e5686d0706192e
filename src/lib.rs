//! fieldbal: field balancing of rotors by experimental influence coefficients.
//!
//! - [`balancing`]: the pure core (session model, validation, influence
//!   coefficients, least-squares and min-max corrections, uncertainty).
//! - [`identification`]: the pure identification core (one-mass rotor from
//!   influence coefficients, free decay, discrete-model correction).
//! - [`http`]: the REST service and the embedded web form.
//! - [`db`]: storage of sessions, runs and solutions in SQLite.
//! - [`cli`]: `fieldbal serve`, `fieldbal solve` and `fieldbal identify`.
//!
//! Angle conventions are the session's own at every edge (phase `lag`/`lead`,
//! weight angles `against_rotation`/`with_rotation`); see `balancing`.

pub mod balancing;
pub mod cli;
pub mod db;
pub mod http;
pub mod identification;

/// The allocator of every binary that links fieldbal: the service, the CLI,
/// the tests and the benches alike (issue 15). glibc's malloc gives the
/// pages of a large solve back to the kernel when it ends (its trim and
/// mmap thresholds) and takes them again in the next: on the large
/// least-squares job (16 planes × 32 sensors × 40 speeds) 800 page faults a
/// solve, a fifth of its time in the kernel (criterion: 10.2 ms with 1.2 s
/// of system time in 5.8 s, against 7.7 ms and 0.02 s with the thresholds
/// raised). mimalloc keeps freed pages for reuse: 7.6 ms, no answer changed
/// (the JSON of `fieldbal solve` on `benches/data/` is byte for byte the
/// same). A one-shot `fieldbal solve` peaks higher (46 MB against 21 MB on
/// that job, 95 MB against 69 MB on the 267-plane one: mimalloc's transparent
/// huge pages, `MIMALLOC_ALLOW_THP=0` turns them off), under issue 15's
/// 200 MB; the worst accepted requests to the service peak at 175 MiB
/// (BENCHMARKS.md, "Issue 15, session 10").
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;
