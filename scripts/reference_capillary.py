#!/usr/bin/env python3
"""High-precision reference tables for the capillary load of wearopt (MODEL.md section 9).

WHAT
    Writes two CSV tables that tests/all/capillary.rs compares the evaluator against:

      reference_capillary_points.csv   the capillary load P_cap(h), dP_cap/dh, d2P_cap/dh2 and the
                                       wetted fraction 1 - exp(-F_w) on a grid of (k, f, h).
      reference_capillary_extrema.csv  scenes of the DMT law (van der Waals and Dugdale) and of the
                                       JKR law (theta, lambda in the theta and c_h columns) with a
                                       meniscus: the pull-off minimum of P_solid + P_cap (h_min,
                                       P_min), the unloaded equilibrium h0 (P = 0 on the falling
                                       branch) and the work of separation G = -int_{h0}^inf P dh.

    The physics (non-dimensional; lengths over sigma, loads over K N R^(1/2) sigma^(3/2) / sqrt(2 pi)):
      k = d_K / sigma (the Kelvin length over sigma), f = sqrt(2 pi) R N d_K, p = flooded load;
      J(h) = int_{-k}^{0} (1 + D/k) w dD + int_0^inf w dD,   w(D) = exp(-(h+D)^2/2),
      F_w = f J,   P_cap = -p (1 - exp(-F_w)),
      P_cap' = -p exp(-F) f J',   P_cap'' = -p exp(-F) (f J'' - f^2 J'^2).

HOW / PRECISION
    mpmath. Two independent methods per value; the script stops unless they agree:
      points:  (1) closed forms in erfc/exp (at 2x the working digits, so that the cancellation of
               the Dugdale part for k << 1 costs nothing); (2) mpmath.quad over D of the defining
               integrals (split at the weight's peak and its e-folds, as scripts/reference_dmt.py).
               Agreement >= 25 digits at mp.dps = 40.
      extrema: P_solid from scripts/reference_dmt.py (DMT) or scripts/reference.py (JKR; its
               methods 1 and 2), P_cap from (1) and (2)
               above. h_min by findroot on dP/dh, h0 by findroot on P; G by (1) mpmath.quad over h of
               P (method 1 everywhere) and (2) the solid part by exchanging the integrals,
               int_{h0}^inf P_solid dh = int p(D) sqrt(pi/2) erfc((h0+D)/sqrt 2) dD, and the
               capillary part by quadrature over h of method (2). Agreement >= 15 digits at mp.dps = 20.
               Both findroots solve for a root of the function times e^{h^2/2}, scaled to ~1 on the
               bracket (findroot's test is absolute). Method 1 (Gauss-Legendre) divides P by
               |P_min| and splits [h0, inf) at unit steps (the attraction's and meniscus's reach),
               at h_min, and where e^{-h^2/2} has fallen from h0 by e^-0.25 ... e^-138: a far
               minimum (the weak Dugdale scene, h0 = 153) decays over 1/h0, inside one unit step.
               Method 2 (tanh-sinh) scales each integral by its largest value at its split points,
               splits the solid part also where erfc((h0+D)/sqrt 2) falls over 1/h0 and at
               D = -h0, and works with 10 guard digits: for a far minimum the solid and meniscus
               parts of G cancel to 1e-3.

USAGE
    python3 scripts/reference_capillary.py --out tests/data
    options: --quick (a few rows: smoke test), --only points|extrema
"""

import argparse
import os
import sys

import mpmath as mp
from mpmath import mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reference as jkr  # noqa: E402
import reference_dmt as dmt  # noqa: E402

K_GRID = ["1e-4", "0.01", "0.5", "3", "50", "400"]
F_GRID = ["1e-3", "0.5", "30"]
P_VALUE = "1.3"
H_GRID = ["-6", "-2", "0", "0.7", "2", "5", "12", "30", "60", "200"]


def dbl(text):
    return mpf(float(text))


def erfc_s(x):
    return mp.erfc(x / mp.sqrt(2))


