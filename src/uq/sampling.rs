//! Output statistics from a sample of the inputs: mean, standard deviation,
//! quantiles and the empirical distribution function, each statistic with a
//! 95 % interval.
//!
//! The inputs are point k of an Owen-scrambled Sobol′ sequence in d dimensions
//! mapped through the input model. Intervals:
//!
//! * mean: x̄ ± 1.96 s/√n;
//! * standard deviation: the variance's asymptotic interval s² ± 1.96
//!   √((m₄ − s⁴)/n) (m₄ the fourth central moment; no normality assumed),
//!   square-rooted;
//! * quantiles: distribution-free order-statistic intervals [X_(l), X_(u)] with
//!   P(K < l) ≤ 2.5 % and P(K ≥ u) ≤ 2.5 %, K ~ Binomial(n, p) (exact for
//!   independent samples, coverage ≥ 95 %); a bound beyond the sample is infinite.
//!
//! These intervals treat the points as independent; for a scrambled Sobol′
//! sample the error of the mean is no larger than for independent points, so they
//! are conservative there. Failed evaluations (`None`) are dropped and counted.

use rayon::prelude::*;
use serde::Serialize;

use super::model::InputModel;
use super::special::binomial_cdf;
use super::Estimate;
use crate::sweep::sequence::{sobol_owen, MAX_DIMENSIONS};

/// The most inputs a sample takes (the Sobol′ sequence's dimensions).
pub const MAX_INPUTS: usize = MAX_DIMENSIONS;

/// The inputs of sample point `k` (an Owen-scrambled Sobol′ point in the model's
/// dimension, mapped through the model).
///
/// # Panics
/// If the model has more than [`MAX_INPUTS`] inputs.
pub fn point(model: &InputModel, k: u64, seed: u64) -> Vec<f64> {
    assert!(
        model.dim() <= MAX_INPUTS,
        "sampling takes at most {MAX_INPUTS} inputs, not {}",
        model.dim()
    );
    model.from_unit(&sobol_owen(k, model.dim(), seed))
}

/// The statistics of one output.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SamplingSummary {
    /// Points evaluated.
    pub samples: usize,
    /// Evaluations that failed (dropped).
    pub failed: usize,
    /// More than 1 % of the evaluations failed.
    pub incomplete: bool,
    /// Mean.
    pub mean: Estimate,
    /// Standard deviation.
    pub sd: Estimate,
    /// 1 % quantile.
    pub p1: Estimate,
    /// 5 % quantile.
    pub p5: Estimate,
    /// Median.
    pub p50: Estimate,
    /// 95 % quantile.
    pub p95: Estimate,
    /// 99 % quantile.
    pub p99: Estimate,
    /// The usable values sorted: the empirical distribution function steps by
    /// 1/n at each.
    pub sorted: Vec<f64>,
}

/// The p-quantile of sorted values (linear interpolation between order
/// statistics, Hyndman & Fan type 7) with its order-statistic 95 % interval.
/// NaN for an empty sample.
pub fn quantile(sorted: &[f64], p: f64) -> Estimate {
    let n = sorted.len();
    if n == 0 {
        return Estimate {
            value: f64::NAN,
            interval: [f64::NAN, f64::NAN],
        };
    }
    let h = p * (n - 1) as f64;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(n - 1);
    let value = sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo]);
    let nn = n as u64;
    // Largest k with P(K ≤ k) ≤ 0.025 (k = −1 if none): lower rank l = k + 1.
    let (mut a, mut b) = (-1i64, n as i64);
    while b - a > 1 {
        let m = (a + b) / 2;
        if binomial_cdf(m, nn, p) <= 0.025 {
            a = m;
        } else {
            b = m;
        }
    }
    let lower = if a >= 0 {
        sorted[a as usize]
    } else {
        f64::NEG_INFINITY
    };
    // Smallest k with P(K ≤ k) ≥ 0.975: upper rank u = k + 1.
    let (mut a, mut b) = (-1i64, n as i64);
    while b - a > 1 {
        let m = (a + b) / 2;
        if binomial_cdf(m, nn, p) >= 0.975 {
            b = m;
        } else {
            a = m;
        }
    }
    let upper = if (b as usize) < n {
        sorted[b as usize]
    } else {
        f64::INFINITY
    };
    Estimate {
        value,
        interval: [lower, upper],
    }
}

