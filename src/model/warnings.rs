//! What an evaluation wants the designer to know, as values: the report words them.
//!
//! A [`Warning`] is a condition under which the numbers may not mean what they seem
//! (outside the model's assumptions, an implausible input, a search that did not
//! converge); a [`Note`] is information (a regime, a value reported as 0 because it
//! underflows). Neither is an error: the evaluation still returns every number.

use serde::Serialize;

use super::parameter::SceneParameter;
use super::scene::Scene;

/// Conditions the designer must know; the report words them.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Warning {
    /// φ0 < 3 with the JKR law: the elastic asperities are outside the regime it holds in.
    OutsideJkrRegime {
        /// φ0.
        tabor_parameter: f64,
    },
    /// φ0 > 0.3 with the DMT law: outside the regime it holds in (above 3: JKR's;
    /// 0.3–3: the transition, where the two laws bracket the truth).
    OutsideDmtRegime {
        /// φ0.
        tabor_parameter: f64,
    },
    /// The separation search stopped without converging.
    SeparationNotConverged {
        /// Model evaluations spent.
        evaluations: usize,
        /// The best estimate of h.
        separation: f64,
    },
    /// |P̄| beyond what the model describes.
    LoadBeyondModel {
        /// P̄.
        nondimensional_load: f64,
        /// The largest |P̄| described.
        limit: f64,
    },
    /// A_r/A_n > 0.1: neighbouring asperities interact, outside Greenwood–Williamson.
    DenseContact {
        /// A_r/A_n.
        real_area_fraction: f64,
    },
    /// A_r > A_n: no real contact is larger than the nominal one (status out_of_range).
    RealAreaExceedsNominal {
        /// A_r/A_n.
        real_area_fraction: f64,
    },
    /// Fewer than [`MIN_CONTACTS`] asperities in contact: the statistics do not hold.
    FewContacts {
        /// The expected number of contacts.
        contact_count: f64,
    },
    /// σ ≥ R: the asperities are not gentle caps on a rough surface.
    RoughnessNotBelowRadius {
        /// σ (m).
        sigma: f64,
        /// R (m).
        asperity_radius: f64,
    },
    /// ηRσ outside 0.01–0.2, where measured surfaces lie (Greenwood–Williamson's
    /// surfaces have 0.03–0.05).
    SummitParameter {
        /// N R σ.
        product: f64,
    },
    /// An input of a magnitude no MEMS or storage contact has: a forgotten unit?
    ImplausibleInput {
        /// Which input.
        input: SceneParameter,
        /// Its value (SI).
        value: f64,
        /// The plausible range (SI).
        plausible_min: f64,
        /// The plausible range (SI).
        plausible_max: f64,
    },
    /// The condensing liquid is water and T is below its freezing point
    /// (273.15 K): ice, not a liquid meniscus, and the Kelvin equation of
    /// docs/model.md §10 does not hold; a temperature meant in °C and read in
    /// kelvin (`temperature = 25`) looks so.
    LiquidBelowFreezing {
        /// T (K).
        temperature: f64,
        /// The liquid's freezing point (K).
        freezing_point: f64,
    },
    /// The Kelvin radius is below 0.5 nm (RH ≲ 35 % for water at 25 °C): the
    /// continuum Kelvin and Laplace equations of docs/model.md §10 are doubtful there.
    KelvinRadiusBelowContinuum {
        /// r_K (m).
        kelvin_radius: f64,
    },
    /// The scene has adhesion but the pull-off search found no minimum of P̄(h)
    /// (not expected: docs/model.md §4 proves there is one; reported, not hidden).
    PullOffNotFound {
        /// Model evaluations spent.
        evaluations: usize,
    },
    /// The pull-off minimum lies beyond |h| = 1e6 (adhesion so weak that P̄ there is
    /// ~e^{-h²/2} < e^{-5e11}): outside the separations the model resolves, so no
    /// pull-off force is reported; it is far below any force a double can hold.
    PullOffBeyondModel {
        /// The minimum's h as found (over σ).
        separation: f64,
        /// The largest |h| the model resolves.
        limit: f64,
    },
    /// A result came out non-finite (status out_of_range).
    NonFiniteResult {
        /// The result's JSON key.
        quantity: &'static str,
    },
    /// More than half of the real area is in junctions wider than the critical
    /// size d* (docs/model.md §13): they break off debris particles. Built by
    /// [`super::debris::Debris::warning`] from the wear law's name.
    DebrisRegime {
        /// The wear law in use (`archard`, …).
        wear_law: &'static str,
        /// Whether that law removes material atom by atom (assumes smoothing).
        assumes_smoothing: bool,
        /// The share of the real area in junctions wider than d*.
        debris_area_fraction: f64,
        /// d* (m).
        critical_junction_size: f64,
    },
}

