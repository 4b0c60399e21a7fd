//! The work of separation: Γ̄ = -∫_{h0}^∞ P̄(h) dh, the apparent work of adhesion
//! of docs/model.md §10 in model units (what a cantilever-beam test measures, per
//! unit nominal area, from the unloaded equilibrium h0 to infinity).
//!
//! **Method: the integrals exchanged** ([`work_of_separation`]). The solid load is
//! a convolution, P̄_s(h) = ∫ p(Δ) φ̄(h + Δ) dΔ with p one asperity's load, so
//!
//! ```text
//! ∫_{h0}^∞ P̄_s(h) dh = ∫ p(Δ) T_0(h0 + Δ) dΔ,   T_0(u) = ∫_u^∞ e^{-x²/2} dx = √(π/2) erfc(u/√2)
//! ```
//!
//! one integral over the summit heights with the Gaussian tail as weight instead
//! of a quadrature over h whose every node is a whole evaluation of the model.
//! p is piecewise smooth: the contact law on [0, Δc] (JKR in v = s - s0 as the
//! model takes it, DMT's Hertz part in t = Δ^{1/2}), the plastic junctions
//! beyond, and under DMT the attraction on Δ < 0 (van der Waals in y = -Δ mapped
//! as y = a + (z0 + a) τ/(1 - τ), which carries its 1/(z0 + y)² exactly and
//! reaches y = ∞; Dugdale on [-Δ_h, 0]). Each piece starts split where the
//! weight turns (at u = h0 + Δ = 0 and at levels of its log) and is refined with
//! the pieces of the capillary term, which is not linear in the coverage and is
//! integrated over h, P̄_cap(h) being a closed form (the substitution below).
//! The Lennard-Jones law's table has no pointwise p; under it the quadrature over
//! h stands ([`work_by_separation`], also the independent check of this one:
//! `exchanged_work_matches_the_quadrature_over_h`).
//!
//! **Quadrature over h** ([`work_by_separation`]). P̄ is smooth in h (a
//! convolution with a Gaussian; the law's jumps are smoothed by it). Over
//! [h0, ∞) substitute h = h0 + L (1 - t)/t, t ∈ (0, 1] (L = 1 plus the longest
//! reach of the attraction or the meniscus, so that their features sit at t of
//! order 1/2): dh = L dt/t², and a van der Waals tail P̄ ~ -C/h² becomes a
//! bounded integrand near t = 0, a Gaussian one a vanishing one. Past
//! h = [`super::coefficients::MAX_SEPARATION`] only the van der Waals tail is
//! left, -c_0 √(2π) z0²/(z0 + h)² (1 + O(h^-2)), integrated in closed form.
//!
//! **Refinement** (both). The pieces are bisected adaptively, the one with the
//! largest error first, each by the Gauss–Kronrod 7–15 pair, until the sum of
//! the pieces' error estimates (QUADPACK's: |K15 - G7| shrunk by
//! (200|K15 - G7|/∫|f|)^{3/2}) falls below 1e-11 of |Γ̄| (or of 1e-3 of the
//! integral of |f|, where Γ̄'s shares cancel), the 15-point values kept.

use super::asperity_law::Tabulated;
use super::gauss::{KRONROD_GAUSS_WEIGHTS, KRONROD_NODES, KRONROD_WEIGHTS};
use super::integrals::{ContactLaw, Integrals, Model};
use super::law::Attraction;
use super::special::{gaussian_tail_fast as tail, kappa, tail0, tail1_given, SQRT_TWO_PI};

/// The relative tolerance of the adaptive quadrature.
const TOLERANCE: f64 = 1e-11;
/// The most pieces the bisection may make.
const MAX_PIECES: usize = 600;

/// What a piece integrates (module docs); `VanDerWaals` carries the start a of
/// its map y = a + (z0 + a) τ/(1 - τ).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Part {
    /// The quadrature over h of the whole load, h = h0 + L (1 - t)/t.
    Load,
    /// JKR's elastic contacts, in v = s - s0.
    Elastic,
    /// DMT's Hertz contacts with their constant pull, in t = Δ^{1/2}.
    Hertz,
    /// The plastic junctions beyond Δc, in Δ.
    Plastic,
    /// DMT's van der Waals attraction, in τ.
    VanDerWaals(f64),
    /// DMT's Dugdale attraction, in x = Δ + Δ_h ∈ [0, Δ_h].
    Dugdale,
    /// The capillary load over h, h = h0 + L (1 - t)/t.
    Capillary,
}

impl Part {
    /// The order in which the pieces are summed: by part, then position.
    fn key(self) -> (u8, f64) {
        match self {
            Part::Load => (0, 0.0),
            Part::Elastic => (1, 0.0),
            Part::Hertz => (2, 0.0),
            Part::Plastic => (3, 0.0),
            Part::VanDerWaals(a) => (4, a),
            Part::Dugdale => (5, 0.0),
            Part::Capillary => (6, 0.0),
        }
    }
}

