//! `P(|R| ≤ ρ)` and its first three derivatives in ρ for a Gaussian `R` in
//! the plane, by the trapezoidal rule over the direction seen from the MEAN
//! in the Gaussian's own (whitened) coordinates: `amplitude_95`'s rule for
//! every row (issue 15, session 8; method §8, formula 8.6).
//!
//! In the principal axes `R = μ + L w`, `L = diag(σ₁, σ₂)`, `w` standard
//! normal. Along the ray `w = r (cos θ, sin θ)` the disc `|R| ≤ ρ` is
//! `a r² + 2 b r − n ≤ 0` with `a = σ₁² cos²θ + σ₂² sin²θ`,
//! `b = μ₁σ₁ cos θ + μ₂σ₂ sin θ`, `n = ρ² − |μ|²`. The quantile lies above
//! `|μ|` (`region::quantile`), so `n > 0`: the mean is inside the disc and
//! every ray leaves it once, at `r₊ = (√d − b)/a = n/(b + √d)`,
//! `d = b² + a n`. With `w`'s density `r e^{−r²/2}/2π` in polar form,
//! `1 − P(ρ) = (1/2π) ∫ e^{−r₊²/2} dθ` — no `Φ` and no per-row constants
//! (the rule before, centred at the origin, needed an `exp` and a `Φ` per
//! direction and per ρ, and as much again to set up each direction). With
//! `r₊' = ρ/√d`, `r₊'' = (1 − aρ²/d)/√d`, `r₊''' = 3aρ(aρ²/d − 1)/d^{3/2}`
//! and `h = r₊r₊'`: `P' = ⟨h g⟩`, `P'' = ⟨(h' − h²) g⟩`,
//! `P''' = ⟨(h'' − 3hh' + h³) g⟩`, `g = e^{−r₊²/2}`, `⟨·⟩` the mean over θ.
//! A direction and its opposite share `a`, `d` and the derivatives of `r₊`.
//!
//! How many directions: the integrand is periodic and analytic in the strip
//! `|Im θ| < α`, where the trapezoidal rule's error falls as `e^{−αN}`
//! (Davis 1959; Trefethen and Weideman, "The exponentially convergent
//! trapezoidal rule", SIAM Review 56, 2014, Thm 3.2: `≤ 2M/(e^{αN} − 1)` in
//! the mean, `M` the bound of `|e^{−r₊²/2}|` in the strip). The integrand
//! is singular where `d = 0` (branch points of `√d`) and where `a = 0`
//! (poles of `r₊` on the far side): `d` is a quadratic form in
//! `(cos θ, sin θ)`, zero at `tan θ = t` with `t` a root of
//! `σ₁²(μ₁² + n) + 2μ₁μ₂σ₁σ₂ t + σ₂²(μ₂² + n) t² = 0`, at `|Im θ| =
//! |Im atan t|`; `a = 0` at `|Im θ| = atanh(σ₂/σ₁)`. So `α` follows from the
//! eccentricity and `|μ|`, `n` in closed form ([`Polar::strip`]), and the
//! rule takes `N = ⌈`[`BUDGET`]`/α⌉` directions without a second, finer sum
//! to confirm it. `BUDGET` stands for `ln(2M/ε)`: on 1500 seeded rows (mean
//! 0 to 10⁴σ₁, `σ₂/σ₁` 0 to 1, at the quantile) the fewest directions that
//! put `P` within 10⁻⁹ and `P'` within 10⁻⁷ had `αN ≤ 28.2`; 32 leaves a
//! factor `e^{3.8}`, and 3000 points anywhere in the bracket were within
//! 1.5·10⁻¹⁰. The large least-squares job (means near the origin,
//! `σ₂/σ₁ > 0.86`) takes 10 to 16 directions, the min-max rows 30 to 64.
//! Where `α` asks for more than [`A_PRIORI`] (thin masses, far means, ρ near
//! `|μ|`) the bound is loose (`M` is tiny there), so the rule doubles from
//! `A_PRIORI` until two nested sums agree (the finer one is then far closer
//! still); past [`NESTED`] directions the caller uses the quadrature.

