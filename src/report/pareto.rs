//! The report of a wear–adhesion sweep (`wearopt pareto`): text, CSV, JSON and
//! an SVG plot of the front. CSV and JSON come in pieces (head, one row per
//! point, tail) so that a caller can write each point as it is final; the
//! whole document is the pieces joined, byte for byte.

use std::fmt::Write as _;

use serde_json::{json, Map, Value};

use super::svg::{Axis, LinePlot, Marker, Scale, Series};
use super::{number, si, sig, sig_exp};
use crate::app::pareto::{ParetoDocument, ParetoOptions, ParetoPlan};
use crate::optimize::pareto::{unit_of, Front, FrontPoint, FrontStatus, PULL_OFF_FLOOR};
use crate::optimize::{AdhesionMeasure, Constraint, Objective, ParetoDirection, SceneParameter};
use crate::problem::Dimensioned;
use crate::units::format_quantity;

/// The formats `wearopt pareto` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[
    super::Format::Text,
    super::Format::Json,
    super::Format::Csv,
    super::Format::Html,
];

/// What the head of a streamed report needs (known before the sweep runs).
#[derive(Debug, Clone, Copy)]
pub struct Head<'a> {
    /// The problem's name.
    pub name: &'a str,
    /// The adhesion measure.
    pub measure: AdhesionMeasure,
    /// The preferred end.
    pub direction: ParetoDirection,
    /// The objective minimised.
    pub objective_name: Objective,
    /// The design variables.
    pub names: &'a [SceneParameter],
}

impl<'a> Head<'a> {
    /// The head of a finished front.
    pub fn of(name: &'a str, front: &'a Front) -> Self {
        Head {
            name,
            measure: front.measure,
            direction: front.direction,
            objective_name: front.objective_name,
            names: &front.names,
        }
    }
}

fn measure_text(m: AdhesionMeasure, v: f64, log10: f64) -> String {
    match m {
        AdhesionMeasure::ElasticAdhesionIndex => sig_exp(v, 4),
        _ if v == 0.0 && log10.is_finite() => format!("1e{} {}", sig(log10, 4), unit_of(m)),
        _ => si(v, unit_of(m), 4),
    }
}

// ---------------------------------------------------------------- documents

/// What `pareto` needs computed for `format`, with `points` in place of the
/// `[pareto]` section's when given.
pub fn options(format: super::Format, points: Option<usize>) -> ParetoOptions {
    ParetoOptions {
        points,
        constraint_values: format == super::Format::Html,
        ..ParetoOptions::default()
    }
}

/// The head of a streamed report of `plan`.
pub fn head_of(plan: &ParetoPlan) -> Head<'_> {
    Head {
        name: &plan.name,
        measure: plan.spec.adhesion,
        direction: plan.spec.direction,
        objective_name: plan.objective,
        names: &plan.names,
    }
}

/// What a streamed report in `format` writes before the first point (CSV's header,
/// JSON's opening; nothing for text and HTML, which come whole at the end).
pub fn stream_head(plan: &ParetoPlan, format: super::Format) -> String {
    match format {
        super::Format::Csv => csv_header(&plan.names),
        super::Format::Json => json_head(&head_of(plan)),
        super::Format::Text | super::Format::Html => String::new(),
    }
}

/// What a streamed report in `format` writes for a point as it is final (`first`:
/// the first point written).
pub fn stream_point(
    plan: &ParetoPlan,
    format: super::Format,
    p: &FrontPoint,
    first: bool,
) -> String {
    match format {
        super::Format::Csv => csv_row(p),
        super::Format::Json => json_point(&plan.names, p, first),
        _ => String::new(),
    }
}

/// What a streamed report in `format` writes once the front is done: the rest of
/// the document ([`stream_head`] + each [`stream_point`] + this = [`render`]).
pub fn stream_tail(doc: &ParetoDocument, format: super::Format) -> String {
    let empty = ConstraintValues::default();
    match format {
        super::Format::Csv => String::new(),
        super::Format::Json => json_tail(&doc.front),
        super::Format::Text => text(&doc.plan.name, &doc.front, &doc.plan.constraints),
        super::Format::Html => html(
            &doc.plan.name,
            &doc.front,
            &doc.plan.constraints,
            doc.constraint_values.as_ref().unwrap_or(&empty),
        ),
    }
}

/// The whole document in `format` (every format of [`FORMATS`]).
pub fn render(doc: &ParetoDocument, format: super::Format) -> String {
    let mut out = stream_head(&doc.plan, format);
    for (i, p) in doc.front.points.iter().enumerate() {
        out.push_str(&stream_point(&doc.plan, format, p, i == 0));
    }
    out.push_str(&stream_tail(doc, format));
    out
}