/// The usable values of `values` sorted, and the number that failed.
fn usable(values: &[Option<f64>]) -> (Vec<f64>, usize) {
    let mut v: Vec<f64> = values
        .iter()
        .filter_map(|x| x.filter(|x| x.is_finite()))
        .collect();
    let failed = values.len() - v.len();
    v.sort_by(f64::total_cmp);
    (v, failed)
}

/// The statistics of one output from its values at points `0..n`.
pub fn summarize(values: &[Option<f64>]) -> SamplingSummary {
    let (sorted, failed) = usable(values);
    let n = sorted.len() as f64;
    let mean = sorted.iter().sum::<f64>() / n;
    let (m2, m4) = sorted.iter().fold((0.0, 0.0), |(a, b), x| {
        let d = (x - mean) * (x - mean);
        (a + d, b + d * d)
    });
    let var = m2 / (n - 1.0);
    let m4 = m4 / n;
    let z = 1.959_963_984_540_054;
    let se_mean = (var / n).sqrt();
    let se_var = ((m4 - var * var).max(0.0) / n).sqrt();
    SamplingSummary {
        samples: values.len(),
        failed,
        incomplete: failed as f64 > 0.01 * values.len() as f64,
        mean: Estimate {
            value: mean,
            interval: [mean - z * se_mean, mean + z * se_mean],
        },
        sd: Estimate {
            value: var.sqrt(),
            interval: [
                (var - z * se_var).max(0.0).sqrt(),
                (var + z * se_var).sqrt(),
            ],
        },
        p1: quantile(&sorted, 0.01),
        p5: quantile(&sorted, 0.05),
        p50: quantile(&sorted, 0.5),
        p95: quantile(&sorted, 0.95),
        p99: quantile(&sorted, 0.99),
        sorted,
    }
}

/// The life percentiles B1, B10, B50 of a life quantity: the 1 %, 10 % and
/// 50 % quantiles (the lives by which 1 %, 10 %, 50 % of the parts have failed).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LifePercentiles {
    /// 1 % quantile.
    pub b1: Estimate,
    /// 10 % quantile.
    pub b10: Estimate,
    /// 50 % quantile.
    pub b50: Estimate,
}

/// B1, B10 and B50 of the values of a life quantity (failed evaluations dropped).
pub fn life_percentiles(values: &[Option<f64>]) -> LifePercentiles {
    let (sorted, _) = usable(values);
    LifePercentiles {
        b1: quantile(&sorted, 0.01),
        b10: quantile(&sorted, 0.10),
        b50: quantile(&sorted, 0.50),
    }
}

/// Evaluates `f` at points `0..n` (in parallel, collected in order) and
/// summarises the output.
pub fn run<F>(model: &InputModel, f: F, n: u64, seed: u64) -> SamplingSummary
where
    F: Fn(&[f64]) -> Option<f64> + Sync,
{
    let values: Vec<Option<f64>> = (0..n)
        .into_par_iter()
        .map(|k| f(&point(model, k, seed)))
        .collect();
    summarize(&values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn order_statistic_interval_of_the_median() {
        // n = 10, p = ½: P(K ≤ 1) = 11/1024 ≤ 0.025 < P(K ≤ 2) = 56/1024, so
        // l = 2; P(K ≤ 7) = 968/1024 < 0.975 ≤ P(K ≤ 8) = 1013/1024, so u = 9:
        // the classical [X_(2), X_(9)].
        let v: Vec<f64> = (1..=10).map(f64::from).collect();
        let q = quantile(&v, 0.5);
        assert_eq!(q.value, 5.5);
        assert_eq!(q.interval, [2.0, 9.0]);
        let q = quantile(&v, 0.01);
        assert_eq!(q.interval[0], f64::NEG_INFINITY);
    }
}
