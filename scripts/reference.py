#!/usr/bin/env python3
"""High-precision reference tables for the wearopt rough-surface adhesion/wear model.

WHAT
    Writes three CSV tables that the Rust tests compare against (at ~1e-12 relative):

      reference_points.csv   load P(h), its elastic and plastic parts, real contact area A(h),
                             plastic area Ap(h) and dP/dh on a grid of (theta, lambda, h),
                             plus the limits gamma = 0 ("no_adhesion"), H = inf
                             ("no_plasticity") and both ("gw", Greenwood-Williamson).
      reference_extrema.csv  every local extremum of P(h) (kind = min/max; the pull-off is the
                             deepest minimum, pull_off = yes) for a few (theta, lambda).
      reference_roots.csv    separation roots of P(h) = target (every root found, kind =
                             all_roots, and the one chosen by docs/model.md section 4, kind = chosen).

    The physics is docs/model.md (non-dimensional model, section 3):
      c_a = sqrt(6 pi / theta), c_d = 2/3 c_a, c_h = pi (18/pi^2)^(1/4) lambda^(1/4) / sqrt(theta),
      c_p = 2 c_h, c_0 = 2 pi / theta;  t = positive root of t^3 - c_h t - c_a = 0,
      Delta_c = t^4 - c_d t = t (c_h t + c_a/3);  w(D) = exp(-(h+D)^2/2);
      p_e(D) = D1^(3/2) - c_a D1^(3/4) with D = D1 - c_d D1^(1/4), D1 >= c_d^(4/3);
      p_p(D) = c_p D - c_0;
      P(h)  = int_0^Dc p_e w dD + int_Dc^inf p_p w dD,   A(h) = int_0^inf D w dD,
      Ap(h) = int_Dc^inf D w dD,   dP/dh = -int p(D) (h+D) w dD.
    gamma = 0: c_a = c_d = c_0 = 0, c_h given.  H = inf: c_h = inf, Delta_c = inf, no plastic part.

SCALING
    Every output is written as a scaled mantissa  value * exp(kappa), kappa = h^2/2 for h > 0
    and kappa = 0 for h <= 0 (so nothing underflows at large h).  The weight is evaluated in
    scaled form directly, exp(-h D - D^2/2) for h > 0, never as a difference of large exponents.
    In reference_extrema.csv, load_min_mantissa is the same scaled mantissa and
    log10_abs_load_min = log10 |P| of the unscaled value.

HOW / PRECISION
    mpmath (only mpmath and the standard library) at mp.dps = 40; closed forms at 40 + 30 digits.
    Every row is computed by two independent methods and the script refuses to write a row
    unless they agree to >= 25 significant digits (relative to max(|value|, sum of |parts|),
    where the parts are the non-cancelling pieces the value is assembled from):

      (1) substitution form: s = D1^(1/4), D = s^4 - c_d s, dD = (4 s^3 - c_d) ds,
          p_e = s^6 - c_a s^3, s from c_d^(1/3) to t -- a polynomial times a Gaussian, integrated
          with mpmath.quad (tanh-sinh); no root solve at the nodes.  Plastic parts, A and Ap in
          closed form with exp/erfc of u_c = h + Delta_c.
      (2) direct form: mpmath.quad over the actual interference D, with D1(D) obtained at every
          node by mpmath.findroot (Newton from a guaranteed upper bound); the plastic parts, A and
          Ap by quadrature as well.

    For gw rows, P and A (and dP/dh) are also checked against the parabolic-cylinder identities
    P = sqrt(2 pi) F_{3/2}(h), A = sqrt(2 pi) F_1(h), dP/dh = -(3/2) sqrt(2 pi) F_{1/2}(h),
    F_n(h) = Gamma(n+1) exp(-h^2/4) D_{-n-1}(h) / sqrt(2 pi) (mpmath.pcfd), and
    F_{3/2}(0) = 2^(1/4) Gamma(5/4) / sqrt(2 pi).

    Quadrature splitting and TRUNCATION: each integral (elastic part over [0, Dc], plastic part
    over [Dc, inf), area over [0, inf)) is split at the maximum of the weight on its interval
    and at the points where the weight has dropped by e^-0.25, e^-1, e^-4, e^-16, e^-64 from
    that maximum (for large h these are ~m/h apart, so quad always sees the narrow peak; for
    a long interval with a narrow weight quad only sees the window), at Delta_c, and, for the
    elastic part, at D0 * 4^k (D0 = c_d^(4/3)) below 1 where D1(D) has structure.  Each
    integral is TRUNCATED where the weight is below 1e-60 of its maximum on that interval
    (ln 1e60 = 138.2): the neglected tail is < 1e-55 of the retained integral, far below the
    40-digit working precision used for the 20 printed digits.  The truncation is per part, so
    a part that is tiny compared with the other (e.g. the elastic part deep in the plastic
    range) is still computed to full relative precision, not set to zero.

    Extrema: dP/dh is scanned (method 1) on a grid (step 0.1 from -(Dc+20) to 10, 0.25 to 40,
    then h/40) until P < 0, dP/dh > 0 and h*P*exp(h^2/2) is within 5 % of its limit p_e(0) =
    -c_a c_d / 3 (then P rises monotonically to 0-); each sign change of dP/dh is refined with
    mpmath.findroot (Anderson, bracketing) on (dP/dh)/|P| and P is evaluated there by both methods.
    Roots: P - target is scanned on the same grid (extended downwards in steps of max(1, |h|/20)
    while P < 1.01 * the largest target + 1; for h < -(Dc+17) P is linear and monotone), each sign change refined
    with findroot (Anderson) on log(P/T) in scaled form (on P / sum of |parts| for T = 0).

USAGE
    python3 scripts/reference.py --out tests/data            # full tables (~see README for time)
    python3 scripts/reference.py --out /tmp/ref --quick      # small subset, for a smoke test
    options: --jobs N (worker processes, default 2), --dps D (default 40)
"""

