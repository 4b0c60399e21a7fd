//! `wearopt roughness`: a height map in, σ, R and N out.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::{Args, ValueEnum};

use wearopt::app::roughness::{self as rough, Levelling, RoughnessOptions};
use wearopt::app::OptionName;
use wearopt::report::{self, Format};

use super::format::formats;
use super::write_output;

#[derive(Debug, Clone, Copy, ValueEnum)]
pub(crate) enum LevelArg {
    None,
    Plane,
    Quadratic,
}

#[derive(Debug, Args)]
pub(crate) struct RoughnessArgs {
    /// The height map: .gsf (Gwyddion), .x3p (ISO 25178-72), .npy (NumPy, shape (ny, nx)),
    /// or an ASCII matrix (.txt, .asc, .dat, .csv; rows along y).
    file: PathBuf,
    /// Short-wavelength cut-off λs (ISO 16610-61 Gaussian), e.g. "100 nm"; default none.
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    cutoff: Option<String>,
    /// Form removal before the analysis.
    #[arg(long, value_enum, default_value_t = LevelArg::Plane)]
    level: LevelArg,
    /// Pixel size (both directions), e.g. "20 nm"; required for .npy and a bare ASCII
    /// matrix, overrides the file's otherwise.
    #[arg(long, value_name = "LENGTH", allow_hyphen_values = true)]
    pixel_size: Option<String>,
    /// The unit of the stored heights, e.g. "nm" or "1e-9"; required for .npy and a bare
    /// ASCII matrix, overrides the file's otherwise.
    #[arg(long, value_name = "UNIT")]
    height_unit: Option<String>,
    /// The ASCII matrix writes its decimals with commas ("1,25"; columns then separated by
    /// whitespace or semicolons). Such a file is refused without it.
    #[arg(long)]
    decimal_comma: bool,
    /// Output format.
    #[arg(long, value_parser = formats("roughness", report::roughness::FORMATS), default_value = "text")]
    format: Format,
    /// Write the power spectral density as a log–log SVG plot ("-": stdout).
    #[arg(long, value_name = "PSD.svg")]
    psd: Option<PathBuf>,
}

impl From<LevelArg> for Levelling {
    fn from(level: LevelArg) -> Self {
        match level {
            LevelArg::None => Levelling::None,
            LevelArg::Plane => Levelling::Plane,
            LevelArg::Quadratic => Levelling::Quadratic,
        }
    }
}

pub(crate) fn run(args: RoughnessArgs) -> Result<ExitCode> {
    let level = args.level.into();
    // As the command line always checked them: pixel size, height unit, cut-off.
    let pixel_size = args
        .pixel_size
        .as_deref()
        .map(|t| rough::length(OptionName("pixel_size"), t))
        .transpose()?;
    let height_unit = args
        .height_unit
        .as_deref()
        .map(|t| rough::height_unit(OptionName("height_unit"), t))
        .transpose()?;
    let cutoff = args
        .cutoff
        .as_deref()
        .map(|t| rough::length(OptionName("cutoff"), t))
        .transpose()?;
    let options = RoughnessOptions {
        cutoff,
        level,
        pixel_size,
        height_unit,
        decimal_comma: args.decimal_comma,
    };
    let doc = rough::roughness(&args.file, &options)?;
    if let Some(path) = &args.psd {
        write_output(path, &report::roughness::psd_plot(&doc), "the PSD plot")?;
    }
    super::print_out(&report::roughness::render(&doc, args.format)?)?;
    Ok(ExitCode::SUCCESS)
}
