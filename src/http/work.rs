//! CPU work off the async threads: solves run on a fixed set of solver
//! threads fed by one queue; large validations run on the blocking pool.
//!
//! A solve waits in the queue for at most the configured wait, then the
//! request is refused with 503 and `Retry-After`, and its solve never runs;
//! one queued while a solver thread is free is taken whatever the wait
//! (with `--solve-queue-ms 0`, refused only when every thread is busy).
//! A request dropped while queued (its time limit passed, or the client left)
//! is skipped by the solver threads; one already solving is asked to stop
//! (`balancing::cancel`): the kit fit's search stops at its next checkpoint,
//! while least squares and the cone solves, bounded by their own limits, run
//! to the end. The threads bound the CPU and memory in use even when clients
//! give up.
//!
//! Why threads of our own and not a semaphore in front of `spawn_blocking`:
//! under load every finished solve then woke the next waiting request on an
//! async worker only for it to hand its work to a blocking thread again, two
//! hand-offs per solve; the solver threads take the next job themselves
//! (BENCHMARKS.md, "After the v2 hardening").

use std::collections::VecDeque;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::Duration;

use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use tokio::sync::oneshot;

use super::error::ApiError;
use crate::balancing::{cancel, InputError};
use crate::db::StoreError;

/// Default number of solves that run at once.
pub fn default_solve_slots() -> usize {
    std::thread::available_parallelism().map_or(2, |n| n.get())
}
/// Default time a solve waits for a solver thread before 503, milliseconds.
pub const DEFAULT_SOLVE_QUEUE_MS: u64 = 2_000;
/// Sessions with fewer readings are validated in place: the blocking pool's
/// hand-off would cost more than the work.
const INLINE_READINGS: usize = 2_000;

/// A queued solve, claimed by whichever of its solver and its request acts
/// first (`State`).
type Job = Box<dyn FnOnce() + Send>;

/// Where a queued solve stands; moves only away from `QUEUED`, by one
/// compare-and-swap, so a solve never both runs and is refused.
const QUEUED: u8 = 0;
const STARTED: u8 = 1;
const ABANDONED: u8 = 2;

/// The solver threads and how long a request waits for one.
#[derive(Debug, Clone)]
pub struct Slots {
    pool: Arc<Handle>,
    wait: Duration,
}

/// Owned by the `Slots` clones: when the last one goes (the server stopped),
/// the threads finish what is queued and exit.
#[derive(Debug)]
struct Handle(Arc<Queue>);

#[derive(Default)]
struct Queue {
    state: Mutex<Pending>,
    ready: Condvar,
}

#[derive(Default)]
struct Pending {
    jobs: VecDeque<Job>,
    closed: bool,
    /// Solver threads waiting for a job: a job queued while more threads
    /// wait than jobs are queued is taken without waiting for a solve to end.
    idle: usize,
}

impl std::fmt::Debug for Queue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Queue")
    }
}

impl Queue {
    /// The queue is only ever pushed to and popped, so a panic elsewhere
    /// while it was locked cannot have left it inconsistent.
    fn lock(&self) -> MutexGuard<'_, Pending> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    fn next(&self) -> Option<Job> {
        let mut pending = self.lock();
        loop {
            if let Some(job) = pending.jobs.pop_front() {
                return Some(job);
            }
            if pending.closed {
                return None;
            }
            pending.idle += 1;
            pending = self.ready.wait(pending).unwrap_or_else(|e| e.into_inner());
            pending.idle -= 1;
        }
    }
}

impl Drop for Handle {
    fn drop(&mut self) {
        self.0.lock().closed = true;
        self.0.ready.notify_all();
    }
}

impl Slots {
    /// Start `count` solver threads (at least one).
    pub fn new(count: usize, wait: Duration) -> Self {
        let queue = Arc::new(Queue::default());
        for i in 0..count.max(1) {
            let queue = queue.clone();
            std::thread::Builder::new()
                .name(format!("fieldbal-solver-{i}"))
                .spawn(move || {
                    while let Some(job) = queue.next() {
                        // A panicking solve drops its answer's sender: its
                        // request gets a 500 and this thread goes on.
                        let _ = catch_unwind(AssertUnwindSafe(job));
                    }
                })
                .expect("cannot start a solver thread");
        }
        Slots {
            pool: Arc::new(Handle(queue)),
            wait,
        }
    }

