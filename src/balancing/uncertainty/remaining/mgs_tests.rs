//! Tests of `mgs`: `Q`, `R`, `Qᵀy` and the residual against a reference, the
//! two kernels against each other, and the leverages' sums.

use super::*;

#[test]
fn q_r_and_qty_agree_with_a_reference_and_both_kernels_agree() {
    let mut seed = 3u64;
    let mut next = || {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for (m, n) in [(9, 4), (40, 6), (5, 5), (7, 1), (37, 8), (2, 2), (61, 13)] {
        let x = DMatrix::from_fn(m, n, |_, _| next());
        let y = DVector::from_fn(m, |_, _| next());
        let mut data = x.as_slice().to_vec();
        data.extend_from_slice(y.as_slice());
        let mut out = data.clone();
        let (r, qty) = qr_in_place(m, n, &mut out);
        let q = DMatrix::from_column_slice(m, n, &out[..m * n]);
        // Q R = X, QᵀQ = I, R upper triangular, Qᵀy and the residual.
        assert!((&q * &r - &x).norm() < 1e-12);
        assert!((q.transpose() * &q - DMatrix::identity(n, n)).norm() < 1e-12);
        assert!((0..n).all(|j| (j + 1..n).all(|i| r[(i, j)] == 0.0)));
        assert!((q.transpose() * &y - &qty).norm() < 1e-12);
        let res = DVector::from_column_slice(&out[m * n..]);
        assert!((&y - &q * &qty - res).norm() < 1e-12);
        // The least-squares solution.
        let sol = r.clone().solve_upper_triangular(&qty).unwrap();
        let reference = x.clone().svd(true, true).solve(&y, 1e-14).unwrap();
        assert!((sol - reference).norm() < 1e-10);
        let (mut a, mut b) = (data.clone(), data);
        let (mut ra, mut rb) = (vec![0.0; n * (n + 1)], vec![0.0; n * (n + 1)]);
        run(m, n, &mut a, &mut ra);
        kernel_plain(m, n, &mut b, &mut rb);
        let close = |p: &[f64], q: &[f64]| p.iter().zip(q).all(|(p, q)| (p - q).abs() <= 1e-13);
        assert!(close(&a, &b) && close(&ra, &rb), "{m} x {n}");
        assert!((dot(&a, &b) - plain::dot(&a, &b)).abs() <= 1e-12 * dot(&a, &a));
    }
}

#[test]
fn a_zero_column_gives_a_zero_diagonal_and_leaves_the_others_alone() {
    let (m, n) = (6, 3);
    let mut data: Vec<f64> = (0..m * (n + 1)).map(|i| (i as f64 * 0.37).sin()).collect();
    data[m..2 * m].fill(0.0);
    let x = DMatrix::from_column_slice(m, n, &data[..m * n]);
    let (r, _) = qr_in_place(m, n, &mut data);
    assert_eq!(r[(1, 1)], 0.0);
    let q = DMatrix::from_column_slice(m, n, &data[..m * n]);
    assert!((&q * &r - &x).norm() < 1e-12);
}

#[test]
fn squares_and_neighbours_sum_the_products() {
    // Two columns of 11 rows (the four-lane body and its tail).
    let q: Vec<f64> = (0..22).map(|i| (i as f64 * 0.7).sin()).collect();
    let (mut c, mut d) = (vec![1.0; 11], vec![0.5; 11]);
    squares_and_neighbours(11, &q, &mut c, &mut d);
    for i in 0..11 {
        let (a, b) = (q[i], q[11 + i]);
        assert!((c[i] - (1.0 + a * a + b * b)).abs() < 1e-15);
        let want = if i < 10 {
            0.5 + a * q[i + 1] + b * q[12 + i]
        } else {
            0.5
        };
        assert!((d[i] - want).abs() < 1e-15, "{i}");
    }
}
