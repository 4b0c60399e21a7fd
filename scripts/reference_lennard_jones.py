#!/usr/bin/env python3
"""Independent reference solver: an elastic sphere with Lennard-Jones surface forces.

WHAT
    The adhesive sphere of Muller, Yushchenko & Derjaguin (1980), Greenwood (1997) and Feng (2000):
    a sphere of radius R and composite modulus E (K = 4E/3) against a rigid flat, with the traction
    p(g) = (8 gamma / (3 Z0)) [(Z0/g)^9 - (Z0/g)^3] (p > 0 repulsive) acting across the gap
        g(r) = Z0 - delta + r^2/(2R) + w(r),
        w(r) = (4/(pi E)) int_0^inf p(s) s/(r+s) K(2 sqrt(rs)/(r+s)) ds      (K: modulus k),
    load P = 2 pi int p r dr. Writes two tables (Maugis units, P^ = P/(pi gamma R),
    delta^ = delta (K^2/(pi^2 gamma^2 R))^(1/3), a^ = a (K/(pi gamma R^2))^(1/3),
    mu = (R gamma^2/(E^2 Z0^3))^(1/3)):

      reference_lennard_jones_points.csv   mu, central_gap (= g(0)/Z0), interference delta^, load P^,
                                           contact_radius a^ (outermost radius where g = 3^(1/6) Z0,
                                           0 if g > 3^(1/6) Z0 everywhere), error_estimate
      reference_lennard_jones_extrema.csv  per mu: pull-off (most negative P^ over the curve) and the
                                           turning points of delta^(g0) (jump in / jump out)

NON-DIMENSIONAL FORM (re-derived)
    r = l r^, l = (pi gamma R^2/K)^(1/3); gaps g = e0 g^, e0 = l^2/R = (pi^2 gamma^2 R/K^2)^(1/3)
    (so delta^ and a^ are the Maugis variables); p = (gamma R/l^2) p~. Then
        z0 = Z0/e0 = 1/(mu (9 pi^2/16)^(1/3)),   p~(g) = (8/(3 z0)) [(z0/g)^9 - (z0/g)^3],
        g(r) = z0 - delta^ + r^2/2 + (16/(3 pi^2)) int p~(s) s/(r+s) K(k) ds,   P^ = 2 int p~ r dr.
    (4/(pi E)) (gamma R/l^2) l / e0 = (4/(pi E)) gamma R^2/l^3 = (4/(pi E)) (K/pi) = 16/(3 pi^2).
    Tail beyond the mesh (gap taken rigid there, dg = r dr): 2 int_{r_m}^inf p~ r dr = 2 int_{g_m}^inf p~ dg
        = (16/3) [(z0/g_m)^8/8 - (z0/g_m)^2/2]   (= 2 W(g_m) with W = (8/3)[...], the work per area).
    Rigid limit: P^ = (2/3)[(Z0/D)^8 - 4 (Z0/D)^2] (Bradley), minimum -2 at D = Z0.

METHOD (independent of the Rust solver's piecewise-constant rings)
    * Pressure is a continuous piecewise polynomial of degree q (default 4; Gauss-Lobatto nodes in each
      element) on a graded mesh 0 = r_0 < ... < r_N = 2000; collocation at every node.
    * Influence coefficients int G(r_i, s) L_k(s) ds by Gauss-Legendre (12 points) on panels no
      closer to r_i (or -r_i) than their length, halving panels that are closer; on the elements
      that contain r_i, double-exponential (tanh-sinh) quadrature split at r_i, which integrates the
      logarithmic singularity K(k) ~ ln(4/k') to rounding. K is scipy.special.ellipk(m) for
      m = k^2 < 1/2 and ellipkm1(k'^2) with k' = |r - s|/(r + s) from the exact difference.
      Load weights 2 int L_k s ds are exact; beyond r = 2000 the closed-form rigid tail is added.
    * Unknowns: nodal gaps and delta^; control: the central gap g_0 = central_gap * z0 (Greenwood's
      choice). Newton with dense LU until |dg/g| < 1e-9, plus one more step (rounding floor ~1e-12
      at mu = 10). d delta^/dg0 and dP^/dg0 by implicit differentiation of the converged system.
    * Mesh map (fixed and smooth for a given state; level L has L * ceil(t(2000)) elements):
        t(r) = 8 asinh(r/rc) + 5 [asinh((r - a)/w) + asinh(a/w)],
      rc ~ max(0.7 sqrt(g0), contact radius); (a, w) = the contact edge (where g = 3^(1/6) z0) and
      the distance from there to g = 2 z0; out of contact a = 0 and w = the radius where the gap
      has risen by z0/2 (the "neck" that the attraction pulls out of the apex at large mu).
    * The curve is followed from far out (central gap 3, or further out until d delta/dg0 < 0) by
      continuation in g0 with a tangent predictor and re-meshing as the edge moves. Once a sharp
      contact edge exists (w < a/4: mu >~ 2) the contact branch is followed in the contact radius
      instead (the gap at r = a held at 3^(1/6) z0 by the integral; predictor: the previous
      profiles in the scaled radius r/a), because in g0 the edge zone travels many widths for a
      tiny change of g0 and a linear predictor fails.
    * Tabulated points: re-solved at the prescribed central gap on a family tailored to that state,
      levels 1, 2, 4 (q = 4); value = level 4; error_estimate = max |level 4 - level 2| over
      interference, load and contact radius. Level 4 agrees with level 8 far better than that
      (e.g. 1e-12 against estimates of 1e-10), so the estimate is a generous bound.
    * Extrema: roots of d delta^/dg0 and dP^/dg0 (bracketed by sign changes along the trace) by
      Brent's method, in g0 or (contact branch, large mu) in the contact radius, at levels 1, 2, 4
      of one family tailored to the root; estimate = |level 4 - level 2|.
    * Contact radius: outermost root of g(r) = 3^(1/6) z0 with g(r) evaluated by the integral.

CHECKS (--only checks, about 2 minutes): Bradley limit (mu = 0.01, 0.02: P^ -> (2/3)[c^-8 - 4c^-2],
    pull-off deficit ~ mu^1.5), JKR at mu = 10 (P^(a^), delta^(a^) within ~1-3 %), Maugis-Dugdale
    pull-off at lambda = 1.16 mu (Maugis 1992 equations solved here), q = 3 against q = 4.

USAGE
    target/venv/bin/python scripts/reference_lennard_jones.py --out tests/data   # both tables
    options: --mu 0.5,1 (a subset; the tables are still written to --out), --only points|extrema|
             checks (repeatable), --fast (extrema at levels 1 and 2 only)
    Dependencies: numpy, scipy (mpmath is not needed). Run with OMP_NUM_THREADS=1.
    Run time (one core, 2-core machine shared with a Rust build): about 13 minutes (788 s) for both
    tables (mu = 10 alone about a third of it); --only checks about 2 minutes.
"""

