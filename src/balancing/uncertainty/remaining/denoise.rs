//! The de-noised conditioning of `joint` (method 8, "Session 24, amp24" and
//! its amp24b paragraph):
//! the all-rows conditioning (8.8) with the noisy coefficients `Ŵ` treated
//! as noisy (errors in variables) instead of known.
//!
//! `joint` recovers the correction's error `Ĉ − C` from the predictions by
//! Aitken's generalised least squares, `δ = G⁻¹ ψ̂`, `G = Σ_b Ŵ_bᵀ D_b⁻¹ Ŵ_b`,
//! `ψ̂ = Σ_b Ŵ_bᵀ D_b⁻¹ R̂_b` (real `2q` forms), with covariance `G⁻¹`. With
//! `Ŵ = W + dW` that estimator is attenuated like any least squares with
//! noisy regressors: `E[ψ̂(C)] = E[Σ_b dW_bᵀ D_b⁻¹ e_b(C)] ≠ 0` and `E[G] =
//! Σ_b W_bᵀ D_b⁻¹ W_b + N`. Fuller's corrected estimator (Fuller 1987,
//! *Measurement Error Models*, §2.2, §4.1: `(M_xx − Σ_uu)⁻¹ (M_xy − Σ_uy)`)
//! takes both off:
//!
//! - a reading `dy_bk` (real 2-vector, covariance `S_bk`) moves row `b` of
//!   `W` by `Mul(dy_bk) Ω_k` and `e_b(C)` by `Mul(λ_k(C)) dy_bk`
//!   (`Mul(z)` the real 2×2 of a complex product, `Ω_k` the real `2 × 2q` of
//!   `ω_k`, `λ_k(C) = ω_k·C (+1 for k = 0)`; `Propagation::omega`, `lambda`),
//!   and `Mul(λ) dy = Mul(dy) λ`, so with `A_k = Σ_b E[Mul(dy_bk)ᵀ D_b⁻¹
//!   Mul(dy_bk)]` (2 × 2, entries `tr(Jᵢᵀ D_b⁻¹ Jⱼ S_bk)`, `J₀ = I`, `J₁` the
//!   quarter turn):
//!
//! ```text
//!   N = Σ_k Ω_kᵀ A_k Ω_k,      E[ψ̂(C)] = Σ_k Ω_kᵀ A_k λ_k(C);
//! ```
//!
//! - `ψ̂(C) = ψ̂(Ĉ) + G (C − Ĉ)`, and solving `ψ̂(C̃) = E[ψ̂(C̃)]` gives the
//!   de-noised error `δ̃ = Ĉ − C̃ = (G − N)⁻¹ (ψ̂(Ĉ) − E[ψ̂(Ĉ)])`: the centre
//!   `m_a = Ŵ_a δ̃` holds the errors-in-variables bias of `Ĉ` (no separate
//!   move, 8.12, is made where this is formed);
//! - its covariance is Fuller's sandwich `(G − N)⁻¹ Var ψ̂ (G − N)⁻¹` with
//!   `Var ψ̂ ≈ Σ_b W_bᵀ D_b⁻¹ W_b + N ≈ G`: `V = (G − N)⁻¹ G (G − N)⁻¹`,
//!   `Σ_ε,a = Ŵ_a V Ŵ_aᵀ`. For one regressor of reliability `k = 1 − N/G`
//!   this is `1/k²` times the naive `Ŵ_a G⁻¹ Ŵ_aᵀ`, which session 23's
//!   `ρ_a = |Ŵ_a C*|²/|Ŵ_a Ĉ|²` stood in for.
//!
//! - The product term (8.9) redone for `δ̃` (amp24b): where `r = 0`,
//!   exactly `R_a − m_a = W_a(C̃ − C) − dW_a δ̃`; the product with the
//!   unknown `C̃ − C` is inside the plug-in `Ŵ_a V Ŵ_aᵀ` already, whose part
//!   `E[dW_a V dW_aᵀ] = ½ Σ_k s_ak ω_k V ω_kᴴ · I` is taken off (`Σ`, at
//!   most 0.9 of the smaller eigenvalue), and the product with the observed
//!   `δ̃` is `dW_a δ̃ = β_a e_a + ζ_a` (`Second::split_denoised`: `β_a`,
//!   `E|ζ_a|² = Σ_k s_ak |ω_k·δ̃|² − V_e,a |β_a|²`). The row's own
//!   prediction `r = R̂_a − m_a = e_a + u` (`u = W_a(C̃ − C)`, `Cov(u, e_a)
//!   = −Λ_a`, `Λ_a = Ŵ_a (G − N)⁻¹ Ŵ_aᵀ`) shows `e_a`, so the error `u −
//!   B e_a − ζ_a` (`B` the real 2×2 of `β_a`, `D = D_a(C*)`) is conditioned
//!   on it (first order, Gaussian, [`row`]):
//!
//! ```text
//!   A = (Σ − Λ_a) − B(D − Λ_a),   Var r = D + Σ − 2Λ_a,
//!   centre m_a + A (Var r)⁻¹ r,
//!   Σ'_ε = Σ + B D Bᵀ + Λ_a Bᵀ + B Λ_a − A (Var r)⁻¹ Aᵀ + ½E|ζ_a|² I.
//! ```
//!
//! Measured on the table (scripts/issue12_table.py, 1,000 jobs, session
//! 21's seeds; method 8, amp24b's form (7)): every ten-speed case inside
//! 93–97 % with stated noise (94.7–96.6 % at 10–20 % trials; the held-out
//! rotor at 1000–5500 rpm came in from 98.3–98.6 %) and, with samples,
//! every case that held before (94.1–96.3 %); one speed is untouched (the
//! all-rows conditioning is not used there). The calibration rotor's
//! structured residual at 100 % trials with samples, outside before, goes
//! 91.5 → 90.9 %.
//!
//! Small-sample modification (session 25, amp25; method §8, "Session 25,
//! amp25"). `(G − N)⁻¹` has no finite moments: where the trials are small
//! `G − N` is near singular in some jobs (and not positive definite in
//! others, where this conditioning used to give way to the one with `Ŵ`
//! known and the larger of the moved and unmoved bound), and the bound,
//! Gaussian about a centre with that heavy-tailed error, held 98.8 % of
//! few_speeds.rs's rows at 10 % trials (on a copy of its rotor a
//! covariance half as large still held 94 %: the excess is in the tails,
//! not the scale). Fuller's
//! modification (Fuller 1977, *Econometrica* 45, "Some properties of a
//! modification of the limited information estimator"; 1987, §2.5.1) takes
//! off a share `c` of `N` instead of all of it, `H = G − cN`, `δ̃ = H⁻¹(ψ̂
//! − c E[ψ̂])`, `V = H⁻¹ G H⁻¹`: with `ν = 2(m − q)` (the fit's real degrees
//! of freedom) and `μ` the smallest root of `|G − μN| = 0`, `c = 1 − α/ν`
//! where `μ ≥ 1 + 1/ν`, else `c = μ − (1 + α)/ν` (`H` is then positive
//! definite at every job, so the conditioning is formed at every job that
//! reaches it). Fuller's `λ̂` is the smallest root of the pencil with the
//! response included; `μ`, without it, is not smaller (interlacing), so `c`
//! here is at least Fuller's. `α = 4` (`FULLER_ALPHA`, his choice for the
//! smallest mean square error; the centre is a prediction; chosen after
//! these figures): few_speeds.rs 98.8 97.9 96.0 → 97.3 97.3 95.9 % at
//! 10/30/100 % trials; `α = 1` (nearly unbiased) 98.9 % at 10 %, and `α =
//! 4` keeping the old fallback where `G − N` is not positive definite
//! 98.2 %. At ten speeds `c` is 0.95 and the
//! table's cases move by 0.0–0.7 points, all inside 93–97 %.

