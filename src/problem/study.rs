//! What a problem asks beyond evaluating its scene: the file stage's side of the
//! study vocabulary. The types themselves ([`DesignVariable`], [`Objective`],
//! [`Constraint`], [`ParetoSpec`], [`OptimizerSettings`]) belong to
//! [`crate::optimize`]; this stage gathers them into a [`Study`] and knows how
//! files write them (units, scene keys, example bounds).

use serde::Serialize;

use crate::optimize::{
    Constraint, ConstraintQuantity, DesignQuantity, DesignVariable, Objective, OptimizerSettings,
    ParetoSpec,
};
use crate::units::Dimension;

/// The dimension a quantity's values and bounds are written in.
pub trait Dimensioned {
    /// The dimension of its values and bounds.
    fn dimension(self) -> Dimension;
}

impl Dimensioned for DesignQuantity {
    fn dimension(self) -> Dimension {
        match self {
            DesignQuantity::YoungsModulus
            | DesignQuantity::YoungsModulusA
            | DesignQuantity::YoungsModulusB
            | DesignQuantity::Hardness => Dimension::Pressure,
            DesignQuantity::PoissonRatio => Dimension::Dimensionless,
            DesignQuantity::WorkOfAdhesion => Dimension::SurfaceEnergy,
            DesignQuantity::Sigma | DesignQuantity::AsperityRadius => Dimension::Length,
            DesignQuantity::AsperityDensity => Dimension::InverseArea,
        }
    }
}

impl Dimensioned for ConstraintQuantity {
    fn dimension(self) -> Dimension {
        match self {
            ConstraintQuantity::PullOffForce | ConstraintQuantity::FrictionForce => {
                Dimension::Force
            }
            ConstraintQuantity::MeanRealPressure => Dimension::Pressure,
            ConstraintQuantity::Separation => Dimension::Length,
            ConstraintQuantity::WearRate => Dimension::WearRate,
            _ => Dimension::Dimensionless,
        }
    }
}

/// How a problem file and its messages name a design variable's scene value.
pub(crate) trait DesignKeys {
    /// The dotted key of the scene value it moves: `roughness.sigma`.
    fn scene_key(self) -> &'static str;
    /// Example bounds as written in a file, for messages.
    fn example_bounds(self) -> &'static str;
}

impl DesignKeys for DesignQuantity {
    fn scene_key(self) -> &'static str {
        match self {
            DesignQuantity::YoungsModulus | DesignQuantity::YoungsModulusA => {
                "bodies.a.youngs_modulus"
            }
            DesignQuantity::YoungsModulusB => "bodies.b.youngs_modulus",
            DesignQuantity::PoissonRatio => "bodies.a.poisson_ratio",
            DesignQuantity::Hardness => "interface.hardness",
            DesignQuantity::WorkOfAdhesion => "interface.work_of_adhesion",
            DesignQuantity::Sigma => "roughness.sigma",
            DesignQuantity::AsperityRadius => "roughness.asperity_radius",
            DesignQuantity::AsperityDensity => "roughness.asperity_density",
        }
    }

    fn example_bounds(self) -> &'static str {
        match self {
            DesignQuantity::YoungsModulus
            | DesignQuantity::YoungsModulusA
            | DesignQuantity::YoungsModulusB => "{ min = \"50 GPa\", max = \"400 GPa\" }",
            DesignQuantity::PoissonRatio => "{ min = 0.1, max = 0.4 }",
            DesignQuantity::Hardness => "{ min = \"1 GPa\", max = \"40 GPa\" }",
            DesignQuantity::WorkOfAdhesion => "{ min = \"5 mJ/m^2\", max = \"0.2 J/m^2\" }",
            DesignQuantity::Sigma => "{ min = \"0.5 nm\", max = \"20 nm\" }",
            DesignQuantity::AsperityRadius => "{ min = \"0.2 um\", max = \"10 um\" }",
            DesignQuantity::AsperityDensity => "{ min = \"1 um^-2\", max = \"100 um^-2\" }",
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