# ------------------------------------------------------------------ J by two methods


def coverage_closed(k, h):
    """J, J', J'' in closed form (method 1)."""
    with mp.workdps(2 * mp.mp.dps):
        a = h - k
        q = mp.sqrt(mp.pi / 2)
        ea, eh = mp.exp(-a * a / 2), mp.exp(-h * h / 2)
        band = q * (erfc_s(a) - erfc_s(h))  # int_a^h exp(-u^2/2) du
        n1 = (ea - eh - a * band) / k
        t = q * erfc_s(h)
        return +(n1 + t), +(-band / k), +(-(eh - ea) / k)


def splits(peak, lo, hi):
    """dmt.split_points, plus the points where the log-weight has dropped by its levels
    from its value at the interval's end nearest the peak (which matters when the peak
    lies outside the interval: the weight then falls like exp(-|peak - near| x))."""
    pts, near = dmt.split_points(peak, lo, hi)
    extra = set(pts)
    s2 = (near - peak) ** 2
    for lev in dmt.LEVELS + [mpf("0.0625"), mpf(2), mpf(8), mpf(32)]:
        r = mp.sqrt(s2 + 2 * lev)
        for x in (peak - r, peak + r):
            if pts[0] < x < pts[-1]:
                extra.add(x)
    return sorted(extra)


def gq_scaled(f, pts, h):
    """dmt.gq with each piece's integrand divided by the weight's largest value on it
    (mpmath.quad tests an absolute error: a piece of size 1e-197 would pass unrefined)."""
    total = mpf(0)
    for a, b in zip(pts[:-1], pts[1:]):
        if b > a:
            x = min(max(-h, a), b)
            m = mp.exp(-(h + x) ** 2 / 2)
            total += m * mp.quad(lambda d: f(d) / m, [a, b])
    return total


def coverage_quad(k, h):
    """J, J', J'' by quadrature over D of the definition, differentiated under the
    integral sign (method 2)."""
    w = lambda d: mp.exp(-(h + d) ** 2 / 2)
    w1 = lambda d: -(h + d) * w(d)
    w2 = lambda d: ((h + d) ** 2 - 1) * w(d)
    pts = splits(-h, -k, mpf(0))
    hi = max(mpf(0), -h) + mp.sqrt(2 * 200)
    pts2 = splits(-h, mpf(0), hi)
    out = []
    for g in (w, w1, w2):
        band = gq_scaled(lambda d: (1 + d / k) * g(d), pts, h)
        out.append(band + gq_scaled(g, pts2, h))
    # The tail beyond hi (below 1e-80 of the peak): its closed forms.
    u = h + hi
    t0 = mp.sqrt(mp.pi / 2) * erfc_s(u)
    return out[0] + t0, out[1] - mp.exp(-u * u / 2), out[2] + u * mp.exp(-u * u / 2)


def capillary(k, f, p, h, method):
    j, dj, d2j = (coverage_closed if method == 1 else coverage_quad)(k, h)
    F = f * j
    e = mp.exp(-F)
    load = p * mp.expm1(-F)
    d1 = -p * e * f * dj
    d2 = -p * e * (f * d2j - f * f * dj * dj)
    return load, d1, d2, -mp.expm1(-F)


def agree(a, b):
    if a == b:
        return mpf(10) ** mp.mp.dps
    s = max(abs(a), abs(b))
    return -mp.log10(abs(a - b) / s)


def sci(x, digits=25):
    return mp.nstr(x, digits, min_fixed=1, max_fixed=0)


def points(quick):
    rows = []
    worst = mpf(100)
    ks = K_GRID[:2] if quick else K_GRID
    for ks_ in ks:
        for fs in (F_GRID[:1] if quick else F_GRID):
            for hs in (H_GRID[:3] if quick else H_GRID):
                k, f, p, h = dbl(ks_), dbl(fs), dbl(P_VALUE), dbl(hs)
                r1 = capillary(k, f, p, h, 1)
                r2 = capillary(k, f, p, h, 2)
                for a, b in zip(r1, r2):
                    worst = min(worst, agree(a, b))
                if worst < 25:
                    sys.exit(f"points k={ks_} f={fs} h={hs}: methods agree to {worst} digits")
                load, d1, d2, wet = r1
                rows.append([ks_, fs, P_VALUE, hs, sci(mp.log(-load)), sci(mp.log(d1)),
                             "1" if d2 > 0 else "-1", sci(mp.log(abs(d2))), sci(wet)])
    return rows, worst


