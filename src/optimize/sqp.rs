//! A trust-region SQP for any [`NonlinearProgram`], as an argmin [`Solver`]:
//! quasi-Newton (damped BFGS) subproblems solved by clarabel (`qp`) in a
//! trust region scaled to the variables' sizes,
//! elastic mode for inconsistent linearisations, acceptance by the ℓ1 merit
//! function `φ = f + ρ Σ max(0, g_j)` with a second-order correction, and
//! convergence on the KKT residual of `multipliers::kkt` measured in
//! the problem's own coordinates.
//!
//! Every tuning constant is a field of [`SqpSettings`], with its default in
//! [`SqpSettings::default`].

use std::time::{Duration, Instant};

use argmin::core::observers::{Observe, ObserverMode};
use argmin::core::{
    Error, Executor, IterState, Problem, Solver, State, TerminationReason, TerminationStatus, KV,
};
use nalgebra::{DMatrix, DVector};
use serde::Serialize;

use super::fd::{gradients, Accuracy, Gradients, EVALUATION_NOISE};

/// The relative decrease of the violation a probe must find to show that a
/// point is not a stationary point of it (the tolerance of
/// [`Sqp::violation_stationary`]'s own test).
const PROBE_DECREASE: f64 = 1e-6;
use super::multipliers::{kkt, least_squares, Kkt, KktData};
use super::program::{NonlinearProgram, Values};
use super::qp::{self, QpFailure, Subproblem};

/// The argmin state the SQP runs on: parameter and gradient are `Vec<f64>`.
pub type SqpState = IterState<Vec<f64>, Vec<f64>, (), (), (), f64>;

/// How hard and how the SQP works. `SqpSettings::default()` holds every default.
#[derive(Debug, Clone, PartialEq)]
pub struct SqpSettings {
    /// `optimal` needs the KKT residual ≤ this (default 1e-8) and the
    /// violation ≤ `feasibility_tolerance`.
    pub tolerance: f64,
    /// A point whose rows (and bounds) are violated by at most this counts as
    /// feasible when a run ends otherwise than `optimal` (default 1e-7).
    pub feasibility_tolerance: f64,
    /// Iteration cap (default 200).
    pub max_iterations: u64,
    /// Wall-clock limit (default none).
    pub time_limit: Option<Duration>,
    /// Initial trust radius (default 0.3): in the units of the scaled trust
    /// region (`scaled_trust_region`), else relative to max(1, ‖x0‖∞).
    pub initial_radius: f64,
    /// The trust region bounds ‖D⁻¹p‖₂, D_i = max(|x_i|, scale_i) at the
    /// current point, instead of ‖p‖₂ (default true): a step may then change
    /// each variable by the same fraction of its size, so variables of 1e-4
    /// and 1e3 beside each other (HS 116) both move.
    pub scaled_trust_region: bool,
    /// A step is accepted when actual/predicted merit reduction exceeds this (default 0.1).
    pub accept_ratio: f64,
    /// The radius grows when the ratio is at least this and the step reached the radius (default 0.5).
    pub grow_ratio: f64,
    /// The radius shrinks after an accepted step whose ratio is below this (default 0.25).
    pub shrink_ratio: f64,
    /// Factor of growth (default 2).
    pub grow_factor: f64,
    /// Factor of shrinking, applied to the step length on rejection (default 0.5).
    pub shrink_factor: f64,
    /// The run stops (`stalled`) when the radius falls below this (times
    /// max(1, ‖x‖∞) without the scaled trust region) (default 1e-12).
    pub min_radius: f64,
    /// The run stops (`stalled`) after this many rejected steps in a row (default 30).
    pub max_rejections: usize,
    /// Initial penalty ρ of the merit function, times max(1, ‖∇f‖∞) (default 5:
    /// at 10, several hundred times the multipliers of HS 100, steps into its
    /// curved rows were rejected again and again; the margin and growth rules
    /// raise ρ where the rows need it. Lower is not better throughout: at 3
    /// HS 116 ends at another KKT point, 2.7e-5 above f*, and at 1 a study
    /// whose start is far from its feasible corner stalls).
    pub penalty_initial: f64,
    /// ρ is kept at least this times the largest multiplier (default 2).
    pub penalty_margin: f64,
    /// ρ is multiplied by this when a linearisation cannot be met (default 10).
    pub penalty_growth: f64,
    /// Largest ρ (default 1e10).
    pub penalty_max: f64,
    /// After an accepted step that did not multiply ρ by the growth, ρ falls towards
    /// max(initial ρ, margin × the step's largest multiplier) by this factor
    /// of its excess (default 0.5, as SLSQP's ½(ρ + |λ|); 1: ρ never falls).
    /// A ρ raised early, far from the solution, to thousands of times the
    /// multipliers makes the merit see nothing but the violation the rows'
    /// curvature leaves after each step: the ratio of actual to predicted
    /// reduction stays low, the radius stays small and the run crawls (HS
    /// 106, HS 116).
    pub penalty_decay: f64,
    /// The merit weighs each row's violation by its own ρ_j, as SLSQP's:
    /// at least the margin times the row's multiplier, its excess over that
    /// shrunk by `penalty_decay` at each iteration, at least the initial ρ
    /// and at most ρ, which stays the subproblem's elastic penalty (default
    /// true; false: every ρ_j is ρ). With one ρ for all rows, rows whose
    /// multipliers are 1e5 times apart (HS 106: ~1e3 on its linear rows,
    /// ~1e-2 on its bilinear ones) weigh the violation the bilinear rows'
    /// curvature leaves after each step at the linear rows' price: the
    /// ratio of actual to predicted merit reduction stays below
    /// `grow_ratio`, the radius small, and the run crawls.
    pub row_penalties: bool,
    /// Finite-difference step relative to max(|x_i|, scale_i) (default 1e-4).
    pub fd_step: f64,
    /// Gradients are forward differences (one evaluation per variable) until
    /// the KKT residual with least-squares multipliers falls to this; from
    /// then on they are central (default 1e-3: a forward difference's error,
    /// ~fd_step/2 times the curvature, is then still about a tenth of what the
    /// residual measures; 0 or less: never forward).
    pub central_below: f64,
    /// Gradients are central differences (two evaluations per variable)
    /// until the KKT residual with least-squares multipliers falls to this or
    /// to 100 × `tolerance`, whichever is larger (but not above
    /// `central_below`); from then on, and at the reported point, they are
    /// Richardson-extrapolated (four per variable), accurate enough for the
    /// KKT test (default 1e-4; 0 or less: always Richardson).
    pub richardson_below: f64,
    /// After this many steps rejected in a row the gradients are made one
    /// level more accurate (forward → central → Richardson) at the current
    /// point: a model whose step fails again and again at shrinking radii has
    /// the wrong slope, and the finite differences' error is where that comes
    /// from (default 2; 0: never).
    pub doubt_after: usize,
    /// A step this short relative to max(1, ‖x‖∞) is no step (default 1e-14).
    pub step_tolerance: f64,
    /// Merit changes within this relative to 1 + |φ| are noise (default 1e-12).
    pub merit_noise: f64,
    /// Rows with g ≥ -t for each t here are tried as the active set of the
    /// least-squares multipliers; the estimate with the smallest residual is
    /// kept (default 1e-10, 1e-7, 1e-4).
    pub active_tolerances: Vec<f64>,
    /// A trial point closer to a bound than this times max(1, |bound|) is put on it
    /// (default 1e-6, a hundredth of the finite-difference step: closer than that
    /// the gradients cannot tell the point from the bound, and an iterate left just
    /// off a bound that is active at the optimum crawls towards it in steps the
    /// subproblem keeps tiny while the KKT test counts the bound as free).
    pub bound_snap: f64,
    /// An accepted step that stayed inside the trust region and reduced the
    /// merit at least this many times as much as the model predicted (the
    /// function is flatter than the model, as where a slope fades
    /// exponentially towards a bound) is extended: doubled, up to the trust
    /// radius or the box, while each doubling lowers the merit further, one
    /// evaluation per doubling (default 1.25; infinite: never).
    pub extend_ratio: f64,
    /// Duality-gap tolerance (absolute and relative) of clarabel's solve of
    /// each subproblem (default 1e-10). The subproblem is solved normalised,
    /// its objective O(1) on a step of its own scale (see `qp`), so this is
    /// relative to the model's change over the step; at 1e-12 clarabel
    /// often ends `AlmostSolved`.
    pub qp_tolerance: f64,
    /// The same while the gradients are forward differences, far from a
    /// solution, where a step need not be exact (default 1e-8: about two
    /// interior-point iterations fewer per subproblem; the rows the step
    /// meets are met exactly all the same, see `qp`).
    pub far_qp_tolerance: f64,
    /// clarabel's interior-point iteration cap per subproblem (default 100; a
    /// well-scaled subproblem takes 10–20).
    pub qp_max_iterations: u32,
}

