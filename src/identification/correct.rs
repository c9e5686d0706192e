//! The lecture's correction of a discrete model by weighted least squares.
//!
//! Unknowns `p = (m, k)`. For each measured mode `j` (Ωⱼ, vⱼ):
//! 1. `Yⱼ k − Ωⱼ² Xⱼ m = −(K0 − Ωⱼ² M0) vⱼ`, with `Kₖ(k) vⱼ = Yⱼ k`,
//!    `Mₖ(m) vⱼ = Xⱼ m` (columns `Kᵢ vⱼ`, `Mᵢ vⱼ`);
//! 2. for mass-normalised shapes, `vᵢᵀ Xⱼ m = δᵢⱼ − vᵢᵀ M0 vⱼ` and
//! 3. `vᵢᵀ Yⱼ k = Ωⱼ² δᵢⱼ − vᵢᵀ K0 vⱼ` (i ≤ j).
//!
//! Groups 2 and 3 fix the scale when masses are estimated; when every mass is
//! known (no mass parameters) only group 1 is used, and shapes may have any
//! scale. Rows are weighted by `G` (the modes' weights) after scaling each
//! group to be dimensionless, and solved through the SVD.
//!
//! Shapes measured at some degrees of freedom only: the unmeasured entries
//! are unknowns too, and the same equations (now bilinear) are solved for
//! parameters and entries together by Gauss–Newton with a halving line
//! search, from the starting parameters and, for each mode, the entries that
//! best satisfy its equations 1 with them (a mode measured nowhere: the
//! vector they most nearly annul, mass-normalised; with every mass known it
//! gets the row `vⱼᵀ M vⱼ = 1`, as its scale is free). Until session 19 the
//! entries were taken from the current model's mode of best MAC on the
//! measured entries and the linear solve repeated: with one measured entry
//! every mode has a MAC of 1, the pick was rounding noise, and a partly
//! measured 2-mass chain answered `not_converged` from any start (or settled
//! on a wrong model).
//!
//! What the data cannot give is refused naming `modes`: fewer equations than
//! unknowns (`too_few_equations`), or equations that leave a direction of
//! parameters and entries free at the fitted model (`unidentifiable`). With
//! every mass known a shape's scale is free, so a shape measured at one
//! degree of freedom tells nothing but its frequency: such data are answered
//! when the frequencies determine the parameters, but frequencies alone may
//! fit several models (a 2-mass chain's two springs: two models), and the
//! one nearest the starting parameters is found.

use nalgebra::{DMatrix, DVector};

use super::model::{self, Checked, ModelCorrection, ModelRequest};
use super::{lsq, modes, ranges};
use crate::balancing::InputError;

/// Most least-squares solves of the iteration.
pub const MAX_ITERATIONS: usize = 200;
/// Relative change of the parameters at which the iteration stops.
pub const TOLERANCE: f64 = 1e-10;
/// Most entries of the equations' matrix (equations × unknowns): 64 MB, a
/// few times that for the SVD. The largest fully measured model the body
/// limit lets through (200 degrees of freedom, 200 modes, masses estimated,
/// 50 parameter matrices) needs about half.
pub const MAX_ENTRIES: usize = 1 << 23;
/// With shapes partly measured, the largest relative distance of a measured
/// frequency from the nearest of the corrected model's. The equations can
/// also be made small by shrinking stiffness and unmeasured entries
/// together: from a start a third of the true springs, a 2-mass chain
/// settled at 0.4 and 0.6 times its true frequencies, a minimum of the sum
/// but no fit. Measured frequencies are good to a percent or so.
pub const FREQUENCY_MATCH: f64 = 0.1;
/// Halvings of a Gauss–Newton step before the line search gives up.
const HALVINGS: usize = 60;

fn assemble(c: &Checked, p: &[f64]) -> (DMatrix<f64>, DMatrix<f64>) {
    let nm = c.mi.len();
    let mut m = c.m0.clone();
    for (a, &x) in c.mi.iter().zip(p) {
        m += a * x;
    }
    let mut k = c.k0.clone();
    for (a, &x) in c.ki.iter().zip(&p[nm..]) {
        k += a * x;
    }
    (m, k)
}

