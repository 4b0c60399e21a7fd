//! The outer optimiser: searches material and roughness parameters to minimise
//! the predicted wear rate (or another objective) under engineering limits, with
//! the wear model as its inner evaluator.
//!
//! * [`study`]: a design study's vocabulary (variables, objective, constraints,
//!   settings), which the problem-file stage builds.
//! * [`program`]: the solver's vocabulary, [`NonlinearProgram`].
//! * [`sqp`]: [`minimize`], a trust-region SQP for any such program (argmin `Solver`).
//! * `qp` (crate-internal): its clarabel subproblem; `multipliers`: KKT
//!   residual and multipliers; `fd`: finite-difference gradients with error
//!   estimates (rayon).
//! * [`design`]: variables in log space, scaled to the unit box.
//! * [`functions`]: a study as a [`NonlinearProgram`] (ln objective, constraint rows).
//! * [`optimize`]: deterministic low-discrepancy multistart in parallel, with a
//!   search for starts in contact, then a search of the vertices adjacent to the
//!   best local optimum ([`vertices`]).

pub mod design;
pub(crate) mod fd;
pub mod functions;
pub mod materials;
pub(crate) mod multipliers;
pub mod pareto;
pub mod program;
pub(crate) mod qp;
pub mod sqp;
pub mod study;
pub mod vertices;

use std::time::{Duration, Instant};

use argmin::core::observers::Observe;
use argmin::core::KV;
use rayon::prelude::*;
use serde::Serialize;

use crate::model::{Evaluation, Scene};

pub use design::DesignSpace;
pub use functions::{Point, Row, Side, StudyFunctions};
pub use program::{NonlinearProgram, Values};
pub use qp::QpFailure;
pub use sqp::{
    minimize, minimize_observed, SqpExit, SqpResult, SqpSettings, SqpState, SqpStatus, TraceRow,
};
pub use study::{
    AdhesionMeasure, Constraint, ConstraintQuantity, DesignVariable, Named, Objective,
    OptimizerSettings, ParetoDirection, ParetoSpec, SceneParameter, SettingsError,
    DEFAULT_RELEASE_MARGIN,
};

/// Rows at or below this (in their scaled units: ln rows are relative) count
/// as met in a study.
pub const FEASIBILITY_TOLERANCE: f64 = 1e-7;

/// Most start points drawn per study while looking for `starts` of them with
/// the surfaces in contact (each draw costs one model evaluation).
pub const CONTACT_SEARCH_BUDGET: usize = 2000;

/// The status of a study is the status of its solver.
pub type OptimizationStatus = SqpStatus;

/// What one start of the multistart did.
#[derive(Debug, Clone, PartialEq)]
pub struct StartOutcome {
    /// Index of the start (0 = the baseline design).
    pub index: usize,
    /// Where it started (unit coordinates).
    pub x0: Vec<f64>,
    /// Where it ended, with its values (None when the start had no contact).
    pub point: Option<Point>,
    /// Row multipliers at the end.
    pub multipliers: Vec<f64>,
    /// KKT residual at the end.
    pub kkt_residual: f64,
    /// Finite-difference error estimate of the last gradients.
    pub gradient_error: f64,
    /// How it ended.
    pub status: OptimizationStatus,
    /// Iterations.
    pub iterations: u64,
    /// Model evaluations.
    pub evaluations: usize,
    /// Per-iteration trace.
    pub trace: Vec<TraceRow>,
    /// Subproblem failures met on the way (clarabel's statuses other than Solved).
    pub qp_failures: Vec<qp::QpFailure>,
}

