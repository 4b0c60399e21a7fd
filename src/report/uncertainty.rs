//! An uncertainty study (`wearopt uncertainty`): a report, CSV, JSON and an HTML
//! page with the indices and their intervals, the distributions of the outputs,
//! the life curve and the design points. No number without its interval or its
//! status.

use std::fmt::Write as _;

use serde_json::{json, Value};

use super::format::FormatError;
use super::svg::{escape, Axis, LinePlot, Marker, Series};
use super::{number, sig_exp, Format};
use crate::app::uncertainty::{
    Analysis, Cause, Method, OutputInfo, PartError, UncertaintyDocument, UncertaintyPart,
    PART_MARKER,
};
use crate::model::Quantity;
use crate::problem::{Event, UncertainInput};
use crate::sweep::Shard;
use crate::units::{format_quantity, Dimension};
use crate::uq::distribution::Distribution;
use crate::uq::reliability::{EventResult, EventStatus, FormStatus, SamplingMethod};
use crate::uq::sobol::SobolStatus;
use crate::uq::Estimate;

/// The formats `wearopt uncertainty` writes (the first is the default).
pub const FORMATS: &[Format] = &[Format::Text, Format::Json, Format::Csv, Format::Html];

/// An index interval wider than this says N is too small.
pub const WIDE_INTERVAL: f64 = 0.1;

/// A sample failure share above this makes an output's results incomplete.
pub const INCOMPLETE_SHARE: f64 = 0.01;

fn q(x: f64, d: Dimension) -> String {
    if x.is_finite() {
        format_quantity(x, d)
    } else {
        "—".to_string()
    }
}

fn law_words(input: &UncertainInput) -> String {
    let d = input.parameter.dimension();
    match input.distribution {
        Distribution::Normal { mean, sd } => {
            format!("normal, mean {}, sd {}", q(mean, d), q(sd, d))
        }
        Distribution::Lognormal { median, factor } => {
            format!(
                "lognormal, median {}, factor {}",
                q(median, d),
                sig_exp(factor, 4)
            )
        }
        Distribution::Uniform { min, max } => format!("uniform on [{}, {}]", q(min, d), q(max, d)),
        Distribution::Beta {
            alpha,
            beta,
            min,
            max,
        } => format!(
            "beta(α {}, β {}) on [{}, {}]",
            sig_exp(alpha, 4),
            sig_exp(beta, 4),
            q(min, d),
            q(max, d)
        ),
        Distribution::Triangular { min, mode, max } => format!(
            "triangular on [{}, {}], mode {}",
            q(min, d),
            q(max, d),
            q(mode, d)
        ),
    }
}

fn method_words(doc: &UncertaintyDocument) -> String {
    let n = doc.samples;
    let d = doc.inputs.len();
    let rounded = doc
        .samples_asked
        .map(|a| format!(" (asked {a}, rounded up to a power of two)"))
        .unwrap_or_default();
    match doc.method {
        Method::Sobol => format!(
            "Sobol′ indices: centred Saltelli (first order S1) and Jansen (total ST) estimators on {} independent Owen scrambles of a {}-dimensional Sobol′ sequence, N = {n}{rounded}, N (d + 2) = {} evaluations; 95 % intervals from the spread between the scrambles",
            crate::uq::sobol::replicates(n),
            2 * d,
            doc.evaluations
        ),
        Method::Morris => format!(
            "Morris screening: {} evaluations on trajectories of d + 1 = {} points (4 levels); μ* = mean |elementary effect|, σ their spread, per unit of each input's probability",
            doc.evaluations,
            d + 1
        ),
        Method::Sampling => format!(
            "sampling: N = {n} scrambled Sobol′ points; 95 % intervals (order statistics for the percentiles)"
        ),
        Method::Reliability => format!(
            "reliability: FORM (HL-RF with a line search, from the median and 2d + 1 = {} starts on the β-sphere), SORM (Breitung, Tvedt), then importance sampling on the design points (Monte Carlo where P ≥ 1e-3) until the coefficient of variation is 0.1; {} evaluations",
            2 * d + 1,
            doc.evaluations
        ),
    }
}

fn failure_words(o: &OutputInfo, total: usize) -> Option<String> {
    let f = o.failed;
    if f.total() == 0 {
        return None;
    }
    let mut parts = Vec::new();
    for (n, what) in [
        (f.separated, "separated"),
        (f.not_converged, "not converged"),
        (f.out_of_range, "out of range"),
        (f.undefined, "undefined there"),
    ] {
        if n > 0 {
            parts.push(format!("{n} {what}"));
        }
    }
    let share = f.total() as f64 / total.max(1) as f64;
    Some(format!(
        "{} of {total} samples without a value ({}){}",
        f.total(),
        parts.join(", "),
        if share > INCOMPLETE_SHARE {
            ": above 1 %, the results of this output are incomplete"
        } else {
            ""
        }
    ))
}

fn interval_text(e: &Estimate, d: Dimension) -> String {
    format!(
        "{} [{}, {}]",
        q(e.value, d),
        q(e.interval[0], d),
        q(e.interval[1], d)
    )
}

/// An index to four places; one within rounding of 0 (|v| < 1e-12, e.g. the
/// last-bit noise of an input that does not act on the output) is 0.0000, not
/// -0.0000. JSON keeps the value as estimated.
fn index_text(v: f64) -> String {
    if v.abs() < 1e-12 {
        "0.0000".into()
    } else if v.is_finite() {
        format!("{v:.4}")
    } else {
        "—".into()
    }
}

fn event_words(e: &Event) -> String {
    match e {
        Event::Stiction => {
            "the pull-off force reaches the restoring force (the part sticks)".into()
        }
        Event::WearOut => {
            "the wear depth over the sliding distance exceeds the allowed wear depth".into()
        }
        Event::Threshold {
            quantity,
            above,
            limit,
            ..
        } => format!(
            "{} {} {}",
            quantity.as_str(),
            if *above { ">" } else { "<" },
            q(*limit, quantity.dimension())
        ),
    }
}

