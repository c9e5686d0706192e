#!/usr/bin/env python3
"""Issue 12, session 17: how far the shipped ellipses are from 95 % per plane,
against the true second-order size `κ_j` of each plane, and three ways of
calibrating them that were measured and not kept (docs/method.md §8,
"Session 17").

For each case (rotor, speeds, trial effect) it prints, over noisy
realisations (2 %/2° on every reading, stated in the options), per plane:

- the share of `fieldbal solve`'s ellipses (covariance_g2, χ²₂ 5.991) holding
  the exact least-squares correction;
- the factor its covariance would need to hold 95 % (95th percentile of the
  Mahalanobis² over 5.991);
- the true `κ_j = M_jj [(WᴴW)⁻¹]_jj` of method (8.4), from the exact
  influence matrix and the noise model (no realisation involved).

With `--prepivot B` also Beran's prepivoting (1987, Biometrika 74): each
answer's ellipse scaled by the 95th percentile of its own pivot over `B`
resamples of the observed readings (each resample solved by the binary), and
with `--kwiden` the ellipse widened along 16 rays, from its boundary outward
(up to 3 times), to the farthest point that Kleibergen's per-plane K
statistic (scripts/issue12_weak_direction.py, other planes profiled along the
least-squares path) does not reject at 95 %.

Rotors: `cal` the calibration rotor (scripts/rotor_model.py `flexible`,
planes at nodes 0, 3, 6, sensors at 1, 2, 4, 5), `ho` the held-out rotor
(`heldout_job`). Case names: rotor, number of speeds, trial effect in %
(`cal4_30`: four speeds 1500–4500 rpm, 30 % trials). Ten speeds are
1200–5700 rpm for `cal` (tests/uncertainty/eiv.rs's) and 1000–5500 rpm for
`ho` (scripts/coverage_heldout.py uses 1000–4500).

Not run by CI (NumPy is not a dependency). About 25 s for the default cases
with 400 realisations; `--prepivot 100` with 60 realisations about 20 s a case.
Usage:
  python3 scripts/issue12_calibrations.py target/release/fieldbal [realisations]
      [--prepivot B] [--kwiden] [case ...]
"""
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from issue12_weak_direction import K95, k_plane, maha, noisy, plain_ls, reading_cov
from rotor_model import flexible, heldout_job

SPEEDS = {
    ("cal", 1): [3000.0], ("cal", 2): [1500.0, 3000.0], ("cal", 3): [1500.0, 3000.0, 4500.0],
    ("cal", 4): [1500.0, 2500.0, 3500.0, 4500.0], ("cal", 10): [1200.0 + 500 * i for i in range(10)],
    ("ho", 1): [3000.0], ("ho", 2): [1500.0, 3000.0], ("ho", 4): [1000.0, 2166.7, 3333.3, 4500.0],
    ("ho", 10): [1000.0 + 500 * i for i in range(10)],
}
DEFAULT = ["cal1_10", "cal1_30", "cal1_100", "cal2_20", "cal2_30", "cal3_20", "cal4_10", "cal4_20", "cal4_30",
           "cal4_50", "cal4_100", "cal10_10", "cal10_30", "cal10_100", "ho1_30", "ho2_30", "ho4_20", "ho10_10",
           "ho10_30"]
S_GRID = np.array([1.0, 1.1, 1.2, 1.35, 1.5, 1.75, 2.0, 2.5, 3.0])


def job(name):
    rotor, rest = name[:-len(name.lstrip("calho"))], name.lstrip("calho")
    n, effect = rest.split("_")
    speeds = SPEEDS[(rotor, int(n))]
    effect = int(effect) / 100
    if rotor == "cal":
        w, y0 = flexible(speeds, (0, 3, 6))
        t = np.array([effect * np.linalg.norm(y0) / np.linalg.norm(w[:, j]) for j in range(3)], complex)
        return w, y0, t, speeds, ["S1", "S2", "S4", "S5"]
    w, y0, t = heldout_job(speeds, effect)
    return w, y0, t, speeds, ["1H", "1V", "2H", "2V"]


def true_kappa(w, y0, t):
    """κ_j of (8.4) at the exact readings: circular noise of 2 %/2° on each."""
    ex = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(3)])
    var = np.abs(ex) ** 2 * (0.02 ** 2 + np.radians(2.0) ** 2)
    m = np.array([np.sum(var[j + 1] + var[0]) / abs(t[j]) ** 2 for j in range(3)])
    return m * np.real(np.diag(np.linalg.inv(w.conj().T @ w)))


def solve(binary, y, t, speeds, sensors):
    """The answer's corrections and per-plane covariances for readings y (runs × rows)."""
    c, cov, _ = solve_full(binary, y, t, speeds, sensors)
    return c, cov


def solve_full(binary, y, t, speeds, sensors):
    """`solve`, and the answer's warnings."""
    c, cov, sol = solve_answer(binary, y, t, speeds, sensors)
    return c, cov, sol.get("warnings", [])


