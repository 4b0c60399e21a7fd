#!/usr/bin/env python3
"""High-precision reference table for the stress-assisted wear law of wearopt (docs/model.md section 12).

WHAT
    Writes tests/data/reference_stress_assisted.csv, which tests/all/stress_assisted_wear.rs
    compares the evaluator's integral against (1e-12 relative):

        I(h) = int_0^Dc D F(s(D)) w(D) dD  +  F(c_h) int_Dc^inf D w(D) dD,
        F(s) = 1 - exp(-c exp(b s)),  w(D) = exp(-(h + D)^2 / 2),

    the summits' removal probability F weighted by their area D (the pi R delta measure of
    section 3) over the Gaussian summit heights, s = p(D)/D the summit's mean pressure in
    model units (a stress over (K/pi)(sigma/R)^(1/2)), c_h = H in those units on a plastic
    junction. The asperity laws (section 3 and 7), lengths over sigma, loads over K R^(1/2)
    sigma^(3/2):
        JKR: D = t^4 - c_d t, p = t^6 - c_a t^3 (t >= t0 = c_d^(1/3)), c_d = 2 c_a / 3;
             Dc = tc (c_h tc + c_a/3), tc the positive root of t^3 - c_h t - c_a = 0.
        DMT: p = D^(3/2) - c_0, c_0 = c_a^2 / 3;  Dc = c_h^2.
    Rows: both laws, elastic only (c_h = inf) and with plastic junctions, h from -4 to 60,
    c from 1e-30 to 1e6 and b up to 20 (b s up to about 60 over the summits that matter).

SCALING
    value is I * exp(kappa), kappa = h^2/2 for h > 0 else 0 (the Rust mantissa), printed
    with 25 significant digits.

HOW / PRECISION
    mpmath at mp.dps = 40. Two independent methods, which must agree to 24 digits:
      (1) mpmath.quad (tanh-sinh) in the law's smooth variable v (t for JKR, D^(1/2) for DMT);
      (2) Gauss-Legendre (mpmath.quad method='gauss-legendre') in y = t^2 (JKR) or w = D^(1/4) (DMT).
    Both on panels split where the integrand has dropped by e^-1 ... e^-64 from its largest
    value and where c exp(b s) = 1 (the band of saturated summits), truncated at e^-90.
    The plastic share is the closed form F(c_h) [phi(u) - ... ] of A_p with erfc at u = h + Dc
    (int_Dc^inf D w = exp(-u^2/2) - h sqrt(pi/2) erfc(u/sqrt 2)), u = h + Dc.

USAGE
    python3 scripts/reference_stress_assisted.py --out tests/data   [--quick] [--dps 40]
"""

import argparse
import os
import sys

import mpmath as mp
from mpmath import mpf

AGREE_DIGITS = 24
LEVELS = [1, 4, 16, 64, 90]


def dbl(text):
    return mpf(float(text))


class Row:
    def __init__(self, law, c_a, c_h, h, c, b):
        self.law, self.texts = law, (c_a, c_h, h, c, b)
        self.c_a = dbl(c_a)
        self.c_h = mp.inf if c_h == "inf" else dbl(c_h)
        self.h, self.c, self.b = dbl(h), dbl(c), dbl(b)
        if law == "jkr":
            self.c_d = 2 * self.c_a / 3
            self.t0 = mp.cbrt(self.c_d)
            if self.c_h == mp.inf:
                self.dc = mp.inf
            else:
                tc = mp.findroot(lambda t: t**3 - self.c_h * t - self.c_a,
                                 mp.sqrt(self.c_h) + mp.cbrt(self.c_a))
                self.dc = tc * (self.c_h * tc + self.c_a / 3)
        else:
            self.c_0 = self.c_a**2 / 3
            self.dc = self.c_h**2

    def removal(self, s):
        """F(s) = 1 - exp(-c e^{b s})."""
        return -mp.expm1(-self.c * mp.exp(self.b * s))

    def var_of(self, d):
        """The smooth variable at D: t (JKR, the root >= t0 of t^4 - c_d t = D) or D^(1/2)."""
        if self.law != "jkr":
            return mp.sqrt(d)
        if d == 0:
            return self.t0
        return mp.findroot(lambda t: t**4 - self.c_d * t - d, max(self.t0, mp.root(d, 4)) + 1)

    def summit(self, v):
        """(D, s, dD/dv) at the smooth variable v."""
        if self.law == "jkr":
            d = v**4 - self.c_d * v
            if d <= 0:
                return mpf(0), mpf(0), mpf(0)
            return d, (v**6 - self.c_a * v**3) / d, 4 * v**3 - self.c_d
        d = v * v
        if d <= 0:
            return mpf(0), mpf(0), mpf(0)
        return d, v - self.c_0 / d, 2 * v

    def integrand(self, v):
        d, s, jac = self.summit(v)
        if d <= 0:
            return mpf(0)
        return d * self.removal(s) * mp.exp(-(self.h + d) ** 2 / 2) * jac

    def panels(self):
        """Edges in the smooth variable: the integrand's levels and the saturated band's ends."""
        reach = mp.sqrt(1600 + max(self.h, 0) ** 2) - self.h
        top = self.var_of(min(self.dc, reach))
        v0 = self.t0 if self.law == "jkr" else mpf(0)
        n = 400
        grid = [v0 + (top - v0) * i / n for i in range(n + 1)]
        lns = []
        with mp.workdps(20):
            for v in grid:
                f = self.integrand(v)
                lns.append(mp.log(f) if f > 0 else -mp.inf)
        peak = max(lns)
        keep = [i for i in range(n + 1) if lns[i] > peak - LEVELS[-1]]
        lo, hi = grid[max(keep[0] - 1, 0)], grid[min(keep[-1] + 1, n)]
        edges = set()
        for lvl in LEVELS:
            for i in range(n):
                a, b = lns[i], lns[i + 1]
                if (a > peak - lvl) != (b > peak - lvl):
                    edges.add(grid[i] if a < b else grid[i + 1])
        ln_c = mp.log(self.c)
        if self.b != 0:
            xs = [ln_c + self.b * self.summit(v)[1] if self.summit(v)[0] > 0 else -mp.inf for v in grid]
            for i in range(n):
                if xs[i] != -mp.inf and (xs[i] > 0) != (xs[i + 1] > 0):
                    r = mp.findroot(lambda v: ln_c + self.b * self.summit(v)[1], (grid[i], grid[i + 1]),
                                    solver="anderson")
                    edges.add(r)
        edges = sorted(e for e in edges if lo < e < hi)
        out = [lo]
        for e in edges + [hi]:
            a = out[-1]
            for k in range(1, 3):
                out.append(a + (e - a) * k / 2)
        return out, peak

    def method_one(self, edges, peak):
        """tanh-sinh in the smooth variable."""
        scale = mp.exp(-peak)
        f = lambda v: self.integrand(v) * scale
        return mp.fsum(mp.quad(f, [a, b]) for a, b in zip(edges, edges[1:]) if b > a) / scale

    def method_two(self, edges, peak):
        """Gauss-Legendre in another variable: y = t^2 under JKR (t >= t0 > 0), w = v^(1/2) under
        DMT (v = w^2; both maps analytic where the integrand is)."""
        scale = mp.exp(-peak)
        if self.law == "jkr":
            f = lambda y: self.integrand(mp.sqrt(y)) / (2 * mp.sqrt(y)) * scale if y > 0 else mpf(0)
            ys = [e * e for e in edges]
        else:
            f = lambda w: self.integrand(w * w) * 2 * w * scale
            ys = [mp.sqrt(e) for e in edges]
        return mp.fsum(mp.quad(f, [a, b], method="gauss-legendre") for a, b in zip(ys, ys[1:]) if b > a) / scale

    def plastic(self):
        if self.dc == mp.inf:
            return mpf(0)
        u = self.h + self.dc
        ap = mp.exp(-u * u / 2) - self.h * mp.sqrt(mp.pi / 2) * mp.erfc(u / mp.sqrt(2))
        return self.removal(self.c_h) * ap