/// The JSON document as a value (what Python reads).
pub fn json_document(doc: &ParetoDocument) -> Value {
    json_value(&doc.plan.name, &doc.front)
}

// ---------------------------------------------------------------- CSV

/// The CSV header: fixed columns, then one column per design variable.
pub fn csv_header(names: &[SceneParameter]) -> String {
    let mut h = String::from(
        "index,target,adhesion,log10_adhesion,wear_rate,objective,status,dominated,on_front",
    );
    for n in names {
        h.push(',');
        h.push_str(n.as_str());
    }
    h.push('\n');
    h
}

/// One CSV row.
pub fn csv_row(p: &FrontPoint) -> String {
    let mut r = format!(
        "{},{},{},{},{},{},{},{},{}",
        p.index,
        number(p.target),
        number(p.adhesion),
        number(p.log10_adhesion),
        number(p.wear_rate),
        number(p.objective),
        p.status.as_str(),
        p.dominated,
        p.on_front
    );
    for v in &p.design {
        r.push(',');
        r.push_str(&number(*v));
    }
    r.push('\n');
    r
}

/// The whole CSV.
pub fn csv(front: &Front) -> String {
    let mut out = csv_header(&front.names);
    for p in &front.points {
        out.push_str(&csv_row(p));
    }
    out
}

// ---------------------------------------------------------------- JSON

fn design_object(names: &[SceneParameter], values: &[f64]) -> Value {
    let mut m = Map::new();
    for (n, v) in names.iter().zip(values) {
        m.insert((*n).to_string(), json!(v));
    }
    Value::Object(m)
}

/// The head's members, in the order the streamed object writes them.
fn head_members(h: &Head) -> [(&'static str, Value); 5] {
    [
        ("name", json!(h.name)),
        ("adhesion_measure", json!(h.measure.as_str())),
        ("direction", json!(h.direction.as_str())),
        ("objective_name", json!(h.objective_name)),
        ("design_variables", json!(h.names)),
    ]
}

/// The JSON object's head, up to the opening of `points`.
pub fn json_head(h: &Head) -> String {
    let mut out = String::from("{\n");
    for (k, v) in head_members(h) {
        let _ = writeln!(
            out,
            "  {}: {},",
            json!(k),
            serde_json::to_string(&v).unwrap_or_else(|_| "null".into())
        );
    }
    out.push_str("  \"points\": [\n");
    out
}

/// One point of `points`, on one line; `first` leaves out the separating comma.
pub fn json_point(names: &[SceneParameter], p: &FrontPoint, first: bool) -> String {
    format!(
        "{}    {}",
        if first { "" } else { ",\n" },
        serde_json::to_string(&point_value(names, p)).unwrap_or_else(|_| "{}".into())
    )
}

/// One point of `points`, as a value.
fn point_value(names: &[SceneParameter], p: &FrontPoint) -> Value {
    json!({
        "index": p.index,
        "target": p.target,
        "target_kind": p.target_kind,
        "adhesion": p.adhesion,
        "log10_adhesion": p.log10_adhesion,
        "wear_rate": p.wear_rate,
        "objective": p.objective,
        "status": p.status.as_str(),
        "dominated": p.dominated,
        "on_front": p.on_front,
        "warm_started": p.warm_started,
        "evaluations": p.evaluations,
        "design": design_object(names, &p.design),
    })
}

/// The members after `points`, as an object.
fn tail_members(front: &Front) -> Map<String, Value> {
    let reference = |r: &crate::optimize::pareto::Reference| {
        json!({
            "adhesion": r.adhesion,
            "log10_adhesion": r.log10_adhesion,
            "wear_rate": r.wear_rate,
            "objective": r.objective,
            "feasible": r.feasible,
            "design": design_object(&front.names, &r.design),
        })
    };
    let rest = json!({
        "status": front.status.as_str(),
        "knee": front.knee,
        "turn": front.turn,
        "front": front.front_indices(),
        "trade_off": front.status == FrontStatus::Ok,
        "strength_range": [front.strength_range.0, front.strength_range.1],
        "floor_end": front.floor_end,
        "least_wear": reference(&front.least_wear),
        "baseline": front.baseline.as_ref().map(reference),
        "probes": front.probes,
        "evaluations": front.evaluations,
    });
    match rest {
        Value::Object(mut m) => {
            if let Some(h) = front.adhesion_humidity {
                m.insert("adhesion_humidity".into(), json!(h));
            }
            m
        }
        _ => Map::new(),
    }
}

/// The rest of the object after the last point.
pub fn json_tail(front: &Front) -> String {
    let m = tail_members(front);
    let mut out = String::from("\n  ],\n");
    let n = m.len();
    for (i, (k, v)) in m.into_iter().enumerate() {
        let v = serde_json::to_string_pretty(&v)
            .unwrap_or_else(|_| "null".into())
            .replace('\n', "\n  ");
        let _ = write!(out, "  {}: {v}", json!(k));
        out.push_str(if i + 1 < n { ",\n" } else { "\n" });
    }
    out.push_str("}\n");
    out
}

/// The object [`json()`] writes, as a value.
pub fn json_value(name: &str, front: &Front) -> Value {
    let mut m = Map::new();
    for (k, v) in head_members(&Head::of(name, front)) {
        m.insert(k.to_string(), v);
    }
    m.insert(
        "points".to_string(),
        Value::Array(
            front
                .points
                .iter()
                .map(|p| point_value(&front.names, p))
                .collect(),
        ),
    );
    m.extend(tail_members(front));
    Value::Object(m)
}

/// The whole JSON object.
pub fn json(name: &str, front: &Front) -> String {
    let mut out = json_head(&Head::of(name, front));
    for (i, p) in front.points.iter().enumerate() {
        out.push_str(&json_point(&front.names, p, i == 0));
    }
    out.push_str(&json_tail(front));
    out
}

// ---------------------------------------------------------------- text

/// The plain sentence for a front without trade-off.
pub(crate) fn no_trade_off_sentence(direction: ParetoDirection) -> &'static str {
    match direction {
        ParetoDirection::Low => {
            "no trade-off: the least-wear design is also the least-adhesion design"
        }
        ParetoDirection::High => {
            "no trade-off: the least-wear design is also the most-adhesion design"
        }
    }
}

