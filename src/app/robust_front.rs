//! `wearopt pareto` on a front against a probability (`[pareto] event = …`;
//! docs/robust-design.md, "A front against a probability"): the objective, or
//! its statistic, against P(event), one robust optimum per level of
//! probability_max.
//!
//! Each level is the file's robust study with the front's event held to
//! P(event) ≤ level (the file's own chance constraint on that event replaced,
//! or one added), solved as `optimize` solves it ([`super::robust::solve`]:
//! SORA from the nominal optimum and the baseline, then verification by
//! sampling), so that a point equals `wearopt optimize` on the file with that
//! `probability_max` (test `robust_pareto::a_front_point_is_optimize_at_its_level`).
//! The levels are solved one after the other, each with the study's
//! `time_limit` of its own.

use std::time::Instant;

use serde::Serialize;

use crate::model::SceneParameter;
use crate::optimize::pareto::FrontStatus;
use crate::optimize::{Objective, Optimum, Study};
use crate::problem::{ChanceConstraint, EventFront, Problem};
use crate::uq::reliability::EventResult;
use crate::uq::robust::{
    chance_probabilities, verification_settings, ChanceReport, RobustResult, RobustStatus,
    Statistic,
};
use crate::uq::Estimate;

use super::robust::{label, settings, solve, RobustProgram};
use super::{study, valid_scene, AppError, OptionName};

/// Relative difference of two statistics below which they count as equal (a
/// front whose points all share one value has no trade-off).
pub const STATISTIC_TOLERANCE: f64 = 1e-6;

/// One level of the front: the robust optimum under P(event) ≤ `level`.
#[derive(Debug, Clone, Serialize)]
pub struct LevelPoint {
    /// Position on the front (0: the loosest level).
    pub index: usize,
    /// probability_max of the front's event at this point.
    pub level: f64,
    /// The design (SI), by design variable in file order.
    pub design: Vec<f64>,
    /// The statistic of the objective (SI; the objective at the medians
    /// without a statistic) on the common random numbers, with its 95 % interval.
    pub statistic: Estimate,
    /// The objective with every uncertain input at its median (SI).
    pub at_medians: f64,
    /// The front event's sampled probability at the design (verification:
    /// importance sampling or Monte Carlo, with its 95 % interval).
    pub probability: EventResult,
    /// The lower end of that interval exceeds `level`.
    pub violated: bool,
    /// A usable point (status `optimal` or `chance_constraint_violated`) that no
    /// other usable point beats on both axes.
    pub on_front: bool,
    /// Everything the engine found (status, chance constraints, SORA history).
    pub result: RobustResult,
    /// Wall time of this level (s).
    pub time_seconds: f64,
}

impl EventFrontDocument {
    /// Each chance constraint of `point` as a reader reads it (`plasticity_index
    /// > 1`), in the order of its `result.chance`.
    pub fn chance_labels(&self) -> Vec<&str> {
        let mut held = self.held.iter();
        (0..self.held.len() + 1)
            .map(|j| {
                if j == self.front_index {
                    self.label.as_str()
                } else {
                    held.next().map_or("", |h| h.label.as_str())
                }
            })
            .collect()
    }

    /// Why `point` is not a usable optimum, where sampling at its design finds a
    /// chance constraint above its target beyond its interval: each such
    /// constraint, e.g. `P(plasticity_index > 1) = 0.0116 [0.0112, 0.0120] > 0.0010`.
    pub fn violations<'a>(&'a self, point: &'a LevelPoint) -> Vec<(&'a str, &'a ChanceReport)> {
        let labels = self.chance_labels();
        point
            .result
            .chance
            .iter()
            .enumerate()
            .filter(|(_, c)| c.violated)
            .map(|(j, c)| (labels.get(j).copied().unwrap_or(""), c))
            .collect()
    }
}

impl LevelPoint {
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
        )
    }
}

/// A chance constraint held at every point beside the front's own.
#[derive(Debug, Clone, Serialize)]
pub struct HeldConstraint {
    /// The event's name.
    pub event: String,
    /// As a reader reads it (`plasticity_index > 1`).
    pub label: String,
    /// Its probability_max.
    pub target: f64,
}

