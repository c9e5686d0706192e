//! Every row's bound conditioned on all the used rows' predictions at once
//! (method 8.8), with the coefficients' noise times the correction's error
//! split along the row's own error (method 8.9; issue 12, item 2).
//!
//! - The rows' own reading errors `e_b` (with `C` fixed) have covariance
//!   `D_b` at the true `C`: `D_b(Ĉ)` (`Propagation::residual`) holds
//!   `E|z_b|²` besides, because `E|λ̂_k|² = |λ_k|² + E|ω_k·dC|²`, so the
//!   conditioning takes `D_b(Ĉ) − E|z_b|²/2 · I` (positive part: at most 0.9
//!   of the smaller eigenvalue is taken off).
//! - `dC | v ~ N(Λ⁻¹ Σ_b W_bᵀ D_b⁻¹ v_b, Λ⁻¹)`, `Λ = Σ_b W_bᵀ D_b⁻¹ W_b`
//!   (Aitken's generalised least squares), through a QR of the whitened
//!   `2 rows × 2q` stack `X_b = L_b⁻¹ W_b` (`D_b = L_b L_bᵀ`, Cholesky) with
//!   the predictions as its right-hand side (`mgs.rs`, modified Gram–Schmidt):
//!   `Λ = RᵀR` is never formed. `m_a = W_a E[dC | v]` for every row; for a
//!   row of the fit `W_b R⁻¹ = L_b Q_b`, so `Σ_ε,b = W_b Λ⁻¹ W_bᵀ = L_b
//!   (Q_b Q_bᵀ) L_bᵀ` from the leverages of `Q`'s rows, and for a row outside
//!   the fit `P = W_a R⁻¹`, `Σ_ε,a = P Pᵀ`.
//! - The product term `z_a = dW_a dC` (method 8.9): `E|z_a|² = Σ_k s_ak M_k`,
//!   `M_k = ω_k K ω_kᴴ`; its part along `e_a` is `β e_a`, `β = g_a·dC`,
//!   `g_a = Σ_k s_ak λ̄_k ω_k / V_e`, so `E|β|² V_e² = Σ_kl s_ak s_al
//!   Re(λ̄_k (Ω K Ωᴴ)_kl λ_l)`: a real quadratic form over the runs, for all
//!   rows in one real product `S [H̃ | H̃']` (`rows × runs × 2 runs`, `H̃'`
//!   the same with the conditional `Λ⁻¹` for `Var(β | v)`), not a `q`-vector
//!   per row. The row's bound adds `E|ζ_a|² + |R̂_a − m_a|² Var(β | v)`
//!   (isotropic) to `Σ_ε`: `R ~ N(m + S (R̂ − m), (1 − S) Σ'_ε + S D_a(Ĉ))`.
//!
//! One degree of freedom. With rows only one more than the planes (one
//! speed, four sensors, three planes) the predictions `v = R̂` span two real
//! dimensions (first order: `v` is a real-linear image of the readings'
//! errors of rank `2(rows − q)`), so every other row's prediction is a fixed
//! linear function of the row's own: conditioning on all rows is the same
//! first-order conditional as on the row's own prediction (method 8.6), and
//! the two forms differ only through (8.9)'s second-order split. Measured
//! (400 realisations, amplitude_95 coverage, trials 10/20/30/100 %):
//!
//! | one speed | own row (8.6) | all rows (8.8 + 8.9) |
//! | --- | --- | --- |
//! | eiv.rs, stated | 95.7 95.1 94.8 94.9 | 95.6 94.2 93.9 94.8 |
//! | eiv.rs, samples | 96.7 96.3 93.8 94.5 | 96.0 94.8 **92.6** 94.0 |
//! | held-out rotor, stated | 97.9 97.9 97.4 97.0 | 97.4 96.1 95.7 96.1 |
//! | held-out rotor, samples | 97.6 97.1 96.8 95.1 | 95.6 95.9 95.0 94.5 |
//!
//! (held-out: scripts/coverage_heldout.py, its own seed). The split lowers
//! one speed by 0.1–2.4 points: into the window on the held-out rotor,
//! below it in eiv.rs's samples at 30 %. So with fewer than two complex
//! degrees of freedom over the planes the caller conditions each row on its
//! own (`rows` returns `None`): nothing new to learn from the other rows,
//! and no case made worse than before outside 93–97 %; the held-out rotor's
//! one-speed over-coverage (97.1–97.9 % in five cases) stays open.
//!
//! Measured with this form (session 11): eiv.rs ten speeds, see
//! BENCHMARKS.md "Issue 12, session 11" (session 10's 95.1/94.2/94.7/94.8 %
//! stated, 95.6/95.0/95.2/94.2 % samples, reproduced to rounding: answers
//! within 3·10⁻¹⁴ of session 10's Householder form); held-out rotor ten
//! speeds 95.1–96.1 % (main 94.8–98.2 %). Cost on the large job
//! (ls-16x32x40, callgrind of `solve_checked` + `validate::check`): 49.6 M
//! instructions against main's 44.3 M, this function 5.6 M (session 10's
//! form: 14.5 M): the QR 2.05 M at about 0.7 instructions per multiply-add
//! (AVX2 + FMA, `mgs.rs`), the product term 1.1 M, the stack written without
//! zero fill 0.8 M; no `R⁻ᵀ Wᵀ` product for the rows of the fit (`Q`'s
//! leverages instead, 1.7 M saved). Open: with the weight forced to 0 the
//! ten-speed figures fall short (scripts/issue12_joint_shortfall.py: the
//! noisy `Ŵ` treated as known), the pooled weight and its calibration
//! making up the rest.
//!
//! De-noised (session 24, `denoise.rs`): where the caller asks for it
//! (`Inputs::denoise`, from `C*`), the correction's error is recovered
//! through the de-noised Gram `ŴᵀD⁻¹Ŵ − cN` (errors in variables, Fuller
//! 1987, with his small-sample share `c`, session 25; method §8, "Session
//! 24, amp24"),
//! its covariance is Fuller's sandwich `V` for every row, and 8.9's product
//! term is replaced by the product with the observed `δ̃`, split along the
//! row's own error and conditioned on its prediction (amp24b's form (7);
//! `denoise::row`). That removes the shortfall above and holds every
//! ten-speed case of the table (module doc of `denoise.rs`).

