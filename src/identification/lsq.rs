//! Linear least squares for the identification models: columns scaled to unit
//! norm, then the SVD (never the normal equations), with a rank check so that
//! an unidentifiable parameter is an error and not a silent minimum-norm guess.

use nalgebra::{DMatrix, DVector};

use crate::balancing::InputError;

/// Singular values below this, relative to the largest (after column scaling),
/// mean that the data cannot tell some parameters apart.
pub(crate) const RANK_TOLERANCE: f64 = 1e-11;

/// `argmin ‖A x − b‖` through the SVD of the column-scaled `A`.
/// `what` names the model in the error when the columns are dependent.
pub fn solve(
    mut a: DMatrix<f64>,
    b: &DVector<f64>,
    what: &str,
) -> Result<DVector<f64>, InputError> {
    if a.nrows() < a.ncols() {
        return Err(InputError::unsolvable(
            "too_few_equations",
            format!(
                "{what}: {} unknowns need at least as many equations; there are {}",
                a.ncols(),
                a.nrows()
            ),
        ));
    }
    if !a.iter().chain(b.iter()).all(|x| x.is_finite()) {
        return Err(InputError::unsolvable(
            "not_finite",
            format!("{what}: the data overflow the model's equations"),
        ));
    }
    // Scale columns so that parameters of very different size (a stiffness of
    // 1e5 beside a damping of 10) weigh alike in the rank decision.
    let scale = unit_columns(&mut a);
    let svd = a.svd(true, true);
    let smax = svd.singular_values.max();
    let smin = svd.singular_values.min();
    if smax == 0.0 || smin <= RANK_TOLERANCE * smax {
        return Err(InputError::unsolvable(
            "unidentifiable",
            format!("{what}: the data cannot tell the parameters apart (the equations are dependent); measure at more points, or at more different ones"),
        ));
    }
    let x = svd
        .solve(b, 0.0)
        .map_err(|e| InputError::unsolvable("solver_failed", e.to_string()))?;
    Ok(DVector::from_iterator(
        x.len(),
        x.iter().zip(&scale).map(|(v, s)| v / s),
    ))
}

/// A Gauss–Newton step: the smallest `x` minimising `‖A x + r‖`, through
/// the SVD of the column-scaled `A` with the singular values under the rank
/// tolerance dropped (so a step is taken even where the equations are
/// momentarily dependent), and whether `A` had full column rank.
pub fn step(
    a: &DMatrix<f64>,
    r: &DVector<f64>,
    what: &str,
) -> Result<(DVector<f64>, bool), InputError> {
    if !a.iter().chain(r.iter()).all(|x| x.is_finite()) {
        return Err(InputError::unsolvable(
            "not_finite",
            format!("{what}: the data overflow the model's equations"),
        ));
    }
    let mut a = a.clone();
    let scale = unit_columns(&mut a);
    let (rows, cols) = a.shape();
    let svd = a.svd(true, true);
    let smax = svd.singular_values.max();
    let full = rows >= cols && smax > 0.0 && svd.singular_values.min() > RANK_TOLERANCE * smax;
    let x = svd
        .solve(&(-r), RANK_TOLERANCE * smax)
        .map_err(|e| InputError::unsolvable("solver_failed", e.to_string()))?;
    Ok((
        DVector::from_iterator(x.len(), x.iter().zip(&scale).map(|(v, s)| v / s)),
        full,
    ))
}