import argparse
import math
import os
import sys
import time

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipk, ellipkm1

CW = 16.0 / (3.0 * np.pi ** 2)
GT = 3.0 ** (1.0 / 6.0)  # gap of the largest tension, in units of z0
RMAX = 2000.0

# ------------------------------------------------------------------ quadrature rules
GL_N = 12
_glx, _glw = np.polynomial.legendre.leggauss(GL_N)
GLX = 0.5 * (_glx + 1.0)
GLW = 0.5 * _glw


def de_rule(h=1.0 / 12, T=3.3):
    """tanh-sinh on [0,1]: nodes as distances from the left end x and from the right end xc."""
    t = np.arange(-T, T + 1e-12, h)
    u = np.pi * np.sinh(t)
    x = 1.0 / (1.0 + np.exp(-u))
    xc = 1.0 / (1.0 + np.exp(u))
    w = h * (np.pi / 2) * np.cosh(t) / (2.0 * np.cosh(u / 2) ** 2)
    return x, xc, w


DEX, DEXC, DEW = de_rule()


def kernel(r, s, diff, summ):
    """s/(r+s) K(k), k = 2 sqrt(rs)/(r+s); diff = r - s and summ = r + s given accurately."""
    m = 4.0 * r * s / summ ** 2
    p1 = (diff / summ) ** 2
    small = m < 0.5
    K = np.empty(np.broadcast(m, p1).shape)
    K[small] = ellipk(m[small])
    K[~small] = ellipkm1(np.maximum(p1[~small], 1e-300))
    return s / summ * K


def local_nodes(q):
    if q == 1:
        return np.array([0.0, 1.0])
    from numpy.polynomial import legendre as L
    c = np.zeros(q + 1)
    c[-1] = 1
    inner = L.legroots(L.legder(c))
    return np.concatenate([[0.0], 0.5 * (np.sort(inner) + 1), [1.0]])


_VINV = {}


def lagrange(xi_nodes, x):
    """values of the Lagrange basis on xi_nodes at the points x: shape (len(x), q + 1)."""
    key = tuple(xi_nodes)
    if key not in _VINV:
        _VINV[key] = np.linalg.inv(np.vander(2 * np.asarray(xi_nodes) - 1, increasing=True))
    return np.vander(2 * np.asarray(x, float) - 1, len(xi_nodes), increasing=True) @ _VINV[key]


class Mesh:
    def __init__(self, edges, q):
        self.edges = np.asarray(edges, float)
        self.q = q
        self.xi = local_nodes(q)
        ne = len(edges) - 1
        self.ne = ne
        a, b = self.edges[:-1], self.edges[1:]
        self.conn = np.arange(ne)[:, None] * q + np.arange(q + 1)[None, :]
        self.n = ne * q + 1
        self.r = np.empty(self.n)
        self.r[self.conn] = a[:, None] + (b - a)[:, None] * self.xi[None, :]
        self.r[self.conn[:, 0]] = a
        self.r[-1] = b[-1]


def _near_and_singular(mesh, r, j, out):
    """elements closer to r than their length (halved recursively) or containing r (tanh-sinh)."""
    E = mesh.edges
    aj, bj = E[j], E[j + 1]
    Lj = bj - aj
    if aj <= r <= bj:
        if r > aj:
            pl = r - aj
            dist = pl * DEXC
            s = r - dist
            G = kernel(r, s, dist, r + s)
            out[mesh.conn[j]] += (G * DEW * pl) @ lagrange(mesh.xi, (s - aj) / Lj)
        if bj > r:
            pl = bj - r
            dist = pl * DEX
            s = r + dist
            G = kernel(r, s, -dist, r + s)
            out[mesh.conn[j]] += (G * DEW * pl) @ lagrange(mesh.xi, (s - aj) / Lj)
        return
    stack = [(aj, bj)]
    while stack:
        pa, pb = stack.pop()
        pl = pb - pa
        pd = max(pa - r, r - pb, 0.0)
        if r > 0:
            pd = min(pd, pa + r)
        if pd >= pl:
            s = pa + pl * GLX
            G = kernel(r, s, r - s, r + s)
            out[mesh.conn[j]] += (G * GLW * pl) @ lagrange(mesh.xi, (s - aj) / Lj)
        else:
            pm = 0.5 * (pa + pb)
            stack.append((pa, pm))
            stack.append((pm, pb))


def _good(mesh, r):
    E = mesh.edges
    a, b = E[:-1], E[1:]
    L = b - a
    r = np.asarray(r)[:, None]
    d = np.maximum(np.maximum(a[None, :] - r, r - b[None, :]), 0.0)
    dd = np.where(r > 0, np.minimum(d, a[None, :] + r), d)
    sing = (r >= a[None, :]) & (r <= b[None, :])
    return (~sing) & (dd >= L[None, :])


def influence(mesh, pts, chunk=64):
    """M[i, j] = int G(pts_i, s) phi_j(s) ds for all global basis functions phi_j."""
    pts = np.asarray(pts, float)
    E = mesh.edges
    a, L = E[:-1], np.diff(E)
    B = lagrange(mesh.xi, GLX)
    s = a[:, None] + L[:, None] * GLX[None, :]              # (ne, 12)
    wgt = GLW[None, :] * L[:, None]
    M = np.zeros((len(pts), mesh.n))
    for i0 in range(0, len(pts), chunk):
        rr = pts[i0:i0 + chunk]
        good = _good(mesh, rr)                                # (nc, ne)
        R3 = rr[:, None, None]
        G = kernel(R3, s[None], R3 - s[None], R3 + s[None])   # (nc, ne, 12)
        G = np.where(good[:, :, None], G, 0.0)
        vals = np.einsum('cek,ek,kq->ceq', G, wgt, B)         # (nc, ne, q+1)
        for k in range(len(mesh.xi)):
            # scatter: basis k of element e is global node conn[e, k]
            np.add.at(M[i0:i0 + chunk].T, mesh.conn[:, k], vals[:, :, k].T)
        for ii, r in enumerate(rr):
            for j in np.nonzero(~good[ii])[0]:
                _near_and_singular(mesh, r, j, M[i0 + ii])
    return M


def row_integrals(mesh, r):
    return influence(mesh, [r])[0]


def load_weights(mesh):
    """2 int phi_j s ds (exact: Gauss-Legendre on polynomials of degree q + 1)."""
    E = mesh.edges
    a, b = E[:-1], E[1:]
    L = b - a
    s = a[:, None] + L[:, None] * GLX[None, :]
    vals = (2.0 * s * GLW[None, :] * L[:, None]) @ lagrange(mesh.xi, GLX)
    out = np.zeros(mesh.n)
    np.add.at(out, mesh.conn, vals)
    return out


