//! The ISO 21940-11 verdict of a solution (method 5.2, issue 17): the
//! residual unbalance per plane against the plane's share of `U_per`, for the
//! rotor as measured and, from the correction's uncertainty, once corrected.

use nalgebra::Matrix2;
use num_complex::Complex64;

use crate::balancing::model::Session;
use crate::balancing::solution::{IsoPlaneVerdict, Solution};
use crate::balancing::uncertainty::amplitude_95;

/// Add the per-plane and overall verdicts to `solution.iso_21940`, when it is
/// there and every corrected plane has a radius; otherwise leave it as it is.
pub fn fill(session: &Session, solution: &mut Solution) {
    let Some(iso) = solution.iso_21940.as_mut() else {
        return;
    };
    let share = iso.permissible_per_plane_gmm;
    let verdicts: Option<Vec<IsoPlaneVerdict>> = solution
        .corrections
        .iter()
        .map(|c| {
            let radius = session.planes.iter().find(|p| p.id == c.plane)?.radius_mm?;
            let residual = c.mass_g * radius;
            // The correction's error is the unbalance left once it is fitted:
            // its 95 % bound is that of |e| for e ~ N(0, covariance).
            let after = c.uncertainty.as_ref().map(|u| {
                let cov = Matrix2::from_fn(|i, j| u.covariance_g2[i][j]);
                radius * amplitude_95(Complex64::new(0.0, 0.0), &cov)
            });
            Some(IsoPlaneVerdict {
                plane: c.plane.clone(),
                residual_unbalance_gmm: residual,
                permissible_gmm: share,
                pass: residual <= share,
                after_correction_95_gmm: after,
                after_correction_pass: after.map(|a| a <= share),
            })
        })
        .collect();
    let Some(verdicts) = verdicts else {
        return;
    };
    iso.pass = Some(verdicts.iter().all(|v| v.pass));
    iso.after_correction_pass = verdicts
        .iter()
        .map(|v| v.after_correction_pass)
        .collect::<Option<Vec<bool>>>()
        .map(|all| all.iter().all(|&p| p));
    iso.planes = Some(verdicts);
}
