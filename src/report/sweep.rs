//! The rows of a design-space sweep (`wearopt sweep`) as CSV or JSON, the join
//! of sharded runs (`wearopt merge`), and the wear–pull-off map as SVG.
//!
//! Both formats come in pieces (head, one line per row, tail) so rows can be
//! written as they are computed. A shard's output is the head, its rows and the
//! tail; the rows of one unsharded run are the rows of all its shards in index
//! order, so [`Merger`] rebuilds the unsharded output byte for byte:
//!
//! * CSV: a header line, then one line per row. The header is the same for every
//!   shard; a part is complete when its last row is the last of its range.
//! * JSON: one object; its head names the sweep (`samples`, `method`, `seed`), its
//!   `rows` array holds one row object per line, and `\n  ]\n}\n` closes it.
//!
//! Every output begins with its fingerprint: a hash of the problem's content
//! (and of the scan its `topography` names), the method, seed, N, wearopt's
//! version and build ([`BUILD`]), and the shard — in CSV a first line
//! `# wearopt sweep fingerprint=… shard=I/N samples=N …` (the comment readers
//! skip: pandas `comment="#"`, NumPy's default), in JSON the keys `fingerprint`
//! and `shard`. A rerun keeps a part only if its head, fingerprint and shard
//! included, is the one it would write; `merge` joins only parts of one
//! fingerprint, checks each part holds exactly its shard's rows of N, and writes
//! the unsharded head (`shard=0/1`).

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::number;
use super::svg::{Axis, LinePlot, Marker, Series};
use crate::optimize::{Named, ParetoDirection};
use crate::sweep::{Shard, Sweep, SweepRow};

/// The formats `wearopt sweep` and `wearopt merge` write (the first is the default).
pub const FORMATS: &[super::Format] = &[super::Format::Csv, super::Format::Json];

/// How a sweep's rows are encoded: the two [`super::Format`]s a sweep writes, as a
/// type of their own so that every piece of a stream (head, rows, tail) and every
/// merged part has exactly one of them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Encoding {
    /// A header line and one line per design.
    Csv,
    /// One object with a `rows` array, one row per line.
    Json,
}

impl Encoding {
    /// The encoding of a report format, if a sweep writes it (see [`FORMATS`]).
    pub fn of(format: super::Format) -> Option<Encoding> {
        match format {
            super::Format::Csv => Some(Encoding::Csv),
            super::Format::Json => Some(Encoding::Json),
            super::Format::Text | super::Format::Html => None,
        }
    }
}

/// What the head of a sweep's output shows.
#[derive(Debug, Clone, Copy)]
pub struct Head<'a> {
    /// The problem's name.
    pub name: &'a str,
    /// The sweep.
    pub sweep: &'a Sweep,
    /// The problem's content as read (the file's bytes, or a dict's JSON text).
    pub problem: &'a [u8],
    /// Which part of the sweep this output holds.
    pub shard: Shard,
}

/// This build of wearopt: a hash of the sources it was compiled from (set by
/// `build.rs`), so that two builds of one version — whose rows may differ — are
/// told apart by a sweep's fingerprint and head.
pub const BUILD: &str = env!("WEAROPT_BUILD_ID");

