#!/usr/bin/env python3
"""Issue 12, session 21: the issue's own table measured again, from outside
through `fieldbal solve -`, on the held-out rotor (scripts/rotor_model.py
`heldout_job`, the rotor of scripts/coverage_heldout.py) and, for
comparison, on the calibration rotor of tests/uncertainty/eiv.rs
(`flexible`, planes at nodes 0, 3, 6; one speed 3000 rpm, ten 1200–5700);
2 %/2° noise on every reading, stated in the options; and the issue's point
checks.

`table` (default) prints one line per case, the issue's cases: one speed
(3000 rpm) with trial effects 10/20/30/100 % of the vibration, and ten speeds
with 10/15/20/100 %, over 1000–4500 rpm (coverage_heldout.py's range) and
over 1000–5500 rpm (past the third mode; issue12_layouts.py's range), then
the calibration rotor's eight. Per
case, over the realisations (seed 21000 + case number, numbered in the order
printed):

  ell      share of the ellipses (covariance_g2, χ²₂ 5.991) holding the exact
           least-squares correction, all planes, then P0/P1/P2;
  warned   the same over the plane-checks with a warning (one naming the
           plane, or the job's `regions_unreliable`), hits/checks;
  quiet    the same over the plane-checks with neither;
  codes    per warning code, the share of jobs carrying it;
  |Ĉ|/|C|  mean (and median) over the realisations of |Ĉ_j| / |C_j| per
           plane (Ĉ the answer's correction, C the exact least-squares one);
  |C*|/|C| the same for `uncertainty.bias_corrected` (Ĉ where absent);
  bias/sd  |mean(C* − C)| over its sd, per plane (the issue's 0.1 sd);
  amp95    share of `amplitude_95` bounds holding the vibration that really
           remains (|Y0 + W Ĉ| per row, exact W), and the median over rows
           and realisations of amplitude_95 over the true 95th percentile of
           that row's remaining vibration (over the realisations).

`samples` prints the same table with six samples per reading (2 %/2°
each) in place of the stated noise, the options left empty (same seeds).

`points` prints the issue's point checks (exact readings unless said):
a plane whose trial changed nothing; two planes with identical influence;
and its point 5 — readings 2.01 % apart in speed with a third sensor's speed
between them, a mass bound binding by 1.3e-5 of its value on an
ill-conditioned job, the angle of a zero correction, and the message with
one sensor selected.

Not run by CI (NumPy is not a dependency). About 2 min for 400 realisations
on a busy 2-core machine. Usage:
  python3 scripts/issue12_table.py target/release/fieldbal [realisations] [table|samples|points] [case numbers]

The optional last argument runs only the cases numbered (0–19, in the order
above, comma-separated: `8,9,10,16,17`), each with its own seed as in the
whole table, so a subset reproduces those lines of a whole run.
"""
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

import numpy as np

from cli_jobs import noisy_session, solve
from rotor_model import flexible, heldout_job

K95 = 5.991464547107979
SENSORS = ["1H", "1V", "2H", "2V"]
ONE = [3000.0]
TEN_A = list(np.linspace(1000, 4500, 10))
TEN_B = [1000.0 + 500 * i for i in range(10)]
TEN_CAL = [1200.0 + 500 * i for i in range(10)]
CASES = ([("ho 1 speed", ONE, e) for e in (0.1, 0.2, 0.3, 1.0)]
         + [("ho 10 1000-4500", TEN_A, e) for e in (0.1, 0.15, 0.2, 1.0)]
         + [("ho 10 1000-5500", TEN_B, e) for e in (0.1, 0.15, 0.2, 1.0)]
         + [("cal 1 speed", ONE, e) for e in (0.1, 0.2, 0.3, 1.0)]
         + [("cal 10 speeds", TEN_CAL, e) for e in (0.1, 0.15, 0.2, 1.0)])


def rotor(name, speeds, effect):
    """The held-out rotor (`ho`) or the calibration rotor of eiv.rs (`cal`:
    planes at nodes 0, 3, 6, real trial masses)."""
    if name.startswith("ho"):
        return heldout_job(speeds, effect)
    w, y0 = flexible(speeds, (0, 3, 6))
    t = np.array([effect * np.linalg.norm(y0) / np.linalg.norm(w[:, j]) for j in range(3)], complex)
    return w, y0, t


def polar(u):
    return u["mass_g"] * np.exp(1j * np.radians(u["angle_deg"]))


