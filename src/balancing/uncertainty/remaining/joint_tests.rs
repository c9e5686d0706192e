//! Tests of `joint`: the products equal the per-row reference form of
//! method 8.8/8.9 (session 9's experiment: a QR of the symmetric-whitened
//! stack, two triangular solves and a `q`-vector `g_a` per row), and in the
//! linear Gaussian model the bound conditioned on all rows holds 95 %.

use super::super::tests::real_row;
use super::super::Pooled;
use super::product::hermitian_part;
use super::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rand_distr::{Distribution, StandardNormal};

fn cx(rng: &mut StdRng) -> Complex64 {
    Complex64::new(rng.gen_range(-1.0..1.0), rng.gen_range(-1.0..1.0))
}

fn spd(rng: &mut StdRng, scale: f64) -> Matrix2<f64> {
    let mut u = || rng.gen::<f64>();
    let a = Matrix2::new(u(), u(), u(), u());
    (a * a.transpose() + Matrix2::identity() * 0.2) * scale
}

fn inv_sqrt(s: &Matrix2<f64>) -> Matrix2<f64> {
    let e = s.symmetric_eigen();
    let mut out = Matrix2::zeros();
    for i in 0..2 {
        let v = e.eigenvectors.column(i);
        out += v * v.transpose() / e.eigenvalues[i].sqrt();
    }
    out
}

/// Every row and plane used, no product term (`omega_lambda` none): the setting
/// of the linear Gaussian tests below.
struct AllUsed {
    planes: Vec<usize>,
    used: Vec<usize>,
    full: DMatrix<f64>,
}

impl AllUsed {
    fn new(n: usize, q: usize) -> AllUsed {
        AllUsed {
            planes: (0..q).collect(),
            used: (0..n).collect(),
            full: DMatrix::zeros(2 * q, 2 * q),
        }
    }

    fn inputs<'a>(
        &'a self,
        w: &'a DMatrix<Complex64>,
        r_hat: &'a DVector<Complex64>,
        own: &'a [Matrix2<f64>],
    ) -> Inputs<'a> {
        Inputs {
            w,
            planes: &self.planes,
            used_rows: &self.used,
            r_hat,
            own,
            correction_full: &self.full,
            omega_lambda: None,
            cov: &[],
            denoise: false,
        }
    }
}

#[test]
fn the_products_equal_the_per_row_reference_form() {
    let mut rng = StdRng::seed_from_u64(5);
    let (n, planes, q) = (9, 3, 2);
    let used_planes = [2usize, 0];
    let used_rows: Vec<usize> = (0..n).filter(|&a| a != 4).collect();
    let w = DMatrix::from_fn(n, planes, |_, _| cx(&mut rng));
    let t_pinv = DMatrix::from_fn(planes, planes, |_, _| cx(&mut rng));
    let runs = planes + 1;
    let c = DVector::from_fn(q, |_, _| cx(&mut rng) * 3.0);
    let r_hat = DVector::from_fn(n, |_, _| cx(&mut rng) * 0.5);
    let cov: Vec<Vec<Matrix2<f64>>> = (0..n)
        .map(|_| (0..runs).map(|_| spd(&mut rng, 0.01)).collect())
        .collect();
    let own: Vec<Matrix2<f64>> = (0..n).map(|_| spd(&mut rng, 0.3)).collect();
    let g = DMatrix::from_fn(2 * q, 2 * q, |_, _| rng.gen_range(-0.1..0.1));
    let full = &g * g.transpose() + DMatrix::identity(2 * q, 2 * q) * 0.01;
    // `ω_k` and `λ_k` as `propagate` forms them (method 8.9), the reference's
    // and `Inputs`'s alike.
    let omega: Vec<DVector<Complex64>> = (0..runs)
        .map(|k| {
            DVector::from_fn(q, |j, _| match k {
                0 => -t_pinv.column(used_planes[j]).sum(),
                _ => t_pinv[(k - 1, used_planes[j])],
            })
        })
        .collect();
    let lambda: Vec<Complex64> = (0..runs)
        .map(|k| omega[k].dot(&c) + if k == 0 { 1.0 } else { 0.0 })
        .collect();
    let omega_rows = DMatrix::from_fn(runs, q, |k, j| omega[k][j]);
    let inp = Inputs {
        w: &w,
        planes: &used_planes,
        used_rows: &used_rows,
        r_hat: &r_hat,
        own: &own,
        correction_full: &full,
        omega_lambda: Some((&omega_rows, &lambda)),
        cov: &cov,
        denoise: false,
    };
    let (rows, _) = rows(&inp).expect("formed");

    // Reference, as session 9 wrote it.
    let wrow = |a: usize| -> Vec<Complex64> { used_planes.iter().map(|&p| w[(a, p)]).collect() };
    let kc = hermitian_part(&full);
    let quad = |g: &DVector<Complex64>, k: &DMatrix<Complex64>| {
        (g.transpose() * k * g.map(|x| x.conj()))[(0, 0)].re
    };
    let ez = |a: usize| -> f64 {
        (0..runs)
            .map(|k| cov[a][k].trace() * quad(&omega[k], &kc))
            .sum()
    };
    let m = used_rows.len();
    let mut x = DMatrix::<f64>::zeros(2 * m, 2 * q);
    let mut y = DVector::<f64>::zeros(2 * m);
    for (i, &b) in used_rows.iter().enumerate() {
        let d = own[b];
        let lo = d.symmetric_eigenvalues().min();
        let cut = (ez(b) * 0.5).min(0.9 * lo).max(0.0);
        let wi = inv_sqrt(&(d - Matrix2::identity() * cut));
        let xb = DMatrix::from_fn(2, 2, |i, j| wi[(i, j)]) * real_row(&wrow(b));
        x.view_mut((2 * i, 0), (2, 2 * q)).copy_from(&xb);
        let rb = wi * Vector2::new(r_hat[b].re, r_hat[b].im);
        y[2 * i] = rb.x;
        y[2 * i + 1] = rb.y;
    }
    let qr = x.qr();
    let r = qr.r();
    let mc = r
        .clone()
        .solve_upper_triangular(&(qr.q().transpose() * &y))
        .unwrap();
    let rt = r.transpose();
    let l_inv = {
        let ri = r.clone().try_inverse().unwrap();
        &ri * ri.transpose()
    };
    let k_cond = hermitian_part(&l_inv);
    for a in 0..n {
        let wa = real_row(&wrow(a));
        let z = rt.solve_lower_triangular(&wa.transpose()).unwrap();
        let eps = z.transpose() * &z;
        let mv = &wa * &mc;
        let ve: f64 = (0..runs)
            .map(|k| cov[a][k].trace() * lambda[k].norm_sqr())
            .sum();
        let mut ga = DVector::<Complex64>::zeros(q);
        for ((o, l), s) in omega.iter().zip(&lambda).zip(&cov[a]) {
            ga += o * (l.conj() * s.trace() / ve);
        }
        let e_hat =
            (Vector2::new(r_hat[a].re, r_hat[a].im) - Vector2::new(mv[0], mv[1])).norm_squared();
        let vz = (ez(a) - quad(&ga, &kc) * ve).max(0.0) + e_hat * quad(&ga, &k_cond);
        let e2 = Matrix2::new(eps[(0, 0)], eps[(0, 1)], eps[(1, 0)], eps[(1, 1)])
            + Matrix2::identity() * (vz * 0.5);
        let Row::Parts(mean, eps_got, k_got) = rows[a] else {
            panic!("row {a} not conditioned");
        };
        let scale = e2.norm();
        assert!(
            (mean - Vector2::new(mv[0], mv[1])).norm() < 1e-10,
            "row {a}"
        );
        assert!(
            (eps_got - e2).norm() < 1e-10 * scale,
            "row {a}: {eps_got} {e2}"
        );
        assert!(
            (k_got - (own[a] - e2)).norm() < 1e-10 * own[a].norm(),
            "row {a}"
        );
    }
}

