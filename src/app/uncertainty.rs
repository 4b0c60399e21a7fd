//! `wearopt uncertainty`: the scene under the scatter of its `[uncertainty]`
//! inputs — Sobol′ indices, Morris screening, percentiles and life, or the
//! probability of each event (FORM, SORM, then sampling) — on the generic
//! engines of [`crate::uq`].

use rayon::prelude::*;
use serde::Serialize;

use crate::model::{
    self, quantity::LN_CEIL, Evaluation, EvaluationOptions, Quantity, Scene, SceneParameter, Status,
};
use crate::problem::{Event, Problem, UncertainInput, Uncertainty};
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

/// One sample: the outputs' values, or the cause of their absence.
type Sample = Vec<Result<f64, Cause>>;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Cause {
    Separated,
    NotConverged,
    OutOfRange,
    Undefined,
}

fn evaluate(scene: &Scene) -> Evaluation {
    model::evaluate(scene, &EvaluationOptions::default())
}

/// The outputs at one evaluation.
fn outputs_of(ev: &Evaluation, scene: &Scene, outputs: &[Quantity]) -> Sample {
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
    let text = format!(
        "{scene:?}|{u:?}|{}|{samples}|{seed}|{}",
        method.as_str(),
        env!("CARGO_PKG_VERSION")
    );
    for &b in text.as_bytes() {
        hash ^= u64::from(b);
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{hash:016x}")
}

/// Runs the problem's uncertainty study. `origin` names the problem in errors;
/// `progress` hears of each sample (or, under `reliability`, each event).
pub fn uncertainty(
    problem: &Problem,
    origin: &str,
    options: &UncertaintyOptions,
    progress: &dyn Progress,
) -> Result<UncertaintyDocument, AppError> {
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
    let seed = options.seed.unwrap_or(u.seed);
    let (samples, samples_asked) = samples_for(options.method, asked);
    let model = u.input_model();
    let nominal = &problem.scene;
    let outputs = &u.outputs;
    let nominal_ev = evaluate(nominal);
    let nominal_values = outputs_of(&nominal_ev, nominal, outputs);
    let run = |x: &[f64]| -> Sample {
        let s = scene_at(nominal, &u.inputs, x);
        outputs_of(&evaluate(&s), &s, outputs)
    };
    let d = model.dim();
    let mut all_samples: Vec<Sample> = Vec::new();
    let (analysis, evaluations) = match options.method {
        Method::Sobol => {
            progress.begin(samples as usize);
            let per_k: Vec<Vec<Sample>> = (0..samples)
                .into_par_iter()
                .map(|k| {
                    let r = sobol::points(&model, k, seed)
                        .iter()
                        .map(|x| run(x))
                        .collect();
                    progress.advance();
                    r
                })
                .collect();
            let results = (0..outputs.len())
                .map(|o| {
                    let values: Vec<Vec<Option<f64>>> = per_k
                        .iter()
                        .map(|pts| pts.iter().map(|s| s[o].ok()).collect())
                        .collect();
                    sobol::analyze(d, &values, seed)
                })
                .collect();
            all_samples = per_k.into_iter().flatten().collect();
            (Analysis::Sobol(results), samples as usize * (d + 2))
        }
        Method::Morris => {
            let trajectories = (samples as usize).div_ceil(d + 1).max(4);
            let settings = MorrisSettings {
                trajectories,
                seed,
                ..MorrisSettings::default()
            };
            let points: Vec<Vec<f64>> = (0..trajectories)
                .flat_map(|r| morris::points(&model, r, &settings))
                .collect();
            progress.begin(points.len());
            let values: Vec<Sample> = points
                .par_iter()
                .map(|x| {
                    let r = run(x);
                    progress.advance();
                    r
                })
                .collect();
            let results = (0..outputs.len())
                .map(|o| {
                    let per_t: Vec<Vec<Option<f64>>> = values
                        .chunks(d + 1)
                        .map(|c| c.iter().map(|s| s[o].ok()).collect())
                        .collect();
                    morris::analyze(d, &per_t, &settings)
                })
                .collect();
            let n = values.len();
            all_samples = values;
            (Analysis::Morris(results), n)
        }
        Method::Sampling => {
            progress.begin(samples as usize);
            let values: Vec<Sample> = (0..samples)
                .into_par_iter()
                .map(|k| {
                    let r = run(&sampling::point(&model, k, seed));
                    progress.advance();
                    r
                })
                .collect();
            let column =
                |o: usize| -> Vec<Option<f64>> { values.iter().map(|s| s[o].ok()).collect() };
            let summaries = (0..outputs.len())
                .map(|o| sampling::summarize(&column(o)))
                .collect();
            let life = outputs
                .iter()
                .position(|&q| matches!(q, Quantity::LifeCycles | Quantity::LifeSlidingDistance))
                .map(|o| (outputs[o], sampling::life_percentiles(&column(o))));
            all_samples = values;
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
                    let s = scene_at(nominal, &u.inputs, x);
                    limit_state(event, &evaluate(&s), &s)
                };
                let r = reliability::analyze(&model, g, &settings);
                evaluations += r.evaluations;
                results.push((event.clone(), r));
                progress.advance();
            }
            (Analysis::Reliability(results), evaluations)
        }
    };
    let outputs_info = outputs
        .iter()
        .enumerate()
        .map(|(o, &quantity)| {
            let mut failed = Failures::default();
            for s in &all_samples {
                match s[o] {
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
    Ok(UncertaintyDocument {
        name: problem.name.clone(),
        method: options.method,
        samples,
        samples_asked,
        seed,
        fingerprint: fingerprint(nominal, u, options.method, samples, seed),
        inputs: u.inputs.clone(),
        correlations: u.correlations.clone(),
        outputs: outputs_info,
        evaluations,
        analysis,
    })
}

/// The value of an input at the nominal scene (SI), for reports.
pub fn nominal_value(scene: &Scene, p: SceneParameter) -> f64 {
    p.get(scene)
}
