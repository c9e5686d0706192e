//! Runs as linear combinations of readings: influence coefficients estimated
//! from any set of trial runs, each against its own reference run (method 2.1,
//! `W = ΔY T⁺` through the SVD of `T`), their covariance from reading noise, and
//! the χ² test of runs against what other data predict.
//!
//! Every quantity here is complex-linear in the readings, so its error is
//! `Σ_m g_m δy_m` over independent readings with 2×2 covariances; a complex
//! factor `g` acts on (Re, Im) as the rotation-scaling `R(g)`.
//!
//! The test: the differences `e = ΔY_K − W T_K` of the tested runs `K` at every
//! row, whitened by their covariance (the tested readings' noise plus the
//! propagated noise of `W`), sum to `χ² = Σ_a e_aᵀ Σ_a⁻¹ e_a` with `2·|K|·rows`
//! degrees of freedom under "the runs are what their weights say". They are
//! called consistent when `χ²` is at most its 99 % quantile (a false alarm in
//! 1 of 100 honest runs).

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

/// Relative singular value below which trial weights count as dependent (as in `influence`).
const RANK_TOLERANCE: f64 = 1e-9;
/// Level of the consistency test.
pub const CHECK_LEVEL: f64 = 0.99;
/// Standard normal quantile of [`CHECK_LEVEL`].
const Z_99: f64 = 2.326_347_874_040_841;

/// One trial run: its column, its reference run's column, its weights (planes).
#[derive(Debug, Clone)]
pub struct Trial {
    pub col: usize,
    pub reference: usize,
    pub weights: DVector<Complex64>,
}

/// Readings of one or more sessions on common rows.
#[derive(Debug, Clone)]
pub struct Data {
    /// Rows × columns, internal phasors (runout subtracted).
    pub y: DMatrix<Complex64>,
    /// `cov[a][m]`: covariance of `y[(a, m)]`.
    pub cov: Vec<Vec<Matrix2<f64>>>,
    pub trials: Vec<Trial>,
    pub planes: usize,
}

/// Influence coefficients as a combination of readings: `W = y D`.
#[derive(Debug, Clone)]
pub struct Estimate {
    /// Columns × planes.
    pub d: DMatrix<Complex64>,
    /// Rows × planes.
    pub w: DMatrix<Complex64>,
}

/// Where the prediction of the tested runs comes from.
pub enum Source<'a> {
    /// Estimated from other runs of the same data.
    Estimated(&'a Estimate),
    /// Given from outside, with a covariance per coefficient (`[row][plane]`).
    Given(&'a DMatrix<Complex64>, &'a [Vec<Matrix2<f64>>]),
}

/// A test of some runs against a prediction.
#[derive(Debug, Clone)]
pub struct Test {
    /// `[tested run][row]`: the prediction of the run's reading.
    pub predicted: Vec<Vec<Complex64>>,
    /// `[tested run][row]`: covariance of reading − prediction.
    pub cov: Vec<Vec<Matrix2<f64>>>,
    pub chi2: f64,
    pub dof: usize,
    pub consistent: bool,
}

/// `R(g)`: multiplication by `g` on (Re, Im).
pub fn rot(g: Complex64) -> Matrix2<f64> {
    Matrix2::new(g.re, -g.im, g.im, g.re)
}

/// Whether the trials `set` give every plane an independent trial.
pub fn determines(data: &Data, set: &[usize]) -> bool {
    if set.len() < data.planes || data.planes == 0 {
        return false;
    }
    let t = weights(data, set);
    let sv = t.singular_values();
    let max = sv.max();
    max > 0.0 && sv.iter().all(|&s| s > RANK_TOLERANCE * max)
}

fn weights(data: &Data, set: &[usize]) -> DMatrix<Complex64> {
    DMatrix::from_fn(data.planes, set.len(), |j, k| {
        data.trials[set[k]].weights[j]
    })
}

/// `W = ΔY T⁺` from the trials `set` (method 2.1), or `None` when they do not
/// determine it.
pub fn estimate(data: &Data, set: &[usize]) -> Option<Estimate> {
    if !determines(data, set) {
        return None;
    }
    let p = weights(data, set)
        .svd(true, true)
        .pseudo_inverse(0.0)
        .ok()?;
    let mut d = DMatrix::zeros(data.y.ncols(), data.planes);
    for (i, &k) in set.iter().enumerate() {
        let tr = &data.trials[k];
        for j in 0..data.planes {
            d[(tr.col, j)] += p[(i, j)];
            d[(tr.reference, j)] -= p[(i, j)];
        }
    }
    let w = &data.y * &d;
    Some(Estimate { d, w })
}

/// Covariance of each `W_aj` of an estimate: `[row][plane]`.
pub fn covariance(data: &Data, est: &Estimate) -> Vec<Vec<Matrix2<f64>>> {
    (0..data.y.nrows())
        .map(|a| {
            (0..data.planes)
                .map(|j| {
                    (0..data.y.ncols())
                        .filter(|&m| est.d[(m, j)] != Complex64::default())
                        .map(|m| {
                            let r = rot(est.d[(m, j)]);
                            r * data.cov[a][m] * r.transpose()
                        })
                        .sum()
                })
                .collect()
        })
        .collect()
}

