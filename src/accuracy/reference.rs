//! A high-precision reference for the non-dimensional integrals, independent of
//! the fast path in [`crate::model::integrals`].
//!
//! It evaluates the *direct* form of docs/model.md §3:
//!
//! ```text
//! P̄(h) = ∫_0^{Δc} p_e(Δ1(Δ)) φ̄ dΔ + ∫_{Δc}^∞ (c_p Δ - c_0) φ̄ dΔ,   φ̄ = e^{-(h+Δ)²/2}
//! Ā(h) = ∫_0^∞ Δ φ̄ dΔ,   Ā_p(h) = ∫_{Δc}^∞ Δ φ̄ dΔ,   dP̄/dh = -∫ p(Δ) (h+Δ) φ̄ dΔ
//! ```
//!
//! with the integration variable the actual interference Δ, Δ1(Δ) by a Newton
//! root solve of `Δ = Δ1 - c_d Δ1^{1/4}` at every node, every part (the plastic
//! load and both areas too, which the fast path takes in closed form) by
//! globally adaptive Gauss–Kronrod G7K15 to a relative tolerance of 1e-15 of
//! `∫|f|`, and the transition cubic by its own safeguarded Newton. What it shares
//! with the fast path is only the [`Coefficients`] it is given.
//!
//! Each integral is taken over the window where the weight is within
//! `e^{-100}` (≈ 4e-44) of its largest value on the part's interval; the window
//! is split at the weight's peak, at every drop of the log-weight by 4, and
//! geometrically towards Δ = 0 (where Δ1^{1/4} changes regime at Δ ≈ Δ0 = c_d^{4/3},
//! and p_e ∝ Δ^{3/2} without adhesion), then bisected where |K15 − G7| is largest.
//! The integrand is computed relative to the weight's peak, `e^{-(x)(u*+x/2)}`,
//! x = Δ − Δ*, u* = h + Δ*, so no weight underflows before the scale `e^{L*}` is
//! applied. Results are mantissas scaled by `e^{κ(h)}`, κ = max(h,0)²/2, exactly
//! as in [`crate::model::Integrals`].
//!
//! Its error estimate is the sum of |K15 − G7| over the final segments (which
//! overestimates the K15 error of a smooth segment by orders of magnitude) plus a
//! rounding term 2ε·∫|f|. `tests/all/accuracy.rs` checks it against 40-digit mpmath
//! tables: it agrees to a few 1e-16 relative to |elastic| + |plastic|.
//!
//! **DMT (docs/model.md §7).** [`ReferenceModel::with_law`] takes the DMT law the
//! same direct way: the elastic asperity load is `Δ·√Δ − c_0` on [0, Δc], Δc = c_h²
//! (Hertz, no root solve needed), the plastic one `c_p Δ − c_0`, and the attraction of
//! the asperities out of contact is integrated adaptively in the gap d = −Δ ≥ 0,
//! `N(h) = −c_0 ∫_0^{d_max} w(d) e^{−(h−d)²/2} dd` (w = (z0/(z0+d))², d_max = ∞, split
//! geometrically towards the pole's scale z0 at d = 0; or w = 1 − d/Δ_h on [0, Δ_h]),
//! its mantissa scaled by `e^{κ(−h)}`. The fast path instead integrates the
//! attraction by fixed Gauss–Legendre panels in `model::dmt` and the Hertz load in
//! s = Δ^{1/4}. `tests/all/accuracy.rs` checks this reference against the 40-digit
//! `reference_dmt_points.csv`.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::model::{AsperityLaw, Attraction, Coefficients};

/// Relative tolerance (of ∫|f|) of the adaptive quadrature.
pub const TOLERANCE: f64 = 1e-15;

/// Where the integration window is cut: the weight is `e^{-WINDOW}` of its peak.
pub const WINDOW: f64 = 100.0;

/// Largest number of segments one adaptive integral may use.
pub const MAX_SEGMENTS: usize = 4000;

/// A value with an estimate of its absolute error.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Estimate {
    /// The value.
    pub value: f64,
    /// An estimate of its absolute error (≥ 0).
    pub error: f64,
    /// ∫|f|, the size of the terms (the scale of the error where f changes sign).
    pub magnitude: f64,
}

