//! `wearopt optimize` on a robust study (docs/uncertainty.md, "Designs that hold
//! in most parts"): the study as an [`UncertainProgram`] for the library's SORA
//! engine ([`crate::uq::robust`]), the robust optimum beside the nominal one, and
//! what each costs and risks at the other.
//!
//! A design variable that is also an uncertain input carries its law with it:
//! at a design value v the input's law is the file's law scaled by
//! v / (its median), so that its relative spread (a lognormal's factor, a
//! normal's coefficient of variation, a bounded law's width over its median) is
//! kept. The other uncertain inputs keep their laws. The study's deterministic
//! `[[constraint]]`s hold at the median of every uncertain input.

use std::time::{Duration, Instant};

use serde::Serialize;

use crate::model::{self, Evaluation, EvaluationOptions, Quantity, Scene, SceneParameter, Status};
use crate::optimize::functions::objective_value;
use crate::optimize::{
    sqp_settings, Constraint, ConstraintQuantity, DesignSpace, Optimum, StudyFunctions,
};
use crate::problem::{Event, Problem, UncertainInput};
use crate::uq::distribution::Distribution;
use crate::uq::model::InputModel;
use crate::uq::reliability::EventResult;
use crate::uq::robust::{
    chance_probabilities, common_points, estimate, objective_values, optimize_robust,
    verification_settings, Outputs, RobustResult, RobustSettings, RobustStatus, Statistic,
    UncertainProgram,
};
use crate::uq::Estimate;

use super::uncertainty::{event_needs_pull_off, limit_state, scene_at};

/// The SQP's KKT tolerance on a statistic objective at least this: a quantile
/// over a fixed sample is smooth only between the designs where two sample
/// values swap ranks, so its finite-difference gradient is good to about the
/// spacing of the sample's order statistics, not to 1e-8.
pub const STATISTIC_TOLERANCE: f64 = 1e-6;

/// The study as a program under uncertainty: the design in the unit box of its
/// [`DesignSpace`], the random inputs those of `[uncertainty.inputs]`.
pub struct RobustProgram<'a> {
    functions: StudyFunctions,
    inputs: &'a [UncertainInput],
    correlations: &'a [(usize, usize, f64)],
    /// Per uncertain input, the design variable whose value centres its law.
    tracks: Vec<Option<usize>>,
    events: Vec<Event>,
    options: EvaluationOptions,
}

/// `law` scaled by `ratio` > 0: the law of `ratio · X`.
fn scaled(law: Distribution, ratio: f64) -> Distribution {
    match law {
        Distribution::Normal { mean, sd } => Distribution::Normal {
            mean: mean * ratio,
            sd: sd * ratio,
        },
        Distribution::Lognormal { median, factor } => Distribution::Lognormal {
            median: median * ratio,
            factor,
        },
        Distribution::Uniform { min, max } => Distribution::Uniform {
            min: min * ratio,
            max: max * ratio,
        },
        Distribution::Beta {
            alpha,
            beta,
            min,
            max,
        } => Distribution::Beta {
            alpha,
            beta,
            min: min * ratio,
            max: max * ratio,
        },
        Distribution::Triangular { min, mode, max } => Distribution::Triangular {
            min: min * ratio,
            mode: mode * ratio,
            max: max * ratio,
        },
    }
}

