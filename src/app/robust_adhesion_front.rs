//! `wearopt pareto` on a robust study against an adhesion measure (`[pareto]
//! adhesion = …` beside a statistic objective or chance constraints;
//! docs/robust-design.md, "A robust front against an adhesion measure"): the
//! objective's statistic against the measure at the medians, one robust
//! optimum per ε level of the measure.
//!
//! * **Levels.** The first is the measure (at the medians) of the file's own
//!   robust optimum, the least-wear end; the last is the preferred end of the
//!   range the nominal front reaches ([`crate::optimize::pareto`] on the
//!   study with each chance constraint's event held off at the nominal
//!   inputs, [`super::robust::nominal_counterparts`]); the `points` levels are
//!   evenly spaced in log10 of the measure between them, solved from the near
//!   end. A level the robust study cannot reach (status `infeasible`) becomes
//!   the far end: the levels not yet solved are spread again, evenly, between
//!   the last usable level and it, so that the points land where the chance
//!   constraints still hold (the infeasible level stays on the report).
//! * **Each level** is the file's robust study with the measure held at or
//!   beyond its ε as a deterministic `[[constraint]]` (pull-off force ≤ ε,
//!   θ ≥ ε for the low direction; the other way for high), holding at the
//!   medians as the robust study's deterministic constraints do; for
//!   `work_of_adhesion`, a design variable, its `[design]` bound is narrowed to
//!   ε instead. The study is solved as `optimize` solves it: the nominal
//!   optimum of that study, then [`super::robust::solve`] (SORA from it and
//!   the baseline, verification by sampling), so that a point equals
//!   `wearopt optimize` on the file with that constraint added (test
//!   `robust_pareto::a_robust_adhesion_front_point_is_optimize_with_its_row`).
//!   The levels are solved one after the other, each with the study's
//!   `time_limit` of its own.

use std::time::Instant;

use serde::Serialize;

use crate::model::SceneParameter;
use crate::optimize::pareto::{measure_of, strength_of, value_at, FrontStatus, Silent};
use crate::optimize::{
    AdhesionMeasure, Constraint, ConstraintQuantity, Objective, ParetoDirection, Study,
};
use crate::problem::Problem;
use crate::uq::robust::{RobustResult, RobustStatus, Statistic, UncertainProgram};
use crate::uq::Estimate;

use super::pareto::{plan, ParetoOptions};
use super::robust::{label, nominal_counterparts, settings, solve, RobustProgram};
use super::robust_front::{HeldConstraint, STATISTIC_TOLERANCE};
use super::{study, valid_scene, AppError};

/// Strength difference (log10 units) below which two adhesions count as equal.
pub const STRENGTH_TOLERANCE: f64 = 1e-6;

/// One level of the front: the robust optimum with the measure held to ε.
#[derive(Debug, Clone, Serialize)]
pub struct AdhesionPoint {
    /// Position on the front, in the order of the levels (0: the file's robust
    /// optimum's own measure).
    pub index: usize,
    /// ε: the measure's bound at this point (SI; θ dimensionless).
    pub target: f64,
    /// The design (SI), by design variable in file order.
    pub design: Vec<f64>,
    /// The statistic of the objective (SI; the objective at the medians
    /// without a statistic) on the common random numbers, with its 95 % interval.
    pub statistic: Estimate,
    /// The objective with every uncertain input at its median (SI).
    pub at_medians: f64,
    /// The measure at the design with every uncertain input at its median
    /// (SI); None where the model gives none.
    pub adhesion: Option<f64>,
    /// Its strength (log10 units, larger = more adhesion).
    pub strength: Option<f64>,
    /// Sampling at the design finds a chance constraint above its target
    /// beyond its interval.
    pub violated: bool,
    /// A usable point (status `optimal` or `chance_constraint_violated`) that no
    /// other usable point beats on both axes.
    pub on_front: bool,
    /// Everything the engine found (status, chance constraints, SORA history).
    pub result: RobustResult,
    /// Wall time of this level (s).
    pub time_seconds: f64,
}

