//! `P(|R| ≤ ρ)` for a Gaussian `R` in the plane by adaptive Simpson
//! quadrature over the major axis: `amplitude_95`'s fallback where the polar
//! trapezoidal rule (`polar`) does not converge at its finest level, and the
//! reference the tests hold the fast path to.

use super::super::normal_cdf;

/// Beyond this many standard deviations a normal tail is below 1e-17: `normal_cdf`
/// returns exactly 1 from 8.3 on.
const TAIL: f64 = 8.5;
/// Tolerance of the adaptive Simpson rule over all panels, in probability.
const TOL: f64 = 1e-9;
/// Deepest refinement of a panel.
const DEPTH: u32 = 30;
/// Refinements of every panel before the error estimate may stop them: with
/// one (and tolerance 10⁻⁴, before issue 15) the coarse and the refined
/// Simpson sums of a panel could agree by accident and the rule was off by up
/// to 6·10⁻³ in probability (2.4·10⁻³ for a centred isotropic residual at its
/// 95 % quantile), which moved `amplitude_95` by up to 0.5 %.
const MIN_SPLITS: u32 = 3;

/// `P((μ₁+σ₁z₁)² + (μ₂+σ₂z₂)² ≤ ρ²)` for independent standard normal z₁, z₂,
/// and its derivative in ρ.
pub(in crate::balancing::uncertainty) fn inside(
    mu1: f64,
    mu2: f64,
    s1: f64,
    s2: f64,
    rho: f64,
) -> [f64; 2] {
    // In `u` with μ₁+σ₁z₁ = ρ sin u, h = ρ cos u: the square-root kinks of the
    // integrand where h → 0 become smooth ends, so Simpson converges fast; and
    // the derivative's 1/h (from ∂h/∂ρ = ρ/h) cancels against dz₁ = h/σ₁ du.
    let norm = 1.0 / std::f64::consts::TAU.sqrt();
    if s2 <= 0.0 {
        // No spread across: |R|² = (μ₁ + σ₁z₁)² + μ₂², so P = Φ(z₊) − Φ(z₋)
        // with z± = (±w − μ₁)/σ₁, w = √(ρ² − μ₂²), in closed form (Simpson
        // on the step this is in u was up to 4·10⁻⁵ off; issue 15, session 8).
        let w2 = rho * rho - mu2 * mu2;
        if w2.is_nan() || w2 <= 0.0 {
            return [0.0, 0.0];
        }
        let w = w2.sqrt();
        let (up, down) = ((w - mu1) / s1, (-w - mu1) / s1);
        let density = ((-0.5 * up * up).exp() + (-0.5 * down * down).exp()) * norm / s1;
        return [normal_cdf(up) - normal_cdf(down), density * rho / w];
    }
    let inner = |u: f64| {
        let (sin, cos) = u.sin_cos();
        let z = (rho * sin - mu1) / s1;
        let h = rho * cos;
        let weight = (-0.5 * z * z).exp() * norm / s1;
        let (a, b) = ((h - mu2) / s2, (-h - mu2) / s2);
        // Both ends beyond 8.5σ₂ (a ≥ b as h ≥ 0): Φ(a) − Φ(b) is exactly 1
        // or 0 in floating point (Φ(x) = 1.0 from x ≥ 8.3, Φ(−8.5) ≈ 1e-17
        // vanishes beside 1) and the density terms are below 1e-15 of
        // their peak; four exponentials saved (issue 15).
        if b >= TAIL || a <= -TAIL {
            return [0.0, 0.0];
        }
        if a >= TAIL && b <= -TAIL {
            return [weight * h, 0.0];
        }
        let p = normal_cdf(a) - normal_cdf(b);
        let dp = ((-0.5 * a * a).exp() + (-0.5 * b * b).exp()) * norm / s2 * rho;
        [p * weight * h, dp * weight]
    };
    let a = ((-rho - mu1) / s1).max(-6.0);
    let b = ((rho - mu1) / s1).min(6.0);
    if a >= b {
        return [0.0, 0.0];
    }
    let to_u = |z: f64| ((mu1 + s1 * z) / rho).clamp(-1.0, 1.0).asin();
    // The inner Φ difference turns from 0 to 1 where h crosses |μ₂| ± 8.5σ₂:
    // for a mass thin across (σ₂ ≪ ρ) a sliver at the ends of the range
    // that whole panels stepped over, up to 10⁻⁶ off in P before issue 15's
    // session 8. Those crossings are panel ends.
    let mut cuts = vec![a, b];
    for h in [mu2.abs() - TAIL * s2, mu2.abs() + TAIL * s2] {
        if h > 0.0 && h < rho {
            let x = (rho * rho - h * h).sqrt();
            cuts.extend(
                [(x - mu1) / s1, (-x - mu1) / s1]
                    .into_iter()
                    .filter(|z| *z > a && *z < b),
            );
        }
    }
    cuts.sort_by(f64::total_cmp);
    // Between them, panels of at most two units of z₁: a support narrower
    // than a panel, which all the panel's nodes could miss, holds under 0.69
    // of the probability, so missing it cannot decide whether P reaches 0.95.
    let mut ends = vec![a];
    for w in cuts.windows(2) {
        let k = ((0.5 * (w[1] - w[0])).ceil() as usize).max(1);
        ends.extend((1..=k).map(|i| w[0] + (w[1] - w[0]) * i as f64 / k as f64));
    }
    let tol = TOL / (ends.len() - 1) as f64;
    ends.windows(2)
        .map(|w| simpson(&inner, to_u(w[0]), to_u(w[1]), tol, DEPTH))
        .fold([0.0, 0.0], |acc, v| [acc[0] + v[0], acc[1] + v[1]])
}

