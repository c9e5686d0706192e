//! `P(|R| ≤ ρ)` and its derivative in ρ for a Gaussian `R` in the plane, by
//! the trapezoidal rule over the direction from the origin with the integral
//! along each ray in closed form: the fast path of `amplitude_95` (issue 15).
//!
//! In the principal axes (`R = (x, y)`, `x ~ N(μ₁, σ₁²)`, `y ~ N(μ₂, σ₂²)`
//! independent) the density along the ray `r·(cos θ, sin θ)` is
//! `exp(−½(A r² − 2B r + C)) / (2π σ₁σ₂)` with `A = cos²θ/σ₁² + sin²θ/σ₂²`,
//! `B = μ₁cos θ/σ₁² + μ₂ sin θ/σ₂²`, `C = μ₁²/σ₁² + μ₂²/σ₂²`. Completing the
//! square (`r₀ = B/A`, `E = C − B r₀ ≥ 0`), the integral along a ray is
//! `∫₀^ρ r e^{−½A(r−r₀)²} dr = (e^{−½A r₀²} − e^{−½A(ρ−r₀)²})/A +
//! r₀ √(2π/A) [Φ(√A(ρ−r₀)) − Φ(−√A r₀)]`,
//! so `P(ρ) = ∫₀^{2π} e^{−E/2} (that)/(2π σ₁σ₂) dθ` and
//! `P'(ρ) = ∫₀^{2π} ρ e^{−E/2} e^{−½A(ρ−r₀)²}/(2π σ₁σ₂) dθ`. Both integrands
//! are smooth and periodic in θ, where the trapezoidal rule converges
//! geometrically (exactly, for `μ = 0` and `σ₁ = σ₂`). The rule is doubled
//! from 8 directions until two successive sums agree to [`TOL_P`] in
//! probability and [`TOL_D`] relative in density (the error of the finer one
//! is then far smaller still); if that takes more than [`MAX_LEVEL`]
//! doublings, or the mass is too narrow in angle for the coarse rule to see
//! it, the caller falls back to the adaptive quadrature.
//!
//! Off the origin the integrand is a bump about `σ_t/|μ|` wide around the
//! mean's direction θ₀ (`σ_t` the spread across μ), where equally spaced
//! directions waste their rays (rows 2–8σ out needed 256–512). So the rule
//! runs in φ with `tan((θ − θ₀)/2) = s tan(φ/2)`, `s = min(1, 2σ_t/|μ|)`,
//! weight `θ'(φ) = s/(cos²(φ/2) + s² sin²(φ/2))`: an analytic periodic map
//! of the circle, so convergence stays geometric, with the nodes `s` times
//! closer near θ₀ (rows 2–13σ out: 64 nodes; issue 15, session 6). Where
//! `s = 1` (the mean within `2σ_t` of the origin) the rule is unmapped and a
//! direction and its opposite share their ray (`A`, `E`, `C`).
//!
//! What does not depend on ρ (per direction `A`, `r₀`, `e^{−E/2}`,
//! `Φ(−√A r₀)`; `e^{−E/2} e^{−½A r₀²} = e^{−C/2}` for all) is computed once
//! per row. Per Newton step and direction: one exponential for `μ = 0`, an
//! exponential and a `Φ` otherwise.

use std::sync::OnceLock;

use super::ray::{add, Axes, Ray};

/// Agreement in probability of two successive trapezoidal sums. The rules
/// converge at least geometrically, each level halving the error far more
/// than twice, so the finer sum is then within about 10⁻⁸ and usually far
/// closer (the tests hold it to 10⁻⁷ against the quadrature). Agreement to
/// 10⁻¹⁰, before issue 15's session 7, often took one level more than the
/// 10⁻⁷ to which `amplitude_95` solves; agreement to 10⁻⁵ (the square law of
/// geometric convergence) let coarse sums through 6·10⁻⁶ off.
const TOL_P: f64 = 1e-8;
/// Agreement of two successive sums of the density, relative.
const TOL_D: f64 = 1e-6;
/// Level `l` has `8·2^l` directions over the full turn (off the origin:
/// nodes of the mapped rule); the finest has 512.
const MAX_LEVEL: usize = 6;
/// Entries of the direction table: the off-centre rule's finest level.
const HALF: usize = 8 << MAX_LEVEL;
/// The map's squeeze over the mass's angular spread (module doc).
const SQUEEZE: f64 = 2.0;

