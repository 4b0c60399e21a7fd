//! Debris or smoothing: which contacts break off a particle and which wear atom
//! by atom (Aghababaei, Warner & Molinari, Nat. Commun. 7 (2016) 11816;
//! docs/model.md §13).
//!
//! A junction wider than the critical size d* = Λ w G / τ_j² (w the work of
//! adhesion, G the shear modulus of the softer body, τ_j the junction's shear
//! strength, Λ a shape factor) breaks off a debris particle; a smaller one is
//! smoothed away atom by atom. A summit's junction diameter is its contact
//! diameter under the scene's asperity law ([`junction_cut`]): Hertz's 2√(Rδ)
//! under DMT, JKR's 2a with δ = a²/R − √(2πwa/E*), the Lennard-Jones sphere's
//! from the law's curves; a plastic junction's is 2√(2Rδ). Each grows with
//! the interference, so the junctions wider than d* are the summits beyond a
//! cut (two stretches where plastic junctions start narrower than the elastic
//! summits below them), and with Gaussian summit heights the share of the
//! contacts and of the real area (the πRδ measure) in them are closed forms
//! in erfc.

use serde::Serialize;

use super::law::AdhesionModel;
use super::lennard_jones::rough::{tabor, RoughLaw};
use super::scene::Scene;
use super::special::{kappa, tail0, tail1_given};
use super::warnings::Warning;

/// Λ when the problem file gives none: the shape factor of Aghababaei et al. (2016).
pub const DEFAULT_DEBRIS_SHAPE_FACTOR: f64 = 12.0;

/// Below this share of the real area in junctions wider than d*, wear is `smoothing`.
pub const SMOOTHING_BELOW: f64 = 0.01;

/// Above this share of the real area in junctions wider than d*, wear is `debris`.
pub const DEBRIS_ABOVE: f64 = 0.5;

/// How the contact wears, from the share of its real area in junctions wider than d*.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WearMechanism {
    /// Less than 1 % of the real area makes debris: atom-by-atom smoothing.
    Smoothing,
    /// Between 1 % and 50 %.
    Mixed,
    /// More than 50 % of the real area makes debris.
    Debris,
}

impl WearMechanism {
    /// The word reports and JSON use.
    pub fn as_str(self) -> &'static str {
        match self {
            WearMechanism::Smoothing => "smoothing",
            WearMechanism::Mixed => "mixed",
            WearMechanism::Debris => "debris",
        }
    }

    /// The mechanism of a contact whose real area is `debris_area_fraction` debris
    /// (a share in [0, 1]): `smoothing` below [`SMOOTHING_BELOW`], `debris` above
    /// [`DEBRIS_ABOVE`], `mixed` between (a boundary value is `mixed`).
    pub fn of(debris_area_fraction: f64) -> WearMechanism {
        if debris_area_fraction < SMOOTHING_BELOW {
            WearMechanism::Smoothing
        } else if debris_area_fraction > DEBRIS_ABOVE {
            WearMechanism::Debris
        } else {
            WearMechanism::Mixed
        }
    }
}

/// Whether the wear law named `wear_law` removes material atom by atom (so that it
/// assumes smoothing and is wrong where most of the area makes debris). Archard's
/// law takes its coefficient from measurement and assumes neither; an atom-by-atom
/// law (`stress_assisted`, docs/model.md §12) does.
pub fn assumes_smoothing(wear_law: &str) -> bool {
    matches!(wear_law, "stress_assisted")
}

/// The debris numbers of one evaluation (SI), present when the scene gives the
/// junction shear strength τ_j.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Debris {
    /// d* = Λ w G / τ_j², the junction diameter above which a junction breaks off a
    /// debris particle (m); 0 without adhesion (w = 0).
    pub critical_junction_size: f64,
    /// The share of the contacts whose junction is wider than d*; None when separated.
    pub debris_contact_fraction: Option<f64>,
    /// The share of the real area (the πRδ measure) in junctions wider than d*;
    /// None when separated.
    pub debris_area_fraction: Option<f64>,
    /// `smoothing`, `mixed` or `debris` from the area share; None when separated.
    pub wear_mechanism: Option<WearMechanism>,
    /// G = E1 / (2(1 + ν1)), the shear modulus of the softer body a (Pa).
    pub shear_modulus: f64,
    /// Λ, the shape factor used.
    pub debris_shape_factor: f64,
}

