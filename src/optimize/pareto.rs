//! The wear–adhesion trade-off of a study by the ε-constraint method.
//!
//! Wear (the study's objective) is minimised with the adhesion measure held at
//! a target ε, for ε across the whole reachable adhesion range; every
//! constraint of the study stays in force. That gives the full wear-versus-
//! adhesion curve; its non-dominated part, for the chosen
//! [`ParetoDirection`], is the Pareto front.
//!
//! * **Strength.** Points are compared on the *adhesion strength* s, in log10
//!   units: `log10 F` for the pull-off force, `log10 γ` for the work of
//!   adhesion and `-log10 θ` for the elastic adhesion index (a larger θ means
//!   less adhesion).
//! * **Holding the measure at ε.** The pull-off force and θ are held by two
//!   constraint rows `min = max = ε`; γ, a design variable, is removed from
//!   the design and set to ε in the scene. One-sided targets (range search,
//!   the floor end) use one row, or for γ a narrowed bound.
//! * **Range.** The least-wear design of the study sits at strength `s_w`. The
//!   reachable range is bracketed by the strongest and the weakest adhesion any
//!   design reaches under every row of the study and A_r ≤ A_n (an explicit
//!   row, so that a design whose real area would exceed the nominal one is
//!   judged by it rather than being a wall), each found as an optimisation
//!   problem from the study's starts, and by the box's corners where one is
//!   stronger still; the study's own limits on the measure cap it. Each end is
//!   then found by bisection on the feasibility of "strength ≥ s" (or ≤ s),
//!   warm-started from the last feasible probe and, failing that, from the
//!   extreme's design. A pull-off force below [`PULL_OFF_FLOOR`] counts as
//!   none: that end of the sweep is the one-sided point "pull-off ≤ floor".
//! * **Targets.** `points` strengths evenly spaced in log10 when the range
//!   spans a decade or more, evenly in value otherwise, ordered from the
//!   preferred end; the target nearest `s_w` is moved onto it, so the front
//!   ends exactly at the study's least-wear design.
//! * **Points spent on the front.** Where the ε-curve turns — the least wear
//!   holds over a stretch of adhesion, so every point past the strongest
//!   of them is dominated — the turn is located by bisection between the last
//!   point above the least wear and the first at it (to [`RANGE_RESOLUTION`],
//!   at most [`MAX_TURN_STEPS`] solves; none when that first point is the
//!   least-wear design itself), and `points` targets are spread again
//!   from the preferred end to the turn (points already solved within a
//!   quarter spacing of a target stand for it). The dominated points past the
//!   turn stay in the sweep, after the front's, and do not count against
//!   `points`.
//! * **Solves.** Each ε-point is the study's own [`optimize`] with the ε-row
//!   added, run with the study's multistart, so that no point is worse than a
//!   standalone run at its ε. Points are solved in waves of [`WAVE`] in
//!   parallel (rayon), each also from the nearest solution known before the
//!   wave. Then every point is re-solved from both neighbours' designs,
//!   keeping the better design, until no point improves
//!   ([`MAX_REFINE_ROUNDS`] at most). Each step reads only designs
//!   known before it, so the result is the same for any thread count; the
//!   [`Observer`] receives the points in order once they are final.
//! * **Dominance.** A point is dominated when an earlier point of the sweep
//!   (nearer the preferred end, so with an adhesion at least as good) has a
//!   wear no larger (to [`WEAR_TOLERANCE`] relative): it is decided as soon as
//!   the point is known. Feasible, non-dominated points are the front.
//! * **Knee.** In normalised log coordinates (strength clamped to the
//!   reachable range the report prints, and log10 wear, each scaled to [0, 1]
//!   over the front), the interior front point farthest from the chord joining
//!   the front's ends; none when the front has fewer than three points or is
//!   straight (distance < [`KNEE_MIN_DISTANCE`]).

use std::time::Instant;

use rayon::prelude::*;
use serde::Serialize;

use super::study::{
    AdhesionMeasure, Constraint, ConstraintQuantity, DesignVariable, Objective, OptimizerSettings,
    ParetoDirection, ParetoSpec, SceneParameter,
};
use super::{optimize, OptimizationStatus, OptimizeError, Study};
use crate::model::{self, Evaluation, EvaluationOptions, Quadrature, Scene, Status};

/// A pull-off force below this (N) counts as none: a femtonewton is three
/// decades under the thermal-noise force of an AFM cantilever, and far under
/// any restoring force a MEMS structure has.
pub const PULL_OFF_FLOOR: f64 = 1e-15;

/// Points solved together; fixed, so that warm starts do not depend on the
/// thread count.
pub const WAVE: usize = 4;

/// Relative wear difference below which two points count as equally good.
pub const WEAR_TOLERANCE: f64 = 1e-6;

/// Strength difference (log10 units) below which two adhesions count as equal.
pub const STRENGTH_TOLERANCE: f64 = 1e-6;

/// Smallest normalised distance to the chord for a knee.
pub const KNEE_MIN_DISTANCE: f64 = 1e-3;

/// Bisection stops when the bracket of a range end is this narrow (decades).
pub const RANGE_RESOLUTION: f64 = 0.01;

/// Most re-solve rounds of the sweep (each point from its neighbours' designs).
pub const MAX_REFINE_ROUNDS: usize = 4;

/// Most feasibility probes per end of the range.
pub const MAX_PROBES: usize = 12;

/// Most solves locating where the ε-curve turns (see the module docs).
pub const MAX_TURN_STEPS: usize = 8;

/// The front's tuning, one documented field each (defaults: the constants above).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParetoSettings {
    /// Points solved together (default [`WAVE`]); fixed, so that warm starts do
    /// not depend on the thread count.
    pub wave: usize,
    /// Relative wear difference below which two points count as equally good
    /// (default [`WEAR_TOLERANCE`]).
    pub wear_tolerance: f64,
    /// Strength difference (log10 units) below which two adhesions count as equal
    /// (default [`STRENGTH_TOLERANCE`]).
    pub strength_tolerance: f64,
    /// Smallest normalised distance to the chord for a knee (default
    /// [`KNEE_MIN_DISTANCE`]).
    pub knee_min_distance: f64,
    /// Bisection of a range end stops when its bracket is this narrow, in decades
    /// (default [`RANGE_RESOLUTION`]).
    pub range_resolution: f64,
    /// Most re-solve rounds of the sweep (default [`MAX_REFINE_ROUNDS`]).
    pub max_refine_rounds: usize,
    /// Most feasibility probes per end of the range (default [`MAX_PROBES`]).
    pub max_probes: usize,
    /// Most solves locating the turn of the ε-curve (default [`MAX_TURN_STEPS`]).
    pub max_turn_steps: usize,
}

impl Default for ParetoSettings {
    fn default() -> Self {
        ParetoSettings {
            wave: WAVE,
            wear_tolerance: WEAR_TOLERANCE,
            strength_tolerance: STRENGTH_TOLERANCE,
            knee_min_distance: KNEE_MIN_DISTANCE,
            range_resolution: RANGE_RESOLUTION,
            max_refine_rounds: MAX_REFINE_ROUNDS,
            max_probes: MAX_PROBES,
            max_turn_steps: MAX_TURN_STEPS,
        }
    }
}

