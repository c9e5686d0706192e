#!/usr/bin/env python3
"""Issue 12 item 1, session 9 (helper "weak"): test-inversion regions for a plane
that the sensors see nearly like another (one speed, 4 sensors, 3 planes, 2 %/2°
noise), measured on the fixtures of tests/uncertainty/dependent_planes.rs, the
held-out rotor of scripts/coverage_heldout.py and the well-conditioned planes.

Not run by CI (NumPy is not a dependency). It reproduces the figures of method
§8, "Nearly dependent planes at one speed": plain least squares `Ĉ`, no
errors-in-variables step, per plane `j` the statistic at the exact correction with
the other planes profiled along the least-squares path
`C(c) = Ĉ + H⁻¹e_j (c − Ĉ_j) / (H⁻¹)_jj`, `H = ŴᴴŴ`:

- `rao`: the score test, i.e. the first-order covariance (8.2) formed at the
  candidate `C(c)` (its `λ_k` and `z = Ŷ0 + Ŵ C`) instead of at `Ĉ` (Fieller's
  idea; Rao's score statistic);
- `LR`: the profile likelihood ratio in the saturated model (every reading's
  mean free, so `r` is a free nuisance), by damped iterated linearisation;
- `K`: Kleibergen's (2002, Econometrica 70, "Pivotal statistics for testing
  structural parameters in instrumental variables regression") statistic: with
  `z(C) = Ŷ0 + Ŵ C` exactly linear in the readings, each row's `Ŵ_a` is made
  independent of `z_a` by `W̃_a = Ŵ_a − Cov(Ŵ_a, z_a) D_a⁻¹ z_a`, and
  `t = W̃ᴴ z` has, given `W̃`, the covariance `Σ_a W̃_aᴴ D_a W̃_a` (real 2×2
  forms); the plane's efficient combination `t_j − H̃_jo H̃_oo⁻¹ t_o`
  (`H̃ = W̃ᴴŴ`) against χ²₂. Exactly χ²₆ for the whole `C` when the residual
  is 0, whatever the conditioning.

Then the regions `{c : K_j(c) ≤ 5.991}` and the score test's are traced on a
polar grid around `Ĉ_j` (24 directions, radii 0.03–300 first-order sd): the
share of realisations whose region (its star-shaped part around `Ĉ_j`)
reaches 300 sd, and for the others the factor by which the first-order
ellipse must be scaled to hold it.

Given the path of a `fieldbal` binary, it also measures the shipped answer
through `fieldbal solve -` (errors-in-variables estimate, `(1 + κ)`): its
coverage, and the factor its covariance would need to hold 95 % (the 95th
percentile of the error's Mahalanobis² over 5.991), with the large-residual
fixture at nodes 0, 3, 4 added.

About 8 minutes of one core with the defaults (1000, 200), plus 1 with a
binary. What the figures mean, and why no region of this kind was adopted
(they are unbounded in most realisations: Gleser & Hwang 1987, Dufour 1997),
is in method §8.

Usage: python3 scripts/issue12_weak_direction.py [calibration realisations]
       [region realisations] [path/to/fieldbal [realisations]]
"""
import sys
import numpy as np

from rotor_model import heldout_job

K95 = 5.991464547107979  # χ²₂ 95 %
K6 = 12.591587243743977  # χ²₆ 95 %


def test_rotor(planes, effect, rpm=3000.0):
    """tests/uncertainty/rotor_model.rs at one speed, corrections at `planes` (nodes)."""
    K = np.zeros((7, 7))
    for i in range(5):
        d = [(i, 1.0), (i + 1, -2.0), (i + 2, 1.0)]
        for a, x in d:
            for b, y in d:
                K[a, b] += 2.7e7 * x * y
    u0 = np.array([m * np.exp(1j * a) for m, a in
                   [(60, .3), (25, 2.), (40, 4.1), (80, 1.1), (30, 5.5), (45, 3.), (70, .9)]])
    om = rpm * 2 * np.pi / 60
    Z = K * (1 + 0.02j) - om * om * 15.0 * np.eye(7)
    for n, kb, cb in [(1, 8.0e6, 2.5e3), (5, 3.0e6, 1.5e3)]:
        Z[n, n] += kb + 1j * om * cb
    sol = lambda u: np.linalg.solve(Z, u * om * om) * 1e6
    sens = [1, 2, 4, 5]
    Y0 = sol(u0 * 1e-9)[sens]
    W = np.zeros((4, len(planes)), complex)
    for j, pl in enumerate(planes):
        u = np.zeros(7, complex); u[pl] = 1e-4
        W[:, j] = sol(u)[sens]
    T = np.array([effect * np.linalg.norm(Y0) / np.linalg.norm(W[:, j]) for j in range(len(planes))])
    return W, Y0, T.astype(complex)


