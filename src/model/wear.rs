//! The dimensional layer: from a [`Scene`] (SI) to indices, separation, real
//! areas, contacts, pull-off and wear under the scene's wear law (docs/model.md
//! §1–3, eqs. 13, 15, 16; the laws in `wear_law/`).

use std::f64::consts::PI;

use serde::Serialize;

use super::capillary::{Capillary, Environment};
use super::coefficients::Coefficients;
use super::integrals::{Integrals, Model};
use super::law::{AdhesionModel, AsperityLaw, AttractionKind};
use super::quadrature::Quadrature;
use super::scaled::Scaled;
use super::scene::{Scene, WearArea};
use super::separation::{
    landscape_from, pull_off_of, solve_separation_at, solve_separation_within, PullOff,
    SeparationOutcome,
};
use super::special::SQRT_TWO_PI;
use super::warnings::{self, Note, Warning};
use super::wear_law::{WearDetails, WearInput};

/// What an evaluation computes beyond the separation and areas.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EvaluationOptions {
    /// Find the pull-off force (a search over h; skipped when false unless the
    /// load is tensile, where the separation solve needs it anyway).
    pub pull_off: bool,
    /// Quadrature settings of the elastic integral.
    pub quadrature: Quadrature,
    /// In humid air (or with a cantilever), also the apparent work of adhesion Γ, an
    /// integral of the load over the separation (about a hundred model evaluations:
    /// `eval` asks for it, studies and sensitivities do not). Needs `pull_off`.
    pub work_of_adhesion: bool,
}

/// Starting points for the separation and pull-off searches (non-dimensional
/// h), e.g. from a nearby design. Only speed depends on them: the branch rules
/// are the same.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SearchHints {
    /// h of the separation.
    pub separation: Option<f64>,
    /// h of the pull-off minimum.
    pub pull_off: Option<f64>,
}

impl Default for EvaluationOptions {
    fn default() -> Self {
        EvaluationOptions {
            pull_off: true,
            quadrature: Quadrature::default(),
            work_of_adhesion: true,
        }
    }
}

/// The outcome of an evaluation: not an error in any case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// The surfaces are in contact at equilibrium under the load.
    Ok,
    /// The load pulls the surfaces apart: no equilibrium in contact.
    Separated,
    /// The separation search did not converge (reported, never hidden).
    NotConverged,
    /// The load is beyond what the model describes (|P̄| above 1e12: the mean
    /// planes would interpenetrate by more than 1e8 σ), e.g. a newton on a
    /// nominal area holding less than one asperity.
    OutOfRange,
}

impl Status {
    /// The status word used in reports.
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Ok => "ok",
            Status::Separated => "separated",
            Status::NotConverged => "not_converged",
            Status::OutOfRange => "out_of_range",
        }
    }
}

/// The four dimensionless indices of docs/model.md §2.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Indices {
    /// θ = K σ^{3/2} R^{1/2} / (γ R) (Fuller–Tabor); ∞ without adhesion.
    pub elastic_adhesion_index: f64,
    /// λ = π² R H⁴ σ / (18 K² γ²) (Johnson); ∞ without adhesion or plasticity.
    pub plastic_adhesion_index: f64,
    /// ψ = (E/H)(σ/R)^{1/2} (Greenwood–Williamson); 0 without plasticity.
    pub plasticity_index: f64,
    /// φ0 = (R γ² / (E² Z0³))^{1/3} (Tabor/Muller); 0 without adhesion.
    pub tabor_parameter: f64,
}

/// Regime classification from the indices.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Regime {
    /// "JKR" (φ0 > 3), "transition" (0.3 ≤ φ0 ≤ 3), "DMT" (φ0 < 0.3) or "none" (γ = 0).
    pub adhesion_model: &'static str,
    /// True when θ ≤ 10: adhesion matters for elastic asperities.
    pub elastic_adhesion_matters: bool,
    /// True when λ ≤ 0.125: adhesion matters for plastic asperities.
    pub plastic_adhesion_matters: bool,
    /// "elastic" (ψ < 0.6), "elastic-plastic" (0.6 ≤ ψ ≤ 1) or "plastic" (ψ > 1).
    pub deformation: &'static str,
}

