#!/usr/bin/env python3
"""Issue 12, session 4: why one regime keeps an exemption from "mean within
0.1 sd" (docs/method.md §8, "One speed, small trials").

A NumPy copy of the flexible rotor of tests/uncertainty/rotor_model.rs and of
the stated 2 %/2° noise of tests/uncertainty/eiv.rs, comparing estimators of
the correction by their mean error in sd (the test's bias/sd) and their rms
and 95th-percentile error beside the exact correction:

  ls        plain least squares;
  full      ÂᴴÂ − M̂ with the hat-weighted noise moments, M̂ = Σ (1 − P_ii) M_i
            (the fixed point of method 8.3 solved exactly, without the
            non-circular terms);
  fuller-a  Fuller (1987) §2.5's modification of it with α = a.

Not run by CI (NumPy is not a dependency). Usage:
  python3 scripts/issue12_estimators.py [realisations]
"""
import sys

import numpy as np

from rotor_model import flexible

PLANES=[0,3,6]; SENSORS=[1,2,4,5]
def response(speeds):
    return flexible(speeds, PLANES, SENSORS)
def rotor(speeds,effect):
    w,y0=response(speeds)
    c=-np.linalg.lstsq(w,y0,rcond=None)[0]
    trial=np.array([effect*np.linalg.norm(y0)/np.linalg.norm(w[:,j]) for j in range(w.shape[1])])
    return w,c,y0,trial
def realise(w,y0,trial,R,rng,pct=2.0,deg=2.0):
    q=len(trial); exact=np.stack([y0]+[y0+w[:,j]*trial[j] for j in range(q)],axis=1)  # m x runs
    n1=rng.standard_normal((R,)+exact.shape); n2=rng.standard_normal((R,)+exact.shape)
    Y=exact[None]*(1+pct/100*n1+1j*np.radians(deg)*n2)
    return Y
def zmat(Y,trial):
    q=len(trial)
    A=(Y[:,:,1:]-Y[:,:,:1])/trial[None,None,:]
    return np.concatenate([A,Y[:,:,:1]],axis=2)
def noise_M(Y,trial,pct=2.0,deg=2.0):
    R,m,runs=Y.shape; q=runs-1
    s=np.abs(Y)**2*((pct/100)**2+np.radians(deg)**2)  # R m runs
    V=np.zeros((runs,q+1))
    V[0,:q]=-1/trial; V[0,q]=1
    for j in range(q): V[j+1,j]=1/trial[j]
    # M = sum_i sum_k s_ik v_k v_k^T (real v)
    S=s.sum(axis=1) # R runs
    return np.einsum('rk,ka,kb->rab',S,V,V).astype(complex)
def est(Z,M,kappa):
    q=Z.shape[2]-1
    H=np.einsum('rma,rmb->rab',Z.conj(),Z)-kappa[:,None,None]*M
    return -np.linalg.solve(H[:,:q,:q],H[:,:q,q:])[...,0]
def lam_min(Z,M):
    G=np.einsum('rma,rmb->rab',Z.conj(),Z)
    L=np.linalg.cholesky(M)
    Li=np.linalg.inv(L)
    X=Li@G@np.conj(np.swapaxes(Li,1,2))
    return np.linalg.eigvalsh(X)[:,0]
def stats(C,c):
    E=C-c[None]
    out=[]
    for j in range(E.shape[1]):
        e=np.stack([E[:,j].real,E[:,j].imag],1)
        mu=e.mean(0); S=np.cov(e.T)
        out.append(np.sqrt(mu@np.linalg.solve(S,mu)/2))
    return np.array(out)


def parts(Y, trial, pct=2.0, deg=2.0):
    R, m, runs = Y.shape
    q = runs - 1
    Z = zmat(Y, trial)
    A = Z[:, :, :q]
    s = np.abs(Y) ** 2 * ((pct / 100) ** 2 + np.radians(deg) ** 2)
    V = np.zeros((runs, q + 1))
    V[0, :q] = -1 / trial
    V[0, q] = 1
    for j in range(q):
        V[j + 1, j] = 1 / trial[j]
    Qm, _ = np.linalg.qr(A)
    P = (np.abs(Qm) ** 2).sum(2)
    Mh = np.einsum('rik,ka,kb->rab', (1 - P)[:, :, None] * s, V, V).astype(complex)
    G = np.einsum('rma,rmb->rab', Z.conj(), Z)
    Li = np.linalg.inv(np.linalg.cholesky(Mh))
    lam = np.linalg.eigvalsh(Li @ G @ np.conj(np.swapaxes(Li, 1, 2)))[:, 0]
    return G, Mh, lam, q, m


def solve_h(G, Mh, kappa, q):
    H = G - kappa[:, None, None] * Mh
    return -np.linalg.solve(H[:, :q, :q], H[:, :q, q:])[..., 0]


if __name__ == "__main__":
    rng = np.random.default_rng(1)
    R = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    for speeds in ([3000.0], [1200.0 + 500 * i for i in range(10)]):
        for eff in [0.1, 0.2, 0.3, 1.0]:
            w, c, y0, trial = rotor(speeds, eff)
            Y = realise(w, y0, trial, R, rng)
            G, Mh, lam, q, m = parts(Y, trial)
            nu = 2 * (m - q)
            found = {'ls': solve_h(G, Mh, np.zeros(R), q), 'full': solve_h(G, Mh, np.ones(R), q)}
            for a in [0.0, 1.0, 4.0]:
                kap = np.where(lam >= 1 + 1 / nu, 1 - a / nu, lam - (1 + a) / nu)
                found['fuller-%g' % a] = solve_h(G, Mh, kap, q)
            for name, C in found.items():
                E = np.abs(C - c[None]) / np.abs(c)[None]
                print('%2d speed(s) trial %3.0f %% %-9s bias/sd %s rms/|C| %s p95/|C| %s' % (
                    len(speeds), eff * 100, name, np.round(stats(C, c), 2),
                    np.round(np.sqrt((E ** 2).mean(0)), 1), np.round(np.percentile(E, 95, axis=0), 1)))