/// A piece: its part and interval, and its Gauss–Kronrod value, error estimate
/// and integral of |f|.
#[derive(Debug, Clone, Copy)]
struct Piece {
    part: Part,
    a: f64,
    b: f64,
    value: f64,
    error: f64,
    size: f64,
}

/// One Gauss–Kronrod 7–15 piece of f on [a, b].
fn kronrod(part: Part, a: f64, b: f64, f: &mut dyn FnMut(Part, f64) -> f64) -> Piece {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut k15, mut g7, mut abs15) = (0.0, 0.0, 0.0);
    for (i, (&x, &w)) in KRONROD_NODES.iter().zip(&KRONROD_WEIGHTS).enumerate() {
        let v = if x == 0.0 {
            f(part, mid)
        } else {
            f(part, mid - half * x) + f(part, mid + half * x)
        };
        k15 += w * v;
        abs15 += w * v.abs();
        if i % 2 == 1 {
            g7 += KRONROD_GAUSS_WEIGHTS[i / 2] * v;
        }
    }
    // QUADPACK's estimate: the K15–G7 difference, shrunk as (200 e / |f|)^{3/2}
    // once it is small (K15's own error falls much faster than G7's).
    let e = half * (k15 - g7).abs();
    let scale = half * abs15;
    let e = if scale > 0.0 && e > 0.0 {
        scale * (200.0 * e / scale).powf(1.5).min(1.0)
    } else {
        e
    };
    Piece {
        part,
        a,
        b,
        value: half * k15,
        error: e,
        size: scale,
    }
}

/// The integral over the pieces `start` (part and interval), bisecting the
/// worst until the error test of the module docs holds, summed in a fixed order
/// (by part and position, so that the result does not depend on the order the
/// pieces were made in beyond the pieces themselves).
fn integrate(start: &[(Part, f64, f64)], f: &mut dyn FnMut(Part, f64) -> f64) -> f64 {
    let mut pieces: Vec<Piece> = start
        .iter()
        .filter(|(_, a, b)| b > a)
        .map(|&(part, a, b)| kronrod(part, a, b, f))
        .collect();
    loop {
        let total: f64 = pieces.iter().map(|p| p.value).sum();
        let size: f64 = pieces.iter().map(|p| p.size).sum();
        let error: f64 = pieces.iter().map(|p| p.error).sum();
        if error <= TOLERANCE * total.abs().max(1e-3 * size) || pieces.len() >= MAX_PIECES {
            break;
        }
        let Some(worst) = pieces
            .iter()
            .enumerate()
            .max_by(|x, y| x.1.error.total_cmp(&y.1.error))
            .map(|(i, _)| i)
        else {
            break;
        };
        let Piece { part, a, b, .. } = pieces.swap_remove(worst);
        let mid = 0.5 * (a + b);
        for (x, y) in [(a, mid), (mid, b)] {
            pieces.push(kronrod(part, x, y, f));
        }
    }
    pieces.sort_by(|x, y| {
        let (kx, ky) = (x.part.key(), y.part.key());
        kx.0.cmp(&ky.0)
            .then(kx.1.total_cmp(&ky.1))
            .then(x.a.total_cmp(&y.a))
    });
    pieces.iter().map(|p| p.value).sum()
}

/// Γ̄ = -∫_{from}^∞ P̄(h) dh (model units: multiply by the load scale per unit area
/// times σ for J/m²), and the integrand evaluations it spent: by the exchanged
/// integrals under JKR and DMT, over h under the Lennard-Jones law's table
/// (module docs).
pub fn work_of_separation(model: &Model, from: f64) -> (f64, usize) {
    let tabulated = model
        .tabulated()
        .and_then(|table| Some((table, table.solid_work(from)?)));
    let (work, evaluations) = match (model.contact_law(), tabulated) {
        (Some(law), _) if from.is_finite() => exchanged(model, &law, from),
        (_, Some((table, solid))) => exchanged_tabulated(model, table, solid, from),
        _ => work_by_separation(model, from),
    };
    // A work that underflows (a minimum at h ~ 150: e^{-1e4}) is 0, not −0 or
    // a subnormal of either sign (the rounding of shares that underflowed).
    let work = if work.abs() < f64::MIN_POSITIVE {
        0.0
    } else {
        work
    };
    (work, evaluations)
}

/// The farthest the unloaded equilibrium's search stops from the root, in h
/// or, where P̄ bends on a shorter length L = |P̄'/P̄''|, in units of L:
/// [`work_of_separation_near`] integrates the rest, whose error is then about
/// (d/L)⁴/24 of Γ̄ (below 1e-13).
pub const UNLOADED_TOLERANCE: f64 = 1e-3;

