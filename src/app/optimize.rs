//! `wearopt optimize`: a design study's optimum, or the ranking of catalogue
//! materials when `[design]` lists them.

use crate::model::{self, EvaluationOptions, LoadCurve};
use crate::optimize::materials::rank_materials;
use crate::problem::{catalogue, Problem};

use super::{study, valid_scene, AppError};

pub use crate::optimize::materials::MaterialRanking;
pub use crate::optimize::{ObserverFactory, OptimizationStatus, Optimum, SqpState, StartObserver};

/// The options of `wearopt optimize`.
#[derive(Default)]
pub struct OptimizeOptions<'a> {
    /// Makes an argmin observer per start (the command line's `--verbose` tables).
    pub observers: Option<ObserverFactory<'a>>,
    /// Also sample the optimum's load–separation curve at this many separations
    /// (what the HTML page draws); `None`: no curve.
    pub load_curve_points: Option<usize>,
}

/// What `wearopt optimize` computes: one optimum, or a ranking when the study's
/// `[design]` lists materials.
#[derive(Debug, Clone)]
pub enum OptimizeDocument {
    /// The optimum of a single study.
    Optimum {
        /// The problem's name.
        name: String,
        /// The optimum.
        optimum: Box<Optimum>,
        /// The optimum's load–separation curve, when asked for.
        load_curve: Option<LoadCurve>,
    },
    /// One study per material, ranked.
    Ranking {
        /// The problem's name.
        name: String,
        /// The ranking.
        ranking: MaterialRanking,
    },
}

impl OptimizeDocument {
    /// Whether the study ended without a usable result (an infeasible optimum, or
    /// no material meeting every constraint): the command line's exit code 1.
    pub fn failed(&self) -> bool {
        match self {
            OptimizeDocument::Optimum { optimum, .. } => {
                optimum.status == OptimizationStatus::Infeasible
            }
            OptimizeDocument::Ranking { ranking, .. } => ranking.best().is_none(),
        }
    }
}

/// Optimises the problem's study (ranks its materials when `[design]` lists
/// them), as `wearopt optimize` does. `origin` names the problem in error messages.
pub fn optimize(
    problem: &Problem,
    origin: &str,
    options: OptimizeOptions,
) -> Result<OptimizeDocument, AppError> {
    valid_scene(problem, origin)?;
    let optimize_error = |error| AppError::Optimize {
        origin: origin.to_string(),
        error,
    };
    if problem.study.materials.is_empty() {
        let optimum = crate::optimize::optimize_observed(&study(problem), options.observers)
            .map_err(optimize_error)?;
        let load_curve = options.load_curve_points.map(|n| {
            model::load_curve(
                &optimum.scene,
                &optimum.evaluation,
                &EvaluationOptions::default(),
                n,
            )
        });
        return Ok(OptimizeDocument::Optimum {
            name: problem.name.clone(),
            optimum: Box::new(optimum),
            load_curve,
        });
    }
    let materials = problem
        .study
        .materials
        .iter()
        .map(|n| {
            catalogue::lookup(n).ok_or_else(|| AppError::UnknownMaterial {
                origin: origin.to_string(),
                name: n.clone(),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    let ranking =
        rank_materials(&study(problem), &materials, options.observers).map_err(optimize_error)?;
    Ok(OptimizeDocument::Ranking {
        name: problem.name.clone(),
        ranking,
    })
}
