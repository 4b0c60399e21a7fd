//! Progress on a terminal: a bar (or a counter where the total is not known
//! ahead) on stderr that advances as work finishes; nothing where stderr is not
//! a terminal, or NO_COLOR or CI asks for plain output.

use std::io::IsTerminal;

use argmin::core::observers::Observe;
use argmin::core::KV;
use indicatif::{ProgressBar, ProgressStyle};
use wearopt::app::optimize::{SqpState, StartObserver};

/// Whether progress may be drawn.
pub(crate) fn wanted() -> bool {
    std::io::stderr().is_terminal()
        && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
        && std::env::var_os("CI").is_none_or(|v| v.is_empty() || v == "false")
}

/// A bar of `len` pieces labelled `what` (`None`: a counter with no total), or
/// None where no progress is wanted.
pub(crate) fn bar(len: Option<u64>, what: &str) -> Option<ProgressBar> {
    if !wanted() {
        return None;
    }
    let (b, template) = match len {
        Some(n) => (
            ProgressBar::new(n),
            "{msg:>12} [{bar:30}] {pos}/{len} {elapsed}",
        ),
        None => (
            ProgressBar::new_spinner(),
            "{spinner} {pos} {msg} {elapsed}",
        ),
    };
    b.set_style(
        ProgressStyle::with_template(template)
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    b.set_message(what.to_string());
    Some(b)
}

/// Drives a bar from the application layer's [`wearopt::app::Progress`].
pub(crate) struct Bar(pub Option<ProgressBar>);

impl wearopt::app::Progress for Bar {
    fn begin(&self, total: usize) {
        if let Some(b) = &self.0 {
            b.set_length(total as u64);
        }
    }

    fn advance(&self) {
        if let Some(b) = &self.0 {
            b.inc(1);
        }
    }
}

impl Drop for Bar {
    fn drop(&mut self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}

/// A start's observer that counts the start on the bar when it ends (argmin
/// drops the observer then), passing everything on to `inner` (`--verbose`).
pub(crate) struct Ticking {
    pub inner: Option<StartObserver>,
    pub bar: Option<ProgressBar>,
}

impl Drop for Ticking {
    fn drop(&mut self) {
        if let Some(b) = &self.bar {
            b.inc(1);
        }
    }
}

impl Observe<SqpState> for Ticking {
    fn observe_init(
        &mut self,
        name: &str,
        state: &SqpState,
        kv: &KV,
    ) -> Result<(), argmin::core::Error> {
        match &mut self.inner {
            Some(o) => o.observe_init(name, state, kv),
            None => Ok(()),
        }
    }

    fn observe_iter(&mut self, state: &SqpState, kv: &KV) -> Result<(), argmin::core::Error> {
        match &mut self.inner {
            Some(o) => o.observe_iter(state, kv),
            None => Ok(()),
        }
    }
}