def eval_interp(mesh, vals, x):
    E = mesh.edges
    x = np.clip(x, 0, E[-1])
    j = np.clip(np.searchsorted(E, x, side='right') - 1, 0, mesh.ne - 1)
    xi = (x - E[j]) / (E[j + 1] - E[j])
    out = np.zeros_like(x)
    q1 = len(mesh.xi)
    for k in range(q1):
        Lk = np.ones_like(x)
        for l in range(q1):
            if l != k:
                Lk *= (xi - mesh.xi[l]) / (mesh.xi[k] - mesh.xi[l])
        out += Lk * vals[mesh.conn[j, k]]
    return out


# ------------------------------------------------------------------ the law


def z0_of_mu(mu):
    return 1.0 / (mu * (9 * np.pi ** 2 / 16) ** (1.0 / 3))


def pressure(g, z0):
    x3 = (z0 / g) ** 3
    return (8.0 / (3 * z0)) * (x3 * x3 * x3 - x3)


def dpressure(g, z0):
    x3 = (z0 / g) ** 3
    return (8.0 / (3 * z0)) * (-9 * x3 * x3 * x3 + 3 * x3) / g


def tail_load(gN, z0):
    x = z0 / gN
    return (16.0 / 3) * (x ** 8 / 8 - x ** 2 / 2)


def bradley(c):
    """rigid sphere, P^ at central gap D = c Z0."""
    return (2.0 / 3) * (c ** -8 - 4 * c ** -2)


# ------------------------------------------------------------------ mesh families


def make_edges(t, dt, rmax, nel):
    tt = np.linspace(0, t(rmax), nel + 1)
    lo = np.zeros_like(tt)
    hi = np.full_like(tt, rmax)
    r = 0.5 * (lo + hi)
    for _ in range(300):
        f = t(r) - tt
        lo = np.where(f < 0, r, lo)
        hi = np.where(f > 0, r, hi)
        rn = r - f / dt(r)
        bad = (rn <= lo) | (rn >= hi)
        rn = np.where(bad, 0.5 * (lo + hi), rn)
        done = np.max(np.abs(rn - r) / (1 + r)) < 1e-16
        r = rn
        if done:
            break
    r[0] = 0.0
    r[-1] = rmax
    return r


class Family:
    """fixed smooth mesh map t(r); level L -> L * nel0 elements (nested refinement in t)."""

    def __init__(self, rc, edge=None, c1=8.0, c2=5.0, rmax=RMAX):
        self.rc, self.edge, self.c1, self.c2, self.rmax = rc, edge, c1, c2, rmax

        def t(r):
            v = c1 * np.arcsinh(r / rc)
            if edge is not None:
                a, w = edge
                v = v + c2 * (np.arcsinh((r - a) / w) + np.arcsinh(a / w))
            return v

        def dt(r):
            v = c1 / np.sqrt(r * r + rc * rc)
            if edge is not None:
                a, w = edge
                v = v + c2 / np.sqrt((r - a) ** 2 + w * w)
            return v

        self.t, self.dt = t, dt
        self.nel0 = int(np.ceil(t(rmax)))

    def mesh(self, level, q):
        return Mesh(make_edges(self.t, self.dt, self.rmax, self.nel0 * level), q)


def crossing(mesh, g, level):
    """outermost radius where the interpolant of g equals level (None if g > level everywhere)."""
    below = np.nonzero(g <= level)[0]
    if len(below) == 0:
        return None
    i = below[-1]
    if i == mesh.n - 1:
        return mesh.r[-1]
    f = lambda x: eval_interp(mesh, g, np.array([x]))[0] - level
    return brentq(f, mesh.r[i], mesh.r[i + 1], xtol=1e-15, rtol=1e-15)


def family_for(z0, c, mesh, g):
    rc = 0.7 * np.sqrt(c * z0)
    a = crossing(mesh, g, GT * z0)
    if a is not None and a > 0:
        # refine around the contact edge (also when it is diffuse: the contact radius is read
        # off the gap between nodes there, which converges only like the interpolation)
        r2 = crossing(mesh, g, 2.0 * z0)
        w = max(r2 - a, 1e-7)
        return Family(max(rc, a), (a, w))
    # out of contact (or a small contact): resolve the neck at the apex
    w0 = crossing(mesh, g, g[0] + 0.5 * z0)
    rc = max(rc, a or 0.0)
    if w0 is not None and w0 < 0.5 * rc:
        return Family(rc, (0.0, max(w0, 1e-7)))
    return Family(rc, None)


def fam_changed(f1, f2, tol=0.5):
    if (f1.edge is None) != (f2.edge is None):
        return True
    if abs(np.log(f1.rc / f2.rc)) > 0.3:
        return True
    if f1.edge is not None:
        a1, w1 = f1.edge
        a2, w2 = f2.edge
        if abs(a1 - a2) > tol * w1 or abs(np.log(w1 / w2)) > 0.4:
            return True
    return False


# ------------------------------------------------------------------ the discrete problem


