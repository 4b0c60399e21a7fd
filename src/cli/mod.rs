//! The command line: clap definitions, and an adapter of the application layer
//! (`wearopt::app`): flags in, one app function called, the report stage's
//! rendering written out, errors worded as flags.

mod accuracy;
mod contact;
mod figures;
mod fit_adhesion;
mod fit_wear;
mod format;
mod pareto;
mod progress;
mod roughness;
mod shard;
mod sweep;
mod uncertainty;
mod verbose;

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Parser, Subcommand};

use wearopt::app::curve::{AdhesionModel, AttractionKind, CurveOptions, LawOptions};
use wearopt::app::optimize::OptimizeOptions;
use wearopt::app::{self, OptionName};
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
    /// Fit the activation energy ΔU and volume ΔV of stress-assisted wear to measured wear rates (ln rate = ln A + σΔV/k_BT − ΔU/k_BT), with standard errors and 95 % intervals; says when ΔU cannot be identified (one temperature) and when the points look saturated.
    #[command(
        after_help = "Header: stress_Pa, then rate_atoms_per_s | rate_m3_per_s | rate_m3_per_m, then optionally temperature_K.\n\
Example:\n  wearopt fit-wear problems/wear-rates.csv\n  \
wearopt fit-wear rates.csv --temperature \"350 K\" --speed \"1 mm/s\" --format json"
    )]
    FitWear(fit_wear::FitWearArgs),
    /// The scene across relative humidity (capillary adhesion): separation, capillary load, pull-off force, apparent work of adhesion Γ, wet fraction and wear rate, and the threshold humidity where Γ reaches ten times its dry value.
    #[command(
        after_help = "Columns: relative_humidity, separation, capillary_load, pull_off_force, apparent_work_of_adhesion, wetted_fraction, wear_rate, status.\n\
The air is the file's [environment] (its relative_humidity is replaced), or water at 25 °C wetting both bodies when it has none.\n\
Example:\n  wearopt humidity problems/micro-gear-humid.toml --from 0 --to 0.95 --points 20\n  \
wearopt humidity problems/micro-gear-humid.toml --from 0 --to 0.95 --points 20 --format csv --plot humidity.svg"
    )]
    Humidity(HumidityArgs),
    /// One asperity's load against its interference in Maugis units (the Lennard-Jones sphere, JKR or DMT): branches, jumps into and out of contact, pull-off.
    #[command(
        after_help = "Columns: interference, load, contact_radius, branch (approach, unstable or contact; an S-shaped curve has several rows at one interference); with a sphere in SI also load_n, interference_m, contact_radius_m.\n\
Units: every format (text, CSV, JSON, HTML) is in Maugis units: load P/(πγR), interference δ (K²/(π²γ²R))^(1/3), contact radius a (K/(πγR²))^(1/3), K = 4E*/3; μ = (Rγ²/(E*²Z0³))^(1/3). --from and --to are Maugis interferences in every case; a sphere given in SI (--radius, --work-of-adhesion, --modulus, --interatomic-distance) sets μ and adds newtons and metres beside them.\n\
Accuracy: the Lennard-Jones rows are converged (three nested meshes, extrapolated) up to μ = 5 unless --fast, and on the trace's mesh above unless --converged.\n\
Example:\n  wearopt asperity --tabor 1 --from -1.5 --to 1 --points 11\n  \
wearopt asperity --tabor 3 --from -1.2 --to 1 --points 45 --format csv --plot asperity.svg\n  \
wearopt asperity --radius 1um --work-of-adhesion 0.5J/m^2 --modulus 100GPa --interatomic-distance 0.3nm --from -2 --to 1 --points 31"
    )]
    Asperity(AsperityArgs),
    /// The scene under the scatter of its [uncertainty] inputs: Sobol′ indices, Morris screening, percentiles and life, or the probability of each event (stiction, wear-out, a threshold) by FORM, SORM and importance sampling.
    #[command(
        after_help = "Every index, percentile and probability comes with its 95 % interval or its status.\n\
Example:\n  wearopt uncertainty problems/micro-gear-scatter.toml\n  \
wearopt uncertainty problems/micro-gear-scatter.toml --method reliability --format json\n  \
wearopt uncertainty problems/micro-gear-scatter.toml --method sampling --samples 8192 --format html --out scatter.html\n  \
wearopt uncertainty problems/micro-gear-scatter.toml --shard 2/8 --out part-2.json   (then: wearopt merge part-*.json)\n\n\
Under a Slurm job array, the shard comes from SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT when --shard is absent."
    )]
    Uncertainty(uncertainty::UncertaintyArgs),
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
    /// Join the shard outputs of one sweep (CSV or JSON), or the parts of one uncertainty study, into the output of the unsharded run, byte for byte.
    #[command(
        after_help = "Example:\n  wearopt merge part-*.csv --samples 1000000 > sweep.csv\n  \
wearopt merge uq-part-*.json --format html --out scatter.html   (the parts of wearopt uncertainty --shard I/N)"
    )]
    Merge(sweep::MergeArgs),
    /// Roughness from a measured height map: spectral moments, the McCool σ, R and N for [roughness], a summit count, the PSD.
    #[command(
        after_help = "Example:\n  wearopt roughness problems/scans/self-affine.gsf --cutoff 100nm\n  \
wearopt roughness scan.npy --pixel-size 20nm --height-unit nm --format json --psd psd.svg\n\n\
Exit code 2 for an unreadable file or a map that cannot be analysed."
    )]
    Roughness(roughness::RoughnessArgs),
    /// Exact contact of a measured height map (FFT boundary elements) at given mean pressures, beside the statistical model's real area on the same map.
    #[command(
        after_help = "Example:\n  wearopt contact problems/scans/self-affine.gsf --modulus 150GPa --pressure 50MPa,100MPa,200MPa\n  \
wearopt contact scan.npy --pixel-size 20nm --height-unit nm --modulus 100GPa --pressure 1GPa --hardness 10GPa --format html > contact.html\n\n\
JSON: pixels, pixel_size, modulus and points (pressure, real_area_fraction, contact_patches, mean_gap, max_pressure, residual, iterations, \
gw_real_area_fraction, gw_contact_count, area_ratio). Exit code 2 for an unreadable file, missing points, a map under 8 × 8 \
or a pressure, modulus or hardness out of range."
    )]
    Contact(contact::ContactArgs),
    /// The non-dimensional model at N evenly spaced separations (what the paper's figures are drawn from).
    #[command(
        after_help = "Columns: h, load, area, plastic_area, critical_interference, dload_dh, noncontact_load.\n\
Example:\n  wearopt curve --theta 10 --lambda 0.125 --from -2 --to 4 --points 61\n  \
wearopt curve --theta inf --lambda inf --from 0 --to 3 --points 4 --format json   (Greenwood-Williamson)"
    )]
    Curve(CurveArgs),
}

