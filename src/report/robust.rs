//! The robust part of `wearopt optimize`'s report (docs/uncertainty.md, "Designs
//! that hold in most parts"): the robust optimum beside the nominal one, the
//! statistic with its sampling interval at both, each chance constraint's target
//! beside its sampled probability, and the objective's distribution at both.

use serde_json::{json, Map, Value};

use super::svg::{Axis, LinePlot, Marker, Series};
use super::{sig, sig_exp};
use crate::app::robust::{ObjectiveSample, RobustOutcome};
use crate::optimize::{Objective, Optimum};
use crate::units::format_quantity;
use crate::uq::reliability::{EventResult, SamplingMethod};
use crate::uq::robust::{RobustStatus, Statistic};
use crate::uq::Estimate;

/// What the statistic reads as: "p95 of wear_rate".
fn statistic_name(r: &RobustOutcome, o: Objective) -> String {
    match r.statistic {
        Some(s) => format!("{} of {}", s.as_str(), o.as_str()),
        None => format!("{} at the medians", o.as_str()),
    }
}

/// The sentence behind a robust status.
fn verdict(r: &RobustOutcome) -> String {
    let res = &r.result;
    match res.status {
        RobustStatus::Optimal => format!(
            "optimal: SORA converged in {} cycle{}, the last solve met its KKT test (tolerance {}) and every sampled probability meets its target",
            res.cycles,
            if res.cycles == 1 { "" } else { "s" },
            sig_exp(r.tolerance, 1)
        ),
        RobustStatus::ChanceConstraintViolated => {
            "chance_constraint_violated: the design meets each target by FORM, but sampling at the design finds a probability above its target beyond its 95 % interval (below): FORM is unconservative here. Set [uncertainty] verify = \"correct\" to move the target by the sampled excess and solve again".to_string()
        }
        RobustStatus::Infeasible => {
            "infeasible: no design meets every constraint with its shifted chance constraints; the least-violating design is shown".to_string()
        }
        RobustStatus::IterationLimit => {
            "iteration_limit: the last solve stopped at max_iterations before its KKT test was met".to_string()
        }
        RobustStatus::TimeLimit => {
            "time_limit: stopped by the study's time_limit before the KKT test was met".to_string()
        }
        RobustStatus::Stalled => {
            "stalled: the last solve made no further progress, but its KKT test was not met".to_string()
        }
        RobustStatus::CycleLimit => format!(
            "cycle_limit: the most probable target points still moved after {} SORA cycles",
            res.cycles
        ),
    }
}

pub(crate) fn estimate_words(e: &Estimate, unit: &str) -> String {
    if !e.value.is_finite() {
        return "—".into();
    }
    let f = |x: f64| {
        if x.is_finite() {
            super::si(x, unit, 3)
        } else {
            "beyond the sample".into()
        }
    };
    format!(
        "{} [{}, {}]",
        super::si(e.value, unit, 4),
        f(e.interval[0]),
        f(e.interval[1])
    )
}

pub(crate) fn probability_words(a: &EventResult) -> String {
    match (a.probability, a.interval, a.upper_bound) {
        (_, _, Some(b)) => format!("< {} (no failure seen)", sig_exp(b, 2)),
        (Some(p), Some(i), _) => format!(
            "{} [{}, {}]",
            sig_exp(p, 3),
            sig_exp(i[0], 3),
            sig_exp(i[1], 3)
        ),
        (Some(p), None, _) => sig_exp(p, 3),
        _ => "—".into(),
    }
}

pub(crate) fn method_word(a: &EventResult) -> &'static str {
    match a.sampling.as_ref().map(|s| s.method) {
        Some(SamplingMethod::ImportanceSampling) => "importance sampling",
        Some(SamplingMethod::MonteCarlo) => "Monte Carlo",
        None => "FORM",
    }
}

