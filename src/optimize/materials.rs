//! Discrete material choice: `[design] materials = [...]` runs the continuous study
//! once per catalogue material of body a (a coating or film) and ranks the results.
//!
//! # How a material enters its study ([`material_case`])
//!
//! * Body a takes the material's E and ν, and the scene's hardness H becomes the
//!   material's (the model's H is that of the rough, softer body a: a counterface
//!   softer than the coating is outside what the ranking models). Body b is unchanged.
//! * Design variables on `youngs_modulus`, `poisson_ratio` or `hardness` are dropped:
//!   the material fixes them (a note says so).
//! * A `work_of_adhesion` design variable keeps the file's bounds **intersected** with
//!   the material's typical γ range: the file says what surface treatments can reach,
//!   the catalogue what is plausible for that material. When the two do not overlap the
//!   material is excluded (status `excluded`, with the reason). The baseline γ is
//!   clamped into the intersection.
//! * Without a `work_of_adhesion` variable the file's γ is kept (the catalogue never
//!   supplies γ to a scene); a note says when it lies outside the material's range.
//! * When no continuous variable is left, the material's scene is evaluated and its
//!   constraints checked (status `evaluated` or `infeasible`).
//!
//! The studies run in parallel with rayon; each is the deterministic multistart of
//! [`super::optimize`], so the ranking does not depend on the thread count.
//!
//! # Ranking
//!
//! Materials with a feasible result (every status except `infeasible`, `excluded` and
//! `no_contact`) come first, by objective value (ties in list order), then the others
//! in list order.

use rayon::prelude::*;
use serde::Serialize;

use super::functions::{objective_value, quantity_value};
use super::study::{Constraint, ConstraintQuantity, DesignVariable, Objective, SceneParameter};
use super::{OptimizationStatus, OptimizeError, Optimum, Study};
use crate::model::Material;
use crate::model::{evaluate, Evaluation, EvaluationOptions, Scene, Status};

/// Relative slack when checking a constraint at a fixed design.
const CONSTRAINT_SLACK: f64 = 1e-9;

/// The study of one material, ready to run.
#[derive(Debug, Clone, PartialEq)]
pub struct MaterialCase {
    /// The catalogue material.
    pub material: &'static Material,
    /// The baseline scene with body a made of the material.
    pub scene: Scene,
    /// The design variables that remain, with γ bounds intersected.
    pub design: Vec<DesignVariable>,
    /// Why the material cannot be studied, if it cannot.
    pub excluded: Option<Exclusion>,
    /// What was changed, or kept and worth knowing (the report words them).
    pub notes: Vec<MaterialNote>,
}

/// Why a material cannot be studied (values in SI; the report words them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Exclusion {
    /// The study's γ bounds and the material's typical γ range do not overlap.
    GammaRangesDisjoint {
        /// The study's γ bounds (J/m²).
        study: (f64, f64),
        /// The material's typical γ range (J/m²).
        typical: (f64, f64),
    },
}

/// What entering a material changed in its study, or kept and is worth knowing
/// (values in SI; the report words them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MaterialNote {
    /// A design variable the material fixes was dropped from the design.
    VariableFixed {
        /// The dropped variable.
        variable: SceneParameter,
        /// Its value with the material (SI).
        value: f64,
    },
    /// The γ bounds became the study's intersected with the material's typical range.
    GammaBoundsIntersected {
        /// Lower bound (J/m²).
        min: f64,
        /// Upper bound (J/m²).
        max: f64,
    },
    /// The baseline γ was clamped into the intersected bounds.
    BaselineGammaMoved {
        /// The file's baseline γ (J/m²).
        from: f64,
        /// The baseline used (J/m²).
        to: f64,
    },
    /// The file's γ (no γ design variable) lies outside the material's typical range.
    GammaOutsideTypical {
        /// The file's γ (J/m²).
        value: f64,
        /// The material's typical γ range (J/m²).
        typical: (f64, f64),
    },
}

