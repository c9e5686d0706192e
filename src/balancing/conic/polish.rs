//! The min-max optimum to rounding: Newton's method on the optimality
//! conditions of the interior point's active set, taken only with a
//! certificate of optimality (session 20).
//!
//! Why: an interior point stops at a relative duality gap (1e-10 here), which
//! fixes the peak `t` to that much but the correction only to about its
//! square root wherever the peak is flat to second order along the optimal
//! set's tangent: one plane and two sensors, where the optimum lies on the
//! curve of equal residuals and moving along it raises the peak
//! quadratically, came back 2·10⁻⁷ relative from its closed form; other
//! jobs 10⁻⁵. Two tools then print different digits for the same job.
//!
//! How: in real form (`x = (Re y, Im y)`) the scaled min-max program is
//! `min s` subject to `|r_a(x)|² ≤ s` (`s = t²`) on every row and
//! `|y_k|² ≤ m_k²` on every bound, convex and smooth. On a guessed active set
//! (rows within [`ACTIVE`] of the peak, bounds within it of their value) the
//! Karush–Kuhn–Tucker conditions are a square system of polynomial equations
//! in `(x, s, μ, ν)`:
//!
//! `Σ μ_a P_aᵀ r_a + Σ ν_k E_k x = 0`, `Σ μ_a = 1`, `|r_a|² = s`, `|y_k|² = m_k²`,
//!
//! (`P_a` the row's 2 × 2n real coefficients, `E_k` picking `Re y_k, Im y_k`)
//! solved by Newton from the interior point's answer with multipliers fitted
//! to it, each step by LU of the column-scaled Jacobian (by SVD, least
//! squares, where a degenerate active set leaves it singular). The answer is taken only when
//! it is a KKT point of the whole program: every multiplier non-negative,
//! every row at most the new peak and every bound kept (to rounding), its
//! peak no higher than the interior point's. A convex program has no other
//! KKT points than its optima, so then it is optimal to rounding. A negative
//! multiplier drops its constraint, a violated row joins the set, for at most
//! [`ROUNDS`] guesses; otherwise the interior point's answer stands.
//!
//! Near a zero peak (exact data, as many planes as needed) the squared
//! constraints lose their curvature; there the least-squares correction
//! (QR) is tried first, taken when its peak is no higher.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

/// A row is guessed active when its residual is within this share of the
/// peak: wide enough for the interior point's ~1e-5 error, the wrong guesses
/// leave by their multipliers' signs.
const ACTIVE: f64 = 1e-3;
/// Active-set guesses before the interior point's answer is kept.
const ROUNDS: usize = 8;
/// Newton steps per guess (quadratic convergence from ~1e-5 needs 3 or 4).
const NEWTON: usize = 12;
/// Peak (scaled, `max |b| = 1`) below which the least-squares correction is
/// tried instead of Newton.
const NEAR_ZERO: f64 = 1e-6;
/// Rounding allowance of the certificate, relative to the peak.
const ROUND: f64 = 1e-12;

