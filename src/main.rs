//! `wearopt`: the command line's thin entry point. It parses the arguments with clap
//! and hands them to `cli/` (one module per command, `cli/mod.rs` the dispatcher),
//! which calls the application layer (`wearopt::app`) and the report stage; exit
//! codes: 0 success, 1 a result that is no answer (infeasible, not converged), 2 bad
//! input.

mod cli;

use std::process::ExitCode;

use clap::error::ErrorKind;
use clap::Parser;

fn main() -> ExitCode {
    let args = match cli::Cli::try_parse() {
        Ok(args) => args,
        // Help and version are not errors: clap prints them and exits 0.
        Err(err)
            if matches!(
                err.kind(),
                ErrorKind::DisplayHelp
                    | ErrorKind::DisplayVersion
                    | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            ) =>
        {
            err.exit()
        }
        // A usage error in the spelling of every other error ("Error:", not clap's
        // "error:"), exit code 2.
        Err(err) => {
            let text = err.render().to_string();
            eprint!("{}", usage_error(&text));
            return ExitCode::from(2);
        }
    };
    match cli::run(args) {
        Ok(code) => code,
        Err(err) => {
            eprintln!("Error: {err:#}");
            ExitCode::from(cli::exit_code(&err))
        }
    }
}

/// clap's rendering of a usage error with its "error:" spelled "Error:".
fn usage_error(text: &str) -> String {
    match text.strip_prefix("error:") {
        Some(rest) => format!("Error:{rest}"),
        None => text.to_string(),
    }
}
