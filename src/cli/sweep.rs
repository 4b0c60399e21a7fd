//! `wearopt sweep` (a study's scene at N designs of its `[design]` box, rows
//! streamed as they are computed, shardable over a Slurm job array, resumable)
//! and `wearopt merge` (the shards joined into the unsharded output).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::{Context, Result};
use clap::ValueEnum;

use wearopt::app::sweep::{self as sw, Method, ParetoDirection, Shard, SweepOptions, SweepRow};
use wearopt::report::sweep::{self as out, Encoding, MergeError};

use super::usage;

/// Sampling methods (command-line spelling).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// Sobol′ points with a seeded digital shift (best with 2^k samples).
    Sobol,
    /// Latin hypercube (seeded).
    Lhs,
    /// Full factorial grid: N = m^n for n variables.
    Grid,
}

/// Arguments of `wearopt sweep`.
#[derive(Debug, clap::Args)]
pub struct SweepArgs {
    /// The problem file (TOML) with a [design] section.
    pub file: PathBuf,
    /// Number of designs N (1 to 2^32), over all shards.
    #[arg(long)]
    pub samples: u64,
    /// How the designs fill the box (log-scaled like the optimiser).
    #[arg(long, value_enum, default_value_t = MethodArg::Sobol)]
    pub method: MethodArg,
    /// Seed of the Sobol′ shift or the Latin hypercube (ignored by grid).
    #[arg(long, default_value_t = 0)]
    pub seed: u64,
    /// Run only part I of N (I = 0 … N−1). Default: from SLURM_ARRAY_TASK_ID and
    /// SLURM_ARRAY_TASK_COUNT (and _MIN, _STEP) when set, else the whole sweep.
    #[arg(long, value_name = "I/N")]
    pub shard: Option<String>,
    /// Output format: CSV (a header line and one line per design) or JSON (one object
    /// with a `rows` array, one row per line).
    #[arg(long, value_parser = super::format::formats("sweep", out::FORMATS), default_value = "csv")]
    pub format: wearopt::report::Format,
    /// Write the rows to this file instead of stdout; a rerun that finds it complete skips the work.
    #[arg(long, value_name = "PATH")]
    pub out: Option<PathBuf>,
    /// Also draw wear rate against pull-off force as SVG (feasible, infeasible, Pareto-optimal).
    #[arg(long, value_name = "MAP.svg")]
    pub plot: Option<PathBuf>,
}

/// Arguments of `wearopt merge`.
#[derive(Debug, clap::Args)]
pub struct MergeArgs {
    /// The shard outputs of one sweep, or the parts of one uncertainty study
    /// (any order).
    #[arg(required = true, value_name = "PARTS")]
    pub parts: Vec<PathBuf>,
    /// Check that the parts hold exactly this many rows (CSV parts cannot tell a
    /// missing last shard otherwise; JSON parts carry it), or that the
    /// uncertainty study is of this many samples.
    #[arg(long)]
    pub samples: Option<u64>,
    /// Uncertainty parts: the format of the report (default text). Sweep
    /// parts are joined in their own format (csv or json), which this must name if given.
    #[arg(long, value_parser = super::format::formats("merge", wearopt::report::uncertainty::FORMATS))]
    pub format: Option<wearopt::report::Format>,
    /// Write the merged output to this file instead of stdout ("-": stdout).
    #[arg(long, value_name = "PATH")]
    pub out: Option<PathBuf>,
}

/// Where rows go: a file or stdout.
struct Sink {
    writer: Box<dyn Write>,
}

impl Sink {
    fn write(&mut self, text: &str) -> std::io::Result<()> {
        self.writer.write_all(text.as_bytes())
    }
}

