//! First-order propagation of reading noise through the influence coefficients
//! (method 2.1) and the weighted least-squares correction (method 3.2, 3.3) to
//! the correction and the predicted residual (method 3.1).
//!
//! Every reading is an independent complex quantity with a real 2×2 covariance.
//! The chain is real-linear but not complex-linear in the readings (the least-
//! squares derivative contains `dWᴴ`), so each reading is perturbed along 1 and
//! along i, giving the real 2×2 Jacobian block of every output; the output
//! covariance is `Σ_readings J Σ_reading Jᵀ`.

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

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
    /// Per row (all rows, used or not), 2×2 covariance of (Re R, Im R).
    pub residual: Vec<Matrix2<f64>>,
    /// Rows × planes (all planes): standard deviation `√tr Cov` (the RMS of the
    /// complex error) of each plane's trial effect `E_aj = W_aj·τ_j`, where
    /// `τ_j = max_k |T_jk|` is the plane's largest trial mass. With one trial per
    /// plane (`T` diagonal) `E_aj` is exactly the change `Y_aj − Y_a0` of method 2.
    pub effect_sd: DMatrix<f64>,
}

/// `(A⁺, (AᴴA)⁺)` from the SVD of `A`, never forming `AᴴA` itself.
fn svd_parts(a: &DMatrix<Complex64>) -> (DMatrix<Complex64>, DMatrix<Complex64>) {
    let (m, q) = a.shape();
    let mut pinv = DMatrix::zeros(q, m);
    let mut gram_inv = DMatrix::zeros(q, q);
    if m == 0 || q == 0 {
        return (pinv, gram_inv);
    }
    let svd = a.clone().svd(true, true);
    let (Some(u), Some(v_t)) = (svd.u, svd.v_t) else {
        return (pinv, gram_inv);
    };
    let smax = svd.singular_values.max();
    for (i, &s) in svd.singular_values.iter().enumerate() {
        if s <= RANK_TOLERANCE * smax || s == 0.0 {
            continue;
        }
        let v = v_t.row(i).adjoint();
        pinv += &v * u.column(i).adjoint() / Complex64::from(s);
        gram_inv += &v * v.adjoint() / Complex64::from(s * s);
    }
    (pinv, gram_inv)
}

/// Real 2×2 Jacobian block from the responses to a perturbation by 1 and by i.
fn block(d1: Complex64, di: Complex64) -> nalgebra::Matrix2<f64> {
    Matrix2::new(d1.re, di.re, d1.im, di.im)
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
    let (n, runs) = y.shape();
    let planes = t.nrows();
    let q = used_planes.len();
    let (tp, _) = svd_parts(t);
    // Column sums of T⁺: how the reference reading enters every influence coefficient.
    let s: Vec<Complex64> = (0..planes).map(|j| tp.column(j).sum()).collect();
    let w = DMatrix::from_fn(n, planes, |a, j| {
        (1..runs)
            .map(|k| (y[(a, k)] - y[(a, 0)]) * tp[(k - 1, j)])
            .sum::<Complex64>()
    });
    let amat = DMatrix::from_fn(used_rows.len(), q, |i, j| {
        w[(used_rows[i], used_planes[j])] * row_weights[i]
    });
    let b = DVector::from_fn(used_rows.len(), |i, _| {
        y[(used_rows[i], 0)] * row_weights[i]
    });
    let r = &amat * c + b;
    let (apinv, gram_inv) = svd_parts(&amat);
    let mut position = vec![None; n];
    for (i, &a) in used_rows.iter().enumerate() {
        position[a] = Some(i);
    }

    // Derivatives of (C, R) for a perturbation `d` of reading (a, k).
    let respond = |a: usize, k: usize, d: Complex64| -> (DVector<Complex64>, DVector<Complex64>) {
        let dw: Vec<Complex64> = used_planes
            .iter()
            .map(|&j| {
                if k == 0 {
                    -d * s[j]
                } else {
                    d * tp[(k - 1, j)]
                }
            })
            .collect();
        let dwc: Complex64 = dw.iter().zip(c.iter()).map(|(x, cj)| x * cj).sum();
        let dy0 = if k == 0 { d } else { Complex64::from(0.0) };
        let dc = match position[a] {
            Some(i) => {
                let g = row_weights[i];
                let v = (dwc + dy0) * g;
                let da_h_r = DVector::from_fn(q, |j, _| (dw[j] * g).conj() * r[i]);
                -(apinv.column(i) * v) - &gram_inv * da_h_r
            }
            None => DVector::zeros(q),
        };
        let mut dr = DVector::from_fn(n, |row, _| {
            (0..q)
                .map(|j| w[(row, used_planes[j])] * dc[j])
                .sum::<Complex64>()
        });
        dr[a] += dwc + dy0;
        (dc, dr)
    };

    let mut correction_full = DMatrix::zeros(2 * q, 2 * q);
    let mut residual = vec![Matrix2::zeros(); n];
    let mut jc = DMatrix::zeros(2 * q, 2);
    for (a, row_cov) in cov.iter().enumerate().take(n) {
        for (k, &sigma) in row_cov.iter().enumerate().take(runs) {
            if sigma == Matrix2::zeros() {
                continue;
            }
            let (dc1, dr1) = respond(a, k, Complex64::new(1.0, 0.0));
            let (dci, dri) = respond(a, k, Complex64::new(0.0, 1.0));
            for j in 0..q {
                jc.fixed_view_mut::<2, 2>(2 * j, 0)
                    .copy_from(&block(dc1[j], dci[j]));
            }
            correction_full += &jc * sigma * jc.transpose();
            for (row, cr) in residual.iter_mut().enumerate() {
                let jr = block(dr1[row], dri[row]);
                *cr += jr * sigma * jr.transpose();
            }
        }
    }
    let correction = (0..q)
        .map(|j| {
            correction_full
                .fixed_view::<2, 2>(2 * j, 2 * j)
                .into_owned()
        })
        .collect();

    // Trial effects: dW_aj = Σ_k dY_a,k T⁺_kj − dY_a0 s_j, independent terms; a
    // complex factor rotates a covariance without changing its trace.
    let effect_sd = DMatrix::from_fn(n, planes, |a, j| {
        let tau = (0..t.ncols()).map(|k| t[(j, k)].norm()).fold(0.0, f64::max);
        let var = (1..runs)
            .map(|k| tp[(k - 1, j)].norm_sqr() * cov[a][k].trace())
            .sum::<f64>()
            + s[j].norm_sqr() * cov[a][0].trace();
        tau * var.sqrt()
    });
    Propagation {
        correction,
        correction_full,
        residual,
        effect_sd,
    }
}
