//! The command line: clap definitions and the wiring of problem → model → report.

mod accuracy;
mod figures;
mod fit_adhesion;
mod format;
mod materials;
mod pareto;
mod roughness;
mod sweep;
mod verbose;

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{bail, Result};
use clap::{Parser, Subcommand, ValueEnum};

use wearopt::documents::{self, Optimized};
use wearopt::model::{
    self, AsperityLaw, Attraction, Coefficients, EvaluationOptions, Model, Quadrature, Status,
};
use wearopt::report::{self, Format};

/// Adhesive wear of rough micro-contacts (MEMS gears and hinges, NEMS switches,
/// storage heads): evaluate the rough-surface adhesion model on a problem file.
#[derive(Debug, Parser)]
#[command(name = "wearopt", version, about, long_about = None)]
#[command(
    after_help = "Exit codes: 0 ok, 1 finished without a usable result, 2 bad input or usage."
)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Work–precision of the evaluator: error and time of each quadrature setting and finite-difference step rule against a high-precision reference.
    #[command(
        after_help = "Example:\n  wearopt accuracy\n  wearopt accuracy problems/micro-gear.toml --format csv --plot work-precision.svg"
    )]
    Accuracy(accuracy::AccuracyArgs),
    /// Evaluate one scene: separation, real area, contacts, pull-off, wear, sensitivities.
    #[command(
        after_help = "Example:\n  wearopt eval problems/micro-gear.toml\n  wearopt eval problems/gold-switch.toml --format json"
    )]
    Eval {
        /// The problem file (TOML).
        file: PathBuf,
        /// Output format.
        #[arg(long, value_parser = format::formats("eval", report::eval::FORMATS), default_value = "text")]
        format: Format,
        /// Write the report to this file instead of stdout ("-": stdout).
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// The paper's figures 1-4: wear volume against load (CSV, SVG), slopes, and a verdict on each claim of §4.
    #[command(
        after_help = "Files: figure1.csv … figure4.csv (theta,lambda,load,wear_volume), figure1.svg … figure4.svg, slopes.csv.\n\
Example:\n  wearopt figures\n  wearopt figures --out figs --points 101 --format json"
    )]
    Figures(figures::FiguresArgs),
    /// Fit the work of adhesion γ (and μ) to friction measurements with the JKR friction law (eq. 14), with a 95 % interval, per-point γ and bond strength.
    #[command(
        after_help = "Example:\n  wearopt fit-adhesion problems/ando-friction.csv --radius 0.3mm --materials steel,silicon\n  \
wearopt fit-adhesion data.csv --radius \"1 mm\" --fit-mu --format json"
    )]
    FitAdhesion(fit_adhesion::FitAdhesionArgs),
    /// Search the design variables of a study for the least wear under its constraints.
    #[command(
        after_help = "Example:\n  wearopt optimize problems/micro-gear-study.toml\n  \
wearopt optimize problems/switch-study.toml --format json --trace trace.csv\n  \
wearopt optimize problems/materials-study.toml   (ranks the [design] materials)\n\n\
Exit code 1 when the study is infeasible."
    )]
    Optimize {
        /// The problem file (TOML) with [design], [objective] and [[constraint]] sections.
        file: PathBuf,
        /// Output format.
        #[arg(long, value_parser = format::formats("optimize", report::optimize::FORMATS), default_value = "text")]
        format: Format,
        /// Print an iteration table per start on stderr.
        #[arg(long)]
        verbose: bool,
        /// Write the per-iteration trace (time, objective, KKT residual, violation) as CSV ("-": stdout).
        #[arg(long, value_name = "TRACE.csv")]
        trace: Option<PathBuf>,
        /// Write the report to this file instead of stdout ("-": stdout).
        #[arg(long, value_name = "FILE")]
        out: Option<PathBuf>,
    },
    /// The wear–adhesion trade-off of a study with a [pareto] section: least wear at each adhesion (ε-constraint), the Pareto front and its knee.
    #[command(after_help = "Example:\n  wearopt pareto problems/micro-gear.toml\n  \