/// One `[[constraint]]` at the reported design.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConstraintReport {
    /// The constrained quantity.
    pub quantity: ConstraintQuantity,
    /// Its value (SI).
    pub value: Option<f64>,
    /// Lower limit.
    pub min: Option<f64>,
    /// Upper limit.
    pub max: Option<f64>,
    /// At its limit (within tolerance) or carrying a multiplier.
    pub active: bool,
    /// The Lagrange multiplier of its scaled row (≥ 0).
    pub multiplier: f64,
    /// d ln(objective) / d ln(limit): relaxing the limit by 1 % changes the
    /// objective by about this many per cent.
    pub shadow_price: f64,
    /// Violation of the scaled row (0 when satisfied).
    pub violation: f64,
    /// A row of it lies at its limit (within 1e-6 of the scaled row), whatever
    /// its multiplier.
    #[serde(skip)]
    pub at_limit: bool,
    /// Over a humidity range: the humidity where the limit binds (its row nearest to
    /// or furthest beyond the limit), at which `value` is taken; absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub humidity: Option<f64>,
}

/// A bound of the design box on which the optimum lies.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ActiveBound {
    /// The design variable.
    pub variable: SceneParameter,
    /// Which bound.
    pub side: Side,
    /// The bound's value (SI).
    pub value: f64,
}

/// Counts over the multistart.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct StartsSummary {
    /// Starts run.
    pub total: usize,
    /// Start points drawn to find `total` with the surfaces in contact.
    pub drawn: usize,
    /// Starts that converged (KKT test met) at a feasible point.
    pub converged: usize,
    /// Starts whose result agrees with the best to 1e-6 relative.
    pub reached_best: usize,
    /// Edges of the best local optima's active sets followed by the vertex
    /// search (the second phase, [`vertices`]).
    pub edges: usize,
    /// Solves the vertex search ran from ends of edges where the objective
    /// is below the optimum's (indices after the `total` starts).
    pub vertex_starts: usize,
    /// Of those, the solves whose result agrees with the best to 1e-6 relative.
    pub vertex_reached_best: usize,
}

/// The result of a study.
#[derive(Debug, Clone)]
pub struct Optimum {
    /// Over a humidity range: the humidity the objective (and `evaluation`) is
    /// taken at; None for a study at one humidity.
    pub objective_humidity: Option<f64>,
    /// How it ended.
    pub status: OptimizationStatus,
    /// The design variables, in file order.
    pub names: Vec<SceneParameter>,
    /// The design found (SI), by variable.
    pub design: Vec<f64>,
    /// The baseline design (SI).
    pub baseline_design: Vec<f64>,
    /// The objective at the design (SI).
    pub objective: f64,
    /// The objective at the baseline (SI).
    pub baseline_objective: f64,
    /// Which objective.
    pub objective_name: Objective,
    /// Constraints at the design.
    pub constraints: Vec<ConstraintReport>,
    /// Bounds on which the design lies.
    pub active_bounds: Vec<ActiveBound>,
    /// For an infeasible study: the constraints that hold its violation up at
    /// the least-violating design, those violated and those at their limit.
    /// (Their multipliers are then 0: at a design that is no optimum the
    /// objective's multipliers mean nothing.)
    pub conflicting: Vec<ConstraintQuantity>,
    /// KKT residual at the design.
    pub kkt_residual: f64,
    /// Finite-difference error estimate at the design.
    pub gradient_error: f64,
    /// Model evaluations over all starts.
    pub evaluations: usize,
    /// Multistart counts.
    pub starts: StartsSummary,
    /// Wall time (s).
    pub time_seconds: f64,
    /// The full evaluation at the design.
    pub evaluation: Evaluation,
    /// The full evaluation at the baseline.
    pub baseline_evaluation: Option<Evaluation>,
    /// The scene at the design.
    pub scene: Scene,
    /// Every start, in index order.
    pub start_outcomes: Vec<StartOutcome>,
    /// The index of the start reported.
    pub best_start: usize,
}

impl Optimum {
    /// Whether the design meets every constraint (each row to [`FEASIBILITY_TOLERANCE`]).
    pub fn feasible(&self) -> bool {
        self.constraints
            .iter()
            .all(|c| c.violation <= FEASIBILITY_TOLERANCE)
    }
}