/// Everything one evaluation of a scene says, in SI units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Evaluation {
    /// ok, separated or not_converged.
    pub status: Status,
    /// Conditions the designer must know (outside the model's assumptions,
    /// implausible inputs, …); the report words them.
    pub warnings: Vec<Warning>,
    /// Informational remarks (regime, underflowed values, …); the report words them.
    pub notes: Vec<Note>,
    /// E = [(1-ν1²)/E1 + (1-ν2²)/E2]⁻¹ (Pa).
    pub equivalent_modulus: f64,
    /// The indices θ, λ, ψ, φ0.
    pub indices: Indices,
    /// Regime classification.
    pub regime: Regime,
    /// Δc·σ: the actual interference at which an asperity turns plastic (m); ∞ without plasticity.
    pub critical_interference: f64,
    /// The force one unit of P̄ stands for over the nominal area: K N R^{1/2} σ^{3/2} A_n / √(2π) (N).
    pub load_scale: f64,
    /// P̄, the load in model units.
    pub nondimensional_load: f64,
    /// d, the mean-plane separation (m); None when separated.
    pub separation: Option<f64>,
    /// h = d/σ; None when separated.
    pub nondimensional_separation: Option<f64>,
    /// A_r = A_n π N R σ Ā / √(2π) (m²): every contact counted as πRδ (the paper's measure).
    pub real_area: f64,
    /// log10 of A_r (finite even where A_r underflows; -inf when there is no contact).
    pub log10_real_area: f64,
    /// Real area of elastic contacts (m²).
    pub elastic_real_area: f64,
    /// Real area of plastic junctions A_rp (m²).
    pub plastic_real_area: f64,
    /// A_r / A_n.
    pub real_area_fraction: f64,
    /// A_rp / A_r (0 when there is no contact).
    pub plastic_area_fraction: f64,
    /// Expected number of asperities in contact.
    pub contact_count: f64,
    /// Expected number of plastic junctions.
    pub plastic_contact_count: f64,
    /// W / A_r (Pa); None when there is no real area.
    pub mean_real_pressure: Option<f64>,
    /// (elastic + plastic load)/A_r (Pa): the mean pressure the contacts carry,
    /// which adhesion (solid and capillary) raises above W/A_r: the contacts
    /// bear the load and every pull besides. None without contact.
    pub mean_contact_pressure: Option<f64>,
    /// Share of the load carried by elastic asperities (N).
    pub elastic_load: f64,
    /// Share of the load carried by plastic asperities (N).
    pub plastic_load: f64,
    /// Magnitude of the most tensile load the rough contact sustains (N); None when not computed.
    pub pull_off_force: Option<f64>,
    /// log10 of the pull-off force (finite even where it underflows).
    pub log10_pull_off_force: Option<f64>,
    /// The separation at pull-off (m).
    pub pull_off_separation: Option<f64>,
    /// The separation at pull-off over σ.
    pub nondimensional_pull_off_separation: Option<f64>,
    /// The JKR pull-off of one asperity, 1.5πγR (N), for comparison.
    pub asperity_pull_off_force: f64,
    /// The pull-off of one asperity under the scene's law (N): JKR's 1.5πγR,
    /// DMT's 2πγR, the Lennard-Jones sphere's (between them, from its table).
    pub law_asperity_pull_off_force: f64,
    /// Which area wears.
    pub wear_area: WearArea,
    /// V = k A L (m³), eq. 13.
    pub wear_volume: f64,
    /// V/L = k A (m³/m).
    pub wear_rate: f64,
    /// log10 of the wear rate (finite even where it underflows; -inf without contact).
    pub log10_wear_rate: f64,
    /// Model evaluations the separation and pull-off searches spent.
    pub evaluations: usize,
    /// Wear depth per sliding distance, V/(A_n L) = wear rate / A_n (m per m slid).
    pub wear_depth_rate: f64,
    /// Sliding distance until the allowed wear depth is worn (m); None without
    /// `allowed_wear_depth` or without wear.
    pub life_sliding_distance: Option<f64>,
    /// Cycles until the allowed wear depth is worn; None without `sliding_per_cycle`.
    pub life_cycles: Option<f64>,
    /// Whether the restoring force frees the part; None without `restoring_force`.
    pub stiction: Option<Stiction>,
    /// Bowden–Tabor friction τ A_r (N); None without `shear_strength`.
    pub friction_force: Option<f64>,
    /// friction_force / load; None without `shear_strength` or for a load ≤ 0.
    pub friction_coefficient: Option<f64>,
    /// Debris or smoothing (docs/model.md §13): d*, the shares of the contacts and
    /// of the real area that make debris, and the wear mechanism; None without
    /// `shear_strength`. Its keys sit at the top level.
    #[serde(flatten)]
    pub debris: Option<super::debris::Debris>,
    /// The asperity law the numbers come from.
    pub adhesion_model: AdhesionModel,
    /// Under DMT, how non-contacting asperities are attracted (absent under JKR).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub attraction: Option<AttractionKind>,
    /// Under DMT with van der Waals attraction, the Hamaker constant A = 12π Z0² γ
    /// that makes the sphere–flat force -A R/(6 (g + Z0)²) equal -2πRγ at contact (J);
    /// under the Lennard-Jones law its far field's, A = 16π Z0² γ.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hamaker_constant: Option<f64>,
    /// The load carried by attracted asperities not in contact (N, ≤ 0; 0 under
    /// JKR); None when separated.
    pub noncontact_load: Option<f64>,
    /// For 0.3 ≤ φ0 ≤ 3 under JKR or DMT, where neither is exact: the
    /// Lennard-Jones law's numbers.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub other_model: Option<OtherModel>,
    /// Under the Lennard-Jones law outside its curves (μ < 9.91e-5 or μ > 3.58e6): the
    /// closed-form limit whose numbers stand in (`dmt` or `jkr`); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stand_in_model: Option<AdhesionModel>,
    /// Capillary adhesion (docs/model.md §10): present when the scene has an
    /// `[environment]` or a cantilever; its keys sit at the top level.
    #[serde(flatten)]
    pub humidity: Option<Humidity>,
    /// The wear law's own numbers (the stress-assisted law's, docs/model.md §12);
    /// absent under Archard. Its keys sit at the top level.
    #[serde(flatten)]
    pub wear_details: Option<WearDetails>,
}

