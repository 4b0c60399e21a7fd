//! Design under uncertainty: a statistic of the objective over the random inputs,
//! chance constraints P(g_j ≤ 0) ≤ p_j solved by SORA, and the verification of
//! every reported optimum by sampling (docs/uncertainty.md, "Robust and
//! chance-constrained design: the engine").
//!
//! A problem is an [`UncertainProgram`]: design variables d in a finite box and,
//! at each d, an [`InputModel`] of the random inputs x (which may move with d: a
//! design variable that is also uncertain is the mean or median of its law) and
//! the model's [`Outputs`] at (d, x).
//!
//! * **Statistic objectives** ([`Statistic`]): the mean, the 95 % and 99 %
//!   quantiles, the conditional value at risk CVaR₉₅ and mean + 3 sd of the
//!   objective over `samples` common random numbers u_k = Φ⁻¹(v_k), v_k the points
//!   of one Owen-scrambled Sobol′ sequence ([`common_points`]), mapped through
//!   `inputs(d).to_physical(u_k)`. The same u_k at every design make the statistic
//!   a continuous function of d that the SQP can differentiate; [`estimate`] gives
//!   its 95 % interval.
//! * **Chance constraints** by SORA (Du & Chen 2004, "Sequential optimization and
//!   reliability assessment method for efficient probabilistic design", J. Mech.
//!   Des. 126:225): cycle k solves the deterministic [`ShiftedProgram`] whose row j
//!   is −g_j(d, T_d(u*_j)) ≤ 0 with u*_j, the most probable target point of the
//!   previous cycle ([`inverse_form`], PMA with β_t = −Φ⁻¹(p_j)), held fixed in
//!   standard space while d moves (for X ~ N(d, s) this is the classical shift
//!   x = d − s_j). The cycles stop when no u*_j moves by more than
//!   `shift_tolerance` × max(1, β_t).
//! * **Verification**: at the design found, [`reliability::analyze`] samples each
//!   chance constraint's probability (importance sampling around FORM's design
//!   points, Monte Carlo where P_FORM is large; [`verification_settings`]: target
//!   coefficient of variation 0.02). A constraint is violated when the lower end
//!   of the sampled 95 % interval exceeds its target; [`Verify::Correct`] then
//!   raises the PMA target by the sampled deficit of β and solves again.
//!
//! Every result is a deterministic function of the inputs and the seed, the same on
//! any number of threads: samples are evaluated in parallel, collected in order and
//! summed in that order; the starts are solved in parallel and collected in order.

use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;
use serde::Serialize;

use super::distribution::{std_normal_cdf, std_normal_quantile};
use super::model::InputModel;
use super::reliability::{self, EventResult, ReliabilitySettings};
use super::sampling::{quantile, MAX_INPUTS};
use super::Estimate;
use crate::optimize::{minimize, NonlinearProgram, SqpResult, SqpSettings, SqpStatus, Values};
use crate::sweep::sequence::sobol_owen;

/// z₀.₉₇₅, the half-width of a 95 % normal interval in standard errors.
const Z95: f64 = 1.959_963_984_540_054;

// ---------------------------------------------------------------------------
// Statistics
// ---------------------------------------------------------------------------

/// A statistic of an output over the random inputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Statistic {
    /// The mean.
    Mean,
    /// The 95 % quantile (the value 95 % of the parts stay below).
    P95,
    /// The 99 % quantile.
    P99,
    /// CVaR₉₅: the mean of the worst 5 % (the mean above the 95 % quantile).
    Cvar95,
    /// The mean plus three standard deviations (serde's snake case would spell
    /// it `mean_plus3_sd`).
    #[serde(rename = "mean_plus_3sd")]
    MeanPlus3Sd,
}

impl Statistic {
    /// Every statistic, in the order of the documentation.
    pub const ALL: [Statistic; 5] = [
        Statistic::Mean,
        Statistic::P95,
        Statistic::P99,
        Statistic::Cvar95,
        Statistic::MeanPlus3Sd,
    ];

    /// The statistic's word: `mean`, `p95`, `p99`, `cvar95`, `mean_plus_3sd`.
    pub fn as_str(self) -> &'static str {
        match self {
            Statistic::Mean => "mean",
            Statistic::P95 => "p95",
            Statistic::P99 => "p99",
            Statistic::Cvar95 => "cvar95",
            Statistic::MeanPlus3Sd => "mean_plus_3sd",
        }
    }

    /// The statistic of a word of [`Statistic::as_str`].
    pub fn parse(s: &str) -> Option<Statistic> {
        Statistic::ALL.into_iter().find(|t| t.as_str() == s)
    }
}