def heldout(effect, speed=3000.0):
    """scripts/coverage_heldout.py's rotor at one speed (P0, P2 nearly dependent)."""
    return heldout_job([speed], effect)


FIXTURES = {
    "small residual, nodes 0,1,6": lambda e: test_rotor([0, 1, 6], e),
    "large residual, nodes 1,2,4": lambda e: test_rotor([1, 2, 4], e),
    "held-out rotor": heldout,
    "well conditioned, nodes 0,3,6": lambda e: test_rotor([0, 3, 6], e),
}


def noisy(rng, Y, pct=2.0, deg=2.0):
    return Y * (1 + pct / 100 * rng.standard_normal(Y.shape) + 1j * np.radians(deg) * rng.standard_normal(Y.shape))


def reading_cov(Y, pct=2.0, deg=2.0):
    """The options' model (method 8.1): radial pct, tangential deg, (..., 2, 2)."""
    a = np.abs(Y); c = Y.real / a; s = Y.imag / a
    r2 = (pct / 100 * a) ** 2; t2 = (a * np.radians(deg)) ** 2
    off = c * s * (r2 - t2)
    return np.stack([np.stack([c * c * r2 + s * s * t2, off], -1), np.stack([off, s * s * r2 + c * c * t2], -1)], -2)


def omegas(T):
    """ω_k of (8.2): how reading k of a row moves that row of Ŵ (runs × planes)."""
    q = len(T)
    om = np.zeros((q + 1, q), complex); om[0] = -1 / T
    for k in range(q):
        om[k + 1, k] = 1 / T[k]
    return om


def cmul_real(w):
    """Real 2×2 matrix of multiplication by the complex w, (..., 2, 2)."""
    return np.stack([np.stack([w.real, -w.imag], -1), np.stack([w.imag, w.real], -1)], -2)


def plain_ls(Y, T):
    W = ((Y[:, 1:, :] - Y[:, :1, :]) / T[None, :, None]).transpose(0, 2, 1)
    return W, -(np.linalg.pinv(W) @ Y[:, 0, :, None])[..., 0]


def profile(W, Chat, j, c):
    H = W.conj().transpose(0, 2, 1) @ W
    Hi = np.linalg.inv(H)
    return Chat + Hi[:, :, j] / Hi[:, j, j][:, None] * (c - Chat[:, j])[:, None]


def maha(d, cov):
    v = np.stack([d.real, d.imag], -1)
    return np.einsum('...i,...ij,...j->...', v, np.linalg.inv(cov), v)


def rao(Y, T, W, j, C, S):
    """(8.2)'s covariance of plane j formed at the candidate C (N, q)."""
    N, R, m = Y.shape
    Ap = np.linalg.pinv(W); Hi = Ap @ Ap.conj().transpose(0, 2, 1)
    om = omegas(T)
    lam = C @ om.T; lam[:, 0] += 1
    z = Y[:, 0, :] + (W @ C[..., None])[..., 0]
    g = Hi @ om.conj().T
    out = np.zeros((N, 2, 2))
    for k in range(R):
        for a in range(m):
            al = -lam[:, k] * Ap[:, j, a]; be = -z[:, a] * g[:, j, k]
            p, n = al + be, al - be
            M = np.stack([np.stack([p.real, -n.imag], -1), np.stack([p.imag, n.real], -1)], -2)
            out += M @ S[:, k, a] @ M.transpose(0, 2, 1)
    return out


