//! The 95 % quantile's numerics: `P(|R| ≤ ρ)` and its derivatives in ρ for a
//! Gaussian `R` in the plane (the polar rule seen from the mean, the adaptive
//! quadrature it falls back on and the tests' reference) and the Newton that
//! solves `P = 0.95`. `region::amplitude_95` drives them; what mean and
//! covariance go in is `remaining`'s business.

#[cfg(test)]
pub(in crate::balancing::uncertainty) mod arc;
pub(in crate::balancing::uncertainty) mod newton;
pub(in crate::balancing::uncertainty) mod polar;
pub(in crate::balancing::uncertainty) mod quadrature;