wearopt pareto problems/micro-gear.toml --points 9 --format csv --plot front.svg\n\n\
Exit code 1 when no point meets the study's constraints; 2 when the file has no [pareto] section.")]
    Pareto(pareto::ParetoArgs),
    /// The study's scene at N designs spread over its [design] box (log-scaled like the optimiser): wear, pull-off, real area, constraints, feasibility; shardable and resumable.
    #[command(
        after_help = "Columns: index, the design variables, status, wear_rate, pull_off_force, real_area, each constrained quantity, feasible.\n\
Example:\n  wearopt sweep problems/micro-gear-study.toml --samples 4096 --plot map.svg > sweep.csv\n  \
wearopt sweep problems/micro-gear-study.toml --samples 1000000 --shard 3/16 --out part-3.csv\n  \
wearopt merge part-*.csv --samples 1000000 > sweep.csv\n\n\
Under a Slurm job array, the shard comes from SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT when --shard is absent."
    )]
    Sweep(sweep::SweepArgs),
    /// Join the shard outputs of one sweep (CSV or JSON) into the output of the unsharded run, byte for byte.
    #[command(after_help = "Example:\n  wearopt merge part-*.csv --samples 1000000 > sweep.csv")]
    Merge(sweep::MergeArgs),
    /// Roughness from a measured height map: spectral moments, the McCool σ, R and N for [roughness], a summit count, the PSD.
    #[command(
        after_help = "Example:\n  wearopt roughness problems/scans/self-affine.gsf --cutoff 100nm\n  \
wearopt roughness scan.npy --pixel-size 20nm --height-unit nm --format json --psd psd.svg\n\n\
Exit code 2 for an unreadable file or a map that cannot be analysed."
    )]
    Roughness(roughness::RoughnessArgs),
    /// The non-dimensional model at N evenly spaced separations (what the paper's figures are drawn from).
    #[command(
        after_help = "Columns: h, load, area, plastic_area, critical_interference, dload_dh, noncontact_load.\n\
Example:\n  wearopt curve --theta 10 --lambda 0.125 --from -2 --to 4 --points 61\n  \
wearopt curve --theta inf --lambda inf --from 0 --to 3 --points 4 --format json   (Greenwood-Williamson)"
    )]
    Curve {
        /// Elastic adhesion index θ > 0 ("inf": no adhesion).
        #[arg(long, allow_hyphen_values = true)]
        theta: f64,
        /// Plastic adhesion index λ > 0 ("inf": no plasticity).
        #[arg(long, allow_hyphen_values = true)]
        lambda: f64,
        /// Hardness coefficient c_h = π R^{1/2} H / (K σ^{1/2}) > 0, used only with --theta inf
        /// (θ and λ are both infinite without adhesion, so c_h cannot come from them).
        #[arg(long, default_value_t = f64::INFINITY, allow_hyphen_values = true)]
        hardness_coefficient: f64,
        /// First separation h = d/σ.
        #[arg(long, allow_hyphen_values = true)]
        from: f64,
        /// Last separation (inclusive).
        #[arg(long, allow_hyphen_values = true)]
        to: f64,
        /// Number of points, 1 to 1,000,000 (1 gives --from alone).
        #[arg(long)]
        points: usize,
        /// Output format.
        #[arg(long, value_parser = format::formats("curve", report::curve::FORMATS), default_value = "csv")]
        format: Format,
        /// The asperity law: jkr (the paper's) or dmt (attraction of asperities not in contact).
        #[arg(long, value_enum, default_value_t = CurveLaw::Jkr)]
        adhesion_model: CurveLaw,
        /// Under dmt: van_der_waals (default) or dugdale.
        #[arg(long, value_enum)]
        attraction: Option<CurveAttraction>,
        /// Under dmt, the attraction's range over σ (required): z0 = Z0/σ for
        /// van_der_waals, Δ_h = h0/σ for dugdale; > 0.
        #[arg(long, allow_hyphen_values = true)]
        attraction_range: Option<f64>,
    },
}

#[derive(Debug, Clone, Copy, ValueEnum)]
enum CurveLaw {
    Jkr,
    Dmt,
}

#[derive(Debug, Clone, Copy, ValueEnum)]
#[value(rename_all = "snake_case")]
enum CurveAttraction {
    VanDerWaals,
    Dugdale,
}

/// The asperity law of `curve`'s flags, or a usage error naming the clash.
fn curve_law(
    law: CurveLaw,
    attraction: Option<CurveAttraction>,
    range: Option<f64>,
) -> Result<AsperityLaw> {
    match law {
        CurveLaw::Jkr => {
            if attraction.is_some() || range.is_some() {
                return Err(usage(
                    "--attraction and --attraction-range apply to --adhesion-model dmt only (the default is jkr)"
                        .to_string(),
                ));
            }
            Ok(AsperityLaw::Jkr)
        }
        CurveLaw::Dmt => {
            let range = range.ok_or_else(|| {
                usage("--adhesion-model dmt needs --attraction-range D: z0 = Z0/σ for van_der_waals, h0/σ for dugdale (e.g. 0.1)".to_string())
            })?;
            if !(range > 0.0 && range.is_finite()) {
                return Err(usage(format!(
                    "--attraction-range {range}: must be finite and > 0"
                )));
            }
            Ok(AsperityLaw::Dmt(match attraction {
                None | Some(CurveAttraction::VanDerWaals) => Attraction::VanDerWaals { range },
                Some(CurveAttraction::Dugdale) => Attraction::Dugdale { range },
            }))
        }
    }
}