/// Γ̄ from the unloaded equilibrium h0 (the root of P̄ = 0), given the model
/// `at` a point h near it: the work from h, plus the strip between h0 and h
/// from P̄ and its two derivatives at h, ∫_{h−d}^{h} P̄ = p d − p′ d²/2 +
/// p″ d³/6, with d = h − h0 Halley's step (error O(d³)). Γ̄ is stationary in
/// its lower end (P̄(h0) = 0), so the step's own error enters only squared:
/// the root need not be found to rounding (two or three evaluations of the
/// model instead of six on the humid hub). Also the evaluations spent.
pub fn work_of_separation_near(model: &Model, at: &Integrals) -> (f64, usize) {
    let (work, evaluations) = work_of_separation(model, at.separation);
    let (p, p1, p2) = (
        at.load().value(),
        at.dload_dh().value(),
        at.d2load_dh2().value(),
    );
    // Halley's step to P̄ = 0, the one the search itself takes.
    let Some((d, bend)) = super::separation::newton_step(0.0, at) else {
        return (work, evaluations);
    };
    let strip = d * (p - d * (0.5 * p1 - d * p2 / 6.0));
    // Where the values underflow or the step is meaningless, h itself (the
    // search stopped within UNLOADED_TOLERANCE of the root either way).
    if strip.is_finite() && d.abs() * bend.max(1.0) <= 2.0 * UNLOADED_TOLERANCE {
        (work - strip, evaluations)
    } else {
        (work, evaluations)
    }
}

/// The levels of the weight's log at which the contact pieces start split.
const LEVELS: [f64; 8] = [0.5, 2.0, 8.0, 24.0, 60.0, 150.0, 400.0, 800.0];

/// Where a Gaussian weight e^{-(a + x)²/2}, x ≥ 0, turns: x at which its log has
/// fallen by each of [`LEVELS`] from its largest value on x ≥ 0 (and, when the
/// peak x = -a lies inside, a few points before it). The last is where it has
/// fallen by 800: beyond it nothing a double holds is left.
fn weight_breaks(a: f64) -> Vec<f64> {
    let mut out = vec![];
    if a < 0.0 {
        let peak = -a;
        out.extend(
            [peak - 8.0, peak - 3.0, peak - 1.0]
                .iter()
                .filter(|&&x| x > 0.0),
        );
        out.push(peak);
        out.extend(LEVELS.iter().map(|l| peak + (2.0 * l).sqrt()));
    } else {
        out.extend(
            LEVELS
                .iter()
                .map(|l| 2.0 * l / (a + (a * a + 2.0 * l).sqrt())),
        );
    }
    out
}

/// [`work_of_separation`] by the exchanged integrals (module docs).
fn exchanged(model: &Model, law: &ContactLaw, h0: f64) -> (f64, usize) {
    let dc = law.critical_interference;
    let breaks = weight_breaks(h0);
    let end = *breaks.last().unwrap_or(&0.0);
    let mut start: Vec<(Part, f64, f64)> = vec![];
    // The contact law on [0, min(Δc, end)], then the plastic junctions.
    let mut edges: Vec<f64> = std::iter::once(0.0)
        .chain(
            breaks
                .iter()
                .copied()
                .filter(|&x| x > 0.0 && x < dc.min(end)),
        )
        .collect();
    edges.push(dc.min(end));
    let hertz = law.hertz_offset != 0.0;
    for w in edges.windows(2) {
        if hertz {
            start.push((Part::Hertz, w[0].sqrt(), w[1].sqrt()));
        } else {
            let v = |d: f64| model.v_of_interference(d);
            start.push((Part::Elastic, v(w[0]), v(w[1])));
        }
    }
    if dc < end {
        let mut edges = vec![dc];
        edges.extend(breaks.iter().copied().filter(|&x| x > dc));
        for w in edges.windows(2) {
            start.push((Part::Plastic, w[0], w[1]));
        }
    }
    // The attraction on Δ < 0 under DMT.
    let c_0 = model.coefficients.c_0;
    let attraction = model.closed_form_attraction().filter(|_| c_0 > 0.0);
    // z0 (van der Waals) or Δ_h (Dugdale).
    let reach = attraction.map_or(0.0, |a| a.range());
    match attraction {
        Some(Attraction::VanDerWaals { .. }) => {
            // y = -Δ: the weight T_0(h0 - y) turns at y = h0.
            let mut ys = vec![0.0];
            ys.extend(
                [-8.0, -3.0, -1.0, 0.0, 1.0, 3.0, 8.0]
                    .iter()
                    .map(|d| h0 + d)
                    .filter(|&y| y > 0.0),
            );
            for (i, &a) in ys.iter().enumerate() {
                // τ of the next edge in this piece's own map (1: y = ∞).
                let top = ys.get(i + 1).map_or(1.0, |&y| (y - a) / (reach + y));
                start.push((Part::VanDerWaals(a), 0.0, top));
            }
        }
        Some(Attraction::Dugdale { range }) => {
            let a = h0 - range;
            let mut edges = vec![0.0];
            edges.extend(
                weight_breaks(a)
                    .into_iter()
                    .filter(|&x| x > 0.0 && x < range),
            );
            edges.push(range);
            for w in edges.windows(2) {
                start.push((Part::Dugdale, w[0], w[1]));
            }
        }
        None => {}
    }
    let cap_scale = capillary_scale(model);
    start.extend(capillary_pieces(model, h0, cap_scale));
    let (s0, s0_3, c_a) = (law.s_touch, law.c_d_cubed, law.c_a);
    let mut evaluations = 0;
    let mut f = |part: Part, x: f64| -> f64 {
        evaluations += 1;
        match part {
            Part::Elastic => {
                let s = s0 + x;
                let s3 = s * s * s;
                // dΔ/ds = 4s³ - c_d = 3 s0³ + 12 s0² v + 12 s0 v² + 4 v³.
                let jac = 3.0 * s0_3 + x * (12.0 * s0 * s0 + x * (12.0 * s0 + 4.0 * x));
                s3 * (s3 - c_a) * jac * tail(h0 + model.interference_of_v(x))
            }
            Part::Hertz => {
                let d = x * x;
                (d * x - law.hertz_offset) * 2.0 * x * tail(h0 + d)
            }
            Part::Plastic => (law.c_p * x - law.c_0) * tail(h0 + x),
            Part::VanDerWaals(a) => {
                let y = (reach + a) * x / (1.0 - x);
                -c_0 * reach * reach / (reach + a) * tail((h0 - a) - y)
            }
            Part::Dugdale => -c_0 / reach * x * tail(h0 - reach + x),
            // The whole load over h is the other method's, never a piece here.
            Part::Load => 0.0,
            Part::Capillary => capillary_integrand(model, h0, cap_scale, x),
        }
    };
    let integral = integrate(&start, &mut f) + capillary_beyond(model, h0);
    (-integral, evaluations)
}

