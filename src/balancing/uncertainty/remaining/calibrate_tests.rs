//! Tests of `calibrate`: the binned solve gives the scale of the direct sum
//! over every row and node (session 7's form) to 10⁻¹², and falls back to it
//! where the grid cannot.

use super::*;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// Session 7's solve of method 8.7, kept verbatim as the reference: Newton
/// from `f = 1` over every row and node with `0.05^(fρ)` by `exp`.
fn reference(ks: &[f64], dof: usize, shrink: f64) -> f64 {
    let s = shrink.clamp(0.0, 1.0);
    if ks.is_empty() || s >= 1.0 - 1e-9 {
        return 1.0;
    }
    let n = dof.max(1) as f64;
    let (a, c) = (1.0 - 1.0 / (9.0 * n), (1.0 / (9.0 * n)).sqrt());
    let weights: [f64; 16] = NODES.map(|z| {
        let g = (a + c * z).max(0.0).powi(3);
        let x = g * n / (1.0 - s);
        if x <= n {
            0.0
        } else {
            1.0 - n / x
        }
    });
    let ln_a = 0.05f64.ln();
    let ratio = |k: f64, w: f64| (1.0 + w * k) / (1.0 + s * k + (s - w).powi(2) * k / (1.0 - s));
    let rls: Vec<f64> = ks
        .iter()
        .flat_map(|&k| weights.map(|w| ratio(k, w) * ln_a))
        .collect();
    let count = rls.len() as f64;
    let mut f = 1.0;
    // Tighter than session 7's 10⁻⁷ stop, so the reference is the root itself.
    for _ in 0..60 {
        let (mut g, mut dg) = (0.0, 0.0);
        for &rl in &rls {
            let e = (f * rl).exp();
            g += e;
            dg += rl * e;
        }
        let step = (g / count - 0.05) / (dg / count);
        f = (f - step).max(0.0);
        if step.abs() <= 1e-15 * f {
            break;
        }
    }
    f
}

/// Jobs like the solve's and wider: sensitivities spread over up to six
/// decades (the large least-squares job's span 1.5–360), few to many rows,
/// the weight from none to nearly all residual.
fn jobs(rng: &mut StdRng) -> Vec<(Vec<f64>, usize, f64)> {
    let mut out = Vec::new();
    for &rows in &[1usize, 3, 12, 40, 400, 1280] {
        for &shrink in &[0.0, 0.02, 0.1, 0.4, 0.8, 0.97] {
            let (lo, hi) = [(-3.0, 1.0), (-1.0, 3.0), (0.0, 6.0)][rng.gen_range(0..3)];
            let ks: Vec<f64> = (0..rows)
                .map(|_| 10f64.powf(rng.gen_range(lo..hi)))
                .collect();
            let dof = (rows + rng.gen_range(0..4)).saturating_sub(2).max(1);
            out.push((ks, dof, shrink));
        }
    }
    out
}

#[test]
fn the_binned_scale_equals_the_direct_sum_over_every_row_and_node_to_1e_12() {
    let mut rng = StdRng::seed_from_u64(15);
    let (mut worst, mut by_bins, mut all) = (0.0f64, 0, 0);
    for (ks, dof, shrink) in jobs(&mut rng) {
        let ok = binned(&ks, &nodes(dof, shrink)).is_some();
        by_bins += usize::from(ok);
        all += 1;
        let (new, old) = (
            calibrated_scale(&ks, dof, shrink),
            reference(&ks, dof, shrink),
        );
        let rel = (new / old - 1.0).abs();
        assert!(
            rel <= 1e-12,
            "{} rows, dof {dof}, Ŝ {shrink}: {new} vs {old}",
            ks.len()
        );
        worst = worst.max(rel);
    }
    eprintln!("worst relative difference {worst:e}, {by_bins} of {all} binned");
    // The comparison is of the binned solve: every job takes it.
    assert_eq!(by_bins, all);
}

#[test]
fn where_the_scale_is_large_the_grid_is_refined_and_still_gives_the_direct_answer() {
    // Sensitivities nine decades apart with a small weight: ρ spans tens and
    // the root f is far above 1, so the first grid is too coarse for it.
    let wide = [1e-3, 3.0, 1e9];
    let nodes_low = nodes(3, 0.001);
    let f = binned(&wide, &nodes_low).expect("refined grid");
    assert!(f > 4.0, "{f}");
    let old = reference(&wide, 3, 0.001);
    assert!((f / old - 1.0).abs() <= 1e-12, "{f} vs {old}");
}