/// How the front came out (contract words).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FrontStatus {
    /// A front of two or more designs: wear and adhesion pull against each other.
    Ok,
    /// The front is one design: the least-wear design is also the best-adhesion design.
    NoTradeOff,
    /// No point met the study's constraints.
    Infeasible,
}

impl FrontStatus {
    /// The status word.
    pub fn as_str(self) -> &'static str {
        match self {
            FrontStatus::Ok => "ok",
            FrontStatus::NoTradeOff => "no_trade_off",
            FrontStatus::Infeasible => "infeasible",
        }
    }
}

/// The adhesion measure held at a target.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// Strength equal to s.
    Equal(f64),
    /// Strength at most s.
    AtMost(f64),
    /// Strength at least s.
    AtLeast(f64),
}

/// One design on the wear–adhesion curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrontPoint {
    /// Position in the sweep (0 = the preferred adhesion end).
    pub index: usize,
    /// The target ε of the measure (SI; θ dimensionless).
    pub target: f64,
    /// Whether ε was held exactly ("equal") or as a bound ("at_most", "at_least").
    pub target_kind: &'static str,
    /// The measure at the design (SI; may underflow to 0 for the pull-off).
    pub adhesion: f64,
    /// log10 of the measure (finite where the value underflows).
    pub log10_adhesion: f64,
    /// The adhesion strength (log10 units, larger = more adhesion).
    pub strength: f64,
    /// The study's objective at the design (SI).
    pub objective: f64,
    /// Wear rate k·A_r at the design (m³/m).
    pub wear_rate: f64,
    /// How the solve ended.
    pub status: OptimizationStatus,
    /// The design meets every constraint of the study and the target.
    pub feasible: bool,
    /// An earlier point is at least as good in adhesion and wear.
    pub dominated: bool,
    /// Feasible and not dominated.
    pub on_front: bool,
    /// The design (SI), in the study's variable order.
    pub design: Vec<f64>,
    /// The solution came from the neighbour's warm start, not the multistart.
    pub warm_started: bool,
    /// Model evaluations spent on this point.
    pub evaluations: usize,
}

/// A design with its measure and wear (the baseline, the least-wear design).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reference {
    /// The measure (SI).
    pub adhesion: f64,
    /// log10 of the measure.
    pub log10_adhesion: f64,
    /// The objective (SI).
    pub objective: f64,
    /// Wear rate (m³/m).
    pub wear_rate: f64,
    /// The design (SI).
    pub design: Vec<f64>,
    /// Whether the design meets every constraint of the study.
    pub feasible: bool,
}

/// The result of a sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Front {
    /// How it came out.
    pub status: FrontStatus,
    /// The adhesion measure.
    pub measure: AdhesionMeasure,
    /// The preferred end.
    pub direction: ParetoDirection,
    /// The objective minimised.
    pub objective_name: Objective,
    /// The design variables, in file order.
    pub names: Vec<SceneParameter>,
    /// Every point of the sweep, from the preferred adhesion end.
    pub points: Vec<FrontPoint>,
    /// Index in `points` of the knee.
    pub knee: Option<usize>,
    /// Where the ε-curve turns: the index in `points` of the front's far end,
    /// the first design (from the preferred end) at the least wear; the
    /// points after it are dominated and do not count against the points
    /// asked for. None where the curve does not turn.
    pub turn: Option<usize>,
    /// The reachable range of the measure, (lowest, highest) strength in log10 units.
    pub strength_range: (f64, f64),
    /// The low end is the pull-off floor (one-sided).
    pub floor_end: bool,
    /// The study's baseline scene.
    pub baseline: Option<Reference>,
    /// The study's least-wear design (no adhesion target).
    pub least_wear: Reference,
    /// The strength of `least_wear`.
    pub least_wear_strength: f64,
    /// Model evaluations over the whole sweep (range search included).
    pub evaluations: usize,
    /// Range-search probes run.
    pub probes: usize,
    /// Wall time (s).
    pub time_seconds: f64,
    /// The scene's factor on the statistical real area (1 unless the problem's
    /// `contact_model` is `bem_corrected`).
    pub real_area_scale: f64,
    /// Over a humidity range: the humidity at which every point's adhesion and
    /// wear are measured (the objective's: the file's `design_humidity`, else
    /// the one where the baseline design's objective is worst), while every
    /// limit of the study holds at each humidity of the range. None for a
    /// scene at one humidity.
    pub adhesion_humidity: Option<f64>,
}

impl Front {
    /// The indices of the front's points.
    pub fn front_indices(&self) -> Vec<usize> {
        self.points
            .iter()
            .filter(|p| p.on_front)
            .map(|p| p.index)
            .collect()
    }
}

/// Receives the sweep as it runs. Every method has a default that does nothing.
pub trait Observer: Sync {
    /// The range search begins.
    fn range_started(&self) {}
    /// A range probe finished (any thread).
    fn probe_done(&self) {}
    /// The sweep of `points` targets begins.
    fn sweep_started(&self, _points: usize) {}
    /// A target of the sweep, or of the turn's search, was solved (any thread).
    fn point_solved(&self) {}
    /// The points are being re-solved from their neighbours' designs.
    fn refine_started(&self) {}
    /// The ε-curve turns: `solves` more targets, at most, spend the points on
    /// the front.
    fn turn_started(&self, _solves: usize) {}
    /// A point is final: called in sweep order from the calling thread.
    fn point_done(&self, _point: &FrontPoint) {}
}

/// An observer that ignores everything.
pub struct Silent;
impl Observer for Silent {}

/// Errors of a sweep definition (bad input).
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum ParetoError {
    /// The study itself is not optimisable.
    #[error(transparent)]
    Study(#[from] OptimizeError),
    /// `work_of_adhesion` is the measure but not a design variable.
    #[error("[pareto] adhesion = \"work_of_adhesion\" needs work_of_adhesion among the [design] variables")]
    WorkOfAdhesionFixed,
    /// Points out of range.
    #[error("{0} points: a front needs 2..=200 points")]
    Points(usize),
}

/// The measure's value and log10 at an evaluation (None where it does not exist):
/// its row of the quantity table's ([`crate::model::Quantity::value`],
/// [`crate::model::Quantity::log10_value`]).
pub fn measure_of(m: AdhesionMeasure, ev: &Evaluation, scene: &Scene) -> Option<(f64, f64)> {
    let q = m.quantity();
    q.value(ev, scene).zip(q.log10_value(ev, scene))
}

/// Strength (log10 units, larger = more adhesion) of a measure's log10.
pub fn strength_of(m: AdhesionMeasure, log10: f64) -> f64 {
    match m {
        AdhesionMeasure::ElasticAdhesionIndex => -log10,
        _ => log10,
    }
}

/// The measure's value at a strength.
pub fn value_at(m: AdhesionMeasure, strength: f64) -> f64 {
    match m {
        AdhesionMeasure::ElasticAdhesionIndex => 10f64.powf(-strength),
        _ => 10f64.powf(strength),
    }
}

/// The SI unit of a measure ("" for θ).
pub fn unit_of(m: AdhesionMeasure) -> &'static str {
    m.quantity().dimension().si_unit()
}