/// Two successive sums `[P, P']` of a rule agree: `P` to `tol[0]`, `P'` to
/// `tol[1]` relative (`arc` uses the same test, with its own tolerances).
pub(in crate::balancing::uncertainty) fn agree(
    prev: Option<[f64; 2]>,
    now: [f64; 2],
    tol: [f64; 2],
) -> bool {
    prev.is_some_and(|prev| {
        (now[0] - prev[0]).abs() <= tol[0] && (now[1] - prev[1]).abs() <= tol[1] * now[1].abs()
    })
}

/// Cos and sin of the directions in `[0, π)`, coarse levels first: `kπ/4`
/// (k < 4), then level `l ≥ 1`'s odd multiples of `π/(4·2^l)`. The first
/// `4·2^l` are the centred rule's level `l`; the first `8·2^l`, as `φ/2`, the
/// off-centre rule's.
fn directions() -> &'static [(f64, f64); HALF] {
    static TABLE: OnceLock<[(f64, f64); HALF]> = OnceLock::new();
    TABLE.get_or_init(|| {
        let mut t = [(0.0, 0.0); HALF];
        let mut n = 0;
        for l in 0..=MAX_LEVEL + 1 {
            // (multiple of `step`, step): kπ/4, then the odd multiples of π/(4·2^l).
            let step = std::f64::consts::PI / f64::from(4u32 << l);
            let count: u32 = if l == 0 { 4 } else { 4 << (l - 1) };
            // Rotations, exact every 16th entry so that rounding cannot build
            // up (a `sin_cos` per entry cost 80 k instructions once).
            let turn = if l == 0 { step } else { 2.0 * step };
            let (ds, dc) = turn.sin_cos();
            let (mut c, mut s) = (1.0, 0.0);
            for k in 0..count {
                let j = if l == 0 { k } else { 2 * k + 1 };
                if k % 16 == 0 {
                    (s, c) = (step * f64::from(j)).sin_cos();
                } else {
                    (c, s) = (c * dc - s * ds, s * dc + c * ds);
                }
                t[n] = (c, s);
                n += 1;
            }
        }
        t
    })
}

/// The rule for one row: the rays computed so far, coarse levels first.
pub(in crate::balancing::uncertainty) struct Polar {
    axes: Axes,
    central: bool,
    /// Off the origin but unmapped (`s = 1`): rays in `[0, π)`, each also
    /// summed for its opposite direction ([`Ray::behind`]), which halves the
    /// per-ray work of rows near the origin.
    paired: bool,
    start: usize,
    /// Off the origin: `(cos θ₀, sin θ₀)` of the mean's direction and the
    /// squeeze `s` of the map that gathers the nodes there (module doc).
    towards: (f64, f64),
    squeeze: f64,
    /// Filled lazily up to the finest level used. Centred or paired: one ray
    /// per direction in `[0, π)`; mapped: one per node, weight `θ'(φ)` in `k`.
    rays: Vec<Ray>,
}

