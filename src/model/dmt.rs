//! The DMT asperity law of docs/model.md §7: the load of the asperities that are
//! attracted but not in contact.
//!
//! With d = -Δ ≥ 0 the gap of an asperity (over σ) and u = h - d the argument of
//! the weight φ̄ = e^{-u²/2}, the non-contact load is
//!
//! ```text
//! N(h) = -c_0 ∫_0^{d_max} w(d) e^{-(h-d)²/2} dd
//!   van der Waals: w(d) = (z0/(z0+d))²,  d_max = ∞
//!   Dugdale:       w(d) = 1 - d/Δ_h,     d_max = Δ_h
//! N'(h)  = -c_0 ∫ w (-u) e^{-u²/2} dd,   N''(h) = -c_0 ∫ w (u² - 1) e^{-u²/2} dd
//! ```
//!
//! The contact terms of the law (Hertz load Δ^{3/2} - c_0 up to Δc = c_h², the
//! plastic c_p Δ - c_0 beyond) are the contact machinery of `integrals.rs` with
//! c_a = c_d = 0: the same panels, the plastic share and every -c_0 in closed form
//! (erfc), and only the Hertz integral ∫ Δ^{3/2} φ̄ by quadrature, in [`hertz`]
//! here (in t = Δ^{1/2}, where JKR needs Δ^{1/4}).
//!
//! **Method.** Every integral is composite Gauss–Legendre in d, on panels whose
//! breakpoints are (a) the points where the log-weight u²/2 has risen by the
//! layout's step (12 for van der Waals, 8 for Dugdale) above its smallest value on
//! [0, d_max], up to [`LOG_WEIGHT_CUT`] (e^{-46} ≈ 1e-20), and, for van der Waals, (b) the geometric
//! points d = z0 (4^k - 1) wherever a panel would otherwise span more than a factor 4
//! in z0 + d: then every panel spans at most 4, so that w changes by at most 16 across it and its
//! length is at most 3/2 of the distance to the pole of w at d = -z0: every panel
//! integrand is then analytic in a Bernstein ellipse of parameter ρ ≥ 3 (order 20:
//! error ≲ 3^{-40} ≈ 1e-19 of the panel's size, times the Gaussian's growth off the
//! real axis, e^{y²/2} ≤ e^{5.3} for a step-12 panel, y ≤ 2.45·(3 - 1/3)/2). The nodes are placed in d, so
//! 1 - d/Δ_h and z0 + d are formed without cancellation for every Δ_h in
//! [1e-6, 1e3] and z0 in [1e-4, 10]: the closed forms in erfc (docs/model.md §7,
//! "checks") cancel for small Δ_h and are not used. The weight is taken relative
//! to its largest value on the window, e^{-u_n²/2} with u_n the u nearest to 0,
//! as `(u - u_n)(u + u_n)` with `u - u_n = d_n - d` exact: every result is a
//! mantissa scaled by e^{u_n²/2}, which for van der Waals and h ≥ 0 is 1.
//!
//! The exponentials, one per node and most of the cost, are `special::exp_fast`: a
//! branch-free polynomial within 2 ulps of `f64::exp`, so that the loop over a
//! panel's nodes vectorizes. The rounding of the log-weight itself (ε·u²/2 ≤ 46ε)
//! is the larger error. Where the CPU has AVX2 (checked once, at run time) the
//! quadratures run a build of the same code with 4-wide vectors instead of SSE2's
//! 2: the same numbers bit for bit (no fused multiply–adds, one node per lane,
//! serial sums; test `wide_vectors_change_no_bit`), so results do not depend on
//! the machine.
//!
//! **Orders.** A panel whose largest weight is e^{-L} of the window's (L the drop of
//! the log-weight from the peak to the panel's nearest point, less 2 ln of the rise of
//! w towards d = 0 under van der Waals) needs only ≈ 1e-16·e^{L} of its own size. Its
//! order steps down with L: with ρ ≥ 3 an n-point panel errs by ≲ 3^{-2n} of its
//! size. Dugdale keeps the contact integral's schedule on a step-8 walk (20 below
//! L = 10, then 16, 12, 8, 6 below 16, 22, 28, 34, and 4: e^{-L}·3^{-2n} < 1e-17 at
//! every step). Van der Waals walks in steps of 12 and steps down two levels
//! earlier (20 below L = 8, then 16, 12, 8, 6 below 14, 20, 26, 32, and 4; e^{-L}·
//! 3^{-2n}·e^{5.3} ≲ 6e-16 at n = 12 from L = 14). A van der Waals panel of
//! length ≤ 1 that spans at most 3/2 in z0 + d and across which the log-weight
//! changes by at most 1 takes at most 12 points: the pole is then ≥ 5 half-lengths
//! away (at ρ ≥ 9.9), so on the ellipse ρ = 8 w grows by at most (4/0.94)² ≈ 18
//! and the weight by at most e^{4} (≤ 2 off the axis, ≤ 2 units of its slope
//! along it), and the panel errs by ≲ 8^{-24}·18·e^{4} ≈ 2e-19. Together: 100
//! nodes instead of 150 at z0 = 0.1, h = 1. Measured against a fine layout (step 4,
//! 20 points on every panel) over z0 ∈ [1e-4, 10], h ∈ [-4, 20) and deep
//! contact: ≤ 2.5e-15 (van der Waals) and 4.0e-15 (Dugdale) in N, N'/(1 + |h|),
//! N''/(1 + h²) relative to |N| (`layout_matches_fine_layout`).
//!
//! **Van der Waals tail.** For h ≥ [`VDW_SERIES_FROM`] the contacting region
//! d ≈ 0 carries less than e^{-h²/2}(h/z0)² ≲ e^{-175} of the term, and
//! N(h) = -c_0 √(2π) z0² Σ_k (2k+1)!! / b^{2k+2} with b = z0 + h (Taylor series of
//! (z0+d)^{-2} about the weight's peak, integrated against the full Gaussian), an
//! asymptotic series whose terms fall below 1e-17 of the first after at most 20
//! terms at b ≥ 20 (the smallest term, near k = b²/2, is ~e^{-b²/2}). So P̄ at
//! h = 40 or 60 is this power law, not an underflow; it decays like b^{-2}.

