//! The separation h for a given load, and the pull-off load of the rough surface
//! (docs/model.md §4).
//!
//! Write the asperity load law as p(Δ) = p_c(Δ) + J·𝟙(Δ > Δc), where p_c is
//! continuous and increasing on the loading branch (p_c(0) = -c_a c_d/3 ≤ 0) and
//! J is the load jump at the elastic–plastic transition. Then
//!
//! ```text
//! P̄'(h)/φ(h) = -p_c(0) - ∫_0^∞ p_c'(x) e^{-hx-x²/2} dx - J e^{-hΔc-Δc²/2},   φ(h) = e^{-h²/2}
//! ```
//!
//! The first two terms increase with h. When J ≥ 0 the last one does too, so
//! P̄' changes sign at most once: P̄ falls to a single minimum (the pull-off, with
//! adhesion) and then rises to 0⁻. Every load then has one root on the falling
//! branch, and no scan is needed.
//!
//! **DMT (docs/model.md §7).** Write P̄'(h) = -∫ p'(Δ) φ̄(Δ) dΔ with p' taken in the sense
//! of distributions (the upward jump J = c_h³ > 0 at Δc is a positive point mass).
//! The per-asperity load falls on Δ < 0 (p' ≤ 0: the attraction grows as the gap
//! closes, for van der Waals and Dugdale alike) and rises on Δ ≥ 0 (p' ≥ 0). Then
//!
//! ```text
//! P̄'(h)/φ(h) = ∫_{Δ<0} |p'(Δ)| e^{-hΔ-Δ²/2} dΔ - ∫_{Δ≥0} p'(Δ) e^{-hΔ-Δ²/2} dΔ
//! ```
//!
//! where e^{-hΔ} grows with h for Δ < 0 and shrinks for Δ > 0: P̄'/φ is strictly
//! increasing, so P̄' changes sign exactly once when γ > 0. **The single-minimum
//! fact holds**: P̄ falls from +∞ to one minimum (the pull-off) and rises to 0⁻
//! (like -c_0 √(2π) z0²/h² under van der Waals, a power law). **So do the
//! single-root facts**: a compressive load has exactly one root; a tensile load
//! above the minimum has one root on the falling branch (the one docs/model.md §4
//! chooses) and one on the rising branch; below it, the surfaces separate.
//! tests/all/dmt.rs checks both on a grid of h for both attractions. The searches
//! below are the J ≥ 0 paths, with the non-contact share carried at its own scale. When J < 0 (strong adhesion, soft asperities)
//! the last term is a bump of width ~1 around h = -Δc that can add a local
//! maximum and minimum; there the critical points are isolated by a sign scan of
//! P̄' (step 1/8 across the bump, growing away from it, on an interval outside which the
//! sign of P̄' is proven), and roots are then found on monotone pieces.
//!
//! **Weak adhesion (DMT, θ ≳ 1e6).** With a short Dugdale range the minimum moves
//! out to where the contacts' Hertz load balances their adhesive offset,
//! e^{h²/2} P̄ ≈ Γ(5/2) h^{-5/2} - c_0/h - c_0 Δ_h/2 = 0, i.e. h ≈ (Γ(5/2)/c_0)^{2/3}
//! (4e4 at θ = 6.45e7), or c_p/c_0 when plastic junctions dominate. There the shares
//! of P̄ cancel to ~1/h² of their size, and P̄'s contact and attracted shares, each
//! scaled by its own e^{κ} with κ ≈ h²/2 a double, must be added at one exactly
//! known scale (`Integrals::noncontact_gap`), or the rounding of κ (1e-7 at
//! h = 4e4) is a bogus slope. Then the Newton walk below finds the minimum from the
//! usual start in 20–35 evaluations: its location to ~ε relative (a point δ off it
//! has P̄' ~ δ·(parts), rounding ε·h·(parts)), P̄ there to ~ε h² relative in its
//! mantissa (and to the rounding of κ in its logarithm). tests/all/dmt_weak.rs checks
//! both against a 60-digit table, the closed-form limit and JKR. Beyond |h| = 1e6
//! the mantissa is no longer resolved; `evaluate` then reports no pull-off with a
//! warning (the force is below 10^{-1e11} N), never a silent null.
//!
//! **The searches and their cost.** Each step costs one [`Model::at`] (P̄, P̄',
//! P̄'' and the areas at one h); the searches spend few of them:
//! - *Separation, compressive load, J ≥ 0* (every optimizer evaluation):
//!   Halley's method on ln P̄(h) = ln T (nearly quadratic in h where P̄ ~ e^{-h²/2};
//!   P̄ - T where P̄ ≤ 0), from the hint or from the root of the Greenwood–Williamson
//!   tail, kept inside the bracket its iterates build (bisection when a step leaves
//!   it or does not halve over two steps; widening toward the root while it is open).
//!   It returns the point whose step is below 2 ulps of h, or, one evaluation
//!   earlier, the end of a step whose predicted error (|d_k|³/d_{k-1}², from two
//!   steps converging at least quadratically, and Halley's |d_k|³(f''/f')²) is 16
//!   times below that. The model
//!   at the returned point is the caller's, so the areas cost nothing more.
//! - *Pull-off, J ≥ 0*: Newton on P̄' (on the balance of the two shares under DMT;
//!   on h·P̄'e^{h²/2}, nearly linear at large h, under JKR beyond h = 1),
//!   safeguarded the same way, stopping on the same two rules; an early stop
//!   takes P̄_min = P̄ - P̄'²/(2P̄'') at the last point (exact to O(P̄'''δ³), required
//!   below ε|P̄|; see `single_minimum`).
//! - *Other loads and J < 0*: the sign scan above and the pieces' roots by the
//!   same safeguarded Halley iteration inside the pieces' known ends, from the
//!   hint when it lies inside the piece.
//!
//! The stopping rules make every result the root (or minimum) to a few ulps of
//! h whatever the start: hints change the cost only (tests/all/search_cost.rs checks
//! 1e-14 relative against cold starts on the shipped scenes, DMT variants,
//! extremes and 250 pairs of nearby study designs, and pins the counts). Measured
//! (tests/all/search_cost.rs's table): the hub costs 9 evaluations cold under JKR
//! (pull-off 5, solve 4, areas included), 10 under DMT with either attraction
//! (5 + 5, 6 + 4), and 2 + 2 from the hints of a design 1e-6 away; the
//! five-variable study's designs 3.6 on average warm from 1e-6 away, 5.5 from
//! 1e-2 away, 8.8 cold.