/// The reference integrals at one separation; every value is a mantissa scaled
/// by `e^{κ(h)}`, κ(h) = max(h,0)²/2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferencePoint {
    /// h.
    pub separation: f64,
    /// κ(h).
    pub scale_exponent: f64,
    /// Elastic part of P̄.
    pub load_elastic: Estimate,
    /// Plastic part of P̄.
    pub load_plastic: Estimate,
    /// Ā.
    pub area: Estimate,
    /// Ā_p.
    pub plastic_area: Estimate,
    /// dP̄/dh.
    pub dload_dh: Estimate,
    /// ∫ |p(Δ) (h+Δ)| φ̄ dΔ: the size of the terms of dP̄/dh (which crosses zero).
    pub dload_dh_parts: f64,
    /// Integrand evaluations spent.
    pub evaluations: usize,
    /// DMT: the load of the attracted asperities out of contact (≤ 0), a mantissa
    /// scaled by `e^{noncontact_exponent}`; 0 under JKR.
    pub noncontact_load: Estimate,
    /// DMT: its h-derivative (same scale).
    pub noncontact_dload_dh: Estimate,
    /// κ(−h) = max(−h, 0)²/2: the scale exponent of the non-contact mantissas.
    pub noncontact_exponent: f64,
}

impl ReferencePoint {
    /// P̄ as a value (contact and non-contact shares), for a moderate h where
    /// neither scale overflows; `(value, dP̄/dh value)`.
    pub fn total_load_value(&self) -> (f64, f64) {
        let k = (-self.scale_exponent).exp();
        let kn = (-self.noncontact_exponent).exp();
        (
            self.load() * k + self.noncontact_load.value * kn,
            self.dload_dh.value * k + self.noncontact_dload_dh.value * kn,
        )
    }
    /// P̄ (mantissa).
    pub fn load(&self) -> f64 {
        self.load_elastic.value + self.load_plastic.value
    }
    /// |elastic| + |plastic|: the scale against which a load error is measured.
    pub fn load_parts(&self) -> f64 {
        self.load_elastic.value.abs() + self.load_plastic.value.abs()
    }
    /// Estimated absolute error of P̄.
    pub fn load_error(&self) -> f64 {
        self.load_elastic.error + self.load_plastic.error
    }
}

/// The reference model at fixed coefficients.
#[derive(Debug, Clone, Copy)]
pub struct ReferenceModel {
    /// The coefficients (the only input shared with the fast path).
    pub coefficients: Coefficients,
    /// The asperity law.
    pub law: AsperityLaw,
    /// t = Δcl^{1/4}, the positive root of `t³ − c_h t − c_a = 0` (∞ without plasticity).
    pub transition_root: f64,
    /// Δc = t⁴ − c_d t, computed as t (c_h t + c_a/3) (equal by the cubic, no cancellation).
    pub critical_interference: f64,
}

impl ReferenceModel {
    /// The reference for these coefficients.
    pub fn new(coefficients: Coefficients) -> Self {
        ReferenceModel::with_law(coefficients, AsperityLaw::Jkr)
    }

    /// The reference of an asperity law (module docs); DMT's Δc = c_h² is the
    /// transition cubic with c_a = 0.
    pub fn with_law(coefficients: Coefficients, law: AsperityLaw) -> Self {
        let c_a = match law {
            // The Lennard-Jones law has no closed-form reference here
            // (`finite_difference::reference_ln_wear_rate` gives none); its
            // JKR limit is the nearest.
            AsperityLaw::Jkr | AsperityLaw::LennardJones { .. } => coefficients.c_a,
            AsperityLaw::Dmt(_) => 0.0,
        };
        let (t, dc) = if coefficients.c_h.is_finite() {
            let t = cubic_root(c_a, coefficients.c_h);
            (t, t * (coefficients.c_h * t + c_a / 3.0))
        } else {
            (f64::INFINITY, f64::INFINITY)
        };
        ReferenceModel {
            coefficients,
            law,
            transition_root: t,
            critical_interference: dc,
        }
    }

