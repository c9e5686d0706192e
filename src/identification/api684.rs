//! API 684's reading of a resonance on a fitted response curve: the
//! amplification factor by the half-power bandwidth and the separation margin
//! API 684 requires for it.
//!
//! - Amplification factor (API 684 SP6.8.2.1): `AF = N_c / (N2 − N1)`, `N_c`
//!   the speed of the peak, `N1 < N_c < N2` the speeds where the amplitude is
//!   `peak/√2` (half power). Here it is read off the fitted displacement
//!   response to a constant unbalance, as off a Bode plot.
//! - Required separation margin (API 684 SP6.8.2.10, as implemented in
//!   petrobras/ross `report.py`): none when `AF < 2.5`; otherwise, for a
//!   critical below the operating speed `min(16, 17·(1 − 1/(AF − 1.5)))` %,
//!   above it `min(26, 10 + 17·(1 − 1/(AF − 1.5)))` %.

/// Below this amplification factor API 684 asks for no separation margin.
pub const AF_NO_MARGIN: f64 = 2.5;

/// How the amplification factor was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Half-power bandwidth on the fitted curve (API 684).
    HalfPower,
    /// `1/(2ζ)`: the fitted curve has no peak with both half-power points
    /// (damping of roughly ζ > 0.35, where API 684 requires no margin anyway).
    DampingRatio,
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Method::HalfPower => "half_power_bandwidth",
            Method::DampingRatio => "one_over_two_zeta",
        }
    }
}

/// The amplification factor and the peak it was read at.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Amplification {
    pub factor: f64,
    /// Angular speed of the peak (1/s), when the curve has one.
    pub peak_w: Option<f64>,
    pub method: Method,
}

/// Amplitude `amp(ω)` of a one-mode response around its natural frequency `wn`
/// with damping ratio `zeta` (used when there is no half-power bandwidth).
pub fn amplification(amp: impl Fn(f64) -> f64, wn: f64, zeta: f64) -> Amplification {
    let fallback = Amplification {
        factor: 1.0 / (2.0 * zeta),
        peak_w: None,
        method: Method::DampingRatio,
    };
    // A log-spaced grid two decades either side: a one-mass response has at
    // most one peak, so the grid's maximum brackets it.
    const N: usize = 4001;
    let (lo, hi) = (wn / 100.0, wn * 100.0);
    let grid: Vec<f64> = (0..N)
        .map(|i| lo * (hi / lo).powf(i as f64 / (N - 1) as f64))
        .collect();
    let values: Vec<f64> = grid.iter().map(|&w| amp(w)).collect();
    let Some(i) = (0..N).max_by(|&a, &b| values[a].total_cmp(&values[b])) else {
        return fallback;
    };
    if i == 0 || i == N - 1 || !values[i].is_finite() {
        return fallback;
    }
    let peak_w = golden_max(&amp, grid[i - 1], grid[i + 1]);
    let level = amp(peak_w) / std::f64::consts::SQRT_2;
    let below = (0..i).rev().find(|&j| values[j] < level);
    let above = (i + 1..N).find(|&j| values[j] < level);
    match (below, above) {
        (Some(j1), Some(j2)) => {
            let w1 = bisect(&amp, level, grid[j1], grid[j1 + 1]);
            let w2 = bisect(&amp, level, grid[j2 - 1], grid[j2]);
            Amplification {
                factor: peak_w / (w2 - w1),
                peak_w: Some(peak_w),
                method: Method::HalfPower,
            }
        }
        _ => Amplification {
            peak_w: Some(peak_w),
            ..fallback
        },
    }
}

/// The maximum of a unimodal function on `[a, b]` by golden-section search.
fn golden_max(f: &impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let g = (5f64.sqrt() - 1.0) / 2.0;
    for _ in 0..200 {
        if b - a <= 1e-13 * b {
            break;
        }
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if f(c) > f(d) {
            b = d;
        } else {
            a = c;
        }
    }
    0.5 * (a + b)
}

/// Where `f` crosses `level` between `a` and `b` (one end above, one below).
fn bisect(f: &impl Fn(f64) -> f64, level: f64, mut a: f64, mut b: f64) -> f64 {
    let fa_above = f(a) > level;
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if (f(m) > level) == fa_above {
            a = m;
        } else {
            b = m;
        }
        if b - a <= 1e-14 * b {
            break;
        }
    }
    0.5 * (a + b)
}

/// Separation margin of a critical from the service speed, % of the service speed.
pub fn separation_margin_pct(critical_rpm: f64, service_rpm: f64) -> f64 {
    100.0 * (critical_rpm - service_rpm).abs() / service_rpm
}

/// The margin API 684 requires for amplification factor `af`, %.
pub fn required_margin_pct(af: f64, critical_rpm: f64, service_rpm: f64) -> f64 {
    if af < AF_NO_MARGIN {
        return 0.0;
    }
    let base = 17.0 * (1.0 - 1.0 / (af - 1.5));
    if critical_rpm < service_rpm {
        base.min(16.0)
    } else {
        (10.0 + base).min(26.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lightly_damped_oscillator_has_an_amplification_factor_near_one_over_two_zeta() {
        let (wn, zeta) = (100.0, 0.02);
        let amp = |w: f64| 1.0 / ((wn * wn - w * w).powi(2) + (2.0 * zeta * wn * w).powi(2)).sqrt();
        let a = amplification(amp, wn, zeta);
        assert_eq!(a.method, Method::HalfPower);
        assert!((a.factor - 1.0 / (2.0 * zeta)).abs() < 0.01 / (2.0 * zeta));
    }

    #[test]
    fn the_required_margin_follows_api_684() {
        assert_eq!(required_margin_pct(2.4, 900.0, 1000.0), 0.0);
        // AF = 3.5: 17·(1 − 1/2) = 8.5 % below, 18.5 % above.
        assert!((required_margin_pct(3.5, 900.0, 1000.0) - 8.5).abs() < 1e-12);
        assert!((required_margin_pct(3.5, 1100.0, 1000.0) - 18.5).abs() < 1e-12);
        assert_eq!(required_margin_pct(100.0, 900.0, 1000.0), 16.0);
        assert_eq!(required_margin_pct(100.0, 1100.0, 1000.0), 26.0);
    }
}
