//! Cooperative cancellation: long searches in the core ask, at their
//! checkpoints, whether the request they serve has ended (time limit passed,
//! client gone), and stop early if so; nobody is waiting for their answer.
//!
//! The flag is per thread, set by the caller around one solve (`scope`), so
//! the core stays free of the service's types and the one-shot CLI, which
//! sets none, never sees a cancellation.

use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// Run `work` on this thread with `flag` as its cancellation flag.
pub fn scope<T>(flag: Arc<AtomicBool>, work: impl FnOnce() -> T) -> T {
    /// Clears the flag even if `work` panics, so the thread's next solve starts clean.
    struct Reset;
    impl Drop for Reset {
        fn drop(&mut self) {
            FLAG.with(|f| f.borrow_mut().take());
        }
    }
    FLAG.with(|f| *f.borrow_mut() = Some(flag));
    let _reset = Reset;
    work()
}

/// Whether the solve running on this thread should stop.
pub fn requested() -> bool {
    FLAG.with(|f| {
        f.borrow()
            .as_ref()
            .is_some_and(|flag| flag.load(Ordering::Relaxed))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_work_inside_a_cancelled_scope_sees_the_request() {
        assert!(!requested());
        let flag = Arc::new(AtomicBool::new(false));
        scope(flag.clone(), || {
            assert!(!requested());
            flag.store(true, Ordering::Relaxed);
            assert!(requested());
        });
        assert!(!requested(), "the flag ends with its scope");
    }
}
