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
//! plastic c_p Δ - c_0 beyond) are the JKR machinery of `integrals.rs` with
//! c_a = c_d = 0 and the constant -c_0 inside the elastic integrand, so they
//! need nothing here.
//!
//! **Method.** Every integral is composite Gauss–Legendre in d, on panels whose
//! breakpoints are (a) the points where the log-weight u²/2 has risen by
//! [`LOG_WEIGHT_STEP`] above its smallest value on [0, d_max], up to
//! [`LOG_WEIGHT_CUT`] (e^{-46} ≈ 1e-20), and, for van der Waals, (b) the geometric
//! points d = z0 (4^k - 1), across each of which w changes by at most 16 and whose
//! length is at most 3/2 of the distance to the pole of w at d = -z0: every panel
//! integrand is then analytic in a Bernstein ellipse of parameter ≥ 3 (order 20:
//! error ≲ 3^{-40} ≈ 1e-19 of the panel's size). The nodes are placed in d, so
//! 1 - d/Δ_h and z0 + d are formed without cancellation for every Δ_h in
//! [1e-6, 1e3] and z0 in [1e-4, 10]: the closed forms in erfc (docs/model.md §7,
//! "checks") cancel for small Δ_h and are not used. The weight is taken relative
//! to its largest value on the window, e^{-u_n²/2} with u_n the u nearest to 0,
//! as `(u - u_n)(u + u_n)` with `u - u_n = d_n - d` exact: every result is a
//! mantissa scaled by e^{u_n²/2}, which for van der Waals and h ≥ 0 is 1.
//!
//! **Orders.** A panel whose largest weight is e^{-L} of the window's (L the drop of
//! the log-weight from the peak to the panel's nearest point, less 2 ln of the rise of
//! w towards d = 0 under van der Waals) needs only ≈ 1e-17·e^{L} of its own size. Its
//! order steps down with L as the contact integral's does (20 below L = 10, then 16,
//! 12, 8, 6 below 16, 22, 28, 34, and 4): with Bernstein ρ ≥ 3 an n-point panel errs
//! by ≲ 3^{-2n} of its size, and e^{-L}·3^{-2n} stays below 1e-17 at every step
//! (n = 12 from L = 16: e^{-16}·3^{-24} ≈ 4e-19). Far panels on a step-8 walk drop
//! from 20 points to 12, 8, 6 and 4.
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
use super::special::SQRT_TWO_PI;

/// Largest log-weight change across one panel.
pub const LOG_WEIGHT_STEP: f64 = 8.0;

/// The window ends where the weight is e^{-46} below its largest value.
pub const LOG_WEIGHT_CUT: f64 = 46.0;

/// Gauss–Legendre points per panel.
pub const ORDER: usize = 20;

/// Ratio of the geometric breakpoints' distances from the pole of w.
const GEOMETRIC_RATIO: f64 = 4.0;

/// From this h on, the van der Waals term is its asymptotic series.
pub const VDW_SERIES_FROM: f64 = 20.0;

const MAX_BREAKS: usize = 96;

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
fn panel_order(attraction: Attraction, h: f64, d_n: f64, u_n: f64, a: f64, b: f64) -> usize {
    let x = d_n.clamp(a, b);
    let u = h - x;
    let mut level = 0.5 * (u - u_n) * (u + u_n);
    if let Attraction::VanDerWaals { range } = attraction {
        if a < d_n {
            level -= 2.0 * ((range + d_n) / (range + a)).ln();
        }
    }
    const SCHEDULE: [(f64, usize); 5] =
        [(10.0, ORDER), (16.0, 16), (22.0, 12), (28.0, 8), (34.0, 6)];
    SCHEDULE
        .iter()
        .find(|(below, _)| level < *below)
        .map_or(4, |&(_, n)| n)
}

/// The composite Gauss–Legendre form (module docs).
fn quadrature(attraction: Attraction, c_0: f64, h: f64) -> Noncontact {
    let d_max = match attraction {
        Attraction::Dugdale { range } => range,
        Attraction::VanDerWaals { .. } => f64::INFINITY,
    };
    // The point of the window nearest the weight's peak u = 0.
    let d_n = h.clamp(0.0, d_max);
    let u_n = h - d_n;
    let mut breaks = [0.0f64; MAX_BREAKS];
    let mut n = 0;
    let mut push = |d: f64, n: &mut usize| {
        if *n < MAX_BREAKS {
            breaks[*n] = d;
            *n += 1;
        }
    };
    push(d_n, &mut n);
    // Rightwards (larger d, u falling below u_n ≤ 0).
    let mut hi = d_n;
    if u_n <= 0.0 && d_n < d_max {
        let mut level = 0.0;
        while level < LOG_WEIGHT_CUT {
            level = (level + LOG_WEIGHT_STEP).min(LOG_WEIGHT_CUT);
            let d = d_n + offset_at_level(u_n, level);
            if d >= d_max {
                hi = d_max;
                push(d_max, &mut n);
                break;
            }
            hi = d;
            push(d, &mut n);
        }
    }
    // Leftwards (smaller d, u rising above u_n ≥ 0). Under van der Waals the
    // growth of w towards d = 0 can outweigh the Gaussian: then walk to 0.
    let left_cut = match attraction {
        Attraction::VanDerWaals { range } if h > 0.0 => {
            let near = 0.5 * h * h - 2.0 * ((range + h) / range).ln();
            if near <= LOG_WEIGHT_CUT {
                f64::INFINITY
            } else {
                LOG_WEIGHT_CUT
            }
        }
        _ => LOG_WEIGHT_CUT,
    };
    let mut lo = d_n;
    if u_n >= 0.0 && d_n > 0.0 {
        let mut level = 0.0;
        loop {
            level = (level + LOG_WEIGHT_STEP).min(left_cut);
            let d = d_n - offset_at_level(u_n, level);
            if d <= 0.0 {
                lo = 0.0;
                push(0.0, &mut n);
                break;
            }
            lo = d;
            push(d, &mut n);
            if level >= left_cut {
                break;
            }
        }
    }
    if let Attraction::VanDerWaals { range } = attraction {
        let mut g = range * (GEOMETRIC_RATIO - 1.0);
        while g < hi {
            if g > lo {
                push(g, &mut n);
            }
            g = range * (GEOMETRIC_RATIO * (g / range + 1.0) - 1.0);
        }
    }
    let breaks = &mut breaks[..n];
    breaks.sort_by(f64::total_cmp);
    let (mut load, mut dload, mut d2load) = (0.0, 0.0, 0.0);
    for k in 1..breaks.len() {
        let (a, b) = (breaks[k - 1], breaks[k]);
        if b <= a {
            continue;
        }
        let rule = gauss::rule(panel_order(attraction, h, d_n, u_n, a, b));
        let mid = 0.5 * (a + b);
        let half = 0.5 * (b - a);
        let (mut pl, mut pd, mut pdd) = (0.0, 0.0, 0.0);
        for (x, wq) in rule.nodes.iter().zip(&rule.weights) {
            let d = mid + half * x;
            let w = match attraction {
                Attraction::VanDerWaals { range } => {
                    let q = range / (range + d);
                    q * q
                }
                // 1 - d/Δ_h as (Δ_h - d)/Δ_h: exact near d = Δ_h.
                Attraction::Dugdale { range } => (range - d) / range,
            };
            let u = h - d;
            let log_weight = 0.5 * (d_n - d) * (u + u_n);
            let f = wq * w * (-log_weight).exp();
            pl += f;
            pd -= f * u;
            pdd += f * (u * u - 1.0);
        }
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
}
