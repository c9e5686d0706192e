//! The root finder of `amplitude_95`: `P(|R| ≤ ρ) = 0.95` by safeguarded
//! Newton steps of third order, stopping on an estimate of the error left
//! (issue 15, session 7).

/// `|P(bound) − 0.95|` that `amplitude_95` keeps, estimated from the terms of
/// its last step: about 10⁻⁶σ in the bound (P' ≈ 0.1/σ there), below
/// 10⁻⁶ of the bound itself. Issue 15's session 7 made the last step count:
/// before, Newton stopped at the first iterate within 2·10⁻⁴ in probability
/// and returned it (up to 2·10⁻³σ off) after evaluating P there.
const TOL_Q: f64 = 1e-7;

/// Safeguarded Newton on `P(ρ) = 0.95` from `x` within `[lo, hi]`, with the
/// step of the inverse Taylor series: for `f + a₁d + a₂d² + a₃d³ = 0`
/// (`aᵢ = P⁽ⁱ⁾/i!`) and `u = −f/a₁`, `d = u − (a₂/a₁)u² + (2(a₂/a₁)² −
/// a₃/a₁)u³ + O(u⁴)`. The terms shrink by about `u/σ` each, so the first
/// term left out is about the last one kept times the ratio of the last two:
/// once that moves P by under [`TOL_Q`], `x + d` is returned without
/// evaluating P there. From the Patnaik start (within about 2·10⁻³ in
/// probability) that is one evaluation of the rule, where Newton took two.
/// The quadrature has no `P''`, and its `P'` is not refined with `P` (off
/// by a third for masses thin across): there the steps are secants of `P`
/// after the first, until `P` itself is within [`TOL_Q`].
pub(in crate::balancing::uncertainty) fn newton(
    mut inside: impl FnMut(f64) -> [f64; 4],
    mut x: f64,
    mut lo: f64,
    mut hi: f64,
) -> f64 {
    let mut before: Option<(f64, f64)> = None;
    for _ in 0..60 {
        if !(x > lo && x < hi) {
            x = 0.5 * (lo + hi);
        }
        let [p, d1, d2, d3] = inside(x);
        let f = p - 0.95;
        if f < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        if f == 0.0 || hi - lo < 1e-9 * hi {
            return x;
        }
        if d2.is_nan() {
            if f.abs() <= TOL_Q {
                return x;
            }
            let slope = match before {
                Some((xb, pb)) if xb != x => (p - pb) / (x - xb),
                _ => d1,
            };
            before = Some((x, p));
            x = if slope > 0.0 { x - f / slope } else { f64::NAN };
            continue;
        }
        if !(d1 > 0.0 && d1.is_finite()) {
            x = f64::NAN;
            continue;
        }
        let u = -f / d1;
        let r2 = 0.5 * d2 / d1;
        let t2 = -r2 * u * u;
        let t3 = (2.0 * r2 * r2 - d3 / (6.0 * d1)) * u * u * u;
        // The terms kept and an estimate of the first one left out.
        let (step, left) = if !t2.is_finite() || t2.abs() > 0.5 * u.abs() {
            // Far from the root: plain Newton, not final.
            (u, f64::INFINITY)
        } else if !t3.is_finite() || t3.abs() > 0.5 * t2.abs() {
            (u + t2, t2 * t2 / u)
        } else {
            (u + t2 + t3, t3 * t3 / t2)
        };
        let next = x + step;
        // A vanishing term makes the estimate 0/0: not final.
        if (left * d1).abs() <= TOL_Q && next > lo && next < hi {
            return next;
        }
        x = next;
    }
    0.5 * (lo + hi)
}