/// The scaled min-max program's optimum to rounding near the interior
/// point's `y0`, or `None` when no certificate was found (module docs).
pub(super) fn polish(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    y0: &[Complex64],
) -> Option<Vec<Complex64>> {
    let n = a.ncols();
    let prog = Real::new(a, b);
    let x0 = stacked(y0);
    let r0 = prog.residuals(&x0);
    let t0 = peak(&r0);
    if !(t0.is_finite() && t0 > 0.0) {
        return None;
    }
    if t0 <= NEAR_ZERO {
        if let Some(y) = least_squares(a, b, bounds, t0) {
            return Some(y);
        }
    }
    // The first guess: the rows nearest the peak, at most 2n + 1 constraints
    // with the bounds (a non-degenerate optimum has no more).
    let mut order: Vec<usize> = (0..prog.m).collect();
    order.sort_by(|&i, &j| r0[j].total_cmp(&r0[i]));
    let near = |&i: &usize| r0[i] >= t0 * (1.0 - ACTIVE);
    let mut kset: Vec<usize> = (0..bounds.len())
        .filter(|&c| {
            let (k, m) = bounds[c];
            x0[k].hypot(x0[n + k]) >= m * (1.0 - ACTIVE)
        })
        .collect();
    let room = (2 * n + 1).saturating_sub(kset.len()).max(1);
    let mut aset: Vec<usize> = order.iter().copied().filter(near).take(room).collect();
    for _ in 0..ROUNDS {
        let (x, mu, nu) = prog.newton(&x0, &aset, bounds, &kset)?;
        // Multipliers: drop the most negative constraint and guess again.
        let worst_mu = mu.iter().enumerate().min_by(|p, q| p.1.total_cmp(q.1));
        let worst_nu = nu.iter().enumerate().min_by(|p, q| p.1.total_cmp(q.1));
        let scale_nu = nu.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
        match (worst_mu, worst_nu) {
            (Some((i, &v)), _) if v < -1e-9 => {
                aset.remove(i);
                continue;
            }
            (_, Some((i, &v))) if v < -1e-9 * scale_nu => {
                kset.remove(i);
                continue;
            }
            _ => {}
        }
        let r = prog.residuals(&x);
        let t = peak(&r);
        if !(t.is_finite() && t > 0.0) {
            return None;
        }
        // The most violated row joins the set; a bound broken ends the try.
        let violated = (0..prog.m)
            .filter(|&i| r[i] > t * (1.0 + ROUND))
            .max_by(|&i, &j| r[i].total_cmp(&r[j]));
        if let Some(i) = violated {
            if aset.contains(&i) {
                return None;
            }
            aset.push(i);
            continue;
        }
        let within = bounds
            .iter()
            .all(|&(k, m)| x[k].hypot(x[n + k]) <= m * (1.0 + ROUND));
        if !within || t > t0 * (1.0 + ROUND) {
            return None;
        }
        return Some((0..n).map(|k| Complex64::new(x[k], x[n + k])).collect());
    }
    None
}

/// The least-squares solution of `m z = rhs` (more rows than columns): by
/// QR, or by SVD where `R` is singular or nearly so (the multipliers' first
/// guess).
fn least_squares_fit(m: DMatrix<f64>, rhs: &DVector<f64>) -> Option<DVector<f64>> {
    if m.nrows() >= m.ncols() {
        let qr = m.clone().qr();
        let r = qr.r();
        let diag = r.diagonal().map(f64::abs);
        // A pivot at rounding level of the largest: rank-deficient, SVD.
        if diag.min() > 1e-12 * diag.max() {
            if let Some(z) = r.solve_upper_triangular(&qr.q().tr_mul(rhs)) {
                if z.iter().all(|v| v.is_finite()) {
                    return Some(z);
                }
            }
        }
    }
    m.svd(true, true).solve(rhs, 1e-14).ok()
}

/// The Newton step `J Δ = −F`: columns of `J` at unit norm, LU for speed,
/// SVD (least squares) where a degenerate active set leaves `J` singular.
fn newton_step(mut j: DMatrix<f64>, f: &DVector<f64>) -> Option<Vec<f64>> {
    let scale: Vec<f64> = j
        .column_iter()
        .map(|c| {
            let v = c.norm();
            if v > 0.0 {
                1.0 / v
            } else {
                1.0
            }
        })
        .collect();
    for (c, &sc) in scale.iter().enumerate() {
        j.column_mut(c).scale_mut(sc);
    }
    let rhs = -f;
    let step = match j.clone().lu().solve(&rhs) {
        Some(st) if st.iter().all(|v| v.is_finite()) => st,
        _ => j.svd(true, true).solve(&rhs, 1e-14).ok()?,
    };
    let step: Vec<f64> = step.iter().zip(&scale).map(|(v, s)| v * s).collect();
    step.iter().all(|v| v.is_finite()).then_some(step)
}