import argparse
import math
import multiprocessing
import os
import sys
import time

import mpmath
from mpmath import mp, mpf

DPS_DEFAULT = 40
AGREE_DIGITS = 25          # required agreement between the two methods
CUT_LOG = None             # ln(1e60), set in setup()
SPLIT_M = (0.25, 1, 4, 16, 64)   # split where the weight has dropped by e^-m
INF = mpmath.inf

THETAS = ["1e-3", "1e-2", "0.1", "1", "3", "10", "30", "100", "1e3", "1e4", "1e6", "1e8"]
LAMBDAS = ["1e-6", "1e-4", "1e-3", "1e-2", "0.125", "1", "5", "100", "1e4", "1e6"]
HS = ["-4", "-2", "-1", "0", "0.5", "1", "2", "3", "5", "8", "12", "20", "35", "60"]
CH_NOADH = ["1e-3", "0.1", "1", "10", "1e3"]
EXTRA_H = ["-10", "-25.489", "-28.838", "-50"]
EXTRA_TL = [("0.1", "1e-3"), ("1", "1")]


def setup(dps):
    global CUT_LOG
    mp.dps = dps
    CUT_LOG = mpmath.log(mpf(10) ** 60)


def num(s):
    """Input number: the IEEE double nearest to the decimal string (what Rust parses), exactly."""
    if s == "inf":
        return INF
    return mpf(float(s))


def fmt(x, digits=20):
    if x == INF:
        return "inf"
    if x == 0:
        return "0.0"
    s = mpmath.nstr(x, digits, min_fixed=1, max_fixed=0, strip_zeros=False)
    if "e" not in s:
        s += "e+0"
    return s


# ----------------------------------------------------------------------------------------------
# model
# ----------------------------------------------------------------------------------------------

class Model:
    def __init__(self, case, theta="inf", lam="inf", ch=None):
        # coefficients are computed and stored with 20 extra digits (mpf keeps its precision)
        with mp.workdps(mp.dps + 20):
            self._init(case, theta, lam, ch)

    def _init(self, case, theta, lam, ch):
        self.case, self.theta_s, self.lam_s = case, theta, lam
        pi = mp.pi
        if case in ("adhesive", "no_plasticity"):
            th = num(theta)
            self.c_a = mpmath.sqrt(6 * pi / th)
            self.c_0 = 2 * pi / th
        else:
            self.c_a = mpf(0)
            self.c_0 = mpf(0)
        self.c_d = 2 * self.c_a / 3
        if case == "adhesive":
            self.c_h = pi * mpmath.root(18 / pi ** 2, 4) * mpmath.root(num(lam), 4) / mpmath.sqrt(num(theta))
        elif case == "no_adhesion":
            self.c_h = num(ch)
        else:
            self.c_h = INF
        self.plastic = self.c_h != INF
        self.c_p = 2 * self.c_h if self.plastic else INF
        self.adh = self.c_a > 0
        self.s0 = mpmath.cbrt(self.c_d)                 # s at D = 0
        self.D0 = self.c_d ** (mpf(4) / 3)               # D1 at D = 0
        if self.plastic:
            self.t = self._transition()
            self.Dc = self.t * (self.c_h * self.t + self.c_a / 3)
        else:
            self.t = INF
            self.Dc = INF
        self.pe0 = -self.c_a * self.c_d / 3             # p_e(0)

    def _transition(self):
        if not self.adh:
            return mpmath.sqrt(self.c_h)
        with mp.workdps(mp.dps + 20):
            ch, ca = self.c_h, self.c_a
            t = mpmath.sqrt(ch) + mpmath.cbrt(ca)        # upper bound; Newton is monotone from here
            for _ in range(200):
                f = t ** 3 - ch * t - ca
                tn = t - f / (3 * t * t - ch)
                if abs(tn - t) <= abs(t) * mpf(10) ** (-mp.dps + 2):
                    t = tn
                    break
                t = tn
            assert abs(t ** 3 - ch * t - ca) <= mpf(10) ** (-mp.dps + 8) * (t ** 3 + ca)
            return +t

    # s(D) by monotone Newton (method 1 only uses this for split points / truncation limits)
    def s_of_D(self, D):
        if not self.adh:
            return mpmath.root(D, 4)
        if D == 0:
            return self.s0
        cd = self.c_d
        s = self.s0 + D / (3 * cd)                     # tangent at s0: upper bound (convexity)
        for _ in range(3):
            s = min(s, mpmath.root(D + cd * s, 4))     # still an upper bound
        for _ in range(200):
            f = s ** 4 - cd * s - D
            sn = s - f / (4 * s ** 3 - cd)
            if abs(sn - s) <= abs(s) * mpf(10) ** (-mp.dps - 5):
                return sn
            s = sn
        return s

    # D1(D) by mpmath.findroot (method 2)
    def D1_of_D(self, D):
        cd = self.c_d
        if D == 0:
            return self.D0
        g = self.D0 + D * 4 / 3                         # tangent at D0: upper bound (convexity)
        for _ in range(3):
            g = min(g, D + cd * mpmath.root(g, 4))
        f = lambda x: x - cd * mpmath.root(x, 4) - D
        df = lambda x: 1 - cd / (4 * mpmath.root(x, 4) ** 3)
        return mpmath.findroot(f, g, solver="newton", df=df)


