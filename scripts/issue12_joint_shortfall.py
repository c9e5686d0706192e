"""Where the S = 0 shortfall of amplitude_95 conditioned on all rows comes
from (issue 12, item 2; method 8 "The product term ..."; session 10, helper
amp). NumPy prototype, not run by CI, a few seconds per case.

The tests' rotor (tests/uncertainty/rotor_model.rs) at ten speeds, 2 %/2°
stated noise, plain least squares (no bias removal), the true residual set to
zero (y0 = -W C), the rows' own covariances D(C) at the true correction.
Per case it prints the coverage of the (8.8) bound at S = 0 against the true
remaining vibration W dC ('truth'), against What dC (the product term left
out of the truth), and of the same conditioning with the exact W in place of
What ('trueW cond').

    python3 scripts/issue12_joint_shortfall.py 0.3 100     # trial effect, realisations
    python3 scripts/issue12_joint_shortfall.py residual    # |r|^2 beside the noise
"""
import numpy as np, sys
NODES=7; PLANES=[0,3,6]; SENSORS=[1,2,4,5]
BEARINGS=[(1,8e6,2.5e3),(5,3e6,1.5e3)]; MASS=15.0; BENDING=2.7e7; LOSS=0.02; RADIUS=0.1
U0=[(60,.3),(25,2.),(40,4.1),(80,1.1),(30,5.5),(45,3.),(70,.9)]
def response(speeds, planes=PLANES):
    K=np.zeros((7,7))
    for i in range(5):
        d=[(i,1.),(i+1,-2.),(i+2,1.)]
        for a,x in d:
            for b,y in d: K[a,b]+=BENDING*x*y
    u0=np.array([m*np.exp(1j*a) for m,a in U0])
    rows=len(speeds)*4
    W=np.zeros((rows,len(planes)),complex); y0=np.zeros(rows,complex)
    for p,rpm in enumerate(speeds):
        om=rpm*2*np.pi/60
        Z=K*(1+1j*LOSS)-om*om*MASS*np.eye(7)
        for node,kb,cb in BEARINGS: Z[node,node]+=kb+1j*om*cb
        sol=lambda u: np.linalg.solve(Z,u*om*om)*1e6
        x0=sol(u0*1e-9)
        for s,node in enumerate(SENSORS): y0[p*4+s]=x0[node]
        for j,pl in enumerate(planes):
            e=np.zeros(7,complex); e[pl]=1e-3*RADIUS
            x=sol(e)
            for s,node in enumerate(SENSORS): W[p*4+s,j]=x[node]
    return W,y0
def rcov(y,pct,deg):
    a=np.abs(y); sr=pct/100*a; st=a*np.deg2rad(deg)
    c=np.where(a>0,y.real/np.where(a>0,a,1),1); s=np.where(a>0,y.imag/np.where(a>0,a,1),0)
    r2,t2=sr*sr,st*st; off=c*s*(r2-t2)
    out=np.zeros(y.shape+(2,2)); out[...,0,0]=c*c*r2+s*s*t2; out[...,0,1]=off; out[...,1,0]=off; out[...,1,1]=s*s*r2+c*c*t2
    return out
def realrow(w):  # complex row (q,) -> 2x2q
    q=len(w); M=np.zeros((2,2*q)); M[0,0::2]=w.real; M[0,1::2]=-w.imag; M[1,0::2]=w.imag; M[1,1::2]=w.real; return M
TEN=[1200.,1700.,2200.,2700.,3200.,3700.,4200.,4700.,5200.,5700.]; ONE=[3000.]


def M(l):
    return np.array([[l.real,-l.imag],[l.imag,l.real]])
def own_cov(covY, lam):  # covY n x runs x2x2 -> n x2x2
    out=np.zeros((covY.shape[0],2,2))
    for k,l in enumerate(lam):
        Mk=M(l); out+=Mk@covY[:,k]@Mk.T
    return out
DRAWS=np.random.default_rng(12345).standard_normal((4000,2))
def covered(mean, cov, R):
    L=np.linalg.cholesky(cov+1e-300*np.eye(2))
    X=mean[None,:]+DRAWS@L.T
    return np.mean(np.hypot(X[:,0],X[:,1])<=abs(R))<=0.95
def cond(What, Rhat, D, rows):
    q=What.shape[1]
    X=[]; y=[]
    for b in rows:
        Li=np.linalg.inv(np.linalg.cholesky(D[b]))
        X.append(Li@realrow(What[b])); y.append(Li@np.array([Rhat[b].real,Rhat[b].imag]))
    X=np.vstack(X); y=np.concatenate(y)
    Q,Rr=np.linalg.qr(X); mc=np.linalg.solve(Rr,Q.T@y)
    Ri=np.linalg.inv(Rr); Linv=Ri@Ri.T
    return mc, Linv