/// What `wearopt pareto` computes on a front against a probability.
#[derive(Debug, Clone, Serialize)]
pub struct EventFrontDocument {
    /// The problem's name.
    pub name: String,
    /// The objective minimised.
    pub objective: Objective,
    /// Its statistic (none: the objective at the medians).
    pub statistic: Option<Statistic>,
    /// The common random numbers of the statistic.
    pub samples: usize,
    /// The front's event.
    pub event: String,
    /// The same as a reader reads it.
    pub label: String,
    /// The design variables, in file order.
    pub names: Vec<SceneParameter>,
    /// The uncertain inputs.
    pub inputs: Vec<SceneParameter>,
    /// The other chance constraints, held at every point.
    pub held: Vec<HeldConstraint>,
    /// Where the front's event stands among each point's chance constraints
    /// (`result.chance`); the others are `held`, in order.
    pub front_index: usize,
    /// The levels, loosest first.
    pub levels: Vec<f64>,
    /// One per level, in the order of `levels`.
    pub points: Vec<LevelPoint>,
    /// `ok`, `no_trade_off` (every usable point has one statistic: the event
    /// never binds) or `infeasible` (no usable point).
    pub status: FrontStatus,
    /// The nominal optimum's design (SI): the study at the nominal inputs, each
    /// chance constraint's event held off there.
    pub nominal_design: Vec<f64>,
    /// The objective there (SI).
    pub nominal_objective: f64,
    /// The front event's sampled probability at the nominal optimum.
    pub nominal_probability: EventResult,
    /// Wall time of the whole front (s).
    pub time_seconds: f64,
}

/// The problem at one level: the front's event held to P ≤ `level`.
fn at_level(problem: &Problem, front: &EventFront, level: f64) -> Problem {
    let mut p = problem.clone();
    match front.replaces {
        Some(i) => p.robust.chance[i].probability_max = level,
        None => p.robust.chance.push(ChanceConstraint {
            index: usize::MAX,
            event: front.event.clone(),
            probability_max: level,
        }),
    }
    p
}

/// Which usable points no other usable point beats: statistic and sampled
/// probability both no larger, one smaller (statistics equal within
/// [`STATISTIC_TOLERANCE`] relative).
fn mark_front(points: &mut [LevelPoint]) {
    let key = |p: &LevelPoint| (p.statistic.value, p.probability.probability.unwrap_or(0.0));
    let usable: Vec<(usize, (f64, f64))> = points
        .iter()
        .enumerate()
        .filter(|(_, p)| p.usable() && p.statistic.value.is_finite())
        .map(|(i, p)| (i, key(p)))
        .collect();
    let le = |a: f64, b: f64| a <= b + STATISTIC_TOLERANCE * b.abs();
    for &(i, (s, q)) in &usable {
        let beaten = usable.iter().any(|&(j, (t, r))| {
            j != i && le(t, s) && r <= q && (t < s * (1.0 - STATISTIC_TOLERANCE) || r < q)
        });
        points[i].on_front = !beaten;
    }
}

