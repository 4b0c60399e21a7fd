//! The dimensional description of one contact (a "scene"), in SI units.

use serde::Serialize;

use super::law::{AdhesionModel, AttractionKind};

/// Which real area wears (paper eq. 13): all contacts, or only the plastic
/// ("welded") junctions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "lowercase")]
pub enum WearArea {
    /// Every contact wears: `A_r` is the total real area.
    #[default]
    Total,
    /// Only plastic junctions wear: `A_rp`.
    Plastic,
}

/// One contact between a rough, softer body `a` and a counterface `b`.
///
/// All fields are SI. `f64::INFINITY` is allowed where a limit makes sense:
/// `youngs_modulus_b` (a rigid counterface) and `hardness` (no plasticity).
/// `work_of_adhesion = 0` means no adhesion. Construct through
/// [`crate::problem`] to get validation, or check a scene built by hand with
/// [`Scene::validate`]; the model assumes a valid scene.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scene {
    /// E1, Young's modulus of the rough body a (Pa), > 0, finite.
    pub youngs_modulus_a: f64,
    /// ν1, Poisson ratio of body a, in (-1, 0.5].
    pub poisson_ratio_a: f64,
    /// E2, Young's modulus of the counterface b (Pa), > 0, may be +inf (rigid).
    pub youngs_modulus_b: f64,
    /// ν2, Poisson ratio of body b, in (-1, 0.5].
    pub poisson_ratio_b: f64,
    /// H, hardness of the softer body (Pa), > 0, may be +inf (no plasticity).
    pub hardness: f64,
    /// γ, work of adhesion (J/m² = N/m), ≥ 0 (0: no adhesion).
    pub work_of_adhesion: f64,
    /// Z0, equilibrium interatomic distance (m), > 0: the Tabor parameter and,
    /// under DMT, the range of the attraction (z0 = Z0/σ, Δ_h = Z0/(1.03σ)).
    pub interatomic_distance: f64,
    /// σ, standard deviation of asperity heights (m), > 0.
    pub sigma: f64,
    /// R, asperity tip radius (m), > 0.
    pub asperity_radius: f64,
    /// N, asperities per unit nominal area (1/m²), > 0.
    pub asperity_density: f64,
    /// W, normal load (N); positive is compressive, negative pulls the bodies apart.
    pub load: f64,
    /// A_n, nominal contact area (m²), > 0.
    pub nominal_area: f64,
    /// L, sliding distance (m), ≥ 0.
    pub sliding_distance: f64,
    /// k, dimensionless Archard wear coefficient, ≥ 0.
    pub wear_coefficient: f64,
    /// Which real area wears.
    pub wear_area: WearArea,
    /// What the designer judges the contact by: allowed wear, cycles, the spring that
    /// must free the part, the interface's shear strength (all optional).
    pub requirements: Requirements,
    /// The asperity law (docs/model.md §3 JKR, §7 DMT). Reported at the top level of
    /// an evaluation, not inside the scene.
    #[serde(skip)]
    pub adhesion_model: AdhesionModel,
    /// Under DMT: how non-contacting asperities are attracted (ignored under JKR).
    #[serde(skip)]
    pub attraction: AttractionKind,
}

/// The optional inputs of the numbers a designer decides on: life, stiction, friction.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
pub struct Requirements {
    /// The wear depth the part may lose over its life (m), > 0.
    pub allowed_wear_depth: Option<f64>,
    /// The sliding distance of one cycle (m), > 0: turns the life into cycles.
    pub sliding_per_cycle: Option<f64>,
    /// The force available to pull the surfaces apart (a spring's restoring force, N), > 0.
    pub restoring_force: Option<f64>,
    /// τ, the shear strength of the junctions (Pa), > 0: friction F = τ A_r (Bowden–Tabor).
    pub shear_strength: Option<f64>,
}

/// A scene or quadrature setting the model cannot use: the field, its value and
/// what is accepted.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{field} = {value}: must be {accepted}")]
pub struct InputError {
    /// The field, as the struct names it (`sigma`, `requirements.restoring_force`,
    /// `order`).
    pub field: &'static str,
    /// The value given.
    pub value: f64,
    /// The accepted values, in words (`finite and > 0`).
    pub accepted: &'static str,
}

/// `Ok` when `ok(value)`, else the error naming `field`, `value` and `accepted`.
pub(crate) fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    accepted: &'static str,
) -> Result<(), InputError> {
    if ok {
        Ok(())
    } else {
        Err(InputError {
            field,
            value,
            accepted,
        })
    }
}

impl Scene {
    /// Checks every field the model reads: finite and in the range its
    /// documentation states (`f64::INFINITY` only where a limit is meant). The
    /// problem loader builds only scenes that pass; a scene built by hand must
    /// pass before it is evaluated, or the numbers mean nothing.
    pub fn validate(&self) -> Result<(), InputError> {
        const POSITIVE: &str = "finite and > 0";
        const NON_NEGATIVE: &str = "finite and ≥ 0";
        let positive = |x: f64| x.is_finite() && x > 0.0;
        let non_negative = |x: f64| x.is_finite() && x >= 0.0;
        let poisson = |x: f64| x > -1.0 && x <= 0.5;
        let e_a = self.youngs_modulus_a;
        check("youngs_modulus_a", e_a, positive(e_a), POSITIVE)?;
        let nu_a = self.poisson_ratio_a;
        check("poisson_ratio_a", nu_a, poisson(nu_a), "in (-1, 0.5]")?;
        let e_b = self.youngs_modulus_b;
        check("youngs_modulus_b", e_b, e_b > 0.0, "> 0 (inf: rigid)")?;
        let nu_b = self.poisson_ratio_b;
        check("poisson_ratio_b", nu_b, poisson(nu_b), "in (-1, 0.5]")?;
        let h = self.hardness;
        check("hardness", h, h > 0.0, "> 0 (inf: no plasticity)")?;
        for (field, value) in [
            ("work_of_adhesion", self.work_of_adhesion),
            ("sliding_distance", self.sliding_distance),
            ("wear_coefficient", self.wear_coefficient),
        ] {
            check(field, value, non_negative(value), NON_NEGATIVE)?;
        }
        for (field, value) in [
            ("interatomic_distance", self.interatomic_distance),
            ("sigma", self.sigma),
            ("asperity_radius", self.asperity_radius),
            ("asperity_density", self.asperity_density),
            ("nominal_area", self.nominal_area),
        ] {
            check(field, value, positive(value), POSITIVE)?;
        }
        check(
            "load",
            self.load,
            self.load.is_finite(),
            "finite (negative pulls the bodies apart)",
        )?;
        let r = &self.requirements;
        for (field, value) in [
            ("requirements.allowed_wear_depth", r.allowed_wear_depth),
            ("requirements.sliding_per_cycle", r.sliding_per_cycle),
            ("requirements.restoring_force", r.restoring_force),
            ("requirements.shear_strength", r.shear_strength),
        ] {
            if let Some(x) = value {
                check(field, x, positive(x), POSITIVE)?;
            }
        }
        Ok(())
    }
}