class Problem:
    def __init__(self, mu, mesh):
        self.mu = mu
        self.z0 = z0_of_mu(mu)
        self.mesh = mesh
        self.A = CW * influence(mesh, mesh.r)
        self.wl = load_weights(mesh)

    def load(self, g):
        return self.wl @ pressure(g, self.z0) + tail_load(g[-1], self.z0)

    def gap_at(self, rr, g, delta):
        row = CW * row_integrals(self.mesh, rr)
        return self.z0 - delta + 0.5 * rr * rr + row @ pressure(g, self.z0)

    def contact_radius(self, g, delta):
        """outermost root of g(r) = 3^(1/6) z0 with g(r) from the integral (0 if none)."""
        lev = GT * self.z0
        below = np.nonzero(g <= lev)[0]
        if len(below) == 0:
            return 0.0
        i = below[-1]
        r = self.mesh.r
        f = lambda x: self.gap_at(x, g, delta) - lev
        lo, hi = r[i], r[min(i + 1, len(r) - 1)]
        if f(lo) > 0:  # interpolation noise at a nearly tangent crossing
            lo = r[max(i - 1, 0)]
        return brentq(f, lo, hi, xtol=1e-15, rtol=1e-15)

    def jacobian(self, g):
        n = self.mesh.n
        J = -self.A * dpressure(g, self.z0)[None, :]
        J[np.arange(n), np.arange(n)] += 1.0
        J[:, 0] = 1.0  # column 0 is delta (g_0 = c z0 is prescribed)
        return J

    def newton(self, g0c, g, delta, tol=1e-13, maxit=40):
        r = self.mesh.r
        z0 = self.z0
        g = g.copy()
        g[0] = g0c
        last = np.inf
        for it in range(maxit):
            F = g - z0 + delta - 0.5 * r * r - self.A @ pressure(g, z0)
            try:
                dx = np.linalg.solve(self.jacobian(g), -F)
            except np.linalg.LinAlgError:
                return None
            if not np.all(np.isfinite(dx)):
                return None
            dg = dx.copy()
            dg[0] = 0.0
            if np.any(g + dg <= 0.2 * g):
                return None
            g = g + dg
            delta = delta + dx[0]
            err = np.max(np.abs(dg) / g)
            if err < tol or last < 1e-9:
                # quadratic convergence: one step after |dg/g| < 1e-9 is at the rounding floor
                # (~1e-12 relative at mu = 10, where the Jacobian's condition number is ~1e6)
                return g, delta, it + 1
            if it > 6 and err > last:
                return None
            last = err
        return None

    def newton_a(self, a, g, delta, tol=1e-13, maxit=40):
        """Newton with the contact radius prescribed instead of the central gap: the gap at r = a
        (by the integral, a need not be a node) equals 3^(1/6) z0; unknowns all g_i and delta."""
        r = self.mesh.r
        z0 = self.z0
        n = self.mesh.n
        ra = CW * row_integrals(self.mesh, a)
        g = g.copy()
        last = np.inf
        for it in range(maxit):
            p = pressure(g, z0)
            pp = dpressure(g, z0)
            F = np.empty(n + 1)
            F[:n] = g - z0 + delta - 0.5 * r * r - self.A @ p
            F[n] = z0 - delta + 0.5 * a * a + ra @ p - GT * z0
            J = np.empty((n + 1, n + 1))
            J[:n, :n] = -self.A * pp[None, :]
            J[np.arange(n), np.arange(n)] += 1.0
            J[:n, n] = 1.0
            J[n, :n] = ra * pp
            J[n, n] = -1.0
            try:
                dx = np.linalg.solve(J, -F)
            except np.linalg.LinAlgError:
                return None
            if not np.all(np.isfinite(dx)):
                return None
            dg = dx[:n]
            if np.any(g + dg <= 0.2 * g):
                return None
            g = g + dg
            delta = delta + dx[n]
            err = np.max(np.abs(dg) / g)
            if err < tol or last < 1e-9:
                return g, delta, it + 1
            if it > 6 and err > last:
                return None
            last = err
        return None

    def tangent(self, g):
        """dg/d(g0), d delta/d(g0), dP/d(g0) at a converged state."""
        z0 = self.z0
        dFdc = -self.A[:, 0] * dpressure(g[0:1], z0)[0]
        dFdc[0] += 1.0
        dx = np.linalg.solve(self.jacobian(g), -dFdc)
        dg = dx.copy()
        dg[0] = 1.0
        x = z0 / g[-1]
        dtail = (16.0 / 3) * (-x ** 8 + x ** 2) / g[-1]
        dP = self.wl @ (dpressure(g, z0) * dg) + dtail * dg[-1]
        return dg, dx[0], dP


def solve_on(mu, fam, level, q, c, old_mesh, old_g, delta):
    pr = Problem(mu, fam.mesh(level, q))
    g0 = eval_interp(old_mesh, old_g, pr.mesh.r)
    res = pr.newton(c * pr.z0, g0, delta)
    if res is None:
        raise RuntimeError("Newton failed on a new mesh at c=%g (mu=%g)" % (c, mu))
    return pr, res[0], res[1]


# ------------------------------------------------------------------ continuation


def trace(mu, c_start, c_end, level=1, q=4, stops=(), log=None, switch_a=True):
    """follow the curve from c_start down to c_end; returns samples (dicts)."""
    z0 = z0_of_mu(mu)
    fam = Family(0.7 * np.sqrt(c_start * z0))
    pr = Problem(mu, fam.mesh(level, q))
    g = c_start * z0 + 0.5 * pr.mesh.r ** 2
    res = pr.newton(c_start * z0, g, 0.0)
    g, delta = res[0], res[1]
    nf = family_for(z0, c_start, pr.mesh, g)
    if fam_changed(fam, nf):
        fam = nf
        pr, g, delta = solve_on(mu, fam, level, q, c_start, pr.mesh, g, delta)
    c = c_start
    out = []
    h = 0.05
    nfail, its = 0, 0
    stops = sorted([s for s in stops if c_end < s < c_start], reverse=True)
    while True:
        dg, dd, dP = pr.tangent(g)
        P = pr.load(g)
        out.append(dict(c=c, delta=delta, P=P, dd=dd * z0, dP=dP * z0, g=g, pr=pr, fam=fam))
        if log:
            log("  trace mu=%g c=%.7f delta=% .9f P=% .9f ddelta/dc=% .3e dP/dc=% .3e n=%d its=%d "
                "fails=%d h=%.2e" % (mu, c, delta, P, dd * z0, dP * z0, pr.mesh.n, its, nfail, h))
        if c <= c_end + 1e-14:
            break
        # step: predicted changes of delta and P of at most ~10 % (+0.1 absolute)
        hb = min(0.1, (0.1 + 0.1 * abs(delta)) / (abs(dd * z0) + 1e-30),
                 (0.1 + 0.1 * abs(P)) / (abs(dP * z0) + 1e-30))
        h = min(h, hb) if h < hb else hb
        while True:
            cn = max(c - h, c_end)
            for s in stops:
                if c - 1e-14 > s > cn:
                    cn = s
            dc = (cn - c) * z0
            res = pr.newton(cn * z0, g + dc * dg, delta + dc * dd)
            if res is not None:
                break
            nfail += 1
            h *= 0.5
            if h < 1e-9:
                raise RuntimeError("continuation stalled at c=%g (mu=%g)" % (c, mu))
        g, delta, its = res
        c = cn
        h = min(0.1, h * (1.5 if its <= 4 else (0.7 if its >= 8 else 1.0)))
        nf = family_for(z0, c, pr.mesh, g)
        if fam_changed(fam, nf, tol=2.0):
            fam = nf
            pr, g, delta = solve_on(mu, fam, level, q, c, pr.mesh, g, delta)
        if (switch_a and fam.edge is not None and fam.edge[0] > 0
                and fam.edge[1] < 0.25 * fam.edge[0] and c > c_end):
            dg, dd, dP = pr.tangent(g)
            st = dict(c=c, delta=delta, P=pr.load(g), dd=dd * z0, dP=dP * z0, g=g, pr=pr, fam=fam)
            out.append(st)
            if log:
                log("  switching to contact-radius continuation at c=%.7f" % c)
            out += trace_a(mu, st, c_end, level, q, log)
            return out
    return out