/// The sweep's fingerprint: FNV-1a (64 bit) of the problem's content (the
/// caller's bytes: the file, and the scan it names — see
/// `app::sweep::fingerprint_content`), the method, seed, N, wearopt's version
/// and [`BUILD`] — the same on every machine for one build.
pub fn fingerprint(problem: &[u8], sweep: &Sweep) -> u64 {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |bytes: &[u8]| {
        for &b in bytes {
            hash ^= u64::from(b);
            hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
        // A separator, so that fields cannot run into each other.
        hash ^= 0xff;
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
    };
    eat(problem);
    eat(sweep.method().as_str().as_bytes());
    eat(&sweep.seed().to_le_bytes());
    eat(&sweep.samples().to_le_bytes());
    eat(env!("CARGO_PKG_VERSION").as_bytes());
    eat(BUILD.as_bytes());
    hash
}

/// The head: the CSV header line, or the JSON object up to the opening of `rows`.
pub fn head(format: Encoding, h: &Head) -> String {
    let print = format!("{:016x}", fingerprint(h.problem, h.sweep));
    let shard = format!("{}/{}", h.shard.index, h.shard.count);
    let names = h.sweep.design_names();
    let constraints: Vec<&str> = h
        .sweep
        .constraint_columns()
        .iter()
        .map(|q| q.as_str())
        .collect();
    match format {
        Encoding::Csv => {
            let mut out = format!(
                "# wearopt sweep fingerprint={print} shard={shard} samples={} method={} seed={} version={} build={BUILD}\n",
                h.sweep.samples(),
                h.sweep.method().as_str(),
                h.sweep.seed(),
                env!("CARGO_PKG_VERSION")
            );
            out.push_str("index");
            for n in &names {
                out.push(',');
                out.push_str(n);
            }
            out.push_str(",status,wear_rate,pull_off_force,log10_pull_off_force,real_area");
            for c in &constraints {
                out.push(',');
                out.push_str(c);
            }
            out.push_str(",feasible");
            for e in h.sweep.chance_columns() {
                let _ = write!(
                    out,
                    ",feasible_probability_{e},feasible_probability_{e}_low,feasible_probability_{e}_high"
                );
            }
            out.push('\n');
            out
        }
        Encoding::Json => {
            let s = |v: Value| serde_json::to_string(&v).unwrap_or_else(|_| "null".into());
            let chance = if h.sweep.chance_columns().is_empty() {
                String::new()
            } else {
                format!(
                    "\n  \"feasible_probability_columns\": {},",
                    s(json!(h.sweep.chance_columns()))
                )
            };
            format!(
                "{{\n  \"fingerprint\": {},\n  \"shard\": {},\n  \"version\": {},\n  \"build\": {},\n  \"name\": {},\n  \"method\": {},\n  \"seed\": {},\n  \"samples\": {},\n  \"design_variables\": {},\n  \"constraint_columns\": {},{chance}\n  \"rows\": [",
                s(json!(print)),
                s(json!(shard)),
                s(json!(env!("CARGO_PKG_VERSION"))),
                s(json!(BUILD)),
                s(json!(h.name)),
                s(json!(h.sweep.method().as_str())),
                h.sweep.seed(),
                h.sweep.samples(),
                s(json!(names)),
                s(json!(constraints)),
            )
        }
    }
}

/// A JSON object on one line with its keys in the given order.
fn object<'a>(pairs: impl Iterator<Item = (&'a str, Value)>) -> String {
    let mut out = String::from("{");
    for (k, (key, v)) in pairs.enumerate() {
        if k > 0 {
            out.push(',');
        }
        let _ = write!(
            out,
            "{}:{}",
            serde_json::to_string(key).unwrap_or_default(),
            serde_json::to_string(&v).unwrap_or_else(|_| "null".into())
        );
    }
    out.push('}');
    out
}

fn csv_cell(v: Option<f64>) -> String {
    v.map(number).unwrap_or_default()
}

/// One row's line, without the separator (see [`row`]).
pub(crate) fn row_line(format: Encoding, sweep: &Sweep, r: &SweepRow) -> String {
    match format {
        Encoding::Csv => {
            let mut out = r.index.to_string();
            for v in &r.design {
                out.push(',');
                out.push_str(&number(*v));
            }
            let _ = write!(
                out,
                ",{},{},{},{},{}",
                r.status.as_str(),
                number(r.wear_rate),
                csv_cell(r.pull_off_force),
                csv_cell(r.log10_pull_off_force),
                number(r.real_area)
            );
            for v in &r.constraints {
                out.push(',');
                out.push_str(&csv_cell(*v));
            }
            let _ = write!(out, ",{}", r.feasible);
            for v in &r.feasible_probability {
                let _ = write!(
                    out,
                    ",{},{},{}",
                    csv_cell(v.map(|f| f.value)),
                    csv_cell(v.map(|f| f.interval[0])),
                    csv_cell(v.map(|f| f.interval[1]))
                );
            }
            out
        }
        Encoding::Json => {
            let design = object(
                sweep
                    .design_names()
                    .iter()
                    .zip(&r.design)
                    .map(|(n, v)| (*n, json!(v))),
            );
            let constraints = object(
                sweep
                    .constraint_columns()
                    .iter()
                    .zip(&r.constraints)
                    .map(|(q, v)| (q.as_str(), json!(v))),
            );
            // Written by hand: the key order is part of the format (index first).
            let s = |v: Value| serde_json::to_string(&v).unwrap_or_else(|_| "null".into());
            let chance = if r.feasible_probability.is_empty() {
                String::new()
            } else {
                let cells: Vec<String> = sweep
                    .chance_columns()
                    .iter()
                    .zip(&r.feasible_probability)
                    .map(|(e, v)| {
                        let inner = v.map_or("null".to_string(), |f| {
                            object(
                                [("value", json!(f.value)), ("interval", json!(f.interval))]
                                    .into_iter(),
                            )
                        });
                        format!("{}:{inner}", s(json!(e)))
                    })
                    .collect();
                format!(",\"feasible_probability\":{{{}}}", cells.join(","))
            };
            format!(
                "    {{\"index\":{},\"design\":{},\"status\":{},\"wear_rate\":{},\"pull_off_force\":{},\"log10_pull_off_force\":{},\"real_area\":{},\"constraints\":{},\"feasible\":{}{chance}}}",
                r.index,
                design,
                s(json!(r.status.as_str())),
                s(json!(r.wear_rate)),
                s(json!(r.pull_off_force)),
                s(json!(r.log10_pull_off_force)),
                s(json!(r.real_area)),
                constraints,
                r.feasible
            )
        }
    }
}