/// The humid air's numbers at the operating point (docs/model.md §10), SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Humidity {
    /// RH, 0 to below 1.
    pub relative_humidity: f64,
    /// T (K).
    pub temperature: f64,
    /// γ_L of the liquid at T (N/m).
    pub surface_tension: f64,
    /// θ_a (rad).
    pub contact_angle_a: f64,
    /// θ_b (rad).
    pub contact_angle_b: f64,
    /// r_K (m); None without a meniscus (RH = 0, or cos θ_a + cos θ_b ≤ 0).
    pub kelvin_radius: Option<f64>,
    /// d_K = r_K (cos θ_a + cos θ_b), the widest gap the liquid bridges (m).
    pub meniscus_height: Option<f64>,
    /// Δp = γ_L / r_K (Pa).
    pub laplace_pressure: Option<f64>,
    /// P_cap A_n at the operating point (N, ≤ 0); None when separated.
    pub capillary_load: Option<f64>,
    /// 1 - e^{-F_w}, the wet fraction of the nominal area; None when separated.
    pub wetted_fraction: Option<f64>,
    /// Γ = -∫_{d0}^∞ (P_solid + P_cap) dd from the unloaded equilibrium (J/m²): what
    /// a cantilever-beam test measures; None when the pull-off is not computed.
    pub apparent_work_of_adhesion: Option<f64>,
    /// The longest cantilever of the scene's thickness and gap that comes free (m);
    /// None without a cantilever, or where Γ is not computed or 0.
    pub detachment_length: Option<f64>,
}

/// The headline numbers of the Lennard-Jones law beside a JKR or DMT scene in
/// the JKR–DMT transition (0.3 ≤ φ0 ≤ 3), where neither limit law is exact.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OtherModel {
    /// Which law.
    pub adhesion_model: AdhesionModel,
    /// Its status under the load.
    pub status: Status,
    /// h = d/σ; None when separated.
    pub nondimensional_separation: Option<f64>,
    /// A_r (m²); 0 when separated.
    pub real_area: f64,
    /// The pull-off force (N).
    pub pull_off_force: Option<f64>,
    /// The wear rate (m³/m); 0 when separated.
    pub wear_rate: f64,
}

