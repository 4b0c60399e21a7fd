//! `wearopt uncertainty`: the scene under the scatter of its `[uncertainty]`
//! inputs — Sobol′ indices, Morris screening, percentiles and life, or the
//! probability of each event (FORM, SORM, then sampling) — on the generic
//! engines of [`crate::uq`].

use std::ops::Range;

use rayon::prelude::*;
use serde::Serialize;

use crate::model::{
    self, quantity::LN_CEIL, Evaluation, EvaluationOptions, Quantity, Scene, SceneParameter,
    SearchHints, Status,
};
use crate::problem::{Event, Problem, UncertainInput, Uncertainty};
use crate::sweep::Shard;
use crate::uq::model::InputModel;
use crate::uq::morris::{self, MorrisResult, MorrisSettings};
use crate::uq::reliability::{self, EventResult, ReliabilitySettings};
use crate::uq::sampling::{self, LifePercentiles, SamplingSummary};
use crate::uq::sobol::{self, SobolResult};

use super::{valid_scene, AppError, OptionName, Progress};

/// The analysis `wearopt uncertainty` runs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Sobol′ first-order and total indices (centred Saltelli and Jansen
    /// estimators on one scrambled 2d-dimensional sequence), N (d + 2) evaluations.
    Sobol,
    /// Morris elementary effects μ*, σ: ⌈N / (d + 1)⌉ trajectories.
    Morris,
    /// Mean, sd and percentiles of each output from N scrambled Sobol′ points.
    Sampling,
    /// The probability of each event: FORM, SORM and importance sampling (or
    /// Monte Carlo).
    Reliability,
}

impl Method {
    /// Every method, in documentation order.
    pub const ALL: [Method; 4] = [
        Method::Sobol,
        Method::Morris,
        Method::Sampling,
        Method::Reliability,
    ];

    /// The name as written on the command line and in JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Method::Sobol => "sobol",
            Method::Morris => "morris",
            Method::Sampling => "sampling",
            Method::Reliability => "reliability",
        }
    }
}

/// The method named `name`.
pub fn method(option: OptionName, name: &str) -> Result<Method, AppError> {
    Method::ALL
        .into_iter()
        .find(|m| m.as_str() == name)
        .ok_or_else(|| AppError::Invalid {
            options: vec![(option, format!("{name:?}"))],
            rule: "expected \"sobol\", \"morris\", \"sampling\" or \"reliability\"".to_string(),
        })
}

/// The options of `wearopt uncertainty`; `None` takes the file's value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct UncertaintyOptions {
    /// The analysis.
    pub method: Method,
    /// N, overriding `[uncertainty] samples`.
    pub samples: Option<u64>,
    /// The seed, overriding `[uncertainty] seed`.
    pub seed: Option<u64>,
}

impl Default for UncertaintyOptions {
    fn default() -> Self {
        UncertaintyOptions {
            method: Method::Sobol,
            samples: None,
            seed: None,
        }
    }
}

/// How many samples ended without a usable value of an output, by cause.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct Failures {
    /// The surfaces separated (a tensile load beyond the pull-off): the outputs
    /// of the operating point do not exist.
    pub separated: usize,
    /// The separation solve did not converge.
    pub not_converged: usize,
    /// Outside the model's range.
    pub out_of_range: usize,
    /// The quantity does not exist at that sample (no life without wear, …).
    pub undefined: usize,
}

impl Failures {
    /// All of them.
    pub fn total(&self) -> usize {
        self.separated + self.not_converged + self.out_of_range + self.undefined
    }
}

/// One output: its value at the file's scene and its failures over the study.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OutputInfo {
    /// The quantity.
    pub quantity: Quantity,
    /// Its value at the nominal scene (the file's), SI.
    pub nominal: Option<f64>,
    /// Samples without a usable value.
    pub failed: Failures,
}

/// The analysis' results.
#[derive(Debug, Clone, PartialEq)]
pub enum Analysis {
    /// Per output, in the order of [`UncertaintyDocument::outputs`].
    Sobol(Vec<SobolResult>),
    /// Per output.
    Morris(Vec<MorrisResult>),
    /// Per output, and the life percentiles of the life output, if one is studied.
    Sampling {
        /// Per output.
        summaries: Vec<SamplingSummary>,
        /// B1, B10, B50 of `life_cycles` (or `life_sliding_distance`).
        life: Option<(Quantity, LifePercentiles)>,
    },
    /// Per event, in the order given.
    Reliability(Vec<(Event, EventResult)>),
}

