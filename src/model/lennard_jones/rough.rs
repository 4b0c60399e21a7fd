//! The rough surface under the Lennard-Jones asperity law (MODEL.md §8,
//! docs/model.md §11): the load of every summit, attracted ones included,
//! integrated over the Gaussian summit heights.
//!
//! In the units of docs/model.md §3 one summit at interference Δ = δ/σ carries
//! p(Δ) = ℓ^{-3/2} P̂(ℓΔ; μ), with ℓ = σ/ε = (2/c_0)^{2/3} (so that the JKR curve
//! in these units is §3's p_e: c_a = √6 ℓ^{-3/4}) and μ = ẑ0/(ℓ z0),
//! z0 = Z0/σ. Then
//!
//! ```text
//! P̄(h) = ∫ p(Δ) φ̄(h+Δ) dΔ,   φ̄(u) = e^{-u²/2},
//! ```
//!
//! over the approach part (Δ below the switch, in τ = G^{-1/2} where the
//! table is smooth), the contact part from the switch to Δc (Gauss–Legendre
//! panels that keep the table's own panel ends), and the plastic junctions
//! beyond Δc (c_p Δ − c_0, in closed form by the caller). Shares with Δ < 0 are
//! the non-contact load. A Tabor parameter between the table's nodes is
//! served by interpolating the integrals (not the curves, whose jumps move)
//! between the four nearest nodes, cubic in 1/μ.
//!
//! **Plastic junctions.** A summit turns plastic when the load it carries
//! inside its contact radius, over the contact area, reaches the hardness:
//! P̂_in/â² = c_h ℓ^{1/2} (P_in/(πa²) = H). Under JKR the whole load acts
//! inside the contact and a² = Rδ1: §3's cubic. Under DMT the adhesion acts
//! outside and P_in is Hertz's, a² = Rδ: Δc = c_h².

use std::sync::OnceLock;

use super::table::{curves, Curve};
use crate::model::gauss;
use crate::model::special::{exp_fast, gaussian_tail_fast, SQRT_TWO_PI};

/// The half-width in Δ of the weight's range: e^{-u²/2} ≥ e^{-46} inside.
const REACH: f64 = 9.591_663_046_625_44;

/// The windows in Δ of the non-contact and the contact share at h (that
/// order) for the attraction range z0: where a summit's weight, relative to
/// its share's scale, is at least e^{-46} of what the share holds.
///
/// A share scaled by e^{-h²/2} (the contact one at h > 0, the non-contact
/// one at h < 0) holds its summits nearest Δ = 0 most: its window is where
/// e^{-(h+Δ)²/2 + h²/2} ≥ e^{-46}, Δ ∈ −h ± √(h² + 92) (REACH
/// either side of the peak at h = 0, wider beyond: a window of REACH about
/// Δ = 0 would cut summits that still weigh at large h: docs/history.md). An
/// unscaled share's window is
/// REACH either side of its peak Δ = −h; the non-contact one at h > 0 reaches
/// further towards contact, where its summits pull hardest: the far summits
/// at the peak pull less by Bradley's (z0/(z0 + h))², so the window grows by
/// that factor's logarithm.
fn windows(h: f64, z0: f64) -> [(f64, f64); 2] {
    let scaled = || {
        let half = h.mul_add(h, REACH * REACH).sqrt();
        (-h - half, -h + half)
    };
    let unscaled = (-h - REACH, -h + REACH);
    if h > 0.0 {
        // ln(1 + h/z0) from above by the binary exponent (a window a little
        // wider than needed, for no logarithm in the hot path).
        let octaves = ((1.0 + h / z0).to_bits() >> 52) as f64 - 1022.0;
        let reach = (4.0 * std::f64::consts::LN_2)
            .mul_add(octaves, REACH * REACH)
            .sqrt();
        [(-h - REACH, -h + reach), scaled()]
    } else if h < 0.0 {
        [scaled(), unscaled]
    } else {
        [unscaled, unscaled]
    }
}

/// The Gauss–Legendre order on each panel (12 on the table's narrow panels).
const ORDER: usize = 20;
const CONTACT_ORDER: usize = 12;

/// The widest approach panel in Δ: order 20 integrates the weight over it to
/// rounding (its Taylor remainder over 4 units is below 1e-30).
const APPROACH_PANEL: f64 = 4.0;

/// The longest approach panel in τ, as a ratio of its ends: δ̂ ∝ −τ⁻² bends
/// over a panel from τ to 1.5τ no more than order 20 resolves (a 4-unit panel
/// next to the switch spans τ = 0.24 … 1 at ℓ = 30 and misses by 2e-9).
const TAU_GROWTH: f64 = 1.5;

/// The widest contact panel in Δ: as wide as the approach part's (the
/// tail's branch point C beyond δ̂_max has panels of its own, doubling from
/// it); 2 gave the same P̄ to 1e-13 and cost 15 % more.
const CONTACT_PANEL: f64 = 4.0;

pub use crate::model::asperity_law::Shares;

/// One node's share of the law: its curve, its weight and its Δc.
#[derive(Debug, Clone, Copy)]
struct Node {
    /// The curve's place in the table.
    index: usize,
    curve: &'static Curve,
    weight: f64,
    /// The weight of its single-summit pull-off (cubic in ln μ).
    pull_off_weight: f64,
    critical: f64,
}

/// The Lennard-Jones law of one scene: ℓ, μ and the nodes that serve μ (a
/// `Copy` value, as the evaluator's model is).
#[derive(Debug, Clone, Copy)]
pub struct RoughLaw {
    /// ℓ = σ/ε.
    pub ell: f64,
    /// μ.
    pub tabor: f64,
    /// z0 = Z0/σ, the attraction's range (ẑ0/ℓ).
    range: f64,
    nodes: [Node; 8],
    count: usize,
}

/// μ of a scene with load coefficient c_0 > 0 and attraction range z0 = Z0/σ
/// (equal to its Tabor parameter φ0).
pub fn tabor(c_0: f64, z0: f64) -> f64 {
    let ell = (2.0 / c_0).powf(2.0 / 3.0);
    super::spacing(1.0) / (ell * z0)
}

/// How far below the law's the stand-in's rough-surface numbers lie at the
/// table's lower end (μ = 9.91e-5): (real area, pull-off), the worst relative
/// falls over the grid of `tests/all/lennard_jones_law.rs`
/// (`stand_in_jump_campaign`: Z0/σ from 0.07 to 1.7), at σ = 0.3 nm, Z0 = 0.5 nm,
/// R = 5 µm and a light load. DMT with van der Waals attraction is one
/// summit's small-μ limit (its pull-off, [`stand_in_pull_off_error`]) but not
/// the rough surface's at any μ: its contact begins at the apex gap Z0, where
/// the sphere's squeezed gap takes up about Z0 of interference (the crossover
/// from the rigid sphere to Hertz's narrows only as μ^{3/19}; docs/model.md
/// §11).
pub const STAND_IN_ROUGH_JUMP: (f64, f64) = (0.9589, 0.5282);

/// The relative error of the closed-form law's pull-off where it takes over
/// from the law's curves: below the table one summit's (Bradley's 2 against
/// the first curve's); above the limit curves the rough surface's (JKR's law
/// against the last limit curve, whose single summit's is JKR's own:
/// [`LIMIT_END_ERROR`](super::table::LIMIT_END_ERROR)).
pub fn stand_in_pull_off_error(above: bool) -> f64 {
    if above {
        return super::table::LIMIT_END_ERROR;
    }
    let end = super::table::pull_off_of(0).1;
    ((-2.0 - end) / end).abs()
}

/// The Tabor parameter where the sphere's loading curve turns S-shaped (the
/// converged solution's: δ̂ against the apex gap G, each point extrapolated
/// on three meshes, has a least slope −dδ̂/dG of +2.07e-4 at μ = 0.697 and
/// −7.5e-4 at 0.698, falling linearly with μ (+1.17e-3 at 0.696); the
/// trace's own mesh puts the cusp within 3e-4 of it; docs/model.md §11 *The
/// rough surface*). The table's last single-valued curve is at 0.692, its
/// first S-shaped one at 0.7275: the test
/// `the_cusp_lies_between_the_tables_kinds_of_curve` asserts that the curves
/// 1e-3 below and 2e-3 above are single-valued and S-shaped, and
/// `cusp_between_kinds_campaign` that the least slope changes sign within
/// ±5e-4. The value it replaced: docs/history.md.
pub const CUSP_TABOR: f64 = 0.6972;