impl AdhesionPoint {
    /// The point's status (the robust study's).
    pub fn status(&self) -> RobustStatus {
        self.result.status
    }

    /// Whether the point has a design to compare: `optimal`, or
    /// `chance_constraint_violated` (marked, not hidden).
    pub fn usable(&self) -> bool {
        matches!(
            self.result.status,
            RobustStatus::Optimal | RobustStatus::ChanceConstraintViolated
        ) && self.strength.is_some()
    }
}

/// What `wearopt pareto` computes on a robust study against an adhesion measure.
#[derive(Debug, Clone, Serialize)]
pub struct AdhesionFrontDocument {
    /// The problem's name.
    pub name: String,
    /// The objective minimised.
    pub objective: Objective,
    /// Its statistic (none: the objective at the medians).
    pub statistic: Option<Statistic>,
    /// The common random numbers of the statistic.
    pub samples: usize,
    /// The adhesion measure on the second axis.
    pub measure: AdhesionMeasure,
    /// Its preferred end.
    pub direction: ParetoDirection,
    /// The design variables, in file order.
    pub names: Vec<SceneParameter>,
    /// The uncertain inputs.
    pub inputs: Vec<SceneParameter>,
    /// The file's chance constraints, held at every point (in the order of each
    /// point's `result.chance`).
    pub held: Vec<HeldConstraint>,
    /// The ε levels (SI), the least-wear end first.
    pub levels: Vec<f64>,
    /// The nominal front's reachable range of the measure, (lowest, highest)
    /// strength in log10 units.
    pub strength_range: (f64, f64),
    /// One per level, in the order of `levels`.
    pub points: Vec<AdhesionPoint>,
    /// `ok`, `no_trade_off` (every usable point has one statistic) or
    /// `infeasible` (no usable point).
    pub status: FrontStatus,
    /// The file's robust optimum (no ε): its design (SI).
    pub robust_design: Vec<f64>,
    /// Its status.
    pub robust_status: RobustStatus,
    /// Its measure at the medians (SI).
    pub robust_adhesion: Option<f64>,
    /// Wall time of the whole front (s).
    pub time_seconds: f64,
}

impl AdhesionFrontDocument {
    /// Each chance constraint of a point as a reader reads it, in the order of
    /// its `result.chance`.
    pub fn chance_labels(&self) -> Vec<&str> {
        self.held.iter().map(|h| h.label.as_str()).collect()
    }

    /// Whether a smaller strength is preferred.
    pub fn low(&self) -> bool {
        self.direction == ParetoDirection::Low
    }
}

/// The problem with the measure held at or beyond the strength `s` (towards the
/// preferred end): a deterministic `[[constraint]]` on the pull-off force or θ,
/// or `work_of_adhesion`'s `[design]` bound narrowed.
fn at_level(problem: &Problem, measure: AdhesionMeasure, low: bool, s: f64) -> Problem {
    let mut p = problem.clone();
    let v = value_at(measure, s);
    match ConstraintQuantity::from_quantity(measure.quantity()) {
        Some(quantity) => {
            // Strength ≤ s is an upper bound on the value, except for θ.
            let upper = low != (measure == AdhesionMeasure::ElasticAdhesionIndex);
            p.study.constraints.push(Constraint {
                quantity,
                min: (!upper).then_some(v),
                max: upper.then_some(v),
                only_at_objective_humidity: false,
            });
        }
        None => {
            if let Some(var) = p
                .study
                .design
                .iter_mut()
                .find(|d| d.name == SceneParameter::WorkOfAdhesion)
            {
                // Keep a non-empty box: a level on the bound itself is the bound.
                let width = (var.max - var.min) * 1e-9;
                if low {
                    var.max = v.clamp(var.min + width, var.max);
                } else {
                    var.min = v.clamp(var.min, var.max - width);
                }
                p.scene.work_of_adhesion = p.scene.work_of_adhesion.clamp(var.min, var.max);
            }
        }
    }
    p
}