/// Errors of a study definition (bad input).
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum OptimizeError {
    /// No `[design]` variables.
    #[error("the study has no [design] variables: nothing to optimise (add e.g. sigma = {{ min = \"0.5 nm\", max = \"20 nm\" }})")]
    NoDesign,
    /// No `[objective]`.
    #[error("the study has no [objective]: add [objective] minimize = \"wear_rate\"")]
    NoObjective,
    /// The baseline scene has no contact and no start found one.
    #[error("no start of the multistart has the surfaces in contact: the load cannot hold them together anywhere tried")]
    NoContact,
}

/// A study: what may move, what to minimise, the limits, the settings.
#[derive(Debug, Clone)]
pub struct Study<'a> {
    /// The baseline scene.
    pub scene: &'a Scene,
    /// Design variables.
    pub design: &'a [DesignVariable],
    /// Objective.
    pub objective: Option<Objective>,
    /// Constraints.
    pub constraints: &'a [Constraint],
    /// Settings.
    pub settings: &'a OptimizerSettings,
}

/// An argmin observer of one start, as the caller builds it.
pub type StartObserver = Box<dyn Observe<SqpState> + Send>;

/// Makes the observer of a start from its index (`--verbose` tables).
pub type ObserverFactory<'a> = &'a (dyn Fn(usize) -> StartObserver + Sync);

struct Boxed(StartObserver);

impl Observe<SqpState> for Boxed {
    fn observe_init(
        &mut self,
        name: &str,
        state: &SqpState,
        kv: &KV,
    ) -> Result<(), argmin::core::Error> {
        self.0.observe_init(name, state, kv)
    }

    fn observe_iter(&mut self, state: &SqpState, kv: &KV) -> Result<(), argmin::core::Error> {
        self.0.observe_iter(state, kv)
    }
}

/// The k-th point of a Halton sequence in the given prime base.
fn halton(mut k: u64, base: u64) -> f64 {
    let mut f = 1.0;
    let mut r = 0.0;
    while k > 0 {
        f /= base as f64;
        r += f * (k % base) as f64;
        k /= base;
    }
    r
}

/// splitmix64: a deterministic shift per seed and dimension.
fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

const PRIMES: [u64; 10] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29];

/// The candidate start points: the baseline, then a Halton sequence with a
/// Cranley–Patterson shift drawn from the seed (deterministic), `count` in all.
pub fn start_points(baseline: &[f64], count: usize, seed: u64) -> Vec<Vec<f64>> {
    let n = baseline.len();
    let shift: Vec<f64> = (0..n)
        .map(|i| {
            (splitmix(seed.wrapping_mul(31).wrapping_add(i as u64)) >> 11) as f64
                / (1u64 << 53) as f64
        })
        .collect();
    let mut out = vec![baseline.to_vec()];
    for k in 1..count.max(1) {
        out.push(
            (0..n)
                .map(|i| {
                    let u = halton(k as u64, PRIMES[i % PRIMES.len()]) + shift[i];
                    // Keep starts off the faces, where the stencil is one-sided.
                    0.02 + 0.96 * (u - u.floor())
                })
                .collect(),
        );
    }
    out
}

/// The first `starts` candidate points with the surfaces in contact, drawn in
/// order (at most [`CONTACT_SEARCH_BUDGET`]), and how many were drawn.
fn starts_in_contact(
    functions: &StudyFunctions,
    baseline: &[f64],
    starts: usize,
    seed: u64,
) -> (Vec<Vec<f64>>, usize) {
    let budget = CONTACT_SEARCH_BUDGET.max(starts);
    let candidates = start_points(baseline, budget, seed);
    let mut found = Vec::new();
    let mut drawn = 0;
    // Checked in batches of `starts` in parallel; the order decides, so the
    // choice does not depend on the thread count.
    for batch in candidates.chunks(starts.max(1)) {
        let contact: Vec<bool> = batch
            .par_iter()
            .map(|x| functions.at(x).is_some())
            .collect();
        for (x, c) in batch.iter().zip(contact) {
            drawn += 1;
            if c {
                found.push(x.clone());
                if found.len() == starts {
                    return (found, drawn);
                }
            }
        }
    }
    (found, drawn)
}