/// The Lagrange weights of the four nodes around μ, cubic in 1/μ (∝ ẑ0, the
/// attraction's range in the sphere's units; six, quintic, above
/// [`SPARSE_ABOVE`] and below μ = 0.01), all on μ's side of the cusp
/// ([`CUSP_TABOR`]; just above it the cusp and three, the cusp's value the
/// four single-valued curves' there), or one at a node;
/// None outside the table. Each node comes with a second weight, cubic in
/// ln μ, for the single summit's pull-off. In 1/μ the integrals: the shares
/// vary with μ at fixed ℓ much like powers of the range (the far attraction
/// as ẑ0²; measured against ln μ, μ^{-1/2} and μ^{-3/2}: docs/history.md).
/// In ln μ the pull-off, a step from DMT's 2 to JKR's 1.5 over a few decades
/// of μ (measured against 1/μ: docs/history.md); above [`SPARSE_ABOVE`] in
/// μ^{-2/3}. What the interpolation errs by:
/// [`INTERPOLATION_ERROR`](super::table::INTERPOLATION_ERROR) and its
/// neighbours; docs/model.md §11 *The rough surface*.
fn stencil(tabor: f64, skip: Option<usize>) -> Option<Vec<(usize, f64, f64)>> {
    let c = curves();
    let (lo, hi) = super::table::tabor_range();
    if !(tabor >= lo * (1.0 - 1e-12) && tabor <= hi * (1.0 + 1e-12)) {
        return None;
    }
    let kept: Vec<usize> = (0..c.len()).filter(|&k| Some(k) != skip).collect();
    if let Some(&k) = kept
        .iter()
        .find(|&&k| (c[k].tabor / tabor - 1.0).abs() < 1e-12)
    {
        return Some(vec![(k, 1.0, 1.0)]);
    }
    let above = kept
        .iter()
        .position(|&k| c[k].tabor >= tabor)
        .unwrap_or(kept.len() - 1);
    // Six curves where the solved grid is sparse, four elsewhere; and six
    // below μ = 0.01, where ẑ0 and with it ℓ = ẑ0/z0 are large and four
    // followed the integrals less well (at the midpoints μ = 1.6e-4 and 6.7e-4:
    // 9.2e-5 at z0 = 3, 2.8e-6 at 1, 3.7e-8 at 0.3; six: 1.7e-6, 7.9e-9,
    // 2.7e-10). The switch lies at the curve of μ = 0.01, which both stencils
    // pass through: P̄ is continuous there.
    let below = tabor < super::table::HUNDREDTH;
    let sparse = (tabor > SPARSE_ABOVE && tabor <= super::table::solved_range().1) || below;
    let width = if sparse { 6 } else { 4 };
    let first = above.saturating_sub(width / 2).min(kept.len() - width);
    // The solver's curves and the limit curves above them are kept apart, as
    // the cusp's sides are: up to the solved table's end a stencil of solved
    // curves; above it, the last solved curve and the limit curves (a
    // stencil reaching down into the solved curves carried the limit
    // curves' 1 % into them: 2.0e-4 at μ = 19.7 against 3.7e-5, on half
    // the grid above μ = 5).
    let solved = kept.iter().filter(|&&k| !c[k].limit).count();
    let first = if tabor <= super::table::solved_range().1 {
        first.min(solved.saturating_sub(width))
    } else {
        first.max(solved.saturating_sub(1))
    };
    // The weights of Lagrange interpolation at `at` in `variable` over the
    // curves at `xs`.
    let lagrange = |at: f64, xs: &[f64], variable: fn(f64) -> f64| -> Vec<f64> {
        let x = variable(at);
        let xs: Vec<f64> = xs.iter().map(|&m| variable(m)).collect();
        (0..xs.len())
            .map(|i| {
                (0..xs.len())
                    .filter(|&j| j != i)
                    .map(|j| (x - xs[j]) / (xs[i] - xs[j]))
                    .product::<f64>()
            })
            .collect()
    };
    // The pull-off in ln μ up to 5, in μ^{-2/3} above, where it nears JKR's
    // 1.5 about as a power of μ.
    let pull_off_variable: fn(f64) -> f64 = if tabor <= SPARSE_ABOVE {
        f64::ln
    } else {
        |m| m.powf(-2.0 / 3.0)
    };
    // The weights at `at` of the `width` curves from `first` on.
    let weights = |first: usize, at: f64| -> Vec<(usize, f64, f64)> {
        let ks = &kept[first..first + width];
        let xs: Vec<f64> = ks.iter().map(|&k| c[k].tabor).collect();
        let (integrals, pull_off) = (
            lagrange(at, &xs, f64::recip),
            lagrange(at, &xs, pull_off_variable),
        );
        (0..width)
            .map(|i| (ks[i], integrals[i], pull_off[i]))
            .collect()
    };
    // A stencil that reaches across the cusp is moved to μ's side of it (the
    // integrals are not smooth in μ there): the nearest four on that side.
    let side = tabor >= CUSP_TABOR;
    let one_sided = |f: usize, side: bool| (f..f + width).all(|i| c[kept[i]].jumps == side);
    let nearest = |side: bool| {
        (0..=kept.len() - width)
            .filter(|&f| one_sided(f, side))
            .min_by_key(|&f| f.abs_diff(first))
    };
    let first = if one_sided(first, side) {
        first
    } else {
        match nearest(side) {
            Some(f) => f,
            None => return Some(weights(first, tabor)),
        }
    };
    // Between the cusp and the second S-shaped curve the cusp itself is the
    // stencil's first node, its value the single-valued side's there (four
    // curves): there the S-shape's loop closes, and the loading path's
    // integrals continue those of the single-valued curves, which are smooth
    // in μ through the cusp (in the apex gap the path is regular), plus the
    // loop's share, which grows from zero as (μ − μ_c)² (the jump in load as
    // (μ − μ_c)^{1/2}, the loop's width in δ̂ as (μ − μ_c)^{3/2}). P̄ is so
    // continuous in μ across the cusp, and extrapolating the S-shaped
    // curves' integrals down to it from 0.7275 erred by 1.5e-5 at μ = 0.71.
    // (The S-shaped curves are the table's last ones below the limit curves,
    // all from the first: `first` is the first when the curve before it is
    // single-valued.)
    let at_first_s_shaped = side && first > 0 && !c[kept[first - 1]].jumps;
    if at_first_s_shaped && tabor < c[kept[first + 1]].tabor {
        if let Some(below) = nearest(false) {
            let ks = &kept[first..first + width - 1];
            let xs: Vec<f64> = std::iter::once(CUSP_TABOR)
                .chain(ks.iter().map(|&k| c[k].tabor))
                .collect();
            let (integrals, pull_off) = (
                lagrange(tabor, &xs, f64::recip),
                lagrange(tabor, &xs, pull_off_variable),
            );
            let at_cusp = weights(below, CUSP_TABOR)
                .into_iter()
                .map(|(k, w, wp)| (k, integrals[0] * w, pull_off[0] * wp));
            let above = (0..width - 1).map(|i| (ks[i], integrals[i + 1], pull_off[i + 1]));
            return Some(at_cusp.chain(above).collect());
        }
    }
    Some(weights(first, tabor))
}

/// The Tabor parameter above which the table's grid is sparser (18.4
/// curves a decade, against 49 below) and six curves serve a stencil up to the
/// solved table's end (four elsewhere): there one summit's pull-off is
/// interpolated in μ^{-2/3} (on half the grid, the curves', left out in turn,
/// within 1.4e-6 in μ^{-2/3}, 1.2e-5 in ln μ and 5.2e-6 in 1/μ; at μ = 10
/// within 1.4e-7 of the independent solution's, 1.1e-6 in ln μ; now at the
/// curves written between, μ = 5.32, 9.93 and 21.0, within 3.3e-8, 1.1e-10
/// and 1.1e-10).
pub const SPARSE_ABOVE: f64 = 5.0;

impl RoughLaw {
    /// The law for the load coefficients c_0 > 0 (adhesion), c_h (∞: no
    /// plasticity) and the attraction range z0 = Z0/σ; None where μ lies
    /// outside the table (its closed-form limits stand in there).
    pub fn new(c_0: f64, c_h: f64, z0: f64) -> Option<RoughLaw> {
        Self::interpolated(c_0, c_h, z0, None)
    }

    /// As [`RoughLaw::new`], interpolating without the table's curve `skip`
    /// (to measure the interpolation in μ where the answer is known).
    #[doc(hidden)]
    pub fn interpolated(c_0: f64, c_h: f64, z0: f64, skip: Option<usize>) -> Option<RoughLaw> {
        let ell = (2.0 / c_0).powf(2.0 / 3.0);
        let tabor = tabor(c_0, z0);
        let stencil = stencil(tabor, skip)?;
        let node = |&(k, weight, pull_off_weight): &(usize, f64, f64)| {
            let curve = &curves()[k];
            Node {
                index: k,
                curve,
                weight,
                pull_off_weight,
                critical: critical_interference(curve, c_h * ell.sqrt()) / ell,
            }
        };
        let first = node(&stencil[0]);
        let mut nodes = [first; 8];
        for (slot, s) in nodes.iter_mut().zip(&stencil) {
            *slot = node(s);
        }
        Some(RoughLaw {
            ell,
            tabor,
            range: z0,
            nodes,
            count: stencil.len(),
        })
    }

    /// The curves in use.
    fn nodes(&self) -> &[Node] {
        &self.nodes[..self.count]
    }

    /// Δc of each node, with its weight.
    pub fn critical_interferences(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.nodes().iter().map(|n| (n.critical, n.weight))
    }

    /// The pull-off of one summit, P̂ (Maugis units, < 0): each curve's,
    /// interpolated cubically in ln μ.
    pub fn asperity_pull_off(&self) -> f64 {
        self.nodes()
            .iter()
            .map(|n| n.pull_off_weight * super::table::pull_off_of(n.index).1)
            .sum()
    }

    /// The curves in use, each with its weight and Δc (what an independent
    /// reference integrates: `accuracy::lennard_jones`).
    pub fn curves(&self) -> impl Iterator<Item = (&'static Curve, f64, f64)> + '_ {
        self.nodes().iter().map(|n| (n.curve, n.weight, n.critical))
    }

    /// Each node's Δc, its weight and the load p(Δc) of one summit on its
    /// curve there (§3 units), for the load jump at the transition.
    pub fn transitions(&self) -> impl Iterator<Item = (f64, f64, f64)> + '_ {
        self.nodes().iter().map(|n| {
            let load = if n.critical.is_finite() {
                self.ell.powf(-1.5) * n.curve.load(self.ell * n.critical)
            } else {
                f64::NAN
            };
            (n.critical, n.weight, load)
        })
    }

    /// p(Δ) = ℓ^{-3/2} Σ_k w_k P̂_k(ℓΔ), one summit's load at interference
    /// Δ ≥ 0 (§3's units, > 0 pressing): each curve's contact part at δ̂ = ℓΔ
    /// (every curve's δ̂_s is < 0, so Δ ≥ 0 lies on it), interpolated in μ with
    /// the weights of the integrals (cubic in 1/μ). At Δ ≥ 0 the curves have
    /// no jump to move, so the loads themselves interpolate; what the
    /// stress-assisted wear law reads as a summit's P (docs/model.md §12).
    pub fn summit_load(&self, d: f64) -> f64 {
        self.ell.powf(-1.5) * self.summit_load_maugis(d)
    }

    /// Σ_k w_k P̂_k(ℓΔ), [`RoughLaw::summit_load`] times ℓ^{3/2} (the curves' own
    /// units, for a caller that hoists the power).
    pub fn summit_load_maugis(&self, d: f64) -> f64 {
        let dd = self.ell * d;
        self.nodes()
            .iter()
            .map(|n| {
                let load = if dd >= n.curve.switch {
                    n.curve.contact_load(dd)
                } else {
                    n.curve.load(dd)
                };
                n.weight * load
            })
            .sum()
    }

    /// [`RoughLaw::summit_load_maugis`] at each Δ of `d` (each ≥ 0), into `out`
    /// (as long): the same numbers, the curves' recurrences run four nodes
    /// abreast ([`Curve::add_contact_loads`]).
    pub fn summit_loads_maugis(&self, d: &[f64], out: &mut [f64]) {
        let mut scaled = [0.0; 32];
        for (dc, oc) in d.chunks(32).zip(out.chunks_mut(32)) {
            let scaled = &mut scaled[..dc.len()];
            for (s, &d) in scaled.iter_mut().zip(dc) {
                *s = self.ell * d;
            }
            oc.fill(0.0);
            for n in self.nodes() {
                n.curve.add_contact_loads(scaled, n.weight, oc);
            }
        }
    }

    /// [`RoughLaw::summit_load_maugis`] and its derivative in Δ (§3's units):
    /// Σ_k w_k (P̂_k, ℓ dP̂_k/dδ̂) at δ̂ = ℓΔ ≥ 0, each curve's contact part.
    pub fn summit_load_slope_maugis(&self, d: f64) -> (f64, f64) {
        let dd = self.ell * d;
        if let [a, b, c, e] = self.nodes() {
            if [a, b, c, e].iter().all(|n| dd >= n.curve.switch) {
                // Four curves (μ inside the table): their recurrences abreast.
                let loads = Curve::contacts4([a.curve, b.curve, c.curve, e.curve], [dd; 4]);
                return [a, b, c, e].iter().zip(loads).fold(
                    (0.0, 0.0),
                    |(p, slope), (n, (pk, sk))| {
                        (p + n.weight * pk, slope + n.weight * sk * self.ell)
                    },
                );
            }
        }
        self.nodes().iter().fold((0.0, 0.0), |(p, slope), n| {
            let (pk, sk) = if dd >= n.curve.switch {
                n.curve.contact(dd)
            } else {
                (n.curve.load(dd), 0.0)
            };
            (p + n.weight * pk, slope + n.weight * sk * self.ell)
        })
    }

