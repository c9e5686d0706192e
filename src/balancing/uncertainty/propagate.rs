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
        // Multiply by real reciprocals: a complex division squares its
        // divisor's modulus, which underflows to 0 (then NaN) for the tiny
        // singular values of readings near 1e-100.
        pinv += &v * u.column(i).adjoint() * Complex64::from(1.0 / s);
        gram_inv += &v * v.adjoint() * Complex64::from((1.0 / s).powi(2));
    }
    (pinv, gram_inv)
}

/// Real 2×2 matrix of the real-linear map `δ ↦ α δ + β δ̄` on (Re δ, Im δ).
fn real_map(alpha: Complex64, beta: Complex64) -> Matrix2<f64> {
    Matrix2::new(
        alpha.re + beta.re,
        beta.im - alpha.im,
        alpha.im + beta.im,
        alpha.re - beta.re,
    )
}

/// A square root `S` of a covariance, `S Sᵀ = Σ` (negative eigenvalues clipped).
fn sqrt_psd(cov: &Matrix2<f64>) -> Matrix2<f64> {
    let e = nalgebra::SymmetricEigen::new((cov + cov.transpose()) / 2.0);
    let d = e.eigenvalues.map(|l| l.max(0.0).sqrt());
    e.eigenvectors * Matrix2::from_diagonal(&d)
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
/// k = 0)` is also the reading's direct effect on `R_a`. That makes the cost
/// `O(readings · planes + rows · planes²)`.
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

    // Whitened Jacobian of C: for reading (a, k) with Σ = S Sᵀ, the 2q × 2 block
    // J S; then Cov(C) = M Mᵀ. Only used rows move C.
    let jc = |i: usize, k: usize, sq: &Matrix2<f64>| -> DMatrix<f64> {
        let g = row_weights[i];
        let mut m = DMatrix::zeros(2 * q, 2);
        for j in 0..q {
            let alpha = -apinv[(j, i)] * lambda[k] * g;
            let beta = -g_omega[k][j] * r[i] * g;
            m.fixed_view_mut::<2, 2>(2 * j, 0)
                .copy_from(&(real_map(alpha, beta) * sq));
        }
        m
    };
    let roots: Vec<Vec<Matrix2<f64>>> = cov
        .iter()
        .take(n)
        .map(|row| row.iter().take(runs).map(sqrt_psd).collect())
        .collect();
    let mut whitened = DMatrix::zeros(2 * q, 2 * used_rows.len() * runs);
    for (i, &a) in used_rows.iter().enumerate() {
        for (k, root) in roots[a].iter().enumerate() {
            whitened
                .columns_mut(2 * (i * runs + k), 2)
                .copy_from(&jc(i, k, root));
        }
    }
    let correction_full = &whitened * whitened.transpose();
    let correction = (0..q)
        .map(|j| {
            correction_full
                .fixed_view::<2, 2>(2 * j, 2 * j)
                .into_owned()
        })
        .collect();

    // dR̂_a = W̃_a dC + λ_k δ for the readings of row a: the first part has
    // covariance W̃ Cov(C) W̃ᵀ; the direct part (which alone is `residual`) and
    // its cross terms with dC come only from row a's own readings.
    let (residual, prediction) = (0..n)
        .map(|a| {
            let wt = DMatrix::from_fn(2, 2 * q, |row, col| {
                let m = real_map(w[(a, used_planes[col / 2])], Complex64::from(0.0));
                m[(row, col % 2)]
            });
            let through_c = &wt * &correction_full * wt.transpose();
            let mut direct_cov = Matrix2::zeros();
            let mut cross_cov = Matrix2::zeros();
            for (k, root) in roots[a].iter().enumerate() {
                let direct = real_map(lambda[k], Complex64::from(0.0)) * root;
                direct_cov += direct * direct.transpose();
                if let Some(i) = position[a] {
                    let via = &wt * jc(i, k, root);
                    let cross = Matrix2::new(via[(0, 0)], via[(0, 1)], via[(1, 0)], via[(1, 1)])
                        * direct.transpose();
                    cross_cov += cross + cross.transpose();
                }
            }
            let through_c = Matrix2::new(
                through_c[(0, 0)],
                through_c[(0, 1)],
                through_c[(1, 0)],
                through_c[(1, 1)],
            );
            (direct_cov, through_c + direct_cov + cross_cov)
        })
        .unzip();

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
        prediction,
        effect_sd,
    }
}