pub use super::law::TRANSITION_TABOR;

/// Does the part come free? The pull-off force against the restoring force.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Stiction {
    /// The pull-off force of the rough contact (N).
    pub pull_off_force: f64,
    /// The restoring force (N).
    pub restoring_force: f64,
    /// pull_off_force / restoring_force: ≥ 1 sticks.
    pub margin: f64,
    /// `sticks` iff margin ≥ 1.
    pub verdict: StictionVerdict,
}

/// The stiction verdict.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum StictionVerdict {
    /// The restoring force exceeds the pull-off force.
    Releases,
    /// The pull-off force is at least the restoring force.
    Sticks,
}

impl Stiction {
    /// The verdict of a pull-off force against a restoring force (> 0).
    pub fn new(pull_off_force: f64, restoring_force: f64) -> Stiction {
        let margin = pull_off_force / restoring_force;
        Stiction {
            pull_off_force,
            restoring_force,
            margin,
            verdict: if margin >= 1.0 {
                StictionVerdict::Sticks
            } else {
                StictionVerdict::Releases
            },
        }
    }
}

/// E = [(1-ν1²)/E1 + (1-ν2²)/E2]⁻¹; E2 = ∞ is a rigid counterface
/// ([`Scene::equivalent_modulus`]).
pub fn equivalent_modulus(scene: &Scene) -> f64 {
    scene.equivalent_modulus()
}

/// The load-law coefficients of a scene ([`Scene::coefficients`]).
pub fn coefficients(scene: &Scene) -> Coefficients {
    scene.coefficients()
}

/// θ, λ, ψ, φ0 of a scene (logs where powers could overflow).
pub fn indices(scene: &Scene) -> Indices {
    let e = equivalent_modulus(scene);
    let k = 4.0 / 3.0 * e;
    let (r, s, g, h) = (
        scene.asperity_radius,
        scene.sigma,
        scene.work_of_adhesion,
        scene.hardness,
    );
    let z0 = scene.interatomic_distance;
    let ln_lambda =
        2.0 * PI.ln() + r.ln() + 4.0 * h.ln() + s.ln() - 18f64.ln() - 2.0 * k.ln() - 2.0 * g.ln();
    let ln_tabor = (r.ln() + 2.0 * g.ln() - 2.0 * e.ln() - 3.0 * z0.ln()) / 3.0;
    Indices {
        elastic_adhesion_index: k * s * s.sqrt() / (g * r.sqrt()),
        plastic_adhesion_index: ln_lambda.exp(),
        plasticity_index: (e / h) * (s / r).sqrt(),
        tabor_parameter: ln_tabor.exp(),
    }
}

fn regime(idx: &Indices, has_adhesion: bool) -> Regime {
    let phi = idx.tabor_parameter;
    Regime {
        adhesion_model: if !has_adhesion {
            "none"
        } else if phi > 3.0 {
            "JKR"
        } else if phi >= 0.3 {
            "transition"
        } else {
            "DMT"
        },
        elastic_adhesion_matters: idx.elastic_adhesion_index <= 10.0,
        plastic_adhesion_matters: idx.plastic_adhesion_index <= 0.125,
        deformation: if idx.plasticity_index < 0.6 {
            "elastic"
        } else if idx.plasticity_index <= 1.0 {
            "elastic-plastic"
        } else {
            "plastic"
        },
    }
}

/// Evaluates a validated scene. Never fails: every outcome is a [`Status`].
pub fn evaluate(scene: &Scene, options: &EvaluationOptions) -> Evaluation {
    evaluate_from(scene, options, SearchHints::default())
}

