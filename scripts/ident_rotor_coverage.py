#!/usr/bin/env python3
"""Coverage of `POST /api/v1/identify/rotor`'s 95 % half-widths, measured from
outside (session 23): noisy sessions of a Jeffcott (one-mass) rotor of known
critical speed and damping ratio are posted to a running service, and each
answer's interval is checked against the truth.

Each record is a two-run session (reference and one trial run, one plane at
200 mm) read by sensors turned 0, 90 and 200 degrees from the reference mark
and scaled 1, 0.7 and 1.3 (three bearings' views of one mode); every reading
gets an amplitude error of `amp` (relative, normal) and a phase error of
`phase` degrees (normal), independently. The service's defaults are used:
mass, forcing and cross-coupling estimated. Per case and interval the table
gives held/checked (every sensor of every record is a check):

- `crit`: |critical_speed_rpm - truth| <= critical_speed_resolution_rpm;
- `zeta`: a resolved damping ratio within damping_ratio_resolution of the
  truth, an unresolved one (damping_ratio_bound "upper") at or above it;
- `b/m`, `q/m`: when given, within b_over_m_resolution (q_over_m_resolution)
  of the truth 2*zeta*omega_n (qfrac * b/m * omega_n, 0 unless a case says);
- `unres`: share of checks with the damping unresolved; `none`: checks with
  no result (no_mode) or a refusal; `poor_fit`: share of checks warned
  `poor_fit`, and the last column `crit` and `zeta` over the unwarned only.

Cases vary one thing at a time from a base (8 speeds from 0.7 to 1.3 times
the critical, 2 %/2 deg, zeta 0.05, trial weight half the original
unbalance): speeds 3 to 60, noise 1 %/1 deg to 5 %/5 deg, zeta 0.02 to 0.2,
the critical near either end of the range or outside it, a small trial
(30 % of the vibration: the coefficients' noise about 4.4 times the
readings'), and some options; then cases where the split of the damping
into direct damping and cross-coupling is resolved (zeta 0.1-0.4, 0.1-1 %,
a cross-coupling q = 0.5 b omega_n in two; the damping ratio checked is
then (1 - qfrac) zeta). Seeds are fixed (case index and record).

Session 23's finding: the critical speed's interval held 0.955-1.000 in
every case (over-wide at many speeds); the damping ratio's held 0.96-1.00
where the fit leaves under 10 % (no poor_fit), but with the coefficients
scattering 15-25 % and many speeds (6.1)'s least squares fit zeta low
(errors in the variables) by more than the interval allows: 0.71 at
5 %/5 deg, a small trial, 25 speeds, always with poor_fit. The fit now
takes that bias out (method 6): 0.935-1.000 in every case. b_over_m and
q_over_m, with the cross-coupling estimated, were given whenever b/m
cleared its resolution, so where the split is not really resolved the few
given are mostly misses (12 of 47 held where fewer than 60 speeds gave
any; 35 of 38 at 60 speeds and 1 %/1 deg). With the cross-coupling
estimated they are now given only when b/m exceeds twice its resolution,
with at least 3 degrees of freedom (method 6): the 1 given in those
cases missed; 0.96-1.00 held where the split is resolved (4 speeds and 0.3 %:
18 of 21).

Not run by CI (NumPy is not a dependency). Usage (a server on a free port):
  target/debug/fieldbal serve --listen 127.0.0.1:18923 --database sqlite:///tmp/x.db &
  python3 scripts/ident_rotor_coverage.py http://127.0.0.1:18923 [records] [case-filter]
"""
import http.client
import json
import sys
import urllib.parse

import numpy as np

CRIT = 2450.0          # rpm
MASS = 150.0           # kg
RADIUS_MM = 200.0
SENSORS = [("1H", 0.0, 1.0), ("1V", 90.0, 0.7), ("2H", 200.0, 1.3)]


def base(**kw):
    case = dict(n=8, lo=0.7, hi=1.3, amp=0.02, phase=2.0, zeta=0.05, qfrac=0.0,
                original=(20.0, 250.0), trial=(10.0, 30.0), options={})
    case.update(kw)
    return case


