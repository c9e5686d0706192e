//! `P(|R| ≤ ρ)` and its derivative for a Gaussian `R` far from the origin
//! beside its spread (`|μ| ≥ 8 σ₁`, the residual rows of a min-max job): the
//! ray integrals of `polar` summed by the trapezoidal rule over the arc of
//! directions that holds the mass, not over the full turn (issue 15).
//!
//! Seen from the origin such a mass is narrow in angle (`σ_t/|μ|`, with
//! `σ_t` its spread across `μ`), so the full-turn rule of `polar` would need
//! thousands of directions and the adaptive quadrature was the fallback
//! (87 % of the instructions of a 1000-row min-max solve). Every point
//! within 6.5σ of the mean (Mahalanobis) is seen within
//! `W = atan(6.5σ_t / (|μ| − 6.5σ₁))` of `arg μ`; directions beyond the arc,
//! and the rays opposite to it, carry less than `e^{−6.5²/2}` = 7·10⁻¹⁰ of
//! the mass, far below the 2·10⁻⁴ to which `amplitude_95` solves for 95 %.
//! The integrand over the arc is smooth and vanishes to that level at both
//! ends, where the trapezoidal rule converges
//! geometrically (spacing `h` leaves about `e^{−2π²(σ_θ/h)²}`); the rule is
//! doubled from 8 intervals until two successive sums agree (`polar::agree`),
//! comparing only levels fine enough to see a mass thin across (`σ₂/|μ|` in
//! angle); one too thin for the finest level goes to the quadrature.

use super::polar::agree;
use super::ray::{add, Axes, Ray};

/// The mean is far from the origin when `|μ| ≥ FAR σ₁`.
const FAR: f64 = 8.0;
/// Standard deviations (Mahalanobis) of the mass that the arc holds: what
/// lies beyond has probability `e^{−REACH²/2}` = 7·10⁻¹⁰.
const REACH: f64 = 6.5;
/// Agreement of two successive sums, `P` absolute and `P'` relative: the
/// coarse levels of the arc rule are not yet in its fast convergence (sums
/// agreeing to 10⁻⁸ were up to 3·10⁻⁷ off), so it keeps the 10⁻¹⁰ that
/// `polar` relaxed in issue 15's session 7.
const TOL: [f64; 2] = [1e-10, 1e-8];
/// Level `l` has `8·2^l` intervals over the arc.
const MAX_LEVEL: usize = 7;

/// The rule for one row: rays at the nodes built so far, in the order of
/// their levels (level 0: the 9 nodes from end to end; level `l ≥ 1`: the
/// `8·2^(l−1)` midpoints it adds).
pub(in crate::balancing::uncertainty) struct Arc {
    axes: Axes,
    centre: f64,
    half: f64,
    /// The first level whose sum is compared with the next one.
    start: usize,
    rays: Vec<Ray>,
}

impl Arc {
    /// The rule for `N((μ₁, μ₂), diag(σ₁², σ₂²))`, `σ₁ ≥ σ₂`; `None` unless
    /// the mean is far from the origin beside `σ₁`.
    pub(in crate::balancing::uncertainty) fn new(
        mu1: f64,
        mu2: f64,
        s1: f64,
        s2: f64,
    ) -> Option<Self> {
        let m = mu1.hypot(mu2);
        if !(m >= FAR * s1 && s2 > 0.0 && m.is_finite()) {
            return None;
        }
        let (u1, u2) = (mu1 / m, mu2 / m);
        let across = (u2 * s1).hypot(u1 * s2);
        let half = (REACH * across / (m - REACH * s1)).atan();
        // A mass thin across (σ₂) makes the ray integrals change within about
        // `σ₂/|μ|` in angle: sums are compared only from the level whose
        // spacing is at most twice that (as in `polar`), so that no two
        // coarse sums agree by both stepping over it; a mass too thin for the
        // finest level is left to the quadrature.
        let width = s2 / m;
        let spacing = |l: usize| 2.0 * half / f64::from(8u32 << l);
        let start = (0..MAX_LEVEL).find(|&l| spacing(l) <= 2.0 * width)?;
        Some(Self {
            axes: Axes::new(mu1, mu2, s1, s2),
            centre: mu2.atan2(mu1),
            half,
            start,
            rays: Vec::with_capacity(65),
        })
    }

