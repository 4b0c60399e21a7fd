//! `wearopt fit-wear`: the activation energy and volume of stress-assisted wear
//! from measured wear rates.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::Args;

use wearopt::app::fit_wear::{self as fit, WearFitSettings};
use wearopt::report::{self, Format};

use super::format::formats;

/// Arguments of `wearopt fit-wear`.
#[derive(Debug, Args)]
pub struct FitWearArgs {
    /// Wear rates: CSV with the header `stress_Pa,RATE` or
    /// `stress_Pa,RATE,temperature_K`, RATE one of `rate_atoms_per_s`,
    /// `rate_m3_per_s`, `rate_m3_per_m` (the unit is in the name); one row per
    /// measurement.
    pub data: PathBuf,
    /// The temperature of every point when the file has no temperature_K column,
    /// e.g. "350 K" (default 298.15 K).
    #[arg(long)]
    pub temperature: Option<String>,
    /// Sliding speed, e.g. "1 mm/s": turns rates in m³ per metre slid into m³/s
    /// (needed for rate_m3_per_m, refused for the others).
    #[arg(long)]
    pub speed: Option<String>,
    /// Output format.
    #[arg(long, value_parser = formats("fit-wear", report::fit_wear::FORMATS), default_value = "text")]
    pub format: Format,
}

/// Runs the fit.
pub fn run(args: FitWearArgs) -> Result<ExitCode> {
    let settings = WearFitSettings {
        temperature: args
            .temperature
            .as_deref()
            .map(fit::temperature_option)
            .transpose()?,
        speed: args.speed.as_deref().map(fit::speed_option).transpose()?,
    };
    let result = fit::fit_wear(&args.data, &settings)?;
    super::print_out(&report::fit_wear::render(&result, args.format)?)?;
    Ok(ExitCode::SUCCESS)
}
