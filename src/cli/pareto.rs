//! `wearopt pareto`: the wear–adhesion front of a study with a `[pareto]`
//! section, by the ε-constraint method. CSV and JSON rows go to stdout as the
//! points are final (flushed each time), so an interrupted sweep keeps what it
//! computed; a progress bar shows on a terminal.

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Mutex;

use anyhow::{Context, Result};

use wearopt::app::pareto::{self as front, FrontPoint, FrontStatus, Observer, ParetoPlan};
use wearopt::app::OptionName;
use wearopt::report::pareto as out;
use wearopt::report::Format;

/// Arguments of `wearopt pareto`.
#[derive(Debug, clap::Args)]
pub struct ParetoArgs {
    /// The problem file (TOML) with [design] and [objective] sections, and a [pareto]
    /// section unless --adhesion, --points or --direction says what front to draw.
    pub file: PathBuf,
    /// Points on the curve (2 to 200; default: [pareto] points, else 15).
    #[arg(long)]
    pub points: Option<usize>,
    /// The adhesion measure on the front's second axis: pull_off_force,
    /// work_of_adhesion (needs it among the [design] variables) or
    /// elastic_adhesion_index (default: [pareto] adhesion, else pull_off_force).
    #[arg(long, value_name = "MEASURE")]
    pub adhesion: Option<String>,
    /// Which end of the adhesion measure is preferred: low (no stiction) or high (a
    /// latch, a switch that must hold) (default: [pareto] direction, else low).
    #[arg(long, value_name = "low|high")]
    pub direction: Option<String>,
    /// Output format: CSV has one row per point (header row), the design flattened into
    /// columns; JSON one object (status, adhesion_measure, points, knee, …).
    #[arg(long, value_parser = super::format::formats("pareto", out::FORMATS), default_value = "text")]
    pub format: Format,
    /// Also draw the front as SVG to this file.
    #[arg(long, value_name = "FRONT.svg")]
    pub plot: Option<PathBuf>,
    /// Write the report to this file instead of stdout ("-": stdout); text, CSV and JSON
    /// rows are written to it as they are solved.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// Streams finished points to stdout (or the --out file) and drives the progress bar.
struct Stream<'a> {
    format: Format,
    plan: &'a ParetoPlan,
    bar: Option<indicatif::ProgressBar>,
    /// Points written so far, the first write error, and the file written
    /// instead of stdout.
    state: Mutex<(usize, Option<std::io::Error>, Option<std::fs::File>)>,
}

impl Stream<'_> {
    fn write(&self, text: &str) {
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        if st.1.is_some() {
            return;
        }
        let written = match &mut st.2 {
            Some(file) => file.write_all(text.as_bytes()).and_then(|_| file.flush()),
            None => {
                let mut stdout = std::io::stdout().lock();
                stdout
                    .write_all(text.as_bytes())
                    .and_then(|_| stdout.flush())
            }
        };
        if let Err(e) = written {
            st.1 = Some(e);
        }
    }
}

impl Observer for Stream<'_> {
    fn range_started(&self) {
        if let Some(b) = &self.bar {
            b.set_message("finding the reachable adhesion range");
        }
    }

    fn probe_done(&self) {
        if let Some(b) = &self.bar {
            b.tick();
        }
    }

    fn sweep_started(&self, points: usize) {
        if let Some(b) = &self.bar {
            b.set_length(points as u64);
            b.set_position(0);
            b.set_message("points");
        }
    }

    fn point_solved(&self) {
        if let Some(b) = &self.bar {
            b.inc(1);
        }
    }

    fn refine_started(&self) {
        if let Some(b) = &self.bar {
            b.set_message("points, re-solving");
        }
    }

    fn turn_started(&self, solves: usize) {
        if let Some(b) = &self.bar {
            // At most this many more: the count ends when the work does.
            b.set_length(b.position() + solves as u64);
            b.set_message("solves at the turn");
        }
    }

    fn point_done(&self, p: &FrontPoint) {
        let first = {
            let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
            st.0 += 1;
            st.0 == 1
        };
        let text = out::stream_point(self.plan, self.format, p, first);
        if !text.is_empty() {
            self.write(&text);
        }
    }
}

