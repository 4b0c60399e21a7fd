//! `wearopt optimize` on a file with `[design] materials`: the ranking of one
//! study per catalogue material of body a ([`wearopt::documents::optimize`]
//! runs them), written out with its trace.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;

use wearopt::optimize::materials::MaterialRanking;
use wearopt::problem::Problem;
use wearopt::report::{self, Format};

/// Writes the ranking of `problem`'s materials to `out` (stdout when `None`) and
/// the per-material trace to `trace`. Exit code 1 when no material meets every
/// constraint.
pub fn write(
    problem: &Problem,
    ranking: &MaterialRanking,
    format: Format,
    out: Option<&Path>,
    trace: Option<PathBuf>,
) -> Result<ExitCode> {
    if let Some(path) = trace {
        super::write_output(&path, &report::materials::trace_csv(ranking), "the trace")?;
    }
    let text = match format {
        Format::Text => report::materials::text(&problem.name, ranking),
        Format::Json => report::json_text(&report::materials::json_value(&problem.name, ranking)),
        Format::Html => report::materials::html(&problem.name, ranking),
        f => {
            return Err(super::format::refuse(
                "optimize",
                f,
                report::materials::FORMATS,
            ))
        }
    };
    super::write_output(out.unwrap_or(Path::new("-")), &text, "the report")?;
    Ok(if ranking.best().is_some() {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    })
}