/// The solver settings of a study.
pub fn sqp_settings(settings: &OptimizerSettings, remaining: Duration) -> SqpSettings {
    SqpSettings {
        tolerance: settings.tolerance,
        feasibility_tolerance: FEASIBILITY_TOLERANCE,
        max_iterations: settings.max_iterations as u64,
        time_limit: Some(remaining),
        ..SqpSettings::default()
    }
}

fn run_start(
    functions: &StudyFunctions,
    index: usize,
    x0: Vec<f64>,
    settings: &OptimizerSettings,
    deadline: Instant,
    observers: Option<ObserverFactory>,
) -> StartOutcome {
    let remaining = deadline.saturating_duration_since(Instant::now());
    let sqp = sqp_settings(settings, remaining);
    let r = minimize_observed(functions, &x0, &sqp, observers.map(|f| Boxed(f(index))));
    let point = r.objective.is_finite().then(|| Point::from_result(&r));
    StartOutcome {
        index,
        x0,
        point,
        multipliers: r.multipliers.clone(),
        kkt_residual: r.kkt_residual,
        gradient_error: r.gradient_error,
        status: r.status,
        iterations: r.iterations,
        evaluations: r.evaluations,
        trace: r.trace,
        qp_failures: r.qp_failures,
    }
}

/// Runs a study: multistart SQP in parallel, deterministic for any thread count.
pub fn optimize(study: &Study) -> Result<Optimum, OptimizeError> {
    optimize_observed(study, None)
}

/// As [`optimize`], with an argmin observer per start (made by `observers`
/// from the start's index); each observer sees only its own start.
pub fn optimize_observed(
    study: &Study,
    observers: Option<ObserverFactory>,
) -> Result<Optimum, OptimizeError> {
    if study.design.is_empty() {
        return Err(OptimizeError::NoDesign);
    }
    let objective = study.objective.ok_or(OptimizeError::NoObjective)?;
    let t0 = Instant::now();
    let deadline = t0 + study.settings.time_limit;
    let space = DesignSpace::new(study.scene, study.design);
    let functions = StudyFunctions::new(space, objective, study.constraints);
    let baseline_x = functions.space.baseline_unit();
    let (starts, drawn) = starts_in_contact(
        &functions,
        &baseline_x,
        study.settings.starts,
        study.settings.seed,
    );
    if starts.is_empty() {
        return Err(OptimizeError::NoContact);
    }
    let mut outcomes: Vec<StartOutcome> = starts
        .into_par_iter()
        .enumerate()
        .map(|(i, x0)| run_start(&functions, i, x0, study.settings, deadline, observers))
        .collect();
    let total = outcomes.len();
    let search = vertex_search(
        &functions,
        &mut outcomes,
        study.settings,
        deadline,
        observers,
    );
    assemble(
        study,
        &functions,
        objective,
        outcomes,
        Multistart {
            total,
            drawn,
            search,
        },
        t0,
    )
}

/// What the vertex search added to the starts' outcomes.
#[derive(Debug, Clone, Copy, Default)]
struct VertexSearch {
    edges: usize,
    evaluations: usize,
}

struct Multistart {
    total: usize,
    drawn: usize,
    search: VertexSearch,
}

/// A scaled row within this of its limit (ln units: 1e-6 relative) is at it:
/// `active` in the report, and part of the conflict of an infeasible study.
const AT_LIMIT: f64 = 1e-6;

/// Relative (ln objective) improvement below which a new optimum is the same
/// one: the 1e-6 of the global-optimum contract and of `reached_best`.
const IMPROVEMENT: f64 = 1e-6;