use nalgebra::{Cholesky, DMatrix, DVector, Matrix2, Vector2};
use num_complex::Complex64;

use super::product::{Second, Split};
use super::{sym, Inputs};

/// The de-noised conditioning's parts for every row.
pub struct Denoised {
    /// The de-noised error `δ̃` (`2q`).
    pub delta: DVector<f64>,
    /// `Z = (G − N)⁻¹ Rᵀ`, so that Fuller's sandwich is `V = Z Zᵀ`.
    pub z: DMatrix<f64>,
    /// `L` with `L Lᵀ = (G − N)⁻¹`, for `Λ_a = Ŵ_a (G − N)⁻¹ Ŵ_aᵀ`.
    pub zh: DMatrix<f64>,
}
/// `r`, `qty`: the QR of the whitened stack and its right-hand side (`G =
/// RᵀR`, `ψ̂ = Rᵀ Qᵀ y`); `f[i]`: `L_b⁻¹` of used row `i`; `cov[b][k]`: the
/// readings' covariances; `omega`, `lambda` at `Ĉ`.
pub fn of(
    r: &DMatrix<f64>,
    qty: &DVector<f64>,
    f: &[[f64; 3]],
    used_rows: &[usize],
    cov: &[Vec<Matrix2<f64>>],
    omega: &DMatrix<Complex64>,
    lambda: &[Complex64],
) -> Option<Denoised> {
    let (runs, q) = (omega.nrows(), omega.ncols());
    let nn = 2 * q;
    if r.nrows() != nn || lambda.len() != runs || cov.iter().any(|c| c.len() < runs) {
        return None;
    }
    let quarter = Matrix2::new(0.0, -1.0, 1.0, 0.0);
    let mut n_mat = DMatrix::<f64>::zeros(nn, nn);
    let mut e_psi = DVector::<f64>::zeros(nn);
    for k in 0..runs {
        let mut a = Matrix2::zeros();
        for (fb, &b) in f.iter().zip(used_rows) {
            let l_inv = Matrix2::new(fb[0], 0.0, fb[1], fb[2]);
            let p = l_inv.transpose() * l_inv;
            let s = cov[b][k];
            let pj = p * quarter;
            a += Matrix2::new(
                (p * s).trace(),
                (pj * s).trace(),
                (quarter.transpose() * p * s).trace(),
                (quarter.transpose() * pj * s).trace(),
            );
        }
        let mut om = DMatrix::<f64>::zeros(2, nn);
        for j in 0..q {
            let w = omega[(k, j)];
            om[(0, 2 * j)] = w.re;
            om[(0, 2 * j + 1)] = -w.im;
            om[(1, 2 * j)] = w.im;
            om[(1, 2 * j + 1)] = w.re;
        }
        let a_d = DMatrix::from_column_slice(2, 2, a.as_slice());
        let at = om.transpose() * a_d;
        n_mat += &at * &om;
        e_psi += &at * DVector::from_column_slice(&[lambda[k].re, lambda[k].im]);
    }
    let g = r.transpose() * r;
    let psi = r.transpose() * qty;
    let c = fuller_share(r, &n_mat, used_rows.len(), q)?;
    let n_mat = n_mat * c;
    let h = (&g - &n_mat + (&g - &n_mat).transpose()) * 0.5;
    let ch = Cholesky::new(h)?;
    let delta = ch.solve(&(psi - e_psi * c));
    let z = ch.solve(&r.transpose());
    let zh = ch.inverse().cholesky()?.l();
    (delta.iter().chain(z.iter()).all(|x| x.is_finite())).then_some(Denoised { delta, z, zh })
}

