//! The product term of method 8.9 for `joint` (module doc there): what the
//! coefficients' noise times the correction's error adds to each row's
//! bound, as real quadratic forms over the runs for all rows at once.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use super::Inputs;

/// Complex `E[x xᴴ]` (`q × q`) of a real `2q × 2q` covariance of
/// `(Re x₀, Im x₀, Re x₁, …)`.
pub fn hermitian_part(full: &DMatrix<f64>) -> DMatrix<Complex64> {
    let q = full.nrows() / 2;
    DMatrix::from_fn(q, q, |j, l| {
        let (xj, yj, xl, yl) = (2 * j, 2 * j + 1, 2 * l, 2 * l + 1);
        Complex64::new(
            full[(xj, xl)] + full[(yj, yl)],
            full[(yj, xl)] - full[(xj, yl)],
        )
    })
}

/// The product term's ingredients (module doc): `Ω` (runs × q, row `k` is
/// `ω_k`: `−1ᵀT⁺` for the reference run, `T⁺`'s row otherwise) and `λ_k`,
/// both as the propagation formed them (`Propagation::omega`, `lambda`), the
/// readings' `s_ak = tr S_ak` (rows × runs), `E|z_a|²`, `V_e,a`, and `K`.
pub struct Second<'a> {
    omega: &'a DMatrix<Complex64>,
    lambda: &'a [Complex64],
    s: DMatrix<f64>,
    pub ez: Vec<f64>,
    ve: Vec<f64>,
    /// `Ω K Ωᴴ`.
    h: DMatrix<Complex64>,
}

impl<'a> Second<'a> {
    pub fn of(omega: &'a DMatrix<Complex64>, lambda: &'a [Complex64], inp: &Inputs) -> Second<'a> {
        let (n, runs) = (inp.w.nrows(), omega.nrows());
        let k_mat = hermitian_part(inp.correction_full);
        let h = omega * &k_mat * omega.adjoint();
        let mut s = Vec::with_capacity(n * runs);
        for k in 0..runs {
            s.extend(inp.cov.iter().map(|row| row[k].trace()));
        }
        let s = DMatrix::from_vec(n, runs, s);
        let (mut ez, mut ve) = (vec![0.0; n], vec![0.0; n]);
        for (k, col) in s.as_slice().chunks_exact(n).enumerate() {
            let (mk, lk) = (h[(k, k)].re, lambda[k].norm_sqr());
            for ((e, v), &sk) in ez.iter_mut().zip(ve.iter_mut()).zip(col) {
                *e += sk * mk;
                *v += sk * lk;
            }
        }
        Second {
            omega,
            lambda,
            s,
            ez,
            ve,
            h,
        }
    }

    /// Per row: `E|ζ_a|² + |R̂_a − m_a|² Var(β | v)` (method 8.9), `l_inv`
    /// the conditional covariance `Λ⁻¹`.
    pub fn added(
        &self,
        l_inv: &DMatrix<f64>,
        r_hat: &DVector<Complex64>,
        centre: &[Complex64],
    ) -> Vec<f64> {
        let runs = self.lambda.len();
        // H̃_kl = Re(λ̄_k (Ω K Ωᴴ)_kl λ_l), then the same with Λ⁻¹.
        let mut ht = DMatrix::<f64>::zeros(runs, 2 * runs);
        let h_cond = self.omega * hermitian_part(l_inv) * self.omega.adjoint();
        for (half, h) in [&self.h, &h_cond].into_iter().enumerate() {
            for kk in 0..runs {
                for l in 0..runs {
                    ht[(kk, half * runs + l)] =
                        (self.lambda[kk].conj() * h[(kk, l)] * self.lambda[l]).re;
                }
            }
        }
        let t = &self.s * ht;
        let n = self.s.nrows();
        // Σ_k s_ak T_ak for both halves, run by run over contiguous columns.
        let (mut b2, mut var) = (vec![0.0; n], vec![0.0; n]);
        let (t1, t2) = t.as_slice().split_at(runs * n);
        let columns = self.s.as_slice().chunks_exact(n);
        for ((s, t1), t2) in columns.zip(t1.chunks_exact(n)).zip(t2.chunks_exact(n)) {
            for (((b, v), s), (x, y)) in b2
                .iter_mut()
                .zip(var.iter_mut())
                .zip(s)
                .zip(t1.iter().zip(t2))
            {
                *b += s * x;
                *v += s * y;
            }
        }
        (0..n)
            .map(|a| {
                let ve = self.ve[a];
                if ve.is_nan() || ve <= 0.0 {
                    return 0.0;
                }
                let unexplained = (self.ez[a] - b2[a] / ve).max(0.0);
                let e_hat = (r_hat[a] - centre[a]).norm_sqr();
                unexplained + e_hat * (var[a] / (ve * ve)).max(0.0)
            })
            .collect()
    }
}

