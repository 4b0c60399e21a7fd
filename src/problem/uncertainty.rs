//! `[uncertainty]`: the inputs a designer does not know exactly (their
//! distributions and correlations), the outputs to study and the events whose
//! probability is wanted (docs/uncertainty.md).

use std::collections::BTreeMap;
use std::ops::Range;

use toml::Spanned;

use super::raw::{RawEvent, RawInput, RawUncertainty};
use super::{Accept, ProblemError, Reader};
use crate::model::{Quantity, Role, Scene, SceneParameter};
use crate::units::{parse_quantity, Dimension};
use crate::uq::distribution::Distribution;
use crate::uq::model::{InputModel, ModelError};

/// The fewest samples a study may ask for.
pub const MIN_SAMPLES: i64 = 64;
/// The most samples a study may ask for (2^24: a Sobol′ study of five inputs is
/// then 1.2e8 evaluations).
pub const MAX_SAMPLES: i64 = 1 << 24;
/// The samples when `samples` is not given.
pub const DEFAULT_SAMPLES: u64 = 4096;
/// Above this probability of a non-positive value a normal law is refused on a
/// quantity that must be positive.
pub const NORMAL_NEGATIVE_TAIL: f64 = 1e-9;

/// One uncertain input: a scene parameter and its law (SI units).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct UncertainInput {
    /// The scene parameter the law replaces.
    pub parameter: SceneParameter,
    /// Its distribution (SI).
    pub distribution: Distribution,
}

/// An event whose probability is wanted.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Event {
    /// The pull-off force reaches the restoring force (`contact.restoring_force`):
    /// the part sticks.
    Stiction,
    /// The wear depth over the sliding distance exceeds `contact.allowed_wear_depth`.
    WearOut,
    /// A quantity beyond a threshold (SI).
    Threshold {
        /// The event's name (as written, or `QUANTITY_above` / `QUANTITY_below`).
        name: String,
        /// The quantity.
        quantity: Quantity,
        /// Failure is `quantity > limit` (true) or `quantity < limit` (false).
        above: bool,
        /// The threshold (SI).
        limit: f64,
    },
}

impl Event {
    /// The event's name in reports.
    pub fn name(&self) -> &str {
        match self {
            Event::Stiction => "stiction",
            Event::WearOut => "wear_out",
            Event::Threshold { name, .. } => name,
        }
    }
}

/// The validated `[uncertainty]` section.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Uncertainty {
    /// N (before a Sobol′ study rounds it up to a power of two).
    pub samples: u64,
    /// The seed of the scrambled sequences and of importance sampling.
    pub seed: u64,
    /// The outputs studied, in the order given.
    pub outputs: Vec<Quantity>,
    /// The uncertain inputs, in the parameter table's order.
    pub inputs: Vec<UncertainInput>,
    /// Gaussian-copula correlations `(i, j, ρ)` between inputs `i < j`.
    pub correlations: Vec<(usize, usize, f64)>,
    /// The events, in the order given.
    pub events: Vec<Event>,
}

impl Uncertainty {
    /// The joint law of the inputs (validated when the file was read).
    pub fn input_model(&self) -> InputModel {
        InputModel::new(
            self.inputs.iter().map(|i| i.distribution).collect(),
            &self.correlations,
        )
        .expect("validated when the problem file was read")
    }
}

/// The outputs studied when `outputs` is not given.
fn default_outputs(scene: &Scene) -> Vec<Quantity> {
    let mut q = vec![Quantity::WearRate, Quantity::PullOffForce];
    if scene.requirements.allowed_wear_depth.is_some() {
        q.push(if scene.requirements.sliding_per_cycle.is_some() {
            Quantity::LifeCycles
        } else {
            Quantity::LifeSlidingDistance
        });
    }
    q
}