/// Arguments of `wearopt asperity`.
#[derive(Debug, clap::Args)]
pub struct AsperityArgs {
    /// The Tabor parameter μ = (Rγ²/(E*²Z0³))^(1/3), > 0 (or give the sphere in SI below).
    #[arg(long, allow_hyphen_values = true)]
    pub tabor: Option<f64>,
    /// The sphere's radius R, e.g. "1 µm" (with the three below, instead of --tabor).
    #[arg(long, allow_hyphen_values = true)]
    pub radius: Option<String>,
    /// The work of adhesion γ of the pair, e.g. "0.5 J/m^2".
    #[arg(long, allow_hyphen_values = true)]
    pub work_of_adhesion: Option<String>,
    /// The composite modulus E* of the pair, 1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2, e.g. "100 GPa".
    #[arg(long, allow_hyphen_values = true)]
    pub modulus: Option<String>,
    /// The interatomic distance Z0 of the Lennard-Jones law (its equilibrium spacing), e.g. "0.3 nm".
    #[arg(long, allow_hyphen_values = true)]
    pub interatomic_distance: Option<String>,
    /// The first interference δ̂ (Maugis units; negative: apart).
    #[arg(long, allow_hyphen_values = true)]
    pub from: f64,
    /// The last interference (inclusive), above --from.
    #[arg(long, allow_hyphen_values = true)]
    pub to: f64,
    /// Number of evenly spaced interferences, 2 or more.
    #[arg(long)]
    pub points: usize,
    /// The asperity law.
    #[arg(long, value_parser = asperity_law_parser(), default_value = "lennard_jones")]
    pub adhesion_model: app::asperity::CurveLaw,
    /// Output format.
    #[arg(long, value_parser = format::formats("asperity", report::asperity::FORMATS), default_value = "text")]
    pub format: Format,
    /// Also write the plot of load against interference (SVG).
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
    /// The Lennard-Jones rows on the trace's mesh (within 1e-3 out of contact, 5e-2 in it) instead of converged: several times faster; the marks stay converged. The default above μ = 5.
    #[arg(long, conflicts_with = "converged")]
    pub fast: bool,
    /// Converge the Lennard-Jones rows also above μ = 5, where it takes minutes (the default up to μ = 5).
    #[arg(long)]
    pub converged: bool,
}

