//! The report of a front against a probability (`wearopt pareto` with
//! `[pareto] event = …`; docs/robust-design.md, "A front against a
//! probability"): text, JSON, CSV and HTML with the front plotted on a log axis
//! of the probability. Every point carries its statistic with its interval, its
//! sampled probability with its interval and its status; a point whose sampled
//! probability exceeds its level beyond the interval is marked, not hidden.

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::robust::{method_word, probability_words};
use super::robust_levels as levels;
use super::svg::{Axis, LinePlot, Marker, Series};
use super::{number, sig_exp};
use crate::app::robust_front::{EventFrontDocument, LevelPoint};

/// What the first axis reads as: "p95 of wear_rate".
fn statistic_name(doc: &EventFrontDocument) -> String {
    levels::statistic_name(doc.objective, doc.statistic)
}

fn unit(doc: &EventFrontDocument) -> &'static str {
    super::objective_unit(doc.objective)
}

fn status_sentence(doc: &EventFrontDocument) -> String {
    use crate::optimize::pareto::FrontStatus;
    match doc.status {
        FrontStatus::Ok => format!(
            "ok: {} of {} levels give a robust optimum; lower P({}) costs {}",
            doc.points.iter().filter(|p| p.usable()).count(),
            doc.points.len(),
            doc.label,
            statistic_name(doc)
        ),
        FrontStatus::NoTradeOff => format!(
            "no_trade_off: every level gives the same {}: P({}) does not bind over these levels",
            statistic_name(doc),
            doc.label
        ),
        FrontStatus::Infeasible => {
            "infeasible: no level gives a robust optimum (each point's status below)".to_string()
        }
    }
}

/// The statistic with its interval; the value alone without a statistic
/// (the objective at the medians has no sampling error).
fn statistic_words(doc: &EventFrontDocument, p: &LevelPoint) -> String {
    levels::statistic_words(doc.statistic, &p.statistic, unit(doc))
}

fn mark(p: &LevelPoint) -> &'static str {
    if p.violated {
        "VIOLATED"
    } else if !p.usable() {
        "—"
    } else if p.on_front {
        "front"
    } else {
        "dominated"
    }
}

/// The plain-text report.
pub fn text(doc: &EventFrontDocument) -> String {
    let mut out = String::new();
    let u = unit(doc);
    let _ = writeln!(out, "{}", doc.name);
    let _ = writeln!(
        out,
        "Front of {} against P({}): one robust optimum per level of probability_max ({} levels, {} down to {}{})",
        statistic_name(doc),
        doc.label,
        doc.levels.len(),
        sig_exp(doc.levels[0], 2),
        sig_exp(*doc.levels.last().unwrap_or(&f64::NAN), 2),
        if doc.statistic.is_some() {
            format!("; the statistic over {} common random numbers", doc.samples)
        } else {
            String::new()
        }
    );
    let _ = writeln!(out, "Status: {}", status_sentence(doc));
    levels::write_held(&mut out, &doc.held);
    let _ = writeln!(
        out,
        "Nominal optimum (every input at its median, each event held off there): {} = {}, P({}) = {} by {}",
        doc.objective.as_str(),
        super::si(doc.nominal_objective, u, 4),
        doc.label,
        probability_words(&doc.nominal_probability),
        method_word(&doc.nominal_probability)
    );
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "  #  level      {:<34}  {:<46}  {:<26}  front",
        levels::statistic_header(doc.objective, doc.statistic),
        format!("P({}) sampled [95 %]", doc.label),
        "status"
    );
    for p in &doc.points {
        let _ = writeln!(
            out,
            "{:>3}  {:<9}  {:<34}  {:<46}  {:<26}  {}",
            p.index,
            sig_exp(p.level, 2),
            statistic_words(doc, p),
            format!(
                "{} ({})",
                probability_words(&p.probability),
                method_word(&p.probability)
            ),
            p.status().as_str(),
            mark(p)
        );
    }
    levels::write_designs(
        &mut out,
        doc.objective,
        &doc.names,
        doc.points
            .iter()
            .map(|q| (q.index, &q.design[..], q.at_medians)),
    );
    // Why a level has no usable optimum: each chance constraint sampling finds
    // above its target at the level's design.
    for p in &doc.points {
        let why = violation_words(doc, p);
        if !why.is_empty() {
            let _ = writeln!(
                out,
                "\n#{} {}: at its design {}",
                p.index,
                p.status().as_str(),
                why
            );
        }
    }
    if doc.points.iter().any(|p| p.violated) {
        let _ = writeln!(
            out,
            "\nVIOLATED: sampling at the design finds P({}) above its level beyond its 95 % interval (FORM is unconservative there); [uncertainty] verify = \"correct\" moves the target by the sampled excess and solves again.",
            doc.label
        );
    }
    let _ = writeln!(out, "\nTime: {:.1} s", doc.time_seconds);
    out
}

