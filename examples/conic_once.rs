//! One solve of a `benches/conic.rs` job, for instruction counts that do not
//! depend on the machine's load: `valgrind --tool=callgrind
//! target/release/examples/conic_once min_max 1000` (jobs: `min_max`,
//! `bounded_min_max`, `session`; rows 11 or 1000). The jobs are built as the
//! bench builds them (same seeds), and the time limit is raised so that
//! valgrind's slowness cannot end a solve.

use fieldbal::balancing::conic::{solve_cone_within, Limits};
use fieldbal::balancing::model::{Objective, Session, SolveOptions};
use fieldbal::balancing::{self};
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use rand::{rngs::StdRng, Rng, SeedableRng};
use serde_json::json;

fn polar(rng: &mut StdRng, scale: f64) -> Complex64 {
    Complex64::from_polar(
        scale * rng.gen_range(0.2..1.0),
        rng.gen_range(0.0..std::f64::consts::TAU),
    )
}

/// The bench's job: influence coefficients ~1.5 µm/g, vibration ~80 µm.
fn job(rows: usize, planes: usize) -> (DMatrix<Complex64>, DVector<Complex64>) {
    let mut rng = StdRng::seed_from_u64(rows as u64 * 31 + planes as u64);
    let a = DMatrix::from_fn(rows, planes, |_, _| polar(&mut rng, 1.5));
    let b = DVector::from_fn(rows, |_, _| polar(&mut rng, 80.0));
    (a, b)
}

/// The bench's session of the 11 × 4 job (lead / with-rotation conventions).
fn session(a: &DMatrix<Complex64>, b: &DVector<Complex64>) -> Session {
    let reading = |i: usize, y: Complex64| {
        json!({"speed_rpm": 3000, "sensor": format!("S{i}"), "amplitude": y.norm(),
               "phase_deg": y.arg().to_degrees()})
    };
    let mut runs = vec![json!({"id": "zero", "weights": [],
        "readings": (0..a.nrows()).map(|i| reading(i, b[i])).collect::<Vec<_>>()})];
    for j in 0..a.ncols() {
        runs.push(json!({"id": format!("trial {j}"),
            "weights": [{"plane": format!("P{j}"), "mass_g": 40, "angle_deg": 0}],
            "readings": (0..a.nrows()).map(|i| reading(i, b[i] + a[(i, j)] * 40.0)).collect::<Vec<_>>()}));
    }
    let s = json!({"name": "bench", "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
        "planes": (0..a.ncols()).map(|j| json!({"id": format!("P{j}")})).collect::<Vec<_>>(),
        "sensors": (0..a.nrows()).map(|i| json!({"id": format!("S{i}"), "unit": "um_pp"})).collect::<Vec<_>>(),
        "runs": runs});
    balancing::parse_session(&serde_json::to_vec(&s).unwrap()).unwrap()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map_or("min_max", String::as_str);
    let rows: usize = args
        .get(2)
        .map_or(11, |s| s.parse().expect("rows: 11 or 1000"));
    let planes = if rows == 11 { 4 } else { 16 };
    let (a, b) = job(rows, planes);
    let limits = Limits {
        max_iter: 200,
        time_limit_s: 1e4,
    };
    match which {
        "min_max" | "bounded_min_max" => {
            let bounds: Vec<Option<f64>> = if which == "min_max" {
                vec![None; planes]
            } else {
                // Half the unbounded least-squares mass, so every bound binds.
                let x = a.clone().svd(true, true).solve(&(-&b), 1e-12).unwrap();
                x.iter().map(|z| Some(0.5 * z.norm())).collect()
            };
            let s = solve_cone_within(&a, &b, Objective::MinMax, &bounds, limits).unwrap();
            println!("{} iterations, max |r| = {:.15e}", s.iterations, s.value);
        }
        "session" => {
            let s = session(&a, &b);
            let options = SolveOptions {
                objective: Some(Objective::MinMax),
                ..SolveOptions::default()
            };
            let solution = balancing::solve(&s, &options).unwrap();
            println!("{} warnings", solution.warnings.len());
        }
        other => panic!("unknown job {other}: min_max, bounded_min_max or session"),
    }
}