/// L of the meniscus's map h = h0 + L (1 − t)/t: 1 plus its reach (capped).
fn capillary_scale(model: &Model) -> f64 {
    model.capillary.map_or(1.0, |c| 1.0 + c.range.min(1e3))
}

/// The meniscus's load over h at t of the map h = h0 + L (1 − t)/t, times dh/dt.
fn capillary_integrand(model: &Model, h0: f64, scale: f64, t: f64) -> f64 {
    let h = h0 + scale * (1.0 - t) / t;
    let Some(capillary) = model.capillary else {
        return 0.0;
    };
    let (load, exponent) = capillary.load_at(h);
    let load = if exponent == 0.0 {
        load
    } else {
        load * (-exponent).exp()
    };
    load * scale / (t * t)
}

/// ∫_{Δc}^∞ (c_p Δ − c_0) T_0(h0 + Δ) dΔ, the plastic junctions' part of the
/// work with the integrals exchanged, in closed form: with a = h0 + Δc and
/// T_n(a) = ∫_0^∞ y^n e^{−(a+y)²/2} dy it is c_p T_2(a)/2 + (c_p Δc − c_0) T_1(a)
/// (∫_a^∞ T_0 = T_1, ∫_a^∞ (u − a) T_0(u) du = T_2/2), T_2 = T_0 − a T_1 by
/// parts. That difference cancels for large a (a² ulps of T_2: 2e-14 at
/// a = 12, where the junctions weigh e^{−72} of the contacts before them).
fn plastic_work(c_p: f64, c_0: f64, h0: f64, dc: f64) -> f64 {
    let a = h0 + dc;
    let scale = (-kappa(a)).exp();
    if scale == 0.0 {
        return 0.0;
    }
    let t0 = tail0(a);
    let t1 = tail1_given(a, t0);
    let t2 = t0 - a * t1;
    (0.5 * c_p * t2 + (c_p * dc - c_0) * t1) * scale
}

/// [`work_of_separation`] under a law that integrates its own shares (the
/// Lennard-Jones law's grid): `solid`, their part with the integrals exchanged
/// ([`Tabulated::solid_work`]), plus each curve's plastic junctions beyond its
/// own Δc with its weight (as the model adds them to P̄) and the meniscus over
/// h, as in [`exchanged`].
fn exchanged_tabulated(model: &Model, table: &dyn Tabulated, solid: f64, h0: f64) -> (f64, usize) {
    let c = &model.coefficients;
    let mut evaluations = 0;
    let mut integral = solid;
    table.plastic_junctions(&mut |dc, weight| {
        if dc.is_finite() {
            integral += weight * plastic_work(c.c_p, c.c_0, h0, dc);
        }
    });
    if model.capillary.is_some() {
        let scale = capillary_scale(model);
        let mut f = |_: Part, t: f64| {
            evaluations += 1;
            capillary_integrand(model, h0, scale, t)
        };
        integral += integrate(&capillary_pieces(model, h0, scale), &mut f);
        integral += capillary_beyond(model, h0);
    }
    (-integral, evaluations)
}

