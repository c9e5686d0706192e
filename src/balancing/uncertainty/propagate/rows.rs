//! Per row of the job: what the correction's error does to the vibration
//! that will remain (method 3.1, 8.6), and each plane's trial effect beside
//! its noise.

use nalgebra::{DMatrix, Matrix2};
use num_complex::Complex64;

use super::correction::Sums;
use super::moments::{moments, real_cov};
use crate::balancing::factor::cmul;

/// Per row (all rows): `through_correction`, `remaining_cross`, `residual`
/// and `prediction` of [`super::Propagation`].
pub(super) struct Rows {
    pub through_correction: Vec<Matrix2<f64>>,
    pub remaining_cross: Vec<Matrix2<f64>>,
    pub residual: Vec<Matrix2<f64>>,
    pub prediction: Vec<Matrix2<f64>>,
}

/// The rows' covariances from the correction's `sums`; `w` rows × planes,
/// `position[a]` row `a`'s place among the used rows.
pub(super) fn rows(
    cov: &[Vec<Matrix2<f64>>],
    w: &DMatrix<Complex64>,
    used_planes: &[usize],
    position: &[Option<usize>],
    runs: usize,
    lambda_sq: &[(f64, Complex64)],
    sums: Sums,
) -> Rows {
    let (n, planes) = w.shape();
    let q = used_planes.len();
    let zero = Complex64::from(0.0);
    let row_moments = |a: usize| cov[a][..runs].iter().map(moments);
    let Sums {
        k_mat,
        j_mat,
        a_vec,
        mk,
        mj,
        s1,
        p1,
    } = sums;
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
    Rows {
        through_correction,
        remaining_cross,
        residual,
        prediction,
    }
}

/// Rows × planes: the standard deviation of each plane's trial effect (see
/// [`super::Propagation::effect_sd`]); `t` planes × trial runs, `tp` `T⁺`,
/// `s` its column sums, `n` the rows.
pub(super) fn effect_sd(
    t: &DMatrix<Complex64>,
    tp: &DMatrix<Complex64>,
    s: &[Complex64],
    cov: &[Vec<Matrix2<f64>>],
    n: usize,
) -> DMatrix<f64> {
    let (planes, runs) = (t.nrows(), t.ncols() + 1);
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
    DMatrix::from_fn(n, planes, |a, j| taus[j] * var[(a, j)].sqrt())
}
