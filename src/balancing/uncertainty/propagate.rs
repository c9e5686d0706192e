//! First-order propagation of reading noise through the influence coefficients
//! (method 2.1) and the weighted least-squares correction (method 3.2, 3.3) to
//! the correction and the predicted residual (method 3.1).
//!
//! Every reading is an independent complex quantity with a real 2×2 covariance.
//! The chain is real-linear but not complex-linear in the readings (the least-
//! squares derivative contains `dWᴴ`): each reading `δ` moves an output by
//! `α δ + β δ̄`, and the output's real covariance follows from the complex
//! covariance and pseudo-covariance (`E[z zᴴ]`, `E[z zᵀ]`) summed over readings.

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

use crate::balancing::factor::{cmul, Factored, ThinSvd};

/// Singular values below this fraction of the largest count as zero (as in the solver).
const RANK_TOLERANCE: f64 = 1e-10;

/// Covariances of everything a solution reports, internal frame, from reading noise.
#[derive(Debug, Clone, PartialEq)]
pub struct Propagation {
    /// Per used plane (in the order of `used_planes`), 2×2 covariance of (Re C, Im C), g².
    pub correction: Vec<Matrix2<f64>>,
    /// Joint covariance of all used planes' corrections, `2q × 2q`, ordered
    /// (Re C₀, Im C₀, Re C₁, …): the planes' errors are correlated.
    pub correction_full: DMatrix<f64>,
    /// Per row (all rows, used or not): covariance of the vibration that will
    /// actually remain once the correction `C` is fitted, around the prediction
    /// `R̂`. `R_true − R̂ = −(dY0 + dW C)` to first order: the errors of this
    /// row's readings, with `C` fixed (it is what goes on the rotor); i.e. the
    /// true vibration given the readings, as with a flat prior on the true `Y0`
    /// and `W`. This is what `amplitude_95` bounds. Over repeated experiments it
    /// is calibrated when rows = planes and conservative when there are more
    /// rows (the fit takes part of the reading noise into `R̂` itself); see
    /// tests/uncertainty. It leaves out the noise of a future check reading.
    pub residual: Vec<Matrix2<f64>>,
    /// Per row: covariance of the prediction `R̂ = Y0 + W C` itself over
    /// repeated experiments, through the whole chain including `dC`. For a
    /// square problem (as many rows as planes) `R̂ ≡ 0` and this is 0, which is
    /// why it is not the bound of the residual.
    pub prediction: Vec<Matrix2<f64>>,
    /// Per row (all rows): covariance of `W_a dC`, the error of the remaining
    /// vibration that comes through the correction alone: `w K wᴴ`, `w J wᵀ`
    /// with `K`, `J` of `correction_full`, already formed for `prediction`
    /// (what `remaining` needs; issue 15 read it from here rather than
    /// recomputing a `2q × 2q` form per row).
    pub through_correction: Vec<Matrix2<f64>>,
    /// Per row (all rows): the real cross-covariance `E[u vᵀ]` of `u = W_a dC`
    /// (`through_correction`) and the prediction's error `v = dR̂_a`, entry
    /// `(i, j)` = `E[u_i v_j]` over (Re, Im). Not zero: `v = u + e_a` with the
    /// row's own reading errors `e_a`, which also move `dC` (issue 12, item 2:
    /// `remaining` conditions on it).
    pub remaining_cross: Vec<Matrix2<f64>>,
    /// Rows × planes (all planes): standard deviation `√tr Cov` (the RMS of the
    /// complex error) of each plane's trial effect `E_aj = W_aj·τ_j`, where
    /// `τ_j = max_k |T_jk|` is the plane's largest trial mass. With one trial per
    /// plane (`T` diagonal) `E_aj` is exactly the change `Y_aj − Y_a0` of method 2.
    pub effect_sd: DMatrix<f64>,
    /// `[(AᴴA)⁻¹]_jj` per used plane from the same thin SVD of `A = G W`, or
    /// `None` when `A` is rank deficient (a singular value at or below the
    /// rank tolerance): what `trust::kappa` needs, without a second SVD (issue 15).
    pub gram_inv_diag: Option<Vec<f64>>,
}