impl std::fmt::Display for Statistic {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The statistic of a sample with its 95 % interval. Non-finite values are
/// dropped; fewer than two finite values give NaN. With n values, mean m,
/// sd s and central moments μ₃, μ₄ of the sample:
///
/// * `mean`: m ± 1.96 s/√n (central limit theorem);
/// * `p95`, `p99`: the type-7 quantile with its distribution-free order-statistic
///   interval ([`super::sampling::quantile`]; an end beyond the sample is infinite);
/// * `cvar95`: Rockafellar & Uryasev's q + Σ(x_i − q)₊ / (0.05 n), q the
///   ⌈0.95 n⌉-th smallest value (the estimator's minimiser over q: the mean of the
///   worst 5 %, the boundary value weighted by its share); interval ± 1.96 σ_c/√n,
///   σ_c² = Var((X − q)₊)/0.05² (the delta method; Trindade et al. 2007,
///   "Financial prediction with constrained tail risk", J. Bank. Finance 31:3524);
/// * `mean_plus_3sd`: m + 3s ± 1.96 σ_t/√n, σ_t² = s² + 3μ₃/s + 9(μ₄ − s⁴)/(4s²)
///   (delta method on the mean and sd; 5.5 s² for a normal law).
///
/// The intervals treat the values as independent: for a scrambled Sobol′ sample
/// they are conservative for the mean. Deterministic (sums in sorted order).
pub fn estimate(values: &[f64], statistic: Statistic) -> Estimate {
    let mut v: Vec<f64> = values.iter().copied().filter(|x| x.is_finite()).collect();
    let nan = Estimate {
        value: f64::NAN,
        interval: [f64::NAN, f64::NAN],
    };
    if v.len() < 2 {
        return nan;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len() as f64;
    let mean = v.iter().sum::<f64>() / n;
    let (m2, m3, m4) = v.iter().fold((0.0, 0.0, 0.0), |(a, b, c), x| {
        let d = x - mean;
        (a + d * d, b + d * d * d, c + d * d * d * d)
    });
    let var = m2 / (n - 1.0);
    let sd = var.sqrt();
    let around = |value: f64, se: f64| Estimate {
        value,
        interval: [value - Z95 * se, value + Z95 * se],
    };
    match statistic {
        Statistic::Mean => around(mean, sd / n.sqrt()),
        Statistic::P95 => quantile(&v, 0.95),
        Statistic::P99 => quantile(&v, 0.99),
        Statistic::Cvar95 => {
            let tail = 0.05;
            let rank = ((1.0 - tail) * n).ceil().clamp(1.0, n) as usize;
            let q = v[rank - 1];
            let excess: Vec<f64> = v.iter().map(|x| (x - q).max(0.0)).collect();
            let e_mean = excess.iter().sum::<f64>() / n;
            let e_var = excess
                .iter()
                .map(|e| (e - e_mean) * (e - e_mean))
                .sum::<f64>()
                / (n - 1.0);
            around(q + e_mean / tail, e_var.sqrt() / tail / n.sqrt())
        }
        Statistic::MeanPlus3Sd => {
            let (mu3, mu4) = (m3 / n, m4 / n);
            let t_var = if sd > 0.0 {
                (var + 3.0 * mu3 / sd + 9.0 * (mu4 - var * var) / (4.0 * var)).max(0.0)
            } else {
                0.0
            };
            around(mean + 3.0 * sd, (t_var / n).sqrt())
        }
    }
}

/// The common random numbers: `samples` points u_k = Φ⁻¹(v_k) of independent
/// standard normal variables in `dim` dimensions, v_k the points 0, 1, … of the
/// Owen-scrambled Sobol′ sequence of `seed`. `dim` ≤ [`MAX_INPUTS`] (larger is
/// cut to it, which [`optimize_robust`] refuses).
pub fn common_points(dim: usize, samples: usize, seed: u64) -> Vec<Vec<f64>> {
    let dim = dim.min(MAX_INPUTS);
    (0..samples as u64)
        .into_par_iter()
        .map(|k| {
            sobol_owen(k, dim, seed)
                .into_iter()
                .map(std_normal_quantile)
                .collect()
        })
        .collect()
}

// ---------------------------------------------------------------------------
// The problem
// ---------------------------------------------------------------------------

/// The values of the model at one design and one realisation of the random inputs.
#[derive(Debug, Clone, PartialEq)]
pub struct Outputs {
    /// The quantity whose statistic is minimised.
    pub objective: f64,
    /// One per chance constraint, in the order of [`RobustSettings::targets`];
    /// failure when ≤ 0.
    pub limit_states: Vec<f64>,
    /// Deterministic rows, ≤ 0 feasible, used at the nominal realisation (u = 0).
    pub constraints: Vec<f64>,
}

/// A design problem under uncertainty, given by values (as
/// [`NonlinearProgram`] is).
pub trait UncertainProgram: Sync {
    /// The number of design variables d.
    fn dimension(&self) -> usize;
    /// Finite lower and upper bounds of d, lower < upper.
    fn bounds(&self) -> (Vec<f64>, Vec<f64>);
    /// The typical magnitude of each design variable (the SQP's finite-difference
    /// and trust-region scale; default 1).
    fn scale(&self) -> Vec<f64> {
        vec![1.0; self.dimension()]
    }
    /// The random inputs at design d (they may move with d; their number may not).
    fn inputs(&self, d: &[f64]) -> InputModel;
    /// The outputs at design d and inputs x; `None`: the model failed there.
    fn outputs(&self, d: &[f64], x: &[f64]) -> Option<Outputs>;
    /// Minimise ln(statistic) instead of the statistic (the quantity is
    /// positive; default false).
    fn logarithmic_objective(&self) -> bool {
        false
    }
}

// ---------------------------------------------------------------------------
// Inverse FORM (PMA)
// ---------------------------------------------------------------------------

/// Settings of the inverse-FORM search.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct InverseFormSettings {
    /// Iterations (a gradient and a line search each) (default 100).
    pub max_iterations: usize,
    /// Converged when |u − u_AMV| ≤ this × max(β_t, 1), u_AMV = −β_t ∇g/|∇g|
    /// (default 1e-8).
    pub tolerance: f64,
    /// Central-difference step of the gradient in u, times max(1, |u_i|)
    /// (default 1e-6).
    pub gradient_step: f64,
    /// Without a start, also search from ±β_t along each axis (2n more runs)
    /// (default true; SORA warm-starts every search after its first).
    pub multistart: bool,
}

impl Default for InverseFormSettings {
    fn default() -> Self {
        InverseFormSettings {
            max_iterations: 100,
            tolerance: 1e-8,
            gradient_step: 1e-6,
            multistart: true,
        }
    }
}

/// How the inverse-FORM search ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InverseFormStatus {
    /// u is the minimum of g on the sphere |u| = β_t (to the tolerance).
    Converged,
    /// The iteration cap came first, or the line search found no decrease:
    /// u is the best point met.
    NotConverged,
    /// g does not vary in u there.
    ZeroGradient,
    /// The model failed where the search needed it.
    ModelFailed,
}

/// The most probable target point: the minimum of g on the sphere |u| = β_t.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InverseForm {
    /// See [`InverseFormStatus`].
    pub status: InverseFormStatus,
    /// The target reliability index β_t.
    pub beta_target: f64,
    /// The point in independent standard normal space (|u| = β_t).
    pub u: Vec<f64>,
    /// The point in physical units.
    pub x: Vec<f64>,
    /// g there: the β_t-percentile performance (≥ 0: P(g ≤ 0) ≤ Φ(−β_t) by FORM).
    pub performance: f64,
    /// Iterations.
    pub iterations: usize,
    /// Model evaluations.
    pub evaluations: usize,
}

