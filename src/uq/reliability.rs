//! The probability of a failure event: FORM, SORM, importance sampling and Monte
//! Carlo, for a limit state g over an [`InputModel`].
//!
//! **Sign convention.** Failure is g(x) ≤ 0; g > 0 is safe. A model failure
//! (`None`, or a non-finite value) is neither: it is counted and skipped.
//!
//! Everything is done in the independent standard normal space u of the input
//! model (x = T(u), [`InputModel::to_physical`]); derivatives are central finite
//! differences in u (one-sided where a side fails).
//!
//! 1. **FORM**: the design point u* (the point of g = 0 nearest the origin) by
//!    the improved HL-RF algorithm (Zhang & Der Kiureghian 1997, "Finite element
//!    reliability methods for inelastic structures", report UCB/SEMM-97/05): the
//!    HL-RF direction with an Armijo line search on the merit
//!    m(u) = ½|u|² + c|g(u)|, c = 2 max(|u|, 1)/|∇g| (> |u|/|∇g|, so the direction
//!    descends). Converged when |g| ≤ tol·|g(0)| and |u − (α·u)α| ≤ tol·max(|u|, 1),
//!    α = −∇g/|∇g|. It starts from the median (u = 0), then from 2d + 1 points on
//!    the sphere of radius β (from the first run; 3 if it failed): ±β along each
//!    axis and β(1, …, 1)/√d, and from ±1.5β along each axis (2d more: a branch
//!    of a series system a little beyond β is the least g only there, as the
//!    four-branch system's at 5/√2 behind its pair at 3). Converged points closer than 10⁻³ max(β, 1) are one
//!    point; the design points kept are those with Φ(−β_j) ≥ 10⁻² Φ(−β_min)
//!    (the others add nothing measurable). β = |u*| (negative when the median
//!    fails) and P_FORM = Φ(−β) of the most probable point.
//! 2. **SORM** at the most probable design point: the Hessian of g in u by finite
//!    differences, divided by |∇g| and rotated so that the last axis is α; its
//!    leading (d−1)×(d−1) block's eigenvalues are the principal curvatures κ_i
//!    (positive when the surface bends away from the origin, shrinking the failure
//!    domain). Breitung (1984): P = Φ(−β) Π (1 + βκ_i)^(−½); Tvedt (1990): the
//!    three-term formula. Either is `None` when some 1 + βκ_i ≤ 0 (or
//!    1 + (β+1)κ_i ≤ 0 for Tvedt's second term).
//! 3. **Sampling**, which gives the reported probability: importance sampling
//!    from the equal-weight mixture of unit normals centred at the design points
//!    when P_FORM < 10⁻³, plain Monte Carlo otherwise (or when FORM failed), in
//!    batches until the coefficient of variation of the estimate is ≤ 0.1 or the
//!    evaluation cap (200 000) is reached. The 95 % interval is P̂ ± 1.96 σ̂. With
//!    no failure in N Monte Carlo samples the result is an upper bound 3/N (95 %).
//!    Draws are hashes of (seed, sample index): deterministic, and the same on any
//!    number of threads.
//!
//! The event status ([`EventStatus`]) flags a FORM probability that sampling
//! contradicts: |P_FORM − P̂| > 3 × the half-width of the 95 % interval.

use nalgebra::{DMatrix, SymmetricEigen};
use rayon::prelude::*;
use serde::Serialize;
use std::sync::atomic::{AtomicUsize, Ordering};

use super::distribution::{std_normal_cdf, std_normal_pdf, std_normal_quantile};
use super::model::InputModel;
use super::rng::{below, hash, open_unit};
use super::Interval;

/// Settings of a reliability analysis.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReliabilitySettings {
    /// HL-RF iterations per start (a gradient and a line search each).
    pub max_iterations: usize,
    /// Convergence tolerance of FORM (relative, see the module doc).
    pub tolerance: f64,
    /// Finite-difference step of the gradient in u, times max(1, |u_i|).
    pub gradient_step: f64,
    /// Finite-difference step of SORM's Hessian in u.
    pub hessian_step: f64,
    /// Restart FORM from 2d + 1 points on the β-sphere and 2d on the 1.5β one.
    pub multistart: bool,
    /// Compute SORM at the most probable design point.
    pub sorm: bool,
    /// Estimate the probability by sampling.
    pub sampling: bool,
    /// Stop sampling at this coefficient of variation.
    pub target_cov: f64,
    /// Evaluations per sampling batch.
    pub batch: usize,
    /// Most sampling evaluations.
    pub max_evaluations: usize,
    /// Plain Monte Carlo where P_FORM is at least this (or FORM failed);
    /// importance sampling below.
    pub monte_carlo_above: f64,
    /// Seed of the sampling.
    pub seed: u64,
}

