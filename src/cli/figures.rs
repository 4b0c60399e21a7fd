//! `wearopt figures`: the paper's figures 1–4 as CSV and SVG, the least-squares
//! slope of each curve, and a verdict on each claim of the paper's §4.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};

use wearopt::figures::{
    assess_claims, compute_figures, paper_figures, FigureError, FigureSettings, MAX_POINTS,
};
use wearopt::report::figures as out;
use wearopt::report::Format;

use super::format::{formats, refuse};

use super::usage;

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
    fs::write(path, contents).with_context(|| format!("cannot write {}", path.display()))
}

/// Runs `wearopt figures`: computes, writes the files, prints the report.
/// Exit code 0, or 1 when some load had no converged separation.
pub fn run(args: FiguresArgs) -> Result<ExitCode> {
    let settings = FigureSettings {
        points: args.points,
        load_min: args.load_min,
        load_max: args.load_max,
    };
    settings.validate().map_err(|e| {
        usage(match e {
            FigureError::Points(n) => {
                format!("--points {n}: must lie in 3..={MAX_POINTS} (a least-squares line needs 3 points)")
            }
            FigureError::LoadRange { min, max } => format!(
                "--load-min {min} --load-max {max}: need 0 < load-min < load-max < inf (compressive loads, e.g. 0.05 and 5)"
            ),
        })
    })?;
    fs::create_dir_all(&args.out).map_err(|e| {
        usage(format!(
            "--out {}: cannot create the directory: {e}",
            args.out.display()
        ))
    })?;

    let figures = compute_figures(&paper_figures(), &settings);
    let claims = assess_claims(&figures);

    let mut files = Vec::new();
    for f in &figures {
        let n = f.spec.number;
        let csv = args.out.join(format!("figure{n}.csv"));
        write(&csv, &out::figure_csv(f))?;
        files.push(csv);
        let svg = args.out.join(format!("figure{n}.svg"));
        write(&svg, &out::svg(f))?;
        files.push(svg);
    }
    let slopes = args.out.join("slopes.csv");
    write(&slopes, &out::slopes_csv(&figures))?;
    files.push(slopes);

    let report = match args.format {
        Format::Text => out::text(&settings, &files, &figures, &claims),
        Format::Json => out::json(&settings, &files, &figures, &claims),
        f => return Err(refuse("figures", f, out::FORMATS)),
    };
    print!("{report}");
    let incomplete = figures
        .iter()
        .flat_map(|f| &f.curves)
        .any(|c| c.failed > 0 || c.fit.is_none());
    Ok(if incomplete {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