use super::gauss;
use super::law::Attraction;
use super::quadrature::{contact_level, Quadrature};
use super::special::{exp_fast, SQRT_TWO_PI};

/// The window ends where the weight is e^{-46} below its largest value.
pub const LOG_WEIGHT_CUT: f64 = 46.0;

/// Gauss–Legendre points per panel.
pub const ORDER: usize = 20;

/// Ratio of the geometric breakpoints' distances from the pole of w.
const GEOMETRIC_RATIO: f64 = 4.0;

/// From this h on, the van der Waals term is its asymptotic series.
pub const VDW_SERIES_FROM: f64 = 20.0;

/// Walk points per side (a walk has at most cut/step + 1 ≤ 13 of them).
const MAX_WALK: usize = 16;

/// Geometric points (log4 of 60/z0: 10 at z0 = 1e-4, 46 at z0 = 1e-26).
const MAX_GEOMETRIC: usize = 48;

/// The largest Gauss–Legendre order a panel uses ([`ORDER`]).
const MAX_ORDER: usize = ORDER;

/// A Hertz panel that starts near t = 0 (below half its end) and spans a
/// log-weight change above this is halved in t ([`hertz`]).
const SPLIT_ABOVE: f64 = 4.0;

/// The largest order a [`Quadrature`] may ask for (the last of [`gauss::ORDERS`]).
const MAX_CONTACT_ORDER: usize = gauss::ORDERS[gauss::ORDERS.len() - 1];

/// The last two passes of a panel: the exponentials of the log-weights `arg` (in
/// place, a branch-free loop that vectorizes), then Σ f, Σ -f u, Σ f (u² - 1)
/// with f = w e^{arg}, summed serially in node order.
#[inline(always)]
fn panel_sums(w: &[f64], arg: &mut [f64], u: &[f64]) -> (f64, f64, f64) {
    for x in arg.iter_mut() {
        *x = exp_fast(*x);
    }
    let (mut s0, mut s1, mut s2) = (0.0, 0.0, 0.0);
    for ((&w, &e), &u) in w.iter().zip(arg.iter()).zip(u) {
        let f = w * e;
        s0 += f;
        s1 -= f * u;
        s2 += f * (u * u - 1.0);
    }
    (s0, s1, s2)
}

/// The non-contact load and its first two h-derivatives, as mantissas scaled
/// by `e^{exponent}` (value = mantissa · e^{-exponent}).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Noncontact {
    /// N(h) mantissa (≤ 0).
    pub load: f64,
    /// N'(h) mantissa.
    pub dload_dh: f64,
    /// N''(h) mantissa.
    pub d2load_dh2: f64,
    /// u_n²/2: the scale exponent of the three mantissas.
    pub exponent: f64,
}

impl Noncontact {
    /// Nothing (no adhesion).
    pub const ZERO: Noncontact = Noncontact {
        load: 0.0,
        dload_dh: 0.0,
        d2load_dh2: 0.0,
        exponent: 0.0,
    };
}