CASES = [
    ("base 8 speeds", base()),
    ("3 speeds", base(n=3)),
    ("4 speeds", base(n=4)),
    ("5 speeds", base(n=5)),
    ("15 speeds", base(n=15)),
    ("25 speeds", base(n=25)),
    ("noise 1%/1deg", base(amp=0.01, phase=1.0)),
    ("noise 5%/5deg", base(amp=0.05, phase=5.0)),
    ("noise 5%/5deg 25 sp", base(n=25, amp=0.05, phase=5.0)),
    ("zeta 0.02", base(zeta=0.02)),
    ("zeta 0.1", base(zeta=0.1)),
    ("zeta 0.2", base(zeta=0.2)),
    ("zeta 0.02 5 sp", base(zeta=0.02, n=5)),
    ("zeta 0.2 3 sp", base(zeta=0.2, n=3)),
    ("edge 0.6-1.02", base(lo=0.6, hi=1.02)),
    ("edge 0.98-1.5", base(lo=0.98, hi=1.5)),
    ("edge 0.6-1.02 5%/5deg", base(lo=0.6, hi=1.02, amp=0.05, phase=5.0)),
    ("outside 0.5-0.9", base(lo=0.5, hi=0.9)),
    ("small trial (30 %)", base(trial=(6.0, 30.0))),
    ("small trial 5%/5deg", base(trial=(6.0, 30.0), amp=0.05, phase=5.0)),
    ("small trial 5%/5deg 25 sp", base(trial=(6.0, 30.0), amp=0.05, phase=5.0, n=25)),
    ("small trial 3%/3deg 25 sp", base(trial=(6.0, 30.0), amp=0.03, phase=3.0, n=25)),
    ("small trial 3%/3deg 40 sp 0.5-1.5", base(trial=(6.0, 30.0), amp=0.03, phase=3.0, n=40,
                                                lo=0.5, hi=1.5)),
    ("noise 3%/3deg 40 sp 0.5-1.5", base(amp=0.03, phase=3.0, n=40, lo=0.5, hi=1.5)),
    ("noise 2%/2deg 40 sp 0.5-1.5", base(n=40, lo=0.5, hi=1.5)),
    ("noise 2%/2deg 60 sp 0.5-1.5", base(n=60, lo=0.5, hi=1.5)),
    ("noise 1%/1deg 60 sp 0.5-1.5", base(n=60, lo=0.5, hi=1.5, amp=0.01, phase=1.0)),
    ("q zero option", base(options={"cross_coupling": "zero"})),
    ("q zero small trial 5%/5deg 25 sp", base(trial=(6.0, 30.0), amp=0.05, phase=5.0, n=25,
                                               options={"cross_coupling": "zero"})),
    ("forcing at weight, 1H only", base(trial=(6.0, 30.0), amp=0.05, phase=5.0, n=25,
                                        options={"unbalance_angle": "at_weight", "sensors": ["1H"]})),
    # Where the split of damping and cross-coupling is (nearly) resolved.
    ("zeta 0.2 60 sp 0.3-1.7 1%/1deg", base(zeta=0.2, n=60, lo=0.3, hi=1.7, amp=0.01, phase=1.0)),
    ("zeta 0.2 25 sp 0.3-1.7 0.3%/0.3deg", base(zeta=0.2, n=25, lo=0.3, hi=1.7, amp=0.003,
                                                 phase=0.3)),
    ("zeta 0.1 60 sp 0.5-1.5 0.3%/0.3deg", base(zeta=0.1, n=60, lo=0.5, hi=1.5, amp=0.003,
                                                 phase=0.3)),
    ("zeta 0.2 8 sp 0.5-1.5 0.3%/0.3deg", base(zeta=0.2, lo=0.5, hi=1.5, amp=0.003, phase=0.3)),
    ("zeta 0.2 4 sp 0.5-1.5 0.3%/0.3deg", base(zeta=0.2, n=4, lo=0.5, hi=1.5, amp=0.003, phase=0.3)),
    ("zeta 0.2 3 sp 0.5-1.5 0.1%/0.1deg", base(zeta=0.2, n=3, lo=0.5, hi=1.5, amp=0.001, phase=0.1)),
    ("zeta 0.2 5 sp 0.5-1.5 0.3%/0.3deg", base(zeta=0.2, n=5, lo=0.5, hi=1.5, amp=0.003, phase=0.3)),
    ("zeta 0.2 5 sp 0.5-1.5 0.1%/0.1deg", base(zeta=0.2, n=5, lo=0.5, hi=1.5, amp=0.001, phase=0.1)),
    ("zeta 0.2 4 sp 0.5-1.5 0.1%/0.1deg", base(zeta=0.2, n=4, lo=0.5, hi=1.5, amp=0.001, phase=0.1)),
    # A cross-coupling q = qfrac * b * omega_n (the damping ratio (1 - qfrac) * zeta).
    ("q 0.5 zeta 0.1", base(zeta=0.1, qfrac=0.5)),
    ("q 0.5 zeta 0.4 25 sp 0.3-1.7 0.3%/0.3deg", base(zeta=0.4, qfrac=0.5, n=25, lo=0.3, hi=1.7,
                                                        amp=0.003, phase=0.3)),
]


def response(w, turn_deg, scale, zeta, u, qfrac=0.0):
    """Displacement (m) of the rotor to unbalance u (kg m) at w, seen by a
    sensor turned by turn_deg (internal frame: lead, with rotation); direct
    damping ratio zeta, cross-coupling q = qfrac * b * omega_n."""
    wn = CRIT * np.pi / 30.0
    c = MASS * wn * wn
    b = 2.0 * zeta * np.sqrt(c * MASS)
    d = c - MASS * w * w + 1j * (w * b - qfrac * b * wn)
    return scale * u * w * w * np.exp(-1j * np.radians(turn_deg)) / d