fn constraint_text(c: &Constraint) -> String {
    let d = c.quantity.dimension();
    match (c.min, c.max) {
        (Some(a), Some(b)) => format!(
            "{} ≤ {} ≤ {}",
            format_quantity(a, d),
            c.quantity,
            format_quantity(b, d)
        ),
        (Some(a), None) => format!("{} ≥ {}", c.quantity, format_quantity(a, d)),
        (None, Some(b)) => format!("{} ≤ {}", c.quantity, format_quantity(b, d)),
        (None, None) => c.quantity.to_string(),
    }
}

/// "wear_rate against pull_off_force, direction low: the good end is low adhesion".
fn trade_off_line(front: &Front) -> String {
    let m = front.measure;
    let good_end = match (front.direction, m) {
        (ParetoDirection::Low, AdhesionMeasure::ElasticAdhesionIndex) => "high θ (little adhesion)",
        (ParetoDirection::High, AdhesionMeasure::ElasticAdhesionIndex) => "low θ (strong adhesion)",
        (ParetoDirection::Low, _) => "low adhesion",
        (ParetoDirection::High, _) => "high adhesion",
    };
    format!(
        "{} against {}, direction {}: the good end is {good_end}",
        front.objective_name,
        m.as_str(),
        front.direction.as_str()
    )
}

/// The status in a sentence.
fn status_sentence(front: &Front) -> String {
    match front.status {
        FrontStatus::Ok => format!(
            "ok: {} designs on the front, wear and adhesion pull against each other",
            front.front_indices().len()
        ),
        FrontStatus::NoTradeOff => no_trade_off_sentence(front.direction).to_string(),
        FrontStatus::Infeasible => {
            "infeasible: no point of the sweep meets every constraint of the study".to_string()
        }
    }
}

/// Over a humidity range: at which humidity the front is measured.
fn humidity_line(front: &Front) -> Option<String> {
    front.adhesion_humidity.map(|h| {
        format!(
            "{} and {} taken at RH = {} % (the range's humidity where the objective is worst at the baseline, or the file's design_humidity); every limit holds at each humidity of the range",
            front.measure,
            front.objective_name,
            super::sig(100.0 * h, 4)
        )
    })
}

/// The reachable range of the measure.
fn reachable_line(front: &Front) -> String {
    let m = front.measure;
    let (lo, hi) = front.strength_range;
    let (vlo, vhi) = (
        crate::optimize::pareto::value_at(m, lo),
        crate::optimize::pareto::value_at(m, hi),
    );
    let (a, b) = if m == AdhesionMeasure::ElasticAdhesionIndex {
        (vhi, vlo)
    } else {
        (vlo, vhi)
    };
    format!(
        "reachable {}: {} to {}{}",
        m.as_str(),
        measure_text(m, a, a.log10()),
        measure_text(m, b, b.log10()),
        if front.floor_end {
            format!(
                " (pull-off below {} counts as none: that end holds it at most there)",
                si(PULL_OFF_FLOOR, "N", 3)
            )
        } else {
            String::new()
        }
    )
}

