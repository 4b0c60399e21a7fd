#!/usr/bin/env python3
"""How many replicates R for the Sobol' intervals of src/uq/sobol.rs (docs/uncertainty.md).

WHAT
    Splits N Saltelli samples of the Ishigami function (a = 7, b = 0.1, x ~ U(-pi, pi)^3) into R
    blocks, each block the first N/R points of its own scrambled 6-dimensional Sobol' sequence,
    pools the centred Saltelli (S1) and Jansen (ST) estimators over all N samples, and puts a
    95 % interval index +- t_{0.975,R-1} se on each, se the delta-method standard error of the
    ratio from the block sums -- the method of src/uq/sobol.rs. Prints, per R, the coverage of
    the closed-form indices (Sobol' & Levitan 1999), the mean interval width, the RMS and the
    largest error over the 6 indices of `seeds` designs.

    The scrambling here is scipy's (linear matrix scramble + digital shift), not the hash-based
    nested (Owen) scramble of src/sweep/sequence.rs: the numbers guide the choice of R; the Rust
    tests (tests/all/uq.rs: ishigami_indices, sobol_interval_coverage_smoke, coverage_campaign)
    measure the shipped method itself.

RUN (numpy, scipy 1.17.1; 2026-12-02)
    python3 scripts/sobol_replicates.py 1024 200 4 8 16 32     # ~20 s
      R=4: coverage 0.967 width 0.0929 rmse 0.0182;  R=8: 0.963 0.0812 0.0198
      R=16: 0.947 0.0828 0.0213;                   R=32: 0.956 0.1052 0.0272
    python3 scripts/sobol_replicates.py 16384 40 8 16 32
      R=8: rmse 0.0018 maxerr 0.0071;  R=16: rmse 0.0017 maxerr 0.0056;  R=32: rmse 0.0054 maxerr 0.0235

USAGE
    sobol_replicates.py N SEEDS R [R ...]
"""
import numpy as np, sys, warnings
from scipy.stats import qmc, t as tdist
warnings.filterwarnings("ignore")
S=np.array([0.3139051911478116,0.4424111447204025,0.0]); ST=np.array([0.5575888552795975,0.4424111447204025,0.243683664132214])
def ish(x): return np.sin(x[...,0])+7*np.sin(x[...,1])**2+0.1*x[...,2]**4*np.sin(x[...,0])
def run(N,R,seed,d=3):
    M=N//R
    rng=np.random.default_rng(seed)
    blocks=[]
    for r in range(R):
        u=qmc.Sobol(2*d,scramble=True,seed=rng).random(M)
        x=-np.pi+2*np.pi*u
        A,B=x[:,:d],x[:,d:]
        fa,fb=ish(A),ish(B)
        fab=[]
        for i in range(d):
            ab=A.copy(); ab[:,i]=B[:,i]; fab.append(ish(ab))
        blocks.append((fa,fb,np.array(fab)))
    fa=np.concatenate([b[0] for b in blocks]); fb=np.concatenate([b[1] for b in blocks])
    mu=(fa.sum()+fb.sum())/(2*N)
    out=[]
    den=[0.5*(((b[0]-mu)**2+(b[1]-mu)**2).sum()) for b in blocks]
    v=np.concatenate([fa,fb]).var(ddof=1)
    tq=tdist.ppf(0.975,R-1)
    res=[]
    for i in range(d):
        first=[((b[1]-mu)*(b[2][i]-b[0])).sum() for b in blocks]
        tot=[0.5*((b[0]-b[2][i])**2).sum() for b in blocks]
        for nums,truth in ((first,S[i]),(tot,ST[i])):
            val=sum(nums)/N/v
            e=np.array(nums)-val*np.array(den)
            se=np.sqrt(((e-e.mean())**2).sum()*R/(R-1))/sum(den)
            res.append((val,val-tq*se,val+tq*se,truth))
    return res
N=int(sys.argv[1]); seeds=int(sys.argv[2])
for R in [int(a) for a in sys.argv[3:]]:
    cov=0;w=0;err2=0;n=0;maxerr=0
    for s in range(seeds):
        for val,lo,hi,tr in run(N,R,s):
            cov+=lo<=tr<=hi; w+=hi-lo; err2+=(val-tr)**2; n+=1; maxerr=max(maxerr,abs(val-tr))
    print(f"N={N} R={R}: coverage {cov/n:.3f} width {w/n:.4f} rmse {np.sqrt(err2/n):.4f} maxerr {maxerr:.4f}",flush=True)