use std::cmp::Ordering;

use super::integrals::{Integrals, Model};
use super::scaled::Scaled;

const MAX_EVALUATIONS: usize = 4000;

/// The largest |P̄| the separation solve accepts: beyond it the root lies below
/// h ≈ -1e8, far outside any contact the model describes.
pub const MAX_LOAD: f64 = 1e12;

/// How the separation solve ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SeparationOutcome {
    /// An equilibrium at separation h (over σ) on the branch docs/model.md §4 names.
    Contact {
        /// h = d/σ.
        separation: f64,
        /// Model evaluations spent.
        evaluations: usize,
    },
    /// The load pulls the surfaces apart: tensile beyond the pull-off, or any
    /// non-compressive load without adhesion.
    Separated {
        /// Model evaluations spent.
        evaluations: usize,
    },
    /// The search ran out of evaluations (not expected; reported, not hidden).
    NotConverged {
        /// The best estimate of h.
        separation: f64,
        /// Model evaluations spent.
        evaluations: usize,
    },
}

/// A critical point of P̄(h).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalPoint {
    /// Where P̄' = 0.
    pub separation: f64,
    /// P̄ there.
    pub load: Scaled,
    /// True for a local minimum, false for a local maximum.
    pub is_minimum: bool,
}

/// The critical points of P̄(h), ascending in h. Between two of them (and
/// beyond the ends) P̄ is monotone; far left it grows without bound.
#[derive(Debug, Clone, PartialEq)]
pub struct Landscape {
    /// The local extrema, ascending in h.
    pub critical_points: Vec<CriticalPoint>,
    /// Model evaluations spent finding them.
    pub evaluations: usize,
    /// The points evaluated on the way, (h, P̄, P̄') as doubles: where the
    /// search for P̄ = 0 starts ([`unloaded_hint`]).
    pub samples: Vec<(f64, f64, f64)>,
}

/// The pull-off load of the rough surface: the most negative local minimum of P̄.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PullOff {
    /// Where the minimum lies.
    pub separation: f64,
    /// P̄ there (negative; may be far below the smallest f64).
    pub load: Scaled,
    /// Model evaluations spent.
    pub evaluations: usize,
    /// How many local minima P̄ has.
    pub local_minima: usize,
}

struct Counter<'a> {
    model: &'a Model,
    evaluations: usize,
    /// Where the points evaluated go, when they are kept.
    samples: Option<Vec<(f64, f64, f64)>>,
}

impl Counter<'_> {
    fn at(&mut self, h: f64) -> Integrals {
        self.evaluations += 1;
        let at = self.model.at(h);
        if let Some(samples) = &mut self.samples {
            samples.push((h, at.load().value(), at.dload_dh().value()));
        }
        at
    }
}

/// The sign-carrying mantissa of P̄'(h): continuous in h. Under DMT it is
/// P̄' e^{k(h)} with k the smaller of the contact and non-contact scales.
fn slope(at: &Integrals) -> f64 {
    if at.has_noncontact() {
        at.dload_dh().mantissa
    } else {
        at.dload_dh_elastic + at.dload_dh_plastic
    }
}

/// The critical points of P̄ (see the module docs for the method).
pub fn landscape(model: &Model) -> Landscape {
    landscape_from(model, None)
}

