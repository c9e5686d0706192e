//! The covariance scale `f` that calibrates `amplitude_95`'s level (method
//! 8.7), solved over binned moments so that a job of many rows costs one pass
//! over rows × nodes, not one `exp` per row, node and Newton step (issue 15:
//! 6.5 M to about 1 M instructions on the large least-squares job).
//!
//! With `y_i = ρ_i ln 0.05 < 0` for every row and node `i` (weight `m_i`, the
//! number of nodes sharing that resampled weight), `f` solves
//! `G(f) = Σ m_i e^{f y_i} / N = 0.05`. The `y_i` are binned on a grid of width
//! `Δ`; in the bin centred on `c`, `e^{f y} = e^{f c} Σ_{k≤7} (f d)^k / k!`
//! with `d = y − c`, `|d| ≤ Δ/2`, to a relative `(fΔ/2)⁸/8!` (below 2·10⁻¹⁶
//! while `fΔ/2 ≤ 0.04`), so `G(f) = Σ_b e^{f c_b} Σ_k f^k M_bk / k! / N` with
//! the bin moments `M_bk = Σ_{i∈b} m_i d_i^k`, gathered once. The `e^{f c_b}`
//! form a geometric sequence in `b` (one `exp` per 64 bins re-anchors it).
//! `ln G` is convex and decreasing in `f` (a log-sum-exp of lines), so Newton
//! on `ln G − ln 0.05` from Jensen's lower bound `f₀ = ln 0.05 / ȳ`
//! (`G(f) ≥ e^{f ȳ}`) rises monotonically to the root, every iterate below
//! it. Where an iterate outgrows the grid (`fΔ/2 > 0.04`: a root above 4), the moments are gathered again on a grid fine enough for it, leaving
//! out the rows and nodes with `f y < −38` (each under `e^{−38}` of `G`'s
//! 0.05); the direct sum is the last resort.

/// Standard normal quantiles at the midpoints of 16 equally likely bins: the
/// nodes over which step 4 averages the weight's sampling distribution.
const NODES: [f64; 16] = [
    -1.862732, -1.318011, -1.009990, -0.776422, -0.579132, -0.402250, -0.237202, -0.078412,
    0.078412, 0.237202, 0.402250, 0.579132, 0.776422, 1.009990, 1.318011, 1.862732,
];

/// Moments kept per bin (`d⁰ … d⁷`).
const ORDER: usize = 8;
/// Preferred bin width in `y`.
const DELTA: f64 = 0.02;
/// Largest `fΔ/2` at which eight moments give `G` to 2·10⁻¹⁶ relative.
const MAX_HALF_STEP: f64 = 0.04;

/// The covariance scale `f` of the bound calibrated for the scatter of the
/// estimated weight (step 4 of `remaining`, Carlin & Gelfand 1990): `ks` the
/// used rows' [`super::weight_sensitivity`], `dof` as
/// [`super::residual_shrinkage`], `shrink` its estimate `Ŝ`. With `Ŝ` taken
/// as the truth, the statistic of [`super::residual_shrinkage`] is
/// `x* = (1 + τ̂²)·dof·G`, `G ~ Γ(dof, 1)/dof` (Wilson–Hilferty at
/// `NODES`), giving the weight `S*` a job like this one would estimate. A
/// row's bound at `S*` then has variance `Σ_ε + S* K` against the true
/// error's `Σ_ε + Ŝ K + (Ŝ − S*)² K / (1 − Ŝ)` (the centre's shift from
/// `Ŝ − S*`, `R̂` having covariance `Σ_v / (1 − Ŝ)`); in the central isotropic
/// approximation a bound of variance ratio `ρ` holds `1 − 0.05^(fρ)`. `f`
/// solves `mean(1 − 0.05^(fρ)) = 0.95` over rows and nodes (method 8.7).
#[inline(never)] // kept out of `apply::fill` so its cost is seen on its own (issue 15)
pub fn calibrated_scale(ks: &[f64], dof: usize, shrink: f64) -> f64 {
    let s = shrink.clamp(0.0, 1.0);
    if ks.is_empty() || s >= 1.0 - 1e-9 {
        return 1.0;
    }
    let nodes = nodes(dof, s);
    binned(ks, &nodes).unwrap_or_else(|| direct(ks, &nodes))
}

