//! Sessions generated from phasors in the internal frame, for the property
//! tests (`tests/solve/properties.rs`), the uncertainty tests
//! (`tests/uncertainty/main.rs`) and the criterion benches (`benches/solve.rs`),
//! which spelled the same `Session` and `Reading` out three times. Each
//! includes this file by path (`#[path = ...] mod generated;`), so the
//! library's public surface holds no test-only builder.
//!
//! Planes are `P0, P1, …`, sensors `S0, S1, …` reading µm pp.

use fieldbal::balancing::model::{Conventions, Plane, Reading, Run, Sensor, Session, Unit};
use fieldbal::balancing::phasor::reading_out;
use num_complex::Complex64;

/// The reading of sensor `S{sensor}` at `speed_rpm` of the phasor `y`
/// (internal frame), in the conventions `conv`; no samples.
pub fn reading(conv: Conventions, speed_rpm: f64, sensor: usize, y: Complex64) -> Reading {
    let (amplitude, phase_deg) = reading_out(conv, y);
    Reading {
        speed_rpm,
        sensor: format!("S{sensor}"),
        amplitude,
        phase_deg,
        samples: None,
    }
}

/// A session named `name` in the conventions `conv` of `runs`, with planes
/// `P0 … P{planes − 1}` (each of radius `radius_mm`, if given) and sensors
/// `S0 … S{sensors − 1}`.
pub fn session(
    name: String,
    conv: Conventions,
    planes: usize,
    radius_mm: Option<f64>,
    sensors: usize,
    runs: Vec<Run>,
) -> Session {
    Session {
        name,
        machine: None,
        conventions: Some(conv),
        rotor: None,
        planes: (0..planes)
            .map(|j| Plane {
                id: format!("P{j}"),
                radius_mm,
                positions: None,
                places_deg: None,
                kit: None,
            })
            .collect(),
        sensors: (0..sensors)
            .map(|k| Sensor {
                id: format!("S{k}"),
                unit: Unit::UmPp,
                label: None,
            })
            .collect(),
        runs,
        runout: None,
        trim: None,
    }
}