/// One solve of the ε-constrained study.
#[derive(Debug, Clone)]
struct Solved {
    status: OptimizationStatus,
    feasible: bool,
    objective: f64,
    wear_rate: f64,
    value: f64,
    log10: f64,
    strength: f64,
    design: Vec<f64>,
    scene: Scene,
    evaluations: usize,
}

/// A study with a Pareto spec, ready to sweep.
struct Sweep<'a> {
    study: &'a Study<'a>,
    measure: AdhesionMeasure,
    objective: Objective,
    options: EvaluationOptions,
    warm_settings: OptimizerSettings,
    settings: ParetoSettings,
}

impl Sweep<'_> {
    fn evaluate(&self, scene: &Scene) -> Evaluation {
        model::evaluate(scene, &self.options)
    }

    /// The original design vector at a scene.
    fn design_at(&self, scene: &Scene) -> Vec<f64> {
        self.study
            .design
            .iter()
            .map(|d| d.name.get(scene))
            .collect()
    }

    fn reference(&self, scene: &Scene, feasible: bool) -> Option<Reference> {
        let ev = self.evaluate(scene);
        if ev.status != Status::Ok {
            return None;
        }
        let (value, log10) = measure_of(self.measure, &ev, scene)?;
        Some(Reference {
            adhesion: value,
            log10_adhesion: log10,
            objective: super::functions::objective_value(self.objective, &ev, scene),
            wear_rate: ev.wear_rate,
            design: self.design_at(scene),
            feasible,
        })
    }

    /// The study with the measure held at `target`, around `scene`: the
    /// ε-row added (pull-off force, θ), or γ fixed or its bound narrowed
    /// (work of adhesion). None when a one-sided γ target leaves no range.
    fn held_at(
        &self,
        target: Target,
        scene: &Scene,
    ) -> Option<(Scene, Vec<DesignVariable>, Vec<Constraint>)> {
        let mut scene = scene.clone();
        let mut design: Vec<DesignVariable> = self.study.design.to_vec();
        let mut constraints: Vec<Constraint> = self.study.constraints.to_vec();
        let (Target::Equal(s) | Target::AtMost(s) | Target::AtLeast(s)) = target;
        let v = value_at(self.measure, s);
        let quantity = match ConstraintQuantity::from_quantity(self.measure.quantity()) {
            Some(q) => q,
            // γ is no constraint: the design holds it.
            None => {
                let i = design
                    .iter()
                    .position(|d| d.name == SceneParameter::WorkOfAdhesion)?;
                match target {
                    Target::Equal(_) => {
                        design.remove(i);
                        scene.work_of_adhesion = v;
                    }
                    Target::AtMost(_) | Target::AtLeast(_) => {
                        let var = &mut design[i];
                        if matches!(target, Target::AtMost(_)) {
                            if v <= var.min {
                                return None;
                            }
                            var.max = var.max.min(v);
                        } else {
                            if v >= var.max {
                                return None;
                            }
                            var.min = var.min.max(v);
                        }
                        scene.work_of_adhesion = scene.work_of_adhesion.clamp(var.min, var.max);
                    }
                }
                return Some((scene, design, constraints));
            }
        };
        let (min, max) = match target {
            Target::Equal(_) => (Some(v), Some(v)),
            Target::AtMost(_) | Target::AtLeast(_) => {
                // "At most this strength" is an upper bound on the value, or a
                // lower one for θ.
                let inverted = self.measure == AdhesionMeasure::ElasticAdhesionIndex;
                let upper = matches!(target, Target::AtMost(_)) != inverted;
                ((!upper).then_some(v), upper.then_some(v))
            }
        };
        // Over a humidity range the measure is taken at the objective's
        // humidity (fixed for the whole front by `pareto_with`): the row holds
        // there, not at each humidity (where one value could not be held at all).
        constraints.push(Constraint {
            quantity,
            min,
            max,
            only_at_objective_humidity: true,
        });
        Some((scene, design, constraints))
    }

    /// Minimise the objective with the measure held at `target`, from `scene`
    /// (its design is start 0) with `settings`: the study's own [`optimize`]
    /// on [`Sweep::held_at`]'s study.
    fn solve(&self, target: Target, scene: &Scene, settings: &OptimizerSettings) -> Option<Solved> {
        let (scene, design, constraints) = self.held_at(target, scene)?;
        let (status, feasible, end_scene, evaluations) = if design.is_empty() {
            // Only γ moved and it is fixed: the point is the scene itself.
            let space = super::DesignSpace::new(&scene, &[]);
            let f = super::StudyFunctions::new(space, self.objective, &constraints);
            let feasible = f.at(&[])?.max_violation() <= super::FEASIBILITY_TOLERANCE;
            let status = if feasible {
                OptimizationStatus::Optimal
            } else {
                OptimizationStatus::Infeasible
            };
            (status, feasible, scene, 1)
        } else {
            let o = optimize(&Study {
                scene: &scene,
                design: &design,
                objective: Some(self.objective),
                constraints: &constraints,
                settings,
            })
            .ok()?;
            (o.status, o.feasible(), o.scene, o.evaluations)
        };
        self.solved(status, feasible, end_scene, evaluations + 1)
    }

    /// A solve's result with its measure, wear and design.
    fn solved(
        &self,
        status: OptimizationStatus,
        feasible: bool,
        scene: Scene,
        evaluations: usize,
    ) -> Option<Solved> {
        let ev = self.evaluate(&scene);
        if ev.status != Status::Ok {
            return None;
        }
        let (value, log10) = measure_of(self.measure, &ev, &scene)?;
        Some(Solved {
            status,
            feasible,
            objective: super::functions::objective_value(self.objective, &ev, &scene),
            wear_rate: ev.wear_rate,
            value,
            log10,
            strength: strength_of(self.measure, log10),
            design: self.design_at(&scene),
            scene,
            evaluations,
        })
    }

    /// The study's own multistart at `target` (the very run a standalone
    /// `optimize` with the ε-row makes), and one start from `warm` (the
    /// nearest solved neighbour); the better of the two. Returns it, whether
    /// the warm start gave it, and the evaluations spent.
    fn solve_point(&self, target: Target, warm: Option<&Scene>) -> (Option<Solved>, bool, usize) {
        let standalone = self.solve(target, self.study.scene, self.study.settings);
        let warm = warm.and_then(|w| self.solve(target, w, &self.warm_settings));
        let evaluations = [&standalone, &warm]
            .iter()
            .map(|r| r.as_ref().map_or(0, |s| s.evaluations))
            .sum();
        match (standalone, warm) {
            (Some(s), Some(w)) if improves(&w, Some(&s), 1e-12) => (Some(w), true, evaluations),
            (Some(s), _) => (Some(s), false, evaluations),
            (None, w) => {
                let from_warm = w.is_some();
                (w, from_warm, evaluations)
            }
        }
    }
}