    /// â(ℓΔ) = Σ_k w_k â_k(ℓΔ), one summit's contact radius in Maugis units
    /// (â = a (K/(πγR²))^{1/3}) at interference Δ ≥ 0 (§3's units), and its
    /// derivative in Δ: each curve's contact part, interpolated in μ with the
    /// weights of [`RoughLaw::summit_load`]; the junction size the debris
    /// regime reads (docs/model.md §13). At least Hertz's √(ℓΔ), and rising.
    pub fn summit_contact_radius_maugis(&self, d: f64) -> (f64, f64) {
        let dd = self.ell * d;
        self.nodes().iter().fold((0.0, 0.0), |(a, slope), n| {
            let ((ak, sk), _) = n.curve.contact_area_slope(dd.max(n.curve.switch));
            (a + n.weight * ak, slope + n.weight * sk * self.ell)
        })
    }

    /// The interference Δ ≥ 0 (§3's units) at which one summit's contact
    /// radius [`RoughLaw::summit_contact_radius_maugis`] reaches `radius`
    /// (Maugis units, ≥ 0): 0 where it is wider already at Δ = 0; by Newton's
    /// method kept inside a bracket (bisection where a step leaves it) from
    /// Hertz's ℓΔ = â², above the root (the law's radius is at least
    /// Hertz's), to a step of 1e-13 relative. It runs in every evaluation of
    /// a scene with a shear strength, so Newton, not bisection.
    pub fn interference_at_contact_radius(&self, radius: f64) -> f64 {
        let f = |d: f64| {
            let (a, slope) = self.summit_contact_radius_maugis(d);
            (a - radius, slope)
        };
        if radius.is_nan() || radius <= 0.0 || f(0.0).0 >= 0.0 {
            return 0.0;
        }
        let (mut lo, mut hi) = (0.0, radius * radius / self.ell);
        // Where interpolating in μ leaves the radius a hair below Hertz's.
        while f(hi).0 < 0.0 && hi < 1e300 {
            hi *= 2.0;
        }
        let mut d = hi;
        for _ in 0..200 {
            let (value, slope) = f(d);
            if value == 0.0 {
                break;
            }
            if value < 0.0 {
                lo = d;
            } else {
                hi = d;
            }
            let newton = d - value / slope;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let step = (next - d).abs();
            d = next;
            if step <= 1e-13 * d || hi - lo <= 1e-13 * hi {
                break;
            }
        }
        d
    }

    /// The shares at separation h.
    pub fn at(&self, h: f64) -> Shares {
        let mut out = Shares {
            noncontact_exponent: 0.5 * (-h).max(0.0).powi(2),
            elastic_exponent: 0.5 * h.max(0.0).powi(2),
            ..Shares::default()
        };
        for node in self.nodes() {
            let s = self.node_at(node, h);
            for i in 0..3 {
                out.noncontact[i] += node.weight * s.noncontact[i];
                out.elastic[i] += node.weight * s.elastic[i];
            }
        }
        out
    }

    /// The log-weight relative to a share's scale, and u = h + Δ.
    #[inline]
    fn weight(h: f64, d: f64, contact: bool) -> f64 {
        // Contact shares scale by κ(h), non-contact ones by κ(−h).
        let scaled = if contact { h > 0.0 } else { h < 0.0 };
        log_weight(h, d, scaled).exp()
    }

    fn node_at(&self, node: &Node, h: f64) -> Shares {
        let mut out = Shares::default();
        let [below, above] = windows(h, self.range);
        // The non-contact share ends where the contact one starts (the
        // switch, or Δ = 0 where the switch lies below it): each share visits
        // its own window, cut there (far out, the contact window is a sliver
        // at Δ ≈ 46/h and the non-contact one ends near −h: one visit over
        // both would walk the approach part between them).
        let edge = (node.curve.switch / self.ell).max(0.0);
        for (contact, (lo, hi)) in [
            (false, (below.0, below.1.min(edge))),
            (true, (above.0.max(edge), above.1)),
        ] {
            let share = if contact {
                &mut out.elastic
            } else {
                &mut out.noncontact
            };
            self.visit(node, lo, hi, &mut |d, f, in_contact| {
                if in_contact == contact {
                    add_moments(share, f * Self::weight(h, d, contact), h + d);
                }
            });
        }
        out
    }

    /// Visits the quadrature nodes of one curve's summits with lo ≤ Δ ≤ hi
    /// and Δ ≤ Δc ([`visit_curve`] at the scene's ℓ).
    fn visit(&self, node: &Node, lo: f64, hi: f64, visit: &mut dyn FnMut(f64, f64, bool)) {
        visit_curve(node.curve, self.ell, node.critical, lo, hi, visit);
    }
}

/// Visits the quadrature nodes of one curve's summits with lo ≤ Δ ≤ hi and
/// Δ ≤ `critical`, in Δ = δ̂/ℓ (whole panels from anchors that do not depend
/// on the window's ends but its lower one): `visit(Δ, f, contact)`, f the
/// load ℓ^{-3/2} P̂ times the node's weight in Δ (the Gaussian weight left
/// out), `contact` for the contact part at Δ ≥ 0. Ascending in Δ.
fn visit_curve(
    c: &Curve,
    ell: f64,
    critical: f64,
    lo: f64,
    hi: f64,
    visit: &mut dyn FnMut(f64, f64, bool),
) {
    let scale = ell.powf(-1.5);
    let switch = c.switch / ell;
    let rule = gauss::rule(ORDER);
    // The approach part, in τ.
    let top = hi.min(switch);
    if lo < top {
        let mut d0 = lo;
        let mut t0 = c.tau_at(ell * d0);
        while d0 < top {
            // At most APPROACH_PANEL wide in Δ and TAU_GROWTH long in τ
            // (where δ̂ ∝ −τ⁻² bends, near the switch at large ℓ).
            let (mut d1, mut t1) = ((d0 + APPROACH_PANEL).min(top), f64::NAN);
            let t_max = TAU_GROWTH * t0;
            if t_max < c.tau_end() {
                let d_max = c.approach_load(t_max).0 / ell;
                if d_max < d1 {
                    (d1, t1) = (d_max, t_max);
                }
            }
            if t1.is_nan() {
                t1 = if d1 == switch {
                    c.tau_end()
                } else {
                    c.tau_at(ell * d1)
                };
            }
            let (mid, half) = (0.5 * (t0 + t1), 0.5 * (t1 - t0));
            let mut taus = [0.0; ORDER];
            for (t, x) in taus.iter_mut().zip(&rule.nodes) {
                *t = mid + half * x;
            }
            let loads = c.approach_loads(&taus);
            for (&(interference, slope, load), w) in loads.iter().zip(&rule.weights) {
                visit(
                    interference / ell,
                    scale * load * slope / ell * w * half,
                    false,
                );
            }
            d0 = d1;
            t0 = t1;
        }
    }
    // The contact part from the switch to Δc.
    for (a, b) in contact_pieces(c, ell, lo.max(switch), hi.min(critical)) {
        visit_piece(c, ell, a, b, &mut |d, f| visit(d, f, a >= 0.0));
    }
}

/// The panels of one curve's contact part over start ≤ Δ ≤ end (Δ = δ̂/ℓ):
/// they keep the table's own panel ends and Δ = 0, none wider than
/// CONTACT_PANEL, and beyond δ̂_max double in their distance from the tail's
/// branch point C. Ascending.
fn contact_pieces(c: &Curve, ell: f64, start: f64, end: f64) -> Vec<(f64, f64)> {
    let mut pieces = Vec::new();
    if start >= end {
        return pieces;
    }
    // Beyond δ̂_max the tail's branch point C lies just behind: panels
    // there double in their distance from it.
    let branch = c.tail_branch() / ell;
    let mut tail = Vec::new();
    let mut cut = c.max_interference() / ell;
    while cut < end && cut > branch {
        cut = branch + 2.0 * (cut - branch);
        tail.push(cut);
    }
    let mut cuts: Vec<f64> = c
        .breaks()
        .iter()
        .map(|b| b / ell)
        .chain(tail)
        .chain([0.0, start, end])
        .filter(|&d| d >= start && d <= end)
        .collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    for pair in cuts.windows(2) {
        let width = pair[1] - pair[0];
        let count = (width / CONTACT_PANEL).ceil().max(1.0) as usize;
        for k in 0..count {
            let a = pair[0] + width * k as f64 / count as f64;
            let b = pair[0] + width * (k + 1) as f64 / count as f64;
            pieces.push((a, b));
        }
    }
    pieces
}

/// The CONTACT_ORDER Gauss–Legendre nodes of one contact panel a ≤ Δ ≤ b:
/// `visit(Δ, f)`, f as [`visit_curve`]'s.
fn visit_piece(c: &Curve, ell: f64, a: f64, b: f64, visit: &mut dyn FnMut(f64, f64)) {
    let scale = ell.powf(-1.5);
    let rule = gauss::rule(CONTACT_ORDER);
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    for (x, w) in rule.nodes.iter().zip(&rule.weights) {
        let d = mid + half * x;
        visit(d, scale * c.contact_load(ell * d) * w * half);
    }
}

/// The log of φ̄(h + Δ) = e^{−(h+Δ)²/2} relative to a share's scale: e^{κ}
/// with κ = h²/2 where `scaled` (the exponent is then −Δ(h + Δ/2), exact for
/// large |h|), else 1.
#[inline(always)]
fn log_weight(h: f64, d: f64, scaled: bool) -> f64 {
    if scaled {
        -d * (h + 0.5 * d)
    } else {
        -0.5 * (h + d) * (h + d)
    }
}

/// Adds one node's g = f φ̄ to a share's [P̄, P̄', P̄''] at u = h + Δ
/// (φ̄' = −u φ̄, φ̄'' = (u² − 1) φ̄).
#[inline]
fn add_moments(share: &mut [f64; 3], g: f64, u: f64) {
    share[0] += g;
    share[1] -= g * u;
    share[2] += g * (u * u - 1.0);
}

/// The separations the per-scene [`Grid`] serves, h ∈ [lo, hi]; outside, the
/// shares are integrated at h itself (docs/model.md §11 *Accuracy and speed
/// in the evaluator*). Every evaluation of `eval` on the shipped
/// Lennard-Jones scenes lies in 1.06…3.9, of `optimize` on the hub's study in
/// 0.47…11.0. Not wider: above 16 the approach part's panels would start
/// further out and land elsewhere near the switch, below −6 the grid's sums
/// of the few non-contact nodes left in the window could differ from the
/// windowed quadrature's in sign (both measured: docs/history.md). Inside,
/// the test `the_stretched_grid_matches_an_adaptive_quadrature` holds the
/// grid to an adaptive quadrature within 1e-12 of the larger share's size.
pub const GRID_SEPARATIONS: (f64, f64) = (-6.0, 16.0);

