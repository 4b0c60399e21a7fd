//! `wearopt optimize` on a file with `[design] materials`: one study per catalogue
//! material of body a, run in parallel, and a ranking.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;

use wearopt::optimize::materials::{rank_materials, MaterialOutcome};
use wearopt::problem::{catalogue, Problem};
use wearopt::report;

/// How the ranking is rendered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rendering {
    /// The ranking table for people.
    Text,
    /// One JSON object.
    Json,
    /// One self-contained HTML page.
    Html,
}

/// Runs the material study of `problem` (read from `file`) and prints the ranking.
/// Exit code 1 when no material meets every constraint.
pub fn run(
    file: &Path,
    problem: &Problem,
    format: Rendering,
    out: Option<&Path>,
    verbose: bool,
    trace: Option<PathBuf>,
) -> Result<ExitCode> {
    let materials = problem
        .study
        .materials
        .iter()
        .map(|n| {
            catalogue::lookup(n).ok_or_else(|| {
                super::usage(format!(
                    "{}: design.materials: {n:?} is not a catalogue material",
                    file.display()
                ))
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let study = wearopt::optimize::Study {
        scene: &problem.scene,
        design: &problem.study.design,
        objective: problem.study.objective,
        constraints: &problem.study.constraints,
        settings: &problem.study.optimizer,
    };
    let tables = super::verbose::Tables::default();
    let make = |start: usize| tables.observer(start);
    let ranking = rank_materials(
        &study,
        &materials,
        verbose.then_some(&make as wearopt::optimize::ObserverFactory),
    )
    .map_err(|e| super::usage(format!("{}: {e}", file.display())))?;
    tables.print();
    if let Some(path) = trace {
        let mut csv = String::new();
        for r in &ranking.results {
            if let MaterialOutcome::Optimized(o) = &r.outcome {
                let t = report::optimize::trace_csv(o);
                for (i, l) in t.lines().enumerate() {
                    if i == 0 && csv.is_empty() {
                        csv.push_str(&format!("material,{l}\n"));
                    } else if i > 0 {
                        csv.push_str(&format!("{},{l}\n", r.name()));
                    }
                }
            }
        }
        super::write_output(&path, &csv, "the trace")?;
    }
    let text = match format {
        Rendering::Text => report::materials::text(&problem.name, &ranking),
        Rendering::Json => report::materials::json(&problem.name, &ranking),
        Rendering::Html => report::materials::html(&problem.name, &ranking),
    };
    super::write_output(out.unwrap_or(Path::new("-")), &text, "the report")?;
    Ok(if ranking.best().is_some() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