/// Fuller's `α` (module doc, "Small-sample modification"): 4, the choice he
/// gives for the smallest mean square error to the order of his
/// approximation (Fuller 1977; 1987, §2.5.1); `α = 1` is his nearly
/// unbiased one.
const FULLER_ALPHA: f64 = 4.0;

/// The share `c` of the noise's Gram `N` taken off `G` (module doc, "Small-
/// sample modification"): with `ν = 2(m − q)` the fit's real degrees of
/// freedom and `μ` the smallest root of `|G − μN| = 0` (`G = RᵀR`: the
/// largest eigenvalue of `R⁻ᵀ N R⁻¹` is `1/μ`), `1 − α/ν` where `μ ≥ 1 +
/// 1/ν`, else `μ − (1 + α)/ν`, so that `G − cN` is positive definite.
/// `None` where the eigenvalues are not finite.
fn fuller_share(r: &DMatrix<f64>, n_mat: &DMatrix<f64>, rows: usize, q: usize) -> Option<f64> {
    let nu = 2.0 * rows.saturating_sub(q).max(1) as f64;
    let y = r.tr_solve_upper_triangular(n_mat)?;
    let m = r.tr_solve_upper_triangular(&y.transpose())?;
    let theta = ((&m + m.transpose()) * 0.5)
        .symmetric_eigen()
        .eigenvalues
        .max();
    if !theta.is_finite() {
        return None;
    }
    let mu = if theta > 0.0 {
        1.0 / theta
    } else {
        f64::INFINITY
    };
    Some(if mu >= 1.0 + 1.0 / nu {
        1.0 - FULLER_ALPHA / nu
    } else {
        mu - (1.0 + FULLER_ALPHA) / nu
    })
}