impl Polar {
    /// The rule for `N((μ₁, μ₂), diag(σ₁², σ₂²))`, `σ₁ ≥ σ₂`; `None` where
    /// the mass is too narrow in angle for the finest level (then the
    /// quadrature is used).
    pub(in crate::balancing::uncertainty) fn new(
        mu1: f64,
        mu2: f64,
        s1: f64,
        s2: f64,
    ) -> Option<Self> {
        // Angular width of the mass seen from the origin: at least σ₂ over
        // the larger of |μ| and σ₁. Start where the spacing (at θ₀, where
        // the map packs the nodes) is at most twice that, so that no coarse
        // rule can step over the mass and agree with the next by both missing it.
        let m = mu1.hypot(mu2);
        let width = s2 / m.max(s1);
        if !(width > 0.0 && width.is_finite()) {
            return None;
        }
        // A mean within 10⁻⁶σ₂ of the origin (exact data leave 10⁻¹² of
        // rounding) moves P by under 10⁻¹²: the centred rule, half the cost.
        let central = m <= 1e-6 * s2;
        let (towards, squeeze) = if central {
            ((1.0, 0.0), 1.0)
        } else {
            // The mass spans about `σ_t/|μ|` in angle (module doc).
            let (u1, u2) = (mu1 / m, mu2 / m);
            let across = (u2 * s1).hypot(u1 * s2);
            ((u1, u2), (SQUEEZE * across / m).min(1.0))
        };
        let paired = !central && squeeze >= 1.0;
        let spacing = |l: usize| squeeze * std::f64::consts::TAU / f64::from(8u32 << l);
        let start = (0..MAX_LEVEL).find(|&l| spacing(l) <= 2.0 * width)?;
        Some(Self {
            axes: Axes::new(mu1, mu2, s1, s2),
            central,
            paired,
            start,
            towards,
            squeeze,
            rays: Vec::with_capacity(8 << (start + 1)),
        })
    }

    /// Rays up to `n` entries of the direction table.
    fn build(&mut self, n: usize) {
        let table = directions();
        let (c0, s0) = self.towards;
        let q = self.squeeze;
        for &(c, s) in &table[self.rays.len()..n.max(self.rays.len())] {
            let ray = if self.central {
                let (a, _) = self.axes.ab(c, s);
                Ray {
                    a,
                    inv_a: 1.0 / a,
                    sa: a.sqrt(),
                    r0: 0.0,
                    k: self.axes.k,
                    ke0: self.axes.k,
                    kphi: 0.0,
                    c0: 0.5,
                }
            } else if self.paired {
                self.axes.ray(c, s)
            } else {
                // The table's (cos, sin) of φ/2; θ − θ₀ = 2 atan(s tan(φ/2)),
                // θ'(φ) = s/(cos²(φ/2) + s² sin²(φ/2)).
                let (cc, ss) = (c * c, q * q * s * s);
                let den = 1.0 / (cc + ss);
                let (cd, sd) = ((cc - ss) * den, 2.0 * q * s * c * den);
                self.axes
                    .ray(c0 * cd - s0 * sd, s0 * cd + c0 * sd)
                    .weighted(q * den)
            };
            self.rays.push(ray);
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
        let mut sum = [0.0; 4];
        let mut last: Option<[f64; 2]> = None;
        let mut done = 0;
        for l in 0..=MAX_LEVEL {
            // Centred or paired: `4·2^l` directions in [0, π) and their
            // opposites; mapped: `8·2^l` nodes φ over the full turn.
            let half_turn = self.central || self.paired;
            let n = if half_turn { 4 << l } else { 8 << l };
            self.build(n);
            for ray in &self.rays[done..n] {
                if self.central {
                    // `along` with r₀ = 0 for both directions.
                    let a = ray.a;
                    let e = (-0.5 * a * rho * rho).exp();
                    let g = 2.0 * ray.k * e;
                    let arr = a * rho * rho;
                    sum[0] += 2.0 * ray.k * (1.0 - e) * ray.inv_a;
                    sum[1] += g * rho;
                    sum[2] += g * (1.0 - arr);
                    sum[3] += g * a * rho * (arr - 3.0);
                } else {
                    add(&mut sum, ray.ahead(rho));
                    if self.paired {
                        add(&mut sum, ray.behind(rho));
                    }
                }
            }
            done = n;
            // The trapezoidal rule over the full turn.
            let nodes = if half_turn { 2 * n } else { n };
            let now = sum.map(|x| x / nodes as f64);
            if agree(last, [now[0], now[1]], [TOL_P, TOL_D]) {
                return Some(now);
            }
            if l >= self.start {
                last = Some([now[0], now[1]]);
            }
        }
        None
    }
}
