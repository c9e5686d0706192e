#!/usr/bin/env python3
"""Issue 12 item 1, session 10 (helper "weak"): widenings along the weak direction
of `A` for nearly dependent planes at one speed, measured on the fixtures of
tests/uncertainty/dependent_planes.rs, the held-out rotor of
scripts/coverage_heldout.py and the well-conditioned planes (method §8, "Nearly
dependent planes", identity 8.10 and the candidates listed there).

Not run by CI (NumPy is not a dependency). Plain least squares, with (8.2) at `Ĉ`
times `1 + κ_j` standing in for the shipped answer ("shipped-like"); per case it
prints the error along `v̂` split by (8.10) into its residual and noise parts (in
first-order sd), and for each candidate widening (added along `v̂`, isotropic per
plane) the coverage per plane and the median ellipse area against the shipped-like
one. Candidates: "V1 bound" (the turn `t` bounded, method's first bullet), "B
c=ln20" (weak variance times 1 + ln 20), "V4 D at edge" / "V4 x3" (the noise
re-formed at the edge of the weak coordinate's 95 % circle, once or three times),
"V3 identity" ((8.10) bounded), and others not in the method ("A ln20", "V2
cross", "ucb r": smaller, all under 93 %; "worst |b|": |r| <= |b|, 7-66 times the
area). Last, the planes' own shares (`trust::own_share`) exactly and their
minimum over noisy realisations, for eiv.rs's and calibration.rs's geometries:
why no trigger on them separates the fixtures from the calibrated cases.

About 2 seconds with the default 400 realisations (seed 5).
Usage: python3 scripts/issue12_weak_widening.py [realisations]
"""
import sys
sys.path.insert(0, __import__('os').path.dirname(__file__))
import numpy as np
from issue12_weak_direction import FIXTURES, test_rotor, heldout, noisy, reading_cov, omegas, plain_ls, rao, maha, K95

FIX = dict(FIXTURES)
FIX["large residual, nodes 0,3,4"] = lambda e: test_rotor([0, 3, 4], e)