/// The study's own limits on the measure, as (lowest, highest) strength.
fn study_limits(m: AdhesionMeasure, constraints: &[Constraint]) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    // γ is no constraint: the study cannot limit it but by its design bounds.
    let Some(q) = ConstraintQuantity::from_quantity(m.quantity()) else {
        return (lo, hi);
    };
    for c in constraints.iter().filter(|c| c.quantity == q) {
        for (bound, is_max) in [(c.min, false), (c.max, true)] {
            let Some(b) = bound.filter(|b| *b > 0.0) else {
                continue;
            };
            let s = strength_of(m, b.log10());
            // A maximum of the value caps the strength, except for θ.
            if is_max != (m == AdhesionMeasure::ElasticAdhesionIndex) {
                hi = hi.min(s);
            } else {
                lo = lo.max(s);
            }
        }
    }
    (lo, hi)
}

/// The adhesion measure as the objective of a program: f = ∓ln(10)·strength
/// (maximised upward, minimised downward; below the pull-off floor the
/// strength counts as the floor's), under every row of the study and the
/// plausibility limit A_r ≤ A_n as an explicit row
/// ([`super::StudyFunctions::area_row`]), on the study's design box.
struct MeasureProgram {
    functions: super::StudyFunctions,
    measure: AdhesionMeasure,
    up: bool,
    floor: f64,
}

impl MeasureProgram {
    fn new(sweep: &Sweep, up: bool, floor: f64) -> Self {
        let mut constraints: Vec<Constraint> = sweep.study.constraints.to_vec();
        constraints.push(Constraint {
            quantity: ConstraintQuantity::RealAreaFraction,
            min: None,
            max: Some(1.0),
            only_at_objective_humidity: false,
        });
        let space = super::DesignSpace::new(sweep.study.scene, sweep.study.design);
        let mut functions = super::StudyFunctions::new(space, sweep.objective, &constraints);
        functions.options.pull_off |= sweep.options.pull_off;
        MeasureProgram {
            functions,
            measure: sweep.measure,
            up,
            floor,
        }
    }
}

impl super::NonlinearProgram for MeasureProgram {
    fn dimension(&self) -> usize {
        self.functions.dim()
    }

    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        self.functions.bounds()
    }

    fn objective(&self, x: &[f64]) -> Option<f64> {
        self.evaluate(x, &[]).map(|v| v.objective)
    }

    fn constraints(&self, x: &[f64]) -> Option<Vec<f64>> {
        self.evaluate(x, &[]).map(|v| v.constraints)
    }

    /// The study's rows at x, with the strength (floored) as the objective;
    /// None where x is not evaluable or has no measure.
    fn evaluate(&self, x: &[f64], near: &[f64]) -> Option<super::Values> {
        let (mut values, ev) = self.functions.values_at(x, near)?;
        let (_, log10) = measure_of(self.measure, &ev, &self.functions.scene_at(x))?;
        let strength = strength_of(self.measure, log10).max(self.floor);
        let sign = if self.up { -1.0 } else { 1.0 };
        values.objective = sign * std::f64::consts::LN_10 * strength;
        Some(values)
    }

    /// f is ±ln of the measure: its differences are relative changes.
    fn logarithmic_objective(&self) -> bool {
        true
    }
}

/// The strongest (`up`) or weakest reachable adhesion under every constraint
/// of the study and A_r ≤ A_n, as an optimisation problem
/// ([`MeasureProgram`]) solved from the study's own starts (the baseline and
/// its quasi-random draws, those in contact), in parallel with a fixed order:
/// the strength and scene of the best feasible end, and the evaluations spent.
/// None when no start ends feasible.
fn measure_extreme(sweep: &Sweep, up: bool, floor: f64) -> (Option<(f64, Scene)>, usize) {
    let program = MeasureProgram::new(sweep, up, floor);
    let settings = sweep.study.settings;
    let deadline = Instant::now() + settings.time_limit;
    let baseline = program.functions.space.baseline_unit();
    let candidates = super::start_points(&baseline, settings.starts.max(1), settings.seed);
    // Each start: the strength and design it ended at (when feasible), and its evaluations.
    type Run = (Option<(f64, Vec<f64>)>, usize);
    let runs: Vec<Run> = candidates
        .into_par_iter()
        .map(|x0| {
            // A start out of contact ends at once, not feasible.
            let remaining = deadline.saturating_duration_since(Instant::now());
            let r = super::minimize(&program, &x0, &super::sqp_settings(settings, remaining));
            let feasible = r.objective.is_finite()
                && r.constraints
                    .iter()
                    .all(|g| *g <= super::FEASIBILITY_TOLERANCE);
            let strength = -r.objective / std::f64::consts::LN_10;
            let strength = if up { strength } else { -strength };
            (feasible.then_some((strength, r.x)), r.evaluations)
        })
        .collect();
    let evaluations = runs.iter().map(|r| r.1).sum();
    let best = runs
        .into_iter()
        .filter_map(|r| r.0)
        .fold(None::<(f64, Vec<f64>)>, |best, c| match best {
            Some(b) if (if up { c.0 <= b.0 } else { c.0 >= b.0 }) => Some(b),
            _ => Some(c),
        });
    let best = best.map(|(s, x)| (s, program.functions.scene_at(&x)));
    (best, evaluations)
}

/// Strengths at the corners of the design box (where the surfaces touch),
/// with the corners' scenes.
fn corner_strengths(sweep: &Sweep) -> Vec<(f64, Scene)> {
    let space = super::DesignSpace::new(sweep.study.scene, sweep.study.design);
    let n = space.dim();
    (0..1usize << n)
        .into_par_iter()
        .filter_map(|mask| {
            let x: Vec<f64> = (0..n).map(|i| ((mask >> i) & 1) as f64).collect();
            let scene = space.scene_at(&x);
            let ev = sweep.evaluate(&scene);
            (ev.status == Status::Ok)
                .then(|| measure_of(sweep.measure, &ev, &scene))
                .flatten()
                .map(|(_, l)| (strength_of(sweep.measure, l), scene))
        })
        .collect()
}

/// One feasibility probe of the range search: a single start from `from`
/// (the last feasible probe), then, when that is not feasible, from `corner`.
/// Returns the probe's result and the evaluations spent.
fn probe_once(
    sweep: &Sweep,
    target: Target,
    from: &Scene,
    corner: Option<&Scene>,
) -> (Option<Solved>, usize) {
    let r = sweep.solve(target, from, &sweep.warm_settings);
    let mut evaluations = r.as_ref().map_or(0, |r| r.evaluations);
    if r.as_ref().is_some_and(|r| r.feasible) {
        return (r, evaluations);
    }
    if let Some(c) = corner {
        let rc = sweep.solve(target, c, &sweep.warm_settings);
        evaluations += rc.as_ref().map_or(0, |r| r.evaluations);
        if rc.as_ref().is_some_and(|r| r.feasible) {
            return (rc, evaluations);
        }
    }
    (r, evaluations)
}