/// The separator written before a row: `first` is true for the first row of the output.
fn separator(format: Encoding, first: bool) -> &'static str {
    match (format, first) {
        (Encoding::Csv, _) => "",
        (Encoding::Json, true) => "\n",
        (Encoding::Json, false) => ",\n",
    }
}

/// The text written after a row (CSV ends each row with a newline).
fn terminator(format: Encoding) -> &'static str {
    match format {
        Encoding::Csv => "\n",
        Encoding::Json => "",
    }
}

/// One row as written, with its separator.
pub fn row(format: Encoding, sweep: &Sweep, r: &SweepRow, first: bool) -> String {
    format!(
        "{}{}{}",
        separator(format, first),
        row_line(format, sweep, r),
        terminator(format)
    )
}

/// What closes the output after the last row.
pub fn tail(format: Encoding) -> &'static str {
    match format {
        Encoding::Csv => "",
        Encoding::Json => "\n  ]\n}\n",
    }
}

// ---------------------------------------------------------------- reading parts

/// Why parts cannot be joined (bad input).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MergeError {
    /// Neither sweep CSV nor sweep JSON.
    #[error("not the output of `wearopt sweep`: {0}")]
    NotASweep(String),
    /// A part cut short: a JSON part without its closing lines, a CSV part in
    /// the middle of a line (what stops, in words).
    #[error("incomplete: {0} (rerun this shard)")]
    Incomplete(&'static str),
    /// A row line that does not parse.
    #[error("line {line}: not a sweep row")]
    BadRow {
        /// 1-based line number in the part.
        line: usize,
    },
    /// Rows out of order within a part.
    #[error("line {line}: row index {found} after {previous}: rows must be in increasing order")]
    Order {
        /// 1-based line number.
        line: usize,
        /// The index found.
        found: u64,
        /// The index before it.
        previous: u64,
    },
    /// Parts of different sweeps, or of different formats.
    #[error("its head differs from the first part's: parts of different sweeps (problem or scan content, method, seed, samples, version, build or format: see the fingerprint line) cannot be joined")]
    HeadMismatch,
    /// A part whose rows are not its shard's.
    #[error("it is shard {index}/{count} of {samples} designs, rows {start}..{end}, but holds {found}: cut short or not this sweep's part (rerun that shard)")]
    ShardRows {
        /// The shard's index.
        index: u64,
        /// The shard count.
        count: u64,
        /// N.
        samples: u64,
        /// The shard's first row.
        start: u64,
        /// One past its last row.
        end: u64,
        /// What the part holds, in words.
        found: String,
    },
    /// A gap or overlap between parts.
    #[error("rows {expected}..{found} are missing (no part starts at row {expected})")]
    Gap {
        /// The next row expected.
        expected: u64,
        /// The row found instead.
        found: u64,
    },
    /// Two parts with the same rows.
    #[error("row {found} appears twice (is one shard given twice?)")]
    Overlap {
        /// The repeated row.
        found: u64,
    },
    /// More rows than the sweep has (`--samples` below the rows found).
    #[error("the parts hold rows 0..{found}, more than the {expected} designs given (--samples {expected}): give the sweep's own N")]
    Long {
        /// Rows the sweep has.
        expected: u64,
        /// Rows found.
        found: u64,
    },
    /// CSV parts without their fingerprint line, and no `--samples`: nothing says
    /// how many rows the sweep has, so a last part cut on a row boundary would
    /// pass.
    #[error("the parts hold rows 0..{found}, but they lack the `# wearopt sweep` line that gives the sweep's N, so a last part cut short cannot be told from a complete one: give --samples N")]
    UnknownTotal {
        /// Rows found.
        found: u64,
    },
    /// Fewer rows than the sweep has.
    #[error("the parts hold rows 0..{found} of {expected}: rows {found}..{expected} are missing")]
    Short {
        /// Rows the sweep has.
        expected: u64,
        /// Rows found.
        found: u64,
    },
    /// No parts at all.
    #[error("no parts to merge")]
    NoParts,
}