/// Information beside the numbers; the report words it.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Note {
    /// θ ≤ 10.
    ElasticAdhesionMatters {
        /// θ.
        elastic_adhesion_index: f64,
    },
    /// λ ≤ 0.125.
    PlasticAdhesionMatters {
        /// λ.
        plastic_adhesion_index: f64,
    },
    /// The plastic load jump is negative: several branches, the loading one is used.
    LoadDropsAtTransition,
    /// The surfaces separate (tensile load beyond pull-off, or no load without adhesion).
    Separated {
        /// Whether the scene has adhesion.
        adhesion: bool,
    },
    /// The pull-off force underflows a double and is reported as 0.
    PullOffUnderflow {
        /// log10 of the force in N.
        log10_force: f64,
    },
    /// The real area underflows a double and is reported as 0.
    RealAreaUnderflow {
        /// log10 of the area in m².
        log10_area: f64,
    },
    /// Under the Lennard-Jones law, φ0 lies outside its curves (0.01–3.6e6) and
    /// the closed-form law there stands in.
    LennardJonesStandIn {
        /// φ0.
        tabor_parameter: f64,
        /// The law whose numbers stand in.
        stand_in: super::law::AdhesionModel,
        /// The relative error of its pull-off at the curves' end: below, one
        /// asperity's; above, the rough surface's (where adhesion is strong).
        pull_off_error: f64,
    },
    /// The debris shares take each junction's diameter as its contact
    /// diameter (docs/model.md §13): an elastic summit's under the scene's law,
    /// a plastic junction's 2√(2Rδ).
    DebrisJunctionSizes {
        /// The scene's asperity law.
        adhesion_model: super::law::AdhesionModel,
    },
    /// Under the Lennard-Jones law, φ0 lies above the solved table (22.4):
    /// the law's curves there are the closed-form limit curves (JKR's contact
    /// branch from the sphere's jump in).
    LennardJonesLimitCurves {
        /// φ0.
        tabor_parameter: f64,
        /// The rough surface's pull-off under the limit curve against the
        /// solved sphere's at the table's end (relative).
        pull_off_error: f64,
    },
}

/// Below this many expected contacts the Gaussian statistics of the model do not hold.
pub const MIN_CONTACTS: f64 = 10.0;

/// Above this real-area fraction asperities interact.
pub const DENSE_CONTACT_FRACTION: f64 = 0.1;

/// The range of η R σ where measured surfaces lie.
pub const SUMMIT_PARAMETER_RANGE: (f64, f64) = (0.01, 0.2);

/// The freezing point of water at 1 atm (K): 0 °C.
pub const WATER_FREEZING_POINT: f64 = 273.15;

/// Warnings that follow from the scene alone: implausible magnitudes, σ ≥ R, ηRσ.
pub fn scene_warnings(scene: &Scene) -> Vec<Warning> {
    let mut w = Vec::new();
    for input in SceneParameter::CHECKED {
        let value = input.get(scene);
        let Some((lo, hi)) = input.plausible_range() else {
            continue;
        };
        // Zero (no load, no adhesion) and infinity (rigid, no plasticity) are exact limits.
        if value == 0.0 || value.is_infinite() || value.is_nan() {
            continue;
        }
        if !(lo..=hi).contains(&value) {
            w.push(Warning::ImplausibleInput {
                input,
                value,
                plausible_min: lo,
                plausible_max: hi,
            });
        }
    }
    if let Some(env) = scene.environment {
        if env.liquid == super::environment::Liquid::Water && env.temperature < WATER_FREEZING_POINT
        {
            w.push(Warning::LiquidBelowFreezing {
                temperature: env.temperature,
                freezing_point: WATER_FREEZING_POINT,
            });
        }
    }
    if scene.sigma >= scene.asperity_radius {
        w.push(Warning::RoughnessNotBelowRadius {
            sigma: scene.sigma,
            asperity_radius: scene.asperity_radius,
        });
    }
    let product = scene.asperity_density * scene.asperity_radius * scene.sigma;
    let (lo, hi) = SUMMIT_PARAMETER_RANGE;
    if product.is_finite() && !(lo..=hi).contains(&product) {
        w.push(Warning::SummitParameter { product });
    }
    w
}
