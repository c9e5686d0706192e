//! The identification core: model coefficients from stand data, pure like
//! `balancing` (no HTTP, no database, no async), sharing its phasors, session
//! model and validation.
//!
//! - [`rotor`]: the one-mass rotor of method §6 (6.1) fitted to a multi-speed
//!   session's influence coefficients: critical speed, damping, API 684
//!   amplification factor and separation margin.
//! - [`decay`]: natural frequency and damping from a sampled free decay by the
//!   linear discrete models of method §7 (7.1 viscous, 7.2 turbulent).
//! - [`model`]: the lecture's weighted least-squares correction of a discrete
//!   (mass/stiffness matrix) model from measured natural frequencies and shapes.
//! - [`textbook`]: the textbook's worked one-mass cases, given as responses.
//! - [`ranges`]: the accepted range of every number, and why.

pub mod api684;
pub mod correct;
pub mod decay;
pub mod lsq;
pub mod model;
pub mod modes;
pub mod onemass;
pub mod ranges;
pub mod rotor;
pub mod textbook;

pub use decay::{FreeDecay, FreeDecayRequest};
pub use model::{ModelCorrection, ModelRequest};
pub use rotor::{RotorIdentification, RotorRequest};