/// Runs `wearopt sweep`.
pub fn run(args: SweepArgs) -> Result<ExitCode> {
    for (path, what) in [(&args.out, "the sweep"), (&args.plot, "the plot")] {
        if let Some(path) = path {
            super::check_output(path, what, &[&args.file])?;
        }
    }
    let problem = wearopt::app::load(&args.file)?;
    super::say_nominal_only(&problem, &args.file, "sweep");
    let method = match args.method {
        MethodArg::Sobol => Method::Sobol,
        MethodArg::Lhs => Method::Lhs,
        MethodArg::Grid => Method::Grid,
    };
    let format = Encoding::of(args.format)
        .ok_or_else(|| super::format::refuse("sweep", args.format, out::FORMATS))?;
    // The sweep is checked before the shard, as it always was.
    let plan = sw::plan(
        &problem,
        &args.file.display().to_string(),
        &SweepOptions {
            samples: args.samples,
            method,
            seed: args.seed,
        },
    )?;
    let shard = match &args.shard {
        Some(s) => super::shard::parse_shard(s)?,
        None => super::shard::slurm_shard()?.unwrap_or(Shard::WHOLE),
    };
    let plan = plan.part(shard);
    let sweep = &plan.sweep;
    let range = plan.range.clone();
    // The problem's content for the fingerprint: the file as read, and its scan.
    let problem_bytes =
        sw::fingerprint_content(&problem, &std::fs::read(&args.file).unwrap_or_default());
    let head = out::head(
        format,
        &out::Head {
            name: &plan.name,
            sweep,
            problem: &problem_bytes,
            shard,
        },
    );
    let direction = plan.direction;

    // Resume: a complete output of this very shard of this very sweep (its head,
    // fingerprint and shard included, as this run would write it) is kept. Only a
    // regular file is read back: a pipe, a terminal or a device such as
    // /dev/stdout or /dev/full is a fresh output (reading it would wait for input
    // that never comes, or read without end).
    if let Some(path) = args
        .out
        .as_ref()
        .filter(|p| super::shard::is_regular_file(p))
    {
        if let Ok(existing) = std::fs::read_to_string(path) {
            if let Ok(part) = out::parse_part(&existing) {
                if part.format == format && part.head == head && part.covers(range.clone()) {
                    eprintln!(
                        "{}: complete (rows {}..{} of {}): skipped",
                        path.display(),
                        range.start,
                        range.end,
                        sweep.samples()
                    );
                    if let Some(plot) = &args.plot {
                        let points = out::map_points(&part)
                            .map_err(|e| usage(format!("{}: {e}", path.display())))?;
                        write_map(plot, &plan.name, &points, direction)?;
                    }
                    return Ok(ExitCode::SUCCESS);
                }
            }
        }
    }

    let writer: Box<dyn Write> = match &args.out {
        Some(path) => Box::new(std::io::BufWriter::new(
            std::fs::File::create(path).map_err(|e| super::unwritable(path, "the sweep", &e))?,
        )),
        None => Box::new(std::io::BufWriter::new(std::io::stdout().lock())),
    };
    let mut sink = Sink { writer };
    let bar = super::progress::wanted().then(|| {
        let b = indicatif::ProgressBar::new(range.end - range.start);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "designs [{bar:30}] {pos}/{len} {elapsed} (eta {eta})",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        b
    });
    let mut points: Vec<(f64, Option<f64>, bool)> = Vec::new();
    let mut first = true;
    let result = sink.write(&head).and_then(|_| {
        plan.run(|rows: &[SweepRow]| {
            let mut text = String::with_capacity(rows.len() * 200);
            for r in rows {
                text.push_str(&out::row(format, sweep, r, first));
                first = false;
                if args.plot.is_some() {
                    points.push((r.wear_rate, r.log10_pull_off_force, r.feasible));
                }
            }
            if let Some(b) = &bar {
                b.inc(rows.len() as u64);
            }
            sink.write(&text)?;
            sink.writer.flush()
        })?;
        sink.write(out::tail(format))?;
        sink.writer.flush()
    });
    if let Some(b) = &bar {
        b.finish_and_clear();
    }
    if let Err(e) = result {
        if args.out.is_some() || e.kind() != std::io::ErrorKind::BrokenPipe {
            let to = args
                .out
                .as_ref()
                .map_or("stdout".to_string(), |p| p.display().to_string());
            return Err(e).with_context(|| format!("writing to {to}"));
        }
    }
    if let Some(plot) = &args.plot {
        write_map(plot, &plan.name, &points, direction)?;
    }
    Ok(ExitCode::SUCCESS)
}