/// The robust optimum of `problem` as `optimize` finds it: the nominal optimum
/// (each chance constraint's event held off at the nominal inputs), then SORA
/// from it and the baseline, verified. Its design (SI), objective at the
/// medians, measure at the medians and the engine's result.
fn robust_optimum(
    problem: &Problem,
    origin: &str,
    measure: AdhesionMeasure,
) -> Result<(Vec<f64>, f64, Option<f64>, RobustResult), AppError> {
    let deadline = Instant::now() + problem.study.optimizer.time_limit;
    let mut constraints = problem.study.constraints.clone();
    constraints.extend(nominal_counterparts(problem));
    let nominal = crate::optimize::optimize(&Study {
        constraints: &constraints,
        ..study(problem)
    })
    .map_err(|error| AppError::Optimize {
        origin: origin.to_string(),
        error,
    })?;
    let program = RobustProgram::new(problem).ok_or_else(|| AppError::NoUncertainty {
        origin: origin.to_string(),
    })?;
    let result = solve(&program, &nominal.design, &settings(problem, deadline));
    let model = program.inputs(&result.design);
    let medians = model.to_physical(&vec![0.0; model.dim()]);
    let at_medians = program
        .outputs(&result.design, &medians)
        .map_or(f64::NAN, |o| o.objective);
    let (scene, mut ev) = program.evaluate(&result.design, &medians);
    if measure == AdhesionMeasure::PullOffForce && ev.pull_off_force.is_none() {
        // No row or event of the study asked for the pull-off: evaluate it.
        let options = crate::model::EvaluationOptions {
            pull_off: true,
            ..program.functions().options
        };
        ev = crate::model::evaluate(&scene, &options);
    }
    let adhesion = measure_of(measure, &ev, &scene)
        .map(|(v, _)| v)
        .filter(|v| v.is_finite());
    let design = program.functions().space.values(&result.design);
    Ok((design, at_medians, adhesion, result))
}

/// Which usable points no other usable point beats: statistic and strength
/// (towards the preferred end) both no worse, one better.
fn mark_front(points: &mut [AdhesionPoint], low: bool) {
    let usable: Vec<(usize, f64, f64)> = points
        .iter()
        .enumerate()
        .filter(|(_, p)| p.usable() && p.statistic.value.is_finite())
        .map(|(i, p)| {
            let s = p.strength.unwrap_or(f64::NAN);
            (i, p.statistic.value, if low { s } else { -s })
        })
        .collect();
    let le = |a: f64, b: f64| a <= b + STATISTIC_TOLERANCE * b.abs();
    for &(i, s, a) in &usable {
        let beaten = usable.iter().any(|&(j, t, b)| {
            j != i
                && le(t, s)
                && b <= a + STRENGTH_TOLERANCE
                && (t < s * (1.0 - STATISTIC_TOLERANCE) || b < a - STRENGTH_TOLERANCE)
        });
        points[i].on_front = !beaten;
    }
}