def session(case, rng):
    speeds = np.linspace(case["lo"], case["hi"], case["n"]) * CRIT
    u0 = case["original"][0] * RADIUS_MM * 1e-6 * np.exp(1j * np.radians(case["original"][1]))
    ut = case["trial"][0] * RADIUS_MM * 1e-6 * np.exp(1j * np.radians(case["trial"][1]))

    def readings(u):
        out = []
        for rpm in speeds:
            w = rpm * np.pi / 30.0
            for sid, turn, scale in SENSORS:
                y = response(w, turn, scale, case["zeta"], u, case["qfrac"]) / 0.5e-6  # um pp
                amp = abs(y) * (1.0 + case["amp"] * rng.standard_normal())
                ph = np.degrees(np.angle(y)) + case["phase"] * rng.standard_normal()
                out.append({"speed_rpm": float(rpm), "sensor": sid,
                            "amplitude": float(abs(amp)), "phase_deg": float(ph % 360.0)})
        return out

    return {
        "name": "coverage",
        "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
        "planes": [{"id": "A", "radius_mm": RADIUS_MM}],
        "sensors": [{"id": s, "unit": "um_pp"} for s, _, _ in SENSORS],
        "runs": [
            {"id": "ref", "weights": [], "readings": readings(u0)},
            {"id": "trial", "weights": [{"plane": "A", "mass_g": case["trial"][0],
                                         "angle_deg": case["trial"][1]}],
             "readings": readings(u0 + ut)},
        ],
    }


class Client:
    def __init__(self, url):
        u = urllib.parse.urlparse(url)
        self.conn = http.client.HTTPConnection(u.hostname, u.port, timeout=60)

    def post(self, path, body):
        data = json.dumps(body)
        self.conn.request("POST", path, data, {"Content-Type": "application/json"})
        r = self.conn.getresponse()
        return r.status, json.loads(r.read())


def run_case(client, k, case, records):
    wn = CRIT * np.pi / 30.0
    bt = 2.0 * case["zeta"] * wn
    qt = case["qfrac"] * bt * wn
    zt = case["zeta"] * (1.0 - case["qfrac"])
    keys = ("crit", "zeta", "b/m", "q/m", "crit ok", "zeta ok")
    tally = {key: [0, 0] for key in keys}
    unres = none = checks = warned = 0
    selected = case["options"].get("sensors", [s for s, _, _ in SENSORS])
    for rec in range(records):
        rng = np.random.default_rng([23, k, rec])
        status, out = client.post("/api/v1/identify/rotor",
                                  {"session": session(case, rng), "options": case["options"]})
        checks += len(selected)
        if status != 200:
            none += len(selected)
            continue
        got = {r["sensor"]: r for r in out["results"]}
        none += len(selected) - len(got)
        poor = {w["message"].split("'")[1] for w in out.get("warnings", []) if w["code"] == "poor_fit"}
        for sid, r in got.items():
            quiet = sid not in poor
            warned += not quiet
            n, rn = r["critical_speed_rpm"], r.get("critical_speed_resolution_rpm")
            held = rn is not None and abs(n - CRIT) <= rn
            z, rz = r["damping_ratio"], r.get("damping_ratio_resolution")
            if r.get("damping_ratio_bound") == "upper":
                unres += 1
                zheld = z >= zt
            else:
                zheld = rz is not None and abs(z - zt) <= rz
            for key, h, count in (("crit", held, True), ("zeta", zheld, True),
                                  ("crit ok", held, quiet), ("zeta ok", zheld, quiet)):
                if count:
                    tally[key][0] += h
                    tally[key][1] += 1
            if "b_over_m" in r:
                tally["b/m"][1] += 1
                tally["b/m"][0] += abs(r["b_over_m"] - bt) <= r["b_over_m_resolution"]
            if "q_over_m" in r:
                tally["q/m"][1] += 1
                tally["q/m"][0] += abs(r["q_over_m"] - qt) <= r["q_over_m_resolution"]
    return tally, unres, none, checks, warned


def main():
    url = sys.argv[1]
    records = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    only = sys.argv[3] if len(sys.argv) > 3 else ""
    client = Client(url)
    print(f"{records} records x {len(SENSORS)} sensors a case; held/checked (share)")
    print("| case | crit | zeta | b/m | q/m | unres | none | poor_fit | crit, zeta unwarned |")
    print("|---|---|---|---|---|---|---|---|---|")
    for k, (name, case) in enumerate(CASES):
        if only and only not in name:
            continue
        tally, unres, none, checks, warned = run_case(client, k, case, records)
        cells = []
        for key in ("crit", "zeta", "b/m", "q/m"):
            h, c = tally[key]
            cells.append(f"{h}/{c} ({h / c:.3f})" if c else "-")
        quiet = [f"{tally[key][0] / tally[key][1]:.3f}" if tally[key][1] else "-"
                 for key in ("crit ok", "zeta ok")]
        print(f"| {name} | " + " | ".join(cells) +
              f" | {unres / checks:.2f} | {none} | {warned / checks:.2f} | {', '.join(quiet)} |",
              flush=True)


if __name__ == "__main__":
    main()