/// As [`evaluate`], and for a scene in the JKR–DMT transition (0.3 ≤ φ0 ≤ 3,
/// with adhesion) also the other law's headline numbers in `other_model`
/// (what `wearopt eval` reports): the Lennard-Jones law, valid there.
pub fn evaluate_with_other(scene: &Scene, options: &EvaluationOptions) -> Evaluation {
    let mut ev = evaluate(scene, options);
    // `bracket` answers only inside the transition.
    let other = scene.adhesion_model.bracket(ev.indices.tabor_parameter);
    if let (true, Some(other)) = (scene.work_of_adhesion > 0.0, other) {
        let other_scene = Scene {
            adhesion_model: other,
            ..scene.clone()
        };
        // Its headline numbers only: no Γ integral.
        let o = evaluate(
            &other_scene,
            &EvaluationOptions {
                work_of_adhesion: false,
                ..*options
            },
        );
        ev.other_model = Some(OtherModel {
            adhesion_model: other_scene.adhesion_model,
            status: o.status,
            nondimensional_separation: o.nondimensional_separation,
            real_area: o.real_area,
            pull_off_force: o.pull_off_force,
            wear_rate: o.wear_rate,
        });
    }
    ev
}

/// The air an evaluation reports on: the scene's `[environment]`, or dry air when it
/// has only a cantilever (whose detachment length needs Γ); None for a dry scene.
/// Its temperature is the scene's.
fn environment_of(scene: &Scene) -> Option<Environment> {
    scene
        .environment
        .or(scene
            .requirements
            .cantilever
            .map(|_| Environment::default()))
        .map(|e| Environment {
            temperature: scene.temperature,
            ..e
        })
}

/// The non-dimensional model of a scene: its asperity law, with the capillary term
/// of docs/model.md §10 where its environment condenses a meniscus.
pub fn model_of(scene: &Scene, quadrature: super::quadrature::Quadrature) -> Model {
    let law = AsperityLaw::of(
        scene.adhesion_model,
        scene.attraction,
        scene.interatomic_distance,
        scene.sigma,
    );
    let k = 4.0 / 3.0 * equivalent_modulus(scene);
    let capillary = environment_of(scene).and_then(|e| e.meniscus()).map(|m| {
        Capillary::new(
            &m,
            k,
            scene.sigma,
            scene.asperity_radius,
            scene.asperity_density,
        )
    });
    Model::with_law(coefficients(scene), law, quadrature).with_capillary(capillary)
}