/// One shard's output, parsed.
#[derive(Debug, Clone, PartialEq)]
pub struct Part<'a> {
    /// CSV or JSON.
    pub format: Encoding,
    /// The head as written (CSV: the header line with its newline).
    pub head: &'a str,
    /// Its rows: index and line (without separator, terminator or trailing comma).
    pub rows: Vec<(u64, &'a str)>,
    /// `samples` from the head (JSON, and CSV with a fingerprint line).
    pub samples: Option<u64>,
    /// The shard the head names (None for an output without a fingerprint).
    pub shard: Option<Shard>,
    /// The head with its shard written as the whole sweep's (`0/1`): the same for
    /// every part of one sweep, and the head of the merged output.
    pub sweep_head: String,
}

impl Part<'_> {
    /// True when the part holds exactly the rows of `range`, in order.
    pub fn covers(&self, range: std::ops::Range<u64>) -> bool {
        self.rows.len() as u64 == range.end - range.start
            && self
                .rows
                .iter()
                .zip(range)
                .all(|(&(i, _), expected)| i == expected)
    }
}

fn leading_index(s: &str) -> Option<u64> {
    let digits = s.len() - s.trim_start_matches(|c: char| c.is_ascii_digit()).len();
    s[..digits].parse().ok()
}

/// Parses the output of one `wearopt sweep` run (CSV or JSON).
pub fn parse_part(text: &str) -> Result<Part<'_>, MergeError> {
    // A sweep writes "\n" only; "\r\n" is a conversion on the way (a Windows
    // editor, git's autocrlf), which would otherwise read as another sweep's head.
    if text.contains("\r\n") {
        return Err(MergeError::NotASweep(
            "its lines end in CR LF (\\r\\n), not the LF a sweep writes: the file was converted on the way (a Windows editor, git's autocrlf); convert it back (dos2unix) and merge again".into(),
        ));
    }
    if text.starts_with('{') {
        let open = "  \"rows\": [";
        let at = text.find(open).ok_or_else(|| {
            MergeError::NotASweep("a JSON object without a \"rows\" array".into())
        })?;
        let head = &text[..at + open.len()];
        let samples = head
            .lines()
            .find_map(|l| l.trim().strip_prefix("\"samples\": "))
            .and_then(|v| v.trim_end_matches(',').parse().ok());
        let shard = head
            .lines()
            .find_map(|l| l.trim().strip_prefix("\"shard\": "))
            .and_then(|v| parse_shard(v.trim_end_matches(',').trim_matches('"')));
        let body = &text[at + open.len()..];
        let body = body
            .strip_suffix(tail(Encoding::Json))
            .or_else(|| (body == "\n  ]\n}\n").then_some(""))
            .ok_or(MergeError::Incomplete(
                "the JSON output stops before its closing `]` and `}`",
            ))?;
        let head_lines = head.lines().count();
        let mut rows = Vec::new();
        for (k, line) in body.lines().enumerate().skip(1) {
            let line_no = head_lines + k;
            let line = line.strip_suffix(',').unwrap_or(line);
            let index = line
                .strip_prefix("    {\"index\":")
                .and_then(leading_index)
                .ok_or(MergeError::BadRow { line: line_no })?;
            rows.push((index, line));
        }
        let body_empty = body.is_empty() || body == "\n  ]\n}\n";
        if !body_empty && rows.is_empty() {
            return Err(MergeError::BadRow {
                line: head_lines + 1,
            });
        }
        check_order(&rows, head_lines + 1)?;
        Ok(Part {
            format: Encoding::Json,
            sweep_head: whole_shard(head, shard, "\"shard\": \""),
            head,
            rows,
            samples,
            shard,
        })
    } else {
        // The fingerprint line, if any, then the header line.
        let (print, skip) = match text.strip_prefix("# wearopt sweep ") {
            Some(rest) => {
                let line = rest.split('\n').next().unwrap_or("");
                (Some(line), "# wearopt sweep ".len() + line.len() + 1)
            }
            None => (None, 0),
        };
        let field = |key: &str| {
            print.and_then(|l| {
                l.split(' ')
                    .find_map(|f| f.strip_prefix(key).and_then(|v| v.strip_prefix('=')))
            })
        };
        let samples = field("samples").and_then(|v| v.parse().ok());
        let shard = field("shard").and_then(parse_shard);
        let end = text
            .get(skip..)
            .and_then(|t| t.find('\n'))
            .map(|e| e + skip)
            .ok_or_else(|| {
                MergeError::NotASweep("no header line (the file is empty or has no newline)".into())
            })?;
        let head = &text[..=end];
        let header = &text[skip..=end];
        if !header.starts_with("index,") || !header.trim_end().ends_with(",feasible") {
            return Err(MergeError::NotASweep(
                "the first line is not a sweep CSV header (index,…,feasible)".into(),
            ));
        }
        let body = &text[end + 1..];
        if !body.is_empty() && !body.ends_with('\n') {
            return Err(MergeError::Incomplete(
                "the CSV output stops in the middle of a line",
            ));
        }
        let columns = header.split(',').count();
        let head_lines = head.lines().count();
        let mut rows = Vec::new();
        for (k, line) in body.lines().enumerate() {
            let index = leading_index(line)
                .filter(|_| line.split(',').count() == columns)
                .ok_or(MergeError::BadRow {
                    line: k + head_lines + 1,
                })?;
            rows.push((index, line));
        }
        check_order(&rows, head_lines + 1)?;
        Ok(Part {
            format: Encoding::Csv,
            sweep_head: whole_shard(head, shard, " shard="),
            head,
            rows,
            samples,
            shard,
        })
    }
}