/// As [`landscape`], starting the search for the single minimum (J ≥ 0) at
/// `hint`, e.g. the pull-off separation of a nearby design.
pub fn landscape_from(model: &Model, hint: Option<f64>) -> Landscape {
    let mut ev = Counter {
        model,
        evaluations: 0,
        samples: Some(Vec::new()),
    };
    let c = model.coefficients;
    let jump = model.transition.jump;
    if !model.has_adhesion() && jump >= 0.0 {
        // P̄' < 0 everywhere: no critical point.
        return Landscape {
            critical_points: Vec::new(),
            evaluations: 0,
            samples: Vec::new(),
        };
    }
    // Right end: P̄' > 0 beyond the point where the increasing terms alone are
    // positive, i.e. where P̄'/φ + (-J)⁺ e^{-hΔc-Δc²/2} > 0 … with J ≥ 0 simply P̄' > 0.
    let dc = model.transition.critical_interference;
    let neg_jump = (-jump).max(0.0);
    let increasing_part = |at: &Integrals| -> f64 {
        let h = at.separation;
        // P̄'/φ(h) as Scaled, minus the decreasing bump term.
        let d = at.dload_dh();
        let f = Scaled::new(d.mantissa, d.exponent - 0.5 * h * h);
        let bump = if neg_jump > 0.0 {
            Scaled::new(neg_jump, h * dc + 0.5 * dc * dc)
        } else {
            Scaled::ZERO
        };
        f.minus(bump).signum()
    };
    // The large-h expansion puts the minimum near h ≈ p'(0)/|p(0)| = (3/2) c_d^{-1/3}/c_a.
    let law = model.effective_law();
    let law_guess = if c.has_adhesion() {
        law.law().separation_scale(law, &c)
    } else {
        f64::INFINITY
    };
    // A meniscus reaches k = d_K/σ: the minimum lies within a few units of it too,
    // or nearer where the solid law's own minimum is.
    let guess = match model.capillary {
        Some(cap) => law_guess.min(1.0 + cap.range.min(1e3)),
        None if law_guess.is_finite() => law_guess,
        None => 1.0,
    };
    if neg_jump == 0.0 {
        // One sign change of P̄': Newton on P̄' with P̄'' from the quadrature.
        let start = hint
            .filter(|h| h.abs() <= super::coefficients::MAX_SEPARATION)
            .unwrap_or(guess);
        if let Some((separation, load)) = single_minimum(&mut ev, start) {
            return Landscape {
                critical_points: vec![CriticalPoint {
                    separation,
                    load,
                    is_minimum: true,
                }],
                evaluations: ev.evaluations,
                samples: ev.samples.unwrap_or_default(),
            };
        }
    }
    let mut right = ev.at(guess);
    let mut step = guess.max(1.0);
    while increasing_part(&right) <= 0.0 && ev.evaluations < MAX_EVALUATIONS {
        right = ev.at(right.separation + step);
        step *= 2.0;
    }
    // Left end: P̄' < 0 for every h below it.
    let mut left_h = if neg_jump > 0.0 {
        // For h ≤ -Δc: P̄' ≤ (|p(0)| + |J|) φ(u_c) - c_p √(π/2), negative once
        // φ(u_c) < c_p √(π/2) / (|p(0)| + |J|).
        // A meniscus adds P̄_cap' ≤ c_cap φ(h) ≤ c_cap φ(u_c) there (capillary.rs).
        let capillary = model.capillary.map_or(0.0, |cap| cap.independent());
        // |p| ≤ c_0 under DMT, and ≤ 2 ℓ^{-3/2} = c_0 under the Lennard-Jones
        // law (its pull-off, 2πγR at most): the bound takes the larger.
        let tension = (-c.load_at_touch()).max(c.c_0);
        let ratio = (tension + neg_jump + capillary) / (c.c_p * super::special::SQRT_HALF_PI);
        let u_left = if ratio > 1.0 {
            -(2.0 * ratio.ln()).sqrt()
        } else {
            0.0
        };
        (u_left - dc).min(right.separation - 1.0)
    } else {
        right.separation - step.max(1.0)
    };
    let mut left = ev.at(left_h);
    let mut step = 1.0_f64;
    while slope(&left) >= 0.0 && ev.evaluations < MAX_EVALUATIONS {
        left_h -= step.max(0.25 * left_h.abs());
        step *= 2.0;
        left = ev.at(left_h);
    }
    // Sign changes of P̄' on [left, right].
    let mut brackets: Vec<(Integrals, Integrals)> = Vec::new();
    if neg_jump == 0.0 {
        brackets.push((left, right));
    } else {
        let bump_lo = -dc - 9.0;
        let bump_hi = -dc + 9.0;
        let mut prev = left;
        while prev.separation < right.separation && ev.evaluations < MAX_EVALUATIONS {
            let h = prev.separation;
            let fine = h >= bump_lo - 1.0 && h <= bump_hi;
            // Fine across the bump; away from it P̄' is that of the continuous
            // law (one sign change, which no step can miss), so steps grow.
            let away = (bump_lo - h).max(h - bump_hi).max(0.0);
            let step = if fine { 0.125 } else { (0.1 * away).max(1.0) };
            let next_h = (h + step).min(right.separation);
            let next = if next_h == right.separation {
                right
            } else {
                ev.at(next_h)
            };
            if (slope(&prev) < 0.0) != (slope(&next) < 0.0) {
                brackets.push((prev, next));
            }
            prev = next;
        }
    }
    let mut critical_points: Vec<CriticalPoint> = brackets
        .into_iter()
        .map(|(a, b)| {
            let is_minimum = slope(&a) < 0.0;
            let at = refine_critical(&mut ev, a, b);
            CriticalPoint {
                separation: at.separation,
                load: at.load(),
                is_minimum,
            }
        })
        .collect();
    critical_points.sort_by(|a, b| a.separation.total_cmp(&b.separation));
    Landscape {
        critical_points,
        evaluations: ev.evaluations,
        samples: ev.samples.unwrap_or_default(),
    }
}