/// The second phase: from each distinct feasible optimal end, solve from the
/// ends of its active set's edges that look better than the best end
/// ([`vertices::edge_starts`]); repeat from the optima those solves find that
/// improve on the best, at most n rounds. The solves are appended to
/// `outcomes` (indices after the starts).
fn vertex_search(
    functions: &StudyFunctions,
    outcomes: &mut Vec<StartOutcome>,
    settings: &OptimizerSettings,
    deadline: Instant,
    observers: Option<ObserverFactory>,
) -> VertexSearch {
    let mut search = VertexSearch::default();
    let mut searched: Vec<f64> = Vec::new();
    let mut from = 0;
    for _ in 0..functions.dim() {
        let ends = distinct_optima(&outcomes[from..]);
        let Some(best) = distinct_optima(outcomes)
            .first()
            .map(|o| o.point.as_ref().unwrap().objective)
        else {
            break;
        };
        let known = |f: f64| searched.iter().any(|&s| (f - s).abs() <= IMPROVEMENT);
        let record = searched.iter().copied().fold(f64::INFINITY, f64::min);
        // The first round searches every optimum the starts found; later
        // rounds only new optima better than every one searched.
        let to_search: Vec<&StartOutcome> = ends
            .into_iter()
            .filter(|o| {
                let f = o.point.as_ref().unwrap().objective;
                !known(f) && (searched.is_empty() || f < record - IMPROVEMENT)
            })
            .collect();
        if to_search.is_empty() || Instant::now() >= deadline {
            break;
        }
        let mut starts = Vec::new();
        for o in to_search {
            let point = o.point.as_ref().unwrap();
            searched.push(point.objective);
            let found = vertices::edge_starts(functions, point, &o.multipliers, best);
            search.edges += found.edges;
            search.evaluations += found.evaluations;
            starts.extend(found.starts);
        }
        from = outcomes.len();
        let solved: Vec<StartOutcome> = starts
            .into_par_iter()
            .enumerate()
            .map(|(k, x0)| run_start(functions, from + k, x0, settings, deadline, observers))
            .collect();
        if solved.is_empty() {
            break;
        }
        outcomes.extend(solved);
    }
    search
}

/// The feasible `optimal` ends, best first, one per objective value (within
/// [`IMPROVEMENT`]); ties go to the lower index.
fn distinct_optima(outcomes: &[StartOutcome]) -> Vec<&StartOutcome> {
    let mut ends: Vec<&StartOutcome> = outcomes
        .iter()
        .filter(|o| o.status == OptimizationStatus::Optimal)
        .filter(|o| {
            o.point
                .as_ref()
                .is_some_and(|p| p.max_violation() <= FEASIBILITY_TOLERANCE)
        })
        .collect();
    ends.sort_by(|a, b| {
        let (pa, pb) = (a.point.as_ref().unwrap(), b.point.as_ref().unwrap());
        pa.objective
            .total_cmp(&pb.objective)
            .then(a.index.cmp(&b.index))
    });
    let mut out: Vec<&StartOutcome> = Vec::new();
    for o in ends {
        let f = o.point.as_ref().unwrap().objective;
        if out
            .last()
            .is_none_or(|l| (f - l.point.as_ref().unwrap().objective).abs() > IMPROVEMENT)
        {
            out.push(o);
        }
    }
    out
}