fn status_name(s: EventStatus) -> &'static str {
    match s {
        EventStatus::Converged => "converged",
        EventStatus::MultipleDesignPoints => "multiple_design_points",
        EventStatus::SamplingDisagrees => "sampling_disagrees",
        EventStatus::NoFailureObserved => "no_failure_observed",
        EventStatus::NotConverged => "not_converged",
        EventStatus::ZeroGradient => "zero_gradient",
        EventStatus::ModelFailed => "model_failed",
    }
}

fn status_words(s: EventStatus) -> &'static str {
    match s {
        EventStatus::Converged => {
            "the sampled probability reached its precision (coefficient of variation ≤ 0.1)"
        }
        EventStatus::MultipleDesignPoints => {
            "converged; FORM found several design points (the failure domain has several parts), the sampled value counts them all"
        }
        EventStatus::SamplingDisagrees => {
            "the sampled probability contradicts FORM's (the limit state is curved or several-sided): trust the sampled value, not FORM's"
        }
        EventStatus::NoFailureObserved => {
            "no failure in the samples: only an upper bound"
        }
        EventStatus::NotConverged => {
            "not converged: no probability (raise the evaluation budget, or the model fails near the design point)"
        }
        EventStatus::ZeroGradient => {
            "the event does not depend on the uncertain inputs near their median (zero gradient)"
        }
        EventStatus::ModelFailed => "the model failed where FORM needed it",
    }
}

/// Why FORM gave no design point, or None where it did.
fn form_failure_words(s: FormStatus) -> Option<&'static str> {
    match s {
        FormStatus::Converged | FormStatus::MultipleDesignPoints => None,
        FormStatus::NotConverged => Some("not converged within its iteration cap"),
        FormStatus::ZeroGradient => {
            Some("the limit state does not vary near the median (zero gradient)")
        }
        FormStatus::ModelFailed => Some("the model failed where FORM needed it"),
    }
}

fn sampling_method_name(m: SamplingMethod) -> &'static str {
    match m {
        SamplingMethod::ImportanceSampling => "importance_sampling",
        SamplingMethod::MonteCarlo => "monte_carlo",
    }
}

fn p_text(p: f64) -> String {
    sig_exp(p, 3)
}

/// Said where a percentile's interval reaches beyond the sample.
const BEYOND: &str = "— : the interval's end lies beyond the sample (too few samples in that tail to bound it): raise --samples";

/// The statistics of an output, in the order every format gives them.
const STATISTICS: [&str; 7] = ["mean", "sd", "p1", "p5", "p50", "p95", "p99"];

/// Each of [`STATISTICS`] with its estimate.
fn statistics(s: &crate::uq::sampling::SamplingSummary) -> [(&'static str, &Estimate); 7] {
    let e = [&s.mean, &s.sd, &s.p1, &s.p5, &s.p50, &s.p95, &s.p99];
    std::array::from_fn(|k| (STATISTICS[k], e[k]))
}

fn beyond_the_sample(s: &crate::uq::sampling::SamplingSummary) -> bool {
    statistics(s)
        .iter()
        .any(|(_, e)| !(e.interval[0].is_finite() && e.interval[1].is_finite()))
}

/// The text report.
pub fn text(doc: &UncertaintyDocument) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "wearopt uncertainty — {}", doc.name);
    let _ = writeln!(out, "method: {}", method_words(doc));
    let _ = writeln!(out, "seed {}, fingerprint {}", doc.seed, doc.fingerprint);
    let _ = writeln!(out, "\nUncertain inputs");
    for i in &doc.inputs {
        let _ = writeln!(
            out,
            "  {:<22} {}",
            format!("{} ({})", i.parameter.as_str(), i.parameter.symbol()),
            law_words(i)
        );
    }
    for &(a, b, rho) in &doc.correlations {
        let _ = writeln!(
            out,
            "  correlation {} – {}: ρ = {} (Gaussian copula: the correlation of the normal scores)",
            doc.inputs[a].parameter.as_str(),
            doc.inputs[b].parameter.as_str(),
            sig_exp(rho, 3)
        );
    }
    let names: Vec<&str> = doc.inputs.iter().map(|i| i.parameter.as_str()).collect();
    let width = names.iter().map(|n| n.len()).max().unwrap_or(5).max(5);
    match &doc.analysis {
        Analysis::Sobol(results) => {
            if !doc.correlations.is_empty() {
                let _ = writeln!(out, "\nThe inputs are correlated: the indices are those of their independent normal scores, in the order listed (the first input's share includes what it passes to the ones it is correlated with).");
            }
            for (o, r) in doc.outputs.iter().zip(results) {
                output_head(&mut out, o, doc);
                match r.status {
                    SobolStatus::Degenerate => {
                        let _ = writeln!(out, "  no indices: the output does not vary, or too few samples have a value");
                        continue;
                    }
                    SobolStatus::Incomplete => {
                        let _ = writeln!(
                            out,
                            "  status: incomplete (more than 1 % of the samples without a value)"
                        );
                    }
                    SobolStatus::Complete => {}
                }
                let _ = writeln!(
                    out,
                    "  {:<width$}  {:>8}  {:<20}  {:>8}  {:<20}",
                    "input", "S1", "95 % interval", "ST", "95 % interval"
                );
                for (k, name) in names.iter().enumerate() {
                    let (s, t) = (&r.first_order[k], &r.total[k]);
                    let _ = writeln!(
                        out,
                        "  {:<width$}  {:>8}  {:<20}  {:>8}  {:<20}",
                        name,
                        index_text(s.value),
                        format!(
                            "[{}, {}]",
                            index_text(s.interval[0]),
                            index_text(s.interval[1])
                        ),
                        index_text(t.value),
                        format!(
                            "[{}, {}]",
                            index_text(t.interval[0]),
                            index_text(t.interval[1])
                        ),
                    );
                }
                if r.wide {
                    let _ = writeln!(out, "  N too small: an interval is wider than {WIDE_INTERVAL}; raise --samples (the intervals narrow as 1/√N)");
                }
                if r.first_order.iter().any(|s| s.value < 0.0) {
                    let _ = writeln!(out, "  A negative S1 is an estimate of an index near 0, shown with its interval as estimated, not clipped.");
                }
            }
        }
        Analysis::Morris(results) => {
            for (o, r) in doc.outputs.iter().zip(results) {
                output_head(&mut out, o, doc);
                let unit = o.quantity.dimension().si_unit();
                let _ = writeln!(
                    out,
                    "  {:<width$}  {:>12}  {:>12}  (output units{} per unit of probability)",
                    "input",
                    "μ*",
                    "σ",
                    if unit.is_empty() {
                        String::new()
                    } else {
                        format!(", {unit},")
                    }
                );
                for (k, name) in names.iter().enumerate() {
                    let e = &r.effects[k];
                    let _ = writeln!(
                        out,
                        "  {:<width$}  {:>12}  {:>12}",
                        name,
                        sig_exp(e.mu_star, 4),
                        sig_exp(e.sigma, 4)
                    );
                }
                if r.incomplete {
                    let _ = writeln!(
                        out,
                        "  status: incomplete (more than 1 % of the evaluations without a value)"
                    );
                }
            }
        }
        Analysis::Sampling { summaries, life } => {
            for (o, s) in doc.outputs.iter().zip(summaries) {
                output_head(&mut out, o, doc);
                if s.incomplete {
                    let _ = writeln!(
                        out,
                        "  status: incomplete (more than 1 % of the samples without a value)"
                    );
                }
                let d = o.quantity.dimension();
                for (label, e) in statistics(s) {
                    let _ = writeln!(out, "  {label:<5} {}", interval_text(e, d));
                }
                if beyond_the_sample(s) {
                    let _ = writeln!(out, "  {BEYOND}");
                }
            }
            if let Some((quantity, l)) = life {
                let d = quantity.dimension();
                let _ = writeln!(
                    out,
                    "\nLife ({}): by B1 1 % of the parts have worn out, by B10 10 %, by B50 half",
                    quantity.as_str()
                );
                for (label, e) in [("B1", &l.b1), ("B10", &l.b10), ("B50", &l.b50)] {
                    let _ = writeln!(out, "  {label:<4} {}", interval_text(e, d));
                }
            }
        }
        Analysis::Reliability(events) => {
            for (event, r) in events {
                event_text(&mut out, event, r, doc);
            }
        }
    }
    out
}