/// One end of the reachable range: from the feasible `start` toward `bound`
/// (inclusive), by probing "strength ≥ s" (upward) or "≤ s" (downward), each
/// probe warm-started from the last feasible one and, when that fails, from
/// `corner` (the box corner nearest the bound: a start where the measure is
/// not lost below the floor of a double, so its row has a gradient).
fn find_end(
    sweep: &Sweep,
    start: &Solved,
    bound: f64,
    corner: Option<&Scene>,
    observer: &dyn Observer,
) -> (f64, Solved, usize, usize) {
    let up = bound > start.strength;
    let mut good = start.clone();
    let mut good_s = start.strength;
    let mut bad: Option<f64> = None;
    let mut probes = 0;
    let mut evaluations = 0;
    if (bound - good_s).abs() <= sweep.settings.strength_tolerance {
        return (good_s, good, probes, evaluations);
    }
    let mut probe = bound;
    while probes < sweep.settings.max_probes {
        let target = if up {
            Target::AtLeast(probe)
        } else {
            Target::AtMost(probe)
        };
        let (r, e) = probe_once(sweep, target, &good.scene, corner);
        evaluations += e;
        probes += 1;
        observer.probe_done();
        match r {
            Some(r) if r.feasible => {
                good_s = probe;
                good = r;
            }
            _ => bad = Some(probe),
        }
        match bad {
            None => break, // the bound itself is reachable
            Some(b) if (b - good_s).abs() <= sweep.settings.range_resolution => break,
            Some(b) => probe = 0.5 * (good_s + b),
        }
    }
    (good_s, good, probes, evaluations)
}

/// Target strengths from the preferred end: evenly in log10 when the range
/// spans a decade, else evenly in value; the one nearest `snap` moved onto it.
pub fn targets(
    measure: AdhesionMeasure,
    lo: f64,
    hi: f64,
    points: usize,
    direction: ParetoDirection,
    snap: Option<f64>,
    settings: &ParetoSettings,
) -> Vec<f64> {
    let n = points.max(1);
    let frac = |k: usize| {
        if n == 1 {
            0.0
        } else {
            k as f64 / (n - 1) as f64
        }
    };
    let mut s: Vec<f64> = if hi - lo >= 1.0 {
        (0..n).map(|k| lo + (hi - lo) * frac(k)).collect()
    } else {
        let (vlo, vhi) = (value_at(measure, lo), value_at(measure, hi));
        (0..n)
            .map(|k| strength_of(measure, (vlo + (vhi - vlo) * frac(k)).log10()))
            .collect()
    };
    // Exact ends, whatever the rounding of the value spacing.
    s[0] = lo;
    s[n - 1] = hi;
    if let Some(w) = snap {
        let tol = settings.strength_tolerance;
        if w > lo + tol && w < hi - tol && n > 2 {
            let k = (1..n - 1)
                .min_by(|&a, &b| (s[a] - w).abs().total_cmp(&(s[b] - w).abs()))
                .unwrap_or(1);
            s[k] = w;
        }
    }
    if direction == ParetoDirection::High {
        s.reverse();
    }
    s
}

/// Dominance of the newest point against the earlier ones (see the module docs).
fn dominated_by_earlier(
    earlier: &[FrontPoint],
    p: &FrontPoint,
    direction: ParetoDirection,
    settings: &ParetoSettings,
) -> bool {
    let pref = |s: f64| match direction {
        ParetoDirection::Low => s,
        ParetoDirection::High => -s,
    };
    earlier.iter().filter(|q| q.feasible).any(|q| {
        pref(q.strength) <= pref(p.strength) + settings.strength_tolerance
            && q.objective <= p.objective * (1.0 + settings.wear_tolerance)
    })
}

/// The knee of the front (see the module docs), with strengths clamped to
/// `range`, the range the report prints (a pull-off of 10^-1105 N sits at its
/// floor end, not a thousand decades beyond it).
pub fn knee(points: &[FrontPoint], range: (f64, f64), settings: &ParetoSettings) -> Option<usize> {
    let front: Vec<&FrontPoint> = points.iter().filter(|p| p.on_front).collect();
    if front.len() < 3 {
        return None;
    }
    let (lo, hi) = (range.0.min(range.1), range.0.max(range.1));
    let xy: Vec<(f64, f64)> = front
        .iter()
        .map(|p| {
            (
                p.strength.clamp(lo, hi),
                p.objective.max(f64::MIN_POSITIVE).log10(),
            )
        })
        .collect();
    let span = |f: fn(&(f64, f64)) -> f64| {
        let lo = xy.iter().map(f).fold(f64::INFINITY, f64::min);
        let hi = xy.iter().map(f).fold(f64::NEG_INFINITY, f64::max);
        (lo, if hi > lo { hi - lo } else { 1.0 })
    };
    let (x0, dx) = span(|p| p.0);
    let (y0, dy) = span(|p| p.1);
    let norm: Vec<(f64, f64)> = xy
        .iter()
        .map(|&(x, y)| ((x - x0) / dx, (y - y0) / dy))
        .collect();
    let (a, b) = (norm[0], norm[norm.len() - 1]);
    let (cx, cy) = (b.0 - a.0, b.1 - a.1);
    let len = (cx * cx + cy * cy).sqrt();
    if len == 0.0 {
        return None;
    }
    let (k, d) = norm
        .iter()
        .enumerate()
        .skip(1)
        .take(norm.len() - 2)
        .map(|(k, &(x, y))| (k, ((x - a.0) * cy - (y - a.1) * cx).abs() / len))
        .fold((0, -1.0), |best, c| if c.1 > best.1 { c } else { best });
    (d >= settings.knee_min_distance).then(|| front[k].index)
}

/// One ε-point of the sweep while it is being solved.
struct Slot {
    strength: f64,
    target: Target,
    solved: Option<Solved>,
    warm_started: bool,
    evaluations: usize,
    /// The designs this point was solved from with a single start (the warm
    /// start, then the refinement's neighbours). A solve is deterministic: the
    /// same target from the same design gives the same result, so none is
    /// solved twice.
    tried: Vec<Vec<f64>>,
}

/// `a` is better than `b` by more than the relative tolerance: feasible where
/// `b` is not, or a lower objective.
fn improves(a: &Solved, b: Option<&Solved>, tolerance: f64) -> bool {
    match b {
        None => true,
        Some(b) => {
            (a.feasible && !b.feasible)
                || (a.feasible == b.feasible && a.objective < b.objective * (1.0 - tolerance))
        }
    }
}