/// One scene's quadrature nodes over every summit the separations of
/// [`GRID_SEPARATIONS`] weigh, with their loads: then the shares at any such h
/// are sums of a Gaussian over them, with no table to evaluate.
///
/// The nodes do not depend on the scene but through ℓ, and through it only
/// as a scale: each curve's nodes are laid out once per process in
/// δ̂ = ℓΔ for the scale s = 2^{k/4} just below ℓ (a layout: [`RoughLaw::at`]'s
/// panels at ℓ = s, over a range wide enough for any ℓ up to 2^{1/4} s), so that
/// in the scene's Δ every panel is as narrow as `at`'s rules ask and the range
/// covers the grid's. A scene's grid is then each curve's layout, the stretch
/// s/ℓ, and the panel its Δc cuts (whose nodes it lays out itself).
#[derive(Debug, Clone)]
pub struct Grid {
    /// The law the nodes are laid out for (and that integrates at h itself
    /// where the grid does not reach).
    law: RoughLaw,
    /// Each curve in the law's order (empty where ℓ lies beyond the layouts'
    /// scales: the law integrates at h itself).
    curves: Vec<GridCurve>,
    /// The level's shared approach nodes' Δ' ([`Shared`]; empty without
    /// curves), the curves' loads there summed, each times its curve's
    /// factor, and the stretch.
    shared: &'static [f64],
    shared_loads: Vec<f64>,
    stretch: f64,
    /// Clusters of every curve in use within MERGE_GAP of each other, merged
    /// (their moments about the first curve's centre, each times its
    /// factor), per share (non-contact, contact): one series instead of one
    /// per curve.
    merged: [Vec<Cluster>; 2],
}

/// How far apart (Δ') clusters of the curves in use may lie to be merged:
/// the merged cluster then spans at most CLUSTER_WIDTH/2 + MERGE_GAP either
/// side of its centre, and its series' first term left out is (9.6 · 0.145)^20
/// / 20! ≈ 3e-16 of its sum at the window's edge (|u| ≤ 9.6).
const MERGE_GAP: f64 = 0.02;

/// One curve of a scene's [`Grid`].
#[derive(Debug, Clone)]
struct GridCurve {
    layout: &'static Layout,
    /// s/ℓ: the scene's Δ is `stretch` times the layout's.
    stretch: f64,
    /// The curve's weight times stretch^{5/2} (the layout's loads are
    /// s^{-5/2} P̂ dδ̂, the scene's ℓ^{-5/2} P̂ dδ̂).
    factor: f64,
    /// The layout's contact nodes kept (the panels wholly below Δc).
    kept: usize,
    /// The nodes of the panel Δc cuts, from its lower end to Δc (layout units).
    cut: Nodes,
    /// The clusters (bits by index, non-contact and contact share) summed
    /// in the grid's merged ones instead.
    skip: [u64; 2],
}

/// One curve's quadrature nodes for the scale s ([`Grid`]), in Δ' = δ̂/s.
#[derive(Debug)]
struct Layout {
    /// The approach part from the level's shared nodes' end ([`Shared`]) and
    /// the contact part below Δ' = 0.
    noncontact: Share,
    /// The load (as [`Nodes`]' loads) at each of the level's shared nodes.
    shared: Vec<f64>,
    /// The contact part at Δ' ≥ 0, CONTACT_ORDER nodes per panel.
    contact: Share,
    /// The contact panels at Δ' ≥ 0, in order.
    pieces: Vec<(f64, f64)>,
    /// The load of every summit below the layout's first node, ∫ f dΔ' over
    /// Δ' < lo (nodes' units): what the work of separation weighs by the
    /// whole Gaussian tail √(2π) ([`Grid::solid_work`]).
    far: f64,
}

/// The widest cluster, in Δ' (so at most as wide in the scene's Δ).
const CLUSTER_WIDTH: f64 = 0.25;

/// The fewest nodes worth a cluster (one exponential and a Hermite series of
/// CLUSTER_TERMS + 2 terms against one exponential per node).
const CLUSTER_NODES: usize = 16;

/// The terms of a cluster's series. The series is that of e^{−uy − y²/2} in
/// y, |y| ≤ w/2 = CLUSTER_WIDTH/2, at |u| ≤ 9.6 (the window): its terms fall
/// as (|u| y)^k / k!, and the first left out, (1.2)^20 / 20! ≈ 2e-17, is below
/// rounding of the cluster's own sum (13 terms left 3e-12 at u = 7.5).
const CLUSTER_TERMS: usize = 20;

/// One share's nodes (ascending in Δ'), those in dense runs summed as clusters.
#[derive(Debug, Default)]
struct Share {
    /// Every node.
    all: Nodes,
    /// The nodes in no cluster, in order, with their places in `all`.
    loose: Nodes,
    loose_index: Vec<usize>,
    /// The clusters, in order.
    clusters: Vec<Cluster>,
}

/// Nodes j = first … end − 1 of a share within CLUSTER_WIDTH of each other,
/// summed as one: with x_j = Δ'_j − c and y = (s/ℓ) x_j, Σ f_j φ̄(u_c + y_j) =
/// φ̄(u_c) Σ_k (−1)^k He_k(u_c) (s/ℓ)^k m_k, m_k = Σ_j f_j x_j^k / k! (the
/// Taylor series of φ̄, whose k-th derivative is (−1)^k He_k φ̄), and the
/// derivatives in h the same with He_{k+1}, He_{k+2}. A regrouping of the same
/// quadrature sum, exact but for the series' tail.
#[derive(Debug, Clone)]
struct Cluster {
    first: usize,
    end: usize,
    center: f64,
    moments: [f64; CLUSTER_TERMS],
}

impl Share {
    /// Groups the nodes greedily into runs no wider than CLUSTER_WIDTH; a run
    /// of CLUSTER_NODES or more becomes a cluster.
    fn new(all: Nodes) -> Share {
        let d = &all.interference;
        let (mut loose, mut loose_index, mut clusters) = (Nodes::default(), Vec::new(), Vec::new());
        let mut first = 0;
        while first < d.len() {
            let end = first + d[first..].partition_point(|&x| x - d[first] <= CLUSTER_WIDTH);
            if end - first >= CLUSTER_NODES {
                let center = 0.5 * (d[first] + d[end - 1]);
                let mut moments = [0.0; CLUSTER_TERMS];
                for (&dj, &f) in d[first..end].iter().zip(&all.load[first..end]) {
                    let x = dj - center;
                    let mut term = f;
                    for (k, m) in moments.iter_mut().enumerate() {
                        *m += term;
                        term *= x / (k + 1) as f64;
                    }
                }
                clusters.push(Cluster {
                    first,
                    end,
                    center,
                    moments,
                });
            } else {
                loose.interference.extend_from_slice(&d[first..end]);
                loose.load.extend_from_slice(&all.load[first..end]);
                loose_index.extend(first..end);
            }
            first = end;
        }
        Share {
            all,
            loose,
            loose_index,
            clusters,
        }
    }

    /// [P̄, P̄', P̄''] of the share's first `count` nodes with lo ≤ Δ' ≤ hi (a
    /// cluster by its centre) at h, as [`Nodes::sums`]; a cluster that `count`
    /// cuts is summed node by node.
    /// The clusters whose bit is set in `skip` are left out (a scene's grid
    /// sums them merged with the other curves': [`Grid`]).
    #[allow(clippy::too_many_arguments)]
    fn sums(
        &self,
        count: usize,
        lo: f64,
        hi: f64,
        h: f64,
        stretch: f64,
        scaled: bool,
        skip: u64,
    ) -> [f64; 3] {
        let loose = self.loose_index.partition_point(|&j| j < count);
        let mut sums = self.loose.sums(0, loose, lo, hi, h, stretch, scaled);
        for (i, cluster) in self.clusters.iter().enumerate() {
            if cluster.first >= count
                || cluster.center < lo
                || cluster.center > hi
                || (i < 64 && skip >> i & 1 == 1)
            {
                continue;
            }
            let part = if cluster.end <= count {
                cluster.sums(h, stretch, scaled)
            } else {
                self.all
                    .sums(cluster.first, count, lo, hi, h, stretch, scaled)
            };
            for (sum, p) in sums.iter_mut().zip(part) {
                *sum += p;
            }
        }
        sums
    }
}

impl Share {
    /// Σ f T_0(h0 + Δ) over the share's first `count` nodes, T_0(u) = ∫_u^∞
    /// e^{−x²/2} dx (√(2π) below the window lo … hi, 0 above it), the clusters
    /// by their series ([`Cluster::tail_sum`]), one that `count` cuts node by node.
    #[allow(clippy::too_many_arguments)]
    fn tail_sum(&self, count: usize, lo: f64, hi: f64, h0: f64, stretch: f64, skip: u64) -> f64 {
        let loose = self.loose_index.partition_point(|&j| j < count);
        let (d, f) = (&self.loose.interference[..loose], &self.loose.load[..loose]);
        let mut sum = tail_window(d, f, lo, hi, h0, stretch);
        for (i, cluster) in self
            .clusters
            .iter()
            .enumerate()
            .take_while(|(_, c)| c.first < count)
        {
            if i < 64 && skip >> i & 1 == 1 {
                continue;
            }
            sum += if cluster.end > count {
                let (d, f) = (&self.all.interference, &self.all.load);
                tail_window(
                    &d[cluster.first..count],
                    &f[cluster.first..count],
                    lo,
                    hi,
                    h0,
                    stretch,
                )
            } else {
                cluster.tail_in(lo, hi, h0, stretch)
            };
        }
        sum
    }
}

/// Σ f T_0(h0 + s d) over nodes (d, f) ascending, s = `stretch`: √(2π) Σ f
/// below lo, T_0 itself up to hi, nothing above (T_0 < e^{−46} there).
fn tail_window(d: &[f64], f: &[f64], lo: f64, hi: f64, h0: f64, stretch: f64) -> f64 {
    let first = d.partition_point(|&x| x < lo);
    let end = d.partition_point(|&x| x <= hi).max(first);
    let below: f64 = f[..first].iter().sum();
    let mut sum = SQRT_TWO_PI * below;
    for (&x, &f) in d[first..end].iter().zip(&f[first..end]) {
        sum += f * gaussian_tail_fast(h0 + stretch * x);
    }
    sum
}

impl Cluster {
    /// [`Cluster::tail_sum`] as a window lo … hi (Δ', by the centre) takes it:
    /// √(2π) m_0 below it, nothing above.
    fn tail_in(&self, lo: f64, hi: f64, h0: f64, stretch: f64) -> f64 {
        if self.center < lo {
            SQRT_TWO_PI * self.moments[0]
        } else if self.center <= hi {
            self.tail_sum(h0, stretch)
        } else {
            0.0
        }
    }

