//! The outputs a designer reads off an evaluation, in one table beside the
//! parameter table ([`super::SceneParameter`]): each one's key, symbol and
//! dimension, its value (SI) and its natural logarithm read from an
//! [`Evaluation`] of a [`Scene`], the values it can take, and the roles it
//! takes (an objective, a constraint, a front's adhesion measure, a sweep
//! column, a quantity of interest of an uncertainty study). The optimiser's
//! objectives, constraint quantities and adhesion measures are subsets of this
//! table, so a quantity means the same number to each of them.
//!
//! Logarithms are taken from the evaluation's log10 companions where the value
//! can underflow (the pull-off force, the wear rate, the real area: docs/model.md
//! §3–§4), so that a pull-off of 10^-8000 N still has a finite logarithm with a
//! slope; the other logarithms are clamped to [`LN_FLOOR`, `LN_CEIL`].
//!
//! A new output is one variant and one row here.

use serde::Serialize;

use super::scene::Scene;
use super::wear::Evaluation;
use crate::units::Dimension;

/// ln of the smallest magnitude kept finite (ln 1e-323 ≈ -744): the floor of every
/// clamped logarithm, and the logarithm of a quantity that does not exist.
pub const LN_FLOOR: f64 = -744.0;

/// ln of the largest magnitude kept finite (ln 1e308 ≈ 709): the ceiling of every
/// clamped logarithm.
pub const LN_CEIL: f64 = 709.0;

/// An output of an evaluation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// V/L = k A, the wear volume per sliding distance (m³/m; docs/model.md §3).
    WearRate,
    /// V = k A L, the wear volume (m³; docs/model.md §3).
    WearVolume,
    /// A_r, the real contact area (m²).
    RealArea,
    /// The magnitude of the most tensile load the rough contact sustains (N;
    /// docs/model.md §4); exists only where the pull-off was searched for.
    PullOffForce,
    /// F = τ A_r, the Bowden–Tabor friction force (N); exists only with a shear
    /// strength τ.
    FrictionForce,
    /// F / W, the friction force over the load; exists only with a shear strength
    /// and a compressive load.
    FrictionCoefficient,
    /// ψ = (E/H)(σ/R)^{1/2}, the plasticity index (docs/model.md §2).
    PlasticityIndex,
    /// θ = K σ^{3/2} R^{1/2} / (γ R), the elastic adhesion index (docs/model.md §2).
    ElasticAdhesionIndex,
    /// λ = π² R H⁴ σ / (18 K² γ²), the plastic adhesion index (docs/model.md §2).
    PlasticAdhesionIndex,
    /// φ0 = (R γ² / (E² Z0³))^{1/3}, the Tabor parameter (docs/model.md §2).
    TaborParameter,
    /// H / E1, the hardness over body a's Young's modulus.
    HardnessToModulus,
    /// A_r / A_n, the real area over the nominal area.
    RealAreaFraction,
    /// A_rp / A_r, the share of the real area in plastic junctions.
    PlasticAreaFraction,
    /// W / A_r, the mean pressure on the real area (Pa); exists only with a real area.
    MeanRealPressure,
    /// The expected number of asperities in contact.
    ContactCount,
    /// d, the mean-plane separation (m); exists only in contact.
    Separation,
    /// The pull-off force over the restoring force: ≥ 1 sticks; exists only with a
    /// restoring force.
    StictionMargin,
    /// The pull-off force over |W|: how far a contact under a tensile load is from
    /// snapping apart (1 = at the pull-off).
    ReleaseMargin,
    /// The cycles until the allowed wear depth is worn; exists only with an allowed
    /// wear depth, a sliding distance per cycle and wear.
    LifeCycles,
    /// The sliding distance until the allowed wear depth is worn (m); exists only
    /// with an allowed wear depth and wear.
    LifeSlidingDistance,
    /// V/(A_n L) = k A / A_n, the wear depth per sliding distance (m per m slid;
    /// docs/model.md §3).
    WearDepthRate,
    /// The real area of elastic contacts (m²).
    ElasticRealArea,
    /// A_rp, the real area of plastic junctions (m²).
    PlasticRealArea,
    /// The expected number of plastic junctions.
    PlasticContactCount,
    /// γ, the work of adhesion (J/m²), read from the scene: the measure a front
    /// trades wear against when a design moves γ.
    WorkOfAdhesion,
    /// k_eff = wear rate / wearing area, the Archard coefficient a wear law
    /// amounts to (docs/model.md §12); exists only under a law that computes it
    /// (stress-assisted) and with a wearing area.
    EffectiveWearCoefficient,
    /// The area-weighted mean of the stress that assists wear (Pa; docs/model.md
    /// §12); exists only under the stress-assisted law, in contact.
    MeanContactStress,
    /// The share of the wear rate from summits with Γa₀/v > 1 (docs/model.md
    /// §12); exists only under the stress-assisted law, with wear.
    SaturatedFraction,
    /// −d ln(wear rate)/d(1/k_BT) at fixed contact (J; docs/model.md §12); exists
    /// only under the stress-assisted law, with wear.
    ApparentActivationEnergy,
    // Debris or smoothing (docs/model.md §13); each exists only with a shear strength τ_j.
    /// d* = Λ w G / τ_j², the junction diameter above which a junction breaks off a
    /// debris particle (m).
    CriticalJunctionSize,
    /// The share of the contacts whose junction (its contact diameter under the
    /// scene's law, docs/model.md §13) is wider than d*; exists only in contact.
    DebrisContactFraction,
    /// The share of the real area in junctions wider than d*; exists only in contact.
    DebrisAreaFraction,
}

