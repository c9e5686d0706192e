//! The extremes of a correction's confidence ellipse seen from the origin, in
//! closed form (issue 15): the nearest and farthest boundary points (the mass
//! interval) and the two tangent points from the origin (the angle interval),
//! where `region` used to sample the boundary and refine each extreme.
//!
//! The ellipse is `{z : (z − c)ᵀ Σ⁻¹ (z − c) ≤ k²}` with `Σ = Σᵢ λᵢ vᵢ vᵢᵀ`;
//! in its principal axes the boundary is `c + (a₁ cos t, a₂ sin t)`,
//! `aᵢ = k √λᵢ`, `a₁ ≥ a₂ ≥ 0` (`a₂ = 0`: a segment, a singular `Σ`).

use nalgebra::Vector2;
use num_complex::Complex64;

/// A confidence ellipse: centre, principal variances (larger first) and axes.
pub(super) struct Ellipse {
    c: Complex64,
    lam: [f64; 2],
    v: [Vector2<f64>; 2],
    /// Semi-axes `k √λᵢ`.
    a: [f64; 2],
    /// The origin relative to the centre, in the principal axes: `−vᵢ·c`.
    q: [f64; 2],
    k: f64,
}

impl Ellipse {
    /// `axes` as `region::axes` gives them: `(λ, v)`, `λ₁ ≥ λ₂ ≥ 0`.
    pub(super) fn new(c: Complex64, axes: &[(f64, Vector2<f64>); 2], k: f64) -> Self {
        let lam = [axes[0].0, axes[1].0];
        let v = [axes[0].1, axes[1].1];
        Ellipse {
            c,
            lam,
            v,
            a: lam.map(|l| k * l.sqrt()),
            q: v.map(|v| -(v.x * c.re + v.y * c.im)),
            k,
        }
    }

    /// The largest `|z|` on the boundary. The farthest point from `q` is
    /// `uᵢ = qᵢ aᵢ²/(aᵢ² + s)` with `s < −a₁²` the one root there of
    /// `Σ (aᵢqᵢ/(aᵢ² + s))² = 1` (Lagrange; Eberly, "Distance from a point
    /// to an ellipse"); with `τ = −s − a₁²` that is [`secular`]'s equation.
    pub(super) fn farthest(&self) -> f64 {
        let [a1, a2] = self.a;
        let alpha = [a1 * self.q[0], a2 * self.q[1]];
        let w = secular(alpha, [0.0, a1 * a1 - a2 * a2]);
        (-a1 * w[0] - self.q[0]).hypot(-a2 * w[1] - self.q[1])
    }

    /// The smallest `|z|` on the boundary, the origin outside the ellipse:
    /// `uᵢ = qᵢ aᵢ²/(aᵢ² + s)` with the root `s > 0` (a segment: the
    /// projection of the origin when it falls inside it, `s = 0`).
    pub(super) fn nearest(&self) -> f64 {
        let [a1, a2] = self.a;
        let alpha = [a1 * self.q[0], a2 * self.q[1]];
        let w = secular(alpha, [a1 * a1, a2 * a2]);
        (a1 * w[0] - self.q[0]).hypot(a2 * w[1] - self.q[1])
    }