impl SqpSettings {
    /// The KKT residual below which gradients are Richardson-extrapolated:
    /// `richardson_below` or 100 × `tolerance`, whichever is larger, but not
    /// above the end of the forward phase (`central_below`, when there is
    /// one): a loose tolerance is met with the cheap gradients of the approach
    /// and checked with accurate ones.
    pub(crate) fn richardson_threshold(&self) -> f64 {
        let near = self.richardson_below.max(100.0 * self.tolerance);
        if self.central_below > 0.0 {
            near.min(self.central_below.max(self.richardson_below))
        } else {
            near
        }
    }

    /// The test for `optimal`: KKT residual ≤ `tolerance` and no row or bound
    /// violated by more than `feasibility_tolerance`.
    pub(crate) fn met(&self, k: &Kkt) -> bool {
        k.residual <= self.tolerance && k.violation <= self.feasibility_tolerance
    }
}

impl Default for SqpSettings {
    fn default() -> Self {
        SqpSettings {
            tolerance: 1e-8,
            feasibility_tolerance: 1e-7,
            max_iterations: 200,
            time_limit: None,
            initial_radius: 0.3,
            scaled_trust_region: true,
            accept_ratio: 0.1,
            grow_ratio: 0.5,
            shrink_ratio: 0.25,
            grow_factor: 2.0,
            shrink_factor: 0.5,
            min_radius: 1e-12,
            max_rejections: 30,
            penalty_initial: 5.0,
            penalty_margin: 2.0,
            penalty_growth: 10.0,
            penalty_max: 1e10,
            penalty_decay: 0.5,
            row_penalties: true,
            fd_step: 1e-4,
            central_below: 1e-3,
            richardson_below: 1e-4,
            doubt_after: 2,
            step_tolerance: 1e-14,
            merit_noise: 1e-12,
            active_tolerances: vec![1e-10, 1e-7, 1e-4],
            bound_snap: 1e-6,
            extend_ratio: 1.25,
            qp_tolerance: 1e-10,
            far_qp_tolerance: 1e-8,
            qp_max_iterations: 100,
        }
    }
}

/// How a run ended (contract words via `Display`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SqpStatus {
    /// KKT residual ≤ tolerance at a feasible point.
    Optimal,
    /// Ended at a stationary point of the violation with a row violated.
    Infeasible,
    /// The iteration cap stopped it.
    IterationLimit,
    /// The time limit stopped it.
    TimeLimit,
    /// No more progress without meeting the KKT test (or the start could not be evaluated).
    Stalled,
}

impl SqpStatus {
    /// The status word.
    pub fn as_str(self) -> &'static str {
        match self {
            SqpStatus::Optimal => "optimal",
            SqpStatus::Infeasible => "infeasible",
            SqpStatus::IterationLimit => "iteration_limit",
            SqpStatus::TimeLimit => "time_limit",
            SqpStatus::Stalled => "stalled",
        }
    }
}

impl std::fmt::Display for SqpStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// One row of the iteration trace.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceRow {
    /// Iteration number (0 = the start point); the row describes the point
    /// the iteration starts from.
    pub iteration: usize,
    /// Wall time since the run began (s).
    pub time: f64,
    /// f at the current point.
    pub objective: f64,
    /// KKT residual at the current point.
    pub kkt_residual: f64,
    /// max_j max(0, g_j) at the current point.
    pub violation: f64,
}