/// What `wearopt uncertainty` computes.
#[derive(Debug, Clone, PartialEq)]
pub struct UncertaintyDocument {
    /// The problem's name.
    pub name: String,
    /// The analysis run.
    pub method: Method,
    /// N used (a Sobol′ study rounds N up to a power of two).
    pub samples: u64,
    /// N as asked, when it was rounded up.
    pub samples_asked: Option<u64>,
    /// The seed.
    pub seed: u64,
    /// A hash of the scene, the study, the method, N, the seed and the version.
    pub fingerprint: String,
    /// The uncertain inputs.
    pub inputs: Vec<UncertainInput>,
    /// Their correlations `(i, j, ρ)`.
    pub correlations: Vec<(usize, usize, f64)>,
    /// The outputs studied (sobol, morris, sampling).
    pub outputs: Vec<OutputInfo>,
    /// Model evaluations in all.
    pub evaluations: usize,
    /// The results.
    pub analysis: Analysis,
}

/// The samples an analysis takes for N asked: (N used, Some(N asked) when rounded).
pub fn samples_for(method: Method, asked: u64) -> (u64, Option<u64>) {
    if method == Method::Sobol {
        let (n, rounded) = sobol::sobol_samples_rounded(asked);
        (n, rounded.then_some(asked))
    } else {
        (asked, None)
    }
}

/// The scene with the inputs set to `x` (SI, in the order of `inputs`).
pub fn scene_at(nominal: &Scene, inputs: &[UncertainInput], x: &[f64]) -> Scene {
    let mut s = nominal.clone();
    for (input, &v) in inputs.iter().zip(x) {
        input.parameter.set(&mut s, v);
    }
    s
}

/// Whether a quantity is a property of the operating point (it does not exist
/// once the surfaces have separated), rather than of the surfaces alone.
fn of_the_operating_point(q: Quantity) -> bool {
    !matches!(
        q,
        Quantity::PullOffForce
            | Quantity::StictionMargin
            | Quantity::ReleaseMargin
            | Quantity::PlasticityIndex
            | Quantity::ElasticAdhesionIndex
            | Quantity::PlasticAdhesionIndex
            | Quantity::TaborParameter
            | Quantity::HardnessToModulus
            | Quantity::WorkOfAdhesion
    )
}

/// One model evaluation: the value of each output (in the order of
/// [`Uncertainty::outputs`]), or the cause of its absence.
pub type Point = Vec<Result<f64, Cause>>;

/// Why an evaluation has no value of an output.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cause {
    /// The surfaces separated (a quantity of the operating point).
    Separated,
    /// The separation solve did not converge.
    NotConverged,
    /// Outside the model's range.
    OutOfRange,
    /// The quantity does not exist there.
    Undefined,
}

impl Cause {
    /// Every cause.
    pub const ALL: [Cause; 4] = [
        Cause::Separated,
        Cause::NotConverged,
        Cause::OutOfRange,
        Cause::Undefined,
    ];

    /// The name, as in the `failed` counts of the JSON.
    pub fn as_str(self) -> &'static str {
        match self {
            Cause::Separated => "separated",
            Cause::NotConverged => "not_converged",
            Cause::OutOfRange => "out_of_range",
            Cause::Undefined => "undefined",
        }
    }

    /// The cause of that name.
    pub fn named(name: &str) -> Option<Cause> {
        Cause::ALL.into_iter().find(|c| c.as_str() == name)
    }
}

/// The evaluation, with the pull-off search only where something read needs it
/// (a root search of its own that the wear outputs do not need).
fn evaluate(scene: &Scene, pull_off: bool) -> Evaluation {
    evaluate_hinted(scene, pull_off, SearchHints::default())
}

/// [`evaluate`] with its separation and pull-off searches started from `hints`
/// (a nearby point's answers): the same branch rules, so the same numbers to the
/// searches' tolerance (5.6e-15 relative in wear rate on the shipped scatter hub),
/// in fewer model evaluations.
fn evaluate_hinted(scene: &Scene, pull_off: bool, hints: SearchHints) -> Evaluation {
    model::evaluate_from(
        scene,
        &EvaluationOptions {
            pull_off,
            ..EvaluationOptions::default()
        },
        hints,
    )
}

