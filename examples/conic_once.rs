//! One solve of a `benches/conic.rs` job, for instruction counts that do not
//! depend on the machine's load: `valgrind --tool=callgrind
//! target/release/examples/conic_once min_max 1000` (jobs: `min_max`,
//! `bounded_min_max`, `bounded_least_squares`, `session`; rows 11 or 1000). The jobs are the bench's own
//! (`benches/support/conic_jobs.rs`), and the time limit is raised so that
//! valgrind's slowness cannot end a solve.

use fieldbal::balancing::conic::{solve_cone_within, Limits};
use fieldbal::balancing::model::{Objective, SolveOptions};
use fieldbal::balancing::{self};

#[path = "../benches/support/conic_jobs.rs"]
mod conic_jobs;
use conic_jobs::{binding_bounds, job, session};

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
            let bounds = if which == "min_max" {
                vec![None; planes]
            } else {
                binding_bounds(&a, &b)
            };
            let s = solve_cone_within(&a, &b, Objective::MinMax, &bounds, limits).unwrap();
            println!("{} iterations, max |r| = {:.15e}", s.iterations, s.value);
        }
        "bounded_least_squares" => {
            let bounds = binding_bounds(&a, &b);
            let s = solve_cone_within(&a, &b, Objective::LeastSquares, &bounds, limits).unwrap();
            println!("{} iterations, ‖r‖ = {:.15e}", s.iterations, s.value);
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
        other => panic!(
            "unknown job {other}: min_max, bounded_min_max, bounded_least_squares or session"
        ),
    }
}