def predict_scaled(hist, a, mesh):
    """gap profile at contact radius a from the last one or two states, in the scaled radius r/a
    (the edge zone travels with a; a linear predictor in a fixed r would smear it)."""
    g1 = eval_interp(hist[-1]['pr'].mesh, hist[-1]['g'], mesh.r * hist[-1]['a'] / a)
    d1 = hist[-1]['delta']
    if len(hist) < 2 or abs(hist[-1]['a'] - hist[-2]['a']) < 1e-9 * a:
        return g1, d1
    g0 = eval_interp(hist[-2]['pr'].mesh, hist[-2]['g'], mesh.r * hist[-2]['a'] / a)
    t = (a - hist[-1]['a']) / (hist[-1]['a'] - hist[-2]['a'])
    return g1 + t * (g1 - g0), d1 + t * (d1 - hist[-2]['delta'])


def family_at(z0, a, w, c):
    return Family(max(0.7 * np.sqrt(c * z0), a), (a, w))


def solve_a(mu, a, hist, level=1, q=4, fam=None, pr=None):
    """the state with contact radius a, on a mesh tailored to it (or on pr's mesh)."""
    z0 = z0_of_mu(mu)
    if pr is None:
        w = hist[-1]['fam'].edge[1]
        fam = fam or family_at(z0, a, w, hist[-1]['c'])
        pr = Problem(mu, fam.mesh(level, q))
    g, d = predict_scaled(hist, a, pr.mesh)
    res = pr.newton_a(a, g, d)
    if res is None and len(hist) > 1:
        res = pr.newton_a(a, *predict_scaled(hist[-1:], a, pr.mesh))
    if res is None:
        return None
    g, d, its = res
    dg, dd, dP = pr.tangent(g)
    return dict(c=g[0] / z0, delta=d, P=pr.load(g), dd=dd * z0, dP=dP * z0, g=g, pr=pr, fam=fam,
                a=a, its=its, mode='a')


def trace_a(mu, s0, c_end, level=1, q=4, log=None):
    """continue the contact branch in the contact radius a from the state s0 until c <= c_end."""
    z0 = z0_of_mu(mu)
    a0 = s0['pr'].contact_radius(s0['g'], s0['delta'])
    first = dict(s0, a=a0, mode='a')
    hist = [first]
    out = []
    da = 0.5 * s0['fam'].edge[1]
    while hist[-1]['c'] > c_end:
        an = hist[-1]['a'] + da
        st = solve_a(mu, an, hist, level, q)
        if st is None:
            da *= 0.5
            if da < 1e-6 * hist[-1]['a']:
                raise RuntimeError("contact continuation stalled at a=%g (mu=%g)" % (an, mu))
            continue
        # the mesh is re-tailored to the new state's edge width next step
        st['fam'] = family_for(z0, st['c'], st['pr'].mesh, st['g'])
        if st['fam'].edge is None or st['fam'].edge[0] <= 0:
            st['fam'] = family_at(z0, an, hist[-1]['fam'].edge[1], st['c'])
        hist.append(st)
        out.append(st)
        if log:
            log("  trace_a mu=%g a=%.6f c=%.9f delta=% .9f P=% .9f ddelta/dc=% .3e dP/dc=% .3e its=%d"
                " da=%.2e" % (mu, an, st['c'], st['delta'], st['P'], st['dd'], st['dP'], st['its'], da))
        da = min(da * (1.5 if st['its'] <= 5 else 1.0), 0.1 * an, 8 * st['fam'].edge[1])
    return out


def start_c(mu, log=None):
    """a central gap on the stable far branch (d delta/dc < 0), at least 3."""
    c = 3.0
    z0 = z0_of_mu(mu)
    while True:
        fam = Family(0.7 * np.sqrt(c * z0))
        pr = Problem(mu, fam.mesh(1, 4))
        res = pr.newton(c * z0, c * z0 + 0.5 * pr.mesh.r ** 2, 0.0)
        g, delta = res[0], res[1]
        dg, dd, dP = pr.tangent(g)
        if dd < 0:
            return c
        c *= 1.6
        if log:
            log("  mu=%g: far branch not stable at c=%g, starting further out" % (mu, c))


# ------------------------------------------------------------------ refined values


def nearest(samples, c):
    return min(samples, key=lambda s: abs(s['c'] - c))


class AStates:
    """states with the contact radius prescribed; each solve starts from the scaled profiles of the
    two cached states nearest in a. With pr=None every solve gets its own mesh tailored to its a
    (the edge refinement is accurate only within a few widths w of its centre)."""

    def __init__(self, pr, seeds, mu=None, w=None, level=1, q=4):
        self.pr = pr
        self.hist = list(seeds)
        self.mu, self.w, self.level, self.q = mu, w, level, q

    def solve(self, a):
        near = sorted(self.hist, key=lambda h: abs(h['a'] - a))
        if len(near) > 1 and abs(near[1]['a'] - near[0]['a']) < 1e-9 * a:
            near = [near[0]] + near[2:]
        pr = self.pr
        if pr is None:
            z0 = z0_of_mu(self.mu)
            pr = Problem(self.mu, family_at(z0, a, self.w, near[0]['c']).mesh(self.level, self.q))
        res = None
        for hs in ([near[1], near[0]] if len(near) > 1 else None, [near[0]]):
            if hs is None:
                continue
            res = pr.newton_a(a, *predict_scaled(hs, a, pr.mesh))
            if res is not None:
                break
        if res is None:
            raise RuntimeError("contact-radius Newton failed at a=%g" % a)
        g, d, _ = res
        z0 = pr.z0
        dg, dd, dP = pr.tangent(g)
        st = dict(pr=pr, g=g, delta=d, a=a, c=g[0] / z0, dd=dd * z0, dP=dP * z0)
        self.hist.append(st)
        return st


def bracket_pair(samples, c):
    """two consecutive samples (sorted by c) around the central gap c."""
    ss = sorted(samples, key=lambda s: s['c'])
    for s1, s2 in zip(ss[:-1], ss[1:]):
        if s1['c'] <= c <= s2['c']:
            return s1, s2
    return None


