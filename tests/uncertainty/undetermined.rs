//! Issue 12, items 3 and 5: planes the readings cannot determine, speed points
//! that must not chain, a zero correction's angle, one reading's grammar, and
//! a mass bound binding by a hair on an ill-conditioned job.

use fieldbal::balancing::model::SolveOptions;
use fieldbal::balancing::{self, ErrorKind};
use num_complex::Complex64;

use super::{c, session, solve, Rotor, LAG_AGAINST, LEAD_WITH};

#[test]
fn a_plane_whose_trial_changed_nothing_is_reported_undetermined() {
    let rotor = Rotor::two_plane(0.8);
    let mut y = rotor.readings();
    y[2] = y[0].clone(); // plane P1's trial run reads exactly the reference
    let sol = solve(
        &session(LAG_AGAINST, &rotor.trial, &y, None),
        &SolveOptions::default(),
    );
    let u = sol.corrections[1].uncertainty.as_ref().unwrap();
    assert_eq!(u.mass_g, None);
    assert_eq!(u.angle_deg, [0.0, 360.0]);
    let w: Vec<_> = sol
        .warnings
        .iter()
        .filter(|w| w.code == "plane_undetermined")
        .collect();
    assert_eq!(w.len(), 1, "{:?}", sol.warnings);
    assert_eq!(w[0].plane.as_deref(), Some("P1"));
    assert!(w[0].message.contains("heavier"), "{}", w[0].message);
    assert!(sol.corrections[0]
        .uncertainty
        .as_ref()
        .unwrap()
        .mass_g
        .is_some());
}

#[test]
fn two_planes_the_sensors_see_identically_are_both_undetermined() {
    let mut rotor = Rotor::two_plane(0.8);
    let col = rotor.w.column(0).into_owned();
    rotor.w.set_column(1, &col);
    rotor.trial[1] = rotor.trial[0];
    let sol = solve(
        &session(LEAD_WITH, &rotor.trial, &rotor.readings(), None),
        &SolveOptions::default(),
    );
    for corr in &sol.corrections {
        let u = corr.uncertainty.as_ref().unwrap();
        assert_eq!(
            (u.mass_g, u.angle_deg),
            (None, [0.0, 360.0]),
            "{}",
            corr.plane
        );
    }
    let planes: Vec<_> = sol
        .warnings
        .iter()
        .filter(|w| w.code == "plane_undetermined")
        .filter_map(|w| w.plane.as_deref())
        .collect();
    assert_eq!(planes, ["P0", "P1"]);
}

#[test]
fn a_zero_correction_has_angle_plus_zero() {
    // Readings that need no correction: Y0 = 0 at every row.
    let rotor = Rotor::two_plane(0.8);
    let y: Vec<Vec<Complex64>> = rotor
        .readings()
        .iter()
        .map(|run| {
            run.iter()
                .zip(&rotor.readings()[0])
                .map(|(z, y0)| z - y0)
                .collect()
        })
        .collect();
    let mut y = y;
    y[0] = vec![c(0.0, 0.0); 4];
    let sol = solve(
        &session(LAG_AGAINST, &rotor.trial, &y, None),
        &SolveOptions::default(),
    );
    for corr in &sol.corrections {
        assert_eq!(corr.mass_g, 0.0);
        let json = serde_json::to_string(&corr.angle_deg).unwrap();
        assert_eq!(json, "0.0", "{}", corr.plane);
    }
}

#[test]
fn readings_more_than_one_percent_apart_are_never_paired_through_another_sensor() {
    // Reference: S0 at 1500, S1 at 1515 (one point, 1 % apart). A trial
    // reading of S0 at 1530 is within 1 % of S1's 1515 but 2 % from
    // S0's 1500: it must not be paired.
    let rotor = Rotor::two_plane(0.8);
    let mut s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    s.runs[0].readings[1].speed_rpm = 1515.0;
    s.runs[1].readings[1].speed_rpm = 1515.0;
    s.runs[2].readings[1].speed_rpm = 1515.0;
    assert!(balancing::solve(&s, &SolveOptions::default()).is_ok());
    s.runs[1].readings[0].speed_rpm = 1530.0;
    let err = balancing::solve(&s, &SolveOptions::default()).unwrap_err();
    assert_eq!(err.kind, ErrorKind::Invalid);
    assert_eq!(err.code, "unpaired_reading");
    assert_eq!(err.field.as_deref(), Some("runs[1].readings[0].speed_rpm"));
}

#[test]
fn one_selected_reading_is_one_not_one_are() {
    let rotor = Rotor::two_plane(0.8);
    let s = session(LAG_AGAINST, &rotor.trial, &rotor.readings(), None);
    let options = SolveOptions {
        sensors: Some(vec!["S0".into()]),
        speeds_rpm: Some(vec![1500.0]),
        ..SolveOptions::default()
    };
    let err = balancing::solve(&s, &options).unwrap_err();
    assert!(err.message.ends_with("1 is selected"), "{}", err.message);
}

#[test]
fn a_mass_bound_binding_by_a_hair_on_an_ill_conditioned_job_is_reported_active() {
    // Plane P1 seen almost exactly like P0 and a thousand times more weakly:
    // a badly conditioned job, where the cone solver stops short of a bound
    // by solver accuracy.
    let rotor = Rotor::two_plane(0.8);
    let mut w = rotor.w.clone();
    let col = w.column(0) * c(1e-3, 2e-4) + w.column(1) * c(2e-6, 0.0);
    w.set_column(1, &col);
    let rotor = Rotor::with_trials(w, rotor.c.clone(), rotor.y0.clone(), 0.8);
    let s = session(LEAD_WITH, &rotor.trial, &rotor.readings(), None);
    let free = solve(&s, &SolveOptions::default());
    assert!(free.warnings.iter().all(|w| w.code != "mass_limit_active"));
    for hair in [1.3e-5, 1e-4] {
        let m = free.corrections[1].mass_g * (1.0 - hair);
        let options = SolveOptions {
            max_mass_g: Some([("P1".to_string(), m)].into_iter().collect()),
            ..SolveOptions::default()
        };
        let bound = solve(&s, &options);
        assert!(bound.corrections[1].mass_g <= m, "{hair}");
        let active: Vec<_> = bound
            .warnings
            .iter()
            .filter(|w| w.code == "mass_limit_active")
            .filter_map(|w| w.plane.as_deref())
            .collect();
        assert_eq!(active, ["P1"], "{hair}: {:?}", bound.warnings);
    }
}