/// Runs `wearopt pareto`.
pub fn run(args: ParetoArgs) -> Result<ExitCode> {
    let problem = wearopt::app::load(&args.file)?;
    let origin = args.file.display().to_string();
    if problem.robust.front.is_some() {
        return event_front(&args, &problem, &origin);
    }
    let mut options = out::options(args.format, args.points);
    options.adhesion = args
        .adhesion
        .as_deref()
        .map(|t| front::measure(OptionName("adhesion"), t))
        .transpose()?;
    options.direction = args
        .direction
        .as_deref()
        .map(|t| front::direction(OptionName("direction"), t))
        .transpose()?;
    if problem.robust.is_robust() {
        return adhesion_front(&args, &problem, &origin, &options);
    }
    let plan = front::plan(&problem, &origin, &options)?;
    let bar = super::progress::wanted().then(|| {
        let b = indicatif::ProgressBar::new(plan.spec.points as u64);
        b.set_style(
            indicatif::ProgressStyle::with_template("{msg:>12} [{bar:30}] {pos}/{len} {elapsed}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
                .progress_chars("=> "),
        );
        b
    });
    // Text, CSV and JSON go to the --out file as they come (HTML is written whole
    // at the end): created before the solves, so a path that cannot be written
    // is refused before any work.
    let streamed_to = args
        .out
        .as_deref()
        .filter(|p| p.as_os_str() != "-" && args.format != Format::Html);
    let file = streamed_to
        .map(|p| std::fs::File::create(p).map_err(|e| super::unwritable(p, "the report", &e)))
        .transpose()?;
    let stream = Stream {
        format: args.format,
        plan: &plan,
        bar,
        state: Mutex::new((0, None, file)),
    };
    let head = out::stream_head(&plan, args.format);
    if !head.is_empty() {
        stream.write(&head);
    }
    let doc = front::pareto(&problem, &origin, &options, &stream)?;
    if let Some(b) = &stream.bar {
        b.finish_and_clear();
    }
    let tail = out::stream_tail(&doc, args.format);
    match args.format {
        Format::Html => super::write_output(
            args.out.as_deref().unwrap_or(std::path::Path::new("-")),
            &tail,
            "the page",
        )?,
        _ if !tail.is_empty() => stream.write(&tail),
        _ => {}
    }
    if let Some(e) = stream
        .state
        .into_inner()
        .unwrap_or_else(|e| e.into_inner())
        .1
    {
        match streamed_to {
            Some(path) => return Err(super::unwritable(path, "the report", &e)),
            None if e.kind() != std::io::ErrorKind::BrokenPipe => {
                return Err(e).context("writing to stdout")
            }
            None => {}
        }
    }
    if let Some(path) = &args.plot {
        super::write_output(path, &out::svg(&doc.plan.name, &doc.front), "the plot")?;
    }
    Ok(match doc.front.status {
        FrontStatus::Infeasible => ExitCode::from(1),
        _ => ExitCode::SUCCESS,
    })
}

/// `wearopt pareto` on a front against a probability (`[pareto] event`): one
/// robust optimum per level, a line on stderr per level on a terminal; the
/// report written whole at the end. Exit code 1 when no level gives a usable
/// point.
fn event_front(
    args: &ParetoArgs,
    problem: &wearopt::problem::Problem,
    origin: &str,
) -> Result<ExitCode> {
    for (flag, given) in [
        ("--adhesion", args.adhesion.is_some()),
        ("--direction", args.direction.is_some()),
    ] {
        if given {
            return Err(super::usage(format!(
                "{flag}: {origin} draws a front against the probability of an event ([pareto] event), whose second axis is that probability, the low end preferred; remove {flag}"
            )));
        }
    }
    check_robust_front_outputs(args)?;
    let progress = super::progress::wanted();
    let doc = wearopt::app::robust_front::event_front(problem, origin, args.points, &mut |p| {
        if progress {
            eprintln!(
                "level {} (P <= {:e}): {} in {:.1} s",
                p.index,
                p.level,
                p.status().as_str(),
                p.time_seconds
            );
        }
    })?;
    write_robust_front(
        args,
        &wearopt::report::robust_front::render(&doc, args.format),
        || wearopt::report::robust_front::svg(&doc),
        doc.status,
    )
}

/// `wearopt pareto` on a robust study against an adhesion measure: one robust
/// optimum per level of the measure, a line on stderr per level on a
/// terminal; the report written whole at the end. Exit code 1 when no level
/// gives a usable point.
fn adhesion_front(
    args: &ParetoArgs,
    problem: &wearopt::problem::Problem,
    origin: &str,
    options: &front::ParetoOptions,
) -> Result<ExitCode> {
    check_robust_front_outputs(args)?;
    let progress = super::progress::wanted();
    let doc =
        wearopt::app::robust_adhesion_front::adhesion_front(problem, origin, options, &mut |p| {
            if progress {
                eprintln!(
                    "level {} ({:e}): {} in {:.1} s",
                    p.index,
                    p.target,
                    p.status().as_str(),
                    p.time_seconds
                );
            }
        })?;
    write_robust_front(
        args,
        &wearopt::report::robust_adhesion_front::render(&doc, args.format),
        || wearopt::report::robust_adhesion_front::svg(&doc),
        doc.status,
    )
}

/// `--out` and `--plot` checked before a robust front's work (not after
/// minutes of it).
fn check_robust_front_outputs(args: &ParetoArgs) -> Result<()> {
    for (path, what) in [(&args.out, "the report"), (&args.plot, "the plot")] {
        if let Some(path) = path {
            super::check_output(path, what, &[&args.file])?;
        }
    }
    Ok(())
}

/// A robust front's report to `--out` (or stdout) and its plot to `--plot`;
/// exit code 1 when no level gives a usable point.
fn write_robust_front(
    args: &ParetoArgs,
    report: &str,
    svg: impl FnOnce() -> String,
    status: FrontStatus,
) -> Result<ExitCode> {
    super::write_output(
        args.out.as_deref().unwrap_or(std::path::Path::new("-")),
        report,
        "the report",
    )?;
    if let Some(path) = &args.plot {
        super::write_output(path, &svg(), "the plot")?;
    }
    Ok(match status {
        FrontStatus::Infeasible => ExitCode::from(1),
        _ => ExitCode::SUCCESS,
    })
}