/// Test the trials `tested` at `rows` against `source`.
pub fn test(data: &Data, tested: &[usize], rows: &[usize], source: Source) -> Test {
    let m_cols = data.y.ncols();
    let n_k = tested.len();
    // g[k][m]: coefficient of column m in e_k = ΔY_k − W T_k.
    let g: Vec<Vec<Complex64>> = tested
        .iter()
        .map(|&k| {
            let tr = &data.trials[k];
            let mut g = vec![Complex64::default(); m_cols];
            g[tr.col] += 1.0;
            g[tr.reference] -= 1.0;
            if let Source::Estimated(est) = &source {
                for (m, gm) in g.iter_mut().enumerate() {
                    *gm -= (0..data.planes)
                        .map(|j| est.d[(m, j)] * tr.weights[j])
                        .sum::<Complex64>();
                }
            }
            g
        })
        .collect();
    let w = match &source {
        Source::Estimated(est) => &est.w,
        Source::Given(w, _) => *w,
    };
    let mut predicted = vec![Vec::with_capacity(rows.len()); n_k];
    let mut covs = vec![Vec::with_capacity(rows.len()); n_k];
    let mut chi2 = 0.0;
    for &a in rows {
        let mut e = DVector::<f64>::zeros(2 * n_k);
        let mut cov = DMatrix::<f64>::zeros(2 * n_k, 2 * n_k);
        let mut scale: f64 = 0.0;
        for (i, &k) in tested.iter().enumerate() {
            let tr = &data.trials[k];
            let pred = data.y[(a, tr.reference)]
                + (0..data.planes)
                    .map(|j| w[(a, j)] * tr.weights[j])
                    .sum::<Complex64>();
            let diff = data.y[(a, tr.col)] - pred;
            e[2 * i] = diff.re;
            e[2 * i + 1] = diff.im;
            scale = scale.max(data.y[(a, tr.col)].norm()).max(pred.norm());
            predicted[i].push(pred);
        }
        // Readings' part: J_m = stack of R(g_km), Σ J_m Σ_am J_mᵀ.
        for m in 0..m_cols {
            if g.iter().all(|gk| gk[m] == Complex64::default()) {
                continue;
            }
            let j = stack(n_k, |i| rot(g[i][m]));
            cov += &j * to_d(&data.cov[a][m]) * j.transpose();
        }
        // Given coefficients' part: e_k has −W_aj T_jk.
        if let Source::Given(_, wcov) = &source {
            for (jp, wc) in wcov[a].iter().enumerate() {
                let j = stack(n_k, |i| rot(-data.trials[tested[i]].weights[jp]));
                cov += &j * to_d(wc) * j.transpose();
            }
        }
        for (i, c) in covs.iter_mut().enumerate() {
            c.push(cov.fixed_view::<2, 2>(2 * i, 2 * i).into_owned());
        }
        // A floor keeps noise-free data (options of zero noise) testable.
        let floor = (1e-9 * scale).powi(2) + f64::MIN_POSITIVE;
        cov += DMatrix::identity(2 * n_k, 2 * n_k) * floor;
        let x = cov
            .clone()
            .cholesky()
            .map(|c| c.solve(&e))
            .unwrap_or_else(|| cov.svd(true, true).solve(&e, 0.0).unwrap_or(e.clone()));
        chi2 += e.dot(&x);
    }
    let dof = 2 * n_k * rows.len();
    Test {
        predicted,
        cov: covs,
        chi2,
        dof,
        consistent: chi2 <= chi2_quantile(dof),
    }
}

fn to_d(m: &Matrix2<f64>) -> DMatrix<f64> {
    DMatrix::from_fn(2, 2, |i, j| m[(i, j)])
}

/// `2n × 2` stack of 2×2 blocks.
fn stack(n: usize, f: impl Fn(usize) -> Matrix2<f64>) -> DMatrix<f64> {
    let mut j = DMatrix::zeros(2 * n, 2);
    for i in 0..n {
        j.fixed_view_mut::<2, 2>(2 * i, 0).copy_from(&f(i));
    }
    j
}

/// The [`CHECK_LEVEL`] quantile of χ² with `k` degrees of freedom
/// (Wilson–Hilferty; exact `−2 ln 0.01` for `k = 2`).
pub fn chi2_quantile(k: usize) -> f64 {
    if k == 0 {
        return 0.0;
    }
    if k == 2 {
        return -2.0 * (1.0 - CHECK_LEVEL).ln();
    }
    let k = k as f64;
    let h = 2.0 / (9.0 * k);
    k * (1.0 - h + Z_99 * h.sqrt()).powi(3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_chi2_quantile_matches_tables() {
        // χ²₀.₉₉ tables: k = 4 → 13.277, 10 → 23.209, 40 → 63.691.
        for (k, want) in [(2, 9.2103), (4, 13.277), (10, 23.209), (40, 63.691)] {
            assert!((chi2_quantile(k) - want).abs() / want < 0.01, "{k}");
        }
    }
}