/// Linear Gaussian model, no product term (`omega_lambda` none): the true
/// remaining vibration `W_a dC` given every row's prediction `v = (I −
/// W W⁺) e` is `N(m_a, Σ_ε,a)` exactly (method 8.8), so the bound at `S = 0`
/// holds 95 %. 2,000 jobs of 12 rows; the checks of one job share its `dC`,
/// so at worst (all twelve alike) the standard error is that of 2,000
/// checks, 0.49 %, and the window 93.5–96.5 % is 3 of those around 95 %.
/// (Written in session 10, first run and passing in session 11.)
#[test]
fn in_the_linear_gaussian_model_the_bound_conditioned_on_all_rows_holds_95_percent() {
    let mut rng = StdRng::seed_from_u64(17);
    let (n, q) = (12, 3);
    let w = DMatrix::from_fn(n, q, |_, _| cx(&mut rng));
    let own: Vec<Matrix2<f64>> = (0..n)
        .map(|a| spd(&mut rng, 0.02 * (1.0 + a as f64)))
        .collect();
    let chol: Vec<Matrix2<f64>> = own.iter().map(|d| d.cholesky().unwrap().l()).collect();
    let fixture = AllUsed::new(n, q);
    let pinv = w.clone().svd(true, true).pseudo_inverse(1e-12).unwrap();
    let (mut held, mut checks) = (0usize, 0usize);
    for _ in 0..2000 {
        let e = DVector::from_fn(n, |a, _| {
            let (x, y): (f64, f64) = (
                StandardNormal.sample(&mut rng),
                StandardNormal.sample(&mut rng),
            );
            let z = chol[a] * Vector2::new(x, y);
            Complex64::new(z.x, z.y)
        });
        let dc = -(&pinv * &e);
        let v = &e + &w * &dc;
        let (rows, _) = rows(&fixture.inputs(&w, &v, &own)).expect("formed");
        let truth = &w * &dc;
        for (a, row) in rows.iter().enumerate() {
            let bound = row.amplitude_95(v[a], Pooled::plug_in(0.0));
            held += usize::from(truth[a].norm() <= bound);
            checks += 1;
        }
    }
    let p = held as f64 / checks as f64;
    assert!((0.935..=0.965).contains(&p), "{p}");
}

/// With rows only one more than the planes the other rows' predictions are a
/// fixed function of the row's own (module doc, "One degree of freedom"):
/// the conditioning is left to each row (`None`); from two complex degrees
/// of freedom it is formed.
#[test]
fn with_one_degree_of_freedom_over_the_planes_each_row_is_left_to_itself() {
    let mut rng = StdRng::seed_from_u64(23);
    let q = 3;
    for (n, formed) in [(4, false), (5, true)] {
        let w = DMatrix::from_fn(n, q, |_, _| cx(&mut rng));
        let own: Vec<Matrix2<f64>> = (0..n).map(|_| spd(&mut rng, 0.05)).collect();
        let v = DVector::from_fn(n, |_, _| cx(&mut rng));
        let fixture = AllUsed::new(n, q);
        assert_eq!(
            rows(&fixture.inputs(&w, &v, &own)).is_some(),
            formed,
            "{n} rows"
        );
    }
}