/// The chance constraints sampling finds above their targets at `p`'s design,
/// e.g. `P(plasticity_index > 1) = 0.0116 [0.0112, 0.0120] > 0.0010`; empty
/// where none is.
fn violation_words(doc: &EventFrontDocument, p: &LevelPoint) -> String {
    doc.violations(p)
        .iter()
        .map(|(label, c)| {
            format!(
                "P({label}) = {} > {}",
                probability_words(&c.verification),
                sig_exp(c.target, 2)
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

fn point_json(doc: &EventFrontDocument, p: &LevelPoint) -> Value {
    let r = &p.result;
    let labels = doc.chance_labels();
    let chance: Vec<Value> = r
        .chance
        .iter()
        .enumerate()
        .map(|(j, c)| {
            json!({
                "label": labels.get(j).copied().unwrap_or(""),
                "target": c.target,
                "probability": c.verification.probability,
                "probability_interval": c.verification.interval,
                "violated": c.violated,
            })
        })
        .collect();
    levels::merged(
        levels::point_json(&doc.names, &p.design, &p.statistic, p.at_medians, r),
        json!({
            "index": p.index,
            "level": p.level,
            "probability": p.probability.probability,
            "probability_interval": p.probability.interval,
            "probability_upper_bound": p.probability.upper_bound,
            "method": p.probability.sampling.as_ref().map(|s| s.method),
            "form_beta": p.probability.form.beta,
            "violated": p.violated,
            "on_front": p.on_front,
            "chance_constraints": chance,
            "time_seconds": p.time_seconds,
        }),
    )
}

/// The JSON document (keys in docs/robust-design.md, "A front against a
/// probability").
pub fn json_value(doc: &EventFrontDocument) -> Value {
    let design = levels::design_json(&doc.names, &doc.nominal_design);
    json!({
        "name": doc.name,
        "status": doc.status.as_str(),
        "front_measure": "probability",
        "event": doc.event,
        "event_label": doc.label,
        "objective": doc.objective.as_str(),
        "statistic": doc.statistic,
        "samples": doc.samples,
        "design_variables": doc.names.iter().map(|n| n.as_str()).collect::<Vec<_>>(),
        "uncertain_inputs": doc.inputs.iter().map(|n| n.as_str()).collect::<Vec<_>>(),
        "held_chance_constraints": doc.held.iter().map(|h| json!({"event": h.event, "target": h.target})).collect::<Vec<_>>(),
        "levels": doc.levels,
        "points": doc.points.iter().map(|p| point_json(doc, p)).collect::<Vec<_>>(),
        "nominal_optimum": {
            "design": design,
            "objective": doc.nominal_objective,
            "probability": doc.nominal_probability.probability,
            "probability_interval": doc.nominal_probability.interval,
            "probability_upper_bound": doc.nominal_probability.upper_bound,
        },
        "time_seconds": doc.time_seconds,
    })
}

/// The JSON text (pretty, ending in a newline).
pub fn json(doc: &EventFrontDocument) -> String {
    let mut s = serde_json::to_string_pretty(&json_value(doc)).unwrap_or_default();
    s.push('\n');
    s
}

/// The CSV header.
pub fn csv_header(doc: &EventFrontDocument) -> String {
    let mut out = String::from("index,level");
    for n in &doc.names {
        out.push(',');
        out.push_str(n.as_str());
    }
    out.push_str(",statistic,statistic_low,statistic_high,at_medians,probability,probability_low,probability_high,status,on_front\n");
    out
}

/// One CSV row.
pub fn csv_row(doc: &EventFrontDocument, p: &LevelPoint) -> String {
    let cell = |v: Option<f64>| v.filter(|x| x.is_finite()).map(number).unwrap_or_default();
    let mut out = format!("{},{}", p.index, number(p.level));
    for v in &p.design {
        out.push(',');
        out.push_str(&number(*v));
    }
    let i = p.probability.interval;
    let _ = writeln!(
        out,
        ",{},{},{},{},{},{},{},{},{}",
        cell(Some(p.statistic.value)),
        cell(Some(p.statistic.interval[0])),
        cell(Some(p.statistic.interval[1])),
        cell(Some(p.at_medians)),
        cell(p.probability.probability),
        cell(i.map(|i| i[0])),
        cell(i.map(|i| i[1]).or(p.probability.upper_bound)),
        p.status().as_str(),
        p.on_front
    );
    let _ = doc;
    out
}

/// The CSV: a header and one row per level.
pub fn csv(doc: &EventFrontDocument) -> String {
    let mut out = csv_header(doc);
    for p in &doc.points {
        out.push_str(&csv_row(doc, p));
    }
    out
}

/// The front as SVG: the statistic against P(event) on a log axis, usable
/// points joined, violated points and the nominal optimum marked apart.
pub fn svg(doc: &EventFrontDocument) -> String {
    let pt = |p: &LevelPoint| {
        p.probability
            .probability
            .filter(|q| *q > 0.0)
            .map(|q| (q, p.statistic.value))
    };
    let front: Vec<(f64, f64)> = doc
        .points
        .iter()
        .filter(|p| p.usable() && !p.violated)
        .filter_map(pt)
        .collect();
    let violated: Vec<(f64, f64)> = doc
        .points
        .iter()
        .filter(|p| p.violated)
        .filter_map(pt)
        .collect();
    let levels: Vec<(f64, f64)> = doc
        .points
        .iter()
        .filter(|p| p.usable())
        .map(|p| (p.level, p.statistic.value))
        .collect();
    let u = unit(doc);
    // Within a decade a linear axis shows the trade-off; a log axis flattens it.
    let (lo, hi) = doc
        .points
        .iter()
        .filter(|p| p.usable() && p.statistic.value > 0.0)
        .fold((f64::INFINITY, 0.0_f64), |(a, b), p| {
            (a.min(p.statistic.value), b.max(p.statistic.value))
        });
    let mut y = if hi > 0.0 && hi < 10.0 * lo {
        Axis::linear(statistic_name(doc))
    } else {
        Axis::log(statistic_name(doc))
    };
    if !u.is_empty() {
        y = y.with_unit(u);
    }
    let mut plot = LinePlot::new(
        format!("{} against P({})", statistic_name(doc), doc.label),
        Axis::log(format!("P({}) sampled at the design", doc.label)),
        y,
    )
    .with_series(Series::new("robust optimum (verified)", front).with_marker(Marker::Circle))
    .with_series(
        Series::new("its level probability_max", levels)
            .with_marker(Marker::Cross)
            .without_line(),
    );
    if !violated.is_empty() {
        plot = plot.with_series(
            Series::new("level violated by sampling", violated)
                .with_marker(Marker::Triangle)
                .without_line(),
        );
    }
    plot.to_svg()
}

/// The HTML page: status, the front plot, the points with their intervals and
/// statuses, and their designs.
pub fn html(doc: &EventFrontDocument) -> String {
    let u = unit(doc);
    let mut p = super::html::Page::new(&format!("wearopt pareto — {}", doc.name));
    p.paragraph(&format!("Status: {}", status_sentence(doc)), Some("status"));
    p.paragraph(
        &format!(
            "Each point is the robust optimum of the study with P({}) ≤ its level (SORA, then the design's probability sampled: importance sampling or Monte Carlo to a coefficient of variation of 0.02){}.",
            doc.label,
            levels::sampled_over(doc.objective, doc.statistic, doc.samples)
        ),
        None,
    );
    levels::html_held(&mut p, &doc.held);
    p.paragraph(
        &format!(
            "The nominal optimum (every input at its median, each event held off there): {} = {}, P({}) = {}.",
            doc.objective.as_str(),
            super::si(doc.nominal_objective, u, 4),
            doc.label,
            probability_words(&doc.nominal_probability)
        ),
        None,
    );
    p.figure(
        "front",
        &svg(doc),
        &format!(
            "{} against the sampled P({}) (log axis); crosses: the level each point was solved at, triangles: points whose sampled P exceeds their level.",
            statistic_name(doc),
            doc.label
        ),
    );
    let stat_header = levels::statistic_header(doc.objective, doc.statistic);
    let p_header = format!("P({}) [95 %]", doc.label);
    let rows: Vec<Vec<String>> = doc
        .points
        .iter()
        .map(|q| {
            vec![
                q.index.to_string(),
                sig_exp(q.level, 2),
                statistic_words(doc, q),
                probability_words(&q.probability),
                method_word(&q.probability).to_string(),
                match violation_words(doc, q) {
                    why if why.is_empty() => q.status().as_str().to_string(),
                    why => format!("{}: {why}", q.status().as_str()),
                },
                mark(q).to_string(),
            ]
        })
        .collect();
    p.table(
        &[
            "#",
            "level",
            &stat_header,
            &p_header,
            "method",
            "status",
            "front",
        ],
        &rows,
        &[4, 5, 6],
    );
    levels::html_designs(
        &mut p,
        doc.objective,
        &doc.names,
        doc.points
            .iter()
            .map(|q| (q.index, &q.design[..], q.at_medians)),
    );
    p.finish()
}

/// The document in `format`.
pub fn render(doc: &EventFrontDocument, format: super::Format) -> String {
    match format {
        super::Format::Json => json(doc),
        super::Format::Csv => csv(doc),
        super::Format::Html => html(doc),
        _ => text(doc),
    }
}
