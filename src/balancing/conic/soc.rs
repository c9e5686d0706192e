//! The algebra of one 3-dimensional second-order cone `{(x₀, x₁) : |x₁| ≤ x₀}`
//! that the primal-dual method (`primal_dual`) needs: Nesterov–Todd scaling,
//! the Jordan product and its inverse, and the longest step inside the cone
//! (Vandenberghe, "The CVXOPT linear and quadratic cone program solvers", § 4).

pub(super) type V3 = [f64; 3];

pub(super) fn dot(u: &V3, v: &V3) -> f64 {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

/// Nesterov–Todd scaling of one cone: `W = β H(w)`, symmetric, with
/// `W λ = W⁻¹ s` (the scaled point `v`); `H(w) = [[w₀, w₁ᵀ], [w₁, I + w₁w₁ᵀ/(1 + w₀)]]`
/// and `H⁻¹` the same with the off-diagonal blocks negated.
pub(super) struct Scaling {
    beta: f64,
    w: V3,
    /// `1/β` and `1/(1 + w₀)`, kept so that applying `W` divides nothing.
    inv_beta: f64,
    inv_1w0: f64,
}

impl Scaling {
    pub(super) fn of(s: &V3, l: &V3) -> Option<Scaling> {
        let sn = (s[0] * s[0] - s[1] * s[1] - s[2] * s[2]).sqrt();
        let ln = (l[0] * l[0] - l[1] * l[1] - l[2] * l[2]).sqrt();
        let (sh, lh) = (s.map(|x| x / sn), l.map(|x| x / ln));
        let gamma = ((1.0 + dot(&sh, &lh)) / 2.0).sqrt();
        let w = [
            (sh[0] + lh[0]) / (2.0 * gamma),
            (sh[1] - lh[1]) / (2.0 * gamma),
            (sh[2] - lh[2]) / (2.0 * gamma),
        ];
        let beta = (sn / ln).sqrt();
        let ok = beta.is_finite() && beta > 0.0 && w.iter().all(|x| x.is_finite());
        ok.then_some(Scaling {
            beta,
            w,
            inv_beta: 1.0 / beta,
            inv_1w0: 1.0 / (1.0 + w[0]),
        })
    }

    /// `H u` (`sign` = 1) or `H⁻¹ u` (`sign` = −1), times `f`.
    fn apply(&self, u: &V3, sign: f64, f: f64) -> V3 {
        let w = &self.w;
        let w1u1 = w[1] * u[1] + w[2] * u[2];
        let k = w1u1 * self.inv_1w0;
        [
            f * (w[0] * u[0] + sign * w1u1),
            f * (sign * u[0] * w[1] + u[1] + k * w[1]),
            f * (sign * u[0] * w[2] + u[2] + k * w[2]),
        ]
    }
    pub(super) fn w(&self, u: &V3) -> V3 {
        self.apply(u, 1.0, self.beta)
    }
    pub(super) fn w_inv(&self, u: &V3) -> V3 {
        self.apply(u, -1.0, self.inv_beta)
    }

    /// `W⁻²` as a matrix: `H(w)` squares to `2wwᵀ − J` (`J = diag(1, −1, −1)`,
    /// `w` on the unit hyperboloid) and `H⁻¹ = H(w̄)`, `w̄ = (w₀, −w₁)`.
    pub(super) fn w_inv_sq(&self) -> [V3; 3] {
        let f = self.inv_beta * self.inv_beta;
        let wb = [self.w[0], -self.w[1], -self.w[2]];
        let j = [1.0, -1.0, -1.0];
        std::array::from_fn(|r| {
            std::array::from_fn(|c| f * (2.0 * wb[r] * wb[c] - if r == c { j[r] } else { 0.0 }))
        })
    }
}

/// The Jordan product `u ∘ v = (u·v, u₀v₁ + v₀u₁)` of the cone's algebra.
pub(super) fn jordan(u: &V3, v: &V3) -> V3 {
    [
        dot(u, v),
        u[0] * v[1] + v[0] * u[1],
        u[0] * v[2] + v[0] * u[2],
    ]
}

/// `u` with `v ∘ u = r` (`v` inside the cone).
pub(super) fn jordan_div(v: &V3, r: &V3) -> V3 {
    let u0 = (v[0] * r[0] - v[1] * r[1] - v[2] * r[2]) / (v[0] * v[0] - v[1] * v[1] - v[2] * v[2]);
    [u0, (r[1] - u0 * v[1]) / v[0], (r[2] - u0 * v[2]) / v[0]]
}

/// The largest `α` (∞ when none) with `x + α d` in the cone, `x` inside it.
pub(super) fn max_step(x: &V3, d: &V3) -> f64 {
    let mut amax = f64::INFINITY;
    if d[0] < 0.0 {
        amax = -x[0] / d[0];
    }
    // (x₀ + αd₀)² − |x₁ + αd₁|² = qa α² + qb α + qc, qc > 0.
    let qa = d[0] * d[0] - d[1] * d[1] - d[2] * d[2];
    let qb = 2.0 * (x[0] * d[0] - x[1] * d[1] - x[2] * d[2]);
    let qc = x[0] * x[0] - x[1] * x[1] - x[2] * x[2];
    let disc = qb * qb - 4.0 * qa * qc;
    if qa == 0.0 {
        if qb < 0.0 {
            amax = amax.min(-qc / qb);
        }
    } else if disc >= 0.0 {
        // Both roots without cancellation: q/qa and qc/q.
        let q = -0.5 * (qb + qb.signum() * disc.sqrt());
        for root in [q / qa, qc / q] {
            if root > 0.0 {
                amax = amax.min(root);
            }
        }
    }
    amax
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_closed_form_inverse_square_of_the_scaling_matches_applying_it_twice() {
        let sc = Scaling::of(&[2.0, 0.5, -1.2], &[1.5, -0.3, 0.9]).unwrap();
        let sq = sc.w_inv_sq();
        let unit = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        for (c, e) in unit.iter().enumerate() {
            let col = sc.w_inv(&sc.w_inv(e));
            for r in 0..3 {
                assert!((sq[r][c] - col[r]).abs() < 1e-12, "{r},{c}");
            }
        }
    }
}