/// What [`minimize`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct SqpResult {
    /// The point (problem coordinates).
    pub x: Vec<f64>,
    /// f(x) (∞ only when the start could not be evaluated).
    pub objective: f64,
    /// g(x).
    pub constraints: Vec<f64>,
    /// How it ended.
    pub status: SqpStatus,
    /// The KKT residual at x: the largest of the relative stationarity
    /// ‖∇f + Σλ_j∇g_j − μ_lower + μ_upper‖∞ / max(1, ‖∇f‖∞), the
    /// complementarity max_j |λ_j g_j| / max(1, |f|) and the largest violation
    /// of a row or bound, in the problem's own coordinates.
    pub kkt_residual: f64,
    /// λ_j ≥ 0, one per row in the order `constraints` returns them.
    pub multipliers: Vec<f64>,
    /// μ ≥ 0 of the lower bounds.
    pub lower_bound_multipliers: Vec<f64>,
    /// μ ≥ 0 of the upper bounds.
    pub upper_bound_multipliers: Vec<f64>,
    /// Calls of the objective (each evaluation of the program counts once).
    pub evaluations: usize,
    /// Iterations run.
    pub iterations: u64,
    /// Largest estimated error of the last finite-difference gradients.
    pub gradient_error: f64,
    /// Per-iteration trace.
    pub trace: Vec<TraceRow>,
    /// Subproblem failures met on the way (clarabel's statuses other than Solved).
    pub qp_failures: Vec<QpFailure>,
    /// The program's warm-start data at x.
    pub warm_start: Vec<f64>,
}

impl SqpResult {
    /// max_j max(0, g_j).
    pub fn max_violation(&self) -> f64 {
        self.constraints.iter().fold(0.0, |m, g| m.max(*g))
    }
}

/// A program as argmin's problem.
pub(crate) struct Program<'a, P: ?Sized>(&'a P);

/// The SQP solver state.
pub(crate) struct Sqp {
    settings: SqpSettings,
    lower: Vec<f64>,
    upper: Vec<f64>,
    scale: Vec<f64>,
    x: Vec<f64>,
    values: Option<Values>,
    grads: Option<Gradients>,
    hessian: DMatrix<f64>,
    radius: f64,
    max_radius: f64,
    /// D of the trust region at the current point (all 1 without the
    /// scaled trust region).
    trust_scale: Vec<f64>,
    penalty: f64,
    /// The initial ρ: the least ρ falls to ([`SqpSettings::penalty_decay`]).
    penalty_floor: f64,
    /// Each row's weight in the merit, at most ρ ([`SqpSettings::row_penalties`]).
    row_penalty: Vec<f64>,
    qp_multipliers: Vec<f64>,
    kkt: Option<(Kkt, Vec<f64>)>,
    /// The least-squares estimate at the current values and gradients, once
    /// computed (it is asked for more than once per iteration).
    least: Option<(Kkt, Vec<f64>)>,
    evaluations: usize,
    rejections: usize,
    started: Option<Instant>,
    trace: Vec<TraceRow>,
    exit: Option<SqpExit>,
    qp_failures: Vec<QpFailure>,
    last_step: f64,
    last_ratio: f64,
    last_kkt: f64,
    accuracy: Accuracy,
    /// f is a logarithm ([`NonlinearProgram::logarithmic_objective`]).
    logarithmic: bool,
}

fn norm2(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum::<f64>().sqrt()
}

fn norm_inf(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, a| m.max(a.abs()))
}

impl Sqp {
    fn new(settings: &SqpSettings, bounds: (Vec<f64>, Vec<f64>), scale: Vec<f64>) -> Self {
        Sqp {
            settings: settings.clone(),
            lower: bounds.0,
            upper: bounds.1,
            scale,
            x: Vec::new(),
            values: None,
            grads: None,
            hessian: DMatrix::identity(0, 0),
            radius: settings.initial_radius,
            max_radius: 1.0,
            trust_scale: Vec::new(),
            penalty: settings.penalty_initial,
            penalty_floor: settings.penalty_initial,
            row_penalty: Vec::new(),
            qp_multipliers: Vec::new(),
            kkt: None,
            least: None,
            evaluations: 0,
            rejections: 0,
            started: None,
            trace: Vec::new(),
            exit: None,
            qp_failures: Vec::new(),
            last_step: f64::NAN,
            last_ratio: f64::NAN,
            last_kkt: f64::NAN,
            accuracy: if settings.richardson_below <= 0.0 {
                Accuracy::Richardson
            } else if settings.central_below <= 0.0 {
                Accuracy::Central
            } else {
                Accuracy::Forward
            },
            logarithmic: false,
        }
    }

    fn evaluate<P: NonlinearProgram + ?Sized>(
        &mut self,
        p: &P,
        x: &[f64],
        near: &[f64],
    ) -> Option<Values> {
        self.evaluations += 1;
        p.evaluate(x, near)
            .filter(|v| v.objective.is_finite() && v.constraints.iter().all(|g| !g.is_nan()))
    }

    fn gradients_at<P: NonlinearProgram + Sync + ?Sized>(
        &mut self,
        p: &P,
        x: &[f64],
        v: &Values,
        same_point: Option<&Gradients>,
    ) -> Option<Gradients> {
        let g = gradients(
            p,
            x,
            v,
            self.settings.fd_step,
            &self.scale,
            &(self.lower.clone(), self.upper.clone()),
            self.accuracy,
            same_point,
        );
        let per_variable = self.accuracy.points();
        self.evaluations += g.as_ref().map_or(per_variable * x.len(), |g| g.evaluations);
        g.filter(|g| {
            g.objective.iter().all(|d| d.is_finite())
                && g.rows.iter().flatten().all(|d| d.is_finite())
        })
    }

    /// Makes the gradients more accurate for good, recomputing them at the
    /// current point (reusing the stencil points already evaluated there):
    /// Richardson once the KKT residual with least-squares multipliers is at
    /// most `richardson_below` (or 100 × `tolerance`), or when `always`;
    /// central once it is at most `central_below`.
    fn sharpen<P: NonlinearProgram + Sync + ?Sized>(&mut self, p: &P, always: bool) {
        if self.accuracy == Accuracy::Richardson {
            return;
        }
        let (Some(v), Some(g)) = (self.values.clone(), self.grads.clone()) else {
            return;
        };
        let near = self.settings.richardson_threshold();
        // Steps rejected one after another: the model's slope is not the
        // function's, and at a short step that is the gradient's error (a
        // forward difference errs by ~fd_step/2 times the curvature: 0.05 on
        // Rosenbrock's valley floor, more than its whole slope there).
        let doubted =
            if self.settings.doubt_after > 0 && self.rejections >= self.settings.doubt_after {
                match self.accuracy {
                    Accuracy::Forward => Accuracy::Central,
                    _ => Accuracy::Richardson,
                }
            } else {
                Accuracy::Forward
            };
        let wanted = if always {
            Accuracy::Richardson
        } else {
            let residual = self.least_kkt().0.residual;
            if residual <= near {
                Accuracy::Richardson
            } else if residual <= self.settings.central_below {
                Accuracy::Central
            } else {
                Accuracy::Forward
            }
        }
        .max(doubted);
        if wanted <= self.accuracy {
            return;
        }
        self.accuracy = wanted;
        let x = self.x.clone();
        if let Some(g) = self.gradients_at(p, &x, &v, Some(&g)) {
            self.grads = Some(g);
            self.kkt = None;
            self.least = None;
        }
    }