def refine_point(mu, c, samples, levels=(1, 2, 4), q=4):
    """delta, P, a at central gap c on a family tailored to the state, levels 1, 2, 4."""
    z0 = z0_of_mu(mu)
    s = nearest(samples, c)
    pair = bracket_pair(samples, c)
    if s['c'] != c and pair and pair[0].get('mode') == 'a' and pair[1].get('mode') == 'a':
        # contact branch followed in a: find a with c(a) = c on a mesh tailored near it
        s1, s2 = pair
        ast = AStates(None, [s1, s2], mu, s1['fam'].edge[1])
        a_star = brentq(lambda a: ast.solve(a)['c'] - c, s1['a'], s2['a'], xtol=1e-13, rtol=1e-15)
        st = ast.solve(a_star)
        pr = st['pr']
        mesh, g, d = pr.mesh, st['g'], st['delta']
        g = g.copy()
        g[0] = c * z0
        res = pr.newton(c * z0, g, d)
        g, d = res[0], res[1]
    else:
        mesh, g, d = s['pr'].mesh, s['g'], s['delta']
        if s['c'] != c:
            dg, dd, _ = s['pr'].tangent(g)
            dc = (c - s['c']) * z0
            res = s['pr'].newton(c * z0, g + dc * dg, d + dc * dd)
            g, d = res[0], res[1]
    fam = family_for(z0, c, mesh, g)
    vals = []
    for L in levels:
        pr, g, d = solve_on(mu, fam, L, q, c, mesh, g, d)
        mesh = pr.mesh
        vals.append(dict(level=L, n=mesh.n, delta=d, P=pr.load(g), a=pr.contact_radius(g, d)))
    return vals


def refine_root(mu, which, s_lo, s_hi, levels=(1, 2, 4), q=4):
    """root of d delta/dc (which='dd') or dP/dc ('dP') bracketed by two samples: in the central
    gap c, or in the contact radius a when both samples come from the contact-radius continuation.
    The mesh family is tailored to the first estimate of the root and fixed for all levels."""
    z0 = z0_of_mu(mu)
    f_lo, f_hi = s_lo[which], s_hi[which]
    amode = s_lo.get('mode') == 'a' and s_hi.get('mode') == 'a'
    x = (lambda st: st['a']) if amode else (lambda st: st['c'])
    lo, hi = sorted([x(s_lo), x(s_hi)])
    x_est = x(s_lo) + (x(s_hi) - x(s_lo)) * f_lo / (f_lo - f_hi)
    s = min((s_lo, s_hi), key=lambda st: abs(x(st) - x_est))
    if amode:
        # the root to ~1e-9 with a mesh tailored to every trial a, then one family for all levels
        w = s['fam'].edge[1]
        ast0 = AStates(None, [s_lo, s_hi], mu, w)
        x_est = brentq(lambda aa: ast0.solve(aa)[which], lo, hi, xtol=1e-9 * hi, rtol=1e-12)
        st0 = ast0.solve(x_est)
        fam = family_at(z0, x_est, w, st0['c'])
        s_lo = s_hi = dict(st0, fam=fam)
        lo, hi = x_est - 2 * w, x_est + 2 * w
    else:
        fam = family_for(z0, x_est, s['pr'].mesh, s['g'])
    out = []
    prev = None
    for L in levels:
        pr = Problem(mu, fam.mesh(L, q))
        if amode:
            seeds = [s_lo, s_hi] if prev is None else [prev]
            ast = AStates(pr, seeds)

            def F(xx):
                return ast.solve(xx)[which]
        else:
            src = s if prev is None else prev
            g0 = eval_interp(src['pr'].mesh, src['g'], pr.mesh.r)
            res = pr.newton(x(src) * z0, g0, src['delta'])
            if res is None:
                raise RuntimeError("Newton failed (root search) mu=%g" % mu)
            cache = dict(c=x(src), g=res[0], delta=res[1])

            def F(cc):
                dg, dd, dP = pr.tangent(cache['g'])
                dc = (cc - cache['c']) * z0
                r2 = pr.newton(cc * z0, cache['g'] + dc * dg, cache['delta'] + dc * dd)
                if r2 is None:
                    raise RuntimeError("Newton failed in root search mu=%g c=%g" % (mu, cc))
                cache.update(c=cc, g=r2[0], delta=r2[1])
                _, dd2, dP2 = pr.tangent(r2[0])
                return (dd2 if which == 'dd' else dP2) * z0
        if prev is None and not amode:
            a_, b_ = lo, hi
            fa, fb = F(a_), F(b_)
            for _ in range(4):  # the root may sit just outside the trace's bracket on this mesh
                if fa * fb <= 0:
                    break
                wd = b_ - a_
                a_, b_ = max(a_ - wd, 0.5 * a_), b_ + wd
                fa, fb = F(a_), F(b_)
            lo, hi = min(lo, a_), max(hi, b_)
        else:
            xp = x_est if prev is None else x(prev)
            wdt = max(1e-7 * abs(xp), 10 * abs(xp - x(out[-2])) if len(out) > 1 else 1e-6 * abs(xp))
            while True:
                a_, b_ = max(lo, xp - wdt), min(hi, xp + wdt)
                fa, fb = F(a_), F(b_)
                if fa * fb <= 0 or (a_ == lo and b_ == hi):
                    break
                wdt *= 8
        if fa * fb > 0:
            raise RuntimeError("lost the bracket mu=%g %s level %d [%.12g, %.12g] F = %g, %g (%s)" % (
                mu, which, L, a_, b_, fa, fb, "a" if amode else "c"))
        root = brentq(F, a_, b_, xtol=1e-14, rtol=1e-15, maxiter=200)
        if amode:
            st = ast.solve(root)
            g, d = st['g'], st['delta']
        else:
            F(root)
            g, d = cache['g'], cache['delta']
        prev = dict(pr=pr, g=g, delta=d, c=g[0] / z0, a=root if amode else None)
        out.append(dict(level=L, n=pr.mesh.n, c=g[0] / z0, delta=d, P=pr.load(g),
                        a=pr.contact_radius(g, d)))
        if amode:
            out[-1]['x'] = root
        prev['x'] = root
    return out


# ------------------------------------------------------------------ Maugis-Dugdale


def md_curve(lam):
    """load-controlled pull-off of the Maugis-Dugdale sphere (Maugis 1992, eqs. in Maugis units)."""

    def fm(m, a):
        s = math.sqrt(m * m - 1)
        at = math.atan(s)
        return (0.5 * lam * a * a * (s + (m * m - 2) * at)
                + (4.0 / 3) * lam * lam * a * (s * at - m + 1) - 1)

    def state(a):
        m = brentq(fm, 1.0 + 1e-15, 1e15, args=(a,), xtol=1e-15, rtol=1e-15, maxiter=1000)
        s = math.sqrt(m * m - 1)
        at = math.atan(s)
        P = a ** 3 - lam * a * a * (s + m * m * at)
        delta = a * a - (4.0 / 3) * a * lam * s
        return P, delta, m

    from scipy.optimize import minimize_scalar
    aa = np.exp(np.linspace(np.log(1e-5), np.log(5.0), 600))
    Ps = [state(a)[0] for a in aa]
    i = int(np.argmin(Ps))
    if i == 0:  # minimum in the limit a -> 0
        return Ps[0], aa[0]
    res = minimize_scalar(lambda a: state(a)[0], bounds=(aa[i - 1], aa[i + 1]), method='bounded',
                          options=dict(xatol=1e-10))
    return res.fun, res.x


