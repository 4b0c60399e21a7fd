//! `wearopt figures`: the paper's figures 1–4 as CSV and SVG, the least-squares
//! slope of each curve, and a verdict on each claim of the paper's §4.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::ValueEnum;
use serde_json::json;

use wearopt::figures::{
    assess_claims, compute_figures, paper_figures, Claim, Figure, FigureError, FigureSettings,
    Varied, EQUAL_SLOPE_RATIO, LINEAR_R_SQUARED, MAX_POINTS,
};
use wearopt::report::number;
use wearopt::report::svg::{Axis, LinePlot, Series};

use super::usage;

/// The report's format on stdout (the files are always CSV and SVG).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FiguresFormat {
    /// Human-readable summary.
    Text,
    /// One JSON object: settings, files, slopes, claims.
    Json,
}

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
    /// Format of the report on stdout.
    #[arg(long, value_enum, default_value_t = FiguresFormat::Text)]
    pub format: FiguresFormat,
}

/// The CSV header of each figure's points.
pub const FIGURE_COLUMNS: &str = "theta,lambda,load,wear_volume";
/// The CSV header of slopes.csv.
pub const SLOPE_COLUMNS: &str = "figure,theta,lambda,slope,r_squared";

const LOAD_LABEL: &str = "non-dimensional load P̄";
const WEAR_LABEL: &str = "non-dimensional wear volume V̄";

/// Every point of a figure's curves, one row each.
fn figure_csv(fig: &Figure) -> String {
    let mut out = format!("{FIGURE_COLUMNS}\n");
    for c in &fig.curves {
        for p in &c.points {
            let _ = writeln!(
                out,
                "{},{},{},{}",
                number(c.theta),
                number(c.lambda),
                number(p.load),
                number(p.wear_volume)
            );
        }
    }
    out
}

/// The least-squares slope and r² of every curve.
fn slopes_csv(figures: &[Figure]) -> String {
    let mut out = format!("{SLOPE_COLUMNS}\n");
    for f in figures {
        for c in &f.curves {
            let (slope, r2) = c
                .fit
                .map_or((f64::NAN, f64::NAN), |x| (x.slope, x.r_squared));
            let _ = writeln!(
                out,
                "{},{},{},{},{}",
                f.spec.number,
                number(c.theta),
                number(c.lambda),
                number(slope),
                number(r2)
            );
        }
    }
    out
}

fn series_name(fig: &Figure, theta: f64, lambda: f64) -> String {
    match fig.spec.varied {
        Varied::Theta => format!("θ = {theta}"),
        Varied::Lambda => format!("λ = {lambda}"),
    }
}

fn figure_svg(fig: &Figure) -> String {
    let mut plot = LinePlot::new(
        fig.spec.caption(),
        Axis::linear(LOAD_LABEL),
        Axis::linear(WEAR_LABEL),
    );
    for c in &fig.curves {
        let pts = c.points.iter().map(|p| (p.load, p.wear_volume)).collect();
        let every = (c.points.len() / 10).max(1);
        plot = plot.with_series(
            Series::new(series_name(fig, c.theta, c.lambda), pts).with_marker_every(every),
        );
    }
    plot.to_svg()
}

fn write(path: &Path, contents: &str) -> Result<()> {
    fs::write(path, contents).with_context(|| format!("cannot write {}", path.display()))
}

fn verdict(holds: Option<bool>) -> &'static str {
    match holds {
        Some(true) => "holds",
        Some(false) => "does not hold",
        None => "undecided",
    }
}