/// Builds the study of `material` from the file's study (see the module docs).
pub fn material_case(study: &Study, material: &'static Material) -> MaterialCase {
    let mut scene = study.scene.clone();
    scene.youngs_modulus_a = material.youngs_modulus;
    scene.poisson_ratio_a = material.poisson_ratio;
    scene.hardness = material.hardness;
    let mut notes = Vec::new();
    let mut design = Vec::new();
    let mut excluded = None;
    let (lo, hi) = material.work_of_adhesion;
    for v in study.design {
        match v.name {
            SceneParameter::YoungsModulus
            | SceneParameter::YoungsModulusA
            | SceneParameter::PoissonRatio
            | SceneParameter::Hardness => {
                notes.push(MaterialNote::VariableFixed {
                    variable: v.name,
                    value: v.name.get(&scene),
                });
            }
            SceneParameter::WorkOfAdhesion => {
                let (min, max) = (v.min.max(lo), v.max.min(hi));
                if min >= max {
                    excluded = Some(Exclusion::GammaRangesDisjoint {
                        study: (v.min, v.max),
                        typical: (lo, hi),
                    });
                    continue;
                }
                if (min, max) != (v.min, v.max) {
                    notes.push(MaterialNote::GammaBoundsIntersected { min, max });
                }
                let g = scene.work_of_adhesion.clamp(min, max);
                if g != scene.work_of_adhesion {
                    notes.push(MaterialNote::BaselineGammaMoved {
                        from: scene.work_of_adhesion,
                        to: g,
                    });
                    scene.work_of_adhesion = g;
                }
                design.push(DesignVariable { min, max, ..*v });
            }
            _ => design.push(*v),
        }
    }
    if !study
        .design
        .iter()
        .any(|v| v.name == SceneParameter::WorkOfAdhesion)
        && scene.work_of_adhesion > 0.0
        && !(lo..=hi).contains(&scene.work_of_adhesion)
    {
        notes.push(MaterialNote::GammaOutsideTypical {
            value: scene.work_of_adhesion,
            typical: (lo, hi),
        });
    }
    MaterialCase {
        material,
        scene,
        design,
        excluded,
        notes,
    }
}

/// How one material's study ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MaterialStatus {
    /// The optimiser's status (see [`OptimizationStatus`]).
    Optimized(OptimizationStatus),
    /// No continuous variable: the scene was evaluated and meets every constraint.
    Evaluated,
    /// No continuous variable, and the scene violates a constraint.
    Violated,
    /// The material could not be studied (γ ranges do not overlap).
    Excluded,
    /// No design put the surfaces in contact.
    NoContact,
}

impl MaterialStatus {
    /// The status word.
    pub fn as_str(self) -> &'static str {
        match self {
            MaterialStatus::Optimized(s) => s.as_str(),
            MaterialStatus::Evaluated => "evaluated",
            MaterialStatus::Violated => "infeasible",
            MaterialStatus::Excluded => "excluded",
            MaterialStatus::NoContact => "no_contact",
        }
    }

    /// Whether the result meets every constraint (and so is ranked).
    pub fn is_usable(self) -> bool {
        match self {
            MaterialStatus::Optimized(s) => s != OptimizationStatus::Infeasible,
            MaterialStatus::Evaluated => true,
            _ => false,
        }
    }
}

/// One constraint at a fixed design (no optimiser ran).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FixedConstraint {
    /// The quantity.
    pub quantity: ConstraintQuantity,
    /// Its value (SI).
    pub value: Option<f64>,
    /// Lower limit.
    pub min: Option<f64>,
    /// Upper limit.
    pub max: Option<f64>,
    /// Whether the value is within its limits.
    pub satisfied: bool,
}

/// What one material gave.
#[derive(Debug, Clone)]
pub enum MaterialOutcome {
    /// The continuous study ran.
    Optimized(Box<Optimum>),
    /// Nothing left to optimise: the scene evaluated.
    Evaluated {
        /// The evaluation.
        evaluation: Box<Evaluation>,
        /// The objective's value.
        objective: f64,
        /// The constraints.
        constraints: Vec<FixedConstraint>,
    },
    /// Not studied.
    Excluded,
    /// The optimiser found no contact.
    NoContact(String),
}

/// One row of the ranking.
#[derive(Debug, Clone)]
pub struct MaterialResult {
    /// 1-based rank among usable results; None for the others.
    pub rank: Option<usize>,
    /// The case studied.
    pub case: MaterialCase,
    /// How it ended.
    pub status: MaterialStatus,
    /// The result.
    pub outcome: MaterialOutcome,
}

impl MaterialResult {
    /// The material's canonical name.
    pub fn name(&self) -> &'static str {
        self.case.material.name
    }

    /// The objective at the reported design.
    pub fn objective(&self) -> Option<f64> {
        match &self.outcome {
            MaterialOutcome::Optimized(o) => Some(o.objective),
            MaterialOutcome::Evaluated { objective, .. } => Some(*objective),
            _ => None,
        }
    }

    /// The evaluation at the reported design.
    pub fn evaluation(&self) -> Option<&Evaluation> {
        match &self.outcome {
            MaterialOutcome::Optimized(o) => Some(&o.evaluation),
            MaterialOutcome::Evaluated { evaluation, .. } => Some(evaluation),
            _ => None,
        }
    }

    /// The scene at the reported design (the baseline when nothing ran).
    pub fn scene(&self) -> &Scene {
        match &self.outcome {
            MaterialOutcome::Optimized(o) => &o.scene,
            _ => &self.case.scene,
        }
    }

    /// The wear rate k·A_r at the reported design (m³/m).
    pub fn wear_rate(&self) -> Option<f64> {
        self.evaluation().map(|e| e.wear_rate)
    }
}