/// The robust section of the text report, put before the nominal optimum's.
pub fn text(name: &str, r: &RobustOutcome, nominal: &Optimum) -> String {
    let mut out = String::new();
    let mut line = |s: String| {
        out.push_str(&s);
        out.push('\n');
    };
    let o = nominal.objective_name;
    let unit = super::objective_unit(o);
    line(format!(
        "wearopt optimize — {} (a design under scatter: {})",
        name,
        statistic_name(r, o)
    ));
    line(String::new());
    line(format!("Robust optimum — status: {}", verdict(r)));
    line(String::new());
    line(format!(
        "{:<18} {:>16} {:>16} {:>16}",
        "design", "robust", "nominal optimum", "baseline"
    ));
    for (i, n) in nominal.names.iter().enumerate() {
        let d = super::design_dimension(*n);
        line(format!(
            "{:<18} {:>16} {:>16} {:>16}",
            n,
            format_quantity(r.design[i], d),
            format_quantity(nominal.design[i], d),
            format_quantity(nominal.baseline_design[i], d)
        ));
    }
    line(String::new());
    let stat = r.statistic.unwrap_or(Statistic::Mean);
    line(format!(
        "{} over {} common random numbers (95 % interval):",
        stat.as_str(),
        r.samples
    ));
    line(format!(
        "  {:<28} {:>40} {:>40}",
        "", "robust", "nominal optimum"
    ));
    line(format!(
        "  {:<28} {:>40} {:>40}",
        format!("{} of {}", stat.as_str(), o.as_str()),
        estimate_words(&r.robust_sample.statistic, unit),
        estimate_words(&r.nominal_sample.statistic, unit)
    ));
    line(format!(
        "  {:<28} {:>40} {:>40}",
        format!("{} at the medians", o.as_str()),
        super::si(r.robust_sample.nominal, unit, 4),
        super::si(r.nominal_sample.nominal, unit, 4)
    ));
    let ratio = |a: f64, b: f64| (a.is_finite() && b > 0.0).then(|| sig(a / b, 3));
    let mut costs = Vec::new();
    if let Some(x) = ratio(r.robust_sample.nominal, r.nominal_sample.nominal) {
        costs.push(format!(
            "×{x} the nominal optimum's {} at the medians",
            o.as_str()
        ));
    }
    if r.statistic.is_some() {
        if let Some(x) = ratio(
            r.robust_sample.statistic.value,
            r.nominal_sample.statistic.value,
        ) {
            costs.push(format!("×{x} its {}", stat.as_str()));
        }
    }
    if !costs.is_empty() {
        line(format!("  the robust design has {}", costs.join(", and ")));
    }
    if let Some(v) = &r.result.objective_verified {
        line(format!(
            "  checked on an independent sample of {}: {} {}",
            crate::uq::robust::RobustSettings::default().verify_samples,
            stat.as_str(),
            estimate_words(v, unit)
        ));
    }
    for (what, s) in [
        ("robust", &r.robust_sample),
        ("nominal optimum", &r.nominal_sample),
    ] {
        if s.failed > 0 {
            line(format!(
                "  at the {what} design {} of {} samples gave no value (the model failed there); the statistic leaves them out",
                s.failed,
                s.failed + s.values.len()
            ));
        }
    }
    if !r.result.chance.is_empty() {
        line(String::new());
        line(format!(
            "{:<28} {:>10} {:>8} {:>8} {:>32} {:>20} {:>10}",
            "chance constraint",
            "target",
            "β target",
            "FORM β",
            "sampled P [95 % interval]",
            "method",
            "verdict"
        ));
        for (c, event) in r.result.chance.iter().zip(&r.labels) {
            let a = &c.verification;
            line(format!(
                "{:<28} {:>10} {:>8} {:>8} {:>32} {:>20} {:>10}",
                format!("P({}) ≤", event),
                sig_exp(c.target, 2),
                sig(c.target_beta, 4),
                c.form_beta.map_or("—".into(), |b| sig(b, 4)),
                probability_words(a),
                method_word(a),
                if c.violated { "VIOLATED" } else { "met" }
            ));
            if c.violated {
                if let Some(e) = c.excess {
                    line(format!(
                        "  P({}) is {} % above its target at the robust design",
                        event,
                        sig(100.0 * e, 3)
                    ));
                }
            }
            if let Some(t) = c.corrected_target {
                line(format!(
                    "  corrected: the design was solved for a target of {} (β {}) so that the sampled probability meets {}",
                    sig_exp(t, 3),
                    sig(c.pma_beta, 4),
                    sig_exp(c.target, 2)
                ));
            }
        }
        for (e, label) in r.nominal_events.iter().zip(&r.labels) {
            line(format!(
                "  at the nominal optimum: P({}) = {} ({}), against its target {}",
                label,
                probability_words(&e.analysis),
                method_word(&e.analysis),
                sig_exp(e.target, 2)
            ));
        }
    }
    line(String::new());
    line(format!(
        "SORA: {} cycle{}, {} correction round{}; KKT residual {} of the last solve (tolerance {}); {} model evaluations; {} s",
        r.result.cycles,
        if r.result.cycles == 1 { "" } else { "s" },
        r.result.corrections,
        if r.result.corrections == 1 { "" } else { "s" },
        sig_exp(r.result.sqp.kkt_residual, 3),
        sig_exp(r.tolerance, 1),
        r.result.evaluations,
        sig(r.time_seconds, 3)
    ));
    line(String::new());
    line(
        "The nominal optimum (every input at its nominal value), as a nominal study reports it:"
            .into(),
    );
    line(String::new());
    out
}