# ------------------------------------------------------------------ extrema and work

# theta, c_h, attraction, range, k, f, p: the polysilicon hub (theta = 184, c_h = 5.12) at about
# RH = 0.5 and 0.95 (water, theta = 0), a flooding scene (slow: ~40 min), and a rough
# polysilicon-like surface with weak adhesion and a small Kelvin length over sigma (the last two).
#
# The rough surface: sigma = 1 um, R = 100 um, N = 5e8 /m^2 (sigma R N = 0.05, Greenwood and
# Williamson's value), the hub's polysilicon (E = 160 GPa, nu = 0.22: K = 112.1 GPa; H = 10 GPa),
# water at 25 C and RH = 0.5 (r_K = 0.757 nm, Laplace pressure 95.1 MPa):
#   k = d_K/sigma = 1e-3: d_K = r_K (cos theta_a + cos theta_b) = 1 nm at a contact angle of 48.6
#       degrees on both bodies (a partly hydrophilic, aged surface; 0 degrees gives k = 1.5e-3);
#   f = sqrt(2 pi) R N d_K = 1.25e-4, p = sqrt(2 pi) Delta_p / (K N R^(1/2) sigma^(3/2)) = 0.425
#       (the same formulas give the hub's 0.04 and 1.3);
#   c_h = 3 pi / (4 psi) = 2.8, psi = (E/H) (sigma/R)^(1/2) = 0.84;
#   range: van der Waals z0 = Z0/sigma = 3e-4 (Z0 = 0.3 nm), Dugdale z0/1.03;
#   theta = 1e4: weak adhesion, gamma ~ 1.1 J/m^2 on this surface (the hub's 0.1 J/m^2 gives
#       theta = 1.1e5, weaker still); the meniscus pulls with p f = 5.3e-5 against c_0 = 6.3e-4.
# Under van der Waals the attraction's power-law tail holds the minimum at h = 7.07; under
# Dugdale nothing reaches past the contacts and it lies at h = 153, where P ~ e^-1.2e4: the
# load there and G underflow a double (the Rust test then checks h_min and h0), and G is 1e-3
# of its solid and meniscus parts, which cancel. This scene was once dropped: method 1 split
# [h0, h0 + 14] at unit steps while the load decays over 1/h0 = 0.0065, mpmath.quad and
# findroot test absolute errors against values of e^-1.2e4, and method 2 lost the cancellation;
# see work_method1, work_method2 and scaled.
EXTREMA = [
    ("184", "5.12", "van_der_waals", "0.1", "0.5", "0.04", "1.3"),
    ("184", "5.12", "van_der_waals", "0.1", "6.8", "0.51", "0.095"),
    ("184", "5.12", "dugdale", "0.0970873786407767", "0.5", "0.04", "1.3"),
    ("10", "3.651", "van_der_waals", "0.1", "20", "50", "0.01"),
    # JKR (c_h column: lambda): theta, lambda as scripts/reference.py takes them.
    ("184", "1e5", "jkr", "0", "0.5", "0.04", "1.3"),
    ("10", "1", "jkr", "0", "3", "0.5", "0.1"),
    # The rough surface above (sigma = 1 um, RH = 0.5), weak adhesion.
    ("1e4", "2.8", "van_der_waals", "3e-4", "1e-3", "1.25e-4", "0.425"),
    ("1e4", "2.8", "dugdale", "2.912621359223301e-4", "1e-3", "1.25e-4", "0.425"),
]