/// The front against a probability of the problem's study (`[pareto] event`),
/// `points` levels in place of the file's when given; `on_point` sees each
/// point as it is solved (a streamed output's rows). An error when the problem
/// asks for no such front, or `points` is out of range.
pub fn event_front(
    problem: &Problem,
    origin: &str,
    points: Option<usize>,
    on_point: &mut dyn FnMut(&LevelPoint),
) -> Result<EventFrontDocument, AppError> {
    let start = Instant::now();
    let Some(front) = problem.robust.front.as_ref() else {
        return Err(AppError::NoPareto {
            origin: origin.to_string(),
        });
    };
    let mut front = front.clone();
    if let Some(n) = points {
        let (lo, hi) = (
            crate::problem::MIN_FRONT_POINTS as usize,
            crate::problem::MAX_FRONT_POINTS as usize,
        );
        if !(lo..=hi).contains(&n) {
            return Err(AppError::Invalid {
                options: vec![(OptionName("points"), n.to_string())],
                rule: format!("must lie in {lo}..={hi} on a front against a probability"),
            });
        }
        front.points = n;
    }
    valid_scene(problem, origin)?;
    let Some(objective) = problem.study.objective else {
        return Err(AppError::NoObjective {
            origin: origin.to_string(),
        });
    };
    let levels = front.levels();
    let front_index = front.replaces.unwrap_or(problem.robust.chance.len());
    // The nominal optimum: the same at every level (each event is held off at the
    // nominal inputs, whatever its probability_max).
    let first = at_level(problem, &front, levels[0]);
    let mut constraints = problem.study.constraints.clone();
    constraints.extend(super::robust::nominal_counterparts(&first));
    let nominal_study = Study {
        constraints: &constraints,
        ..study(problem)
    };
    let nominal: Optimum =
        crate::optimize::optimize(&nominal_study).map_err(|error| AppError::Optimize {
            origin: origin.to_string(),
            error,
        })?;
    let mut out = Vec::with_capacity(levels.len());
    let mut nominal_probability = None;
    for (index, &level) in levels.iter().enumerate() {
        let t0 = Instant::now();
        let p = at_level(problem, &front, level);
        let program = RobustProgram::new(&p).ok_or_else(|| AppError::NoUncertainty {
            origin: origin.to_string(),
        })?;
        if nominal_probability.is_none() {
            let unit = program.functions().space.unit(&nominal.design);
            let all = chance_probabilities(
                &program,
                &unit,
                p.robust.chance.len(),
                &verification_settings(),
            );
            nominal_probability = all.into_iter().nth(front_index);
        }
        let deadline = Instant::now() + problem.study.optimizer.time_limit;
        let result = solve(&program, &nominal.design, &settings(&p, deadline));
        let space = &program.functions().space;
        let design = space.values(&result.design);
        let model = crate::uq::robust::UncertainProgram::inputs(&program, &result.design);
        let at_medians = crate::uq::robust::UncertainProgram::outputs(
            &program,
            &result.design,
            &model.to_physical(&vec![0.0; model.dim()]),
        )
        .map_or(f64::NAN, |o| o.objective);
        let chance = &result.chance[front_index];
        let point = LevelPoint {
            index,
            level,
            design,
            statistic: result.objective,
            at_medians,
            probability: chance.verification.clone(),
            violated: chance.violated,
            on_front: false,
            result,
            time_seconds: t0.elapsed().as_secs_f64(),
        };
        on_point(&point);
        out.push(point);
    }
    mark_front(&mut out);
    let usable: Vec<&LevelPoint> = out.iter().filter(|p| p.usable()).collect();
    let status = if usable.is_empty() {
        FrontStatus::Infeasible
    } else {
        let lo = usable
            .iter()
            .map(|p| p.statistic.value)
            .fold(f64::INFINITY, f64::min);
        let hi = usable
            .iter()
            .map(|p| p.statistic.value)
            .fold(f64::NEG_INFINITY, f64::max);
        if usable.len() < 2 || hi - lo <= STATISTIC_TOLERANCE * hi.abs() {
            FrontStatus::NoTradeOff
        } else {
            FrontStatus::Ok
        }
    };
    let held = first
        .robust
        .chance
        .iter()
        .enumerate()
        .filter(|(j, _)| *j != front_index)
        .map(|(_, c)| HeldConstraint {
            event: c.event.name().to_string(),
            label: label(&c.event),
            target: c.probability_max,
        })
        .collect();
    Ok(EventFrontDocument {
        name: problem.name.clone(),
        objective,
        statistic: problem.robust.statistic,
        samples: problem.robust.samples,
        event: front.event.name().to_string(),
        label: label(&front.event),
        names: problem.study.design.iter().map(|d| d.name).collect(),
        inputs: problem
            .uncertainty
            .as_ref()
            .map(|u| u.inputs.iter().map(|i| i.parameter).collect())
            .unwrap_or_default(),
        held,
        front_index,
        levels,
        points: out,
        status,
        nominal_design: nominal.design.clone(),
        nominal_objective: nominal.objective,
        nominal_probability: nominal_probability.expect("at least two levels"),
        time_seconds: start.elapsed().as_secs_f64(),
    })
}