impl Default for ReliabilitySettings {
    fn default() -> Self {
        ReliabilitySettings {
            max_iterations: 100,
            tolerance: 1e-6,
            gradient_step: 1e-5,
            hessian_step: 1e-3,
            multistart: true,
            sorm: true,
            sampling: true,
            target_cov: 0.1,
            batch: 500,
            max_evaluations: 200_000,
            monte_carlo_above: 1e-3,
            seed: 0,
        }
    }
}

/// How FORM ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FormStatus {
    /// One design point.
    Converged,
    /// Several distinct design points (the failure domain has several parts that
    /// matter): P_FORM of the most probable one underestimates.
    MultipleDesignPoints,
    /// No start converged within the iteration cap: no FORM probability.
    NotConverged,
    /// The gradient vanished (g does not vary in u): no FORM probability.
    ZeroGradient,
    /// The model failed at the median or where the gradient needed it.
    ModelFailed,
}

/// A design point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DesignPoint {
    /// β = |u*|, negative when the median is in the failure domain.
    pub beta: f64,
    /// Φ(−β).
    pub probability: f64,
    /// The point in independent standard normal space.
    pub u: Vec<f64>,
    /// The point in physical units.
    pub x: Vec<f64>,
    /// The unit vector α = −∇g/|∇g| (towards failure), per independent variable.
    pub alpha: Vec<f64>,
    /// Importance factors α_i² (sum 1): the share of each variable in β².
    pub importance: Vec<f64>,
}

/// The FORM result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FormResult {
    /// See [`FormStatus`].
    pub status: FormStatus,
    /// β of the most probable design point.
    pub beta: Option<f64>,
    /// Φ(−β).
    pub probability: Option<f64>,
    /// The distinct design points kept, most probable first.
    pub design_points: Vec<DesignPoint>,
    /// Starts run.
    pub starts: usize,
    /// Starts that converged.
    pub converged_starts: usize,
    /// Iterations of the run from the median.
    pub iterations: usize,
    /// Model evaluations.
    pub evaluations: usize,
}

/// The SORM result at the most probable design point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SormResult {
    /// Principal curvatures κ_i (d − 1 values, ascending).
    pub curvatures: Vec<f64>,
    /// Breitung's probability.
    pub breitung: Option<f64>,
    /// Tvedt's probability.
    pub tvedt: Option<f64>,
    /// Model evaluations (the Hessian).
    pub evaluations: usize,
}

/// How the probability was sampled.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SamplingMethod {
    /// Importance sampling around the design points.
    ImportanceSampling,
    /// Plain Monte Carlo.
    MonteCarlo,
}

/// How sampling ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SamplingStatus {
    /// The target coefficient of variation was reached.
    Converged,
    /// The evaluation cap came first.
    NotConverged,
    /// Monte Carlo saw no failure: only the upper bound 3/N.
    NoFailureObserved,
}

/// The sampled probability.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SamplingResult {
    /// See [`SamplingMethod`].
    pub method: SamplingMethod,
    /// See [`SamplingStatus`].
    pub status: SamplingStatus,
    /// The estimate P̂ (0 when no failure was seen).
    pub probability: f64,
    /// P̂ ± 1.96 σ̂, the lower end at least 0 (`[0, 3/N]` when no failure was seen).
    pub interval: Interval,
    /// σ̂/P̂ (infinite when P̂ = 0).
    pub cov: f64,
    /// Samples used (evaluations that succeeded).
    pub samples: usize,
    /// Samples in the failure domain.
    pub failures: usize,
    /// Evaluations where the model failed (skipped).
    pub model_failures: usize,
    /// Model evaluations.
    pub evaluations: usize,
}