/// What a quantity may be used as.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Role {
    /// What a study may minimise (`[objective] minimize`).
    Objective,
    /// What a `[[constraint]]` may bound.
    Constraint,
    /// The adhesion axis of a Pareto front (`[pareto] adhesion`).
    FrontMeasure,
    /// A column of a design-space sweep's rows.
    SweepColumn,
    /// An output of an uncertainty study.
    QuantityOfInterest,
}

const OBJECTIVE: u8 = 1;
const CONSTRAINT: u8 = 2;
const FRONT_MEASURE: u8 = 4;
const SWEEP_COLUMN: u8 = 8;
const QUANTITY_OF_INTEREST: u8 = 16;

impl Role {
    fn bit(self) -> u8 {
        match self {
            Role::Objective => OBJECTIVE,
            Role::Constraint => CONSTRAINT,
            Role::FrontMeasure => FRONT_MEASURE,
            Role::SweepColumn => SWEEP_COLUMN,
            Role::QuantityOfInterest => QUANTITY_OF_INTEREST,
        }
    }
}

/// One row of the table.
struct Row {
    key: &'static str,
    symbol: &'static str,
    dimension: Dimension,
    /// The values it can take, (lowest, highest).
    range: (f64, f64),
    /// The roles, a set of the bits above.
    roles: u8,
}

/// Any value.
const ANY: (f64, f64) = (f64::NEG_INFINITY, f64::INFINITY);
/// A magnitude.
const POSITIVE: (f64, f64) = (0.0, f64::INFINITY);
/// A share of a whole.
const FRACTION: (f64, f64) = (0.0, 1.0);

/// ln x, clamped to [`LN_FLOOR`, `LN_CEIL`]; [`LN_FLOOR`] for NaN.
fn ln_clamped(x: f64) -> f64 {
    if x.is_nan() {
        LN_FLOOR
    } else {
        x.ln().clamp(LN_FLOOR, LN_CEIL)
    }
}