/// The performance-measure approach (Tu, Choi & Park 1999, "A new study on
/// reliability-based design optimization", J. Mech. Des. 121:557): the minimum
/// of g(T(u)) on the sphere |u| = β_t (β_t ≥ 0), by the advanced mean value
/// iteration u ← u_AMV = −β_t ∇g/|∇g| with a line search along the sphere
/// (the step from u towards u_AMV halved until g decreases), so that g never
/// increases (plain AMV oscillates on concave g). Starts from `start` scaled
/// onto the sphere; without one, from u_AMV at the median and, with
/// `multistart`, also from ±β_t along each axis (in parallel), keeping the
/// lowest performance (ties to the earlier start): the iteration stops at any
/// point where ∇g is normal to the sphere, a maximum of g along it included
/// (g = 5 − u₁ − u₂², β_t = 2: u_AMV at the median is (2, 0), g = 3, where the
/// minimum is g = 0.75 at (0.5, ±1.94)). The gradient is a central difference
/// in u. β_t = 0 gives the median.
pub fn inverse_form<G>(
    model: &InputModel,
    g: G,
    beta_target: f64,
    start: Option<&[f64]>,
    settings: &InverseFormSettings,
) -> InverseForm
where
    G: Fn(&[f64]) -> Option<f64> + Sync,
{
    let first = inverse_form_from(model, &g, beta_target, start, settings);
    if start.is_some() || !settings.multistart || beta_target <= 0.0 {
        return first;
    }
    let n = model.dim();
    let starts: Vec<Vec<f64>> = (0..n)
        .flat_map(|i| {
            [1.0, -1.0].map(|sign| {
                let mut u = vec![0.0; n];
                u[i] = sign * beta_target;
                u
            })
        })
        .collect();
    let more: Vec<InverseForm> = starts
        .par_iter()
        .map(|u| inverse_form_from(model, &g, beta_target, Some(u), settings))
        .collect();
    let evaluations = first.evaluations + more.iter().map(|r| r.evaluations).sum::<usize>();
    let usable = |r: &InverseForm| {
        matches!(
            r.status,
            InverseFormStatus::Converged | InverseFormStatus::NotConverged
        ) && r.performance.is_finite()
    };
    let mut best = first;
    for r in more {
        let better = match (usable(&r), usable(&best)) {
            (true, false) => true,
            (true, true) => {
                r.performance < best.performance - 1e-12 * best.performance.abs().max(1.0)
            }
            _ => false,
        };
        if better {
            best = r;
        }
    }
    best.evaluations = evaluations;
    best
}

/// [`inverse_form`] from one start.
fn inverse_form_from<G>(
    model: &InputModel,
    g: &G,
    beta_target: f64,
    start: Option<&[f64]>,
    settings: &InverseFormSettings,
) -> InverseForm
where
    G: Fn(&[f64]) -> Option<f64> + Sync,
{
    let n = model.dim();
    let count = AtomicUsize::new(0);
    let at = |u: &[f64]| {
        count.fetch_add(1, Ordering::Relaxed);
        g(&model.to_physical(u)).filter(|v| v.is_finite())
    };
    let gradient = |u: &[f64]| -> Option<Vec<f64>> {
        (0..n)
            .into_par_iter()
            .map(|i| {
                let h = settings.gradient_step * u[i].abs().max(1.0);
                let mut up = u.to_vec();
                up[i] += h;
                let mut down = u.to_vec();
                down[i] -= h;
                Some((at(&up)? - at(&down)?) / (2.0 * h))
            })
            .collect()
    };
    let beta = beta_target.max(0.0);
    let onto_sphere = |v: &[f64]| -> Option<Vec<f64>> {
        let r = norm(v);
        (r > 0.0 && r.is_finite()).then(|| v.iter().map(|x| x * beta / r).collect())
    };
    let amv = |grad: &[f64]| onto_sphere(&grad.iter().map(|x| -x).collect::<Vec<_>>());
    let done = |status, u: Vec<f64>, performance: f64, iterations| InverseForm {
        status,
        beta_target,
        x: model.to_physical(&u),
        u,
        performance,
        iterations,
        evaluations: count.load(Ordering::Relaxed),
    };
    let origin = vec![0.0; n];
    if beta == 0.0 {
        return match at(&origin) {
            Some(g0) => done(InverseFormStatus::Converged, origin, g0, 0),
            None => done(InverseFormStatus::ModelFailed, origin, f64::NAN, 0),
        };
    }
    let mut u = match start.and_then(onto_sphere) {
        Some(u) => u,
        None => {
            let Some(g0) = at(&origin) else {
                return done(InverseFormStatus::ModelFailed, origin, f64::NAN, 0);
            };
            let Some(grad) = gradient(&origin) else {
                return done(InverseFormStatus::ModelFailed, origin, f64::NAN, 0);
            };
            match amv(&grad) {
                Some(u) => u,
                None => return done(InverseFormStatus::ZeroGradient, origin, g0, 0),
            }
        }
    };
    let Some(mut gu) = at(&u) else {
        return done(InverseFormStatus::ModelFailed, u, f64::NAN, 0);
    };
    for it in 0..settings.max_iterations {
        let Some(grad) = gradient(&u) else {
            return done(InverseFormStatus::ModelFailed, u, gu, it);
        };
        let Some(target) = amv(&grad) else {
            return done(InverseFormStatus::ZeroGradient, u, gu, it);
        };
        let gap: Vec<f64> = target.iter().zip(&u).map(|(t, a)| t - a).collect();
        if norm(&gap) <= settings.tolerance * beta.max(1.0) {
            return done(InverseFormStatus::Converged, u, gu, it);
        }
        let mut omega = 1.0;
        let mut accepted = None;
        for _ in 0..40 {
            let trial: Vec<f64> = u.iter().zip(&gap).map(|(a, s)| a + omega * s).collect();
            if let Some(v) = onto_sphere(&trial) {
                if let Some(gv) = at(&v) {
                    if gv < gu {
                        accepted = Some((v, gv));
                        break;
                    }
                }
            }
            omega *= 0.5;
        }
        match accepted {
            Some((v, gv)) => {
                u = v;
                gu = gv;
            }
            // No decrease along the sphere towards u_AMV: u is a minimum to the
            // precision of g's values (the gap test above is the stricter one).
            None => return done(InverseFormStatus::NotConverged, u, gu, it + 1),
        }
    }
    done(
        InverseFormStatus::NotConverged,
        u,
        gu,
        settings.max_iterations,
    )
}

fn norm(a: &[f64]) -> f64 {
    a.iter().map(|x| x * x).sum::<f64>().sqrt()
}

// ---------------------------------------------------------------------------
// The deterministic shifted program
// ---------------------------------------------------------------------------

/// The deterministic program of one SORA cycle, for the SQP:
///
/// ```text
/// min  S_k[f(d, T_d(u_k))]  (or f(d, T_d(0)) without a statistic)
/// s.t. c_i(d, T_d(0)) ≤ 0               (the deterministic rows at the median)
///      −g_j(d, T_d(u*_j)) ≤ 0           (each chance constraint at its MPTP)
/// ```
///
/// with T_d = `inputs(d).to_physical`, u_k the common random numbers and u*_j
/// held fixed in standard space while d moves. `None` (the SQP shrinks its step)
/// where any evaluation fails, the number of limit states differs from the
/// number of MPTPs, or the logarithmic objective's statistic is not positive.
pub struct ShiftedProgram<'a, P: UncertainProgram> {
    /// The problem.
    pub program: &'a P,
    /// The statistic of the objective; `None`: the objective at u = 0.
    pub statistic: Option<Statistic>,
    /// The common random numbers u_k (used with a statistic only).
    pub points: &'a [Vec<f64>],
    /// u*_j per chance constraint.
    pub mptp: Vec<Vec<f64>>,
    /// At most this many of the common random numbers may fail at a design
    /// (they are dropped from the statistic); more, and the design cannot be
    /// evaluated (default 0 from [`ShiftedProgram::new`]). A point that fails
    /// at some designs and not at others makes the statistic jump there.
    pub failures_allowed: usize,
    evaluations: AtomicUsize,
}