    /// s = Δ1^{1/4} for an actual interference Δ ≥ 0: the root s ≥ c_d^{1/3} of
    /// `s⁴ − c_d s = Δ` (eq. 10, corrected), by Newton from the right.
    ///
    /// `s_hi = max((2Δ)^{1/4}, (2c_d)^{1/3})` has `s⁴ − c_d s ≥ Δ` (if s³ ≥ 2c_d then
    /// s(s³ − c_d) ≥ s⁴/2), and the quartic is convex and increasing for s ≥ c_d^{1/3},
    /// so Newton falls monotonically onto the root; it stops when it no longer falls.
    pub fn quarter_apparent_interference(&self, delta: f64) -> f64 {
        let c_d = self.coefficients.c_d;
        if c_d == 0.0 {
            return delta.sqrt().sqrt();
        }
        let mut s = (2.0 * delta).sqrt().sqrt().max((2.0 * c_d).cbrt());
        for _ in 0..200 {
            let f = s * (s * s * s - c_d) - delta;
            let df = 4.0 * s * s * s - c_d;
            let next = s - f / df;
            // Stop when Newton no longer falls (or is NaN).
            if next.partial_cmp(&s) != Some(Ordering::Less) {
                break;
            }
            s = next;
        }
        s
    }

    /// p_e(Δ) = Δ1^{3/2} − c_a Δ1^{3/4} (eq. 1) with Δ1 from the root solve.
    /// Under DMT: the Hertz load with the adhesive offset, Δ^{3/2} − c_0.
    pub fn elastic_load(&self, delta: f64) -> f64 {
        if let AsperityLaw::Dmt(_) = self.law {
            return delta * delta.sqrt() - self.coefficients.c_0;
        }
        let s = self.quarter_apparent_interference(delta);
        let s3 = s * s * s;
        s3 * (s3 - self.coefficients.c_a)
    }

    /// All reference integrals at separation h.
    pub fn at(&self, h: f64) -> ReferencePoint {
        let c = self.coefficients;
        let dc = self.critical_interference;
        let mut evaluations = 0;
        // Elastic part on [0, Δc]: [p_e φ̄, −p_e (h+Δ) φ̄].
        let [load_elastic, dload_elastic] =
            integrate(h, 0.0, dc, self.split_scale(), &mut evaluations, |d| {
                let p = self.elastic_load(d);
                [p, -p * (h + d)]
            });
        // Plastic part on [Δc, ∞): [(c_p Δ − c_0) φ̄, Δ φ̄, −(c_p Δ − c_0)(h+Δ) φ̄].
        let [load_plastic, plastic_area, dload_plastic] = if dc.is_finite() {
            integrate(h, dc, f64::INFINITY, None, &mut evaluations, |d| {
                let p = c.c_p * d - c.c_0;
                [p, d, -p * (h + d)]
            })
        } else {
            [Estimate::default(); 3]
        };
        // Ā on [0, ∞), split geometrically towards 0 is not needed (Δ is smooth).
        let [area] = integrate(h, 0.0, f64::INFINITY, None, &mut evaluations, |d| [d]);
        // DMT: the attraction in the gap d = −Δ, weight e^{−(−h+d)²/2} (so `integrate`
        // at −h), p = −c_0 w(d), dp/dh-term −p (h − d).
        let (noncontact_load, noncontact_dload_dh) = match self.law {
            AsperityLaw::Dmt(attraction) if c.c_0 > 0.0 => {
                let (d_max, near_zero) = match attraction {
                    Attraction::VanDerWaals { range } => (f64::INFINITY, Some(range)),
                    Attraction::Dugdale { range } => (range, None),
                };
                let [n, dn] = integrate(-h, 0.0, d_max, near_zero, &mut evaluations, |d| {
                    let w = match attraction {
                        Attraction::VanDerWaals { range } => (range / (range + d)).powi(2),
                        Attraction::Dugdale { range } => (range - d) / range,
                    };
                    let p = -c.c_0 * w;
                    [p, -p * (h - d)]
                });
                (n, dn)
            }
            _ => (Estimate::default(), Estimate::default()),
        };
        ReferencePoint {
            separation: h,
            scale_exponent: if h > 0.0 { 0.5 * h * h } else { 0.0 },
            load_elastic,
            load_plastic,
            area,
            plastic_area,
            dload_dh: Estimate {
                value: dload_elastic.value + dload_plastic.value,
                error: dload_elastic.error + dload_plastic.error,
                magnitude: dload_elastic.magnitude + dload_plastic.magnitude,
            },
            dload_dh_parts: dload_elastic.magnitude + dload_plastic.magnitude,
            evaluations,
            noncontact_load,
            noncontact_dload_dh,
            noncontact_exponent: if h < 0.0 { 0.5 * h * h } else { 0.0 },
        }
    }