    /// The moments about `center` instead, times `factor`: m'_k = Σ_{i≤k}
    /// m_i δ^{k−i}/(k−i)!, δ = the old centre − the new (exact: each depends
    /// on the lower moments only).
    fn moments_about(&self, center: f64, factor: f64) -> [f64; CLUSTER_TERMS] {
        let delta = self.center - center;
        // δ^j/j! by one chain of products; the powers behind K zeros, so that m_i's terms are one
        // slice of fixed length: out[k] += m_i p[K + k − i] (zero for k < i).
        const K: usize = CLUSTER_TERMS;
        const RECIPROCALS: [f64; K] = {
            let mut r = [1.0; K];
            let mut j = 2;
            while j < K {
                r[j] = 1.0 / j as f64;
                j += 1;
            }
            r
        };
        let mut padded = [0.0; 2 * K];
        padded[K] = 1.0;
        for j in 1..K {
            padded[K + j] = padded[K + j - 1] * (delta * RECIPROCALS[j]);
        }
        let mut out = [0.0; K];
        for (i, &m) in self.moments.iter().enumerate() {
            for (slot, &p) in out.iter_mut().zip(&padded[K - i..2 * K - i]) {
                *slot += m * p;
            }
        }
        out.map(|x| factor * x)
    }

    /// Σ f_j T_0(u_c + y_j) over the cluster's nodes (y = `stretch` x), by
    /// T_0(u + y) = T_0(u) − ∫_0^y φ̄(u + t) dt = T_0(u) − φ̄(u) Σ_k (−1)^k
    /// He_k(u) y^{k+1}/(k + 1)!: T_0(u_c) m_0 − φ̄(u_c) Σ_k (−1)^k He_k(u_c)
    /// stretch^{k+1} m_{k+1} (unscaled).
    fn tail_sum(&self, h0: f64, stretch: f64) -> f64 {
        let u = h0 + stretch * self.center;
        let (mut he0, mut he1) = (1.0, u);
        let mut scale = stretch;
        let mut series = 0.0;
        for (k, &m) in self.moments[1..].iter().enumerate() {
            series += scale * m * he0;
            let he2 = u * he1 - (k + 1) as f64 * he0;
            (he0, he1) = (he1, he2);
            scale *= -stretch;
        }
        gaussian_tail_fast(u) * self.moments[0] - (-0.5 * u * u).exp() * series
    }

    /// [P̄, P̄', P̄''] of the cluster's nodes at h (Δ = `stretch` Δ'), relative
    /// to the share's scale as [`window_sums`].
    fn sums(&self, h: f64, stretch: f64, scaled: bool) -> [f64; 3] {
        let c = stretch * self.center;
        let u = h + c;
        let weight = log_weight(h, c, scaled).exp();
        // He_0 … He_{K+1} by He_{k+1} = u He_k − k He_{k−1}, each term's
        // (−stretch)^k m_k against He_k, He_{k+1}, He_{k+2}.
        let (mut he0, mut he1) = (1.0, u);
        let mut scale = 1.0;
        let mut sums = [0.0; 3];
        for (k, &m) in self.moments.iter().enumerate() {
            let he2 = u * he1 - (k + 1) as f64 * he0;
            let a = scale * m;
            sums[0] += a * he0;
            sums[1] -= a * he1;
            sums[2] += a * he2;
            (he0, he1) = (he1, he2);
            scale *= -stretch;
        }
        sums.map(|x| weight * x)
    }
}

/// The layouts' scales s = 2^{k/4}, k = LEVELS.0 … LEVELS.1: ℓ from 2.4e-4 to
/// 2.7e8 (ℓ = (θ/π)^{2/3}: θ from 1e-5 to 1.4e13).
const LEVELS: (i32, i32) = (-48, 112);

/// The layout of `curves()[index]` at level k (built once, on first use).
fn layout(index: usize, level: i32) -> &'static Layout {
    static CACHE: OnceLock<Vec<OnceLock<Box<Layout>>>> = OnceLock::new();
    let count = (LEVELS.1 - LEVELS.0 + 1) as usize;
    let cache = CACHE.get_or_init(|| {
        (0..curves().len() * count)
            .map(|_| OnceLock::new())
            .collect()
    });
    cache[index * count + (level - LEVELS.0) as usize]
        .get_or_init(|| Box::new(Layout::new(&curves()[index], level)))
}

/// Lays out the nodes of `curves()[index]` for the scale just below ℓ afresh,
/// without the cache, and counts them (what a scene's first use of that
/// curve and scale costs, once per process: `cargo bench -p wearopt-benches --bench evaluator`).
#[doc(hidden)]
pub fn lay_out_uncached(index: usize, ell: f64) -> usize {
    level_of(ell).map_or(0, |level| {
        let layout = Layout::new(&curves()[index], level);
        layout.noncontact.all.len() + layout.shared.len() + layout.contact.all.len()
    })
}

/// s = 2^{k/4}.
fn level_scale(level: i32) -> f64 {
    (0.25 * level as f64).exp2()
}

/// The level whose scale is the largest at or below ℓ; None beyond LEVELS.
fn level_of(ell: f64) -> Option<i32> {
    let mut level = (4.0 * ell.log2()).floor();
    if !(level >= LEVELS.0 as f64 && level <= LEVELS.1 as f64) {
        return None;
    }
    if level_scale(level as i32) > ell {
        level -= 1.0;
    }
    (level >= LEVELS.0 as f64).then_some(level as i32)
}

/// The approach part's nodes far below every curve's switch, the same for
/// every curve at one scale s: Gauss–Legendre panels of ORDER nodes, as wide
/// as APPROACH_PANEL, from the layouts' lower end up to SHARED_MARGIN (in
/// Δ') below the table's lowest switch. A scene's grid sums its curves' loads there once,
/// weighted, instead of each curve's own nodes (three quarters of the
/// approach part's nodes in a window where four curves are interpolated).
/// So far from the switch (the load's nearest singularity lies at or beyond
/// it) the load is as smooth in Δ as the weight, and a panel 4 wide is
/// integrated to rounding.
#[derive(Debug)]
struct Shared {
    /// The nodes' Δ', and as loads the rule's weights (panel half-widths
    /// included).
    nodes: Nodes,
    /// Where the shared nodes end and each curve's own begin (Δ').
    end: f64,
}

/// The shared nodes' distance below the table's lowest switch, in Δ'.
const SHARED_MARGIN: f64 = 1.0;

impl Shared {
    fn new(s: f64) -> Shared {
        let (lo, _) = layout_range();
        let lowest = curves()
            .iter()
            .map(|c| c.switch)
            .fold(f64::INFINITY, f64::min);
        let end = (lowest / s - SHARED_MARGIN).max(lo);
        // Equal panels from lo to `end`, none wider than APPROACH_PANEL.
        let count = ((end - lo) / APPROACH_PANEL).ceil() as usize;
        let mut nodes = Nodes::default();
        let rule = gauss::rule(ORDER);
        for k in 0..count {
            let a = lo + (end - lo) * k as f64 / count as f64;
            let b = lo + (end - lo) * (k + 1) as f64 / count as f64;
            let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
            for (x, w) in rule.nodes.iter().zip(&rule.weights) {
                nodes.push(mid + half * x, w * half);
            }
        }
        Shared { nodes, end }
    }

    /// The shared nodes at level k, the scale s = 2^{k/4} (built once).
    fn at(level: i32) -> &'static Shared {
        static CACHE: OnceLock<Vec<OnceLock<Shared>>> = OnceLock::new();
        let count = (LEVELS.1 - LEVELS.0 + 1) as usize;
        let cache = CACHE.get_or_init(|| (0..count).map(|_| OnceLock::new()).collect());
        cache[(level - LEVELS.0) as usize].get_or_init(|| Shared::new(level_scale(level)))
    }
}

/// The range in Δ' every layout covers: the summits that separations in
/// [`GRID_SEPARATIONS`] weigh, for any ℓ in [s, 2^{1/4} s) (in the layout's
/// Δ' = Δ ℓ/s the scene's range stretches by up to 2^{1/4}).
fn layout_range() -> (f64, f64) {
    let (h_lo, h_hi) = GRID_SEPARATIONS;
    let wider = 2f64.powf(0.25) * (1.0 + 1e-9);
    ((-h_hi - REACH) * wider, (-h_lo + REACH) * wider)
}

impl Layout {
    /// The nodes at ℓ = s over every summit that separations in
    /// [`GRID_SEPARATIONS`] weigh for any ℓ in [s, 2^{1/4} s).
    fn new(curve: &Curve, level: i32) -> Layout {
        let s = level_scale(level);
        let (lo, hi) = layout_range();
        let shared = Shared::at(level);
        let scale = s.powf(-1.5);
        let shared_loads = (shared.nodes.interference.iter().zip(&shared.nodes.load))
            .map(|(&d, &w)| scale * curve.load(s * d) * w)
            .collect();
        let (mut noncontact, mut contact) = (Nodes::default(), Nodes::default());
        visit_curve(
            curve,
            s,
            f64::INFINITY,
            shared.end,
            hi,
            &mut |d, f, in_contact| {
                let nodes = if in_contact {
                    &mut contact
                } else {
                    &mut noncontact
                };
                nodes.push(d, f);
            },
        );
        let switch = curve.switch / s;
        let pieces: Vec<(f64, f64)> = contact_pieces(curve, s, lo.max(switch), hi)
            .into_iter()
            .filter(|&(a, _)| a >= 0.0)
            .collect();
        debug_assert_eq!(pieces.len() * CONTACT_ORDER, contact.len());
        Layout {
            noncontact: Share::new(noncontact),
            shared: shared_loads,
            contact: Share::new(contact),
            pieces,
            far: far_load(curve, s, lo, FAR_GROWTH),
        }
    }
}

/// The ratio of the far field's panels in τ ([`far_load`]).
const FAR_GROWTH: f64 = 1.5;

/// ∫ f dΔ' over the summits below Δ' = `lo` at the scale s (f as
/// [`visit_curve`]'s: s^{-5/2} P̂ dδ̂): the approach part up to the τ where
/// `visit_curve` starts, Gauss–Legendre in τ on panels whose ends shrink by
/// `growth` towards τ = 0 (the integrand P̂ dδ̂/dτ ~ −(16/3) ẑ0 τ there, smooth:
/// the table's series are analytic on [0, τ_end]), and the contact part from
/// the switch where `lo` lies beyond it.
fn far_load(c: &Curve, s: f64, lo: f64, growth: f64) -> f64 {
    let scale = s.powf(-2.5);
    let rule = gauss::rule(ORDER);
    let switch = c.switch / s;
    let top = if lo < switch {
        c.tau_at(s * lo)
    } else {
        c.tau_end()
    };
    // Panels [τ/growth, τ] from the top down to 1e-3 of it, then [0, that].
    let mut ends = vec![top];
    while *ends.last().unwrap_or(&0.0) > 1e-3 * top {
        let next = ends[ends.len() - 1] / growth;
        ends.push(next);
    }
    ends.push(0.0);
    let mut far = 0.0;
    for pair in ends.windows(2).rev() {
        let (t0, t1) = (pair[1], pair[0]);
        let (mid, half) = (0.5 * (t0 + t1), 0.5 * (t1 - t0));
        let mut taus = [0.0; ORDER];
        for (t, x) in taus.iter_mut().zip(&rule.nodes) {
            *t = mid + half * x;
        }
        for (&(_, slope, load), w) in c.approach_loads(&taus).iter().zip(&rule.weights) {
            far += scale * load * slope * w * half;
        }
    }
    for (a, b) in contact_pieces(c, s, switch, lo) {
        visit_piece(c, s, a, b, &mut |_, f| far += f);
    }
    far
}