/// As [`evaluate`], starting the searches from `hints`.
pub fn evaluate_from(scene: &Scene, options: &EvaluationOptions, hints: SearchHints) -> Evaluation {
    let e = equivalent_modulus(scene);
    let k = 4.0 / 3.0 * e;
    let coeffs = coefficients(scene);
    let env = environment_of(scene);
    let meniscus = env.and_then(|e| e.meniscus());
    let model = model_of(scene, options.quadrature);
    let adhesive = model.has_adhesion();
    let idx = indices(scene);
    let reg = regime(&idx, coeffs.has_adhesion());
    let (r, s, n, an) = (
        scene.asperity_radius,
        scene.sigma,
        scene.asperity_density,
        scene.nominal_area,
    );
    let load_scale = k * n * r.sqrt() * s * s.sqrt() * an / SQRT_TWO_PI;
    let area_scale = an * PI * n * r * s / SQRT_TWO_PI * scene.real_area_scale;
    let count_scale = an * n / SQRT_TWO_PI;
    let target = scene.load / load_scale;

    let mut warnings = warnings::scene_warnings(scene);
    let mut notes = Vec::new();
    let phi = idx.tabor_parameter;
    if coeffs.has_adhesion() {
        warnings.extend(scene.adhesion_model.law().outside_regime(phi));
    }
    let stand_in = model.stand_in();
    if let Some(law) = stand_in {
        notes.extend(model.law.law().stand_in_note(law, phi));
    } else if coeffs.has_adhesion() {
        notes.extend(model.law.law().approximation_note(model.law, phi));
    }
    let stand_in = stand_in.map(|law| law.adhesion_model());
    if reg.elastic_adhesion_matters {
        notes.push(Note::ElasticAdhesionMatters {
            elastic_adhesion_index: idx.elastic_adhesion_index,
        });
    }
    if reg.plastic_adhesion_matters {
        notes.push(Note::PlasticAdhesionMatters {
            plastic_adhesion_index: idx.plastic_adhesion_index,
        });
    }
    if model.transition.jump < 0.0 {
        notes.push(Note::LoadDropsAtTransition);
    }
    if let Some(m) = meniscus.filter(|m| m.kelvin_radius < super::capillary::MIN_KELVIN_RADIUS) {
        warnings.push(Warning::KelvinRadiusBelowContinuum {
            kelvin_radius: m.kelvin_radius,
        });
    }

    // The critical points of P̄(h): needed for the pull-off, for a tensile load,
    // and where the load law jumps down (several branches).
    let need_landscape =
        adhesive && (options.pull_off || scene.load <= 0.0 || model.transition.jump < 0.0);
    let land = need_landscape.then(|| landscape_from(&model, hints.pull_off));
    let mut evaluations = land.as_ref().map_or(0, |l| l.evaluations);
    let mut pull_off: Option<PullOff> = land.as_ref().and_then(pull_off_of);
    if adhesive && (options.pull_off || scene.load <= 0.0) {
        // No accepted scene reports a silent null: a minimum the model cannot
        // resolve (|h| > 1e6, where P̄'s shares cancel below ε) or none at all is a warning.
        let limit = super::coefficients::MAX_SEPARATION;
        match pull_off {
            Some(p) if p.separation.abs() > limit => {
                warnings.push(Warning::PullOffBeyondModel {
                    separation: p.separation,
                    limit,
                });
                pull_off = None;
            }
            None => warnings.push(Warning::PullOffNotFound { evaluations }),
            Some(_) => {}
        }
    }
    let (outcome, found) = solve_separation_at(&model, target, land.as_ref(), hints.separation);
    let (status, h) = match outcome {
        SeparationOutcome::Contact {
            separation,
            evaluations: ev,
        } => {
            evaluations += ev;
            (Status::Ok, Some(separation))
        }
        SeparationOutcome::Separated { evaluations: ev } => {
            evaluations += ev;
            (Status::Separated, None)
        }
        SeparationOutcome::NotConverged {
            separation,
            evaluations: ev,
        } => {
            evaluations += ev;
            if separation.is_finite() {
                warnings.push(Warning::SeparationNotConverged {
                    evaluations: ev,
                    separation,
                });
                (Status::NotConverged, Some(separation))
            } else {
                warnings.push(Warning::LoadBeyondModel {
                    nondimensional_load: target,
                    limit: super::separation::MAX_LOAD,
                });
                (Status::OutOfRange, None)
            }
        }
    };
    if status == Status::Separated {
        notes.push(Note::Separated { adhesion: adhesive });
    }

    let (pull_off_force, log10_pull_off_force, pull_off_separation) = match &pull_off {
        Some(p) if options.pull_off || scene.load <= 0.0 => {
            let force = p.load.negate().scale(load_scale);
            let value = force.value();
            if value == 0.0 && force.mantissa != 0.0 {
                notes.push(Note::PullOffUnderflow {
                    log10_force: force.log10_abs(),
                });
            }
            (
                Some(value.max(0.0)),
                Some(force.log10_abs()),
                Some(p.separation * s),
            )
        }
        _ if !adhesive => (Some(0.0), None, None),
        _ => (None, None, None),
    };

    let zero = Scaled::ZERO;
    // The model at the separation: the solve's last evaluation (for `Contact`),
    // else evaluated here (a `NotConverged` estimate).
    let at = h.map(|h| {
        found
            .filter(|a| a.separation == h)
            .unwrap_or_else(|| model.at(h))
    });
    let area = at.map_or(zero, |a| a.area());
    // Where the plastic share underflows against the contact's scale, its own
    // closed form keeps its size (a finite log of a plastic-only wear).
    let plastic_area = match (at, h) {
        (Some(a), Some(h)) if a.plastic_area().mantissa == 0.0 => model.plastic_area_scaled(h),
        (Some(a), _) => a.plastic_area(),
        _ => zero,
    };
    let elastic_area = at.map_or(zero, |a| a.elastic_area());
    let wearing_area = match scene.wear_area {
        WearArea::Total => area,
        WearArea::Plastic => plastic_area,
    };
    let wear = scene.wear_law.law().rate(&WearInput {
        scene,
        model: &model,
        separation: h,
        wearing_area,
        plastic_area,
        elastic_load: at.map_or(zero, |a| Scaled::new(a.load_elastic, a.scale_exponent)),
        area_scale,
        equivalent_modulus: e,
    });
    let wear_area_scaled = wear.rate;
    let real_area = area.scale(area_scale).value();
    let plastic_real_area = plastic_area.scale(area_scale).value();
    let wear_rate = wear_area_scaled.value();
    if at.is_some() && real_area == 0.0 && area.mantissa != 0.0 {
        notes.push(Note::RealAreaUnderflow {
            log10_area: area.scale(area_scale).log10_abs(),
        });
    }
    let share_load = |load: fn(&Integrals) -> f64| {
        at.map_or(0.0, |a| {
            Scaled::new(load(&a), a.scale_exponent)
                .scale(load_scale)
                .value()
        })
    };
    let (elastic_load, plastic_load) = (
        share_load(|a| a.load_elastic),
        share_load(|a| a.load_plastic),
    );
    let evaluation = Evaluation {
        status,
        warnings,
        notes,
        equivalent_modulus: e,
        indices: idx,
        regime: reg,
        critical_interference: model.critical_interference() * s,
        load_scale,
        nondimensional_load: target,
        separation: h.map(|h| h * s),
        nondimensional_separation: h,
        real_area,
        log10_real_area: area.scale(area_scale).log10_abs(),
        elastic_real_area: elastic_area.scale(area_scale).value(),
        plastic_real_area,
        real_area_fraction: real_area / an,
        plastic_area_fraction: if area.mantissa > 0.0 {
            plastic_area.ratio(area)
        } else {
            0.0
        },
        contact_count: at.map_or(0.0, |a| a.contacts().scale(count_scale).value()),
        plastic_contact_count: at.map_or(0.0, |a| a.plastic_contacts().scale(count_scale).value()),
        mean_real_pressure: (real_area > 0.0).then(|| scene.load / real_area),
        mean_contact_pressure: (at.is_some() && real_area > 0.0)
            .then(|| (elastic_load + plastic_load) / real_area),
        elastic_load,
        plastic_load,
        pull_off_force,
        log10_pull_off_force,
        pull_off_separation,
        nondimensional_pull_off_separation: pull_off_separation.map(|d| d / s),
        asperity_pull_off_force: 1.5 * PI * scene.work_of_adhesion * r,
        law_asperity_pull_off_force: model.asperity_pull_off() * PI * scene.work_of_adhesion * r,
        wear_area: scene.wear_area,
        wear_volume: wear_rate * scene.sliding_distance,
        wear_rate,
        log10_wear_rate: wear_area_scaled.log10_abs(),
        evaluations,
        wear_depth_rate: 0.0,
        life_sliding_distance: None,
        life_cycles: None,
        stiction: None,
        friction_force: None,
        friction_coefficient: None,
        debris: None,
        adhesion_model: scene.adhesion_model,
        attraction: scene
            .adhesion_model
            .takes_attraction()
            .then_some(scene.attraction),
        hamaker_constant: scene
            .adhesion_model
            .law()
            .hamaker_factor(scene.attraction)
            .map(|factor| {
                factor * PI * scene.interatomic_distance.powi(2) * scene.work_of_adhesion
            }),
        noncontact_load: at.map(|a| a.noncontact_load().scale(load_scale).value()),
        other_model: None,
        stand_in_model: stand_in,
        humidity: None,
        wear_details: wear.details,
    };
    let humidity = env.map(|env| {
        // Γ from the unloaded equilibrium (the tensile rule's root of P̄ = 0),
        // when the pull-off (and so the landscape) is computed.
        let work = if !adhesive {
            Some(0.0)
        } else if options.pull_off && options.work_of_adhesion {
            // Started where the operating point and the pull-off put the root,
            // and stopped near it: Γ̄ is stationary there (`work_of_separation_near`).
            let hint = land
                .as_ref()
                .zip(pull_off)
                .and_then(|(land, po)| super::separation::unloaded_hint(found.as_ref(), land, &po));
            let tolerance = super::work::UNLOADED_TOLERANCE;
            match solve_separation_within(&model, 0.0, land.as_ref(), hint, tolerance) {
                (SeparationOutcome::Contact { separation, .. }, at) => {
                    let at = at.unwrap_or_else(|| model.at(separation));
                    let (w, _) = super::work::work_of_separation_near(&model, &at);
                    Some(w * load_scale / an * s)
                }
                (SeparationOutcome::Separated { .. }, _) => Some(0.0),
                (SeparationOutcome::NotConverged { .. }, _) => None,
            }
        } else {
            None
        };
        Humidity {
            relative_humidity: env.relative_humidity,
            temperature: env.temperature,
            surface_tension: env.liquid.surface_tension(env.temperature),
            contact_angle_a: env.contact_angle_a,
            contact_angle_b: env.contact_angle_b,
            kelvin_radius: meniscus.map(|m| m.kelvin_radius),
            meniscus_height: meniscus.map(|m| m.height),
            laplace_pressure: meniscus.map(|m| m.laplace_pressure),
            capillary_load: at.map(|a| a.capillary_load().scale(load_scale).value()),
            wetted_fraction: at.map(|a| a.capillary.wetted_fraction),
            apparent_work_of_adhesion: work,
            detachment_length: scene
                .requirements
                .cantilever
                .zip(work)
                .and_then(|(c, w)| c.detachment_length(w)),
        }
    });
    let evaluation = Evaluation {
        humidity,
        ..evaluation
    };
    with_contact_checks(with_designer_numbers(evaluation, scene))
}

