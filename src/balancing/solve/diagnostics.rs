//! Can the numbers be trusted? Plane independence (Darlow's significance
//! factors, method §4 "Conditioning") and the size of each trial's effect.

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use crate::balancing::factor::Factored;
use crate::balancing::phasor::modulus;

/// Below this significance factor a plane counts as dependent (Darlow).
pub const SIGNIFICANCE_THRESHOLD: f64 = 0.2;
/// Relative difference of norms below which Gram–Schmidt's pivot is a tie
/// (far above rounding, far below any difference a reading can make).
const PIVOT_TIE: f64 = 1e-9;
/// Field practice: a trial should change some reading by at least 30 % (method §4).
pub const TRIAL_EFFECT_THRESHOLD: f64 = 0.3;

/// Darlow's significance factors of the columns of `a` (rows × planes).
///
/// Columns are scaled to unit norm; Gram–Schmidt with pivoting picks at each
/// step the column with the largest part orthogonal to those already picked,
/// and that part's norm is its factor. The first plane picked gets 1; a plane
/// whose column is nearly a combination of more significant ones gets nearly 0.
/// Returned in column order.
///
/// Norms equal within `PIVOT_TIE` are a tie, won by the plane listed first.
/// The first step is always such a tie (every column has norm 1), and without
/// the tolerance rounding in the scaling picked the winner: the same readings
/// with `W` computed another way moved every factor by up to 5 % (issue 15).
pub fn significance_factors(a: &DMatrix<Complex64>) -> Vec<f64> {
    let n = a.ncols();
    let mut cols: Vec<DVector<Complex64>> = (0..n)
        .map(|j| {
            let c = a.column(j).clone_owned();
            let norm = c.norm();
            if norm > 0.0 {
                c / Complex64::from(norm)
            } else {
                c
            }
        })
        .collect();
    let mut factor = vec![0.0; n];
    let mut left: Vec<usize> = (0..n).collect();
    while !left.is_empty() {
        let norms: Vec<f64> = left.iter().map(|&k| cols[k].norm()).collect();
        let top = norms.iter().cloned().fold(0.0, f64::max);
        // The largest norm is among them unless the norms are not numbers
        // (never from checked readings): those planes keep the factor 0.
        let Some((pos, &j)) = left
            .iter()
            .enumerate()
            .filter(|&(i, _)| norms[i] >= top * (1.0 - PIVOT_TIE))
            .min_by_key(|&(_, &k)| k)
        else {
            break;
        };
        left.swap_remove(pos);
        let norm = norms[pos];
        factor[j] = norm;
        if norm <= 1e-14 {
            continue;
        }
        let q = &cols[j] / Complex64::from(norm);
        for &k in &left {
            let proj = q.dotc(&cols[k]);
            cols[k] -= &q * proj;
        }
    }
    factor
}

/// Relative singular value (columns at unit norm) at or below which a
/// combination of planes moves no reading beyond rounding: those planes are
/// undetermined (issue 12).
pub const UNDETERMINED_TOLERANCE: f64 = 1e-9;

/// Per column of `a`: whether the readings leave that plane's correction
/// undetermined, i.e. it takes part in a combination of corrections that
/// changes no reading (a trial that changed nothing, or two planes the
/// sensors see identically, of which only a combination is determined).
/// Found from the right singular vectors of the column-scaled `a`.
pub fn undetermined_planes(a: &DMatrix<Complex64>) -> Vec<bool> {
    undetermined(&Factored::of(a))
}

/// [`undetermined_planes`] of the factored `A` (issue 15: from `R`, `A = Q R`).
pub fn undetermined(f: &Factored) -> Vec<bool> {
    let r = f.small();
    let q = r.ncols();
    if f.nrows() < q {
        return vec![true; q];
    }
    // A zero column of `A` is a zero column of `R` (reflections of a zero vector).
    let mut out: Vec<bool> = r.column_iter().map(|c| c.norm() == 0.0).collect();
    if let Some((singular_values, v_t)) = f.scaled_null(UNDETERMINED_TOLERANCE) {
        let smax = singular_values.max();
        for (i, &sv) in singular_values.iter().enumerate() {
            if sv <= UNDETERMINED_TOLERANCE * smax {
                for (j, flag) in out.iter_mut().enumerate() {
                    *flag |= v_t[(i, j)].norm() > 1e-6;
                }
            }
        }
    }
    out
}

/// `cond(A)` after scaling the columns to unit norm: σ_max/σ_min, capped at 1e16.
pub fn condition_number(a: &DMatrix<Complex64>) -> f64 {
    Factored::of(a).condition_number()
}