impl<'a, P: UncertainProgram> ShiftedProgram<'a, P> {
    /// The program with these MPTPs.
    pub fn new(
        program: &'a P,
        statistic: Option<Statistic>,
        points: &'a [Vec<f64>],
        mptp: Vec<Vec<f64>>,
    ) -> Self {
        ShiftedProgram {
            program,
            statistic,
            points,
            mptp,
            failures_allowed: 0,
            evaluations: AtomicUsize::new(0),
        }
    }

    /// Model evaluations (calls of `outputs`) so far.
    pub fn evaluations(&self) -> usize {
        self.evaluations.load(Ordering::Relaxed)
    }

    fn outputs(&self, d: &[f64], x: &[f64]) -> Option<Outputs> {
        self.evaluations.fetch_add(1, Ordering::Relaxed);
        self.program
            .outputs(d, x)
            .filter(|o| o.limit_states.len() == self.mptp.len())
    }

    /// The objective's values at the common random numbers (in order), the
    /// failed ones dropped; `None` when more than `failures_allowed` failed.
    pub fn sample(&self, d: &[f64]) -> Option<Vec<f64>> {
        let model = self.program.inputs(d);
        let values: Vec<Option<f64>> = self
            .points
            .par_iter()
            .map(|u| {
                self.outputs(d, &model.to_physical(u))
                    .map(|o| o.objective)
                    .filter(|v| v.is_finite())
            })
            .collect();
        let kept: Vec<f64> = values.into_iter().flatten().collect();
        (self.points.len() - kept.len() <= self.failures_allowed).then_some(kept)
    }

    fn statistic_value(&self, d: &[f64], nominal: &Outputs) -> Option<f64> {
        let value = match self.statistic {
            None => nominal.objective,
            Some(s) => estimate(&self.sample(d)?, s).value,
        };
        if self.program.logarithmic_objective() {
            (value > 0.0).then(|| value.ln())
        } else {
            value.is_finite().then_some(value)
        }
    }

    fn rows(&self, d: &[f64], model: &InputModel, nominal: &Outputs) -> Option<Vec<f64>> {
        let mut rows = nominal.constraints.clone();
        for (j, u) in self.mptp.iter().enumerate() {
            let o = self.outputs(d, &model.to_physical(u))?;
            rows.push(-o.limit_states[j]);
        }
        rows.iter().all(|r| r.is_finite()).then_some(rows)
    }
}

impl<P: UncertainProgram> NonlinearProgram for ShiftedProgram<'_, P> {
    fn dimension(&self) -> usize {
        self.program.dimension()
    }

    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        self.program.bounds()
    }

    fn objective(&self, d: &[f64]) -> Option<f64> {
        let model = self.program.inputs(d);
        let nominal = self.outputs(d, &model.to_physical(&vec![0.0; model.dim()]))?;
        self.statistic_value(d, &nominal)
    }

    fn constraints(&self, d: &[f64]) -> Option<Vec<f64>> {
        let model = self.program.inputs(d);
        let nominal = self.outputs(d, &model.to_physical(&vec![0.0; model.dim()]))?;
        self.rows(d, &model, &nominal)
    }

    fn evaluate(&self, d: &[f64], _near: &[f64]) -> Option<Values> {
        let model = self.program.inputs(d);
        let nominal = self.outputs(d, &model.to_physical(&vec![0.0; model.dim()]))?;
        Some(Values {
            objective: self.statistic_value(d, &nominal)?,
            constraints: self.rows(d, &model, &nominal)?,
            warm_start: Vec::new(),
        })
    }

    fn scale(&self) -> Vec<f64> {
        self.program.scale()
    }

    fn logarithmic_objective(&self) -> bool {
        self.program.logarithmic_objective()
    }
}

// ---------------------------------------------------------------------------
// Settings and results
// ---------------------------------------------------------------------------

/// What to do when sampling finds a chance constraint violated at the optimum.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verify {
    /// Report it: status `chance_constraint_violated`, with the excess.
    Report,
    /// Raise the PMA target of each violated constraint by its sampled deficit
    /// of β and solve again (at most [`RobustSettings::max_corrections`] rounds).
    Correct,
}

/// The reliability settings of the verification: [`ReliabilitySettings`]'
/// defaults but a target coefficient of variation of 0.02 (the 95 % interval
/// ±4 % of P: Youn & Choi's sampled 0.00151 is then told from the target
/// 0.00135), importance sampling wherever P_FORM < 0.05 (at P ≈ 1e-3 Monte
/// Carlo would need ~2.5 million evaluations for that CoV), at most 2 million
/// evaluations, no SORM (not reported here) and seed 1.
pub fn verification_settings() -> ReliabilitySettings {
    ReliabilitySettings {
        target_cov: 0.02,
        monte_carlo_above: 0.05,
        max_evaluations: 2_000_000,
        batch: 2000,
        sorm: false,
        seed: 1,
        ..ReliabilitySettings::default()
    }
}

/// Settings of [`optimize_robust`]. Defaults in [`RobustSettings::default`].
#[derive(Debug, Clone, PartialEq)]
pub struct RobustSettings {
    /// The statistic of the objective; `None`: the objective at the median
    /// realisation (u = 0) (default none).
    pub statistic: Option<Statistic>,
    /// Common random numbers for the statistic (default 512, at least 16).
    pub samples: usize,
    /// At most this many of them may fail at a design, dropped from the
    /// statistic (default 0: a design where one fails cannot be evaluated and the
    /// SQP steps back; at most `samples`/10).
    pub failures_allowed: usize,
    /// probability_max per chance constraint, each in (0, 0.5] (default none).
    pub targets: Vec<f64>,
    /// What a violated verification does (default report).
    pub verify: Verify,
    /// The SQP of each deterministic solve (default [`SqpSettings::default`]).
    pub sqp: SqpSettings,
    /// The verification's reliability analysis (default [`verification_settings`]).
    pub reliability: ReliabilitySettings,
    /// The inverse-FORM searches (default [`InverseFormSettings::default`]).
    pub inverse_form: InverseFormSettings,
    /// Most SORA cycles per solve (default 20, at least 1).
    pub max_cycles: usize,
    /// SORA stops when no MPTP moves by more than this × max(1, β_t) in u
    /// (default 1e-6, > 0).
    pub shift_tolerance: f64,
    /// Most correction rounds under [`Verify::Correct`] (default 5).
    pub max_corrections: usize,
    /// Seed of the common random numbers and of the verification of the
    /// objective's statistic (default 1).
    pub seed: u64,
    /// Points of the independent sample on which the statistic is verified at
    /// the optimum (default 4096; 0: none).
    pub verify_samples: usize,
    /// When SORA must stop (default none): no deterministic solve runs past it
    /// (each gets the time left as its time limit), no new cycle or correction
    /// round starts after it, and a run it stops ends `time_limit`. The
    /// verification of the design reached still runs.
    pub deadline: Option<std::time::Instant>,
}

