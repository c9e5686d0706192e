//! The correction's covariance from reading noise (method 8.2): the complex
//! sums `K = E[dC dCᴴ]` and `J = E[dC dCᵀ]` over independent readings, and
//! the per-row pieces of them that the rows' cross terms reuse (`rows`).

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

use super::moments::moments;
use crate::balancing::factor::cmul;

/// `K`, `J` of the used planes' corrections, and per used row `i`:
/// `a_i = −g A⁺[:, i]` (column `i` of `a_vec`), `s1_i = Σ_k s |λ_k|²`,
/// `p1_i = Σ_k p λ_k²` and `mk`, `mj` (row `i`), the row's own readings'
/// share of `dC` through the second term of (8.2).
pub(super) struct Sums {
    pub k_mat: DMatrix<Complex64>,
    pub j_mat: DMatrix<Complex64>,
    pub a_vec: DMatrix<Complex64>,
    pub mk: DMatrix<Complex64>,
    pub mj: DMatrix<Complex64>,
    pub s1: Vec<f64>,
    pub p1: Vec<Complex64>,
}

/// Per reading (a, k) at used position i: dC = α δ + β δ̄ with α = λ_k a_i,
/// a_i = −g A⁺[:, i], and β = b_i ξ_k, b_i = −g r_i, ξ_k = (AᴴA)⁻¹ ω̄_k. With
/// s = E|δ|², p = E[δ²] of the reading, summed over independent readings:
///   K = Σ s(|λ|² a aᴴ + |b|² ξ ξᴴ) + (p λ b̄ a ξᴴ + its adjoint),
///   J = Σ p λ² a aᵀ + p̄ b² ξ ξᵀ + s λ b (a ξᵀ + ξ aᵀ),
/// each a product of a q × rows, a rows × runs and a runs × q matrix: time
/// O(rows·runs·q + rows·q²) and memory O(rows·(runs + q)), never a
/// Jacobian per reading (issue 15).
///
/// `amat` is `A = G W[u,p]`, `r` the weighted residual, `gram_inv` `(AᴴA)⁺`,
/// `lambda`, `lambda_sq` `λ_k` and `(|λ_k|², λ_k²)` per run, `g_omega`
/// `ξ_k = (AᴴA)⁻¹ ω̄_k` per run.
#[allow(clippy::too_many_arguments)]
pub(super) fn sums(
    cov: &[Vec<Matrix2<f64>>],
    used_rows: &[usize],
    row_weights: &[f64],
    runs: usize,
    amat: &DMatrix<Complex64>,
    r: &DVector<Complex64>,
    gram_inv: &DMatrix<Complex64>,
    lambda: &[Complex64],
    lambda_sq: &[(f64, Complex64)],
    g_omega: &[DVector<Complex64>],
) -> Sums {
    let q = amat.ncols();
    let m = used_rows.len();
    // Moments of a row's readings, formed where they are summed (four
    // additions each: cheaper than a flat copy of them all, issue 15).
    let row_moments = |a: usize| cov[a][..runs].iter().map(moments);
    // a = −A⁺ G = −(AᴴA)⁺ Aᴴ G, one `q × q × rows` product from the `(AᴴA)⁺`
    // of the SVD of `R` (issue 15; `R⁺ Qᴴ` through the reflectors took three).
    // Not the normal equations: `AᴴA` is never formed, and with the SVD of
    // `R + δR` backward stable, `(R̃ᴴR̃)⁻¹ Rᴴ = R̃⁻¹ (I − R̃⁻ᴴ δRᴴ)` is `A⁺`
    // within `ε κ ‖A⁺‖`, the accuracy of `R̃⁻¹ Qᴴ` itself.
    // Entry (j, i) = −conj(A_ij) g_i, written in storage order (session 9).
    let ams = amat.as_slice();
    let mut data = Vec::with_capacity(q * m);
    for (i, &g) in row_weights.iter().enumerate().take(m) {
        data.extend((0..q).map(|j| -ams[i + j * m].conj() * g));
    }
    let neg_ah_g = DMatrix::from_vec(q, m, data);
    let a_vec = cmul(gram_inv, &neg_ah_g);
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
        // Column by column through the storage slices (issue 15, session 9):
        // column j of `px` is [Re P x_j; Im P x_j], column q + j the same
        // with Im x_j.
        let (pxs, sys) = (px.as_slice(), sy.as_slice());
        let mut data = Vec::with_capacity(m * q);
        for j in 0..q {
            let (re_re, im_re) = pxs[2 * m * j..2 * m * (j + 1)].split_at(m);
            let (re_im, im_im) = pxs[2 * m * (q + j)..2 * m * (q + j + 1)].split_at(m);
            data.extend(
                re_re
                    .iter()
                    .zip(im_im)
                    .zip(re_im.iter().zip(im_re))
                    .zip(&b_vec)
                    .map(|(((rr, ii), (ri, ir)), b)| b.conj() * Complex64::new(rr - ii, ri + ir)),
            );
        }
        mk = DMatrix::from_vec(m, q, data);
        let mut data = Vec::with_capacity(m * q);
        for j in 0..q {
            let (re, im) = (&sys[m * j..m * (j + 1)], &sys[m * (q + j)..m * (q + j + 1)]);
            data.extend(
                re.iter()
                    .zip(im)
                    .zip(&b_vec)
                    .map(|((&re, &im), b)| b * Complex64::new(re, im)),
            );
        }
        mj = DMatrix::from_vec(m, q, data);
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
        // Written once, a column at a time, through the storage slices
        // (issue 15, session 9: zeros then a fill through nalgebra's `(i, j)`
        // indexing cost 0.9 M instructions on 20,480 × 2 entries). Entry
        // (j, i) of `a` is at `j + i q`.
        let avs = a_vec.as_slice();
        let mut data = Vec::with_capacity(m * 2 * q);
        for (j, col) in mk.as_slice().chunks_exact(m.max(1)).enumerate() {
            let aj = avs[j..].iter().step_by(q);
            data.extend(
                col.iter()
                    .zip(&s1)
                    .zip(aj)
                    .map(|((&v, &s), a)| v + (s * 0.5) * a.conj()),
            );
        }
        for (j, col) in mj.as_slice().chunks_exact(m.max(1)).enumerate() {
            let aj = avs[j..].iter().step_by(q);
            data.extend(
                col.iter()
                    .zip(&p1)
                    .zip(aj)
                    .map(|((&v, &p), a)| v + (p * 0.5) * a),
            );
        }
        let mkj = DMatrix::from_vec(m, 2 * q, data);
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
    Sums {
        k_mat,
        j_mat,
        a_vec,
        mk,
        mj,
        s1,
        p1,
    }
}