/// Largest change a plane's trial weight made at any of `rows`, relative to the
/// reference amplitude there: `max_a |W_aj|·t_j / |Y0_a|`, with `t_j` the
/// largest trial mass used in plane `j`. Rows with zero reference amplitude are
/// skipped. `y0_abs[a]` is `|Y0_a|`, computed once for every plane (issue 15).
pub fn trial_effect_ratio(
    w: &DMatrix<Complex64>,
    y0_abs: &[f64],
    t: &DMatrix<Complex64>,
    j: usize,
    rows: &[usize],
) -> f64 {
    let trial = t.row(j).iter().map(|x| x.norm()).fold(0.0, f64::max);
    rows.iter()
        .map(|&a| (a, y0_abs[a]))
        .filter(|&(_, y)| y > 0.0)
        .map(|(a, y)| modulus(w[(a, j)]) * trial / y)
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(re: f64, im: f64) -> Complex64 {
        Complex64::new(re, im)
    }

    #[test]
    fn independent_planes_have_factors_near_one() {
        let a = DMatrix::from_row_slice(
            3,
            2,
            &[
                c(1.0, 0.0),
                c(0.0, 0.0),
                c(0.0, 0.0),
                c(0.0, 2.0),
                c(0.0, 0.0),
                c(0.0, 0.0),
            ],
        );
        let f = significance_factors(&a);
        assert!((f[0] - 1.0).abs() < 1e-12 && (f[1] - 1.0).abs() < 1e-12);
        assert!((condition_number(&a) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn a_column_that_is_not_a_number_ranks_nothing_and_does_not_panic() {
        let a = DMatrix::from_row_slice(
            2,
            2,
            &[c(f64::NAN, 0.0), c(1.0, 0.0), c(0.0, 0.0), c(0.0, 1.0)],
        );
        let f = significance_factors(&a);
        // The finite column is ranked first; the other keeps 0.
        assert!(f[0] == 0.0 && (f[1] - 1.0).abs() < 1e-12, "{f:?}");
    }

    #[test]
    fn a_nearly_parallel_plane_gets_a_small_factor() {
        // Column 1 is column 0 rotated by a complex factor plus a little: dependent.
        let a = DMatrix::from_row_slice(
            2,
            2,
            &[c(1.0, 0.0), c(0.0, 1.0), c(1.0, 1.0), c(-1.0, 1.05)],
        );
        let f = significance_factors(&a);
        assert!(f.iter().cloned().fold(1.0, f64::min) < 0.05, "{f:?}");
        assert!(condition_number(&a) > 20.0);
    }

    #[test]
    fn planes_the_readings_cannot_tell_apart_are_undetermined() {
        // Column 1 moves nothing; columns 2 and 3 are the same: only their sum is determined.
        let a = DMatrix::from_row_slice(
            4,
            4,
            &[
                c(0.0, 3.0),
                c(0.0, 0.0),
                c(1.0, 1.0),
                c(1.0, 1.0),
                c(1.0, 0.0),
                c(0.0, 0.0),
                c(0.5, 1.0),
                c(0.5, 1.0),
                c(0.2, 0.0),
                c(0.0, 0.0),
                c(1.0, 0.0),
                c(1.0, 0.0),
                c(0.0, 1.0),
                c(0.0, 0.0),
                c(0.0, -2.0),
                c(0.0, -2.0),
            ],
        );
        assert_eq!(undetermined_planes(&a), vec![false, true, true, true]);
        let independent =
            DMatrix::from_row_slice(2, 2, &[c(1.0, 0.0), c(0.0, 0.0), c(0.0, 0.0), c(0.0, 1e-6)]);
        assert_eq!(undetermined_planes(&independent), vec![false, false]);
    }

    #[test]
    fn the_factors_do_not_depend_on_how_each_column_was_scaled() {
        // P2 is nearly P0 + P1. Scaling a column changes only the rounding of
        // its unit-norm copy, which used to decide the first pivot (a tie).
        let base = DMatrix::from_row_slice(
            4,
            3,
            &[
                c(1.0, 0.2),
                c(0.1, 0.9),
                c(1.1, 1.15),
                c(0.3, -0.5),
                c(0.8, 0.1),
                c(1.1, -0.35),
                c(-0.2, 0.4),
                c(0.5, 0.5),
                c(0.3, 0.92),
                c(0.7, 0.0),
                c(-0.1, 0.6),
                c(0.6, 0.61),
            ],
        );
        let reference = significance_factors(&base);
        assert!(reference[2] < SIGNIFICANCE_THRESHOLD, "{reference:?}");
        let mut seed = 0x9e37_79b9_u64;
        for _ in 0..200 {
            let mut a = base.clone();
            for mut col in a.column_iter_mut() {
                seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
                let s = 0.1 + (seed >> 11) as f64 / (1u64 << 53) as f64 * 10.0;
                col *= Complex64::from(s);
            }
            let f = significance_factors(&a);
            for (x, y) in f.iter().zip(&reference) {
                assert!((x - y).abs() < 1e-9, "{f:?} against {reference:?}");
            }
        }
    }

    #[test]
    fn a_plane_that_moves_nothing_has_factor_zero() {
        let a =
            DMatrix::from_row_slice(2, 2, &[c(1.0, 0.0), c(0.0, 0.0), c(0.5, 0.0), c(0.0, 0.0)]);
        assert_eq!(significance_factors(&a)[1], 0.0);
    }
}