/// The ranking of a material study.
#[derive(Debug, Clone)]
pub struct MaterialRanking {
    /// The objective's name.
    pub objective_name: Objective,
    /// Ranked rows first (by objective), then the others in list order.
    pub results: Vec<MaterialResult>,
    /// Wall time (s).
    pub time_seconds: f64,
}

impl MaterialRanking {
    /// The best usable material, if any.
    pub fn best(&self) -> Option<&MaterialResult> {
        self.results.first().filter(|r| r.rank.is_some())
    }
}

fn check_fixed(constraints: &[Constraint], ev: &Evaluation, scene: &Scene) -> Vec<FixedConstraint> {
    constraints
        .iter()
        .map(|c| {
            let value = quantity_value(c.quantity, ev, scene);
            let slack = |limit: f64| CONSTRAINT_SLACK * limit.abs().max(f64::MIN_POSITIVE);
            let satisfied = value.is_some_and(|v| {
                c.min.is_none_or(|m| v >= m - slack(m)) && c.max.is_none_or(|m| v <= m + slack(m))
            });
            FixedConstraint {
                quantity: c.quantity,
                value,
                min: c.min,
                max: c.max,
                satisfied,
            }
        })
        .collect()
}

/// Runs one material's case.
pub fn run_case(
    study: &Study,
    case: MaterialCase,
    observers: Option<super::ObserverFactory>,
) -> Result<MaterialResult, OptimizeError> {
    let objective = study.objective.ok_or(OptimizeError::NoObjective)?;
    let (status, outcome) = if case.excluded.is_some() {
        (MaterialStatus::Excluded, MaterialOutcome::Excluded)
    } else if case.design.is_empty() {
        let ev = evaluate(&case.scene, &EvaluationOptions::default());
        let constraints = check_fixed(study.constraints, &ev, &case.scene);
        let ok = ev.status == Status::Ok && constraints.iter().all(|c| c.satisfied);
        (
            if ok {
                MaterialStatus::Evaluated
            } else {
                MaterialStatus::Violated
            },
            MaterialOutcome::Evaluated {
                objective: objective_value(objective, &ev, &case.scene),
                evaluation: Box::new(ev),
                constraints,
            },
        )
    } else {
        let sub = Study {
            scene: &case.scene,
            design: &case.design,
            objective: Some(objective),
            constraints: study.constraints,
            settings: study.settings,
        };
        match super::optimize_observed(&sub, observers) {
            Ok(o) => (
                MaterialStatus::Optimized(o.status),
                MaterialOutcome::Optimized(Box::new(o)),
            ),
            Err(e @ OptimizeError::NoContact) => (
                MaterialStatus::NoContact,
                MaterialOutcome::NoContact(e.to_string()),
            ),
            Err(e) => return Err(e),
        }
    };
    Ok(MaterialResult {
        rank: None,
        case,
        status,
        outcome,
    })
}

/// Runs the study once per material in parallel and ranks them. Look the names of
/// `[design] materials` up with [`crate::problem::catalogue::lookup`].
pub fn rank_materials(
    study: &Study,
    materials: &[&'static Material],
    observers: Option<super::ObserverFactory>,
) -> Result<MaterialRanking, OptimizeError> {
    let objective = study.objective.ok_or(OptimizeError::NoObjective)?;
    let t0 = std::time::Instant::now();
    let cases: Vec<MaterialCase> = materials.iter().map(|m| material_case(study, m)).collect();
    let mut results = cases
        .into_par_iter()
        .map(|case| run_case(study, case, observers))
        .collect::<Result<Vec<_>, _>>()?;
    // Stable sort: usable by objective, the rest after in list order.
    results.sort_by(|a, b| {
        let key = |r: &MaterialResult| {
            (
                !r.status.is_usable(),
                r.objective().unwrap_or(f64::INFINITY),
            )
        };
        let (ka, kb) = (key(a), key(b));
        ka.0.cmp(&kb.0).then(if ka.0 {
            std::cmp::Ordering::Equal
        } else {
            ka.1.total_cmp(&kb.1)
        })
    });
    let mut rank = 0;
    for r in &mut results {
        if r.status.is_usable() {
            rank += 1;
            r.rank = Some(rank);
        }
    }
    Ok(MaterialRanking {
        objective_name: objective,
        results,
        time_seconds: t0.elapsed().as_secs_f64(),
    })
}