# ------------------------------------------------------------------ tables

MUS = [0.05, 0.1, 0.3, 0.5, 1.0, 2.0, 3.0, 5.0, 10.0]


def central_gaps(mu):
    """far (3, 2), near contact (1.5, 1.2), contact (1.1 ... 0.98), compressed (last); the
    compressed end moves towards 1 as mu grows (at mu = 5, central gap 0.97 is already P^ ~ 40)."""
    if mu <= 2:
        return [3.0, 2.0, 1.5, 1.2, 1.1, 1.05, 1.0, 0.98, 0.95]
    if mu <= 3:
        return [3.0, 2.0, 1.5, 1.2, 1.1, 1.05, 1.02, 1.0, 0.98, 0.96]
    if mu <= 5:
        return [3.0, 2.0, 1.5, 1.2, 1.1, 1.05, 1.02, 1.0, 0.99, 0.98]
    return [3.0, 2.0, 1.5, 1.2, 1.1, 1.05, 1.02, 1.01, 1.0, 0.995, 0.99]


def fmt(x):
    return "%.15e" % x if x != 0 else "0"


def run_mu(mu, do_points, do_extrema, log, ext_levels):
    t0 = time.time()
    cs = central_gaps(mu)
    c0 = max(start_c(mu, log), 3.0)
    samples = trace(mu, c0, min(cs), stops=cs, log=None)
    log("mu=%g: traced %d states from c=%g to %g in %.0f s" % (mu, len(samples), c0, min(cs),
                                                               time.time() - t0))
    samples.sort(key=lambda s: s['c'])
    rows, ext = [], {}
    # sign changes of the derivatives along the curve
    turns = []
    pmins = []
    for s1, s2 in zip(samples[:-1], samples[1:]):
        if s1['dd'] * s2['dd'] < 0:
            turns.append((s1, s2))
        if s1['dP'] < 0 < s2['dP']:
            pmins.append((s1, s2))
    log("mu=%g: %d turning points of delta(c) at c ~ %s, %d local minima of P at c ~ %s" % (
        mu, len(turns), ["%.4f" % s1['c'] for s1, _ in turns], len(pmins),
        ["%.4f" % s1['c'] for s1, _ in pmins]))
    if do_points:
        # a point on each unstable branch (d delta/dc > 0): midway (in c) between its turning points
        extra = []
        cl = sorted([0.5 * (a['c'] + b['c']) for a, b in turns])
        for x, y in zip(cl[:-1], cl[1:]):
            mid = float(round(0.5 * (x + y), 4))
            if nearest(samples, mid)['dd'] > 0 and all(abs(mid - c) > 0.002 for c in cs):
                extra.append(mid)
        for c in sorted(cs + extra, reverse=True):
            vals = refine_point(mu, c, samples)
            v = vals[-1]
            err = max(abs(vals[-1][k] - vals[-2][k]) for k in ('delta', 'P', 'a'))
            rows.append((mu, c, v['delta'], v['P'], v['a'], err, vals))
            log("  mu=%g c=%.4f delta=% .13f P=% .13f a=%.13f err=%.1e (n=%s)" % (
                mu, c, v['delta'], v['P'], v['a'], err, [x['n'] for x in vals]))
    if do_extrema:
        mins = []
        for s1, s2 in pmins:
            r = refine_root(mu, 'dP', s1, s2, levels=ext_levels)
            mins.append(r)
            log("  mu=%g local min of P: c=%.10f P=% .13f delta=% .13f (levels %s, dP %.1e)" % (
                mu, r[-1]['c'], r[-1]['P'], r[-1]['delta'], [x['n'] for x in r],
                abs(r[-1]['P'] - r[-2]['P'])))
        tps = []
        for s1, s2 in turns:
            r = refine_root(mu, 'dd', s1, s2, levels=ext_levels)
            tps.append(r)
            log("  mu=%g turning point: c=%.10f delta=% .13f P=% .13f (levels %s, d %.1e)" % (
                mu, r[-1]['c'], r[-1]['delta'], r[-1]['P'], [x['n'] for x in r],
                max(abs(r[-1]['P'] - r[-2]['P']), abs(r[-1]['delta'] - r[-2]['delta']))))
        ext = dict(mins=mins, turns=tps)
    log("mu=%g done in %.0f s" % (mu, time.time() - t0))
    return rows, ext


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("--out", default="tests/data")
    ap.add_argument("--mu", default=",".join("%g" % m for m in MUS))
    ap.add_argument("--only", choices=["points", "extrema", "checks"], action="append")
    ap.add_argument("--fast", action="store_true", help="extrema at levels 1, 2 only")
    args = ap.parse_args()
    only = set(args.only or ["points", "extrema"])
    mus = [float(x) for x in args.mu.split(",")]

    def log(msg):
        print(msg, flush=True)

    T0 = time.time()
    if "checks" in only:
        run_checks(log)
    allrows, allext = [], []
    for mu in mus:
        if not ({"points", "extrema"} & only):
            break
        rows, ext = run_mu(mu, "points" in only, "extrema" in only, log,
                           (1, 2) if args.fast else (1, 2, 4))
        allrows += rows
        allext.append((mu, ext))
    log("total %.0f s" % (time.time() - T0))
    # writing is done by write_tables (separate, so that partial runs can be merged)
    write_tables(args.out, allrows, allext, only, time.time() - T0, sys.argv)


