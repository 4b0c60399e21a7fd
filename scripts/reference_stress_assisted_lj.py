#!/usr/bin/env python3
"""Reference for the stress-assisted wear integral under the Lennard-Jones law (docs/model.md §11, §12).

WHAT
    I(h) = int_0^inf Delta F(s(Delta)) phi(h + Delta) dDelta,   phi(u) = exp(-u^2/2),
    F(s) = 1 - exp(-c exp(b s)),   s(Delta) = p(Delta)/Delta,
    p(Delta) = l^(-3/2) sum_k w_k P^_k(l Delta)      (no plasticity: c_h = infinity),
    the loads P^_k of the table's curves (src/model/lennard_jones/table.txt, Maugis units) at the
    Tabor parameter mu interpolated with Lagrange weights cubic in 1/mu over the four curves around
    mu (the rough law's stencil, src/model/lennard_jones/rough.rs, away from the cusp at 0.697 and
    below mu = 5 where the stencil has four curves). Written as value = I e^{kappa},
    kappa = h^2/2 for h > 0 (else 0), as tests/data/reference_stress_assisted.csv is.

METHOD (independent of the Rust code's)
    * Each curve's contact part is read from its samples: on every contact panel (the `breaks`
      line) the 13 values at the panel's Chebyshev-Lobatto nodes (the `contact` line), evaluated
      by the barycentric formula (the Rust code sums a Chebyshev series through the same points).
    * The integral in x = Delta^(1/2) in double precision (the weight taken relative to e^{-kappa}),
      split at every curve's panel ends, at the weight's peak region, at 40 uniform pieces, at the
      saturation front (ln(c e^{b s}) = 0, by bisection) and geometrically towards x = 0, where s
      has a pole; two rules on the same pieces: QUADPACK (scipy.integrate.quad, to 1e-13 on each
      piece) and composite Gauss-Legendre of order 48 on each piece cut in eight. The rows give
      their relative difference and keep those where they agree to 1e-11 (measured: 2e-15).
    * Only the sampled part of the curves is used (l Delta <= the smallest delta^_max of the
      stencil): a row is kept only if the whole Gaussian weight beyond, int Delta phi, is below
      1e-13 of I (F <= 1 there).

USAGE
    /work/venv-testers/bin/python scripts/reference_stress_assisted_lj.py > tests/data/reference_stress_assisted_lj.csv
    Dependencies: numpy, scipy. Run time: about 11 minutes (689 s) on a 2-core machine shared with builds.
"""

import math
import sys
import time

import numpy as np
import scipy
from scipy.integrate import quad
from scipy.special import erfcx
TABLE = "src/model/lennard_jones/table.txt"
DEGREE = 12  # PANEL_DEGREE in table.rs
CUSP = 0.6972


def read_table(path):
    curves, cur = [], None
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        words = line.split()
        if words[0] == "curve":
            head = [float(w) for w in words[1:]]
            cur = {"tabor": head[0], "switch": head[2], "jumps": head[3] != 0.0}
            curves.append(cur)
        else:
            cur[words[0]] = [float(w) for w in words[1:]]
    return curves


class Contact:
    """One curve's contact part: barycentric interpolation panel by panel (float64, vectorised)."""

    def __init__(self, curve):
        n = DEGREE
        self.breaks = np.array([float(b) for b in curve["breaks"]])
        values = np.array([float(v) for v in curve["contact"]])
        i = np.arange(n + 1)
        self.unit = -np.cos(np.pi * i / n)  # Lobatto nodes on [-1, 1], ascending
        self.unit[0], self.unit[-1] = -1.0, 1.0
        self.w = (-1.0) ** i
        self.w[0] *= 0.5
        self.w[-1] *= 0.5
        self.values = np.array([values[k * n: k * n + n + 1] for k in range(len(self.breaks) - 1)])

    def load(self, d):
        d = np.atleast_1d(np.asarray(d, dtype=float))
        k = np.clip(np.searchsorted(self.breaks, d, side="right") - 1, 0, len(self.breaks) - 2)
        lo, hi = self.breaks[k], self.breaks[k + 1]
        t = (2.0 * d - lo - hi) / (hi - lo)
        diff = t[:, None] - self.unit[None, :]
        exact = diff == 0.0
        diff[exact] = 1.0
        q = self.w[None, :] / diff
        y = self.values[k]
        out = (q * y).sum(axis=1) / q.sum(axis=1)
        hit = exact.any(axis=1)
        out[hit] = y[hit][exact[hit]]
        return out

    def end(self):
        return self.breaks[-1]