/// Samples of the load–separation curve drawn on the HTML pages (dense enough that the
/// stretch around the operating point stays smooth when the page shows only that).
const LOAD_CURVE_POINTS: usize = 1001;

/// An error that is the user's input, not ours: exit code 2.
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct UsageError(String);

/// Runs the parsed command line.
pub fn run(cli: Cli) -> Result<ExitCode> {
    match cli.command {
        Command::Accuracy(args) => accuracy::run(args),
        Command::Eval { file, format, out } => eval(file, format, out),
        Command::Optimize {
            file,
            format,
            verbose,
            trace,
            out,
        } => optimize(file, format, verbose, trace, out),
        Command::Figures(args) => figures::run(args),
        Command::Pareto(args) => pareto::run(args),
        Command::Sweep(args) => sweep::run(args),
        Command::Merge(args) => sweep::merge(args),
        Command::Roughness(args) => roughness::run(args),
        Command::FitAdhesion(args) => fit_adhesion::run(args),
        Command::Curve {
            theta,
            lambda,
            hardness_coefficient,
            from,
            to,
            points,
            format,
            adhesion_model,
            attraction,
            attraction_range,
        } => curve(
            curve_law(adhesion_model, attraction, attraction_range)?,
            theta,
            lambda,
            hardness_coefficient,
            from,
            to,
            points,
            format,
        ),
    }
}

fn eval(file: PathBuf, format: Format, out: Option<PathBuf>) -> Result<ExitCode> {
    let problem = wearopt::problem::load(&file)?;
    let eval = documents::eval(&problem, &file.display().to_string())?;
    let evaluation = &eval.evaluation;
    let r = eval.report(&problem);
    let text = match format {
        Format::Text => report::eval::text(&r),
        Format::Json => report::json_text(&report::eval::json_value(&r)),
        Format::Html => {
            let curve = model::load_curve(
                &problem.scene,
                evaluation,
                &EvaluationOptions::default(),
                LOAD_CURVE_POINTS,
            );
            report::eval::html(&r, &curve)
        }
        f => return Err(format::refuse("eval", f, report::eval::FORMATS)),
    };
    write_output(
        out.as_deref().unwrap_or(std::path::Path::new("-")),
        &text,
        "the report",
    )?;
    Ok(match evaluation.status {
        Status::Ok | Status::Separated => ExitCode::SUCCESS,
        Status::NotConverged | Status::OutOfRange => ExitCode::from(1),
    })
}

fn optimize(
    file: PathBuf,
    format: Format,
    verbose: bool,
    trace: Option<PathBuf>,
    out: Option<PathBuf>,
) -> Result<ExitCode> {
    let to_stdout = out.as_deref().is_none_or(|p| p.as_os_str() == "-");
    if trace.as_deref().is_some_and(|p| p.as_os_str() == "-") && format != Format::Text && to_stdout
    {
        return Err(usage(
            "--trace - would write the CSV trace to stdout, where the JSON report goes: give --trace a file name (--trace trace.csv), or use --format text".to_string(),
        ));
    }
    let problem = wearopt::problem::load(&file)?;
    let tables = verbose::Tables::default();
    let make = |start: usize| tables.observer(start);
    let optimized = documents::optimize(
        &problem,
        &file.display().to_string(),
        verbose.then_some(&make as wearopt::optimize::ObserverFactory),
    )?;
    tables.print();
    let optimum = match optimized {
        Optimized::Optimum(o) => o,
        Optimized::Ranking(ranking) => {
            return materials::write(&problem, &ranking, format, out.as_deref(), trace)
        }
    };
    if let Some(path) = trace {
        write_output(&path, &report::optimize::trace_csv(&optimum), "the trace")?;
    }
    let text = match format {
        Format::Text => report::optimize::text(&problem.name, &optimum),
        Format::Json => report::json_text(&report::optimize::json_value(&problem.name, &optimum)),
        Format::Html => {
            let curve = model::load_curve(
                &optimum.scene,
                &optimum.evaluation,
                &EvaluationOptions::default(),
                LOAD_CURVE_POINTS,
            );
            report::optimize::html(&problem.name, &optimum, &curve)
        }
        f => return Err(format::refuse("optimize", f, report::optimize::FORMATS)),
    };
    write_output(
        out.as_deref().unwrap_or(std::path::Path::new("-")),
        &text,
        "the report",
    )?;
    Ok(match optimum.status {
        wearopt::optimize::OptimizationStatus::Infeasible => ExitCode::from(1),
        _ => ExitCode::SUCCESS,
    })
}