/// The searches' answers at `ev`, as hints for a point near it.
fn hints_from(ev: &Evaluation) -> SearchHints {
    SearchHints {
        separation: ev.nondimensional_separation,
        pull_off: ev.nondimensional_pull_off_separation,
    }
}

/// Whether an event's limit state reads the pull-off force.
pub(crate) fn event_needs_pull_off(event: &Event) -> bool {
    match event {
        Event::Stiction => true,
        Event::WearOut => false,
        Event::Threshold { quantity, .. } => quantity.needs_pull_off(),
    }
}

/// The outputs at one evaluation.
fn outputs_of(ev: &Evaluation, scene: &Scene, outputs: &[Quantity]) -> Point {
    outputs
        .iter()
        .map(|&q| match ev.status {
            Status::NotConverged => Err(Cause::NotConverged),
            Status::OutOfRange => Err(Cause::OutOfRange),
            Status::Separated if of_the_operating_point(q) => Err(Cause::Separated),
            _ => q
                .value(ev, scene)
                .filter(|v| v.is_finite())
                .ok_or(Cause::Undefined),
        })
        .collect()
}

/// The limit state g of an event at an evaluation: failure is g ≤ 0. In the
/// logarithms of the quantities where they are positive (so that g keeps a slope
/// where a pull-off underflows); None where the model gave no answer.
pub fn limit_state(event: &Event, ev: &Evaluation, scene: &Scene) -> Option<f64> {
    if matches!(ev.status, Status::NotConverged | Status::OutOfRange) {
        return None;
    }
    let ln10 = std::f64::consts::LN_10;
    let ln_pull_off = || {
        ev.log10_pull_off_force
            .filter(|l| l.is_finite())
            .map_or(-LN_CEIL, |l| l * ln10)
    };
    match event {
        Event::Stiction => {
            let restoring = scene.requirements.restoring_force?;
            Some(restoring.ln() - ln_pull_off())
        }
        Event::WearOut => {
            let allowed = scene.requirements.allowed_wear_depth?;
            if ev.status == Status::Separated || ev.wear_rate.is_nan() || ev.wear_rate <= 0.0 {
                return Some(LN_CEIL);
            }
            let ln_depth = ev.log10_wear_rate * ln10 + scene.sliding_distance.max(1e-300).ln()
                - scene.nominal_area.ln();
            Some(allowed.ln() - ln_depth)
        }
        Event::Threshold {
            quantity,
            above,
            limit,
            ..
        } => {
            if ev.status == Status::Separated && of_the_operating_point(*quantity) {
                return None;
            }
            let sign = if *above { 1.0 } else { -1.0 };
            if *limit > 0.0 && quantity.natural_range().0 >= 0.0 {
                let ln_value = quantity.ln_value(ev, scene);
                Some(sign * (limit.ln() - ln_value))
            } else {
                let v = quantity.value(ev, scene)?;
                Some(sign * (limit - v) / limit.abs().max(f64::MIN_POSITIVE))
            }
        }
    }
}

/// A hash (FNV-1a, hexadecimal) of what determines the numbers.
fn fingerprint(scene: &Scene, u: &Uncertainty, method: Method, samples: u64, seed: u64) -> String {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    // The build (a hash of the sources, build.rs) too: parts computed by two
    // builds of one version may differ in their last digits and never merge.
    let text = format!(
        "{scene:?}|{u:?}|{}|{samples}|{seed}|{}|{}",
        method.as_str(),
        env!("CARGO_PKG_VERSION"),
        env!("WEAROPT_BUILD_ID")
    );
    for &b in text.as_bytes() {
        hash ^= u64::from(b);
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{hash:016x}")
}

/// The units a study's samples come in, which shards divide: Sobol′ and
/// sampling, the N samples (a Sobol′ sample is d + 2 evaluations); Morris, its
/// ⌈N / (d + 1)⌉ trajectories (at least 4); reliability, none (it is sequential).
pub fn units(method: Method, samples: u64, d: usize) -> u64 {
    match method {
        Method::Sobol | Method::Sampling => samples,
        Method::Morris => samples.div_ceil(d as u64 + 1).max(4),
        Method::Reliability => 0,
    }
}

/// The evaluations in one unit (see [`units`]): d + 2 for Sobol′, d + 1 for a
/// Morris trajectory, 1 for sampling.
pub fn points_per_unit(method: Method, d: usize) -> usize {
    match method {
        Method::Sobol => d + 2,
        Method::Morris => d + 1,
        Method::Sampling => 1,
        Method::Reliability => 0,
    }
}

/// What the units of a method are called in messages.
pub fn unit_name(method: Method) -> &'static str {
    match method {
        Method::Morris => "trajectories",
        _ => "samples",
    }
}