fn output_head(out: &mut String, o: &OutputInfo, doc: &UncertaintyDocument) {
    let nominal = o
        .nominal
        .map(|v| format!(" (at the file's values: {})", q(v, o.quantity.dimension())))
        .unwrap_or_default();
    let _ = writeln!(out, "\n{}{nominal}", o.quantity.as_str());
    let total = match doc.method {
        Method::Sobol => doc.evaluations,
        _ => doc.evaluations,
    };
    if let Some(w) = failure_words(o, total) {
        let _ = writeln!(out, "  {w}");
    }
}

fn event_text(out: &mut String, event: &Event, r: &EventResult, doc: &UncertaintyDocument) {
    let _ = writeln!(out, "\nEvent {}: {}", event.name(), event_words(event));
    let _ = writeln!(
        out,
        "  status: {} — {}",
        status_name(r.status),
        status_words(r.status)
    );
    match (r.probability, r.interval, &r.sampling) {
        (Some(p), Some(iv), Some(s)) if r.status != EventStatus::NotConverged => {
            let _ = writeln!(
                out,
                "  P = {} [{}, {}] ({}, {} samples, coefficient of variation {})",
                p_text(p),
                p_text(iv[0]),
                p_text(iv[1]),
                sampling_method_name(s.method).replace('_', " "),
                s.samples,
                sig_exp(s.cov, 2)
            );
        }
        _ => {}
    }
    if let Some(b) = r.upper_bound {
        let _ = writeln!(out, "  P ≤ {} (3/N: no failure in the samples)", p_text(b));
    }
    if let Some(beta) = r.beta {
        let _ = writeln!(
            out,
            "  β = {} (the generalised reliability index −Φ⁻¹(P))",
            sig_exp(beta, 4)
        );
    }
    let form = &r.form;
    if let Some(why) = form_failure_words(form.status) {
        let _ = writeln!(
            out,
            "  FORM: {why} (from {} starts): no design point; the probability is the sampled one alone, by Monte Carlo",
            form.starts
        );
    }
    if let (Some(b), Some(p)) = (form.beta, form.probability) {
        let sorm = r
            .sorm
            .as_ref()
            .map(|s| {
                format!(
                    "; SORM Breitung {}, Tvedt {}",
                    s.breitung.map_or("—".into(), p_text),
                    s.tvedt.map_or("—".into(), p_text)
                )
            })
            .unwrap_or_default();
        let _ = writeln!(out, "  FORM β = {}, P = {}{sorm}", sig_exp(b, 4), p_text(p));
    }
    let _ = writeln!(
        out,
        "  design points: {} distinct of {} starts ({} converged)",
        form.design_points.len(),
        form.starts,
        form.converged_starts
    );
    for dp in &form.design_points {
        let coords: Vec<String> = doc
            .inputs
            .iter()
            .zip(&dp.x)
            .map(|(i, &x)| format!("{} {}", i.parameter.as_str(), q(x, i.parameter.dimension())))
            .collect();
        let _ = writeln!(out, "    β {}: {}", sig_exp(dp.beta, 4), coords.join(", "));
    }
    if let Some(dp) = form.design_points.first() {
        let shares: Vec<String> = doc
            .inputs
            .iter()
            .zip(&dp.importance)
            .map(|(i, &a)| format!("{} {:.1} %", i.parameter.as_str(), 100.0 * a))
            .collect();
        let _ = writeln!(out, "  importance (share of β²): {}", shares.join(", "));
    }
    let _ = writeln!(out, "  evaluations: {}", r.evaluations);
}

fn opt(x: Option<f64>) -> Value {
    x.map_or(Value::Null, |v| json!(v))
}