def run_checks(log):
    """Bradley (mu -> 0), JKR (mu = 10), Maugis-Dugdale pull-off, q = 3 vs q = 4."""
    log("check 1: Bradley rigid sphere, P^ = (2/3)[c^-8 - 4 c^-2], at mu = 0.01 and 0.02")
    for mu in (0.01, 0.02):
        cs = [3.0, 2.0, 1.5, 1.2, 1.0]
        smp = trace(mu, 3.0, 0.97, stops=cs)
        for c in cs:
            v = refine_point(mu, c, smp, levels=(1, 2))[-1]
            log("  mu=%g c=%.2f P=% .10f Bradley=% .10f diff=% .3e" % (mu, c, v['P'], bradley(c),
                                                                     v['P'] - bradley(c)))
        smp.sort(key=lambda x: x['c'])
        pm = [(a, b) for a, b in zip(smp[:-1], smp[1:]) if a['dP'] < 0 < b['dP']]
        r = refine_root(mu, 'dP', pm[0][0], pm[0][1], levels=(1, 2))[-1]
        log("  mu=%g pull-off P=%.10f at c=%.8f (Bradley: -2 at c=1)" % (mu, r['P'], r['c']))
    log("check 2: JKR at mu = 10 (contact branch): P^ vs a^^3 - sqrt(6 a^^3), delta^ vs a^^2 - (2/3)sqrt(6 a^)")
    mu = 10.0
    cs = [1.0, 0.995, 0.99]
    smp = trace(mu, start_c(mu), 0.99, stops=cs)
    for c in cs:
        v = refine_point(mu, c, smp, levels=(1, 2))[-1]
        a = v['a']
        log("  mu=10 c=%.3f a=%.6f P=% .6f JKR % .6f   delta=% .6f JKR % .6f" % (
            c, a, v['P'], a ** 3 - math.sqrt(6 * a ** 3), v['delta'], a * a - (2.0 / 3) * math.sqrt(6 * a)))
    log("check 3: Maugis-Dugdale load-controlled pull-off at lambda = 1.16 mu (Maugis 1992 equations)")
    for mu in MUS:
        P, a = md_curve(1.16 * mu)
        log("  mu=%g lambda=%.4f MD pull-off P^=%.8f at a^=%.6f" % (mu, 1.16 * mu, P, a))
    log("check 4: degree q = 3 (level 4) against q = 4 (level 4)")
    for mu, c in ((0.1, 1.0), (1.0, 1.2), (1.0, 0.98), (5.0, 1.3), (5.0, 0.99)):
        smp = trace(mu, start_c(mu), c - 1e-3, stops=[c])
        s = nearest(smp, c)
        v4 = refine_point(mu, c, smp, levels=(1, 2, 4), q=4)[-1]
        v3 = refine_point(mu, c, smp, levels=(4,), q=3)[-1]
        log("  mu=%g c=%.2f q4: delta=% .13f P=% .13f a=%.12f | q3-q4: %.1e %.1e %.1e" % (
            mu, c, v4['delta'], v4['P'], v4['a'], v3['delta'] - v4['delta'], v3['P'] - v4['P'],
            v3['a'] - v4['a']))


def write_tables(out, rows, exts, only, runtime, argv):
    os.makedirs(out, exist_ok=True)
    cmd = "python3 scripts/reference_lennard_jones.py " + " ".join(argv[1:])
    common = [
        "# wearopt reference table: elastic sphere with Lennard-Jones surface forces "
        "(Muller-Yushchenko-Derjaguin 1980, Greenwood 1997, Feng 2000)",
        "# generated by: %s  (numpy %s, scipy %s; run time %.0f s)" % (
            cmd, np.__version__, __import__("scipy").__version__, runtime),
        "# units (Maugis): load P/(pi gamma R), interference delta (K^2/(pi^2 gamma^2 R))^(1/3), "
        "radius a (K/(pi gamma R^2))^(1/3), mu = (R gamma^2/(E^2 Z0^3))^(1/3), K = 4E/3; "
        "p(g) = (8 gamma/(3 Z0))[(Z0/g)^9 - (Z0/g)^3]",
        "# method: continuous piecewise-quartic pressure (Gauss-Lobatto nodes), collocation at the "
        "nodes, exact (tanh-sinh) integration of the log-singular kernel, Newton on the nodal gaps "
        "with the central gap g(0) = central_gap * Z0 prescribed; mesh to r = 2000 (analytic tail "
        "beyond), graded to the contact edge, levels 1, 2, 4 (doubling); values from level 4",
    ]
    if "points" in only:
        worst = max((r[5] for r in rows), default=0.0)
        with open(os.path.join(out, "reference_lennard_jones_points.csv"), "w") as f:
            for l in common:
                f.write(l + "\n")
            f.write("# central_gap = g(0)/Z0; contact_radius = outermost radius where g = 3^(1/6) Z0 "
                    "(largest tension), 0 if none; error_estimate = max |level 4 - level 2| over "
                    "interference, load, contact_radius (absolute; worst %.1e)\n" % worst)
            f.write("mu,central_gap,interference,load,contact_radius,error_estimate\n")
            for mu, c, d, P, a, err, _ in rows:
                f.write("%g,%s,%s,%s,%s,%.1e\n" % (mu, repr(float(c)), fmt(d), fmt(P), fmt(a), err))
    if "extrema" in only:
        with open(os.path.join(out, "reference_lennard_jones_extrema.csv"), "w") as f:
            for l in common:
                f.write(l + "\n")
            f.write("# pull_off = most negative load over the curve (a root of dP/dg0); jump in / out = "
                    "the outermost / innermost turning point of interference(g0) (d delta/dg0 = 0); "
                    "empty where interference(g0) is monotonic\n")
            f.write("# extra columns: the central gaps (g(0)/Z0) of the three points and "
                    "error_estimate = max |level 4 - level 2| over the row (absolute)\n")
            for mu, ext in exts:
                tps = sorted(ext['turns'], key=lambda r: -r[-1]['c'])
                if len(tps) > 2:
                    f.write("# mu=%g has %d turning points of interference(g0): %s\n" % (
                        mu, len(tps), "; ".join("central_gap %.10f interference %.12f load %.12f" % (
                            r[-1]['c'], r[-1]['delta'], r[-1]['P']) for r in tps)))
                md, _ = md_curve(1.16 * mu)
                po = min(ext['mins'], key=lambda r: r[-1]['P'])
                f.write("# mu=%g: pull-off %.9f, Maugis-Dugdale (lambda = 1.16 mu) %.9f, "
                        "ratio %.5f\n" % (mu, po[-1]['P'], md, po[-1]['P'] / md))
            f.write("mu,pull_off_load,pull_off_interference,jump_in_interference,jump_in_load,"
                    "jump_out_interference,jump_out_load,pull_off_central_gap,jump_in_central_gap,"
                    "jump_out_central_gap,error_estimate\n")
            for mu, ext in exts:
                po = min(ext['mins'], key=lambda r: r[-1]['P'])
                tps = sorted(ext['turns'], key=lambda r: -r[-1]['c'])
                used = [po] + ([tps[0], tps[-1]] if tps else [])
                err = max(max(abs(r[-1][k] - r[-2][k]) for k in ('delta', 'P')) for r in used)
                cells = [fmt(po[-1]['P']), fmt(po[-1]['delta'])]
                if tps:
                    cells += [fmt(tps[0][-1]['delta']), fmt(tps[0][-1]['P']),
                              fmt(tps[-1][-1]['delta']), fmt(tps[-1][-1]['P'])]
                else:
                    cells += ["", "", "", ""]
                cells += ["%.12f" % po[-1]['c']]
                cells += ["%.12f" % tps[0][-1]['c'], "%.12f" % tps[-1][-1]['c']] if tps else ["", ""]
                f.write("%g,%s,%.1e\n" % (mu, ",".join(cells), err))


if __name__ == "__main__":
    main()
