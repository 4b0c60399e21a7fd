//! `wearopt figures`: the paper's figures 1–4 as CSV and SVG, the least-squares
//! slope of each curve, and a verdict on each claim of the paper's §4.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;

use wearopt::app::figures::{self as fig, FigureSettings};
use wearopt::app::{AppError, OptionName};
use wearopt::report::figures as out;
use wearopt::report::Format;

use super::format::formats;

/// Arguments of `wearopt figures`.
#[derive(Debug, clap::Args)]
pub struct FiguresArgs {
    /// Directory for figure1.csv … figure4.csv, figure1.svg … figure4.svg and slopes.csv (created if missing).
    #[arg(long, default_value = "figures")]
    pub out: PathBuf,
    /// Points per curve: evenly spaced loads from --load-min to --load-max (3 to 10000).
    #[arg(long, default_value_t = FigureSettings::default().points)]
    pub points: usize,
    /// Smallest non-dimensional load P̄ drawn (> 0, compressive).
    #[arg(long, default_value_t = FigureSettings::default().load_min, allow_hyphen_values = true)]
    pub load_min: f64,
    /// Largest non-dimensional load P̄ drawn (> --load-min).
    #[arg(long, default_value_t = FigureSettings::default().load_max, allow_hyphen_values = true)]
    pub load_max: f64,
    /// Format of the report on stdout (the files are always CSV and SVG): a summary for
    /// people, or one JSON object (settings, files, slopes, claims).
    #[arg(long, value_parser = formats("figures", out::FORMATS), default_value = "text")]
    pub format: Format,
}

fn write(path: &Path, contents: &str) -> Result<()> {
    super::write_output(path, contents, "the figure")
}

/// Runs `wearopt figures`: computes, writes the files, prints the report.
/// Exit code 0, or 1 when some load had no converged separation.
pub fn run(args: FiguresArgs) -> Result<ExitCode> {
    let settings = FigureSettings {
        points: args.points,
        load_min: args.load_min,
        load_max: args.load_max,
    };
    settings.validate().map_err(AppError::Figures)?;
    fs::create_dir_all(&args.out).map_err(|e| AppError::Output {
        option: OptionName("out"),
        path: args.out.display().to_string(),
        reason: e.to_string(),
    })?;
    let doc = fig::figures(&settings, &args.out)?;
    for (path, which) in &doc.files {
        write(path, &out::file(&doc, *which))?;
    }
    super::print_out(&out::render(&doc, args.format)?)?;
    Ok(if doc.incomplete() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
