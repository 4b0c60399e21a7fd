//! A trust-region SQP as an argmin [`Solver`]: quasi-Newton (damped BFGS)
//! subproblems solved by clarabel ([`super::qp`]), elastic mode for
//! inconsistent linearisations, acceptance by the ℓ1 merit function
//! `φ = f + ρ Σ max(0, g_j)`, and convergence on the KKT residual.

use std::time::Instant;

use argmin::core::{
    Error, IterState, Problem, Solver, State, TerminationReason, TerminationStatus, KV,
};
use nalgebra::{DMatrix, DVector};

use super::fd::{gradients, Gradients};
use super::functions::{Point, StudyFunctions};
use super::qp::{self, Subproblem};

/// The argmin state the SQP runs on: parameter and gradient are `Vec<f64>`.
pub type SqpState = IterState<Vec<f64>, Vec<f64>, (), (), (), f64>;

/// Rows at or below this (in their scaled units) count as satisfied.
pub const FEASIBILITY_TOLERANCE: f64 = 1e-7;

/// Unit coordinates closer than this to a face are put on it (1e-8 of the
/// log range of a variable: far below any engineering meaning).
pub const BOUND_SNAP: f64 = 1e-8;

/// One row of the iteration trace.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceRow {
    /// Iteration number (0 = the start point); the row describes the point
    /// the iteration starts from.
    pub iteration: usize,
    /// Wall time since the start's first evaluation (s).
    pub time: f64,
    /// ln(objective) at the current point.
    pub objective: f64,
    /// KKT residual at the current point.
    pub kkt_residual: f64,
    /// max_j max(0, g_j) at the current point.
    pub violation: f64,
}

/// The SQP solver and, after a run, what it found.
pub struct Sqp {
    tolerance: f64,
    point: Option<Point>,
    grads: Option<Gradients>,
    hessian: DMatrix<f64>,
    radius: f64,
    penalty: f64,
    /// Multipliers of the rows at the current point.
    pub multipliers: Vec<f64>,
    /// KKT residual at the current point.
    pub kkt_residual: f64,
    /// Largest error estimate of the last gradients.
    pub gradient_error: f64,
    /// Model evaluations spent.
    pub evaluations: usize,
    rejections: usize,
    started: Option<Instant>,
    /// Per-iteration trace.
    pub trace: Vec<TraceRow>,
    /// Why the run stopped when the solver stopped it ("converged", "stalled", "infeasible").
    pub exit: Option<&'static str>,
    /// Subproblem failures (clarabel statuses other than Solved).
    pub qp_failures: Vec<String>,
    last_step: f64,
    last_ratio: f64,
}

impl Sqp {
    /// A solver converging when the KKT residual is below `tolerance` (or below
    /// twice the finite-difference error, which it cannot beat).
    pub fn new(tolerance: f64) -> Self {
        Sqp {
            tolerance,
            point: None,
            grads: None,
            hessian: DMatrix::identity(0, 0),
            radius: 0.3,
            penalty: 10.0,
            multipliers: Vec::new(),
            kkt_residual: f64::INFINITY,
            gradient_error: 0.0,
            evaluations: 0,
            rejections: 0,
            started: None,
            trace: Vec::new(),
            exit: None,
            qp_failures: Vec::new(),
            last_step: f64::NAN,
            last_ratio: f64::NAN,
        }
    }

    /// The current point (after a run: where it stopped).
    pub fn point(&self) -> Option<&Point> {
        self.point.as_ref()
    }

    /// The gradients at the current point.
    pub fn gradients(&self) -> Option<&Gradients> {
        self.grads.as_ref()
    }

    fn record(&mut self, iteration: usize) {
        if let Some(p) = &self.point {
            self.trace.push(TraceRow {
                iteration,
                time: self.started.map_or(0.0, |t| t.elapsed().as_secs_f64()),
                objective: p.objective,
                kkt_residual: self.kkt_residual,
                violation: p.max_violation(),
            });
        }
    }
}

/// The KKT residual at a point with multipliers λ: the largest of
/// `‖x - P_box(x - ∇_x L)‖∞` (stationarity, with the bounds' own multipliers
/// implied by the projection, so a point a hair inside a bound is judged by its
/// distance to it), `max_j max(0, g_j)` (feasibility) and `max_j |λ_j g_j|`
/// (complementarity). λ ≥ 0 holds by construction.
pub fn kkt_residual(point: &Point, grads: &Gradients, multipliers: &[f64]) -> f64 {
    let n = point.x.len();
    let mut worst = 0.0f64;
    for i in 0..n {
        let mut r = grads.objective[i];
        for (j, l) in multipliers.iter().enumerate() {
            r += l * grads.rows[j][i];
        }
        let x = point.x[i];
        worst = worst.max((x - (x - r).clamp(0.0, 1.0)).abs());
    }
    for (j, &g) in point.rows.iter().enumerate() {
        worst = worst.max(g.max(0.0));
        worst = worst.max((multipliers.get(j).copied().unwrap_or(0.0) * g).abs());
    }
    worst
}

