//! `wearopt pareto`: the wear–adhesion front of a study with a `[pareto]`
//! section, by the ε-constraint method. CSV and JSON rows go to stdout as the
//! points are final (flushed each time), so an interrupted sweep keeps what it
//! computed; a progress bar shows on a terminal.

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Mutex;

use anyhow::{Context, Result};

use wearopt::documents;
use wearopt::optimize::pareto::{Front, FrontPoint, FrontStatus, Observer};
use wearopt::optimize::Study;
use wearopt::report::pareto as out;
use wearopt::report::Format;

use super::usage;

/// Arguments of `wearopt pareto`.
#[derive(Debug, clap::Args)]
pub struct ParetoArgs {
    /// The problem file (TOML) with [design], [objective] and [pareto] sections.
    pub file: PathBuf,
    /// Points on the curve (2 to 200; default: [pareto] points).
    #[arg(long)]
    pub points: Option<usize>,
    /// Output format: CSV has one row per point (header row), the design flattened into
    /// columns; JSON one object (status, adhesion_measure, points, knee, …).
    #[arg(long, value_parser = super::format::formats("pareto", out::FORMATS), default_value = "text")]
    pub format: Format,
    /// Also draw the front as SVG to this file.
    #[arg(long, value_name = "FRONT.svg")]
    pub plot: Option<PathBuf>,
    /// Write the HTML page to this file instead of stdout (with --format html).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// Whether a progress bar may be drawn: stderr is a terminal, and neither
/// NO_COLOR nor CI asks for plain output.
fn progress_wanted() -> bool {
    std::io::stderr().is_terminal()
        && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
        && std::env::var_os("CI").is_none_or(|v| v.is_empty() || v == "false")
}

/// Streams finished points to stdout and drives the progress bar.
struct Stream<'a> {
    format: Format,
    names: &'a [&'static str],
    bar: Option<indicatif::ProgressBar>,
    /// Points written so far, and the first write error.
    state: Mutex<(usize, Option<std::io::Error>)>,
}

impl Stream<'_> {
    fn write(&self, text: &str) {
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        if st.1.is_some() {
            return;
        }
        let mut stdout = std::io::stdout().lock();
        if let Err(e) = stdout
            .write_all(text.as_bytes())
            .and_then(|_| stdout.flush())
        {
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

    fn point_done(&self, p: &FrontPoint) {
        if let Some(b) = &self.bar {
            b.inc(1);
        }
        let first = {
            let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
            st.0 += 1;
            st.0 == 1
        };
        match self.format {
            Format::Csv => self.write(&out::csv_row(p)),
            Format::Json => self.write(&out::json_point(self.names, p, first)),
            Format::Text | Format::Html => {}
        }
    }
}

/// The study's constraint quantities at every design of the front, the least-wear
/// design and the baseline: one model evaluation each, of the scene the optimiser's
/// own design space builds from the design.
fn constraint_values(study: &Study, front: &Front) -> out::ConstraintValues {
    let space = wearopt::optimize::DesignSpace::new(study.scene, study.design);
    let options = wearopt::model::EvaluationOptions::default();
    let at = |design: &[f64]| -> Vec<Option<f64>> {
        // The design space's unit coordinates of the SI design (its own map inverted).
        let x: Vec<f64> = space
            .variables
            .iter()
            .zip(design)
            .map(|(v, &d)| {
                let u = if v.logarithmic {
                    (d / v.min).ln() / (v.max / v.min).ln()
                } else {
                    (d - v.min) / (v.max - v.min)
                };
                if u.is_finite() {
                    u.clamp(0.0, 1.0)
                } else {
                    0.0
                }
            })
            .collect();
        let scene = space.scene_at(&x);
        let ev = wearopt::model::evaluate(&scene, &options);
        study
            .constraints
            .iter()
            .map(|c| {
                wearopt::optimize::functions::quantity_value(c.quantity, &ev, &scene)
                    .filter(|v| v.is_finite())
            })
            .collect()
    };
    out::ConstraintValues {
        points: front.points.iter().map(|p| at(&p.design)).collect(),
        least_wear: at(&front.least_wear.design),
        baseline: front.baseline.as_ref().map(|b| at(&b.design)),
    }
}

/// Runs `wearopt pareto`.
pub fn run(args: ParetoArgs) -> Result<ExitCode> {
    if args.out.is_some() && args.format != Format::Html {
        return Err(usage(
            "--out is for --format html; text, CSV and JSON stream to stdout (redirect it)"
                .to_string(),
        ));
    }
    let problem = wearopt::problem::load(&args.file)?;
    let origin = args.file.display().to_string();
    let spec = documents::pareto_spec(&problem, &origin, args.points)?;
    let names: Vec<&'static str> = problem
        .study
        .design
        .iter()
        .map(|d| d.name.as_str())
        .collect();
    let bar = progress_wanted().then(|| {
        let b = indicatif::ProgressBar::new(spec.points as u64);
        b.set_style(
            indicatif::ProgressStyle::with_template("{msg:>12} [{bar:30}] {pos}/{len} {elapsed}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
                .progress_chars("=> "),
        );
        b
    });
    let stream = Stream {
        format: args.format,
        names: &names,
        bar,
        state: Mutex::new((0, None)),
    };
    let head = out::Head {
        name: &problem.name,
        measure: spec.adhesion,
        direction: spec.direction,
        objective_name: problem.study.objective.map_or("", |o| o.as_str()),
        names: &names,
    };
    match args.format {
        Format::Csv => stream.write(&out::csv_header(&names)),
        Format::Json => stream.write(&out::json_head(&head)),
        Format::Text | Format::Html => {}
    }
    let front = documents::pareto(&problem, &origin, &spec, &stream)?;
    if let Some(b) = &stream.bar {
        b.finish_and_clear();
    }
    match args.format {
        Format::Csv => {}
        Format::Json => stream.write(&out::json_tail(&front)),
        Format::Text => stream.write(&out::text(
            &problem.name,
            &front,
            &problem.study.constraints,
        )),
        Format::Html => {
            let values = constraint_values(&documents::study(&problem), &front);
            let page = out::html(&problem.name, &front, &problem.study.constraints, &values);
            super::write_output(
                args.out.as_deref().unwrap_or(std::path::Path::new("-")),
                &page,
                "the page",
            )?;
        }
    }
    if let Some(e) = stream
        .state
        .into_inner()
        .unwrap_or_else(|e| e.into_inner())
        .1
    {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            return Err(e).context("writing to stdout");
        }
    }
    if let Some(path) = &args.plot {
        std::fs::write(path, out::svg(&problem.name, &front))
            .with_context(|| format!("writing the plot to {}", path.display()))?;
    }
    Ok(match front.status {
        FrontStatus::Infeasible => ExitCode::from(1),
        _ => ExitCode::SUCCESS,
    })
}