/// One curve's quadrature nodes, ascending in Δ (as its panels visit them):
/// their Δ, and the load times the node's weight (two arrays, so that the
/// loop over a window vectorizes).
#[derive(Debug, Clone, Default)]
struct Nodes {
    interference: Vec<f64>,
    load: Vec<f64>,
}

impl Nodes {
    fn push(&mut self, d: f64, f: f64) {
        self.interference.push(d);
        self.load.push(f);
    }

    fn len(&self) -> usize {
        self.interference.len()
    }

    /// [P̄, P̄', P̄''] of nodes `from` … `to` − 1 with lo ≤ Δ' ≤ hi at h, Δ =
    /// `stretch` Δ', relative to the share's scale (`scaled`: e^{κ} with κ =
    /// h²/2; else 1).
    #[allow(clippy::too_many_arguments)]
    fn sums(
        &self,
        from: usize,
        to: usize,
        lo: f64,
        hi: f64,
        h: f64,
        stretch: f64,
        scaled: bool,
    ) -> [f64; 3] {
        window_of(
            &self.interference[from..to],
            &self.load[from..to],
            lo,
            hi,
            h,
            stretch,
            scaled,
        )
    }
}

/// [`Nodes::sums`] of the nodes (d, f) ascending in d.
fn window_of(
    d: &[f64],
    f: &[f64],
    lo: f64,
    hi: f64,
    h: f64,
    stretch: f64,
    scaled: bool,
) -> [f64; 3] {
    let first = d.partition_point(|&x| x < lo);
    let end = d.partition_point(|&x| x <= hi).max(first);
    let (d, f) = (&d[first..end], &f[first..end]);
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { window_sums_avx2(d, f, h, stretch, scaled) };
    }
    window_sums(d, f, h, stretch, scaled)
}

/// [`window_sums`] compiled for AVX2: the same numbers bit for bit (no fused
/// multiply–adds, one node per lane, serial sums).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn window_sums_avx2(d: &[f64], f: &[f64], h: f64, stretch: f64, scaled: bool) -> [f64; 3] {
    window_sums(d, f, h, stretch, scaled)
}

/// Σ g, Σ −g u, Σ g (u² − 1) with g = f φ̄ over nodes at Δ = `stretch` d,
/// u = h + Δ, in a fixed order: the log-weights of a chunk, their
/// exponentials (branch-free [`exp_fast`], which vectorizes), then four
/// partial sums.
#[inline(always)]
fn window_sums(d: &[f64], f: &[f64], h: f64, stretch: f64, scaled: bool) -> [f64; 3] {
    const CHUNK: usize = 64;
    const LANES: usize = 4;
    let mut g = [0.0f64; CHUNK];
    let mut u = [0.0f64; CHUNK];
    // Moment k of node i in lanes[k][i mod 4].
    let mut lanes = [[0.0f64; LANES]; 3];
    for (d, f) in d.chunks(CHUNK).zip(f.chunks(CHUNK)) {
        let (g, u) = (&mut g[..d.len()], &mut u[..d.len()]);
        // One loop per scale, so that neither branches.
        if scaled {
            for (g, &d) in g.iter_mut().zip(d) {
                *g = log_weight(h, stretch * d, true);
            }
        } else {
            for (g, &d) in g.iter_mut().zip(d) {
                *g = log_weight(h, stretch * d, false);
            }
        }
        for ((g, u), (&d, &f)) in g.iter_mut().zip(u.iter_mut()).zip(d.iter().zip(f)) {
            *g = f * exp_fast(*g);
            *u = h + stretch * d;
        }
        // Four partial sums per moment, node i into lane i mod 4 (a fixed
        // order, so the same numbers on every machine), break the chain of
        // dependent adds; one loop per moment, each a vector of four lanes.
        moment_lanes(&mut lanes[0], g, u, |g, _| g);
        moment_lanes(&mut lanes[1], g, u, |g, u| -(g * u));
        moment_lanes(&mut lanes[2], g, u, |g, u| g * (u * u - 1.0));
    }
    let mut sums = [0.0; 3];
    for (sum, lanes) in sums.iter_mut().zip(&lanes) {
        *sum = (lanes[0] + lanes[1]) + (lanes[2] + lanes[3]);
    }
    sums
}

/// Adds term(g_i, u_i) into lanes[i mod 4] over one chunk (a multiple of four
/// nodes but for the last chunk).
#[inline(always)]
fn moment_lanes(lanes: &mut [f64; 4], g: &[f64], u: &[f64], term: impl Fn(f64, f64) -> f64) {
    let mut quads = g.chunks_exact(4).zip(u.chunks_exact(4));
    for (g, u) in &mut quads {
        for lane in 0..4 {
            lanes[lane] += term(g[lane], u[lane]);
        }
    }
    let rest = g.len() - g.len() % 4;
    for (lane, (&g, &u)) in g[rest..].iter().zip(&u[rest..]).enumerate() {
        lanes[lane] += term(g, u);
    }
}

impl Grid {
    /// True when the grid holds every summit the weight at h reaches.
    pub fn serves(h: f64) -> bool {
        h >= GRID_SEPARATIONS.0 && h <= GRID_SEPARATIONS.1
    }

    /// The law the grid is laid out for.
    pub fn law(&self) -> &RoughLaw {
        &self.law
    }

    /// The shares at any h: from the grid where it serves h, else integrated
    /// at h itself ([`RoughLaw::at`]).
    pub fn shares(&self, h: f64) -> Shares {
        if Self::serves(h) && !self.curves.is_empty() {
            self.at(h)
        } else {
            self.law.at(h)
        }
    }

    /// The nodes in use, non-contact and contact.
    pub fn len(&self) -> usize {
        self.curves
            .iter()
            .map(|c| c.layout.noncontact.all.len() + c.kept + c.cut.len())
            .sum::<usize>()
            + self.shared.len()
    }

    /// True without nodes.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The shares at h (which the grid serves: [`Grid::serves`]), curve by
    /// curve in the law's order.
    pub fn at(&self, h: f64) -> Shares {
        let mut out = Shares {
            noncontact_exponent: 0.5 * (-h).max(0.0).powi(2),
            elastic_exponent: 0.5 * h.max(0.0).powi(2),
            ..Shares::default()
        };
        let [noncontact, contact] = windows(h, self.law.range);
        if !self.shared.is_empty() {
            let stretch = self.stretch;
            let (lo, hi) = (noncontact.0 / stretch, noncontact.1 / stretch);
            out.noncontact =
                window_of(self.shared, &self.shared_loads, lo, hi, h, stretch, h < 0.0);
        }
        // The merged clusters, each by its centre in its share's window.
        for (share, (window, scaled)) in [(noncontact, h < 0.0), (contact, h > 0.0)]
            .into_iter()
            .enumerate()
        {
            let (lo, hi) = (window.0 / self.stretch, window.1 / self.stretch);
            for cluster in &self.merged[share] {
                if cluster.center < lo || cluster.center > hi {
                    continue;
                }
                let part = cluster.sums(h, self.stretch, scaled);
                let sums = if share == 0 {
                    &mut out.noncontact
                } else {
                    &mut out.elastic
                };
                for (sum, p) in sums.iter_mut().zip(part) {
                    *sum += p;
                }
            }
        }
        for curve in &self.curves {
            let (stretch, factor) = (curve.stretch, curve.factor);
            // The windows in the layout's Δ'.
            let (lo, hi) = (noncontact.0 / stretch, noncontact.1 / stretch);
            let below = &curve.layout.noncontact;
            let part = below.sums(below.all.len(), lo, hi, h, stretch, h < 0.0, curve.skip[0]);
            let (lo, hi) = (contact.0 / stretch, contact.1 / stretch);
            for (sum, p) in out.noncontact.iter_mut().zip(part) {
                *sum += factor * p;
            }
            let mut part =
                curve
                    .layout
                    .contact
                    .sums(curve.kept, lo, hi, h, stretch, h > 0.0, curve.skip[1]);
            let cut = curve
                .cut
                .sums(0, curve.cut.len(), lo, hi, h, stretch, h > 0.0);
            for ((sum, p), c) in out.elastic.iter_mut().zip(&mut part).zip(cut) {
                *p += c;
                *sum += factor * *p;
            }
        }
        out
    }
}

impl Grid {
    /// ∫ p(Δ) T_0(h0 + Δ) dΔ over the elastic and non-contact shares (every
    /// summit up to its curve's Δc, attracted ones down to Δ = −∞), T_0(u) =
    /// ∫_u^∞ e^{−x²/2} dx: the solid load's part of the work of separation
    /// from h0 with the integrals exchanged (`model::work`). The grid's own
    /// quadrature sum with the tail T_0 as weight instead of φ̄ (the same
    /// nodes, so the same accuracy as the shares): T_0 = √(2π) to rounding
    /// below the window (and over the layout's far field, `Layout::far`), and
    /// below e^{−46} above it. None where the grid does not serve h0.
    pub fn solid_work(&self, h0: f64) -> Option<f64> {
        if !Self::serves(h0) || self.curves.is_empty() {
            return None;
        }
        let (lo, hi) = ((-h0 - REACH) / self.stretch, (-h0 + REACH) / self.stretch);
        let mut total = tail_window(self.shared, &self.shared_loads, lo, hi, h0, self.stretch);
        for cluster in self.merged.iter().flatten() {
            total += cluster.tail_in(lo, hi, h0, self.stretch);
        }
        for curve in &self.curves {
            let (lo, hi) = ((-h0 - REACH) / curve.stretch, (-h0 + REACH) / curve.stretch);
            let layout = curve.layout;
            let stretch = curve.stretch;
            let sum = SQRT_TWO_PI * layout.far
                + layout.noncontact.tail_sum(
                    layout.noncontact.all.len(),
                    lo,
                    hi,
                    h0,
                    stretch,
                    curve.skip[0],
                )
                + layout
                    .contact
                    .tail_sum(curve.kept, lo, hi, h0, stretch, curve.skip[1])
                + tail_window(
                    &curve.cut.interference,
                    &curve.cut.load,
                    lo,
                    hi,
                    h0,
                    stretch,
                );
            total += curve.factor * sum;
        }
        Some(total)
    }
}