/// Least squares under mass bounds, `min ‖b + A y‖₂` subject to
/// `|y_k| ≤ m_k`, to rounding near the interior point's `y0` (module docs):
/// Newton on the KKT system of the bounds guessed binding, in augmented
/// form (`r = b + A y` an unknown beside `y`, so `AᴴA` is never formed),
///
/// `r − P x = r₀`, `Pᵀ r + Σ ν_k E_k x = 0`, `|y_k|² = m_k²`,
///
/// taken only with every `ν_k ≥ 0`, every bound kept and `‖r‖₂` no higher
/// than the interior point's.
pub(super) fn polish_least_squares(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    y0: &[Complex64],
) -> Option<Vec<Complex64>> {
    let n = a.ncols();
    let prog = Real::new(a, b);
    let x0 = stacked(y0);
    let norm = |x: &[f64]| prog.residuals(x).iter().map(|v| v * v).sum::<f64>().sqrt();
    let t0 = norm(&x0);
    if !t0.is_finite() {
        return None;
    }
    let mut kset: Vec<usize> = (0..bounds.len())
        .filter(|&c| {
            let (k, m) = bounds[c];
            x0[k].hypot(x0[n + k]) >= m * (1.0 - ACTIVE)
        })
        .collect();
    for _ in 0..ROUNDS {
        let (x, nu) = prog.newton_least_squares(&x0, bounds, &kset)?;
        let scale_nu = nu.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
        if let Some((i, _)) = nu
            .iter()
            .enumerate()
            .filter(|p| *p.1 < -1e-9 * scale_nu)
            .min_by(|p, q| p.1.total_cmp(q.1))
        {
            kset.remove(i);
            continue;
        }
        let broken = (0..bounds.len())
            .filter(|c| !kset.contains(c))
            .map(|c| (c, x[bounds[c].0].hypot(x[n + bounds[c].0]) / bounds[c].1))
            .filter(|&(_, ratio)| ratio > 1.0 + ROUND)
            .max_by(|p, q| p.1.total_cmp(&q.1));
        if let Some((c, _)) = broken {
            kset.push(c);
            continue;
        }
        let within = bounds
            .iter()
            .all(|&(k, m)| x[k].hypot(x[n + k]) <= m * (1.0 + ROUND));
        let t = norm(&x);
        // (A NaN norm fails `t.is_finite()`.)
        if !within || !t.is_finite() || t > t0 * (1.0 + ROUND) + 1e-300 {
            return None;
        }
        return Some((0..n).map(|k| Complex64::new(x[k], x[n + k])).collect());
    }
    None
}

fn peak(r: &[f64]) -> f64 {
    r.iter().copied().fold(0.0, f64::max)
}

/// The least-squares correction when its peak is no higher than `t0` and it
/// keeps every bound: the min-max optimum of an exactly solvable job.
fn least_squares(
    a: &DMatrix<Complex64>,
    b: &DVector<Complex64>,
    bounds: &[(usize, f64)],
    t0: f64,
) -> Option<Vec<Complex64>> {
    if a.nrows() < a.ncols() {
        return None;
    }
    let qr = a.clone().qr();
    let y = qr.r().solve_upper_triangular(&(-qr.q().ad_mul(b)))?;
    let finite = y.iter().all(|z| z.re.is_finite() && z.im.is_finite());
    let t = (b + a * &y).iter().map(|z| z.norm()).fold(0.0, f64::max);
    let within = bounds.iter().all(|&(k, m)| y[k].norm() <= m);
    (finite && within && t <= t0).then(|| y.iter().copied().collect())
}

/// The rows of `b + A y` in real form: `Re r_a = re0 + p_a·x`,
/// `Im r_a = im0 + q_a·x`, `x = (Re y, Im y)`.
struct Real {
    n: usize,
    m: usize,
    r0: Vec<[f64; 2]>,
    /// Rows' coefficients, `2n` per row, one buffer each (one allocation).
    p: Vec<f64>,
    q: Vec<f64>,
}