/// The study's result from its starts' outcomes.
fn assemble(
    study: &Study,
    functions: &StudyFunctions,
    objective: Objective,
    outcomes: Vec<StartOutcome>,
    multistart: Multistart,
    t0: Instant,
) -> Result<Optimum, OptimizeError> {
    let baseline_x = functions.space.baseline_unit();
    let evaluations =
        outcomes.iter().map(|o| o.evaluations).sum::<usize>() + multistart.search.evaluations;

    // The best: lowest objective among feasible ends (optimal first), else the least violating.
    let feasible = |o: &&StartOutcome| {
        o.point
            .as_ref()
            .is_some_and(|p| p.max_violation() <= FEASIBILITY_TOLERANCE)
    };
    let by_objective = |a: &&StartOutcome, b: &&StartOutcome| {
        let (pa, pb) = (a.point.as_ref().unwrap(), b.point.as_ref().unwrap());
        pa.objective
            .total_cmp(&pb.objective)
            .then(a.index.cmp(&b.index))
    };
    let optimal = outcomes
        .iter()
        .filter(|o| o.status == OptimizationStatus::Optimal)
        .filter(feasible)
        .min_by(by_objective);
    let any_feasible = outcomes.iter().filter(feasible).min_by(by_objective);
    let best = match optimal.or(any_feasible) {
        Some(b) => b,
        None => outcomes
            .iter()
            .filter(|o| o.point.is_some())
            .min_by(|a, b| {
                let (pa, pb) = (a.point.as_ref().unwrap(), b.point.as_ref().unwrap());
                pa.max_violation()
                    .total_cmp(&pb.max_violation())
                    .then(a.index.cmp(&b.index))
            })
            .ok_or(OptimizeError::NoContact)?,
    };
    let best_point = best.point.clone().expect("best start has a point");
    // Infeasible only when every start ended at a stationary point of the
    // violation; a start stopped otherwise says how it stopped.
    let status = if best_point.max_violation() <= FEASIBILITY_TOLERANCE {
        best.status
    } else if outcomes
        .iter()
        .all(|o| o.status == OptimizationStatus::Infeasible)
    {
        OptimizationStatus::Infeasible
    } else {
        match best.status {
            OptimizationStatus::Optimal => OptimizationStatus::Stalled,
            s => s,
        }
    };
    let reaches_best = |o: &&StartOutcome| {
        let f = o.point.as_ref().unwrap().objective;
        (f - best_point.objective).abs() <= 1e-6 * (1.0 + best_point.objective.abs())
    };
    let (starts, vertex) = outcomes.split_at(multistart.total);
    let reached_best = starts.iter().filter(feasible).filter(reaches_best).count();
    let vertex_reached_best = vertex.iter().filter(feasible).filter(reaches_best).count();
    let converged = starts
        .iter()
        .filter(|o| o.status == OptimizationStatus::Optimal)
        .filter(feasible)
        .count();

    let scene = functions.scene_at(&best_point.x);
    let evaluation = crate::model::evaluate(&scene, &functions.options);
    let baseline_scene = match functions.objective_humidity {
        Some(h) => functions::at_humidity(study.scene.clone(), h),
        None => study.scene.clone(),
    };
    let baseline_evaluation = {
        let ev = crate::model::evaluate(&baseline_scene, &functions.options);
        (ev.status == crate::model::Status::Ok).then_some(ev)
    };
    let constraints = constraint_reports(
        functions,
        study.constraints,
        &best_point,
        &best.multipliers,
        &evaluation,
        &scene,
    );
    // At the least-violating design of an infeasible study the conflict is
    // every limit that holds the violation up: those violated and those at
    // their limit (pull-off ≥ 48 mN against A_r ≤ A_n, the second met
    // exactly). Its rows' multipliers are the objective's KKT estimate at a
    // point that is no optimum: they mean nothing there, and are set to 0.
    let infeasible = status == OptimizationStatus::Infeasible;
    let conflicting = if infeasible {
        constraints
            .iter()
            .filter(|c| c.violation > FEASIBILITY_TOLERANCE || c.at_limit)
            .map(|c| c.quantity)
            .collect()
    } else {
        Vec::new()
    };
    let constraints = if infeasible {
        constraints
            .into_iter()
            .map(|c| ConstraintReport {
                multiplier: 0.0,
                shadow_price: 0.0,
                ..c
            })
            .collect()
    } else {
        constraints
    };
    let names: Vec<SceneParameter> = functions
        .space
        .variables
        .iter()
        .map(|v| v.quantity)
        .collect();
    let design = functions.space.values(&best_point.x);
    let active_bounds = functions
        .space
        .variables
        .iter()
        .zip(&best_point.x)
        .filter_map(|(v, &u)| {
            if u <= 1e-6 {
                Some(ActiveBound {
                    variable: v.quantity,
                    side: Side::Min,
                    value: v.min,
                })
            } else if u >= 1.0 - 1e-6 {
                Some(ActiveBound {
                    variable: v.quantity,
                    side: Side::Max,
                    value: v.max,
                })
            } else {
                None
            }
        })
        .collect();
    Ok(Optimum {
        objective_humidity: functions.objective_humidity,
        status,
        baseline_design: functions.space.values(&baseline_x),
        names,
        design,
        objective: functions::objective_value(objective, &evaluation, &scene),
        baseline_objective: baseline_evaluation.as_ref().map_or(f64::NAN, |ev| {
            functions::objective_value(objective, ev, &baseline_scene)
        }),
        objective_name: objective,
        constraints,
        active_bounds,
        conflicting,
        kkt_residual: best.kkt_residual,
        gradient_error: best.gradient_error,
        evaluations,
        starts: StartsSummary {
            total: multistart.total,
            drawn: multistart.drawn,
            converged,
            reached_best,
            edges: multistart.search.edges,
            vertex_starts: outcomes.len() - multistart.total,
            vertex_reached_best,
        },
        time_seconds: t0.elapsed().as_secs_f64(),
        evaluation,
        baseline_evaluation,
        scene,
        best_start: best.index,
        start_outcomes: outcomes,
    })
}