impl Default for RobustSettings {
    fn default() -> Self {
        RobustSettings {
            statistic: None,
            samples: 512,
            failures_allowed: 0,
            targets: Vec::new(),
            verify: Verify::Report,
            sqp: SqpSettings::default(),
            reliability: verification_settings(),
            inverse_form: InverseFormSettings::default(),
            max_cycles: 20,
            shift_tolerance: 1e-6,
            max_corrections: 5,
            seed: 1,
            verify_samples: 4096,
            deadline: None,
        }
    }
}

/// A setting of [`RobustSettings`] outside its range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RobustSettingsError {
    /// A field out of range.
    #[error("{field} = {value} is not accepted: {accepted}")]
    OutOfRange {
        /// The field.
        field: &'static str,
        /// Its value, as written.
        value: String,
        /// The accepted range.
        accepted: &'static str,
    },
}

impl RobustSettings {
    /// Checks every field (`targets[j]` named by index).
    pub fn validate(&self) -> Result<(), RobustSettingsError> {
        let bad = |field, value: String, accepted| {
            Err(RobustSettingsError::OutOfRange {
                field,
                value,
                accepted,
            })
        };
        if self.samples < 16 {
            return bad("samples", self.samples.to_string(), "at least 16");
        }
        if self.failures_allowed > self.samples / 10 {
            return bad(
                "failures_allowed",
                self.failures_allowed.to_string(),
                "at most a tenth of samples",
            );
        }
        for p in &self.targets {
            if !(p.is_finite() && *p > 0.0 && *p <= 0.5) {
                return bad("targets", p.to_string(), "each in (0, 0.5]");
            }
        }
        if self.max_cycles == 0 {
            return bad("max_cycles", "0".into(), "at least 1");
        }
        if !(self.shift_tolerance.is_finite() && self.shift_tolerance > 0.0) {
            return bad(
                "shift_tolerance",
                self.shift_tolerance.to_string(),
                "finite and > 0",
            );
        }
        Ok(())
    }
}

/// How [`optimize_robust`] ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RobustStatus {
    /// SORA converged, the last SQP was optimal and every sampled probability
    /// meets its target (to its interval).
    Optimal,
    /// As `Optimal`, but the lower end of some sampled probability's 95 %
    /// interval exceeds its target.
    ChanceConstraintViolated,
    /// The last SQP ended at a stationary point of the violation.
    Infeasible,
    /// The last SQP reached its iteration cap.
    IterationLimit,
    /// The last SQP reached its time limit, or the deadline stopped SORA
    /// ([`RobustSettings::deadline`]).
    TimeLimit,
    /// The last SQP made no more progress (or its start could not be evaluated),
    /// or the settings were invalid.
    Stalled,
    /// The MPTPs still moved after `max_cycles` SORA cycles.
    CycleLimit,
}

impl RobustStatus {
    /// The status word.
    pub fn as_str(self) -> &'static str {
        match self {
            RobustStatus::Optimal => "optimal",
            RobustStatus::ChanceConstraintViolated => "chance_constraint_violated",
            RobustStatus::Infeasible => "infeasible",
            RobustStatus::IterationLimit => "iteration_limit",
            RobustStatus::TimeLimit => "time_limit",
            RobustStatus::Stalled => "stalled",
            RobustStatus::CycleLimit => "cycle_limit",
        }
    }

    fn of_sqp(s: SqpStatus) -> RobustStatus {
        match s {
            SqpStatus::Optimal => RobustStatus::Optimal,
            SqpStatus::Infeasible => RobustStatus::Infeasible,
            SqpStatus::IterationLimit => RobustStatus::IterationLimit,
            SqpStatus::TimeLimit => RobustStatus::TimeLimit,
            SqpStatus::Stalled => RobustStatus::Stalled,
        }
    }
}

impl std::fmt::Display for RobustStatus {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// One chance constraint at the reported design.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChanceReport {
    /// probability_max.
    pub target: f64,
    /// −Φ⁻¹(target).
    pub target_beta: f64,
    /// The β_t the last PMA used (`target_beta` raised by the corrections).
    pub pma_beta: f64,
    /// Φ(−`pma_beta`) when corrections raised it, else none.
    pub corrected_target: Option<f64>,
    /// The most probable target point of the last cycle, in u and in x.
    pub mptp: InverseForm,
    /// FORM's β at the design (from the verification).
    pub form_beta: Option<f64>,
    /// The verification: sampled probability, interval, method.
    pub verification: EventResult,
    /// The lower end of the sampled interval exceeds `target`.
    pub violated: bool,
    /// sampled / target − 1 (positive: above the target).
    pub excess: Option<f64>,
}

/// One SORA cycle.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SoraCycle {
    /// The design of the cycle's deterministic solve.
    pub design: Vec<f64>,
    /// The program's objective there (ln of the statistic for a logarithmic one).
    pub objective: f64,
    /// The SQP's status.
    pub sqp_status: SqpStatus,
    /// The new MPTPs' performance g_j(d, T_d(u*_j)) (≥ 0: FORM-feasible).
    pub performance: Vec<f64>,
    /// The new MPTPs u*_j in standard normal space (the shifts of the next cycle).
    pub mptp_u: Vec<Vec<f64>>,
    /// The same in physical units at the cycle's design, x*_j = T_d(u*_j).
    pub mptp_x: Vec<Vec<f64>>,
    /// The largest move of an MPTP in u from the previous cycle.
    pub shift_change: f64,
    /// The correction round (0: before any correction).
    pub round: usize,
}

/// What [`optimize_robust`] found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RobustResult {
    /// See [`RobustStatus`].
    pub status: RobustStatus,
    /// The design.
    pub design: Vec<f64>,
    /// The last deterministic solve.
    #[serde(skip)]
    pub sqp: SqpResult,
    /// The statistic at the design on the common random numbers (what was
    /// minimised) with its interval, or the nominal value (zero width).
    pub objective: Estimate,
    /// The statistic at the design on an independent scrambled sample of
    /// `verify_samples` points (seed + 1), free of the optimiser's bias towards
    /// the common random numbers; none without a statistic or samples.
    pub objective_verified: Option<Estimate>,
    /// Per chance constraint.
    pub chance: Vec<ChanceReport>,
    /// SORA cycles of the chosen start, all rounds.
    pub cycles: usize,
    /// Correction rounds run.
    pub corrections: usize,
    /// The start the design came from (index into `starts`).
    pub start: usize,
    /// Model evaluations, all starts, searches and verifications.
    pub evaluations: usize,
    /// Per SORA cycle of the chosen start.
    pub history: Vec<SoraCycle>,
}

