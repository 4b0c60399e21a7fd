//! Variance-based sensitivity: first-order and total Sobol′ indices.
//!
//! Design (Saltelli 2002/2010): N samples; sample k has two points A_k and B_k,
//! the first and last d coordinates of point k of ONE Owen-scrambled Sobol′
//! sequence in 2d dimensions (two blocks of a d-dimensional sequence would be
//! correlated), and the d points AB_k^(i): A_k with its coordinate i taken from
//! B_k. Sample k therefore needs d + 2 evaluations, in the order
//! `[A, B, AB_1, …, AB_d]`.
//!
//! Estimators (Saltelli et al. 2010, Comput. Phys. Commun. 181, 259, table 2),
//! on outputs centred by the mean of all f(A) and f(B):
//!
//! * first order S_i = mean(f_B · (f_ABi − f_A)) / V,
//! * total ST_i = mean((f_A − f_ABi)²) / (2V) (Jansen 1999),
//!
//! V the variance of the 2N values f(A) ∪ f(B). Every index carries a bootstrap
//! 95 % percentile interval (samples k resampled with replacement, 1000 times, by
//! a generator seeded from the seed). Estimates are never clipped: a small
//! negative first-order index is the estimator's noise around zero.
//!
//! The swapped coordinates are those of the independent uniform variables behind
//! the input model, so with correlated inputs the indices are those of the
//! independent standard normal variables u of [`crate::uq::model`] (input i's u_i
//! is its normal score with the parts explained by inputs 0 … i−1 removed), not
//! of the correlated physical inputs.
//!
//! A model failure (`None`) drops its whole sample k (all d + 2 values).

use rayon::prelude::*;
use serde::Serialize;

use super::model::InputModel;
use super::rng::Rng;
use super::Interval;
use crate::sweep::sequence::{sobol_owen, MAX_DIMENSIONS};

/// The most inputs a Sobol′ analysis takes (the sequence has 2d dimensions).
pub const MAX_INPUTS: usize = MAX_DIMENSIONS / 2;

/// Bootstrap resamples for the intervals.
pub const RESAMPLES: usize = 1000;

/// An interval wider than this is flagged `wide` (more samples needed).
pub const WIDE: f64 = 0.1;

/// The fraction of failed samples above which a result is `Incomplete`.
pub const MAX_FAILED_FRACTION: f64 = 0.01;

/// `n` rounded up to a power of two (at least 2), and whether it changed. The
/// stratification of the Sobol′ points, and so the small error of the
/// estimates, holds for powers of two.
pub fn sobol_samples_rounded(n: u64) -> (u64, bool) {
    let m = n.max(2).next_power_of_two();
    (m, m != n)
}

/// The unit-cube points of sample `k` for `d` inputs: `[A, B, AB_1, …, AB_d]`,
/// each in (0, 1)^d.
///
/// # Panics
/// If `d` is 0 or exceeds [`MAX_INPUTS`].
pub fn unit_points(d: usize, k: u64, seed: u64) -> Vec<Vec<f64>> {
    assert!(
        (1..=MAX_INPUTS).contains(&d),
        "Sobol′ indices take 1 to {MAX_INPUTS} inputs, not {d}"
    );
    let v = sobol_owen(k, 2 * d, seed);
    let (a, b) = v.split_at(d);
    let mut out = Vec::with_capacity(d + 2);
    out.push(a.to_vec());
    out.push(b.to_vec());
    for i in 0..d {
        let mut ab = a.to_vec();
        ab[i] = b[i];
        out.push(ab);
    }
    out
}

/// The physical points of sample `k`, `[A, B, AB_1, …, AB_d]`, to be evaluated
/// and handed to [`analyze`] in this order.
pub fn points(model: &InputModel, k: u64, seed: u64) -> Vec<Vec<f64>> {
    unit_points(model.dim(), k, seed)
        .iter()
        .map(|v| model.from_unit(v))
        .collect()
}

/// Whether the analysis could use its samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SobolStatus {
    /// At most 1 % of the samples failed.
    Complete,
    /// More than 1 % of the samples had a failed evaluation (dropped).
    Incomplete,
    /// Fewer than two usable samples, or an output without variance: no indices.
    Degenerate,
}

