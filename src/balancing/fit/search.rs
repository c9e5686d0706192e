//! The exact joint choice: a branch-and-bound over the planes (a sphere
//! decoder) that picks one candidate sum per plane to minimise the solve's
//! own objective on `r = b + A s` (method 3.1 and 3.3: `A = G W`, `b = G Y0`).
//!
//! Bound. With the thin QR `A = Q R` (Householder, never the normal
//! equations), `‖b + A s‖² = c₀ + Σᵢ |zᵢ + Σ_{j≥i} R_ij s_j|²` where `z = Qᴴb`
//! and `c₀ = ‖b − Q z‖²`. Planes are fixed from the last to the first; once
//! planes `i..` are fixed, the terms `k ≥ i` are fixed and the remaining terms
//! can all be made zero by continuous (unbounded) values of the remaining
//! planes, since `R` is triangular. So `c₀ + Σ_{k≥i}` is exactly the optimum
//! of the continuous relaxation of the remaining planes over all of ℂ, a
//! superset of their candidates: a valid lower bound (a convex QP over the
//! whole space rather than over the candidates' hull: looser, but exact and
//! free). A child of plane `i` at `s` costs `D + |R_ii|²|s − ŝᵢ|²` with
//! `ŝᵢ = −tᵢ/R_ii`, so the children that can beat the incumbent `U` lie in a
//! disc round `ŝᵢ`: only those are visited (found in the candidates sorted by
//! real part), nearest first (the continuous optimum orders the search).
//!
//! `min_max`: the largest weighted residual `g = maxₐ |rₐ|` satisfies
//! `g² ≥ ‖r‖²/m` over the `m` rows, so the same bound divided by `m` is a valid
//! bound on `g²`; leaves are scored exactly.
//!
//! Incumbent: the caller's rounding (each plane's candidate nearest to the
//! solve's continuous correction). Past the time or node limit the search
//! stops and the best found is returned with `optimal = false`.

use std::time::{Duration, Instant};

use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;

use crate::balancing::model::Objective;

/// Most child evaluations one search may make, whatever the time bound.
pub const NODE_LIMIT: u64 = 200_000_000;

/// The problem: rows × planes `a`, rows `b`, per plane its candidate sums
/// sorted by real part.
pub struct Problem<'a> {
    pub a: &'a DMatrix<Complex64>,
    pub b: &'a DVector<Complex64>,
    pub sums: Vec<Vec<Complex64>>,
    pub objective: Objective,
    pub time_limit: Duration,
    pub node_limit: u64,
}

/// The best choice found: a candidate index per plane.
#[derive(Debug, Clone, PartialEq)]
pub struct Found {
    pub choice: Vec<usize>,
    /// The objective: `‖r‖²` (least squares) or `maxₐ |rₐ|` (min-max).
    pub value: f64,
    pub optimal: bool,
    pub nodes: u64,
}

/// The objective of a choice, computed from `A` and `b` directly.
pub fn objective(p: &Problem, choice: &[usize]) -> f64 {
    let s = DVector::from_fn(choice.len(), |j, _| p.sums[j][choice[j]]);
    let r = p.b + p.a * s;
    match p.objective {
        Objective::LeastSquares => r.norm_squared(),
        Objective::MinMax => r.iter().map(|x| x.norm()).fold(0.0, f64::max),
    }
}

struct State<'p, 'a> {
    p: &'p Problem<'a>,
    r: DMatrix<Complex64>,
    z: DVector<Complex64>,
    c0: f64,
    rows: f64,
    choice: Vec<usize>,
    best: Vec<usize>,
    /// Incumbent in the bound's units: `‖r‖²`, or `m·g²` for min-max.
    limit: f64,
    best_value: f64,
    nodes: u64,
    /// Node count at which the clock and the cancellation flag are next read:
    /// `nodes` grows by a node's children at once, so it may skip any multiple.
    next_check: u64,
    start: Instant,
    stopped: bool,
    children: Vec<Vec<(f64, usize)>>,
}

impl State<'_, '_> {
    fn to_bound_units(&self, value: f64) -> f64 {
        match self.p.objective {
            Objective::LeastSquares => value,
            Objective::MinMax => self.rows * value * value,
        }
    }

    fn out_of_budget(&mut self) -> bool {
        if self.nodes > self.p.node_limit {
            self.stopped = true;
        } else if self.nodes >= self.next_check {
            self.next_check = self.nodes + 1024;
            if self.start.elapsed() > self.p.time_limit || crate::balancing::cancel::requested() {
                self.stopped = true;
            }
        }
        self.stopped
    }

    /// Fix plane `i` (and then those below it), the planes above being fixed, at partial cost `d`.
    fn descend(&mut self, i: usize, d: f64) {
        let n = self.choice.len();
        let mut t = self.z[i];
        for j in i + 1..n {
            t += self.r[(i, j)] * self.p.sums[j][self.choice[j]];
        }
        let rii = self.r[(i, i)];
        let h = rii.norm_sqr();
        let centre = if h > 0.0 {
            -t / rii
        } else {
            Complex64::new(0.0, 0.0)
        };
        let room = self.limit * (1.0 + 1e-12) - self.c0 - d;
        if room < 0.0 {
            return;
        }
        let radius = if h > 1e-300 {
            (room / h).sqrt()
        } else {
            f64::INFINITY
        };
        let sums = &self.p.sums[i];
        let lo = sums.partition_point(|s| s.re < centre.re - radius);
        let mut kids = std::mem::take(&mut self.children[i]);
        kids.clear();
        for (k, s) in sums.iter().enumerate().skip(lo) {
            if s.re > centre.re + radius {
                break;
            }
            let cost = d + (t + rii * s).norm_sqr();
            if self.c0 + cost <= self.limit * (1.0 + 1e-12) {
                kids.push((cost, k));
            }
        }
        self.nodes += kids.len() as u64 + 1;
        kids.sort_by(|a, b| a.0.total_cmp(&b.0));
        for &(cost, k) in &kids {
            if self.out_of_budget() {
                break;
            }
            // The incumbent may have improved since the children were listed.
            if self.c0 + cost > self.limit * (1.0 + 1e-12) {
                break;
            }
            self.choice[i] = k;
            if i == 0 {
                let value = objective(self.p, &self.choice);
                if value < self.best_value {
                    self.best_value = value;
                    self.best.clone_from(&self.choice);
                    self.limit = self.to_bound_units(value);
                }
            } else {
                self.descend(i - 1, cost);
            }
        }
        self.children[i] = kids;
    }
}

/// Search from the incumbent `start` (a candidate index per plane).
pub fn search(p: &Problem, start: Vec<usize>) -> Found {
    let n = p.sums.len();
    let start_value = objective(p, &start);
    if n == 0 {
        return Found {
            choice: start,
            value: start_value,
            optimal: true,
            nodes: 0,
        };
    }
    let qr = p.a.clone().qr();
    let q = qr.q();
    let r = qr.r();
    let z = q.adjoint() * p.b;
    let c0 = (p.b - &q * &z).norm_squared();
    let mut st = State {
        p,
        r,
        z,
        c0,
        rows: p.b.len().max(1) as f64,
        choice: start.clone(),
        best: start,
        limit: 0.0,
        best_value: start_value,
        nodes: 0,
        next_check: 0,
        start: Instant::now(),
        stopped: false,
        children: vec![Vec::new(); n],
    };
    st.limit = st.to_bound_units(start_value);
    st.descend(n - 1, 0.0);
    Found {
        choice: st.best,
        value: st.best_value,
        optimal: !st.stopped,
        nodes: st.nodes,
    }
}