impl RoughLaw {
    /// The scene's [`Grid`]: each curve in use with its layout, its weight
    /// and the panel its Δc cuts.
    pub fn grid(&self) -> Grid {
        let level = level_of(self.ell);
        let mut curves: Vec<GridCurve> = match level {
            Some(level) => {
                let s = level_scale(level);
                let stretch = s / self.ell;
                self.nodes()
                    .iter()
                    .map(|node| {
                        let layout = layout(node.index, level);
                        // Δc in the layout's Δ'.
                        let critical = node.critical / stretch;
                        let first = layout.pieces.partition_point(|&(_, b)| b <= critical);
                        let mut cut = Nodes::default();
                        if let Some(&(a, _)) = layout.pieces.get(first) {
                            if a < critical {
                                visit_piece(node.curve, s, a, critical, &mut |d, f| cut.push(d, f));
                            }
                        }
                        GridCurve {
                            layout,
                            stretch,
                            factor: node.weight * stretch.powf(2.5),
                            kept: first * CONTACT_ORDER,
                            cut,
                            skip: [0; 2],
                        }
                    })
                    .collect()
            }
            None => Vec::new(),
        };
        // The shared nodes' loads, each curve's times its factor.
        let (mut shared, mut shared_loads, mut stretch): (&[f64], _, _) = (&[], Vec::new(), 1.0);
        if let (Some(level), Some(first)) = (level, curves.first()) {
            stretch = first.stretch;
            shared = &Shared::at(level).nodes.interference;
            shared_loads = vec![0.0; shared.len()];
            for curve in &curves {
                for (sum, &f) in shared_loads.iter_mut().zip(&curve.layout.shared) {
                    *sum += curve.factor * f;
                }
            }
        }
        let merged = merge_clusters(&mut curves);
        Grid {
            law: *self,
            curves,
            shared,
            shared_loads,
            stretch,
            merged,
        }
    }
}

/// The clusters that every curve in use has within MERGE_GAP of the first
/// curve's (whole: not cut by Δc), merged per share; each member's bit set
/// in its curve's `skip`.
fn merge_clusters(curves: &mut [GridCurve]) -> [Vec<Cluster>; 2] {
    let mut merged: [Vec<Cluster>; 2] = [Vec::new(), Vec::new()];
    if curves.len() < 2 || curves.len() > 8 {
        return merged;
    }
    for (share, out) in merged.iter_mut().enumerate() {
        let of = |c: &GridCurve| -> (&'static Share, usize) {
            if share == 0 {
                (&c.layout.noncontact, c.layout.noncontact.all.len())
            } else {
                (&c.layout.contact, c.kept)
            }
        };
        let (first, count) = of(&curves[0]);
        for (i0, c0) in first.clusters.iter().enumerate().take(64) {
            if c0.end > count {
                continue;
            }
            // Each curve's nearest such cluster not merged already (the
            // first curve's own is c0); the clusters ascend in centre.
            let mut members = [usize::MAX; 8];
            for (slot, c) in members.iter_mut().zip(curves.iter()) {
                let (s, count) = of(c);
                let clusters = &s.clusters[..s.clusters.len().min(64)];
                let from = clusters.partition_point(|x| x.center < c0.center - MERGE_GAP);
                let mut best = f64::INFINITY;
                for (k, x) in clusters.iter().enumerate().skip(from) {
                    if x.center > c0.center + MERGE_GAP {
                        break;
                    }
                    let gap = (x.center - c0.center).abs();
                    if c.skip[share] >> k & 1 == 0 && x.end <= count && gap < best {
                        (*slot, best) = (k, gap);
                    }
                }
            }
            let members = &members[..curves.len()];
            if members[0] != i0 || members.contains(&usize::MAX) {
                continue;
            }
            let mut moments = [0.0; CLUSTER_TERMS];
            for (c, &k) in curves.iter_mut().zip(members) {
                let (s, _) = of(c);
                for (m, x) in moments
                    .iter_mut()
                    .zip(s.clusters[k].moments_about(c0.center, c.factor))
                {
                    *m += x;
                }
                c.skip[share] |= 1 << k;
            }
            out.push(Cluster {
                first: 0,
                end: 0,
                center: c0.center,
                moments,
            });
        }
    }
    merged
}

/// P̂_in/â² of one curve on its contact part at δ̂, the plastic rule's ratio
/// (in these units proportional to the mean pressure inside the contact
/// radius; −∞ where there is no contact area).
fn inner_pressure(curve: &Curve, d: f64) -> f64 {
    let (a, inner) = curve.contact_area(d);
    if a <= 0.0 {
        f64::NEG_INFINITY
    } else {
        inner / (a * a)
    }
}

/// The ratio P̂_in/â² of a curve of the table (None for another curve) at the
/// start of its contact part (max(δ̂_s, 0)), at its panel ends beyond it and
/// at δ̂_max 2^j, j = 1 … 64: ascending in δ̂ and, the contact part being
/// stiffer the deeper, in the ratio. Computed once per curve.
fn ratio_samples(curve: &Curve) -> Option<&'static [(f64, f64)]> {
    type Samples = OnceLock<Vec<(f64, f64)>>;
    static CACHE: OnceLock<Vec<Samples>> = OnceLock::new();
    let all = curves();
    let index = all.iter().position(|c| std::ptr::eq(c, curve))?;
    let cache = CACHE.get_or_init(|| all.iter().map(|_| OnceLock::new()).collect());
    Some(cache[index].get_or_init(|| sample_ratios(curve)))
}

/// [`ratio_samples`], computed afresh.
fn sample_ratios(curve: &Curve) -> Vec<(f64, f64)> {
    let ratio = |d: f64| inner_pressure(curve, d);
    let start = curve.switch.max(0.0);
    let max = curve.max_interference();
    let mut points: Vec<f64> = std::iter::once(start)
        .chain(curve.breaks().iter().copied().filter(|&b| b > start))
        .collect();
    let mut d = max;
    for _ in 0..64 {
        d *= 2.0;
        points.push(d);
    }
    let mut samples: Vec<(f64, f64)> = points.into_iter().map(|d| (d, ratio(d))).collect();
    // A bracket needs the ratio ascending: keep a sample only above the
    // last one kept (the search's root is then the first crossing, as a
    // search from the start would find), and every −∞ before contact (the
    // last of them is the nearest lower end).
    let mut top = f64::NEG_INFINITY;
    samples.retain(|&(_, r)| {
        let keep = r > top || top == f64::NEG_INFINITY && r == top;
        top = top.max(r);
        keep
    });
    samples
}

/// δ̂c of one curve: where P̂_in/â² first reaches `target` = c_h ℓ^{1/2} on
/// the contact part (regula falsi; ∞ for c_h = ∞; the switch where the ratio
/// already exceeds it there).
pub fn critical_interference(curve: &Curve, target: f64) -> f64 {
    if target.is_infinite() {
        return f64::INFINITY;
    }
    let ratio = |d: f64| inner_pressure(curve, d);
    // The bracket from the curve's ratios at its panel ends and at doublings
    // beyond δ̂_max, computed once per curve (no evaluation here).
    let owned;
    let samples = match ratio_samples(curve) {
        Some(samples) => samples,
        None => {
            owned = sample_ratios(curve);
            &owned[..]
        }
    };
    let k = samples.partition_point(|&(_, r)| r < target);
    if k == 0 {
        return samples[0].0;
    }
    let (mut lo, mut hi, f_lo, f_hi) = match samples.get(k) {
        Some(&(hi, r_hi)) => {
            let (lo, r_lo) = samples[k - 1];
            (lo, hi, r_lo - target, r_hi - target)
        }
        None => {
            // Beyond the last sample: doubling, as far as doubles go.
            let (mut lo, mut hi) = (samples[k - 1].0, 2.0 * samples[k - 1].0);
            while ratio(hi) < target {
                lo = hi;
                hi *= 2.0;
                if hi > 1e300 {
                    return f64::INFINITY;
                }
            }
            (lo, hi, ratio(lo) - target, ratio(hi) - target)
        }
    };
    // Newton's method on the ratio with its slope from the table's derivative
    // series, kept inside the bracket (the ratio is smooth and increasing
    // there): the regula falsi point first, a bisection wherever a step
    // leaves the bracket, and done once a step is within 4 ulps (the Illinois
    // variant of regula falsi took 7–28 evaluations on the hub's curves, this
    // 4–5).
    let mut x = hi - f_hi * (hi - lo) / (f_hi - f_lo);
    for _ in 0..200 {
        if !(x > lo && x < hi) {
            x = 0.5 * (lo + hi);
        }
        if x <= lo || x >= hi || hi - lo <= 4.0 * f64::EPSILON * hi {
            return 0.5 * (lo + hi);
        }
        let (f, slope) = inner_pressure_slope(curve, x);
        let f = f - target;
        if f == 0.0 {
            return x;
        }
        if f < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let step = f / slope;
        if step.abs() <= 4.0 * f64::EPSILON * x {
            return x - step;
        }
        x -= step;
    }
    0.5 * (lo + hi)
}