fn interval_json(i: [f64; 2]) -> Value {
    json!([i[0], i[1]])
}

fn inputs_json(doc: &UncertaintyDocument) -> Value {
    Value::Array(
        doc.inputs
            .iter()
            .map(|i| {
                let mut v = serde_json::to_value(i.distribution).unwrap_or(Value::Null);
                if let Value::Object(m) = &mut v {
                    let kind = m.remove("kind").unwrap_or(Value::Null);
                    m.insert("distribution".into(), kind);
                    m.insert("name".into(), json!(i.parameter.as_str()));
                }
                v
            })
            .collect(),
    )
}

/// The JSON document (keys: docs/uncertainty.md).
pub fn json_value(doc: &UncertaintyDocument) -> Value {
    let names: Vec<&str> = doc.inputs.iter().map(|i| i.parameter.as_str()).collect();
    let failed: serde_json::Map<String, Value> = doc
        .outputs
        .iter()
        .map(|o| {
            (
                o.quantity.as_str().to_string(),
                json!({
                    "total": o.failed.total(),
                    "separated": o.failed.separated,
                    "not_converged": o.failed.not_converged,
                    "out_of_range": o.failed.out_of_range,
                    "undefined": o.failed.undefined,
                }),
            )
        })
        .collect();
    let mut v = json!({
        "name": doc.name,
        "method": doc.method.as_str(),
        "samples": doc.samples,
        "samples_asked": doc.samples_asked,
        "seed": doc.seed,
        "fingerprint": doc.fingerprint,
        "evaluations": doc.evaluations,
        "failed": failed,
        "inputs": inputs_json(doc),
        "correlations": doc.correlations.iter().map(|&(a, b, rho)| json!({
            "between": [names[a], names[b]], "rho": rho
        })).collect::<Vec<_>>(),
        "nominal": doc.outputs.iter().map(|o| (o.quantity.as_str().to_string(), opt(o.nominal))).collect::<serde_json::Map<_, _>>(),
    });
    let m = v.as_object_mut().expect("an object");
    match &doc.analysis {
        Analysis::Sobol(results) => {
            let mut rows = Vec::new();
            let mut statuses = serde_json::Map::new();
            for (o, r) in doc.outputs.iter().zip(results) {
                statuses.insert(
                    o.quantity.as_str().into(),
                    json!({"status": r.status, "wide": r.wide, "mean": r.mean, "variance": r.variance, "replicates": r.replicates}),
                );
                for (k, name) in names.iter().enumerate() {
                    let (Some(s), Some(t)) = (r.first_order.get(k), r.total.get(k)) else {
                        continue;
                    };
                    rows.push(json!({
                        "input": name,
                        "output": o.quantity.as_str(),
                        "first_order": s.value,
                        "first_order_interval": interval_json(s.interval),
                        "total_order": t.value,
                        "total_order_interval": interval_json(t.interval),
                        "wide": s.wide || t.wide,
                    }));
                }
            }
            m.insert("indices".into(), Value::Array(rows));
            m.insert("output_status".into(), Value::Object(statuses));
        }
        Analysis::Morris(results) => {
            let mut rows = Vec::new();
            for (o, r) in doc.outputs.iter().zip(results) {
                for (k, name) in names.iter().enumerate() {
                    let e = &r.effects[k];
                    rows.push(json!({
                        "input": name,
                        "output": o.quantity.as_str(),
                        "mu_star": e.mu_star,
                        "mu": e.mu,
                        "sigma": e.sigma,
                    }));
                }
            }
            m.insert("indices".into(), Value::Array(rows));
            m.insert(
                "trajectories".into(),
                json!(results.first().map_or(0, |r| r.trajectories)),
            );
        }
        Analysis::Sampling { summaries, life } => {
            let mut rows = Vec::new();
            for (o, s) in doc.outputs.iter().zip(summaries) {
                let mut row = serde_json::Map::new();
                row.insert("name".into(), json!(o.quantity.as_str()));
                for (label, e) in statistics(s) {
                    row.insert(label.into(), json!(e.value));
                    row.insert(format!("{label}_interval"), interval_json(e.interval));
                }
                row.insert("incomplete".into(), json!(s.incomplete));
                row.insert("samples".into(), json!(s.samples));
                row.insert("cdf".into(), json!(s.sorted));
                rows.push(Value::Object(row));
            }
            m.insert("outputs".into(), Value::Array(rows));
            m.insert(
                "life".into(),
                life.as_ref().map_or(Value::Null, |(quantity, l)| {
                    json!({
                        "quantity": quantity.as_str(),
                        "b1": l.b1.value, "b1_interval": interval_json(l.b1.interval),
                        "b10": l.b10.value, "b10_interval": interval_json(l.b10.interval),
                        "b50": l.b50.value, "b50_interval": interval_json(l.b50.interval),
                    })
                }),
            );
        }
        Analysis::Reliability(events) => {
            let rows: Vec<Value> = events
                .iter()
                .map(|(event, r)| {
                    let design_points: Vec<Value> = r
                        .form
                        .design_points
                        .iter()
                        .map(|dp| {
                            let point: serde_json::Map<String, Value> = names
                                .iter()
                                .zip(&dp.x)
                                .map(|(n, &x)| (n.to_string(), json!(x)))
                                .collect();
                            json!({"point": point, "beta": dp.beta})
                        })
                        .collect();
                    let importance: serde_json::Map<String, Value> = r
                        .form
                        .design_points
                        .first()
                        .map(|dp| {
                            names
                                .iter()
                                .zip(&dp.importance)
                                .map(|(n, &a)| (n.to_string(), json!(a)))
                                .collect()
                        })
                        .unwrap_or_default();
                    json!({
                        "name": event.name(),
                        "event": event,
                        "status": status_name(r.status),
                        "probability": opt(r.probability),
                        "probability_interval": r.interval.map_or(Value::Null, interval_json),
                        "upper_bound": opt(r.upper_bound),
                        "method": r.sampling.as_ref().map_or(Value::Null, |s| json!(sampling_method_name(s.method))),
                        "coefficient_of_variation": r.sampling.as_ref().map_or(Value::Null, |s| json!(s.cov)),
                        "beta": opt(r.beta),
                        "form_beta": opt(r.form.beta),
                        "form_probability": opt(r.form.probability),
                        "form_status": r.form.status,
                        "sorm_probability": opt(r.sorm.as_ref().and_then(|s| s.breitung)),
                        "sorm_tvedt_probability": opt(r.sorm.as_ref().and_then(|s| s.tvedt)),
                        "design_points": design_points,
                        "importance_factors": importance,
                        "evaluations": r.evaluations,
                    })
                })
                .collect();
            m.insert("events".into(), Value::Array(rows));
        }
    }
    v
}

