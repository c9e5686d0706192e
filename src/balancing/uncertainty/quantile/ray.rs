//! One direction of the polar rules (`polar`, `arc`): what its ray
//! contributes to `P(|R| ≤ ρ)` and its derivatives in ρ, in closed form
//! along the ray (the formulas are in `polar`'s module doc), and the
//! Gaussian's principal-axes constants the rays share.

use super::super::region::normal_cdf;

/// Rays whose `E/2` of `polar`'s module doc exceeds this carry under `e^{−60}`
/// (10⁻²⁶) of the density's peak: nothing in 10⁻¹⁰, even summed over every
/// node and weighted by the map. Their `exp` and `Φ` are skipped (issue 15,
/// session 7): the mapped rule's nodes on the far side of the turn.
const NEGLIGIBLE: f64 = 60.0;

/// What a direction contributes that does not depend on ρ.
#[derive(Clone, Copy)]
pub(super) struct Ray {
    /// `A`, `1/A` and `√A`.
    pub(super) a: f64,
    pub(super) inv_a: f64,
    pub(super) sa: f64,
    /// `r₀` of the direction.
    pub(super) r0: f64,
    /// `k = e^{−E/2}/(σ₁σ₂)` (times the node's weight, where there is one).
    pub(super) k: f64,
    /// `k e^{−½A r₀²} = e^{−C/2}/(σ₁σ₂)` (`E + A r₀² = C`), times the weight.
    pub(super) ke0: f64,
    /// `k r₀ √(2π/A)`.
    pub(super) kphi: f64,
    /// `Φ(−√A r₀)`.
    pub(super) c0: f64,
}

impl Ray {
    /// The direction with `A`, `B` of `polar`'s module doc, for `C` = `c`,
    /// `1/(σ₁σ₂)` = `k` and `e^{−C/2}/(σ₁σ₂)` = `kc`.
    fn off_centre(a: f64, b: f64, c: f64, k: f64, kc: f64) -> Ray {
        let r0 = b / a;
        let sa = a.sqrt();
        let e = (c - b * r0).max(0.0);
        if 0.5 * e > NEGLIGIBLE {
            // `e^{−C/2} ≤ e^{−E/2}`: `ke0` is as negligible as `k`.
            return Ray {
                a,
                inv_a: 1.0 / a,
                sa,
                r0,
                k: 0.0,
                ke0: 0.0,
                kphi: 0.0,
                c0: 0.0,
            };
        }
        let k = (-0.5 * e).exp() * k;
        Ray {
            a,
            inv_a: 1.0 / a,
            sa,
            r0,
            k,
            ke0: kc,
            kphi: k * r0 * std::f64::consts::TAU.sqrt() / sa,
            c0: normal_cdf(-sa * r0),
        }
    }

    /// The ray with its contributions weighted by `w`.
    pub(super) fn weighted(mut self, w: f64) -> Ray {
        self.k *= w;
        self.ke0 *= w;
        self.kphi *= w;
        self
    }

    /// `k ·` the integral along the ray from 0 to ρ, and `k ·` its first
    /// three derivatives in ρ.
    pub(super) fn ahead(&self, rho: f64) -> [f64; 4] {
        self.along(rho, self.r0, self.kphi, self.c0)
    }

    /// [`Ray::ahead`] for the opposite direction, which shares `A`, `E` and
    /// `C` (`r₀` and `k r₀ √(2π/A)` change sign, `Φ(−√A r₀)` becomes `1 −` it).
    pub(super) fn behind(&self, rho: f64) -> [f64; 4] {
        self.along(rho, -self.r0, -self.kphi, 1.0 - self.c0)
    }

    /// The ray's integral for the given `r₀`, `k r₀ √(2π/A)` and `Φ(−√A r₀)`,
    /// and its derivatives: with `q = ρ − r₀` and `g = k e^{−½A q²}`, `gρ`,
    /// `g (1 − Aρq)` and `g A (Aρq² − 2q − ρ)` (no further exponential: the
    /// second and third feed `amplitude_95`'s higher-order Newton step).
    fn along(&self, rho: f64, r0: f64, kphi: f64, c0: f64) -> [f64; 4] {
        if self.k == 0.0 {
            return [0.0; 4];
        }
        let q = rho - r0;
        let t = self.sa * q;
        let g = self.k * (-0.5 * t * t).exp();
        let along = (self.ke0 - g) * self.inv_a + kphi * (normal_cdf(t) - c0);
        let aq = self.a * q;
        [
            along,
            g * rho,
            g * (1.0 - aq * rho),
            g * self.a * (aq * q * rho - 2.0 * q - rho),
        ]
    }
}

/// `N((μ₁, μ₂), diag(σ₁², σ₂²))` as the rays need it: `μ`, `1/σ²`,
/// `1/(σ₁σ₂)` and `C` of `polar`'s module doc (`arc` shares it).
#[derive(Clone, Copy)]
pub(super) struct Axes {
    pub(super) mu: [f64; 2],
    pub(super) inv_var: [f64; 2],
    pub(super) k: f64,
    pub(super) c: f64,
    /// `e^{−C/2}/(σ₁σ₂)`.
    pub(super) kc: f64,
}

impl Axes {
    pub(super) fn new(mu1: f64, mu2: f64, s1: f64, s2: f64) -> Self {
        let c = mu1 * mu1 / (s1 * s1) + mu2 * mu2 / (s2 * s2);
        let k = 1.0 / (s1 * s2);
        Self {
            mu: [mu1, mu2],
            inv_var: [1.0 / (s1 * s1), 1.0 / (s2 * s2)],
            k,
            c,
            kc: (-0.5 * c).exp() * k,
        }
    }

    /// `A` and `B` of `polar`'s module doc for the direction `(cos θ, sin θ)`.
    pub(super) fn ab(&self, c: f64, s: f64) -> (f64, f64) {
        let a = c * c * self.inv_var[0] + s * s * self.inv_var[1];
        let b = self.mu[0] * c * self.inv_var[0] + self.mu[1] * s * self.inv_var[1];
        (a, b)
    }

    /// The ray of the direction `(cos θ, sin θ)` for a mean off the origin.
    pub(super) fn ray(&self, c: f64, s: f64) -> Ray {
        let (a, b) = self.ab(c, s);
        Ray::off_centre(a, b, self.c, self.k, self.kc)
    }
}

/// `sum += x`, element by element (`arc` shares it).
pub(super) fn add(sum: &mut [f64; 4], x: [f64; 4]) {
    for (s, x) in sum.iter_mut().zip(x) {
        *s += x;
    }
}