type Pair = [f64; 2];

fn add(x: Pair, y: Pair, k: f64) -> Pair {
    [x[0] + k * y[0], x[1] + k * y[1]]
}

/// Simpson's rule on a pair of integrands.
fn rule(h: f64, fa: Pair, fm: Pair, fb: Pair) -> Pair {
    [
        h / 6.0 * (fa[0] + 4.0 * fm[0] + fb[0]),
        h / 6.0 * (fa[1] + 4.0 * fm[1] + fb[1]),
    ]
}

/// Adaptive Simpson quadrature of a pair of integrands, refined on the first
/// (generic over the integrand so that it inlines: issue 15).
fn simpson<F: Fn(f64) -> Pair>(f: &F, a: f64, b: f64, tol: f64, depth: u32) -> Pair {
    let (fa, fm, fb) = (f(a), f(0.5 * (a + b)), f(b));
    refine(f, a, b, [fa, fm, fb], rule(b - a, fa, fm, fb), tol, depth)
}

fn refine<F: Fn(f64) -> Pair>(
    f: &F,
    a: f64,
    b: f64,
    fs: [Pair; 3],
    whole: Pair,
    tol: f64,
    depth: u32,
) -> Pair {
    let [fa, fm, fb] = fs;
    let m = 0.5 * (a + b);
    let (flm, frm) = (f(0.5 * (a + m)), f(0.5 * (m + b)));
    let left = rule(m - a, fa, flm, fm);
    let right = rule(b - m, fm, frm, fb);
    let sum = add(left, right, 1.0);
    let delta = add(sum, whole, -1.0);
    if depth == 0 || (depth <= DEPTH - MIN_SPLITS && delta[0].abs() <= 15.0 * tol) {
        return add(sum, delta, 1.0 / 15.0);
    }
    add(
        refine(f, a, m, [fa, flm, fm], left, tol / 2.0, depth - 1),
        refine(f, m, b, [fm, frm, fb], right, tol / 2.0, depth - 1),
        1.0,
    )
}
