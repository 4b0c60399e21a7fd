//! `wearopt accuracy`: the work–precision report of the evaluator.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::Args;

use wearopt::accuracy::{work_precision, Options};
use wearopt::report::{self, Format};

use super::format::{formats, refuse};

/// Arguments of `wearopt accuracy`.
#[derive(Debug, Args)]
pub struct AccuracyArgs {
    /// A problem file whose region (θ, λ, h and neighbours), loads and sensitivities
    /// are added to the extreme-range grid; without it the shipped scenes are used.
    pub file: Option<PathBuf>,
    /// Output format: tables for people; CSV
    /// (`quantity,setting,max_rel_error,median_rel_error,time_per_eval_ns,is_default,adhesion_model,attraction`);
    /// or one JSON object (provenance and the rows).
    #[arg(long, value_parser = formats("accuracy", report::accuracy::FORMATS), default_value = "text")]
    pub format: Format,
    /// Also write a log–log SVG of error against time per evaluation to this file.
    #[arg(long, value_name = "WORK_PRECISION.svg")]
    pub plot: Option<PathBuf>,
}

/// The shipped scenes used when no file is given.
const SHIPPED: [(&str, &str); 3] = [
    (
        "problems/micro-gear.toml",
        include_str!("../../problems/micro-gear.toml"),
    ),
    (
        "problems/dlc-contact.toml",
        include_str!("../../problems/dlc-contact.toml"),
    ),
    (
        "problems/gold-switch.toml",
        include_str!("../../problems/gold-switch.toml"),
    ),
];

/// Runs the report.
pub fn run(args: AccuracyArgs) -> Result<ExitCode> {
    let scenes = match &args.file {
        Some(path) => {
            let p = wearopt::problem::load(path)?;
            vec![(p.name, p.scene)]
        }
        None => SHIPPED
            .iter()
            .map(|(origin, text)| wearopt::problem::parse(text, origin).map(|p| (p.name, p.scene)))
            .collect::<Result<Vec<_>, _>>()?,
    };
    let wp = work_precision(&scenes, Options::default());
    if let Some(path) = &args.plot {
        std::fs::write(path, report::accuracy::svg(&wp))
            .with_context(|| format!("writing the plot to {}", path.display()))?;
    }
    let out = match args.format {
        Format::Text => report::accuracy::text(&wp),
        Format::Csv => report::accuracy::csv(&wp),
        Format::Json => report::accuracy::json(&wp),
        f => return Err(refuse("accuracy", f, report::accuracy::FORMATS)),
    };
    print!("{out}");
    Ok(ExitCode::SUCCESS)
}