/// [`inner_pressure`] and its δ̂-derivative, (P̂_in/â²)' = P̂_in'/â² −
/// 2 P̂_in â'/â³ (NaN where there is no contact area: the caller bisects).
fn inner_pressure_slope(curve: &Curve, d: f64) -> (f64, f64) {
    let ((a, da), (inner, dinner)) = curve.contact_area_slope(d);
    if a <= 0.0 {
        (f64::NEG_INFINITY, f64::NAN)
    } else {
        let a2 = a * a;
        (inner / a2, dinner / a2 - 2.0 * inner * da / (a2 * a))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::lennard_jones::table::AT_HUNDREDTH;

    /// The summit loads taken a panel at a time, and with their slopes four
    /// curves abreast, are the one-at-a-time sums bit for bit: over μ from the
    /// table's DMT end to JKR-like (four curves each), Δ from 1e-6 to past the
    /// tails' last panel, slices of 1 … 9 nodes (whole and partial groups of four).
    #[test]
    fn summit_loads_abreast_are_the_loads_one_by_one() {
        let ds: Vec<f64> = (0..106)
            .map(|i| 1e-6 * 10f64.powf(i as f64 * 0.2))
            .collect();
        for (c_0, z0) in [(0.05, 2.0), (0.3, 0.05), (2.0 * 12f64.powf(-1.5), 0.2)] {
            let law = RoughLaw::new(c_0, f64::INFINITY, z0).expect("in the table");
            assert_eq!(law.nodes().len(), 4);
            for n in 1..=9 {
                for chunk in ds.chunks(n) {
                    let mut out = vec![f64::NAN; chunk.len()];
                    law.summit_loads_maugis(chunk, &mut out);
                    for (&d, &got) in chunk.iter().zip(&out) {
                        assert_eq!(
                            got.to_bits(),
                            law.summit_load_maugis(d).to_bits(),
                            "Δ = {d}"
                        );
                    }
                }
            }
            for &d in &ds {
                let dd = law.ell * d;
                let want = law.nodes().iter().fold((0.0, 0.0), |(p, s), n| {
                    let (pk, sk) = n.curve.contact(dd);
                    (p + n.weight * pk, s + n.weight * sk * law.ell)
                });
                let got = law.summit_load_slope_maugis(d);
                assert_eq!(got.0.to_bits(), want.0.to_bits(), "Δ = {d}");
                assert_eq!(got.1.to_bits(), want.1.to_bits(), "Δ = {d}");
            }
        }
    }

    /// A cluster regroups the same quadrature sum (docs/model.md §11): each
    /// share summed with its clusters against the same nodes one by one, on
    /// the hub's four curves at a scale, over the stretches s/ℓ ∈ (2^{-1/4}, 1]
    /// and separations across the grid's range, all three moments, within
    /// 1e-14 of the nodes' Σ|f| φ̄ (1 + u²) (rounding).
    #[test]
    fn clusters_sum_what_their_nodes_sum() {
        let mut clustered = 0;
        for index in (AT_HUNDREDTH + 32..AT_HUNDREDTH + 40).step_by(2) {
            let layout = layout(index, 15);
            for share in [&layout.noncontact, &layout.contact] {
                clustered += share.clusters.len();
                let n = share.all.len();
                for stretch in [1.0, 0.92, 0.841] {
                    for h in [-6.0, -1.3, 0.0, 0.4, 2.0, 7.5, 16.0] {
                        for scaled in [false, true] {
                            let (lo, hi) = ((-h - REACH) / stretch, (-h + REACH) / stretch);
                            let got = share.sums(n, lo, hi, h, stretch, scaled, 0);
                            let first = share.all.interference.partition_point(|&d| d < lo);
                            let end = share.all.interference.partition_point(|&d| d <= hi);
                            let (mut want, mut size) = ([0.0; 3], 0.0f64);
                            for j in first..end {
                                let d = stretch * share.all.interference[j];
                                let g = share.all.load[j] * log_weight(h, d, scaled).exp();
                                add_moments(&mut want, g, h + d);
                                size += g.abs() * (1.0 + (h + d).powi(2));
                            }
                            for k in 0..3 {
                                assert!(
                                    (got[k] - want[k]).abs() <= 1e-14 * size.max(1e-300),
                                    "curve {index} stretch {stretch} h {h}: {got:?} vs {want:?}"
                                );
                            }
                        }
                    }
                }
            }
        }
        assert!(
            clustered >= 8,
            "the hub's curves have dense runs: {clustered}"
        );
    }

    /// The same for the work of separation's sums Σ f T_0(h0 + Δ): the
    /// clusters' series of T_0 against the nodes one by one (in the same
    /// window), within 1e-14 of Σ|f| T_0 (rounding), on the same curves,
    /// stretches and separations.
    #[test]
    fn clusters_sum_the_tail_as_their_nodes() {
        for index in (AT_HUNDREDTH + 32..AT_HUNDREDTH + 40).step_by(2) {
            let layout = layout(index, 15);
            for share in [&layout.noncontact, &layout.contact] {
                let n = share.all.len();
                for stretch in [1.0, 0.92, 0.841] {
                    for h0 in [-6.0, -1.3, 0.0, 0.4, 2.0, 7.5, 16.0] {
                        let (lo, hi) = ((-h0 - REACH) / stretch, (-h0 + REACH) / stretch);
                        let got = share.tail_sum(n, lo, hi, h0, stretch, 0);
                        let (mut want, mut size) = (0.0, 0.0f64);
                        for (&d, &f) in share.all.interference.iter().zip(&share.all.load) {
                            // The window's: the whole tail below it, nothing above.
                            let t = if d < lo {
                                SQRT_TWO_PI
                            } else if d <= hi {
                                crate::model::special::gaussian_tail(h0 + stretch * d)
                            } else {
                                0.0
                            };
                            want += f * t;
                            size += (f * t).abs();
                        }
                        assert!(
                            (got - want).abs() <= 1e-14 * size.max(1e-300),
                            "curve {index} stretch {stretch} h0 {h0}: {got} vs {want}"
                        );
                    }
                }
            }
        }
    }

    /// The approach part's nodes shared by every curve at one scale (Gauss in
    /// Δ', [`Shared`]) against the curve's own (Gauss in τ, as the windowed
    /// quadrature lays them out from the same lower end) over the same
    /// stretch of summits, at separations across the grid's: the same sums
    /// to 1e-13 of the whole non-contact share's size (times √(0.01/μ) below
    /// μ = 0.01), on curves across the table (both sides of the
    /// cusp) and scales from 0.6 to 300.
    #[test]
    fn the_shared_nodes_sum_what_each_curves_own_sum() {
        let mut compared = 0;
        for index in [0, 49, 98, 138, 174, 188, 189, 190, 230] {
            let curve = &curves()[index];
            for level in [-3, 0, 12, 33] {
                let s = level_scale(level);
                let shared = Shared::at(level);
                let loads = &layout(index, level).shared;
                if loads.is_empty() {
                    continue;
                }
                let (lo, _) = layout_range();
                let mut own = Nodes::default();
                visit_curve(curve, s, f64::INFINITY, lo, shared.end, &mut |d, f, _| {
                    own.push(d, f)
                });
                for h in [-6.0, -1.0, 0.0, 3.0, 9.0, 16.0] {
                    let sum = |d: &[f64], f: &[f64]| {
                        let (mut total, mut size) = ([0.0; 3], 0.0f64);
                        for (&d, &f) in d.iter().zip(f) {
                            let g = f * (-0.5 * (h + d) * (h + d)).exp();
                            add_moments(&mut total, g, h + d);
                            size += g.abs() * (1.0 + (h + d).powi(2));
                        }
                        (total, size)
                    };
                    // Relative to the whole non-contact share's size at h
                    // (its summits near contact included), as the grid sums.
                    let all = &layout(index, level).noncontact.all;
                    let (a, shared_size) = sum(&shared.nodes.interference, loads);
                    let (b, _) = sum(&own.interference, &own.load);
                    let size = shared_size + sum(&all.interference, &all.load).1;
                    // Below μ = 0.01 the rounding of δ̂ = ẑ0 (1 − G + e) near
                    // the switch grows with ẑ0 (measured: 1.7e-13 at μ = 1e-4,
                    // 2.7e-14 at 1e-3, below 1e-14 from 0.01 up).
                    let tol = 1e-13 * (0.01 / curve.tabor).max(1.0).sqrt();
                    for k in 0..3 {
                        assert!(
                            (a[k] - b[k]).abs() <= tol * size + 1e-300,
                            "curve {index} s {s} h {h}: {a:?} vs {b:?}"
                        );
                    }
                    compared += 1;
                }
            }
        }
        assert!(compared >= 60, "{compared}");
    }

    /// A scene's merged clusters (the curves' clusters near one another
    /// re-expanded about one centre and summed once) against the same grid
    /// summing each curve's own: the same shares and work of separation to
    /// 1e-14 of their size (times 1 + h² for the shares), on the hub (four curves), at a plastic scene
    /// whose Δc cuts panels, and between curves elsewhere in the table.
    #[test]
    fn merged_clusters_sum_what_each_curves_sum() {
        let mut merged_any = 0;
        for (c_0, c_h, z0) in [
            (2.0 * std::f64::consts::PI / 184.0, 10.0, 0.1),
            (0.3, 1.5, 0.05),
            (0.01, 3.0, 0.3),
            (0.05, f64::INFINITY, 1.0),
        ] {
            let law = RoughLaw::new(c_0, c_h, z0).expect("in the table");
            let grid = law.grid();
            merged_any += grid.merged[0].len() + grid.merged[1].len();
            let mut plain = grid.clone();
            plain.merged = [Vec::new(), Vec::new()];
            for c in &mut plain.curves {
                c.skip = [0; 2];
            }
            for h in [-6.0, -2.0, 0.0, 0.5, 2.0, 4.0, 9.0, 16.0] {
                let (a, b) = (grid.at(h), plain.at(h));
                for (x, y) in [(a.noncontact, b.noncontact), (a.elastic, b.elastic)] {
                    // As `clusters_sum_what_their_nodes_sum` measures:
                    // against the share's size times 1 + u² (the series
                    // lose digits as |u| grows: at h = 16, 2.7e-14 of P̄'').
                    let size = y.iter().fold(1e-300f64, |m, v| m.max(v.abs())) * (1.0 + h * h);
                    for k in 0..3 {
                        assert!(
                            (x[k] - y[k]).abs() <= 1e-14 * size,
                            "c_0 {c_0} h {h}: {x:?} vs {y:?}"
                        );
                    }
                }
                let (wa, wb) = (grid.solid_work(h).unwrap(), plain.solid_work(h).unwrap());
                assert!((wa - wb).abs() <= 1e-14 * wb.abs(), "h {h}: {wa} vs {wb}");
            }
        }
        assert!(merged_any >= 2, "the hub's clusters merge: {merged_any}");
    }

    /// The far field below a layout's first node, on panels shrinking by 1.5
    /// against 1.05 in τ (three times as many): the same integral to 5e-12
    /// (4e-15 but where the layout starts on the contact part, s = 0.01; what
    /// earlier tables gave there: docs/history.md), on curves across
    /// the table and scales from 0.01 to 300.
    #[test]
    fn the_far_field_is_converged() {
        for index in [0, 49, 98, 130, 162, 174, 189, 202, 230] {
            for s in [0.01, 1.0, 8.0, 300.0] {
                let a = far_load(&curves()[index], s, -30.0, FAR_GROWTH);
                let b = far_load(&curves()[index], s, -30.0, 1.05);
                assert!(a < 0.0, "curve {index} s {s}: attracted summits pull ({a})");
                let tol = if s < 0.1 { 5e-12 } else { 4e-15 };
                assert!(
                    (a - b).abs() <= tol * b.abs(),
                    "curve {index} s {s}: {a} vs {b}"
                );
            }
        }
    }

    /// Δc from the cached bracket against plain bisection from the contact
    /// part's start outwards (the ratio P̂_in/â² is increasing there), on
    /// curves across the table and targets from the start's ratio to deep in
    /// the tail: the same root to 1e-12.
    #[test]
    fn the_critical_interference_is_the_root_bisection_finds() {
        for index in [0, 49, 98, 130, 162, 174, 189, 202, 230] {
            let curve = &curves()[index];
            let ratio = |d: f64| inner_pressure(curve, d);
            let start = curve.switch.max(0.0);
            for target in [0.5, 2.0, 7.0, 20.0, 80.0, 400.0, 3e3] {
                let got = critical_interference(curve, target);
                if ratio(start) >= target {
                    assert_eq!(got, start);
                    continue;
                }
                let (mut lo, mut hi) = (start, 1.0f64.max(2.0 * start));
                while ratio(hi) < target {
                    (lo, hi) = (hi, 2.0 * hi);
                }
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    if ratio(mid) < target {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                assert!(
                    (got - hi).abs() <= 1e-12 * hi,
                    "curve {index} target {target}: {got} against {hi}"
                );
            }
        }
    }
}