def case(speeds, effect, R=400, seed=0, zero_r=False, pct=2., deg=2., variants=('A','B')):
    W,y0=response(speeds); n,q=W.shape
    C=-np.linalg.lstsq(W,y0,rcond=None)[0]
    if zero_r: y0=-W@C
    m=effect*np.linalg.norm(y0)/np.linalg.norm(W,axis=0)
    Y=np.column_stack([y0]+[y0+W[:,j]*m[j] for j in range(q)])
    lam=np.concatenate([[1-np.sum(C/m)],C/m])
    Dtrue=own_cov(rcov(Y,pct,deg),lam)
    r=y0+W@C
    rng=np.random.default_rng(seed)
    hits={v:0 for v in variants}; tot=0
    ratio=np.sum(np.abs(r)**2)/np.sum(np.trace(Dtrue,axis1=1,axis2=2))
    for it in range(R):
        Yn=Y*(1+pct/100*rng.standard_normal(Y.shape)+1j*np.deg2rad(deg)*rng.standard_normal(Y.shape))
        What=(Yn[:,1:]-Yn[:,[0]])/m
        Chat=-np.linalg.lstsq(What,Yn[:,0],rcond=None)[0]
        Rhat=Yn[:,0]+What@Chat
        Rt=y0+W@Chat
        lamh=np.concatenate([[1-np.sum(Chat/m)],Chat/m])
        Dh=own_cov(rcov(Yn,pct,deg),lamh)
        for v in variants:
            D={'A':Dh,'B':Dtrue}[v]
            mc,Linv=cond(What,Rhat,D,range(n))
            for a in range(n):
                Wa=realrow(What[a]); mean=Wa@mc; eps=Wa@Linv@Wa.T
                hits[v]+=covered(mean,eps,Rt[a])
        tot+=n
    return ratio,{v:hits[v]/tot for v in variants}

def diag(eff, NR):
    W,y0=response(TEN); n,q=W.shape
    C=-np.linalg.lstsq(W,y0,rcond=None)[0]; y0=-W@C
    m=eff*np.linalg.norm(y0)/np.linalg.norm(W,axis=0)
    Y=np.column_stack([y0]+[y0+W[:,j]*m[j] for j in range(q)])
    lam=np.concatenate([[1-np.sum(C/m)],C/m]); D=own_cov(rcov(Y,2,2),lam)
    rng=np.random.default_rng(2); h={'truth':0,'What dC':0,'trueW cond':0}; t=0
    for it in range(NR):
        Yn=Y*(1+0.02*rng.standard_normal(Y.shape)+1j*np.deg2rad(2)*rng.standard_normal(Y.shape))
        What=(Yn[:,1:]-Yn[:,[0]])/m
        Chat=-np.linalg.lstsq(What,Yn[:,0],rcond=None)[0]; dC=Chat-C
        Rhat=Yn[:,0]+What@Chat
        mc,Linv=cond(What,Rhat,D,range(n))
        mc2,Linv2=cond(W,Rhat,D,range(n))
        for a in range(n):
            Wa=realrow(What[a]); mean=Wa@mc; eps=Wa@Linv@Wa.T
            h['truth']+=covered(mean,eps,(W@dC)[a]); h['What dC']+=covered(mean,eps,(What@dC)[a])
            Wt=realrow(W[a]); h['trueW cond']+=covered(Wt@mc2,Wt@Linv2@Wt.T,(W@dC)[a]); t+=1
    print(eff,{k:v/t for k,v in h.items()})

def residual():
    for sp,name in [(TEN,'ten'),(ONE,'one')]:
        for eff in [0.1,0.2,0.3,1.0]:
            W,y0=response(sp); n,q=W.shape
            C=-np.linalg.lstsq(W,y0,rcond=None)[0]; r=y0+W@C
            m=eff*np.linalg.norm(y0)/np.linalg.norm(W,axis=0)
            Y=np.column_stack([y0]+[y0+W[:,j]*m[j] for j in range(q)])
            lam=np.concatenate([[1-np.sum(C/m)],C/m])
            D=own_cov(rcov(Y,2,2),lam); tD=np.trace(D,axis1=1,axis2=2)
            z=np.abs(r)**2/tD
            print(name,eff,'pooled |r|^2/trD %.3f'%(np.sum(np.abs(r)**2)/np.sum(tD)),'rows: median %.3f max %.3f'%(np.median(z),z.max()), '|r|/|y0| %.4f'%(np.linalg.norm(r)/np.linalg.norm(y0)))

if __name__ == '__main__':
    if sys.argv[1] == 'residual':
        residual()
    else:
        diag(float(sys.argv[1]), int(sys.argv[2]))