def kleibergen(Y, T, W, C, S):
    """t = W̃ᴴ z(C) (real 2q), its covariance given W̃, and W̃ (module doc)."""
    N, R, m = Y.shape; q = len(T)
    om = omegas(T)
    lam = C @ om.T; lam[:, 0] += 1
    z = Y[:, 0, :] + (W @ C[..., None])[..., 0]
    t = np.zeros((N, 2 * q)); V = np.zeros((N, 2 * q, 2 * q)); Wt = np.zeros((N, m, q), complex)
    Om = np.concatenate([np.concatenate([cmul_real(np.array(om[k, j])) for k in range(R)], -1) for j in range(q)], -2)
    for a in range(m):
        Sx = np.zeros((N, 2 * R, 2 * R))
        for k in range(R):
            Sx[:, 2 * k:2 * k + 2, 2 * k:2 * k + 2] = S[:, k, a]
        Lam = np.concatenate([cmul_real(lam[:, k]) for k in range(R)], -1)
        D = Lam @ Sx @ Lam.transpose(0, 2, 1)
        G = Om[None] @ Sx @ Lam.transpose(0, 2, 1)
        zr = np.stack([z[:, a].real, z[:, a].imag], -1)
        wr = np.stack([W[:, a].real, W[:, a].imag], -1).reshape(N, 2 * q)
        wt = (wr - (G @ np.linalg.solve(D, zr[..., None]))[..., 0]).reshape(N, q, 2)
        wtc = wt[..., 0] + 1j * wt[..., 1]
        Wt[:, a] = wtc
        Mz = np.concatenate([cmul_real(wtc[:, i].conj()) for i in range(q)], -2)
        t += (Mz @ zr[..., None])[..., 0]
        V += Mz @ D @ Mz.transpose(0, 2, 1)
    return t, V, Wt


def k_plane(Y, T, W, Chat, S, j, c):
    """Plane j's K statistic at values c (N complex), the others profiled."""
    q = len(T)
    t, V, Wt = kleibergen(Y, T, W, profile(W, Chat, j, c), S)
    Hm = Wt.conj().transpose(0, 2, 1) @ W
    o = [i for i in range(q) if i != j]
    L = np.zeros((len(c), q), complex); L[:, j] = 1
    L[:, o] = -(Hm[:, j:j + 1, o] @ np.linalg.inv(Hm[:, o][:, :, o]))[:, 0]
    tc = t.reshape(-1, q, 2); tc = tc[..., 0] + 1j * tc[..., 1]
    Lr = np.concatenate([cmul_real(L[:, i]) for i in range(q)], -1)
    return maha((L * tc).sum(-1), Lr @ V @ Lr.transpose(0, 2, 1)), t, V


def lr_at(Y, T, S, j, c, iters=60, damp=0.5):
    """Profile likelihood ratio of `C_j = c` in the saturated model of the readings (every
    reading's mean free): min over means μ with C_j(μ) = c of Σ (Y−μ)ᵀ S⁻¹ (Y−μ), by damped
    iterated linearisation of the constraint (each step's Jacobian is (8.2) at μ). Returns the
    statistic and whether the constraint was met."""
    N, R, m = Y.shape
    Yr = np.stack([Y.real, Y.imag], -1)
    mu = Y.copy()

    def jac(mu):
        W = ((mu[:, 1:, :] - mu[:, :1, :]) / T[None, :, None]).transpose(0, 2, 1)
        Ap = np.linalg.pinv(W); Hi = Ap @ Ap.conj().transpose(0, 2, 1)
        C = -(Ap @ mu[:, 0, :, None])[..., 0]
        om = omegas(T)
        lam = C @ om.T; lam[:, 0] += 1
        z = mu[:, 0, :] + (W @ C[..., None])[..., 0]
        g = Hi @ om.conj().T
        M = np.zeros((N, R, m, 2, 2))
        for k in range(R):
            for a in range(m):
                al = -lam[:, k] * Ap[:, j, a]; be = -z[:, a] * g[:, j, k]
                p, n = al + be, al - be
                M[:, k, a] = np.stack([np.stack([p.real, -n.imag], -1), np.stack([p.imag, n.real], -1)], -2)
        return C[:, j], M
    for _ in range(iters):
        g, M = jac(mu)
        lin = np.einsum('nkaij,nkaj->ni', M, Yr - np.stack([mu.real, mu.imag], -1))
        res = np.stack([g.real - c.real, g.imag - c.imag], -1) + lin
        P = np.einsum('nkaij,nkajl,nkaml->nim', M, S, M)
        st = np.einsum('nkaij,nkalj,nl->nkai', S, M, np.linalg.solve(P, res[..., None])[..., 0])
        mu = mu + damp * ((Yr - st)[..., 0] + 1j * (Yr - st)[..., 1] - mu)
    d = Yr - np.stack([mu.real, mu.imag], -1)
    g, _ = jac(mu)
    return np.einsum('nkai,nkaij,nkaj->n', d, np.linalg.inv(S), d), np.abs(g - c) < 1e-4 * np.abs(c)


