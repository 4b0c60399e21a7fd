//! Design-space sweeps: a study's scene evaluated at many designs spread over its
//! `[design]` box, in the same log-scaled unit coordinates as the optimiser.
//!
//! Every design is a pure function of (method, seed, samples, index), and every
//! row a pure function of its design: a sweep can be cut into shards, run on any
//! number of machines and threads, resumed, and joined again into exactly the
//! rows of one unsharded run. Rows are produced in fixed-size chunks evaluated in
//! parallel and handed over in index order, so memory does not grow with the
//! number of samples.

pub(crate) mod sequence;

use std::ops::Range;

use rayon::prelude::*;

use crate::model::{self, EvaluationOptions, Scene, Status};
use crate::optimize::functions::quantity_value;
use crate::optimize::{
    Constraint, ConstraintQuantity, DesignSpace, DesignVariable, Named, Objective, ParetoDirection,
    StudyFunctions, FEASIBILITY_TOLERANCE,
};

/// The most samples one sweep may have: 2^32 (the period of the 32-bit Sobol′ points).
pub const MAX_SAMPLES: u64 = 1 << 32;

/// Rows evaluated in parallel at a time (fixed, so that nothing depends on the
/// number of threads).
pub const CHUNK: usize = 1024;

/// How the designs are spread over the box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Digitally shifted Sobol′ points (low discrepancy; best with 2^k samples).
    Sobol,
    /// Latin hypercube: every variable's range cut into N equal strata, each hit once.
    Lhs,
    /// Full factorial grid: N must be m^n for n variables (m levels each, both ends included).
    Grid,
}

impl Named for Method {
    const ALL: &'static [Self] = &[Method::Sobol, Method::Lhs, Method::Grid];
    fn as_str(self) -> &'static str {
        match self {
            Method::Sobol => "sobol",
            Method::Lhs => "lhs",
            Method::Grid => "grid",
        }
    }
}

/// The I-th of N equal parts of a sweep (`0 ≤ index < count`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// I, 0-based.
    pub index: u64,
    /// N ≥ 1.
    pub count: u64,
}

impl Shard {
    /// The whole sweep as one part.
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// A shard, checked: `count ≥ 1` and `index < count`.
    pub fn new(index: u64, count: u64) -> Result<Shard, SweepError> {
        if count == 0 || index >= count {
            return Err(SweepError::Shard { index, count });
        }
        Ok(Shard { index, count })
    }

    /// The rows of this part of `samples`: `[⌊I·S/N⌋, ⌊(I+1)·S/N⌋)`. The parts of
    /// one N tile `0..S` without gap or overlap (empty parts when N > S).
    pub fn range(self, samples: u64) -> Range<u64> {
        let at = |i: u64| ((i as u128 * samples as u128) / self.count as u128) as u64;
        at(self.index)..at(self.index + 1)
    }

    /// The shard of a Slurm job-array task: I = (ID − MIN) / STEP of N = COUNT
    /// (`SLURM_ARRAY_TASK_ID`, `_MIN`, `_STEP`, `_COUNT`; MIN defaults to 0 and
    /// STEP to 1).
    pub fn from_slurm(
        id: u64,
        count: u64,
        min: Option<u64>,
        step: Option<u64>,
    ) -> Result<Shard, SweepError> {
        let min = min.unwrap_or(0);
        let step = step.unwrap_or(1).max(1);
        if id < min || !(id - min).is_multiple_of(step) {
            return Err(SweepError::Slurm {
                id,
                min,
                step,
                count,
            });
        }
        Shard::new((id - min) / step, count).map_err(|_| SweepError::Slurm {
            id,
            min,
            step,
            count,
        })
    }
}