/// Re-solves the ε-points until none improves (at most [`MAX_REFINE_ROUNDS`]
/// rounds): each point from both neighbours' designs; the better design is
/// kept. (Every point already holds the result of the study's multistart,
/// see [`Sweep::solve_point`].) A point is never solved again from a design
/// it was already solved from ([`Slot::tried`]): the same solve would give
/// the same design. Each round reads the previous round's designs only, so the result
/// does not depend on the thread count.
fn refine(sweep: &Sweep, slots: &mut [Slot]) {
    let tolerance = sweep
        .study
        .settings
        .tolerance
        .max(sweep.settings.wear_tolerance * 1e-3);
    for _ in 0..sweep.settings.max_refine_rounds {
        let designs: Vec<Option<&Solved>> = slots
            .iter()
            .map(|s| s.solved.as_ref().filter(|r| r.feasible && r.log10 > -300.0))
            .collect();
        let updates: Vec<(Option<Solved>, usize, Vec<Vec<f64>>)> = (0..slots.len())
            .into_par_iter()
            .map(|i| {
                let current = slots[i].solved.as_ref();
                let mut best: Option<Solved> = None;
                let mut evaluations = 0;
                let mut tried = Vec::new();
                let neighbours = [i.checked_sub(1), Some(i + 1)];
                for k in neighbours.into_iter().flatten() {
                    let Some(Some(from)) = designs.get(k) else {
                        continue;
                    };
                    if slots[i].tried.contains(&from.design) || tried.contains(&from.design) {
                        continue;
                    }
                    tried.push(from.design.clone());
                    let r = sweep.solve(slots[i].target, &from.scene, &sweep.warm_settings);
                    evaluations += r.as_ref().map_or(0, |r| r.evaluations);
                    if let Some(r) = r {
                        if improves(&r, best.as_ref().or(current), tolerance) {
                            best = Some(r);
                        }
                    }
                }
                (best, evaluations, tried)
            })
            .collect();
        let mut improved = false;
        for (slot, (best, evaluations, tried)) in slots.iter_mut().zip(updates) {
            slot.evaluations += evaluations;
            slot.tried.extend(tried);
            if let Some(b) = best {
                slot.solved = Some(b);
                slot.warm_started = false;
                improved = true;
            }
        }
        if !improved {
            break;
        }
    }
}

/// The reported point of a solved slot.
fn front_point(index: usize, slot: &Slot, measure: AdhesionMeasure, n: usize) -> FrontPoint {
    let kind = match slot.target {
        Target::AtMost(_) => "at_most",
        Target::AtLeast(_) => "at_least",
        Target::Equal(_) => "equal",
    };
    let target = value_at(measure, slot.strength);
    match &slot.solved {
        Some(r) => FrontPoint {
            index,
            target,
            target_kind: kind,
            adhesion: r.value,
            log10_adhesion: r.log10,
            strength: r.strength,
            objective: r.objective,
            wear_rate: r.wear_rate,
            status: r.status,
            feasible: r.feasible,
            dominated: false,
            on_front: false,
            design: r.design.clone(),
            warm_started: slot.warm_started,
            evaluations: slot.evaluations,
        },
        None => FrontPoint {
            index,
            target,
            target_kind: kind,
            adhesion: f64::NAN,
            log10_adhesion: f64::NAN,
            strength: f64::NAN,
            objective: f64::NAN,
            wear_rate: f64::NAN,
            status: OptimizationStatus::Infeasible,
            feasible: false,
            dominated: false,
            on_front: false,
            design: vec![f64::NAN; n],
            warm_started: false,
            evaluations: slot.evaluations,
        },
    }
}

/// The reachable range of the measure and the designs at its ends.
struct Range {
    lo: f64,
    hi: f64,
    lo_solved: Solved,
    hi_solved: Solved,
    /// The low end is the pull-off floor (one-sided).
    floor_end: bool,
    probes: usize,
    evaluations: usize,
}

/// The reachable range around the least-wear design `start` (see the module
/// docs): bracketed by the box corners and the study's own limits on the
/// measure, each end then found by [`find_end`].
fn reachable_range(sweep: &Sweep, start: &Solved, observer: &dyn Observer) -> Range {
    let s_w = start.strength;
    let corners = corner_strengths(sweep);
    let (limit_lo, limit_hi) = study_limits(sweep.measure, sweep.study.constraints);
    let floor = match sweep.measure {
        AdhesionMeasure::PullOffForce => PULL_OFF_FLOOR.log10(),
        _ => f64::NEG_INFINITY,
    };
    let extreme = |better: fn(f64, f64) -> bool| {
        corners
            .iter()
            .fold(None::<&(f64, Scene)>, |best, c| match best {
                Some(b) if !better(c.0, b.0) => Some(b),
                _ => Some(c),
            })
    };
    let mut weakest = extreme(|a, b| a < b).cloned();
    let mut strongest = extreme(|a, b| a > b).cloned();
    // Each end as an optimisation problem (the study's rows and A_r ≤ A_n):
    // a corner can be out of range (its real area above the nominal one) or
    // not the extreme at all, and a range bracketed by the corners alone
    // then stops short of what a design can reach. The extreme's design is
    // the start the end's probes fall back on.
    let (mut probes, mut evaluations) = (0, 0);
    if start.feasible {
        let (hi, e) = measure_extreme(sweep, true, floor);
        evaluations += e;
        if let Some(hi) = hi.filter(|h| strongest.as_ref().is_none_or(|c| h.0 > c.0)) {
            strongest = Some(hi);
        }
        if s_w > floor {
            let (lo, e) = measure_extreme(sweep, false, floor);
            evaluations += e;
            if let Some(lo) = lo.filter(|l| weakest.as_ref().is_none_or(|c| l.0 < c.0)) {
                weakest = Some(lo);
            }
        }
    }
    let (weakest, strongest) = (weakest.as_ref(), strongest.as_ref());
    let box_lo = weakest.map_or(s_w, |c| c.0.min(s_w)).max(limit_lo);
    let box_hi = strongest.map_or(s_w, |c| c.0.max(s_w)).min(limit_hi);
    let (lo, lo_solved, floor_end) = if !start.feasible {
        (s_w, start.clone(), false)
    } else if s_w <= floor {
        // The least-wear design has no pull-off to speak of: it is the low end.
        (floor, start.clone(), true)
    } else {
        let corner = weakest.map(|c| &c.1);
        let (lo, solved, p, e) = find_end(sweep, start, box_lo.max(floor), corner, observer);
        probes += p;
        evaluations += e;
        (lo, solved, lo <= floor + sweep.settings.strength_tolerance)
    };
    let (hi, hi_solved) = if start.feasible {
        let corner = strongest.map(|c| &c.1);
        let (hi, solved, p, e) = find_end(sweep, start, box_hi.max(floor), corner, observer);
        probes += p;
        evaluations += e;
        (hi.max(lo), solved)
    } else {
        (s_w.max(lo), start.clone())
    };
    Range {
        lo,
        hi,
        lo_solved,
        hi_solved,
        floor_end,
        probes,
        evaluations,
    }
}