def calibration(name, eff, R, seed=3):
    W0, Y00, T = FIXTURES[name](eff)
    Cex = -np.linalg.lstsq(W0, Y00, rcond=None)[0]
    sv = np.linalg.svd(W0, compute_uv=False)
    res = np.linalg.norm(Y00 + W0 @ Cex) / np.linalg.norm(Y00)
    rng = np.random.default_rng(seed)
    ex = np.stack([Y00] + [Y00 + W0[:, j] * T[j] for j in range(len(T))])
    Y = noisy(rng, np.repeat(ex[None], R, 0)); S = reading_cov(Y)
    W, Chat = plain_ls(Y, T)
    q = len(T)
    tt, VV, _ = kleibergen(Y, T, W, np.repeat(Cex[None], R, 0), S)
    full = np.einsum('ni,nij,nj->n', tt, np.linalg.inv(VV), tt)
    line = f"{name}, trial {eff:.0%} (condition {sv[0] / sv[-1]:.1f}, residual {res:.3f}):\n"
    rh = np.linalg.norm(Y[:, 0, :] + (W @ Chat[..., None])[..., 0], axis=1) / np.linalg.norm(Y00)
    line += f"   fitted residual |r̂|/|Y0| quartiles {np.round(np.quantile(rh, [.25, .5, .75]), 3)}\n"
    line += f"   K, whole C against χ²₆: {np.mean(full <= K6):.3f} (mean {full.mean():.2f}, 6 when calibrated)\n"
    for j in range(q):
        c = np.full(R, Cex[j])
        first = rao(Y, T, W, j, Chat, S)
        fo = np.mean(maha(Cex[j] - Chat[:, j], first) <= K95)
        st_rao = maha(Cex[j] - Chat[:, j], rao(Y, T, W, j, profile(W, Chat, j, c), S))
        st_k, _, _ = k_plane(Y, T, W, Chat, S, j, c)
        st_lr, met = lr_at(Y, T, S, j, c)
        line += (f"   P{j}: first order at Ĉ {fo:.3f}, score (8.2 at the candidate) {np.mean(st_rao <= K95):.3f}, "
                 f"K {np.mean(st_k <= K95):.3f}, LR {np.mean(st_lr <= K95):.3f} (met {met.mean():.2f})\n")
    print(line, end="", flush=True)


def region(name, eff, R, seed=11, ndir=24, radii=np.geomspace(0.03, 300, 40)):
    W0, Y00, T = FIXTURES[name](eff)
    rng = np.random.default_rng(seed)
    ex = np.stack([Y00] + [Y00 + W0[:, j] * T[j] for j in range(len(T))])
    Y = noisy(rng, np.repeat(ex[None], R, 0)); S = reading_cov(Y)
    W, Chat = plain_ls(Y, T)
    phis = np.exp(1j * np.linspace(0, 2 * np.pi, ndir, endpoint=False))
    G = ndir * len(radii)
    rep = lambda x: np.repeat(x, G, 0)
    out = {"K": [], "score": []}
    for j in range(len(T)):
        first = rao(Y, T, W, j, Chat, S)
        sd = np.sqrt(np.trace(first, axis1=1, axis2=2) / 2)
        off = (radii[None, :] * phis[:, None]).ravel()
        cand = (Chat[:, j, None] + sd[:, None] * off[None]).ravel()
        st_k, _, _ = k_plane(rep(Y), T, rep(W), rep(Chat), rep(S), j, cand)
        st_s = maha(cand - rep(Chat)[:, j], rao(rep(Y), T, rep(W), j, profile(rep(W), rep(Chat), j, cand), rep(S)))
        for key, st in [("K", st_k), ("score", st_s)]:
            inside = (st <= K95).reshape(R, ndir, len(radii))
            # star-shaped part around Ĉ_j: along each ray up to the first exit
            exits = np.where((~inside).any(2), (~inside).argmax(2), len(radii))
            unbounded = (exits >= len(radii)).any(1)
            f = []
            for n in np.nonzero(~unbounded)[0]:
                pts = sd[n] * radii[np.minimum(exits[n], len(radii) - 1)] * phis
                P = np.stack([pts.real, pts.imag], -1)
                f.append(np.einsum('ij,jk,ik->i', P, np.linalg.inv(first[n]), P).max() / K95)
            out[key].append(f"P{j} {unbounded.mean():.2f}, {np.median(f) if f else np.nan:.0f}")
    for key, v in out.items():
        print(f"   {name}, trial {eff:.0%}: {key} region " + "; ".join(v), flush=True)