def stencil(curves, mu):
    """The four curves' indices and Lagrange weights in 1/mu (one at a node)."""
    for k, c in enumerate(curves):
        if abs(c["tabor"] / mu - 1) < 1e-12:
            return [(k, 1.0)]
    above = next(k for k, c in enumerate(curves) if c["tabor"] >= mu)
    first = max(above - 2, 0)
    ks = list(range(first, first + 4))
    side = mu >= CUSP
    assert all(curves[k]["jumps"] == side for k in ks), "stencil across the cusp"
    x = 1 / mu
    xs = [1 / curves[k]["tabor"] for k in ks]
    out = []
    for i, k in enumerate(ks):
        w = 1.0
        for j in range(4):
            if j != i:
                w *= (x - xs[j]) / (xs[i] - xs[j])
        out.append((k, w))
    return out


def integral(parts, ell, h, ln_c, b):
    """I e^kappa by two rules on the same pieces: QUADPACK (scipy.integrate.quad, adaptive
    Gauss-Kronrod 21, to 1e-13 on each piece) and composite Gauss-Legendre of order 48 on each piece cut in
    eight; and the whole weight beyond the sampled part, int_top^inf Delta phi e^kappa."""
    scale = ell ** -1.5
    top = min(c.end() for c, _ in parts) / ell

    def ln_x(x):
        d = np.asarray(x, dtype=float) ** 2
        p = scale * sum(float(w) * c.load(ell * d) for c, w in parts)
        with np.errstate(divide="ignore"):
            return ln_c + b * p / d

    def f(x):
        x = np.atleast_1d(np.asarray(x, dtype=float))
        d = x * x
        out = np.zeros_like(x)
        ok = d > 0
        lx = ln_x(x[ok])
        removal = -np.expm1(-np.exp(np.minimum(lx, 700.0)))
        dd = d[ok]
        weight = np.exp(-dd * (h + 0.5 * dd)) if h > 0 else np.exp(-0.5 * (h + dd) ** 2)
        out[ok] = dd * removal * weight * 2.0 * x[ok]
        return out

    x_top = math.sqrt(top)
    cuts = {0.0, x_top}
    for c, _ in parts:
        for br in c.breaks:
            d = br / ell
            if 0 < d < top:
                cuts.add(math.sqrt(d))
    # The weight's peak region and its e^-50 edges (twenty uniform pieces), and uniform pieces
    # in x over the whole range.
    lo_u, hi_u = max(-h - 10, 0), max(-h + 10, 0)
    for i in range(21):
        d = lo_u + (hi_u - lo_u) * i / 20
        if 0 < d < top:
            cuts.add(math.sqrt(d))
    for i in range(1, 40):
        cuts.add(x_top * i / 40)
    # Geometric cuts towards 0, where s has its pole (and, for large h, the peak lies).
    x = x_top
    for _ in range(60):
        x /= 2
        cuts.add(x)
    cuts = sorted(cuts)
    # The saturation front: ln x = 0 between neighbouring cuts.
    extra = []
    for a, bb in zip(cuts, cuts[1:]):
        fa = ln_x(a)[0] if a > 0 else -np.inf
        fb = ln_x(bb)[0]
        if (fa > 0) != (fb > 0):
            lo, hi = a, bb
            for _ in range(200):
                m = 0.5 * (lo + hi)
                if m <= lo or m >= hi:
                    break
                if (ln_x(m)[0] > 0) == (fa > 0):
                    lo = m
                else:
                    hi = m
            extra.append(0.5 * (lo + hi))
    cuts = sorted(set(cuts) | set(extra))
    quadpack = 0.0
    for a, bb in zip(cuts, cuts[1:]):
        quadpack += quad(lambda t: f(t)[0], a, bb, epsabs=0.0, epsrel=1e-13, limit=200)[0]
    nodes, weights = np.polynomial.legendre.leggauss(48)
    legendre = 0.0
    for a, bb in zip(cuts, cuts[1:]):
        for k in range(8):
            lo = a + (bb - a) * k / 8
            hi = a + (bb - a) * (k + 1) / 8
            legendre += 0.5 * (hi - lo) * np.dot(weights, f(0.5 * (lo + hi) + 0.5 * (hi - lo) * nodes))
    u = h + top
    kappa = 0.5 * h * h if h > 0 else 0.0
    # erfc(z) = erfcx(z) e^{-z^2}, z = u/sqrt(2) > 0 here.
    beyond = math.exp(kappa - 0.5 * u * u) * (1.0 + top * math.sqrt(math.pi / 2) * erfcx(u / math.sqrt(2)))
    return quadpack, legendre, beyond