    /// Clamp into the box and put points a hair from a bound on it.
    fn project(&self, x: &[f64]) -> Vec<f64> {
        x.iter()
            .enumerate()
            .map(|(i, &v)| {
                let (lo, hi) = (self.lower[i], self.upper[i]);
                let y = v.clamp(lo, hi);
                let snap = |b: f64| self.settings.bound_snap * b.abs().max(1.0);
                if y - lo <= snap(lo) {
                    lo
                } else if hi - y <= snap(hi) {
                    hi
                } else {
                    y
                }
            })
            .collect()
    }

    fn merit(&self, v: &Values) -> f64 {
        v.objective + self.weighted_violation(&v.constraints)
    }

    /// Σ_j ρ_j max(0, g_j): the merit's share of the rows.
    fn weighted_violation(&self, rows: &[f64]) -> f64 {
        rows.iter()
            .zip(&self.row_penalty)
            .map(|(g, r)| r * g.max(0.0))
            .sum()
    }

    /// Σ_j ρ_j max(0, g_j + ∇g_jᵀp).
    fn weighted_linear_violation(&self, rows: &[f64], p: &[f64]) -> f64 {
        let g = self.grads.as_ref().expect("initialised");
        rows.iter()
            .zip(&g.rows)
            .zip(&self.row_penalty)
            .map(|((&r, d), w)| w * (r + d.iter().zip(p).map(|(a, b)| a * b).sum::<f64>()).max(0.0))
            .sum()
    }

    /// The rows' weights after a step whose multipliers are `lambda` (a row
    /// the step misses, slack > 0, counts as multiplier ρ): each at least
    /// the margin times its multiplier, falling towards that from above by
    /// `penalty_decay`, at least the initial ρ and at most ρ.
    fn update_row_penalties(&mut self, lambda: &[f64], slack: &[f64]) {
        let m = self.row_penalty.len();
        for j in 0..m {
            let t = if self.settings.row_penalties {
                if slack[j] == 0.0 {
                    self.settings.penalty_margin * lambda[j]
                } else {
                    self.penalty
                }
            } else {
                self.penalty
            };
            let r = self.row_penalty[j];
            let next = if r > t {
                t + self.settings.penalty_decay * (r - t)
            } else {
                t
            };
            self.row_penalty[j] = next.max(self.penalty_floor).min(self.penalty);
        }
    }