# ----------------------------------------------------------------------------------------------
# weights, windows and split points
# ----------------------------------------------------------------------------------------------

def kappa(h):
    return h * h / 2 if h > 0 else mpf(0)


def log_w(h, D):
    """log of the scaled weight exp(kappa) * exp(-(h+D)^2/2), without cancellation."""
    if h > 0:
        return -h * D - D * D / 2
    u = h + D
    return -u * u / 2


def part_window(h, a, b):
    """Truncated window of [a, b] (b may be inf): the part of [a, b] where the weight
    exp(-(h+D)^2/2) is >= 1e-60 of its maximum over [a, b], split at that maximum ("anchor")
    and where the weight has dropped by e^-m, m in SPLIT_M, from it.
    Returns (anchor, offsets): the split points are anchor + offsets."""
    ua = h + a
    ms = list(SPLIT_M) + [CUT_LOG]
    if ua >= 0:                                  # maximum at a, weight falls to the right
        offs = [mpf(0)] + [2 * m / (ua + mpmath.sqrt(ua * ua + 2 * m)) for m in ms]
        hi = offs[-1] if b == INF else min(b - a, offs[-1])
        return a, sorted(set([o for o in offs if o < hi] + [hi]))
    if b != INF and h + b <= 0:                  # maximum at b, weight falls to the left
        ub = -(h + b)
        offs = [mpf(0)] + [-2 * m / (ub + mpmath.sqrt(ub * ub + 2 * m)) for m in ms]
        lo = max(a - b, offs[-1])
        return b, sorted(set([o for o in offs if o > lo] + [lo]))
    c = -h                                       # interior maximum at D = -h
    offs = [mpf(0)]
    for m in ms:
        r = mpmath.sqrt(2 * m)
        offs += [-r, r]
    lo = max(a - c, -mpmath.sqrt(2 * CUT_LOG))
    hi = min(b - c, mpmath.sqrt(2 * CUT_LOG)) if b != INF else mpmath.sqrt(2 * CUT_LOG)
    return c, sorted(set([o for o in offs if lo < o < hi] + [lo, hi]))


def elastic_part(model, h):
    """(anchor, offsets) of the truncated elastic interval [0, Dc], or None if it is empty."""
    anc, offs = part_window(h, mpf(0), model.Dc)
    if len(offs) < 2:
        return None
    if model.adh:                                # structure of D1(D) near D = 0 (scale D0)
        lo, hi = anc + offs[0], anc + offs[-1]
        D = model.D0 / 4
        extra = []
        while D < 1 and D < hi:
            if D > lo:
                extra.append(D - anc)
            D *= 4
        offs = sorted(set(offs + extra))
    return anc, offs


def plastic_part(model, h):
    if not model.plastic:
        return None
    return part_window(h, model.Dc, INF)


def area_part(model, h):
    anc, offs = part_window(h, mpf(0), INF)
    if model.plastic and anc + offs[0] < model.Dc < anc + offs[-1]:
        offs = sorted(set(offs + [model.Dc - anc]))
    return anc, offs


def quad(f, pts):
    """mpmath.quad over the split points pts, with the integrand normalised to magnitude ~1 first:
    mpmath.quad's convergence test is absolute (~2^-prec), so a tiny scaled integrand (e.g. a
    plastic part ~1e-120) would otherwise be accepted at a low degree.  Returns (value, error)."""
    if len(pts) < 2:
        return mpf(0), mpf(0)
    samples = list(pts) + [(x + y) / 2 for x, y in zip(pts, pts[1:])]
    M = max(abs(f(x)) for x in samples)
    if M == 0:
        M = mpf(1)
    v, e = mp.quad(lambda x: f(x) / M, pts, error=True, maxdegree=10)
    return v * M, e * M


# ----------------------------------------------------------------------------------------------
# method 1: substitution form + closed forms
# ----------------------------------------------------------------------------------------------