/// A study checked, its N, seed and joint law fixed.
struct Setup<'a> {
    problem: &'a Problem,
    u: &'a Uncertainty,
    method: Method,
    samples: u64,
    samples_asked: Option<u64>,
    seed: u64,
    model: InputModel,
}

impl Setup<'_> {
    fn d(&self) -> usize {
        self.model.dim()
    }

    fn units(&self) -> u64 {
        units(self.method, self.samples, self.d())
    }

    fn morris_settings(&self) -> MorrisSettings {
        MorrisSettings {
            trajectories: self.units() as usize,
            seed: self.seed,
            ..MorrisSettings::default()
        }
    }

    fn fingerprint(&self) -> String {
        fingerprint(
            &self.problem.scene,
            self.u,
            self.method,
            self.samples,
            self.seed,
        )
    }
}

/// Checks the problem and the options, and fixes the study.
fn setup<'a>(
    problem: &'a Problem,
    origin: &str,
    options: &UncertaintyOptions,
) -> Result<Setup<'a>, AppError> {
    valid_scene(problem, origin)?;
    let u = problem
        .uncertainty
        .as_ref()
        .ok_or_else(|| AppError::NoUncertainty {
            origin: origin.to_string(),
        })?;
    let asked = options.samples.unwrap_or(u.samples);
    if !(crate::problem::uncertainty::MIN_SAMPLES as u64
        ..=crate::problem::uncertainty::MAX_SAMPLES as u64)
        .contains(&asked)
    {
        return Err(AppError::Invalid {
            options: vec![(OptionName("samples"), asked.to_string())],
            rule: format!(
                "must lie in {}..={}",
                crate::problem::uncertainty::MIN_SAMPLES,
                crate::problem::uncertainty::MAX_SAMPLES
            ),
        });
    }
    if options.method == Method::Reliability && u.events.is_empty() {
        return Err(AppError::NoEvent {
            origin: origin.to_string(),
        });
    }
    let (samples, samples_asked) = samples_for(options.method, asked);
    Ok(Setup {
        problem,
        u,
        method: options.method,
        samples,
        samples_asked,
        seed: options.seed.unwrap_or(u.seed),
        model: u.input_model(),
    })
}

/// Evaluates the units `range` (see [`units`]): their points, unit after unit.
/// Every point depends on its index alone, so any split of the units over
/// threads or shards gives the same values.
fn evaluate_units(s: &Setup, range: Range<u64>, progress: &dyn Progress) -> Vec<Point> {
    let nominal = &s.problem.scene;
    let u = s.u;
    let pull_off = u.outputs.iter().any(|q| q.needs_pull_off());
    // The outputs at x, the searches started from `hints`; and x's own answers
    // as hints for the next point.
    let run = |x: &[f64], hints: SearchHints| -> (Point, SearchHints) {
        let sc = scene_at(nominal, &u.inputs, x);
        let ev = evaluate_hinted(&sc, pull_off, hints);
        (outputs_of(&ev, &sc, &u.outputs), hints_from(&ev))
    };
    match s.method {
        Method::Sobol => {
            progress.begin((range.end - range.start) as usize);
            // A sample's points after A are A with one coordinate changed (B
            // aside): their searches start from A's answers, which halves the
            // model evaluations (2.0 s against 4.1 s for 2048 samples of the
            // shipped hub on one thread). Each sample is whole in one unit, so
            // the numbers do not depend on threads or shards.
            let per_k: Vec<Vec<Point>> = range
                .into_par_iter()
                .map(|k| {
                    let points = sobol::points(&s.model, k, s.samples, s.seed);
                    let mut hints = SearchHints::default();
                    let r = points
                        .iter()
                        .enumerate()
                        .map(|(j, x)| {
                            let (point, next) = run(x, hints);
                            if j == 0 {
                                hints = next;
                            }
                            point
                        })
                        .collect();
                    progress.advance();
                    r
                })
                .collect();
            per_k.into_iter().flatten().collect()
        }
        Method::Morris => {
            let settings = s.morris_settings();
            let trajectories: Vec<Vec<Vec<f64>>> = range
                .map(|r| morris::points(&s.model, r as usize, &settings))
                .collect();
            progress.begin(trajectories.iter().map(Vec::len).sum());
            // Each point of a trajectory moves one input from the last: its
            // searches start from the last point's answers (one trajectory, one
            // unit: the numbers do not depend on threads or shards).
            let per_trajectory: Vec<Vec<Point>> = trajectories
                .par_iter()
                .map(|points| {
                    let mut hints = SearchHints::default();
                    points
                        .iter()
                        .map(|x| {
                            let (point, next) = run(x, hints);
                            hints = next;
                            progress.advance();
                            point
                        })
                        .collect()
                })
                .collect();
            per_trajectory.into_iter().flatten().collect()
        }
        Method::Sampling => {
            progress.begin((range.end - range.start) as usize);
            range
                .into_par_iter()
                .map(|k| {
                    let (r, _) = run(
                        &sampling::point(&s.model, k, s.seed),
                        SearchHints::default(),
                    );
                    progress.advance();
                    r
                })
                .collect()
        }
        Method::Reliability => Vec::new(),
    }
}