/// The non-contact load at separation h for adhesive coefficient c_0 = 2π/θ.
pub fn noncontact(attraction: Attraction, c_0: f64, h: f64) -> Noncontact {
    if c_0 == 0.0 {
        return Noncontact::ZERO;
    }
    match attraction {
        Attraction::VanDerWaals { range } if h >= VDW_SERIES_FROM => vdw_series(range, c_0, h),
        _ => quadrature(attraction, c_0, h),
    }
}

/// The asymptotic series of the van der Waals term (module docs).
fn vdw_series(z0: f64, c_0: f64, h: f64) -> Noncontact {
    let b = z0 + h;
    let r = 1.0 / (b * b);
    // S = Σ a_k r^{k+1}, a_k = (2k+1)!!; S' and S'' in b termwise.
    let (mut s, mut ds, mut d2s) = (0.0, 0.0, 0.0);
    let mut a = 1.0; // (2k+1)!! r^{k+1}
    let mut term = r;
    for k in 0..40 {
        let n = 2.0 * k as f64 + 2.0; // the power of 1/b
        let t = a * term;
        s += t;
        ds -= n * t / b;
        d2s += n * (n + 1.0) * t * r;
        if t < 1e-18 * s {
            break;
        }
        a *= 2.0 * k as f64 + 3.0;
        term *= r;
    }
    let scale = -c_0 * SQRT_TWO_PI * z0 * z0;
    Noncontact {
        load: scale * s,
        dload_dh: scale * ds,
        d2load_dh2: scale * d2s,
        exponent: 0.0,
    }
}

/// δ ≥ 0 with ((|u_n| + δ)² - u_n²)/2 = level, without cancellation.
#[inline]
fn offset_at_level(u_n: f64, level: f64) -> f64 {
    2.0 * level / ((u_n * u_n + 2.0 * level).sqrt() + u_n.abs())
}

/// The Gauss–Legendre order of the panel [a, b] (module docs, "Orders"): the
/// schedule of [`super::Quadrature::panel_order`] at the panel's level, the
/// log-weight drop from the window's peak to the panel's point nearest it, less
/// the growth of the van der Waals factor w from d_n to the panel's left end.
#[inline]
fn panel_order(
    layout: &Layout,
    attraction: Attraction,
    h: f64,
    d_n: f64,
    u_n: f64,
    a: f64,
    b: f64,
) -> usize {
    let x = d_n.clamp(a, b);
    let u = h - x;
    let mut level = 0.5 * (u - u_n) * (u + u_n);
    if let Attraction::VanDerWaals { range } = attraction {
        if a < d_n {
            level -= 2.0 * ((range + d_n) / (range + a)).ln();
        }
    }
    layout
        .schedule
        .iter()
        .find(|(below, _)| level < *below)
        .map_or(4, |&(_, n)| n)
}

/// The panel layout of [`quadrature`]: the log-weight walk's step and cut, and the
/// order schedule by level (orders ≤ [`ORDER`]).
#[derive(Debug, Clone, Copy)]
struct Layout {
    step: f64,
    cut: f64,
    schedule: [(f64, usize); 5],
}

/// The van der Waals layout (module docs, "Orders").
const LAYOUT_VDW: Layout = Layout {
    step: 12.0,
    cut: LOG_WEIGHT_CUT,
    schedule: [(8.0, ORDER), (14.0, 16), (20.0, 12), (26.0, 8), (32.0, 6)],
};

/// The Dugdale layout (module docs, "Orders").
const LAYOUT_DUGDALE: Layout = Layout {
    step: 8.0,
    cut: LOG_WEIGHT_CUT,
    schedule: [(10.0, ORDER), (16.0, 16), (22.0, 12), (28.0, 8), (34.0, 6)],
};

/// The composite Gauss–Legendre form (module docs).
fn quadrature(attraction: Attraction, c_0: f64, h: f64) -> Noncontact {
    quadrature_with(layout_of(attraction), attraction, c_0, h)
}

/// The production layout of an attraction.
fn layout_of(attraction: Attraction) -> &'static Layout {
    match attraction {
        Attraction::VanDerWaals { .. } => &LAYOUT_VDW,
        Attraction::Dugdale { .. } => &LAYOUT_DUGDALE,
    }
}

/// [`quadrature`] on a given layout.
fn quadrature_with(layout: &Layout, attraction: Attraction, c_0: f64, h: f64) -> Noncontact {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { quadrature_avx2(layout, attraction, c_0, h) };
    }
    quadrature_body(layout, attraction, c_0, h)
}

/// [`quadrature_body`] compiled for AVX2 (module docs).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn quadrature_avx2(layout: &Layout, attraction: Attraction, c_0: f64, h: f64) -> Noncontact {
    quadrature_body(layout, attraction, c_0, h)
}