def method1(model, h):
    ca, cd = model.c_a, model.c_d
    part = elastic_part(model, h)
    pe_pts = [part[0] + o for o in part[1]] if part else []
    if part and part[1][0] == -part[0]:
        pe_pts[0] = mpf(0)
    if part and model.plastic and part[0] + part[1][-1] >= model.Dc:
        pe_pts[-1] = model.Dc
    r = {}
    qerr = mpf(0)
    if pe_pts:
        spts = []
        for D in pe_pts:
            if D == 0:
                spts.append(model.s0)
            elif model.plastic and D == model.Dc:
                spts.append(model.t)
            else:
                spts.append(model.s_of_D(D))
        cache = {}

        def core(s):
            v = cache.get(s)
            if v is None:
                s3 = s ** 3
                D = s * (s3 - cd)
                w = mpmath.exp(log_w(h, D)) * (4 * s3 - cd)
                v = (s3, D, w)
                cache[s] = v
            return v

        def i6(s):
            s3, D, w = core(s)
            return s3 * s3 * w

        def i3(s):
            s3, D, w = core(s)
            return s3 * w

        def j6(s):
            s3, D, w = core(s)
            return s3 * s3 * (h + D) * w

        def j3(s):
            s3, D, w = core(s)
            return s3 * (h + D) * w

        I6, e1 = quad(i6, spts)
        J6, e3 = quad(j6, spts)
        if model.adh:
            I3, e2 = quad(i3, spts)
            J3, e4 = quad(j3, spts)
        else:
            I3 = J3 = e2 = e4 = mpf(0)
        qerr = max(e1 / max(abs(I6), mpf(10) ** -300), e3 / max(abs(J6), mpf(10) ** -300))
    else:
        I6 = I3 = J6 = J3 = mpf(0)
    r["load_elastic"] = I6 - ca * I3
    r["scale_e"] = abs(I6) + ca * abs(I3)
    r["dload_elastic"] = -(J6 - ca * J3)
    r["scale_de"] = abs(J6) + ca * abs(J3)

    with mp.workdps(mp.dps + 30):
        k = kappa(h)
        sq = mpmath.sqrt(mp.pi / 2)
        # area: A = e^{-h^2/2} - h sqrt(pi/2) erfc(h/sqrt 2), scaled
        A = mpmath.exp(-h * h / 2 + k) - h * sq * mpmath.erfc(h / mpmath.sqrt(2)) * mpmath.exp(k)
        if model.plastic:
            Dc = model.Dc
            uc = h + Dc
            G = mpmath.exp(log_w(h, Dc))                                   # scaled e^{-uc^2/2}
            M0 = sq * mpmath.erfc(uc / mpmath.sqrt(2)) * mpmath.exp(k)      # scaled int_uc^inf e^{-u^2/2}
            M1 = G - h * M0                                                 # scaled Ap
            Lp = model.c_p * M1 - model.c_0 * M0
            sLp = model.c_p * abs(M1) + model.c_0 * M0
            dLp = -(model.c_p * (Dc * G + M0) - model.c_0 * G)
            sdLp = model.c_p * abs(Dc * G + M0) + model.c_0 * G
        else:
            M1 = Lp = sLp = dLp = sdLp = mpf(0)
        r["area"] = +A
        r["plastic_area"] = +M1
        r["load_plastic"] = +Lp
        r["scale_p"] = +sLp
        r["dload_plastic"] = +dLp
        r["scale_dp"] = +sdLp
    r["load"] = r["load_elastic"] + r["load_plastic"]
    r["dload_dh"] = r["dload_elastic"] + r["dload_plastic"]
    r["scale_load"] = r["scale_e"] + r["scale_p"]
    r["scale_dload"] = r["scale_de"] + r["scale_dp"]
    r["quad_err"] = qerr
    return r


# ----------------------------------------------------------------------------------------------
# method 2: direct form (root solve per node), everything by quadrature
# ----------------------------------------------------------------------------------------------

def method2(model, h):
    """Quadrature over the actual interference.  Each part is integrated in the offset
    o = D - anchor from the maximum of its weight, with the weight exp(log_w(anchor)) *
    exp(-(u_a o + o^2/2)), u_a = h + anchor: for a far-away part (e.g. Dc ~ 1e7) this keeps the
    huge exponent out of the rounding of the nodes."""
    ca, cp, c0 = model.c_a, model.c_p, model.c_0
    pcache = {}

    def pe(D):
        v = pcache.get(D)
        if v is None:
            if model.adh:
                D1 = model.D1_of_D(D)
                q = mpmath.root(D1, 4) ** 3                 # D1^(3/4)
                v = q * q - ca * q
            else:
                v = D * mpmath.sqrt(D)
            pcache[D] = v
        return v

    def weight(anc):
        with mp.workdps(mp.dps + 30):
            lw = log_w(h, anc)
            ua = h + anc
            w0 = mpmath.exp(lw)
        wc = {}

        def W(o):
            v = wc.get(o)
            if v is None:
                v = w0 * mpmath.exp(-(ua * o + o * o / 2))
                wc[o] = v
            return v
        return W

    r = {}
    part = elastic_part(model, h)
    if part:
        anc, offs = part
        W = weight(anc)
        Dof = lambda o: anc + o
        r["load_elastic"], _ = quad(lambda o: pe(Dof(o)) * W(o), offs)
        r["dload_elastic"], _ = quad(lambda o: -pe(Dof(o)) * (h + Dof(o)) * W(o), offs)
    else:
        r["load_elastic"] = r["dload_elastic"] = mpf(0)
    part = plastic_part(model, h)
    if part:
        anc, offs = part
        W = weight(anc)
        r["load_plastic"], _ = quad(lambda o: (cp * (anc + o) - c0) * W(o), offs)
        r["dload_plastic"], _ = quad(lambda o: -(cp * (anc + o) - c0) * (h + anc + o) * W(o), offs)
        r["plastic_area"], _ = quad(lambda o: (anc + o) * W(o), offs)
    else:
        r["load_plastic"] = r["dload_plastic"] = r["plastic_area"] = mpf(0)
    anc, offs = area_part(model, h)
    W = weight(anc)
    r["area"], _ = quad(lambda o: (anc + o) * W(o), offs)
    r["load"] = r["load_elastic"] + r["load_plastic"]
    r["dload_dh"] = r["dload_elastic"] + r["dload_plastic"]
    return r


# ----------------------------------------------------------------------------------------------
# comparison
# ----------------------------------------------------------------------------------------------

def digits(a, b, scale):
    den = max(abs(a), abs(b), scale)
    d = abs(a - b)
    if d == 0:
        return 99.0
    if den == 0:
        return -99.0
    return float(-mpmath.log10(d / den))


OUTPUTS = ["load", "load_elastic", "load_plastic", "area", "plastic_area", "dload_dh"]


def compare(r1, r2):
    sc = {
        "load": r1["scale_load"],
        "load_elastic": r1["scale_e"],
        "load_plastic": r1["scale_p"],
        "area": abs(r1["area"]),
        "plastic_area": abs(r1["plastic_area"]),
        "dload_dh": r1["scale_dload"],
    }
    return {k: digits(r1[k], r2[k], sc[k]) for k in OUTPUTS}