def main():
    curves = read_table(TABLE)
    contacts = {}
    mus = [0.05, 0.1254, 0.3258809260931582, 0.45, 2.0, 4.0]
    ells = [1.5, 4.0, 12.0]
    hs = [-4.0, -1.0, 0.0, 1.5, 4.0, 12.0, 60.0]
    kernels = [(-69.0, 0.0), (-69.0, 3.0), (-27.6, 0.5), (-27.6, 20.0), (-3.0, 3.0), (0.0, 8.0),
               (13.8, 0.5), (-10.0, 20.0), (-3.0, 12.0)]
    print("# wearopt reference: the stress-assisted wear integral under the Lennard-Jones law (docs/model.md §12)")
    print("# generated by: /work/venv-testers/bin/python scripts/reference_stress_assisted_lj.py "
          "> tests/data/reference_stress_assisted_lj.csv (numpy %s, scipy %s)" % (np.__version__, scipy.__version__))
    print("# value = I e^kappa, I = int_0^inf Delta (1 - exp(-c e^{b p/Delta})) e^{-(h+Delta)^2/2} dDelta, "
          "kappa = h^2/2 for h > 0; p the table's curves interpolated in 1/mu; c_h = infinity; "
          "difference = |QUADPACK - Gauss-Legendre| / value")
    print("tabor,ell,h,ln_c,b,value,difference")
    start = time.time()
    row = 0
    for mu in mus:
        st = stencil(curves, mu)
        for k, _ in st:
            if k not in contacts:
                contacts[k] = Contact(curves[k])
        parts = [(contacts[k], w) for k, w in st]
        for ell in ells:
            top = min(contacts[k].end() for k, _ in st) / ell
            # Two separations each, cycling through hs, among those where the sampled
            # part holds the weight (h + top >= 8; the rows check it below).
            usable = [h for h in hs if h + top >= 8]
            for i in range(2):
                h = usable[(row + 3 * i) % len(usable)]
                ln_c, b = kernels[row % len(kernels)]
                row += 1
                ts, gl, beyond = integral(parts, ell, h, ln_c, b)
                if not ts > 0:
                    continue
                diff = abs(ts - gl) / ts
                if diff > 1e-11 or beyond > 1e-13 * ts:
                    print("skipped mu=%g ell=%g h=%g: difference %.3g, beyond %.3g" %
                          (mu, ell, h, diff, beyond / ts), file=sys.stderr)
                    continue
                print("%r,%r,%r,%r,%r,%.17g,%.3g" % (mu, ell, h, ln_c, b, ts, diff))
                sys.stdout.flush()
    print("done in %.0f s" % (time.time() - start), file=sys.stderr)


if __name__ == "__main__":
    main()
