//! `wearopt roughness`: a height map in, σ, R and N out.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;
use clap::{Args, ValueEnum};

use wearopt::problem::units::{parse_quantity, Dimension};
use wearopt::report;
use wearopt::surface::psd::Psd;
use wearopt::surface::read::{self, parse_height_unit, Format, Overrides};
use wearopt::surface::{analyse, level, Levelling, Settings};

use super::{usage, write_output};

#[derive(Debug, Clone, Copy, ValueEnum)]
pub(crate) enum LevelArg {
    None,
    Plane,
    Quadratic,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
pub(crate) enum RoughnessFormat {
    Text,
    Json,
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
    /// Output format.
    #[arg(long, value_enum, default_value_t = RoughnessFormat::Text)]
    format: RoughnessFormat,
    /// Write the power spectral density as a log–log SVG plot ("-": stdout).
    #[arg(long, value_name = "PSD.svg")]
    psd: Option<PathBuf>,
}

fn length(flag: &str, text: &str) -> Result<f64> {
    let x = parse_quantity(text, Dimension::Length)
        .map_err(|e| usage(format!("{flag} {text:?}: {e}")))?;
    if !(x.is_finite() && x > 0.0) {
        return Err(usage(format!(
            "{flag} {text:?}: must be a positive finite length"
        )));
    }
    Ok(x)
}

pub(crate) fn run(args: RoughnessArgs) -> Result<ExitCode> {
    let origin = args.file.display().to_string();
    let overrides = Overrides {
        pixel_size: args
            .pixel_size
            .as_deref()
            .map(|t| length("--pixel-size", t))
            .transpose()?,
        height_unit: args
            .height_unit
            .as_deref()
            .map(|t| {
                parse_height_unit(t).ok_or_else(|| {
                    usage(format!(
                        "--height-unit {t:?}: not a length unit; expected e.g. \"nm\", \"um\", \"m\" or \"1e-9\""
                    ))
                })
            })
            .transpose()?,
    };
    let cutoff = args
        .cutoff
        .as_deref()
        .map(|t| length("--cutoff", t))
        .transpose()?;
    let level_kind = match args.level {
        LevelArg::None => Levelling::None,
        LevelArg::Plane => Levelling::Plane,
        LevelArg::Quadratic => Levelling::Quadratic,
    };
    let format = Format::from_path(Path::new(&args.file)).unwrap_or(Format::Ascii);
    let map = read::load(&args.file, &overrides).map_err(|e| usage(e.to_string()))?;
    let settings = Settings {
        level: level_kind,
        cutoff,
    };
    let roughness = analyse(&map, &settings).map_err(|e| usage(format!("{origin}: {e}")))?;
    let levelled = level(&map, level_kind).map_err(|e| usage(format!("{origin}: {e}")))?;
    let psd = Psd::of(&levelled);
    let r = report::roughness::RoughnessReport {
        file: &origin,
        format,
        roughness: &roughness,
        psd: Some(&psd),
    };
    if let Some(path) = &args.psd {
        write_output(path, &report::roughness::psd_svg(&r, &psd), "the PSD plot")?;
    }
    let out = match args.format {
        RoughnessFormat::Text => report::roughness::text(&r),
        RoughnessFormat::Json => report::roughness::json(&r),
    };
    print!("{out}");
    Ok(ExitCode::SUCCESS)
}