/// The problem's layout: parameters, then the unmeasured entries (mode, dof)
/// in order; the weights of the equations, fixed at the start.
struct Layout {
    n: usize,
    nm: usize,
    params: usize,
    /// Per mode, the columns of its unmeasured entries: (dof, column).
    unknown: Vec<Vec<(usize, usize)>>,
    /// Modes measured nowhere, given the row `vᵀ M v = 1` (known masses only).
    scale_rows: Vec<usize>,
    rows: usize,
    /// Group 1's weight per mode.
    s: Vec<f64>,
}

impl Layout {
    fn new(c: &Checked) -> Layout {
        let n = c.m0.nrows();
        let (nm, nk) = (c.mi.len(), c.ki.len());
        let params = nm + nk;
        let mut col = params;
        let unknown: Vec<Vec<(usize, usize)>> = c
            .shapes
            .iter()
            .map(|s| {
                (0..n)
                    .filter(|&i| s[i].is_none())
                    .map(|i| {
                        col += 1;
                        (i, col - 1)
                    })
                    .collect()
            })
            .collect();
        let modes = c.shapes.len();
        let scale_rows: Vec<usize> = if nm == 0 {
            (0..modes).filter(|&j| unknown[j].len() == n).collect()
        } else {
            vec![]
        };
        let pairs = if nm > 0 { modes * (modes + 1) } else { 0 };
        Layout {
            n,
            nm,
            params,
            rows: modes * n + pairs + scale_rows.len(),
            unknown,
            scale_rows,
            s: vec![],
        }
    }

    fn columns(&self) -> usize {
        self.params + self.unknown.iter().map(Vec::len).sum::<usize>()
    }

    fn partial(&self) -> bool {
        self.columns() > self.params
    }

    /// The shapes with the unknowns `x[params..]` in place.
    fn shapes(&self, c: &Checked, x: &[f64]) -> Vec<DVector<f64>> {
        c.shapes
            .iter()
            .zip(&self.unknown)
            .map(|(s, u)| {
                let mut v = DVector::from_iterator(self.n, s.iter().map(|e| e.unwrap_or(0.0)));
                for &(i, col) in u {
                    v[i] = x[col];
                }
                v
            })
            .collect()
    }
}

/// Each mode's unmeasured entries that best satisfy its equations 1 with the
/// parameters `p` (a mode measured nowhere: the vector `K − Ω² M` most
/// nearly annuls, scaled to `vᵀ M v = 1` where that is positive).
fn start_entries(c: &Checked, l: &Layout, p: &[f64]) -> Vec<f64> {
    let (m, k) = assemble(c, p);
    let mut out = Vec::new();
    for (j, s) in c.shapes.iter().enumerate() {
        let u = &l.unknown[j];
        if u.is_empty() {
            continue;
        }
        let a = &k - &m * c.w2[j];
        if u.len() == l.n {
            let svd = a.clone().svd(false, true);
            let v_t = svd.v_t.expect("computed");
            let last = (0..svd.singular_values.len())
                .min_by(|&x, &y| svd.singular_values[x].total_cmp(&svd.singular_values[y]))
                .unwrap_or(0);
            let v: DVector<f64> = v_t.row(last).transpose();
            let norm = v.dot(&(&m * &v));
            let scale = if norm > 0.0 { norm.sqrt() } else { 1.0 };
            out.extend(v.iter().map(|x| x / scale));
            continue;
        }
        let cols: Vec<usize> = u.iter().map(|&(i, _)| i).collect();
        let au = DMatrix::from_fn(l.n, cols.len(), |r, q| a[(r, cols[q])]);
        let known = DVector::from_iterator(l.n, s.iter().map(|e| e.unwrap_or(0.0)));
        let rhs = -(&a * known);
        let svd = au.svd(true, true);
        let tol = lsq::RANK_TOLERANCE * svd.singular_values.max();
        match svd.solve(&rhs, tol) {
            Ok(x) if x.iter().all(|v| v.is_finite()) => out.extend(x.iter()),
            _ => out.extend(std::iter::repeat_n(0.0, cols.len())),
        }
    }
    out
}

