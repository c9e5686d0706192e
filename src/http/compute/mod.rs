//! The endpoints that compute: one-shot and stored solves, trial-weight
//! sizing, identification and the residual-unbalance check. The heavy ones run
//! in the solve slots (`http::work`).

pub mod identify;
pub mod residual;
pub mod solve;
pub mod trial_weights;