def lr_ray(name="well conditioned, nodes 0,3,6", eff=0.3, seed=11, j=0):
    """The LR along one ray from `Ĉ_j` (first realisation, direction +Re): it falls again far out."""
    W0, Y00, T = FIXTURES[name](eff)
    rng = np.random.default_rng(seed)
    ex = np.stack([Y00] + [Y00 + W0[:, i] * T[i] for i in range(len(T))])
    Y = noisy(rng, np.repeat(ex[None], 4, 0))[:1]; S = reading_cov(Y)
    W, Chat = plain_ls(Y, T)
    sd = np.sqrt(np.trace(rao(Y, T, W, j, Chat, S)[0]) / 2)
    vals = [lr_at(Y, T, S, j, Chat[:, j] + sd * t, iters=200)[0][0] for t in [1, 2, 3, 5]]
    print(f"   {name}, trial {eff:.0%}, P{j}, first realisation: LR at 1, 2, 3, 5 sd along +Re: "
          f"{np.round(vals, 2)}", flush=True)


def shipped(binary, name, eff, R, seed=21):
    """Coverage of `fieldbal solve`'s ellipses and the factor on its covariance for 95 %."""
    import json, subprocess
    W0, Y00, T = FIXTURES[name](eff)
    Cex = -np.linalg.lstsq(W0, Y00, rcond=None)[0]
    rng = np.random.default_rng(seed)
    ex = np.stack([Y00] + [Y00 + W0[:, j] * T[j] for j in range(len(T))])
    Y = noisy(rng, np.repeat(ex[None], R, 0))
    q, m = len(T), Y.shape[2]
    m2 = np.zeros((R, q))
    for n in range(R):
        runs = [{"id": f"R{k}", "readings": [{"amplitude": float(abs(Y[n, k, a])),
                 "phase_deg": float(np.degrees(np.angle(Y[n, k, a])) % 360), "speed_rpm": 3000.0,
                 "sensor": f"S{a}"} for a in range(m)],
                 "weights": [] if k == 0 else [{"plane": f"P{k - 1}", "mass_g": float(abs(T[k - 1])),
                                                "angle_deg": float(np.degrees(np.angle(T[k - 1])) % 360)}]}
                for k in range(q + 1)]
        job = {"session": {"name": "weak", "conventions": {"phase": "lead", "angle_direction": "with_rotation"},
                           "planes": [{"id": f"P{j}"} for j in range(q)],
                           "sensors": [{"id": f"S{a}", "unit": "um_pp"} for a in range(m)], "runs": runs},
               "options": {"amplitude_noise_pct": 2.0, "phase_noise_deg": 2.0}}
        sol = json.loads(subprocess.run([binary, "solve", "-"], input=json.dumps(job).encode(),
                                        capture_output=True, check=True).stdout)
        for j, c in enumerate(sol["corrections"]):
            d = Cex[j] - c["mass_g"] * np.exp(1j * np.radians(c["angle_deg"]))
            m2[n, j] = maha(d, np.array(c["uncertainty"]["covariance_g2"]))
    print(f"   {name}, trial {eff:.0%}: shipped ellipse {np.round((m2 <= K95).mean(0), 3)}, "
          f"factor for 95 % {np.round(np.quantile(m2, 0.95, axis=0) / K95, 2)}", flush=True)


FIXTURES_SHIPPED = dict(FIXTURES, **{"large residual, nodes 0,3,4": lambda e: test_rotor([0, 3, 4], e)})


if __name__ == "__main__":
    Rc = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    Rr = int(sys.argv[2]) if len(sys.argv) > 2 else 200
    print(f"Coverage at the exact correction, {Rc} realisations (binomial sd {np.sqrt(.95 * .05 / Rc):.3f}):")
    for eff in [0.3, 1.0]:
        for name in FIXTURES:
            calibration(name, eff, Rc)
    print(f"Regions, {Rr} realisations, per plane: share reaching 300 first-order sd, "
          "median scale of the first-order ellipse holding the rest")
    for eff in [0.3, 1.0]:
        for name in FIXTURES:
            region(name, eff, Rr)
    lr_ray()
    if len(sys.argv) > 3:
        Rs = int(sys.argv[4]) if len(sys.argv) > 4 else 400
        FIXTURES.update(FIXTURES_SHIPPED)
        print(f"The shipped answer, {Rs} realisations:")
        for eff in [0.3, 1.0]:
            for name in FIXTURES:
                shipped(sys.argv[3], name, eff, Rs)