    /// The scale near Δ = 0 below which the elastic integrand changes character:
    /// Δ0 = c_d^{4/3} with adhesion, 0 (split down to tiny Δ) without and under DMT.
    fn split_scale(&self) -> Option<f64> {
        if let AsperityLaw::Dmt(_) = self.law {
            // Δ^{3/2} down to Δ = 0.
            return Some(0.0);
        }
        let c_d = self.coefficients.c_d;
        Some(if c_d > 0.0 { c_d.powf(4.0 / 3.0) } else { 0.0 })
    }
}

/// The positive root of t³ − c_h t − c_a (c_a ≥ 0, 0 < c_h < ∞): bracketed
/// Newton on [√c_h, √c_h + c_a^{1/3}] (the cubic is ≤ 0 at the left end since
/// t³ − c_h t = 0 there, and ≥ 0 at the right), bisecting when Newton leaves the bracket.
fn cubic_root(c_a: f64, c_h: f64) -> f64 {
    let f = |t: f64| t * (t * t - c_h) - c_a;
    let (mut lo, mut hi) = (c_h.sqrt(), c_h.sqrt() + c_a.cbrt());
    if c_a == 0.0 {
        return lo;
    }
    let mut t = hi;
    for _ in 0..400 {
        let ft = f(t);
        if ft == 0.0 {
            return t;
        }
        if ft > 0.0 {
            hi = t;
        } else {
            lo = t;
        }
        let newton = t - ft / (3.0 * t * t - c_h);
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - t).abs() <= 0.5 * f64::EPSILON * t || next == lo || next == hi {
            return next;
        }
        t = next;
    }
    t
}

use crate::model::gauss::{
    KRONROD_GAUSS_WEIGHTS as WG, KRONROD_NODES as XGK, KRONROD_WEIGHTS as WGK,
};

/// One G7K15 segment: K15 values, |K15 − G7| per component, ∫|f| by K15.
#[derive(Debug, Clone, Copy)]
struct Segment<const N: usize> {
    a: f64,
    b: f64,
    value: [f64; N],
    error: [f64; N],
    abs: [f64; N],
    /// The largest error of the segment relative to the running totals (heap key).
    key: f64,
}

impl<const N: usize> PartialEq for Segment<N> {
    fn eq(&self, other: &Self) -> bool {
        self.key == other.key
    }
}
impl<const N: usize> Eq for Segment<N> {}
impl<const N: usize> PartialOrd for Segment<N> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl<const N: usize> Ord for Segment<N> {
    fn cmp(&self, other: &Self) -> Ordering {
        self.key.total_cmp(&other.key)
    }
}

fn gk15<const N: usize>(f: &impl Fn(f64) -> [f64; N], a: f64, b: f64) -> Segment<N> {
    let mid = 0.5 * (a + b);
    let half = 0.5 * (b - a);
    let mut k = [0.0; N];
    let mut g = [0.0; N];
    let mut abs = [0.0; N];
    for (j, (&x, &wk)) in XGK.iter().zip(&WGK).enumerate() {
        let points: &[f64] = if x == 0.0 {
            &[mid]
        } else {
            &[mid - half * x, mid + half * x]
        };
        for &p in points {
            let v = f(p);
            for i in 0..N {
                k[i] += wk * v[i];
                abs[i] += wk * v[i].abs();
                if j % 2 == 1 {
                    g[i] += WG[j / 2] * v[i];
                }
            }
        }
    }
    let mut error = [0.0; N];
    for i in 0..N {
        k[i] *= half;
        g[i] *= half;
        abs[i] *= half;
        error[i] = (k[i] - g[i]).abs();
    }
    Segment {
        a,
        b,
        value: k,
        error,
        abs,
        key: 0.0,
    }
}