/// `(A⁺, (AᴴA)⁺)` from the SVD of `A`, never forming `AᴴA` itself; the thin
/// SVD goes through the QR of a tall `A` (`factor`, issue 15).
pub(super) fn svd_parts(a: &DMatrix<Complex64>) -> (DMatrix<Complex64>, DMatrix<Complex64>) {
    let svd = ThinSvd::of(a);
    svd.pinv_and_gram_inv(RANK_TOLERANCE * svd.max())
}

/// Second moments of a complex error `z`: `k = E[z z̄]` and the pseudo-
/// covariance `p = E[z²]`; for a vector, `K = E[z zᴴ]` and `J = E[z zᵀ]`.
/// Together they are the real covariance of (Re z, Im z) (see [`real_cov`]),
/// and for `dC = α δ + β δ̄` they sum over independent readings without ever
/// forming a per-reading Jacobian.
pub(super) fn moments(cov: &Matrix2<f64>) -> (f64, Complex64) {
    (
        cov[(0, 0)] + cov[(1, 1)],
        Complex64::new(cov[(0, 0)] - cov[(1, 1)], cov[(0, 1)] + cov[(1, 0)]),
    )
}

/// The real 2×2 covariance of (Re z, Im z) from `k = E|z|²` and `p = E[z²]`.
fn real_cov(k: f64, p: Complex64) -> Matrix2<f64> {
    Matrix2::new((k + p.re) / 2.0, p.im / 2.0, p.im / 2.0, (k - p.re) / 2.0)
}

/// The real `2q × 2q` covariance, ordered (Re z₀, Im z₀, Re z₁, …), from
/// `K = E[z zᴴ]` and `J = E[z zᵀ]`: `E[x_j x_l] = Re(K+J)/2`,
/// `E[y_j y_l] = Re(K−J)/2`, `E[x_j y_l] = Im(J−K)/2`, `E[y_j x_l] = Im(J+K)/2`.
fn real_cov_full(k: &DMatrix<Complex64>, j: &DMatrix<Complex64>) -> DMatrix<f64> {
    let q = k.nrows();
    DMatrix::from_fn(2 * q, 2 * q, |r, c| {
        let (kk, jj) = (k[(r / 2, c / 2)], j[(r / 2, c / 2)]);
        match (r % 2, c % 2) {
            (0, 0) => (kk.re + jj.re) / 2.0,
            (1, 1) => (kk.re - jj.re) / 2.0,
            (0, _) => (jj.im - kk.im) / 2.0,
            _ => (jj.im + kk.im) / 2.0,
        }
    })
}

/// Propagate reading noise to the correction and the residual.
///
/// - `t`: planes × trial runs weights (exact); `y`: rows × (1 + trial runs)
///   readings, column 0 the reference `Y0`; `cov[a][k]` the 2×2 covariance of `y[(a, k)]`;
/// - `used_rows`, `row_weights` (one per used row, `G` of 3.3), `used_planes`;
/// - `c`: the correction of the used planes.
///
/// With `A = G W[u,p]`, `b = G Y0[u]`, `r = A C + b` (the weighted residual),
/// differentiating the normal equations `Aᴴ(A C + b) = 0` gives
/// `dC = −A⁺(dA C + db) − (AᴴA)⁻¹ dAᴴ r`. The second term vanishes for an exact
/// fit and is what makes `dC` not complex-linear. `dW = (dY_trial − dY0 1ᵀ) T⁺`
/// (2.1), `dR = dY0 + dW[:,p] C + W[:,p] dC` (3.1).
///
/// A reading `(a, k)` moves only row `a` of `W`, by `δ ω_k` with `ω_0 = −1ᵀT⁺`
/// and `ω_k = T⁺[k−1, :]`, so `dC = α δ + β δ̄` with
/// `α = −g λ_k A⁺[:, i]`, `β = −g r_i (AᴴA)⁻¹ ω̄_k`, where `λ_k = ω_k·C (+1 for
/// k = 0)` is also the reading's direct effect on `R_a`. The covariances are
/// summed in complex form (`E[dC dCᴴ]`, `E[dC dCᵀ]`) as a few matrix products,
/// so time is `O(rows · runs · planes + rows · planes²)` and memory
/// `O(rows · (runs + planes))`.
///
/// Extension point: a covariance of supplied influence coefficients (not
/// estimated from these readings) adds its own term to `K`, `J` below (`dC`
/// from `dW` is `−A⁺ G dW C − (AᴴA)⁻¹ G dWᴴ r`) before they become real.
///
/// For a solution that is not the least-squares one (min-max, active mass
/// bounds), this is the derivative of the least-squares solution taken at `c`:
/// an approximation, see [`super::fill`].
pub fn propagate(
    t: &DMatrix<Complex64>,
    y: &DMatrix<Complex64>,
    cov: &[Vec<Matrix2<f64>>],
    used_rows: &[usize],
    row_weights: &[f64],
    used_planes: &[usize],
    c: &DVector<Complex64>,
) -> Propagation {
    propagate_factored(t, y, cov, used_rows, row_weights, used_planes, c, None)
}