def solve_answer(binary, y, t, speeds, sensors):
    """`solve`: the corrections, their covariances, and the whole answer."""
    ns = len(sensors)
    runs = [{"id": f"R{k}", "readings": [
        {"amplitude": float(abs(y[k, a])), "phase_deg": float(np.degrees(np.angle(y[k, a])) % 360),
         "speed_rpm": float(speeds[a // ns]), "sensor": sensors[a % ns]} for a in range(y.shape[1])],
        "weights": [] if k == 0 else [{"plane": f"P{k - 1}", "mass_g": float(abs(t[k - 1])),
                                       "angle_deg": float(np.degrees(np.angle(t[k - 1])) % 360)}]}
        for k in range(y.shape[0])]
    session = {"name": "calibrations", "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
               "planes": [{"id": f"P{j}"} for j in range(len(t))],
               "sensors": [{"id": s, "unit": "um_pp"} for s in sensors], "runs": runs}
    body = {"session": session, "options": {"amplitude_noise_pct": 2.0, "phase_noise_deg": 2.0}}
    out = subprocess.run([binary, "solve", "-"], input=json.dumps(body).encode(), capture_output=True, check=True)
    sol = json.loads(out.stdout)
    c = np.array([x["mass_g"] * np.exp(1j * np.radians(x["angle_deg"])) for x in sol["corrections"]])
    return c, np.array([x["uncertainty"]["covariance_g2"] for x in sol["corrections"]]), sol


def kwiden(y, t, c, cov, ndir=16):
    """Per realisation and plane, the factor on the covariance that reaches the farthest
    point (contiguous from the boundary) K does not reject along ndir rays."""
    r = len(y)
    s = reading_cov(y)
    w, chat = plain_ls(y, t)
    u = np.stack([np.cos(np.linspace(0, 2 * np.pi, ndir, endpoint=False)),
                  np.sin(np.linspace(0, 2 * np.pi, ndir, endpoint=False))], -1)
    g = ndir * len(S_GRID)
    rep = lambda x: np.repeat(x, g, 0)
    f = np.zeros((r, 3))
    for j in range(3):
        chol = np.linalg.cholesky(cov[:, j] * K95)
        off = np.einsum("nij,dj->ndi", chol, u)[:, :, None, :] * S_GRID[None, None, :, None]
        cand = (c[:, j, None, None] + off[..., 0] + 1j * off[..., 1]).reshape(-1)
        st, _, _ = k_plane(rep(y), t, rep(w), rep(chat), rep(s), j, cand)
        run = np.cumprod((st <= K95).reshape(r, ndir, len(S_GRID)), axis=2)
        far = np.where(run.any(2), S_GRID[np.maximum(run.sum(2) - 1, 0)], 1.0)
        f[:, j] = far.max(1) ** 2
    return f


def main():
    args = sys.argv[1:]
    binary = args.pop(0)
    reps = int(args.pop(0)) if args and args[0].isdigit() else 400
    boot = 0
    if "--prepivot" in args:
        i = args.index("--prepivot"); boot = int(args[i + 1]); del args[i:i + 2]
    widen = "--kwiden" in args
    args = [a for a in args if a != "--kwiden"] or DEFAULT
    pool = ThreadPoolExecutor(3)
    for name in args:
        w, y0, t, speeds, sensors = job(name)
        rng = np.random.default_rng(11 + sum(map(ord, name)))
        exact_c = -np.linalg.lstsq(w, y0, rcond=None)[0]
        ex = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(3)])
        y = noisy(rng, np.repeat(ex[None], reps, 0))
        answers = list(pool.map(lambda yy: solve(binary, yy, t, speeds, sensors), y))
        c = np.array([a[0] for a in answers]); cov = np.array([a[1] for a in answers])
        m2 = np.array([[maha(exact_c[j] - c[n, j], cov[n, j]) for j in range(3)] for n in range(reps)])
        line = (f"{name:9s} ellipses {np.round((m2 <= K95).mean(0) * 100, 1)} factor for 95 % "
                f"{np.round(np.quantile(m2, 0.95, axis=0) / K95, 2)} true kappa {np.round(true_kappa(w, y0, t), 3)}")
        if boot:
            f = np.zeros((reps, 3))
            for n in range(reps):
                ys = noisy(rng, np.repeat(y[n][None], boot, 0))
                outs = list(pool.map(lambda yy: solve(binary, yy, t, speeds, sensors), ys))
                piv = np.array([[maha(o[0][j] - c[n, j], o[1][j]) for j in range(3)] for o in outs])
                f[n] = np.quantile(piv, 0.95, axis=0) / K95
            line += f" | prepivoted {np.round((m2 <= K95 * f).mean(0) * 100, 1)} median scale {np.round(np.median(f, 0), 2)}"
        if widen:
            f = kwiden(y, t, c, cov)
            line += (f" | K-widened {np.round((m2 <= K95 * f).mean(0) * 100, 1)} median scale "
                     f"{np.round(np.median(f, 0), 2)} at 3x {np.round((f >= 9).mean(0), 2)}")
        print(line, flush=True)


if __name__ == "__main__":
    main()
