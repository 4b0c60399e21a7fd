//! The one set of formats every report is rendered in, and which of them each command
//! renders. A command's accepted subset is a constant beside its renderers (e.g.
//! [`super::eval::FORMATS`]); [`parse`] reads a format name for a command and, for a
//! format it cannot render, says which ones it can.

use std::fmt;

/// A rendering of a report.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// A report for people, on a terminal.
    Text,
    /// One JSON document, SI units, every number the shortest string that round-trips.
    Json,
    /// Comma-separated values with a header row, SI units.
    Csv,
    /// One self-contained HTML page: tables and inline SVG plots, no URL.
    Html,
}

impl Format {
    /// Every format, in the order help lists them.
    pub const ALL: [Format; 4] = [Format::Text, Format::Json, Format::Csv, Format::Html];

    /// The name on the command line: "text", "json", "csv", "html".
    pub fn as_str(self) -> &'static str {
        match self {
            Format::Text => "text",
            Format::Json => "json",
            Format::Csv => "csv",
            Format::Html => "html",
        }
    }

    /// The format of a name (exactly as [`Format::as_str`] writes it).
    pub fn from_name(name: &str) -> Option<Format> {
        Format::ALL.into_iter().find(|f| f.as_str() == name)
    }

    /// What the format is, in a few words (for help).
    pub fn describe(self) -> &'static str {
        match self {
            Format::Text => "a report for people",
            Format::Json => "one JSON document, SI units",
            Format::Csv => "comma-separated values with a header row, SI units",
            Format::Html => "one self-contained HTML page with tables and inline SVG plots",
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A format a command was asked for and cannot give.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FormatError {
    /// A format the command does not render.
    NotRendered {
        /// The command, e.g. "eval".
        command: &'static str,
        /// The format asked for.
        given: Format,
        /// The formats the command renders.
        accepted: &'static [Format],
    },
    /// A name that is no format.
    Unknown {
        /// The command.
        command: &'static str,
        /// The name given.
        given: String,
        /// The formats the command renders.
        accepted: &'static [Format],
    },
}

fn list(formats: &[Format]) -> String {
    formats
        .iter()
        .map(|f| f.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FormatError::NotRendered {
                command,
                given,
                accepted,
            } => write!(
                f,
                "--format {given}: {command} does not write {given}; accepted: {}",
                list(accepted)
            ),
            FormatError::Unknown {
                command,
                given,
                accepted,
            } => write!(
                f,
                "--format {given:?}: not a format; {command} accepts: {}",
                list(accepted)
            ),
        }
    }
}

impl std::error::Error for FormatError {}

/// The format named `name`, if `command` renders it (one of `accepted`).
pub fn parse(
    command: &'static str,
    name: &str,
    accepted: &'static [Format],
) -> Result<Format, FormatError> {
    match Format::from_name(name) {
        Some(f) if accepted.contains(&f) => Ok(f),
        Some(f) => Err(FormatError::NotRendered {
            command,
            given: f,
            accepted,
        }),
        None => Err(FormatError::Unknown {
            command,
            given: name.to_string(),
            accepted,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_refusals_list_the_accepted() {
        for f in Format::ALL {
            assert_eq!(Format::from_name(f.as_str()), Some(f));
        }
        const EVAL: &[Format] = &[Format::Text, Format::Json, Format::Html];
        assert_eq!(parse("eval", "html", EVAL), Ok(Format::Html));
        assert_eq!(
            parse("eval", "csv", EVAL).unwrap_err().to_string(),
            "--format csv: eval does not write csv; accepted: text, json, html"
        );
        assert_eq!(
            parse("eval", "xml", EVAL).unwrap_err().to_string(),
            "--format \"xml\": not a format; eval accepts: text, json, html"
        );
        assert!(parse("eval", "JSON", EVAL).is_err());
    }
}