/// The weighted equations' residuals at `x` (parameters, then unmeasured
/// entries) and their Jacobian.
fn equations(c: &Checked, l: &Layout, x: &[f64]) -> (DVector<f64>, DMatrix<f64>) {
    let n = l.n;
    let nm = l.nm;
    let p = &x[..l.params];
    let (m, k) = assemble(c, p);
    let v = l.shapes(c, x);
    let mv: Vec<DVector<f64>> = v.iter().map(|vj| &m * vj).collect();
    let kv: Vec<DVector<f64>> = v.iter().map(|vj| &k * vj).collect();
    let miv: Vec<Vec<DVector<f64>>> =
        c.mi.iter()
            .map(|a| v.iter().map(|vj| a * vj).collect())
            .collect();
    let kiv: Vec<Vec<DVector<f64>>> =
        c.ki.iter()
            .map(|a| v.iter().map(|vj| a * vj).collect())
            .collect();
    let mut r = DVector::zeros(l.rows);
    let mut jac = DMatrix::zeros(l.rows, l.columns());
    let mut row = 0;
    for (j, w2) in c.w2.iter().copied().enumerate() {
        // Group 1, in units of M v Ω², made dimensionless.
        let s = l.s[j];
        for i in 0..n {
            r[row + i] = (kv[j][i] - w2 * mv[j][i]) * s;
            for (q, a) in miv.iter().enumerate() {
                jac[(row + i, q)] = -w2 * a[j][i] * s;
            }
            for (q, a) in kiv.iter().enumerate() {
                jac[(row + i, nm + q)] = a[j][i] * s;
            }
            for &(d, col) in &l.unknown[j] {
                jac[(row + i, col)] = (k[(i, d)] - w2 * m[(i, d)]) * s;
            }
        }
        row += n;
    }
    // Rows `g·f(vₐ, v_b)` of a symmetric bilinear form `f(x, y) = xᵀ F y`:
    // the parameters' columns given, the entries' from `F vₐ` and `F v_b`.
    let pair =
        |jac: &mut DMatrix<f64>, row: usize, a: usize, b: usize, g: f64, fv: &[DVector<f64>]| {
            for &(d, col) in &l.unknown[a] {
                jac[(row, col)] += g * fv[b][d];
            }
            for &(d, col) in &l.unknown[b] {
                jac[(row, col)] += g * fv[a][d];
            }
        };
    if nm > 0 {
        let modes = v.len();
        for (a, va) in v.iter().enumerate() {
            for b in a..modes {
                let g = (c.weights[a] * c.weights[b]).sqrt();
                let delta = if a == b { 1.0 } else { 0.0 };
                r[row] = (va.dot(&mv[b]) - delta) * g;
                for (q, mi) in miv.iter().enumerate() {
                    jac[(row, q)] = va.dot(&mi[b]) * g;
                }
                pair(&mut jac, row, a, b, g, &mv);
                row += 1;
                let s = g / (c.w2[a] * c.w2[b]).sqrt();
                r[row] = (va.dot(&kv[b]) - c.w2[b] * delta) * s;
                for (q, ki) in kiv.iter().enumerate() {
                    jac[(row, nm + q)] = va.dot(&ki[b]) * s;
                }
                pair(&mut jac, row, a, b, s, &kv);
                row += 1;
            }
        }
    }
    for &j in &l.scale_rows {
        let g = c.weights[j];
        r[row] = (v[j].dot(&mv[j]) - 1.0) * g;
        pair(&mut jac, row, j, j, g, &mv);
        row += 1;
    }
    (r, jac)
}

/// The request ended (time limit, client gone): nobody waits for the answer.
fn cancelled() -> InputError {
    InputError::unsolvable("cancelled", "the request ended before the fit")
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum::<f64>().sqrt()
}