def gw_check(h, r1):
    """Greenwood-Williamson identities via parabolic-cylinder functions (scaled like the rows)."""
    with mp.workdps(mp.dps + 30):
        k = kappa(h)
        e = mpmath.exp(-h * h / 4 + k)
        P = mpmath.gamma(mpf(5) / 2) * e * mpmath.pcfd(mpf(-5) / 2, h)
        A = mpmath.gamma(2) * e * mpmath.pcfd(-2, h)
        dP = -mpf(3) / 2 * mpmath.gamma(mpf(3) / 2) * e * mpmath.pcfd(mpf(-3) / 2, h)
    return min(digits(P, r1["load"], 0), digits(A, r1["area"], 0), digits(dP, r1["dload_dh"], 0))


# ----------------------------------------------------------------------------------------------
# points table
# ----------------------------------------------------------------------------------------------

POINT_COLS = ["case", "theta", "lambda", "c_a", "c_h", "h", "critical_interference", "load",
              "load_elastic", "load_plastic", "area", "plastic_area", "dload_dh"]


def model_from_task(task):
    case, th, la, ch = task
    return Model(case, th, la, ch)


def point_task(args):
    (case, th, la, ch, hs), dps = args
    setup(dps)
    t0 = time.time()
    m = Model(case, th, la, ch)
    h = num(hs)
    r1 = method1(m, h)
    r2 = method2(m, h)
    ag = compare(r1, r2)
    worst = min(ag.values())
    extra = ""
    if case == "gw":
        g = gw_check(h, r1)
        worst_gw = g
        if g < AGREE_DIGITS:
            raise AssertionError("gw pcfd check failed at h=%s: %.1f digits" % (hs, g))
    else:
        worst_gw = None
    if worst < AGREE_DIGITS:
        raise AssertionError("methods disagree (%s) for %r: %r\n m1=%r\n m2=%r" % (worst, (case, th, la, ch, hs), ag,
                                                                               {k: mpmath.nstr(r1[k], 25) for k in OUTPUTS},
                                                                               {k: mpmath.nstr(r2[k], 25) for k in OUTPUTS}))
    row = [case, th, la, fmt(m.c_a) if m.c_a != 0 else "0.0", fmt(m.c_h), hs, fmt(m.Dc)] + \
          [fmt(r1[k]) for k in OUTPUTS[:3]] + [fmt(r1["area"]), fmt(r1["plastic_area"]), fmt(r1["dload_dh"])]
    return row, worst, worst_gw, time.time() - t0, float(r1["quad_err"])


def point_tasks(quick):
    tasks = []
    if quick:
        thetas, lams, hs = ["1e-3", "1", "10", "1e8"], ["1e-6", "0.125", "1e6"], ["-4", "0", "1", "8", "60"]
        for th in thetas:
            for la in lams:
                for h in hs:
                    tasks.append(("adhesive", th, la, "inf", h))
    else:
        for i, th in enumerate(THETAS):
            for j, la in enumerate(LAMBDAS):
                for k, h in enumerate(HS):
                    if adhesive_subset(i, j, k):
                        tasks.append(("adhesive", th, la, "inf", h))
        hs = HS
    for th, la in EXTRA_TL:
        for h in EXTRA_H:
            tasks.append(("adhesive", th, la, "inf", h))
    for ch in CH_NOADH:
        for h in hs:
            tasks.append(("no_adhesion", "inf", "inf", ch, h))
    for th in (thetas if quick else THETAS):
        for h in hs:
            tasks.append(("no_plasticity", th, "inf", "inf", h))
    for h in hs:
        tasks.append(("gw", "inf", "inf", "inf", h))
    return tasks


SUBSET_RULE = "all"


def adhesive_subset(i, j, k):
    """Which (theta index i, lambda index j, h index k) adhesive grid points are written."""
    if SUBSET_RULE == "all":
        return True
    # deterministic subset: every h for the 4 (theta, lambda) corners; otherwise the h indices
    # k with (k - i - 3 j) mod 3 == 0 (each (theta, lambda) pair gets every third h, staggered)
    corner = i in (0, len(THETAS) - 1) and j in (0, len(LAMBDAS) - 1)
    return corner or (k - i - 3 * j) % 3 == 0


# ----------------------------------------------------------------------------------------------
# extrema and roots
# ----------------------------------------------------------------------------------------------

def PD(model, h):
    r = method1(model, h)
    return r["load"], r["dload_dh"], r