impl<'a> RobustProgram<'a> {
    /// The program of a problem with a robust study (None without
    /// `[uncertainty]`, an objective or a design).
    pub fn new(problem: &'a Problem) -> Option<RobustProgram<'a>> {
        let u = problem.uncertainty.as_ref()?;
        let objective = problem.study.objective?;
        let space = DesignSpace::new(&problem.scene, &problem.study.design);
        let functions = StudyFunctions::new(space, objective, &problem.study.constraints);
        let tracks = u
            .inputs
            .iter()
            .map(|i| {
                problem
                    .study
                    .design
                    .iter()
                    .position(|v| v.name == i.parameter)
            })
            .collect();
        let events: Vec<Event> = problem
            .robust
            .chance
            .iter()
            .map(|c| c.event.clone())
            .collect();
        let pull_off = functions.options.pull_off || events.iter().any(event_needs_pull_off);
        let options = EvaluationOptions {
            pull_off,
            ..functions.options
        };
        Some(RobustProgram {
            functions,
            inputs: &u.inputs,
            correlations: &u.correlations,
            tracks,
            events,
            options,
        })
    }

    /// The study's deterministic functions (design space, objective, rows).
    pub fn functions(&self) -> &StudyFunctions {
        &self.functions
    }

    /// The scene at unit design `d` with the uncertain inputs at `x` (SI).
    pub fn scene(&self, d: &[f64], x: &[f64]) -> Scene {
        scene_at(&self.functions.scene_at(d), self.inputs, x)
    }

    /// The evaluation at unit design `d` and inputs `x`.
    pub fn evaluate(&self, d: &[f64], x: &[f64]) -> (Scene, Evaluation) {
        let scene = self.scene(d, x);
        let ev = model::evaluate(&scene, &self.options);
        (scene, ev)
    }
}

impl UncertainProgram for RobustProgram<'_> {
    fn dimension(&self) -> usize {
        self.functions.dim()
    }

    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        (vec![0.0; self.dimension()], vec![1.0; self.dimension()])
    }

    fn inputs(&self, d: &[f64]) -> InputModel {
        let values = self.functions.space.values(d);
        let marginals = self
            .inputs
            .iter()
            .zip(&self.tracks)
            .map(|(i, t)| match t {
                Some(j) => {
                    let median = i.distribution.median();
                    if median > 0.0 && values[*j] > 0.0 {
                        scaled(i.distribution, values[*j] / median)
                    } else {
                        i.distribution
                    }
                }
                None => i.distribution,
            })
            .collect();
        InputModel::new(marginals, self.correlations)
            .expect("a scaled law keeps the copula validated when the file was read")
    }

    fn outputs(&self, d: &[f64], x: &[f64]) -> Option<Outputs> {
        let (scene, ev) = self.evaluate(d, x);
        if matches!(ev.status, Status::NotConverged | Status::OutOfRange) {
            return None;
        }
        let limit_states = self
            .events
            .iter()
            .map(|e| limit_state(e, &ev, &scene))
            .collect::<Option<Vec<f64>>>()?;
        Some(Outputs {
            objective: objective_value(self.functions.objective, &ev, &scene),
            limit_states,
            constraints: self.functions.point_of(d, &ev, &scene).rows,
        })
    }

    /// The objectives are positive quantities minimised in ln, as in a nominal study.
    fn logarithmic_objective(&self) -> bool {
        true
    }
}

/// The deterministic counterpart of each chance constraint's event, for the
/// nominal study beside the robust one: the event must not happen with every
/// input at its nominal value (stiction: pull-off force ≤ restoring force;
/// wear-out: wear rate ≤ allowed depth × nominal area / sliding distance; a threshold on
/// a quantity a constraint can bound: that bound). Such a design sits on its
/// limit when the limit binds, where about half the parts fail: what the robust
/// study is for.
pub fn nominal_counterparts(problem: &Problem) -> Vec<Constraint> {
    let scene = &problem.scene;
    let req = &scene.requirements;
    problem
        .robust
        .chance
        .iter()
        .filter_map(|c| {
            let (q, min, max) = match &c.event {
                Event::Stiction => (Quantity::PullOffForce, None, req.restoring_force),
                Event::WearOut => (
                    Quantity::WearRate,
                    None,
                    req.allowed_wear_depth
                        .filter(|_| scene.sliding_distance > 0.0)
                        .map(|a| a * scene.nominal_area / scene.sliding_distance),
                ),
                Event::Threshold {
                    quantity,
                    above,
                    limit,
                    ..
                } => {
                    if *above {
                        (*quantity, None, Some(*limit))
                    } else {
                        (*quantity, Some(*limit), None)
                    }
                }
            };
            let quantity = ConstraintQuantity::from_quantity(q)?;
            (min.is_some() || max.is_some()).then_some(Constraint {
                quantity,
                min,
                max,
                only_at_objective_humidity: false,
            })
        })
        .collect()
}