impl Real {
    fn new(a: &DMatrix<Complex64>, b: &DVector<Complex64>) -> Real {
        let (m, n) = a.shape();
        let (mut p, mut q) = (vec![0.0; 2 * n * m], vec![0.0; 2 * n * m]);
        for i in 0..m {
            let (pi, qi) = (&mut p[2 * n * i..], &mut q[2 * n * i..]);
            for k in 0..n {
                let c = a[(i, k)];
                pi[k] = c.re;
                pi[n + k] = -c.im;
                qi[k] = c.im;
                qi[n + k] = c.re;
            }
        }
        let r0 = b.iter().map(|z| [z.re, z.im]).collect();
        Real { n, m, r0, p, q }
    }

    /// Row `i`'s real-part coefficients (2n).
    fn p(&self, i: usize) -> &[f64] {
        &self.p[2 * self.n * i..2 * self.n * (i + 1)]
    }

    /// Row `i`'s imaginary-part coefficients (2n).
    fn q(&self, i: usize) -> &[f64] {
        &self.q[2 * self.n * i..2 * self.n * (i + 1)]
    }

    fn residual(&self, i: usize, x: &[f64]) -> [f64; 2] {
        let dot = |v: &[f64]| v.iter().zip(x).map(|(a, b)| a * b).sum::<f64>();
        [
            self.r0[i][0] + dot(self.p(i)),
            self.r0[i][1] + dot(self.q(i)),
        ]
    }

    fn residuals(&self, x: &[f64]) -> Vec<f64> {
        (0..self.m)
            .map(|i| {
                let r = self.residual(i, x);
                r[0].hypot(r[1])
            })
            .collect()
    }

    /// `P_aᵀ r_a`, the half gradient of `|r_a|²`.
    fn gradient(&self, i: usize, x: &[f64]) -> Vec<f64> {
        let r = self.residual(i, x);
        (0..2 * self.n)
            .map(|j| self.p(i)[j] * r[0] + self.q(i)[j] * r[1])
            .collect()
    }

    /// Newton on the augmented KKT system of least squares under the
    /// bounds `kset` (indices into `bounds`) from `x0`: unknowns `r` (2 per
    /// row), `x`, `ν`; the converged `(x, ν)`, or `None`.
    fn newton_least_squares(
        &self,
        x0: &[f64],
        bounds: &[(usize, f64)],
        kset: &[usize],
    ) -> Option<(Vec<f64>, Vec<f64>)> {
        let (n, n2, m2) = (self.n, 2 * self.n, 2 * self.m);
        let nk = kset.len();
        let dim = m2 + n2 + nk;
        let mut x = x0.to_vec();
        let mut r: Vec<f64> = (0..self.m).flat_map(|i| self.residual(i, &x)).collect();
        // Multipliers fitted to x0 (SVD least squares): Pᵀ r + Σ ν E x = 0.
        let pr: Vec<f64> = (0..n2)
            .map(|j| {
                (0..self.m)
                    .map(|i| self.p(i)[j] * r[2 * i] + self.q(i)[j] * r[2 * i + 1])
                    .sum()
            })
            .collect();
        let fit = DMatrix::from_fn(n2, nk, |row, c| {
            let k = bounds[kset[c]].0;
            if row == k || row == n + k {
                x[row]
            } else {
                0.0
            }
        });
        let mut nu: Vec<f64> = if nk == 0 {
            Vec::new()
        } else {
            let rhs = -DVector::from_vec(pr);
            least_squares_fit(fit, &rhs)?.iter().copied().collect()
        };
        let mut last = f64::INFINITY;
        for _ in 0..NEWTON {
            let mut f = DVector::zeros(dim);
            let mut j = DMatrix::zeros(dim, dim);
            // r − P x − r₀ = 0.
            for i in 0..self.m {
                let (ri, xi) = (2 * i, m2);
                let fit = self.residual(i, &x);
                f[ri] = r[ri] - fit[0];
                f[ri + 1] = r[ri + 1] - fit[1];
                j[(ri, ri)] = 1.0;
                j[(ri + 1, ri + 1)] = 1.0;
                for c in 0..n2 {
                    j[(ri, xi + c)] = -self.p(i)[c];
                    j[(ri + 1, xi + c)] = -self.q(i)[c];
                    // Pᵀ r: row m2 + c.
                    j[(m2 + c, ri)] = self.p(i)[c];
                    j[(m2 + c, ri + 1)] = self.q(i)[c];
                    f[m2 + c] += self.p(i)[c] * r[ri] + self.q(i)[c] * r[ri + 1];
                }
            }
            for (c, &kc) in kset.iter().enumerate() {
                let (k, mk) = bounds[kc];
                let col = m2 + n2 + c;
                for v in [k, n + k] {
                    f[m2 + v] += nu[c] * x[v];
                    j[(m2 + v, m2 + v)] += nu[c];
                    j[(m2 + v, col)] = x[v];
                    j[(col, m2 + v)] = 2.0 * x[v];
                }
                f[col] = x[k] * x[k] + x[n + k] * x[n + k] - mk * mk;
            }
            let step = newton_step(j, &f)?;
            for (v, d) in r.iter_mut().zip(&step[..m2]) {
                *v += d;
            }
            for (v, d) in x.iter_mut().zip(&step[m2..m2 + n2]) {
                *v += d;
            }
            for (v, d) in nu.iter_mut().zip(&step[m2 + n2..]) {
                *v += d;
            }
            let rn = r.iter().map(|v| v * v).sum::<f64>().sqrt();
            let xn = x.iter().map(|v| v * v).sum::<f64>().sqrt();
            let mn = bounds.iter().map(|b| b.1 * b.1).fold(0.0, f64::max);
            let stat = f.rows(m2, n2).amax();
            let settled = f.rows(0, m2).amax() <= 1e-13 * (1.0 + rn + xn)
                && stat <= 1e-11 * (rn + 1e-300) + 1e-14
                && (nk == 0 || f.rows(m2 + n2, nk).amax() <= 1e-11 * mn + 1e-300);
            let size = step[m2..m2 + n2].iter().map(|v| v * v).sum::<f64>().sqrt();
            if settled && (size <= 1e-14 * (1.0 + xn) || size >= last) {
                return Some((x, nu));
            }
            last = size;
        }
        None
    }