/// Solves the targets `strengths` in waves of [`WAVE`] from the preferred end,
/// each point by [`Sweep::solve_point`], warm from the nearest design known
/// before its wave (`seeds`, then each wave's). The point at `floor_index`
/// holds its target as an upper bound.
fn sweep_waves(
    sweep: &Sweep,
    strengths: &[f64],
    floor_index: Option<usize>,
    seeds: &[&Solved],
    observer: &dyn Observer,
) -> Vec<Slot> {
    // Only designs whose measure a double can hold (a pull-off below 1e-300 N
    // leaves its row without a gradient).
    let mut known: Vec<(f64, Scene)> = Vec::new();
    let remember = |known: &mut Vec<(f64, Scene)>, r: &Solved| {
        if r.feasible && r.log10 > -300.0 {
            known.push((r.strength, r.scene.clone()));
        }
    };
    for r in seeds {
        remember(&mut known, r);
    }
    let mut slots: Vec<Slot> = Vec::with_capacity(strengths.len());
    let size = sweep.settings.wave.max(1);
    for (w, wave) in strengths.chunks(size).enumerate() {
        let solved: Vec<Slot> = wave
            .par_iter()
            .enumerate()
            .map(|(j, &s)| {
                let target = if Some(w * size + j) == floor_index {
                    Target::AtMost(s)
                } else {
                    Target::Equal(s)
                };
                let warm = known
                    .iter()
                    .min_by(|a, b| (a.0 - s).abs().total_cmp(&(b.0 - s).abs()))
                    .map(|k| &k.1);
                let (solved, warm_started, evaluations) = sweep.solve_point(target, warm);
                observer.point_solved();
                Slot {
                    strength: s,
                    target,
                    solved,
                    warm_started,
                    evaluations,
                    tried: warm.map(|w| sweep.design_at(w)).into_iter().collect(),
                }
            })
            .collect();
        for slot in solved {
            if let Some(r) = &slot.solved {
                remember(&mut known, r);
            }
            slots.push(slot);
        }
    }
    slots
}

/// Where the ε-curve turns, spends the points on the front (see the module
/// docs): returns the new slots (the front's `points` targets, then the
/// dominated points past the turn), the evaluations of the slots left out,
/// and the index of the turn (None where the curve does not turn).
fn spend_on_front(
    sweep: &Sweep,
    slots: Vec<Slot>,
    points: usize,
    direction: ParetoDirection,
    least_wear_strength: f64,
    observer: &dyn Observer,
) -> (Vec<Slot>, usize, Option<usize>) {
    let settings = &sweep.settings;
    let n = sweep.study.design.len();
    let preview = points_of(&slots, sweep.measure, n, direction, settings, &Silent);
    let front: Vec<usize> = preview
        .iter()
        .filter(|p| p.on_front)
        .map(|p| p.index)
        .collect();
    let Some(&last) = front.last() else {
        return (slots, 0, None);
    };
    let beyond = preview[last + 1..]
        .iter()
        .any(|p| p.feasible && p.dominated);
    if last == 0 || !beyond {
        return (slots, 0, None);
    }
    if front.len() >= points || points < 3 {
        return (slots, 0, Some(last));
    }
    observer.turn_started(settings.max_turn_steps + points);
    // The turn: between the last point above the least wear and the first at it.
    let least = preview[last].objective;
    let at_least =
        |r: &Solved| r.feasible && r.objective <= least * (1.0 + settings.wear_tolerance);
    let (mut above, mut at) = (slots[last - 1].strength, slots[last].strength);
    if (at - least_wear_strength).abs() <= settings.strength_tolerance {
        // The first point at the least wear is the study's least-wear design
        // itself (its target was snapped onto it): the wear rises on both
        // sides of it, and it is the turn.
        above = at;
    }
    let mut warm = slots[last].solved.as_ref().map(|r| r.scene.clone());
    let mut found: Vec<Slot> = Vec::new();
    let mut turn: Option<Slot> = None;
    for _ in 0..settings.max_turn_steps {
        if (above - at).abs() <= settings.range_resolution {
            break;
        }
        let mid = 0.5 * (above + at);
        let target = Target::Equal(mid);
        let (solved, warm_started, evaluations) = sweep.solve_point(target, warm.as_ref());
        observer.point_solved();
        let slot = Slot {
            strength: mid,
            target,
            solved,
            warm_started,
            evaluations,
            tried: warm.iter().map(|w| sweep.design_at(w)).collect(),
        };
        match slot.solved.as_ref() {
            Some(r) if at_least(r) => {
                at = mid;
                warm = Some(r.scene.clone());
                found.extend(turn.replace(slot));
            }
            _ => {
                above = mid;
                found.push(slot);
            }
        }
    }
    // The front's targets, from the preferred end to the turn.
    let end = slots[0].strength;
    let goal = targets(
        sweep.measure,
        end.min(at),
        end.max(at),
        points,
        direction,
        None,
        settings,
    );
    let mut old: Vec<Option<Slot>> = slots.into_iter().map(Some).collect();
    let tail: Vec<Slot> = old
        .drain(last + usize::from(turn.is_none())..)
        .flatten()
        .collect();
    let mut pool: Vec<Option<Slot>> = old.into_iter().chain(found.into_iter().map(Some)).collect();
    // The front's last point: the turn (or, not found, the first point at the
    // least wear, which is then the pool's last old point).
    let turn = turn.or_else(|| pool.get_mut(last).and_then(Option::take));
    let mut chosen: Vec<Option<Slot>> = Vec::with_capacity(points);
    let mut fresh: Vec<f64> = Vec::new();
    for (k, &g) in goal.iter().enumerate().take(points - 1) {
        let spacing = |j: usize| goal.get(j).map_or(f64::INFINITY, |&x: &f64| (x - g).abs());
        let near = 0.25 * spacing(k + 1).min(k.checked_sub(1).map_or(f64::INFINITY, spacing));
        let best = pool
            .iter()
            .enumerate()
            .filter_map(|(i, s)| s.as_ref().map(|s| (i, (s.strength - g).abs())))
            .filter(|&(_, d)| d <= near)
            .min_by(|a, b| a.1.total_cmp(&b.1));
        match best {
            Some((i, _)) => chosen.push(pool[i].take()),
            None => {
                chosen.push(None);
                fresh.push(g);
            }
        }
    }
    let seeds: Vec<&Solved> = chosen
        .iter()
        .flatten()
        .filter_map(|s| s.solved.as_ref())
        .collect();
    let mut solved = sweep_waves(sweep, &fresh, None, &seeds, observer).into_iter();
    let mut front: Vec<Slot> = chosen
        .into_iter()
        .filter_map(|s| s.or_else(|| solved.next()))
        .chain(turn)
        .collect();
    refine(sweep, &mut front);
    let dropped = pool.iter().flatten().map(|s| s.evaluations).sum();
    let turn = front.len() - 1;
    front.extend(tail);
    (front, dropped, Some(turn))
}

/// The reported points of the final slots, in sweep order, with dominance
/// decided against the earlier points; each goes to the observer.
fn points_of(
    slots: &[Slot],
    measure: AdhesionMeasure,
    n: usize,
    direction: ParetoDirection,
    settings: &ParetoSettings,
    observer: &dyn Observer,
) -> Vec<FrontPoint> {
    let mut points: Vec<FrontPoint> = Vec::with_capacity(slots.len());
    for (index, slot) in slots.iter().enumerate() {
        let mut p = front_point(index, slot, measure, n);
        if p.feasible {
            p.dominated = dominated_by_earlier(&points, &p, direction, settings);
            p.on_front = !p.dominated;
        }
        observer.point_done(&p);
        points.push(p);
    }
    points
}

/// Sweeps the wear–adhesion curve of a study (see the module docs) with the
/// default [`ParetoSettings`]. The result is the same for any number of rayon
/// threads.
pub fn pareto(
    study: &Study,
    spec: &ParetoSpec,
    observer: &dyn Observer,
) -> Result<Front, ParetoError> {
    pareto_with(study, spec, &ParetoSettings::default(), observer)
}

