//! `wearopt optimize`: a design study's optimum, or the ranking of catalogue
//! materials when `[design]` lists them.

use crate::model::{self, EvaluationOptions, LoadCurve};
use crate::optimize::functions::quantity_value;
use crate::optimize::materials::rank_materials;
use crate::optimize::{ConstraintQuantity, Side, FEASIBILITY_TOLERANCE};
use crate::problem::{catalogue, Problem};

use super::{study, valid_scene, AppError};

pub use super::robust::RobustOutcome;
pub use crate::optimize::materials::MaterialRanking;
pub use crate::optimize::{ObserverFactory, OptimizationStatus, Optimum, SqpState, StartObserver};

/// A constraint the baseline design breaks.
#[derive(Debug, Clone, PartialEq)]
pub struct BaselineViolation {
    /// The constrained quantity.
    pub quantity: ConstraintQuantity,
    /// Its value at the baseline (SI); None where it does not exist there.
    pub value: Option<f64>,
    /// The limit it breaks (SI).
    pub limit: f64,
    /// Which limit.
    pub side: Side,
}

/// The constraints the baseline (the problem file's scene at its baseline design)
/// breaks by more than the optimiser's feasibility tolerance, relative to the limit
/// ([`crate::optimize::FEASIBILITY_TOLERANCE`]: what its scaled rows allow).
fn baseline_violations(o: &Optimum) -> Vec<BaselineViolation> {
    let Some(ev) = &o.baseline_evaluation else {
        return Vec::new();
    };
    let mut scene = o.scene.clone();
    for (q, v) in o.names.iter().zip(&o.baseline_design) {
        q.set(&mut scene, *v);
    }
    let tol = |limit: f64| FEASIBILITY_TOLERANCE * limit.abs().max(f64::MIN_POSITIVE);
    let mut out = Vec::new();
    for c in &o.constraints {
        let q = c.quantity;
        let value = quantity_value(q, ev, &scene);
        for (side, limit, breaks) in [
            (
                Side::Min,
                c.min,
                value.is_none_or(|v| c.min.is_some_and(|m| v < m - tol(m))),
            ),
            (
                Side::Max,
                c.max,
                value.is_none_or(|v| c.max.is_some_and(|m| v > m + tol(m))),
            ),
        ] {
            if let (Some(limit), true) = (limit, breaks) {
                out.push(BaselineViolation {
                    quantity: q,
                    value,
                    limit,
                    side,
                });
            }
        }
    }
    out
}

/// The study's asperity law used, at the optimum, outside the Tabor parameters
/// φ0 where it is exact (docs/model.md §2 and §11: JKR for φ0 ≥ 3, DMT for φ0 ≤ 0.3;
/// the Lennard-Jones law holds at every φ0). The optimum is still the optimum of the
/// model the file states (the status stays, and so does exit code 0), but its
/// adhesion numbers (the pull-off above all) may be far from the truth: the reports
/// say so on the status line, with the edit that re-runs the study under the law
/// that holds. Held by `tests/all/law_regime.rs`.
#[derive(Debug, Clone, PartialEq)]
pub struct LawOutsideRegime {
    /// The study's law.
    pub law: model::AdhesionModel,
    /// φ0 at the optimum.
    pub tabor_parameter: f64,
    /// The φ0 over which `law` is exact (closed ends; the upper may be ∞).
    pub valid_tabor: (f64, f64),
    /// The law that holds at every φ0 (the Lennard-Jones sphere).
    pub law_that_holds: model::AdhesionModel,
    /// The problem file (as given), for the command that re-runs it.
    pub origin: String,
}

/// The optimum's law outside its regime, if it is: read from the evaluation's
/// own regime warning (the one "Warnings at the optimum" words), so the two never
/// disagree.
pub fn law_outside_regime(o: &Optimum, origin: &str) -> Option<LawOutsideRegime> {
    use crate::model::Warning;
    let tabor_parameter = o.evaluation.warnings.iter().find_map(|w| match w {
        Warning::OutsideJkrRegime { tabor_parameter }
        | Warning::OutsideDmtRegime { tabor_parameter } => Some(*tabor_parameter),
        _ => None,
    })?;
    let law = o.scene.adhesion_model;
    let law_that_holds = model::AdhesionModel::ALL
        .into_iter()
        .find(|m| m.law().general())?;
    Some(LawOutsideRegime {
        law,
        tabor_parameter,
        valid_tabor: law.valid_tabor(),
        law_that_holds,
        origin: origin.to_string(),
    })
}

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
        /// The constraints the baseline design (the problem file's scene) breaks.
        baseline_violations: Vec<BaselineViolation>,
        /// The optimum's load–separation curve, when asked for.
        load_curve: Option<LoadCurve>,
        /// A robust study's optimum (a statistic objective or chance
        /// constraints), beside the nominal `optimum`.
        robust: Option<Box<RobustOutcome>>,
        /// The law used outside its regime at the optimum, if it is.
        law_regime: Option<LawOutsideRegime>,
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
            OptimizeDocument::Optimum {
                optimum, robust, ..
            } => match robust {
                Some(r) => r.failed(),
                None => optimum.status == OptimizationStatus::Infeasible,
            },
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
        let deadline = std::time::Instant::now() + problem.study.optimizer.time_limit;
        // A robust study's nominal twin holds each chance constraint's event
        // off at the nominal inputs (app::robust::nominal_counterparts).
        let mut constraints = problem.study.constraints.clone();
        constraints.extend(super::robust::nominal_counterparts(problem));
        let nominal_study = crate::optimize::Study {
            constraints: &constraints,
            ..study(problem)
        };
        let optimum = crate::optimize::optimize_observed(&nominal_study, options.observers)
            .map_err(optimize_error)?;
        let robust = problem
            .robust
            .is_robust()
            .then(|| super::robust::robust(problem, &optimum, deadline))
            .flatten()
            .map(Box::new);
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
            law_regime: law_outside_regime(&optimum, origin),
            baseline_violations: baseline_violations(&optimum),
            optimum: Box::new(optimum),
            load_curve,
            robust,
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
