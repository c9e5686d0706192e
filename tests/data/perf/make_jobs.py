#!/usr/bin/env python3
"""Write the random jobs of tests/perf_equivalence.rs (issue 15): small and
mid-size noisy sessions, each with the solve options it is run under.

    python3 tests/data/perf/make_jobs.py      # from the repository root

The answers in `expected/` were computed from these files by the release
`fieldbal solve` of the code before issue 15's restructuring (commit feeb62d):

    for f in tests/data/perf/jobs/*.json; do
        fieldbal solve "$f" > "tests/data/perf/expected/$(basename "$f")"
    done
"""
import cmath
import json
import math
import os
import random


def phasor(rng, scale):
    return cmath.rect(scale * (0.2 + rng.random()), 2 * math.pi * rng.random())


def session(rng, planes, sensors, speeds, samples):
    rows = sensors * speeds
    w = [[phasor(rng, 2.0) for _ in range(planes)] for _ in range(rows)]
    u = [phasor(rng, 30.0) for _ in range(planes)]
    y0 = [sum(w[a][j] * u[j] for j in range(planes)) + phasor(rng, 1.0) for a in range(rows)]

    def reading(a, z):
        r = {
            "speed_rpm": 500.0 + 250.0 * (a // sensors),
            "sensor": f"S{a % sensors}",
            "amplitude": round(abs(z), 6),
            "phase_deg": round(math.degrees(cmath.phase(z)) % 360.0, 4),
        }
        if samples and a % 3 == 0:
            r["samples"] = [
                {"amplitude": round(abs(z + phasor(rng, 0.3)), 6),
                 "phase_deg": round(math.degrees(cmath.phase(z + phasor(rng, 0.3))) % 360.0, 4)}
                for _ in range(samples)
            ]
        return r

    def readings(y):
        return [reading(a, y[a] + phasor(rng, 0.5)) for a in range(rows)]

    runs = [{"id": "zero", "weights": [], "readings": readings(y0)}]
    for j in range(planes):
        t = phasor(rng, 40.0)
        y = [y0[a] + w[a][j] * t for a in range(rows)]
        runs.append({
            "id": f"trial {j}",
            "weights": [{"plane": f"P{j}", "mass_g": round(abs(t), 6),
                         "angle_deg": round(math.degrees(cmath.phase(t)) % 360.0, 4)}],
            "readings": readings(y),
        })
    return {
        "name": f"perf {planes}x{sensors}x{speeds}",
        "conventions": {"phase": rng.choice(["lead", "lag"]),
                        "angle_direction": rng.choice(["with_rotation", "against_rotation"])},
        "planes": [{"id": f"P{j}", "radius_mm": 150} for j in range(planes)],
        "sensors": [{"id": f"S{k}", "unit": "um_pp"} for k in range(sensors)],
        "runs": runs,
    }


def options(rng, kind, planes, sensors):
    o = {"amplitude_noise_pct": rng.choice([1.0, 2.0, 5.0]),
         "phase_noise_deg": rng.choice([1.0, 2.0, 4.0])}
    if kind == "weighted":
        o["row_weights"] = [{"sensor": f"S{k}", "weight": round(0.5 + rng.random(), 3)}
                            for k in range(0, sensors, 2)]
    if kind == "min_max":
        o["objective"] = "min_max"
    return o


if __name__ == "__main__":
    rng = random.Random(15)
    os.makedirs("tests/data/perf/jobs", exist_ok=True)
    shapes = [(2, 4, 1), (2, 3, 2), (3, 4, 2), (4, 11, 1), (4, 6, 3), (5, 8, 2),
              (6, 10, 3), (8, 12, 3), (3, 3, 1), (4, 4, 1)]
    n = 0
    for kind in ["plain", "weighted", "samples", "min_max"]:
        for planes, sensors, speeds in shapes:
            s = session(rng, planes, sensors, speeds, 4 if kind == "samples" else 0)
            job = {"session": s, "options": options(rng, kind, planes, sensors)}
            with open(f"tests/data/perf/jobs/{n:02}-{kind}-{planes}x{sensors}x{speeds}.json", "w") as f:
                json.dump(job, f, separators=(",", ":"))
            n += 1
