//! `wearopt fit-adhesion`: the work of adhesion (and μ) from friction measurements
//! by the JKR friction law (docs/model.md §5).

use std::path::Path;

use crate::calibrate::{self, FitSettings, FrictionData, Quoted};

use super::AppError;

pub use crate::calibrate::{Calibration, FrictionCoefficient};

/// Where the equivalent modulus comes from.
#[derive(Debug, Clone, PartialEq)]
pub enum Modulus {
    /// Not given: no contact radius or bond strength.
    None,
    /// E itself (Pa).
    Value(f64),
    /// Catalogue materials of the sphere and the flat (one name: both).
    Materials(Vec<String>),
}

/// The options of `wearopt fit-adhesion` (SI values).
#[derive(Debug, Clone, PartialEq)]
pub struct FitAdhesionOptions {
    /// R, radius of the sphere (m).
    pub radius: f64,
    /// How μ is treated.
    pub friction_coefficient: FrictionCoefficient,
    /// The equivalent modulus.
    pub modulus: Modulus,
    /// A quoted work of adhesion to compare with (N/m).
    pub quoted_gamma: Option<f64>,
    /// A quoted bond strength F/(πr²) to compare with (Pa).
    pub quoted_bond_strength: Option<f64>,
}

/// Reads the friction data at `path` and fits it, as `wearopt fit-adhesion` does.
pub fn fit_adhesion(path: &Path, options: &FitAdhesionOptions) -> Result<Calibration, AppError> {
    let equivalent_modulus = match &options.modulus {
        Modulus::None => None,
        Modulus::Value(e) => Some(*e),
        Modulus::Materials(names) => {
            let m = calibrate::lookup_materials(names)?;
            Some(calibrate::equivalent_modulus(m[0], m[m.len() - 1]))
        }
    };
    let data = calibrate::read_csv(path)?;
    fit_data(&data, options, equivalent_modulus)
}

fn fit_data(
    data: &FrictionData,
    options: &FitAdhesionOptions,
    equivalent_modulus: Option<f64>,
) -> Result<Calibration, AppError> {
    let radius = options.radius;
    // The paper's own table: compare with what the paper quotes from it.
    let ando = data.is_ando_table() && (radius / calibrate::ANDO_RADIUS - 1.0).abs() < 1e-9;
    let quoted = if options.quoted_gamma.is_some() || options.quoted_bond_strength.is_some() {
        Some(Quoted {
            source: "the quoted values".into(),
            work_of_adhesion: options.quoted_gamma,
            bond_strength: options.quoted_bond_strength,
        })
    } else if ando {
        Some(Quoted::paper())
    } else {
        None
    };
    let settings = FitSettings {
        radius,
        friction_coefficient: options.friction_coefficient,
        equivalent_modulus,
        quoted,
    };
    Ok(calibrate::fit(data, &settings)?)
}
