//! Morris screening: elementary effects along one-at-a-time trajectories
//! (Morris 1991, Technometrics 33, 161; μ* of Campolongo, Cariboni & Saltelli
//! 2007, Environ. Model. Softw. 22, 1509).
//!
//! Each input is gridded by probability: with p levels (default 4), level j of
//! input i is the point where its distribution function equals (j + ½)/p (the
//! centre of the j-th of p equally likely strata, so that unbounded laws are
//! gridded too). A trajectory starts at a random grid point and moves each input
//! once, in a random order, by Δ = ⌊p/2⌋ levels (Δ = p/(2(p−1)) of the grid's
//! span, Morris's choice, for even p) up or down, so it has d + 1 points.
//!
//! **Scale of the effects.** An elementary effect is the change of the output
//! divided by the change of the input's probability (its distribution function
//! value): EE_i = (f(x′) − f(x)) / (F_i(x′_i) − F_i(x_i)), a step of ⌊p/2⌋/p
//! (½ for even p). It is therefore in output units per unit of probability:
//! comparable across inputs of different units, and for a uniform input it is
//! the physical slope times the input's range. μ* = mean |EE|, μ = mean EE,
//! σ = the standard deviation of EE (n − 1 in the denominator).
//!
//! With correlated inputs the grid is over the independent variables behind the
//! copula ([`crate::uq::model`]), so the effects are those of those variables.
//!
//! Deterministic from the seed; trajectory `r` is computable from `r` alone.

use rayon::prelude::*;
use serde::Serialize;

use super::model::InputModel;
use super::rng::Rng;

/// Settings of a Morris screening.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MorrisSettings {
    /// Trajectories r (each d + 1 evaluations).
    pub trajectories: usize,
    /// Grid levels p ≥ 2 (even recommended).
    pub levels: usize,
    /// Seed of the trajectories.
    pub seed: u64,
}

impl Default for MorrisSettings {
    fn default() -> Self {
        MorrisSettings {
            trajectories: 20,
            levels: 4,
            seed: 0,
        }
    }
}

/// One trajectory in the unit (probability) cube.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// The d + 1 points, each in (0, 1)^d (values of the inputs' distribution
    /// functions, independent coordinates).
    pub unit: Vec<Vec<f64>>,
    /// The input moved at step s (from point s to s + 1).
    pub input: Vec<usize>,
    /// The signed change of that input's probability at step s.
    pub step: Vec<f64>,
}

/// Trajectory `r` for `d` inputs.
///
/// # Panics
/// If `levels < 2` or `d == 0`.
pub fn trajectory(d: usize, r: usize, settings: &MorrisSettings) -> Trajectory {
    let p = settings.levels;
    assert!(p >= 2 && d >= 1, "Morris needs ≥ 2 levels and ≥ 1 input");
    let jump = p / 2;
    let mut rng = Rng::new(settings.seed, 0x3033_0000 + r as u64);
    let mut level: Vec<usize> = (0..d).map(|_| rng.below(p)).collect();
    let mut order: Vec<usize> = (0..d).collect();
    for i in (1..d).rev() {
        let j = rng.below(i + 1);
        order.swap(i, j);
    }
    let to_unit = |level: &[usize]| -> Vec<f64> {
        level.iter().map(|&j| (j as f64 + 0.5) / p as f64).collect()
    };
    let mut unit = vec![to_unit(&level)];
    let mut step = Vec::with_capacity(d);
    for &i in &order {
        if level[i] + jump < p {
            level[i] += jump;
            step.push(jump as f64 / p as f64);
        } else {
            level[i] -= jump;
            step.push(-(jump as f64) / p as f64);
        }
        unit.push(to_unit(&level));
    }
    Trajectory {
        unit,
        input: order,
        step,
    }
}

/// The d + 1 physical points of trajectory `r`, to be evaluated in this order.
pub fn points(model: &InputModel, r: usize, settings: &MorrisSettings) -> Vec<Vec<f64>> {
    trajectory(model.dim(), r, settings)
        .unit
        .iter()
        .map(|v| model.from_unit(v))
        .collect()
}

/// The screening measures of one input.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MorrisEffect {
    /// μ* = mean |EE| (output units per unit of probability).
    pub mu_star: f64,
    /// μ = mean EE.
    pub mu: f64,
    /// σ = standard deviation of EE (0 with a single effect).
    pub sigma: f64,
    /// Elementary effects behind the numbers.
    pub count: usize,
}

/// The Morris measures of one output.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MorrisResult {
    /// Trajectories given.
    pub trajectories: usize,
    /// Model evaluations, r (d + 1).
    pub evaluations: usize,
    /// Failed evaluations; an effect needing one is dropped.
    pub failed: usize,
    /// More than 1 % of the evaluations failed.
    pub incomplete: bool,
    /// One per input.
    pub effects: Vec<MorrisEffect>,
}

/// The measures of one output from the values of trajectories `0..r` in order,
/// each the d + 1 values at [`points`] (`None`: failed).
///
/// # Panics
/// If a trajectory does not have d + 1 values.
pub fn analyze(d: usize, values: &[Vec<Option<f64>>], settings: &MorrisSettings) -> MorrisResult {
    let mut effects: Vec<Vec<f64>> = vec![Vec::new(); d];
    let mut failed = 0;
    for (r, v) in values.iter().enumerate() {
        assert_eq!(v.len(), d + 1, "a Morris trajectory has d + 1 values");
        failed += v.iter().filter(|x| !x.is_some_and(f64::is_finite)).count();
        let t = trajectory(d, r, settings);
        for s in 0..d {
            if let (Some(a), Some(b)) = (v[s], v[s + 1]) {
                if a.is_finite() && b.is_finite() {
                    effects[t.input[s]].push((b - a) / t.step[s]);
                }
            }
        }
    }
    let evaluations = values.len() * (d + 1);
    MorrisResult {
        trajectories: values.len(),
        evaluations,
        failed,
        incomplete: failed as f64 > 0.01 * evaluations as f64,
        effects: effects
            .iter()
            .map(|e| {
                let n = e.len() as f64;
                let mu = e.iter().sum::<f64>() / n;
                let mu_star = e.iter().map(|x| x.abs()).sum::<f64>() / n;
                let sigma = if e.len() > 1 {
                    (e.iter().map(|x| (x - mu).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
                } else {
                    0.0
                };
                MorrisEffect {
                    mu_star,
                    mu,
                    sigma,
                    count: e.len(),
                }
            })
            .collect(),
    }
}

/// Evaluates `f` along the trajectories (in parallel, collected in order) and
/// analyses them.
pub fn indices<F>(model: &InputModel, f: F, settings: &MorrisSettings) -> MorrisResult
where
    F: Fn(&[f64]) -> Option<f64> + Sync,
{
    let values: Vec<Vec<Option<f64>>> = (0..settings.trajectories)
        .into_par_iter()
        .map(|r| points(model, r, settings).iter().map(|x| f(x)).collect())
        .collect();
    analyze(model.dim(), &values, settings)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_trajectory_moves_each_input_once_by_half() {
        let s = MorrisSettings::default();
        let t = trajectory(5, 3, &s);
        assert_eq!(t.unit.len(), 6);
        let mut seen = [false; 5];
        for (k, &i) in t.input.iter().enumerate() {
            assert!(!seen[i]);
            seen[i] = true;
            assert_eq!(t.step[k].abs(), 0.5);
            assert!((t.unit[k + 1][i] - t.unit[k][i] - t.step[k]).abs() < 1e-15);
            assert!(t.unit[k + 1][i] > 0.0 && t.unit[k + 1][i] < 1.0);
        }
    }
}
