//! The report of a robust front against an adhesion measure (`wearopt pareto`
//! on a robust study with `[pareto] adhesion = …`; docs/robust-design.md, "A
//! robust front against an adhesion measure"): text, JSON, CSV and HTML with
//! the front plotted against the measure on a log axis. Every point carries
//! its statistic with its interval, its measure at the medians, its status and
//! each chance constraint's sampled probability; a point that sampling finds
//! violating a chance constraint is marked, not hidden.

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::robust::probability_words;
use super::robust_levels as levels;
use super::svg::{Axis, LinePlot, Marker, Series};
use super::{number, sig_exp};
use crate::app::robust_adhesion_front::{AdhesionFrontDocument, AdhesionPoint};
use crate::optimize::pareto::FrontStatus;
use crate::units::format_quantity;

/// What the first axis reads as: "p95 of wear_rate".
fn statistic_name(doc: &AdhesionFrontDocument) -> String {
    levels::statistic_name(doc.objective, doc.statistic)
}

fn unit(doc: &AdhesionFrontDocument) -> &'static str {
    super::objective_unit(doc.objective)
}

/// The measure's value in words with its unit.
fn measure_words(doc: &AdhesionFrontDocument, v: Option<f64>) -> String {
    match v.filter(|v| v.is_finite()) {
        Some(v) => format_quantity(v, doc.measure.quantity().dimension()),
        None => "—".into(),
    }
}

/// The bound each point holds, as a reader reads it: `pull_off_force <= 12 nN`.
fn bound_words(doc: &AdhesionFrontDocument, target: f64) -> String {
    let upper =
        doc.low() != (doc.measure == crate::optimize::AdhesionMeasure::ElasticAdhesionIndex);
    format!(
        "{} {} {}",
        doc.measure.as_str(),
        if upper { "<=" } else { ">=" },
        measure_words(doc, Some(target))
    )
}

fn status_sentence(doc: &AdhesionFrontDocument) -> String {
    match doc.status {
        FrontStatus::Ok => format!(
            "ok: {} of {} levels give a robust optimum; {} {} costs {}",
            doc.points.iter().filter(|p| p.usable()).count(),
            doc.points.len(),
            if doc.low() { "less" } else { "more" },
            doc.measure.as_str(),
            statistic_name(doc)
        ),
        FrontStatus::NoTradeOff if doc.points.iter().filter(|p| p.usable()).count() < 2 => {
            format!(
                "no_trade_off: only one level gives a robust optimum: the chance constraints allow no other {}",
                doc.measure.as_str()
            )
        }
        FrontStatus::NoTradeOff => format!(
            "no_trade_off: every level gives the same {}: {} does not bind over these levels",
            statistic_name(doc),
            doc.measure.as_str()
        ),
        FrontStatus::Infeasible => {
            "infeasible: no level gives a robust optimum (each point's status below)".to_string()
        }
    }
}

fn statistic_words(doc: &AdhesionFrontDocument, p: &AdhesionPoint) -> String {
    levels::statistic_words(doc.statistic, &p.statistic, unit(doc))
}

fn mark(p: &AdhesionPoint) -> &'static str {
    if !p.usable() {
        "—"
    } else if p.violated {
        "VIOLATED"
    } else if p.on_front {
        "front"
    } else {
        "dominated"
    }
}

