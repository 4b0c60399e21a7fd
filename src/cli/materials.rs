//! `wearopt optimize` on a file with `[design] materials`: the ranking of one
//! study per catalogue material of body a ([`wearopt::documents::optimize`]
//! runs them), written out with its trace.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;

use wearopt::optimize::materials::{MaterialOutcome, MaterialRanking};
use wearopt::problem::Problem;
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

/// Writes the ranking of `problem`'s materials to `out` (stdout when `None`) and
/// the per-material trace to `trace`. Exit code 1 when no material meets every
/// constraint.
pub fn write(
    problem: &Problem,
    ranking: &MaterialRanking,
    format: Rendering,
    out: Option<&Path>,
    trace: Option<PathBuf>,
) -> Result<ExitCode> {
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
        Rendering::Text => report::materials::text(&problem.name, ranking),
        Rendering::Json => {
            report::json_text(&report::materials::json_value(&problem.name, ranking))
        }
        Rendering::Html => report::materials::html(&problem.name, ranking),
    };
    super::write_output(out.unwrap_or(Path::new("-")), &text, "the report")?;
    Ok(if ranking.best().is_some() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
