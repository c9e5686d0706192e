//! What a request's writes have reached, so that its time limit answers
//! truthfully: a request cut short before any commit began stored nothing
//! (its transaction is rolled back when dropped); once a commit has begun it
//! may be stored, so the request is left to finish and answer its real result.

use std::future::Future;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Shared between the time limit and the request's writes.
#[derive(Debug, Default)]
pub struct WriteWatch {
    committing: AtomicBool,
}

impl WriteWatch {
    /// Whether a commit of this request has begun.
    pub fn committing(&self) -> bool {
        self.committing.load(Ordering::Acquire)
    }
}

tokio::task_local! {
    static WATCH: Arc<WriteWatch>;
}

/// Run a request's future with `watch` seeing its commits.
pub async fn watched<F: Future>(watch: Arc<WriteWatch>, f: F) -> F::Output {
    WATCH.scope(watch, f).await
}

/// Called by `WriteTx::commit` before it sends COMMIT.
pub(crate) fn committing() {
    let _ = WATCH.try_with(|w| w.committing.store(true, Ordering::Release));
}