impl Debris {
    /// The warning where most of the real area makes debris (`wear_mechanism` is
    /// `debris`), naming `wear_law`, the wear law in use, and whether it assumes
    /// smoothing ([`assumes_smoothing`]); None otherwise.
    pub fn warning(&self, wear_law: &'static str) -> Option<Warning> {
        (self.wear_mechanism == Some(WearMechanism::Debris)).then(|| Warning::DebrisRegime {
            wear_law,
            assumes_smoothing: assumes_smoothing(wear_law),
            debris_area_fraction: self.debris_area_fraction.unwrap_or(1.0),
            critical_junction_size: self.critical_junction_size,
        })
    }
}

/// G = E / (2(1 + ν)) (Pa) of a body of Young's modulus E (Pa) and Poisson ratio ν.
pub fn shear_modulus(youngs_modulus: f64, poisson_ratio: f64) -> f64 {
    youngs_modulus / (2.0 * (1.0 + poisson_ratio))
}

/// d* = Λ w G / τ_j² (m): Λ the shape factor (> 0), w the work of adhesion (J/m²),
/// G the shear modulus (Pa), τ_j the junction shear strength (Pa, > 0).
pub fn critical_junction_size(
    shape_factor: f64,
    work_of_adhesion: f64,
    shear_modulus: f64,
    shear_strength: f64,
) -> f64 {
    shape_factor * work_of_adhesion * shear_modulus / (shear_strength * shear_strength)
}

/// The shares (of the contacts, of the πRδ real area) of summits whose
/// interference exceeds `cut` (in units of σ, ≥ 0) at the non-dimensional
/// separation `h`, with Gaussian summit heights (docs/model.md §3):
///
/// - contacts: Q(h + cut) / Q(h) = T_0(a) / T_0(h),
/// - area: [φ(a) − h Q(a)] / [φ(h) − h Q(h)] = [T_1(a) + cut T_0(a)] / T_1(h),
///
/// with a = h + cut, Q the upper tail of the standard normal, φ its density and
/// T_n the tail moments of `special`. Both are ratios of the scaled moments times
/// e^{κ(h) − κ(a)}, so nothing underflows before the share itself does (a share
/// below 1e-308 is 0) and the far tail keeps its relative accuracy.
pub fn debris_fractions(h: f64, cut: f64) -> (f64, f64) {
    let a = h + cut;
    let (t0_h, t0_a) = (tail0(h), tail0(a));
    let scale = (kappa(h) - kappa(a)).exp();
    let contacts = t0_a / t0_h * scale;
    let area = (tail1_given(a, t0_a) + cut * t0_a) / tail1_given(h, t0_h) * scale;
    (contacts.clamp(0.0, 1.0), area.clamp(0.0, 1.0))
}

/// The interference δ*/σ (≥ 0) beyond which a summit's junction under the
/// scene's asperity law is wider than `diameter` (m, ≥ 0), elastic summits'
/// sizes (docs/model.md §13):
///
/// - DMT, and any law without adhesion: Hertz, δ* = a*²/R with a* = d/2;
/// - JKR: δ* = a*²/R − √(2πwa*/E*) (E* the composite modulus), below Hertz's:
///   a JKR summit is wider at the same interference, already at δ = 0;
/// - Lennard-Jones: where the law's interpolated contact radius reaches a*
///   ([`RoughLaw::interference_at_contact_radius`]), between JKR's and
///   Hertz's; outside the table the closed form that stands in (JKR above
///   μ = 1, Hertz below).
///
/// 0 where every summit in contact is wider than `diameter`; at most 1e4.
pub fn junction_cut(scene: &Scene, diameter: f64) -> f64 {
    let (r, s, w) = (scene.asperity_radius, scene.sigma, scene.work_of_adhesion);
    let a = 0.5 * diameter;
    let hertz = a * a / r;
    let jkr = || {
        let e = scene.equivalent_modulus();
        hertz - (2.0 * std::f64::consts::PI * w * a / e).sqrt()
    };
    let delta = if w <= 0.0 {
        hertz
    } else {
        match scene.adhesion_model {
            AdhesionModel::Dmt => hertz,
            AdhesionModel::Jkr => jkr(),
            AdhesionModel::LennardJones => {
                let c = scene.coefficients();
                let z0 = scene.interatomic_distance / s;
                match RoughLaw::new(c.c_0, c.c_h, z0) {
                    Some(law) => {
                        // â = a (K/(πγR²))^{1/3}; Δ in units of σ.
                        let k = 4.0 / 3.0 * scene.equivalent_modulus();
                        let unit = (std::f64::consts::PI * w * r * r / k).cbrt();
                        law.interference_at_contact_radius(a / unit) * s
                    }
                    None if tabor(c.c_0, z0) > 1.0 => jkr(),
                    None => hertz,
                }
            }
        }
    };
    // Beyond 1e4 σ no Gaussian summit reaches (the shares are 0 from 1e3).
    let cut = delta / s;
    if cut.is_nan() {
        0.0
    } else {
        cut.clamp(0.0, 1e4)
    }
}