    fn kkt_data<'a>(&'a self, v: &'a Values, g: &'a Gradients) -> KktData<'a> {
        KktData {
            x: &self.x,
            lower: &self.lower,
            upper: &self.upper,
            objective: v.objective,
            rows: &v.constraints,
            gradient: &g.objective,
            jacobian: &g.rows,
            logarithmic: self.logarithmic,
        }
    }

    /// The least-squares estimate at the current point ([`Sqp::best_kkt`]
    /// without extras), computed once per point.
    fn least_kkt(&mut self) -> (Kkt, Vec<f64>) {
        if let Some(l) = &self.least {
            return l.clone();
        }
        let (v, g) = (
            self.values.as_ref().expect("initialised"),
            self.grads.as_ref().expect("initialised"),
        );
        let l = self.best_kkt(v, g, &[]);
        self.least = Some(l.clone());
        l
    }

    /// The best multiplier estimate among `extra` and the least-squares ones.
    /// Active tolerances that select the same rows give the same estimate:
    /// it is computed once.
    fn best_kkt(&self, v: &Values, g: &Gradients, extra: &[Vec<f64>]) -> (Kkt, Vec<f64>) {
        let d = self.kkt_data(v, g);
        let mut candidates: Vec<Vec<f64>> = extra.to_vec();
        let mut selections: Vec<Vec<bool>> = Vec::new();
        for &t in &self.settings.active_tolerances {
            let rows: Vec<bool> = v.constraints.iter().map(|&r| r >= -t).collect();
            if selections.contains(&rows) {
                continue;
            }
            selections.push(rows);
            candidates.push(least_squares(&d, t));
        }
        candidates
            .into_iter()
            .map(|l| (kkt(&d, &l), l))
            .min_by(|a, b| a.0.residual.total_cmp(&b.0.residual))
            .unwrap_or_else(|| {
                let l = vec![0.0; v.constraints.len()];
                (kkt(&d, &l), l)
            })
    }

    /// As [`Sqp::best_kkt`] with the least-squares pick already made:
    /// the first estimate of `extra` with the smallest residual, unless
    /// `least` has a smaller one.
    fn better_kkt(
        &self,
        v: &Values,
        g: &Gradients,
        extra: &[Vec<f64>],
        least: (Kkt, Vec<f64>),
    ) -> (Kkt, Vec<f64>) {
        let d = self.kkt_data(v, g);
        extra
            .iter()
            .map(|l| (kkt(&d, l), l.clone()))
            .min_by(|a, b| a.0.residual.total_cmp(&b.0.residual))
            .filter(|best| best.0.residual <= least.0.residual)
            .unwrap_or(least)
    }

    /// D of the trust region at x.
    fn trust_scale_at(&self, x: &[f64]) -> Vec<f64> {
        if self.settings.scaled_trust_region {
            x.iter()
                .zip(&self.scale)
                .map(|(a, s)| a.abs().max(*s).max(f64::MIN_POSITIVE))
                .collect()
        } else {
            vec![1.0; x.len()]
        }
    }

    /// ‖D⁻¹p‖₂: a step's length as the trust region measures it.
    fn trust_length(&self, p: &[f64]) -> f64 {
        p.iter()
            .zip(&self.trust_scale)
            .map(|(a, d)| (a / d) * (a / d))
            .sum::<f64>()
            .sqrt()
    }

    /// What radii relative to the point are relative to: 1 with the scaled
    /// trust region (it is relative already), max(1, ‖x‖∞) without.
    fn radius_unit(&self, x: &[f64]) -> f64 {
        if self.settings.scaled_trust_region {
            1.0
        } else {
            norm_inf(x).max(1.0)
        }
    }

    /// The subproblem in the trust region's variables v = D⁻¹p (the Hessian
    /// DBD, the gradients D∇), its step mapped back to p.
    fn scaled_subproblem(
        &self,
        hessian: &DMatrix<f64>,
        gradient: &[f64],
        rows: &[f64],
        radius: f64,
        penalty: f64,
        all_rows: bool,
    ) -> Result<qp::Step, qp::QpFailure> {
        let g = self.grads.as_ref().expect("initialised");
        let d = &self.trust_scale;
        let n = d.len();
        let scaled = |v: &[f64]| -> Vec<f64> { v.iter().zip(d).map(|(a, s)| a * s).collect() };
        let unscaled = |v: &[f64]| -> Vec<f64> { v.iter().zip(d).map(|(a, s)| a / s).collect() };
        let jacobian: Vec<Vec<f64>> = g.rows.iter().map(|r| scaled(r)).collect();
        let include = if all_rows {
            vec![true; rows.len()]
        } else {
            rows.iter()
                .zip(&jacobian)
                .map(|(&g, dg)| g + norm2(dg) * radius >= -1e-12 * (1.0 + g.abs()))
                .collect()
        };
        let h = DMatrix::from_fn(n, n, |i, j| hessian[(i, j)] * d[i] * d[j]);
        let mut step = qp::solve(&Subproblem {
            x: &unscaled(&self.x),
            lower: &unscaled(&self.lower),
            upper: &unscaled(&self.upper),
            include: &include,
            hessian: &h,
            gradient: &scaled(gradient),
            rows,
            jacobian: &jacobian,
            radius,
            penalty,
            gap_tolerance: self.gap_tolerance(),
            max_iterations: self.settings.qp_max_iterations,
        })?;
        step.p = scaled(&step.p);
        Ok(step)
    }

    fn subproblem(&self, rows: &[f64], radius: f64) -> Result<qp::Step, qp::QpFailure> {
        let g = self.grads.as_ref().expect("initialised");
        self.scaled_subproblem(
            &self.hessian,
            &g.objective,
            rows,
            radius,
            self.penalty,
            false,
        )
    }

    /// The subproblem's duality-gap tolerance: loose while the gradients are
    /// forward differences, tight from then on.
    fn gap_tolerance(&self) -> f64 {
        if self.accuracy == Accuracy::Forward {
            self.settings.far_qp_tolerance
        } else {
            self.settings.qp_tolerance
        }
    }

    /// Σ_j max(0, g_j + ∇g_jᵀp): the linearised violation after step p.
    fn linear_violation(&self, rows: &[f64], p: &[f64]) -> f64 {
        let g = self.grads.as_ref().expect("initialised");
        rows.iter()
            .zip(&g.rows)
            .map(|(&r, d)| (r + d.iter().zip(p).map(|(a, b)| a * b).sum::<f64>()).max(0.0))
            .sum()
    }

    /// The least linearised violation any step within `radius` reaches.
    fn least_linear_violation(&self, v: &Values, radius: f64) -> Option<f64> {
        let n = self.x.len();
        // 1e-8 in the trust region's variables.
        let tiny = DMatrix::from_fn(n, n, |i, j| {
            if i == j {
                1e-8 / (self.trust_scale[i] * self.trust_scale[i])
            } else {
                0.0
            }
        });
        let zero = vec![0.0; n];
        self.scaled_subproblem(&tiny, &zero, &v.constraints, radius, 1.0, true)
            .ok()
            .map(|step| self.linear_violation(&v.constraints, &step.p))
    }

    /// Whether no step decreases the linearised violation (a stationary point of it).
    fn violation_stationary(&self, v: &Values) -> bool {
        let radius = self.settings.initial_radius * self.radius_unit(&self.x);
        self.least_linear_violation(v, radius)
            .is_none_or(|least| least >= v.violation() * (1.0 - PROBE_DECREASE))
    }

    /// Whether a point near x has less violation than x (by more than
    /// rounding): the evidence `infeasible` must survive, since the stationarity
    /// [`Sqp::violation_stationary`] finds is that of finite-difference
    /// gradients, which a flat patch of the violation with noise on it (or a
    /// kink within a step) can fake. Probes x ± r e_i for r = R, R/10, R/100
    /// (R the radius of the stationarity test), inside the bounds: at most 6n
    /// evaluations, spent only where a run would end `infeasible`.
    fn violation_falls_nearby<P: NonlinearProgram + ?Sized>(
        &mut self,
        problem: &P,
        v: &Values,
    ) -> bool {
        let viol = v.violation();
        let enough = viol * PROBE_DECREASE + EVALUATION_NOISE * (1.0 + viol);
        let radius = self.settings.initial_radius * norm_inf(&self.x).max(1.0);
        for r in [radius, 0.1 * radius, 0.01 * radius] {
            for i in 0..self.x.len() {
                for sign in [1.0, -1.0] {
                    let mut y = self.x.clone();
                    y[i] = (y[i] + sign * r).clamp(self.lower[i], self.upper[i]);
                    if y[i] == self.x[i] {
                        continue;
                    }
                    if let Some(w) = self.evaluate(problem, &y, &v.warm_start) {
                        if w.violation() < viol - enough {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }

    /// Whether step p reduces the linearised violation by less than half of
    /// what a step of its length could (then the penalty is too small).
    fn steps_too_little_to_feasibility(&self, v: &Values, p: &[f64]) -> bool {
        let viol = v.violation();
        let reached = viol - self.linear_violation(&v.constraints, p);
        match self.least_linear_violation(v, self.trust_length(p).max(1e-300)) {
            Some(least) => reached < 0.5 * (viol - least),
            None => true,
        }
    }

    /// Ends a run that cannot go on: `infeasible` at a stationary point of a
    /// violation, `stalled` otherwise.
    fn stop_stuck(&mut self) {
        let v = self.values.clone().expect("initialised");
        self.exit = Some(
            if v.max_violation() > self.settings.feasibility_tolerance
                && self.violation_stationary(&v)
            {
                SqpExit::Infeasible
            } else {
                SqpExit::Stalled
            },
        );
    }

    fn record(&mut self, iteration: usize) {
        if let (Some(v), Some((k, _))) = (&self.values, &self.kkt) {
            self.trace.push(TraceRow {
                iteration,
                time: self.started.map_or(0.0, |t| t.elapsed().as_secs_f64()),
                objective: v.objective,
                kkt_residual: k.residual,
                violation: v.max_violation(),
            });
        }
    }

    fn reject(&mut self, step_length: f64) {
        self.radius = self.settings.shrink_factor * step_length.min(self.radius);
        self.rejections += 1;
        let floor = self.settings.min_radius * self.radius_unit(&self.x);
        if self.radius < floor || self.rejections > self.settings.max_rejections {
            self.stop_stuck();
        }
    }

    fn kv(&self) -> KV {
        let (obj, viol) = self
            .values
            .as_ref()
            .map_or((f64::NAN, f64::NAN), |v| (v.objective, v.max_violation()));
        argmin::kv!(
            "objective" => obj;
            "violation" => viol;
            "kkt" => self.last_kkt;
            "radius" => self.radius;
            "penalty" => self.penalty;
            "evaluations" => self.evaluations as u64;
            "step" => self.last_step;
            "ratio" => self.last_ratio;
        )
    }

    /// Doubles the accepted step from `x` to `to` (values `at`), up to the
    /// trust radius and into the box, while that lowers the merit by more
    /// than `noise` (see [`SqpSettings::extend_ratio`]).
    fn extend<P: NonlinearProgram + ?Sized>(
        &mut self,
        p: &P,
        x: &[f64],
        mut to: Vec<f64>,
        mut at: Values,
        noise: f64,
    ) -> (Vec<f64>, Values) {
        loop {
            let s: Vec<f64> = to.iter().zip(x).map(|(a, b)| a - b).collect();
            let len = self.trust_length(&s);
            if len >= 0.99 * self.radius || len == 0.0 {
                break;
            }
            let factor = (self.radius / len).min(2.0);
            let target: Vec<f64> = x.iter().zip(&s).map(|(a, d)| a + factor * d).collect();
            let next = self.project(&target);
            if next == to {
                break;
            }
            let near = at.warm_start.clone();
            match self.evaluate(p, &next, &near) {
                Some(v) if self.merit(&v) < self.merit(&at) - noise => {
                    to = next;
                    at = v;
                }
                _ => break,
            }
        }
        (to, at)
    }

    /// Damped BFGS update (Powell) of the Lagrangian Hessian.
    fn update_hessian(&mut self, s: &[f64], old: &Gradients, new: &Gradients, lambda: &[f64]) {
        let n = s.len();
        let lag = |g: &Gradients| {
            DVector::from_iterator(
                n,
                (0..n).map(|i| {
                    g.objective[i]
                        + lambda
                            .iter()
                            .zip(&g.rows)
                            .map(|(l, r)| l * r[i])
                            .sum::<f64>()
                }),
            )
        };
        let s = DVector::from_column_slice(s);
        let y = lag(new) - lag(old);
        let bs = &self.hessian * &s;
        let sbs = s.dot(&bs);
        let sy = s.dot(&y);
        if sbs > 1e-300 {
            let theta = if sy >= 0.2 * sbs {
                1.0
            } else {
                0.8 * sbs / (sbs - sy)
            };
            let r = &y * theta + &bs * (1.0 - theta);
            let sr = s.dot(&r);
            if sr > 1e-300 {
                self.hessian += &r * r.transpose() / sr - &bs * bs.transpose() / sbs;
            }
        }
    }
}

/// The merit ratio actual/predicted, with noise and sign rules.
fn merit_ratio(actual: f64, predicted: f64, noise: f64) -> f64 {
    if predicted.abs() <= noise {
        if actual >= -noise {
            1.0
        } else {
            -1.0
        }
    } else if predicted > 0.0 {
        actual / predicted
    } else if actual > 0.0 {
        1.0
    } else {
        -1.0
    }
}

impl<P: NonlinearProgram + Sync + ?Sized> Solver<Program<'_, P>, SqpState> for Sqp {
    fn name(&self) -> &str {
        "SQP (clarabel subproblems, damped BFGS, ℓ1 merit)"
    }

    fn init(
        &mut self,
        problem: &mut Problem<Program<'_, P>>,
        state: SqpState,
    ) -> Result<(SqpState, Option<KV>), Error> {
        self.started = Some(Instant::now());
        let prog = problem
            .problem
            .as_ref()
            .map(|p| p.0)
            .ok_or_else(|| Error::msg("no problem"))?;
        let x0 = state
            .get_param()
            .cloned()
            .ok_or_else(|| Error::msg("the SQP needs a start point"))?;
        self.x = self.project(&x0);
        let n = self.x.len();
        self.hessian = DMatrix::identity(n, n);
        self.trust_scale = self.trust_scale_at(&self.x);
        self.radius = self.settings.initial_radius * self.radius_unit(&self.x);
        let widths: Vec<f64> = self
            .lower
            .iter()
            .zip(&self.upper)
            .map(|(l, u)| u - l)
            .collect();
        self.max_radius = self.trust_length(&widths).max(self.radius);
        let x = self.x.clone();
        let values = self.evaluate(prog, &x, &[]);
        let grads = values
            .as_ref()
            .and_then(|v| self.gradients_at(prog, &x, v, None));
        let (Some(values), Some(grads)) = (values, grads) else {
            self.exit = Some(SqpExit::Unevaluable);
            return Ok((state, None));
        };
        self.penalty = self.settings.penalty_initial * norm_inf(&grads.objective).max(1.0);
        self.penalty_floor = self.penalty;
        self.row_penalty = vec![self.penalty; values.constraints.len()];
        self.qp_multipliers = vec![0.0; values.constraints.len()];
        let cost = values.objective;
        let gradient = grads.objective.clone();
        let least = self.best_kkt(&values, &grads, &[]);
        self.kkt = Some(least.clone());
        self.least = Some(least);
        self.values = Some(values);
        self.grads = Some(grads);
        Ok((state.cost(cost).gradient(gradient), None))
    }

    fn next_iter(
        &mut self,
        problem: &mut Problem<Program<'_, P>>,
        state: SqpState,
    ) -> Result<(SqpState, Option<KV>), Error> {
        let prog = problem
            .problem
            .as_ref()
            .map(|p| p.0)
            .ok_or_else(|| Error::msg("no problem"))?;
        self.sharpen(prog, false);
        let v = self
            .values
            .clone()
            .ok_or_else(|| Error::msg("not initialised"))?;
        let grads = self
            .grads
            .clone()
            .ok_or_else(|| Error::msg("not initialised"))?;
        // The least-squares multipliers first: where they already meet the
        // KKT test the run ends without solving a subproblem.
        let least = self.least_kkt();
        if self.settings.met(&least.0) {
            self.last_kkt = least.0.residual;
            self.kkt = Some(least);
            self.record(state.get_iter() as usize);
            self.exit = Some(SqpExit::Converged);
            return Ok((state.cost(v.objective), Some(self.kv())));
        }
        let step = match self.subproblem(&v.constraints, self.radius) {
            Ok(s) => s,
            Err(fail) => {
                self.qp_failures.push(fail);
                let r = self.radius;
                self.reject(r);
                return Ok((state.cost(v.objective), Some(self.kv())));
            }
        };
        // Multipliers: the subproblem's (without the trust region where it
        // binds, since there they are not the KKT multipliers) and the
        // least-squares ones; the estimate with the smallest residual. The
        // estimate without the trust region serves only the KKT test: it is
        // solved only where the least-squares one says the point is near a
        // KKT point (residual within the Richardson threshold).
        let p_len = self.trust_length(&step.p);
        let mut extra = vec![step.multipliers.clone()];
        let near = self.settings.richardson_threshold();
        if p_len >= 0.99 * self.radius && least.0.residual <= near {
            if let Ok(s) = self.subproblem(&v.constraints, 1e3 * self.max_radius) {
                extra.push(s.multipliers);
            }
        }
        self.kkt = Some(self.better_kkt(&v, &grads, &extra, least));
        self.last_kkt = self.kkt.as_ref().map_or(f64::NAN, |k| k.0.residual);
        self.record(state.get_iter() as usize);
        if self.kkt.as_ref().is_some_and(|k| self.settings.met(&k.0)) {
            self.exit = Some(SqpExit::Converged);
            return Ok((state.cost(v.objective), Some(self.kv())));
        }
        // No step: the subproblem's, put into the box, does not move x.
        let xs = norm_inf(&self.x).max(1.0);
        let x_old = self.x.clone();
        let target: Vec<f64> = x_old.iter().zip(&step.p).map(|(a, b)| a + b).collect();
        let mut trial_x = self.project(&target);
        let moved: Vec<f64> = trial_x.iter().zip(&x_old).map(|(a, b)| a - b).collect();
        if p_len <= self.settings.step_tolerance * self.radius_unit(&x_old)
            || norm2(&moved) <= self.settings.step_tolerance * xs
        {
            self.stop_stuck();
            return Ok((state.cost(v.objective), Some(self.kv())));
        }
        // Penalty: above the multipliers of the rows the step meets by a
        // margin; up when the linearisation could not be met. A row whose
        // linearisation the step misses (slack > 0) has multiplier ρ itself
        // and is left out: with it the margin would double ρ at every such
        // step, to 1e8-1e10 before the rows are met, and the merit would then
        // see nothing but the violation.
        let lmax = step
            .multipliers
            .iter()
            .zip(&step.slack)
            .filter(|(_, t)| **t == 0.0)
            .fold(0.0f64, |m, (l, _)| m.max(*l));
        let slack: f64 = step.slack.iter().sum();
        self.penalty = self
            .penalty
            .max(self.settings.penalty_margin * lmax)
            .min(self.settings.penalty_max);
        self.update_row_penalties(&step.multipliers, &step.slack);
        let predicted = -step.objective_change + self.weighted_violation(&v.constraints)
            - self.weighted_linear_violation(&v.constraints, &step.p);
        let noise = self.settings.merit_noise * (1.0 + self.merit(&v).abs());
        let mut trial = self.evaluate(prog, &trial_x, &v.warm_start);
        let ratio_of = |s: &Sqp, t: &Option<Values>| match t {
            None => -1.0,
            Some(t) => merit_ratio(s.merit(&v) - s.merit(t), predicted, noise),
        };
        let mut ratio = ratio_of(self, &trial);
        // Second-order correction: the rows re-linearised with their values at
        // the trial point (against the Maratos effect near curved active rows).
        if ratio < self.settings.accept_ratio {
            if let Some(t) = &trial {
                if t.violation() > v.violation() {
                    let s: Vec<f64> = trial_x.iter().zip(&x_old).map(|(a, b)| a - b).collect();
                    let rows: Vec<f64> = t
                        .constraints
                        .iter()
                        .zip(&grads.rows)
                        .map(|(g, d)| g - d.iter().zip(&s).map(|(a, b)| a * b).sum::<f64>())
                        .collect();
                    if let Ok(c) = self.subproblem(&rows, self.radius) {
                        let target: Vec<f64> = x_old.iter().zip(&c.p).map(|(a, b)| a + b).collect();
                        let cx = self.project(&target);
                        let ct = self.evaluate(prog, &cx, &v.warm_start);
                        let cr = ratio_of(self, &ct);
                        if cr >= self.settings.accept_ratio {
                            trial_x = cx;
                            trial = ct;
                            ratio = cr;
                        }
                    }
                }
            }
        }
        self.last_step = p_len;
        self.last_ratio = ratio;
        if ratio < self.settings.accept_ratio {
            if slack > 1e-9 && self.steps_too_little_to_feasibility(&v, &step.p) {
                self.penalty =
                    (self.settings.penalty_growth * self.penalty).min(self.settings.penalty_max);
            }
            self.reject(p_len);
            return Ok((state.cost(v.objective), Some(self.kv())));
        }
        let mut trial = trial.expect("accepted steps have values");
        if ratio >= self.settings.extend_ratio && p_len < 0.99 * self.radius {
            (trial_x, trial) = self.extend(prog, &x_old, trial_x, trial, noise);
        }
        let Some(new_grads) = self.gradients_at(prog, &trial_x, &trial, None) else {
            self.reject(p_len);
            return Ok((state.cost(v.objective), Some(self.kv())));
        };
        let s: Vec<f64> = trial_x.iter().zip(&x_old).map(|(a, b)| a - b).collect();
        self.update_hessian(&s, &grads, &new_grads, &step.multipliers);
        let s_len = self.trust_length(&s);
        if ratio >= self.settings.grow_ratio && s_len >= 0.8 * self.radius {
            self.radius = (self.settings.grow_factor * self.radius).min(self.max_radius);
        } else if ratio < self.settings.shrink_ratio {
            self.radius *= self.settings.shrink_factor;
        }
        if slack > 1e-9 && self.steps_too_little_to_feasibility(&v, &step.p) {
            self.penalty =
                (self.settings.penalty_growth * self.penalty).min(self.settings.penalty_max);
        } else {
            let target = self.penalty_floor.max(self.settings.penalty_margin * lmax);
            if self.penalty > target {
                self.penalty = target + self.settings.penalty_decay * (self.penalty - target);
            }
        }
        self.rejections = 0;
        self.qp_multipliers = step.multipliers;
        self.x = trial_x;
        self.trust_scale = self.trust_scale_at(&self.x);
        let cost = trial.objective;
        let gradient = new_grads.objective.clone();
        self.kkt = None;
        self.least = None;
        self.values = Some(trial);
        self.grads = Some(new_grads);
        Ok((
            state.cost(cost).gradient(gradient).param(self.x.clone()),
            Some(self.kv()),
        ))
    }

    fn terminate(&mut self, _state: &SqpState) -> TerminationStatus {
        match self.exit {
            Some(SqpExit::Converged) => {
                TerminationStatus::Terminated(TerminationReason::SolverConverged)
            }
            Some(other) => TerminationStatus::Terminated(TerminationReason::SolverExit(
                other.as_str().to_string(),
            )),
            None => TerminationStatus::NotTerminated,
        }
    }
}

/// Why the solver itself ended a run (before the driver's caps): what the
/// result's status is made from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SqpExit {
    /// The KKT test was met.
    Converged,
    /// A stationary point of the violation with the violation above tolerance.
    Infeasible,
    /// No progress: the radius collapsed or steps kept being rejected.
    Stalled,
    /// The program could not be evaluated at the start.
    Unevaluable,
}

impl SqpExit {
    /// The word argmin's termination reason carries.
    pub fn as_str(self) -> &'static str {
        match self {
            SqpExit::Converged => "converged",
            SqpExit::Infeasible => "infeasible",
            SqpExit::Stalled => "stalled",
            SqpExit::Unevaluable => "unevaluable",
        }
    }
}

/// An observer that does nothing.
pub struct NoObserver;
impl Observe<SqpState> for NoObserver {}

/// Minimises `problem` from `x0` (projected into the bounds). Never
/// evaluates outside the bounds; bad input shows in the status.
pub fn minimize(
    problem: &(impl NonlinearProgram + Sync),
    x0: &[f64],
    settings: &SqpSettings,
) -> SqpResult {
    minimize_observed(problem, x0, settings, None::<NoObserver>)
}

/// As [`minimize`], with an argmin observer that sees every iteration's
/// key-value diagnostics (`objective`, `violation`, `kkt`, `radius`,
/// `penalty`, `evaluations`, `step`, `ratio`).
pub fn minimize_observed<P, O>(
    problem: &P,
    x0: &[f64],
    settings: &SqpSettings,
    observer: Option<O>,
) -> SqpResult
where
    P: NonlinearProgram + Sync + ?Sized,
    O: Observe<SqpState> + 'static,
{
    let n = problem.dimension();
    let bounds = problem.bounds();
    let mut scale = problem.scale();
    scale.resize(n, 1.0);
    let mut x0 = x0.to_vec();
    x0.resize(n, 0.0);
    let mut solver = Sqp::new(settings, bounds, scale);
    solver.logarithmic = problem.logarithmic_objective();
    let mut exec = Executor::new(Program(problem), solver)
        .configure(|s| s.param(x0.clone()).max_iters(settings.max_iterations));
    if let Some(t) = settings.time_limit {
        exec = exec.timeout(t.max(Duration::from_nanos(1)));
    }
    if let Some(o) = observer {
        exec = exec.add_observer(o, ObserverMode::Always);
    }
    let (mut solver, reason, iterations) = match exec.run() {
        Ok(res) => {
            let reason = res.state.get_termination_reason().cloned();
            (res.solver, reason, res.state.get_iter())
        }
        Err(_) => {
            let mut s = Sqp::new(settings, problem.bounds(), problem.scale());
            s.logarithmic = problem.logarithmic_objective();
            s.exit = Some(SqpExit::Unevaluable);
            (s, None, 0)
        }
    };
    solver.sharpen(problem, true);
    finish(problem, &mut solver, reason, iterations)
}

fn finish<P: NonlinearProgram + Sync + ?Sized>(
    problem: &P,
    solver: &mut Sqp,
    reason: Option<TerminationReason>,
    iterations: u64,
) -> SqpResult {
    let (Some(v), Some(g)) = (solver.values.clone(), solver.grads.clone()) else {
        let x = solver.project(&solver.x);
        let m = problem.constraints(&x).map_or(0, |c| c.len());
        return SqpResult {
            x,
            objective: f64::INFINITY,
            constraints: vec![0.0; m],
            status: SqpStatus::Stalled,
            kkt_residual: f64::INFINITY,
            multipliers: vec![0.0; m],
            lower_bound_multipliers: vec![0.0; problem.dimension()],
            upper_bound_multipliers: vec![0.0; problem.dimension()],
            evaluations: solver.evaluations,
            iterations,
            gradient_error: 0.0,
            trace: Vec::new(),
            qp_failures: solver.qp_failures.clone(),
            warm_start: Vec::new(),
        };
    };
    if solver.kkt.is_none() {
        let extra = vec![solver.qp_multipliers.clone()];
        let least = solver.least_kkt();
        solver.kkt = Some(solver.better_kkt(&v, &g, &extra, least));
        solver.record(iterations as usize);
    }
    if solver.exit == Some(SqpExit::Infeasible) && solver.violation_falls_nearby(problem, &v) {
        solver.exit = Some(SqpExit::Stalled);
    }
    let (k, lambda) = solver.kkt.clone().expect("set above");
    let status = match (solver.exit, &reason) {
        (Some(SqpExit::Converged), _) => SqpStatus::Optimal,
        (Some(SqpExit::Infeasible), _) => SqpStatus::Infeasible,
        (Some(SqpExit::Stalled | SqpExit::Unevaluable), _) => SqpStatus::Stalled,
        (None, Some(TerminationReason::Timeout)) => SqpStatus::TimeLimit,
        (None, Some(TerminationReason::MaxItersReached)) => SqpStatus::IterationLimit,
        (None, _) => SqpStatus::Stalled,
    };
    // The test is the residual itself: a run stopped otherwise that happens
    // to meet it is optimal, one marked converged that does not is not.
    let status = if solver.settings.met(&k) {
        SqpStatus::Optimal
    } else if status == SqpStatus::Optimal {
        SqpStatus::Stalled
    } else {
        status
    };
    SqpResult {
        x: solver.x.clone(),
        objective: v.objective,
        constraints: v.constraints.clone(),
        status,
        kkt_residual: k.residual,
        multipliers: lambda,
        lower_bound_multipliers: k.lower,
        upper_bound_multipliers: k.upper,
        evaluations: solver.evaluations,
        iterations,
        gradient_error: g.error,
        trace: solver.trace.clone(),
        qp_failures: solver.qp_failures.clone(),
        warm_start: v.warm_start,
    }
}