/// The analysis of all the study's points (in unit order; none for
/// reliability, which evaluates as it goes and tells `progress` of each event).
fn analyse(s: &Setup, points: Vec<Point>, progress: &dyn Progress) -> UncertaintyDocument {
    let nominal = &s.problem.scene;
    let u = s.u;
    let outputs = &u.outputs;
    let (d, seed, samples) = (s.d(), s.seed, s.samples);
    let column = |o: usize| -> Vec<Option<f64>> { points.iter().map(|p| p[o].ok()).collect() };
    let (analysis, evaluations) = match s.method {
        Method::Sobol => {
            let results = (0..outputs.len())
                .map(|o| {
                    let values: Vec<Vec<Option<f64>>> = points
                        .chunks(d + 2)
                        .map(|pts| pts.iter().map(|p| p[o].ok()).collect())
                        .collect();
                    sobol::analyze(d, &values)
                })
                .collect();
            (Analysis::Sobol(results), samples as usize * (d + 2))
        }
        Method::Morris => {
            let settings = s.morris_settings();
            let results = (0..outputs.len())
                .map(|o| {
                    let per_t: Vec<Vec<Option<f64>>> = points
                        .chunks(d + 1)
                        .map(|c| c.iter().map(|p| p[o].ok()).collect())
                        .collect();
                    morris::analyze(d, &per_t, &settings)
                })
                .collect();
            (Analysis::Morris(results), points.len())
        }
        Method::Sampling => {
            let summaries = (0..outputs.len())
                .map(|o| sampling::summarize(&column(o)))
                .collect();
            let life = outputs
                .iter()
                .position(|&q| matches!(q, Quantity::LifeCycles | Quantity::LifeSlidingDistance))
                .map(|o| (outputs[o], sampling::life_percentiles(&column(o))));
            (Analysis::Sampling { summaries, life }, samples as usize)
        }
        Method::Reliability => {
            progress.begin(u.events.len());
            let settings = ReliabilitySettings {
                seed,
                ..ReliabilitySettings::default()
            };
            let mut results = Vec::new();
            let mut evaluations = 0;
            for event in &u.events {
                let g = |x: &[f64]| {
                    let sc = scene_at(nominal, &u.inputs, x);
                    limit_state(event, &evaluate(&sc, event_needs_pull_off(event)), &sc)
                };
                let r = reliability::analyze(&s.model, g, &settings);
                evaluations += r.evaluations;
                results.push((event.clone(), r));
                progress.advance();
            }
            (Analysis::Reliability(results), evaluations)
        }
    };
    let nominal_values = outputs_of(&evaluate(nominal, true), nominal, outputs);
    let outputs_info = outputs
        .iter()
        .enumerate()
        .map(|(o, &quantity)| {
            let mut failed = Failures::default();
            for p in &points {
                match p[o] {
                    Ok(_) => {}
                    Err(Cause::Separated) => failed.separated += 1,
                    Err(Cause::NotConverged) => failed.not_converged += 1,
                    Err(Cause::OutOfRange) => failed.out_of_range += 1,
                    Err(Cause::Undefined) => failed.undefined += 1,
                }
            }
            OutputInfo {
                quantity,
                nominal: nominal_values[o].ok(),
                failed,
            }
        })
        .collect();
    UncertaintyDocument {
        name: s.problem.name.clone(),
        method: s.method,
        samples,
        samples_asked: s.samples_asked,
        seed,
        fingerprint: s.fingerprint(),
        inputs: u.inputs.clone(),
        correlations: u.correlations.clone(),
        outputs: outputs_info,
        evaluations,
        analysis,
    }
}

