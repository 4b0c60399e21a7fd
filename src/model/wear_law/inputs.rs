//! What a scene says of its wear law (docs/model.md §3, §12): the law's name,
//! the stress-assisted law's inputs and their accepted ranges. Plain data,
//! importing nothing of the model, so that the scene can hold it without
//! depending on the laws that compute with it ([`super`]).

use serde::Serialize;

/// The wear laws by name (`[wear] law`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WearModel {
    /// V = k A L (docs/model.md §3): the wear coefficient k is an input.
    #[default]
    Archard,
    /// Atom-by-atom removal, thermally activated and assisted by the contact
    /// stress (docs/model.md §12): k follows from ΔU, ΔV, f₀, T and the speed.
    StressAssisted,
}

/// Which stress assists the stress-assisted law (`[wear] stress`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ContactStress {
    /// Each summit's mean contact pressure P/A under the asperity law (H on a
    /// plastic junction).
    #[default]
    Normal,
    /// The interface's shear strength τ, the same on every summit.
    Shear,
}

impl ContactStress {
    /// Both, in the order messages list them.
    pub const ALL: [ContactStress; 2] = [ContactStress::Normal, ContactStress::Shear];

    /// The word used in problem files.
    pub fn as_str(self) -> &'static str {
        match self {
            ContactStress::Normal => "normal",
            ContactStress::Shear => "shear",
        }
    }
}

/// The inputs of the stress-assisted law (docs/model.md §12), SI. The ranges are
/// those [`crate::model::Scene::validate`] checks.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Activation {
    /// ΔU, the activation energy (J), in (0, 10 eV].
    pub activation_energy: f64,
    /// ΔV, the activation volume (m³), in [0, 1 nm³].
    pub activation_volume: f64,
    /// f₀, the attempt frequency (Hz), > 0, finite.
    pub attempt_frequency: f64,
    /// a₀, the spacing of surface sites (m), > 0, finite.
    pub site_spacing: f64,
    /// Ω, the volume one removed atom takes (m³), in (0, 10 a₀³].
    pub atomic_volume: f64,
    /// Which stress assists.
    pub stress: ContactStress,
    /// v, the sliding speed (m/s), > 0, finite.
    pub sliding_speed: f64,
}

/// Default attempt frequency f₀ (Hz): a lattice vibration.
pub const ATTEMPT_FREQUENCY: f64 = 1e13;

/// The largest activation energy accepted (J): 10 eV.
pub const MAX_ACTIVATION_ENERGY: f64 = 10.0 * crate::units::ELECTRON_VOLT;

/// The largest activation volume accepted (m³): 1 nm³.
pub const MAX_ACTIVATION_VOLUME: f64 = 1e-27;

/// The largest atomic volume accepted, over a₀³.
pub const MAX_ATOMIC_VOLUME_RATIO: f64 = 10.0;
