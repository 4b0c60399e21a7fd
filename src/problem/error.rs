//! Errors in problem files, and the helpers that make them precise: byte offsets to
//! line numbers, and "did you mean" suggestions by edit distance.

use std::fmt;

/// Where in which file: `problems/x.toml:7`, or just the file when no line applies.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The file name as given to [`super::load`] or [`super::parse`].
    pub origin: String,
    /// 1-based line number, when the error belongs to a line.
    pub line: Option<usize>,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(line) => write!(f, "{}:{}", self.origin, line),
            None => f.write_str(&self.origin),
        }
    }
}

/// A problem file that cannot be used, and why.
///
/// Every message is one line that names the file, the line (where there is one), the
/// dotted field (`contact.load`), the value as written and what would be accepted. A
/// program maps all of these to exit code 2 ([`ProblemError::exit_code`]).
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ProblemError {
    /// The file could not be read.
    #[error("{path}: cannot read the file: {io}")]
    Io {
        /// The path as given.
        path: String,
        /// The underlying error (its text is part of this message).
        io: std::io::Error,
    },
    /// The file is not UTF-8 text.
    #[error("{at}: the file is not valid UTF-8 (first bad byte at byte offset {byte}); save it as UTF-8 text")]
    NotUtf8 {
        /// File and line of the first bad byte.
        at: Location,
        /// Byte offset of the first bad byte.
        byte: usize,
    },
    /// Nothing but whitespace and comments.
    #[error("{at}: the file is empty; a problem needs the tables [contact], [bodies], [interface] and [roughness] (see problems/micro-gear.toml)")]
    Empty {
        /// The file.
        at: Location,
    },
    /// Not valid TOML.
    #[error("{at}: TOML syntax error: {message}")]
    Syntax {
        /// File and line.
        at: Location,
        /// The parser's description.
        message: String,
    },
    /// A key that the schema does not have.
    #[error("{at}: unknown key `{key}`{} (valid keys: {})",
        .suggestion.as_ref().map(|s| format!("; did you mean `{s}`?")).unwrap_or_default(),
        .valid.join(", "))]
    UnknownKey {
        /// File and line.
        at: Location,
        /// The dotted key as written: `contact.lod`.
        key: String,
        /// The nearest valid key of that table, if one is close.
        suggestion: Option<String>,
        /// Every valid key of that table.
        valid: Vec<String>,
    },
    /// A required key or table is absent.
    #[error("{at}: missing {key}: {hint}")]
    MissingKey {
        /// File and line of the table that lacks it.
        at: Location,
        /// The dotted key: `contact.load`, or a table: `[roughness]`.
        key: String,
        /// What it is and an example.
        hint: String,
    },
    /// A value of the wrong TOML type (a boolean for a number, ...).
    #[error("{at}: {key} = {value}: wrong type: {message}")]
    WrongType {
        /// File and line.
        at: Location,
        /// The dotted key.
        key: String,
        /// The value as written.
        value: String,
        /// What was found and what was expected.
        message: String,
    },
    /// A value of the right type that is not acceptable: a bad unit, out of range, an
    /// unknown material, a bound that does not contain the scene's value, ...
    #[error("{at}: {key} = {value}: {reason}")]
    InvalidValue {
        /// File and line.
        at: Location,
        /// The dotted key.
        key: String,
        /// The value as written.
        value: String,
        /// Why it is refused and what would be accepted.
        reason: String,
    },
}

impl ProblemError {
    /// The process exit code for bad input: always 2 (0 ok, 1 no usable result).
    pub fn exit_code(&self) -> i32 {
        2
    }

    /// The file (or path) the error is about.
    pub fn origin(&self) -> &str {
        match self {
            ProblemError::Io { path, .. } => path,
            ProblemError::NotUtf8 { at, .. }
            | ProblemError::Empty { at }
            | ProblemError::Syntax { at, .. }
            | ProblemError::UnknownKey { at, .. }
            | ProblemError::MissingKey { at, .. }
            | ProblemError::WrongType { at, .. }
            | ProblemError::InvalidValue { at, .. } => &at.origin,
        }
    }

    /// The 1-based line the error is on, when it has one.
    pub fn line(&self) -> Option<usize> {
        match self {
            ProblemError::Io { .. } => None,
            ProblemError::NotUtf8 { at, .. }
            | ProblemError::Empty { at }
            | ProblemError::Syntax { at, .. }
            | ProblemError::UnknownKey { at, .. }
            | ProblemError::MissingKey { at, .. }
            | ProblemError::WrongType { at, .. }
            | ProblemError::InvalidValue { at, .. } => at.line,
        }
    }