/// Runs the problem's uncertainty study. `origin` names the problem in errors;
/// `progress` hears of each sample (Morris: each evaluation; reliability: each
/// event).
pub fn uncertainty(
    problem: &Problem,
    origin: &str,
    options: &UncertaintyOptions,
    progress: &dyn Progress,
) -> Result<UncertaintyDocument, AppError> {
    let s = setup(problem, origin, options)?;
    let points = evaluate_units(&s, 0..s.units(), progress);
    Ok(analyse(&s, points, progress))
}

// ---------------------------------------------------------------- shards

/// What marks a part (the value of its first key, `wearopt`).
pub const PART_MARKER: &str = "uncertainty part";

/// One shard of a study (`wearopt uncertainty FILE --shard I/N`): the values of
/// its units, and all that [`merge`] needs to rebuild the study — the problem's
/// text among them.
#[derive(Debug, Clone, PartialEq)]
pub struct UncertaintyPart {
    /// The study's fingerprint (the unsharded document's).
    pub fingerprint: String,
    /// The wearopt version that wrote it.
    pub version: String,
    /// The problem's name.
    pub name: String,
    /// The analysis.
    pub method: Method,
    /// N used.
    pub samples: u64,
    /// N as asked, when it was rounded up.
    pub samples_asked: Option<u64>,
    /// The seed.
    pub seed: u64,
    /// The shard.
    pub shard: Shard,
    /// The study's units ([`units`]): the shards divide `0..units`.
    pub units: u64,
    /// The units this part holds.
    pub range: Range<u64>,
    /// Evaluations per unit ([`points_per_unit`]).
    pub points_per_unit: usize,
    /// The outputs, by name, in the order of each point's values.
    pub outputs: Vec<String>,
    /// The problem's origin (its path as given): its default name, and where a
    /// `topography` scan is looked for.
    pub origin: String,
    /// The problem's text.
    pub problem: String,
    /// The values: `points_per_unit` points per unit of `range`, in order.
    pub points: Vec<Point>,
}

/// Why parts cannot be merged (bad input).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PartError {
    /// Not a part, or one whose fields cannot be read.
    #[error(
        "not a wearopt uncertainty part (the JSON of `wearopt uncertainty FILE --shard I/N`): {0}"
    )]
    NotAPart(String),
    /// Written by another version.
    #[error("written by wearopt {found}, this is wearopt {ours}: merge with the version that wrote the parts")]
    Version {
        /// The part's version.
        found: String,
        /// Ours.
        ours: String,
    },
    /// Another study's part.
    #[error("its fingerprint {found} is not {expected}, the fingerprint of {first}: parts of different studies (problem, method, samples, seed or version) cannot be merged")]
    Foreign {
        /// The part's fingerprint.
        found: String,
        /// The first part's.
        expected: String,
        /// The first part, as named.
        first: String,
    },
    /// Fields that contradict the fingerprint.
    #[error("its {field} differs from {first}'s under the same fingerprint: an edited part")]
    Inconsistent {
        /// The field.
        field: &'static str,
        /// The first part, as named.
        first: String,
    },
    /// A range outside the study, or values that do not fill it.
    #[error("{0}: cut short or edited (rerun that shard)")]
    Values(String),
    /// Units no part holds.
    #[error("{what} {missing} of 0..{units} are missing: no part holds them (a shard not given?)")]
    Missing {
        /// "samples" or "trajectories".
        what: &'static str,
        /// The missing ranges, `a..b, c..d`.
        missing: String,
        /// The study's units.
        units: u64,
    },
    /// Units two parts hold.
    #[error("{what} {start}..{end} are in both {a} and {b} (one shard given twice?)")]
    Overlap {
        /// "samples" or "trajectories".
        what: &'static str,
        /// The first unit held twice.
        start: u64,
        /// One past the last.
        end: u64,
        /// One part, as named.
        a: String,
        /// The other.
        b: String,
    },
    /// The embedded problem cannot be read again.
    #[error("its problem ({origin}) cannot be read again: {message}")]
    Problem {
        /// The problem's origin.
        origin: String,
        /// Why.
        message: String,
    },
    /// The embedded problem does not give the part's fingerprint.
    #[error("its problem gives the fingerprint {computed}, not the {carried} it carries: an edited part, or a `topography` scan that changed since")]
    Reproduce {
        /// Of the problem as read again.
        computed: String,
        /// Carried by the part.
        carried: String,
    },
    /// `samples` asked of the merge is not the study's.
    #[error("the parts are of a study of {found} samples, not {expected}")]
    Samples {
        /// Asked.
        expected: u64,
        /// The study's.
        found: u64,
    },
    /// No parts at all.
    #[error("no parts to merge")]
    NoParts,
}

