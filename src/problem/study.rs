//! What a problem asks beyond evaluating its scene: the file stage's side of the
//! study vocabulary. The types themselves ([`DesignVariable`], [`Objective`],
//! [`Constraint`], [`ParetoSpec`], [`OptimizerSettings`]) belong to
//! [`crate::optimize`]; this stage gathers them into a [`Study`] and knows how
//! files write them (units, scene keys, example bounds).

use serde::Serialize;

use crate::optimize::{
    Constraint, ConstraintQuantity, DesignVariable, Objective, OptimizerSettings, ParetoSpec,
    SceneParameter,
};
use crate::units::Dimension;

/// The dimension a quantity's values and bounds are written in.
pub trait Dimensioned {
    /// The dimension of its values and bounds.
    fn dimension(self) -> Dimension;
}

impl Dimensioned for SceneParameter {
    fn dimension(self) -> Dimension {
        SceneParameter::dimension(self)
    }
}

impl Dimensioned for ConstraintQuantity {
    fn dimension(self) -> Dimension {
        self.quantity().dimension()
    }
}

/// How a problem file and its messages name a design variable's scene value.
pub(crate) trait DesignKeys {
    /// The dotted key of the scene value it moves: `roughness.sigma`.
    fn scene_key(self) -> &'static str;
    /// Example bounds as written in a file, for messages.
    fn example_bounds(self) -> &'static str;
}

impl DesignKeys for SceneParameter {
    fn scene_key(self) -> &'static str {
        match self {
            SceneParameter::YoungsModulus | SceneParameter::YoungsModulusA => {
                "bodies.a.youngs_modulus"
            }
            SceneParameter::YoungsModulusB => "bodies.b.youngs_modulus",
            SceneParameter::PoissonRatio => "bodies.a.poisson_ratio",
            SceneParameter::Hardness => "interface.hardness",
            SceneParameter::WorkOfAdhesion => "interface.work_of_adhesion",
            SceneParameter::Sigma => "roughness.sigma",
            SceneParameter::AsperityRadius => "roughness.asperity_radius",
            SceneParameter::AsperityDensity => "roughness.asperity_density",
            SceneParameter::NominalArea => "contact.nominal_area",
            SceneParameter::Load => "contact.load",
            SceneParameter::InteratomicDistance => "interface.interatomic_distance",
            SceneParameter::ContactAngle => "interface.contact_angle",
            SceneParameter::ContactAngleA => "interface.contact_angle_a",
            SceneParameter::ContactAngleB => "interface.contact_angle_b",
            SceneParameter::Temperature => "environment.temperature",
            SceneParameter::WearCoefficient => "contact.wear_coefficient",
            SceneParameter::SlidingDistance => "contact.sliding_distance",
            SceneParameter::RelativeHumidity => "environment.relative_humidity",
            SceneParameter::ActivationEnergy => "wear.activation_energy",
            SceneParameter::ActivationVolume => "wear.activation_volume",
            SceneParameter::SlidingSpeed => "wear.sliding_speed",
        }
    }

    fn example_bounds(self) -> &'static str {
        match self {
            SceneParameter::YoungsModulus
            | SceneParameter::YoungsModulusA
            | SceneParameter::YoungsModulusB => "{ min = \"50 GPa\", max = \"400 GPa\" }",
            SceneParameter::PoissonRatio => "{ min = 0.1, max = 0.4 }",
            SceneParameter::Hardness => "{ min = \"1 GPa\", max = \"40 GPa\" }",
            SceneParameter::WorkOfAdhesion => "{ min = \"5 mJ/m^2\", max = \"0.2 J/m^2\" }",
            SceneParameter::Sigma => "{ min = \"0.5 nm\", max = \"20 nm\" }",
            SceneParameter::AsperityRadius => "{ min = \"0.2 um\", max = \"10 um\" }",
            SceneParameter::AsperityDensity => "{ min = \"1 um^-2\", max = \"100 um^-2\" }",
            SceneParameter::ContactAngle
            | SceneParameter::ContactAngleA
            | SceneParameter::ContactAngleB => "{ min = \"0 deg\", max = \"110 deg\" }",
            SceneParameter::Temperature => "{ min = \"273 K\", max = \"350 K\" }",
            SceneParameter::ActivationEnergy => "{ min = \"0.5 eV\", max = \"1.5 eV\" }",
            SceneParameter::ActivationVolume => "{ min = \"1e-3 nm^3\", max = \"0.02 nm^3\" }",
            SceneParameter::SlidingSpeed => "{ min = \"1 um/s\", max = \"0.1 m/s\" }",
            // Not design variables: bounds no message asks for.
            SceneParameter::NominalArea
            | SceneParameter::Load
            | SceneParameter::InteratomicDistance
            | SceneParameter::WearCoefficient
            | SceneParameter::SlidingDistance
            | SceneParameter::RelativeHumidity => "",
        }
    }
}

/// Everything a problem asks beyond its scene. Empty when the file has only a scene.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct Study {
    /// `[design]` variables, in file order.
    pub design: Vec<DesignVariable>,
    /// `[design] materials`: catalogue names (canonical spelling) body a may be made of.
    pub materials: Vec<String>,
    /// `[objective]`.
    pub objective: Option<Objective>,
    /// `[[constraint]]`s in file order.
    pub constraints: Vec<Constraint>,
    /// `[pareto]`.
    pub pareto: Option<ParetoSpec>,
    /// `[optimizer]`, defaults filled in.
    pub optimizer: OptimizerSettings,
}

impl Study {
    /// Whether the study moves anything (variables or materials).
    pub fn has_design(&self) -> bool {
        !self.design.is_empty() || !self.materials.is_empty()
    }
}