/// ln of the pull-off force, divided by `per` when given, from its log10 so that
/// it keeps a slope where the force underflows; not clamped; [`LN_FLOOR`] where
/// there is no pull-off force.
fn ln_pull_off(ev: &Evaluation, per: Option<f64>) -> f64 {
    ev.log10_pull_off_force
        .filter(|l| l.is_finite())
        .map_or(LN_FLOOR, |l| match per {
            Some(per) => l * std::f64::consts::LN_10 - per.ln(),
            None => l * std::f64::consts::LN_10,
        })
}

/// ln of the friction force τ A_r (or of its ratio to the load), from log10 A_r so
/// that it keeps a slope where A_r underflows; τ = 1 Pa without a shear strength.
fn ln_friction(per_load: bool, ev: &Evaluation, scene: &Scene) -> f64 {
    let tau = scene.requirements.shear_strength.unwrap_or(1.0);
    let mut v = ev.log10_real_area * std::f64::consts::LN_10 + tau.ln();
    if per_load {
        v -= scene.load.abs().max(f64::MIN_POSITIVE).ln();
    }
    if v.is_nan() {
        LN_CEIL
    } else {
        v.clamp(LN_FLOOR, LN_CEIL)
    }
}

impl Quantity {
    /// Every quantity, in table order.
    pub const ALL: [Quantity; 32] = [
        Quantity::WearRate,
        Quantity::WearVolume,
        Quantity::RealArea,
        Quantity::PullOffForce,
        Quantity::FrictionForce,
        Quantity::FrictionCoefficient,
        Quantity::PlasticityIndex,
        Quantity::ElasticAdhesionIndex,
        Quantity::PlasticAdhesionIndex,
        Quantity::TaborParameter,
        Quantity::HardnessToModulus,
        Quantity::RealAreaFraction,
        Quantity::PlasticAreaFraction,
        Quantity::MeanRealPressure,
        Quantity::ContactCount,
        Quantity::Separation,
        Quantity::StictionMargin,
        Quantity::ReleaseMargin,
        Quantity::LifeCycles,
        Quantity::LifeSlidingDistance,
        Quantity::WearDepthRate,
        Quantity::ElasticRealArea,
        Quantity::PlasticRealArea,
        Quantity::PlasticContactCount,
        Quantity::WorkOfAdhesion,
        Quantity::EffectiveWearCoefficient,
        Quantity::MeanContactStress,
        Quantity::SaturatedFraction,
        Quantity::ApparentActivationEnergy,
        Quantity::CriticalJunctionSize,
        Quantity::DebrisContactFraction,
        Quantity::DebrisAreaFraction,
    ];