/// The robust front of the problem's study against its `[pareto]` adhesion
/// measure, `options` (points, adhesion, direction) in place of the file's
/// where given; `on_point` sees each point as it is solved. An error when the
/// problem asks for no front, has no objective, or `points` is out of range.
pub fn adhesion_front(
    problem: &Problem,
    origin: &str,
    options: &ParetoOptions,
    on_point: &mut dyn FnMut(&AdhesionPoint),
) -> Result<AdhesionFrontDocument, AppError> {
    let start = Instant::now();
    let plan = plan(problem, origin, options)?;
    valid_scene(problem, origin)?;
    let spec = plan.spec;
    let measure = spec.adhesion;
    let low = spec.direction == ParetoDirection::Low;
    // The reachable range: the nominal front of the study with each event held
    // off at the nominal inputs (two points: only its range is read).
    let mut constraints = problem.study.constraints.clone();
    constraints.extend(nominal_counterparts(problem));
    let nominal_study = Study {
        constraints: &constraints,
        ..study(problem)
    };
    let range_spec = crate::optimize::ParetoSpec {
        points: crate::optimize::ParetoSpec::MIN_POINTS,
        ..spec
    };
    let nominal_front = crate::optimize::pareto::pareto(&nominal_study, &range_spec, &Silent)
        .map_err(|error| AppError::Pareto {
            origin: origin.to_string(),
            error,
        })?;
    let range = nominal_front.strength_range;
    let far = if low { range.0 } else { range.1 };
    // The least-wear end: the file's own robust optimum.
    let (robust_design, _, robust_adhesion, robust_result) =
        robust_optimum(problem, origin, measure)?;
    let near = robust_adhesion
        .filter(|v| *v > 0.0)
        .map(|v| strength_of(measure, v.log10()))
        .unwrap_or(if low { range.1 } else { range.0 })
        .clamp(range.0, range.1);
    let n = spec.points;
    // Levels from the near end towards the far one; a level the robust study
    // cannot reach (status `infeasible`) becomes the far end, and the levels
    // not yet solved are spread again between the last usable level and it.
    let mut strengths: Vec<f64> = (0..n)
        .map(|i| near + (far - near) * i as f64 / (n - 1) as f64)
        .collect();
    let mut out: Vec<AdhesionPoint> = Vec::with_capacity(n);
    let mut last_usable = None::<f64>;
    for k in 0..n {
        let s = strengths[k];
        let t0 = Instant::now();
        let p = at_level(problem, measure, low, s);
        let (design, at_medians, adhesion, result) = robust_optimum(&p, origin, measure)?;
        let violated = result.chance.iter().any(|c| c.violated);
        let point = AdhesionPoint {
            index: k,
            target: value_at(measure, s),
            design,
            statistic: result.objective,
            at_medians,
            adhesion,
            strength: adhesion
                .filter(|v| *v > 0.0)
                .map(|v| strength_of(measure, v.log10())),
            violated,
            on_front: false,
            result,
            time_seconds: t0.elapsed().as_secs_f64(),
        };
        on_point(&point);
        if point.status() == RobustStatus::Infeasible {
            if let Some(a) = last_usable {
                let m = n - k - 1;
                for (j, t) in strengths[k + 1..].iter_mut().enumerate() {
                    *t = a + (s - a) * (j + 1) as f64 / (m + 1) as f64;
                }
            }
        } else if point.usable() {
            last_usable = Some(s);
        }
        out.push(point);
    }
    // In the order of the levels, the least-wear end first.
    out.sort_by(|a, b| {
        let (x, y) = (
            strength_of(measure, a.target.log10()),
            strength_of(measure, b.target.log10()),
        );
        if low {
            y.total_cmp(&x)
        } else {
            x.total_cmp(&y)
        }
    });
    for (i, p) in out.iter_mut().enumerate() {
        p.index = i;
    }
    let levels: Vec<f64> = out.iter().map(|p| p.target).collect();
    mark_front(&mut out, low);
    let usable: Vec<&AdhesionPoint> = out.iter().filter(|p| p.usable()).collect();
    let status = if usable.is_empty() {
        FrontStatus::Infeasible
    } else {
        let (lo, hi) = usable
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p.statistic.value), b.max(p.statistic.value))
            });
        if usable.len() < 2 || hi - lo <= STATISTIC_TOLERANCE * hi.abs() {
            FrontStatus::NoTradeOff
        } else {
            FrontStatus::Ok
        }
    };
    let held = problem
        .robust
        .chance
        .iter()
        .map(|c| HeldConstraint {
            event: c.event.name().to_string(),
            label: label(&c.event),
            target: c.probability_max,
        })
        .collect();
    Ok(AdhesionFrontDocument {
        name: problem.name.clone(),
        objective: plan.objective,
        statistic: problem.robust.statistic,
        samples: problem.robust.samples,
        measure,
        direction: spec.direction,
        names: plan.names,
        inputs: problem
            .uncertainty
            .as_ref()
            .map(|u| u.inputs.iter().map(|i| i.parameter).collect())
            .unwrap_or_default(),
        held,
        levels,
        strength_range: range,
        points: out,
        status,
        robust_design,
        robust_status: robust_result.status,
        robust_adhesion,
        time_seconds: start.elapsed().as_secs_f64(),
    })
}