/// The status of the reported probability, most serious first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EventStatus {
    /// A probability and its interval.
    Converged,
    /// As `Converged`, and FORM found several design points.
    MultipleDesignPoints,
    /// The sampled probability contradicts FORM's (FORM's approximation is poor).
    SamplingDisagrees,
    /// No failure seen: only an upper bound.
    NoFailureObserved,
    /// Sampling reached its cap before its target (the probability is less
    /// precise than asked), or, without sampling, FORM did not converge.
    NotConverged,
    /// Without sampling: FORM's gradient vanished.
    ZeroGradient,
    /// Without sampling: the model failed where FORM needed it.
    ModelFailed,
}

/// The result of a reliability analysis of one event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EventResult {
    /// See [`EventStatus`].
    pub status: EventStatus,
    /// The probability of failure: sampled when sampling ran, else FORM's.
    pub probability: Option<f64>,
    /// Its 95 % interval (sampled probabilities only).
    pub interval: Option<Interval>,
    /// The generalised reliability index −Φ⁻¹(probability).
    pub beta: Option<f64>,
    /// 3/N when Monte Carlo saw no failure in N samples.
    pub upper_bound: Option<f64>,
    /// FORM.
    pub form: FormResult,
    /// SORM, when asked and FORM converged with β > 0.
    pub sorm: Option<SormResult>,
    /// Sampling, when asked.
    pub sampling: Option<SamplingResult>,
    /// All model evaluations.
    pub evaluations: usize,
}

/// g in u space with an evaluation counter.
struct Limit<'a, G> {
    model: &'a InputModel,
    g: &'a G,
    count: AtomicUsize,
}