/// A report for people; only the sections the study has.
pub fn text(name: &str, front: &Front, constraints: &[Constraint]) -> String {
    let mut out = String::new();
    let mut line = |s: String| {
        out.push_str(&s);
        out.push('\n');
    };
    let m = front.measure;
    let ounit = super::objective_unit(front.objective_name);
    line(format!("wearopt pareto — {name}"));
    if let Some(n) = super::words::real_area_scale_note(front.real_area_scale) {
        line(n);
    }
    line(String::new());
    line(trade_off_line(front));
    line(format!("Status: {}", status_sentence(front)));
    line(reachable_line(front));
    if let Some(h) = humidity_line(front) {
        line(h);
    }
    if !constraints.is_empty() {
        let list: Vec<String> = constraints.iter().map(constraint_text).collect();
        line(format!("every point also meets: {}", list.join(", ")));
    }
    line(String::new());
    let mut header = format!(
        "{:>3} {:>14} {:>14} {:<16} {:<6}",
        "#",
        match m {
            AdhesionMeasure::PullOffForce => "pull-off",
            AdhesionMeasure::WorkOfAdhesion => "γ",
            AdhesionMeasure::ElasticAdhesionIndex => "θ",
        },
        front.objective_name,
        "status",
        "front"
    );
    for n in &front.names {
        let _ = write!(header, " {n:>16}");
    }
    line(header);
    for p in &front.points {
        let mark = if front.knee == Some(p.index) {
            "knee"
        } else if p.on_front {
            "yes"
        } else if p.dominated {
            "dom."
        } else {
            "—"
        };
        let mut row = format!(
            "{:>3} {:>14} {:>14} {:<16} {:<6}",
            p.index,
            measure_text(m, p.adhesion, p.log10_adhesion),
            si(p.objective, ounit, 4),
            p.status.as_str(),
            mark
        );
        for (n, v) in front.names.iter().zip(&p.design) {
            let _ = write!(
                row,
                " {:>16}",
                format_quantity(*v, super::design_dimension(*n))
            );
        }
        line(row);
    }
    line("  front: feasible and not dominated; dom.: an earlier point has as good an adhesion and no more wear".into());
    line(String::new());
    if let Some(k) = front.knee.and_then(|k| front.points.get(k)) {
        line(format!(
            "knee (farthest from the chord of the front in normalised log coordinates): point {}, {} = {}, {} = {}",
            k.index,
            m.as_str(),
            measure_text(m, k.adhesion, k.log10_adhesion),
            front.objective_name,
            si(k.objective, ounit, 4)
        ));
    }
    if let Some(t) = front.turn.and_then(|t| front.points.get(t)) {
        line(turn_sentence(front, t));
    }
    let lw = &front.least_wear;
    line(format!(
        "least-wear design of the study: {} = {}, {} = {}",
        m.as_str(),
        measure_text(m, lw.adhesion, lw.log10_adhesion),
        front.objective_name,
        si(lw.objective, ounit, 4)
    ));
    if let Some(b) = &front.baseline {
        line(format!(
            "baseline design: {} = {}, {} = {}{}",
            m.as_str(),
            measure_text(m, b.adhesion, b.log10_adhesion),
            front.objective_name,
            si(b.objective, ounit, 4),
            if b.feasible {
                ""
            } else {
                " (violates a constraint)"
            }
        ));
    }
    line(format!(
        "{} points ({} on the front), {} range probes, {} model evaluations",
        front.points.len(),
        front.front_indices().len(),
        front.probes,
        front.evaluations
    ));
    out
}

/// `s` with its first letter in upper case.
fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().chain(c).collect())
        .unwrap_or_default()
}

/// Where the curve turns, in words: the front's far end and the points past it.
fn turn_sentence(front: &Front, t: &FrontPoint) -> String {
    let m = front.measure;
    let past = front.points.len() - 1 - t.index;
    let dominated = if past == 1 {
        "the point past it has no less wear and a worse adhesion (dominated; shown, not one of the front's points)".to_string()
    } else {
        format!("the {past} points past it have no less wear and a worse adhesion (dominated; shown, not among the front's points)")
    };
    format!(
        "the front turns at point {}, {} = {}, {} = {}: the least wear is reached there; {dominated}",
        t.index,
        m.as_str(),
        measure_text(m, t.adhesion, t.log10_adhesion),
        front.objective_name,
        si(t.objective, super::objective_unit(front.objective_name), 4)
    )
}