/// The zero of P̄' when P̄' changes sign once (J ≥ 0), by Newton's method with
/// P̄'' safeguarded by the bracket the signs of P̄' build: the minimum's
/// separation and the model at the last point evaluated. None if it fails to
/// converge (the caller then falls back to bracketing).
///
/// It stops when Newton's step falls below 4 ulps of h (that point is the
/// minimum), or one evaluation earlier once two Newton steps shrink
/// quadratically (|d_k| ≤ |d_{k-1}|/10): the step d_k then leaves an error of
/// about M d_k², M ≈ |d_k|/d_{k-1}², and when 16 times that is below 4 ulps the
/// step's end is the separation returned. Its load is then P̄ - c at the point
/// the step starts from, c = P̄'²/(2P̄''): with δ the distance to the minimum,
/// P̄ = P̄_min + P̄''δ²/2 + O(P̄'''δ³) and P̄'²/(2P̄'') = P̄''δ²/2 + O(P̄'''δ³). The
/// remainder is ~(2c/|P̄|)^{3/2}|P̄| where P̄ varies on its own length scale (a
/// Gaussian tail: P̄'' ~ h²P̄, P̄''' ~ h³P̄), below ε|P̄| when |c| ≤ 1e-11 |P̄|, which
/// the early stop requires. The force to an ulp, the separation to a few,
/// whatever the start.
fn single_minimum(ev: &mut Counter, start: f64) -> Option<(f64, Scaled)> {
    let mut at = ev.at(start);
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    // The lengths of the last two steps, when they were Newton's.
    let mut last_newton = f64::NAN;
    let mut before_last = f64::NAN;
    for _ in 0..80 {
        let h = at.separation;
        let g = slope(&at);
        if g == 0.0 {
            return Some((h, at.load()));
        }
        if g < 0.0 {
            lo = lo.max(h);
        } else {
            hi = hi.min(h);
        }
        // Newton on g = P̄' e^{κ(h)}, which for h > 0 is the smooth, increasing
        // p(0)-less-integral form (module docs) rather than a Gaussian tail:
        // g' = (P̄'' + h P̄') e^{κ(h)}.
        let (d1, dg) = if at.has_noncontact() {
            // g = P̄' e^{k}, k = u_n²/2 of the larger share's scale (u_n = max(h, 0)
            // for the contact share; h, 0 or h - Δ_h for the non-contact one), so
            // g' = (P̄'' + k' P̄') e^{k} with k' = ±√(2k), the sign of h.
            let s1 = at.dload_dh();
            let k = s1.exponent;
            let d2 = at.d2load_dh2();
            let k_slope = (2.0 * k).sqrt().copysign(h);
            let d2_at_k = d2.mantissa * (k - d2.exponent).exp();
            (s1.mantissa, d2_at_k + k_slope * s1.mantissa)
        } else {
            let (d1, d2) = (at.dload_dh_elastic + at.dload_dh_plastic, at.d2load_dh2);
            (d1, if h > 0.0 { d2 + h * d1 } else { d2 })
        };
        let (newton, curvature_ok) = match balance_newton(&at) {
            Some(next) => (next, true),
            // JKR beyond h = 1: Newton on h·g. For large h, g → |p(0)| - p'(0)/h -
            // O(h^-2) (the balance whose root is the guess), so h·g is nearly
            // linear, where g's own Newton step undershoots by ~h/h_min (7.8 →
            // 11.4 → 14.5 → 15.9 → 16.1 for the hub): (h g)' = g + h g'.
            None if !at.has_noncontact() && h > 1.0 && d1 + h * dg > 0.0 => {
                (h - h * d1 / (d1 + h * dg), true)
            }
            None => (h - d1 / dg, dg > 0.0),
        };
        let tol = 4.0 * f64::EPSILON * h.abs().max(1.0);
        let d = (newton - h).abs();
        if curvature_ok && d <= tol {
            // Converged: the step is below the spacing of doubles at h.
            return Some((h, at.load()));
        }
        if curvature_ok
            && newton > lo
            && newton < hi
            && d <= 0.1 * last_newton
            && 16.0 * d * d * d <= tol * last_newton * last_newton
            && steady(before_last, last_newton, d)
        {
            // Quadratic convergence (see above): the step's end is the minimum,
            // and its load P̄ - P̄'²/(2P̄'') to O(P̄''' δ³).
            let load = at.load();
            let (s1, s2) = (at.dload_dh(), at.d2load_dh2());
            let correction = Scaled::new(
                0.5 * s1.mantissa * s1.mantissa / s2.mantissa,
                2.0 * s1.exponent - s2.exponent,
            );
            if s2.mantissa > 0.0 && correction.ratio(load).abs() <= 1e-11 {
                return Some((newton, load.minus(correction)));
            }
        }
        // Under DMT a far start (the attraction's reach) can see a nearly flat
        // slope and propose a jump far past the minimum (h = 21 → −2e15 for
        // θ = 1, H = ∞, Dugdale Δ_h = 20, found by the million-case run): a step
        // longer than 4·max(|h|, 1) falls back to the halving walk below. JKR's
        // iterates are unchanged.
        let trust = if at.has_noncontact() {
            4.0 * h.abs().max(1.0)
        } else {
            f64::INFINITY
        };
        let next = if curvature_ok
            && newton.is_finite()
            && newton > lo
            && newton < hi
            && (newton - h).abs() <= trust
        {
            newton
        } else if lo.is_finite() && hi.is_finite() {
            0.5 * (lo + hi)
        } else if g < 0.0 {
            h + (0.5 * h.abs()).max(1.0)
        } else {
            h - (0.5 * h.abs()).max(1.0)
        };
        if (next - h).abs() <= 4.0 * f64::EPSILON * h.abs().max(1.0) {
            return Some((h, at.load()));
        }
        if lo.is_finite() && hi.is_finite() && hi - lo <= 4.0 * f64::EPSILON * hi.abs().max(1.0) {
            return Some((h, at.load()));
        }
        before_last = last_newton;
        last_newton = if next == newton {
            (next - h).abs()
        } else {
            f64::NAN
        };
        if last_newton.is_nan() {
            before_last = f64::NAN;
        }
        at = ev.at(next);
    }
    None
}

/// Whether three Newton steps a, b, c (newest last) show one quadratic rate:
/// M = c/b² within a factor 10 of b/a². A step of a function that bends on a
/// length shorter than the steps (a log near a zero of its argument) shows a
/// jump in M instead, and its steps' ratio alone would look converged. With
/// only two steps known (a is NaN: a warm start) the pair decides.
fn steady(a: f64, b: f64, c: f64) -> bool {
    if a.is_nan() {
        return true;
    }
    let (earlier, later) = (b / (a * a), c / (b * b));
    later <= 10.0 * earlier && earlier <= 10.0 * later
}