/// Bad sweep settings (bad input).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SweepError {
    /// No `[design]` variables to vary.
    #[error("the study has no [design] variables: nothing to sweep (add e.g. sigma = {{ min = \"0.5 nm\", max = \"20 nm\" }})")]
    NoDesign,
    /// A materials list in `[design]`.
    #[error("[design] materials: a sweep varies the continuous [design] variables only; rank materials with `wearopt optimize`")]
    Materials,
    /// More variables than Sobol′ direction numbers.
    #[error("{dims} [design] variables: a Sobol′ sweep takes at most {max}; use lhs")]
    TooManyDimensions {
        /// Variables in the study.
        dims: usize,
        /// The most Sobol′ supports.
        max: usize,
    },
    /// Samples out of range.
    #[error("{samples} samples: must lie in 1..={max}")]
    Samples {
        /// Samples asked for.
        samples: u64,
        /// The most allowed.
        max: u64,
    },
    /// A grid whose sample count is no m^n.
    #[error("{samples} samples on a grid of {dims} variables: the count must be m^{dims} (m levels per variable); nearest: {below} or {above}")]
    Grid {
        /// Samples asked for.
        samples: u64,
        /// Variables.
        dims: usize,
        /// The nearest m^n below.
        below: u64,
        /// The nearest m^n above.
        above: u64,
    },
    /// The study's scene is not one the model can evaluate.
    #[error("scene: {0}")]
    Scene(crate::model::InputError),
    /// A shard outside `0..count`.
    #[error("shard {index}/{count}: must be I/N with 0 <= I < N and N >= 1")]
    Shard {
        /// I.
        index: u64,
        /// N.
        count: u64,
    },
    /// Slurm variables that name no shard.
    #[error("SLURM_ARRAY_TASK_ID={id} with SLURM_ARRAY_TASK_MIN={min}, SLURM_ARRAY_TASK_STEP={step}, SLURM_ARRAY_TASK_COUNT={count}: not one of the array's {count} tasks")]
    Slurm {
        /// SLURM_ARRAY_TASK_ID.
        id: u64,
        /// SLURM_ARRAY_TASK_MIN.
        min: u64,
        /// SLURM_ARRAY_TASK_STEP.
        step: u64,
        /// SLURM_ARRAY_TASK_COUNT.
        count: u64,
    },
}

/// One evaluated design.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepRow {
    /// Its index in the sweep, `0..samples`.
    pub index: u64,
    /// The design variables' values (SI), in `[design]` order.
    pub design: Vec<f64>,
    /// The evaluation's status.
    pub status: Status,
    /// Wear volume per sliding distance, k·A (m³/m).
    pub wear_rate: f64,
    /// Pull-off force of the rough surface (N); None when the model could not give one.
    pub pull_off_force: Option<f64>,
    /// log10 of the pull-off force, finite where the force underflows to 0.
    pub log10_pull_off_force: Option<f64>,
    /// Real contact area A_r (m²).
    pub real_area: f64,
    /// The value of each of [`Sweep::constraint_columns`] (SI); None where it does not exist.
    pub constraints: Vec<Option<f64>>,
    /// Status ok and every constraint met (to the optimiser's feasibility tolerance).
    pub feasible: bool,
    /// Per [`Sweep::chance_columns`]: P(the event does not occur) at the
    /// design with its 95 % interval, filled by the caller that samples the
    /// scatter (`app::sweep`); empty without chance constraints.
    pub feasible_probability: Vec<Option<FeasibleProbability>>,
}

/// P(an event does not occur) at a design, counted on a fixed sample of the
/// uncertain inputs (docs/robust-design.md, "`sweep`: feasible_probability").
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeasibleProbability {
    /// 1 − events / samples.
    pub value: f64,
    /// Its exact 95 % interval (Clopper–Pearson on the count).
    pub interval: [f64; 2],
}

/// A sweep ready to run: the scaled design space, the constraints, the sequence.
#[derive(Debug, Clone)]
pub struct Sweep {
    functions: StudyFunctions,
    constraint_columns: Vec<ConstraintQuantity>,
    method: Method,
    seed: u64,
    samples: u64,
    grid_levels: u64,
    chance_columns: Vec<String>,
}