/// As [`pareto`], with `settings`.
pub fn pareto_with(
    study: &Study,
    spec: &ParetoSpec,
    settings: &ParetoSettings,
    observer: &dyn Observer,
) -> Result<Front, ParetoError> {
    let t0 = Instant::now();
    if study.design.is_empty() {
        return Err(OptimizeError::NoDesign.into());
    }
    let objective = study.objective.ok_or(OptimizeError::NoObjective)?;
    if !(ParetoSpec::MIN_POINTS..=ParetoSpec::MAX_POINTS).contains(&spec.points) {
        return Err(ParetoError::Points(spec.points));
    }
    // Over a humidity range, one humidity for the whole front: the objective's,
    // chosen once at the study's baseline and then named as the design
    // humidity, so that every solve (each from its own start or warm scene,
    // which would choose afresh) measures wear and adhesion there.
    let adhesion_humidity = study
        .scene
        .environment
        .and_then(|e| e.humidity_range)
        .and_then(|_| {
            let space = super::DesignSpace::new(study.scene, study.design);
            super::StudyFunctions::new(space, objective, study.constraints).objective_humidity
        });
    let fixed_scene = adhesion_humidity.map(|h| {
        let mut scene = super::functions::at_humidity(study.scene.clone(), h);
        if let Some(r) = scene
            .environment
            .as_mut()
            .and_then(|e| e.humidity_range.as_mut())
        {
            r.design_given = true;
        }
        scene
    });
    let fixed_study;
    let study = match &fixed_scene {
        Some(scene) => {
            fixed_study = Study { scene, ..*study };
            &fixed_study
        }
        None => study,
    };
    let measure = spec.adhesion;
    if measure == AdhesionMeasure::WorkOfAdhesion
        && !study
            .design
            .iter()
            .any(|d| d.name == SceneParameter::WorkOfAdhesion)
    {
        return Err(ParetoError::WorkOfAdhesionFixed);
    }
    let sweep = Sweep {
        study,
        measure,
        objective,
        options: EvaluationOptions {
            pull_off: measure == AdhesionMeasure::PullOffForce,
            quadrature: Quadrature::default(),
            work_of_adhesion: false,
        },
        warm_settings: OptimizerSettings {
            starts: 1,
            ..*study.settings
        },
        settings: *settings,
    };
    let names: Vec<SceneParameter> = study.design.iter().map(|d| d.name).collect();

    // The least-wear design: the study without an adhesion target.
    observer.range_started();
    let optimum = optimize(study)?;
    let mut evaluations = optimum.evaluations;
    let least_wear_feasible = optimum.feasible();
    let least_wear = sweep
        .reference(&optimum.scene, least_wear_feasible)
        .ok_or(OptimizeError::NoContact)?;
    let s_w = strength_of(measure, least_wear.log10_adhesion);
    let start = Solved {
        status: optimum.status,
        feasible: least_wear_feasible,
        objective: least_wear.objective,
        wear_rate: least_wear.wear_rate,
        value: least_wear.adhesion,
        log10: least_wear.log10_adhesion,
        strength: s_w,
        design: least_wear.design.clone(),
        scene: optimum.scene.clone(),
        evaluations: 0,
    };
    let baseline = sweep.reference(study.scene, false).map(|mut r| {
        r.feasible = {
            let space = super::DesignSpace::new(study.scene, study.design);
            let f = super::StudyFunctions::new(space.clone(), objective, study.constraints);
            f.at(&space.baseline_unit())
                .is_some_and(|p| p.max_violation() <= super::FEASIBILITY_TOLERANCE)
        };
        r
    });

    // The reachable range.
    let range = reachable_range(&sweep, &start, observer);
    evaluations += range.evaluations;
    let (lo, hi, floor_end, probes) = (range.lo, range.hi, range.floor_end, range.probes);
    let snap = (s_w > lo).then_some(s_w);
    let strengths = targets(measure, lo, hi, spec.points, spec.direction, snap, settings);

    // The sweep, in waves from the preferred end.
    observer.sweep_started(strengths.len());
    let floor_index = floor_end.then(|| match spec.direction {
        ParetoDirection::Low => 0,
        ParetoDirection::High => strengths.len() - 1,
    });
    let mut slots = sweep_waves(
        &sweep,
        &strengths,
        floor_index,
        &[&range.lo_solved, &range.hi_solved, &start],
        observer,
    );
    observer.refine_started();
    refine(&sweep, &mut slots);
    let (slots, dropped, turn) =
        spend_on_front(&sweep, slots, spec.points, spec.direction, s_w, observer);
    evaluations += dropped + slots.iter().map(|s| s.evaluations).sum::<usize>();
    let points = points_of(
        &slots,
        measure,
        names.len(),
        spec.direction,
        settings,
        observer,
    );
    let front = points.iter().filter(|p| p.on_front).count();
    let status = match front {
        0 => FrontStatus::Infeasible,
        1 => FrontStatus::NoTradeOff,
        _ => FrontStatus::Ok,
    };
    Ok(Front {
        status,
        measure,
        direction: spec.direction,
        objective_name: objective,
        names,
        knee: knee(&points, (lo, hi), settings),
        turn: turn.filter(|&t| points.get(t).is_some_and(|p| p.on_front)),
        points,
        strength_range: (lo, hi),
        floor_end,
        baseline,
        least_wear,
        least_wear_strength: s_w,
        evaluations,
        probes,
        time_seconds: t0.elapsed().as_secs_f64(),
        real_area_scale: study.scene.real_area_scale,
        adhesion_humidity,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_are_even_in_log_and_snap_to_the_least_wear_strength() {
        let s = targets(
            AdhesionMeasure::PullOffForce,
            -12.0,
            -4.0,
            5,
            ParetoDirection::Low,
            Some(-7.9),
            &ParetoSettings::default(),
        );
        assert_eq!(s, vec![-12.0, -10.0, -7.9, -6.0, -4.0]);
        let s = targets(
            AdhesionMeasure::PullOffForce,
            -12.0,
            -4.0,
            3,
            ParetoDirection::High,
            None,
            &ParetoSettings::default(),
        );
        assert_eq!(s, vec![-4.0, -8.0, -12.0]);
        // Less than a decade: even in value.
        let s = targets(
            AdhesionMeasure::WorkOfAdhesion,
            0.01f64.log10(),
            0.05f64.log10(),
            5,
            ParetoDirection::Low,
            None,
            &ParetoSettings::default(),
        );
        let v: Vec<f64> = s
            .iter()
            .map(|&x| value_at(AdhesionMeasure::WorkOfAdhesion, x))
            .collect();
        for (a, b) in v.iter().zip([0.01, 0.02, 0.03, 0.04, 0.05]) {
            assert!((a / b - 1.0).abs() < 1e-12, "{a} vs {b}");
        }
    }

    #[test]
    fn theta_strength_is_inverted() {
        assert_eq!(
            strength_of(AdhesionMeasure::ElasticAdhesionIndex, 2.0),
            -2.0
        );
        assert!((value_at(AdhesionMeasure::ElasticAdhesionIndex, -2.0) - 100.0).abs() < 1e-12);
    }
}
