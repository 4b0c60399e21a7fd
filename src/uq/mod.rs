//! Uncertainty quantification: generic engines over a model `f(x) -> Option<f64>`
//! (`None`: the model failed at that point) whose inputs `x` are random.
//!
//! The engines know nothing of the physics, files or commands: a caller builds an
//! [`model::InputModel`] (marginal [`distribution::Distribution`]s joined by a
//! Gaussian copula) and hands over a closure. Each engine offers
//!
//! * a batch interface: the evaluation points of sample `k` computed from `k`
//!   alone (`points`/`point`), and an `analyze`/`summarize` taking the values in
//!   sample order, so that a caller can shard a run, evaluate several outputs at
//!   once and show progress;
//! * a convenience function taking `F: Fn(&[f64]) -> Option<f64> + Sync` that
//!   evaluates the points in parallel (rayon, collected in index order).
//!
//! Every result is a deterministic function of the inputs and the seed: the same on
//! any number of threads (parallel maps are collected in index order and every sum
//! is taken in a fixed order).
//!
//! * [`distribution`]: marginal laws, their quantiles and the maps to and from a
//!   standard normal variable.
//! * [`model`]: the joint input model (Nataf / Gaussian copula).
//! * [`sobol`]: Sobol′ sensitivity indices (Saltelli 2010, Jansen) with
//!   intervals from independent scrambles (replicates) of the design.
//! * [`morris`]: Morris elementary effects (screening).
//! * [`sampling`]: output statistics and quantiles from a scrambled Sobol′ sample.
//! * [`reliability`]: probability of a failure event g(x) ≤ 0: FORM, SORM,
//!   importance sampling and Monte Carlo.
//! * [`robust`]: design under uncertainty: statistic objectives over common random
//!   numbers and chance constraints by SORA, each optimum verified by sampling.
//!
//! Intervals are `[lo, hi]` pairs; a bound that the data cannot give is infinite.

pub mod distribution;
pub mod model;
pub mod morris;
pub mod reliability;
pub mod robust;
pub mod sampling;
pub mod sobol;

pub(crate) mod rng;
pub(crate) mod special;

/// A two-sided interval `[lo, hi]`.
pub type Interval = [f64; 2];

/// A statistic with its 95 % confidence interval.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Estimate {
    /// The point estimate.
    pub value: f64,
    /// The 95 % confidence interval `[lo, hi]`.
    pub interval: Interval,
}
