//! The work of separation: Γ̄ = -∫_{h0}^∞ P̄(h) dh, the apparent work of adhesion
//! of docs/model.md §9 in model units (what a cantilever-beam test measures, per
//! unit nominal area, from the unloaded equilibrium h0 to infinity).
//!
//! **Method.** P̄ is smooth in h (a convolution with a Gaussian; the law's jumps
//! are smoothed by it). Over [h0, ∞) substitute h = h0 + L (1 - t)/t, t ∈ (0, 1]
//! (L = 1 plus the longest reach of the attraction or the meniscus, so that their
//! features sit at t of order 1/2): dh = L dt/t², and a van der Waals tail
//! P̄ ~ -C/h² becomes a bounded integrand near t = 0, a Gaussian one a vanishing
//! one. The t-interval is bisected adaptively, each piece by the Gauss–Kronrod 7–15
//! pair, until the sum of the pieces' error estimates (QUADPACK's: |K15 - G7|
//! shrunk by (200|K15 - G7|/∫|f|)^{3/2}) falls below 1e-11 of |Γ̄| (or of 1e-3 of the
//! integral of |P̄|, where Γ̄'s shares cancel), the 15-point value kept. Past
//! h = [`super::coefficients::MAX_SEPARATION`] only the van der Waals tail is left,
//! -c_0 √(2π) z0²/(z0 + h)² (1 + O(h^-2)), integrated in closed form.

use super::integrals::Model;
use super::law::{AsperityLaw, Attraction};
use super::special::SQRT_TWO_PI;

/// The Gauss–Kronrod 7–15 pair (QUADPACK's qk15): the 15 Kronrod nodes on [0, 1)
/// (each ± but the last, 0), their weights, and the weights of the 7-point Gauss rule
/// on the odd-indexed ones and 0. Checked by `kronrod_pair_is_exact`: degree 22 and 13.
#[allow(clippy::excessive_precision)] // QUADPACK's published digits
const KRONROD_NODES: [f64; 8] = [
    0.991_455_371_120_812_639_206_854_697_526_329,
    0.949_107_912_342_758_524_526_189_684_047_851,
    0.864_864_423_359_769_072_789_712_788_640_926,
    0.741_531_185_599_394_439_863_864_773_280_788,
    0.586_087_235_467_691_130_294_144_845_693_013,
    0.405_845_151_377_397_166_906_606_412_076_961,
    0.207_784_955_007_898_467_600_689_403_773_245,
    0.0,
];
#[allow(clippy::excessive_precision)] // QUADPACK's published digits
const KRONROD_WEIGHTS: [f64; 8] = [
    0.022_935_322_010_529_224_963_732_008_058_970,
    0.063_092_092_629_978_553_290_700_663_189_204,
    0.104_790_010_322_250_183_839_876_322_541_518,
    0.140_653_259_715_525_918_745_189_590_510_238,
    0.169_004_726_639_267_902_826_583_426_598_550,
    0.190_350_578_064_785_409_913_256_402_421_014,
    0.204_432_940_075_298_892_414_161_999_234_649,
    0.209_482_141_084_727_828_012_999_174_891_714,
];
#[allow(clippy::excessive_precision)] // QUADPACK's published digits
const GAUSS_WEIGHTS: [f64; 4] = [
    0.129_484_966_168_869_693_270_611_432_679_082,
    0.279_705_391_489_276_667_901_467_771_423_780,
    0.381_830_050_505_118_944_950_369_775_488_975,
    0.417_959_183_673_469_387_755_102_040_816_327,
];

/// The relative tolerance of the adaptive quadrature.
const TOLERANCE: f64 = 1e-11;
/// The most pieces the bisection may make.
const MAX_PIECES: usize = 400;

/// Γ̄ = -∫_{from}^∞ P̄(h) dh (model units: multiply by the load scale per unit area
/// times σ for J/m²), and the model evaluations it spent.
pub fn work_of_separation(model: &Model, from: f64) -> (f64, usize) {
    let reach = match model.effective_law() {
        AsperityLaw::Dmt(a) => a.range(),
        AsperityLaw::LennardJones { range } => range,
        AsperityLaw::Jkr => 0.0,
    }
    .max(model.capillary.map_or(0.0, |c| c.range))
    .min(1e3);
    let scale = 1.0 + reach;
    let limit = super::coefficients::MAX_SEPARATION;
    let t_end = if from < limit {
        scale / (scale + (limit - from))
    } else {
        1.0
    };
    let mut evaluations = 0;
    let mut integrand = |t: f64| {
        evaluations += 1;
        let h = from + scale * (1.0 - t) / t;
        model.at(h).load().value() * scale / (t * t)
    };
    let piece = |a: f64, b: f64, f: &mut dyn FnMut(f64) -> f64| -> (f64, f64, f64) {
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        let (mut k15, mut g7, mut abs15) = (0.0, 0.0, 0.0);
        for (i, (&x, &w)) in KRONROD_NODES.iter().zip(&KRONROD_WEIGHTS).enumerate() {
            let v = if x == 0.0 {
                f(mid)
            } else {
                f(mid - half * x) + f(mid + half * x)
            };
            k15 += w * v;
            abs15 += w * v.abs();
            if i % 2 == 1 {
                g7 += GAUSS_WEIGHTS[i / 2] * v;
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
        (half * k15, e, scale)
    };
    // (a, b, value, error, |value|) of each piece; bisect the worst until done.
    let mut pieces = vec![];
    let (v, e, m) = piece(t_end, 1.0, &mut integrand);
    pieces.push((t_end, 1.0, v, e, m));
    loop {
        let total: f64 = pieces.iter().map(|p| p.2).sum();
        let size: f64 = pieces.iter().map(|p| p.4).sum();
        let error: f64 = pieces.iter().map(|p| p.3).sum();
        if error <= TOLERANCE * total.abs().max(1e-3 * size) || pieces.len() >= MAX_PIECES {
            break;
        }
        let worst = pieces
            .iter()
            .enumerate()
            .max_by(|x, y| x.1 .3.total_cmp(&y.1 .3))
            .map_or(0, |(i, _)| i);
        let (a, b, ..) = pieces.swap_remove(worst);
        let mid = 0.5 * (a + b);
        for (x, y) in [(a, mid), (mid, b)] {
            let (v, e, m) = piece(x, y, &mut integrand);
            pieces.push((x, y, v, e, m));
        }
    }
    // Sum in a fixed order (by position), so the result does not depend on the
    // order the pieces were made in beyond the pieces themselves.
    pieces.sort_by(|x, y| x.0.total_cmp(&y.0));
    let mut integral: f64 = pieces.iter().map(|p| p.2).sum();
    // Beyond h = MAX_SEPARATION a power-law attraction's tail in closed form:
    // −c_0 (z0/(z0 + h))² per summit under van der Waals, 4/3 of it under
    // Lennard-Jones (Hamaker constant 16π Z0² γ against 12π).
    let tail = match model.effective_law() {
        AsperityLaw::Dmt(Attraction::VanDerWaals { range }) => Some((range, 1.0)),
        AsperityLaw::LennardJones { range } => Some((range, 4.0 / 3.0)),
        _ => None,
    };
    if let Some((range, factor)) = tail {
        if t_end < 1.0 {
            let c_0 = model.coefficients.c_0;
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
                    g += GAUSS_WEIGHTS[i / 2] * v;
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

    #[test]
    fn the_humid_hub_costs_a_few_hundred_evaluations() {
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
        // Pinned (7 pieces of 15 points): a change in the cost shows here.
        assert!(w > 0.0 && evaluations == 105, "{evaluations}");
    }
}