fn constraint_reports(
    functions: &StudyFunctions,
    constraints: &[Constraint],
    point: &Point,
    multipliers: &[f64],
    ev: &Evaluation,
    scene: &Scene,
) -> Vec<ConstraintReport> {
    constraints
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let rows: Vec<(usize, &Row)> = functions
                .rows
                .iter()
                .enumerate()
                .filter(|(_, r)| r.constraint == i)
                .collect();
            let (mut multiplier, mut shadow, mut violation, mut active, mut at_limit) =
                (0.0f64, 0.0, 0.0f64, false, false);
            // Over a humidity range: the humidity of the row nearest its limit (none
            // where every humidity gives the same value: the limit binds at all alike).
            let (lo, hi) = rows
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (j, _)| {
                    (a.min(point.rows[*j]), b.max(point.rows[*j]))
                });
            let binding = rows
                .iter()
                .max_by(|a, b| point.rows[a.0].total_cmp(&point.rows[b.0]))
                .and_then(|(_, r)| r.humidity)
                .filter(|_| hi - lo > 1e-12 * hi.abs().max(1.0));
            for (j, r) in rows {
                let l = multipliers.get(j).copied().unwrap_or(0.0);
                let g = point.rows[j];
                violation = violation.max(g.max(0.0));
                at_limit |= g >= -AT_LIMIT;
                if g >= -AT_LIMIT || l > 1e-9 {
                    active = true;
                }
                if l >= multiplier {
                    multiplier = l;
                    shadow = r.shadow_price(l) + 0.0; // no "-0" in reports
                }
            }
            let value = match binding {
                Some(h) => {
                    let s = functions::at_humidity(scene.clone(), h);
                    let e = crate::model::evaluate(&s, &functions.options);
                    functions::quantity_value(c.quantity, &e, &s)
                }
                None => functions::quantity_value(c.quantity, ev, scene),
            };
            ConstraintReport {
                quantity: c.quantity,
                value,
                min: c.min,
                max: c.max,
                active,
                multiplier,
                shadow_price: shadow,
                violation,
                at_limit,
                humidity: binding,
            }
        })
        .collect()
}