    /// The dotted key the error is about, when it is about one.
    pub fn key(&self) -> Option<&str> {
        match self {
            ProblemError::UnknownKey { key, .. }
            | ProblemError::MissingKey { key, .. }
            | ProblemError::WrongType { key, .. }
            | ProblemError::InvalidValue { key, .. } => Some(key),
            _ => None,
        }
    }
}

/// 1-based line number of a byte offset in `text`.
pub(crate) fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Optimal-string-alignment edit distance: insertions, deletions, substitutions and
/// transpositions of neighbours each cost 1 (`lod` → `load` is 1, `laod` → `load` is 1).
pub fn edit_distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let (n, m) = (a.len(), b.len());
    let mut d = vec![vec![0usize; m + 1]; n + 1];
    for (i, row) in d.iter_mut().enumerate() {
        row[0] = i;
    }
    for (j, cell) in d[0].iter_mut().enumerate() {
        *cell = j;
    }
    for i in 1..=n {
        for j in 1..=m {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut best = (d[i - 1][j] + 1)
                .min(d[i][j - 1] + 1)
                .min(d[i - 1][j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                best = best.min(d[i - 2][j - 2] + 1);
            }
            d[i][j] = best;
        }
    }
    d[n][m]
}

/// Whether a word of `len` characters at edit distance `distance` from a candidate is a
/// plausible typo of it: at most 2 edits, or a third of the word for long words, and
/// never the whole word.
pub(crate) fn close_enough(distance: usize, len: usize) -> bool {
    distance < len && distance <= 2.max(len / 3)
}

/// The candidate nearest to `word`, if it is close enough to be a typo. Ties go to the
/// first candidate.
pub fn suggest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let lower = word.to_lowercase();
    let mut best: Option<(usize, &'a str)> = None;
    for candidate in candidates {
        let d = edit_distance(&lower, &candidate.to_lowercase());
        if best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, candidate));
        }
    }
    best.filter(|&(d, _)| close_enough(d, word.chars().count()))
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances() {
        assert_eq!(edit_distance("", ""), 0);
        assert_eq!(edit_distance("load", "load"), 0);
        assert_eq!(edit_distance("lod", "load"), 1);
        assert_eq!(edit_distance("laod", "load"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("", "abc"), 3);
        assert_eq!(edit_distance("µm", "um"), 1);
    }

    #[test]
    fn suggestions() {
        let keys = [
            "load",
            "nominal_area",
            "sliding_distance",
            "wear_coefficient",
            "wear_area",
        ];
        assert_eq!(suggest("lod", keys), Some("load"));
        assert_eq!(suggest("Load", keys), Some("load"));
        assert_eq!(suggest("nominal_aera", keys), Some("nominal_area"));
        assert_eq!(suggest("wear_coeficient", keys), Some("wear_coefficient"));
        assert_eq!(suggest("weararea", keys), Some("wear_area"));
        assert_eq!(suggest("sliding", keys), None);
        assert_eq!(suggest("xyz", keys), None);
        assert_eq!(suggest("q", keys), None);
        assert_eq!(suggest("anything", std::iter::empty()), None);
        let rough = ["sigma", "asperity_radius", "asperity_density"];
        assert_eq!(suggest("sigam", rough), Some("sigma"));
        assert_eq!(suggest("asperity_radus", rough), Some("asperity_radius"));
        assert_eq!(suggest("asperity_densty", rough), Some("asperity_density"));
    }

    #[test]
    fn lines() {
        let text = "a = 1\nb = 2\n\nc = 3";
        assert_eq!(line_of(text, 0), 1);
        assert_eq!(line_of(text, 6), 2);
        assert_eq!(line_of(text, text.find('c').unwrap()), 4);
        assert_eq!(line_of(text, 10_000), 4);
    }

    #[test]
    fn message_shapes() {
        let at = Location {
            origin: "problems/x.toml".into(),
            line: Some(12),
        };
        let e = ProblemError::UnknownKey {
            at: at.clone(),
            key: "contact.lod".into(),
            suggestion: Some("load".into()),
            valid: vec!["load".into(), "nominal_area".into()],
        };
        assert_eq!(
            e.to_string(),
            "problems/x.toml:12: unknown key `contact.lod`; did you mean `load`? (valid keys: load, nominal_area)"
        );
        assert_eq!(e.exit_code(), 2);
        assert_eq!(e.line(), Some(12));
        assert_eq!(e.key(), Some("contact.lod"));
        let e = ProblemError::Empty {
            at: Location {
                origin: "e.toml".into(),
                line: None,
            },
        };
        assert!(e.to_string().starts_with("e.toml: the file is empty"));
    }
}