/// Wear depth and life, stiction and friction from an evaluation and the scene's
/// [`super::Requirements`].
fn with_designer_numbers(mut ev: Evaluation, scene: &Scene) -> Evaluation {
    let req = &scene.requirements;
    ev.wear_depth_rate = ev.wear_rate / scene.nominal_area;
    if let Some(depth) = req.allowed_wear_depth {
        let life = depth / ev.wear_depth_rate;
        ev.life_sliding_distance = life.is_finite().then_some(life);
        if let (Some(l), Some(per)) = (ev.life_sliding_distance, req.sliding_per_cycle) {
            let cycles = l / per;
            ev.life_cycles = cycles.is_finite().then_some(cycles);
        }
    }
    if let (Some(f), Some(restoring)) = (ev.pull_off_force, req.restoring_force) {
        ev.stiction = Some(Stiction::new(f, restoring));
    }
    if let Some(tau) = req.shear_strength {
        let f = tau * ev.real_area;
        ev.friction_force = Some(f);
        ev.friction_coefficient = (scene.load > 0.0).then(|| f / scene.load);
    }
    ev.debris = super::debris::debris_of(
        scene,
        ev.nondimensional_separation,
        ev.critical_interference,
    );
    if let Some(d) = &ev.debris {
        ev.notes.push(Note::DebrisJunctionSizes {
            adhesion_model: scene.adhesion_model,
        });
        ev.warnings.extend(d.warning(scene.wear_law.as_str()));
    }
    ev
}