def jkr_load(model, h, method):
    """P_solid(h), dP_solid/dh of the JKR law (MODEL.md section 3) by scripts/reference.py's
    method 1 (s = D1^(1/4) and closed forms) or method 2 (a root solve per node), unscaled."""
    r = (jkr.method1 if method == 1 else jkr.method2)(model, h)
    e = mp.exp(-jkr.kappa(h))
    return r["load"] * e, r["dload_dh"] * e


def total(c0, ch, kind, rng, k, f, p, h, method):
    if kind == "jkr":
        ps, dps_ = jkr_load(ch, h, method)  # ch is the reference.Model here
    else:
        ps, dps_ = dmt.total_load(c0, ch, kind, rng, h, method)
    pc, dpc, _, _ = capillary(k, f, p, h, method)
    return ps + pc, dps_ + dpc


def solid_law(c0, ch, kind, rng, d):
    """One asperity's load p(D) of the DMT law (MODEL.md section 7)."""
    if d < 0:
        if kind == "van_der_waals":
            return -c0 * (rng / (rng - d)) ** 2
        return -c0 * (1 + d / rng) if d >= -rng else mpf(0)
    dc = ch * ch
    if d <= dc:
        return d ** mpf(1.5) - c0
    return 2 * ch * d - c0


def work_method1(c0, ch, kind, rng, k, f, p, h0, hmin, pmin):
    """G by Gauss-Legendre over h of method 1's P. The integrand is divided by |P_min| (the
    largest |P| on [h0, inf), where P < 0: mpmath.quad tests an absolute error, and a weak
    scene's P ~ e^-1e4 would pass unrefined). Split at unit steps from h0 (the attraction's
    and the meniscus's reach), at h_min, and where e^{-h^2/2} has fallen from its value at h0
    by the LEVELS: for h0 >> 1 the load decays over 1/h0, inside the first unit step."""
    m = abs(pmin)
    P = lambda h: total(c0, ch, kind, rng, k, f, p, h, 1)[0] / m
    reach = max(k, rng if kind == "dugdale" else mpf(0))
    if kind == "jkr":
        reach = k
    pts = [h0 + i for i in range(0, int(reach) + 14)]
    tail = pts[-1] * 2 + 10
    inner = set(pts)
    if h0 < hmin < pts[-1]:
        inner.add(hmin)
    for lev in dmt.LEVELS:
        x = mp.sqrt(max(h0, mpf(0)) ** 2 + 2 * lev)
        if h0 < x < pts[-1]:
            inner.add(x)
    pts = sorted(inner) + [tail]
    body = mp.quad(P, pts, method="gauss-legendre")
    return -m * (body + mp.quad(P, [tail, mp.inf]))


def jkr_solid_work(model, h0):
    """int_{h0}^inf P_solid dh = int p(D) sqrt(pi/2) erfc((h0+D)/sqrt 2) dD for JKR: the
    elastic part in s = D1^(1/4) (D = s^4 - c_d s, p = s^6 - c_a s^3), the plastic part
    (c_p D - c_0) beyond Delta_c."""
    q = mp.sqrt(mp.pi / 2)
    t0 = lambda u: q * erfc_s(u)
    cd, ca = model.c_d, model.c_a
    s_top = model.t if model.plastic else model.s_of_D(max(mpf(0), -h0) + 60)
    ds = [model.s0] + [model.s_of_D(d) for d in (mpf("0.25"), 1, 4, 16, 64) if model.s_of_D(d) < s_top] + [s_top]
    el = mp.quad(lambda s_: (s_ ** 6 - ca * s_ ** 3) * t0(h0 + s_ ** 4 - cd * s_) * (4 * s_ ** 3 - cd), ds)
    pl = mpf(0)
    if model.plastic:
        dc = model.Dc
        pl = mp.quad(lambda d: (model.c_p * d - model.c_0) * t0(h0 + d), [dc, dc + 1, dc + 4, dc + 16, dc + 64])
    return el + pl


