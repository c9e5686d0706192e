#!/usr/bin/env python3
"""Issue 12, session 24: the true `κ_j` of `trial_effect_small` (method 8.4,
uncertainty/trust.rs) for the cases of scripts/issue12_table.py, from the
exact influence matrix and the stated 2 %/2° noise.

`κ_j = M_jj [(WᴴW)⁻¹]_jj`, `M_jj = Σ_a E|dW_aj|²`, with `W_aj = (Y_aj −
Y_a0) / t_j` and each reading's complex noise `E|dY|² = |Y|² (0.02² +
(2°)²)` (radial 2 % and tangential 2°); rows unweighted, as in the table's
jobs. The warning fires where the readings' estimate of `κ_j` exceeds 0.15.

Not run by CI (NumPy). Usage: python3 scripts/issue12_true_kappa.py
"""
import numpy as np

from rotor_model import flexible, heldout_job

ONE = [3000.0]
TEN_A = list(np.linspace(1000, 4500, 10))
TEN_B = [1000.0 + 500 * i for i in range(10)]
TEN_CAL = [1200.0 + 500 * i for i in range(10)]
NOISE = 0.02 ** 2 + np.radians(2.0) ** 2


def rotor(name, speeds, effect):
    """As scripts/issue12_table.py's `rotor`."""
    if name == "held-out":
        return heldout_job(speeds, effect)
    w, y0 = flexible(speeds, (0, 3, 6))
    t = np.array([effect * np.linalg.norm(y0) / np.linalg.norm(w[:, j]) for j in range(3)], complex)
    return w, y0, t


def kappa(w, y0, t):
    m = np.array([np.sum((np.abs(y0 + w[:, j] * t[j]) ** 2 + np.abs(y0) ** 2) * NOISE) / abs(t[j]) ** 2
                  for j in range(w.shape[1])])
    return m * np.real(np.diag(np.linalg.inv(w.conj().T @ w)))


def main():
    for name, label, speeds in [("held-out", "1 speed", ONE), ("held-out", "10 speeds 1000-4500", TEN_A),
                                ("held-out", "10 speeds 1000-5500", TEN_B), ("calibration", "1 speed", ONE),
                                ("calibration", "10 speeds", TEN_CAL)]:
        for effect in (0.1, 0.15, 0.2, 0.3, 1.0):
            k = kappa(*rotor(name, speeds, effect))
            print(f"{name:11s} {label:20s} {effect:4.0%}: κ {' '.join(f'{x:.3g}' for x in k)}")


if __name__ == "__main__":
    main()