/// JSON text.
pub fn json(doc: &UncertaintyDocument) -> String {
    super::json_text(&json_value(doc))
}

fn cell(x: f64) -> String {
    if x.is_finite() {
        number(x)
    } else {
        String::new()
    }
}

/// CSV: one row per (input, output) index, per output's statistics or per event.
pub fn csv(doc: &UncertaintyDocument) -> String {
    let names: Vec<&str> = doc.inputs.iter().map(|i| i.parameter.as_str()).collect();
    let mut out = String::new();
    match &doc.analysis {
        Analysis::Sobol(results) => {
            out.push_str("input,output,first_order,first_order_low,first_order_high,total_order,total_order_low,total_order_high\n");
            for (o, r) in doc.outputs.iter().zip(results) {
                for (k, name) in names.iter().enumerate() {
                    let (Some(s), Some(t)) = (r.first_order.get(k), r.total.get(k)) else {
                        continue;
                    };
                    let _ = writeln!(
                        out,
                        "{name},{},{},{},{},{},{},{}",
                        o.quantity.as_str(),
                        cell(s.value),
                        cell(s.interval[0]),
                        cell(s.interval[1]),
                        cell(t.value),
                        cell(t.interval[0]),
                        cell(t.interval[1])
                    );
                }
            }
        }
        Analysis::Morris(results) => {
            out.push_str("input,output,mu_star,mu,sigma\n");
            for (o, r) in doc.outputs.iter().zip(results) {
                for (k, name) in names.iter().enumerate() {
                    let e = &r.effects[k];
                    let _ = writeln!(
                        out,
                        "{name},{},{},{},{}",
                        o.quantity.as_str(),
                        cell(e.mu_star),
                        cell(e.mu),
                        cell(e.sigma)
                    );
                }
            }
        }
        Analysis::Sampling { summaries, .. } => {
            out.push_str("name");
            for s in STATISTICS {
                let _ = write!(out, ",{s},{s}_low,{s}_high");
            }
            out.push('\n');
            for (o, s) in doc.outputs.iter().zip(summaries) {
                out.push_str(o.quantity.as_str());
                for (_, e) in statistics(s) {
                    let _ = write!(
                        out,
                        ",{},{},{}",
                        cell(e.value),
                        cell(e.interval[0]),
                        cell(e.interval[1])
                    );
                }
                out.push('\n');
            }
        }
        Analysis::Reliability(events) => {
            out.push_str("name,status,probability,probability_low,probability_high,method,beta,form_probability,sorm_probability,design_points,evaluations\n");
            for (event, r) in events {
                let iv = r.interval.unwrap_or([f64::NAN, f64::NAN]);
                let _ = writeln!(
                    out,
                    "{},{},{},{},{},{},{},{},{},{},{}",
                    event.name(),
                    status_name(r.status),
                    cell(r.probability.unwrap_or(f64::NAN)),
                    cell(iv[0]),
                    cell(iv[1]),
                    r.sampling
                        .as_ref()
                        .map_or("", |s| sampling_method_name(s.method)),
                    cell(r.beta.unwrap_or(f64::NAN)),
                    cell(r.form.probability.unwrap_or(f64::NAN)),
                    cell(r.sorm.as_ref().and_then(|s| s.breitung).unwrap_or(f64::NAN)),
                    r.form.design_points.len(),
                    r.evaluations
                );
            }
        }
    }
    out
}

