//! The study vocabulary: what a design search may move ([`DesignVariable`]),
//! what it minimises ([`Objective`]), the limits it keeps ([`Constraint`]), the
//! adhesion axis of a front ([`ParetoSpec`]) and how hard it tries
//! ([`OptimizerSettings`]).
//!
//! These are the optimiser's own inputs; the problem-file stage
//! ([`crate::problem`]) parses and validates TOML into them, as it does into a
//! [`crate::model::Scene`].

use std::time::Duration;

use serde::Serialize;

pub use crate::model::{Quantity, SceneParameter};

/// A closed set of names as written in problem files.
pub trait Named: Copy + Sized + 'static {
    /// Every value, in documentation order.
    const ALL: &'static [Self];
    /// The name as written in a problem file.
    fn as_str(self) -> &'static str;
    /// The value written as `name` (exact match).
    fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|v| v.as_str() == name)
    }
    /// Every name, for messages.
    fn names() -> Vec<&'static str> {
        Self::ALL.iter().map(|v| v.as_str()).collect()
    }
}

macro_rules! named_enum {
    ($(#[$meta:meta])* $name:ident { $($(#[$vmeta:meta])* $variant:ident => $text:expr,)+ }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
        #[serde(rename_all = "snake_case")]
        pub enum $name {
            $($(#[$vmeta])* $variant,)+
        }
        impl Named for $name {
            const ALL: &'static [Self] = &[$($name::$variant,)+];
            fn as_str(self) -> &'static str {
                match self {
                    $($name::$variant => $text,)+
                }
            }
        }
        impl $name {
            /// The name as written in a problem file.
            pub fn as_str(self) -> &'static str {
                <Self as Named>::as_str(self)
            }
        }
        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.pad(self.as_str())
            }
        }
    };
}

/// A role subset of the quantity table: each variant is the [`Quantity`] of the
/// same name (its value, logarithm, dimension and range), and its name is the
/// row's key.
macro_rules! quantity_subset {
    ($(#[$meta:meta])* $name:ident { $($(#[$vmeta:meta])* $variant:ident,)+ }) => {
        named_enum! {
            $(#[$meta])*
            $name {
                $(
                    #[doc = concat!("[`Quantity::", stringify!($variant), "`].")]
                    $(#[$vmeta])*
                    $variant => Quantity::$variant.as_str(),
                )+
            }
        }
        impl $name {
            /// Its row of the quantity table.
            pub fn quantity(self) -> Quantity {
                match self {
                    $($name::$variant => Quantity::$variant,)+
                }
            }
            /// The one whose row is `q`, if `q` is one of them.
            pub fn from_quantity(q: Quantity) -> Option<Self> {
                <Self as Named>::ALL.iter().copied().find(|v| v.quantity() == q)
            }
        }
    };
}

/// The scene parameters a design may move are the `[design]` keys.
impl Named for SceneParameter {
    const ALL: &'static [Self] = &SceneParameter::DESIGN;
    fn as_str(self) -> &'static str {
        SceneParameter::as_str(self)
    }
}

/// One variable the optimiser may move, within `[min, max]` (SI units).
///
/// `min < max`, both finite and in the quantity's valid range, and the scene's value
/// lies inside. Not every range is positive: `poisson_ratio` may go below 0 and
/// `work_of_adhesion` may start at 0, so an optimiser that scales variables
/// logarithmically must check `min > 0` itself.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DesignVariable {
    /// Which scene quantity.
    pub name: SceneParameter,
    /// Lower bound (SI).
    pub min: f64,
    /// Upper bound (SI).
    pub max: f64,
}

quantity_subset! {
    /// What `[objective] minimize = …` asks to make small.
    Objective {
        WearRate,
        WearVolume,
        RealArea,
        PullOffForce,
        /// Needs `interface.shear_strength`.
        FrictionForce,
        /// Needs `interface.shear_strength`.
        FrictionCoefficient,
    }
}

quantity_subset! {
    /// A quantity a `[[constraint]]` bounds.
    ConstraintQuantity {
        PullOffForce,
        PlasticityIndex,
        ElasticAdhesionIndex,
        PlasticAdhesionIndex,
        TaborParameter,
        HardnessToModulus,
        RealAreaFraction,
        PlasticAreaFraction,
        MeanRealPressure,
        ContactCount,
        Separation,
        WearRate,
        /// Needs `contact.restoring_force`.
        StictionMargin,
        /// Needs `interface.shear_strength`.
        FrictionForce,
        /// Needs `interface.shear_strength`.
        FrictionCoefficient,
        /// For a tensile load only.
        ReleaseMargin,
    }
}

/// The `release_margin` minimum added to every study under a tensile load that
/// does not bound it itself: a design holding with less than 20 % to spare is one
/// small disturbance (a shock, a drift of the load) from releasing.
pub const DEFAULT_RELEASE_MARGIN: f64 = 1.2;

impl ConstraintQuantity {
    /// The values the quantity can take, `(lowest, highest)`; bounds outside can never
    /// be met and are refused.
    pub fn natural_range(self) -> (f64, f64) {
        self.quantity().natural_range()
    }
}

/// One `[[constraint]]`: `min <= quantity <= max` (SI); at least one bound is present
/// and `min < max` when both are.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Constraint {
    /// What is bounded.
    pub quantity: ConstraintQuantity,
    /// Lower bound (SI), if any.
    pub min: Option<f64>,
    /// Upper bound (SI), if any.
    pub max: Option<f64>,
    /// Over a humidity range: held only at the humidity the objective is taken
    /// at, not at each of the range's (a front's ε-row, which holds the adhesion
    /// measured there). Every `[[constraint]]` of a file holds at each (false).
    #[serde(skip)]
    pub only_at_objective_humidity: bool,
}