/// a + b = s + e exactly (Knuth's two-sum).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// a · b = p + e exactly (by fused multiply–add).
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// Breakpoints where the log-weight has dropped by 4, 8, … below its peak, and
/// the window ends (drop of [`WINDOW`]).
fn window(h: f64, a: f64, b: f64) -> (f64, f64, f64, (f64, f64), Vec<f64>) {
    let peak = (-h).clamp(a, b);
    let u = h + peak;
    // L* in mantissa scale, κ(h) − u*²/2, as an unevaluated sum hi + lo: at
    // |L*| ≈ 600 one rounding of L* alone would move e^{L*} by 7e-14.
    let log_peak = if h > 0.0 {
        // −peak (h + peak/2)
        let (s, es) = two_sum(h, 0.5 * peak);
        let (p, ep) = two_product(peak, s);
        (-p, -(ep + peak * es))
    } else {
        // −(h + peak)²/2
        let (u, eu) = two_sum(h, peak);
        let (p, ep) = two_product(u, u);
        (-0.5 * p, -0.5 * (ep + 2.0 * u * eu))
    };
    let reach = |c: f64| 2.0 * c / (u.abs() + (u * u + 2.0 * c).sqrt());
    let mut points = vec![peak];
    let mut lo = a;
    let mut hi = b;
    let mut level = 4.0;
    loop {
        let last = level >= WINDOW;
        let level_now = level.min(WINDOW);
        let d = reach(level_now);
        if peak < b {
            let x = peak + d;
            if last {
                hi = hi.min(x);
            } else if x < b {
                points.push(x);
            }
        }
        if peak > a {
            let x = peak - d;
            if last {
                lo = lo.max(x);
            } else if x > a {
                points.push(x);
            }
        }
        if last {
            break;
        }
        level += 4.0;
    }
    (lo, hi, peak, log_peak, points)
}

