#!/usr/bin/env python3
# Run from the repository root: python3 scripts/reference_fit_wear.py (needs mpmath).
# Independent least squares of problems/wear-rates.csv (mpmath LU at 50 digits on the
# normal equations), with the standard errors: the reference of tests/all/fit_wear.rs.
import math
from mpmath import matrix, lu_solve, mp, inverse, sqrt
mp.dps=50
kB=mp.mpf('1.380649e-23'); eV=mp.mpf('1.602176634e-19')
rows=[l.strip().split(',') for l in open('problems/wear-rates.csv') if l[0].isdigit()]
X=matrix([[1, mp.mpf(s)*mp.mpf('1e-30')/(kB*mp.mpf(T)), -eV/(kB*mp.mpf(T))] for s,r,T in rows]); y=matrix([mp.log(mp.mpf(r)) for s,r,T in rows])
XtX=X.T*X; beta=lu_solve(XtX, X.T*y)
res=y-X*beta; n=len(rows); s2=sum(r**2 for r in res)/(n-3); cov=inverse(XtX)*s2
print('lnA', mp.nstr(beta[0],17), 'se', mp.nstr(sqrt(cov[0,0]),10))
print('dV_A3', mp.nstr(beta[1],17), 'se', mp.nstr(sqrt(cov[1,1]),10))
print('dU_eV', mp.nstr(beta[2],17), 'se', mp.nstr(sqrt(cov[2,2]),10))