def scan(model, targets=(), base=None):
    """Grid scan of P and dP/dh (method 1).  Returns a list of (h, Ps, Ds) sorted by h.
    With base (an earlier scan of the same model), only the downward extension is added."""
    if base is not None:
        pts = list(base)
        tmax = max([t for t in targets] + [0])
        hh, Ps = min((p[0], p[1]) for p in pts)
        while not Ps > tmax * mpf("1.01") + 1:
            hh -= max(1, abs(hh) / 20)
            Ps, Ds, _ = PD(model, hh)
            pts.append((hh, Ps, Ds))
        pts.sort(key=lambda p: p[0])
        return pts
    Dc = model.Dc if model.plastic else mpf(0)
    # adhesive: extrema can sit near h = -Dc (load jump), so start below -(Dc+17), where P is
    # linear; without adhesion P is monotone and only the brackets of the targets matter.
    h_lo = -(Dc + 20) if model.adh else mpf(-5)
    pts = []
    h = mpf(h_lo)
    step = mpf("0.1")
    # downward extension: P linear and increasing as h decreases below -(Dc+17)
    tmax = max([t for t in targets] + [0])
    hh = h
    while True:
        Ps, Ds, _ = PD(model, hh)
        pts.append((hh, Ps, Ds))
        if Ps > tmax * mpf("1.01") + 1:
            break
        hh -= max(1, abs(hh) / 20)
    # upward scan
    h = h_lo + step
    tpos = [t for t in targets if t > 0]
    tmin_log = min([mpmath.log(t) for t in tpos]) if tpos else None
    while True:
        Ps, Ds, r = PD(model, h)
        pts.append((h, Ps, Ds))
        if h > 10:
            if model.adh:
                if Ps < 0 and Ds > 0 and abs(h * Ps / model.pe0 - 1) < mpf("0.05"):
                    break
            else:
                lp = mpmath.log(Ps) - kappa(h) if Ps > 0 else -INF
                if tmin_log is None or lp < tmin_log - 5:
                    break
        if h > 3000:
            raise RuntimeError("scan did not terminate")
        if model.adh:
            st = mpf("0.1") if h < 10 else (mpf("0.25") if h < 40 else h / 40)
        else:
            st = mpf("0.5")
        h = h + st
    pts.sort(key=lambda p: p[0])
    return pts


def find_extrema(model, pts):
    ext = []
    for (h1, P1, D1), (h2, P2, D2) in zip(pts, pts[1:]):
        if D1 == 0:
            hs_ = [h1]
        elif (D1 < 0) != (D2 < 0):
            def f(h):
                Ps, Ds, _ = PD(model, h)
                return Ds / abs(Ps)
            hs_ = [mpmath.findroot(f, (h1, h2), solver="anderson")]
        else:
            continue
        for hx in hs_:
            kind = "max" if D1 > 0 else "min"      # P rising then falling = maximum
            ext.append((hx, kind))
    return ext


def extrema_task(args):
    (th, la), dps = args
    setup(dps)
    t0 = time.time()
    m = Model("adhesive", th, la)
    pts = scan(m)
    ext = find_extrema(m, pts)
    rows = []
    worst = 99.0
    mins = []
    for hx, kind in ext:
        r1 = method1(m, hx)
        r2 = method2(m, hx)
        ag = digits(r1["load"], r2["load"], r1["scale_load"])
        worst = min(worst, ag)
        if ag < AGREE_DIGITS:
            raise AssertionError("extremum load disagreement %s %s" % (th, la))
        # stationarity check with method 2
        dres = abs(r2["dload_dh"]) / r1["scale_dload"]
        assert dres < mpf(10) ** -AGREE_DIGITS, (th, la, hx, dres)
        P = r1["load"]
        lg = mpmath.log10(abs(P)) - kappa(hx) / mpmath.log(10)
        rows.append([hx, kind, P, lg])
        if kind == "min":
            mins.append((P * mpmath.exp(-kappa(hx)), hx))
    po = min(mins)[1] if mins else None
    out = []
    for hx, kind, P, lg in rows:
        out.append(["adhesive", th, la, fmt(m.c_a), fmt(m.c_h), fmt(hx), fmt(P), fmt(lg), kind,
                    "yes" if hx == po else "no"])
    return out, worst, time.time() - t0, (pts, ext, po)


def solve_roots(model, pts, T):
    """All roots of P(h) = T bracketed by the scan (sign changes of P - T)."""
    T = mpf(T)

    def g_log(h):
        # log(P/T) in scaled form: smooth and nearly linear in h (P and T of one sign)
        Ps, _, _ = PD(model, h)
        return mpmath.log(Ps / T) - kappa(h)

    def g_bounded(h):
        Ps, _, _ = PD(model, h)
        Te = T * mpmath.exp(kappa(h))
        return (Ps - Te) / (abs(Ps) + abs(Te))

    def g_zero(h):
        # P / (sum of |parts|): smooth, zero where P = 0
        r = method1(model, h)
        return r["load"] / r["scale_load"]

    roots = []
    vals = [(h, P, P - T * mpmath.exp(kappa(h))) for h, P, _ in pts]
    for (h1, P1, v1), (h2, P2, v2) in zip(vals, vals[1:]):
        if v1 == 0:
            roots.append(h1)
        elif (v1 < 0) != (v2 < 0):
            if T != 0 and P1 / T > 0 and P2 / T > 0:
                roots.append(mpmath.findroot(g_log, (h1, h2), solver="anderson"))
            else:
                # shrink the bracket by bisection until P has the target's sign at both ends
                # (or T = 0), then Anderson on the bounded form
                a, b, va = h1, h2, v1
                for _ in range(60):
                    c = (a + b) / 2
                    Pc, _, _ = PD(model, c)
                    vc = Pc - T * mpmath.exp(kappa(c))
                    if (vc < 0) == (va < 0):
                        a, va = c, vc
                    else:
                        b = c
                    if b - a < mpf("1e-6"):
                        break
                Pa, _, _ = PD(model, a)
                Pb, _, _ = PD(model, b)
                if T == 0:
                    roots.append(mpmath.findroot(g_zero, (a, b), solver="anderson"))
                elif Pa / T > 0 and Pb / T > 0:
                    roots.append(mpmath.findroot(g_log, (a, b), solver="anderson"))
                else:
                    roots.append(mpmath.findroot(g_bounded, (a, b), solver="anderson"))
    for hr in roots:
        assert hr >= min(p[0] for p in pts) and hr <= max(p[0] for p in pts)
    return roots