/// Row `a`'s centre and `Σ'_ε` conditioned on its own prediction (module
/// doc); `sigma` is `Ŵ_a V Ŵ_aᵀ`, `centre` `m_a`. Where `Var r` is singular
/// or `Σ'_ε` not positive definite: `m_a` and `Σ + ½Σ_k s_ak |ω_k·δ̃|² I`.
pub fn row(
    inp: &Inputs,
    a: usize,
    centre: Complex64,
    sigma: Matrix2<f64>,
    den: &Denoised,
    second: &Second,
    parts: &Split,
) -> (Complex64, Matrix2<f64>) {
    let (e11, e12, e22) = (sigma.m11, sigma.m12, sigma.m22);
    let known = parts.known[a];
    let b = parts.beta[a];
    let bm = Matrix2::new(b.re, -b.im, b.im, b.re);
    // The plug-in's `E[dW_a V dW_aᵀ]` taken off, at most 0.9 of the smaller
    // eigenvalue.
    let lo = 0.5 * (e11 + e22 - ((e11 - e22).powi(2) + 4.0 * e12 * e12).sqrt());
    let off = (0.5 * parts.vterm[a]).min(0.9 * lo.max(0.0));
    let sig = Matrix2::new(e11 - off, e12, e12, e22 - off);
    let (l11, l12, l22) = super::unused_row(inp, a, &den.zh);
    let lam = Matrix2::new(l11, l12, l12, l22);
    let d = sym(&inp.own[a]);
    let cov_er = (sig - lam) - bm * (d - lam);
    let var_r = d + sig - lam * 2.0;
    let var_e = sig + bm * d * bm.transpose() + lam * bm.transpose() + bm * lam;
    let zeta = (known - second.ve(a) * b.norm_sqr()).max(0.0);
    if let Some(vi) = var_r.try_inverse() {
        let rr = inp.r_hat[a] - centre;
        let shift = cov_er * vi * Vector2::new(rr.re, rr.im);
        let cc = var_e - cov_er * vi * cov_er.transpose();
        let cc = (cc + cc.transpose()) * 0.5 + Matrix2::identity() * (0.5 * zeta);
        let clo = 0.5 * (cc.trace() - ((cc.m11 - cc.m22).powi(2) + 4.0 * cc.m12.powi(2)).sqrt());
        if clo > 0.0 && shift.iter().all(|x| x.is_finite()) {
            return (centre + Complex64::new(shift[0], shift[1]), cc);
        }
    }
    (
        centre,
        Matrix2::new(e11 + known * 0.5, e12, e12, e22 + known * 0.5),
    )
}