/// Bars of the indices with their intervals as whiskers: per input, S1 and ST.
pub fn indices_svg(
    title: &str,
    names: &[&str],
    first: &[(f64, [f64; 2])],
    total: &[(f64, [f64; 2])],
) -> String {
    let (w, row, left, right, top) = (720.0, 34.0, 170.0, 30.0, 44.0);
    let h = top + row * names.len() as f64 + 40.0;
    let lo = first
        .iter()
        .chain(total)
        .map(|(v, i)| v.min(i[0]))
        .filter(|x| x.is_finite())
        .fold(0.0f64, f64::min)
        .max(-0.5);
    let hi = first
        .iter()
        .chain(total)
        .map(|(v, i)| v.max(i[1]))
        .filter(|x| x.is_finite())
        .fold(1.0f64, f64::max)
        .min(1.5);
    let x = |v: f64| left + (v.clamp(lo, hi) - lo) / (hi - lo) * (w - left - right);
    let mut s = String::new();
    let _ = write!(
        s,
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"12\">\n<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n<text x=\"{}\" y=\"20\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n",
        w / 2.0,
        escape(title)
    );
    // Legend.
    let _ = writeln!(s, "<rect x=\"{left}\" y=\"28\" width=\"12\" height=\"8\" fill=\"#1f77b4\"/><text x=\"{}\" y=\"36\">first order S1</text><rect x=\"{}\" y=\"28\" width=\"12\" height=\"8\" fill=\"#ff7f0e\"/><text x=\"{}\" y=\"36\">total ST</text><text x=\"{}\" y=\"36\">(whiskers: 95 % intervals)</text>", left + 16.0, left + 130.0, left + 146.0, left + 230.0);
    for (k, name) in names.iter().enumerate() {
        let y0 = top + row * k as f64;
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>",
            left - 8.0,
            y0 + row / 2.0 + 4.0,
            escape(name)
        );
        for (j, (v, iv), color) in [(0, first.get(k), "#1f77b4"), (1, total.get(k), "#ff7f0e")]
            .into_iter()
            .filter_map(|(j, e, c)| e.map(|(v, i)| (j, (*v, *i), c)))
        {
            let yb = y0 + 5.0 + 12.0 * j as f64;
            let (a, b) = (x(0.0), x(v));
            let _ = writeln!(
                s,
                "<rect x=\"{:.1}\" y=\"{yb:.1}\" width=\"{:.1}\" height=\"10\" fill=\"{color}\"/>",
                a.min(b),
                (b - a).abs().max(0.5)
            );
            if iv[0].is_finite() && iv[1].is_finite() {
                let yc = yb + 5.0;
                let _ = writeln!(
                    s,
                    "<line x1=\"{:.1}\" y1=\"{yc:.1}\" x2=\"{:.1}\" y2=\"{yc:.1}\" stroke=\"black\"/><line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"black\"/><line x1=\"{:.1}\" y1=\"{:.1}\" x2=\"{:.1}\" y2=\"{:.1}\" stroke=\"black\"/>",
                    x(iv[0]),
                    x(iv[1]),
                    x(iv[0]),
                    yc - 4.0,
                    x(iv[0]),
                    yc + 4.0,
                    x(iv[1]),
                    yc - 4.0,
                    x(iv[1]),
                    yc + 4.0
                );
            }
        }
    }
    let base = top + row * names.len() as f64 + 6.0;
    let _ = writeln!(
        s,
        "<line x1=\"{left}\" y1=\"{base}\" x2=\"{}\" y2=\"{base}\" stroke=\"black\"/>",
        w - right
    );
    // (+ 0.0: a tick at −0 is written 0.)
    let mut t = (lo * 4.0).ceil() / 4.0 + 0.0;
    while t <= hi + 1e-9 {
        let _ = writeln!(
            s,
            "<line x1=\"{0:.1}\" y1=\"{base}\" x2=\"{0:.1}\" y2=\"{1}\" stroke=\"black\"/><text x=\"{0:.1}\" y=\"{2}\" text-anchor=\"middle\">{3}</text>",
            x(t),
            base + 5.0,
            base + 18.0,
            sig_exp(t + 0.0, 2)
        );
        t += 0.25;
    }
    let _ = write!(
        s,
        "<line x1=\"{0:.1}\" y1=\"{top}\" x2=\"{0:.1}\" y2=\"{base}\" stroke=\"#888\" stroke-dasharray=\"3,3\"/>\n</svg>\n",
        x(0.0)
    );
    s
}

/// The empirical distribution function of one output (log axis where every value
/// is positive).
fn cdf_svg(title: &str, quantity: Quantity, sorted: &[f64], label: &str) -> String {
    let n = sorted.len();
    let positive = sorted.first().is_some_and(|&v| v > 0.0);
    let step = (n / 2000).max(1);
    let points: Vec<(f64, f64)> = sorted
        .iter()
        .enumerate()
        .filter(|(k, _)| k % step == 0 || *k + 1 == n)
        .map(|(k, &v)| (v, (k + 1) as f64 / n as f64))
        .collect();
    let unit = quantity.dimension().si_unit();
    let mut xa = if positive {
        Axis::log(quantity.as_str())
    } else {
        Axis::linear(quantity.as_str())
    };
    if !unit.is_empty() {
        xa = xa.with_unit(unit);
    }
    LinePlot::new(title, xa, Axis::linear(label).with_range(0.0, 1.0))
        .with_series(Series::new("sampled parts", points).with_marker(Marker::None))
        .to_svg()
}

