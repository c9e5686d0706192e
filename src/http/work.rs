//! CPU work off the async threads: validation and solves run on the blocking
//! pool, and solves take one of a bounded number of slots.
//!
//! A solve waits briefly for a slot, then the request is refused with 503 and
//! `Retry-After`. A request whose time limit passes while it waits is dropped
//! and never starts its solve; one already solving holds its slot until the
//! core returns (the core is not interruptible), so the slots bound the CPU
//! and memory in use even when clients give up.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Duration;

use axum::http::{header, StatusCode};
use axum::response::{IntoResponse, Response};
use tokio::sync::Semaphore;

use super::error::ApiError;
use crate::balancing::InputError;
use crate::db::StoreError;

/// Default number of solves that run at once.
pub fn default_solve_slots() -> usize {
    std::thread::available_parallelism().map_or(2, |n| n.get())
}
/// Default time a solve waits for a slot before 503, milliseconds.
pub const DEFAULT_SOLVE_QUEUE_MS: u64 = 2_000;
/// Sessions with fewer readings are validated in place: the blocking pool's
/// hand-off would cost more than the work.
const INLINE_READINGS: usize = 2_000;

/// The solve slots and how long to wait for one.
#[derive(Debug, Clone)]
pub struct Slots {
    semaphore: Arc<Semaphore>,
    wait: Duration,
}

impl Slots {
    pub fn new(count: usize, wait: Duration) -> Self {
        Slots {
            semaphore: Arc::new(Semaphore::new(count.max(1))),
            wait,
        }
    }

    /// Run `work` (a solve) on the blocking pool once a slot is free.
    pub async fn solve<T: Send + 'static>(
        &self,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> Result<T, Refused> {
        let permit = tokio::time::timeout(self.wait, self.semaphore.clone().acquire_owned())
            .await
            .map_err(|_| Refused::Busy {
                retry_after_secs: self.wait.as_secs().max(1),
            })?
            .map_err(|e| ApiError::internal(&e))?;
        let gone = Gone::new();
        let flag = gone.flag.clone();
        let result = tokio::task::spawn_blocking(move || {
            let _permit = permit;
            // The request may have timed out while the task waited for a thread.
            (!flag.load(Ordering::Acquire)).then(work)
        })
        .await
        .map_err(|e| ApiError::internal(&e))?;
        gone.disarm();
        result.ok_or_else(|| ApiError::internal(&"solve skipped after its request ended").into())
    }
}

/// Marks the request as gone when the handler's future is dropped (by the
/// time limit, or a closed connection) before the work started.
struct Gone {
    flag: Arc<AtomicBool>,
    armed: bool,
}

impl Gone {
    fn new() -> Self {
        Gone {
            flag: Arc::new(AtomicBool::new(false)),
            armed: true,
        }
    }
    fn disarm(mut self) {
        self.armed = false;
    }
}

impl Drop for Gone {
    fn drop(&mut self) {
        if self.armed {
            self.flag.store(true, Ordering::Release);
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
