//! Variance-based sensitivity: first-order and total Sobol′ indices.
//!
//! Design (Saltelli 2002/2010): N samples; sample k has two points A_k and B_k,
//! the first and last d coordinates of one point of an Owen-scrambled Sobol′
//! sequence in 2d dimensions (two blocks of a d-dimensional sequence would be
//! correlated), and the d points AB_k^(i): A_k with its coordinate i taken from
//! B_k. Sample k therefore needs d + 2 evaluations, in the order
//! `[A, B, AB_1, …, AB_d]`.
//!
//! Replicates (randomized quasi-Monte Carlo, Owen 1997; L'Ecuyer & Lemieux
//! 2002): the N samples form R = [`replicates`]`(N)` blocks of M = N/R
//! consecutive samples; block r is the first M points of the 2d-dimensional
//! sequence under its own independent Owen scramble (seed drawn from the
//! study's seed and r). The blocks are independent and identically distributed,
//! each a scrambled net, so the spread between them measures the error of the
//! design, variance reduction included. (A bootstrap over the samples of one
//! scrambled design treats them as independent and ignores that reduction:
//! its 95 % intervals covered the Ishigami indices in 100 % of 200 designs at
//! N = 2¹⁰, the intervals below in the 90–99 % asked, `tests/all/uq.rs`.)
//!
//! R = 16 from N = 128 on: 15 degrees of freedom put the Student quantile
//! (2.13) within 9 % of the normal one, and each block keeps M = N/16 points
//! (64 at N = 2¹⁰, 1024 at N = 2¹⁴). The point estimate's error is that of R
//! nets of M points, not of one net of N, the price of honest intervals, and
//! the price grows with R: on Ishigami with R = 32 the error at N = 2¹⁴ was
//! three times that with R = 16 (RMS 0.0054 against 0.0017 over 40 designs),
//! and at N = 2¹⁰ the intervals were wider (mean 0.105 against 0.083, both
//! covering in about 95 %); R = 8 gives no narrower intervals than 16 (0.081)
//! on a standard error known less well (`scripts/sobol_replicates.py`).
//! Below N = 128 the blocks keep 8 samples and R = N/8 falls (8 at the
//! smallest N the command takes, 64: t = 2.36, wider intervals, the index
//! flagged `wide` when they exceed [`WIDE`]); a library caller with N < 16 gets
//! R = 2.
//!
//! Estimators (Saltelli et al. 2010, Comput. Phys. Commun. 181, 259, table 2),
//! pooled over all N samples, on outputs centred by the mean of all f(A) and
//! f(B):
//!
//! * first order S_i = mean(f_B · (f_ABi − f_A)) / V,
//! * total ST_i = mean((f_A − f_ABi)²) / (2V) (Jansen 1999),
//!
//! V the variance of the 2N values f(A) ∪ f(B). Each is a ratio of two sample
//! means, so its bias is O(1/N). Every index carries a 95 % interval
//! index ± t_{0.975, R′−1} · se, se the ratio's delta-method (linearization)
//! standard error from the R′ blocks with usable samples: with e_k = num_k −
//! index · den_k per sample and E_r the sum of e_k over block r,
//! se² = R′/(R′ − 1) · Σ_r (E_r − Ē)² / (Σ_k den_k)². With fewer than two such
//! blocks the interval is unbounded (±∞) and flagged `wide`. Estimates are
//! never clipped: a small negative first-order index is the estimator's noise
//! around zero.
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
use super::rng::hash;
use super::special::student_t_two_sided;
use super::Interval;
use crate::sweep::sequence::{sobol_owen, MAX_DIMENSIONS};

/// The most inputs a Sobol′ analysis takes (the sequence has 2d dimensions).
pub const MAX_INPUTS: usize = MAX_DIMENSIONS / 2;

/// The most independent replicates (scrambles) the N samples are split into.
pub const REPLICATES: u64 = 16;

/// The fewest samples per replicate before R falls below [`REPLICATES`].
pub const MIN_PER_REPLICATE: u64 = 8;

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

/// R, the independent replicates N samples are split into: N/8 clamped to
/// 2 … [`REPLICATES`] (see the module documentation).
pub fn replicates(n: u64) -> u64 {
    (n / MIN_PER_REPLICATE).clamp(2, REPLICATES)
}

/// M, the samples per replicate: ⌈N/R⌉ (N/R for a power of two N ≥ 2); the
/// last block is shorter when R does not divide N.
pub fn per_replicate(n: u64) -> u64 {
    n.div_ceil(replicates(n)).max(1)
}