fn asperity_law_parser() -> impl TypedValueParser<Value = app::asperity::CurveLaw> {
    PossibleValuesParser::new(app::asperity::CurveLaw::ALL.map(|l| l.as_str()))
        .try_map(|name| app::asperity::law(&name))
}

/// Arguments of `wearopt humidity`.
#[derive(Debug, clap::Args)]
pub struct HumidityArgs {
    /// The problem file (TOML).
    pub file: PathBuf,
    /// The first relative humidity: a fraction in [0, 1) or a percentage ("0.5" or "50%").
    #[arg(long, value_name = "RH", allow_hyphen_values = true)]
    pub from: String,
    /// The last relative humidity (inclusive), in [--from, 1): a fraction or a percentage.
    #[arg(long, value_name = "RH", allow_hyphen_values = true)]
    pub to: String,
    /// Number of evenly spaced humidities, 2 or more.
    #[arg(long)]
    pub points: usize,
    /// Output format.
    #[arg(long, value_parser = format::formats("humidity", report::humidity::FORMATS), default_value = "text")]
    pub format: Format,
    /// Also write the plot of Γ and the pull-off force against RH (SVG).
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// Arguments of `wearopt curve`.
#[derive(Debug, clap::Args)]
pub struct CurveArgs {
    /// Elastic adhesion index θ > 0 ("inf": no adhesion).
    #[arg(long, allow_hyphen_values = true)]
    pub theta: f64,
    /// Plastic adhesion index λ > 0 ("inf": no plasticity).
    #[arg(long, allow_hyphen_values = true)]
    pub lambda: f64,
    /// Hardness coefficient c_h = π R^{1/2} H / (K σ^{1/2}) > 0, used only with --theta inf
    /// (θ and λ are both infinite without adhesion, so c_h cannot come from them).
    #[arg(long, default_value_t = f64::INFINITY, allow_hyphen_values = true)]
    pub hardness_coefficient: f64,
    /// First separation h = d/σ.
    #[arg(long, allow_hyphen_values = true)]
    pub from: f64,
    /// Last separation (inclusive).
    #[arg(long, allow_hyphen_values = true)]
    pub to: f64,
    /// Number of points, 1 to 1,000,000 (1 gives --from alone).
    #[arg(long)]
    pub points: usize,
    /// Output format.
    #[arg(long, value_parser = format::formats("curve", report::curve::FORMATS), default_value = "csv")]
    pub format: Format,
    /// The asperity law: jkr (the paper's), dmt (attraction of asperities not in
    /// contact) or lennard_jones (the self-consistent sphere, for every Tabor parameter).
    #[arg(long, value_parser = law_parser(), default_value = "jkr")]
    pub adhesion_model: AdhesionModel,
    /// Under dmt: van_der_waals (default) or dugdale.
    #[arg(long, value_parser = attraction_parser())]
    pub attraction: Option<AttractionKind>,
    /// Under dmt and lennard_jones, the attraction's range over σ (required):
    /// z0 = Z0/σ for van_der_waals and lennard_jones, Δ_h = h0/σ for dugdale; > 0.
    #[arg(long, allow_hyphen_values = true)]
    pub attraction_range: Option<f64>,
}

/// `--adhesion-model`: the names of the registry of asperity laws.
fn law_parser() -> impl TypedValueParser<Value = AdhesionModel> {
    PossibleValuesParser::new(AdhesionModel::names())
        .try_map(|name| app::curve::adhesion_model(OptionName("adhesion_model"), &name))
}

/// `--attraction`: the names of the attractions.
fn attraction_parser() -> impl TypedValueParser<Value = AttractionKind> {
    PossibleValuesParser::new(AttractionKind::names())
        .try_map(|name| app::curve::attraction(OptionName("attraction"), &name))
}

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
        Command::Contact(args) => contact::run(args),
        Command::FitAdhesion(args) => fit_adhesion::run(args),
        Command::FitWear(args) => fit_wear::run(args),
        Command::Curve(args) => curve(args),
        Command::Humidity(args) => humidity(args),
        Command::Asperity(args) => asperity(args),
        Command::Uncertainty(args) => uncertainty::run(args),
    }
}

