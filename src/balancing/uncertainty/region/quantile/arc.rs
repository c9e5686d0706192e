//! The far-mean rows (`|μ| ≥ 8σ₁`, the residual rows of a min-max job) as
//! the tests address them. Until issue 15's session 8 they had a rule of
//! their own, over the arc of directions from the origin that holds the
//! mass; `polar`'s rule, seen from the mean, now serves them with the rest
//! (fewer instructions, one rule), and this is it under the name the tests use.

use super::polar::Polar;

/// The mean is far from the origin when `|μ| ≥ FAR σ₁`.
const FAR: f64 = 8.0;

/// `polar`'s rule for a row whose mean is far from the origin.
pub(in crate::balancing::uncertainty) struct Arc(Polar);

impl Arc {
    /// The rule for `N((μ₁, μ₂), diag(σ₁², σ₂²))`, `σ₁ ≥ σ₂`; `None` unless
    /// the mean is far from the origin beside `σ₁`.
    pub(in crate::balancing::uncertainty) fn new(
        mu1: f64,
        mu2: f64,
        s1: f64,
        s2: f64,
    ) -> Option<Self> {
        (mu1.hypot(mu2) >= FAR * s1)
            .then(|| Polar::new(mu1, mu2, s1, s2).map(Arc))
            .flatten()
    }

    /// `[P(ρ), P'(ρ)]`, or `None` where the rule does not apply.
    pub(in crate::balancing::uncertainty) fn inside(&mut self, rho: f64) -> Option<[f64; 2]> {
        self.0.inside(rho)
    }
}
