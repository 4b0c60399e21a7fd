//! The application layer: one function per command, typed options in, a typed
//! document out.
//!
//! `wearopt eval`, `optimize` (a ranking too, when `[design]` lists materials),
//! `pareto`, `curve`, `figures`, `accuracy`, `fit-adhesion`, `roughness`, `contact`, `sweep`
//! and `merge` each have a function here. The command line (`src/cli/`) and the
//! Python package (`python/`) are adapters: they turn flags or keyword arguments
//! into these options, call one function, hand the document to the report stage
//! ([`crate::report`], one `render` per document and format) and word errors in
//! their own vocabulary ([`AppError::message`] with [`Vocabulary::Flags`] or
//! [`Vocabulary::Keywords`]). Neither imports `model`, `optimize` or `sweep`: what
//! they need of them is re-exported here. Their results agree by construction.
//!
//! Errors are bad input, each naming the input (the file as the caller names it),
//! the field or option, the value and what is accepted. Outcomes (separated,
//! infeasible, not converged) are statuses inside the documents, never errors.

pub mod accuracy;
pub mod asperity;
pub mod contact;
pub mod curve;
pub mod eval;
pub mod figures;
pub mod fit_adhesion;
pub mod fit_wear;
pub mod humidity;
pub mod optimize;
pub mod pareto;
pub mod quantity;
pub mod robust;
pub mod robust_adhesion_front;
pub mod robust_front;
pub mod roughness;
pub mod sweep;
pub mod uncertainty;

mod error;
mod scan_contact;

pub use error::{AppError, OptionName, Vocabulary};

pub use crate::problem::{Problem, ProblemError};

/// Reads and validates a problem file ([`crate::problem::load`]), then fulfils what
/// it asks of the application layer ([`contact::fulfil`]: the exact contact on its
/// scan under `contact_model = "bem_corrected"`). What every command loads.
pub fn load(path: &std::path::Path) -> Result<Problem, ProblemError> {
    contact::fulfil(crate::problem::load(path)?)
}

/// Parses and validates problem-file text ([`crate::problem::parse`]; `origin` names
/// it in messages), then fulfils it as [`load`] does.
pub fn parse(text: &str, origin: &str) -> Result<Problem, ProblemError> {
    contact::fulfil(crate::problem::parse(text, origin)?)
}

use crate::optimize::Study;

/// Receives a long command's progress as its work finishes (the command line
/// draws a bar from it on a terminal). Every method does nothing by default.
pub trait Progress: Sync {
    /// `total` pieces of work are ahead (called again when a stage adds some).
    fn begin(&self, _total: usize) {}
    /// One piece finished.
    fn advance(&self) {}
}

/// A [`Progress`] that ignores everything.
pub struct Quiet;
impl Progress for Quiet {}

/// The problem's scene, checked ([`crate::model::Scene::validate`]).
fn valid_scene(problem: &Problem, origin: &str) -> Result<(), AppError> {
    problem.scene.validate().map_err(|error| AppError::Scene {
        origin: origin.to_string(),
        error,
    })
}

/// The optimiser's view of a problem's study (what every study command runs).
pub fn study(problem: &Problem) -> Study<'_> {
    Study {
        scene: &problem.scene,
        design: &problem.study.design,
        objective: problem.study.objective,
        constraints: &problem.study.constraints,
        settings: &problem.study.optimizer,
    }
}