def case(binary, number, name, speeds, effect, reps, pool, samples=False):
    w, y0, t = rotor(name, speeds, effect)
    c = -np.linalg.lstsq(w, y0, rcond=None)[0]
    exact = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(3)], axis=1)
    rng = np.random.default_rng(21000 + number)
    sessions = [noisy_session(rng, exact, t, speeds, SENSORS, samples) for _ in range(reps)]
    opts = {} if samples else {"amplitude_noise_pct": 2.0, "phase_noise_deg": 2.0}
    answers = list(pool.map(lambda s: solve(binary, s, opts), sessions))
    hits, warned, chat, cstar, remain, amp95 = [], [], [], [], [], []
    codes = {}
    for sol, ch in answers:
        if ch is None:
            print("error", sol)
            continue
        warn = sol.get("warnings", [])
        for code in {x["code"] for x in warn}:
            codes[code] = codes.get(code, 0) + 1
        job = any(x["code"] == "regions_unreliable" for x in warn)
        h, wd, cs = [], [], []
        for j, corr in enumerate(sol["corrections"]):
            u = corr["uncertainty"]
            if u.get("mass_g") is None:
                h.append(True)
            else:
                d = c[j] - ch[j]
                dv = np.array([d.real, d.imag])
                h.append(dv @ np.linalg.solve(np.array(u["covariance_g2"]), dv) <= K95)
            wd.append(job or any(x.get("plane") == corr["plane"] for x in warn))
            cs.append(polar(u["bias_corrected"]) if "bias_corrected" in u else ch[j])
        hits.append(h); warned.append(wd); chat.append(ch); cstar.append(cs)
        remain.append(np.abs(y0 + w @ ch))
        amp95.append([pr["amplitude_95"] for pr in sol["predicted_residual"]])
    hits, warned = np.array(hits), np.array(warned)
    chat, cstar = np.array(chat), np.array(cstar)
    remain, amp95 = np.array(remain), np.array(amp95)
    n = len(hits)
    p95 = np.quantile(remain, 0.95, axis=0)
    err = cstar - c
    bias_sd = np.abs(err.mean(0)) / np.sqrt(np.mean(np.abs(err - err.mean(0)) ** 2, axis=0) / 2)
    ww, qq = hits[warned], hits[~warned]
    code_txt = " ".join(f"{k} {v / n:.2f}" for k, v in sorted(codes.items())) or "none"
    print(f"{name:16s} {effect:4.0%} n {n}: ell {hits.mean():.3f} ({' '.join(f'{x:.3f}' for x in hits.mean(0))}) "
          f"warned {ww.sum()}/{ww.size} quiet {qq.sum()}/{qq.size} | codes {code_txt} | "
          f"|Ĉ|/|C| {np.round(np.mean(np.abs(chat) / np.abs(c), 0), 2)} (median {np.round(np.median(np.abs(chat) / np.abs(c), 0), 2)}) "
          f"|C*|/|C| {np.round(np.mean(np.abs(cstar) / np.abs(c), 0), 2)} (median {np.round(np.median(np.abs(cstar) / np.abs(c), 0), 2)}) "
          f"bias/sd C* {np.round(bias_sd, 2)} | "
          f"amp95 {np.mean(remain <= amp95):.3f} median/true p95 {np.median(amp95 / p95):.2f}", flush=True)


def cli(binary, session, options):
    out = subprocess.run([binary, "solve", "-"], input=json.dumps({"session": session, "options": options}).encode(),
                         capture_output=True)
    return json.loads(out.stdout)


def job(w, y0, t, speeds, sensors, planes=None):
    """An exact session (no noise): reference and one trial run per plane."""
    exact = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(w.shape[1])], axis=1)
    s = noisy_session(np.random.default_rng(0), exact, t, speeds, sensors, pct=0.0, deg=0.0)
    return s


def short(sol):
    if "corrections" not in sol:
        return json.dumps(sol)
    parts = []
    for c in sol["corrections"]:
        u = c.get("uncertainty", {})
        parts.append(f"{c['plane']}: {c['mass_g']:.6g} g at {c['angle_deg']!r}°, mass interval {u.get('mass_g')}, "
                     f"angle interval {u.get('angle_deg')}")
    return "; ".join(parts) + " | warnings " + ", ".join(f"{x['code']}({x.get('plane', '-')})" for x in sol["warnings"])