def rows(quick):
    """Both laws with and without plastic junctions over h in [-4, 60], c in [1e-30, 1e6] and
    b s up to 60; then weak adhesion (JKR c_a = 0.2) and none (DMT c_a = 0)."""
    cases = [("-4", "1e-30", "20"), ("0", "1e-12", "3"), ("3", "1", "0"), ("3", "1e-3", "20"),
             ("20", "1e6", "3"), ("60", "1e-30", "20")]
    if quick:
        cases = cases[:2]
    for law, c_a in [("jkr", "1.5"), ("dmt", "0.5")]:
        for c_h in ["inf", "4"]:
            for h, c, b in cases:
                yield Row(law, c_a, c_h, h, c, "15" if (c_h != "inf" and b == "20") else b)
    if not quick:
        for law, c_a in [("jkr", "0.2"), ("dmt", "0")]:
            for h, c, b in [("-1", "1e-6", "3"), ("1.5", "1e-30", "15"), ("8", "1", "3")]:
                yield Row(law, c_a, "4", h, c, b)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="tests/data")
    ap.add_argument("--dps", type=int, default=40)
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    mp.mp.dps = args.dps
    path = os.path.join(args.out, "reference_stress_assisted.csv")
    lines = [
        "# wearopt reference table: the stress-assisted wear law's integral (docs/model.md section 12)",
        f"# generated by: python3 scripts/reference_stress_assisted.py --out tests/data  (mpmath {mp.__version__}, mp.dps = {args.dps})",
        "# I = int_0^Dc D F(p/D) w dD + F(c_h) A_p, F(s) = 1 - exp(-c e^{b s}), w = exp(-(h+D)^2/2); value = I exp(kappa(h))",
        "# inputs are the IEEE doubles of the printed decimals; methods: (1) tanh-sinh in t (JKR) or D^(1/2) (DMT), (2) Gauss-Legendre in t^2 (JKR) or D^(1/4) (DMT); agree to >= 24 digits",
        "law,c_a,c_h,h,c,b,value",
    ]
    n = 0
    for r in rows(args.quick):
        p = r.plastic()
        edges, peak = r.panels()
        one = r.method_one(edges, peak) + p
        two = r.method_two(edges, peak) + p
        if one == 0 and two == 0:
            value = mpf(0)
        else:
            rel = abs(one - two) / max(abs(one), abs(two))
            if rel > mpf(10) ** (-AGREE_DIGITS):
                sys.exit(f"methods disagree ({mp.nstr(rel, 3)}) at {r.law} {r.texts}")
            value = one
        kappa = r.h**2 / 2 if r.h > 0 else 0
        lines.append(",".join([r.law, *r.texts, mp.nstr(value * mp.exp(kappa), 25, min_fixed=1, max_fixed=0)]))
        n += 1
        print(n, r.law, r.texts, mp.nstr(value * mp.exp(kappa), 12), file=sys.stderr, flush=True)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {n} rows to {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
