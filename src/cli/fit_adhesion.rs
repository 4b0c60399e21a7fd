//! `wearopt fit-adhesion`: the work of adhesion (and μ) from friction measurements.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::Args;

use wearopt::app::fit_adhesion::{self as fit, FitAdhesionOptions, FrictionCoefficient, Modulus};
use wearopt::app::quantity::{positive_quantity, OptionQuantity};
use wearopt::app::OptionName;
use wearopt::report::{self, Format};

use super::format::formats;

/// Arguments of `wearopt fit-adhesion`.
#[derive(Debug, Args)]
pub struct FitAdhesionArgs {
    /// Friction measurements: CSV with the header `load,friction`, one row per
    /// measurement; numbers in newtons or strings such as "20 uN".
    pub data: PathBuf,
    /// Radius R of the sphere, e.g. "0.3 mm" (a plain number is metres).
    #[arg(long)]
    pub radius: String,
    /// Friction coefficient μ, held fixed (default 0.1, the paper's value).
    #[arg(long, conflicts_with = "fit_mu")]
    pub mu: Option<f64>,
    /// Fit μ together with γ.
    #[arg(long)]
    pub fit_mu: bool,
    /// Equivalent modulus E = [(1-ν1²)/E1 + (1-ν2²)/E2]⁻¹, e.g. "100 GPa", for the
    /// contact radius and the bond strength F/(πr²).
    #[arg(long, conflicts_with = "materials")]
    pub modulus: Option<String>,
    /// Catalogue materials of the sphere and the flat (one name: both), for E.
    #[arg(long, value_delimiter = ',', value_name = "A,B")]
    pub materials: Vec<String>,
    /// A quoted work of adhesion to compare the fit with, e.g. "0.1 N/m" (the paper's
    /// 0.1 N/m and 65 MPa are compared automatically for its own table).
    #[arg(long, value_name = "GAMMA")]
    pub quoted_gamma: Option<String>,
    /// A quoted bond strength F/(πr²) to compare with, e.g. "65 MPa".
    #[arg(long, value_name = "STRESS")]
    pub quoted_bond_strength: Option<String>,
    /// Output format.
    #[arg(long, value_parser = formats("fit-adhesion", report::calibrate::FORMATS), default_value = "text")]
    pub format: Format,
}

fn quantity(name: &'static str, text: &str, quantity: OptionQuantity) -> Result<f64> {
    Ok(positive_quantity(OptionName(name), text, quantity)?)
}

/// Runs the calibration.
pub fn run(args: FitAdhesionArgs) -> Result<ExitCode> {
    let radius = quantity("radius", &args.radius, OptionQuantity::SphereRadius)?;
    let friction_coefficient = match (args.mu, args.fit_mu) {
        (Some(mu), _) => FrictionCoefficient::Given(mu),
        (None, true) => FrictionCoefficient::Fit,
        (None, false) => FrictionCoefficient::Default,
    };
    let modulus = match (&args.modulus, args.materials.is_empty()) {
        (Some(e), _) => Modulus::Value(quantity("modulus", e, OptionQuantity::Modulus)?),
        (None, false) => Modulus::Materials(args.materials.clone()),
        (None, true) => Modulus::None,
    };
    let quoted_gamma = args
        .quoted_gamma
        .as_deref()
        .map(|q| quantity("quoted_gamma", q, OptionQuantity::WorkOfAdhesion))
        .transpose()?;
    let quoted_bond_strength = args
        .quoted_bond_strength
        .as_deref()
        .map(|q| quantity("quoted_bond_strength", q, OptionQuantity::Stress))
        .transpose()?;
    let options = FitAdhesionOptions {
        radius,
        friction_coefficient,
        modulus,
        quoted_gamma,
        quoted_bond_strength,
    };
    let calibration = fit::fit_adhesion(&args.data, &options)?;
    super::print_out(&report::calibrate::render(&calibration, args.format)?)?;
    Ok(ExitCode::SUCCESS)
}