/// The meniscus's starting pieces in t of the map h = from + L (1 − t)/t: cut
/// at t = 1/8, 1/4, 3/8, 1/2, 3/4 (h = from + 7L, 3L, 5L/3, L, L/3), where the
/// refinement from one piece cut them anyway on the humid hub (its Gaussian
/// decay beyond the meniscus's reach lies there): the same final pieces,
/// without first estimating the coarser ones they were cut from.
/// The farthest, h ≥ from + 7L, is left out where it cannot matter: |P̄_cap| ≤
/// c_cap J (1 − e^{−F} ≤ F) and ∫_H^∞ J dh = (1/k) ∫_{H−k}^{H} T_1 ≤ T_1(H − k),
/// so that piece is at most c_cap T_1(H − k) in size; it is dropped where that
/// is below 1e-16 of what the meniscus holds near `from`, ∫_{from}^{from + L/3}
/// |P̄_cap| ≥ (L/3) |P̄_cap(from + L/3)| (|P̄_cap| falls with h) — far below the
/// quadrature's tolerance (on the humid hub it holds 1e-41 of the total).
fn capillary_pieces(model: &Model, from: f64, scale: f64) -> Vec<(Part, f64, f64)> {
    let Some(capillary) = model.capillary else {
        return vec![];
    };
    let t_end = capillary_end(from, scale);
    const FAR: f64 = 0.125;
    let negligible = || {
        let u = from + scale * (1.0 - FAR) / FAR - capillary.range;
        let bound = capillary.independent() * tail1_given(u, tail0(u)) * (-kappa(u)).exp();
        let w = scale / 3.0;
        let (load, exponent) = capillary.load_at(from + w);
        bound <= 1e-16 * w * load.abs() * (-exponent).exp()
    };
    let first = if t_end < FAR && negligible() {
        FAR
    } else {
        t_end
    };
    let mut edges = vec![first];
    edges.extend([FAR, 0.25, 0.375, 0.5, 0.75].iter().filter(|&&t| t > first));
    edges.push(1.0);
    edges
        .windows(2)
        .map(|w| (Part::Capillary, w[0], w[1]))
        .collect()
}

/// ∫_{H}^∞ P̄_cap dh (≤ 0), H = max(from, [`super::coefficients::MAX_SEPARATION`]):
/// the meniscus beyond the quadrature's end, which matters only where the
/// Kelvin gap reaches past H (RH within about 3e-7 of 1 at σ = 3 nm). There
/// T_1(h) = 0 and J(h) = T_1(h − k)/k, so with u = h − k and c = f/k = 2π R N σ
///
/// ```text
/// ∫_H^∞ P̄_cap dh = −p ∫_{H−k}^∞ (1 − e^{−c T_1(u)}) du
/// ```
///
/// On u ≤ −U (U = 40) T_1(u) = √(2π)|u| + T_1(|u|) is √(2π)|u| to rounding, and
/// that part is the closed form ∫_U^{k−H} (1 − e^{−c√(2π) v}) dv; the rest,
/// u ∈ [max(H − k, −U), U], is the module's adaptive quadrature (T_1(U) underflows).
/// As RH → 1 (k → ∞) the whole work of the meniscus tends to p k, i.e. γ_L
/// (cos θ_a + cos θ_b) in J/m² (docs/model.md §10: the flooded interface); test
/// `the_flooded_limit_holds_as_humidity_reaches_one`.
fn capillary_beyond(model: &Model, from: f64) -> f64 {
    const U: f64 = 40.0;
    let Some(capillary) = model.capillary else {
        return 0.0;
    };
    let k = capillary.range;
    let start = from.max(super::coefficients::MAX_SEPARATION);
    let lo = start - k;
    if lo >= U || !lo.is_finite() {
        return 0.0;
    }
    let c = capillary.wetting / k;
    // The linear part, v = −u ∈ [U, k − H]: L(1 − e^{−aU}) + e^{−aU}(aL − (1 − e^{−aL}))/a.
    let linear = if lo < -U {
        let a = c * SQRT_TWO_PI;
        let l = -lo - U;
        let x = a * l;
        // x − (1 − e^{−x}) without its cancellation for small x.
        let excess = if x < 1e-3 {
            x * x * (0.5 - x * (1.0 / 6.0 - x * (1.0 / 24.0 - x / 120.0)))
        } else {
            x + (-x).exp_m1()
        };
        l * -(-a * U).exp_m1() + (-a * U).exp() * excess / a
    } else {
        0.0
    };
    let from_u = lo.max(-U);
    let edges = [
        -U, -20.0, -10.0, -6.0, -3.0, -1.0, 0.0, 1.0, 3.0, 6.0, 10.0, U,
    ];
    let mut cuts = vec![from_u];
    cuts.extend(edges.iter().copied().filter(|&e| e > from_u));
    let pieces: Vec<(Part, f64, f64)> = cuts
        .windows(2)
        .map(|w| (Part::Capillary, w[0], w[1]))
        .collect();
    let mut f = |_: Part, u: f64| {
        let t1 = tail1_given(u, tail0(u)) * (-kappa(u)).exp();
        -(-c * t1).exp_m1()
    };
    let rest = integrate(&pieces, &mut f);
    -capillary.flooded * (linear + rest)
}

