#!/usr/bin/env python3
"""Write the large least-squares job files of BENCHMARKS.md (issue 15):
a noisy session with one removed trial per plane, linear in the weights.

    python3 benches/data/make_ls_jobs.py   # from the repository root

ls-16x32x40.json   16 planes, 32 sensors, 40 speeds (1280 rows, 21,760 readings)
ls-64x256x3.json   64 planes, 256 sensors, 3 speeds (768 rows, 49,920 readings:
                   the largest job the limits accept)
ls-267x267x1.json  267 planes, 267 sensors, 1 speed (over the plane limit; the
                   core alone, through `fieldbal solve`, if it accepts it)
"""
import cmath
import json
import math
import random


def phasor(rng, scale):
    return cmath.rect(scale * (0.2 + rng.random()), 2 * math.pi * rng.random())


def job(planes, sensors, speeds, seed=1):
    rng = random.Random(seed)
    rows = sensors * speeds
    w = [[phasor(rng, 2.0) for _ in range(planes)] for _ in range(rows)]
    u = [phasor(rng, 30.0) for _ in range(planes)]
    y0 = [sum(w[a][j] * u[j] for j in range(planes)) + phasor(rng, 1.0) for a in range(rows)]

    def readings(y):
        out = []
        for a in range(rows):
            z = y[a] + phasor(rng, 0.5)
            # Internal frame is phase lead / with rotation: the session says so.
            out.append({
                "speed_rpm": 500.0 + 250.0 * (a // sensors),
                "sensor": f"S{a % sensors}",
                "amplitude": round(abs(z), 6),
                "phase_deg": round(math.degrees(cmath.phase(z)) % 360.0, 4),
            })
        return out

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
        "name": f"ls {planes}x{sensors}x{speeds}",
        "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
        "planes": [{"id": f"P{j}", "radius_mm": 150} for j in range(planes)],
        "sensors": [{"id": f"S{k}", "unit": "um_pp"} for k in range(sensors)],
        "runs": runs,
    }


if __name__ == "__main__":
    for p, s, n in [(16, 32, 40), (64, 256, 3), (267, 267, 1)]:
        with open(f"benches/data/ls-{p}x{s}x{n}.json", "w") as f:
            json.dump(job(p, s, n), f, separators=(",", ":"))