// ---------------------------------------------------------------------------
// The driver
// ---------------------------------------------------------------------------

/// One start's SORA run.
struct Run {
    sqp: SqpResult,
    mptp: Vec<InverseForm>,
    history: Vec<SoraCycle>,
    converged: bool,
    /// The deadline stopped it before its cycles converged.
    timed_out: bool,
    evaluations: usize,
}

/// SORA from `d0` with the PMA targets `betas` and MPTPs `u0` (zero: the first
/// cycle is the deterministic design at the median).
fn sora<P: UncertainProgram>(
    program: &P,
    points: &[Vec<f64>],
    d0: &[f64],
    betas: &[f64],
    u0: Vec<Vec<f64>>,
    round: usize,
    s: &RobustSettings,
) -> Run {
    let mut evaluations = 0;
    let mut u = u0;
    let mut d = d0.to_vec();
    let mut history = Vec::new();
    let mut last: Option<(SqpResult, Vec<InverseForm>)> = None;
    for _ in 0..s.max_cycles {
        let mut sqp_settings = s.sqp.clone();
        if let Some(deadline) = s.deadline {
            let left = deadline.saturating_duration_since(std::time::Instant::now());
            if left.is_zero() {
                if let Some((sqp, mptp)) = last {
                    return Run {
                        sqp,
                        mptp,
                        history,
                        converged: false,
                        timed_out: true,
                        evaluations,
                    };
                }
            }
            sqp_settings.time_limit = Some(sqp_settings.time_limit.map_or(left, |t| t.min(left)));
        }
        let mut shifted = ShiftedProgram::new(program, s.statistic, points, u.clone());
        shifted.failures_allowed = s.failures_allowed;
        let sqp = minimize(&shifted, &d, &sqp_settings);
        evaluations += shifted.evaluations();
        d = sqp.x.clone();
        let model = program.inputs(&d);
        let mptp: Vec<InverseForm> = betas
            .iter()
            .enumerate()
            .map(|(j, &beta)| {
                let g = |x: &[f64]| {
                    program
                        .outputs(&d, x)
                        .and_then(|o| o.limit_states.get(j).copied())
                };
                let start = (norm(&u[j]) > 0.0).then_some(u[j].as_slice());
                inverse_form(&model, g, beta, start, &s.inverse_form)
            })
            .collect();
        evaluations += mptp.iter().map(|m| m.evaluations).sum::<usize>();
        let change = mptp
            .iter()
            .zip(&u)
            .zip(betas)
            .map(|((m, old), b)| {
                let gap: Vec<f64> = m.u.iter().zip(old).map(|(a, b)| a - b).collect();
                norm(&gap) / b.max(1.0)
            })
            .fold(0.0, f64::max);
        history.push(SoraCycle {
            design: d.clone(),
            objective: sqp.objective,
            sqp_status: sqp.status,
            performance: mptp.iter().map(|m| m.performance).collect(),
            mptp_u: mptp.iter().map(|m| m.u.clone()).collect(),
            mptp_x: mptp.iter().map(|m| m.x.clone()).collect(),
            shift_change: change,
            round,
        });
        u = mptp.iter().map(|m| m.u.clone()).collect();
        let stop = sqp.status != SqpStatus::Optimal || change <= s.shift_tolerance;
        last = Some((sqp, mptp));
        if stop {
            let (sqp, mptp) = last.expect("set above");
            let converged = change <= s.shift_tolerance;
            return Run {
                sqp,
                mptp,
                history,
                converged,
                timed_out: false,
                evaluations,
            };
        }
    }
    let (sqp, mptp) = last.expect("max_cycles ≥ 1");
    Run {
        sqp,
        mptp,
        history,
        converged: false,
        timed_out: false,
        evaluations,
    }
}

/// The rank of a run for the choice among starts: converged and optimal first,
/// then feasible, then the rest; the objective within a rank.
fn rank(r: &Run, feasibility: f64) -> (u8, f64) {
    let class = if r.converged && r.sqp.status == SqpStatus::Optimal {
        0
    } else if r.sqp.max_violation() <= feasibility {
        1
    } else {
        2
    };
    let f = if r.sqp.objective.is_finite() {
        r.sqp.objective
    } else {
        f64::INFINITY
    };
    (class, f)
}