/// What one shard of the study would hold, without evaluating it: the study's
/// fingerprint, the units `shard.range(units)` and the values per unit (the
/// points times the outputs). A rerun that finds a part with these, whole, may
/// keep it ([`UncertaintyPart::is_complete_for`]).
pub fn part_identity(
    problem: &Problem,
    origin: &str,
    options: &UncertaintyOptions,
    shard: Shard,
) -> Result<(String, Range<u64>), AppError> {
    let s = setup(problem, origin, options)?;
    Ok((s.fingerprint(), shard.range(s.units())))
}

impl UncertaintyPart {
    /// True when this part is the whole of `shard` of the study `fingerprint`
    /// whose units are `range` ([`part_identity`]), written by this version: every
    /// point present (a cut file fails to parse before this).
    pub fn is_complete_for(&self, fingerprint: &str, shard: Shard, range: &Range<u64>) -> bool {
        self.fingerprint == fingerprint
            && self.shard == shard
            && self.range == *range
            && self.version == env!("CARGO_PKG_VERSION")
            && self.points.len() as u64 == (range.end - range.start) * self.points_per_unit as u64
    }
}

/// Evaluates one shard of the study: the units `shard.range(units)`. `source`
/// is the problem's text (`problem` as parsed from it with `origin`), carried in
/// the part so that [`merge`] needs nothing else. Reliability is refused: its
/// searches and its importance sampling are sequential.
pub fn uncertainty_part(
    problem: &Problem,
    origin: &str,
    source: &str,
    options: &UncertaintyOptions,
    shard: Shard,
    progress: &dyn Progress,
) -> Result<UncertaintyPart, AppError> {
    if options.method == Method::Reliability {
        return Err(AppError::Invalid {
            options: vec![
                (OptionName("shard"), format!("{}/{}", shard.index, shard.count)),
                (OptionName("method"), "reliability".to_string()),
            ],
            rule: "reliability cannot be sharded: each FORM step and each importance-sampling round depends on the last; run it unsharded (sobol, morris and sampling shard)".to_string(),
        });
    }
    let s = setup(problem, origin, options)?;
    let units = s.units();
    let range = shard.range(units);
    let points = evaluate_units(&s, range.clone(), progress);
    Ok(UncertaintyPart {
        fingerprint: s.fingerprint(),
        version: env!("CARGO_PKG_VERSION").to_string(),
        name: problem.name.clone(),
        method: s.method,
        samples: s.samples,
        samples_asked: s.samples_asked,
        seed: s.seed,
        shard,
        units,
        range,
        points_per_unit: points_per_unit(s.method, s.d()),
        outputs: s.u.outputs.iter().map(|q| q.as_str().to_string()).collect(),
        origin: origin.to_string(),
        problem: source.to_string(),
        points,
    })
}