fn unidentifiable(l: &Layout) -> InputError {
    let (entries, start) = if l.partial() {
        (
            " and the unmeasured shape entries",
            ", or start nearer the true parameters",
        )
    } else {
        ("", "")
    };
    InputError::invalid(
        "unidentifiable",
        "modes",
        format!("the measured modes cannot tell the parameters{entries} apart (the equations are dependent at the fitted model); measure more modes, or more entries of their shapes (with every mass known, a shape measured at one degree of freedom gives only its frequency){start}"),
    )
}

/// Gauss–Newton over parameters and unmeasured entries from `x`; the solution,
/// the solves made and the residual RMS.
fn iterate(c: &Checked, l: &Layout, mut x: Vec<f64>) -> Result<(Vec<f64>, usize, f64), InputError> {
    let what = "the model-correction equations";
    let (mut r, mut jac) = equations(c, l, &x);
    let mut iterations = 0;
    loop {
        if crate::balancing::cancel::requested() {
            return Err(cancelled());
        }
        iterations += 1;
        let (step, _) = lsq::step(&jac, &r, what)?;
        // Settled when the full step is small, whatever the line search takes.
        let (change, size) = (norm(&step.as_slice()[..l.params]), norm(&x[..l.params]));
        let settled = change <= TOLERANCE * (1.0 + size);
        let before = r.norm_squared();
        let mut t = 1.0;
        let mut accepted = None;
        for _ in 0..HALVINGS {
            if crate::balancing::cancel::requested() {
                return Err(cancelled());
            }
            let next: Vec<f64> = x.iter().zip(step.iter()).map(|(a, d)| a + t * d).collect();
            let (rn, jn) = equations(c, l, &next);
            if rn.norm_squared() <= before {
                accepted = Some((next, rn, jn));
                break;
            }
            t *= 0.5;
        }
        // No decrease along the step: a minimum, to rounding.
        let Some((next, rn, jn)) = accepted else {
            break;
        };
        x = next;
        r = rn;
        jac = jn;
        if settled {
            break;
        }
        if iterations >= MAX_ITERATIONS {
            return Err(InputError::unsolvable(
                "not_converged",
                format!("the parameters did not settle in {MAX_ITERATIONS} iterations (last change {change:.3e}); measure more degrees of freedom or give better initial values"),
            ));
        }
    }
    let (_, full) = lsq::step(&jac, &r, what)?;
    if !full {
        return Err(unidentifiable(l));
    }
    Ok((x, iterations, lsq::rms(r.iter().copied())))
}

/// The mean mass group 1 is divided by: of `M` at the start `p`, or, where
/// that is below the lightest accepted mass, of `M0` and the patterns `Mᵢ`
/// together (1 if they are all zero on the diagonal). A start of zero
/// masses divided by the smallest positive number: weights near 1e305,
/// column norms that overflowed, and a well-posed request refused as
/// `unidentifiable` (session 19).
fn mass_scale(c: &Checked, p: &[f64]) -> f64 {
    let n = c.m0.nrows() as f64;
    let (m, _) = assemble(c, p);
    let at_start = (m.trace() / n).abs();
    if at_start >= ranges::MASS.0 {
        return at_start;
    }
    let patterns = std::iter::once(&c.m0)
        .chain(&c.mi)
        .map(|a| a.diagonal().abs().sum())
        .sum::<f64>()
        / n;
    if patterns > 0.0 {
        patterns
    } else {
        1.0
    }
}