/// Minimises the statistic (or the nominal objective) subject to the
/// deterministic rows at the median and P(g_j ≤ 0) ≤ `targets[j]`, by SORA from
/// each start (in parallel, collected in order; the best converged optimal run is
/// kept, ties to the earlier start), then verifies the design by sampling (module
/// doc). Under [`Verify::Correct`], each violated constraint's PMA target is
/// raised by β_t − β̂ (β̂ = −Φ⁻¹(sampled P)) and SORA re-run from the design,
/// until no constraint is violated or `max_corrections` rounds have run.
///
/// Invalid settings ([`RobustSettings::validate`]), no start, or a statistic
/// over more than [`MAX_INPUTS`] random inputs give status `stalled` at the
/// first start (or the lower bounds) without evaluating.
pub fn optimize_robust<P: UncertainProgram>(
    program: &P,
    starts: &[Vec<f64>],
    settings: &RobustSettings,
) -> RobustResult {
    let s = settings;
    let n = program.dimension();
    let too_many_inputs = s.statistic.is_some()
        && starts
            .first()
            .is_some_and(|d| program.inputs(d).dim() > MAX_INPUTS);
    if s.validate().is_err() || starts.is_empty() || too_many_inputs {
        let x = starts
            .first()
            .cloned()
            .unwrap_or_else(|| program.bounds().0);
        return RobustResult {
            status: RobustStatus::Stalled,
            design: x.clone(),
            sqp: SqpResult {
                x,
                objective: f64::INFINITY,
                constraints: Vec::new(),
                status: SqpStatus::Stalled,
                kkt_residual: f64::INFINITY,
                multipliers: Vec::new(),
                lower_bound_multipliers: vec![0.0; n],
                upper_bound_multipliers: vec![0.0; n],
                evaluations: 0,
                iterations: 0,
                gradient_error: 0.0,
                trace: Vec::new(),
                qp_failures: Vec::new(),
                warm_start: Vec::new(),
            },
            objective: Estimate {
                value: f64::NAN,
                interval: [f64::NAN, f64::NAN],
            },
            objective_verified: None,
            chance: Vec::new(),
            cycles: 0,
            corrections: 0,
            start: 0,
            evaluations: 0,
            history: Vec::new(),
        };
    }
    let dim_x = program.inputs(&starts[0]).dim();
    let points = match s.statistic {
        Some(_) => common_points(dim_x, s.samples, s.seed),
        None => Vec::new(),
    };
    let target_betas: Vec<f64> = s.targets.iter().map(|p| -std_normal_quantile(*p)).collect();
    let zero = vec![vec![0.0; dim_x]; s.targets.len()];
    let runs: Vec<Run> = starts
        .par_iter()
        .map(|d0| sora(program, &points, d0, &target_betas, zero.clone(), 0, s))
        .collect();
    let mut evaluations: usize = runs.iter().map(|r| r.evaluations).sum();
    let best = (0..runs.len())
        .min_by(|&a, &b| {
            let (ra, rb) = (
                rank(&runs[a], s.sqp.feasibility_tolerance),
                rank(&runs[b], s.sqp.feasibility_tolerance),
            );
            ra.0.cmp(&rb.0).then(ra.1.total_cmp(&rb.1))
        })
        .expect("starts is not empty");
    let mut run = runs.into_iter().nth(best).expect("index in range");
    let mut history = std::mem::take(&mut run.history);
    let mut pma_betas = target_betas.clone();
    let mut corrections = 0;
    let mut chance;
    loop {
        let d = run.sqp.x.clone();
        let (reports, evals) = verify(program, &d, &run.mptp, &pma_betas, &target_betas, s);
        evaluations += evals;
        chance = reports;
        let violated: Vec<usize> = (0..chance.len()).filter(|&j| chance[j].violated).collect();
        let late = s.deadline.is_some_and(|dl| std::time::Instant::now() >= dl);
        if violated.is_empty()
            || s.verify == Verify::Report
            || corrections >= s.max_corrections
            || late
        {
            break;
        }
        corrections += 1;
        for &j in &violated {
            if let Some(p) = chance[j].verification.probability {
                pma_betas[j] += target_betas[j] - (-std_normal_quantile(p));
            }
        }
        let u0 = run.mptp.iter().map(|m| m.u.clone()).collect();
        let mut next = sora(program, &points, &d, &pma_betas, u0, corrections, s);
        evaluations += next.evaluations;
        history.append(&mut next.history);
        run = next;
    }
    let d = run.sqp.x.clone();
    let objective = match s.statistic {
        None => {
            let model = program.inputs(&d);
            evaluations += 1;
            let v = program
                .outputs(&d, &model.to_physical(&vec![0.0; dim_x]))
                .map_or(f64::NAN, |o| o.objective);
            Estimate {
                value: v,
                interval: [v, v],
            }
        }
        Some(stat) => {
            let values = objective_values(program, &d, &points);
            evaluations += points.len();
            estimate(&values, stat)
        }
    };
    let objective_verified = match s.statistic {
        Some(stat) if s.verify_samples > 0 => {
            let fresh = common_points(dim_x, s.verify_samples, s.seed.wrapping_add(1));
            evaluations += fresh.len();
            Some(estimate(&objective_values(program, &d, &fresh), stat))
        }
        _ => None,
    };
    let status = if run.timed_out {
        RobustStatus::TimeLimit
    } else if !run.converged && run.sqp.status == SqpStatus::Optimal {
        RobustStatus::CycleLimit
    } else if run.sqp.status != SqpStatus::Optimal {
        RobustStatus::of_sqp(run.sqp.status)
    } else if chance.iter().any(|c| c.violated) {
        RobustStatus::ChanceConstraintViolated
    } else {
        RobustStatus::Optimal
    };
    RobustResult {
        status,
        design: d,
        sqp: run.sqp,
        objective,
        objective_verified,
        chance,
        cycles: history.len(),
        corrections,
        start: best,
        evaluations,
        history,
    }
}

/// The objective at design d and each of `points` (u in standard normal space,
/// e.g. [`common_points`]), evaluated in parallel and returned in order; failed
/// ones NaN, which [`estimate`] drops.
pub fn objective_values<P: UncertainProgram>(
    program: &P,
    d: &[f64],
    points: &[Vec<f64>],
) -> Vec<f64> {
    let model = program.inputs(d);
    points
        .par_iter()
        .map(|u| {
            program
                .outputs(d, &model.to_physical(u))
                .map_or(f64::NAN, |o| o.objective)
        })
        .collect()
}

/// The sampled probability P(g_j ≤ 0) of each of the first `count` limit states
/// at design d ([`reliability::analyze`] with `reliability`, e.g.
/// [`verification_settings`]), one after the other (each parallel inside).
pub fn chance_probabilities<P: UncertainProgram>(
    program: &P,
    d: &[f64],
    count: usize,
    reliability: &ReliabilitySettings,
) -> Vec<EventResult> {
    let model = program.inputs(d);
    (0..count)
        .map(|j| {
            let g = |x: &[f64]| {
                program
                    .outputs(d, x)
                    .and_then(|o| o.limit_states.get(j).copied())
            };
            reliability::analyze(&model, g, reliability)
        })
        .collect()
}

/// The exact (Clopper–Pearson) 95 % interval of a binomial proportion: `k`
/// events in `n` trials give [p_lo, p_hi] with P(K ≥ k; p_lo) = 0.025 and
/// P(K ≤ k; p_hi) = 0.025 (p_lo = 0 for k = 0, p_hi = 1 for k = n; for k = 0,
/// p_hi = 1 − 0.025^(1/n) ≈ 3.69/n). Solved by bisection on the binomial CDF
/// to 1e-12 relative; `n` = 0 gives [0, 1]. Tested against closed forms in
/// `tests::clopper_pearson_closed_forms`.
pub fn clopper_pearson(k: u64, n: u64) -> super::Interval {
    use super::special::binomial_cdf;
    if n == 0 {
        return [0.0, 1.0];
    }
    let k = k.min(n);
    // The p in (0, 1) where the decreasing f(p) = P(K ≤ m; n, p) crosses `level`.
    let crossing = |m: u64, level: f64| {
        let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if binomial_cdf(m as i64, n, mid) > level {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-12 * hi {
                break;
            }
        }
        0.5 * (lo + hi)
    };
    // P(K ≥ k; p_lo) = 0.025 ⇔ P(K ≤ k − 1; p_lo) = 0.975.
    let lower = if k == 0 { 0.0 } else { crossing(k - 1, 0.975) };
    let upper = if k == n { 1.0 } else { crossing(k, 0.025) };
    [lower, upper]
}

/// A probability counted on a fixed sample: `events` of `samples` realisations
/// where the event happened (model failures left out of both).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Counted {
    /// Realisations where the event happened (limit state ≤ 0).
    pub events: u64,
    /// Realisations where the model gave a value.
    pub samples: u64,
    /// Realisations where the model failed (not counted).
    pub failed: u64,
    /// events / samples (NaN with no samples).
    pub probability: f64,
    /// Its exact 95 % interval ([`clopper_pearson`]).
    pub interval: super::Interval,
}