// ---------------------------------------------------------------- SVG

/// The plot: the whole curve, the front, dominated points, the knee and the
/// baseline, the knee ringed and labelled; an axis is log where the front
/// spans a decade or more along it, linear otherwise, its range fitted to all that
/// is drawn (`tests/all/svg_bounds.rs` holds the spread).
pub fn svg(name: &str, front: &Front) -> String {
    let m = front.measure;
    // Underflowed pull-off forces (at most the floor) are drawn at the floor.
    let floor = (m == AdhesionMeasure::PullOffForce).then_some(PULL_OFF_FLOOR);
    let mut clamped = false;
    let mut x_of = |adhesion: f64, log10: f64| -> f64 {
        match floor {
            Some(f) if log10 < f.log10() => {
                clamped = true;
                f
            }
            _ if adhesion == 0.0 => 10f64.powf(log10),
            _ => adhesion,
        }
    };
    let usable: Vec<&FrontPoint> = front
        .points
        .iter()
        .filter(|p| p.objective.is_finite() && p.log10_adhesion.is_finite())
        .collect();
    let mut curve: Vec<(f64, f64, f64)> = usable
        .iter()
        .map(|p| (p.strength, x_of(p.adhesion, p.log10_adhesion), p.objective))
        .collect();
    curve.sort_by(|a, b| a.0.total_cmp(&b.0));
    let pick = |f: &dyn Fn(&FrontPoint) -> bool, x_of: &mut dyn FnMut(f64, f64) -> f64| {
        usable
            .iter()
            .filter(|p| f(p))
            .map(|p| (x_of(p.adhesion, p.log10_adhesion), p.objective))
            .collect::<Vec<_>>()
    };
    let on_front = pick(&|p| p.on_front, &mut x_of);
    let dominated = pick(&|p| p.dominated, &mut x_of);
    let infeasible = pick(&|p| !p.feasible, &mut x_of);
    let knee = pick(&|p| front.knee == Some(p.index), &mut x_of);
    let baseline_feasible = front.baseline.as_ref().is_none_or(|b| b.feasible);
    let baseline: Vec<(f64, f64)> = front
        .baseline
        .iter()
        .map(|b| (x_of(b.adhesion, b.log10_adhesion), b.objective))
        .collect();
    let xs: Vec<f64> = curve
        .iter()
        .map(|c| c.1)
        .chain(baseline.iter().map(|b| b.0))
        .collect();
    let ys: Vec<f64> = curve
        .iter()
        .map(|c| c.2)
        .chain(baseline.iter().map(|b| b.1))
        .collect();
    // A log axis only where the front itself spans a decade or more (the front is
    // what the plot is for: a log axis over the dominated points' decades would
    // squeeze it into a corner); the range then fits everything drawn.
    let spans_decades = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        lo > 0.0 && hi >= 10.0 * lo && v.iter().all(|x| *x > 0.0)
    };
    let front_xs: Vec<f64> = on_front.iter().chain(&knee).map(|p| p.0).collect();
    let front_ys: Vec<f64> = on_front.iter().chain(&knee).map(|p| p.1).collect();
    let (log_x, log_y) = if front_xs.is_empty() {
        (spans_decades(&xs), spans_decades(&ys))
    } else {
        (spans_decades(&front_xs), spans_decades(&front_ys))
    };
    let axis = |label: String, unit: &str, log: bool| {
        let a = if log {
            Axis::log(label)
        } else {
            Axis::linear(label)
        };
        if unit.is_empty() {
            a
        } else {
            a.with_unit(unit)
        }
    };
    let xlabel = match m {
        AdhesionMeasure::PullOffForce => "pull-off force".to_string(),
        AdhesionMeasure::WorkOfAdhesion => "work of adhesion γ".to_string(),
        AdhesionMeasure::ElasticAdhesionIndex => {
            "elastic adhesion index θ (larger: less adhesion)".to_string()
        }
    };
    let ylabel = front.objective_name.as_str().replace('_', " ");
    let title = format!(
        "{name}: {} against {} ({})",
        ylabel,
        m.as_str().replace('_', " "),
        match front.status {
            FrontStatus::Ok => "trade-off",
            FrontStatus::NoTradeOff => "no trade-off",
            FrontStatus::Infeasible => "infeasible",
        }
    );
    // The tables' units: the prefix the largest value takes there.
    let (xf, xu) = crate::units::axis_unit_of(xs.iter().copied(), unit_of(m));
    let (yf, yu) = crate::units::axis_unit_of(
        ys.iter().copied(),
        super::objective_unit(front.objective_name),
    );
    let scaled = |v: Vec<(f64, f64)>| -> Vec<(f64, f64)> {
        v.into_iter().map(|(x, y)| (x / xf, y / yf)).collect()
    };
    let (on_front, dominated, infeasible, knee, baseline) = (
        scaled(on_front),
        scaled(dominated),
        scaled(infeasible),
        scaled(knee),
        scaled(baseline),
    );
    // A linear axis spans what is drawn and 4 % of that on each side (not the next
    // round tick, which may double it), and stays at or above zero for a quantity
    // that is.
    let fitted = |a: Axis, v: &[f64], factor: f64| {
        let v: Vec<f64> = v
            .iter()
            .map(|x| x / factor)
            .filter(|x| x.is_finite())
            .collect();
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if a.scale != Scale::Linear || hi <= lo {
            return a;
        }
        let pad = 0.04 * (hi - lo);
        let low = if lo >= 0.0 {
            (lo - pad).max(0.0)
        } else {
            lo - pad
        };
        a.with_range(low, hi + pad)
    };
    let mut plot = LinePlot::new(
        title,
        fitted(axis(xlabel, &xu, log_x), &xs, xf),
        fitted(axis(ylabel, &yu, log_y), &ys, yf),
    );
    plot = plot.with_series(
        Series::new(
            "all points (ε-constraint curve)",
            scaled(curve.iter().map(|c| (c.1, c.2)).collect()),
        )
        .with_marker(Marker::None)
        .with_color("#999999"),
    );
    let front_name = if clamped {
        format!(
            "Pareto front (pull-off ≤ {} drawn at it)",
            si(PULL_OFF_FLOOR, "N", 1)
        )
    } else {
        "Pareto front".to_string()
    };
    plot = plot.with_series(
        Series::new(front_name, on_front)
            .with_marker(Marker::Circle)
            .with_color("#0072B2"),
    );
    if !dominated.is_empty() {
        plot = plot.with_series(
            Series::new("dominated", dominated)
                .without_line()
                .with_marker(Marker::Cross)
                .with_color("#D55E00"),
        );
    }
    if !infeasible.is_empty() {
        plot = plot.with_series(
            Series::new("infeasible", infeasible)
                .without_line()
                .with_marker(Marker::Triangle)
                .with_color("#CC79A7"),
        );
    }
    if let Some(&(kx, ky)) = knee.first() {
        // Ringed and labelled with its values: a marker alone hides under the
        // front's dots.
        plot = plot
            .with_series(
                Series::new("knee", knee)
                    .without_line()
                    .with_marker(Marker::Diamond)
                    .with_color("#009E73"),
            )
            .with_label(
                (kx, ky),
                format!(
                    "knee: {}, {}",
                    format!("{} {xu}", sig(kx, 4)).trim_end(),
                    format!("{} {yu}", sig(ky, 4)).trim_end()
                ),
                "#007A5A",
            );
    }
    if !baseline.is_empty() {
        // An infeasible baseline breaks a constraint: it is no rival of the front,
        // however low its wear, and is drawn so.
        plot = plot.with_series(if baseline_feasible {
            Series::new("baseline design", baseline)
                .without_line()
                .with_marker(Marker::Square)
                .with_color("#000000")
        } else {
            Series::new(
                "baseline design (infeasible: breaks a constraint)",
                baseline,
            )
            .without_line()
            .with_marker(Marker::Cross)
            .with_color("#CC0000")
        });
    }
    plot.to_svg()
}