/// The shares (of the contacts, of the πRδ real area) of the junctions wider
/// than d* at separation `h`, every interference over σ: elastic summits
/// (below `critical`, Δc) are wider beyond `elastic` ([`junction_cut`]),
/// plastic ones (from Δc on, diameter 2√(2Rδ)) beyond `plastic`
/// (d*²/(8R)). The set is (elastic, Δc) ∪ (max(Δc, plastic), ∞): two tails'
/// difference plus a tail of [`debris_fractions`], a plastic junction being
/// narrower at Δc than a JKR or Lennard-Jones summit just below it can be.
/// `critical` = ∞ without plasticity.
pub fn junction_fractions(h: f64, elastic: f64, critical: f64, plastic: f64) -> (f64, f64) {
    let tail = |cut: f64| {
        if cut < 1e4 {
            debris_fractions(h, cut.max(0.0))
        } else {
            (0.0, 0.0)
        }
    };
    let late = tail(critical.max(plastic));
    if elastic < critical {
        let (from, to) = (tail(elastic), tail(critical));
        (
            (from.0 - to.0 + late.0).clamp(0.0, 1.0),
            (from.1 - to.1 + late.1).clamp(0.0, 1.0),
        )
    } else {
        late
    }
}

/// The debris numbers of `scene` at the non-dimensional separation `h` (None when
/// separated) and the critical interference Δc·σ (m, ∞ without plasticity);
/// None without `requirements.shear_strength`. Λ is
/// `requirements.debris_shape_factor` or [`DEFAULT_DEBRIS_SHAPE_FACTOR`].
pub fn debris_of(scene: &Scene, h: Option<f64>, critical_interference: f64) -> Option<Debris> {
    let tau = scene.requirements.shear_strength?;
    let shape = scene
        .requirements
        .debris_shape_factor
        .unwrap_or(DEFAULT_DEBRIS_SHAPE_FACTOR);
    let g = shear_modulus(scene.youngs_modulus_a, scene.poisson_ratio_a);
    let d = critical_junction_size(shape, scene.work_of_adhesion, g, tau);
    let s = scene.sigma;
    let (elastic, plastic) = (
        junction_cut(scene, d),
        d * d / (8.0 * scene.asperity_radius) / s,
    );
    let critical = critical_interference / s;
    let fractions = h.map(|h| {
        junction_fractions(
            h,
            elastic,
            if critical.is_nan() {
                f64::INFINITY
            } else {
                critical
            },
            plastic,
        )
    });
    Some(Debris {
        critical_junction_size: d,
        debris_contact_fraction: fractions.map(|f| f.0),
        debris_area_fraction: fractions.map(|f| f.1),
        wear_mechanism: fractions.map(|f| WearMechanism::of(f.1)),
        shear_modulus: g,
        debris_shape_factor: shape,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// h of the shipped hub (`problems/micro-gear.toml`, Lennard-Jones law, 800 µN).
    const HUB_H: f64 = 2.082_115_779_067_568;

    /// The table for the hub (σ = 3 nm, R = 1 µm, polysilicon E = 160 GPa,
    /// ν = 0.22 so G = 65.57 GPa, w = 0.1 J/m², Λ = 12): (τ_j, d*, contact share,
    /// area share). The references are mpmath at 40 digits of the same closed
    /// forms, the area share checked against mpmath quadrature of (z − h)φ(z)
    /// over z > h + δ*/σ (the two agree to 15 digits): `scripts/reference_debris.py`.
    const TABLE: [(f64, f64, f64, f64); 3] = [
        (1e9, 7.86885245902e-8, 0.251097679393895, 0.572657675313914),
        (2e9, 1.96721311475e-8, 0.923716547827155, 0.996659111278884),
        (
            0.5e9,
            3.14754098361e-7,
            1.27110200451798e-23,
            2.9159233626524e-22,
        ),
    ];

    #[test]
    fn the_hub_table() {
        let g = shear_modulus(160e9, 0.22);
        assert!((g - 65.5737704918e9).abs() < 1e2, "{g}");
        for (tau, d_ref, count_ref, area_ref) in TABLE {
            let d = critical_junction_size(12.0, 0.1, g, tau);
            assert!((d / d_ref - 1.0).abs() < 1e-11, "τ {tau}: d* {d}");
            let cut = d * d / (4.0 * 1e-6) / 3e-9;
            let (count, area) = debris_fractions(HUB_H, cut);
            // erfcx is good to a few ulps; the far tail's ratio to 1e-12.
            assert!((count / count_ref - 1.0).abs() < 1e-12, "τ {tau}: {count}");
            assert!((area / area_ref - 1.0).abs() < 1e-12, "τ {tau}: {area}");
        }
        // The rounded number.
        let d = critical_junction_size(12.0, 0.1, g, 1e9);
        assert_eq!(format!("{:.1}", d * 1e9), "78.7");
    }

    /// No cut: every contact and all the area; a cut beyond every double: none.
    #[test]
    fn limits_of_the_cut() {
        for h in [-30.0, -2.0, 0.0, 2.0, 15.0, 40.0] {
            let (c, a) = debris_fractions(h, 0.0);
            assert!(
                (c - 1.0).abs() < 1e-13 && (a - 1.0).abs() < 1e-12,
                "h {h}: {c} {a}"
            );
            assert_eq!(debris_fractions(h, 1e3), (0.0, 0.0), "h {h}");
        }
    }

    /// Far out (h = 40, where Q(h) itself is 3.6e-350 and underflows) the
    /// shares stay finite and follow the Gaussian tail: with T_0(u) ≈ e^{−u²/2}/u
    /// and T_1(u) ≈ e^{−u²/2}/u² (each to a relative 1/u²), the contact share is
    /// (h/a) e^{−(a² − h²)/2} and the area share (1/a² + cut/a) h² e^{−(a² − h²)/2},
    /// to the size of the next term (a few 1/h² ≈ 6e-4).
    #[test]
    fn far_tail_does_not_underflow() {
        let (h, cut) = (40.0, 0.05);
        let a: f64 = h + cut;
        let e = (-(a * a - h * h) / 2.0).exp();
        let (c, ar) = debris_fractions(h, cut);
        let c_asym = h / a * e;
        assert!((c / c_asym - 1.0).abs() < 2.0 / (h * h), "{c} {c_asym}");
        // T_1(u) ≈ φ-scaled 1/u², T_0(u) ≈ 1/u: area ≈ (1/a² + cut/a) h² e.
        let a_asym = (1.0 / (a * a) + cut / a) * h * h * e;
        assert!((ar / a_asym - 1.0).abs() < 3.0 / (h * h), "{ar} {a_asym}");
        assert!(c > 0.0 && c < 1.0 && ar > c);
    }

    /// The union of stretches against an independent quadrature: composite
    /// Simpson on each stretch of u = δ/σ (ends exact, 20 000 panels, the
    /// tail cut at u = 14 where φ(h + u) < 1e-50) of φ(h + u) and u φ(h + u),
    /// over the same on (0, 14), to 1e-12.
    #[test]
    fn a_plastic_stretch_against_quadrature() {
        let h = 1.5;
        let simpson = |f: &dyn Fn(f64) -> f64, a: f64, b: f64| {
            let n = 20_000;
            let step = (b - a) / n as f64;
            let mut sum = f(a) + f(b);
            for k in 1..n {
                sum += f(a + k as f64 * step) * if k % 2 == 1 { 4.0 } else { 2.0 };
            }
            sum * step / 3.0
        };
        let count = |u: f64| (-0.5 * (h + u) * (h + u)).exp();
        let area = |u: f64| u * count(u);
        let shares = |stretches: &[(f64, f64)]| {
            let part = |f: &dyn Fn(f64) -> f64| {
                stretches
                    .iter()
                    .map(|&(a, b)| simpson(f, a, b))
                    .sum::<f64>()
                    / simpson(f, 0.0, 14.0)
            };
            (part(&count), part(&area))
        };
        type Stretches = Vec<(f64, f64)>;
        let cases: [((f64, f64, f64), Stretches); 3] = [
            ((0.35, 0.84, 1.26), vec![(0.35, 0.84), (1.26, 14.0)]),
            ((1.05, 0.84, 0.56), vec![(0.84, 14.0)]),
            ((0.35, f64::INFINITY, 1.0), vec![(0.35, 14.0)]),
        ];
        for ((elastic, critical, plastic), stretches) in cases {
            let got = junction_fractions(h, elastic, critical, plastic);
            let want = shares(&stretches);
            assert!(
                (got.0 - want.0).abs() < 1e-12 && (got.1 - want.1).abs() < 1e-12,
                "{elastic} {critical} {plastic}: {got:?} {want:?}"
            );
        }
    }

    #[test]
    fn mechanism_thresholds() {
        assert_eq!(WearMechanism::of(0.0099), WearMechanism::Smoothing);
        assert_eq!(WearMechanism::of(0.01), WearMechanism::Mixed);
        assert_eq!(WearMechanism::of(0.5), WearMechanism::Mixed);
        assert_eq!(WearMechanism::of(0.5001), WearMechanism::Debris);
        assert!(assumes_smoothing("stress_assisted"));
        assert!(!assumes_smoothing("archard"));
    }
}