    /// Position in `[−1, 1]` of node `i` in level order.
    fn node(i: usize) -> f64 {
        if i <= 8 {
            return -1.0 + i as f64 / 4.0;
        }
        // Level l ≥ 1 holds nodes 8·2^(l−1) + 1 ..= 8·2^l: its k-th is the
        // odd multiple 2k + 1 of the level's spacing 2/(8·2^l) from −1.
        let l = Self::level(i);
        let k = i - 1 - (8 << (l - 1));
        -1.0 + (2 * k + 1) as f64 / f64::from(4u32 << l)
    }

    /// Rays at the first `n` nodes.
    /// The nodes of a level are equally spaced: one `sin_cos` for its first
    /// and one for its step, then rotations (a `sin_cos` per node was a
    /// third of the two-plane solve's bound).
    fn build(&mut self, n: usize) {
        let mut i = self.rays.len();
        while i < n {
            let (end, dx) = match Self::level(i) {
                0 => (9, 0.25),
                l => ((8 << l) + 1, 2.0 / f64::from(4u32 << l)),
            };
            let end = end.min(n);
            let (mut s, mut c) = (self.centre + self.half * Self::node(i)).sin_cos();
            let (ds, dc) = (self.half * dx).sin_cos();
            for _ in i..end {
                self.rays.push(self.axes.ray(c, s));
                (c, s) = (c * dc - s * ds, s * dc + c * ds);
            }
            i = end;
        }
    }

    /// The level node `i` belongs to.
    fn level(i: usize) -> usize {
        if i <= 8 {
            0
        } else {
            (usize::BITS - (i - 1).leading_zeros()) as usize - 3
        }
    }

    /// `[P(ρ), P'(ρ)]`, or `None` where the rule did not converge (the
    /// tests' view of [`Self::moments`]).
    #[cfg(test)]
    pub(in crate::balancing::uncertainty) fn inside(&mut self, rho: f64) -> Option<[f64; 2]> {
        self.moments(rho).map(|[p, dp, ..]| [p, dp])
    }

    /// `[P, P', P'', P''']` at ρ, or `None` where the rule did not converge
    /// (convergence is judged on `P` and `P'`).
    pub(in crate::balancing::uncertainty) fn moments(&mut self, rho: f64) -> Option<[f64; 4]> {
        let mut inner = [0.0; 4];
        let mut last: Option<[f64; 2]> = None;
        let mut done = 0;
        for l in 0..=MAX_LEVEL {
            let n = (8 << l) + 1;
            self.build(n);
            for (i, ray) in self.rays[done..n].iter().enumerate() {
                let v = ray.ahead(rho);
                // The two ends of the arc (level 0's first and last node) weigh ½.
                let w = if done + i == 0 || done + i == 8 {
                    0.5
                } else {
                    1.0
                };
                add(&mut inner, v.map(|x| w * x));
            }
            done = n;
            // Spacing 2W/(8·2^l); the density is over the full turn's 2π.
            let h = 2.0 * self.half / f64::from(8u32 << l) / std::f64::consts::TAU;
            let now = inner.map(|x| x * h);
            if agree(last, [now[0], now[1]], TOL) {
                return Some(now);
            }
            if l >= self.start {
                last = Some([now[0], now[1]]);
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nodes_of_each_level_halve_the_spacing_of_the_one_before() {
        let mut seen: Vec<f64> = Vec::new();
        for l in 0..=4usize {
            let n = (8 << l) + 1;
            seen.extend((seen.len()..n).map(Arc::node));
            let mut sorted = seen.clone();
            sorted.sort_by(f64::total_cmp);
            let step = 2.0 / f64::from(8u32 << l);
            for (j, x) in sorted.iter().enumerate() {
                assert!(
                    (x - (-1.0 + j as f64 * step)).abs() < 1e-15,
                    "level {l}: {sorted:?}"
                );
            }
        }
    }
}