/// Newton's step for the minimum under DMT where the contacts' share of P̄' is
/// negative and the attracted asperities' positive (about every minimum): P̄' = 0 is
/// φ = ln(-s_c) - ln(s_n) = 0, with s_c and s_n the shares' values. φ falls through 0
/// and is nearly quadratic in h (a Gaussian tail against a power law, or two Gaussian
/// tails), where P̄' itself decays like e^{-h²/2} and Newton on it creeps by ~1/h a
/// step (15 evaluations from h = 1.1 to the hub's minimum at 3.93 under van der
/// Waals). None where the form does not apply (the caller's Newton on P̄' then).
fn balance_newton(at: &Integrals) -> Option<f64> {
    let s_c = at.dload_dh_elastic + at.dload_dh_plastic;
    if at.has_capillary() {
        // The attracted share is the attraction's and the meniscus's together,
        // each at its own scale: the same φ, in scaled arithmetic.
        let contact = Scaled::new(s_c, at.scale_exponent);
        let attracted = Scaled::new(at.dload_dh_noncontact, at.noncontact_exponent)
            .plus(Scaled::new(at.capillary.dload_dh, at.capillary.exponent));
        if !(s_c < 0.0 && attracted.mantissa > 0.0) {
            return None;
        }
        let attracted_d2 = Scaled::new(at.d2load_dh2_noncontact, at.noncontact_exponent)
            .plus(Scaled::new(at.capillary.d2load_dh2, at.capillary.exponent));
        let phi = contact.ln_abs() - attracted.ln_abs();
        let dphi = at.d2load_dh2 / s_c - attracted_d2.ratio(attracted);
        let next = at.separation - phi / dphi;
        return (dphi < 0.0 && next.is_finite()).then_some(next);
    }
    let s_n = at.dload_dh_noncontact;
    if !(s_c < 0.0 && s_n > 0.0) {
        return None;
    }
    // The shares' scales differ by κ - E (exact where both are large).
    let gap = at
        .noncontact_gap
        .unwrap_or(at.scale_exponent - at.noncontact_exponent);
    let phi = (-s_c).ln() - s_n.ln() - gap;
    // φ' = s_c'/s_c - s_n'/s_n (each ratio taken at its share's own scale).
    let dphi = at.d2load_dh2 / s_c - at.d2load_dh2_noncontact / s_n;
    let next = at.separation - phi / dphi;
    (dphi < 0.0 && next.is_finite()).then_some(next)
}

/// Zero of the slope mantissa in [a, b] (opposite signs at the ends): Illinois
/// regula falsi, which keeps the bracket.
fn refine_critical(ev: &mut Counter, a: Integrals, b: Integrals) -> Integrals {
    let (mut xa, mut ga) = (a.separation, slope(&a));
    let (mut xb, mut gb) = (b.separation, slope(&b));
    let mut best = if ga.abs() < gb.abs() { a } else { b };
    let mut side = 0;
    for _ in 0..200 {
        if xb - xa <= 4.0 * f64::EPSILON * xa.abs().max(xb.abs()).max(1.0) {
            break;
        }
        let mut x = xb - gb * (xb - xa) / (gb - ga);
        if !(x > xa && x < xb) {
            x = 0.5 * (xa + xb);
        }
        let at = ev.at(x);
        let gx = slope(&at);
        if gx.abs() <= slope(&best).abs() {
            best = at;
        }
        if gx == 0.0 {
            break;
        }
        if (gx < 0.0) == (ga < 0.0) {
            xa = x;
            ga = gx;
            if side == -1 {
                gb *= 0.5;
            }
            side = -1;
        } else {
            xb = x;
            gb = gx;
            if side == 1 {
                ga *= 0.5;
            }
            side = 1;
        }
    }
    best
}

/// The pull-off of the rough surface from its landscape: the most negative
/// local minimum. None without adhesion (P̄ > 0 everywhere then).
pub fn pull_off_of(landscape: &Landscape) -> Option<PullOff> {
    let minima = landscape
        .critical_points
        .iter()
        .filter(|c| c.is_minimum && c.load.signum() < 0.0);
    let count = landscape
        .critical_points
        .iter()
        .filter(|c| c.is_minimum)
        .count();
    minima
        .fold(None::<&CriticalPoint>, |best, c| match best {
            Some(b) if b.load.minus(c.load).signum() <= 0.0 => Some(b),
            _ => Some(c),
        })
        .map(|c| PullOff {
            separation: c.separation,
            load: c.load,
            evaluations: landscape.evaluations,
            local_minima: count,
        })
}

/// The pull-off of the rough surface (None without adhesion).
pub fn find_pull_off(model: &Model) -> Option<PullOff> {
    pull_off_of(&landscape(model))
}

/// The separation h at which P̄(h) equals `target`, by docs/model.md §4's rule:
/// a compressive target takes the largest root; a tensile (or zero) one the
/// largest root below the pull-off minimum; beyond the pull-off, `Separated`.
pub fn solve_separation(model: &Model, target: f64) -> SeparationOutcome {
    solve_separation_with(model, target, None)
}

/// As [`solve_separation`], reusing a landscape already computed for this model.
pub fn solve_separation_with(
    model: &Model,
    target: f64,
    known: Option<&Landscape>,
) -> SeparationOutcome {
    solve_separation_from(model, target, known, None)
}

/// As [`solve_separation_with`], starting from `hint` (e.g. the separation of a
/// nearby design). The result does not depend on the hint beyond a few ulps of h.
pub fn solve_separation_from(
    model: &Model,
    target: f64,
    known: Option<&Landscape>,
    hint: Option<f64>,
) -> SeparationOutcome {
    solve_separation_at(model, target, known, hint).0
}

/// As [`solve_separation_from`], also returning the model at the separation found
/// (for `Contact`): the caller's areas and contact counts come from it without a
/// second evaluation ([`Model::at`] is a function of h alone, so they are the
/// very same numbers).
pub fn solve_separation_at(
    model: &Model,
    target: f64,
    known: Option<&Landscape>,
    hint: Option<f64>,
) -> (SeparationOutcome, Option<Integrals>) {
    solve_separation_within(model, target, known, hint, 0.0)
}