/// Joins the parts of one study (any order; each named by its label, a file
/// name, in errors) into the document of the unsharded run: one fingerprint,
/// the units covered exactly once, the problem read again from the parts and
/// its fingerprint checked, then the analysis. `samples`, if given, must be the
/// study's N (used or asked).
pub fn merge(
    parts: Vec<(String, UncertaintyPart)>,
    samples: Option<u64>,
) -> Result<UncertaintyDocument, AppError> {
    let fail = |origin: &str, error: PartError| AppError::Part {
        origin: origin.to_string(),
        error,
    };
    let Some((first_name, first)) = parts.first() else {
        return Err(fail("merge", PartError::NoParts));
    };
    let ours = env!("CARGO_PKG_VERSION");
    for (name, p) in &parts {
        if p.version != ours {
            return Err(fail(
                name,
                PartError::Version {
                    found: p.version.clone(),
                    ours: ours.to_string(),
                },
            ));
        }
        if p.fingerprint != first.fingerprint {
            return Err(fail(
                name,
                PartError::Foreign {
                    found: p.fingerprint.clone(),
                    expected: first.fingerprint.clone(),
                    first: first_name.clone(),
                },
            ));
        }
        let inconsistent = |field: &'static str| {
            fail(
                name,
                PartError::Inconsistent {
                    field,
                    first: first_name.clone(),
                },
            )
        };
        if p.method != first.method {
            return Err(inconsistent("method"));
        }
        if (p.samples, p.samples_asked, p.units)
            != (first.samples, first.samples_asked, first.units)
        {
            return Err(inconsistent("samples"));
        }
        if p.seed != first.seed {
            return Err(inconsistent("seed"));
        }
        if p.outputs != first.outputs || p.points_per_unit != first.points_per_unit {
            return Err(inconsistent("outputs"));
        }
        if p.range.start > p.range.end || p.range.end > p.units {
            return Err(fail(
                name,
                PartError::Values(format!(
                    "its range {}..{} is not within the study's 0..{}",
                    p.range.start, p.range.end, p.units
                )),
            ));
        }
        let expected = (p.range.end - p.range.start) as usize * p.points_per_unit;
        if p.points.len() != expected {
            return Err(fail(
                name,
                PartError::Values(format!(
                    "it holds {} points, but {} {}..{} are {expected}",
                    p.points.len(),
                    unit_name(p.method),
                    p.range.start,
                    p.range.end
                )),
            ));
        }
        if let Some(k) = p.points.iter().position(|v| v.len() != p.outputs.len()) {
            return Err(fail(
                name,
                PartError::Values(format!(
                    "its point {k} has {} values for {} outputs",
                    p.points[k].len(),
                    p.outputs.len()
                )),
            ));
        }
    }
    // Coverage: every unit in exactly one part.
    let what = unit_name(first.method);
    let all = format!("{} parts", parts.len());
    let mut order: Vec<usize> = (0..parts.len())
        .filter(|&i| !parts[i].1.range.is_empty())
        .collect();
    order.sort_by_key(|&i| (parts[i].1.range.start, parts[i].1.range.end, i));
    let mut missing = Vec::new();
    let mut next = 0;
    let mut holder: Option<usize> = None;
    for &i in &order {
        let r = &parts[i].1.range;
        if r.start < next {
            let a = holder.map_or_else(String::new, |h| parts[h].0.clone());
            return Err(fail(
                &all,
                PartError::Overlap {
                    what,
                    start: r.start,
                    end: next.min(r.end),
                    a,
                    b: parts[i].0.clone(),
                },
            ));
        }
        if r.start > next {
            missing.push(format!("{next}..{}", r.start));
        }
        next = r.end;
        holder = Some(i);
    }
    if next < first.units {
        missing.push(format!("{next}..{}", first.units));
    }
    if !missing.is_empty() {
        return Err(fail(
            &all,
            PartError::Missing {
                what,
                missing: missing.join(", "),
                units: first.units,
            },
        ));
    }
    if let Some(n) = samples {
        if n != first.samples && Some(n) != first.samples_asked {
            return Err(fail(
                &all,
                PartError::Samples {
                    expected: n,
                    found: first.samples,
                },
            ));
        }
    }
    // The problem, read again from the part, must be the study's.
    let problem = super::parse(&first.problem, &first.origin).map_err(|e| {
        fail(
            first_name,
            PartError::Problem {
                origin: first.origin.clone(),
                message: e.to_string(),
            },
        )
    })?;
    let options = UncertaintyOptions {
        method: first.method,
        samples: Some(first.samples_asked.unwrap_or(first.samples)),
        seed: Some(first.seed),
    };
    let s = setup(&problem, &first.origin, &options)?;
    let computed = s.fingerprint();
    if computed != first.fingerprint {
        return Err(fail(
            first_name,
            PartError::Reproduce {
                computed,
                carried: first.fingerprint.clone(),
            },
        ));
    }
    let mut parts = parts;
    parts.sort_by_key(|(_, p)| p.range.start);
    let points: Vec<Point> = parts.into_iter().flat_map(|(_, p)| p.points).collect();
    Ok(analyse(&s, points, &super::Quiet))
}

/// The value of an input at the nominal scene (SI), for reports.
pub fn nominal_value(scene: &Scene, p: SceneParameter) -> f64 {
    p.get(scene)
}