    /// The least and greatest `arg(z c̄)` (radians) over the ellipse, the
    /// origin outside it: the two tangent points from the origin. A line
    /// `nᵀz = 0` touches the ellipse where `|nᵀc| = k √(nᵀΣn)`, i.e. `n` is a
    /// null vector of `M = c cᵀ − k²Σ` (indefinite when the origin is
    /// outside); it touches at the support point `c ∓ k Σn/√(nᵀΣn)`.
    pub(super) fn tangent_offsets(&self) -> (f64, f64) {
        let ([l1, l2], k2) = (self.lam, self.k * self.k);
        let p = [-self.q[0], -self.q[1]];
        let (m11, m12, m22) = (p[0] * p[0] - k2 * l1, p[0] * p[1], p[1] * p[1] - k2 * l2);
        // −det M = k²(cᵀ adj(Σ) c − k² det Σ), without the cancellation of m12² − m11 m22.
        let disc = (k2 * (l2 * p[0] * p[0] + l1 * p[1] * p[1] - k2 * l1 * l2)).max(0.0);
        // The roots of m11 x² + 2 m12 x + m22 = 0 (x = n₁/n₂) without
        // cancellation, as homogeneous vectors: (h, m11) and (m22, h).
        let h = -(m12 + m12.signum() * disc.sqrt());
        let offset = |n: [f64; 2]| {
            let s = l1 * n[0] * n[0] + l2 * n[1] * n[1];
            if s.is_nan() || s <= 0.0 {
                // Σn = 0 along n: a segment pointing at the origin.
                return 0.0;
            }
            let f = (n[0] * p[0] + n[1] * p[1]).signum() * self.k / s.sqrt();
            let (u1, u2) = (p[0] - f * l1 * n[0], p[1] - f * l2 * n[1]);
            let z = self.v[0] * u1 + self.v[1] * u2;
            (Complex64::new(z.x, z.y) * self.c.conj()).arg()
        };
        let (x, y) = (offset([h, m11]), offset([m22, h]));
        (x.min(y), x.max(y))
    }
}

/// The unit vector `w`, `wᵢ = αᵢ/(x + βᵢ)`, at the root `x > 0` of
/// `g(x) = Σ (αᵢ/(x + βᵢ))² − 1` (`βᵢ ≥ 0`; convex and decreasing for
/// `x > 0`), or at `x = 0` when `g(0) ≤ 0`; a `wᵢ` whose `x + βᵢ` is 0 (then
/// `αᵢ = 0`, a degenerate ellipse or point) is whatever completes `|w| = 1`.
///
/// Newton's method from the left of the root, `x₀ = maxᵢ(|αᵢ| − βᵢ)` (where
/// one term alone is 1), climbs monotonically to it: the tangent of a convex
/// decreasing function lies below it. The distance is stationary in the
/// point's position along the ellipse, so `w` normalised onto the circle
/// gives it to rounding.
fn secular(alpha: [f64; 2], beta: [f64; 2]) -> [f64; 2] {
    // A zero αᵢ contributes nothing, whatever x + βᵢ (no 0/0).
    let term = |x: f64, i: usize| {
        if alpha[i] == 0.0 {
            [0.0, 0.0]
        } else {
            let t = alpha[i] / (x + beta[i]);
            [t, t * t / (x + beta[i])]
        }
    };
    let mut x = (0..2).fold(0.0_f64, |m, i| m.max(alpha[i].abs() - beta[i]));
    // 200 steps: far more than the ~6 this needs from x₀ (the root is at most √2 x₀ away).
    for _ in 0..200 {
        let ([t0, d0], [t1, d1]) = (term(x, 0), term(x, 1));
        let g = t0 * t0 + t1 * t1 - 1.0;
        if g.is_nan() || g <= 0.0 {
            break;
        }
        let dg = -2.0 * (d0 + d1);
        let step = -g / dg;
        if step.is_nan() || step <= 1e-16 * x || step.is_infinite() {
            break;
        }
        x += step;
    }
    let w = [0, 1].map(|i| (x + beta[i] > 0.0).then(|| term(x, i)[0]));
    let w = match w {
        [Some(w0), Some(w1)] => [w0, w1],
        [Some(w0), None] => [w0, (1.0 - w0 * w0).max(0.0).sqrt()],
        [None, Some(w1)] => [(1.0 - w1 * w1).max(0.0).sqrt(), w1],
        [None, None] => [1.0, 0.0],
    };
    let norm = w[0].hypot(w[1]);
    if norm > 0.0 {
        w.map(|x| x / norm)
    } else {
        [1.0, 0.0]
    }
}

#[cfg(test)]
#[path = "ellipse_tests.rs"]
mod tests;