/// The unit-cube points of sample `k` of `n` for `d` inputs:
/// `[A, B, AB_1, …, AB_d]`, each in (0, 1)^d. Sample k is point k mod M of
/// replicate ⌊k/M⌋, M = [`per_replicate`]`(n)`.
///
/// # Panics
/// If `d` is 0 or exceeds [`MAX_INPUTS`].
pub fn unit_points(d: usize, k: u64, n: u64, seed: u64) -> Vec<Vec<f64>> {
    assert!(
        (1..=MAX_INPUTS).contains(&d),
        "Sobol′ indices take 1 to {MAX_INPUTS} inputs, not {d}"
    );
    let m = per_replicate(n);
    let replicate_seed = hash(seed, 0x50B0_5EED, k / m);
    let v = sobol_owen(k % m, 2 * d, replicate_seed);
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

/// The physical points of sample `k` of `n`, `[A, B, AB_1, …, AB_d]`, to be
/// evaluated and handed to [`analyze`] in this order.
pub fn points(model: &InputModel, k: u64, n: u64, seed: u64) -> Vec<Vec<f64>> {
    unit_points(model.dim(), k, n, seed)
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

/// One index with its interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SensitivityIndex {
    /// The estimate (not clipped to [0, 1]).
    pub value: f64,
    /// The 95 % interval from the spread between replicates (unbounded when
    /// fewer than two replicates have usable samples).
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
    /// R′: the replicates with usable samples behind the intervals (R′ − 1
    /// degrees of freedom).
    pub replicates: usize,
}

/// Per-replicate sums of the centred outputs of its usable samples.
#[derive(Clone)]
struct Block {
    /// Usable samples.
    count: usize,
    /// Σ (f_A + f_B).
    sum: f64,
    /// Σ (f_A² + f_B²)/2: the denominator's sum.
    den: f64,
    /// Σ f_B (f_ABi − f_A), per input.
    first: Vec<f64>,
    /// Σ (f_ABi − f_A), per input.
    shift: Vec<f64>,
    /// Σ (f_A − f_ABi)²/2, per input.
    total: Vec<f64>,
}

impl Block {
    fn new(d: usize) -> Self {
        Block {
            count: 0,
            sum: 0.0,
            den: 0.0,
            first: vec![0.0; d],
            shift: vec![0.0; d],
            total: vec![0.0; d],
        }
    }

    /// Adds one sample's centred values `[f_A, f_B, f_AB1, …]`.
    fn add(&mut self, r: &[f64]) {
        let (fa, fb) = (r[0], r[1]);
        self.count += 1;
        self.sum += fa + fb;
        self.den += 0.5 * (fa * fa + fb * fb);
        for (i, &fab) in r[2..].iter().enumerate() {
            let delta = fab - fa;
            self.first[i] += fb * delta;
            self.shift[i] += delta;
            self.total[i] += 0.5 * delta * delta;
        }
    }
}

/// The 95 % interval of the ratio `value` = Σ num / Σ den from the blocks'
/// sums (delta method over independent blocks, Student t with R′ − 1 degrees
/// of freedom); unbounded with fewer than two blocks.
fn ratio_interval(value: f64, blocks: &[(f64, f64)], t: f64) -> Interval {
    let r = blocks.len();
    if r < 2 {
        return [f64::NEG_INFINITY, f64::INFINITY];
    }
    let den: f64 = blocks.iter().map(|b| b.1).sum();
    let e: Vec<f64> = blocks.iter().map(|&(nu, de)| nu - value * de).collect();
    let mean = e.iter().sum::<f64>() / r as f64;
    let ss: f64 = e.iter().map(|x| (x - mean) * (x - mean)).sum();
    let se = (ss * r as f64 / (r - 1) as f64).sqrt() / den;
    [value - t * se, value + t * se]
}

/// The indices of one output from the values of samples `0..N` in sample order,
/// each `[f(A), f(B), f(AB_1), …, f(AB_d)]` (`None`: the evaluation failed),
/// the samples being those of [`points`] for this N (which fixes the
/// replicates).
///
/// # Panics
/// If a sample does not have d + 2 values.
pub fn analyze(d: usize, values: &[Vec<Option<f64>>]) -> SobolResult {
    let n = values.len();
    let w = d + 2;
    let m_per = per_replicate(n as u64) as usize;
    // Usable samples' values and their replicates.
    let mut rows = Vec::with_capacity(n * w);
    let mut replicate_of = Vec::with_capacity(n);
    let mut failed = 0;
    for (k, sample) in values.iter().enumerate() {
        assert_eq!(sample.len(), w, "a Sobol′ sample has d + 2 = {w} values");
        if sample.iter().all(|v| v.is_some_and(f64::is_finite)) {
            rows.extend(sample.iter().map(|v| v.unwrap_or(f64::NAN)));
            replicate_of.push(k / m_per);
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
        replicates: 0,
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
    // Sums per replicate, in sample order (deterministic), then pooled.
    let r_count = replicates(n as u64) as usize;
    let mut blocks = vec![Block::new(d); r_count];
    for (k, &r) in replicate_of.iter().enumerate() {
        blocks[r].add(&rows[k * w..(k + 1) * w]);
    }
    blocks.retain(|b| b.count > 0);
    let mut pooled = Block::new(d);
    for b in &blocks {
        pooled.count += b.count;
        pooled.sum += b.sum;
        pooled.den += b.den;
        for i in 0..d {
            pooled.first[i] += b.first[i];
            pooled.shift[i] += b.shift[i];
            pooled.total[i] += b.total[i];
        }
    }
    let mf = pooled.count as f64;
    let mu = pooled.sum / (2.0 * mf);
    let v = (pooled.den / mf - mu * mu) * (2.0 * mf) / (2.0 * mf - 1.0);
    result.mean = mean;
    result.variance = v;
    if v.is_nan() || v <= 0.0 {
        result.status = SobolStatus::Degenerate;
        return result;
    }
    result.replicates = blocks.len();
    let t = if blocks.len() >= 2 {
        student_t_two_sided(0.05, (blocks.len() - 1) as f64)
    } else {
        f64::INFINITY
    };
    let index = |value: f64, sums: Vec<(f64, f64)>| {
        let interval = ratio_interval(value, &sums, t);
        SensitivityIndex {
            value,
            interval,
            wide: interval[1] - interval[0] > WIDE,
        }
    };
    result.first_order = (0..d)
        .map(|i| {
            // Σ (f_B − μ)(f_ABi − f_A) = Σ f_B (f_ABi − f_A) − μ Σ (f_ABi − f_A),
            // the data being centred already so that μ is small.
            let s = (pooled.first[i] - mu * pooled.shift[i]) / mf / v;
            index(s, blocks.iter().map(|b| (b.first[i], b.den)).collect())
        })
        .collect();
    result.total = (0..d)
        .map(|i| {
            let st = pooled.total[i] / (mf * v);
            index(st, blocks.iter().map(|b| (b.total[i], b.den)).collect())
        })
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
        .map(|k| points(model, k, n, seed).iter().map(|x| f(x)).collect())
        .collect();
    analyze(model.dim(), &values)
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
        let p = unit_points(3, 5, 64, 9);
        assert_eq!(p.len(), 5);
        for (i, ab) in p[2..].iter().enumerate() {
            for (j, &x) in ab.iter().enumerate() {
                let want = if i == j { p[1][j] } else { p[0][j] };
                assert_eq!(x, want);
            }
        }
    }

    #[test]
    fn replicates_by_n() {
        let r: Vec<(u64, u64)> = [2, 16, 64, 128, 256, 1024, 1 << 14]
            .iter()
            .map(|&n| (replicates(n), per_replicate(n)))
            .collect();
        assert_eq!(
            r,
            [
                (2, 1),
                (2, 8),
                (8, 8),
                (16, 8),
                (16, 16),
                (16, 64),
                (16, 1024)
            ]
        );
        // Not a power of two: the last block is shorter.
        assert_eq!((replicates(100), per_replicate(100)), (12, 9));
    }

    /// Each replicate is a scrambled net on its own: the M = 16 points of a
    /// block of N = 256 put one point in each sixteenth of every coordinate of
    /// A and B (a (0, 4, 1)-net per dimension), and the blocks are different
    /// scrambles.
    #[test]
    fn each_replicate_is_a_scrambled_net() {
        let (n, d) = (256u64, 3);
        let m = per_replicate(n);
        let mut firsts = Vec::new();
        for r in 0..replicates(n) {
            let pts: Vec<Vec<Vec<f64>>> = (r * m..(r + 1) * m)
                .map(|k| unit_points(d, k, n, 4))
                .collect();
            for (which, j) in [0, 1].iter().flat_map(|&w| (0..d).map(move |j| (w, j))) {
                let mut cells: Vec<usize> = pts
                    .iter()
                    .map(|p| (p[which][j] * m as f64) as usize)
                    .collect();
                cells.sort_unstable();
                assert_eq!(cells, (0..m as usize).collect::<Vec<_>>(), "block {r}");
            }
            firsts.push(pts[0][0][0]);
        }
        firsts.sort_by(f64::total_cmp);
        firsts.dedup();
        assert_eq!(firsts.len(), replicates(n) as usize);
    }

    #[test]
    fn failures_drop_whole_samples() {
        // f = x_0 on 2 inputs; sample 3 fails once: it is dropped.
        let mut values: Vec<Vec<Option<f64>>> = (0..64u64)
            .map(|k| {
                unit_points(2, k, 64, 1)
                    .iter()
                    .map(|x| Some(x[0]))
                    .collect()
            })
            .collect();
        values[3][2] = None;
        let r = analyze(2, &values);
        assert_eq!(r.failed, 1);
        assert_eq!(r.status, SobolStatus::Incomplete);
        // ST_0 = 1 exactly; 63 samples in 8 replicates give ±0.37 (t_7 = 2.36).
        let iv = r.total[0].interval;
        assert!(iv[0] <= 1.0 && 1.0 <= iv[1] && iv[1] - iv[0] < 0.8, "{r:?}");
        assert_eq!(r.replicates, 8);
        assert!(r.total[1].value.abs() < 1e-12);
    }
}
