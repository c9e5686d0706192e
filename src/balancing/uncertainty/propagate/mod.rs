//! First-order propagation of reading noise through the influence coefficients
//! (method 2.1) and the weighted least-squares correction (method 3.2, 3.3) to
//! the correction and the predicted residual (method 3.1).
//!
//! Every reading is an independent complex quantity with a real 2×2 covariance.
//! The chain is real-linear but not complex-linear in the readings (the least-
//! squares derivative contains `dWᴴ`): each reading `δ` moves an output by
//! `α δ + β δ̄`, and the output's real covariance follows from the complex
//! covariance and pseudo-covariance (`E[z zᴴ]`, `E[z zᵀ]`) summed over readings.
//!
//! Here the setup (`A`, `r`, `ω_k`, `λ_k`, `ξ_k`); the sums over readings
//! that give the correction's covariance in `correction`, the rows' figures
//! in `rows`, the complex/real forms of a covariance in `moments`.

use nalgebra::{DMatrix, DVector, Matrix2};
use num_complex::Complex64;

use crate::balancing::factor::Factored;

mod correction;
mod moments;
mod rows;

use moments::real_cov_full;
pub(in crate::balancing::uncertainty) use moments::{moments, svd_parts};

/// Singular values below this fraction of the largest count as zero (as in the solver).
pub(super) const RANK_TOLERANCE: f64 = 1e-10;

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
    /// `Ω`, runs × used planes: row `k` is `ω_k` over the used planes, how
    /// reading `k` of a row moves that row of `W` (`ω_0 = −1ᵀT⁺`, `ω_k =
    /// T⁺[k−1, :]`); `remaining::joint`'s product term (method 8.9) reads it
    /// from here rather than forming it again.
    pub omega: DMatrix<Complex64>,
    /// `λ_k = ω_k·C (+1 for k = 0)` per run: the reading's direct effect on
    /// `R_a`, with `omega` for the product term.
    pub lambda: Vec<Complex64>,
}

/// The readings and the selection that a propagation (and `bias`'s
/// expansion of the same normal equations) is taken over.
#[derive(Clone, Copy)]
pub struct Problem<'a> {
    /// Planes × trial runs weights (exact).
    pub t: &'a DMatrix<Complex64>,
    /// Rows × (1 + trial runs) readings, column 0 the reference `Y0`.
    pub y: &'a DMatrix<Complex64>,
    /// `cov[a][k]`, the 2×2 covariance of `y[(a, k)]`.
    pub cov: &'a [Vec<Matrix2<f64>>],
    /// The rows of the fit.
    pub used_rows: &'a [usize],
    /// One per used row: `G` of method 3.3.
    pub row_weights: &'a [f64],
    /// The solved planes, in the order of the correction.
    pub used_planes: &'a [usize],
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

/// Propagate reading noise to the correction and the residual.
///
/// - `p`: the readings, their covariances and the selection ([`Problem`]);
/// - `c`: the correction of the used planes;
/// - `known`: what the solve already has: `T⁺`, `W` and the factorisation
///   of `A = G W[u,p]` (issue 15: `A⁺` and `(AᴴA)⁺` from the one
///   factorisation, not a QR and SVD of their own); `None` computes them here.
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
pub fn propagate(p: &Problem, c: &DVector<Complex64>, known: Option<Known>) -> Propagation {
    let Problem {
        t,
        y,
        cov,
        used_rows,
        row_weights,
        used_planes,
    } = *p;
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
    // `A = G W[u,p]`, a column at a time through the storage slices (issue
    // 15, session 9: a third of `from_fn`'s cost).
    let mut data = Vec::with_capacity(used_rows.len() * q);
    for &p in used_planes {
        let col = &w.as_slice()[p * n..(p + 1) * n];
        data.extend(used_rows.iter().zip(row_weights).map(|(&a, &g)| col[a] * g));
    }
    let amat = DMatrix::from_vec(used_rows.len(), q, data);
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
    let omega = DMatrix::from_fn(runs, q, |k, j| match k {
        0 => -s[used_planes[j]],
        _ => tp[(k - 1, used_planes[j])],
    });
    let lambda: Vec<Complex64> = (0..runs)
        .map(|k| {
            omega
                .row(k)
                .iter()
                .zip(c.iter())
                .map(|(o, cj)| o * cj)
                .sum::<Complex64>()
                + if k == 0 { 1.0 } else { 0.0 }
        })
        .collect();
    let g_omega: Vec<DVector<Complex64>> = omega
        .row_iter()
        .map(|o| &gram_inv * o.transpose().map(|x| x.conj()))
        .collect();
    // |λ_k|² and λ_k², once per run rather than once per reading.
    let lambda_sq: Vec<(f64, Complex64)> = lambda.iter().map(|l| (l.norm_sqr(), l * l)).collect();
    let sums = correction::sums(
        cov,
        used_rows,
        row_weights,
        runs,
        &amat,
        &r,
        &gram_inv,
        &lambda,
        &lambda_sq,
        &g_omega,
    );
    let correction_full = real_cov_full(&sums.k_mat, &sums.j_mat);
    let correction = (0..q)
        .map(|j| {
            correction_full
                .fixed_view::<2, 2>(2 * j, 2 * j)
                .into_owned()
        })
        .collect();
    let rows = rows::rows(cov, w, used_planes, &position, runs, &lambda_sq, sums);
    Propagation {
        correction,
        correction_full,
        residual: rows.residual,
        prediction: rows.prediction,
        through_correction: rows.through_correction,
        remaining_cross: rows.remaining_cross,
        effect_sd: rows::effect_sd(t, tp, &s, cov, n),
        gram_inv_diag,
        omega,
        lambda,
    }
}