/// What the solve already computed that the propagation needs (issue 15).
#[derive(Clone, Copy)]
pub struct Known<'a> {
    /// `T⁺`, trial runs × planes.
    pub t_pinv: &'a DMatrix<Complex64>,
    /// `W = ΔY T⁺`, rows × planes (method 2.1).
    pub w: &'a DMatrix<Complex64>,
    /// The factorisation of `A = G W[u,p]`.
    pub factor: &'a Factored,
}

/// [`propagate`] with what the solve already has: `T⁺`, `W` and the
/// factorisation of `A = G W[u,p]` (issue 15: `A⁺` and `(AᴴA)⁺` from the one
/// factorisation, not a QR and SVD of their own); `None` computes them here.
#[allow(clippy::too_many_arguments)]
pub fn propagate_factored(
    t: &DMatrix<Complex64>,
    y: &DMatrix<Complex64>,
    cov: &[Vec<Matrix2<f64>>],
    used_rows: &[usize],
    row_weights: &[f64],
    used_planes: &[usize],
    c: &DVector<Complex64>,
    known: Option<Known>,
) -> Propagation {
    let (n, runs) = y.shape();
    let planes = t.nrows();
    let q = used_planes.len();
    let (own_tp, own_w);
    let (tp, w) = match known {
        Some(k) => (k.t_pinv, k.w),
        None => {
            own_tp = svd_parts(t).0;
            own_w = DMatrix::from_fn(n, planes, |a, j| {
                (1..runs)
                    .map(|k| (y[(a, k)] - y[(a, 0)]) * own_tp[(k - 1, j)])
                    .sum::<Complex64>()
            });
            (&own_tp, &own_w)
        }
    };
    // Column sums of T⁺: how the reference reading enters every influence coefficient.
    let s: Vec<Complex64> = (0..planes).map(|j| tp.column(j).sum()).collect();
    let amat = DMatrix::from_fn(used_rows.len(), q, |i, j| {
        w[(used_rows[i], used_planes[j])] * row_weights[i]
    });
    let b = DVector::from_fn(used_rows.len(), |i, _| {
        y[(used_rows[i], 0)] * row_weights[i]
    });
    let r = &amat * c + b;
    let own;
    let factor = match known {
        Some(k) => k.factor,
        None => {
            own = Factored::of(&amat);
            &own
        }
    };
    let tol = RANK_TOLERANCE * factor.max();
    let gram_inv = factor.gram_inv(tol);
    let sv = factor.singular_values();
    let full_rank = sv.len() == q && sv.iter().all(|&s| s > tol);
    let gram_inv_diag = full_rank.then(|| (0..q).map(|j| gram_inv[(j, j)].re).collect());
    let mut position = vec![None; n];
    for (i, &a) in used_rows.iter().enumerate() {
        position[a] = Some(i);
    }
    // Per run k: ω_k over the used planes, λ_k, and (AᴴA)⁻¹ ω̄_k.
    let omega: Vec<DVector<Complex64>> = (0..runs)
        .map(|k| {
            DVector::from_fn(q, |j, _| match k {
                0 => -s[used_planes[j]],
                _ => tp[(k - 1, used_planes[j])],
            })
        })
        .collect();
    let lambda: Vec<Complex64> = (0..runs)
        .map(|k| {
            omega[k]
                .iter()
                .zip(c.iter())
                .map(|(o, cj)| o * cj)
                .sum::<Complex64>()
                + if k == 0 { 1.0 } else { 0.0 }
        })
        .collect();
    let g_omega: Vec<DVector<Complex64>> = omega
        .iter()
        .map(|o| &gram_inv * o.map(|x| x.conj()))
        .collect();

    // Per reading (a, k) at used position i: dC = α δ + β δ̄ with α = λ_k a_i,
    // a_i = −g A⁺[:, i], and β = b_i ξ_k, b_i = −g r_i, ξ_k = (AᴴA)⁻¹ ω̄_k. With
    // s = E|δ|², p = E[δ²] of the reading, summed over independent readings:
    //   K = Σ s(|λ|² a aᴴ + |b|² ξ ξᴴ) + (p λ b̄ a ξᴴ + its adjoint),
    //   J = Σ p λ² a aᵀ + p̄ b² ξ ξᵀ + s λ b (a ξᵀ + ξ aᵀ),
    // each a product of a q × rows, a rows × runs and a runs × q matrix: time
    // O(rows·runs·q + rows·q²) and memory O(rows·(runs + q)), never a
    // Jacobian per reading (issue 15).
    let m = used_rows.len();
    // Moments of a row's readings, formed where they are summed (four
    // additions each: cheaper than a flat copy of them all, issue 15).
    let row_moments = |a: usize| cov[a][..runs].iter().map(moments);
    // |λ_k|² and λ_k², once per run rather than once per reading.
    let lambda_sq: Vec<(f64, Complex64)> = lambda.iter().map(|l| (l.norm_sqr(), l * l)).collect();
    // a = −A⁺ G = −(AᴴA)⁺ Aᴴ G, one `q × q × rows` product from the `(AᴴA)⁺`
    // of the SVD of `R` (issue 15; `R⁺ Qᴴ` through the reflectors took three).
    // Not the normal equations: `AᴴA` is never formed, and with the SVD of
    // `R + δR` backward stable, `(R̃ᴴR̃)⁻¹ Rᴴ = R̃⁻¹ (I − R̃⁻ᴴ δRᴴ)` is `A⁺`
    // within `ε κ ‖A⁺‖`, the accuracy of `R̃⁻¹ Qᴴ` itself.
    let neg_ah_g = DMatrix::from_fn(q, m, |j, i| -amat[(i, j)].conj() * row_weights[i]);
    let a_vec = cmul(&gram_inv, &neg_ah_g);
    let b_vec: Vec<Complex64> = (0..m).map(|i| -r[i] * row_weights[i]).collect();
    let xi = DMatrix::from_fn(q, runs, |j, k| g_omega[k][j]);
    let zero = Complex64::from(0.0);
    let k_mat;
    let j_mat;
    // Per used row, `mk = p3 ξᴴ` and `mj = s3 ξᵀ` (see below), which also
    // give the cross terms of a row's own readings.
    let mk;
    let mj;
    // s1, p1 per used row, s2, p2 per run.
    let (mut s1, mut p1) = (vec![0.0; m], vec![zero; m]);
    {
        // s1, p1, s2, p2 and the readings' moments as real matrices, in one
        // pass over the readings (the same sums in the same order as one
        // pass each): [Re p; Im p] (2m × runs) and s (m × runs).
        let (mut s2, mut p2) = (vec![0.0; runs], vec![zero; runs]);
        let mut pp = DMatrix::<f64>::zeros(2 * m, runs);
        let mut sm = DMatrix::<f64>::zeros(m, runs);
        for (i, &a) in used_rows.iter().enumerate() {
            let bi = b_vec[i];
            let (bn, b2) = (bi.norm_sqr(), bi * bi);
            for (k, (sk, pk)) in row_moments(a).enumerate() {
                let (ln, l2) = lambda_sq[k];
                s1[i] += sk * ln;
                p1[i] += pk * l2;
                s2[k] += sk * bn;
                p2[k] += pk.conj() * b2;
                pp[(i, k)] = pk.re;
                pp[(m + i, k)] = pk.im;
                sm[(i, k)] = sk;
            }
        }
        // p3 = diag(b̄) P diag(λ) and s3 = diag(b) S diag(λ), so
        // mk = p3 ξᴴ = diag(b̄) P (diag(λ) ξᴴ) and mj = diag(b) S (diag(λ) ξᵀ):
        // with S real, three real products instead of eight (issue 15).
        let mut xy = DMatrix::<f64>::zeros(runs, 4 * q);
        for k in 0..runs {
            for j in 0..q {
                let x = lambda[k] * xi[(j, k)].conj();
                let y = lambda[k] * xi[(j, k)];
                xy[(k, j)] = x.re;
                xy[(k, q + j)] = x.im;
                xy[(k, 2 * q + j)] = y.re;
                xy[(k, 3 * q + j)] = y.im;
            }
        }
        let px = &pp * xy.columns(0, 2 * q);
        let sy = &sm * xy.columns(2 * q, 2 * q);
        mk = DMatrix::from_fn(m, q, |i, j| {
            let re = px[(i, j)] - px[(m + i, q + j)];
            let im = px[(i, q + j)] + px[(m + i, j)];
            b_vec[i].conj() * Complex64::new(re, im)
        });
        mj = DMatrix::from_fn(m, q, |i, j| {
            b_vec[i] * Complex64::new(sy[(i, j)], sy[(i, q + j)])
        });
        let xi_scaled = |d: &[f64]| {
            let mut x = xi.clone();
            for (k, mut col) in x.column_iter_mut().enumerate() {
                col *= Complex64::from(d[k].sqrt());
            }
            x
        };
        // a diag(s1) aᴴ + k3 + k3ᴴ as X + Xᴴ with X = a (diag(s1/2) aᴴ + p3 ξᴴ),
        // and the same for J with transposes: one q × rows × q product each
        // instead of three (issue 15). diag(s1) is real and diag(p1) enters
        // a symmetric form, so halving it on both sides is exact. Both in
        // one product `a [mk | mj]`.
        let mut mkj = DMatrix::from_element(m, 2 * q, zero);
        for i in 0..m {
            let (half_s, half_p) = (s1[i] * 0.5, p1[i] * 0.5);
            for j in 0..q {
                let aij = a_vec[(j, i)];
                mkj[(i, j)] = mk[(i, j)] + half_s * aij.conj();
                mkj[(i, q + j)] = mj[(i, j)] + half_p * aij;
            }
        }
        let akj = cmul(&a_vec, &mkj);
        let (ak, aj) = (akj.columns(0, q), akj.columns(q, q));
        let xs = xi_scaled(&s2);
        k_mat = ak + ak.adjoint() + &xs * xs.adjoint();
        let mut xp = xi.clone();
        for (k, mut col) in xp.column_iter_mut().enumerate() {
            col *= p2[k];
        }
        j_mat = aj + aj.transpose() + xp * xi.transpose();
    }
    let correction_full = real_cov_full(&k_mat, &j_mat);
    let correction = (0..q)
        .map(|j| {
            correction_full
                .fixed_view::<2, 2>(2 * j, 2 * j)
                .into_owned()
        })
        .collect();

    // dR̂_a = W̃_a dC + Σ_k λ_k δ_ak: the direct part (alone `residual`), the
    // part through C (w K wᴴ, w J wᵀ), and for a used row the cross terms of
    // its own readings, whose share of dC is (w·a_i) λ_k δ + (w·ξ_k) b_i δ̄.
    // Summed over the row's readings these are
    //   E[u ē] = (w·a_i) s1_i + Σ_k (w·ξ_k) b_i λ̄_k p̄_k = (w·a_i) s1_i + w·conj(mk_i),
    //   E[u e] = (w·a_i) p1_i + Σ_k (w·ξ_k) b_i λ_k s_k = (w·a_i) p1_i + w·mj_i,
    // `q` products per row instead of a `rows × q × runs` product `W ξ` and
    // a pass over the row's readings (issue 15).
    // `W` itself when every plane is used (no copy).
    let w_sub = (!used_planes.iter().copied().eq(0..planes))
        .then(|| DMatrix::from_fn(n, q, |a, j| w[(a, used_planes[j])]));
    let w_used = w_sub.as_ref().unwrap_or(w);
    // [w K | w J] in one product (n × 2q).
    let mut kj = DMatrix::from_element(q, 2 * q, zero);
    kj.columns_mut(0, q).copy_from(&k_mat);
    kj.columns_mut(q, q).copy_from(&j_mat);
    let wkj = cmul(w_used, &kj);
    let mut through_correction = Vec::with_capacity(n);
    let mut remaining_cross = Vec::with_capacity(n);
    let mut residual = Vec::with_capacity(n);
    let mut prediction = Vec::with_capacity(n);
    for a in 0..n {
        let (mut kx, mut jx) = (zero, zero);
        let (kd, jd) = match position[a] {
            // The same sums, in the same order, as s1 and p1.
            Some(i) => {
                // w_a · a_i, the row's own share (never a rows × rows product).
                let wa = w_used.row(a).tr_dot(&a_vec.column(i));
                kx = wa * s1[i];
                jx = wa * p1[i];
                for j in 0..q {
                    let waj = w_used[(a, j)];
                    kx += waj * mk[(i, j)].conj();
                    jx += waj * mj[(i, j)];
                }
                (s1[i], p1[i])
            }
            None => {
                let (mut kd, mut jd) = (0.0, zero);
                for (k, (sk, pk)) in row_moments(a).enumerate() {
                    let (ln, l2) = lambda_sq[k];
                    kd += sk * ln;
                    jd += pk * l2;
                }
                (kd, jd)
            }
        };
        let (mut kt, mut jt) = (zero, zero);
        for j in 0..q {
            let wa = w_used[(a, j)];
            kt += wkj[(a, j)] * wa.conj();
            jt += wkj[(a, q + j)] * wa;
        }
        let through = real_cov(kt.re, jt);
        // E[u ēₐ] = kx and E[u eₐ] = jx as a real cross-covariance
        // (E[u₁e₁] = Re(kx+jx)/2, E[u₁e₂] = Im(jx−kx)/2, E[u₂e₁] =
        // Im(jx+kx)/2, E[u₂e₂] = Re(kx−jx)/2); Cov(u, v) = Σ_u + Cov(u, eₐ).
        let cross_e = Matrix2::new(
            (kx.re + jx.re) / 2.0,
            (jx.im - kx.im) / 2.0,
            (jx.im + kx.im) / 2.0,
            (kx.re - jx.re) / 2.0,
        );
        remaining_cross.push(through + cross_e);
        through_correction.push(through);
        residual.push(real_cov(kd, jd));
        prediction.push(real_cov(kt.re + kd + 2.0 * kx.re, jt + jd + 2.0 * jx));
    }

    // Trial effects: dW_aj = Σ_k dY_a,k T⁺_kj − dY_a0 s_j, independent terms; a
    // complex factor rotates a covariance without changing its trace. The
    // variances of all (row, plane) pairs are one real product of the
    // readings' traces (rows × runs) by `[|s_j|²; |T⁺_kj|²]` (runs × planes)
    // (issue 15).
    let taus: Vec<f64> = (0..planes)
        .map(|j| (0..t.ncols()).map(|k| t[(j, k)].norm()).fold(0.0, f64::max))
        .collect();
    let gains = DMatrix::from_fn(runs, planes, |k, j| match k {
        0 => s[j].norm_sqr(),
        _ => tp[(k - 1, j)].norm_sqr(),
    });
    let traces = DMatrix::from_fn(n, runs, |a, k| cov[a][k].trace());
    let var = traces * gains;
    let effect_sd = DMatrix::from_fn(n, planes, |a, j| taus[j] * var[(a, j)].sqrt());
    Propagation {
        correction,
        correction_full,
        residual,
        prediction,
        through_correction,
        remaining_cross,
        effect_sd,
        gram_inv_diag,
    }
}