/// The HTML page.
pub fn html(doc: &UncertaintyDocument) -> String {
    let mut p = super::html::Page::new(&format!("wearopt uncertainty — {}", doc.name));
    p.paragraph(&format!("Method: {}.", method_words(doc)), None);
    p.paragraph(
        &format!("Seed {}, fingerprint {}.", doc.seed, doc.fingerprint),
        Some("note"),
    );
    p.heading("Uncertain inputs");
    let rows: Vec<Vec<String>> = doc
        .inputs
        .iter()
        .map(|i| {
            vec![
                format!("{} ({})", i.parameter.as_str(), i.parameter.symbol()),
                law_words(i),
            ]
        })
        .collect();
    p.table(&["input", "distribution"], &rows, &[1]);
    let names: Vec<&str> = doc.inputs.iter().map(|i| i.parameter.as_str()).collect();
    for &(a, b, rho) in &doc.correlations {
        p.paragraph(
            &format!(
                "Correlation {} – {}: ρ = {} (Gaussian copula of the normal scores).",
                names[a],
                names[b],
                sig_exp(rho, 3)
            ),
            Some("note"),
        );
    }
    let total = doc.evaluations;
    match &doc.analysis {
        Analysis::Sobol(results) => {
            for (o, r) in doc.outputs.iter().zip(results) {
                p.heading(&format!("Sobol′ indices of {}", o.quantity.as_str()));
                let mut notes = Vec::new();
                if let Some(w) = failure_words(o, total) {
                    notes.push(w);
                }
                if r.status == SobolStatus::Degenerate {
                    notes.push(
                        "No indices: the output does not vary, or too few samples have a value."
                            .into(),
                    );
                    p.list(&notes, "warn");
                    continue;
                }
                if r.wide {
                    notes.push(format!("N too small: an interval is wider than {WIDE_INTERVAL}; raise the samples (the intervals narrow as 1/√N)."));
                }
                if r.first_order.iter().any(|s| s.value < 0.0) {
                    notes.push("A negative S1 is an estimate of an index near 0, shown with its interval as estimated, not clipped.".into());
                }
                p.list(&notes, "warn");
                let first: Vec<(f64, [f64; 2])> = r
                    .first_order
                    .iter()
                    .map(|s| (s.value, s.interval))
                    .collect();
                let tot: Vec<(f64, [f64; 2])> =
                    r.total.iter().map(|s| (s.value, s.interval)).collect();
                p.figure(
                    &format!("sobol-{}", o.quantity.as_str()),
                    &indices_svg(&format!("Sobol′ indices of {}", o.quantity.as_str()), &names, &first, &tot),
                    "First-order (S1: the share of the variance each input causes alone) and total (ST: alone and with the others) indices, with 95 % intervals from the spread between independent scrambles of the design.",
                );
                let rows: Vec<Vec<String>> = names
                    .iter()
                    .enumerate()
                    .map(|(k, n)| {
                        let (s, t) = (&r.first_order[k], &r.total[k]);
                        vec![
                            n.to_string(),
                            index_text(s.value),
                            format!(
                                "[{}, {}]",
                                index_text(s.interval[0]),
                                index_text(s.interval[1])
                            ),
                            index_text(t.value),
                            format!(
                                "[{}, {}]",
                                index_text(t.interval[0]),
                                index_text(t.interval[1])
                            ),
                        ]
                    })
                    .collect();
                p.table(
                    &["input", "S1", "95 % interval", "ST", "95 % interval"],
                    &rows,
                    &[],
                );
            }
        }
        Analysis::Morris(results) => {
            for (o, r) in doc.outputs.iter().zip(results) {
                p.heading(&format!("Morris screening of {}", o.quantity.as_str()));
                if let Some(w) = failure_words(o, total) {
                    p.list(&[w], "warn");
                }
                let rows: Vec<Vec<String>> = names
                    .iter()
                    .enumerate()
                    .map(|(k, n)| {
                        let e = &r.effects[k];
                        vec![n.to_string(), sig_exp(e.mu_star, 4), sig_exp(e.sigma, 4)]
                    })
                    .collect();
                p.table(&["input", "μ*", "σ"], &rows, &[]);
            }
        }
        Analysis::Sampling { summaries, life } => {
            for (o, s) in doc.outputs.iter().zip(summaries) {
                p.heading(&format!("Distribution of {}", o.quantity.as_str()));
                let mut notes = Vec::new();
                if let Some(w) = failure_words(o, total) {
                    notes.push(w);
                }
                p.list(&notes, "warn");
                let d = o.quantity.dimension();
                let rows: Vec<Vec<String>> = statistics(s)
                    .iter()
                    .map(|(l, e)| {
                        vec![
                            l.to_string(),
                            q(e.value, d),
                            format!("[{}, {}]", q(e.interval[0], d), q(e.interval[1], d)),
                        ]
                    })
                    .collect();
                p.table(&["statistic", "value", "95 % interval"], &rows, &[]);
                if beyond_the_sample(s) {
                    p.paragraph(BEYOND, Some("note"));
                }
                if s.sorted.len() >= 2 {
                    p.figure(
                        &format!("cdf-{}", o.quantity.as_str()),
                        &cdf_svg(&format!("Distribution of {}", o.quantity.as_str()), o.quantity, &s.sorted, "fraction of parts at or below"),
                        "The empirical distribution function: the fraction of the sampled parts whose value is at most the abscissa.",
                    );
                }
            }
            if let (Some((quantity, l)), Some(s)) = (
                life,
                life.as_ref().and_then(|(lq, _)| {
                    doc.outputs
                        .iter()
                        .position(|o| o.quantity == *lq)
                        .map(|k| &summaries[k])
                }),
            ) {
                p.heading("Life");
                let d = quantity.dimension();
                let rows: Vec<Vec<String>> = [("B1", &l.b1), ("B10", &l.b10), ("B50", &l.b50)]
                    .iter()
                    .map(|(n, e)| {
                        vec![
                            n.to_string(),
                            q(e.value, d),
                            format!("[{}, {}]", q(e.interval[0], d), q(e.interval[1], d)),
                        ]
                    })
                    .collect();
                p.table(&["life", "value", "95 % interval"], &rows, &[]);
                if s.sorted.len() >= 2 {
                    p.figure(
                        "life",
                        &cdf_svg("Life curve", *quantity, &s.sorted, "fraction of parts worn out"),
                        "The fraction of parts worn out (their wear depth beyond the allowed one) by each life; B1, B10, B50 are where it crosses 1 %, 10 %, 50 %.",
                    );
                }
            }
        }
        Analysis::Reliability(events) => {
            for (event, r) in events {
                p.heading(&format!("Event {}", event.name()));
                p.paragraph(&event_words(event), None);
                p.paragraph(
                    &format!(
                        "Status: {} — {}.",
                        status_name(r.status),
                        status_words(r.status)
                    ),
                    Some("status"),
                );
                let mut t = String::new();
                event_text(&mut t, event, r, doc);
                p.raw(&format!("<pre>{}</pre>", escape(t.trim())));
                let rows: Vec<Vec<String>> = r
                    .form
                    .design_points
                    .iter()
                    .map(|dp| {
                        let mut row = vec![sig_exp(dp.beta, 4)];
                        row.extend(
                            doc.inputs
                                .iter()
                                .zip(&dp.x)
                                .map(|(i, &x)| q(x, i.parameter.dimension())),
                        );
                        row
                    })
                    .collect();
                if !rows.is_empty() {
                    let mut header = vec!["β"];
                    header.extend(names.iter().copied());
                    p.table(&header, &rows, &[]);
                }
            }
        }
    }
    p.finish()
}

/// The document in `format` (one of [`FORMATS`]).
pub fn render(doc: &UncertaintyDocument, format: Format) -> Result<String, FormatError> {
    Ok(match format {
        Format::Text => text(doc),
        Format::Csv => csv(doc),
        Format::Json => json(doc),
        Format::Html => html(doc),
    })
}

// ---------------------------------------------------------------- shards

