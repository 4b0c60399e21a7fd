//! Rendering results: text reports, JSON, CSV, SVG plots and self-contained HTML
//! pages. Knows nothing of how the numbers were computed; the library's values
//! (warnings, notes, statuses) are worded here and only here. Every number written
//! to JSON or CSV is the shortest string that round-trips the f64 exactly.
//!
//! One module per result type, each with one renderer per [`Format`] it writes and
//! the list of those formats (`FORMATS`, checked by [`format::parse`]):
//! [`eval`], [`optimize`], [`materials`], [`pareto`], [`sweep`], [`accuracy`],
//! [`calibrate`] (fit-adhesion), [`humidity`], [`roughness`], [`contact`], [`curve`], [`figures`]. Shared
//! pieces: [`crate::units`] (SI prefixes and the numbers' text), [`words`] (the library's
//! warnings and notes in words), [`svg`] (line plots and bar charts).

pub mod accuracy;
pub mod asperity;
pub mod calibrate;
pub mod contact;
pub mod curve;
pub mod eval;
pub mod figures;
pub mod fit_wear;
pub mod format;
pub(crate) mod html;
pub mod humidity;
pub mod materials;
pub mod optimize;
pub mod pareto;
pub(crate) mod png;
pub mod robust;
pub mod robust_adhesion_front;
pub mod robust_front;
mod robust_levels;
pub mod roughness;
pub mod svg;
pub mod sweep;
pub mod trace;
pub mod uncertainty;

pub mod words;

/// A JSON value as the command line writes it: pretty-printed, one trailing newline.
pub fn json_text(v: &serde_json::Value) -> String {
    let mut s = serde_json::to_string_pretty(v).unwrap_or_else(|_| "null".to_string());
    s.push('\n');
    s
}

/// The SI unit of an objective.
pub(crate) fn objective_unit(objective: crate::optimize::Objective) -> &'static str {
    objective.quantity().dimension().si_unit()
}

/// Why a scene's wear is exactly zero (its logarithm -∞), in words: no wear
/// coefficient, or only plastic junctions wear and none lies within the Gaussian's
/// reach (the model sets their share to zero, not to a rounded tiny number).
pub(crate) fn zero_wear_reason(sc: &crate::model::Scene) -> &'static str {
    if sc.wear_coefficient == 0.0 {
        "the wear coefficient k is 0"
    } else if sc.wear_area == crate::model::WearArea::Plastic {
        "only plastic junctions wear, and no asperity is tall enough to turn plastic"
    } else {
        "no contact wears"
    }
}

/// Why a scene's wear rate is too small for a double (its logarithm finite, its
/// value 0), in words: the thermally activated law's removal of atoms that slow, or
/// only plastic junctions wearing and those that rare.
pub(crate) fn tiny_wear_reason(sc: &crate::model::Scene) -> &'static str {
    if sc.wear_law == crate::model::WearModel::StressAssisted {
        "the thermally activated removal of atoms is that slow at this temperature, speed and barrier"
    } else if sc.wear_area == crate::model::WearArea::Plastic {
        "only plastic junctions wear, and asperities tall enough to turn plastic are that rare"
    } else {
        "the wearing area and the wear coefficient are that small"
    }
}

/// The dimension of a design variable.
pub(crate) fn design_dimension(p: crate::model::SceneParameter) -> crate::units::Dimension {
    p.dimension()
}

pub use crate::units::{number, si, sig, sig_exp};
pub use format::Format;
