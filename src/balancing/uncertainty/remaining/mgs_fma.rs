//! The kernels of `mgs` with AVX2 and FMA: four lanes, four independent
//! sums, the fused multiply-add (mgs.rs, module doc).

use std::arch::x86_64::*;

#[inline]
#[target_feature(enable = "avx2,fma")]
unsafe fn hsum(v: __m256d) -> f64 {
    let lo = _mm256_castpd256_pd128(v);
    let hi = _mm256_extractf128_pd(v, 1);
    let s = _mm_add_pd(lo, hi);
    _mm_cvtsd_f64(_mm_add_sd(s, _mm_unpackhi_pd(s, s)))
}

#[inline]
#[target_feature(enable = "avx2,fma")]
pub unsafe fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len();
    assert!(b.len() >= n);
    let (pa, pb) = (a.as_ptr(), b.as_ptr());
    let mut s = [_mm256_setzero_pd(); 4];
    let mut i = 0;
    while i + 16 <= n {
        for (l, s) in s.iter_mut().enumerate() {
            let o = i + 4 * l;
            *s = _mm256_fmadd_pd(_mm256_loadu_pd(pa.add(o)), _mm256_loadu_pd(pb.add(o)), *s);
        }
        i += 16;
    }
    while i + 4 <= n {
        s[0] = _mm256_fmadd_pd(_mm256_loadu_pd(pa.add(i)), _mm256_loadu_pd(pb.add(i)), s[0]);
        i += 4;
    }
    let mut t = hsum(_mm256_add_pd(
        _mm256_add_pd(s[0], s[1]),
        _mm256_add_pd(s[2], s[3]),
    ));
    while i < n {
        t += a[i] * b[i];
        i += 1;
    }
    t
}

#[inline]
#[target_feature(enable = "avx2,fma")]
pub unsafe fn dot2(u: &[f64], a: &[f64], b: &[f64]) -> (f64, f64) {
    let n = u.len();
    assert!(a.len() >= n && b.len() >= n);
    let (pu, pa, pb) = (u.as_ptr(), a.as_ptr(), b.as_ptr());
    let mut s = [_mm256_setzero_pd(); 4];
    let mut i = 0;
    while i + 8 <= n {
        let (u0, u1) = (_mm256_loadu_pd(pu.add(i)), _mm256_loadu_pd(pu.add(i + 4)));
        s[0] = _mm256_fmadd_pd(u0, _mm256_loadu_pd(pa.add(i)), s[0]);
        s[1] = _mm256_fmadd_pd(u1, _mm256_loadu_pd(pa.add(i + 4)), s[1]);
        s[2] = _mm256_fmadd_pd(u0, _mm256_loadu_pd(pb.add(i)), s[2]);
        s[3] = _mm256_fmadd_pd(u1, _mm256_loadu_pd(pb.add(i + 4)), s[3]);
        i += 8;
    }
    let (mut ta, mut tb) = (
        hsum(_mm256_add_pd(s[0], s[1])),
        hsum(_mm256_add_pd(s[2], s[3])),
    );
    while i < n {
        ta += u[i] * a[i];
        tb += u[i] * b[i];
        i += 1;
    }
    (ta, tb)
}

#[inline]
#[target_feature(enable = "avx2,fma")]
pub unsafe fn sub(y: &mut [f64], d: f64, x: &[f64]) {
    let n = y.len();
    assert!(x.len() >= n);
    let (py, px) = (y.as_mut_ptr(), x.as_ptr());
    let nd = _mm256_set1_pd(-d);
    let mut i = 0;
    while i + 4 <= n {
        let v = _mm256_fmadd_pd(nd, _mm256_loadu_pd(px.add(i)), _mm256_loadu_pd(py.add(i)));
        _mm256_storeu_pd(py.add(i), v);
        i += 4;
    }
    while i < n {
        y[i] -= d * x[i];
        i += 1;
    }
}

/// [`super::squares_and_neighbours`] (lengths checked there).
#[target_feature(enable = "avx2,fma")]
pub unsafe fn squares_and_neighbours(m: usize, q: &[f64], c: &mut [f64], d: &mut [f64]) {
    let (pc, pd) = (c.as_mut_ptr(), d.as_mut_ptr());
    for a in q.chunks_exact(m) {
        let pa = a.as_ptr();
        let mut i = 0;
        while i + 5 <= m {
            let x = _mm256_loadu_pd(pa.add(i));
            let y = _mm256_loadu_pd(pa.add(i + 1));
            _mm256_storeu_pd(pc.add(i), _mm256_fmadd_pd(x, x, _mm256_loadu_pd(pc.add(i))));
            _mm256_storeu_pd(pd.add(i), _mm256_fmadd_pd(x, y, _mm256_loadu_pd(pd.add(i))));
            i += 4;
        }
        while i < m {
            c[i] += a[i] * a[i];
            if i + 1 < m {
                d[i] += a[i] * a[i + 1];
            }
            i += 1;
        }
    }
}

#[inline]
#[target_feature(enable = "avx2,fma")]
pub unsafe fn sub2(a: &mut [f64], da: f64, b: &mut [f64], db: f64, x: &[f64]) {
    let n = x.len();
    assert!(a.len() >= n && b.len() >= n);
    let (pa, pb, px) = (a.as_mut_ptr(), b.as_mut_ptr(), x.as_ptr());
    let (na, nb) = (_mm256_set1_pd(-da), _mm256_set1_pd(-db));
    let mut i = 0;
    while i + 4 <= n {
        let xv = _mm256_loadu_pd(px.add(i));
        _mm256_storeu_pd(
            pa.add(i),
            _mm256_fmadd_pd(na, xv, _mm256_loadu_pd(pa.add(i))),
        );
        _mm256_storeu_pd(
            pb.add(i),
            _mm256_fmadd_pd(nb, xv, _mm256_loadu_pd(pb.add(i))),
        );
        i += 4;
    }
    while i < n {
        a[i] -= da * x[i];
        b[i] -= db * x[i];
        i += 1;
    }
}