fn text_report(
    settings: &FigureSettings,
    files: &[PathBuf],
    figures: &[Figure],
    claims: &[Claim],
) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "Figures 1-4 (paper §4): wear volume V̄ = Ā against load P̄ for P̄ = {} to {} \
({} evenly spaced loads per curve; each solved for h on the loading branch, docs/model.md §4).",
        settings.load_min, settings.load_max, settings.points
    );
    let _ = writeln!(o, "\nFiles written:");
    for f in files {
        let _ = writeln!(o, "  {}", f.display());
    }
    let _ = writeln!(o, "\nLeast-squares lines V̄ ≈ slope·P̄ + intercept:");
    let _ = writeln!(
        o,
        "  {:>3} {:>6} {:>7} {:>8} {:>9} {:>9} {:>11} {:>11}",
        "fig", "θ", "λ", "slope", "intercept", "r²", "V̄(P̄ min)", "V̄(P̄ max)"
    );
    let mut failed = 0;
    for f in figures {
        for c in &f.curves {
            failed += c.failed;
            let (slope, icpt, r2) = c.fit.map_or((f64::NAN, f64::NAN, f64::NAN), |x| {
                (x.slope, x.intercept, x.r_squared)
            });
            let first = c.points.first().map_or(f64::NAN, |p| p.wear_volume);
            let last = c.points.last().map_or(f64::NAN, |p| p.wear_volume);
            let _ = writeln!(
                o,
                "  {:>3} {:>6} {:>7} {:>8.4} {:>9.4} {:>9.5} {:>11.4} {:>11.4}",
                f.spec.number, c.theta, c.lambda, slope, icpt, r2, first, last
            );
        }
    }
    if failed > 0 {
        let _ = writeln!(
            o,
            "  {failed} load(s) had no converged separation and are left out"
        );
    }
    let _ = writeln!(
        o,
        "\nClaims of §4 under the exact model (thresholds: r² ≥ {LINEAR_R_SQUARED}, max/min slope ≤ {EQUAL_SLOPE_RATIO}):"
    );
    for (i, c) in claims.iter().enumerate() {
        let _ = writeln!(
            o,
            "  ({}) {}: {}. Test: {}. {}.",
            i + 1,
            verdict(c.holds).to_uppercase(),
            c.statement,
            c.criterion,
            c.evidence
        );
    }
    o
}

fn json_report(
    settings: &FigureSettings,
    files: &[PathBuf],
    figures: &[Figure],
    claims: &[Claim],
) -> String {
    let curves: Vec<_> = figures
        .iter()
        .flat_map(|f| {
            f.curves.iter().map(move |c| {
                json!({
                    "figure": f.spec.number,
                    "theta": c.theta,
                    "lambda": c.lambda,
                    "slope": c.fit.map(|x| x.slope),
                    "intercept": c.fit.map(|x| x.intercept),
                    "r_squared": c.fit.map(|x| x.r_squared),
                    "points": c.points.len(),
                    "failed": c.failed,
                    "pull_off_load": c.pull_off_load,
                    "plastic_jump": c.plastic_jump,
                })
            })
        })
        .collect();
    let claims: Vec<_> = claims
        .iter()
        .map(|c| {
            json!({
                "id": c.id,
                "statement": c.statement,
                "criterion": c.criterion,
                "holds": c.holds,
                "evidence": c.evidence,
            })
        })
        .collect();
    let v = json!({
        "settings": settings,
        "thresholds": {
            "linear_r_squared": LINEAR_R_SQUARED,
            "equal_slope_ratio": EQUAL_SLOPE_RATIO,
        },
        "files": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        "curves": curves,
        "claims": claims,
    });
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_else(|_| "{}".to_string());
    s.push('\n');
    s
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
        write(&csv, &figure_csv(f))?;
        files.push(csv);
        let svg = args.out.join(format!("figure{n}.svg"));
        write(&svg, &figure_svg(f))?;
        files.push(svg);
    }
    let slopes = args.out.join("slopes.csv");
    write(&slopes, &slopes_csv(&figures))?;
    files.push(slopes);

    let out = match args.format {
        FiguresFormat::Text => text_report(&settings, &files, &figures, &claims),
        FiguresFormat::Json => json_report(&settings, &files, &figures, &claims),
    };
    print!("{out}");
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
