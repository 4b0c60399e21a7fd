//! `--format` for every command: the report stage's one [`Format`], read through a
//! parser that knows the command's accepted subset, so that help lists exactly what
//! the command writes and a format it cannot write is refused (exit code 2) with the
//! accepted ones named.

use std::ffi::OsStr;

use clap::builder::{PossibleValue, TypedValueParser};
use clap::error::ErrorKind;

use wearopt::report::format::{parse, Format};

/// The `--format` parser of one command.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Formats {
    command: &'static str,
    accepted: &'static [Format],
}

/// The parser for `command`, which renders the formats in `accepted`.
pub(crate) fn formats(command: &'static str, accepted: &'static [Format]) -> Formats {
    Formats { command, accepted }
}

impl TypedValueParser for Formats {
    type Value = Format;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        _arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<Format, clap::Error> {
        let name = value.to_string_lossy();
        parse(self.command, &name, self.accepted)
            .map_err(|e| clap::Error::raw(ErrorKind::InvalidValue, format!("{e}\n")).with_cmd(cmd))
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(
            self.accepted
                .iter()
                .map(|f| PossibleValue::new(f.as_str()).help(f.describe())),
        ))
    }
}

/// The usage error (exit code 2) for a format that reached a command not rendering it
/// (the parser refuses it first; this keeps every match total without a panic).
pub(crate) fn refuse(
    command: &'static str,
    given: Format,
    accepted: &'static [Format],
) -> anyhow::Error {
    super::usage(
        wearopt::report::format::FormatError::NotRendered {
            command,
            given,
            accepted,
        }
        .to_string(),
    )
}
