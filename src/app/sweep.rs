//! `wearopt sweep`: a study's scene at N designs spread over its `[design]` box,
//! rows streamed as they are computed, in shards; and what `merge` and the map plot
//! need of a sweep.

use std::ops::Range;

use crate::problem::Problem;
use crate::sweep::SweepError;

use super::{AppError, OptionName};

pub use crate::optimize::ParetoDirection;
pub use crate::sweep::{FeasibleProbability, Method, Shard, Sweep, SweepRow};

/// The options of `wearopt sweep` (which part of it to run is
/// [`SweepPlan::part`]'s).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SweepOptions {
    /// Number of designs N over all shards.
    pub samples: u64,
    /// How the designs fill the box.
    pub method: Method,
    /// Seed of the Sobol′ shift or the Latin hypercube.
    pub seed: u64,
}

/// A sweep ready to run: what its output's head says and the rows it will compute.
#[derive(Debug, Clone)]
pub struct SweepPlan {
    /// The problem's name.
    pub name: String,
    /// The sweep.
    pub sweep: Sweep,
    /// The rows to run: all of them, or a shard's ([`SweepPlan::part`]).
    pub range: Range<u64>,
    /// Which end of the pull-off the study prefers (its `[pareto]` direction;
    /// low without one): what the map's Pareto-optimal designs minimise.
    pub direction: ParetoDirection,
    /// With chance constraints: the problem and the common random numbers its
    /// `feasible_probability` columns are counted on.
    chance: Option<(Box<Problem>, Vec<Vec<f64>>)>,
}

/// The sampling method named `name` ("sobol", "lhs", "grid").
pub fn method(option: OptionName, name: &str) -> Result<Method, AppError> {
    match name {
        "sobol" => Ok(Method::Sobol),
        "lhs" => Ok(Method::Lhs),
        "grid" => Ok(Method::Grid),
        other => Err(AppError::Invalid {
            options: vec![(option, format!("{other:?}"))],
            rule: "expected \"sobol\", \"lhs\" or \"grid\"".to_string(),
        }),
    }
}

/// Part `index` of `count`.
pub fn shard(index: u64, count: u64) -> Result<Shard, AppError> {
    Shard::new(index, count).map_err(|_| AppError::Invalid {
        options: vec![(OptionName("shard"), format!("{index}/{count}"))],
        rule: "expected I/N with 0 <= I < N".to_string(),
    })
}

/// The whole sweep of the problem's study under `options`, checked up front.
pub fn plan(
    problem: &Problem,
    origin: &str,
    options: &SweepOptions,
) -> Result<SweepPlan, AppError> {
    let sweep_error = |error| AppError::Sweep {
        origin: origin.to_string(),
        samples: options.samples,
        error,
    };
    if !problem.study.materials.is_empty() {
        return Err(sweep_error(SweepError::Materials));
    }
    let sweep = Sweep::new(
        &problem.scene,
        &problem.study.design,
        &problem.study.constraints,
        options.method,
        options.samples,
        options.seed,
    )
    .map_err(sweep_error)?;
    let chance = problem
        .uncertainty
        .as_ref()
        .filter(|_| !problem.robust.chance.is_empty())
        .map(|u| {
            let points =
                crate::uq::robust::common_points(u.inputs.len(), problem.robust.samples, u.seed);
            (Box::new(problem.clone()), points)
        });
    let sweep = match &chance {
        Some(_) => sweep.with_chance_columns(
            problem
                .robust
                .chance
                .iter()
                .map(|c| c.event.name().to_string())
                .collect(),
        ),
        None => sweep,
    };
    Ok(SweepPlan {
        chance,
        name: problem.name.clone(),
        range: 0..sweep.samples(),
        sweep,
        direction: problem
            .study
            .pareto
            .as_ref()
            .map_or(ParetoDirection::Low, |p| p.direction),
    })
}

impl SweepPlan {
    /// The plan of part `shard` of this sweep.
    pub fn part(self, shard: Shard) -> SweepPlan {
        SweepPlan {
            range: shard.range(self.sweep.samples()),
            ..self
        }
    }

    /// Computes the rows of this shard in order, handing them to `sink` in blocks
    /// as they are final (memory does not grow with N).
    /// With chance constraints each row's `feasible_probability` is filled:
    /// per chance constraint, 1 − P(event) counted on the study's common random
    /// numbers at the design (`[objective] samples` of them, seed
    /// `[uncertainty] seed`), with its exact 95 % interval
    /// ([`crate::uq::robust::counted_probabilities`]).
    pub fn run<E>(&self, mut sink: impl FnMut(&[SweepRow]) -> Result<(), E>) -> Result<(), E> {
        let Some((problem, points)) = &self.chance else {
            return self.sweep.run(self.range.clone(), sink);
        };
        let program = super::robust::RobustProgram::new(problem)
            .expect("a problem with chance constraints has uncertainty, an objective and a design");
        let count = problem.robust.chance.len();
        self.sweep.run(self.range.clone(), |rows: &[SweepRow]| {
            let mut rows = rows.to_vec();
            for r in &mut rows {
                let d = self.sweep.unit_point(r.index);
                r.feasible_probability =
                    crate::uq::robust::counted_probabilities(&program, &d, points, count)
                        .into_iter()
                        .map(|c| {
                            (c.samples > 0).then(|| FeasibleProbability {
                                value: 1.0 - c.probability,
                                interval: [1.0 - c.interval[1], 1.0 - c.interval[0]],
                            })
                        })
                        .collect();
            }
            sink(&rows)
        })
    }
}

/// Which of the map's points (wear rate, log10 pull-off, feasible) are
/// Pareto-optimal among the feasible ones in the study's direction.
pub fn pareto_optimal(
    points: &[(f64, Option<f64>, bool)],
    direction: ParetoDirection,
) -> Vec<bool> {
    crate::sweep::pareto_optimal(points, direction)
}

/// The content a sweep's fingerprint covers (`report::sweep::fingerprint`):
/// `problem_bytes` (the problem file as read, or a dict's JSON text) and, when
/// the problem names a measured scan (`[roughness] topography`), the scan file's
/// bytes — so that a changed scan under the same name is a different sweep, whose
/// old output is neither kept by a rerun nor merged with new parts. A scan that
/// cannot be read again adds its path only (the problem was loaded from it).
pub fn fingerprint_content(problem: &Problem, problem_bytes: &[u8]) -> Vec<u8> {
    let mut content = problem_bytes.to_vec();
    if let Some(scan) = &problem.scan {
        content.extend_from_slice(b"\0scan\0");
        content.extend_from_slice(scan.path.as_bytes());
        content.push(0);
        if let Ok(bytes) = std::fs::read(&scan.path) {
            content.extend_from_slice(&bytes);
        }
    }
    content
}