    /// Run `work` (a solve) on a solver thread, once one is free.
    pub async fn solve<T: Send + 'static>(
        &self,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> Result<T, Refused> {
        let (send, mut answer) = oneshot::channel();
        let claim = Claim {
            state: Arc::new(AtomicU8::new(QUEUED)),
            cancel: Arc::new(AtomicBool::new(false)),
        };
        let (state, cancel) = (claim.state.clone(), claim.cancel.clone());
        let job: Job = Box::new(move || {
            if state
                .compare_exchange(QUEUED, STARTED, Ordering::AcqRel, Ordering::Acquire)
                .is_ok()
            {
                let _ = send.send(cancel::scope(cancel, work));
            }
        });
        let free = {
            let queue = &self.pool.0;
            let mut pending = queue.lock();
            let free = pending.idle > pending.jobs.len();
            pending.jobs.push_back(job);
            queue.ready.notify_one();
            free
        };
        // A thread is free for it: it is not waiting behind other solves, so
        // it is not refused, however long that thread takes to wake (with no
        // wait configured, it was refused whenever the thread had not picked
        // it up by the timer's first tick).
        let waited = if free {
            Ok((&mut answer).await)
        } else {
            tokio::time::timeout(self.wait, &mut answer).await
        };
        let received = match waited {
            Ok(received) => received,
            // Still queued: refuse, and the solve never runs. Already
            // started: its answer is on the way.
            Err(_) if claim.abandon() => {
                return Err(Refused::Busy {
                    retry_after_secs: self.wait.as_secs().max(1),
                })
            }
            Err(_) => answer.await,
        };
        received.map_err(|_| ApiError::internal(&"the solver stopped without an answer").into())
    }
}

/// The request's hold on its solve: dropped with the request (time limit,
/// closed connection), it abandons a solve that has not started and asks one
/// that has to stop at its next checkpoint (`balancing::cancel`).
struct Claim {
    state: Arc<AtomicU8>,
    cancel: Arc<AtomicBool>,
}

impl Claim {
    /// True when the solve had not started and now never will.
    fn abandon(&self) -> bool {
        self.state
            .compare_exchange(QUEUED, ABANDONED, Ordering::AcqRel, Ordering::Acquire)
            .is_ok()
    }
}

impl Drop for Claim {
    fn drop(&mut self) {
        if !self.abandon() {
            // Started: a finished solve ignores this; a running one stops.
            self.cancel.store(true, Ordering::Relaxed);
        }
    }
}

/// Validate (or otherwise check) `value` off the async threads when it is large.
pub async fn check_blocking<V: Send + 'static>(
    value: V,
    readings: usize,
    check: impl FnOnce(&V) -> Result<(), InputError> + Send + 'static,
) -> Result<V, ApiError> {
    if readings < INLINE_READINGS {
        check(&value)?;
        return Ok(value);
    }
    tokio::task::spawn_blocking(move || check(&value).map(|()| value))
        .await
        .map_err(|e| ApiError::internal(&e))?
        .map_err(ApiError::from)
}

/// Why a request that needs a solve slot was not answered with its result.
#[derive(Debug)]
pub enum Refused {
    Api(ApiError),
    /// Every slot stayed busy for the queue's wait.
    Busy {
        retry_after_secs: u64,
    },
}

impl From<ApiError> for Refused {
    fn from(e: ApiError) -> Self {
        Refused::Api(e)
    }
}

impl From<InputError> for Refused {
    fn from(e: InputError) -> Self {
        Refused::Api(e.into())
    }
}

impl From<StoreError> for Refused {
    fn from(e: StoreError) -> Self {
        Refused::Api(e.into())
    }
}