/// One index with its bootstrap interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SensitivityIndex {
    /// The estimate (not clipped to [0, 1]).
    pub value: f64,
    /// The 95 % bootstrap percentile interval.
    pub interval: Interval,
    /// The interval is wider than [`WIDE`]: N too small for this index.
    pub wide: bool,
}

/// The Sobol′ indices of one output.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SobolResult {
    /// See [`SobolStatus`].
    pub status: SobolStatus,
    /// Samples N given.
    pub samples: usize,
    /// Samples dropped because an evaluation failed.
    pub failed: usize,
    /// Model evaluations, N (d + 2).
    pub evaluations: usize,
    /// Mean of the output over f(A) ∪ f(B).
    pub mean: f64,
    /// Variance V of the output over f(A) ∪ f(B).
    pub variance: f64,
    /// First-order indices S_i, one per input (empty when `Degenerate`).
    pub first_order: Vec<SensitivityIndex>,
    /// Total indices ST_i, one per input (empty when `Degenerate`).
    pub total: Vec<SensitivityIndex>,
    /// Some interval is wider than [`WIDE`].
    pub wide: bool,
    /// Bootstrap resamples behind the intervals.
    pub resamples: usize,
}

/// The outputs of the usable samples, centred by their overall mean.
struct Data {
    d: usize,
    /// Per sample: f_A, f_B, f_AB1 … f_ABd (centred), d + 2 values.
    rows: Vec<f64>,
}

impl Data {
    fn len(&self) -> usize {
        self.rows.len() / (self.d + 2)
    }

    /// (S, ST, V) over the samples `idx` (with repetitions).
    fn estimate(&self, idx: impl Iterator<Item = usize>) -> (Vec<f64>, Vec<f64>, f64) {
        let d = self.d;
        let w = d + 2;
        let mut m = 0usize;
        let (mut sum, mut sum2) = (0.0, 0.0);
        let mut first = vec![0.0; d];
        let mut shift = vec![0.0; d];
        let mut total = vec![0.0; d];
        for k in idx {
            let r = &self.rows[k * w..(k + 1) * w];
            let (fa, fb) = (r[0], r[1]);
            m += 1;
            sum += fa + fb;
            sum2 += fa * fa + fb * fb;
            for i in 0..d {
                let delta = r[2 + i] - fa;
                first[i] += fb * delta;
                shift[i] += delta;
                total[i] += delta * delta;
            }
        }
        let mf = m as f64;
        let mu = sum / (2.0 * mf);
        let v = (sum2 / (2.0 * mf) - mu * mu) * (2.0 * mf) / (2.0 * mf - 1.0);
        // Σ (f_B − μ)(f_ABi − f_A) = Σ f_B (f_ABi − f_A) − μ Σ (f_ABi − f_A), the
        // data being centred already so that μ is small.
        let s = (0..d)
            .map(|i| (first[i] - mu * shift[i]) / mf / v)
            .collect();
        let st = total.iter().map(|t| t / (2.0 * mf * v)).collect();
        (s, st, v)
    }
}

/// The 2.5 % and 97.5 % points of `values` (linear interpolation between order
/// statistics).
fn percentile_interval(mut values: Vec<f64>) -> Interval {
    values.sort_by(f64::total_cmp);
    let at = |p: f64| {
        let h = p * (values.len() - 1) as f64;
        let lo = h.floor() as usize;
        let hi = (lo + 1).min(values.len() - 1);
        values[lo] + (h - lo as f64) * (values[hi] - values[lo])
    };
    [at(0.025), at(0.975)]
}

/// The indices of one output from the values of samples `0..N` in sample order,
/// each `[f(A), f(B), f(AB_1), …, f(AB_d)]` (`None`: the evaluation failed),
/// with [`RESAMPLES`] bootstrap resamples drawn from `seed`.
///
/// # Panics
/// If a sample does not have d + 2 values.
pub fn analyze(d: usize, values: &[Vec<Option<f64>>], seed: u64) -> SobolResult {
    analyze_with(d, values, seed, RESAMPLES)
}