/// As [`solve_separation_at`], stopping as soon as the next step is at most
/// `tolerance` in h, or that fraction of the length |P̄'/P̄''| over which P̄
/// bends where it is shorter (0: to a few ulps): the point returned is the last one
/// evaluated, within about `tolerance` of the root, for a caller that corrects
/// for the rest itself from the model there (the apparent work of adhesion:
/// [`super::work::work_of_separation_near`]).
pub fn solve_separation_within(
    model: &Model,
    target: f64,
    known: Option<&Landscape>,
    hint: Option<f64>,
    tolerance: f64,
) -> (SeparationOutcome, Option<Integrals>) {
    let mut ev = Counter {
        model,
        evaluations: 0,
        samples: None,
    };
    if target.is_nan() || target.abs() > MAX_LOAD {
        // Beyond any contact the model describes (h would be below -1e8), or
        // not a number: no search, an honest outcome.
        return (
            SeparationOutcome::NotConverged {
                separation: f64::NAN,
                evaluations: 0,
            },
            None,
        );
    }
    if target <= 0.0 && !model.has_adhesion() {
        return (SeparationOutcome::Separated { evaluations: 0 }, None);
    }
    if target > 0.0 && model.transition.jump >= 0.0 {
        // One falling branch carries every positive load (module docs): Newton
        // from the hint, or from the root of the Greenwood–Williamson tail
        // P̄ ≈ e^{-h²/2} (large h) or of P̄ ≈ 2 (1 - h)^{3/2} (h < 0).
        let start = hint
            .filter(|h| h.abs() <= super::coefficients::MAX_SEPARATION)
            .unwrap_or(if target < 1.0 {
                (-2.0 * target.ln()).sqrt()
            } else {
                1.0 - (target / 2.0).powf(2.0 / 3.0)
            });
        let at = ev.at(start);
        return newton_root(&mut ev, target, at, None, None, true, tolerance);
    }
    let computed;
    let land = match known {
        Some(l) => l,
        None => {
            computed = landscape(model);
            ev.evaluations += computed.evaluations;
            &computed
        }
    };
    let cps = &land.critical_points;
    let separated = |ev: &Counter| {
        (
            SeparationOutcome::Separated {
                evaluations: ev.evaluations,
            },
            None,
        )
    };
    // The largest h bound for the root: +∞ for a compressive target, the
    // pull-off minimum for a tensile one.
    let limit = if target > 0.0 {
        cps.len()
    } else {
        match pull_off_of(land) {
            None => return separated(&ev),
            Some(po) => {
                if po.load.cmp_f64(target) == Ordering::Greater {
                    return separated(&ev);
                }
                cps.iter()
                    .position(|c| c.separation == po.separation)
                    .unwrap_or(cps.len())
            }
        }
    };
    // Walk the monotone pieces from the right: piece i lies between critical
    // points i-1 and i (piece 0 is unbounded on the left, piece len on the right).
    for i in (0..=limit).rev() {
        let right = if i < cps.len() { Some(cps[i]) } else { None };
        let left = if i > 0 { Some(cps[i - 1]) } else { None };
        let hi_load = right.map(|r| r.load);
        let lo_load = left.map(|l| l.load);
        // Does the target lie in the range of this monotone piece?
        let below_right = hi_load.is_none_or(|l| l.cmp_f64(target) != Ordering::Greater);
        let above_left = lo_load.is_none_or(|l| l.cmp_f64(target) != Ordering::Less);
        // A piece falls from its left end to its right end when its right end is
        // a minimum (or there is none and it is the far-left piece).
        let falling = right.is_none_or(|r| r.is_minimum) && left.is_none_or(|l| !l.is_minimum);
        let end = |p: CriticalPoint| End {
            h: p.separation,
            miss: miss_of(target, p.load),
            at: None,
        };
        if !falling {
            // Rising pieces run from a minimum to a maximum (or to 0⁻ at +∞): a
            // compressive target cannot lie there, since P̄ < 0 right of the
            // last minimum … except between a compressive min and max.
            if let (Some(l), Some(r)) = (left, right) {
                let in_range = l.load.cmp_f64(target) != Ordering::Greater
                    && r.load.cmp_f64(target) != Ordering::Less;
                if in_range {
                    let start = ev.at(inside(l.separation, r.separation, hint)
                        .unwrap_or(0.5 * (l.separation + r.separation)));
                    return newton_root(
                        &mut ev,
                        target,
                        start,
                        Some(end(l)),
                        Some(end(r)),
                        false,
                        tolerance,
                    );
                }
            }
            continue;
        }
        if below_right && above_left {
            // Start one unit inside the piece from its right end (a minimum: P̄'
            // vanishes there), or from its middle when it is narrower.
            let (lo, hi) = (
                left.map_or(f64::NEG_INFINITY, |l| l.separation),
                right.map_or(f64::INFINITY, |r| r.separation),
            );
            let start_h = inside(lo, hi, hint).unwrap_or(match (left, right) {
                (Some(l), Some(r)) if r.separation - l.separation <= 2.0 => {
                    0.5 * (l.separation + r.separation)
                }
                (_, Some(r)) => r.separation - 1.0,
                (Some(l), None) => l.separation + 1.0,
                (None, None) => 0.0,
            });
            let start = ev.at(start_h);
            return newton_root(
                &mut ev,
                target,
                start,
                left.map(end),
                right.map(end),
                true,
                tolerance,
            );
        }
    }
    (
        SeparationOutcome::NotConverged {
            separation: cps.first().map_or(0.0, |c| c.separation),
            evaluations: ev.evaluations,
        },
        None,
    )
}