impl<G: Fn(&[f64]) -> Option<f64> + Sync> Limit<'_, G> {
    fn at(&self, u: &[f64]) -> Option<f64> {
        self.count.fetch_add(1, Ordering::Relaxed);
        (self.g)(&self.model.to_physical(u)).filter(|v| v.is_finite())
    }

    fn evaluations(&self) -> usize {
        self.count.load(Ordering::Relaxed)
    }

    /// The gradient at `u` (g(u) = `gu`): central differences, one-sided where a
    /// side fails, `None` where both do.
    fn gradient(&self, u: &[f64], gu: f64, step: f64) -> Option<Vec<f64>> {
        (0..u.len())
            .into_par_iter()
            .map(|i| {
                let h = step * u[i].abs().max(1.0);
                let mut up = u.to_vec();
                up[i] += h;
                let mut down = u.to_vec();
                down[i] -= h;
                match (self.at(&up), self.at(&down)) {
                    (Some(a), Some(b)) => Some((a - b) / (2.0 * h)),
                    (Some(a), None) => Some((a - gu) / h),
                    (None, Some(b)) => Some((gu - b) / h),
                    (None, None) => None,
                }
            })
            .collect()
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn norm(a: &[f64]) -> f64 {
    dot(a, a).sqrt()
}

/// One HL-RF run.
struct Run {
    status: FormStatus,
    u: Vec<f64>,
    gradient: Vec<f64>,
    iterations: usize,
}

fn hlrf<G: Fn(&[f64]) -> Option<f64> + Sync>(
    limit: &Limit<G>,
    start: Vec<f64>,
    g_scale: f64,
    s: &ReliabilitySettings,
) -> Run {
    let fail = |status, u: Vec<f64>, iterations| Run {
        status,
        gradient: vec![0.0; u.len()],
        u,
        iterations,
    };
    let mut u = start;
    let Some(mut gu) = limit.at(&u) else {
        return fail(FormStatus::ModelFailed, u, 0);
    };
    for it in 0..s.max_iterations {
        let Some(grad) = limit.gradient(&u, gu, s.gradient_step) else {
            return fail(FormStatus::ModelFailed, u, it);
        };
        let gn = norm(&grad);
        if gn.is_nan() || gn <= 1e-8 * g_scale.max(gu.abs()) {
            return fail(FormStatus::ZeroGradient, u, it);
        }
        let alpha: Vec<f64> = grad.iter().map(|x| -x / gn).collect();
        let au = dot(&alpha, &u);
        let off: f64 = u
            .iter()
            .zip(&alpha)
            .map(|(ui, ai)| (ui - au * ai).powi(2))
            .sum::<f64>()
            .sqrt();
        let un = norm(&u);
        if gu.abs() <= s.tolerance * g_scale && off <= s.tolerance * un.max(1.0) {
            return Run {
                status: FormStatus::Converged,
                u,
                gradient: grad,
                iterations: it,
            };
        }
        // HL-RF point: ((∇g·u − g)/|∇g|²) ∇g; direction d from u.
        let scale = (dot(&grad, &u) - gu) / (gn * gn);
        let d: Vec<f64> = grad
            .iter()
            .zip(&u)
            .map(|(gi, ui)| scale * gi - ui)
            .collect();
        let c = 2.0 * un.max(1.0) / gn;
        let merit = |u: &[f64], g: f64| 0.5 * dot(u, u) + c * g.abs();
        let m0 = merit(&u, gu);
        let slope = dot(&u, &d) + c * gu.signum() * dot(&grad, &d);
        let mut lambda = 1.0;
        let mut accepted = None;
        for _ in 0..40 {
            let trial: Vec<f64> = u.iter().zip(&d).map(|(a, b)| a + lambda * b).collect();
            if let Some(gt) = limit.at(&trial) {
                if merit(&trial, gt) <= m0 + 0.1 * lambda * slope.min(0.0) {
                    accepted = Some((trial, gt));
                    break;
                }
            }
            lambda *= 0.5;
        }
        match accepted {
            Some((trial, gt)) => {
                u = trial;
                gu = gt;
            }
            None => return fail(FormStatus::NotConverged, u, it + 1),
        }
    }
    fail(FormStatus::NotConverged, u, s.max_iterations)
}

/// The radius of the second ring of FORM starts, in units of the first ring's
/// β. A start sees the branch of a series system whose g is least there: on the
/// β-sphere the nearest branch can hide one a little farther out (the
/// four-branch system's points at 5/√2 behind those at 3), which wins a
/// start taken farther from the origin.
const OUTER_RING: f64 = 1.5;

fn form<G: Fn(&[f64]) -> Option<f64> + Sync>(
    limit: &Limit<G>,
    s: &ReliabilitySettings,
) -> (FormResult, Option<Vec<f64>>) {
    let d = limit.model.dim();
    let origin = vec![0.0; d];
    let Some(g0) = limit.at(&origin) else {
        return (
            FormResult {
                status: FormStatus::ModelFailed,
                beta: None,
                probability: None,
                design_points: Vec::new(),
                starts: 1,
                converged_starts: 0,
                iterations: 0,
                evaluations: limit.evaluations(),
            },
            None,
        );
    };
    let g_scale = if g0 != 0.0 { g0.abs() } else { 1.0 };
    let sign = if g0 > 0.0 { 1.0 } else { -1.0 };
    let main = hlrf(limit, origin, g_scale, s);
    let mut runs = vec![main];
    if s.multistart {
        let radius = if runs[0].status == FormStatus::Converged && norm(&runs[0].u) > 0.1 {
            norm(&runs[0].u)
        } else {
            3.0
        };
        let mut starts = Vec::with_capacity(4 * d + 1);
        for r in [radius, OUTER_RING * radius] {
            for i in 0..d {
                for sgn in [1.0, -1.0] {
                    let mut u = vec![0.0; d];
                    u[i] = sgn * r;
                    starts.push(u);
                }
            }
            if r == radius {
                starts.push(vec![radius / (d as f64).sqrt(); d]);
            }
        }
        let more: Vec<Run> = starts
            .into_par_iter()
            .map(|u| hlrf(limit, u, g_scale, s))
            .collect();
        runs.extend(more);
    }
    let starts = runs.len();
    // Converged points with the origin on the safe side of their tangent plane
    // (or on the failure side, when the median fails).
    let mut found: Vec<(f64, &Run)> = runs
        .iter()
        .filter(|r| r.status == FormStatus::Converged)
        .filter(|r| sign * dot(&r.gradient, &r.u) <= 1e-9 * norm(&r.gradient) * norm(&r.u))
        .map(|r| (sign * norm(&r.u), r))
        .collect();
    let converged_starts = found.len();
    found.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut distinct: Vec<(f64, &Run)> = Vec::new();
    for (beta, run) in found {
        let same = distinct.iter().any(|(b, r)| {
            let gap = norm(
                &r.u.iter()
                    .zip(&run.u)
                    .map(|(a, b)| a - b)
                    .collect::<Vec<_>>(),
            );
            gap < 1e-3 * b.abs().max(1.0)
        });
        if !same {
            distinct.push((beta, run));
        }
    }
    let iterations = runs[0].iterations;
    if distinct.is_empty() {
        let status = runs[0].status;
        return (
            FormResult {
                status: if status == FormStatus::Converged {
                    FormStatus::NotConverged
                } else {
                    status
                },
                beta: None,
                probability: None,
                design_points: Vec::new(),
                starts,
                converged_starts,
                iterations,
                evaluations: limit.evaluations(),
            },
            None,
        );
    }
    let p_min = std_normal_cdf(-distinct[0].0);
    let points: Vec<DesignPoint> = distinct
        .iter()
        .filter(|(b, _)| std_normal_cdf(-b) >= 1e-2 * p_min)
        .map(|(beta, run)| {
            let gn = norm(&run.gradient);
            let alpha: Vec<f64> = run.gradient.iter().map(|g| -g / gn).collect();
            DesignPoint {
                beta: *beta,
                probability: std_normal_cdf(-beta),
                x: limit.model.to_physical(&run.u),
                u: run.u.clone(),
                importance: alpha.iter().map(|a| a * a).collect(),
                alpha,
            }
        })
        .collect();
    let best_gradient = distinct[0].1.gradient.clone();
    (
        FormResult {
            status: if points.len() > 1 {
                FormStatus::MultipleDesignPoints
            } else {
                FormStatus::Converged
            },
            beta: Some(points[0].beta),
            probability: Some(points[0].probability),
            design_points: points,
            starts,
            converged_starts,
            iterations,
            evaluations: limit.evaluations(),
        },
        Some(best_gradient),
    )
}

/// z^(−½) of z = re + i·im as (modulus, argument).
fn inv_sqrt_polar(re: f64, im: f64) -> (f64, f64) {
    (re.hypot(im).powf(-0.5), -0.5 * im.atan2(re))
}

/// Breitung's and Tvedt's probabilities for β and the curvatures κ.
pub fn sorm_probabilities(beta: f64, kappa: &[f64]) -> (Option<f64>, Option<f64>) {
    if kappa.iter().any(|k| 1.0 + beta * k <= 0.0) {
        return (None, None);
    }
    let p1 = std_normal_cdf(-beta);
    let prod = |b: f64| {
        kappa
            .iter()
            .map(|k| (1.0 + b * k).powf(-0.5))
            .product::<f64>()
    };
    let breitung = p1 * prod(beta);
    if kappa.iter().any(|k| 1.0 + (beta + 1.0) * k <= 0.0) {
        return (Some(breitung), None);
    }
    let psi = beta * p1 - std_normal_pdf(beta);
    let a2 = psi * (prod(beta) - prod(beta + 1.0));
    let (modulus, arg) = kappa.iter().fold((1.0, 0.0), |(m, a), k| {
        let (mk, ak) = inv_sqrt_polar(1.0 + beta * k, *k);
        (m * mk, a + ak)
    });
    let a3 = (beta + 1.0) * psi * (prod(beta) - modulus * arg.cos());
    (Some(breitung), Some(breitung + a2 + a3))
}

fn sorm<G: Fn(&[f64]) -> Option<f64> + Sync>(
    limit: &Limit<G>,
    point: &DesignPoint,
    gradient: &[f64],
    s: &ReliabilitySettings,
) -> Option<SormResult> {
    let d = point.u.len();
    let before = limit.evaluations();
    let h = s.hessian_step;
    let u = &point.u;
    let shifted = |moves: &[(usize, f64)]| {
        let mut v = u.clone();
        for &(i, m) in moves {
            v[i] += m;
        }
        v
    };
    let g0 = limit.at(u)?;
    let mut jobs: Vec<(usize, usize)> = (0..d).map(|i| (i, i)).collect();
    for i in 0..d {
        for j in 0..i {
            jobs.push((i, j));
        }
    }
    let entries: Vec<Option<f64>> = jobs
        .par_iter()
        .map(|&(i, j)| {
            if i == j {
                let a = limit.at(&shifted(&[(i, h)]))?;
                let b = limit.at(&shifted(&[(i, -h)]))?;
                Some((a - 2.0 * g0 + b) / (h * h))
            } else {
                let pp = limit.at(&shifted(&[(i, h), (j, h)]))?;
                let pm = limit.at(&shifted(&[(i, h), (j, -h)]))?;
                let mp = limit.at(&shifted(&[(i, -h), (j, h)]))?;
                let mm = limit.at(&shifted(&[(i, -h), (j, -h)]))?;
                Some((pp - pm - mp + mm) / (4.0 * h * h))
            }
        })
        .collect();
    let gn = norm(gradient);
    let mut a = DMatrix::<f64>::zeros(d, d);
    for (&(i, j), e) in jobs.iter().zip(&entries) {
        let e = (*e)? / gn;
        a[(i, j)] = e;
        a[(j, i)] = e;
    }
    // Householder reflection H with H α = e_d; H A H's leading block.
    let mut v: Vec<f64> = point.alpha.clone();
    v[d - 1] -= 1.0;
    let vv = dot(&v, &v);
    let hmat = if vv < 1e-30 {
        DMatrix::<f64>::identity(d, d)
    } else {
        DMatrix::<f64>::from_fn(d, d, |i, j| {
            (if i == j { 1.0 } else { 0.0 }) - 2.0 * v[i] * v[j] / vv
        })
    };
    let rotated = &hmat * a * &hmat;
    let block = rotated.view((0, 0), (d - 1, d - 1)).clone_owned();
    let mut curvatures: Vec<f64> = if d > 1 {
        SymmetricEigen::new(block)
            .eigenvalues
            .iter()
            .copied()
            .collect()
    } else {
        Vec::new()
    };
    curvatures.sort_by(f64::total_cmp);
    let (breitung, tvedt) = sorm_probabilities(point.beta, &curvatures);
    Some(SormResult {
        curvatures,
        breitung,
        tvedt,
        evaluations: limit.evaluations() - before,
    })
}

fn sample<G: Fn(&[f64]) -> Option<f64> + Sync>(
    limit: &Limit<G>,
    centres: &[Vec<f64>],
    s: &ReliabilitySettings,
) -> SamplingResult {
    let d = limit.model.dim();
    let method = if centres.is_empty() {
        SamplingMethod::MonteCarlo
    } else {
        SamplingMethod::ImportanceSampling
    };
    let m = centres.len().max(1) as f64;
    let half_norms: Vec<f64> = centres.iter().map(|c| 0.5 * dot(c, c)).collect();
    let draw = |k: u64| -> Option<f64> {
        let mut u: Vec<f64> = (0..d)
            .map(|i| std_normal_quantile(open_unit(hash(s.seed, 100 + i as u64, k))))
            .collect();
        let mut w = 1.0;
        if !centres.is_empty() {
            let j = below(hash(s.seed, 7, k), centres.len());
            for (ui, ci) in u.iter_mut().zip(&centres[j]) {
                *ui += ci;
            }
            // w = φ(u) / ((1/m) Σ_j φ(u − c_j)) = m / Σ_j exp(c_j·u − |c_j|²/2).
            let e: Vec<f64> = centres
                .iter()
                .zip(&half_norms)
                .map(|(c, h)| dot(c, &u) - h)
                .collect();
            let top = e.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let sum: f64 = e.iter().map(|x| (x - top).exp()).sum();
            w = m / (top.exp() * sum);
        }
        let g = limit.at(&u)?;
        Some(if g <= 0.0 { w } else { 0.0 })
    };
    let z = 1.959_963_984_540_054;
    let (mut n, mut s1, mut s2) = (0usize, 0.0, 0.0);
    let (mut failures, mut model_failures, mut evaluations) = (0usize, 0usize, 0usize);
    let mut next = 0u64;
    let mut status = SamplingStatus::NotConverged;
    let (mut p, mut cov) = (0.0, f64::INFINITY);
    while evaluations < s.max_evaluations {
        let size = s.batch.max(1).min(s.max_evaluations - evaluations) as u64;
        let values: Vec<Option<f64>> = (next..next + size).into_par_iter().map(draw).collect();
        next += size;
        evaluations += size as usize;
        for v in values {
            match v {
                None => model_failures += 1,
                Some(w) => {
                    n += 1;
                    if w > 0.0 {
                        failures += 1;
                        s1 += w;
                        s2 += w * w;
                    }
                }
            }
        }
        if n > 1 && failures > 0 {
            let nf = n as f64;
            p = s1 / nf;
            let var = ((s2 / nf - p * p) / (nf - 1.0)).max(0.0);
            cov = var.sqrt() / p;
            if cov <= s.target_cov {
                status = SamplingStatus::Converged;
                break;
            }
        }
    }
    if failures == 0 {
        let bound = 3.0 / n.max(1) as f64;
        return SamplingResult {
            method,
            status: if method == SamplingMethod::MonteCarlo {
                SamplingStatus::NoFailureObserved
            } else {
                SamplingStatus::NotConverged
            },
            probability: 0.0,
            interval: [0.0, bound],
            cov: f64::INFINITY,
            samples: n,
            failures,
            model_failures,
            evaluations,
        };
    }
    let half = z * cov * p;
    SamplingResult {
        method,
        status,
        probability: p,
        interval: [(p - half).max(0.0), p + half],
        cov,
        samples: n,
        failures,
        model_failures,
        evaluations,
    }
}

/// The probability of failure g(x) ≤ 0 (module doc: FORM, SORM, sampling).
/// Sequential in its stages (each uses the previous), parallel inside them.
pub fn analyze<G>(model: &InputModel, g: G, settings: &ReliabilitySettings) -> EventResult
where
    G: Fn(&[f64]) -> Option<f64> + Sync,
{
    let limit = Limit {
        model,
        g: &g,
        count: AtomicUsize::new(0),
    };
    let (form, gradient) = form(&limit, settings);
    let sorm = match (&gradient, form.design_points.first()) {
        (Some(grad), Some(point)) if settings.sorm && point.beta > 0.0 => {
            sorm(&limit, point, grad, settings)
        }
        _ => None,
    };
    let sampling = settings.sampling.then(|| {
        let centres: Vec<Vec<f64>> = match form.probability {
            Some(p) if p < settings.monte_carlo_above => form
                .design_points
                .iter()
                .filter(|dp| dp.beta > 0.0)
                .map(|dp| dp.u.clone())
                .collect(),
            _ => Vec::new(),
        };
        sample(&limit, &centres, settings)
    });
    let mut result = EventResult {
        status: EventStatus::Converged,
        probability: None,
        interval: None,
        beta: None,
        upper_bound: None,
        form,
        sorm,
        sampling,
        evaluations: limit.evaluations(),
    };
    match &result.sampling {
        Some(smp) => {
            if smp.failures == 0 {
                result.status = if smp.status == SamplingStatus::NoFailureObserved {
                    EventStatus::NoFailureObserved
                } else {
                    EventStatus::NotConverged
                };
                result.upper_bound =
                    (smp.status == SamplingStatus::NoFailureObserved).then_some(smp.interval[1]);
                return result;
            }
            result.probability = Some(smp.probability);
            result.interval = Some(smp.interval);
            result.beta = Some(-std_normal_quantile(smp.probability));
            let half = 0.5 * (smp.interval[1] - smp.interval[0]);
            let disagrees = result
                .form
                .probability
                .is_some_and(|pf| (pf - smp.probability).abs() > 3.0 * half);
            result.status = if smp.status == SamplingStatus::NotConverged {
                EventStatus::NotConverged
            } else if disagrees {
                EventStatus::SamplingDisagrees
            } else if result.form.design_points.len() > 1 {
                EventStatus::MultipleDesignPoints
            } else {
                EventStatus::Converged
            };
        }
        None => {
            result.probability = result.form.probability;
            result.beta = result.form.beta;
            result.status = match result.form.status {
                FormStatus::Converged => EventStatus::Converged,
                FormStatus::MultipleDesignPoints => EventStatus::MultipleDesignPoints,
                FormStatus::NotConverged => EventStatus::NotConverged,
                FormStatus::ZeroGradient => EventStatus::ZeroGradient,
                FormStatus::ModelFailed => EventStatus::ModelFailed,
            };
        }
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorm_formulas_reduce_to_form_without_curvature() {
        let (b, t) = sorm_probabilities(2.0, &[0.0, 0.0]);
        let p = std_normal_cdf(-2.0);
        assert!((b.unwrap() - p).abs() < 1e-16);
        assert!((t.unwrap() - p).abs() < 1e-16);
        assert_eq!(sorm_probabilities(2.0, &[-0.5]), (None, None));
    }
}