/// [`analyze`] with a chosen number of bootstrap resamples (0: no intervals,
/// each interval the point estimate).
pub fn analyze_with(
    d: usize,
    values: &[Vec<Option<f64>>],
    seed: u64,
    resamples: usize,
) -> SobolResult {
    let n = values.len();
    let w = d + 2;
    let mut rows = Vec::with_capacity(n * w);
    let mut failed = 0;
    for sample in values {
        assert_eq!(sample.len(), w, "a Sobol′ sample has d + 2 = {w} values");
        if sample.iter().all(|v| v.is_some_and(f64::is_finite)) {
            rows.extend(sample.iter().map(|v| v.unwrap_or(f64::NAN)));
        } else {
            failed += 1;
        }
    }
    let used = n - failed;
    let mut result = SobolResult {
        status: if failed as f64 > MAX_FAILED_FRACTION * n as f64 {
            SobolStatus::Incomplete
        } else {
            SobolStatus::Complete
        },
        samples: n,
        failed,
        evaluations: n * w,
        mean: f64::NAN,
        variance: f64::NAN,
        first_order: Vec::new(),
        total: Vec::new(),
        wide: false,
        resamples,
    };
    if used < 2 {
        result.status = SobolStatus::Degenerate;
        return result;
    }
    let mean = (0..used)
        .map(|k| rows[k * w] + rows[k * w + 1])
        .sum::<f64>()
        / (2 * used) as f64;
    for r in rows.iter_mut() {
        *r -= mean;
    }
    let data = Data { d, rows };
    let (s, st, v) = data.estimate(0..used);
    result.mean = mean;
    result.variance = v;
    if v.is_nan() || v <= 0.0 {
        result.status = SobolStatus::Degenerate;
        return result;
    }
    let boot: Vec<(Vec<f64>, Vec<f64>)> = (0..resamples)
        .into_par_iter()
        .map(|r| {
            let mut rng = Rng::new(seed, 0x50B0_0000 + r as u64);
            let m = data.len();
            let idx: Vec<usize> = (0..m).map(|_| rng.below(m)).collect();
            let (s, st, _) = data.estimate(idx.into_iter());
            (s, st)
        })
        .collect();
    let index = |value: f64, column: Vec<f64>| {
        let interval = if column.is_empty() {
            [value, value]
        } else {
            percentile_interval(column)
        };
        SensitivityIndex {
            value,
            interval,
            wide: interval[1] - interval[0] > WIDE,
        }
    };
    result.first_order = (0..d)
        .map(|i| index(s[i], boot.iter().map(|b| b.0[i]).collect()))
        .collect();
    result.total = (0..d)
        .map(|i| index(st[i], boot.iter().map(|b| b.1[i]).collect()))
        .collect();
    result.wide = result
        .first_order
        .iter()
        .chain(&result.total)
        .any(|x| x.wide);
    result
}

/// Evaluates `f` at the points of samples `0..n` (in parallel, collected in
/// sample order) and analyses them: the Sobol′ indices of `f` over `model`.
pub fn indices<F>(model: &InputModel, f: F, n: u64, seed: u64) -> SobolResult
where
    F: Fn(&[f64]) -> Option<f64> + Sync,
{
    let values: Vec<Vec<Option<f64>>> = (0..n)
        .into_par_iter()
        .map(|k| points(model, k, seed).iter().map(|x| f(x)).collect())
        .collect();
    analyze(model.dim(), &values, seed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_to_powers_of_two() {
        assert_eq!(sobol_samples_rounded(1024), (1024, false));
        assert_eq!(sobol_samples_rounded(1000), (1024, true));
        assert_eq!(sobol_samples_rounded(0), (2, true));
    }

    #[test]
    fn ab_points_swap_one_coordinate() {
        let p = unit_points(3, 5, 9);
        assert_eq!(p.len(), 5);
        for (i, ab) in p[2..].iter().enumerate() {
            for (j, &x) in ab.iter().enumerate() {
                let want = if i == j { p[1][j] } else { p[0][j] };
                assert_eq!(x, want);
            }
        }
    }

    #[test]
    fn failures_drop_whole_samples() {
        // f = x_0 on 2 inputs; sample 3 fails once: it is dropped.
        let mut values: Vec<Vec<Option<f64>>> = (0..64u64)
            .map(|k| unit_points(2, k, 1).iter().map(|x| Some(x[0])).collect())
            .collect();
        values[3][2] = None;
        let r = analyze_with(2, &values, 1, 50);
        assert_eq!(r.failed, 1);
        assert_eq!(r.status, SobolStatus::Incomplete);
        assert!((r.total[0].value - 1.0).abs() < 0.1, "{r:?}");
        assert!(r.total[1].value.abs() < 1e-12);
    }
}
