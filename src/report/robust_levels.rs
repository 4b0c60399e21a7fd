//! The words and tables the two robust fronts of `wearopt pareto` share
//! (docs/robust-design.md, "Fronts"): against a probability (`robust_front`) and
//! against an adhesion measure (`robust_adhesion_front`). Each point of either is
//! a robust optimum with its statistic, its design and its objective at the
//! medians; the chance constraints held at every point are the same list.

use std::fmt::Write as _;

use serde_json::{json, Map, Value};

use super::robust::{estimate_json, estimate_words};
use super::sig_exp;
use crate::app::robust_front::HeldConstraint;
use crate::model::SceneParameter;
use crate::optimize::Objective;
use crate::units::format_quantity;
use crate::uq::robust::{RobustResult, Statistic};
use crate::uq::Estimate;

/// What each point minimises: `p95 of wear_rate`, or `wear_rate at the medians`
/// without a statistic.
pub(super) fn statistic_name(objective: Objective, statistic: Option<Statistic>) -> String {
    match statistic {
        Some(s) => format!("{} of {}", s.as_str(), objective.as_str()),
        None => format!("{} at the medians", objective.as_str()),
    }
}

/// The statistic's column header: with `[95 %]` where it has a sampling interval.
pub(super) fn statistic_header(objective: Objective, statistic: Option<Statistic>) -> String {
    match statistic {
        Some(_) => format!("{} [95 %]", statistic_name(objective, statistic)),
        None => statistic_name(objective, statistic),
    }
}

/// A point's statistic with its interval; the value alone without a statistic
/// (the objective at the medians has no sampling error).
pub(super) fn statistic_words(
    statistic: Option<Statistic>,
    value: &Estimate,
    unit: &str,
) -> String {
    match statistic {
        Some(_) => estimate_words(value, unit),
        None => super::si(value.value, unit, 4),
    }
}

/// The text report's lines naming the chance constraints held at every point.
pub(super) fn write_held(out: &mut String, held: &[HeldConstraint]) {
    for h in held {
        let _ = writeln!(
            out,
            "Held at every point: P({}) <= {}",
            h.label,
            sig_exp(h.target, 2)
        );
    }
}

/// The page's note naming the chance constraints held at every point (none
/// without them).
pub(super) fn html_held(p: &mut super::html::Page, held: &[HeldConstraint]) {
    if held.is_empty() {
        return;
    }
    let items: Vec<String> = held
        .iter()
        .map(|h| {
            format!(
                "held at every point: P({}) ≤ {}",
                h.label,
                sig_exp(h.target, 2)
            )
        })
        .collect();
    p.list(&items, "note");
}

/// ", p95 of wear_rate taken over 256 common random numbers" for the page's
/// opening paragraph; empty without a statistic.
pub(super) fn sampled_over(
    objective: Objective,
    statistic: Option<Statistic>,
    samples: usize,
) -> String {
    match statistic {
        Some(_) => format!(
            ", {} taken over {} common random numbers",
            statistic_name(objective, statistic),
            samples
        ),
        None => String::new(),
    }
}

/// The text report's "Designs:" table: each point's index, design variables
/// and objective at the medians. `points` yields (index, design, at the medians).
pub(super) fn write_designs<'a>(
    out: &mut String,
    objective: Objective,
    names: &[SceneParameter],
    points: impl Iterator<Item = (usize, &'a [f64], f64)>,
) {
    let unit = super::objective_unit(objective);
    let _ = writeln!(out);
    let _ = writeln!(out, "Designs:");
    let mut header = String::from("  #");
    for n in names {
        let _ = write!(header, "  {:>16}", n.as_str());
    }
    let _ = writeln!(out, "{header}  {:>16}", "at the medians");
    for (index, design, at_medians) in points {
        let mut row = format!("{index:>3}");
        for (n, v) in names.iter().zip(design) {
            let _ = write!(
                row,
                "  {:>16}",
                format_quantity(*v, super::design_dimension(*n))
            );
        }
        let _ = writeln!(out, "{row}  {:>16}", super::si(at_medians, unit, 4));
    }
}

/// The page's "Designs" table: each point's index, design variables and
/// objective at the medians. `points` yields (index, design, at the medians).
pub(super) fn html_designs<'a>(
    p: &mut super::html::Page,
    objective: Objective,
    names: &[SceneParameter],
    points: impl Iterator<Item = (usize, &'a [f64], f64)>,
) {
    let mut header: Vec<&str> = vec!["#"];
    header.extend(names.iter().map(|n| n.as_str()));
    let medians = format!("{} at the medians", objective.as_str());
    header.push(&medians);
    let unit = super::objective_unit(objective);
    let rows: Vec<Vec<String>> = points
        .map(|(index, design, at_medians)| {
            let mut r = vec![index.to_string()];
            r.extend(
                names
                    .iter()
                    .zip(design)
                    .map(|(n, v)| format_quantity(*v, super::design_dimension(*n))),
            );
            r.push(super::si(at_medians, unit, 4));
            r
        })
        .collect();
    p.heading("Designs");
    p.table(&header, &rows, &[]);
}

/// A design as JSON: each variable's name to its SI value.
pub(super) fn design_json(names: &[SceneParameter], design: &[f64]) -> Map<String, Value> {
    names
        .iter()
        .zip(design)
        .map(|(n, v)| (n.as_str().to_string(), json!(v)))
        .collect()
}

/// The keys every robust front's point carries: its design, its statistic with
/// the interval and the verification's, its objective at the medians, and the
/// robust solve's status and cost. The caller adds its level and its events.
pub(super) fn point_json(
    names: &[SceneParameter],
    design: &[f64],
    statistic: &Estimate,
    at_medians: f64,
    result: &RobustResult,
) -> Map<String, Value> {
    let stat = estimate_json(statistic);
    let mut m = Map::new();
    m.insert("design".into(), Value::Object(design_json(names, design)));
    m.insert("statistic".into(), json!(stat.get("value")));
    m.insert("statistic_interval".into(), json!(stat.get("interval")));
    m.insert(
        "statistic_verified".into(),
        json!(result.objective_verified.as_ref().map(estimate_json)),
    );
    m.insert(
        "at_medians".into(),
        json!(at_medians.is_finite().then_some(at_medians)),
    );
    m.insert("status".into(), json!(result.status));
    m.insert("cycles".into(), json!(result.cycles));
    m.insert("corrections".into(), json!(result.corrections));
    m.insert("evaluations".into(), json!(result.evaluations));
    m
}

/// `common`'s keys with `extra`'s (an object) added: a point's JSON from
/// [`point_json`] and what its front adds.
pub(super) fn merged(mut common: Map<String, Value>, extra: Value) -> Value {
    if let Value::Object(extra) = extra {
        common.extend(extra);
    }
    Value::Object(common)
}
