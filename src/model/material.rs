//! A material's properties as the model and the design search read them (the
//! catalogue of `problem::catalogue` holds the values).

use serde::Serialize;

/// One catalogue material. All values SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Material {
    /// Canonical name, as written in problem files and reports.
    pub name: &'static str,
    /// Other accepted names (matched case-insensitively, like `name`).
    pub aliases: &'static [&'static str],
    /// E, Young's modulus (Pa).
    pub youngs_modulus: f64,
    /// ν, Poisson ratio.
    pub poisson_ratio: f64,
    /// H, indentation hardness (Pa).
    pub hardness: f64,
    /// Typical range of the work of adhesion γ (J/m²), low to high.
    pub work_of_adhesion: (f64, f64),
    /// Where the numbers come from.
    pub source: &'static str,
}