/// Writes `text` to `path`, or to stdout when the path is "-".
pub(crate) fn write_output(path: &std::path::Path, text: &str, what: &str) -> Result<()> {
    if path.as_os_str() == "-" {
        print!("{text}");
        Ok(())
    } else {
        std::fs::write(path, text)
            .map_err(|e| anyhow::anyhow!("writing {what} to {}: {e}", path.display()))
    }
}

fn usage(msg: String) -> anyhow::Error {
    UsageError(msg).into()
}

#[allow(clippy::too_many_arguments)]
fn curve(
    law: AsperityLaw,
    theta: f64,
    lambda: f64,
    c_h: f64,
    from: f64,
    to: f64,
    points: usize,
    format: Format,
) -> Result<ExitCode> {
    if theta.is_nan() || theta <= 0.0 {
        return Err(usage(format!(
            "--theta {theta}: must be > 0 (or inf for no adhesion)"
        )));
    }
    if lambda.is_nan() || lambda <= 0.0 {
        return Err(usage(format!(
            "--lambda {lambda}: must be > 0 (or inf for no plasticity)"
        )));
    }
    if c_h.is_nan() || c_h <= 0.0 {
        return Err(usage(format!(
            "--hardness-coefficient {c_h}: must be > 0 (or inf for no plasticity)"
        )));
    }
    if !from.is_finite() || !to.is_finite() {
        return Err(usage(format!(
            "--from {from} --to {to}: separations must be finite"
        )));
    }
    if from > to {
        return Err(usage(format!(
            "--from {from} is above --to {to}: give an increasing range"
        )));
    }
    if !(1..=1_000_000).contains(&points) {
        return Err(usage(format!("--points {points}: must lie in 1..=1000000")));
    }
    if points > 1 && from == to {
        return Err(usage(format!(
            "--from and --to are both {from}: with --points {points} the range must not be empty"
        )));
    }
    let coefficients = if theta.is_infinite() {
        Coefficients::new(0.0, c_h)
    } else if lambda.is_infinite() {
        Coefficients::from_indices_or_limits(theta, lambda, c_h)
    } else {
        Coefficients::from_indices(theta, lambda)
    };
    if coefficients.c_a.is_nan() || coefficients.c_h.is_nan() {
        bail!("coefficients are undefined for θ = {theta}, λ = {lambda}");
    }
    let m = Model::with_law(coefficients, law, Quadrature::default());
    let dc = m.critical_interference();
    let rows: Vec<report::curve::CurveRow> = (0..points)
        .map(|i| {
            let h = if points == 1 {
                from
            } else {
                from + (to - from) * (i as f64) / ((points - 1) as f64)
            };
            let at = m.at(h);
            report::curve::CurveRow {
                h,
                load: at.load().value(),
                area: at.area().value(),
                plastic_area: at.plastic_area().value(),
                critical_interference: dc,
                dload_dh: at.dload_dh().value(),
                noncontact_load: at.noncontact_load().value(),
            }
        })
        .collect();
    let out = match format {
        Format::Csv => report::curve::csv(&rows),
        Format::Json => report::curve::json(&rows),
        f => return Err(format::refuse("curve", f, report::curve::FORMATS)),
    };
    print!("{out}");
    Ok(ExitCode::SUCCESS)
}

/// The exit code for an error: 2 for bad input and usage, 1 otherwise.
pub fn exit_code(err: &anyhow::Error) -> u8 {
    if err
        .downcast_ref::<wearopt::problem::ProblemError>()
        .is_some()
        || err.downcast_ref::<UsageError>().is_some()
        || err
            .downcast_ref::<wearopt::calibrate::CalibrationError>()
            .is_some()
        || err
            .downcast_ref::<wearopt::documents::DocumentError>()
            .is_some()
    {
        2
    } else {
        1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn cli_definition_is_consistent() {
        Cli::command().debug_assert();
    }
}