/// [`quadrature_with`]'s work.
#[inline(always)]
fn quadrature_body(layout: &Layout, attraction: Attraction, c_0: f64, h: f64) -> Noncontact {
    let d_max = match attraction {
        Attraction::Dugdale { range } => range,
        Attraction::VanDerWaals { .. } => f64::INFINITY,
    };
    // The point of the window nearest the weight's peak u = 0.
    let d_n = h.clamp(0.0, d_max);
    let u_n = h - d_n;
    // The walk's breakpoints in ascending order: leftwards ones (stored
    // descending in `left`), d_n, then rightwards ones.
    let (step, cut) = (layout.step, layout.cut);
    let mut left = [0.0f64; MAX_WALK];
    let mut n_left = 0;
    let mut right = [0.0f64; MAX_WALK];
    let mut n_right = 0;
    // Rightwards (larger d, u falling below u_n ≤ 0).
    let mut hi = d_n;
    if u_n <= 0.0 && d_n < d_max {
        let mut level = 0.0;
        while level < cut && n_right < MAX_WALK {
            level = (level + step).min(cut);
            let d = d_n + offset_at_level(u_n, level);
            if d >= d_max {
                hi = d_max;
                right[n_right] = d_max;
                n_right += 1;
                break;
            }
            hi = d;
            right[n_right] = d;
            n_right += 1;
        }
    }
    // Leftwards (smaller d, u rising above u_n ≥ 0). Under van der Waals the
    // growth of w towards d = 0 can outweigh the Gaussian: then walk to 0.
    let left_cut = match attraction {
        Attraction::VanDerWaals { range } if h > 0.0 => {
            let near = 0.5 * h * h - 2.0 * ((range + h) / range).ln();
            if near <= cut {
                f64::INFINITY
            } else {
                cut
            }
        }
        _ => cut,
    };
    let mut lo = d_n;
    if u_n >= 0.0 && d_n > 0.0 {
        let mut level = 0.0;
        while n_left < MAX_WALK {
            level = (level + step).min(left_cut);
            let d = d_n - offset_at_level(u_n, level);
            if d <= 0.0 {
                lo = 0.0;
                left[n_left] = 0.0;
                n_left += 1;
                break;
            }
            lo = d;
            left[n_left] = d;
            n_left += 1;
            if level >= left_cut {
                break;
            }
        }
    }
    let mut walk = [0.0f64; 2 * MAX_WALK + 1];
    let mut n_walk = 0;
    for &d in left[..n_left]
        .iter()
        .rev()
        .chain([d_n].iter())
        .chain(&right[..n_right])
    {
        walk[n_walk] = d;
        n_walk += 1;
    }
    // Merge the geometric points (ascending) into the walk, each only where the
    // panel from the last breakpoint to the next walk point spans more than the
    // ratio in z0 + d: every panel then spans at most that ratio.
    let mut breaks = [0.0f64; 2 * MAX_WALK + 1 + MAX_GEOMETRIC];
    let mut n = 0;
    let mut k_walk = 0;
    if let Attraction::VanDerWaals { range } = attraction {
        let mut g = range * (GEOMETRIC_RATIO - 1.0);
        while g < hi && n + n_walk < breaks.len() {
            if g > lo {
                while k_walk < n_walk && walk[k_walk] <= g {
                    breaks[n] = walk[k_walk];
                    n += 1;
                    k_walk += 1;
                }
                // walk[0] = lo < g was pushed, and walk[n_walk - 1] = hi > g.
                let next = walk[k_walk.min(n_walk - 1)];
                if range + next > GEOMETRIC_RATIO * (range + breaks[n - 1]) {
                    breaks[n] = g;
                    n += 1;
                }
            }
            g = range * (GEOMETRIC_RATIO * (g / range + 1.0) - 1.0);
        }
    }
    for &d in &walk[k_walk..n_walk] {
        breaks[n] = d;
        n += 1;
    }
    let breaks = &breaks[..n];
    let (mut load, mut dload, mut d2load) = (0.0, 0.0, 0.0);
    let (mut weight, mut arg, mut us) = ([0.0; MAX_ORDER], [0.0; MAX_ORDER], [0.0; MAX_ORDER]);
    for k in 1..breaks.len() {
        let (a, b) = (breaks[k - 1], breaks[k]);
        if b <= a {
            continue;
        }
        let mut order = panel_order(layout, attraction, h, d_n, u_n, a, b);
        if let Attraction::VanDerWaals { range } = attraction {
            // A short panel far from the pole, across which the weight is
            // nearly flat (module docs, "Orders").
            let (ua, ub) = (h - a, h - b);
            if b - a <= 1.0
                && 2.0 * (range + b) <= 3.0 * (range + a)
                && (0.5 * (ua - ub) * (ua + ub)).abs() <= 1.0
            {
                order = order.min(12);
            }
        }
        let rule = gauss::rule(order);
        let mid = 0.5 * (a + b);
        let half = 0.5 * (b - a);
        // Three passes over the panel's nodes, so that the exponentials (the
        // bulk of the cost) form a branch-free loop the compiler vectorizes.
        let count = rule.nodes.len().min(MAX_ORDER);
        match attraction {
            Attraction::VanDerWaals { range } => {
                for i in 0..count {
                    let d = mid + half * rule.nodes[i];
                    let q = range / (range + d);
                    let u = h - d;
                    us[i] = u;
                    weight[i] = rule.weights[i] * q * q;
                    arg[i] = -0.5 * (d_n - d) * (u + u_n);
                }
            }
            Attraction::Dugdale { range } => {
                for i in 0..count {
                    let d = mid + half * rule.nodes[i];
                    let u = h - d;
                    us[i] = u;
                    // 1 - d/Δ_h as (Δ_h - d)/Δ_h: exact near d = Δ_h.
                    weight[i] = rule.weights[i] * ((range - d) / range);
                    arg[i] = -0.5 * (d_n - d) * (u + u_n);
                }
            }
        }
        let (pl, pd, pdd) = panel_sums(&weight[..count], &mut arg[..count], &us[..count]);
        load += pl * half;
        dload += pd * half;
        d2load += pdd * half;
    }
    // N = -c_0 ∫ w φ, N' = -c_0 ∫ w (-u) φ, N'' = -c_0 ∫ w (u² - 1) φ.
    Noncontact {
        load: -c_0 * load,
        dload_dh: -c_0 * dload,
        d2load_dh2: -c_0 * d2load,
        exponent: 0.5 * u_n * u_n,
    }
}