/// Correct the model: estimate its parameters from the measured modes.
pub fn correct(req: &ModelRequest) -> Result<ModelCorrection, InputError> {
    let c = model::check(req)?;
    let mut l = Layout::new(&c);
    let unknowns = l.columns();
    if l.rows < unknowns {
        let entries = unknowns - l.params;
        return Err(InputError::invalid(
            "too_few_equations",
            "modes",
            format!(
                "{} parameters and {entries} unmeasured shape entries are unknown, but the {} measured modes give only {} equations; measure more modes, or more entries of their shapes",
                l.params,
                c.shapes.len(),
                l.rows
            ),
        ));
    }
    if l.rows.saturating_mul(unknowns) > MAX_ENTRIES {
        return Err(InputError::invalid(
            "too_large",
            "modes",
            format!(
                "{} equations in {unknowns} unknowns (parameters and unmeasured shape entries) exceed the {MAX_ENTRIES} entries a correction may use; give fewer modes or measure more entries",
                l.rows
            ),
        ));
    }
    let mut x = c.initial.clone();
    x.extend(start_entries(&c, &l, &c.initial));
    // Group 1's weights, fixed at the start so that every step minimises
    // the same sum: `G / (Ω² · mean mass · |v|)`, |v| over the measured
    // entries (the whole start where none is measured).
    let mass_scale = mass_scale(&c, &c.initial);
    let start = l.shapes(&c, &x);
    l.s = (0..c.shapes.len())
        .map(|j| {
            let measured = c.shapes[j]
                .iter()
                .flatten()
                .map(|e| e * e)
                .sum::<f64>()
                .sqrt();
            let size = if measured > 0.0 {
                measured
            } else {
                start[j].norm()
            };
            c.weights[j] / (c.w2[j] * mass_scale * size.max(f64::MIN_POSITIVE))
        })
        .collect();
    let (p, iterations, residual) = if l.partial() {
        // A start that never settles is the request's to change: the error
        // names `initial` where the request gave one (it named no field, a
        // 4xx a client could not point at), else the modes it fitted.
        let (x, iterations, residual) = iterate(&c, &l, x).map_err(|mut e| {
            if e.code == "not_converged" && e.field.is_none() {
                e.field = Some(
                    if req.initial.is_some() {
                        "initial"
                    } else {
                        "modes"
                    }
                    .into(),
                );
            }
            e
        })?;
        (x[..l.params].to_vec(), iterations, residual)
    } else {
        // Linear: one solve from zero gives the least-squares parameters.
        let zero = vec![0.0; l.params];
        let (r, a) = equations(&c, &l, &zero);
        let b = -r;
        let p = lsq::solve(a.clone(), &b, "the model-correction equations").map_err(|e| match e
            .code
        {
            "unidentifiable" => unidentifiable(&l),
            _ => e,
        })?;
        let residual = lsq::rms((&a * &p - &b).iter().copied());
        (p.iter().copied().collect(), 1, residual)
    };
    let (m, k) = assemble(&c, &p);
    // A matrix entry of 1e300 passed the solve and overflowed the parameters
    // and the residual, answered as null (fuzzing, session 15); in-range
    // entries no longer do, and this stays as a backstop.
    if !(residual.is_finite() && p.iter().all(|x| x.is_finite())) {
        return Err(InputError::unsolvable(
            "not_finite",
            "the model-correction equations: a result overflows (matrix entries of very different orders of magnitude?)",
        ));
    }
    // Masses of 1e-9 and 1e9 kg side by side answered 0 Hz and 6.9e9 Hz
    // (ranges' module doc): refused naming what gave them.
    let freqs = ranges::frequencies(
        &modes::solve(&m, &k)?.w2,
        "mass and stiffness (with the estimated parameters)",
    )?;
    if l.partial() {
        for (j, mode) in req.modes.iter().enumerate() {
            let f = mode.frequency_hz;
            let nearest = freqs
                .iter()
                .copied()
                .min_by(|a, b| (a - f).abs().total_cmp(&(b - f).abs()))
                .unwrap_or(f64::NAN);
            let off = (nearest - f).abs();
            if off.is_nan() || off > FREQUENCY_MATCH * f {
                return Err(InputError::invalid(
                    "not_converged",
                    format!("modes[{j}].frequency_hz"),
                    format!("the fit settled on a model whose nearest frequency is {nearest:.4} Hz, not the measured {f} Hz (more than {:.0} % off): a minimum of the equations that fits nothing; give starting parameters nearer the true ones, or measure more entries of the shapes", 100.0 * FREQUENCY_MATCH),
                ));
            }
        }
    }
    let nm = c.mi.len();
    Ok(ModelCorrection {
        mass_parameters: p[..nm].to_vec(),
        stiffness_parameters: p[nm..].to_vec(),
        frequencies_hz: freqs,
        iterations,
        residual,
    })
}
