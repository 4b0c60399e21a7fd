#!/usr/bin/env python3
# The debris shares of the hub (docs/model.md §13; src/model/debris.rs tests, tests/all/debris.rs):
# closed forms and an independent quadrature, mpmath at 40 digits. Columns: τ_j, d*, δ*/σ,
# contact share, area share (closed form), area share (quadrature).
from mpmath import mp, mpf, erfc, sqrt, exp, pi, quad, inf
mp.dps = 40
h = mpf('2.082115779067568'); s = mpf('3e-9'); R = mpf('1e-6'); G = mpf(160e9)/(2*(1+mpf('0.22'))); w = mpf('0.1')
Q = lambda x: erfc(x/sqrt(2))/2
phi = lambda x: exp(-x*x/2)/sqrt(2*pi)
print('G', G)
for tau in ['1e9','2e9','0.5e9']:
    t = mpf(tau); d = 12*w*G/t**2; cut = d*d/(4*R)/s; a = h+cut
    cf = Q(a)/Q(h); af = (phi(a)-h*Q(a))/(phi(h)-h*Q(h))
    # independent: quadrature of (z-h) phi(z) over z>a
    num = quad(lambda z: (z-h)*phi(z), [a, a+5, inf]); den = quad(lambda z: (z-h)*phi(z), [h, h+5, inf])
    print(tau, mp.nstr(d,12), mp.nstr(cut,12), mp.nstr(cf,15), mp.nstr(af,15), mp.nstr(num/den,15))