    /// The table. Roles: the objectives are the wear, the area, the pull-off and
    /// friction; every quantity a constraint bounds and the real area are sweep
    /// columns; the quantities of interest are every output but γ (an input).
    fn row(self) -> Row {
        use Dimension::*;
        const OSQ: u8 = OBJECTIVE | SWEEP_COLUMN | QUANTITY_OF_INTEREST;
        const CSQ: u8 = CONSTRAINT | SWEEP_COLUMN | QUANTITY_OF_INTEREST;
        const ALL_BUT_FRONT: u8 = OBJECTIVE | CSQ;
        let row = |key, symbol, dimension, range, roles| Row {
            key,
            symbol,
            dimension,
            range,
            roles,
        };
        match self {
            Quantity::WearRate => row("wear_rate", "V/L", WearRate, POSITIVE, ALL_BUT_FRONT),
            Quantity::WearVolume => row(
                "wear_volume",
                "V",
                Volume,
                POSITIVE,
                OBJECTIVE | QUANTITY_OF_INTEREST,
            ),
            Quantity::RealArea => row("real_area", "A_r", Area, POSITIVE, OSQ),
            Quantity::PullOffForce => row(
                "pull_off_force",
                "F_po",
                Force,
                ANY,
                ALL_BUT_FRONT | FRONT_MEASURE,
            ),
            Quantity::FrictionForce => row("friction_force", "F", Force, POSITIVE, ALL_BUT_FRONT),
            Quantity::FrictionCoefficient => row(
                "friction_coefficient",
                "F/W",
                Dimensionless,
                POSITIVE,
                ALL_BUT_FRONT,
            ),
            Quantity::PlasticityIndex => row("plasticity_index", "ψ", Dimensionless, POSITIVE, CSQ),
            Quantity::ElasticAdhesionIndex => row(
                "elastic_adhesion_index",
                "θ",
                Dimensionless,
                POSITIVE,
                CSQ | FRONT_MEASURE,
            ),
            Quantity::PlasticAdhesionIndex => {
                row("plastic_adhesion_index", "λ", Dimensionless, POSITIVE, CSQ)
            }
            Quantity::TaborParameter => row("tabor_parameter", "φ0", Dimensionless, POSITIVE, CSQ),
            Quantity::HardnessToModulus => {
                row("hardness_to_modulus", "H/E", Dimensionless, POSITIVE, CSQ)
            }
            Quantity::RealAreaFraction => row(
                "real_area_fraction",
                "A_r/A_n",
                Dimensionless,
                FRACTION,
                CSQ,
            ),
            Quantity::PlasticAreaFraction => row(
                "plastic_area_fraction",
                "A_rp/A_r",
                Dimensionless,
                FRACTION,
                CSQ,
            ),
            Quantity::MeanRealPressure => {
                row("mean_real_pressure", "W/A_r", Pressure, POSITIVE, CSQ)
            }
            Quantity::ContactCount => row("contact_count", "n", Dimensionless, POSITIVE, CSQ),
            Quantity::Separation => row("separation", "d", Length, ANY, CSQ),
            Quantity::StictionMargin => {
                row("stiction_margin", "F_po/F_r", Dimensionless, POSITIVE, CSQ)
            }
            Quantity::ReleaseMargin => {
                row("release_margin", "F_po/|W|", Dimensionless, POSITIVE, CSQ)
            }
            Quantity::LifeCycles => row(
                "life_cycles",
                "n_life",
                Dimensionless,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::LifeSlidingDistance => row(
                "life_sliding_distance",
                "L_life",
                Length,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::WearDepthRate => row(
                "wear_depth_rate",
                "V/(A_n L)",
                Dimensionless,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::ElasticRealArea => row(
                "elastic_real_area",
                "A_re",
                Area,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::PlasticRealArea => row(
                "plastic_real_area",
                "A_rp",
                Area,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::PlasticContactCount => row(
                "plastic_contact_count",
                "n_p",
                Dimensionless,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::WorkOfAdhesion => row(
                "work_of_adhesion",
                "γ",
                SurfaceEnergy,
                POSITIVE,
                FRONT_MEASURE,
            ),
            Quantity::EffectiveWearCoefficient => row(
                "effective_wear_coefficient",
                "k_eff",
                Dimensionless,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::MeanContactStress => row(
                "mean_contact_stress",
                "σ_mean",
                Pressure,
                ANY,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::SaturatedFraction => row(
                "saturated_fraction",
                "f_sat",
                Dimensionless,
                FRACTION,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::ApparentActivationEnergy => row(
                "apparent_activation_energy",
                "E_app",
                Energy,
                ANY,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::CriticalJunctionSize => row(
                "critical_junction_size",
                "d*",
                Length,
                POSITIVE,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::DebrisContactFraction => row(
                "debris_contact_fraction",
                "n_debris/n",
                Dimensionless,
                FRACTION,
                QUANTITY_OF_INTEREST,
            ),
            Quantity::DebrisAreaFraction => row(
                "debris_area_fraction",
                "A_debris/A_r",
                Dimensionless,
                FRACTION,
                QUANTITY_OF_INTEREST,
            ),
        }
    }

    /// The key as problem files, JSON and reports write it.
    pub fn as_str(self) -> &'static str {
        self.row().key
    }

    /// The quantity whose key is `name` (exact match).
    pub fn from_key(name: &str) -> Option<Quantity> {
        Self::ALL.into_iter().find(|q| q.as_str() == name)
    }

    /// The symbol reports write for it.
    pub fn symbol(self) -> &'static str {
        self.row().symbol
    }

    /// The dimension of its values.
    pub fn dimension(self) -> Dimension {
        self.row().dimension
    }

    /// The values it can take, `(lowest, highest)` (SI): bounds outside can never
    /// be met.
    pub fn natural_range(self) -> (f64, f64) {
        self.row().range
    }

    /// Whether it may be used as `role`.
    pub fn has_role(self, role: Role) -> bool {
        self.row().roles & role.bit() != 0
    }

    /// The quantities that may be used as `role`, in table order.
    pub fn with_role(role: Role) -> Vec<Quantity> {
        Self::ALL.into_iter().filter(|q| q.has_role(role)).collect()
    }

    /// Whether its value needs the pull-off search
    /// ([`super::EvaluationOptions::pull_off`]).
    pub fn needs_pull_off(self) -> bool {
        matches!(
            self,
            Quantity::PullOffForce | Quantity::StictionMargin | Quantity::ReleaseMargin
        )
    }

    /// Its value (SI) in evaluation `ev` of `scene`; None where it does not exist
    /// (see each variant).
    pub fn value(self, ev: &Evaluation, scene: &Scene) -> Option<f64> {
        Some(match self {
            Quantity::WearRate => ev.wear_rate,
            Quantity::WearVolume => ev.wear_volume,
            Quantity::RealArea => ev.real_area,
            Quantity::PullOffForce => ev.pull_off_force?,
            Quantity::FrictionForce => ev.friction_force?,
            Quantity::FrictionCoefficient => ev.friction_coefficient?,
            Quantity::PlasticityIndex => ev.indices.plasticity_index,
            Quantity::ElasticAdhesionIndex => ev.indices.elastic_adhesion_index,
            Quantity::PlasticAdhesionIndex => ev.indices.plastic_adhesion_index,
            Quantity::TaborParameter => ev.indices.tabor_parameter,
            Quantity::HardnessToModulus => scene.hardness / scene.youngs_modulus_a,
            Quantity::RealAreaFraction => ev.real_area_fraction,
            Quantity::PlasticAreaFraction => ev.plastic_area_fraction,
            Quantity::MeanRealPressure => ev.mean_real_pressure?,
            Quantity::ContactCount => ev.contact_count,
            Quantity::Separation => ev.separation?,
            Quantity::StictionMargin => ev.stiction?.margin,
            Quantity::ReleaseMargin => ev.pull_off_force? / scene.load.abs(),
            Quantity::LifeCycles => ev.life_cycles?,
            Quantity::LifeSlidingDistance => ev.life_sliding_distance?,
            Quantity::WearDepthRate => ev.wear_depth_rate,
            Quantity::ElasticRealArea => ev.elastic_real_area,
            Quantity::PlasticRealArea => ev.plastic_real_area,
            Quantity::PlasticContactCount => ev.plastic_contact_count,
            Quantity::WorkOfAdhesion => scene.work_of_adhesion,
            Quantity::EffectiveWearCoefficient => ev.wear_details?.effective_wear_coefficient?,
            Quantity::MeanContactStress => ev.wear_details?.mean_contact_stress?,
            Quantity::SaturatedFraction => ev.wear_details?.saturated_fraction?,
            Quantity::ApparentActivationEnergy => ev.wear_details?.apparent_activation_energy?,
            Quantity::CriticalJunctionSize => ev.debris?.critical_junction_size,
            Quantity::DebrisContactFraction => ev.debris?.debris_contact_fraction?,
            Quantity::DebrisAreaFraction => ev.debris?.debris_area_fraction?,
        })
    }

    /// log10 of its value, not clamped: the evaluation's log10 companion for the
    /// pull-off force, the wear rate and the real area (finite where the value
    /// underflows; -∞ without contact), else log10 of [`Quantity::value`]. None
    /// where the value does not exist.
    pub fn log10_value(self, ev: &Evaluation, scene: &Scene) -> Option<f64> {
        match self {
            Quantity::PullOffForce => ev.log10_pull_off_force,
            Quantity::WearRate => Some(ev.log10_wear_rate),
            Quantity::RealArea => Some(ev.log10_real_area),
            _ => self.value(ev, scene).map(f64::log10),
        }
    }

    /// ln of its value, finite wherever the value is positive, for an optimiser to
    /// work in relative units:
    ///
    /// - the pull-off force and the two margins over it, from the pull-off's
    ///   log10, not clamped (a slope even at 10^-8000 N); [`LN_FLOOR`] where
    ///   there is no pull-off force; the stiction margin over 1 N without a
    ///   restoring force;
    /// - the wear rate, the wear volume (L = 0 counts as 1 m), the real area and
    ///   the real-area fraction, from the log10 companions, clamped to
    ///   [`LN_FLOOR`, `LN_CEIL`] (NaN stays NaN);
    /// - the friction force and coefficient, from log10 A_r (τ = 1 Pa without a
    ///   shear strength), clamped, [`LN_CEIL`] for NaN;
    /// - every other quantity: ln of its value (0 where it does not exist),
    ///   clamped, [`LN_FLOOR`] for NaN.
    pub fn ln_value(self, ev: &Evaluation, scene: &Scene) -> f64 {
        let ln10 = std::f64::consts::LN_10;
        match self {
            Quantity::PullOffForce => ln_pull_off(ev, None),
            Quantity::StictionMargin => {
                ln_pull_off(ev, Some(scene.requirements.restoring_force.unwrap_or(1.0)))
            }
            Quantity::ReleaseMargin => ln_pull_off(ev, Some(scene.load.abs())),
            Quantity::WearRate => (ev.log10_wear_rate * ln10).clamp(LN_FLOOR, LN_CEIL),
            Quantity::WearVolume => (ev.log10_wear_rate * ln10
                + if scene.sliding_distance > 0.0 {
                    scene.sliding_distance.ln()
                } else {
                    0.0
                })
            .clamp(LN_FLOOR, LN_CEIL),
            Quantity::RealArea => (ev.log10_real_area * ln10).clamp(LN_FLOOR, LN_CEIL),
            Quantity::RealAreaFraction => {
                (ev.log10_real_area * ln10 - scene.nominal_area.ln()).clamp(LN_FLOOR, LN_CEIL)
            }
            Quantity::FrictionForce => ln_friction(false, ev, scene),
            Quantity::FrictionCoefficient => ln_friction(true, ev, scene),
            _ => ln_clamped(self.value(ev, scene).unwrap_or(0.0)),
        }
    }
}

impl std::fmt::Display for Quantity {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{evaluate, EvaluationOptions, Status};

    fn keys(role: Role) -> Vec<&'static str> {
        Quantity::with_role(role)
            .into_iter()
            .map(Quantity::as_str)
            .collect()
    }

    fn sorted(mut v: Vec<&'static str>) -> Vec<&'static str> {
        v.sort_unstable();
        v
    }

    /// The names problem files accept for each role, as the optimiser's enums list
    /// them: a changed spelling fails here.
    #[test]
    fn role_subsets_are_the_accepted_names() {
        let objectives = [
            "wear_rate",
            "wear_volume",
            "real_area",
            "pull_off_force",
            "friction_force",
            "friction_coefficient",
        ];
        let constraints = [
            "pull_off_force",
            "plasticity_index",
            "elastic_adhesion_index",
            "plastic_adhesion_index",
            "tabor_parameter",
            "hardness_to_modulus",
            "real_area_fraction",
            "plastic_area_fraction",
            "mean_real_pressure",
            "contact_count",
            "separation",
            "wear_rate",
            "stiction_margin",
            "friction_force",
            "friction_coefficient",
            "release_margin",
        ];
        let measures = [
            "pull_off_force",
            "work_of_adhesion",
            "elastic_adhesion_index",
        ];
        // The objectives' table order is their documentation order.
        assert_eq!(keys(Role::Objective), objectives);
        assert_eq!(sorted(keys(Role::Constraint)), sorted(constraints.to_vec()));
        assert_eq!(sorted(keys(Role::FrontMeasure)), sorted(measures.to_vec()));
        let mut columns = constraints.to_vec();
        columns.push("real_area");
        assert_eq!(sorted(keys(Role::SweepColumn)), sorted(columns));
        for q in Quantity::ALL {
            assert_eq!(
                q.has_role(Role::QuantityOfInterest),
                q != Quantity::WorkOfAdhesion,
                "{q}"
            );
        }
    }

    #[test]
    fn keys_round_trip_and_are_snake_case() {
        for q in Quantity::ALL {
            assert_eq!(Quantity::from_key(q.as_str()), Some(q));
            let json = serde_json::to_string(&q).unwrap();
            assert_eq!(json, format!("\"{}\"", q.as_str()));
        }
        assert_eq!(Quantity::from_key("Wear_Rate"), None);
        assert_eq!(format!("{:<10}|", Quantity::WearRate), "wear_rate |");
    }

    #[test]
    fn natural_ranges() {
        assert_eq!(
            Quantity::PullOffForce.natural_range(),
            (f64::NEG_INFINITY, f64::INFINITY)
        );
        assert_eq!(Quantity::RealAreaFraction.natural_range(), (0.0, 1.0));
        assert_eq!(Quantity::WearRate.natural_range(), (0.0, f64::INFINITY));
    }

    /// The micro-gear of the shipped problems, with every requirement set and the
    /// stress-assisted wear law (silicon's values) so that every quantity exists,
    /// and its evaluation with the pull-off.
    fn micro_gear() -> (Scene, Evaluation) {
        let problem =
            crate::problem::load(std::path::Path::new("problems/micro-gear.toml")).unwrap();
        let mut scene = problem.scene;
        scene.requirements.restoring_force = Some(1e-6);
        scene.requirements.shear_strength = Some(1e8);
        scene.requirements.allowed_wear_depth = Some(1e-7);
        scene.requirements.sliding_per_cycle = Some(1e-4);
        scene.wear_law = crate::model::WearModel::StressAssisted;
        scene.activation = Some(crate::model::wear_law::Activation {
            activation_energy: 0.91 * crate::units::ELECTRON_VOLT,
            activation_volume: 6.7e-30,
            attempt_frequency: 1e13,
            site_spacing: 0.384e-9,
            atomic_volume: 20.02e-30,
            stress: crate::model::wear_law::ContactStress::Normal,
            sliding_speed: 38e-3,
        });
        let options = EvaluationOptions {
            pull_off: true,
            ..Default::default()
        };
        let ev = evaluate(&scene, &options);
        assert_eq!(ev.status, Status::Ok);
        (scene, ev)
    }

    #[test]
    fn values_are_the_evaluation_fields() {
        let (s, ev) = micro_gear();
        let field = |q: Quantity| -> Option<f64> {
            match q {
                Quantity::WearRate => Some(ev.wear_rate),
                Quantity::WearVolume => Some(ev.wear_volume),
                Quantity::RealArea => Some(ev.real_area),
                Quantity::PullOffForce => ev.pull_off_force,
                Quantity::FrictionForce => ev.friction_force,
                Quantity::FrictionCoefficient => ev.friction_coefficient,
                Quantity::PlasticityIndex => Some(ev.indices.plasticity_index),
                Quantity::ElasticAdhesionIndex => Some(ev.indices.elastic_adhesion_index),
                Quantity::PlasticAdhesionIndex => Some(ev.indices.plastic_adhesion_index),
                Quantity::TaborParameter => Some(ev.indices.tabor_parameter),
                Quantity::HardnessToModulus => Some(s.hardness / s.youngs_modulus_a),
                Quantity::RealAreaFraction => Some(ev.real_area_fraction),
                Quantity::PlasticAreaFraction => Some(ev.plastic_area_fraction),
                Quantity::MeanRealPressure => ev.mean_real_pressure,
                Quantity::ContactCount => Some(ev.contact_count),
                Quantity::Separation => ev.separation,
                Quantity::StictionMargin => ev.stiction.map(|st| st.margin),
                Quantity::ReleaseMargin => ev.pull_off_force.map(|f| f / s.load.abs()),
                Quantity::LifeCycles => ev.life_cycles,
                Quantity::LifeSlidingDistance => ev.life_sliding_distance,
                Quantity::WearDepthRate => Some(ev.wear_depth_rate),
                Quantity::ElasticRealArea => Some(ev.elastic_real_area),
                Quantity::PlasticRealArea => Some(ev.plastic_real_area),
                Quantity::PlasticContactCount => Some(ev.plastic_contact_count),
                Quantity::WorkOfAdhesion => Some(s.work_of_adhesion),
                Quantity::EffectiveWearCoefficient => {
                    ev.wear_details.and_then(|w| w.effective_wear_coefficient)
                }
                Quantity::MeanContactStress => ev.wear_details.and_then(|w| w.mean_contact_stress),
                Quantity::SaturatedFraction => ev.wear_details.and_then(|w| w.saturated_fraction),
                Quantity::ApparentActivationEnergy => {
                    ev.wear_details.and_then(|w| w.apparent_activation_energy)
                }
                Quantity::CriticalJunctionSize => ev.debris.map(|d| d.critical_junction_size),
                Quantity::DebrisContactFraction => {
                    ev.debris.and_then(|d| d.debris_contact_fraction)
                }
                Quantity::DebrisAreaFraction => ev.debris.and_then(|d| d.debris_area_fraction),
            }
        };
        for q in Quantity::ALL {
            let v = q.value(&ev, &s);
            assert!(v.is_some(), "{q}: every quantity exists on this scene");
            assert_eq!(v.map(f64::to_bits), field(q).map(f64::to_bits), "{q}");
        }
    }

    #[test]
    fn logarithms_are_those_of_the_values() {
        let (s, ev) = micro_gear();
        let mut checked = 0;
        for q in Quantity::ALL {
            let v = q.value(&ev, &s).unwrap();
            if !(v > 0.0 && v.is_finite()) {
                continue;
            }
            let ln = q.ln_value(&ev, &s);
            assert!(
                (ln - v.ln()).abs() <= 1e-12 * v.ln().abs().max(1.0),
                "{q}: ln_value {ln} against ln {}",
                v.ln()
            );
            let log10 = q.log10_value(&ev, &s).unwrap();
            assert!(
                (log10 - v.log10()).abs() <= 1e-12 * v.log10().abs().max(1.0),
                "{q}: log10_value {log10} against log10 {}",
                v.log10()
            );
            checked += 1;
        }
        assert!(checked >= 20, "only {checked} positive values");
    }

    #[test]
    fn a_missing_value_has_the_floor_for_logarithm() {
        let (mut s, mut ev) = micro_gear();
        ev.pull_off_force = None;
        ev.log10_pull_off_force = None;
        ev.separation = None;
        s.requirements.restoring_force = None;
        for q in [
            Quantity::PullOffForce,
            Quantity::StictionMargin,
            Quantity::ReleaseMargin,
            Quantity::Separation,
        ] {
            assert_eq!(q.ln_value(&ev, &s), LN_FLOOR, "{q}");
        }
        assert_eq!(Quantity::PullOffForce.value(&ev, &s), None);
        assert_eq!(Quantity::PullOffForce.log10_value(&ev, &s), None);
    }
}