/// A part (`wearopt uncertainty FILE --shard I/N`) as JSON: the marker
/// `"wearopt": "uncertainty part"` first, the study (fingerprint, version, name,
/// method, samples, samples_asked, seed), the shard, `units` and the `range` of
/// them it holds, `points_per_unit`, `outputs`, the problem (`origin`, `problem`:
/// its text), then `points`, one line each: a value per output, or the name of
/// the cause of its absence (`separated`, `not_converged`, `out_of_range`,
/// `undefined`). Values are written in the fewest digits that read back to the
/// same bits.
pub fn part_json(part: &UncertaintyPart) -> String {
    let s = |v: Value| serde_json::to_string(&v).unwrap_or_else(|_| "null".into());
    let mut out = format!(
        "{{\n  \"wearopt\": {},\n  \"fingerprint\": {},\n  \"version\": {},\n  \"name\": {},\n  \"method\": {},\n  \"samples\": {},\n  \"samples_asked\": {},\n  \"seed\": {},\n  \"shard\": {},\n  \"units\": {},\n  \"range\": [{}, {}],\n  \"points_per_unit\": {},\n  \"outputs\": {},\n  \"origin\": {},\n  \"problem\": {},\n  \"points\": [",
        s(json!(PART_MARKER)),
        s(json!(part.fingerprint)),
        s(json!(part.version)),
        s(json!(part.name)),
        s(json!(part.method.as_str())),
        part.samples,
        s(json!(part.samples_asked)),
        part.seed,
        s(json!(format!("{}/{}", part.shard.index, part.shard.count))),
        part.units,
        part.range.start,
        part.range.end,
        part.points_per_unit,
        s(json!(part.outputs)),
        s(json!(part.origin)),
        s(json!(part.problem)),
    );
    for (k, point) in part.points.iter().enumerate() {
        out.push_str(if k == 0 { "\n    [" } else { ",\n    [" });
        for (o, v) in point.iter().enumerate() {
            if o > 0 {
                out.push(',');
            }
            match v {
                Ok(x) => out.push_str(&s(json!(x))),
                Err(c) => out.push_str(&s(json!(c.as_str()))),
            }
        }
        out.push(']');
    }
    out.push_str(if part.points.is_empty() {
        "]\n}\n"
    } else {
        "\n  ]\n}\n"
    });
    out
}

/// True when `text` looks like a part: a JSON object whose first key is
/// `wearopt` ([`parse_part`] checks the rest).
pub fn is_part(text: &str) -> bool {
    text.trim_start_matches('\u{feff}')
        .trim_start()
        .strip_prefix('{')
        .is_some_and(|rest| rest.trim_start().starts_with("\"wearopt\""))
}

/// Reads a part written by [`part_json`] (or the same object with other
/// spacing or key order, as Python's `json.dumps` of the dict writes it).
pub fn parse_part(text: &str) -> Result<UncertaintyPart, PartError> {
    let bad = |m: String| PartError::NotAPart(m);
    let v: Value = serde_json::from_str(text.trim_start_matches('\u{feff}'))
        .map_err(|e| bad(format!("not JSON ({e})")))?;
    let o = v
        .as_object()
        .ok_or_else(|| bad("not a JSON object".into()))?;
    if o.get("wearopt").and_then(Value::as_str) != Some(PART_MARKER) {
        return Err(bad(format!(
            "no \"wearopt\": \"{PART_MARKER}\" key (a sweep part? those merge apart)"
        )));
    }
    let field = |key: &str| o.get(key).ok_or_else(|| bad(format!("no \"{key}\"")));
    let text_of = |key: &str| -> Result<String, PartError> {
        field(key)?
            .as_str()
            .map(str::to_string)
            .ok_or_else(|| bad(format!("\"{key}\" is not a string")))
    };
    let int = |v: &Value, key: &str| -> Result<u64, PartError> {
        v.as_u64()
            .ok_or_else(|| bad(format!("\"{key}\" is not a non-negative integer")))
    };
    let method_name = text_of("method")?;
    let method = Method::ALL
        .into_iter()
        .find(|m| m.as_str() == method_name)
        .ok_or_else(|| bad(format!("\"method\": unknown {method_name:?}")))?;
    let shard = text_of("shard")?;
    let shard = shard
        .split_once('/')
        .and_then(|(i, n)| Shard::new(i.parse().ok()?, n.parse().ok()?).ok())
        .ok_or_else(|| bad(format!("\"shard\": {shard:?} is not I/N with I < N")))?;
    let range = match field("range")?.as_array().map(Vec::as_slice) {
        Some([a, b]) => int(a, "range")?..int(b, "range")?,
        _ => return Err(bad("\"range\" is not [start, end]".into())),
    };
    let samples_asked = match field("samples_asked")? {
        Value::Null => None,
        v => Some(int(v, "samples_asked")?),
    };
    let outputs = field("outputs")?
        .as_array()
        .and_then(|a| {
            a.iter()
                .map(|v| v.as_str().map(str::to_string))
                .collect::<Option<Vec<_>>>()
        })
        .ok_or_else(|| bad("\"outputs\" is not a list of names".into()))?;
    let value = |v: &Value| -> Option<Result<f64, Cause>> {
        match v {
            Value::Number(n) => n.as_f64().map(Ok),
            Value::String(c) => Cause::named(c).map(Err),
            _ => None,
        }
    };
    let points = field("points")?
        .as_array()
        .ok_or_else(|| bad("\"points\" is not a list".into()))?
        .iter()
        .enumerate()
        .map(|(k, p)| {
            p.as_array()
                .and_then(|vs| vs.iter().map(value).collect::<Option<Vec<_>>>())
                .ok_or_else(|| {
                    bad(format!(
                        "point {k} is not a list of numbers and causes (separated, not_converged, out_of_range, undefined)"
                    ))
                })
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(UncertaintyPart {
        fingerprint: text_of("fingerprint")?,
        version: text_of("version")?,
        name: text_of("name")?,
        method,
        samples: int(field("samples")?, "samples")?,
        samples_asked,
        seed: int(field("seed")?, "seed")?,
        shard,
        units: int(field("units")?, "units")?,
        range,
        points_per_unit: int(field("points_per_unit")?, "points_per_unit")? as usize,
        outputs,
        origin: text_of("origin")?,
        problem: text_of("problem")?,
        points,
    })
}