/// Each chance constraint's sampled probability at `p`'s design, compact:
/// `stiction 2.1e-4 ≤ 1.0e-3`.
fn chance_words(doc: &AdhesionFrontDocument, p: &AdhesionPoint) -> String {
    let labels = doc.chance_labels();
    p.result
        .chance
        .iter()
        .enumerate()
        .map(|(j, c)| {
            format!(
                "{} {}",
                labels.get(j).copied().unwrap_or(""),
                match (c.verification.probability, c.verification.upper_bound) {
                    (_, Some(b)) => format!("< {}", sig_exp(b, 2)),
                    (Some(q), _) => sig_exp(q, 2),
                    _ => "—".into(),
                }
            )
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The chance constraints sampling finds above their targets at `p`'s design,
/// e.g. `P(stiction) = 0.0116 [0.0112, 0.0120] > 0.0010`; empty where none is.
fn violation_words(doc: &AdhesionFrontDocument, p: &AdhesionPoint) -> String {
    let labels = doc.chance_labels();
    p.result
        .chance
        .iter()
        .enumerate()
        .filter(|(_, c)| c.violated)
        .map(|(j, c)| {
            format!(
                "P({}) = {} > {}",
                labels.get(j).copied().unwrap_or(""),
                probability_words(&c.verification),
                sig_exp(c.target, 2)
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The plain-text report.
pub fn text(doc: &AdhesionFrontDocument) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}", doc.name);
    let _ = writeln!(
        out,
        "Robust front of {} against {} at the medians ({} end preferred): one robust optimum per level of {} ({} levels){}",
        statistic_name(doc),
        doc.measure.as_str(),
        doc.direction.as_str(),
        doc.measure.as_str(),
        doc.levels.len(),
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
        "The file's robust optimum (no level): {} = {} at the medians ({})",
        doc.measure.as_str(),
        measure_words(doc, doc.robust_adhesion),
        doc.robust_status.as_str()
    );
    let _ = writeln!(out);
    let stat_header = levels::statistic_header(doc.objective, doc.statistic);
    let _ = writeln!(
        out,
        "  #  {:<28}  {:<14}  {:<34}  {:<26}  {:<10}  sampled P at the design",
        "level", "at the medians", stat_header, "status", "front"
    );
    for p in &doc.points {
        let _ = writeln!(
            out,
            "{:>3}  {:<28}  {:<14}  {:<34}  {:<26}  {:<10}  {}",
            p.index,
            bound_words(doc, p.target),
            measure_words(doc, p.adhesion),
            statistic_words(doc, p),
            p.status().as_str(),
            mark(p),
            chance_words(doc, p)
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
    if doc.points.iter().any(|p| p.usable() && p.violated) {
        let _ = writeln!(
            out,
            "\nVIOLATED: sampling at the design finds a chance constraint above its target beyond its 95 % interval (FORM is unconservative there); [uncertainty] verify = \"correct\" moves the target by the sampled excess and solves again."
        );
    }
    let _ = writeln!(out, "\nTime: {:.1} s", doc.time_seconds);
    out
}

fn point_json(doc: &AdhesionFrontDocument, p: &AdhesionPoint) -> Value {
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
                "probability_upper_bound": c.verification.upper_bound,
                "violated": c.violated,
            })
        })
        .collect();
    levels::merged(
        levels::point_json(&doc.names, &p.design, &p.statistic, p.at_medians, r),
        json!({
            "index": p.index,
            "target": p.target,
            "adhesion": p.adhesion,
            "violated": p.violated,
            "on_front": p.on_front,
            "chance_constraints": chance,
            "time_seconds": p.time_seconds,
        }),
    )
}

/// The JSON document (keys in docs/robust-design.md, "A robust front against an
/// adhesion measure").
pub fn json_value(doc: &AdhesionFrontDocument) -> Value {
    let design = levels::design_json(&doc.names, &doc.robust_design);
    let f = |x: f64| x.is_finite().then_some(x);
    json!({
        "name": doc.name,
        "status": doc.status.as_str(),
        "front_measure": "adhesion",
        "adhesion_measure": doc.measure.as_str(),
        "direction": doc.direction.as_str(),
        "objective": doc.objective.as_str(),
        "statistic": doc.statistic,
        "samples": doc.samples,
        "design_variables": doc.names.iter().map(|n| n.as_str()).collect::<Vec<_>>(),
        "uncertain_inputs": doc.inputs.iter().map(|n| n.as_str()).collect::<Vec<_>>(),
        "held_chance_constraints": doc.held.iter().map(|h| json!({"event": h.event, "label": h.label, "target": h.target})).collect::<Vec<_>>(),
        "levels": doc.levels,
        "strength_range": [f(doc.strength_range.0), f(doc.strength_range.1)],
        "points": doc.points.iter().map(|p| point_json(doc, p)).collect::<Vec<_>>(),
        "robust_optimum": {
            "design": design,
            "status": doc.robust_status,
            "adhesion": doc.robust_adhesion,
        },
        "time_seconds": doc.time_seconds,
    })
}

/// The JSON text (pretty, ending in a newline).
pub fn json(doc: &AdhesionFrontDocument) -> String {
    super::json_text(&json_value(doc))
}

/// The CSV: a header and one row per level.
pub fn csv(doc: &AdhesionFrontDocument) -> String {
    let mut out = String::from("index,target");
    for n in &doc.names {
        out.push(',');
        out.push_str(n.as_str());
    }
    out.push_str(",adhesion,statistic,statistic_low,statistic_high,at_medians,status,on_front\n");
    let cell = |v: Option<f64>| v.filter(|x| x.is_finite()).map(number).unwrap_or_default();
    for p in &doc.points {
        let _ = write!(out, "{},{}", p.index, number(p.target));
        for v in &p.design {
            out.push(',');
            out.push_str(&number(*v));
        }
        let _ = writeln!(
            out,
            ",{},{},{},{},{},{},{}",
            cell(p.adhesion),
            cell(Some(p.statistic.value)),
            cell(Some(p.statistic.interval[0])),
            cell(Some(p.statistic.interval[1])),
            cell(Some(p.at_medians)),
            p.status().as_str(),
            p.on_front
        );
    }
    out
}

/// The front as SVG: the statistic against the measure at the medians (log
/// axis), the front's points joined, dominated and violated points apart,
/// infeasible points left out.
pub fn svg(doc: &AdhesionFrontDocument) -> String {
    let pt = |p: &AdhesionPoint| {
        p.adhesion
            .filter(|a| *a > 0.0)
            .map(|a| (a, p.statistic.value))
    };
    let mut front: Vec<(f64, f64)> = doc
        .points
        .iter()
        .filter(|p| p.usable() && !p.violated && p.on_front)
        .filter_map(pt)
        .collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    let dominated: Vec<(f64, f64)> = doc
        .points
        .iter()
        .filter(|p| p.usable() && !p.violated && !p.on_front)
        .filter_map(pt)
        .collect();
    // An infeasible point is no design to pick: the table lists it, the plot does not.
    let violated: Vec<(f64, f64)> = doc
        .points
        .iter()
        .filter(|p| p.usable() && p.violated)
        .filter_map(pt)
        .collect();
    let u = unit(doc);
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
    let mut x = Axis::log(format!("{} at the medians", doc.measure.as_str()));
    let mu = crate::optimize::pareto::unit_of(doc.measure);
    if !mu.is_empty() {
        x = x.with_unit(mu);
    }
    let mut plot = LinePlot::new(
        format!("{} against {}", statistic_name(doc), doc.measure.as_str()),
        x,
        y,
    )
    .with_series(Series::new("robust optimum (verified)", front).with_marker(Marker::Circle));
    if !dominated.is_empty() {
        plot = plot.with_series(
            Series::new("dominated", dominated)
                .with_marker(Marker::Cross)
                .without_line(),
        );
    }
    if !violated.is_empty() {
        plot = plot.with_series(
            Series::new("a chance constraint violated by sampling", violated)
                .with_marker(Marker::Triangle)
                .without_line(),
        );
    }
    plot.to_svg()
}

/// The HTML page: status, the front plot, the points with their statuses and
/// sampled probabilities, and their designs.
pub fn html(doc: &AdhesionFrontDocument) -> String {
    let mut p = super::html::Page::new(&format!("wearopt pareto — {}", doc.name));
    p.paragraph(&format!("Status: {}", status_sentence(doc)), Some("status"));
    p.paragraph(
        &format!(
            "Each point is the robust optimum of the study with {} held at its level at the medians of the uncertain inputs (a deterministic constraint), solved as wearopt optimize solves it (SORA, then each chance constraint sampled at the design){}.",
            doc.measure.as_str(),
            levels::sampled_over(doc.objective, doc.statistic, doc.samples)
        ),
        None,
    );
    levels::html_held(&mut p, &doc.held);
    p.paragraph(
        &format!(
            "The file's robust optimum (no level): {} = {} at the medians ({}).",
            doc.measure.as_str(),
            measure_words(doc, doc.robust_adhesion),
            doc.robust_status.as_str()
        ),
        None,
    );
    p.figure(
        "front",
        &svg(doc),
        &format!(
            "{} against {} at the medians (log axis); crosses: dominated points, triangles: points where sampling finds a chance constraint violated; infeasible levels are in the table only.",
            statistic_name(doc),
            doc.measure.as_str()
        ),
    );
    let stat_header = levels::statistic_header(doc.objective, doc.statistic);
    let mut header: Vec<String> = vec![
        "#".into(),
        "level".into(),
        format!("{} at the medians", doc.measure.as_str()),
        stat_header,
    ];
    let labels = doc.chance_labels();
    header.extend(labels.iter().map(|l| format!("P({l}) [95 %]")));
    header.push("status".into());
    header.push("front".into());
    let rows: Vec<Vec<String>> = doc
        .points
        .iter()
        .map(|q| {
            let mut r = vec![
                q.index.to_string(),
                bound_words(doc, q.target),
                measure_words(doc, q.adhesion),
                statistic_words(doc, q),
            ];
            r.extend(
                q.result
                    .chance
                    .iter()
                    .map(|c| probability_words(&c.verification)),
            );
            r.push(match violation_words(doc, q) {
                why if why.is_empty() => q.status().as_str().to_string(),
                why => format!("{}: {why}", q.status().as_str()),
            });
            r.push(mark(q).to_string());
            r
        })
        .collect();
    let n = header.len();
    let header_refs: Vec<&str> = header.iter().map(|s| s.as_str()).collect();
    p.table(&header_refs, &rows, &[1, n - 2, n - 1]);
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
pub fn render(doc: &AdhesionFrontDocument, format: super::Format) -> String {
    match format {
        super::Format::Json => json(doc),
        super::Format::Csv => csv(doc),
        super::Format::Html => html(doc),
        _ => text(doc),
    }
}
