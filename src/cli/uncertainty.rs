//! `wearopt uncertainty`: the scene under the scatter of its `[uncertainty]`
//! inputs, whole or one shard of it; and `wearopt merge` of the shards' parts.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use anyhow::Result;
use clap::Args;

use wearopt::app::uncertainty::{self as uq, Analysis, UncertaintyDocument, UncertaintyOptions};
use wearopt::app::{self, OptionName, Problem};
use wearopt::report::{self, Format};

use super::format::formats;
use super::{progress, usage, write_output};

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
    /// The seed of the scrambled sequences and of importance sampling (overrides [uncertainty] seed).
    #[arg(long)]
    seed: Option<u64>,
    /// Run only part I of N (I = 0 … N−1) and write it as a part (JSON) for
    /// `wearopt merge`. Default: from SLURM_ARRAY_TASK_ID and
    /// SLURM_ARRAY_TASK_COUNT (and _MIN, _STEP) when set, else the whole study.
    /// Not with reliability (sequential).
    #[arg(long, value_name = "I/N")]
    shard: Option<String>,
    /// Output format (default text). A shard writes its part as JSON whatever
    /// is asked here but json: give the format to `wearopt merge`.
    #[arg(long, value_parser = formats("uncertainty", report::uncertainty::FORMATS))]
    format: Option<Format>,
    /// Write the report (or the part) to this file instead of stdout ("-": stdout).
    #[arg(long, value_name = "PATH")]
    out: Option<PathBuf>,
}

pub(crate) fn run(args: UncertaintyArgs) -> Result<ExitCode> {
    let method = uq::method(OptionName("method"), &args.method)?;
    let shard = match &args.shard {
        Some(s) => Some((super::shard::parse_shard(s)?, false)),
        None => super::shard::slurm_shard()?.map(|s| (s, true)),
    };
    let options = UncertaintyOptions {
        method,
        samples: args.samples,
        seed: args.seed,
    };
    let origin = args.file.display().to_string();
    let out = args.out.as_deref().unwrap_or(Path::new("-"));
    let bar = progress::Bar(progress::bar(
        Some(0),
        match method {
            uq::Method::Reliability => "events",
            uq::Method::Morris => "evaluations",
            _ => "samples",
        },
    ));
    if let Some((shard, from_slurm)) = shard {
        let whence = if from_slurm {
            format!(
                "SLURM_ARRAY_TASK_ID makes this run shard {}/{} of a job array",
                shard.index, shard.count
            )
        } else {
            format!("--shard {}/{}", shard.index, shard.count)
        };
        if let Some(f) = args.format.filter(|&f| f != Format::Json) {
            return Err(usage(format!(
                "{whence}: a shard writes a part (JSON) for `wearopt merge`, not --format {}; give the format to the merge (wearopt merge PARTS... --format {})",
                f.as_str(),
                f.as_str()
            )));
        }
        if from_slurm && method == uq::Method::Reliability {
            return Err(usage(format!(
                "{whence}, but reliability cannot be sharded (each FORM step and importance-sampling round depends on the last): run it outside the array, or with SLURM_ARRAY_TASK_ID unset"
            )));
        }
        let (problem, source) = load_with_text(&args.file)?;
        // Resume, as a sweep does: a complete part of this very shard of this very
        // study (fingerprint, shard, units, every point) at --out is kept. Only a
        // regular file is read back (not a pipe or a device).
        if let Some(path) = args
            .out
            .as_ref()
            .filter(|p| super::shard::is_regular_file(p))
        {
            let (fingerprint, range) = uq::part_identity(&problem, &origin, &options, shard)?;
            let done = std::fs::read_to_string(path)
                .ok()
                .and_then(|text| report::uncertainty::parse_part(&text).ok())
                .is_some_and(|part| part.is_complete_for(&fingerprint, shard, &range));
            if done {
                eprintln!(
                    "{}: complete (units {}..{} of shard {}/{}): skipped",
                    path.display(),
                    range.start,
                    range.end,
                    shard.index,
                    shard.count
                );
                return Ok(ExitCode::SUCCESS);
            }
        }
        let part = uq::uncertainty_part(&problem, &origin, &source, &options, shard, &bar)?;
        if let Some(b) = &bar.0 {
            b.finish_and_clear();
        }
        write_output(out, &report::uncertainty::part_json(&part), "the part")?;
        return Ok(ExitCode::SUCCESS);
    }
    let problem = app::load(&args.file)?;
    let doc = uq::uncertainty(&problem, &origin, &options, &bar)?;
    if let Some(b) = &bar.0 {
        b.finish_and_clear();
    }
    write_document(&doc, args.format, out)
}

/// The problem and its text, as parsed.
fn load_with_text(path: &Path) -> Result<(Problem, String)> {
    match std::fs::read(path).map(String::from_utf8) {
        Ok(Ok(text)) => {
            let problem = app::parse(&text, &path.display().to_string())?;
            Ok((problem, text))
        }
        // Not readable, or not UTF-8: the loader's words for it.
        _ => {
            let problem = app::load(path)?;
            let text = std::fs::read_to_string(path)?;
            Ok((problem, text))
        }
    }
}

/// Renders the document to `out`; exit code 1 when no event has a probability.
fn write_document(
    doc: &UncertaintyDocument,
    format: Option<Format>,
    out: &Path,
) -> Result<ExitCode> {
    let text = report::uncertainty::render(doc, format.unwrap_or(Format::Text))?;
    write_output(out, &text, "the report")?;
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

/// `wearopt merge` of uncertainty parts: the unsharded run's report, in `format`
/// (default text) to `out` (default stdout).
pub(crate) fn merge(
    paths: &[PathBuf],
    samples: Option<u64>,
    format: Option<Format>,
    out: Option<&Path>,
) -> Result<ExitCode> {
    let mut parts = Vec::with_capacity(paths.len());
    for path in paths {
        let name = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| usage(format!("{name}: {e}")))?;
        let part = report::uncertainty::parse_part(&text).map_err(|error| app::AppError::Part {
            origin: name.clone(),
            error,
        })?;
        parts.push((name, part));
    }
    let doc = uq::merge(parts, samples)?;
    write_document(&doc, format, out.unwrap_or(Path::new("-")))
}

/// Whether the file holds an uncertainty part (it is merged as one).
pub(crate) fn is_part_file(path: &Path) -> bool {
    use std::io::Read;
    let mut head = [0u8; 256];
    let n = std::fs::File::open(path)
        .and_then(|mut f| f.read(&mut head))
        .unwrap_or(0);
    report::uncertainty::is_part(&String::from_utf8_lossy(&head[..n]))
}
