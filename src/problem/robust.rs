//! The robust side of a study (docs/uncertainty.md, "Designs that hold in most
//! parts"): a statistic objective (`[objective] statistic = "p95"`), chance
//! constraints (`[[constraint]] event = "stiction", probability_max = 1e-3`) and
//! what to do when sampling contradicts their FORM-based design
//! (`[uncertainty] verify`).

use std::ops::Range;

use serde::Serialize;
use toml::Spanned;

use super::raw::{RawConstraint, RawEvent, RawPareto, RawProblem, RawQuantity};
use super::{Accept, ProblemError, Reader, Study, Uncertainty};
use crate::model::{Quantity, Scene};
use crate::units::Dimension;
use crate::uq::robust::{Statistic, Verify};

pub use super::uncertainty::Event;

/// The common random numbers of a statistic objective when `[objective] samples`
/// is not given.
pub const DEFAULT_STATISTIC_SAMPLES: usize = 256;
/// The fewest common random numbers a statistic objective may use (a p99 needs
/// points beyond its quantile).
pub const MIN_STATISTIC_SAMPLES: i64 = 64;
/// The most (each design the SQP tries costs this many evaluations).
pub const MAX_STATISTIC_SAMPLES: i64 = 1 << 16;

/// `P(event) ≤ probability_max`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChanceConstraint {
    /// Its index among the file's `[[constraint]]` tables.
    pub index: usize,
    /// The event.
    pub event: Event,
    /// The largest probability allowed, in (0, 0.5).
    pub probability_max: f64,
}

/// The fewest points of a probability front.
pub const MIN_FRONT_POINTS: i64 = 2;
/// The most (each point is a robust optimum: seconds each).
pub const MAX_FRONT_POINTS: i64 = 40;
/// Points of a probability front when `[pareto] points` is not given: the
/// decades 1e-1, 1e-2, 1e-3, 1e-4 of the default levels.
pub const DEFAULT_FRONT_POINTS: usize = 4;
/// The loosest level when `[pareto] probability_max` is not given.
pub const DEFAULT_FRONT_PROBABILITY_MAX: f64 = 0.1;
/// The tightest level when `[pareto] probability_min` is not given.
pub const DEFAULT_FRONT_PROBABILITY_MIN: f64 = 1e-4;

/// `[pareto] event = …`: the front of the objective (or its statistic) against
/// P(event), one chance-constrained robust optimum per level of
/// probability_max (docs/robust-design.md, "A front against a probability").
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct EventFront {
    /// The event whose probability is the front's second axis.
    pub event: Event,
    /// The levels: `points` values of probability_max spaced evenly in log10
    /// from `probability_max` down to `probability_min`.
    pub points: usize,
    /// The loosest level, in (0, 0.5).
    pub probability_max: f64,
    /// The tightest level, in (0, probability_max).
    pub probability_min: f64,
    /// The file's chance constraint on the same event, which each level
    /// replaces (an index into [`Robust::chance`]); none: the level is added.
    pub replaces: Option<usize>,
}

impl EventFront {
    /// The levels of probability_max, loosest first: evenly spaced in log10
    /// between the ends (both included).
    pub fn levels(&self) -> Vec<f64> {
        let (a, b) = (self.probability_max.log10(), self.probability_min.log10());
        let n = self.points.max(2);
        (0..n)
            .map(|i| {
                if i == 0 {
                    self.probability_max
                } else if i + 1 == n {
                    self.probability_min
                } else {
                    10f64.powf(a + (b - a) * i as f64 / (n - 1) as f64)
                }
            })
            .collect()
    }
}

/// What makes a study robust; empty (the default) for a nominal study.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Robust {
    /// The statistic of the objective over the uncertain inputs, if asked.
    pub statistic: Option<Statistic>,
    /// The common random numbers the statistic is taken over.
    pub samples: usize,
    /// The chance constraints, in file order.
    pub chance: Vec<ChanceConstraint>,
    /// What to do when a sampled probability exceeds its target.
    pub verify: Verify,
    /// `[pareto] event = …`: a front against a probability, if asked.
    pub front: Option<EventFront>,
}