/// A distinct resampled weight `S*`: `ρ = (1 + w k)/(1 + c k)` for a row of
/// sensitivity `k`, shared by `m` of the 16 nodes.
#[derive(Debug, Clone, Copy)]
struct Node {
    w: f64,
    c: f64,
    m: f64,
}

/// The nodes' weights `S*` (doc of [`calibrated_scale`]), equal ones merged
/// (at `Ŝ = 0` about half the nodes resample `S* = 0`).
fn nodes(dof: usize, s: f64) -> Vec<Node> {
    let n = dof.max(1) as f64;
    let (a, c) = (1.0 - 1.0 / (9.0 * n), (1.0 / (9.0 * n)).sqrt());
    let mut out: Vec<Node> = Vec::with_capacity(NODES.len());
    for z in NODES {
        let g = (a + c * z).max(0.0).powi(3);
        let x = g * n / (1.0 - s);
        let w = if x <= n { 0.0 } else { 1.0 - n / x };
        match out.last_mut() {
            Some(last) if last.w == w => last.m += 1.0,
            _ => out.push(Node {
                w,
                c: s + (s - w).powi(2) / (1.0 - s),
                m: 1.0,
            }),
        }
    }
    out
}

/// `y = ρ ln 0.05` of a row of sensitivity `k` at a node.
#[inline]
fn y_of(node: &Node, k: f64) -> f64 {
    LN_005 * (1.0 + node.w * k) / (1.0 + node.c * k)
}

const LN_005: f64 = -2.995_732_273_553_991;

/// `f` over binned moments (module doc); `None` where the grid cannot give it
/// to full precision.
fn binned(ks: &[f64], nodes: &[Node]) -> Option<f64> {
    // ρ is monotone in k at every node: the range of y from the extreme rows.
    let (k_lo, k_hi) = ks.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &k| {
        (lo.min(k), hi.max(k))
    });
    let (mut y_lo, mut y_hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for node in nodes {
        for k in [k_lo, k_hi] {
            let y = y_of(node, k);
            (y_lo, y_hi) = (y_lo.min(y), y_hi.max(y));
        }
    }
    if !(y_lo.is_finite() && y_hi.is_finite() && y_hi < 0.0) {
        return None;
    }
    let mut grid = Grid::gather(ks, nodes, y_hi, y_lo, DELTA.max((y_hi - y_lo) / FIT_BINS));
    let total = grid.total;
    // Newton on ln G(f) − ln 0.05, convex and decreasing (a log-sum-exp of
    // lines), from Jensen's f₀ where it is ≥ 0: monotone from below.
    let mut f = LN_005 / (grid.sum_y / total);
    let mut regrids = 0;
    for _ in 0..60 {
        if !(f.is_finite() && f > 0.0) {
            return None;
        }
        if f * grid.delta * 0.5 > MAX_HALF_STEP {
            // Finer bins for this f (≤ the root): rows below −FLOOR/f add
            // under e^−38 each and are left out.
            regrids += 1;
            let floor = y_lo.max((-FLOOR / f).min(y_hi));
            grid = Grid::gather(ks, nodes, y_hi, floor, FINE * 2.0 / f);
            if regrids > 6 || f * grid.delta * 0.5 > MAX_HALF_STEP {
                return None;
            }
        }
        let (g, dg) = grid.sums(f);
        let step = ((g / total).ln() - LN_005) * g / dg;
        f -= step;
        // Quadratic convergence: the root lies within ~step² of f.
        if step.abs() <= 3e-8 * f {
            return (f.is_finite() && f > 0.0 && f * grid.delta * 0.5 <= MAX_HALF_STEP)
                .then_some(f);
        }
    }
    None
}

/// Bins for the grid of the first pass: a spread of `y` beyond ~80 widens them.
const FIT_BINS: f64 = 4093.0;
/// `−ln` of the share below which a row and node is left out of a finer grid.
const FLOOR: f64 = 38.0;
/// The `fΔ/2` a finer grid is built for, a third of [`MAX_HALF_STEP`]: room
/// for the root above the `f` it is built at.
const FINE: f64 = 0.013;

/// The bin moments `M_bk / k!` of the `y` in `[floor, y_hi]` (module doc), bin
/// `b` centred on `y_hi − bΔ`.
struct Grid {
    y_hi: f64,
    delta: f64,
    mom: Vec<[f64; ORDER]>,
    /// `Σ m` and `Σ m y` over the rows and nodes gathered.
    total: f64,
    sum_y: f64,
}

