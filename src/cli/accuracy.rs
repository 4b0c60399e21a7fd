//! `wearopt accuracy`: the work–precision report of the evaluator.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::Args;

use wearopt::report::{self, Format};

use super::format::formats;

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

/// Runs the report.
pub fn run(args: AccuracyArgs) -> Result<ExitCode> {
    let problem = args.file.as_deref().map(wearopt::app::load).transpose()?;
    let wp = wearopt::app::accuracy::accuracy(problem.as_ref())?;
    if let Some(path) = &args.plot {
        super::write_output(path, &report::accuracy::svg(&wp), "the plot")?;
    }
    super::print_out(&report::accuracy::render(&wp, args.format)?)?;
    Ok(ExitCode::SUCCESS)
}