def points(binary):
    w, y0, t = heldout_job(ONE, 0.3)
    noise = {"amplitude_noise_pct": 2.0, "phase_noise_deg": 2.0}
    # A plane whose trial changed nothing: P1's column zero.
    w0 = w.copy(); w0[:, 1] = 0
    s = job(w0, y0, t, ONE, SENSORS)
    print("trial changed nothing, exact:", short(cli(binary, s, {})))
    print("trial changed nothing, noise stated:", short(cli(binary, s, noise)))
    rng = np.random.default_rng(21)
    exact = np.stack([y0] + [y0 + w0[:, j] * t[j] for j in range(3)], axis=1)
    sn = noisy_session(rng, exact, t, ONE, SENSORS)
    print("trial changed nothing, noisy readings, noise stated:", short(cli(binary, sn, noise)))
    # Two planes with identical influence: P1's column equal to P0's.
    w2 = w.copy(); w2[:, 1] = w2[:, 0]
    t2 = t.copy(); t2[1] = t2[0]
    s = job(w2, y0, t2, ONE, SENSORS)
    print("identical influence P0 = P1, exact:", short(cli(binary, s, {})))
    print("identical influence P0 = P1, noise stated:", short(cli(binary, s, noise)))
    exact = np.stack([y0] + [y0 + w2[:, j] * t2[j] for j in range(3)], axis=1)
    sn = noisy_session(rng, exact, t2, ONE, SENSORS)
    print("identical influence P0 = P1, noisy readings, noise stated:", short(cli(binary, sn, noise)))
    # Point 5a: S0's reference at 1000 rpm, its trial reading at 1020.1 (2.01 %),
    # the other sensor at 1010 in both runs.
    s = job(w[:2, :1], y0[:2], t[:1], ONE, ["S0", "S1"])
    speeds = [[1000.0, 1010.0], [1020.1, 1010.0]]
    for r, run in enumerate(s["runs"]):
        for k, rd in enumerate(run["readings"]):
            rd["speed_rpm"] = speeds[r][k]
    s["planes"] = s["planes"][:1]
    print("5a readings 2.01 % apart, bridged:", json.dumps(cli(binary, s, {}))[:400])
    # Point 5b: P1 nearly P0 and a thousand times weaker; P1's bound 1.3e-5
    # under its free mass.
    w3 = w[:, :2].copy(); w3[:, 1] = w3[:, 0] * (1e-3 + 2e-4j) + w[:, 1] * 2e-6
    t3 = np.array([t[0], t[0] * 1000])
    s = job(w3, w3 @ np.array([20, 15e3 * np.exp(1j)]), t3, ONE, SENSORS)
    s["planes"] = s["planes"][:2]
    free = cli(binary, s, {})
    m = free["corrections"][1]["mass_g"]
    for hair in (1.3e-5, 1e-4):
        b = cli(binary, s, {"max_mass_g": {"P1": m * (1 - hair)}})
        print(f"5b bound {hair:g} under the free {m:.6g} g (cond {free['condition_number']:.3g}):", short(b))
    # Point 5c: a zero correction (the vibration is nil).
    s = job(w, np.zeros_like(y0), np.abs(t) + 0j, ONE, SENSORS)
    out = subprocess.run([binary, "solve", "-"], input=json.dumps({"session": s, "options": {}}).encode(),
                         capture_output=True).stdout.decode()
    print("5c zero correction: '-0.0' in the answer:", "-0.0" in out, "| angles:",
          [c["angle_deg"] for c in json.loads(out).get("corrections", [])], json.loads(out).get("error"))
    # Point 5d: one sensor selected, too few rows for three planes.
    s = job(w, y0, t, ONE, SENSORS)
    print("5d one sensor selected:", json.dumps(cli(binary, s, {"sensors": ["1H"]}))[:300])


def main():
    binary = sys.argv[1]
    reps = int(sys.argv[2]) if len(sys.argv) > 2 else 400
    what = sys.argv[3] if len(sys.argv) > 3 else "table"
    if what == "points":
        points(binary)
        return
    only = ({int(n) for n in sys.argv[4].split(",")} if len(sys.argv) > 4
            else set(range(len(CASES))))
    pool = ThreadPoolExecutor(2)
    for number, (name, speeds, effect) in enumerate(CASES):
        if number not in only:
            continue
        case(binary, number, name, speeds, effect, reps, pool, samples=what == "samples")


if __name__ == "__main__":
    main()