fn eval(file: PathBuf, format: Format, out: Option<PathBuf>) -> Result<ExitCode> {
    if let Some(path) = &out {
        check_output(path, "the report", &[&file])?;
    }
    let problem = app::load(&file)?;
    let origin = file.display().to_string();
    let doc = app::eval::eval(&problem, &origin, &report::eval::options(format))?;
    let text = report::eval::render(&doc, format)?;
    write_output(
        out.as_deref().unwrap_or(std::path::Path::new("-")),
        &text,
        "the report",
    )?;
    Ok(if doc.failed() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
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
    let problem = app::load(&file)?;
    let tables = verbose::Tables::default();
    // A counter of the optimiser's solves (starts, vertex searches, materials):
    // their number is known only as they come.
    let bar = progress::bar(None, "solves");
    let make = |start: usize| -> app::optimize::StartObserver {
        Box::new(progress::Ticking {
            inner: verbose.then(|| tables.observer(start)),
            bar: bar.clone(),
        })
    };
    let doc = app::optimize::optimize(
        &problem,
        &file.display().to_string(),
        OptimizeOptions {
            observers: (verbose || bar.is_some())
                .then_some(&make as app::optimize::ObserverFactory),
            ..report::optimize::options(format)
        },
    )?;
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    tables.print();
    if let Some(path) = trace {
        write_output(&path, &report::optimize::trace(&doc), "the trace")?;
    }
    let text = report::optimize::render(&doc, format)?;
    write_output(
        out.as_deref().unwrap_or(std::path::Path::new("-")),
        &text,
        "the report",
    )?;
    Ok(if doc.failed() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// Writes `text` to stdout. A reader that has gone (`wearopt … | head`) ends the
/// output quietly, as it does for any Unix tool; other write errors are errors
/// (`print!` would panic on both).
pub(crate) fn print_out(text: &str) -> Result<()> {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|_| stdout.flush())
    {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            Err(anyhow::anyhow!("writing to stdout: {e}"))
        }
        _ => Ok(()),
    }
}

/// Writes `text` to `path`, or to stdout when the path is "-". A path that cannot be
/// written (a missing folder, no permission) is the user's input: exit code 2.
pub(crate) fn write_output(path: &std::path::Path, text: &str, what: &str) -> Result<()> {
    if path.as_os_str() == "-" {
        print_out(text)
    } else {
        std::fs::write(path, text).map_err(|e| unwritable(path, what, &e))
    }
}

/// Says on stderr what of a robust file `command` ("sweep") works at the
/// nominal inputs (docs/robust-design.md, "Beyond `optimize`"): a sweep's
/// columns are nominal beside its `feasible_probability` columns, and it takes
/// no statistic. (`pareto` is robust against a probability and against an
/// adhesion measure, and says nothing.)
pub(crate) fn say_nominal_only(
    problem: &wearopt::problem::Problem,
    file: &std::path::Path,
    command: &str,
) {
    if !problem.robust.is_robust() {
        return;
    }
    let file = file.display();
    if command == "sweep" && problem.robust.statistic.is_some() {
        eprintln!(
            "note: {file}: the statistic objective is read by `wearopt optimize` and by `wearopt pareto` only; this sweep's columns are at the nominal inputs{}",
            if problem.robust.chance.is_empty() {
                ""
            } else {
                ", beside one feasible_probability column per chance constraint"
            }
        );
    }
}

/// Checks an output path before the work, so that a long computation is not lost
/// at its end (exit code 2): `path` ("-": stdout, always fine) must not be one of
/// `inputs` (the same file by any name: writing would overwrite what was read)
/// and must be writable — a missing folder, a folder in its place or no permission
/// is found now. Only a regular file or a new path is opened (not truncated; a new
/// file made by the check is removed again); a device or a pipe is left to the
/// write.
pub(crate) fn check_output(
    path: &std::path::Path,
    what: &str,
    inputs: &[&std::path::Path],
) -> Result<()> {
    if path.as_os_str() == "-" {
        return Ok(());
    }
    if let Ok(out) = std::fs::canonicalize(path) {
        if let Some(input) = inputs
            .iter()
            .find(|i| std::fs::canonicalize(i).is_ok_and(|i| i == out))
        {
            return Err(usage(format!(
                "cannot write {what} to {}: it is the input {} (writing would overwrite it): choose another path",
                path.display(),
                input.display()
            )));
        }
    }
    let existing = std::fs::metadata(path).ok();
    if existing
        .as_ref()
        .is_some_and(|m| !m.is_file() && !m.is_dir())
    {
        return Ok(());
    }
    let opened = std::fs::OpenOptions::new()
        .append(true)
        .create(true)
        .open(path);
    match opened {
        Ok(_) => {
            if existing.is_none() {
                let _ = std::fs::remove_file(path);
            }
            Ok(())
        }
        Err(e) => Err(unwritable(path, what, &e)),
    }
}

/// The error of an output path that cannot be written (exit code 2).
pub(crate) fn unwritable(path: &std::path::Path, what: &str, e: &std::io::Error) -> anyhow::Error {
    usage(format!("cannot write {what} to {}: {e}", path.display()))
}

pub(crate) fn usage(msg: String) -> anyhow::Error {
    UsageError(msg).into()
}

fn curve(args: CurveArgs) -> Result<ExitCode> {
    let doc = app::curve::curve(&CurveOptions {
        theta: args.theta,
        lambda: args.lambda,
        hardness_coefficient: args.hardness_coefficient,
        from: args.from,
        to: args.to,
        points: args.points,
        law: LawOptions {
            adhesion_model: args.adhesion_model,
            attraction: args.attraction,
            attraction_range: args.attraction_range,
        },
    })?;
    print_out(&report::curve::render(&doc, args.format)?)?;
    Ok(ExitCode::SUCCESS)
}

fn asperity(args: AsperityArgs) -> Result<ExitCode> {
    let (tabor, sphere) = app::asperity::tabor_or_sphere(
        args.tabor,
        [
            args.radius.as_deref(),
            args.work_of_adhesion.as_deref(),
            args.modulus.as_deref(),
            args.interatomic_distance.as_deref(),
        ],
    )?;
    let options = app::asperity::AsperityOptions {
        tabor,
        from: args.from,
        to: args.to,
        points: args.points,
        law: args.adhesion_model,
        rows: app::asperity::rows_for(tabor, (args.fast || args.converged).then_some(args.fast)),
        sphere,
    };
    options.validate()?;
    if let Some(path) = &args.plot {
        check_output(path, "the plot", &[])?;
    }
    // A traced curve takes seconds to a minute: a spinner while it is traced,
    // then a bar over its converged rows and marks.
    let bar = progress::Bar(
        options
            .traced()
            .then(|| progress::bar(None, "tracing the Lennard-Jones sphere"))
            .flatten(),
    );
    if let Some(b) = &bar.0 {
        b.enable_steady_tick(std::time::Duration::from_millis(200));
    }
    let doc = app::asperity::asperity_with(&options, &Converging(&bar));
    drop(bar);
    let doc = doc?;
    if let Some(path) = &args.plot {
        write_output(path, &report::asperity::plot_svg(&doc), "the plot")?;
    }
    print_out(&report::asperity::render(&doc, args.format)?)?;
    Ok(if doc.status == app::asperity::AsperityStatus::Ok {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}

/// The asperity's bar: the trace's spinner becomes a bar over the converged
/// points once their number is known.
struct Converging<'a>(&'a progress::Bar);

impl app::Progress for Converging<'_> {
    fn begin(&self, total: usize) {
        if let Some(b) = &self.0 .0 {
            if total > 0 {
                b.set_style(
                    indicatif::ProgressStyle::with_template(
                        "{msg:>12} [{bar:30}] {pos}/{len} {elapsed}",
                    )
                    .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
                    .progress_chars("=> "),
                );
                b.set_message("converging rows and marks");
                b.set_position(0);
            }
        }
        app::Progress::begin(self.0, total);
    }

    fn advance(&self) {
        app::Progress::advance(self.0);
    }
}

fn humidity(args: HumidityArgs) -> Result<ExitCode> {
    let options = app::humidity::HumidityOptions {
        from: app::humidity::relative_humidity(OptionName("from"), &args.from)?,
        to: app::humidity::relative_humidity(OptionName("to"), &args.to)?,
        points: args.points,
    };
    options.validate()?;
    if let Some(path) = &args.plot {
        check_output(path, "the plot", &[&args.file])?;
    }
    let problem = app::load(&args.file)?;
    let bar = progress::Bar(progress::bar(Some(0), "humidities"));
    let doc =
        app::humidity::humidity_with(&problem, &args.file.display().to_string(), &options, &bar)?;
    drop(bar);
    if let Some(path) = &args.plot {
        write_output(path, &report::humidity::plot_svg(&doc), "the plot")?;
    }
    print_out(&report::humidity::render(&doc, args.format)?)?;
    // No usable row is no usable result (the report says why), as for eval.
    Ok(if doc.failed() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// The exit code for an error: 2 for bad input and usage, 1 otherwise.
pub fn exit_code(err: &anyhow::Error) -> u8 {
    if err.downcast_ref::<app::ProblemError>().is_some()
        || err.downcast_ref::<UsageError>().is_some()
        || err.downcast_ref::<app::AppError>().is_some()
        || err.downcast_ref::<report::format::FormatError>().is_some()
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