impl Default for Robust {
    fn default() -> Self {
        Robust {
            statistic: None,
            samples: DEFAULT_STATISTIC_SAMPLES,
            chance: Vec::new(),
            verify: Verify::Report,
            front: None,
        }
    }
}

impl Robust {
    /// Whether the study is robust (a statistic or a chance constraint).
    pub fn is_robust(&self) -> bool {
        self.statistic.is_some() || !self.chance.is_empty()
    }
}

/// The accepted values of `probability_max`.
fn probability_accept() -> Accept {
    Accept::interval(Dimension::Dimensionless, 0.0, true, 0.5, true)
        .why("a probability of failure below one half (e.g. 1e-3: one part in a thousand)")
}

impl Reader<'_> {
    /// Stage two of the robust keys, once `[uncertainty]` is read.
    pub(super) fn robust(
        &self,
        raw: &RawProblem,
        scene: &Scene,
        study: &Study,
        uncertainty: Option<&Uncertainty>,
        uncertainty_span: Option<Range<usize>>,
    ) -> Result<Robust, ProblemError> {
        let mut robust = Robust::default();
        let no_inputs = |key: &str, span: &Range<usize>, what: &str| {
            self.invalid(
                key,
                span,
                format!(
                    "{what} is taken over the uncertain inputs, and the file has none: add [uncertainty.inputs], e.g. sigma = {{ distribution = \"lognormal\", median = \"3 nm\", factor = 1.5 }}"
                ),
            )
        };
        if let Some(objective) = &raw.objective {
            let o = objective.get_ref();
            if let Some(s) = &o.statistic {
                let statistic = Statistic::parse(s.get_ref().trim()).ok_or_else(|| {
                    let names: Vec<&str> = Statistic::ALL.iter().map(|s| s.as_str()).collect();
                    self.invalid(
                        "objective.statistic",
                        &s.span(),
                        format!("unknown statistic (one of: {})", names.join(", ")),
                    )
                })?;
                if uncertainty.is_none() {
                    return Err(no_inputs("objective.statistic", &s.span(), "a statistic"));
                }
                robust.statistic = Some(statistic);
            }
            if let Some(n) = &o.samples {
                if o.statistic.is_none() {
                    return Err(self.invalid(
                        "objective.samples",
                        &n.span(),
                        "is the sample a statistic objective is taken over: give statistic = \"p95\" (or mean, p99, cvar95, mean_plus_3sd) beside it, or remove it",
                    ));
                }
                robust.samples = self.integer(
                    "objective.samples",
                    n,
                    MIN_STATISTIC_SAMPLES,
                    MAX_STATISTIC_SAMPLES,
                    "the common random numbers of the statistic",
                )? as usize;
            }
        }
        for (index, c) in raw.constraint.iter().enumerate() {
            let Some(event) = &c.get_ref().event else {
                continue;
            };
            let key = format!("constraint[{index}].event");
            let Some(u) = uncertainty else {
                return Err(no_inputs(&key, &event.span(), "a chance constraint"));
            };
            let event = self.chance_event(&key, event, scene, u)?;
            let probability_max = match &c.get_ref().probability_max {
                Some(p) => self.quantity(
                    &format!("constraint[{index}].probability_max"),
                    p,
                    probability_accept(),
                )?,
                None => {
                    return Err(self.missing(
                        &format!("constraint[{index}].probability_max"),
                        Some(&c.span()),
                        "a chance constraint bounds the probability of its event: add probability_max = 1e-3 (at most one part in a thousand)",
                    ))
                }
            };
            robust.chance.push(ChanceConstraint {
                index,
                event,
                probability_max,
            });
        }
        if let Some(u) = &raw.uncertainty {
            if let Some(v) = &u.get_ref().verify {
                robust.verify = match v.get_ref().trim() {
                    "report" => Verify::Report,
                    "correct" => Verify::Correct,
                    _ => {
                        return Err(self.invalid(
                            "uncertainty.verify",
                            &v.span(),
                            "one of: report (print the sampled probability and flag a violated target), correct (move the target by the sampled excess and solve again)",
                        ))
                    }
                };
            }
        }
        if let Some(pareto) = &raw.pareto {
            robust.front = self.event_front(pareto, scene, uncertainty, &robust)?;
        }
        let robust_or_front = robust.is_robust() || robust.front.is_some();
        if robust_or_front && !study.has_design() {
            let span = uncertainty_span.unwrap_or(0..0);
            return Err(self.invalid(
                "design",
                &span,
                "a statistic objective or a chance constraint needs something to vary: add a [design] table with at least one variable",
            ));
        }
        if robust_or_front && !study.materials.is_empty() {
            let span = raw.design.as_ref().map_or(0..0, |d| d.span());
            return Err(self.invalid(
                "design.materials",
                &span,
                "a ranking of catalogue materials is a nominal study: remove materials, or the statistic and chance constraints",
            ));
        }
        if robust_or_front
            && scene
                .environment
                .is_some_and(|e| e.humidity_range.is_some())
        {
            let span = raw.environment.as_ref().map_or(0..0, |e| e.span());
            return Err(self.invalid(
                "environment.relative_humidity",
                &span,
                "a robust study takes the humidity as an uncertain input, not a range: give one humidity and add [uncertainty.inputs] relative_humidity = { distribution = \"uniform\", min = 0.2, max = 0.8 }",
            ));
        }
        if robust.front.is_some() && study.objective.is_none() {
            let span = raw.pareto.as_ref().map_or(0..0, |p| p.span());
            return Err(self.missing(
                "objective.minimize",
                Some(&span),
                "a front against a probability minimises something at each level: add [objective] minimize = \"wear_rate\"",
            ));
        }
        if !robust.chance.is_empty() && study.objective.is_none() {
            let span = raw.constraint[robust.chance[0].index].span();
            return Err(self.missing(
                "objective.minimize",
                Some(&span),
                "a chance-constrained study minimises something: add [objective] minimize = \"wear_rate\"",
            ));
        }
        Ok(robust)
    }

    /// `[pareto] event = …` and its levels (None when the section has no event).
    fn event_front(
        &self,
        pareto: &Spanned<RawPareto>,
        scene: &Scene,
        uncertainty: Option<&Uncertainty>,
        robust: &Robust,
    ) -> Result<Option<EventFront>, ProblemError> {
        let p = pareto.get_ref();
        let Some(event) = &p.event else {
            return Ok(None);
        };
        let Some(u) = uncertainty else {
            return Err(self.invalid(
                "pareto.event",
                &event.span(),
                "a front against the probability of an event samples the uncertain inputs, and the file has none: add [uncertainty.inputs], e.g. sigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 1.5 }",
            ));
        };
        for (key, value) in [
            ("pareto.adhesion", p.adhesion.as_ref().map(|v| v.span())),
            ("pareto.direction", p.direction.as_ref().map(|v| v.span())),
        ] {
            if let Some(span) = value {
                return Err(self.invalid(
                    key,
                    &span,
                    "a front against P(event) has the probability as its second axis, the low end preferred: remove this key, or event",
                ));
            }
        }
        let event = self.chance_event("pareto.event", event, scene, u)?;
        let points = match &p.points {
            None => DEFAULT_FRONT_POINTS,
            Some(v) => self.integer(
                "pareto.points",
                v,
                MIN_FRONT_POINTS,
                MAX_FRONT_POINTS,
                "levels of probability on the front, each a robust optimum",
            )? as usize,
        };
        let level = |key: &str, v: &Option<Spanned<RawQuantity>>, default: f64| match v {
            Some(v) => self.quantity(key, v, probability_accept()),
            None => Ok(default),
        };
        let probability_max = level(
            "pareto.probability_max",
            &p.probability_max,
            DEFAULT_FRONT_PROBABILITY_MAX,
        )?;
        let probability_min = level(
            "pareto.probability_min",
            &p.probability_min,
            DEFAULT_FRONT_PROBABILITY_MIN,
        )?;
        if probability_min >= probability_max {
            let (key, span) = match (&p.probability_min, &p.probability_max) {
                (Some(v), _) => ("pareto.probability_min", v.span()),
                (None, Some(v)) => ("pareto.probability_max", v.span()),
                (None, None) => ("pareto.event", pareto.span()),
            };
            return Err(self.invalid(
                key,
                &span,
                format!(
                    "the levels run from probability_max = {probability_max:e} down to probability_min = {probability_min:e}: probability_min must be the smaller"
                ),
            ));
        }
        let replaces = robust
            .chance
            .iter()
            .position(|c| c.event.name() == event.name());
        Ok(Some(EventFront {
            event,
            points,
            probability_max,
            probability_min,
            replaces,
        }))
    }

    /// A chance constraint's event: a built-in or `[[uncertainty.event]]` name, or
    /// an inline `{ quantity = …, above = … }`.
    fn chance_event(
        &self,
        key: &str,
        value: &Spanned<toml::Value>,
        scene: &Scene,
        uncertainty: &Uncertainty,
    ) -> Result<Event, ProblemError> {
        let span = value.span();
        match value.get_ref() {
            toml::Value::String(name) => {
                let name = name.trim();
                if let Some(e) = uncertainty.events.iter().find(|e| e.name() == name) {
                    return Ok(e.clone());
                }
                if matches!(name, "stiction" | "wear_out") {
                    let raw = RawEvent {
                        name: Some(Spanned::new(span.clone(), name.to_string())),
                        quantity: None,
                        above: None,
                        below: None,
                    };
                    return self.event_at(key, &Spanned::new(span.clone(), raw), scene);
                }
                let mut names = vec!["stiction".to_string(), "wear_out".to_string()];
                names.extend(uncertainty.events.iter().map(|e| e.name().to_string()));
                Err(self.invalid(
                    key,
                    &span,
                    format!(
                        "unknown event `{name}` (one of: {}, or an inline {{ quantity = \"wear_rate\", above = \"50 um^3/m\" }})",
                        names.join(", ")
                    ),
                ))
            }
            toml::Value::Table(t) => {
                for k in t.keys() {
                    if !matches!(k.as_str(), "name" | "quantity" | "above" | "below") {
                        return Err(self.invalid(
                            &format!("{key}.{k}"),
                            &span,
                            "unknown key (an event takes quantity, above or below, and name)",
                        ));
                    }
                }
                let text = |k: &str| -> Result<Option<Spanned<String>>, ProblemError> {
                    match t.get(k) {
                        None => Ok(None),
                        Some(toml::Value::String(s)) => {
                            Ok(Some(Spanned::new(span.clone(), s.clone())))
                        }
                        Some(_) => Err(self.invalid(
                            &format!("{key}.{k}"),
                            &span,
                            "must be a string",
                        )),
                    }
                };
                let bound = |k: &str| -> Result<Option<Spanned<RawQuantity>>, ProblemError> {
                    match t.get(k) {
                        None => Ok(None),
                        Some(v) => RawQuantity::from_value(v)
                            .map(|q| Some(Spanned::new(span.clone(), q)))
                            .ok_or_else(|| {
                                self.invalid(
                                    &format!("{key}.{k}"),
                                    &span,
                                    "must be a number in SI units or a string with a unit such as \"50 um^3/m\"",
                                )
                            }),
                    }
                };
                let raw = RawEvent {
                    name: text("name")?,
                    quantity: text("quantity")?,
                    above: bound("above")?,
                    below: bound("below")?,
                };
                if raw.quantity.is_none() {
                    return Err(self.invalid(
                        key,
                        &span,
                        format!(
                            "an inline event names a quantity and its threshold, e.g. {{ quantity = \"wear_rate\", above = \"50 um^3/m\" }} (quantities: {})",
                            Quantity::ALL.iter().map(|q| q.as_str()).collect::<Vec<_>>().join(", ")
                        ),
                    ));
                }
                self.event_at(key, &Spanned::new(span.clone(), raw), scene)
            }
            _ => Err(self.invalid(
                key,
                &span,
                "an event: \"stiction\", \"wear_out\", the name of an [[uncertainty.event]], or { quantity = \"wear_rate\", above = \"50 um^3/m\" }",
            )),
        }
    }
}

/// Whether a `[[constraint]]` table is a chance constraint.
pub(super) fn is_chance(c: &RawConstraint) -> bool {
    c.event.is_some()
}
