"""The rotor models the NumPy prototypes of issue 12 share (not run by CI;
NumPy is not a dependency). Imported by scripts/issue12_estimators.py and
scripts/coverage_heldout.py, which run from any directory (Python puts the
script's own folder on the path).

- `flexible(speeds, planes, sensors)`: a NumPy copy of the 7-node flexible
  rotor of tests/uncertainty/rotor_model.rs: influence matrix (rows
  speed-major, sensor within speed) and as-found vibration, um per g and um;
- `heldout_w(speed, zcols)`: the 3-mode, anisotropic rotor of
  scripts/coverage_heldout.py (sensors 1H, 1V, 2H, 2V), the influence of a
  unit unbalance at each axial station of `zcols`, um per g;
- `heldout_job(speeds, effect)`: that rotor's job: planes at stations 0.2,
  0.5, 0.8, unbalance also at 0.35 and 0.65 (outside the planes), trials of
  `effect` times the RMS vibration at phases 0, 1.3, 2.6 rad; returns the
  influence matrix, the as-found vibration and the complex trial masses.
"""
import numpy as np

NODES = 7
BEARINGS = [(1, 8.0e6, 2.5e3), (5, 3.0e6, 1.5e3)]
MASS = 15.0; BEND = 2.7e7; LOSS = 0.02; RAD = 0.1
U0 = [(60, .3), (25, 2.), (40, 4.1), (80, 1.1), (30, 5.5), (45, 3.), (70, .9)]


def flexible(speeds, planes=(0, 3, 6), sensors=(1, 2, 4, 5)):
    k = np.zeros((NODES, NODES))
    for i in range(NODES - 2):
        d = [(i, 1.0), (i + 1, -2.0), (i + 2, 1.0)]
        for a, x in d:
            for b, y in d:
                k[a, b] += BEND * x * y
    u0 = np.array([m * np.exp(1j * a) for m, a in U0])
    ns = len(sensors)
    rows = len(speeds) * ns
    w = np.zeros((rows, len(planes)), complex); y0 = np.zeros(rows, complex)
    for p, rpm in enumerate(speeds):
        om = rpm * 2 * np.pi / 60
        z = k * (1 + 1j * LOSS) - om * om * MASS * np.eye(NODES)
        for node, kb, cb in BEARINGS:
            z[node, node] += kb + 1j * om * cb
        sol = lambda u: np.linalg.solve(z, u * om * om) * 1e6
        x0 = sol(u0 * 1e-9)
        for s, node in enumerate(sensors):
            y0[p * ns + s] = x0[node]
        for j, pl in enumerate(planes):
            u = np.zeros(NODES, complex); u[pl] = 1e-3 * RAD
            x = sol(u)
            for s, node in enumerate(sensors):
                w[p * ns + s, j] = x[node]
    return w, y0


ZS = np.array([0.05, 0.05, 0.95, 0.95])
ANISO = np.array([1.0, 1.18, 1.0, 1.12])
WK = np.array([1500.0, 2800.0, 5200.0]); ZK = np.array([0.03, 0.05, 0.08])


def phi(k, z):
    return np.sin((k + 1) * np.pi * (z + 0.1) / 1.2)


def heldout_w(speed, zcols):
    out = np.zeros((4, len(zcols)), complex)
    for s in range(4):
        for j, z in enumerate(zcols):
            for k in range(3):
                w = WK[k] * ANISO[s]
                out[s, j] += phi(k, ZS[s]) * phi(k, z) * speed**2 / (w**2 - speed**2 + 2j * ZK[k] * w * speed)
    return out * 0.8  # um per g


def heldout_job(speeds, effect):
    zp = np.array([0.2, 0.5, 0.8])
    w = np.vstack([heldout_w(sp, zp) for sp in speeds])
    w_extra = np.vstack([heldout_w(sp, [0.35, 0.65]) for sp in speeds])
    y0 = w @ (50 * np.exp(1j * np.array([0.3, 2.1, 4.0]))) + w_extra @ (15 * np.exp(1j * np.array([1.0, 5.0])))
    ystd = np.sqrt(np.mean(np.abs(y0) ** 2))
    t = np.array([effect * ystd / np.sqrt(np.mean(np.abs(w[:, j]) ** 2)) for j in range(3)])
    return w, y0, t * np.exp(1j * np.array([0.0, 1.3, 2.6]))