/// ∫_a^b g(Δ) φ̄(Δ) e^{κ(h)} dΔ for each of the N components of g, adaptively.
fn integrate<const N: usize>(
    h: f64,
    a: f64,
    b: f64,
    near_zero: Option<f64>,
    evaluations: &mut usize,
    g: impl Fn(f64) -> [f64; N],
) -> [Estimate; N] {
    let (lo, hi, peak, log_peak, mut points) = window(h, a, b);
    if hi.partial_cmp(&lo) != Some(Ordering::Greater) {
        return [Estimate::default(); N];
    }
    let u = h + peak;
    let f = |d: f64| {
        let x = d - peak;
        let w = (-x * (u + 0.5 * x)).exp();
        let mut v = g(d);
        for vi in &mut v {
            *vi *= w;
        }
        v
    };
    if let Some(scale) = near_zero {
        // Geometric splits towards 0: around Δ0 with adhesion, down to 1e-12 of
        // the window without (p_e ∝ Δ^{3/2} there).
        let top = hi.min(if scale > 0.0 { 64.0 * scale } else { hi });
        let bottom = if scale > 0.0 {
            scale / 64.0
        } else {
            1e-12 * hi
        };
        let mut x = top;
        while x > bottom {
            points.push(x);
            x *= 0.25;
        }
    }
    points.retain(|&x| x > lo && x < hi);
    points.push(lo);
    points.push(hi);
    points.sort_by(f64::total_cmp);
    points.dedup();
    let mut heap = BinaryHeap::new();
    let mut total = [0.0; N];
    let mut total_abs = [0.0; N];
    let mut total_err = [0.0; N];
    let mut segments = Vec::new();
    for w in points.windows(2) {
        let s = gk15(&f, w[0], w[1]);
        *evaluations += 15;
        for i in 0..N {
            total[i] += s.value[i];
            total_abs[i] += s.abs[i];
            total_err[i] += s.error[i];
        }
        segments.push(s);
    }
    let keyed = |mut s: Segment<N>, total_abs: &[f64; N]| {
        s.key = (0..N)
            .map(|i| s.error[i] / total_abs[i].max(f64::MIN_POSITIVE))
            .fold(0.0, f64::max);
        s
    };
    for s in segments {
        heap.push(keyed(s, &total_abs));
    }
    let done = |err: &[f64; N], abs: &[f64; N]| (0..N).all(|i| err[i] <= TOLERANCE * abs[i]);
    while !done(&total_err, &total_abs) && heap.len() < MAX_SEGMENTS {
        let Some(worst) = heap.pop() else { break };
        let mid = 0.5 * (worst.a + worst.b);
        if !(mid > worst.a && mid < worst.b) {
            // Cannot split further: keep it and stop.
            heap.push(worst);
            break;
        }
        let left = gk15(&f, worst.a, mid);
        let right = gk15(&f, mid, worst.b);
        *evaluations += 30;
        for i in 0..N {
            total[i] += left.value[i] + right.value[i] - worst.value[i];
            total_abs[i] += left.abs[i] + right.abs[i] - worst.abs[i];
            total_err[i] += left.error[i] + right.error[i] - worst.error[i];
        }
        heap.push(keyed(left, &total_abs));
        heap.push(keyed(right, &total_abs));
    }
    // Re-sum the final segments with Neumaier's compensation.
    let mut sum = [0.0; N];
    let mut comp = [0.0; N];
    let mut err = [0.0; N];
    let mut abs = [0.0; N];
    for s in heap.iter() {
        for i in 0..N {
            let t = sum[i] + s.value[i];
            comp[i] += if sum[i].abs() >= s.value[i].abs() {
                (sum[i] - t) + s.value[i]
            } else {
                (s.value[i] - t) + sum[i]
            };
            sum[i] = t;
            err[i] += s.error[i];
            abs[i] += s.abs[i];
        }
    }
    let scale = log_peak.0.exp() * (1.0 + log_peak.1);
    let mut out = [Estimate::default(); N];
    for i in 0..N {
        out[i] = Estimate {
            value: (sum[i] + comp[i]) * scale,
            error: (err[i] + 2.0 * f64::EPSILON * abs[i]) * scale,
            magnitude: abs[i] * scale,
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kronrod_rule_integrates_polynomials() {
        // K15 is exact to degree 22, G7 to degree 13.
        for k in 0..=22 {
            let seg = gk15(&|x: f64| [x.powi(k)], 0.0, 1.0);
            let exact = 1.0 / (k as f64 + 1.0);
            assert!((seg.value[0] - exact).abs() < 1e-15, "K15 x^{k}");
            if k <= 13 {
                assert!(seg.error[0] < 1e-15, "G7 x^{k}: {}", seg.error[0]);
            }
        }
    }

    #[test]
    fn cubic_root_and_root_solve() {
        let m = ReferenceModel::new(Coefficients::from_indices(0.1, 1e-3));
        let c = m.coefficients;
        let t = m.transition_root;
        assert!((t * t * t - c.c_h * t - c.c_a).abs() < 1e-13 * t * t * t);
        for &d in &[0.0, 1e-12, 1e-3, 1.0, 30.0, 1e5] {
            let s = m.quarter_apparent_interference(d);
            let back = s.powi(4) - c.c_d * s;
            assert!((back - d).abs() <= 4e-16 * s.powi(4), "{d}: {back}");
        }
    }

    #[test]
    fn greenwood_williamson_area_closed_form() {
        // Ā(0) = 1 and Ā(h) = e^{-h²/2} − h √(π/2) erfc(h/√2).
        let m = ReferenceModel::new(Coefficients::new(0.0, f64::INFINITY));
        let at = m.at(0.0);
        assert!(
            (at.area.value - 1.0).abs() < 2e-16,
            "{:e}",
            at.area.value - 1.0
        );
        assert!(at.area.error < 1e-14);
    }
}