/// `I/N` as a shard.
fn parse_shard(text: &str) -> Option<Shard> {
    let (i, n) = text.split_once('/')?;
    Shard::new(i.parse().ok()?, n.parse().ok()?).ok()
}

/// `head` with the shard after `key` written as `0/1`.
fn whole_shard(head: &str, shard: Option<Shard>, key: &str) -> String {
    match shard {
        Some(s) => head.replacen(
            &format!("{key}{}/{}", s.index, s.count),
            &format!("{key}0/1"),
            1,
        ),
        None => head.to_string(),
    }
}

fn check_order(rows: &[(u64, &str)], first_line: usize) -> Result<(), MergeError> {
    for (k, w) in rows.windows(2).enumerate() {
        if w[1].0 != w[0].0 + 1 {
            return Err(MergeError::Order {
                line: first_line + k + 1,
                found: w[1].0,
                previous: w[0].0,
            });
        }
    }
    Ok(())
}

/// Joins parts in row order, producing the text piece by piece (so a caller can
/// read one part at a time). Feed the parts sorted by their first row
/// ([`sort_key`]); parts without rows may come anywhere.
#[derive(Debug, Clone)]
pub struct Merger {
    format: Encoding,
    head: String,
    samples: Option<u64>,
    next: u64,
}

/// The order in which parts are fed to a [`Merger`]: by first row, empty parts first.
pub fn sort_key(part: &Part) -> Option<u64> {
    part.rows.first().map(|r| r.0)
}

impl Merger {
    /// A merger for parts like `first`; returns it and the head to write.
    pub fn new(first: &Part) -> (Merger, String) {
        let head = first.sweep_head.clone();
        (
            Merger {
                format: first.format,
                head: head.clone(),
                samples: first.samples,
                next: 0,
            },
            head,
        )
    }