def diag(name, eff, R=400, seed=5, cands=None):
    W0, Y00, T = FIX[name](eff)
    Cex = -np.linalg.lstsq(W0, Y00, rcond=None)[0]
    rex = Y00 + W0 @ Cex
    rng = np.random.default_rng(seed)
    ex = np.stack([Y00] + [Y00 + W0[:, j] * T[j] for j in range(len(T))])
    Y = noisy(rng, np.repeat(ex[None], R, 0)); S = reading_cov(Y)
    W, Chat = plain_ls(Y, T)
    N, runs, m = Y.shape; q = len(T)
    trS = S[..., 0, 0] + S[..., 1, 1]  # (N, runs, m) complex variance
    om = omegas(T)  # runs x q
    lam = Chat @ om.T; lam[:, 0] += 1  # N x runs
    D = np.einsum('nk,nka->na', np.abs(lam) ** 2, trS)  # complex var of eps_a at Chat
    U, s, Vh = np.linalg.svd(W)  # U N x m x m
    smin = s[:, -1]; vm = Vh[:, -1, :].conj(); um = U[:, :, q - 1]; up = U[:, :, q]
    rhat = Y[:, 0, :] + (W @ Chat[..., None])[..., 0]
    bhat = Y[:, 0, :]
    # Var(W_a vm) = sum_k |omega_k . vm|^2 trS_ak
    ov = np.einsum('kj,nj->nk', om, vm)
    varWv = np.einsum('nk,nka->na', np.abs(ov) ** 2, trS)
    s2_em = np.einsum('na,na->n', np.abs(um) ** 2, D)
    s2_ep = np.einsum('na,na->n', np.abs(up) ** 2, D)
    s2_Ew = np.einsum('na,na->n', np.abs(up) ** 2, varWv)
    kperp = s2_Ew / smin ** 2
    # kappa_j
    varW = (trS[:, 1:, :].transpose(0, 2, 1) + trS[:, :1, :].transpose(0, 2, 1)) / np.abs(T) ** 2  # N m q
    Hi = np.linalg.inv(W.conj().transpose(0, 2, 1) @ W)
    kap = varW.sum(1) * np.real(np.diagonal(Hi, axis1=1, axis2=2))
    share = 1 / np.sqrt(np.sum(np.abs(W) ** 2, 1) * np.real(np.diagonal(Hi, axis1=1, axis2=2)))
    print(f"   own share per plane: min {np.round(share.min(0),3)}, median {np.round(np.median(share,0),3)}, max {np.round(share.max(0),3)}")
    first = np.stack([rao(Y, T, W, j, Chat, S) for j in range(q)], 1)  # N q 2 2
    ship = first * (1 + kap)[..., None, None]
    d = Chat - Cex
    z = Y[:, 0, :] + (W @ Cex[..., None])[..., 0]
    eps = z - rex
    wr = np.einsum('na,a->n', um.conj(), rex) / smin
    we = np.einsum('na,na->n', um.conj(), eps) / smin
    sdw = np.sqrt(s2_em) / smin
    print(f"== {name}, trial {eff:.0%}: |r|/|Y0| {np.linalg.norm(rex)/np.linalg.norm(Y00):.3f}, "
          f"|rhat|/|Y0| q {np.round(np.quantile(np.linalg.norm(rhat,axis=1)/np.linalg.norm(Y00),[.25,.5,.75]),3)}, "
          f"kappa med {np.round(np.median(kap,0),2)}, kperp q {np.round(np.quantile(kperp,[.25,.5,.75]),2)}, "
          f"cond med {np.median(s[:,0]/s[:,-1]):.0f}")
    print(f"   weak err r-part/sd q {np.round(np.quantile(np.abs(wr)/sdw,[.5,.9,.95]),2)}, eps-part/sd q {np.round(np.quantile(np.abs(we)/sdw,[.5,.9,.95]),2)}"
          f", s2_ep/s2_em {np.median(s2_ep/s2_em):.2f}, |vm_j|^2 med {np.round(np.median(np.abs(vm)**2,0),2)}")
    m2 = maha(d, ship)
    print(f"   shipped-like coverage {np.round((m2 <= K95).mean(0),3)}, factor {np.round(np.quantile(m2,.95,axis=0)/K95,2)};  first-order {np.round((maha(d, first) <= K95).mean(0),3)}")
    def s2v_at(Cp):
        lp = Cp @ om.T; lp[:, 0] += 1
        Dp = np.einsum('nk,nka->na', np.abs(lp) ** 2, trS)
        return np.einsum('na,na->n', np.abs(um) ** 2, Dp)
    sdw_c = np.sqrt(s2_em) / smin
    def v4(rounds=1):
        var = s2_em.copy()
        for _ in range(rounds):
            best = var.copy()
            for ph in np.exp(1j * np.linspace(0, 2 * np.pi, 8, endpoint=False)):
                Cp = Chat + (np.sqrt(np.log(20) * var) / smin * ph)[:, None] * vm
                best = np.maximum(best, s2v_at(Cp))
            var = best
        return var
    V4a = v4(1); V4b = v4(3)
    ctx = dict(V4a=V4a, V4b=V4b, smin=smin, vm=vm, s2_em=s2_em, s2_ep=s2_ep, s2_Ew=s2_Ew, rhat2=np.linalg.norm(rhat, axis=1) ** 2,
               bhat2=np.linalg.norm(bhat, axis=1) ** 2, kperp=kperp, kap=kap, ship=ship, first=first, q=q, Y00=Y00)
    for cname, f in (cands or {}).items():
        x = f(ctx)  # extra complex variance along vm, (N,)
        add = (x[:, None] * np.abs(vm) ** 2 / 2)[..., None, None] * np.eye(2)
        new = ship + add
        m2 = maha(d, new)
        grow = np.sqrt(np.linalg.det(new) / np.linalg.det(ship))
        print(f"   {cname:14s} coverage {np.round((m2 <= K95).mean(0),3)}, area x med {np.round(np.median(grow,0),2)}")
    return ctx


CANDS = {
    "B c=ln20": lambda c: np.log(20) * c["s2_em"] / c["smin"] ** 2,
    "A ln20": lambda c: np.log(20) * c["s2_em"] * c["s2_Ew"] / c["smin"] ** 4,
    "V1 bound": lambda c: (np.log(20) * c["kperp"] * c["s2_em"] + 2 * np.sqrt((1 + np.log(20) * c["kperp"]) * c["kperp"] * c["s2_em"] * c["rhat2"])) / c["smin"] ** 2,
    "V2 cross": lambda c: (2 * np.sqrt((1 + np.log(20) * c["kperp"]) * c["kperp"] * c["s2_em"] * c["rhat2"])) / c["smin"] ** 2,
    "V3 identity": lambda c: np.maximum(((np.sqrt(c["rhat2"]) + np.sqrt(np.log(20) * c["s2_ep"])) * np.sqrt(1 + np.log(20) * c["kperp"]) + np.sqrt(4.744 * (c["s2_em"] + c["s2_ep"]))) ** 2 - c["rhat2"], 0) / np.log(20) / c["smin"] ** 2 - c["s2_em"] / c["smin"] ** 2,
    "V4 D at edge": lambda c: (c["V4a"] - c["s2_em"]) / c["smin"] ** 2,
    "V4 x3": lambda c: (c["V4b"] - c["s2_em"]) / c["smin"] ** 2,
    "worst |b|": lambda c: (c["bhat2"] - c["rhat2"]) * c["s2_Ew"] / c["smin"] ** 4,
    "ucb r": lambda c: ((np.sqrt(c["rhat2"]) + np.sqrt(np.log(20) * c["s2_ep"])) ** 2 - c["rhat2"]) * c["s2_Ew"] / c["smin"] ** 4,
}