/// The checks that need the results: dense or too few contacts, a real area above the
/// nominal one, non-finite results. The last two make the status `out_of_range`: no
/// impossible or non-finite number comes with `ok`.
fn with_contact_checks(mut ev: Evaluation) -> Evaluation {
    if ev.status != Status::Ok {
        return ev;
    }
    let f = ev.real_area_fraction;
    if f > 1.0 {
        ev.warnings.push(Warning::RealAreaExceedsNominal {
            real_area_fraction: f,
        });
        ev.status = Status::OutOfRange;
    } else if f > warnings::DENSE_CONTACT_FRACTION {
        ev.warnings.push(Warning::DenseContact {
            real_area_fraction: f,
        });
    }
    if ev.contact_count < warnings::MIN_CONTACTS {
        ev.warnings.push(Warning::FewContacts {
            contact_count: ev.contact_count,
        });
    }
    let results = [
        ("separation", ev.separation.unwrap_or(0.0)),
        ("real_area", ev.real_area),
        ("real_area_fraction", ev.real_area_fraction),
        ("contact_count", ev.contact_count),
        ("elastic_load", ev.elastic_load),
        ("plastic_load", ev.plastic_load),
        ("wear_rate", ev.wear_rate),
        ("wear_volume", ev.wear_volume),
        ("pull_off_force", ev.pull_off_force.unwrap_or(0.0)),
    ];
    for (quantity, x) in results {
        if !x.is_finite() {
            ev.warnings.push(Warning::NonFiniteResult { quantity });
            ev.status = Status::OutOfRange;
        }
    }
    ev
}