fn lagrangian_gradient(grads: &Gradients, multipliers: &[f64]) -> DVector<f64> {
    let n = grads.objective.len();
    DVector::from_iterator(
        n,
        (0..n).map(|i| {
            grads.objective[i]
                + multipliers
                    .iter()
                    .enumerate()
                    .map(|(j, l)| l * grads.rows[j][i])
                    .sum::<f64>()
        }),
    )
}

fn merit(p: &Point, penalty: f64) -> f64 {
    p.objective + penalty * p.violation()
}

impl Solver<StudyFunctions, SqpState> for Sqp {
    fn name(&self) -> &str {
        "SQP (clarabel subproblems, damped BFGS, ℓ1 merit)"
    }

    fn init(
        &mut self,
        problem: &mut Problem<StudyFunctions>,
        state: SqpState,
    ) -> Result<(SqpState, Option<KV>), Error> {
        self.started = Some(Instant::now());
        let x0 = state
            .get_param()
            .cloned()
            .ok_or_else(|| Error::msg("the SQP needs a start point"))?;
        let n = x0.len();
        self.hessian = DMatrix::identity(n, n);
        let (point, grads) = problem.problem("evaluations", |f| {
            let p = f.at(&x0);
            let g = p.as_ref().and_then(|p| gradients(f, p));
            Ok((p, g))
        })?;
        self.evaluations += 1 + grads.as_ref().map_or(0, |g| g.evaluations);
        let (Some(point), Some(grads)) = (point, grads) else {
            self.exit = Some("no_contact");
            return Ok((
                state.terminate_with(TerminationReason::SolverExit(
                    "no contact at the start".into(),
                )),
                None,
            ));
        };
        let scale = grads.objective.iter().fold(1.0f64, |m, g| m.max(g.abs()));
        self.penalty = 10.0 * scale;
        self.multipliers = vec![0.0; point.rows.len()];
        self.gradient_error = grads.error;
        self.kkt_residual = kkt_residual(&point, &grads, &self.multipliers);
        let cost = point.objective;
        let gradient = grads.objective.clone();
        self.point = Some(point);
        self.grads = Some(grads);
        Ok((state.cost(cost).gradient(gradient), None))
    }

