//! `--shard I/N` and Slurm's job-array variables: which part of a sweep or of an
//! uncertainty study one run computes.

use anyhow::Result;

use wearopt::app::sweep::Shard;

use super::usage;

/// `--shard I/N` as given.
pub(crate) fn parse_shard(text: &str) -> Result<Shard> {
    let bad = || {
        usage(format!(
            "--shard {text}: expected I/N with 0 <= I < N, e.g. --shard 0/4"
        ))
    };
    let (i, n) = text.split_once('/').ok_or_else(bad)?;
    let (i, n) = (
        i.trim().parse::<u64>().map_err(|_| bad())?,
        n.trim().parse::<u64>().map_err(|_| bad())?,
    );
    Shard::new(i, n).map_err(|_| bad())
}

/// The shard from Slurm's job-array variables, if they are set.
pub(crate) fn slurm_shard() -> Result<Option<Shard>> {
    let var = |name: &str| -> Result<Option<u64>> {
        match std::env::var(name) {
            Ok(v) if !v.trim().is_empty() => v.trim().parse().map(Some).map_err(|_| {
                usage(format!(
                    "{name}={v}: expected a non-negative integer (a Slurm job-array variable)"
                ))
            }),
            _ => Ok(None),
        }
    };
    let Some(id) = var("SLURM_ARRAY_TASK_ID")? else {
        return Ok(None);
    };
    let count = var("SLURM_ARRAY_TASK_COUNT")?.ok_or_else(|| {
        usage(format!(
            "SLURM_ARRAY_TASK_ID={id} without SLURM_ARRAY_TASK_COUNT: cannot tell the shard; give --shard I/N"
        ))
    })?;
    let shard = Shard::from_slurm(
        id,
        count,
        var("SLURM_ARRAY_TASK_MIN")?,
        var("SLURM_ARRAY_TASK_STEP")?,
    )
    .map_err(|e| usage(e.to_string()))?;
    Ok(Some(shard))
}

/// True when `path` is a regular file (following symbolic links): the only kind of
/// `--out` a rerun reads back to skip a finished shard (a pipe, a terminal or a
/// device such as /dev/stdout is never read).
pub(crate) fn is_regular_file(path: &std::path::Path) -> bool {
    std::fs::metadata(path).is_ok_and(|m| m.is_file())
}
