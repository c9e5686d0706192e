#!/usr/bin/env python3
"""Issue 12, session 21: a parametric bootstrap from a de-noised world
(docs/method.md §8, "Session 21"). Not kept; no code changed.

Session 15's bootstrap took the observed readings as the truth and failed
because that world (Â, Ĉ) is farther from singular than the real one: the
noise has pushed Â's weak singular value up. Here the world's influence
matrix is Â with its singular values shrunk by the noise they carry,
`σ̃_k² = max(σ̂_k² − v_kᴴ M̂ v_k, floor · v_kᴴ M̂ v_k)` (`M̂ = E[dAᴴ dA]` from
the readings' magnitudes and the stated 2 %/2°, `v_k` Â's right singular
vectors), its reference readings the observed ones and its correction the
least-squares one of that world, `C̃ = −Ã⁺ Ŷ0` (or, `keepC`, the world's
reference chosen so that its correction is Ĉ itself; `fuller`, so that it
is Fuller's de-attenuated `σ̂_k/σ̃_k²` along each singular direction, least
squares' `1/σ̂_k` where `σ̃_k = 0`). The world's readings
are resampled with the stated noise, each resample solved by plain least
squares, and the region around the answer Ĉ is the resamples' mean square
error about C̃ (`mse`) or their scatter about their mean (`sc`).

For each case (rotor_speeds_effect: `cal` the calibration rotor of
tests/uncertainty/eiv.rs, planes at nodes 0, 3, 6; `ho` the held-out rotor of
scripts/coverage_heldout.py, ten speeds over 1000–4500 rpm; `hob` the
held-out rotor over 1000–5500 rpm) it prints per world (`plain`: session
15's, Â itself; `denoise`: floor 0; `floor:c`; `…:keepC`; `…:fuller`; `oracle`: the
exact readings and correction, the fixed ellipse of least squares' true
mean square error) the share of the per-plane ellipses (χ²₂ 5.991) holding
the exact least-squares correction, P0/P1/P2. With `diag` it prints instead,
per world, the median of the world's weakest singular value over the true
one, the share of jobs where the de-noised one is zero, the median |C̃|/|C|
per plane, and the median of the resamples' mean square error over least
squares' true one per plane.

Plain least squares stands in for the answer (Ĉ is least squares, method
§8, session 13). The jobs of a case are drawn with seed 7 (the same for
every world), each world's resamples with seed [7, its number in WORLDS].
Not run by CI (NumPy is not a dependency). About 8 min for 400 jobs and 200
resamples on a busy 2-core machine. Usage:
  python3 scripts/issue12_denoised_bootstrap.py REALISATIONS RESAMPLES [diag] [CASE ...]
e.g. python3 scripts/issue12_denoised_bootstrap.py 400 200
"""
import sys

import numpy as np

from issue12_weak_direction import K95, maha, noisy
from rotor_model import flexible, heldout_job

SPEEDS = {("cal", 1): [3000.0], ("cal", 4): [1500.0, 2500.0, 3500.0, 4500.0],
          ("cal", 10): [1200.0 + 500 * i for i in range(10)],
          ("ho", 1): [3000.0], ("ho", 2): [1500.0, 3000.0], ("ho", 10): list(np.linspace(1000, 4500, 10)),
          ("hob", 10): [1000.0 + 500 * i for i in range(10)]}
CASES = ["ho_1_10", "ho_1_20", "ho_1_30", "ho_1_100", "ho_2_30", "ho_10_10", "ho_10_20", "ho_10_100",
         "hob_10_10", "hob_10_20", "hob_10_100", "cal_1_10", "cal_1_20", "cal_1_30", "cal_1_100",
         "cal_4_20", "cal_4_30", "cal_10_10", "cal_10_30", "cal_10_100"]
WORLDS = ["plain", "denoise", "floor:0.5", "floor:1", "denoise:keepC", "denoise:fuller", "oracle"]
V = 0.02 ** 2 + np.radians(2.0) ** 2  # E|dY|² / |Y|² of a reading


def job(name):
    rotor, n, eff = name.split("_")
    speeds = SPEEDS[(rotor, int(n))]
    eff = int(eff) / 100
    if rotor == "cal":
        w, y0 = flexible(speeds, (0, 3, 6))
        t = np.array([eff * np.linalg.norm(y0) / np.linalg.norm(w[:, j]) for j in range(3)], complex)
        return w, y0, t
    return heldout_job(speeds, eff)


def ls(y, t):
    """Readings (..., runs, rows) -> influence matrix (..., rows, q) and least-squares correction."""
    a = np.swapaxes((y[..., 1:, :] - y[..., :1, :]) / t[:, None], -1, -2)
    return a, -(np.linalg.pinv(a) @ y[..., 0, :, None])[..., 0]


