//! `wearopt uncertainty`: the scene under the scatter of its `[uncertainty]` inputs.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::Result;
use clap::Args;

use wearopt::app::uncertainty::{self as uq, Analysis, UncertaintyOptions};
use wearopt::app::{self, OptionName};
use wearopt::report::{self, Format};

use super::format::formats;
use super::{progress, write_output};

#[derive(Debug, Args)]
pub(crate) struct UncertaintyArgs {
    /// The problem file (TOML) with an [uncertainty] section.
    file: PathBuf,
    /// The analysis: sobol (indices), morris (screening), sampling (percentiles,
    /// life), reliability (the probability of each [[uncertainty.event]]).
    #[arg(long, default_value = "sobol", value_parser = ["sobol", "morris", "sampling", "reliability"])]
    method: String,
    /// N, the samples (overrides [uncertainty] samples; Sobol′ rounds it up to a
    /// power of two and costs N (d + 2) evaluations).
    #[arg(long)]
    samples: Option<u64>,
    /// The seed of the scrambled sequences and the bootstrap (overrides [uncertainty] seed).
    #[arg(long)]
    seed: Option<u64>,
    /// Output format.
    #[arg(long, value_parser = formats("uncertainty", report::uncertainty::FORMATS), default_value = "text")]
    format: Format,
    /// Write the report to this file instead of stdout ("-": stdout).
    #[arg(long, value_name = "PATH")]
    out: Option<PathBuf>,
}

pub(crate) fn run(args: UncertaintyArgs) -> Result<ExitCode> {
    let method = uq::method(OptionName("method"), &args.method)?;
    let problem = app::load(&args.file)?;
    let bar = progress::Bar(progress::bar(
        Some(0),
        match method {
            uq::Method::Reliability => "events",
            uq::Method::Morris => "evaluations",
            _ => "samples",
        },
    ));
    let doc = uq::uncertainty(
        &problem,
        &args.file.display().to_string(),
        &UncertaintyOptions {
            method,
            samples: args.samples,
            seed: args.seed,
        },
        &bar,
    )?;
    if let Some(b) = &bar.0 {
        b.finish_and_clear();
    }
    let text = report::uncertainty::render(&doc, args.format)?;
    write_output(
        args.out.as_deref().unwrap_or(std::path::Path::new("-")),
        &text,
        "the report",
    )?;
    // No usable result: every event without a probability.
    let failed = match &doc.analysis {
        Analysis::Reliability(events) => events
            .iter()
            .all(|(_, r)| r.probability.is_none() && r.upper_bound.is_none()),
        _ => false,
    };
    Ok(if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}