impl Grid {
    fn gather(ks: &[f64], nodes: &[Node], y_hi: f64, floor: f64, delta: f64) -> Grid {
        // b = round((y_hi − y)/Δ); two spare bins take the rounding of rows
        // between the extremes.
        let bins = ((y_hi - floor) / delta) as usize + 3;
        let inv = 1.0 / delta;
        let mut mom = vec![[0.0f64; ORDER]; bins];
        for &k in ks {
            for node in nodes {
                let y = y_of(node, k);
                let y = if y > y_hi { y_hi } else { y };
                if y < floor {
                    continue;
                }
                // t + 2⁵² holds round(t) in its low mantissa bits (0 ≤ t < 2³¹).
                let t = (y_hi - y) * inv + ROUND;
                let b = t.to_bits() as u32;
                let d = (y - y_hi) + (t - ROUND) * delta;
                let m = &mut mom[(b as usize).min(bins - 1)];
                let mut p = node.m;
                for slot in m.iter_mut() {
                    *slot += p;
                    p *= d;
                }
            }
        }
        let (mut total, mut sum_y, mut c) = (0.0, 0.0, y_hi);
        for m in mom.iter_mut() {
            total += m[0];
            sum_y += c * m[0] + m[1];
            c -= delta;
            let mut fact = 1.0;
            for (k, slot) in m.iter_mut().enumerate().skip(1) {
                fact *= k as f64;
                *slot /= fact;
            }
        }
        Grid {
            y_hi,
            delta,
            mom,
            total,
            sum_y,
        }
    }

    /// `N·G(f)` and `N·G'(f)` (module doc).
    fn sums(&self, f: f64) -> (f64, f64) {
        let q = (-f * self.delta).exp();
        let (mut g, mut dg, mut e, mut c) = (0.0, 0.0, 0.0, self.y_hi);
        for (b, m) in self.mom.iter().enumerate() {
            e = if b % 64 == 0 {
                (f * (self.y_hi - b as f64 * self.delta)).exp()
            } else {
                e * q
            };
            if m[0] != 0.0 {
                // P(f) = Σ a_k f^k and P'(f), Horner.
                let (mut p, mut dp) = (m[ORDER - 1], 0.0);
                for k in (0..ORDER - 1).rev() {
                    dp = dp * f + p;
                    p = p * f + m[k];
                }
                g += e * p;
                dg += e * (c * p + dp);
            }
            c -= self.delta;
        }
        (g, dg)
    }
}

/// 2⁵²: adding it to a non-negative `t < 2³¹` rounds `t` to an integer, held
/// in the low mantissa bits.
const ROUND: f64 = 4_503_599_627_370_496.0;

/// `f` by Newton over every row and node (the reference form; used where the
/// grid is too coarse). `0.05^(fρ)` is convex and decreasing in `f`, so after
/// the first step from `f = 1` it converges from below.
fn direct(ks: &[f64], nodes: &[Node]) -> f64 {
    let rls: Vec<(f64, f64)> = ks
        .iter()
        .flat_map(|&k| nodes.iter().map(move |n| (y_of(n, k), n.m)))
        .collect();
    let count: f64 = rls.iter().map(|x| x.1).sum();
    let (mut f, mut last) = (1.0, f64::INFINITY);
    for _ in 0..60 {
        let (mut g, mut dg) = (0.0, 0.0);
        for &(rl, m) in &rls {
            let e = m * (f * rl).exp();
            g += e;
            dg += rl * e;
        }
        let step = (g / count - 0.05) / (dg / count);
        f = (f - step).max(0.0);
        if !f.is_finite() {
            return 1.0;
        }
        if converged(step, &mut last, f) {
            break;
        }
    }
    f
}

/// Newton's stop: a step below 10⁻¹⁴ of `f`, or one near it that no longer
/// shrinks (the rounding floor of the sums; the root is then within it).
fn converged(step: f64, last: &mut f64, f: f64) -> bool {
    let small = step.abs() <= 1e-14 * f || (step.abs() <= 1e-11 * f && step.abs() >= *last);
    *last = step.abs();
    small
}

#[cfg(test)]
#[path = "calibrate_tests.rs"]
mod tests;