pub use crate::app::pareto::ConstraintValues;

/// Whether `v` lies outside the constraint's limits by more than a relative 1e-6
/// (the optimiser's own tolerance is tighter; this flags what a reader must see).
fn breaks(c: &Constraint, v: Option<f64>) -> bool {
    let Some(v) = v else { return false };
    let tol = |limit: f64| 1e-6 * limit.abs().max(f64::MIN_POSITIVE);
    c.min.is_some_and(|a| v < a - tol(a)) || c.max.is_some_and(|b| v > b + tol(b))
}

/// A constraint's value in its unit, with "(breaks)" where it lies outside its limits.
fn constraint_cell(c: &Constraint, v: Option<f64>) -> String {
    match v {
        None => "—".to_string(),
        Some(x) if !x.is_finite() => "—".to_string(),
        Some(x) => {
            let q = format_quantity(x, c.quantity.dimension());
            if breaks(c, v) {
                format!("{q} (breaks)")
            } else {
                q
            }
        }
    }
}

/// The role of a point on the front, in words.
fn point_role(front: &Front, p: &FrontPoint) -> &'static str {
    if front.knee == Some(p.index) {
        "knee"
    } else if p.on_front {
        "on the front"
    } else if p.dominated {
        "dominated"
    } else if !p.feasible {
        "infeasible"
    } else {
        "—"
    }
}