/// The Hertz part of the DMT law's elastic contact integral and its first two
/// h-derivatives, scaled by e^{κ(h)}:
///
/// ```text
/// H(h) = ∫_0^{Δc} Δ^{3/2} φ̄ dΔ,  H' = ∫ Δ^{3/2} (-u) φ̄ dΔ,  H'' = ∫ Δ^{3/2} (u² - 1) φ̄ dΔ,  u = h + Δ
/// ```
///
/// (the constant -c_0 of the elastic asperity load is closed form, added by the
/// caller) on the contact integral's panels `bounds` (ascending in Δ, each spanning
/// a log-weight change ≤ the quadrature's step), each taken by Gauss–Legendre in
/// t = Δ^{1/2}: there the integrand 2t⁴ e^{-(h + t²)²/2} is a polynomial times an
/// entire weight whose exponent is quartic in t (the JKR coordinate Δ^{1/4}, which
/// c_d ≠ 0 needs, makes it octic and needs twice the panels). For h ≤ 0,
/// u = h + t² is formed about the weight's peak t_r = (min(-h, Δc))^{1/2} as
/// u_r + δ(2 t_r + δ), δ = t - t_r, so that far left (h ≈ -3e7) the nodes carry no
/// ε|h| of rounding in u, only a common shift u_r.
///
/// Near t = 0 the exponent is quartic in t rather than quadratic: one 20-point rule
/// on a panel from 0 across a log-weight change of 12 errs by 1e-12 (h = 0), so a
/// panel that starts below half its end in t and spans a change above
/// [`SPLIT_ABOVE`] is halved in t; then every panel agrees with a fine layout to
/// 1e-15 (`hertz_matches_fine_layout` in `integrals.rs`). The nodes' exponentials
/// are `special::exp_fast`, in the same three passes as the non-contact quadrature.
pub(super) fn hertz(quadrature: &Quadrature, h: f64, dc: f64, bounds: &[f64]) -> (f64, f64, f64) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { hertz_avx2(quadrature, h, dc, bounds) };
    }
    hertz_body(quadrature, h, dc, bounds)
}

/// [`hertz_body`] compiled for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn hertz_avx2(quadrature: &Quadrature, h: f64, dc: f64, bounds: &[f64]) -> (f64, f64, f64) {
    hertz_body(quadrature, h, dc, bounds)
}

