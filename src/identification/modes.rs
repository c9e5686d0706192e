//! Natural frequencies and mass-normalised mode shapes of `K φ = ω² M φ`:
//! the generalised symmetric eigenproblem through the Cholesky factor of `M`
//! (`L⁻¹ K L⁻ᵀ` is symmetric) and nalgebra's `SymmetricEigen`.

use nalgebra::{DMatrix, DVector};

use crate::balancing::InputError;

/// Eigenpairs in ascending order of `ω²`; shapes with `φᵀ M φ = 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct Modes {
    /// `ω²`, 1/s² (negative when `K` is not positive semi-definite;
    /// `ranges::frequencies` refuses those).
    pub w2: Vec<f64>,
    /// Columns: the shapes.
    pub shapes: DMatrix<f64>,
}

/// Solve `K φ = ω² M φ` for symmetric `K` and symmetric positive-definite `M`.
pub fn solve(m: &DMatrix<f64>, k: &DMatrix<f64>) -> Result<Modes, InputError> {
    let chol = m.clone().cholesky().ok_or_else(|| {
        InputError::unsolvable(
            "mass_not_positive_definite",
            "the mass matrix (mass.fixed plus the mass parameters times mass.parameters) is not positive definite for these parameters: every motion of the model needs a positive mass; check the signs and sizes of the mass entries",
        )
    })?;
    let l = chol.l();
    let l_inv = l.clone().try_inverse().ok_or_else(|| {
        InputError::unsolvable(
            "mass_not_positive_definite",
            "the mass matrix (mass.fixed plus the mass parameters times mass.parameters) is singular for these parameters: check the signs and sizes of the mass entries",
        )
    })?;
    let mut a = &l_inv * k * l_inv.transpose();
    // Symmetrise away rounding so that SymmetricEigen sees a symmetric matrix.
    a = (&a + a.transpose()) * 0.5;
    let eig = a.symmetric_eigen();
    let mut order: Vec<usize> = (0..eig.eigenvalues.len()).collect();
    order.sort_by(|&x, &y| eig.eigenvalues[x].total_cmp(&eig.eigenvalues[y]));
    let back = l_inv.transpose();
    let n = m.nrows();
    let mut shapes = DMatrix::zeros(n, n);
    for (c, &j) in order.iter().enumerate() {
        let phi: DVector<f64> = &back * eig.eigenvectors.column(j);
        shapes.set_column(c, &phi);
    }
    Ok(Modes {
        w2: order.iter().map(|&j| eig.eigenvalues[j]).collect(),
        shapes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_two_mass_chain_has_its_textbook_frequencies_and_normalised_shapes() {
        // m = 1, k = 1 both springs (ground–1, 1–2): ω² = (3 ∓ √5)/2.
        let m = DMatrix::identity(2, 2);
        let k = DMatrix::from_row_slice(2, 2, &[2.0, -1.0, -1.0, 1.0]);
        let modes = solve(&m, &k).unwrap();
        assert!((modes.w2[0] - (3.0 - 5f64.sqrt()) / 2.0).abs() < 1e-12);
        assert!((modes.w2[1] - (3.0 + 5f64.sqrt()) / 2.0).abs() < 1e-12);
        for c in 0..2 {
            let phi = modes.shapes.column(c);
            assert!(((phi.transpose() * &m * phi)[(0, 0)] - 1.0).abs() < 1e-12);
        }
    }
}
