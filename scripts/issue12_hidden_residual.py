#!/usr/bin/env python3
"""Issue 12, session 17: does the answer leave a plane looking trustworthy
where nearly alike planes can hide a residual? (docs/method.md §8, "Session
17"; src/balancing/uncertainty/hidden.rs.)

For each case (planes of the calibration rotor at the given nodes, or the
held-out rotor; speeds; trial effect) it solves the same noisy realisations
(2 %/2° on every reading, stated in the options) with each binary given and
prints: the ellipses' coverage per plane, the share of jobs carrying the
job-level `regions_unreliable`, and the planes under no warning at all
(neither their own `trial_effect_small` / `ill_conditioned` nor the job's):
their ellipse misses over checks. A calibrated region misses 5 % of its
checks; the excess is false precision.

Fixtures (scripts/rotor_model.py): planes at nodes 0, 3, 4 and 1, 2, 4 leave
3–5 % of the vibration uncorrected (tests/uncertainty/dependent_planes.rs's
large-residual fixtures), 0, 1, 6 and 0, 3, 6 almost none; `ho` is the
held-out rotor (nothing left uncorrected).

Not run by CI (NumPy is not a dependency). About 2 minutes per binary with
300 realisations. Usage:
  python3 scripts/issue12_hidden_residual.py [realisations] BINARY [BINARY ...]
"""
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from issue12_calibrations import solve_full
from issue12_weak_direction import K95, maha, noisy
from rotor_model import flexible, heldout_job


def cases():
    for planes in [(0, 3, 4), (1, 2, 4), (0, 1, 6), (0, 3, 6)]:
        for speeds in [[2500.0, 3000.0], [3000.0], [1500.0, 2500.0, 3500.0, 4500.0]]:
            for effect in [0.3, 1.0]:
                w, y0 = flexible(speeds, planes)
                t = np.array([effect * np.linalg.norm(y0) / np.linalg.norm(w[:, j]) for j in range(3)], complex)
                yield f"nodes {planes} {len(speeds)} sp {effect:.0%}", w, y0, t, speeds, ["S1", "S2", "S4", "S5"]
    for speeds in [[3000.0], [1500.0, 3000.0], list(np.linspace(1000, 4500, 10))]:
        for effect in [0.3, 1.0]:
            w, y0, t = heldout_job(speeds, effect)
            yield f"held-out {len(speeds)} sp {effect:.0%}", w, y0, t, speeds, ["1H", "1V", "2H", "2V"]


def main():
    args = sys.argv[1:]
    reps = int(args.pop(0)) if args and args[0].isdigit() else 300
    pool = ThreadPoolExecutor(3)
    for name, w, y0, t, speeds, sensors in cases():
        exact_c = -np.linalg.lstsq(w, y0, rcond=None)[0]
        ex = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(3)])
        y = noisy(np.random.default_rng(7), np.repeat(ex[None], reps, 0))
        out = []
        for binary in args:
            answers = list(pool.map(lambda yy: solve_full(binary, yy, t, speeds, sensors), y))
            hit = np.array([[maha(exact_c[j] - c[j], cov[j]) <= K95 for j in range(3)] for c, cov, _ in answers])
            job = np.array([any(x["code"] == "regions_unreliable" for x in warn) for _, _, warn in answers])
            own = np.array([[any(x.get("plane") == f"P{j}" for x in warn) for j in range(3)] for _, _, warn in answers])
            quiet = ~own & ~job[:, None]
            out.append(f"ellipses {np.round(hit.mean(0) * 100, 1)} unreliable {job.mean():.2f} "
                       f"unwarned misses {(~hit & quiet).sum()}/{quiet.sum()}")
        print(f"{name:24s} " + " | ".join(out), flush=True)


if __name__ == "__main__":
    main()