    /// The text that `part`'s rows add; checks that it continues the rows so far.
    pub fn push(&mut self, part: &Part) -> Result<String, MergeError> {
        if part.format != self.format || part.sweep_head != self.head {
            return Err(MergeError::HeadMismatch);
        }
        if let (Some(shard), Some(samples)) = (part.shard, part.samples.or(self.samples)) {
            let range = shard.range(samples);
            if !part.covers(range.clone()) {
                let found = match (part.rows.first(), part.rows.last()) {
                    (Some(a), Some(b)) => format!("rows {}..{}", a.0, b.0 + 1),
                    _ => "no rows".to_string(),
                };
                return Err(MergeError::ShardRows {
                    index: shard.index,
                    count: shard.count,
                    samples,
                    start: range.start,
                    end: range.end,
                    found,
                });
            }
        }
        let Some(&(first, _)) = part.rows.first() else {
            return Ok(String::new());
        };
        if first > self.next {
            return Err(MergeError::Gap {
                expected: self.next,
                found: first,
            });
        }
        if first < self.next {
            return Err(MergeError::Overlap { found: first });
        }
        let mut out = String::new();
        for &(_, line) in &part.rows {
            out.push_str(separator(self.format, self.next == 0));
            out.push_str(line);
            out.push_str(terminator(self.format));
            self.next += 1;
        }
        Ok(out)
    }

    /// The closing text; checks that the rows are exactly the sweep's N (the
    /// caller's `samples`, else the heads'; refused when neither gives it).
    pub fn finish(self, samples: Option<u64>) -> Result<String, MergeError> {
        let found = self.next;
        match samples.or(self.samples) {
            Some(expected) if found > expected => return Err(MergeError::Long { expected, found }),
            Some(expected) if found < expected => {
                return Err(MergeError::Short { expected, found })
            }
            Some(_) => {}
            None => return Err(MergeError::UnknownTotal { found }),
        }
        Ok(tail(self.format).to_string())
    }
}

/// Joins whole parts held in memory (any order); `samples` checks the total
/// (JSON parts know it themselves). The error's index names the part at fault.
pub fn merge(texts: &[&str], samples: Option<u64>) -> Result<String, (Option<usize>, MergeError)> {
    let mut parts = texts
        .iter()
        .enumerate()
        .map(|(i, t)| parse_part(t).map(|p| (i, p)).map_err(|e| (Some(i), e)))
        .collect::<Result<Vec<_>, _>>()?;
    parts.sort_by_key(|(i, p)| (sort_key(p), *i));
    let Some((_, first)) = parts.first() else {
        return Err((None, MergeError::NoParts));
    };
    let (mut merger, mut out) = Merger::new(first);
    for (i, p) in &parts {
        out.push_str(&merger.push(p).map_err(|e| (Some(*i), e))?);
    }
    out.push_str(&merger.finish(samples).map_err(|e| (None, e))?);
    Ok(out)
}

// ---------------------------------------------------------------- the map

/// The (wear rate, log10 of the pull-off force, feasible) of each row of a part, for the map.
pub fn map_points(part: &Part) -> Result<Vec<(f64, Option<f64>, bool)>, MergeError> {
    let header = part.head.lines().last().unwrap_or("");
    let columns: Vec<&str> = header.trim_end().split(',').collect();
    let col = |name: &str| columns.iter().position(|c| *c == name);
    let head_lines = part.head.lines().count();
    part.rows
        .iter()
        .enumerate()
        .map(|(k, &(_, line))| {
            let bad = MergeError::BadRow {
                line: head_lines + k + 1,
            };
            match part.format {
                Encoding::Csv => {
                    let cells: Vec<&str> = line.split(',').collect();
                    let get = |name: &str| col(name).and_then(|i| cells.get(i).copied());
                    let wear = get("wear_rate").and_then(|v| v.parse().ok());
                    let pull_off = get("log10_pull_off_force").map(|v| v.parse().ok());
                    let feasible = get("feasible").and_then(|v| v.parse().ok());
                    match (wear, pull_off, feasible) {
                        (Some(w), Some(p), Some(f)) => Ok((w, p, f)),
                        _ => Err(bad),
                    }
                }
                Encoding::Json => {
                    let v: Value = serde_json::from_str(line.trim()).map_err(|_| bad.clone())?;
                    match (v["wear_rate"].as_f64(), v["feasible"].as_bool()) {
                        (Some(w), Some(f)) => Ok((w, v["log10_pull_off_force"].as_f64(), f)),
                        _ => Err(bad),
                    }
                }
            }
        })
        .collect()
}