/// A self-contained HTML page: the status, the front (with knee and baseline) as
/// inline SVG, a table of the end points, the knee, the least-wear and the baseline
/// designs, a table of every point with its design and the study's constraints at it,
/// and the constraints with their limits.
pub fn html(
    name: &str,
    front: &Front,
    constraints: &[Constraint],
    values: &ConstraintValues,
) -> String {
    let m = front.measure;
    let ounit = super::objective_unit(front.objective_name);
    let show_wear = front.objective_name != Objective::WearRate;
    let mut p = super::html::Page::new(&format!("wearopt pareto — {name}"));
    p.paragraph(
        &format!("Status: {}", status_sentence(front)),
        Some("status"),
    );
    if let Some(n) = super::words::real_area_scale_note(front.real_area_scale) {
        p.paragraph(&n, Some("note"));
    }
    p.paragraph(&trade_off_line(front), None);
    p.paragraph(&reachable_line(front), None);
    if let Some(h) = humidity_line(front) {
        p.paragraph(&format!("{h}."), None);
    }
    if let Some(t) = front.turn.and_then(|t| front.points.get(t)) {
        p.paragraph(&format!("{}.", capitalised(&turn_sentence(front, t))), None);
    }
    if let Some(b) = front.baseline.as_ref().filter(|b| !b.feasible) {
        let broken: Vec<String> = constraints
            .iter()
            .zip(values.baseline.iter().flatten())
            .filter(|(c, v)| breaks(c, **v))
            .map(|(c, v)| format!("{} = {}", c.quantity, constraint_cell(c, *v)))
            .collect();
        p.list(
            &[format!(
                "the baseline design breaks a constraint of the study{} ({} = {}): it is no rival of the front, however low its wear",
                if broken.is_empty() {
                    String::new()
                } else {
                    format!(": {}", broken.join(", "))
                },
                front.objective_name,
                si(b.objective, ounit, 4)
            )],
            "warn",
        );
    }
    p.figure(
        "front",
        &svg(name, front),
        "Least wear at each adhesion (ε-constraint curve), the Pareto front, its knee and the baseline design.",
    );

    let adhesion_header = match m {
        AdhesionMeasure::PullOffForce => "pull-off force".to_string(),
        AdhesionMeasure::WorkOfAdhesion => "work of adhesion γ".to_string(),
        AdhesionMeasure::ElasticAdhesionIndex => "elastic adhesion index θ".to_string(),
    };
    let objective_header = front.objective_name.as_str().replace('_', " ");
    let design_cells = |design: &[f64]| -> Vec<String> {
        front
            .names
            .iter()
            .zip(design)
            .map(|(n, v)| format_quantity(*v, super::design_dimension(*n)))
            .collect()
    };
    let mut header: Vec<&str> = vec!["design", &adhesion_header, &objective_header];
    if show_wear {
        header.push("wear rate");
    }
    header.push("meets the constraints");
    // Spaces, not underscores, so that a header wraps and the table fits the page.
    let design_headers: Vec<String> = front
        .names
        .iter()
        .map(|n| n.as_str().replace('_', " "))
        .collect();
    header.extend(design_headers.iter().map(String::as_str));

    p.heading("End points, knee and baseline");
    let mut rows: Vec<Vec<String>> = Vec::new();
    let mut point_row = |label: String, pt: &FrontPoint| {
        let mut r = vec![
            label,
            measure_text(m, pt.adhesion, pt.log10_adhesion),
            si(pt.objective, ounit, 4),
        ];
        if show_wear {
            r.push(si(pt.wear_rate, "m³/m", 4));
        }
        r.push(if pt.feasible { "yes" } else { "no" }.into());
        r.extend(design_cells(&pt.design));
        rows.push(r);
    };
    let (first, last) = (front.points.first(), front.points.last());
    if let Some(pt) = first {
        point_row(
            format!("point {}: the preferred adhesion end", pt.index),
            pt,
        );
    }
    if let Some(pt) = last.filter(|l| front.points.len() > 1 && l.index != 0) {
        point_row(format!("point {}: the far end", pt.index), pt);
    }
    if let Some(t) = front.turn.and_then(|t| front.points.get(t)) {
        point_row(
            format!(
                "point {}: the turn, where the least wear is reached",
                t.index
            ),
            t,
        );
    }
    if let Some(k) = front
        .knee
        .and_then(|k| front.points.iter().find(|p| p.index == k))
    {
        point_row(format!("point {}: the knee", k.index), k);
    }
    let mut reference_row = |label: &str, r: &crate::optimize::pareto::Reference| {
        let mut row = vec![
            label.to_string(),
            measure_text(m, r.adhesion, r.log10_adhesion),
            si(r.objective, ounit, 4),
        ];
        if show_wear {
            row.push(si(r.wear_rate, "m³/m", 4));
        }
        row.push(if r.feasible { "yes" } else { "no" }.into());
        row.extend(design_cells(&r.design));
        rows.push(row);
    };
    reference_row("least-wear design of the study", &front.least_wear);
    if let Some(b) = &front.baseline {
        reference_row("baseline design (the problem file's)", b);
    }
    let text_cols = [header.len() - front.names.len() - 1];
    p.table(&header, &rows, &text_cols);

    p.heading("Points");
    let mut header: Vec<String> = vec![
        "point".into(),
        adhesion_header.clone(),
        objective_header.clone(),
    ];
    if show_wear {
        header.push("wear rate".into());
    }
    header.push("status".into());
    header.push("front".into());
    header.extend(design_headers.iter().cloned());
    header.extend(
        constraints
            .iter()
            .map(|c| format!("{} (constraint)", c.quantity.to_string().replace('_', " "))),
    );
    let status_col = if show_wear { 4 } else { 3 };
    let rows: Vec<Vec<String>> =
        front
            .points
            .iter()
            .enumerate()
            .map(|(i, pt)| {
                let mut r = vec![
                    pt.index.to_string(),
                    measure_text(m, pt.adhesion, pt.log10_adhesion),
                    si(pt.objective, ounit, 4),
                ];
                if show_wear {
                    r.push(si(pt.wear_rate, "m³/m", 4));
                }
                r.push(pt.status.as_str().to_string());
                r.push(point_role(front, pt).to_string());
                r.extend(design_cells(&pt.design));
                let at = values.points.get(i);
                r.extend(constraints.iter().enumerate().map(|(j, c)| {
                    constraint_cell(c, at.and_then(|a| a.get(j).copied().flatten()))
                }));
                r
            })
            .collect();
    let header_refs: Vec<&str> = header.iter().map(String::as_str).collect();
    p.table(&header_refs, &rows, &[status_col, status_col + 1]);
    p.paragraph(
        "on the front: feasible and not dominated; dominated: an earlier point has as good an adhesion and no more wear; knee: the front's point farthest from its chord in normalised log coordinates; (breaks): outside the constraint's limits.",
        Some("note"),
    );

    if !constraints.is_empty() {
        p.heading("Constraints");
        let knee_at = front
            .knee
            .and_then(|k| front.points.iter().position(|p| p.index == k))
            .and_then(|i| values.points.get(i));
        let rows: Vec<Vec<String>> = constraints
            .iter()
            .enumerate()
            .map(|(j, c)| {
                let d = c.quantity.dimension();
                let limit = |x: Option<f64>| x.map_or("—".to_string(), |v| format_quantity(v, d));
                let at = |v: Option<&Vec<Option<f64>>>| {
                    constraint_cell(c, v.and_then(|a| a.get(j).copied().flatten()))
                };
                let mut row = vec![c.quantity.to_string(), limit(c.min), limit(c.max)];
                if knee_at.is_some() {
                    row.push(at(knee_at));
                }
                row.push(at(Some(&values.least_wear)));
                if values.baseline.is_some() {
                    row.push(at(values.baseline.as_ref()));
                }
                row
            })
            .collect();
        let mut header = vec!["constraint", "min", "max"];
        if knee_at.is_some() {
            header.push("at the knee");
        }
        header.push("least-wear design");
        if values.baseline.is_some() {
            header.push("baseline");
        }
        p.table(&header, &rows, &[]);
    }
    p.paragraph(
        &format!(
            "{} points, {} range probes, {} model evaluations, {} s.",
            front.points.len(),
            front.probes,
            front.evaluations,
            sig(front.time_seconds, 3)
        ),
        Some("note"),
    );
    p.finish()
}