def gq_max_scaled(f, pts):
    """dmt.gq with the integrand divided by its largest magnitude at the split points
    (mpmath.quad tests an absolute error; the points include where the integrand peaks)."""
    m = max(abs(f(x)) for x in pts if mp.isfinite(x))
    if m == 0:
        return mpf(0)
    return m * dmt.gq(lambda x: f(x) / m, pts)


def decay_points(h0):
    """Offsets x > 0 where e^{-(h0+x)^2/2} has fallen from its value at x = 0 by the
    LEVELS (for h0 > 0; the weight then decays over 1/h0)."""
    if h0 <= 0:
        return []
    return [mp.sqrt(h0 * h0 + 2 * lev) - h0 for lev in dmt.LEVELS]


def capillary_work(k, f, p, h0):
    """int_{h0}^inf P_cap dh by tanh-sinh over h of method (2)'s P_cap, scaled by its value
    at h0 (|P_cap| falls with h), split at unit steps and at h0 + 4^j / max(1, h0)."""
    cap = lambda h: capillary(k, f, p, h, 2)[0]
    top = h0 + int(k) + 13
    cpts = {h0 + i for i in range(0, int(k) + 14)}
    cpts |= {h0 + mpf(4) ** j / max(1, h0) for j in range(-2, 4)}
    return gq_max_scaled(cap, sorted(x for x in cpts if x <= top) + [mp.inf])


def work_method2(c0, ch, kind, rng, k, f, p, h0):
    """G as the solid part by exchanged integrals plus the meniscus part over h, both with
    10 guard digits: for a far minimum the two nearly cancel (G ~ 1e-3 of either at
    h0 = 153) and the solid integrand cancels inside (D^(3/2) against c_0 for D ~ 1/h0),
    while mpmath.quad's error is absolute, ~10^-dps of the integrand's largest value."""
    with mp.workdps(mp.mp.dps + 10):
        return work_parts(c0, ch, kind, rng, k, f, p, h0)


def work_parts(c0, ch, kind, rng, k, f, p, h0):
    q = mp.sqrt(mp.pi / 2)
    if kind == "jkr":
        return -(jkr_solid_work(ch, h0) + capillary_work(k, f, p, h0))
    weight = lambda d: solid_law(c0, ch, kind, rng, d) * q * erfc_s(h0 + d)
    dc = ch * ch
    lo = -rng if kind == "dugdale" else -mp.inf
    pts = [lo, mpf(0)]
    if kind == "van_der_waals":
        pts = [-mp.inf, -1000 * rng, -10 * rng, -rng, mpf(0)]
    # The summit heights that carry the integral: around D = -h0 (where erfc turns), and,
    # when -h0 < 0, just above D = 0 (where the weight falls over 1/h0).
    peak = -h0
    for x in [peak - 8, peak - 2, peak, peak + 2, peak + 8, peak + 20] + decay_points(h0):
        if x > lo and x != 0:
            pts.append(x)
    if dc != mp.inf:
        pts.append(dc)
    pts = sorted(set(pts))
    pts.append(max(pts[-1], mpf(0)) + 40 + abs(h0))
    return -(gq_max_scaled(weight, pts) + capillary_work(k, f, p, h0))


def scaled(g, ends, c):
    """g(x) e^{(x^2 - c^2)/2} over its largest magnitude at the bracket's ends: the same
    roots, but of size ~1 across the bracket. findroot (anderson) stops once |value| is
    below its tolerance, an absolute one (~1e-18 at mp.dps = 20): unscaled, the weak Dugdale
    scene (P ~ e^-1.2e4) stopped at its first step: h_min 1.7e-3 off, h0 = h_min."""
    e = lambda x: mp.exp((x * x - c * c) / 2)
    m = max(abs(g(x) * e(x)) for x in ends)
    return lambda x: g(x) * e(x) / m