impl IntoResponse for Refused {
    fn into_response(self) -> Response {
        match self {
            Refused::Api(e) => e.into_response(),
            Refused::Busy { retry_after_secs } => {
                let mut r = ApiError::new(
                    StatusCode::SERVICE_UNAVAILABLE,
                    "busy",
                    format!(
                        "every solver is busy; nothing was computed or stored: retry after {retry_after_secs} s"
                    ),
                )
                .into_response();
                r.headers_mut()
                    .insert(header::RETRY_AFTER, retry_after_secs.into());
                r
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use std::sync::mpsc;

    use super::*;

    /// Occupy the only solver thread until the returned sender is used.
    async fn hold(slots: &Slots) -> (mpsc::Sender<()>, tokio::task::JoinHandle<()>) {
        let (release, held) = mpsc::channel::<()>();
        let (started, running) = oneshot::channel::<()>();
        let slots = slots.clone();
        let task = tokio::spawn(async move {
            let work = move || {
                let _ = started.send(());
                held.recv().ok()
            };
            assert!(slots.solve(work).await.is_ok());
        });
        running.await.unwrap();
        (release, task)
    }

    /// Wait until the single solver thread has passed everything queued so far.
    async fn drain(slots: &Slots) {
        assert!(matches!(slots.solve(|| ()).await, Ok(())));
    }

    #[tokio::test]
    async fn a_solve_runs_on_a_solver_thread_and_answers() {
        let slots = Slots::new(2, Duration::from_secs(5));
        let name = slots
            .solve(|| std::thread::current().name().map(str::to_string))
            .await;
        assert!(matches!(name, Ok(Some(n)) if n.starts_with("fieldbal-solver-")));
    }

    /// With no wait (`--solve-queue-ms 0`) a solve is refused only when every
    /// solver thread is busy: an idle thread takes it, however long the
    /// thread takes to wake. It was refused whenever the thread had not
    /// picked it up by the timer's first tick, so on a loaded machine none
    /// of four concurrent solves ran (CI, tests/hardening/limits.rs).
    #[tokio::test(flavor = "current_thread", start_paused = true)]
    async fn an_idle_solver_takes_a_solve_even_with_no_wait() {
        let slots = Slots::new(1, Duration::ZERO);
        for i in 0..200 {
            // The thread is back waiting for jobs (bounded): it answers a
            // solve just before it returns to the queue, and a solve queued
            // in between finds it busy, as it would any other.
            for _ in 0..1_000 {
                if slots.pool.0.lock().idle == 1 {
                    break;
                }
                std::thread::sleep(std::time::Duration::from_millis(1));
            }
            assert!(slots.solve(|| ()).await.is_ok(), "solve {i} was refused");
        }
    }

    #[tokio::test]
    async fn a_solve_still_queued_when_the_wait_ends_is_refused_and_never_runs() {
        let slots = Slots::new(1, Duration::from_millis(50));
        let (release, holder) = hold(&slots).await;
        let ran = Arc::new(AtomicBool::new(false));
        let flag = ran.clone();
        let refused = slots
            .solve(move || flag.store(true, Ordering::SeqCst))
            .await;
        assert!(matches!(
            refused,
            Err(Refused::Busy {
                retry_after_secs: 1
            })
        ));
        release.send(()).unwrap();
        holder.await.unwrap();
        drain(&slots).await;
        assert!(!ran.load(Ordering::SeqCst), "a refused solve must not run");
    }

    #[tokio::test]
    async fn a_request_dropped_while_queued_never_starts_its_solve() {
        let slots = Slots::new(1, Duration::from_secs(30));
        let (release, holder) = hold(&slots).await;
        let ran = Arc::new(AtomicBool::new(false));
        let flag = ran.clone();
        let dropped = tokio::time::timeout(
            Duration::from_millis(50),
            slots.solve(move || flag.store(true, Ordering::SeqCst)),
        )
        .await;
        assert!(dropped.is_err(), "the request's own limit ends it first");
        release.send(()).unwrap();
        holder.await.unwrap();
        drain(&slots).await;
        assert!(
            !ran.load(Ordering::SeqCst),
            "an abandoned solve must not run"
        );
    }

    #[tokio::test]
    async fn a_running_solve_whose_request_ends_is_asked_to_stop() {
        let slots = Slots::new(1, Duration::from_secs(30));
        let saw = Arc::new(AtomicBool::new(false));
        let flag = saw.clone();
        let (started, running) = oneshot::channel::<()>();
        let mut request = Box::pin(slots.solve(move || {
            let _ = started.send(());
            let give_up = std::time::Instant::now() + Duration::from_secs(10);
            while std::time::Instant::now() < give_up {
                if cancel::requested() {
                    flag.store(true, Ordering::SeqCst);
                    return;
                }
                std::thread::sleep(Duration::from_millis(1));
            }
        }));
        tokio::select! {
            _ = &mut request => panic!("the work ends only when cancelled"),
            _ = running => {}
        }
        drop(request);
        drain(&slots).await;
        assert!(
            saw.load(Ordering::SeqCst),
            "the running work saw the request end"
        );
    }

    #[tokio::test]
    async fn a_solve_that_started_before_the_wait_ended_still_answers() {
        // The wait must end while the solve runs; on a loaded machine the
        // thread may not pick the job up within a short wait, so try longer
        // ones (the refused attempts are the other test's case).
        for wait_ms in [20, 200, 2_000] {
            let slots = Slots::new(1, Duration::from_millis(wait_ms));
            let (release, held) = mpsc::channel::<()>();
            let (started, running) = oneshot::channel::<()>();
            let solving = tokio::spawn(async move {
                slots
                    .solve(move || {
                        let _ = started.send(());
                        held.recv().map(|()| 42).ok()
                    })
                    .await
            });
            if running.await.is_err() {
                continue;
            }
            tokio::time::sleep(Duration::from_millis(wait_ms + 50)).await;
            release.send(()).unwrap();
            assert!(matches!(solving.await.unwrap(), Ok(Some(42))));
            return;
        }
        panic!("the solver thread never started a job within 2 s");
    }

    #[tokio::test]
    async fn a_panicking_solve_is_an_internal_error_and_its_thread_goes_on() {
        let slots = Slots::new(1, Duration::from_secs(5));
        let failed = slots.solve(|| -> u8 { panic!("solver bug") }).await;
        match failed {
            Err(Refused::Api(e)) => assert_eq!(e.status, StatusCode::INTERNAL_SERVER_ERROR),
            other => panic!("expected a 500, got {other:?}"),
        }
        assert!(matches!(slots.solve(|| 7).await, Ok(7)));
    }
}