use nalgebra::{DMatrix, DVector, Matrix2, Vector2};
use num_complex::Complex64;

use super::mgs::{qr_in_place, squares_and_neighbours};
use super::{sym, Row};

#[path = "denoise.rs"]
mod denoise;
#[path = "joint_product.rs"]
mod product;
use product::Second;

/// What the conditioning reads from the solve and the propagation.
pub struct Inputs<'a> {
    /// `W`, all rows × all planes.
    pub w: &'a DMatrix<Complex64>,
    /// The solved planes (columns of `w`), in the order of the correction.
    pub planes: &'a [usize],
    /// The rows of the fit.
    pub used_rows: &'a [usize],
    /// `R̂` at every row.
    pub r_hat: &'a DVector<Complex64>,
    /// `D_a(Ĉ)`, the covariance of the row's own reading errors with `C`
    /// fixed, every row (`Propagation::residual`).
    pub own: &'a [Matrix2<f64>],
    /// The real `2q × 2q` covariance of `dC` (`Propagation::correction_full`).
    pub correction_full: &'a DMatrix<f64>,
    /// `Ω` (runs × q, row `k` is `ω_k`) and `λ_k` of the propagation
    /// (`Propagation::omega`, `lambda`); `None`: no product term.
    pub omega_lambda: Option<(&'a DMatrix<Complex64>, &'a [Complex64])>,
    /// The readings' covariances, `[row][run]`.
    pub cov: &'a [Vec<Matrix2<f64>>],
    /// Condition through the de-noised Gram (`denoise.rs`, errors in
    /// variables) where `omega_lambda` is given.
    pub denoise: bool,
}

