//! The 95 % quantile's numerics: `P(|R| ≤ ρ)` and its derivatives in ρ for a
//! Gaussian `R` in the plane (the polar and arc rules over rays, the adaptive
//! quadrature they fall back on) and the Newton that solves `P = 0.95`.
//! `region::amplitude_95` chooses among them; what mean and covariance go in
//! is `remaining`'s business.

pub(super) mod arc;
pub(super) mod newton;
pub(super) mod polar;
pub(super) mod quadrature;
mod ray;