/// Where P̄ = 0 likely lies left of the pull-off minimum, from what an
/// evaluation already knows: the points its landscape evaluated, the
/// operating point (P̄ = W there) and the minimum itself (P̄' = 0). The
/// nearest of them on either side of the root, h < h_po, bound it: the root
/// of the cubic that matches P̄ and P̄' at both. Where none is known above
/// it, Halley's step from the operating point. None where neither applies.
pub fn unloaded_hint(
    operating: Option<&Integrals>,
    land: &Landscape,
    pull_off: &PullOff,
) -> Option<f64> {
    let po = (pull_off.separation, pull_off.load.value(), 0.0);
    if po.1.is_nan() || po.1 >= 0.0 {
        return None;
    }
    let op = operating.map(|at| (at.separation, at.load().value(), at.dload_dh().value()));
    let known = land.samples.iter().copied().chain(op).chain([po]);
    let usable = |s: &(f64, f64, f64)| s.0 <= po.0 && s.1.is_finite() && s.2.is_finite();
    let above = known
        .clone()
        .filter(|s| usable(s) && s.1 > 0.0)
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let Some(a) = above else {
        let at = operating.filter(|at| at.load().signum() < 0.0)?;
        return newton_step(0.0, at).map(|(d, _)| at.separation - d);
    };
    let b = known
        .filter(|s| usable(s) && s.1 < 0.0 && s.0 > a.0)
        .min_by(|x, y| x.0.total_cmp(&y.0))?;
    // Cubic Hermite on t ∈ [0, 1]: H(0) = P̄(a) > 0 > P̄(b) = H(1), bisected.
    let w = b.0 - a.0;
    let cubic = |t: f64| {
        let (t2, t3) = (t * t, t * t * t);
        (2.0 * t3 - 3.0 * t2 + 1.0) * a.1
            + (t3 - 2.0 * t2 + t) * w * a.2
            + (3.0 * t2 - 2.0 * t3) * b.1
            + (t3 - t2) * w * b.2
    };
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if cubic(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(a.0 + w * 0.5 * (lo + hi))
}

/// The hint when it lies strictly inside (lo, hi) (a piece's ends).
fn inside(lo: f64, hi: f64, hint: Option<f64>) -> Option<f64> {
    hint.filter(|h| *h > lo && *h < hi && h.abs() <= super::coefficients::MAX_SEPARATION)
}

/// One end of the bracket a root search keeps: where, how far its load is from
/// the target, and the model there when it was evaluated.
#[derive(Clone, Copy)]
struct End {
    h: f64,
    miss: f64,
    at: Option<Integrals>,
}

/// The end of a bracket whose load misses the target least (the left one on a
/// tie), or `here` when neither end is known.
fn closer_end(left: Option<End>, right: Option<End>, here: End) -> End {
    match (left, right) {
        (Some(l), Some(r)) if l.miss <= r.miss => l,
        (_, Some(r)) => r,
        (Some(l), None) => l,
        (None, None) => here,
    }
}

/// The root of P̄ = target on a monotone piece (falling with h, or rising), from
/// the evaluated point `start`, with `left` and `right` the known ends of the
/// bracket (either may be unknown). Newton's method (in ln P̄ where the load and
/// the target are positive: nearly quadratic in h where P̄ ~ e^{-h²/2}),
/// safeguarded: a step must stay inside the bracket its iterates build, and a
/// step longer than half the one before the last is a bisection.
///
/// It stops when Newton's step falls below 2 ulps of h (that point is the
/// root), or, to save the confirming evaluation, one step earlier: once two
/// Newton steps d_{k-1}, d_k shrink quadratically (|d_k| ≤ |d_{k-1}|/10), the
/// error after the step d_k is about M d_k² with M ≈ |d_k|/d_{k-1}²; when 16
/// times that is below the same 2 ulps, and so is 16 |d_k|³ (f''/f')² (Halley's
/// cubic term, which the steps' ratio misses where f bends on a short length:
/// ln P̄ 1e-7 from a zero of P̄), the point the step reaches is evaluated (its
/// areas are needed anyway) and returned. Either way the result is the root to
/// a few ulps, whatever the start: the hint changes only the cost.
#[allow(clippy::too_many_arguments)]
fn newton_root(
    ev: &mut Counter,
    target: f64,
    start: Integrals,
    mut left: Option<End>,
    mut right: Option<End>,
    falling: bool,
    tolerance: f64,
) -> (SeparationOutcome, Option<Integrals>) {
    let mut cur = start;
    // Lengths of the last two steps taken, newest first, and whether the last
    // one was Newton's.
    let mut steps = [f64::INFINITY; 2];
    let mut newton_taken = false;
    let mut expand = 1.0_f64;
    let mut pull_step = 1.0_f64;
    loop {
        let contact = |ev: &Counter, at: Integrals| {
            (
                SeparationOutcome::Contact {
                    separation: at.separation,
                    evaluations: ev.evaluations,
                },
                Some(at),
            )
        };
        let x = cur.separation;
        let order = cur.load().cmp_f64(target);
        if order == Ordering::Equal {
            return contact(ev, cur);
        }
        let here = End {
            h: x,
            miss: miss(target, &cur),
            at: Some(cur),
        };
        // Above the target on a falling piece: the root lies to the right.
        if (order == Ordering::Greater) == falling {
            left = Some(here);
        } else {
            right = Some(here);
        }
        let lo = left.map_or(f64::NEG_INFINITY, |e| e.h);
        let hi = right.map_or(f64::INFINITY, |e| e.h);
        let tol = 2.0 * f64::EPSILON * x.abs().max(1.0);
        let bracketed = lo.is_finite() && hi.is_finite();
        if bracketed && hi - lo <= 4.0 * f64::EPSILON * lo.abs().max(hi.abs()).max(1.0) {
            // The bracket is a few ulps wide: its better end is the root.
            let best = closer_end(left, right, here);
            let at = best.at.unwrap_or_else(|| ev.at(best.h));
            return contact(ev, at);
        }
        if ev.evaluations >= MAX_EVALUATIONS {
            return (
                SeparationOutcome::NotConverged {
                    separation: x,
                    evaluations: ev.evaluations,
                },
                None,
            );
        }
        let (step, bend) = match newton_step(target, &cur) {
            Some((d, bend)) => (Some(d), bend),
            None => (None, f64::INFINITY),
        };
        // A caller's tolerance holds on the length over which P̄ bends.
        if step.is_some_and(|d| d.abs() <= tol.max(tolerance / bend.max(1.0))) {
            return contact(ev, cur);
        }
        let newton = step
            .map(|d| x - d)
            .filter(|n| n.is_finite() && *n > lo && *n < hi);
        // Not halving over two steps (far from the root, or near a double root
        // where Newton is linear): bisect what is known.
        let slow = bracketed && newton.is_some_and(|n| (n - x).abs() > 0.5 * steps[1]);
        let reach = 4.0 * x.abs().max(1.0);
        // One-sided on a falling piece where a meniscus's pull still outweighs
        // the contacts, P̄ ≤ 0 < W: the linear Newton step follows the
        // meniscus's flat plateau far past the root, which lies where the
        // contacts load up, their load growing like e^{h Δh}. Step one unit
        // towards it, doubling while P̄ stays ≤ 0 (16 → 9 evaluations on the
        // humid hub; without a meniscus the solid attraction's slope guides
        // Newton well enough, and a strong JKR scene took more this way).
        let pulled = !bracketed
            && falling
            && target > 0.0
            && ev.model.capillary.is_some()
            && cur.load().signum() <= 0.0;
        let (next, is_newton) = match newton {
            _ if pulled => {
                let step = pull_step.min(reach);
                pull_step *= 2.0;
                (x - step, false)
            }
            Some(n) if !slow && (bracketed || (n - x).abs() <= reach) => (n, true),
            // One-sided and far: at most `reach` toward the root.
            Some(n) if !slow => (x + reach.copysign(n - x), false),
            _ if bracketed => (0.5 * (lo + hi), false),
            _ => {
                // Newton points away from the root (past the pull-off minimum,
                // where P̄ rises) or is undefined: widen from the known end.
                let e = expand.max(0.25 * x.abs());
                expand *= 2.0;
                (if lo.is_finite() { lo + e } else { hi - e }, false)
            }
        };
        if !(next > lo && next < hi) {
            // Rounding put the midpoint on an end: the bracket is as narrow as h allows.
            let best = closer_end(left, right, here);
            let at = best.at.unwrap_or_else(|| ev.at(best.h));
            return contact(ev, at);
        }
        // Quadratic convergence: the step's error is about |d|³/d_prev² (see
        // above), and the step is short against the length 1/|f''/f'| over which
        // f bends (ln P̄ a few 1e-8 from a zero of P̄: the steps' ratio alone
        // looked converged there, found by the million-case run).
        let length = (next - x).abs();
        let accept = is_newton
            && newton_taken
            && length <= 0.1 * steps[0]
            && 16.0 * length * length * length <= tol * steps[0] * steps[0]
            && 16.0 * length * length * length * bend * bend <= tol;
        let at = ev.at(next);
        if accept {
            return contact(ev, at);
        }
        steps = [length, steps[0]];
        newton_taken = is_newton;
        cur = at;
    }
}

/// How far a load is from the target (in ln terms when both are positive).
fn miss_of(target: f64, l: Scaled) -> f64 {
    if target > 0.0 && l.signum() > 0.0 {
        (l.ln_abs() - target.ln()).abs()
    } else {
        l.minus(Scaled::from_f64(target)).value().abs()
    }
}

/// How far a point's load is from the target (in ln terms when both are positive).
fn miss(target: f64, at: &Integrals) -> f64 {
    miss_of(target, at.load())
}

/// The step to the root of P̄ = T from one point: Halley's (f/f')/(1 - f f''/(2f'²))
/// for f = ln P̄ - ln T where both are positive (nearly quadratic in h where
/// P̄ ~ e^{-h²/2}), else for f = P̄ - T; with f'' from P̄'', which every
/// evaluation carries, it converges cubically. Newton's f/f' where the correction
/// is large (|f f''/f'²| > 1, far from the root); None where the step is
/// meaningless.
///
/// Also |f''/f'|, the inverse of the length over which the step's function
/// bends: Halley's error after a step d is about C d³ with C of order
/// (f''/f')² (and f'''/f', of the same order where f has a singularity nearby,
/// e.g. ln P̄ near a zero of P̄).
pub(crate) fn newton_step(target: f64, at: &Integrals) -> Option<(f64, f64)> {
    let load = at.load();
    let slope = at.dload_dh();
    if slope.mantissa == 0.0 {
        return None;
    }
    let curvature = at.d2load_dh2();
    let (newton, correction, bend) = if target > 0.0 && load.signum() > 0.0 {
        // f' = P̄'/P̄, f'' = P̄''/P̄ - f'².
        let f = load.ln_abs() - target.ln();
        let d1 = slope.ratio(load);
        let d2 = curvature.ratio(load) - d1 * d1;
        (f / d1, f * d2 / (d1 * d1), (d2 / d1).abs())
    } else {
        let f = load.minus(Scaled::from_f64(target));
        let newton = f.ratio(slope);
        let bend = curvature.ratio(slope);
        (newton, newton * bend, bend.abs())
    };
    let step = if correction.abs() <= 1.0 {
        newton / (1.0 - 0.5 * correction)
    } else {
        newton
    };
    step.is_finite().then_some((step, bend))
}