/// Every row's bound parts (module doc), and whether the de-noised
/// conditioning (`denoise.rs`) was formed (its centre holds the
/// errors-in-variables bias: no move, 8.12); `None` where the conditioning
/// on all rows is not used: with fewer than two complex degrees of freedom
/// over the planes (rows `< q + 2`; module doc, "One degree of freedom"), a
/// row without noise, a rank deficient stack. The caller then conditions
/// each row on its own (method 8.6).
#[inline(never)] // seen on its own in callgrind (issue 15)
pub fn rows(inp: &Inputs) -> Option<(Vec<Row>, bool)> {
    let n = inp.w.nrows();
    let (q, m) = (inp.planes.len(), inp.used_rows.len());
    if q == 0
        || !crate::balancing::uncertainty::two_or_more_spare(m, q)
        || inp.r_hat.len() != n
        || inp.own.len() != n
    {
        return None;
    }
    let (nn, mm) = (2 * q, 2 * m);
    let second = inp
        .omega_lambda
        .map(|(omega, lambda)| Second::of(omega, lambda, inp));
    // The whitening of each used row's own errors at the true `C`.
    let mut f = Vec::with_capacity(m);
    for &b in inp.used_rows {
        let d = sym(&inp.own[b]);
        let cut = second.as_ref().map_or(0.0, |s| {
            let lo = 0.5 * (d.trace() - ((d.m11 - d.m22).powi(2) + 4.0 * d.m12.powi(2)).sqrt());
            (s.ez[b] * 0.5).min(0.9 * lo).max(0.0)
        });
        f.push(chol_inv(&(d - Matrix2::identity() * cut))?);
    }
    // The whitened stack [L_b⁻¹ W_b | L_b⁻¹ R̂_b], column-major 2m × (2q + 1),
    // written once (no zero fill: issue 15).
    let ws = inp.w.as_slice();
    let mut data = Vec::with_capacity(mm * (nn + 1));
    let rows_f = || inp.used_rows.iter().zip(&f);
    for &p in inp.planes {
        let col = &ws[p * n..(p + 1) * n];
        // `flat_map` into arrays has an exact length: one reservation, no
        // check per entry.
        data.extend(rows_f().flat_map(|(&b, fb)| {
            let z = col[b];
            [fb[0] * z.re, fb[1] * z.re + fb[2] * z.im]
        }));
        data.extend(rows_f().flat_map(|(&b, fb)| {
            let z = col[b];
            [-fb[0] * z.im, -fb[1] * z.im + fb[2] * z.re]
        }));
    }
    data.extend(rows_f().flat_map(|(&b, fb)| {
        let z = inp.r_hat[b];
        [fb[0] * z.re, fb[1] * z.re + fb[2] * z.im]
    }));
    // X = Q R (modified Gram–Schmidt, `Q` kept in `data`).
    let (r, qty) = qr_in_place(mm, nn, &mut data);
    let top = r.diagonal().iter().fold(0.0f64, |a, d| a.max(d.abs()));
    if !top.is_finite() || top <= 0.0 || r.diagonal().iter().any(|d| d.abs() <= 1e-10 * top) {
        return None;
    }
    // The diagonal was checked nonzero above.
    let r_inv = r.solve_upper_triangular(&DMatrix::identity(nn, nn))?;
    let den = match (inp.denoise, inp.omega_lambda) {
        (true, Some((omega, lambda))) => {
            denoise::of(&r, &qty, &f, inp.used_rows, inp.cov, omega, lambda)
        }
        _ => None,
    };
    let mc = match &den {
        Some(d) => d.delta.clone(),
        None => &r_inv * qty,
    };
    // The used rows' leverages `H_b = Q_b Q_bᵀ` (2 × 2) from `Q`'s columns:
    // `W_b R⁻¹ = L_b Q_b`, so `Σ_ε,b = W_b Λ⁻¹ W_bᵀ = L_b H_b L_bᵀ` without
    // the product `R⁻ᵀ Wᵀ` (issue 15).
    let (mut sq, mut nb) = (vec![0.0; mm], vec![0.0; mm]);
    squares_and_neighbours(mm, &data[..mm * nn], &mut sq, &mut nb);
    let mut used = vec![usize::MAX; n];
    for (i, &b) in inp.used_rows.iter().enumerate() {
        used[b] = i;
    }
    // m_a = W_a E[dC | v], through the complex W.
    let mut centre = vec![Complex64::new(0.0, 0.0); n];
    for (j, &p) in inp.planes.iter().enumerate() {
        let cj = Complex64::new(mc[2 * j], mc[2 * j + 1]);
        for (x, z) in centre.iter_mut().zip(&ws[p * n..(p + 1) * n]) {
            *x += z * cj;
        }
    }
    // Where the de-noised conditioning is formed, the product with the
    // observed `δ̃` split along the row's own error (`denoise.rs`, amp24b);
    // otherwise 8.9's product term with `Λ⁻¹`.
    let split = match (&den, &second) {
        (Some(d), Some(s)) => Some((d, s, s.split_denoised(&d.delta, &(&d.z * d.z.transpose())))),
        _ => None,
    };
    let added = match split {
        Some(_) => None,
        None => second.as_ref().map(|s| {
            let l_inv = &r_inv * r_inv.transpose();
            s.added(&l_inv, inp.r_hat, &centre)
        }),
    };
    let out = (0..n)
        .map(|a| {
            let (e11, e12, e22) = match (used[a], &den) {
                (_, Some(d)) => unused_row(inp, a, &d.z),
                (usize::MAX, None) => unused_row(inp, a, &r_inv),
                (i, None) => {
                    let [g0, g1, g2] = f[i];
                    // L_b = (L_b⁻¹)⁻¹, lower triangular.
                    let (l11, l22) = (1.0 / g0, 1.0 / g2);
                    let l21 = -g1 * l11 * l22;
                    let (h11, h12, h22) = (sq[2 * i], nb[2 * i], sq[2 * i + 1]);
                    let e11 = l11 * l11 * h11;
                    let e12 = l11 * (l21 * h11 + l22 * h12);
                    let e22 = l21 * l21 * h11 + 2.0 * l21 * l22 * h12 + l22 * l22 * h22;
                    (e11, e12, e22)
                }
            };
            let sigma = Matrix2::new(e11, e12, e12, e22);
            let (c, eps) = match &split {
                Some((d, s, parts)) => denoise::row(inp, a, centre[a], sigma, d, s, parts),
                None => {
                    let vz = added.as_ref().map_or(0.0, |v| v[a]);
                    (centre[a], sigma + Matrix2::identity() * (vz * 0.5))
                }
            };
            let mean = Vector2::new(c.re, c.im);
            Row::Parts(mean, eps, sym(&inp.own[a]) - eps)
        })
        .collect();
    Some((out, den.is_some()))
}

