//! `wearopt accuracy`: the work–precision of the evaluator and of its
//! finite-difference sensitivities against an independent reference.

use crate::accuracy::{work_precision, Options};
use crate::problem::Problem;

use super::AppError;

pub use crate::accuracy::WorkPrecision;

/// The shipped scenes the report uses when it is given no problem.
const SHIPPED: [(&str, &str); 3] = [
    (
        "problems/micro-gear.toml",
        include_str!("../../problems/micro-gear.toml"),
    ),
    (
        "problems/dlc-contact.toml",
        include_str!("../../problems/dlc-contact.toml"),
    ),
    (
        "problems/gold-switch.toml",
        include_str!("../../problems/gold-switch.toml"),
    ),
];

/// The work–precision report of the problem's scene (its region θ, λ, h and
/// neighbours, loads and sensitivities added to the extreme-range grid), or of
/// the shipped scenes when `problem` is `None`.
pub fn accuracy(problem: Option<&Problem>) -> Result<WorkPrecision, AppError> {
    let scenes = match problem {
        Some(p) => vec![(p.name.clone(), p.scene.clone())],
        None => SHIPPED
            .iter()
            .map(|(origin, text)| crate::problem::parse(text, origin).map(|p| (p.name, p.scene)))
            .collect::<Result<Vec<_>, _>>()?,
    };
    Ok(work_precision(&scenes, Options::default()))
}