use super::quadrature;

/// `αN` of the a priori rule, `ln(2M/ε)` of the error bound (module doc).
const BUDGET: f64 = 32.0;
/// The most directions taken on the a priori bound alone.
const A_PRIORI: usize = 80;
/// The most directions of the doubling rule.
const NESTED: usize = 1280;
/// Agreement of two nested sums: `P` absolute, `P'` relative.
const TOL: [f64; 2] = [1e-9, 1e-7];
/// Directions with `r₊²/2` beyond this carry `e^{−40}` = 4·10⁻¹⁸: their
/// `exp` is skipped (the far side of a far mean, the long axis of a thin one).
const NEGLIGIBLE: f64 = 40.0;

/// The rule for one row: `N((μ₁, μ₂), diag(σ₁², σ₂²))`, `σ₁ ≥ σ₂ ≥ 0`.
pub(in crate::balancing::uncertainty) struct Polar {
    /// `μ₁σ₁`, `μ₂σ₂`, `σ₁²`, `σ₂²`.
    ms: [f64; 2],
    var: [f64; 2],
    mu: [f64; 2],
    s: [f64; 2],
    /// `|μ|²`.
    m2: f64,
    /// `atanh(σ₂/σ₁)`: the strip up to the poles where `a = 0`.
    poles: f64,
}

impl Polar {
    /// The rule for `N((μ₁, μ₂), diag(σ₁², σ₂²))`, `σ₁ ≥ σ₂ ≥ 0`; `None`
    /// without a finite positive `σ₁` or a finite mean.
    pub(in crate::balancing::uncertainty) fn new(
        mu1: f64,
        mu2: f64,
        s1: f64,
        s2: f64,
    ) -> Option<Self> {
        let sane = s1 > 0.0 && s1.is_finite() && (0.0..=s1).contains(&s2);
        (sane && mu1.is_finite() && mu2.is_finite()).then(|| Self {
            ms: [mu1 * s1, mu2 * s2],
            var: [s1 * s1, s2 * s2],
            mu: [mu1, mu2],
            s: [s1, s2],
            m2: mu1 * mu1 + mu2 * mu2,
            poles: (s2 / s1).atanh(),
        })
    }

    /// `α` of the module doc for `n = ρ² − |μ|² > 0`.
    fn strip(&self, n: f64, rho: f64) -> f64 {
        let ([m1, m2], [s1, s2]) = (self.mu, self.s);
        let c = self.var[1] * (m2 * m2 + n);
        if c.is_nan() || c <= 0.0 {
            return 0.0;
        }
        // Roots `u ± iv` of the quadratic in t; its discriminant is
        // `−(σ₁σ₂ρ)² n`. `Im atan(u + iv) = ¼ ln((u² + (1+v)²)/(u² + (1−v)²))`.
        let (u, v) = (-m1 * m2 * s1 * s2 / c, s1 * s2 * rho * n.sqrt() / c);
        let branch = 0.25 * ((u * u + (1.0 + v).powi(2)) / (u * u + (1.0 - v).powi(2))).ln();
        branch.abs().min(self.poles)
    }

    /// `[P(ρ), P'(ρ)]`, or `None` where the rule does not apply or did not
    /// converge (the tests' view of [`Self::moments`]).
    #[cfg(test)]
    pub(in crate::balancing::uncertainty) fn inside(&mut self, rho: f64) -> Option<[f64; 2]> {
        self.moments(rho).map(|[p, dp, ..]| [p, dp])
    }

