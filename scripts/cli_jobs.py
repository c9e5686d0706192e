"""Noisy balancing jobs for `fieldbal solve -`, shared by the NumPy prototypes
that measure fieldbal from outside (scripts/coverage_heldout.py,
scripts/issue12_remaining_vibration.py). Not run by CI (NumPy is not a
dependency).

- `noisy_session(rng, exact, trials, speeds, sensors, samples, pct, deg)`: a
  session (contract v1 JSON, phase lead, angles with rotation) whose run 0 is
  the reference and run j + 1 carries the complex trial mass `trials[j]` in
  plane Pj; `exact` holds the noise-free readings, rows speed-major (sensor
  within speed) by runs. Each reading gets radial noise `pct` % and phase
  noise `deg`°, or with `samples` six such samples and their mean;
- `solve(binary, session, options)`: the CLI's answer as JSON, and the
  corrections as complex masses (g, angle in the session's convention).
"""
import json
import subprocess

import numpy as np


def _reading(rng, v, pct, deg, samples):
    def one():
        return abs(v) * (1 + pct / 100 * rng.standard_normal()), np.degrees(np.angle(v)) + deg * rng.standard_normal()
    if not samples:
        amp, ph = one()
        return {"amplitude": amp, "phase_deg": ph % 360}
    ss = [one() for _ in range(6)]
    z = np.mean([a * np.exp(1j * np.radians(p)) for a, p in ss])
    return {"amplitude": abs(z), "phase_deg": np.degrees(np.angle(z)) % 360,
            "samples": [{"amplitude": a, "phase_deg": p % 360} for a, p in ss]}


def noisy_session(rng, exact, trials, speeds, sensors, samples=False, pct=2.0, deg=2.0):
    ns = len(sensors)
    runs = []
    for i in range(exact.shape[1]):
        readings = []
        for a, v in enumerate(exact[:, i]):
            rd = _reading(rng, v, pct, deg, samples)
            rd.update({"speed_rpm": float(speeds[a // ns]), "sensor": sensors[a % ns]})
            readings.append(rd)
        weights = [] if i == 0 else [{"plane": "P%d" % (i - 1), "mass_g": abs(trials[i - 1]),
                                      "angle_deg": np.degrees(np.angle(trials[i - 1])) % 360}]
        runs.append({"id": "R%d" % i, "weights": weights, "readings": readings})
    return {"name": "outside", "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
            "planes": [{"id": "P%d" % j} for j in range(len(trials))],
            "sensors": [{"id": s, "unit": "um_pp"} for s in sensors], "runs": runs}


def solve(binary, session, options):
    out = subprocess.run([binary, "solve", "-"], input=json.dumps({"session": session, "options": options}).encode(),
                         capture_output=True)
    sol = json.loads(out.stdout)
    if "corrections" not in sol:
        return sol, None
    return sol, np.array([c["mass_g"] * np.exp(1j * np.radians(c["angle_deg"])) for c in sol["corrections"]])