/// [`hertz`]'s work.
#[inline(always)]
fn hertz_body(quadrature: &Quadrature, h: f64, dc: f64, bounds: &[f64]) -> (f64, f64, f64) {
    // The log-weight's minimum over [0, Δc], and a panel's level above it.
    let peak = (-h).max(0.0).min(dc);
    let level_of = |a: f64, b: f64| contact_level(h, peak, a, b);
    let t_ref = peak.sqrt();
    let u_ref = h + t_ref * t_ref;
    let (mut load, mut dload, mut d2load) = (0.0, 0.0, 0.0);
    let (mut weight, mut arg, mut us) = (
        [0.0; MAX_CONTACT_ORDER],
        [0.0; MAX_CONTACT_ORDER],
        [0.0; MAX_CONTACT_ORDER],
    );
    let Some((&first, rest)) = bounds.split_first() else {
        return (0.0, 0.0, 0.0);
    };
    let (mut d_lo, mut t_lo) = (first, first.sqrt());
    for &d_hi in rest {
        let t_hi = d_hi.sqrt();
        let level = level_of(d_lo, d_hi);
        // The log-weight's change across the panel (it is convex in Δ); a panel
        // from near t = 0 across a large change is halved in t (doc above).
        let change = level_of(d_lo, d_lo).max(level_of(d_hi, d_hi)) - level;
        let t_mid = 0.5 * t_hi;
        let (pieces, n) = if 4.0 * d_lo < d_hi && change > SPLIT_ABOVE {
            let upper = level_of(t_mid * t_mid, d_hi);
            ([(t_lo, t_mid, level), (t_mid, t_hi, upper)], 2)
        } else {
            ([(t_lo, t_hi, level), (t_hi, t_hi, level)], 1)
        };
        (d_lo, t_lo) = (d_hi, t_hi);
        for &(t_lo, t_hi, level) in &pieces[..n] {
            let rule = gauss::rule(quadrature.panel_order(level));
            let (dt_lo, dt_hi) = (t_lo - t_ref, t_hi - t_ref);
            let to_mid = 0.5 * (dt_lo + dt_hi);
            let half = 0.5 * (dt_hi - dt_lo);
            let count = rule.nodes.len().min(MAX_CONTACT_ORDER);
            for i in 0..count {
                let dt = to_mid + half * rule.nodes[i];
                let t = t_ref + dt;
                let u = u_ref + dt * (2.0 * t_ref + dt);
                us[i] = u;
                // e^{-u²/2} e^{κ(h)}: for h > 0 (t_r = 0) that is e^{-Δ(h + Δ/2)}.
                let t2 = t * t;
                arg[i] = if h > 0.0 {
                    -t2 * (h + 0.5 * t2)
                } else {
                    -0.5 * u * u
                };
                // Δ^{3/2} dΔ = 2t⁴ dt.
                weight[i] = rule.weights[i] * 2.0 * (t2 * t2);
            }
            let (pl, pd, pdd) = panel_sums(&weight[..count], &mut arg[..count], &us[..count]);
            load += pl * half;
            dload += pd * half;
            d2load += pdd * half;
        }
    }
    (load, dload, d2load)
}

/// The DMT law's entry in the registry: Hertz contact with the adhesive offset
/// −c_0 (the contact machinery of `integrals.rs` with c_a = c_d = 0) and the
/// attraction of the asperities out of contact above.
pub struct Dmt;

