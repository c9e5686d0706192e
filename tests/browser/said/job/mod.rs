//! What the form says as a job goes on: coefficients pooled from jobs that
//! disagree, a store whose answer was lost, a trim job, a run typed while
//! the service is away, and a whole job walked through.

pub(super) mod pooled;
pub(super) mod retry;
pub(super) mod trim;
pub(super) mod unreachable;
pub(super) mod walk;