def roots_task(args):
    (case, th, la, ch, targets), dps, prior = args
    setup(dps)
    t0 = time.time()
    m = Model(case, th, la, ch)
    tvals = [num(t) for t in targets]
    po = None
    if prior is not None:                      # scan and pull-off from the extrema run
        base, po = prior
        pts = scan(m, tvals, base=base)
    else:
        pts = scan(m, tvals)
    if m.adh and prior is None:
        ext = find_extrema(m, pts)
        mins = []
        for hx, kind in ext:
            if kind == "min":
                Ps, _, _ = PD(m, hx)
                mins.append((Ps * mpmath.exp(-kappa(hx)), hx))
        if mins:
            Pmin, po = min(mins)
    out = []
    worst = 99.0
    for ts, T in zip(targets, tvals):
        roots = solve_roots(m, pts, T)
        # verify each root with method 2
        for hr in roots:
            r1 = method1(m, hr)
            r2 = method2(m, hr)
            Te = T * mpmath.exp(kappa(hr))
            scale = max(r1["scale_load"], abs(Te))
            res = abs(r2["load"] - Te) / scale
            dg = float(-mpmath.log10(res)) if res > 0 else 99.0
            worst = min(worst, dg)
            assert dg >= AGREE_DIGITS, (case, th, la, ch, ts, hr, dg)
        if T > 0 or (T == 0):
            chosen = max(roots) if roots else None
        else:
            below = [hr for hr in roots if po is not None and hr < po]
            chosen = max(below) if below else None
        base = [case, th, la, fmt(m.c_a) if m.c_a != 0 else "0.0", fmt(m.c_h), ts]
        if len(roots) > 1 or case == "adhesive":
            for hr in roots:
                out.append(base + [fmt(hr), "all_roots"])
        out.append(base + [fmt(chosen) if chosen is not None else "none_separates", "chosen"])
    return out, worst, time.time() - t0


EXTREMA_CASES = [("1e4", "100"), ("10", "1"), ("0.1", "1e-3"), ("1", "1"), ("3", "0.125"), ("100", "5")]
ROOT_CASES = [
    ("adhesive", "0.1", "1e-3", "inf", ["180"]),
    ("adhesive", "1e4", "100", "inf", ["100"]),
    ("adhesive", "10", "1", "inf", ["1", "0.1", "1e-3", "0", "-1e-3"]),
    ("gw", "inf", "inf", "inf", ["1", "1e-10", "1e-100", "1e-300"]),
] + [("no_adhesion", "inf", "inf", ch, ["1", "1e-10", "1e-100", "1e-300"]) for ch in CH_NOADH]


# ----------------------------------------------------------------------------------------------
# driver
# ----------------------------------------------------------------------------------------------

def header(args, title, methods, agreement, extra=()):
    cmd = "python3 scripts/reference.py --out %s%s" % (args.out, " --quick" if args.quick else "")
    lines = ["# wearopt reference table: %s" % title,
             "# generated by: %s  (mpmath %s, mp.dps = %d)" % (cmd, mpmath.__version__, args.dps),
             "# model: docs/model.md section 3 (non-dimensional); inputs theta/lambda/c_h/h are the IEEE doubles of the printed decimals",
             "# scaling: every load/area/derivative value is the mantissa value*exp(kappa), kappa = h^2/2 for h > 0, 0 for h <= 0",
             "# methods: %s" % methods,
             "# agreement: %s" % agreement]
    lines += ["# " + e for e in extra]
    return lines


def write_csv(path, head, cols, rows):
    with open(path, "w") as f:
        for l in head:
            f.write(l + "\n")
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(str(x) for x in r) + "\n")


