//! `--verbose`: an iteration table per start of the multistart, collected by
//! argmin observers while the starts run in parallel and printed to stderr in
//! start order afterwards, so that tables are never interleaved.

use std::sync::{Arc, Mutex};

use argmin::core::observers::Observe;
use argmin::core::{State, KV};
use wearopt::app::optimize::{SqpState, StartObserver};

/// Finished tables, by start index.
#[derive(Default, Clone)]
pub struct Tables(Arc<Mutex<Vec<(usize, String)>>>);

struct Table {
    start: usize,
    text: String,
    sink: Tables,
}

impl Drop for Table {
    fn drop(&mut self) {
        let text = std::mem::take(&mut self.text);
        let mut v = self.sink.0.lock().unwrap_or_else(|e| e.into_inner());
        v.push((self.start, text));
    }
}

impl Observe<SqpState> for Table {
    fn observe_init(
        &mut self,
        name: &str,
        _state: &SqpState,
        _kv: &KV,
    ) -> Result<(), argmin::core::Error> {
        self.text
            .push_str(&format!("start {:>3}: {name}\n", self.start));
        self.text.push_str(
            "start iter        objective    violation          KKT       radius         step        ratio  evaluations\n",
        );
        Ok(())
    }

    fn observe_iter(&mut self, state: &SqpState, kv: &KV) -> Result<(), argmin::core::Error> {
        let get = |k: &str| kv.get(k).and_then(|v| v.get_float()).unwrap_or(f64::NAN);
        self.text.push_str(&format!(
            "{:>5} {:>4} {:>16.10} {:>12.3e} {:>12.3e} {:>12.3e} {:>12.3e} {:>12.3e} {:>12}\n",
            self.start,
            state.get_iter(),
            get("objective"),
            get("violation"),
            get("kkt"),
            get("radius"),
            get("step"),
            get("ratio"),
            get("evaluations") as u64
        ));
        Ok(())
    }
}

impl Tables {
    /// The observer of start `start`.
    pub fn observer(&self, start: usize) -> StartObserver {
        Box::new(Table {
            start,
            text: String::new(),
            sink: self.clone(),
        })
    }

    /// Prints every table to stderr, in start order.
    pub fn print(&self) {
        let mut v = std::mem::take(&mut *self.0.lock().unwrap_or_else(|e| e.into_inner()));
        v.sort_by_key(|(s, _)| *s);
        for (_, t) in v {
            eprint!("{t}");
        }
    }
}