impl Sweep {
    /// A sweep of `samples` designs of `design` around `scene`, checked up front.
    pub fn new(
        scene: &Scene,
        design: &[DesignVariable],
        constraints: &[Constraint],
        method: Method,
        samples: u64,
        seed: u64,
    ) -> Result<Sweep, SweepError> {
        scene.validate().map_err(SweepError::Scene)?;
        let dims = design.len();
        if dims == 0 {
            return Err(SweepError::NoDesign);
        }
        if samples == 0 || samples > MAX_SAMPLES {
            return Err(SweepError::Samples {
                samples,
                max: MAX_SAMPLES,
            });
        }
        if method == Method::Sobol && dims > sequence::MAX_DIMENSIONS {
            return Err(SweepError::TooManyDimensions {
                dims,
                max: sequence::MAX_DIMENSIONS,
            });
        }
        let grid_levels = if method == Method::Grid {
            sequence::grid_levels(samples, dims).ok_or_else(|| {
                let m = (samples as f64).powf(1.0 / dims as f64).floor().max(1.0) as u64;
                let pow = |m: u64| {
                    (m as u128)
                        .saturating_pow(dims as u32)
                        .min(u64::MAX as u128)
                };
                let (mut lo, mut hi) = (m, m + 1);
                while lo > 1 && pow(lo) > samples as u128 {
                    lo -= 1;
                }
                while pow(hi) < samples as u128 {
                    hi += 1;
                }
                SweepError::Grid {
                    samples,
                    dims,
                    below: pow(lo) as u64,
                    above: pow(hi) as u64,
                }
            })?
        } else {
            0
        };
        let mut functions = StudyFunctions::new(
            DesignSpace::new(scene, design),
            Objective::WearRate,
            constraints,
        );
        functions.options = EvaluationOptions {
            pull_off: true,
            ..functions.options
        };
        let fixed = [
            ConstraintQuantity::WearRate,
            ConstraintQuantity::PullOffForce,
        ];
        let mut constraint_columns: Vec<ConstraintQuantity> = Vec::new();
        for c in constraints {
            if !fixed.contains(&c.quantity) && !constraint_columns.contains(&c.quantity) {
                constraint_columns.push(c.quantity);
            }
        }
        Ok(Sweep {
            functions,
            constraint_columns,
            method,
            seed,
            samples,
            grid_levels,
            chance_columns: Vec::new(),
        })
    }

    /// The sweep with one `feasible_probability` column per chance constraint
    /// (event names, in file order), whose values the caller fills.
    pub fn with_chance_columns(mut self, events: Vec<String>) -> Sweep {
        self.chance_columns = events;
        self
    }

    /// The chance constraints' events with a `feasible_probability` column.
    pub fn chance_columns(&self) -> &[String] {
        &self.chance_columns
    }

    /// The number of designs, N.
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// The method.
    pub fn method(&self) -> Method {
        self.method
    }

    /// The seed (unused by a grid).
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The design variables' names, in `[design]` order.
    pub fn design_names(&self) -> Vec<&'static str> {
        self.functions
            .space
            .variables
            .iter()
            .map(|v| v.quantity.as_str())
            .collect()
    }

    /// The constraint quantities with a column of their own: each constrained
    /// quantity once, in file order, except wear rate and pull-off (always columns).
    pub fn constraint_columns(&self) -> &[ConstraintQuantity] {
        &self.constraint_columns
    }

    /// Design `index` in unit coordinates (`index < samples`).
    pub fn unit_point(&self, index: u64) -> Vec<f64> {
        let dims = self.functions.dim();
        match self.method {
            Method::Sobol => sequence::sobol(index, dims, self.seed),
            Method::Lhs => sequence::latin_hypercube(index, self.samples, dims, self.seed),
            Method::Grid => sequence::grid(index, self.grid_levels, dims),
        }
    }

    /// Evaluates design `index`.
    pub fn row(&self, index: u64) -> SweepRow {
        let x = self.unit_point(index);
        let scene = self.functions.scene_at(&x);
        let ev = model::evaluate(&scene, &self.functions.options);
        // Over a humidity range the limits hold at each humidity: the study's own rows.
        let feasible = ev.status == Status::Ok
            && if self.functions.humidities.is_empty() {
                self.functions.point_of(&x, &ev, &scene).max_violation() <= FEASIBILITY_TOLERANCE
            } else {
                self.functions
                    .at(&x)
                    .is_some_and(|p| p.max_violation() <= FEASIBILITY_TOLERANCE)
            };
        let finite = |v: Option<f64>| v.filter(|v| v.is_finite());
        SweepRow {
            index,
            design: self.functions.space.values(&x),
            status: ev.status,
            wear_rate: ev.wear_rate,
            pull_off_force: finite(ev.pull_off_force),
            log10_pull_off_force: finite(ev.log10_pull_off_force),
            real_area: ev.real_area,
            constraints: self
                .constraint_columns
                .iter()
                .map(|&q| finite(quantity_value(q, &ev, &scene)))
                .collect(),
            feasible,
            feasible_probability: Vec::new(),
        }
    }

    /// Evaluates the designs of `range` in chunks of [`CHUNK`], in parallel
    /// within a chunk, and hands each chunk to `sink` in index order. Stops early
    /// when `sink` returns an error, and returns it.
    pub fn run<E>(
        &self,
        range: Range<u64>,
        mut sink: impl FnMut(&[SweepRow]) -> Result<(), E>,
    ) -> Result<(), E> {
        let mut start = range.start;
        while start < range.end {
            let end = range.end.min(start + CHUNK as u64);
            let rows: Vec<SweepRow> = (start..end).into_par_iter().map(|i| self.row(i)).collect();
            sink(&rows)?;
            start = end;
        }
        Ok(())
    }
}