/// `L⁻¹` of `D = L Lᵀ` (Cholesky) as `[l⁻¹₁₁, l⁻¹₂₁, l⁻¹₂₂]`; `None` when
/// `D` is singular to 10⁻¹² of its trace or not finite.
fn chol_inv(d: &Matrix2<f64>) -> Option<[f64; 3]> {
    let (a, b, c) = (d.m11, d.m12, d.m22);
    let tr = a + c;
    let det = a * c - b * b;
    if !(tr.is_finite() && tr > 0.0 && a > 0.0 && det > 1e-12 * tr * tr) {
        return None;
    }
    let l11 = a.sqrt();
    let l21 = b / l11;
    let l22 = (det / a).sqrt();
    Some([1.0 / l11, -l21 / (l11 * l22), 1.0 / l22])
}

/// `W_a Λ⁻¹ W_aᵀ` of a row outside the fit: `P = W_a R⁻¹` (2 × 2q, `W_a`'s
/// real rows `(Re w_j, −Im w_j)`, `(Im w_j, Re w_j)`), `P Pᵀ`.
fn unused_row(inp: &Inputs, a: usize, r_inv: &DMatrix<f64>) -> (f64, f64, f64) {
    let nn = r_inv.nrows();
    let (mut w0, mut w1) = (DVector::zeros(nn), DVector::zeros(nn));
    for (j, &p) in inp.planes.iter().enumerate() {
        let z = inp.w[(a, p)];
        (w0[2 * j], w0[2 * j + 1], w1[2 * j], w1[2 * j + 1]) = (z.re, -z.im, z.im, z.re);
    }
    let (p0, p1) = (r_inv.tr_mul(&w0), r_inv.tr_mul(&w1));
    (p0.dot(&p0), p0.dot(&p1), p1.dot(&p1))
}

#[cfg(test)]
#[path = "joint_tests.rs"]
mod tests;
