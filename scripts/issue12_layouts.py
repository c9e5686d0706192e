#!/usr/bin/env python3
"""Issue 12, session 18: the ellipses per plane on five plane layouts, and
where they hold with no warning (docs/method.md §8, "Session 18").

Earlier calibrations measured one layout of the calibration rotor (planes at
nodes 0, 3, 6) and the held-out rotor. This sweep adds three more layouts of
the calibration rotor (scripts/rotor_model.py `flexible`, sensors at nodes 1,
2, 4, 5): planes at nodes 1, 3, 5 / 0, 2, 6 / 1, 4, 6, each at one, two, four
and ten speeds (3000; 1500, 3000; 1500–4500 in four; 1200–5700 in ten rpm),
with trial effects of 10, 20, 30, 50 and 100 % of the vibration, and the
held-out rotor (`heldout_job`, ten speeds 1000–5500 rpm) at the same speed
counts. Noise 2 %/2° on every reading, stated in the options.

For each case and binary it prints per plane the share of `fieldbal solve`'s
ellipses (covariance_g2, χ²₂ 5.991) holding the exact least-squares
correction, the factor their covariance would need for 95 %, the true `κ_j`
of (8.4) and the plane's own share (Darlow's factor from the exact influence
matrix), then the share of `amplitude_95` bounds holding the vibration that
really remains (`|Y0 + W Ĉ|` per row, exact `W`), the share of jobs flagged
`regions_unreliable` and the coverage
of the planes with no warning at all (neither their own nor the job's). A
last line per binary sums the 300 plane-cases: how many lie in 93–97 %,
under 93 and 90 %, over 97 and 98.5 %, the mean distance from the window,
and the unwarned misses over the unwarned checks, and the range of the
cases' `amplitude_95` coverage.

Not run by CI (NumPy is not a dependency). About 60 s a binary with 200
realisations on an idle 2-core machine. Usage:
  python3 scripts/issue12_layouts.py REALISATIONS BINARY [BINARY ...]
e.g. python3 scripts/issue12_layouts.py 200 /tmp/old/fieldbal target/release/fieldbal
"""
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from issue12_calibrations import solve_answer, true_kappa
from issue12_weak_direction import K95, maha, noisy
from rotor_model import flexible, heldout_job

SPEEDS = {1: [3000.0], 2: [1500.0, 3000.0], 4: [1500.0, 2500.0, 3500.0, 4500.0],
          10: [1200.0 + 500 * i for i in range(10)]}
HELD_OUT_TEN = [1000.0 + 500 * i for i in range(10)]
LAYOUTS = [(0, 3, 6), (1, 3, 5), (0, 2, 6), (1, 4, 6), None]
EFFECTS = [0.1, 0.2, 0.3, 0.5, 1.0]


def cases():
    for planes in LAYOUTS:
        for ns in SPEEDS:
            for eff in EFFECTS:
                if planes is None:
                    speeds = HELD_OUT_TEN if ns == 10 else SPEEDS[ns]
                    w, y0, t = heldout_job(speeds, eff)
                    yield "held-out", ns, eff, w, y0, t, speeds, ["1H", "1V", "2H", "2V"], 99
                else:
                    speeds = SPEEDS[ns]
                    w, y0 = flexible(speeds, planes)
                    t = np.array([eff * np.linalg.norm(y0) / np.linalg.norm(w[:, j]) for j in range(3)], complex)
                    yield f"nodes {planes}", ns, eff, w, y0, t, speeds, ["S1", "S2", "S4", "S5"], sum(planes)


def own_share(w):
    """Darlow's significance factor per plane: the part of its column outside the others' span."""
    g = np.real(np.diag(np.linalg.inv(w.conj().T @ w)))
    return np.sqrt(1 / (g * np.linalg.norm(w, axis=0) ** 2))


def main():
    reps = int(sys.argv[1])
    binaries = sys.argv[2:]
    pool = ThreadPoolExecutor(3)
    totals = {b: [] for b in binaries}
    quiet_totals = {b: [0, 0] for b in binaries}
    amp_totals = {b: [] for b in binaries}
    for name, ns, eff, w, y0, t, speeds, sensors, salt in cases():
        exact_c = -np.linalg.lstsq(w, y0, rcond=None)[0]
        ex = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(3)])
        rng = np.random.default_rng(5 + ns * 7 + int(eff * 100) + salt)
        y = noisy(rng, np.repeat(ex[None], reps, 0))
        head = (f"{name:16s} {ns:2d} sp {eff:4.0%} kappa {np.round(true_kappa(w, y0, t), 2)} "
                f"share {np.round(own_share(w), 2)}")
        print(head, flush=True)
        for binary in binaries:
            answers = list(pool.map(lambda yy: solve_answer(binary, yy, t, speeds, sensors), y))
            amp = np.mean([[abs(y0[a] + w[a] @ c) <= pr["amplitude_95"] for a, pr in enumerate(sol["predicted_residual"])]
                           for c, _, sol in answers])
            amp_totals[binary].append(amp * 100)
            answers = [(c, cov, sol.get("warnings", [])) for c, cov, sol in answers]
            m2 = np.array([[maha(exact_c[j] - c[j], cov[j]) for j in range(3)] for c, cov, _ in answers])
            hit = m2 <= K95
            job = np.array([any(x["code"] == "regions_unreliable" for x in warn) for _, _, warn in answers])
            own = np.array([[any(x.get("plane") == f"P{j}" for x in warn) for j in range(3)]
                            for _, _, warn in answers])
            quiet = ~own & ~job[:, None]
            cov95 = hit.mean(0) * 100
            totals[binary].extend(cov95)
            quiet_totals[binary][0] += (~hit & quiet).sum()
            quiet_totals[binary][1] += quiet.sum()
            qcov = (hit & quiet).sum(0) / np.maximum(quiet.sum(0), 1) * 100
            print(f"    ellipses {np.round(cov95, 1)} factor {np.round(np.quantile(m2, 0.95, axis=0) / K95, 2)} "
                  f"amplitude_95 {amp_totals[binary][-1]:.1f} unreliable {job.mean():.2f} unwarned {quiet.sum(0)} holding {np.round(qcov, 1)}", flush=True)
    for binary in binaries:
        c = np.array(totals[binary])
        dev = np.mean(np.maximum(93 - c, 0) + np.maximum(c - 97, 0))
        miss, n = quiet_totals[binary]
        amp = np.array(amp_totals[binary])
        print(f"{binary}: {len(c)} plane-cases, in 93-97 % {np.sum((c >= 93) & (c <= 97))}, under 93 {np.sum(c < 93)}, "
              f"under 90 {np.sum(c < 90)}, over 97 {np.sum(c > 97)}, over 98.5 {np.sum(c > 98.5)}, "
              f"mean distance from the window {dev:.2f} points, unwarned misses {miss}/{n} ({miss / max(n, 1):.1%}); "
              f"amplitude_95 per case {amp.min():.1f}-{amp.max():.1f} %, {np.sum((amp >= 93) & (amp <= 97))} of {len(amp)} "
              f"cases in 93-97 %, under 93 {np.sum(amp < 93)}, over 97 {np.sum(amp > 97)}")


if __name__ == "__main__":
    main()