/// Which rows are Pareto-optimal among the feasible ones: least wear rate
/// together with the least (direction low) or greatest (high) pull-off force.
/// Rows are (wear rate, a pull-off measure, feasible); any increasing function of
/// the force gives the same front (pass its log10, which stays finite where the
/// force underflows).
/// Rows without a pull-off force are never on the front. Equal points are both kept.
pub fn pareto_optimal(rows: &[(f64, Option<f64>, bool)], direction: ParetoDirection) -> Vec<bool> {
    let sign = match direction {
        ParetoDirection::Low => 1.0,
        ParetoDirection::High => -1.0,
    };
    let mut order: Vec<(usize, f64, f64)> = rows
        .iter()
        .enumerate()
        .filter_map(|(i, &(w, p, feasible))| {
            let p = p?;
            (feasible && w.is_finite() && p.is_finite()).then_some((i, w, sign * p))
        })
        .collect();
    // By wear, then by (signed) pull-off: a point is optimal when its pull-off is
    // no worse than every point before it, strictly better than every point of
    // smaller wear.
    order.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.2.total_cmp(&b.2)));
    let mut optimal = vec![false; rows.len()];
    let mut best_before = f64::INFINITY; // best pull-off at strictly smaller wear
    let mut k = 0;
    while k < order.len() {
        let w = order[k].1;
        let group_best = order[k].2;
        let mut j = k;
        while j < order.len() && order[j].1 == w {
            if order[j].2 == group_best && group_best < best_before {
                optimal[order[j].0] = true;
            }
            j += 1;
        }
        best_before = best_before.min(group_best);
        k = j;
    }
    optimal
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shards_tile_the_samples() {
        for samples in [1u64, 7, 100, 1001] {
            for count in [1u64, 2, 3, 7, 150] {
                let mut next = 0;
                for i in 0..count {
                    let r = Shard::new(i, count).unwrap().range(samples);
                    assert_eq!(r.start, next);
                    assert!(r.end >= r.start);
                    assert!(r.end - r.start <= samples / count + 1);
                    next = r.end;
                }
                assert_eq!(next, samples);
            }
        }
    }

    #[test]
    fn slurm_task_ids_map_to_shards() {
        assert_eq!(
            Shard::from_slurm(5, 8, Some(1), None).unwrap(),
            Shard { index: 4, count: 8 }
        );
        assert_eq!(
            Shard::from_slurm(4, 3, Some(0), Some(2)).unwrap(),
            Shard { index: 2, count: 3 }
        );
        assert!(Shard::from_slurm(3, 3, Some(0), Some(2)).is_err());
        assert!(Shard::from_slurm(9, 8, Some(1), None).is_err());
        assert!(Shard::from_slurm(0, 8, Some(1), None).is_err());
    }

    #[test]
    fn pareto_front_of_a_small_cloud() {
        // (wear, pull-off): (1, 5) (2, 3) (3, 3) (2, 4) (4, 1) (0.5, None) and an infeasible (0.1, 0.1).
        let rows = [
            (1.0, Some(5.0), true),
            (2.0, Some(3.0), true),
            (3.0, Some(3.0), true),
            (2.0, Some(4.0), true),
            (4.0, Some(1.0), true),
            (0.5, None, true),
            (0.1, Some(0.1), false),
        ];
        let low = pareto_optimal(&rows, ParetoDirection::Low);
        assert_eq!(low, vec![true, true, false, false, true, false, false]);
        let high = pareto_optimal(&rows, ParetoDirection::High);
        assert_eq!(high, vec![true, false, false, false, false, false, false]);
    }
}