pub(crate) fn estimate_json(e: &Estimate) -> Value {
    let f = |x: f64| x.is_finite().then_some(x);
    json!({
        "value": f(e.value),
        "interval": [f(e.interval[0]), f(e.interval[1])],
    })
}

fn event_json(name: &str, target: f64, a: &EventResult) -> Value {
    json!({
        "event": name,
        "target": target,
        "status": a.status,
        "probability": a.probability,
        "probability_interval": a.interval,
        "upper_bound": a.upper_bound,
        "method": a.sampling.as_ref().map(|s| s.method),
        "beta": a.beta,
        "form_probability": a.form.probability,
        "evaluations": a.evaluations,
    })
}

fn sample_json(s: &ObjectiveSample) -> Value {
    let pick = |p: f64| {
        let n = s.values.len();
        (n > 0).then(|| s.values[((p * (n - 1) as f64).round() as usize).min(n - 1)])
    };
    json!({
        "statistic": estimate_json(&s.statistic),
        "at_medians": s.nominal.is_finite().then_some(s.nominal),
        "failed": s.failed,
        "min": s.values.first(),
        "p50": pick(0.5),
        "max": s.values.last(),
    })
}

/// The `robust` object of the JSON document (SI units).
pub fn json_value(r: &RobustOutcome, nominal: &Optimum) -> Value {
    let names = &r.inputs;
    let mut design = Map::new();
    for (n, v) in nominal.names.iter().zip(&r.design) {
        design.insert(n.as_str().into(), json!(v));
    }
    let chance: Vec<Value> = r
        .result
        .chance
        .iter()
        .zip(&r.events)
        .map(|(c, event)| {
            let mut v = event_json(event, c.target, &c.verification);
            let mptp: Map<String, Value> = names
                .iter()
                .zip(&c.mptp.x)
                .map(|(n, x)| (n.as_str().to_string(), json!(x)))
                .collect();
            if let Value::Object(m) = &mut v {
                m.insert("target_beta".into(), json!(c.target_beta));
                m.insert("pma_beta".into(), json!(c.pma_beta));
                m.insert("corrected_target".into(), json!(c.corrected_target));
                m.insert("form_beta".into(), json!(c.form_beta));
                m.insert("violated".into(), json!(c.violated));
                m.insert("excess".into(), json!(c.excess));
                m.insert("most_probable_target_point".into(), Value::Object(mptp));
            }
            v
        })
        .collect();
    let nominal_chance: Vec<Value> = r
        .nominal_events
        .iter()
        .map(|e| event_json(&e.event, e.target, &e.analysis))
        .collect();
    json!({
        "status": r.result.status.as_str(),
        "statistic": r.statistic.map(|s| s.as_str()),
        "samples": r.samples,
        "design": design,
        "evaluation": super::words::evaluation_json(&r.evaluation),
        "warnings": super::words::warnings(&r.evaluation),
        "objective": estimate_json(&r.result.objective),
        "objective_verified": r.result.objective_verified.as_ref().map(estimate_json),
        "at_robust_design": sample_json(&r.robust_sample),
        "at_nominal_optimum": sample_json(&r.nominal_sample),
        "chance_constraints": chance,
        "chance_at_nominal_optimum": nominal_chance,
        "cycles": r.result.cycles,
        "corrections": r.result.corrections,
        "evaluations": r.result.evaluations,
        "kkt_residual": r.result.sqp.kkt_residual,
        "tolerance": r.tolerance,
        "time_seconds": r.time_seconds,
        "history": r.result.history,
    })
}