quantity_subset! {
    /// The adhesion measure on the second axis of a Pareto front.
    AdhesionMeasure {
        PullOffForce,
        /// Needs `work_of_adhesion` among the design variables.
        WorkOfAdhesion,
        ElasticAdhesionIndex,
    }
}

named_enum! {
    /// Which end of the adhesion measure the front is to favour.
    ParetoDirection {
        /// Small adhesion is good (the usual MEMS goal: no stiction).
        Low => "low",
        /// Large adhesion is good (e.g. a switch that must hold closed).
        High => "high",
    }
}

/// `[pareto]`: trade the objective against an adhesion measure.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ParetoSpec {
    /// The adhesion measure.
    pub adhesion: AdhesionMeasure,
    /// Number of points on the front, 2..=200.
    pub points: usize,
    /// Which end of the adhesion measure is preferred.
    pub direction: ParetoDirection,
}

impl ParetoSpec {
    /// Fewest points a front may have.
    pub const MIN_POINTS: usize = 2;
    /// Most points a front may have (a sweep refuses nonsense up front).
    pub const MAX_POINTS: usize = 200;
    /// Points when the file does not say.
    pub const DEFAULT_POINTS: usize = 15;
}

/// `[optimizer]`: how hard the optimiser tries. Every field has a default
/// ([`OptimizerSettings::default`]); [`OptimizerSettings::validate`] names the field and
/// the accepted range of anything out of bounds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OptimizerSettings {
    /// Number of starting points of the multistart (1..=1000; default 8).
    pub starts: usize,
    /// Seed of the random starting points (default 1): the same seed gives the same run.
    pub seed: u64,
    /// Relative tolerance on the KKT conditions and steps, in (0, 1) (default 1e-8).
    pub tolerance: f64,
    /// Iteration cap per start (1..=10000; default 200).
    pub max_iterations: usize,
    /// Wall-clock limit of the whole study, > 0 (default 60 s).
    #[serde(serialize_with = "seconds")]
    pub time_limit: Duration,
}

fn seconds<S: serde::Serializer>(d: &Duration, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_f64(d.as_secs_f64())
}

impl Default for OptimizerSettings {
    fn default() -> Self {
        OptimizerSettings {
            starts: 8,
            seed: 1,
            tolerance: 1e-8,
            max_iterations: 200,
            time_limit: Duration::from_secs(60),
        }
    }
}

/// A setting out of its accepted range.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("optimizer.{field} = {value}: {expected}")]
pub struct SettingsError {
    /// The key in `[optimizer]`.
    pub field: &'static str,
    /// The value given.
    pub value: String,
    /// The accepted range.
    pub expected: String,
}

impl OptimizerSettings {
    /// Accepted range of `starts`.
    pub const STARTS: (usize, usize) = (1, 1000);
    /// Accepted range of `max_iterations`.
    pub const MAX_ITERATIONS: (usize, usize) = (1, 10_000);