/// An event as a reader reads it: its name, or for a threshold named by
/// default, `quantity > limit`.
pub(crate) fn label(e: &Event) -> String {
    match e {
        Event::Threshold {
            name,
            quantity,
            above,
            limit,
        } if *name
            == format!(
                "{}_{}",
                quantity.as_str(),
                if *above { "above" } else { "below" }
            ) =>
        {
            format!(
                "{} {} {}",
                quantity.as_str(),
                if *above { ">" } else { "<" },
                crate::units::format_quantity(*limit, quantity.dimension())
            )
        }
        _ => e.name().to_string(),
    }
}

/// One chance constraint at a design: its sampled probability.
#[derive(Debug, Clone, Serialize)]
pub struct EventAt {
    /// The event's name.
    pub event: String,
    /// The largest probability allowed.
    pub target: f64,
    /// The reliability analysis there (sampled probability, interval, FORM).
    pub analysis: EventResult,
}

/// The objective's distribution at a design, on the study's common random numbers.
#[derive(Debug, Clone, Serialize)]
pub struct ObjectiveSample {
    /// The values (SI), ascending; samples where the model failed left out.
    pub values: Vec<f64>,
    /// Samples where the model failed.
    pub failed: usize,
    /// The objective at the median of every uncertain input.
    pub nominal: f64,
    /// The study's statistic (or, for a nominal objective, the mean) with its interval.
    pub statistic: Estimate,
}

/// The robust optimum beside the nominal one.
#[derive(Debug, Clone, Serialize)]
pub struct RobustOutcome {
    /// The statistic minimised (None: the nominal objective, under chance constraints).
    pub statistic: Option<Statistic>,
    /// The common random numbers.
    pub samples: usize,
    /// The uncertain inputs, in the order of the engine's vectors.
    pub inputs: Vec<SceneParameter>,
    /// The chance constraints' event names, in the order of `result.chance`.
    pub events: Vec<String>,
    /// The same events as a reader reads them: `stiction`,
    /// `plasticity_index > 1`.
    pub labels: Vec<String>,
    /// What the engine found (status, design in unit coordinates, chance
    /// constraints with their verification, SORA history).
    pub result: RobustResult,
    /// The robust design (SI), by design variable in file order.
    pub design: Vec<f64>,
    /// The scene at the robust design, uncertain inputs at their medians.
    #[serde(skip)]
    pub scene: Scene,
    /// The evaluation there.
    #[serde(skip)]
    pub evaluation: Evaluation,
    /// The objective's distribution at the robust design.
    pub robust_sample: ObjectiveSample,
    /// The objective's distribution at the nominal optimum.
    pub nominal_sample: ObjectiveSample,
    /// Each chance constraint's sampled probability at the nominal optimum.
    pub nominal_events: Vec<EventAt>,
    /// The KKT tolerance the deterministic solves used.
    pub tolerance: f64,
    /// Wall time (s).
    pub time_seconds: f64,
}

impl RobustOutcome {
    /// Whether the robust study ended without a usable design (infeasible, or a
    /// chance constraint that sampling finds violated): exit code 1.
    pub fn failed(&self) -> bool {
        matches!(
            self.result.status,
            RobustStatus::Infeasible | RobustStatus::ChanceConstraintViolated
        )
    }
}

fn objective_sample(
    program: &RobustProgram,
    d: &[f64],
    points: &[Vec<f64>],
    statistic: Option<Statistic>,
) -> ObjectiveSample {
    let all = objective_values(program, d, points);
    let mut values: Vec<f64> = all.into_iter().filter(|v| v.is_finite()).collect();
    let failed = points.len() - values.len();
    values.sort_by(f64::total_cmp);
    let model = program.inputs(d);
    let nominal = program
        .outputs(d, &model.to_physical(&vec![0.0; model.dim()]))
        .map_or(f64::NAN, |o| o.objective);
    let statistic = estimate(&values, statistic.unwrap_or(Statistic::Mean));
    ObjectiveSample {
        values,
        failed,
        nominal,
        statistic,
    }
}

