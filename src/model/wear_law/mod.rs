//! The wear laws: how a contact's real area and stresses become a wear rate
//! (docs/model.md §3 and §12). Each law is a module implementing the trait
//! [`WearLaw`] on a unit struct (`archard.rs`); [`WearModel::law`] is the
//! registry that lists them, and the one line a new law adds. The evaluation
//! (`wear.rs`), the reports and the problem file read the trait; none of them
//! names a law.

mod archard;
pub mod inputs;
pub mod stress_assisted;

pub use inputs::{
    Activation, ContactStress, WearModel, ATTEMPT_FREQUENCY, MAX_ACTIVATION_ENERGY,
    MAX_ACTIVATION_VOLUME, MAX_ATOMIC_VOLUME_RATIO,
};

use serde::Serialize;

use super::integrals::Model;
use super::scaled::Scaled;
use super::scene::Scene;

/// A wear law's own numbers beside the wear rate (the stress-assisted law's,
/// docs/model.md §12), SI; flattened into an evaluation's JSON.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WearDetails {
    /// The law.
    pub wear_law: WearModel,
    /// k_eff = wear rate / wearing area (A_r, or A_rp under `wear_area =
    /// "plastic"`); None without a wearing area.
    pub effective_wear_coefficient: Option<f64>,
    /// log10 of k_eff, finite where k_eff itself underflows to 0 (a cold or
    /// slow contact: the rate is carried in logarithms, docs/model.md §12);
    /// None where k_eff is None or there is no wear.
    pub log10_effective_wear_coefficient: Option<f64>,
    /// The area-weighted mean of the stress that assists (Pa); None without contact.
    pub mean_contact_stress: Option<f64>,
    /// The share of the rate from summits with Γa₀/v > 1; None without wear.
    pub saturated_fraction: Option<f64>,
    /// −d ln(rate)/d(1/k_BT) at fixed contact (J); None without wear.
    pub apparent_activation_energy: Option<f64>,
    /// T (K) the law was taken at.
    pub temperature: f64,
}

/// What a wear law is given at the operating point of one evaluation.
#[derive(Debug, Clone, Copy)]
pub struct WearInput<'a> {
    /// The scene (its wear coefficient, wearing area, law settings).
    pub scene: &'a Scene,
    /// The scene's non-dimensional model.
    pub model: &'a Model,
    /// h = d/σ at the operating point; None without contact.
    pub separation: Option<f64>,
    /// The non-dimensional wearing area (Ā, or Ā_p under `wear_area = "plastic"`),
    /// scaled as the model's integrals are.
    pub wearing_area: Scaled,
    /// Ā_p, the plastic junctions' share of Ā.
    pub plastic_area: Scaled,
    /// The elastic summits' share of the load P̄ (their Σ p, in the model's
    /// units), scaled as the model's integrals are.
    pub elastic_load: Scaled,
    /// The real area one unit of Ā stands for (m²): A_n π N R σ / √(2π) times the
    /// scene's real-area scale.
    pub area_scale: f64,
    /// E, the equivalent modulus of the pair (Pa; docs/model.md §1).
    pub equivalent_modulus: f64,
}

/// A wear law's answer: the wear rate and, for a law that computes them, its
/// own numbers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WearOutcome {
    /// V/L, the wear volume per sliding distance (m³/m), scaled so that it keeps a
    /// logarithm where it underflows.
    pub rate: Scaled,
    /// The law's own numbers (None under Archard, whose k is an input).
    pub details: Option<WearDetails>,
}

/// One wear law as its module gives it: the registry's entry (its names, a
/// report's words) and its rate. Nothing outside the law's module and
/// [`WearModel::law`] names a law.
pub trait WearLaw: Sync {
    /// The word used in problem files and reports (`[wear] law`).
    fn name(&self) -> &'static str;
    /// Its short name in prose ("Archard").
    fn label(&self) -> &'static str;
    /// Its formula as a report heads its section with ("V = k A L").
    fn formula(&self) -> &'static str;
    /// Where docs/model.md states it ("docs/model.md §3").
    fn section(&self) -> &'static str;
    /// The wear rate at the operating point.
    fn rate(&self, input: &WearInput<'_>) -> WearOutcome;
}

impl WearModel {
    /// Every wear law, in the order problem files and messages list them.
    pub const ALL: [WearModel; 2] = [WearModel::Archard, WearModel::StressAssisted];

    /// The law's module. **The registration**: a new law is a variant of
    /// `WearModel`, its module, and one line here.
    pub fn law(self) -> &'static dyn WearLaw {
        match self {
            WearModel::Archard => &archard::Archard,
            WearModel::StressAssisted => &stress_assisted::StressAssisted,
        }
    }

    /// The word used in problem files and reports.
    pub fn as_str(self) -> &'static str {
        self.law().name()
    }

    /// The law named `name` (as [`WearModel::as_str`] writes it).
    pub fn from_name(name: &str) -> Option<WearModel> {
        Self::ALL.into_iter().find(|m| m.as_str() == name)
    }

    /// The names of every law, in order.
    pub fn names() -> Vec<&'static str> {
        Self::ALL.into_iter().map(WearModel::as_str).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each name reads back as its law, and the default is today's Archard.
    #[test]
    fn names_round_trip() {
        for m in WearModel::ALL {
            assert_eq!(WearModel::from_name(m.as_str()), Some(m));
        }
        assert_eq!(WearModel::default().as_str(), "archard");
        assert_eq!(WearModel::from_name("Archard"), None);
    }
}