/// The product with the observed `δ̃` per row (`Second::split_denoised`).
pub struct Split {
    /// `Σ_k s_ak |ω_k·δ̃|²`.
    pub known: Vec<f64>,
    /// `Σ_k s_ak ω_k V ω_kᴴ`, twice the plug-in's `E[dW_a V dW_aᵀ]`.
    pub vterm: Vec<f64>,
    /// `β_a`, the product's part along the row's own error.
    pub beta: Vec<Complex64>,
}

impl Second<'_> {
    /// The product term redone for the de-noised conditioning (`denoise.rs`;
    /// method 8, session 24, amp24b). Where `r = 0`, `R_a − m_a = W_a(C̃ −
    /// C) − dW_a δ̃` exactly (`m_a = Ŵ_a δ̃`, `δ̃ = Ĉ − C̃`), so the product
    /// with the unknown part `C̃ − C` is already inside the plug-in `Ŵ_a V
    /// Ŵ_aᵀ` (whose mean is `W_a V W_aᵀ + E[dW_a V dW_aᵀ]`) and the product
    /// that remains is with the observed `δ̃`. Per row: `Σ_k s_ak
    /// |ω_k·δ̃|²`, `Σ_k s_ak ω_k V ω_kᴴ` (`V` real `2q × 2q`) and `β_a = Σ_k
    /// s_ak λ̄_k (ω_k·δ̃) / V_e,a` (0 where `V_e,a` is not positive).
    pub fn split_denoised(&self, delta: &DVector<f64>, v: &DMatrix<f64>) -> Split {
        let (n, runs) = (self.s.nrows(), self.lambda.len());
        let q = self.omega.ncols();
        let d: Vec<Complex64> = (0..q)
            .map(|j| Complex64::new(delta[2 * j], delta[2 * j + 1]))
            .collect();
        let wd: Vec<Complex64> = (0..runs)
            .map(|k| (0..q).map(|j| self.omega[(k, j)] * d[j]).sum())
            .collect();
        let hv = self.omega * hermitian_part(v) * self.omega.adjoint();
        let (mut known, mut vterm, mut beta) = (
            vec![0.0; n],
            vec![0.0; n],
            vec![Complex64::new(0.0, 0.0); n],
        );
        for k in 0..runs {
            let (mk, vk, lw) = (
                wd[k].norm_sqr(),
                hv[(k, k)].re,
                self.lambda[k].conj() * wd[k],
            );
            for a in 0..n {
                let s = self.s[(a, k)];
                known[a] += s * mk;
                vterm[a] += s * vk;
                beta[a] += lw * s;
            }
        }
        for (b, &ve) in beta.iter_mut().zip(&self.ve) {
            *b = if ve.is_finite() && ve > 0.0 {
                *b / ve
            } else {
                Complex64::new(0.0, 0.0)
            };
        }
        Split { known, vterm, beta }
    }

    /// `V_e,a = Σ_k s_ak |λ_k|²`, the variance of the row's own error.
    pub fn ve(&self, a: usize) -> f64 {
        self.ve[a]
    }
}