def extrema(quick, only=None):
    rows = []
    worst = mpf(100)
    chosen = EXTREMA[:1] if quick else EXTREMA
    if only is not None:
        chosen = [EXTREMA[i] for i in only]
    for th, chs, kind, rg, ks_, fs, ps_ in chosen:
        theta = dbl(th)
        c0 = 2 * mp.pi / theta
        if kind == "jkr":
            jkr.setup(mp.mp.dps)
            ch = jkr.Model("adhesive", th, chs)  # the model object stands in for c_h
        else:
            ch = mp.inf if chs == "inf" else dbl(chs)
        rng, k, f, p = dbl(rg), dbl(ks_), dbl(fs), dbl(ps_)
        slope = lambda h: total(c0, ch, kind, rng, k, f, p, h, 1)[1]
        h = mpf(-4)
        prev = slope(h)
        while True:
            hn = h + mpf("0.05")
            s = slope(hn)
            if prev < 0 <= s:
                break
            h, prev = hn, s
            if h > 200:
                sys.exit(f"no minimum for {th} {chs} {kind} {rg} {ks_}")
        hmin = mp.findroot(scaled(slope, (h, hn), hn), (h, hn), solver="anderson")
        pmin1 = total(c0, ch, kind, rng, k, f, p, hmin, 1)[0]
        pmin2 = total(c0, ch, kind, rng, k, f, p, hmin, 2)[0]
        worst = min(worst, agree(pmin1, pmin2))
        # h0: P = 0 on the falling branch, left of the minimum.
        P = lambda x: total(c0, ch, kind, rng, k, f, p, x, 1)[0]
        lo = hmin - 1
        while P(lo) < 0:
            lo -= 1
        h0 = mp.findroot(scaled(P, (lo, hmin), hmin), (lo, hmin), solver="anderson")
        w1 = work_method1(c0, ch, kind, rng, k, f, p, h0, hmin, pmin1)
        w2 = work_method2(c0, ch, kind, rng, k, f, p, h0)
        worst = min(worst, agree(w1, w2))
        print(f"{th} {chs} {kind} {rg} k={ks_}: hmin {mp.nstr(hmin, 12)} Pmin {mp.nstr(pmin1, 12)} "
              f"h0 {mp.nstr(h0, 12)} G {mp.nstr(w1, 12)} / {mp.nstr(w2, 12)}", file=sys.stderr)
        if worst < 15:
            sys.exit(f"extrema {th} {chs} {kind} {rg} {ks_}: methods agree to {worst} digits")
        rows.append([th, chs, kind, rg, ks_, fs, ps_, sci(hmin), sci(pmin1), sci(h0), sci(w1)])
    return rows, worst


def write(path, title, head, rows, worst, dps):
    with open(path, "w") as out:
        out.write(f"# wearopt reference table: {title} (MODEL.md section 9)\n")
        out.write(f"# generated by: python3 scripts/reference_capillary.py --out tests/data  "
                  f"(mpmath {mp.__version__}, mp.dps = {dps})\n")
        out.write("# inputs are the IEEE doubles of the printed decimals; two methods (see the script) "
                  f"agree to {mp.nstr(worst, 3)} digits or more\n")
        out.write(",".join(head) + "\n")
        for r in rows:
            out.write(",".join(r) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", default="tests/data")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--only", choices=["points", "extrema"])
    ap.add_argument("--rows", help="comma-separated indices of EXTREMA to compute (default all)")
    a = ap.parse_args()
    if a.only in (None, "points"):
        mp.mp.dps = 40
        rows, worst = points(a.quick)
        write(os.path.join(a.out, "reference_capillary_points.csv"), "capillary load",
              ["k", "f", "p", "h", "ln_load", "ln_dload_dh", "d2_sign", "ln_abs_d2load_dh2",
               "wetted_fraction"], rows, worst, 40)
    if a.only in (None, "extrema"):
        mp.mp.dps = 20
        only = [int(i) for i in a.rows.split(",")] if a.rows else None
        rows, worst = extrema(a.quick, only)
        write(os.path.join(a.out, "reference_capillary_extrema.csv"), "the rough surface with a meniscus",
              ["theta", "c_h", "attraction", "range", "k", "f", "p", "h_min", "load_min", "h_0",
               "work"], rows, worst, 20)


if __name__ == "__main__":
    main()