/// The engine's settings for the robust study of `problem` with `deadline`
/// (the file's statistic, samples, targets, verify and seed; the SQP of its
/// `[optimizer]` with the time left, its KKT tolerance at least
/// [`STATISTIC_TOLERANCE`] under a statistic).
pub fn settings(problem: &Problem, deadline: Instant) -> RobustSettings {
    let r = &problem.robust;
    let seed = problem.uncertainty.as_ref().map_or(1, |u| u.seed);
    let mut settings = RobustSettings {
        statistic: r.statistic,
        samples: r.samples,
        targets: r.chance.iter().map(|c| c.probability_max).collect(),
        verify: r.verify,
        seed,
        deadline: Some(deadline),
        ..RobustSettings::default()
    };
    let remaining = deadline.saturating_duration_since(Instant::now());
    settings.sqp = sqp_settings(
        &problem.study.optimizer,
        remaining.max(Duration::from_secs(1)),
    );
    if r.statistic.is_some() {
        settings.sqp.tolerance = settings.sqp.tolerance.max(STATISTIC_TOLERANCE);
    }
    settings
}

/// The robust optimum of `program` (the program of `problem`) by the engine's
/// SORA and verification, started from `nominal` (the nominal optimum's design,
/// SI) and the baseline: what `optimize` reports, and each point of a front
/// against a probability.
pub fn solve(program: &RobustProgram, nominal: &[f64], settings: &RobustSettings) -> RobustResult {
    let space = &program.functions.space;
    let mut starts = vec![space.unit(nominal)];
    let baseline = space.baseline_unit();
    if baseline != starts[0] {
        starts.push(baseline);
    }
    optimize_robust(program, &starts, settings)
}

/// The robust study of `problem`, started from the nominal optimum and the
/// baseline. `deadline` (the study's `time_limit` from its start) bounds SORA:
/// past it no solve, cycle or correction starts, and the status is `time_limit`.
pub fn robust(problem: &Problem, nominal: &Optimum, deadline: Instant) -> Option<RobustOutcome> {
    let start = Instant::now();
    let program = RobustProgram::new(problem)?;
    let u = problem.uncertainty.as_ref()?;
    let r = &problem.robust;
    let space = &program.functions.space;
    let settings = settings(problem, deadline);
    let result = solve(&program, &nominal.design, &settings);
    let design = space.values(&result.design);
    let medians = |d: &[f64]| {
        let m = program.inputs(d);
        m.to_physical(&vec![0.0; m.dim()])
    };
    let (scene, evaluation) = program.evaluate(&result.design, &medians(&result.design));
    let points = common_points(u.inputs.len(), r.samples, settings.seed);
    let robust_sample = objective_sample(&program, &result.design, &points, r.statistic);
    let nominal_unit = space.unit(&nominal.design);
    let nominal_sample = objective_sample(&program, &nominal_unit, &points, r.statistic);
    let nominal_events = chance_probabilities(
        &program,
        &nominal_unit,
        r.chance.len(),
        &verification_settings(),
    )
    .into_iter()
    .zip(&r.chance)
    .map(|(analysis, c)| EventAt {
        event: c.event.name().to_string(),
        target: c.probability_max,
        analysis,
    })
    .collect();
    Some(RobustOutcome {
        statistic: r.statistic,
        inputs: u.inputs.iter().map(|i| i.parameter).collect(),
        events: r
            .chance
            .iter()
            .map(|c| c.event.name().to_string())
            .collect(),
        labels: r.chance.iter().map(|c| label(&c.event)).collect(),
        samples: r.samples,
        design,
        scene,
        evaluation,
        robust_sample,
        nominal_sample,
        nominal_events,
        tolerance: settings.sqp.tolerance,
        time_seconds: start.elapsed().as_secs_f64(),
        result,
    })
}
