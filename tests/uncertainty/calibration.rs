//! The calibration test: 95 % regions hold the exact correction in
//! 93–97 % of noisy realisations, for a well-sized and for a small trial.

use super::{coverage, Rotor, LAG_AGAINST};

// 2000 realisations: the binomial sd of a 95 % coverage is 0.49 %, so the
// window 93–97 % is ±4 sd around a calibrated 95 %.
const REALISATIONS: usize = 2000;

#[test]
fn the_95_percent_regions_hold_the_exact_correction_in_95_percent_of_realisations_with_a_well_sized_trial(
) {
    let cov = coverage(&Rotor::two_plane(1.0), LAG_AGAINST, REALISATIONS, 1);
    eprintln!("well-sized trial coverage {cov:?}");
    assert!(cov.iter().all(|&p| (0.93..=0.97).contains(&p)), "{cov:?}");
}

#[test]
fn the_95_percent_regions_hold_the_exact_correction_in_95_percent_of_realisations_with_a_small_trial(
) {
    let cov = coverage(&Rotor::two_plane(0.3), LAG_AGAINST, REALISATIONS, 2);
    eprintln!("small trial coverage {cov:?}");
    assert!(cov.iter().all(|&p| (0.93..=0.97).contains(&p)), "{cov:?}");
}