/// t at h = [`super::coefficients::MAX_SEPARATION`] in the map h = from + L (1 - t)/t
/// (1 when from is already beyond it).
fn capillary_end(from: f64, scale: f64) -> f64 {
    let limit = super::coefficients::MAX_SEPARATION;
    if from < limit {
        scale / (scale + (limit - from))
    } else {
        1.0
    }
}

/// Γ̄ by the quadrature of the whole load over h (module docs): the method under
/// the Lennard-Jones law's table, and the independent check of the exchanged one.
pub fn work_by_separation(model: &Model, from: f64) -> (f64, usize) {
    let law = model.effective_law();
    let reach = law
        .range()
        .max(model.capillary.map_or(0.0, |c| c.range))
        .min(1e3);
    let scale = 1.0 + reach;
    let t_end = capillary_end(from, scale);
    let mut evaluations = 0;
    let mut integrand = |_: Part, t: f64| {
        evaluations += 1;
        let h = from + scale * (1.0 - t) / t;
        model.at(h).load().value() * scale / (t * t)
    };
    let mut integral =
        integrate(&[(Part::Load, t_end, 1.0)], &mut integrand) + capillary_beyond(model, from);
    // Beyond h = MAX_SEPARATION a power-law attraction's tail in closed form:
    // −c_0 (z0/(z0 + h))² per summit under van der Waals, 4/3 of it under
    // Lennard-Jones (Hamaker constant 16π Z0² γ against 12π).
    let tail = law
        .law()
        .hamaker_factor(law.attraction_kind())
        .map(|factor| (law.range(), factor / 12.0));
    if let Some((range, factor)) = tail {
        if t_end < 1.0 {
            let c_0 = model.coefficients.c_0;
            let limit = super::coefficients::MAX_SEPARATION;
            integral -= factor * c_0 * SQRT_TWO_PI * range * range / (range + limit);
        }
    }
    (-integral, evaluations)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::capillary::Capillary;
    use crate::model::{Coefficients, Quadrature};

    /// Without adhesion and plasticity the load is Greenwood–Williamson's,
    /// P̄(h) = ∫_0^∞ Δ^{3/2} φ̄ dΔ, and exchanging the integrals gives Γ̄ from h0 = 0 in
    /// closed form (a negative work: the surfaces push apart).
    /// K15 integrates x^k exactly to degree 22, G7 to degree 13, on [-1, 1].
    #[test]
    fn kronrod_pair_is_exact() {
        for k in 0..=22 {
            let (mut kr, mut g) = (0.0, 0.0);
            for (i, (&x, &w)) in KRONROD_NODES.iter().zip(&KRONROD_WEIGHTS).enumerate() {
                let v = if x == 0.0 {
                    if k == 0 {
                        1.0
                    } else {
                        0.0
                    }
                } else {
                    x.powi(k) + (-x).powi(k)
                };
                kr += w * v;
                if i % 2 == 1 {
                    g += KRONROD_GAUSS_WEIGHTS[i / 2] * v;
                }
            }
            let exact = if k % 2 == 0 {
                2.0 / (k + 1) as f64
            } else {
                0.0
            };
            assert!((kr - exact).abs() < 4e-16, "K15 x^{k}: {kr} vs {exact}");
            if k <= 13 {
                assert!((g - exact).abs() < 4e-16, "G7 x^{k}: {g} vs {exact}");
            }
        }
    }

    #[test]
    fn greenwood_williamson_work_is_its_moment() {
        // ∫_0^∞ P̄_GW(h) dh = ∫_0^∞ Δ^{3/2} ∫_0^∞ e^{-(h+Δ)²/2} dh dΔ
        //   = ∫_0^∞ Δ^{3/2} √(π/2) erfc(Δ/√2) dΔ = 2^{5/4} Γ(9/4)... by mpmath:
        //   mp.quad(lambda d: d**1.5*mp.sqrt(mp.pi/2)*mp.erfc(d/mp.sqrt(2)), [0, mp.inf])
        //   = 2^{3/4} Γ(7/4) / (5/2) (∫_0^∞ x^a erfc(x/c) dx = c^{a+1} Γ(a/2+1)/((a+1)√π))
        //   = 0.618269107376997349689517304146 (mpmath, 30 digits; both forms agree).
        let want = 0.618_269_107_376_997_3;
        let m = Model::new(Coefficients::new(0.0, f64::INFINITY));
        let (w, evaluations) = work_of_separation(&m, 0.0);
        assert!((-w / want - 1.0).abs() < 1e-13, "{w} vs {want}");
        assert!(evaluations < 2000, "{evaluations}");
    }

    /// The two methods are independent (one integrates the model's P̄ over h,
    /// the other one asperity's law against the Gaussian tail): they agree on
    /// JKR and DMT scenes (both attractions, short and long ranges), with and
    /// without a meniscus (from a sub-σ one to a flooding one), from deep in
    /// contact to far out, and with and without plasticity.
    #[test]
    fn exchanged_work_matches_the_quadrature_over_h() {
        use crate::model::AsperityLaw::{Dmt, Jkr};
        use crate::model::Attraction::{Dugdale, VanDerWaals};
        let laws = [
            Jkr,
            Dmt(VanDerWaals { range: 0.1 }),
            Dmt(VanDerWaals { range: 3e-3 }),
            Dmt(Dugdale { range: 0.1 }),
            Dmt(Dugdale { range: 2.0 }),
        ];
        let capillaries = [
            None,
            Some(Capillary {
                range: 0.5,
                wetting: 0.04,
                flooded: 1.3,
            }),
            Some(Capillary {
                range: 20.0,
                wetting: 50.0,
                flooded: 0.01,
            }),
        ];
        let mut worst = 0.0f64;
        for law in laws {
            for (theta, lambda) in [(184.0, 1e5), (3.0, 10.0), (0.5, 2.0), (30.0, f64::INFINITY)] {
                for cap in capillaries {
                    let m = Model::with_law(
                        Coefficients::from_indices(theta, lambda),
                        law,
                        Quadrature::default(),
                    )
                    .with_capillary(cap);
                    for from in [-6.0, -1.0, 0.0, 0.7, 2.9, 6.0] {
                        let (a, _) = work_of_separation(&m, from);
                        let (b, _) = work_by_separation(&m, from);
                        let e = (a - b).abs() / b.abs().max(1e-300);
                        worst = worst.max(e);
                        assert!(
                            e < 1e-9 && a.is_finite(),
                            "{law:?} θ={theta} λ={lambda} {cap:?} h0={from}: {a} vs {b}"
                        );
                    }
                }
            }
        }
        // (2.7e-10 at most when this was written: both are held to 1e-11 of
        // |Γ̄| or 1e-3 of ∫|f|, and the shares cancel on some of these scenes.)
        assert!(worst > 0.0);
    }

    /// The plastic junctions' closed form against the quadrature the JKR and
    /// DMT method takes for them (Gauss–Kronrod, 1e-11), from deep in contact
    /// to far out in the weight's tail: 1e-13 (4e-13 at a = h0 + Δc = 12,
    /// where T_2 = T_0 − a T_1 has cancelled a² ulps).
    #[test]
    fn plastic_work_is_its_quadrature() {
        let (c_p, c_0) = (3.7, 0.4);
        for h0 in [-6.0, -1.0, 0.0, 1.3, 4.0] {
            for dc in [0.0, 0.3, 2.0, 8.0] {
                let got = plastic_work(c_p, c_0, h0, dc);
                let breaks = weight_breaks(h0 + dc);
                let edges: Vec<f64> = std::iter::once(0.0).chain(breaks).collect();
                let start: Vec<(Part, f64, f64)> = edges
                    .windows(2)
                    .map(|w| (Part::Plastic, dc + w[0], dc + w[1]))
                    .collect();
                let want = integrate(&start, &mut |_, x| {
                    (c_p * x - c_0) * crate::model::special::gaussian_tail(h0 + x)
                });
                let tol = if h0 + dc > 10.0 { 4e-13 } else { 1e-13 };
                assert!(
                    (got - want).abs() <= tol * want.abs(),
                    "h0 {h0} Δc {dc}: {got} vs {want}"
                );
            }
        }
    }

    /// Under the Lennard-Jones law the grid's exchanged sum against the
    /// quadrature of the model's P̄ over h: hub-like, short- and long-range
    /// scenes, with and without plasticity and a meniscus, from deep in
    /// contact to far out. The two differ by the far field beyond h = 1e6,
    /// which the quadrature over h takes in closed form as Bradley's
    /// (P̂/B = 1) and the grid integrates as the table has it: so the bound is
    /// 1e-9 of Γ̄ plus 1e-3 of that closed-form tail (measured: 3.1e-4 of it,
    /// the rest not yet traced, some 4e-6 of Γ̄; what an earlier table gave:
    /// docs/history.md).
    #[test]
    fn the_lennard_jones_work_by_its_grid_matches_the_quadrature_over_h() {
        use crate::model::AsperityLaw;
        let mut exchanged_cases = 0;
        for (theta, lambda, z0) in [
            (184.0, 1e5, 0.1),
            (184.0, 10.0, 0.1),
            (30.0, 3.0, 0.3),
            (1e3, 1e2, 0.02),
            (3.0, f64::INFINITY, 1.0),
        ] {
            for cap in [
                None,
                Some(Capillary {
                    range: 0.5,
                    wetting: 0.04,
                    flooded: 1.3,
                }),
            ] {
                let m = Model::with_law(
                    Coefficients::from_indices(theta, lambda),
                    AsperityLaw::LennardJones { range: z0 },
                    Quadrature::default(),
                )
                .with_capillary(cap);
                let far = 4.0 / 3.0 * m.coefficients.c_0 * SQRT_TWO_PI * z0 * z0
                    / (z0 + super::super::coefficients::MAX_SEPARATION);
                for from in [-3.0, 0.0, 1.0, 2.9, 6.0] {
                    let table = m.tabulated().expect("μ inside the table");
                    exchanged_cases += usize::from(table.solid_work(from).is_some());
                    let (a, _) = work_of_separation(&m, from);
                    let (b, _) = work_by_separation(&m, from);
                    assert!(
                        (a - b).abs() <= 1e-9 * b.abs() + 1e-3 * far && a.is_finite(),
                        "θ={theta} λ={lambda} z0={z0} {cap:?} h0={from}: {a} vs {b} (far {far})"
                    );
                }
            }
        }
        assert_eq!(exchanged_cases, 50);
    }

    /// Γ̄ from a point near the unloaded equilibrium (within the search's
    /// tolerance in units of the length over which P̄ bends, either side)
    /// against Γ̄ from the root itself (solved to
    /// rounding): within 1e-12 of Γ̄, under JKR, DMT and the Lennard-Jones
    /// law, dry and with a meniscus. From h itself, uncorrected, the work
    /// misses by |P̄'| d²/2 (6e-8 of Γ̄ at d = 1e-3 on the DMT hub).
    #[test]
    fn the_work_from_near_the_root_is_the_work_from_it() {
        use crate::model::separation::{landscape, solve_separation_at, SeparationOutcome};
        use crate::model::{AsperityLaw, Attraction};
        let meniscus = Capillary {
            range: 0.5,
            wetting: 0.04,
            flooded: 1.3,
        };
        let mut checked = 0;
        for law in [
            AsperityLaw::Jkr,
            AsperityLaw::Dmt(Attraction::VanDerWaals { range: 0.1 }),
            AsperityLaw::LennardJones { range: 0.1 },
        ] {
            for cap in [None, Some(meniscus)] {
                let m = Model::with_law(
                    Coefficients::from_indices(184.0, 10.0),
                    law,
                    Quadrature::default(),
                )
                .with_capillary(cap);
                let land = landscape(&m);
                let SeparationOutcome::Contact { separation: h0, .. } =
                    solve_separation_at(&m, 0.0, Some(&land), None).0
                else {
                    panic!("{law:?} {cap:?}: no unloaded equilibrium");
                };
                let (want, _) = work_of_separation(&m, h0);
                let at = m.at(h0);
                let length = at.dload_dh().ratio(at.d2load_dh2()).abs().min(1.0);
                for d in [-1.0, -0.1, 0.01, 1.0].map(|f| f * UNLOADED_TOLERANCE * length) {
                    let (got, _) = work_of_separation_near(&m, &m.at(h0 + d));
                    let (plain, _) = work_of_separation(&m, h0 + d);
                    assert!(
                        (got - want).abs() <= 1e-12 * want.abs(),
                        "{law:?} {cap:?} d = {d}: {got} against {want} (uncorrected {plain})"
                    );
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 24);
    }

    #[test]
    fn the_humid_hubs_work_costs_what_it_did() {
        let m = Model::with_law(
            Coefficients::from_indices(184.0, 1e5),
            crate::model::AsperityLaw::Dmt(crate::model::Attraction::VanDerWaals { range: 0.1 }),
            Quadrature::default(),
        )
        .with_capillary(Some(Capillary {
            range: 0.5,
            wetting: 0.04,
            flooded: 1.3,
        }));
        let (w, evaluations) = work_of_separation(&m, 2.9);
        // Pinned (32 Gauss–Kronrod pieces of 15 points over the Hertz contacts,
        // the plastic junctions, the van der Waals attraction and the meniscus,
        // 5 of them the meniscus's: 9 created when it started as one piece, 540
        // evaluations in all): a change in the cost shows here. Over h the same
        // work took 105 evaluations of the whole model, each dearer than all 480
        // of the exchanged integrand's. The work is the one-piece start's
        // (3.2780863138543717e-4, printed by it) to rounding: the same final
        // pieces (the coverage's fast Mills ratio and exponential move its
        // last bit).
        assert!(w > 0.0 && evaluations == 480, "{evaluations}");
        assert!(
            (w / 3.278_086_313_854_371_7e-4 - 1.0).abs() < 1e-15,
            "{w:e}"
        );
    }
}