    /// `[P, P', P'', P''']` at ρ (for `ρ ≤ |μ|` the quadrature's `[P, P']`,
    /// the others NaN); `None` where the doubling rule did not converge.
    pub(in crate::balancing::uncertainty) fn moments(&mut self, rho: f64) -> Option<[f64; 4]> {
        let n = rho * rho - self.m2;
        if !n.is_finite() {
            return None;
        }
        if n <= 0.0 {
            // Below |μ|, outside `amplitude_95`'s bracket (only the tests ask):
            // the rays that meet the disc do so between two roots, and the
            // integrand has square-root ends at the tangent directions, where
            // the trapezoidal rule converges slowly. The quadrature answers.
            let ([mu1, mu2], [s1, s2]) = (self.mu, self.s);
            let [p, dp] = quadrature::inside(mu1, mu2, s1, s2, rho);
            return Some([p, dp, f64::NAN, f64::NAN]);
        }
        let alpha = self.strip(n, rho);
        if alpha * A_PRIORI as f64 >= BUDGET {
            let count = ((BUDGET / alpha).ceil() as usize).clamp(4, A_PRIORI);
            let count = count + count % 2;
            return Some(mean(self.sum(rho, n, count, false), count));
        }
        let mut count = A_PRIORI / 2;
        let mut sum = self.sum(rho, n, count, false);
        let mut last = mean(sum, count);
        while count < NESTED {
            // The nodes halfway between the present ones.
            let odd = self.sum(rho, n, count, true);
            sum = [0, 1, 2, 3].map(|i| sum[i] + odd[i]);
            count *= 2;
            let now = mean(sum, count);
            if (now[0] - last[0]).abs() <= TOL[0] && (now[1] - last[1]).abs() <= TOL[1] * now[1] {
                return Some(now);
            }
            last = now;
        }
        None
    }

    /// Sums over the `count` (even) directions `θ = 2π(k + ½·shifted)/count`
    /// of `[g, h g, (h' − h²) g, (h'' − 3hh' + h³) g]`.
    fn sum(&self, rho: f64, n: f64, count: usize, shifted: bool) -> [f64; 4] {
        let step = std::f64::consts::TAU / count as f64;
        let (ds, dc) = step.sin_cos();
        let (mut s, mut c) = if shifted {
            (0.5 * step).sin_cos()
        } else {
            (0.0, 1.0)
        };
        let mut acc = [0.0; 4];
        // A direction and its opposite: same `a` and `d`, `b` of either sign.
        for _ in 0..count / 2 {
            let a = self.var[0] * c * c + self.var[1] * s * s;
            let b = (self.ms[0] * c + self.ms[1] * s).abs();
            let d = b * b + a * n;
            let sq = d.sqrt();
            let r1 = rho / sq;
            let ar = a * rho * rho / d;
            let r2 = (1.0 - ar) / sq;
            let r3 = 3.0 * a * rho / (sq * d) * (ar - 1.0);
            // Towards growing |R| (`b ≥ 0`) in the stable form, and away.
            for r in [n / (b + sq), (sq + b) / a] {
                // Also skips the infinite and NaN `r₊` of a ray that never
                // leaves the disc (`a = 0`, `σ₂ = 0`): it contributes 0.
                let half = 0.5 * r * r;
                if half.is_nan() || half > NEGLIGIBLE {
                    continue;
                }
                let g = (-half).exp();
                let h = r * r1;
                let h1 = r1 * r1 + r * r2;
                let h2 = 3.0 * r1 * r2 + r * r3;
                acc[0] += g;
                acc[1] += h * g;
                acc[2] += (h1 - h * h) * g;
                acc[3] += (h2 - 3.0 * h * h1 + h * h * h) * g;
            }
            (c, s) = (c * dc - s * ds, s * dc + c * ds);
        }
        acc
    }
}

/// `[P, P', P'', P''']` from the sums over `count` directions.
fn mean(sum: [f64; 4], count: usize) -> [f64; 4] {
    let w = 1.0 / count as f64;
    [1.0 - sum[0] * w, sum[1] * w, sum[2] * w, sum[3] * w]
}