/// `(AᵀA)⁻¹ v` through the SVD of the column-scaled `A` (`A = U Σ Vᵀ D`,
/// `D` the column norms, so `(AᵀA)⁻¹ = D⁻¹ V Σ⁻² Vᵀ D⁻¹`), never forming `AᵀA`, whose condition is
/// the square of `A`'s; `None` where `A`'s columns are dependent (the rank
/// tolerance of [`solve`]) or fewer rows than columns.
pub fn gram_inverse_times(a: &DMatrix<f64>, v: &DVector<f64>) -> Option<DVector<f64>> {
    if a.nrows() < a.ncols() || !a.iter().chain(v.iter()).all(|x| x.is_finite()) {
        return None;
    }
    let mut scaled = a.clone();
    let scale = unit_columns(&mut scaled);
    let svd = scaled.svd(false, true);
    let vt = svd.v_t?;
    let sigma = &svd.singular_values;
    let smax = sigma.max();
    if smax == 0.0 || sigma.min() <= RANK_TOLERANCE * smax {
        return None;
    }
    let sv = DVector::from_iterator(v.len(), v.iter().zip(&scale).map(|(x, s)| x / s));
    let mut w = &vt * sv;
    for (k, x) in w.iter_mut().enumerate() {
        *x /= sigma[k] * sigma[k];
    }
    let out = vt.transpose() * w;
    Some(DVector::from_iterator(
        out.len(),
        out.iter().zip(&scale).map(|(x, s)| x / s),
    ))
}

/// Scale `a`'s columns to unit norm in place; returns each column's norm
/// (at least the smallest positive number), by which the solution of the
/// scaled problem is divided to give the unscaled one.
pub(crate) fn unit_columns(a: &mut DMatrix<f64>) -> Vec<f64> {
    let scale: Vec<f64> = a
        .column_iter()
        .map(|c| c.norm().max(f64::MIN_POSITIVE))
        .collect();
    for (j, mut col) in a.column_iter_mut().enumerate() {
        col /= scale[j];
    }
    scale
}

/// Root mean square of a vector's entries (0 for an empty vector).
pub fn rms(v: impl IntoIterator<Item = f64>) -> f64 {
    let (sum, n) = v
        .into_iter()
        .fold((0.0, 0usize), |(s, n), x| (s + x * x, n + 1));
    if n == 0 {
        0.0
    } else {
        (sum / n as f64).sqrt()
    }
}

/// A finite number or an error naming `field`.
pub fn finite(field: impl FnOnce() -> String, x: f64) -> Result<f64, InputError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(InputError::invalid(
            "invalid_value",
            field(),
            "must be a finite number",
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_exact_system_of_very_different_column_sizes_is_solved_exactly() {
        let a = DMatrix::from_row_slice(3, 2, &[1e5, 1e-3, 2e5, 3e-3, -1e5, 5e-3]);
        let x = DVector::from_vec(vec![2.0, 7e6]);
        let got = solve(a.clone(), &(&a * &x), "test").unwrap();
        assert!((got - x).norm() < 1e-6);
    }

    /// `(AᵀA)⁻¹ v` of columns 1e8 apart in size (a Gram of condition ~1e16
    /// that a solve of `AᵀA` itself would lose): `AᵀA x = v` holds to the
    /// precision of `A`, checked without forming `AᵀA` (`Aᵀ(A x)`).
    #[test]
    fn the_gram_inverse_is_had_from_the_svd_of_very_different_columns() {
        let a = DMatrix::from_row_slice(3, 2, &[1e5, 1e-3, 2e5, 3e-3, -1e5, 5e-3]);
        let x = DVector::from_vec(vec![2.0, 7e6]);
        let v = a.transpose() * (&a * &x);
        let got = gram_inverse_times(&a, &v).unwrap();
        assert!(
            ((&got - &x).component_div(&x)).amax() < 1e-9,
            "{got} against {x}"
        );
        let dependent = DMatrix::from_row_slice(3, 2, &[1.0, 2.0, 2.0, 4.0, 3.0, 6.0]);
        assert!(gram_inverse_times(&dependent, &DVector::from_vec(vec![1.0, 1.0])).is_none());
    }

    #[test]
    fn dependent_columns_are_an_error() {
        let a = DMatrix::from_row_slice(3, 2, &[1.0, 2.0, 2.0, 4.0, 3.0, 6.0]);
        let err = solve(a, &DVector::from_vec(vec![1.0, 2.0, 3.0]), "test").unwrap_err();
        assert_eq!(err.code, "unidentifiable");
        // It read "measure at more or more different points" (review, session 17).
        assert!(
            err.message
                .ends_with("measure at more points, or at more different ones"),
            "{}",
            err.message
        );
    }
}