def main():
    global SUBSET_RULE
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default="tests/data")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--dps", type=int, default=DPS_DEFAULT)
    ap.add_argument("--subset", choices=["all", "stagger3"], default="all",
                    help="adhesive grid: all 1680 points, or the deterministic staggered subset")
    ap.add_argument("--only", choices=["points", "extrema", "roots"], action="append")
    args = ap.parse_args()
    if args.dps < 40:
        sys.exit("--dps must be >= 40")
    SUBSET_RULE = args.subset
    setup(args.dps)
    # F_{3/2}(0) = 2^(1/4) Gamma(5/4) / sqrt(2 pi)  against the pcfd form and method 1
    f32 = mpmath.root(2, 4) * mpmath.gamma(mpf(5) / 4) / mpmath.sqrt(2 * mp.pi)
    f32p = mpmath.gamma(mpf(5) / 2) * mpmath.pcfd(mpf(-5) / 2, 0) / mpmath.sqrt(2 * mp.pi)
    f32m = method1(Model("gw"), mpf(0))["load"] / mpmath.sqrt(2 * mp.pi)
    assert digits(f32, f32p, 0) > 35 and digits(f32, f32m, 0) > 35, (f32, f32p, f32m)
    print("F_3/2(0) = %s (closed form = pcfd = method 1 to %.1f digits)"
          % (mpmath.nstr(f32, 25), min(digits(f32, f32p, 0), digits(f32, f32m, 0))), flush=True)
    os.makedirs(args.out, exist_ok=True)
    only = set(args.only or ["points", "extrema", "roots"])
    T0 = time.time()
    pool = multiprocessing.Pool(args.jobs) if args.jobs > 1 else None
    pmap = (lambda f, xs: pool.imap(f, xs)) if pool else (lambda f, xs: map(f, xs))
    m1 = ("(1) substitution s = D1^(1/4) + mpmath.quad (tanh-sinh), plastic part/A/Ap closed form (exp, erfc); "
          "(2) mpmath.quad over D with D1(D) by mpmath.findroot at every node, plastic part/A/Ap by quadrature; "
          "quadratures truncated where the weight < 1e-60 of its max on each part's interval")

    if "points" in only:
        tasks = point_tasks(args.quick)
        t1 = time.time()
        rows, worst, worst_gw, tmax = [], 99.0, 99.0, 0.0
        for n, (row, w, wg, dt, qe) in enumerate(pmap(point_task, [(t, args.dps) for t in tasks])):
            rows.append(row)
            worst = min(worst, w)
            if wg is not None:
                worst_gw = min(worst_gw, wg)
            tmax = max(tmax, dt)
            if (n + 1) % 100 == 0:
                print("  points %d/%d  %.0fs" % (n + 1, len(tasks), time.time() - t1), flush=True)
        n_adh = sum(1 for r in rows if r[0] == "adhesive")
        rule = ("adhesive grid: all theta x lambda x h" if SUBSET_RULE == "all" else
                "adhesive grid subset: theta/lambda corners all h, else h index k with (k - i - 3j) mod 3 == 0")
        head = header(args, "reference points", m1,
                      "worst over all rows and columns %.1f significant digits between (1) and (2) (required >= %d; "
                      "relative to max(|value|, sum of |parts|)); gw rows also match the pcfd identities to %.1f digits"
                      % (worst, AGREE_DIGITS, worst_gw),
                      ["%s; %d adhesive rows (+8 extra negative-h rows), %d rows in all" % (rule, n_adh - 8, len(rows)),
                       "case: adhesive | no_adhesion (gamma=0: c_a=c_d=c_0=0, c_h given) | no_plasticity (H=inf: c_h=inf, no plastic part) | gw (both)",
                       "critical_interference = Delta_c = t(c_h t + c_a/3), t^3 - c_h t - c_a = 0 (inf without plasticity)",
                       "values printed with 20 significant digits; a scaled mantissa below the double range (e.g. a part ~1e-500) is printed as is"])
        write_csv(os.path.join(args.out, "reference_points.csv"), head, POINT_COLS, rows)
        print("points: %d rows, worst agreement %.1f digits, gw pcfd %.1f digits, slowest row %.1fs, %.0fs"
              % (len(rows), worst, worst_gw, tmax, time.time() - t1), flush=True)

    ext_info = {}
    if "extrema" in only:
        t1 = time.time()
        cases = EXTREMA_CASES if not args.quick else [("10", "1"), ("0.1", "1e-3")]
        rows, worst = [], 99.0
        for c, (out, w, dt, info) in zip(cases, pmap(extrema_task, [(c, args.dps) for c in cases])):
            rows += out
            ext_info[c] = (info[0], info[2])
            worst = min(worst, w)
            print("  extrema %s,%s: %d found, %.0fs" % (out[0][1], out[0][2], len(out), dt), flush=True)
        head = header(args, "local extrema of P(h)", m1 + "; extrema located by a scan of dP/dh (method 1) and refined "
                      "with mpmath.findroot (anderson) on (dP/dh)/|P|; stationarity confirmed with method (2)",
                      "P at the extrema agrees to %.1f digits between (1) and (2)" % worst,
                      ["h_min = location of the extremum (a minimum or a maximum, see kind); load_min_mantissa = P*exp(kappa) "
                       "there; log10_abs_load_min = log10|P| unscaled; pull_off = yes for the deepest minimum"])
        write_csv(os.path.join(args.out, "reference_extrema.csv"), head,
                  ["case", "theta", "lambda", "c_a", "c_h", "h_min", "load_min_mantissa", "log10_abs_load_min", "kind", "pull_off"],
                  rows)
        print("extrema: %d rows, worst %.1f digits, %.0fs" % (len(rows), worst, time.time() - t1), flush=True)

    if "roots" in only:
        t1 = time.time()
        cases = ROOT_CASES if not args.quick else ROOT_CASES[2:4]
        rows, worst = [], 99.0
        tasks = [(c, args.dps, ext_info.get((c[1], c[2])) if c[0] == "adhesive" else None) for c in cases]
        for out, w, dt in pmap(roots_task, tasks):
            rows += out
            worst = min(worst, w)
            print("  roots %s %s %s %s: %.0fs" % (out[0][0], out[0][1], out[0][2], out[0][4], dt), flush=True)
        head = header(args, "separation roots P(h) = target", m1 + "; roots bracketed by a scan (method 1) and refined "
                      "with mpmath.findroot (anderson) on log(P/T) in scaled form (P/sum|parts| for T = 0)",
                      "P(h_root) by method (2) equals the target to %.1f digits (relative to the sum of |parts|)" % worst,
                      ["rule (docs/model.md section 4): compressive target (and 0) -> largest h with P = target; tensile target -> "
                       "largest root below the h of the deepest minimum (pull-off); none_separates if there is none",
                       "kind = all_roots: every root in the scanned range (listed for adhesive cases and whenever there are several); kind = chosen: the rule's root"])
        write_csv(os.path.join(args.out, "reference_roots.csv"), head,
                  ["case", "theta", "lambda", "c_a", "c_h", "target_load", "h_root", "kind"], rows)
        print("roots: %d rows, worst %.1f digits, %.0fs" % (len(rows), worst, time.time() - t1), flush=True)

    if pool:
        pool.close()
        pool.join()
    print("total %.0fs" % (time.time() - T0))


if __name__ == "__main__":
    main()