/// The objective's CDF at both designs.
pub fn distribution_svg(r: &RobustOutcome, o: Objective) -> String {
    let cdf = |s: &ObjectiveSample| -> Vec<(f64, f64)> {
        let n = s.values.len();
        s.values
            .iter()
            .enumerate()
            .filter(|(_, v)| **v > 0.0)
            .map(|(k, &v)| (v, (k + 1) as f64 / n as f64))
            .collect()
    };
    let unit = o.quantity().dimension().si_unit();
    let all = r
        .robust_sample
        .values
        .iter()
        .chain(&r.nominal_sample.values);
    let (lo, hi) = all
        .filter(|v| **v > 0.0)
        .fold((f64::INFINITY, 0.0_f64), |(a, b), &v| (a.min(v), b.max(v)));
    // Within a decade a linear axis shows the shapes; a log axis squeezes them.
    let mut x = if hi > 0.0 && hi < 10.0 * lo {
        Axis::linear(o.as_str())
    } else {
        Axis::log(o.as_str())
    };
    if !unit.is_empty() {
        x = x.with_unit(unit);
    }
    LinePlot::new(
        format!(
            "{} over the scatter: robust against nominal optimum",
            o.as_str()
        ),
        x,
        Axis::linear("fraction of parts at or below").with_range(0.0, 1.0),
    )
    .with_series(Series::new("robust design", cdf(&r.robust_sample)).with_marker(Marker::None))
    .with_series(Series::new("nominal optimum", cdf(&r.nominal_sample)).with_marker(Marker::None))
    .to_svg()
}

/// The robust section of the HTML page.
pub fn html_section(p: &mut super::html::Page, r: &RobustOutcome, nominal: &Optimum) {
    let o = nominal.objective_name;
    let unit = super::objective_unit(o);
    p.heading("Robust optimum");
    p.paragraph(&format!("Status: {}", verdict(r)), Some("status"));
    let rows: Vec<Vec<String>> = nominal
        .names
        .iter()
        .enumerate()
        .map(|(i, n)| {
            let d = super::design_dimension(*n);
            vec![
                n.to_string(),
                format_quantity(r.design[i], d),
                format_quantity(nominal.design[i], d),
                format_quantity(nominal.baseline_design[i], d),
            ]
        })
        .collect();
    p.table(
        &["variable", "robust", "nominal optimum", "baseline"],
        &rows,
        &[],
    );
    let stat = r.statistic.unwrap_or(Statistic::Mean);
    p.table(
        &["", "robust", "nominal optimum"],
        &[
            vec![
                format!("{} of {} (95 % interval)", stat.as_str(), o.as_str()),
                estimate_words(&r.robust_sample.statistic, unit),
                estimate_words(&r.nominal_sample.statistic, unit),
            ],
            vec![
                format!("{} at the medians", o.as_str()),
                super::si(r.robust_sample.nominal, unit, 4),
                super::si(r.nominal_sample.nominal, unit, 4),
            ],
        ],
        &[0],
    );
    if !r.result.chance.is_empty() {
        let rows: Vec<Vec<String>> = r
            .result
            .chance
            .iter()
            .zip(&r.labels)
            .zip(&r.nominal_events)
            .map(|((c, event), at_nominal)| {
                vec![
                    event.clone(),
                    sig_exp(c.target, 2),
                    c.form_beta.map_or("—".into(), |b| sig(b, 4)),
                    probability_words(&c.verification),
                    method_word(&c.verification).to_string(),
                    if c.violated { "VIOLATED" } else { "met" }.to_string(),
                    probability_words(&at_nominal.analysis),
                ]
            })
            .collect();
        p.table(
            &[
                "event",
                "target",
                "FORM β",
                "sampled P [95 %]",
                "method",
                "verdict",
                "P at the nominal optimum",
            ],
            &rows,
            &[0, 4, 5],
        );
    }
    p.figure(
        "robust-distribution",
        &distribution_svg(r, o),
        &format!(
            "The distribution of {} over {} sampled parts at the robust design and at the nominal optimum.",
            o.as_str(),
            r.samples
        ),
    );
    p.heading("Nominal optimum");
}