fn write_map(
    path: &Path,
    name: &str,
    points: &[(f64, Option<f64>, bool)],
    direction: ParetoDirection,
) -> Result<()> {
    let optimal = sw::pareto_optimal(points, direction);
    super::write_output(
        path,
        &out::map_svg(name, points, &optimal, direction),
        "the plot",
    )
}

/// Runs `wearopt merge`: uncertainty parts when the first part is one, else
/// sweep parts.
pub fn merge(args: MergeArgs) -> Result<ExitCode> {
    let out_path = args.out.as_deref().filter(|p| p.as_os_str() != "-");
    if args
        .parts
        .first()
        .is_some_and(|p| super::uncertainty::is_part_file(p))
    {
        return super::uncertainty::merge(&args.parts, args.samples, args.format, out_path);
    }
    let read =
        |p: &Path| std::fs::read_to_string(p).map_err(|e| usage(format!("{}: {e}", p.display())));
    let fail = |p: &Path, e: MergeError| usage(format!("{}: {e}", p.display()));
    // First pass: check every part and find its place; one file in memory at a time.
    let mut order = Vec::with_capacity(args.parts.len());
    let mut encoding = None;
    for (i, path) in args.parts.iter().enumerate() {
        let text = read(path)?;
        if wearopt::report::uncertainty::is_part(&text) {
            return Err(usage(format!(
                "{}: an uncertainty part among the parts of a sweep: merge the parts of one run at a time",
                path.display()
            )));
        }
        let part = out::parse_part(&text).map_err(|e| fail(path, e))?;
        encoding.get_or_insert(part.format);
        order.push((out::sort_key(&part), i));
    }
    order.sort();
    if let (Some(format), Some(encoding)) = (args.format, encoding) {
        if Encoding::of(format) != Some(encoding) {
            return Err(usage(format!(
                "--format {}: sweep parts are joined in their own format ({}), not converted",
                format.as_str(),
                match encoding {
                    Encoding::Csv => "csv",
                    Encoding::Json => "json",
                }
            )));
        }
    }
    let mut stdout: Box<dyn Write> = match out_path {
        Some(path) => Box::new(std::io::BufWriter::new(
            std::fs::File::create(path).map_err(|e| super::unwritable(path, "the merge", &e))?,
        )),
        None => Box::new(std::io::BufWriter::new(std::io::stdout().lock())),
    };
    let mut merger = None;
    let mut write = |text: &str| -> Result<bool> {
        match stdout.write_all(text.as_bytes()) {
            Ok(()) => Ok(true),
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(false),
            Err(e) => Err(e).context(match out_path {
                Some(p) => format!("writing to {}", p.display()),
                None => "writing to stdout".to_string(),
            }),
        }
    };
    for &(_, i) in &order {
        let path = &args.parts[i];
        let text = read(path)?;
        let part = out::parse_part(&text).map_err(|e| fail(path, e))?;
        let m = match &mut merger {
            Some(m) => m,
            None => {
                let (m, head) = out::Merger::new(&part);
                if !write(&head)? {
                    return Ok(ExitCode::SUCCESS);
                }
                merger.insert(m)
            }
        };
        let rows = m.push(&part).map_err(|e| fail(path, e))?;
        if !write(&rows)? {
            return Ok(ExitCode::SUCCESS);
        }
    }
    let tail = merger
        .expect("at least one part")
        .finish(args.samples)
        .map_err(|e| usage(format!("{} parts: {e}", args.parts.len())))?;
    write(&tail)?;
    stdout.flush().or_else(|e| {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            Ok(())
        } else {
            Err(e)
        }
    })?;
    Ok(ExitCode::SUCCESS)
}
