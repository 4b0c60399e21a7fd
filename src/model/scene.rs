//! The dimensional description of one contact (a "scene"), in SI units.

use serde::Serialize;

use super::environment::Environment;
use super::law::{AdhesionModel, AttractionKind};
use super::wear_law::inputs::{self as wear_law, Activation, ContactStress, WearModel};

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
    /// The wear law (docs/model.md §3 Archard); reported beside the wear, not
    /// inside the scene.
    #[serde(skip)]
    pub wear_law: WearModel,
    /// T, the temperature of the contact (K), > 0, finite: the capillary term's
    /// (docs/model.md §10, where `environment.temperature` equals it) and the
    /// stress-assisted wear law's (§12). 298.15 K unless the file says otherwise.
    #[serde(skip)]
    pub temperature: f64,
    /// The stress-assisted law's inputs (docs/model.md §12): Some exactly when
    /// `wear_law` is [`WearModel::StressAssisted`].
    #[serde(skip)]
    pub activation: Option<Activation>,
    /// A measured factor on the statistical model's real area (and so on its wear
    /// and friction), > 0, finite: 1 for the model as it is;
    /// `[roughness] contact_model = "bem_corrected"` sets it to the exact-to-statistical
    /// ratio of real areas on the scene's scan at the file's operating point.
    pub real_area_scale: f64,
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
    /// The humid air around the contact (docs/model.md §10: the problem file's
    /// `[environment]`); None is dry air, the paper's scene.
    #[serde(skip)]
    pub environment: Option<Environment>,
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
    /// Λ, the shape factor of the critical junction size d* = Λ w G / τ_j² beyond
    /// which a junction makes debris (docs/model.md §13), > 0; None is the default
    /// [`super::debris::DEFAULT_DEBRIS_SHAPE_FACTOR`] (12). Used only with `shear_strength`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub debris_shape_factor: Option<f64>,
    /// A cantilever beam held down by the interface: turns the apparent work of
    /// adhesion into the longest beam that comes free (de Boer & Michalske 1999).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cantilever: Option<Cantilever>,
}

/// A cantilever beam over the contact (the `[stiction] cantilever` table), SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Cantilever {
    /// t, the beam's thickness (m), > 0.
    pub thickness: f64,
    /// h_g, the gap under the beam (m), > 0.
    pub gap: f64,
    /// E_b, the beam's Young's modulus (Pa), > 0.
    pub youngs_modulus: f64,
}

impl Cantilever {
    /// l_c = (3 E_b t³ h_g² / (2Γ))^{1/4}: the longest beam that does not stay stuck
    /// in an S-shape at an apparent work of adhesion Γ (J/m²); None for Γ ≤ 0
    /// (every length comes free).
    pub fn detachment_length(&self, work_of_adhesion: f64) -> Option<f64> {
        let (t, g) = (self.thickness, self.gap);
        (work_of_adhesion > 0.0).then(|| {
            (1.5 * self.youngs_modulus * t * t * t * g * g / work_of_adhesion)
                .sqrt()
                .sqrt()
        })
    }
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
    /// E = [(1-ν1²)/E1 + (1-ν2²)/E2]⁻¹ (Pa); E2 = ∞ is a rigid counterface.
    pub fn equivalent_modulus(&self) -> f64 {
        let compliance = |e: f64, nu: f64| {
            if e.is_infinite() {
                0.0
            } else {
                (1.0 - nu * nu) / e
            }
        };
        1.0 / (compliance(self.youngs_modulus_a, self.poisson_ratio_a)
            + compliance(self.youngs_modulus_b, self.poisson_ratio_b))
    }

    /// The load-law coefficients (docs/model.md §3), computed directly (never
    /// via θ and λ) so that γ = 0 and H = ∞ are exact.
    pub fn coefficients(&self) -> super::coefficients::Coefficients {
        use std::f64::consts::PI;
        let k = 4.0 / 3.0 * self.equivalent_modulus();
        let (r, s) = (self.asperity_radius, self.sigma);
        // c_a² = 6π/θ = 6π γ R^{1/2} / (K σ^{3/2}).
        let c_a = (6.0 * PI * self.work_of_adhesion * r.sqrt() / (k * s * s.sqrt())).sqrt();
        // c_h = π R^{1/2} H / (K σ^{1/2}).
        let c_h = PI * r.sqrt() * self.hardness / (k * s.sqrt());
        super::coefficients::Coefficients::new(c_a, c_h)
    }