    fn next_iter(
        &mut self,
        problem: &mut Problem<StudyFunctions>,
        state: SqpState,
    ) -> Result<(SqpState, Option<KV>), Error> {
        let point = self
            .point
            .clone()
            .ok_or_else(|| Error::msg("not initialised"))?;
        let grads = self
            .grads
            .clone()
            .ok_or_else(|| Error::msg("not initialised"))?;
        let n = point.x.len();
        let sp = Subproblem {
            x: &point.x,
            hessian: &self.hessian,
            gradient: &grads.objective,
            rows: &point.rows,
            jacobian: &grads.rows,
            radius: self.radius,
            penalty: self.penalty,
        };
        let step = match qp::solve(&sp) {
            Ok(s) => s,
            Err(fail) => {
                // Not Solved is not solved: shrink the region and try again.
                self.qp_failures.push(fail.status);
                self.radius *= 0.25;
                self.rejections += 1;
                if self.radius < 1e-10 || self.rejections > 30 {
                    self.exit = Some("stalled");
                }
                return Ok((state.cost(point.objective), Some(self.kv())));
            }
        };
        // Converged? KKT at x with the subproblem's multipliers; where the trust
        // region binds they are not the KKT multipliers, so take them from the
        // same subproblem without it.
        let p_len = step.p.iter().map(|v| v * v).sum::<f64>().sqrt();
        let estimate = if p_len >= 0.99 * self.radius {
            qp::solve(&Subproblem {
                radius: (n as f64).sqrt() + 1.0,
                ..sp
            })
            .map(|s| s.multipliers)
            .unwrap_or_else(|_| step.multipliers.clone())
        } else {
            step.multipliers.clone()
        };
        // The best of the two estimates (each gives an upper bound on the
        // residual minimised over λ ≥ 0).
        let estimate = match qp::least_squares_multipliers(
            &point.x,
            &grads.objective,
            &point.rows,
            &grads.rows,
            1e-6,
        ) {
            Some(ls)
                if kkt_residual(&point, &grads, &ls) < kkt_residual(&point, &grads, &estimate) =>
            {
                ls
            }
            _ => estimate,
        };
        let kkt = kkt_residual(&point, &grads, &estimate);
        self.kkt_residual = kkt;
        self.record(state.get_iter() as usize);
        // Finite-difference gradients carry an error of `grads.error` per
        // component; stationarity cannot be resolved below what that error
        // becomes through ∇f + Σ λ_j ∇g_j (with a safety factor of 10 for an
        // estimate that is itself estimated).
        let resolvable = 10.0 * grads.error * (1.0 + estimate.iter().sum::<f64>());
        let threshold = self.tolerance.max(resolvable);
        let slack: f64 = step.slack.iter().sum();
        if kkt <= threshold {
            self.multipliers = estimate;
            self.exit = Some("converged");
            return Ok((state.cost(point.objective), Some(self.kv())));
        }
        let p_norm = step.p.iter().map(|v| v * v).sum::<f64>().sqrt();
        if p_norm <= 1e-12 {
            // The subproblem cannot move: a stationary point of the violation
            // (infeasible) or a point the KKT test cannot certify (stalled).
            self.exit = Some(if point.max_violation() > FEASIBILITY_TOLERANCE {
                "infeasible"
            } else {
                "stalled"
            });
            return Ok((state.cost(point.objective), Some(self.kv())));
        }
        let predicted = -step.objective_change + self.penalty * (point.violation() - slack);
        // Interior-point steps stop a hair from a bound: snap to the face.
        let trial_x: Vec<f64> = point
            .x
            .iter()
            .zip(&step.p)
            .map(|(x, d)| {
                let y = (x + d).clamp(0.0, 1.0);
                if y < BOUND_SNAP {
                    0.0
                } else if y > 1.0 - BOUND_SNAP {
                    1.0
                } else {
                    y
                }
            })
            .collect();
        let hints = point.hints;
        let trial = problem.problem("evaluations", |f| Ok(f.at_from(&trial_x, hints)))?;
        self.evaluations += 1;
        // The merit is known to about 1e-13 (evaluator accuracy in ln units):
        // a step whose predicted change lies within that noise cannot be judged
        // by the ratio and is taken when it does not lose more than the noise.
        let noise = 1e-12 * (1.0 + merit(&point, self.penalty).abs());
        let ratio = match &trial {
            None => -1.0,
            Some(t) => {
                let actual = merit(&point, self.penalty) - merit(t, self.penalty);
                if predicted.abs() <= noise {
                    // Within the noise: take the step unless it loses more than it.
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
        };
        self.last_step = p_norm;
        self.last_ratio = ratio;
        if ratio > 0.1 {
            let trial = trial.expect("ratio > 0 only with a trial point");
            let new_grads = problem.problem("gradients", |f| Ok(gradients(f, &trial)))?;
            let Some(new_grads) = new_grads else {
                self.radius = 0.25 * p_norm;
                self.rejections += 1;
                return Ok((state.cost(point.objective), Some(self.kv())));
            };
            self.evaluations += new_grads.evaluations;
            // Damped BFGS on the Lagrangian (Powell).
            let s = DVector::from_iterator(n, trial.x.iter().zip(&point.x).map(|(a, b)| a - b));
            let y = lagrangian_gradient(&new_grads, &step.multipliers)
                - lagrangian_gradient(&grads, &step.multipliers);
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
            if ratio > 0.75 && p_norm >= 0.8 * self.radius {
                self.radius = (2.0 * self.radius).min((n as f64).sqrt());
            }
            self.rejections = 0;
            self.multipliers = step.multipliers;
            self.gradient_error = new_grads.error;
            let cost = trial.objective;
            let gradient = new_grads.objective.clone();
            self.point = Some(trial);
            self.grads = Some(new_grads);
            if slack > 1e-9 {
                // The linearisation could not be met: weigh feasibility more.
                self.penalty = (10.0 * self.penalty).min(1e8);
            }
            return Ok((
                state
                    .cost(cost)
                    .gradient(gradient)
                    .param(self.point.as_ref().map(|p| p.x.clone()).unwrap_or_default()),
                Some(self.kv()),
            ));
        }
        // Rejected.
        self.radius = 0.5 * p_norm.min(self.radius);
        self.rejections += 1;
        if slack > 1e-9 && self.penalty < 1e8 {
            self.penalty = (10.0 * self.penalty).min(1e8);
        }
        if self.radius < 1e-10 || self.rejections > 30 {
            self.exit = Some(if point.max_violation() > FEASIBILITY_TOLERANCE {
                "infeasible"
            } else {
                "stalled"
            });
        }
        Ok((state.cost(point.objective), Some(self.kv())))
    }

    fn terminate(&mut self, _state: &SqpState) -> TerminationStatus {
        match self.exit {
            Some("converged") => TerminationStatus::Terminated(TerminationReason::SolverConverged),
            Some(other) => {
                TerminationStatus::Terminated(TerminationReason::SolverExit(other.to_string()))
            }
            None => TerminationStatus::NotTerminated,
        }
    }
}

impl Sqp {
    fn kv(&self) -> KV {
        let (obj, viol) = self
            .point
            .as_ref()
            .map_or((f64::NAN, f64::NAN), |p| (p.objective, p.max_violation()));
        argmin::kv!(
            "objective" => obj;
            "violation" => viol;
            "kkt" => self.kkt_residual;
            "radius" => self.radius;
            "penalty" => self.penalty;
            "evaluations" => self.evaluations as u64;
            "step" => self.last_step;
            "ratio" => self.last_ratio;
        )
    }
}