    /// Newton on the KKT system of the active rows `aset` and bounds `kset`
    /// (indices into `bounds`) from `x0`; the converged `(x, μ, ν)`, or `None`.
    #[allow(clippy::type_complexity)]
    fn newton(
        &self,
        x0: &[f64],
        aset: &[usize],
        bounds: &[(usize, f64)],
        kset: &[usize],
    ) -> Option<(Vec<f64>, Vec<f64>, Vec<f64>)> {
        let (n, n2) = (self.n, 2 * self.n);
        let (na, nk) = (aset.len(), kset.len());
        if na == 0 {
            return None;
        }
        let dim = n2 + 1 + na + nk;
        let mut x = x0.to_vec();
        let r2 = |x: &[f64], i: usize| {
            let r = self.residual(i, x);
            r[0] * r[0] + r[1] * r[1]
        };
        let mut s = aset.iter().map(|&i| r2(&x, i)).fold(0.0, f64::max);
        // Multipliers fitted to x0: least squares (SVD) of the stationarity
        // conditions with Σ μ = 1.
        let grads: Vec<Vec<f64>> = aset.iter().map(|&i| self.gradient(i, &x)).collect();
        let bgrad = |x: &[f64], c: usize| -> Vec<f64> {
            let k = bounds[kset[c]].0;
            let mut g = vec![0.0; n2];
            g[k] = x[k];
            g[n + k] = x[n + k];
            g
        };
        let fit = DMatrix::from_fn(n2 + 1, na + nk, |row, col| match (row < n2, col < na) {
            (true, true) => grads[col][row],
            (true, false) => bgrad(&x, col - na)[row],
            (false, true) => 1.0,
            (false, false) => 0.0,
        });
        let mut rhs = DVector::zeros(n2 + 1);
        rhs[n2] = 1.0;
        let lam = least_squares_fit(fit, &rhs)?;
        let mut mu: Vec<f64> = lam.iter().take(na).copied().collect();
        let mut nu: Vec<f64> = lam.iter().skip(na).copied().collect();
        let mut last = f64::INFINITY;
        for _ in 0..NEWTON {
            let grads: Vec<Vec<f64>> = aset.iter().map(|&i| self.gradient(i, &x)).collect();
            let bgrads: Vec<Vec<f64>> = (0..nk).map(|c| bgrad(&x, c)).collect();
            // F and its Jacobian J, rows: stationarity (2n), Σμ − 1, rows, bounds.
            let mut f = DVector::zeros(dim);
            let mut j = DMatrix::zeros(dim, dim);
            for (c, g) in grads.iter().enumerate() {
                for r in 0..n2 {
                    f[r] += mu[c] * g[r];
                    j[(r, n2 + 1 + c)] = g[r];
                    j[(n2 + 1 + c, r)] = 2.0 * g[r];
                }
                let i = aset[c];
                for r in 0..n2 {
                    for col in 0..n2 {
                        j[(r, col)] +=
                            mu[c] * (self.p(i)[r] * self.p(i)[col] + self.q(i)[r] * self.q(i)[col]);
                    }
                }
                f[n2 + 1 + c] = r2(&x, i) - s;
                j[(n2 + 1 + c, n2)] = -1.0;
                j[(n2, n2 + 1 + c)] = 1.0;
            }
            f[n2] = mu.iter().sum::<f64>() - 1.0;
            for (c, g) in bgrads.iter().enumerate() {
                let (k, m) = bounds[kset[c]];
                let col = n2 + 1 + na + c;
                for r in 0..n2 {
                    f[r] += nu[c] * g[r];
                    j[(r, col)] = g[r];
                    j[(col, r)] = 2.0 * g[r];
                }
                j[(k, k)] += nu[c];
                j[(n + k, n + k)] += nu[c];
                f[col] = x[k] * x[k] + x[n + k] * x[n + k] - m * m;
            }
            let step = newton_step(j, &f)?;
            for (xi, d) in x.iter_mut().zip(&step[..n2]) {
                *xi += d;
            }
            s += step[n2];
            for (v, d) in mu.iter_mut().zip(&step[n2 + 1..n2 + 1 + na]) {
                *v += d;
            }
            for (v, d) in nu.iter_mut().zip(&step[n2 + 1 + na..]) {
                *v += d;
            }
            // Converged when F (before this step) is at rounding and the
            // steps have stopped shrinking: stationarity against the peak
            // `√s`, the constraints against `s`.
            let stat = f.rows(0, n2).amax() + f[n2].abs();
            let cons = f.rows(n2 + 1, na + nk).amax();
            let size = step[..n2].iter().map(|v| v * v).sum::<f64>().sqrt();
            let xn = x.iter().map(|v| v * v).sum::<f64>().sqrt();
            let settled = stat <= 1e-11 * s.sqrt().max(1e-300) + 1e-14 && cons <= 1e-11 * s + 1e-14;
            if settled && (size <= 1e-14 * (1.0 + xn) || size >= last) {
                return Some((x, mu, nu));
            }
            last = size;
        }
        // Not converged: no certificate from this guess.
        None
    }
}

/// `y` as the real unknowns `[Re y; Im y]` of the polishing programs.
fn stacked(y: &[Complex64]) -> Vec<f64> {
    y.iter()
        .map(|v| v.re)
        .chain(y.iter().map(|v| v.im))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> Complex64 {
        Complex64::new(re, im)
    }

    #[test]
    fn a_point_off_the_optimum_is_moved_onto_it() {
        // One plane, two sensors: the optimum equalises the two residuals on
        // the segment between the zeros u_a = −b_a/a_a.
        let a = DMatrix::from_column_slice(2, 1, &[c(1.0, 0.0), c(1.0, 0.0)]);
        let b = DVector::from_column_slice(&[c(-1.0, 0.0), c(1.0, 0.0)]);
        let got = polish(&a, &b, &[], &[c(1e-4, 2e-4)]).unwrap();
        assert!(got[0].norm() <= 1e-15, "{got:?}");
    }
}