    /// The wear law's inputs: present and in range exactly under the
    /// stress-assisted law, which also needs τ under `stress = "shear"`.
    fn validate_wear_law(&self) -> Result<(), InputError> {
        let Some(a) = self.activation else {
            return match self.wear_law {
                WearModel::Archard => Ok(()),
                WearModel::StressAssisted => Err(InputError {
                    field: "activation",
                    value: f64::NAN,
                    accepted: "given under the stress-assisted wear law",
                }),
            };
        };
        if self.wear_law == WearModel::Archard {
            return Err(InputError {
                field: "activation",
                value: a.activation_energy,
                accepted: "absent under the Archard wear law (it takes k alone)",
            });
        }
        let positive = |x: f64| x.is_finite() && x > 0.0;
        let du = a.activation_energy;
        check(
            "activation.activation_energy",
            du,
            du > 0.0 && du <= wear_law::MAX_ACTIVATION_ENERGY,
            "in (0, 10 eV]",
        )?;
        let dv = a.activation_volume;
        check(
            "activation.activation_volume",
            dv,
            (0.0..=wear_law::MAX_ACTIVATION_VOLUME).contains(&dv),
            "in [0, 1 nm³]",
        )?;
        for (field, value) in [
            ("activation.attempt_frequency", a.attempt_frequency),
            ("activation.site_spacing", a.site_spacing),
            ("activation.sliding_speed", a.sliding_speed),
        ] {
            check(field, value, positive(value), "finite and > 0")?;
        }
        let omega = a.atomic_volume;
        check(
            "activation.atomic_volume",
            omega,
            omega > 0.0 && omega <= wear_law::MAX_ATOMIC_VOLUME_RATIO * a.site_spacing.powi(3),
            "in (0, 10 a₀³]",
        )?;
        match a.stress {
            ContactStress::Shear => check(
                "requirements.shear_strength",
                f64::NAN,
                self.requirements.shear_strength.is_some(),
                "given: stress = shear reads τ",
            ),
            // Every asperity law gives its summits' loads (the Lennard-Jones
            // law's from its curves, interpolated in μ).
            ContactStress::Normal => Ok(()),
        }
    }

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
            ("real_area_scale", self.real_area_scale),
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
            ("requirements.debris_shape_factor", r.debris_shape_factor),
        ] {
            if let Some(x) = value {
                check(field, x, positive(x), POSITIVE)?;
            }
        }
        if let Some(c) = r.cantilever {
            for (field, value) in [
                ("requirements.cantilever.thickness", c.thickness),
                ("requirements.cantilever.gap", c.gap),
                ("requirements.cantilever.youngs_modulus", c.youngs_modulus),
            ] {
                check(field, value, positive(value), POSITIVE)?;
            }
        }
        let t = self.temperature;
        check("temperature", t, positive(t), "finite and > 0 K")?;
        self.validate_wear_law()?;
        if let Some(env) = &self.environment {
            let rh = env.relative_humidity;
            check(
                "environment.relative_humidity",
                rh,
                (0.0..1.0).contains(&rh),
                "in [0, 1)",
            )?;
            let t = env.temperature;
            check(
                "environment.temperature",
                t,
                positive(t),
                "finite and > 0 K",
            )?;
            check(
                "environment.temperature",
                t,
                t == self.temperature,
                "the scene's temperature (one temperature for the air and the contact)",
            )?;
            for (field, value) in [
                ("environment.contact_angle_a", env.contact_angle_a),
                ("environment.contact_angle_b", env.contact_angle_b),
            ] {
                check(
                    field,
                    value,
                    (0.0..=std::f64::consts::PI).contains(&value),
                    "in [0, π] rad (0° to 180°)",
                )?;
            }
            if let super::environment::Liquid::Given {
                surface_tension,
                molar_volume,
            } = env.liquid
            {
                check(
                    "environment.liquid.surface_tension",
                    surface_tension,
                    positive(surface_tension),
                    POSITIVE,
                )?;
                check(
                    "environment.liquid.molar_volume",
                    molar_volume,
                    positive(molar_volume),
                    POSITIVE,
                )?;
            }
        }
        Ok(())
    }
}