    /// Checks every field against its accepted range.
    pub fn validate(&self) -> Result<(), SettingsError> {
        let err = |field, value: String, expected: &str| SettingsError {
            field,
            value,
            expected: expected.to_string(),
        };
        if !(Self::STARTS.0..=Self::STARTS.1).contains(&self.starts) {
            return Err(err(
                "starts",
                self.starts.to_string(),
                "must be an integer in 1..=1000 (number of starting points)",
            ));
        }
        if !(self.tolerance > 0.0 && self.tolerance < 1.0) {
            return Err(err(
                "tolerance",
                self.tolerance.to_string(),
                "must be in (0, 1), e.g. 1e-8",
            ));
        }
        if !(Self::MAX_ITERATIONS.0..=Self::MAX_ITERATIONS.1).contains(&self.max_iterations) {
            return Err(err(
                "max_iterations",
                self.max_iterations.to_string(),
                "must be an integer in 1..=10000 (iterations per start)",
            ));
        }
        // A zero time limit is accepted: the study then stops after evaluating
        // its starts, with status time_limit.
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for q in SceneParameter::DESIGN {
            assert_eq!(<SceneParameter as Named>::from_name(q.as_str()), Some(q));
        }
        for q in ConstraintQuantity::ALL {
            assert_eq!(ConstraintQuantity::from_name(q.as_str()), Some(*q));
        }
        assert_eq!(Objective::from_name("wear_rate"), Some(Objective::WearRate));
        assert_eq!(Objective::from_name("Wear_Rate"), None);
    }

    /// The names files and messages accept, in the order messages list them: a
    /// changed spelling or order fails here.
    #[test]
    fn accepted_names_are_unchanged() {
        assert_eq!(
            Objective::names(),
            [
                "wear_rate",
                "wear_volume",
                "real_area",
                "pull_off_force",
                "friction_force",
                "friction_coefficient",
            ]
        );
        assert_eq!(
            ConstraintQuantity::names(),
            [
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
            ]
        );
        assert_eq!(
            AdhesionMeasure::names(),
            [
                "pull_off_force",
                "work_of_adhesion",
                "elastic_adhesion_index"
            ]
        );
        assert_eq!(
            <SceneParameter as Named>::names(),
            [
                "youngs_modulus",
                "youngs_modulus_a",
                "youngs_modulus_b",
                "poisson_ratio",
                "hardness",
                "work_of_adhesion",
                "sigma",
                "asperity_radius",
                "asperity_density",
                "contact_angle",
                "contact_angle_a",
                "contact_angle_b",
                "temperature",
                "activation_energy",
                "activation_volume",
                "sliding_speed",
            ]
        );
    }

    /// Each subset is its role's rows of the quantity table, and serialises as
    /// the row's key.
    #[test]
    fn subsets_are_the_table_roles() {
        use crate::model::Role;
        fn check<T: Named + Serialize + PartialEq + std::fmt::Debug>(
            role: Role,
            quantity: fn(T) -> Quantity,
            from: fn(Quantity) -> Option<T>,
        ) {
            let mut ours: Vec<Quantity> = T::ALL.iter().map(|&v| quantity(v)).collect();
            let mut table = Quantity::with_role(role);
            for &v in T::ALL {
                assert_eq!(v.as_str(), quantity(v).as_str());
                assert_eq!(from(quantity(v)), Some(v));
                let json = serde_json::to_string(&v).unwrap();
                assert_eq!(json, format!("\"{}\"", v.as_str()));
            }
            ours.sort_by_key(|q| q.as_str());
            table.sort_by_key(|q| q.as_str());
            assert_eq!(ours, table);
        }
        check(
            Role::Objective,
            Objective::quantity,
            Objective::from_quantity,
        );
        check(
            Role::Constraint,
            ConstraintQuantity::quantity,
            ConstraintQuantity::from_quantity,
        );
        check(
            Role::FrontMeasure,
            AdhesionMeasure::quantity,
            AdhesionMeasure::from_quantity,
        );
        assert_eq!(
            ConstraintQuantity::from_quantity(Quantity::WearVolume),
            None
        );
    }

    #[test]
    fn default_settings_are_valid() {
        assert_eq!(OptimizerSettings::default().validate(), Ok(()));
        let bad = OptimizerSettings {
            starts: 0,
            ..Default::default()
        };
        assert_eq!(bad.validate().unwrap_err().field, "starts");
    }
}