def geometry(name, eff=1.0):
    W0, Y00, T = FIX[name](eff)
    Hi = np.linalg.inv(W0.conj().T @ W0)
    share = 1 / np.sqrt(np.sum(np.abs(W0) ** 2, 0) * np.real(np.diag(Hi)))
    Wn = W0 / np.linalg.norm(W0, axis=0)
    sv = np.linalg.svd(Wn, compute_uv=False)
    # Darlow significance factors: pivoted Gram-Schmidt of unit columns
    cols = [Wn[:, j].copy() for j in range(W0.shape[1])]
    fac = [None] * len(cols); left = list(range(len(cols)))
    while left:
        j = max(left, key=lambda k: np.linalg.norm(cols[k]))
        fac[j] = np.linalg.norm(cols[j]); e = cols[j] / fac[j]; left.remove(j)
        for k in left:
            cols[k] = cols[k] - e * (e.conj() @ cols[k])
    print(f"{name}: own share {np.round(share,3)}, scaled cond {sv[0]/sv[-1]:.1f}, significance {np.round(fac,3)}")


TEN = [1200.0, 1700.0, 2200.0, 2700.0, 3200.0, 3700.0, 4200.0, 4700.0, 5200.0, 5700.0]


def rotor_speeds(planes, eff, speeds):
    Ws, Ys = [], []
    for rpm in speeds:
        W, Y0, _ = test_rotor(planes, 1.0, rpm)
        Ws.append(W); Ys.append(Y0)
    W = np.vstack(Ws); Y0 = np.concatenate(Ys)
    T = np.array([eff * np.linalg.norm(Y0) / np.linalg.norm(W[:, j]) for j in range(W.shape[1])]).astype(complex)
    return W, Y0, T


def two_plane(eff):
    c = complex
    W = np.array([[c(1.2, 0.8), c(0.3, -0.4)], [c(-0.5, 1.1), c(0.9, 0.2)], [c(2.0, -0.6), c(0.7, 0.9)], [c(0.4, 0.5), c(-1.3, 0.6)]])
    Ct = np.array([40 * np.exp(0.5j), 25 * np.exp(3.5j)])
    v = np.array([c(3, 1), c(-2, 2), c(1, -3), c(2, 2)])
    Q, _ = np.linalg.qr(W)
    perp = v - Q @ (Q.conj().T @ v)
    Y0 = -(W @ Ct) + perp
    T = np.array([eff / max(abs(W[a, j]) / abs(Y0[a]) for a in range(4)) for j in range(2)]).astype(complex)
    return W, Y0, T


def share_noisy(W0, Y00, T, R=400, seed=1, pct=2.0):
    rng = np.random.default_rng(seed)
    ex = np.stack([Y00] + [Y00 + W0[:, j] * T[j] for j in range(len(T))])
    Y = noisy(rng, np.repeat(ex[None], R, 0), pct, pct)
    W, _ = plain_ls(Y, T)
    Hi = np.linalg.inv(W.conj().transpose(0, 2, 1) @ W)
    share = 1 / np.sqrt(np.sum(np.abs(W) ** 2, 1) * np.real(np.diagonal(Hi, axis1=1, axis2=2)))
    return share.min()


def trigger_margins():
    exact = lambda W: 1 / np.sqrt(np.sum(np.abs(W) ** 2, 0) * np.real(np.diag(np.linalg.inv(W.conj().T @ W))))
    for label, mk in [("eiv one speed 0,3,6", lambda e: rotor_speeds([0, 3, 6], e, [3000.0])),
                      ("eiv ten speeds 0,3,6", lambda e: rotor_speeds([0, 3, 6], e, TEN)),
                      ("calibration two_plane", two_plane),
                      ("fixture small 0,1,6", lambda e: rotor_speeds([0, 1, 6], e, [3000.0])),
                      ("fixture large 1,2,4", lambda e: rotor_speeds([1, 2, 4], e, [3000.0])),
                      ("fixture large 0,3,4", lambda e: rotor_speeds([0, 3, 4], e, [3000.0])),
                      ("held-out one speed", heldout)]:
        W0, Y00, T = mk(1.0)
        mins = [share_noisy(*mk(e), pct=p) for e in [0.1, 0.3, 1.0] for p in [2.0, 5.0]]
        print(f"{label}: exact own shares {np.round(exact(W0),3)}, min over noisy (10/30/100 %, 2 and 5 %): {np.round(mins,3)}")


if __name__ == "__main__":
    R = int(sys.argv[1]) if len(sys.argv) > 1 else 400
    for eff in [0.3, 1.0]:
        for name in ["small residual, nodes 0,1,6", "large residual, nodes 1,2,4", "large residual, nodes 0,3,4", "held-out rotor", "well conditioned, nodes 0,3,6"]:
            diag(name, eff, R, cands=CANDS)
    trigger_margins()

