#!/usr/bin/env python3
"""Issue 12, session 18 (amp18): `amplitude_95` row by row on one ten-speed
job of the calibration rotor (docs/method.md §8, "All rows at once",
session 18, amp18).

The job: scripts/rotor_model.py `flexible` at ten speeds (1200-5700 rpm),
sensors at nodes 1, 2, 4, 5, planes at the nodes given, trial effects of the
given share of the vibration, 2 %/2 deg noise on every reading, stated in
the options. Each realisation is solved by `fieldbal solve -`; the vibration
that really remains at row a is |Y0_a + W_a C_hat| (exact W).

It prints the share of all rows' bounds that hold, then per row: the exact
least-squares residual |r|, the Monte Carlo sd of the prediction about it
(sdv, about sqrt(tr Sigma_v)) and of the remaining vibration about it (sdu,
about sqrt(tr Sigma_u)), |r| in units of each, the median bound over |r|,
and the share of the row's bounds that hold. On planes at nodes 1, 4, 6 with
100 % trials (session 18, main at a99dd9e, 400 realisations): 90.7 % over
all rows; the exact residual is at most 1.5 sdv at every row (so no row's
own statistic |R_hat|^2 / tr Sigma_v can single it out), and the rows that
under-cover (50-85 %) are those with |r| over about 1.1 sdu, mostly sensor
S1 (node 1) at every speed.

RESIDUAL_SCALE (default 1) multiplies the exact residual of the reference
readings (Y0 = P Y0 + s (I - P) Y0).

Not run by CI (NumPy is not a dependency). A few seconds for 400
realisations. Usage (from scripts/):
  python3 issue12_amp_rows.py BINARY REALISATIONS PLANES EFFECT [RESIDUAL_SCALE]
e.g. python3 issue12_amp_rows.py ../target/release/fieldbal 400 1,4,6 1.0
"""
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from issue12_calibrations import solve_answer
from issue12_weak_direction import noisy
from rotor_model import flexible

SPEEDS = [1200.0 + 500 * i for i in range(10)]
SENSORS = ["S1", "S2", "S4", "S5"]


def main():
    binary, reps = sys.argv[1], int(sys.argv[2])
    planes = tuple(map(int, sys.argv[3].split(",")))
    eff = float(sys.argv[4])
    scale = float(sys.argv[5]) if len(sys.argv) > 5 else 1.0
    w, y0 = flexible(SPEEDS, planes)
    p = w @ np.linalg.lstsq(w, y0, rcond=None)[0]
    y0 = p + scale * (y0 - p)
    t = np.array([eff * np.linalg.norm(y0) / np.linalg.norm(w[:, j]) for j in range(3)], complex)
    r = y0 + w @ (-np.linalg.lstsq(w, y0, rcond=None)[0])
    ex = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(3)])
    y = noisy(np.random.default_rng(1), np.repeat(ex[None], reps, 0))
    answers = list(ThreadPoolExecutor(3).map(lambda yy: solve_answer(binary, yy, t, SPEEDS, SENSORS), y))
    remains = np.array([y0 + w @ c for c, _, _ in answers])
    bound = np.array([[pr["amplitude_95"] for pr in sol["predicted_residual"]] for _, _, sol in answers])
    r_hat = np.array([[pr["amplitude"] * np.exp(1j * np.radians(pr["phase_deg"]))
                       for pr in sol["predicted_residual"]] for _, _, sol in answers])
    held = np.abs(remains) <= bound
    sdv = np.sqrt(np.mean(np.abs(r_hat - r) ** 2, 0))
    sdu = np.sqrt(np.mean(np.abs(remains - r) ** 2, 0))
    print(f"all rows {held.mean() * 100:.1f} %")
    for a in range(len(y0)):
        print(f"row {a:2d} {SPEEDS[a // 4]:6.0f} {SENSORS[a % 4]} |r| {abs(r[a]):.2e} sdv {sdv[a]:.2e} "
              f"sdu {sdu[a]:.2e} |r|/sdv {abs(r[a]) / sdv[a]:5.2f} |r|/sdu {abs(r[a]) / sdu[a]:5.2f} "
              f"bound/|r| {np.median(bound[:, a]) / max(abs(r[a]), 1e-300):7.2f} held {held[:, a].mean() * 100:5.1f}")


if __name__ == "__main__":
    main()