impl Reader<'_> {
    /// Stage two of `[uncertainty]`.
    pub(super) fn uncertainty(
        &mut self,
        raw: &Spanned<RawUncertainty>,
        scene: &Scene,
    ) -> Result<Uncertainty, ProblemError> {
        let span = raw.span();
        let u = raw.get_ref();
        let samples = match &u.samples {
            Some(s) => self.integer(
                "uncertainty.samples",
                s,
                MIN_SAMPLES,
                MAX_SAMPLES,
                "N, the samples of the study",
            )? as u64,
            None => DEFAULT_SAMPLES,
        };
        let seed = match &u.seed {
            Some(s) => self.integer("uncertainty.seed", s, 0, i64::MAX, "a seed")? as u64,
            None => 1,
        };
        let outputs = match &u.outputs {
            None => default_outputs(scene),
            Some(list) => {
                if list.get_ref().is_empty() {
                    return Err(self.invalid(
                        "uncertainty.outputs",
                        &list.span(),
                        "must name at least one output (e.g. [\"wear_rate\", \"pull_off_force\"])",
                    ));
                }
                let mut out = Vec::new();
                for name in list.get_ref() {
                    let q = self.output(name)?;
                    if !out.contains(&q) {
                        out.push(q);
                    }
                }
                out
            }
        };
        let inputs_table = self.required(
            &u.inputs,
            "uncertainty.inputs",
            Some(&span),
            "the uncertain inputs, e.g. [uncertainty.inputs] sigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 1.5 }",
        )?;
        let mut inputs: Vec<(UncertainInput, Range<usize>)> = Vec::new();
        for (key, value) in inputs_table.get_ref() {
            let field = format!("uncertainty.inputs.{key}");
            let parameter = SceneParameter::from_key(key).ok_or_else(|| {
                let names: Vec<&str> = SceneParameter::ALL.iter().map(|p| p.as_str()).collect();
                let hint = super::suggest(key, names.iter().copied())
                    .map(|s| format!("; did you mean `{s}`?"))
                    .unwrap_or_default();
                self.invalid(
                    &field,
                    &value.span(),
                    format!(
                        "unknown scene parameter `{key}`{hint} (one of: {})",
                        names.join(", ")
                    ),
                )
            })?;
            if parameter.is_environmental() && scene.environment.is_none() {
                return Err(self.invalid(
                    &field,
                    &value.span(),
                    format!(
                        "{key} is a property of the humid air, and the problem has no [environment] table: add one (docs/model.md §10)"
                    ),
                ));
            }
            if parameter.is_wear_law_input() && scene.activation.is_none() {
                return Err(self.invalid(
                    &field,
                    &value.span(),
                    format!(
                        "{key} is an input of the stress-assisted wear law, and the problem's law is Archard's: add [wear] law = \"stress_assisted\" (docs/model.md §12)"
                    ),
                ));
            }
            let distribution = self.distribution(&field, value, parameter)?;
            inputs.push((
                UncertainInput {
                    parameter,
                    distribution,
                },
                value.span(),
            ));
        }
        if inputs.is_empty() {
            return Err(self.invalid(
                "uncertainty.inputs",
                &inputs_table.span(),
                "must list at least one uncertain input",
            ));
        }
        let order = |p: SceneParameter| SceneParameter::ALL.iter().position(|&q| q == p);
        inputs.sort_by_key(|(i, _)| order(i.parameter));
        for pair in inputs.windows(2) {
            if shares_value(pair[0].0.parameter, pair[1].0.parameter) {
                return Err(self.invalid(
                    &format!("uncertainty.inputs.{}", pair[1].0.parameter.as_str()),
                    &pair[1].1,
                    format!(
                        "moves the same value as uncertainty.inputs.{}: give one of the two",
                        pair[0].0.parameter.as_str()
                    ),
                ));
            }
        }
        let mut correlations = Vec::new();
        for c in &u.correlation {
            let cspan = c.span();
            let between = self.required(
                &c.get_ref().between,
                "uncertainty.correlation.between",
                Some(&cspan),
                "the two inputs, e.g. between = [\"sigma\", \"asperity_radius\"]",
            )?;
            let rho = self.required(
                &c.get_ref().rho,
                "uncertainty.correlation.rho",
                Some(&cspan),
                "the correlation of the two inputs' normal scores, e.g. rho = -0.5",
            )?;
            let names = between.get_ref();
            if names.len() != 2 {
                return Err(self.invalid(
                    "uncertainty.correlation.between",
                    &between.span(),
                    "must name exactly two inputs of [uncertainty.inputs]",
                ));
            }
            let mut index = [0usize; 2];
            for (k, name) in names.iter().enumerate() {
                index[k] = inputs
                    .iter()
                    .position(|(i, _)| i.parameter.as_str() == name.get_ref())
                    .ok_or_else(|| {
                        let listed: Vec<&str> =
                            inputs.iter().map(|(i, _)| i.parameter.as_str()).collect();
                        self.invalid(
                            "uncertainty.correlation.between",
                            &name.span(),
                            format!(
                                "`{}` is not an uncertain input (listed: {})",
                                name.get_ref(),
                                listed.join(", ")
                            ),
                        )
                    })?;
            }
            let r = *rho.get_ref();
            if index[0] == index[1] {
                return Err(self.invalid(
                    "uncertainty.correlation.between",
                    &between.span(),
                    "names one input twice: a correlation is between two inputs",
                ));
            }
            if !(r.is_finite() && r.abs() < 1.0) {
                return Err(self.invalid(
                    "uncertainty.correlation.rho",
                    &rho.span(),
                    "must lie in (-1, 1) (|ρ| = 1 makes two inputs one)",
                ));
            }
            let (i, j) = (index[0].min(index[1]), index[0].max(index[1]));
            if correlations.iter().any(|&(a, b, _)| (a, b) == (i, j)) {
                return Err(self.invalid(
                    "uncertainty.correlation.between",
                    &between.span(),
                    "this pair is correlated twice",
                ));
            }
            correlations.push((i, j, r));
        }
        let marginals: Vec<Distribution> = inputs.iter().map(|(i, _)| i.distribution).collect();
        if let Err(e) = InputModel::new(marginals, &correlations) {
            let reason = match e {
                ModelError::NotPositiveDefinite { pair } => format!(
                    "the correlations contradict each other (their matrix is not positive definite){}; weaken one",
                    pair.map(|(i, j)| format!(
                        ": the contradiction appears with {} and {}",
                        inputs[i].0.parameter.as_str(),
                        inputs[j].0.parameter.as_str()
                    ))
                    .unwrap_or_default()
                ),
                other => other.to_string(),
            };
            let at = u
                .correlation
                .first()
                .map(|c| c.span())
                .unwrap_or(span.clone());
            return Err(self.invalid("uncertainty.correlation", &at, reason));
        }
        let mut events = Vec::new();
        for e in &u.event {
            let event = self.event(e, scene)?;
            if events.iter().any(|x: &Event| x.name() == event.name()) {
                return Err(self.invalid(
                    "uncertainty.event.name",
                    &e.span(),
                    format!("the event `{}` is listed twice", event.name()),
                ));
            }
            events.push(event);
        }
        Ok(Uncertainty {
            samples,
            seed,
            outputs,
            inputs: inputs.into_iter().map(|(i, _)| i).collect(),
            correlations,
            events,
        })
    }

    /// An output name of `outputs` or of an event's `quantity`.
    fn output(&self, name: &Spanned<String>) -> Result<Quantity, ProblemError> {
        Quantity::from_key(name.get_ref())
            .filter(|q| q.has_role(Role::QuantityOfInterest))
            .ok_or_else(|| {
                let names: Vec<&str> = Quantity::with_role(Role::QuantityOfInterest)
                    .into_iter()
                    .map(|q| q.as_str())
                    .collect();
                let hint = super::suggest(name.get_ref(), names.iter().copied())
                    .map(|s| format!("; did you mean \"{s}\"?"))
                    .unwrap_or_default();
                self.invalid(
                    "uncertainty.outputs",
                    &name.span(),
                    format!("unknown output{hint} (one of: {})", names.join(", ")),
                )
            })
    }

    /// One input's law, in SI units.
    fn distribution(
        &self,
        field: &str,
        value: &Spanned<RawInput>,
        parameter: SceneParameter,
    ) -> Result<Distribution, ProblemError> {
        let raw = value.get_ref();
        let span = value.span();
        let kind = self.required(
            &raw.distribution,
            &format!("{field}.distribution"),
            Some(&span),
            "the law: \"normal\", \"lognormal\", \"uniform\", \"beta\" or \"triangular\"",
        )?;
        let dim = parameter.dimension();
        // The parameters each law takes, and which of them carry the input's unit.
        let (takes, hint): (&[(&str, bool)], &str) = match kind.get_ref().as_str() {
            "normal" => (&[("mean", true), ("sd", true)], "mean and sd"),
            "lognormal" => (
                &[("median", true), ("factor", false)],
                "median and factor (e^s, > 1)",
            ),
            "uniform" => (&[("min", true), ("max", true)], "min and max"),
            "beta" => (
                &[
                    ("alpha", false),
                    ("beta", false),
                    ("min", true),
                    ("max", true),
                ],
                "alpha, beta, min and max",
            ),
            "triangular" => (
                &[("min", true), ("mode", true), ("max", true)],
                "min, mode and max",
            ),
            other => {
                let names = ["normal", "lognormal", "uniform", "beta", "triangular"];
                let hint = super::suggest(other, names)
                    .map(|s| format!("; did you mean \"{s}\"?"))
                    .unwrap_or_default();
                return Err(self.invalid(
                    &format!("{field}.distribution"),
                    &kind.span(),
                    format!("unknown distribution{hint} (one of: {})", names.join(", ")),
                ));
            }
        };
        let slots = [
            ("median", &raw.median),
            ("factor", &raw.factor),
            ("mean", &raw.mean),
            ("sd", &raw.sd),
            ("min", &raw.min),
            ("max", &raw.max),
            ("mode", &raw.mode),
            ("alpha", &raw.alpha),
            ("beta", &raw.beta),
        ];
        let mut got = BTreeMap::new();
        for (name, slot) in slots {
            let Some(v) = slot else { continue };
            let Some(&(_, dimensional)) = takes.iter().find(|(n, _)| *n == name) else {
                return Err(self.invalid(
                    &format!("{field}.{name}"),
                    &v.span(),
                    format!("a {} law takes {hint}, not {name}", kind.get_ref()),
                ));
            };
            let d = if dimensional {
                dim
            } else {
                Dimension::Dimensionless
            };
            let x = parse_quantity(v.get_ref().as_input(), d)
                .map_err(|e| self.invalid(&format!("{field}.{name}"), &v.span(), e.to_string()))?;
            got.insert(name, (x, v.span()));
        }
        for (name, _) in takes {
            if !got.contains_key(name) {
                return Err(self.missing(
                    &format!("{field}.{name}"),
                    Some(&span),
                    &format!("a {} law takes {hint}", kind.get_ref()),
                ));
            }
        }
        let x = |n: &str| got[n].0;
        let distribution = match kind.get_ref().as_str() {
            "normal" => Distribution::Normal {
                mean: x("mean"),
                sd: x("sd"),
            },
            "lognormal" => Distribution::Lognormal {
                median: x("median"),
                factor: x("factor"),
            },
            "uniform" => Distribution::Uniform {
                min: x("min"),
                max: x("max"),
            },
            "beta" => Distribution::Beta {
                alpha: x("alpha"),
                beta: x("beta"),
                min: x("min"),
                max: x("max"),
            },
            _ => Distribution::Triangular {
                min: x("min"),
                mode: x("mode"),
                max: x("max"),
            },
        };
        if let Err(e) = distribution.validate() {
            let at = got
                .get(e.parameter)
                .map(|(_, s)| s.clone())
                .unwrap_or(span.clone());
            return Err(self.invalid(
                &format!("{field}.{}", e.parameter),
                &at,
                format!("must be {} for a {} law", e.accepted, e.distribution),
            ));
        }
        // The law's support must lie where the parameter has a meaning.
        let (lo, hi) = valid_range(parameter);
        let p_low = distribution.cdf(lo);
        let too_low = if lo == 0.0 {
            distribution.probability_nonpositive()
        } else {
            p_low
        };
        if too_low > NORMAL_NEGATIVE_TAIL {
            let suggestion = if matches!(distribution, Distribution::Normal { .. }) && lo == 0.0 {
                "; a positive quantity takes a lognormal law (median and factor)"
            } else {
                ""
            };
            return Err(self.invalid(
                &format!("{field}.distribution"),
                &kind.span(),
                format!(
                    "gives {} ≤ {lo} with probability {too_low:.3e} (at most {NORMAL_NEGATIVE_TAIL:e} accepted){suggestion}",
                    parameter.as_str()
                ),
            ));
        }
        let too_high = if hi.is_finite() {
            distribution.sf(hi)
        } else {
            0.0
        };
        if too_high > NORMAL_NEGATIVE_TAIL {
            return Err(self.invalid(
                &format!("{field}.distribution"),
                &kind.span(),
                format!(
                    "gives {} ≥ {hi} with probability {too_high:.3e} (at most {NORMAL_NEGATIVE_TAIL:e} accepted; {} must lie below {hi})",
                    parameter.as_str(),
                    parameter.as_str()
                ),
            ));
        }
        Ok(distribution)
    }

    /// One `[[uncertainty.event]]`.
    fn event(&self, e: &Spanned<RawEvent>, scene: &Scene) -> Result<Event, ProblemError> {
        self.event_at("uncertainty.event", e, scene)
    }

    /// An event as written at `key` (`uncertainty.event`, or a chance
    /// constraint's `constraint[i].event`).
    pub(super) fn event_at(
        &self,
        key: &str,
        e: &Spanned<RawEvent>,
        scene: &Scene,
    ) -> Result<Event, ProblemError> {
        let span = e.span();
        let raw = e.get_ref();
        if let Some(q) = &raw.quantity {
            let quantity = Quantity::from_key(q.get_ref()).ok_or_else(|| {
                let names: Vec<&str> = Quantity::ALL.iter().map(|q| q.as_str()).collect();
                self.invalid(
                    &format!("{key}.quantity"),
                    &q.span(),
                    format!("unknown quantity (one of: {})", names.join(", ")),
                )
            })?;
            let (bound, above) = match (&raw.above, &raw.below) {
                (Some(a), None) => (a, true),
                (None, Some(b)) => (b, false),
                _ => {
                    return Err(self.invalid(
                        key,
                        &span,
                        "an event on a quantity takes one threshold: above = … (failure above it) or below = …",
                    ))
                }
            };
            let key = if above {
                &format!("{key}.above")
            } else {
                &format!("{key}.below")
            };
            let limit = self.quantity(key, bound, Accept::any(quantity.dimension()))?;
            let name = match &raw.name {
                Some(n) if !n.get_ref().trim().is_empty() => n.get_ref().trim().to_string(),
                _ => format!(
                    "{}_{}",
                    quantity.as_str(),
                    if above { "above" } else { "below" }
                ),
            };
            if matches!(name.as_str(), "stiction" | "wear_out") {
                return Err(self.invalid(
                    &format!("{key}.name"),
                    &span,
                    format!("`{name}` is a built-in event: name this one otherwise"),
                ));
            }
            return Ok(Event::Threshold {
                name,
                quantity,
                above,
                limit,
            });
        }
        if raw.above.is_some() || raw.below.is_some() {
            return Err(self.invalid(
                key,
                &span,
                "a threshold (above, below) needs quantity = … (e.g. quantity = \"wear_rate\", above = \"50 um^3/m\")",
            ));
        }
        let name = self.required(
            &raw.name,
            &format!("{key}.name"),
            Some(&span),
            "\"stiction\", \"wear_out\", or quantity = … with above = … or below = …",
        )?;
        match name.get_ref().as_str() {
            "stiction" => {
                if scene.requirements.restoring_force.is_none() {
                    return Err(self.invalid(
                        &format!("{key}.name"),
                        &name.span(),
                        "stiction is the pull-off force reaching the restoring force: give contact.restoring_force",
                    ));
                }
                Ok(Event::Stiction)
            }
            "wear_out" => {
                if scene.requirements.allowed_wear_depth.is_none() {
                    return Err(self.invalid(
                        &format!("{key}.name"),
                        &name.span(),
                        "wear_out is the wear depth over the sliding distance beyond the allowed one: give contact.allowed_wear_depth",
                    ));
                }
                Ok(Event::WearOut)
            }
            other => {
                let hint = super::suggest(other, ["stiction", "wear_out"])
                    .map(|s| format!("; did you mean \"{s}\"?"))
                    .unwrap_or_default();
                Err(self.invalid(
                    &format!("{key}.name"),
                    &name.span(),
                    format!("unknown event{hint} (stiction, wear_out, or quantity = … with above = … or below = …)"),
                ))
            }
        }
    }
}

/// Two parameters that move the same value of a scene (a shared modulus and body
/// a's, a contact angle on both bodies and on one).
fn shares_value(a: SceneParameter, b: SceneParameter) -> bool {
    use SceneParameter as P;
    let group = |p| match p {
        P::YoungsModulus | P::YoungsModulusA => 1,
        P::ContactAngle | P::ContactAngleA | P::ContactAngleB => 2,
        _ => 0,
    };
    group(a) != 0 && group(a) == group(b)
}

/// Where a parameter's values have a meaning: `(lo, hi)`, values must lie above lo
/// (strictly, for lo = 0 on a positive quantity) and below hi.
fn valid_range(p: SceneParameter) -> (f64, f64) {
    use SceneParameter as P;
    match p {
        P::PoissonRatio => (-1.0, 0.5),
        P::RelativeHumidity => (0.0, 1.0),
        P::ContactAngle | P::ContactAngleA | P::ContactAngleB => (0.0, std::f64::consts::PI),
        P::WearCoefficient => (0.0, 1.0),
        _ => (0.0, f64::INFINITY),
    }
}