/// Most points drawn per class; beyond, every k-th design is drawn (the
/// Pareto-optimal ones always), and the legend says so.
pub const MAX_DRAWN: usize = 5000;

/// The map's horizontal axis spans at most this many decades below the largest
/// pull-off force; smaller forces (down to the underflowed 10^-8000 N of a
/// nearly non-adhesive design) are drawn on its left edge.
pub const MAP_DECADES: f64 = 12.0;

/// The map of a sweep: wear rate against pull-off force, feasible and infeasible
/// designs apart, the Pareto-optimal ones marked. `points` are (wear rate, log10
/// of the pull-off force, feasible) by row; `optimal` marks the Pareto-optimal rows.
pub fn map_svg(
    name: &str,
    points: &[(f64, Option<f64>, bool)],
    optimal: &[bool],
    direction: ParetoDirection,
) -> String {
    let top = points
        .iter()
        .filter_map(|p| p.1)
        .filter(|l| l.is_finite())
        .fold(f64::NEG_INFINITY, f64::max);
    let floor = top - MAP_DECADES;
    let lowest = points
        .iter()
        .filter_map(|p| p.1)
        .filter(|l| l.is_finite())
        .fold(f64::INFINITY, f64::min);
    let clamped = lowest < floor;
    // Wear in the tables' unit: the prefix the largest wear rate takes there.
    let (wf, wu) = crate::units::axis_unit_of(points.iter().map(|p| p.0), "m³/m");
    let at = |w: f64, l: f64| (10f64.powf(l.max(floor)), w / wf);
    let class = |want: bool| -> Vec<(f64, f64)> {
        points
            .iter()
            .filter(|p| p.2 == want)
            .filter_map(|&(w, l, _)| l.filter(|l| l.is_finite()).map(|l| at(w, l)))
            .collect()
    };
    let thin = |all: Vec<(f64, f64)>, what: &str, total: usize| -> Series {
        let k = all.len().div_ceil(MAX_DRAWN).max(1);
        let label = if k > 1 {
            format!("{what} ({total}; 1 in {k} drawn)")
        } else {
            format!("{what} ({total})")
        };
        Series::new(label, all.into_iter().step_by(k).collect()).without_line()
    };
    let mut front: Vec<(f64, f64)> = points
        .iter()
        .zip(optimal)
        .filter(|(_, &o)| o)
        .filter_map(|(&(w, l, _), _)| l.filter(|l| l.is_finite()).map(|l| at(w, l)))
        .collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let front_n = front.len();
    let count = |want: bool| points.iter().filter(|p| p.2 == want).count();
    let mut x_label = "pull-off force (N)".to_string();
    if clamped {
        // How many: half a sweep's designs may sit there, one on another.
        let below = points
            .iter()
            .filter_map(|p| p.1)
            .filter(|l| l.is_finite() && *l < floor)
            .count();
        let _ = write!(
            x_label,
            "; {below} of {} below 1e{} N at the left edge",
            points.len(),
            floor.round()
        );
    }
    let title: String = if name.chars().count() > 64 {
        name.chars().take(63).chain(['…']).collect()
    } else {
        name.to_string()
    };
    let mut plot = LinePlot::new(
        format!("{title}: {} designs", points.len()),
        Axis::log(x_label),
        Axis::log("wear rate").with_unit(wu),
    );
    if top.is_finite() {
        plot.x = plot.x.with_range(
            10f64.powf(floor.floor()),
            10f64.powf(top.ceil().max(floor.floor() + 1.0)),
        );
    }
    plot.width = 900.0;
    plot.with_series(
        thin(class(false), "infeasible", count(false))
            .with_marker(Marker::Cross)
            .with_color("#999999"),
    )
    .with_series(
        thin(class(true), "feasible", count(true))
            .with_marker(Marker::Circle)
            .with_color("#0072B2"),
    )
    .with_series(
        Series::new(
            format!(
                "Pareto-optimal ({front_n}): least wear, {} pull-off",
                match direction {
                    ParetoDirection::Low => "least",
                    ParetoDirection::High => "most",
                }
            ),
            front,
        )
        .with_marker(Marker::Diamond)
        .with_color("#D55E00"),
    )
    .to_svg()
}