/// P(g_j ≤ 0) of each of the first `count` limit states at design d, counted on
/// `points` (u in standard normal space, e.g. [`common_points`]): one model
/// evaluation per point for all limit states together, in parallel, summed in
/// order. A cheap estimate (its resolution is 1/N; no event in N gives the
/// interval [0, 1 − 0.025^(1/N)]), for a sweep's columns; an optimum's are
/// verified by [`chance_probabilities`].
pub fn counted_probabilities<P: UncertainProgram>(
    program: &P,
    d: &[f64],
    points: &[Vec<f64>],
    count: usize,
) -> Vec<Counted> {
    let model = program.inputs(d);
    let states: Vec<Option<Vec<f64>>> = points
        .par_iter()
        .map(|u| {
            program
                .outputs(d, &model.to_physical(u))
                .map(|o| o.limit_states)
                .filter(|g| g.len() >= count && g[..count].iter().all(|v| v.is_finite()))
        })
        .collect();
    let failed = states.iter().filter(|s| s.is_none()).count() as u64;
    let samples = points.len() as u64 - failed;
    (0..count)
        .map(|j| {
            let events = states.iter().flatten().filter(|g| g[j] <= 0.0).count() as u64;
            Counted {
                events,
                samples,
                failed,
                probability: if samples > 0 {
                    events as f64 / samples as f64
                } else {
                    f64::NAN
                },
                interval: clopper_pearson(events, samples),
            }
        })
        .collect()
}

/// Whether a sampled probability violates its target: the lower end of its
/// 95 % interval exceeds `target` (no interval, as with FORM alone or no failure
/// seen: not violated).
pub fn violates(result: &EventResult, target: f64) -> bool {
    result.interval.is_some_and(|i| i[0] > target)
}

/// The verification of each chance constraint at design d, and the model
/// evaluations it took.
fn verify<P: UncertainProgram>(
    program: &P,
    d: &[f64],
    mptp: &[InverseForm],
    pma_betas: &[f64],
    target_betas: &[f64],
    s: &RobustSettings,
) -> (Vec<ChanceReport>, usize) {
    let results = chance_probabilities(program, d, s.targets.len(), &s.reliability);
    let evaluations = results.iter().map(|r| r.evaluations).sum();
    let reports = results
        .into_iter()
        .enumerate()
        .map(|(j, verification)| {
            let target = s.targets[j];
            let violated = violates(&verification, target);
            let excess = verification.probability.map(|p| p / target - 1.0);
            let corrected = pma_betas[j] != target_betas[j];
            ChanceReport {
                target,
                target_beta: target_betas[j],
                pma_beta: pma_betas[j],
                corrected_target: corrected.then(|| std_normal_cdf(-pma_betas[j])),
                mptp: mptp[j].clone(),
                form_beta: verification.form.beta,
                verification,
                violated,
                excess,
            }
        })
        .collect();
    (reports, evaluations)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::uq::distribution::Distribution;

    #[test]
    fn statistic_words_round_trip() {
        for s in Statistic::ALL {
            assert_eq!(Statistic::parse(s.as_str()), Some(s));
            assert_eq!(
                serde_json::to_string(&s).unwrap(),
                format!("\"{}\"", s.as_str())
            );
        }
        assert_eq!(Statistic::parse("p90"), None);
    }

    /// On 1..=100: mean 50.5 (closed form); CVaR₉₅ = the mean of the top five
    /// values 96..=100 = 98 (q = the 95th value, 95; Σ(x − 95)₊ = 15; 95 + 15/5).
    #[test]
    fn estimates_on_a_known_sample() {
        let v: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(estimate(&v, Statistic::Mean).value, 50.5);
        let c = estimate(&v, Statistic::Cvar95);
        assert!((c.value - 98.0).abs() < 1e-12, "{c:?}");
        assert!(c.interval[0] < 98.0 && c.interval[1] > 98.0);
        let p = estimate(&v, Statistic::P95);
        // Type 7: h = 0.95·99 = 94.05 → 95 + 0.05.
        assert!((p.value - 95.05).abs() < 1e-12, "{p:?}");
        assert!(estimate(&[1.0], Statistic::Mean).value.is_nan());
    }

    /// Clopper–Pearson closed forms: k = 0 gives [0, 1 − 0.025^(1/n)], k = n gives
    /// [0.025^(1/n), 1]; n = 1, k = 0: [0, 0.975]. Symmetry: (k, n) ↔ (n − k, n).
    #[test]
    fn clopper_pearson_closed_forms() {
        for n in [1_u64, 10, 256, 4096] {
            let a = clopper_pearson(0, n);
            let hi = 1.0 - 0.025_f64.powf(1.0 / n as f64);
            assert_eq!(a[0], 0.0);
            assert!((a[1] - hi).abs() <= 1e-10 * hi, "{n}: {a:?} vs {hi}");
            let b = clopper_pearson(n, n);
            assert!((b[0] - 0.025_f64.powf(1.0 / n as f64)).abs() < 1e-10);
            assert_eq!(b[1], 1.0);
        }
        let (x, y) = (clopper_pearson(3, 20), clopper_pearson(17, 20));
        assert!((x[0] - (1.0 - y[1])).abs() < 1e-10 && (x[1] - (1.0 - y[0])).abs() < 1e-10);
        // Independently: bisection on the direct binomial sum in Python,
        // 0.0320709372 and 0.3789268265 (R's binom.test(3, 20) gives the same).
        assert!(
            (x[0] - 0.032_070_937_2).abs() < 1e-9 && (x[1] - 0.378_926_826_5).abs() < 1e-9,
            "{x:?}"
        );
    }

    /// A linear g = 3 − u₀ (β = 3 exactly) seen through x = 2 + 0.5 u: the MPTP on
    /// the sphere of radius 2 is u = (2, 0), where g = 1 (closed form).
    #[test]
    fn inverse_form_of_a_linear_limit_state() {
        let model = InputModel::independent(vec![
            Distribution::Normal { mean: 2.0, sd: 0.5 },
            Distribution::Normal { mean: 0.0, sd: 1.0 },
        ])
        .unwrap();
        let g = |x: &[f64]| Some(3.0 - (x[0] - 2.0) / 0.5 + 0.0 * x[1]);
        let r = inverse_form(&model, g, 2.0, None, &InverseFormSettings::default());
        assert_eq!(r.status, InverseFormStatus::Converged);
        assert!((r.performance - 1.0).abs() < 1e-8, "{r:?}");
        assert!((r.u[0] - 2.0).abs() < 1e-8 && r.u[1].abs() < 1e-8);
        assert!((r.x[0] - 3.0).abs() < 1e-8);
    }
}