def gram_noise(y, t):
    """M̂ = E[dAᴴ dA], (..., q, q): the reference's noise enters every column."""
    v = np.abs(y) ** 2 * V
    m = v[..., 0, :].sum(-1)[..., None, None] * (1 / np.conj(t))[:, None] * (1 / t)[None, :]
    return m + v[..., 1:, :].sum(-1)[..., :, None] * np.eye(len(t)) / np.abs(t)[:, None] ** 2


def world(y, t, kind):
    """The world's exact readings, its correction, the observed Ĉ and its weakest singular value."""
    a, c = ls(y, t)
    u, s, vh = np.linalg.svd(a, full_matrices=False)
    n = np.real(np.einsum("...ki,...ij,...kj->...k", vh.conj(), gram_noise(y, t), vh))
    parts = kind.split(":")
    if parts[0] == "plain":
        st = s
    else:
        floor = float(parts[1]) if parts[0] == "floor" else 0.0
        st = np.sqrt(np.maximum(s ** 2 - n, floor * n))
    at = u @ (st[..., :, None] * vh)
    if parts[-1] in ("keepC", "fuller"):
        cw = c
        if parts[-1] == "fuller":
            # Fuller's de-attenuation along each singular direction, σ̂/σ̃²
            # (least squares' 1/σ̂ where σ̃ = 0)
            f = np.divide(s, st ** 2, out=1 / s, where=st > 0)
            cw = -(np.conj(np.swapaxes(vh, -1, -2))
                   @ (f[..., :, None] * (np.conj(np.swapaxes(u, -1, -2)) @ y[..., 0, :, None])))[..., 0]
        y0w = y[..., 0, :] + (a @ c[..., None])[..., 0] - (at @ cw[..., None])[..., 0]
        yw = np.concatenate([y0w[..., None, :], y0w[..., None, :] + np.swapaxes(at * t, -1, -2)], axis=-2)
        return yw, cw.copy(), c, st[..., -1]
    inv = np.where(st > 1e-12 * s[..., :1], 1 / np.maximum(st, 1e-300), 0)
    ct = -(np.conj(np.swapaxes(vh, -1, -2))
           @ (inv[..., :, None] * (np.conj(np.swapaxes(u, -1, -2)) @ y[..., 0, :, None])))[..., 0]
    yw = np.concatenate([y[..., :1, :], y[..., :1, :] + np.swapaxes(at * t, -1, -2)], axis=-2)
    return yw, ct, c, st[..., -1]


def run(name, reps, resamples, diag, seed=7):
    """One case: the same noisy jobs (seed `seed`) for every world."""
    w, y0, t = job(name)
    c = -np.linalg.lstsq(w, y0, rcond=None)[0]
    exact = np.stack([y0] + [y0 + w[:, j] * t[j] for j in range(3)])
    rng = np.random.default_rng(seed)
    y = noisy(rng, np.repeat(exact[None], reps, 0))
    s_true = np.linalg.svd(w, compute_uv=False)[-1]
    chat_all = ls(y, t)[1]
    mse_true = np.mean(np.abs(chat_all - c) ** 2, 0)
    out = [name]
    for number, kind in enumerate(WORLDS):
        rng = np.random.default_rng([seed, number])  # each world's resamples its own
        if kind == "oracle":
            yw, ct, chat, smin = np.repeat(exact[None], reps, 0), np.repeat(c[None], reps, 0), chat_all, None
        else:
            yw, ct, chat, smin = world(y, t, kind)
        _, cb = ls(noisy(rng, np.repeat(yw[:, None], resamples, 1)), t)
        if diag:
            if smin is None:
                continue
            mse_b = np.mean(np.abs(cb - ct[:, None]) ** 2, 1)
            out.append(f"{kind}: s_min/true {np.median(smin) / s_true:.2f} zero {np.mean(smin == 0):.2f} "
                       f"|C~|/|C| {np.round(np.median(np.abs(ct) / np.abs(c), 0), 2)} "
                       f"mse/true {np.round(np.median(mse_b, 0) / mse_true, 2)}")
            continue
        for form in ("mse", "sc"):
            d = cb - (ct if form == "mse" else cb.mean(1))[:, None]
            dv = np.stack([d.real, d.imag], -1)
            cov = np.einsum("rbqi,rbqj->rqij", dv, dv) / resamples
            held = (maha(c[None] - chat, cov) <= K95).mean(0) * 100
            out.append(f"{kind} {form} {' '.join(f'{x:.1f}' for x in held)}")
    print(" | ".join(out), flush=True)


def main():
    reps, resamples = int(sys.argv[1]), int(sys.argv[2])
    rest = sys.argv[3:]
    diag = bool(rest) and rest[0] == "diag"
    for name in (rest[1:] if diag else rest) or CASES:
        run(name, reps, resamples, diag)


if __name__ == "__main__":
    main()