impl super::asperity_law::Law for Dmt {
    fn name(&self) -> &'static str {
        "dmt"
    }
    fn label(&self) -> &'static str {
        "DMT"
    }
    fn takes_attraction(&self) -> bool {
        true
    }
    fn range_meaning(&self) -> &'static str {
        "z0 = Z0/σ for van_der_waals, h0/σ for dugdale"
    }
    fn section(&self) -> &'static str {
        "docs/model.md §7"
    }
    fn valid_tabor(&self) -> (f64, f64) {
        (0.0, super::law::TRANSITION_TABOR.0)
    }
    fn description(&self, attraction: super::law::AttractionKind) -> &'static str {
        match attraction {
            super::law::AttractionKind::VanDerWaals => "DMT with van der Waals attraction of asperities not in contact (range z0 = Z0/σ = {z0}, Hamaker constant A = 12π Z0² γ = {hamaker} J)",
            super::law::AttractionKind::Dugdale => "DMT with Dugdale attraction of asperities not in contact (stress 1.03 γ/Z0 over h0 = Z0/1.03; h0/σ = {dugdale_range})",
        }
    }
    fn hamaker_factor(&self, attraction: super::law::AttractionKind) -> Option<f64> {
        (attraction == super::law::AttractionKind::VanDerWaals).then_some(12.0)
    }
    fn attracts_out_of_contact(&self) -> bool {
        true
    }
    fn closed_form_pull_off(&self) -> Option<f64> {
        Some(2.0)
    }
    fn with_range(
        &self,
        attraction: super::law::AttractionKind,
        range: f64,
    ) -> super::law::AsperityLaw {
        super::law::AsperityLaw::Dmt(Attraction::new(attraction, range))
    }
    fn prepare(
        &self,
        law: super::law::AsperityLaw,
        c: &super::coefficients::Coefficients,
    ) -> super::asperity_law::Prepared {
        let contact = super::coefficients::Coefficients {
            c_a: 0.0,
            c_d: 0.0,
            ..*c
        };
        super::asperity_law::Prepared::closed_form(law, contact, c.c_0)
    }
    fn closed_form_attraction(&self, law: super::law::AsperityLaw) -> Option<Attraction> {
        match law {
            super::law::AsperityLaw::Dmt(a) => Some(a),
            _ => None,
        }
    }
    fn separation_scale(
        &self,
        law: super::law::AsperityLaw,
        _c: &super::coefficients::Coefficients,
    ) -> f64 {
        // The minimum lies within a few units of the attraction's reach.
        1.0 + law.range().min(1e3)
    }
    fn outside_regime(&self, tabor: f64) -> Option<super::warnings::Warning> {
        (tabor > self.valid_tabor().1).then_some(super::warnings::Warning::OutsideDmtRegime {
            tabor_parameter: tabor,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dugdale with Δ_h → 0: N → -c_0 (Δ_h/2) e^{-h²/2} (docs/model.md §7). Expanding
    /// e^{hd - d²/2} under ∫_0^{Δ_h} (1 - d/Δ_h) … dd gives the next orders,
    /// -c_0 (Δ_h/2)(1 + h Δ_h/3 + (h² - 1) Δ_h²/12 + O(h³Δ_h³)), below 1e-13 at Δ_h = 1e-6, h ≤ 40.
    #[test]
    fn dugdale_short_range_limit() {
        let dh = 1e-6;
        for &h in &[-3.0, 0.0, 0.7, 5.0, 40.0] {
            let n = noncontact(Attraction::Dugdale { range: dh }, 1.0, h);
            let value = n.load * (-n.exponent).exp();
            let scaled = -(0.5 * dh) * (1.0 + h * dh / 3.0 + (h * h - 1.0) * dh * dh / 12.0);
            // Compare the mantissas at the scale e^{-(h - Δ_h)²/2} or e^{-h²/2}.
            let want = scaled * (-0.5 * h * h + n.exponent).exp();
            assert!(
                (n.load / want - 1.0).abs() < 1e-11,
                "h={h}: {} vs {want} ({value})",
                n.load
            );
        }
    }

    /// `exp_fast` against `f64::exp` (glibc, < 1 ulp): within 2 ulps over the
    /// whole range the quadratures use and beyond, and clamped (finite) outside.
    #[test]
    fn exp_fast_matches_std() {
        let mut worst = 0.0f64;
        let mut x = -708.0;
        while x <= 709.0 {
            for dx in [0.0, 1e-9, 0.3465, 0.34658, 0.693] {
                let y = x + dx;
                if y > 709.0 {
                    continue;
                }
                let e = (exp_fast(y) / y.exp() - 1.0).abs();
                worst = worst.max(e);
            }
            x += 0.0137;
        }
        for y in [0.0, -0.0, 1e-300, -1e-300, 1e-17, -1e-17] {
            assert_eq!(exp_fast(y), 1.0, "{y}");
        }
        eprintln!("exp_fast: worst relative error {worst:e}");
        assert!(
            worst <= 2.0 * f64::EPSILON,
            "worst relative error {worst:e}"
        );
        assert!(exp_fast(-1e6) > 0.0 && exp_fast(-1e6) < 1e-307);
        assert!(exp_fast(1e6).is_finite());
    }

    /// The series and the quadrature agree where both are valid.
    #[test]
    fn vdw_series_meets_quadrature() {
        for &z0 in &[1e-4, 0.1, 10.0] {
            let a = vdw_series(z0, 1.0, VDW_SERIES_FROM);
            let b = quadrature(Attraction::VanDerWaals { range: z0 }, 1.0, VDW_SERIES_FROM);
            assert_eq!(b.exponent, 0.0);
            assert!((a.load / b.load - 1.0).abs() < 1e-14, "{z0}: {a:?} {b:?}");
            assert!((a.dload_dh / b.dload_dh - 1.0).abs() < 1e-13, "{z0}");
            assert!((a.d2load_dh2 / b.d2load_dh2 - 1.0).abs() < 1e-13, "{z0}");
        }
    }

    /// The production layout against a fine one (log-weight step 4, window e^{-46},
    /// 20 points on every panel: each panel's error ≲ 3^{-40} of its size by the
    /// Bernstein bound of the module docs), for both attractions over z0, Δ_h ∈
    /// [1e-4, 10] (4 per decade; Dugdale on to 1e3) and h ∈ [-4, 20) in steps of 0.05,
    /// plus deep contact. N is measured against itself, N' against |N|(1 + |h|) and
    /// N'' against |N|(1 + h²), the sizes of the terms they integrate.
    #[test]
    fn layout_matches_fine_layout() {
        const FINE: Layout = Layout {
            step: 4.0,
            cut: 46.0,
            schedule: [(f64::INFINITY, ORDER); 5],
        };
        let mut hs: Vec<f64> = (0..480).map(|k| -4.0 + 0.05 * k as f64).collect();
        hs.extend([-4.5, -7.0, -12.0, -30.0, -200.0, -1e4, 19.999]);
        for dugdale in [false, true] {
            let mut worst = (0.0f64, String::new());
            let decades = if dugdale { 28 } else { 20 };
            for j in 0..=decades {
                let range = 10f64.powf(-4.0 + 0.25 * j as f64);
                let att = if dugdale {
                    Attraction::Dugdale { range }
                } else {
                    Attraction::VanDerWaals { range }
                };
                for &h in &hs {
                    let a = quadrature(att, 1.0, h);
                    let b = quadrature_with(&FINE, att, 1.0, h);
                    assert_eq!(a.exponent, b.exponent);
                    let n = b.load.abs();
                    for (what, x, y, scale) in [
                        ("N", a.load, b.load, n),
                        ("N'", a.dload_dh, b.dload_dh, n * (1.0 + h.abs())),
                        ("N''", a.d2load_dh2, b.d2load_dh2, n * (1.0 + h * h)),
                    ] {
                        assert!(x.is_finite() && scale > 0.0, "{what} {att:?} h={h}: {x}");
                        let e = (x - y).abs() / scale;
                        if e > worst.0 {
                            worst = (e, format!("{what} {att:?} h={h}: {x} vs {y}"));
                        }
                    }
                }
            }
            eprintln!("worst against the fine layout: {:e} ({})", worst.0, worst.1);
            assert!(worst.0 < 1e-14, "{worst:?}");
        }
    }

    /// For large negative h only d ≈ 0 counts: N ≈ -c_0 e^{-h²/2}/|h| (Mills).
    #[test]
    fn deep_contact_limit() {
        let h = -200.0;
        for att in [
            Attraction::VanDerWaals { range: 10.0 },
            Attraction::Dugdale { range: 1e3 },
        ] {
            let n = noncontact(att, 1.0, h);
            assert_eq!(n.exponent, 0.5 * h * h);
            // ∫_0^∞ e^{-(h-d)²/2 + h²/2} dd = ∫ e^{-|h| d - d²/2} ≈ 1/|h| (1 - 1/h² …), w ≈ 1.
            let want = -1.0 / 200.0;
            assert!((n.load / want - 1.0).abs() < 2e-3, "{att:?}: {n:?}");
        }
    }

    /// The AVX2 builds of the two quadratures give the very numbers of the
    /// portable ones, bit for bit (no fused multiply–adds; each vector lane does one
    /// node's arithmetic in the same order, and the sums stay serial), so results do
    /// not depend on the CPU. Checked where the CPU has AVX2.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn wide_vectors_change_no_bit() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let q = Quadrature::default();
        let mut checked = 0;
        for range in [1e-4, 3e-3, 0.1, 1.0, 10.0, 1e3] {
            for attraction in [
                Attraction::VanDerWaals { range },
                Attraction::Dugdale { range },
            ] {
                let layout = layout_of(attraction);
                for k in -40..=200 {
                    let h = 0.1 * k as f64 + 0.013;
                    let portable = quadrature_body(layout, attraction, 0.7, h);
                    // SAFETY: the CPU has AVX2 (checked above).
                    let wide = unsafe { quadrature_avx2(layout, attraction, 0.7, h) };
                    assert_eq!(portable, wide, "{attraction:?} h={h}");
                    checked += 1;
                }
            }
        }
        for bounds in [
            &[0.0, 0.3, 1.7][..],
            &[0.0, 4.9, 6.9, 8.5, 9.6],
            &[0.5, 2.0, 30.0],
        ] {
            for k in -40..=40 {
                let h = 0.25 * k as f64 - 0.03;
                let dc = bounds[bounds.len() - 1];
                let portable = hertz_body(&q, h, dc, bounds);
                // SAFETY: as above.
                let wide = unsafe { hertz_avx2(&q, h, dc, bounds) };
                assert_eq!(portable, wide, "{bounds:?} h={h}");
                checked += 1;
            }
        }
        assert_eq!(checked, 12 * 241 + 3 * 81);
    }
}
