//! The report of a design study (`wearopt optimize`): text, JSON, and the
//! per-iteration trace as CSV.

use serde_json::{json, Map, Value};

use super::format::FormatError;
use super::{si, sig, sig_exp};
use crate::app::optimize::{
    BaselineViolation, LawOutsideRegime, OptimizeDocument, OptimizeOptions,
};
use crate::optimize::{ConstraintQuantity, Objective, SceneParameter, Side};
use crate::optimize::{OptimizationStatus, Optimum};
use crate::units::format_quantity;

/// The formats `wearopt optimize` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[
    super::Format::Text,
    super::Format::Json,
    super::Format::Html,
];

/// What `optimize` needs computed for `format`.
pub fn options<'a>(format: super::Format) -> OptimizeOptions<'a> {
    OptimizeOptions {
        observers: None,
        load_curve_points: (format == super::Format::Html)
            .then_some(crate::app::eval::LOAD_CURVE_POINTS),
    }
}

/// The document in `format` (one of [`FORMATS`]): an optimum, or a ranking of
/// materials ([`super::materials`]).
pub fn render(doc: &OptimizeDocument, format: super::Format) -> Result<String, FormatError> {
    match (doc, format) {
        (
            OptimizeDocument::Optimum {
                name,
                optimum,
                baseline_violations,
                robust,
                law_regime,
                ..
            },
            super::Format::Text,
        ) => {
            let nominal = text(name, optimum, baseline_violations, law_regime.as_ref());
            Ok(match robust {
                Some(r) => super::robust::text(name, r, optimum) + &nominal,
                None => nominal,
            })
        }
        (OptimizeDocument::Optimum { .. }, super::Format::Json) => {
            Ok(super::json_text(&json_document(doc)))
        }
        (
            OptimizeDocument::Optimum {
                name,
                optimum,
                baseline_violations,
                load_curve,
                robust,
                law_regime,
            },
            super::Format::Html,
        ) => Ok(html(
            name,
            optimum,
            baseline_violations,
            load_curve.as_ref(),
            robust.as_deref(),
            law_regime.as_ref(),
        )),
        (OptimizeDocument::Ranking { name, ranking }, super::Format::Text) => {
            Ok(super::materials::text(name, ranking))
        }
        (OptimizeDocument::Ranking { name, ranking }, super::Format::Json) => Ok(super::json_text(
            &super::materials::json_value(name, ranking),
        )),
        (OptimizeDocument::Ranking { name, ranking }, super::Format::Html) => {
            Ok(super::materials::html(name, ranking))
        }
        (_, given) => Err(FormatError::NotRendered {
            command: "optimize",
            given,
            accepted: FORMATS,
        }),
    }
}

/// The JSON document as a value (what Python reads).
pub fn json_document(doc: &OptimizeDocument) -> Value {
    match doc {
        OptimizeDocument::Optimum {
            name,
            optimum,
            baseline_violations,
            robust,
            law_regime,
            ..
        } => {
            let mut v = json_value(name, optimum, baseline_violations, law_regime.as_ref());
            if let (Some(r), Value::Object(obj)) = (robust, &mut v) {
                obj.insert("robust".into(), super::robust::json_value(r, optimum));
            }
            v
        }
        OptimizeDocument::Ranking { name, ranking } => super::materials::json_value(name, ranking),
    }
}

/// The per-iteration trace as CSV (of every optimised material for a ranking).
pub fn trace(doc: &OptimizeDocument) -> String {
    match doc {
        OptimizeDocument::Optimum { optimum, .. } => trace_csv(optimum),
        OptimizeDocument::Ranking { ranking, .. } => super::materials::trace_csv(ranking),
    }
}

/// How a side of a constraint reads: "min" or "max".
fn side_word(side: Side) -> &'static str {
    match side {
        Side::Min => "min",
        Side::Max => "max",
    }
}

/// A constraint's value or limit with its unit.
fn constraint_quantity(q: ConstraintQuantity, x: f64) -> String {
    use crate::problem::Dimensioned;
    crate::units::quantity(x, q.dimension(), 4)
}

fn design_object(names: &[SceneParameter], values: &[f64]) -> Value {
    let mut m = Map::new();
    for (n, v) in names.iter().zip(values) {
        m.insert(n.as_str().to_string(), json!(v));
    }
    Value::Object(m)
}

/// One JSON object, SI units.
pub fn json(
    name: &str,
    o: &Optimum,
    broken: &[BaselineViolation],
    law: Option<&LawOutsideRegime>,
) -> String {
    super::json_text(&json_value(name, o, broken, law))
}

/// The object [`json()`] writes, as a value. With `law` (the study's law outside
/// its regime at the optimum) it gains `law_regime`: `law`, `tabor_parameter`,
/// `valid_tabor_min`, `valid_tabor_max` (null: no bound), `law_that_holds`,
/// `note` and `rerun` (the text report's words); without, the key is absent.
pub fn json_value(
    name: &str,
    o: &Optimum,
    broken: &[BaselineViolation],
    law: Option<&LawOutsideRegime>,
) -> Value {
    let mut v = json_fields(name, o, broken);
    if let (Some(l), Value::Object(obj)) = (law, &mut v) {
        let bound = |x: f64| if x.is_finite() { json!(x) } else { Value::Null };
        obj.insert(
            "law_regime".into(),
            json!({
                "law": l.law.as_str(),
                "tabor_parameter": l.tabor_parameter,
                "valid_tabor_min": bound(l.valid_tabor.0),
                "valid_tabor_max": bound(l.valid_tabor.1),
                "law_that_holds": l.law_that_holds.as_str(),
                "note": format!("{}; {}", outside_words(l), consequence_words(l)),
                "rerun": rerun_words(l),
            }),
        );
    }
    if let (Some(h), Value::Object(obj)) = (o.objective_humidity, &mut v) {
        obj.insert("objective_humidity".into(), json!(h));
    }
    if let (true, Value::Object(obj)) = (o.scene.real_area_scale != 1.0, &mut v) {
        obj.insert("real_area_scale".into(), json!(o.scene.real_area_scale));
    }
    v
}

fn json_fields(name: &str, o: &Optimum, broken: &[BaselineViolation]) -> Value {
    json!({
        "name": name,
        "status": o.status.as_str(),
        "objective_name": o.objective_name,
        "objective": o.objective,
        "baseline_objective": o.baseline_objective,
        "improvement_factor": o.baseline_objective / o.objective,
        "design": design_object(&o.names, &o.design),
        "baseline_design": design_object(&o.names, &o.baseline_design),
        "wear_rate": o.evaluation.wear_rate,
        "baseline_wear_rate": o.baseline_evaluation.as_ref().map(|e| e.wear_rate),
        "constraints": o.constraints,
        "active_bounds": o.active_bounds,
        "conflicting_constraints": o.conflicting,
        "kkt_residual": o.kkt_residual,
        "gradient_error": o.gradient_error,
        "evaluations": o.evaluations,
        "starts": o.starts,
        "best_start": o.best_start,
        "time_seconds": o.time_seconds,
        "evaluation": super::words::evaluation_json(&o.evaluation),
        "warnings": super::words::warnings(&o.evaluation),
        "baseline_feasible": broken.is_empty(),
        "baseline_violations": broken.iter().map(|b| json!({
            "quantity": b.quantity,
            "value": b.value,
            "limit": b.limit,
            "side": side_word(b.side),
        })).collect::<Vec<_>>(),
    })
}

pub use super::trace::trace_csv;

/// "outside the JKR law's regime at the optimum: φ0 = 0.0161 < 3": what follows
/// the status word on the status line.
fn outside_words(l: &LawOutsideRegime) -> String {
    let (lo, hi) = l.valid_tabor;
    let side = if l.tabor_parameter < lo {
        format!("< {lo}")
    } else {
        format!("> {hi}")
    };
    format!(
        "outside the {} law's regime at the optimum: φ0 = {} {side}",
        l.law.label(),
        sig_exp(l.tabor_parameter, 3)
    )
}

/// Where the law is exact and what leaving it costs.
fn consequence_words(l: &LawOutsideRegime) -> String {
    let (lo, hi) = l.valid_tabor;
    let exact = if hi.is_finite() {
        format!("φ0 ≤ {hi}")
    } else {
        format!("φ0 ≥ {lo}")
    };
    format!(
        "the {} law is exact for {exact} only, so this optimum's adhesion (the pull-off above all) may be far from the truth",
        l.law.label()
    )
}

/// The edit and the command that re-run the study under the law that holds.
fn rerun_words(l: &LawOutsideRegime) -> String {
    format!(
        "re-run under the {} law, which holds at every φ0: set [interface] adhesion_model = \"{}\" in {}, then wearopt optimize {}",
        l.law_that_holds.label(),
        l.law_that_holds.as_str(),
        l.origin,
        l.origin
    )
}

/// A report for people. With `law` (the study's law outside its regime at the
/// optimum) the status line says so and the line under it gives the re-run.
pub fn text(
    name: &str,
    o: &Optimum,
    broken: &[BaselineViolation],
    law: Option<&LawOutsideRegime>,
) -> String {
    let mut out = String::new();
    let mut line = |s: String| {
        out.push_str(&s);
        out.push('\n');
    };
    line(format!("wearopt optimize — {name}"));
    if let Some(n) = super::words::real_area_scale_note(o.scene.real_area_scale) {
        line(n);
    }
    line(String::new());
    let verdict = match o.status {
        OptimizationStatus::Optimal => {
            "optimal: the KKT conditions hold to tolerance at a feasible design"
        }
        OptimizationStatus::Infeasible => {
            "infeasible: no design meets every constraint; the least-violating design is shown"
        }
        OptimizationStatus::IterationLimit => {
            "iteration_limit: stopped by max_iterations before the KKT test was met"
        }
        OptimizationStatus::TimeLimit => {
            "time_limit: stopped by time_limit before the KKT test was met"
        }
        OptimizationStatus::Stalled => {
            "stalled: no further progress was possible, but the KKT test was not met"
        }
    };
    match (law, verdict.split_once(": ")) {
        (Some(l), Some((word, rest))) => {
            line(format!("Status: {word} ({}): {rest}", outside_words(l)));
            line(format!("  {}; {}", consequence_words(l), rerun_words(l)));
        }
        _ => line(format!("Status: {verdict}")),
    }
    line(String::new());
    line(format!(
        "{:<18} {:>16} {:>16}",
        "design", "optimum", "baseline"
    ));
    for ((n, v), b) in o.names.iter().zip(&o.design).zip(&o.baseline_design) {
        let d = super::design_dimension(*n);
        line(format!(
            "{:<18} {:>16} {:>16}",
            n,
            format_quantity(*v, d),
            format_quantity(*b, d)
        ));
    }
    for b in &o.active_bounds {
        line(format!(
            "  bound active: {} at its {} ({})",
            b.variable,
            b.side,
            format_quantity(b.value, super::design_dimension(b.variable))
        ));
    }
    if !o.active_bounds.is_empty() && o.active_bounds.len() == o.names.len() {
        line("  every variable sits on a bound: the optimum is a corner of the design box".into());
    }
    line(String::new());
    let unit = super::objective_unit(o.objective_name);
    if o.baseline_evaluation.is_none() {
        line(format!(
            "{}: {} at the optimum; the baseline has no contact (the load pulls its surfaces apart)",
            o.objective_name,
            si(o.objective, unit, 4),
        ));
    } else {
        if let Some(h) = o.objective_humidity {
            line(format!(
                "{} taken at RH = {} % (the range's humidity where it is worst at the baseline, or the file's design_humidity); every limit holds at each humidity of the range",
                o.objective_name,
                sig(100.0 * h, 4)
            ));
        }
        line(format!(
            "{}: {} at the optimum, {} at the baseline{}",
            o.objective_name,
            si(o.objective, unit, 4),
            si(o.baseline_objective, unit, 4),
            if o.objective == 0.0 && o.baseline_objective > 0.0 && unit.starts_with("m³") {
                // A ratio would be ×inf: say why nothing wears (or why the wear is
                // too small for a double), and that the optimum is then one of
                // many designs.
                let log10 = o.evaluation.log10_wear_rate
                    + match o.objective_name {
                        Objective::WearVolume if o.scene.sliding_distance > 0.0 => {
                            o.scene.sliding_distance.log10()
                        }
                        _ => 0.0,
                    };
                if log10.is_finite() {
                    format!(
                        "\n  (10^{} {unit} at the optimum, below the smallest number a double holds: {}; every design this far down is as good to the optimiser, and this is one of them)",
                        sig(log10, 5),
                        super::tiny_wear_reason(&o.scene)
                    )
                } else {
                    format!(
                        "\n  (zero at the optimum: {}; every design where that holds wears nothing, and this is one of them)",
                        super::zero_wear_reason(&o.scene)
                    )
                }
            } else if broken.is_empty() {
                format!(
                    " (improvement ×{})",
                    sig(o.baseline_objective / o.objective, 4)
                )
            } else {
                String::new()
            }
        ));
    }
    for b in broken {
        line(format!(
            "  the baseline is INFEASIBLE: {} = {} breaks its {} of {}{}",
            b.quantity,
            b.value
                .map_or("(undefined)".to_string(), |v| constraint_quantity(
                    b.quantity, v
                )),
            side_word(b.side),
            constraint_quantity(b.quantity, b.limit),
            if !o.feasible() {
                ""
            } else {
                "; the optimum meets every limit, so compare it with feasible designs, not with the baseline"
            }
        ));
    }
    if o.objective_name != Objective::WearRate {
        line(format!(
            "wear rate: {} at the optimum, {} at the baseline",
            si(o.evaluation.wear_rate, "m³/m", 4),
            o.baseline_evaluation
                .as_ref()
                .map_or("—".into(), |e| si(e.wear_rate, "m³/m", 4))
        ));
    }
    let infeasible = o.status == OptimizationStatus::Infeasible;
    let price = |v: f64| price(o, v);
    if !o.constraints.is_empty() {
        line(String::new());
        line(format!(
            "{:<22} {:>14} {:>12} {:>12} {:>7} {:>12} {:>14}",
            "constraint", "value", "min", "max", "active", "multiplier", "shadow price"
        ));
        for c in &o.constraints {
            let f = |x: Option<f64>| {
                x.map_or("—".to_string(), |v| constraint_quantity(c.quantity, v))
            };
            line(format!(
                "{:<22} {:>14} {:>12} {:>12} {:>7} {:>12} {:>14}",
                c.quantity,
                f(c.value),
                f(c.min),
                f(c.max),
                if c.active { "yes" } else { "no" },
                price(c.multiplier),
                price(c.shadow_price)
            ));
            if let Some(h) = c.humidity {
                line(format!(
                    "  {} holds at each humidity of the range; it binds at RH = {} % (the value shown)",
                    c.quantity,
                    sig(100.0 * h, 4)
                ));
            }
        }
        if infeasible {
            line("  no multiplier or shadow price: the least-violating design is no optimum, so they have no meaning there".into());
        } else {
            line("  shadow price = d ln(objective) / d ln(limit): relaxing a limit by 1 % changes the objective by about that many per cent".into());
        }
    }
    if !o.conflicting.is_empty() {
        line(format!(
            "  conflicting constraints (violated, or at their limit, at the least-violating design): {}",
            conflict_names(o)
        ));
    }
    let warnings = super::words::warnings(&o.evaluation);
    if !warnings.is_empty() {
        line(String::new());
        line("Warnings at the optimum".into());
        for w in warnings {
            line(format!("  WARNING: {w}"));
        }
    }
    line(String::new());
    line(format!(
        "KKT residual {} (finite-difference gradient error ≈ {}); {} model evaluations; {} s",
        sig_exp(o.kkt_residual, 3),
        sig_exp(o.gradient_error, 2),
        o.evaluations,
        sig(o.time_seconds, 3)
    ));
    line(starts_line(o));
    line(vertex_search_line(o));
    out
}

/// "start 3", or "vertex-search solve 8" for a solve of the second phase.
fn run_name(o: &Optimum, index: usize) -> String {
    if index < o.starts.total {
        format!("start {index}")
    } else {
        format!("vertex-search solve {index}")
    }
}

/// The multistart's counts, in one sentence.
fn starts_line(o: &Optimum) -> String {
    format!(
        "starts: {} run, {} converged, {} reached the best ({} reported)",
        o.starts.total,
        o.starts.converged,
        o.starts.reached_best,
        run_name(o, o.best_start)
    )
}

/// How the vertex search (second phase of the multistart) went, in one sentence.
fn vertex_search_line(o: &Optimum) -> String {
    let s = &o.starts;
    let found_by = if o.best_start >= s.total {
        "; it found the reported design, better than every start"
    } else {
        ""
    };
    if s.vertex_starts == 0 {
        format!(
            "vertex search: {} edge{} of the active sets of the optima found followed; none leads to a lower objective",
            s.edges,
            if s.edges == 1 { "" } else { "s" }
        )
    } else {
        format!(
            "vertex search: {} edge{} of the active sets of the optima found followed; {} solve{} from edge ends with a lower objective, {} reached the best{found_by}",
            s.edges,
            if s.edges == 1 { "" } else { "s" },
            s.vertex_starts,
            if s.vertex_starts == 1 { "" } else { "s" },
            s.vertex_reached_best,
        )
    }
}

/// The convergence of every start: KKT residual against iteration (log scale).
pub fn convergence_svg(name: &str, o: &Optimum) -> String {
    use super::svg::{Axis, LinePlot, Series};
    let mut plot = LinePlot::new(
        format!("Convergence — {name}"),
        Axis::linear("iteration"),
        Axis::log("KKT residual"),
    );
    for s in &o.start_outcomes {
        let pts: Vec<(f64, f64)> = s
            .trace
            .iter()
            .map(|r| (r.iteration as f64, r.kkt_residual.max(1e-17)))
            .collect();
        if !pts.is_empty() {
            plot = plot.with_series(Series::new(run_name(o, s.index), pts));
        }
    }
    plot.to_svg()
}

/// A self-contained HTML page: status (with the law outside its regime, when `law`
/// says so), design, objective, constraints, warnings, the convergence of every
/// start and the optimum's load–separation curve.
pub fn html(
    name: &str,
    o: &Optimum,
    broken: &[BaselineViolation],
    curve: Option<&crate::model::LoadCurve>,
    robust: Option<&crate::app::robust::RobustOutcome>,
    law: Option<&LawOutsideRegime>,
) -> String {
    let mut p = super::html::Page::new(&format!("wearopt optimize — {name}"));
    if let Some(r) = robust {
        super::robust::html_section(&mut p, r, o);
    }
    match law {
        Some(l) => {
            p.paragraph(
                &format!("Status: {} ({})", o.status.as_str(), outside_words(l)),
                Some("status"),
            );
            // A sentence of its own: capitalised (the words start with "the").
            let words = format!("{}; {}", consequence_words(l), rerun_words(l));
            let mut chars = words.chars();
            let sentence: String = chars
                .next()
                .map(|c| c.to_uppercase().chain(chars).collect())
                .unwrap_or_default();
            p.paragraph(&sentence, Some("warn"));
        }
        None => p.paragraph(&format!("Status: {}", o.status.as_str()), Some("status")),
    }
    if let Some(n) = super::words::real_area_scale_note(o.scene.real_area_scale) {
        p.paragraph(&n, Some("note"));
    }
    let mut warnings: Vec<String> = broken
        .iter()
        .map(|b| {
            format!(
                "the baseline is infeasible: {} = {} breaks its {} of {}",
                b.quantity,
                b.value
                    .map_or("(undefined)".to_string(), |v| constraint_quantity(
                        b.quantity, v
                    )),
                side_word(b.side),
                constraint_quantity(b.quantity, b.limit)
            )
        })
        .collect();
    warnings.extend(
        super::words::warnings(&o.evaluation)
            .into_iter()
            .map(|w| format!("at the optimum: {w}")),
    );
    p.list(&warnings, "warn");
    p.heading("Design");
    let rows: Vec<Vec<String>> = o
        .names
        .iter()
        .zip(&o.design)
        .zip(&o.baseline_design)
        .map(|((n, v), b)| {
            let d = super::design_dimension(*n);
            vec![
                n.to_string(),
                format_quantity(*v, d),
                format_quantity(*b, d),
            ]
        })
        .collect();
    p.table(&["variable", "optimum", "baseline"], &rows, &[]);
    let bounds: Vec<String> = o
        .active_bounds
        .iter()
        .map(|b| {
            format!(
                "bound active: {} at its {} ({})",
                b.variable,
                b.side,
                format_quantity(b.value, super::design_dimension(b.variable))
            )
        })
        .collect();
    p.list(&bounds, "note");
    let unit = super::objective_unit(o.objective_name);
    p.heading("Objective");
    if let Some(h) = o.objective_humidity {
        p.paragraph(
            &format!(
                "{} is taken at RH = {} % (the range's humidity where it is worst at the baseline, or the file's design_humidity); every limit holds at each humidity of the range.",
                o.objective_name,
                sig(100.0 * h, 4)
            ),
            None,
        );
    }
    let mut rows = vec![vec![
        o.objective_name.to_string(),
        si(o.objective, unit, 4),
        si(o.baseline_objective, unit, 4),
    ]];
    // The wear rate beside another objective (not twice when it is the objective).
    if o.objective_name != Objective::WearRate {
        rows.push(vec![
            "wear_rate".into(),
            si(o.evaluation.wear_rate, "m³/m", 4),
            o.baseline_evaluation
                .as_ref()
                .map_or("—".into(), |e| si(e.wear_rate, "m³/m", 4)),
        ]);
    }
    p.table(&["quantity", "optimum", "baseline"], &rows, &[]);
    if !o.constraints.is_empty() {
        p.heading("Constraints");
        let price = |v: f64| price(o, v);
        let f = |q: ConstraintQuantity, x: Option<f64>| {
            x.map_or("—".to_string(), |v| constraint_quantity(q, v))
        };
        let rows: Vec<Vec<String>> = o
            .constraints
            .iter()
            .map(|c| {
                vec![
                    match c.humidity {
                        Some(h) => format!("{} (binds at RH {} %)", c.quantity, sig(100.0 * h, 4)),
                        None => c.quantity.to_string(),
                    },
                    f(c.quantity, c.value),
                    f(c.quantity, c.min),
                    f(c.quantity, c.max),
                    if c.active { "yes" } else { "no" }.into(),
                    price(c.multiplier),
                    price(c.shadow_price),
                ]
            })
            .collect();
        p.table(
            &[
                "constraint",
                "value",
                "min",
                "max",
                "active",
                "multiplier",
                "shadow price",
            ],
            &rows,
            &[4],
        );
        if o.status == OptimizationStatus::Infeasible {
            p.paragraph(
                "No multiplier or shadow price: the least-violating design is no optimum, so they have no meaning there.",
                None,
            );
        }
    }
    if !o.conflicting.is_empty() {
        p.paragraph(
            &format!(
                "Conflicting constraints (violated, or at their limit, at the least-violating design): {}.",
                conflict_names(o)
            ),
            Some("note"),
        );
    }
    p.paragraph(
        &format!(
            "KKT residual {} (finite-difference gradient error ≈ {}); {} model evaluations; {} s; {}; {}.",
            sig_exp(o.kkt_residual, 3),
            sig_exp(o.gradient_error, 2),
            o.evaluations,
            sig(o.time_seconds, 3),
            starts_line(o),
            vertex_search_line(o)
        ),
        None,
    );
    p.figure(
        "convergence",
        &convergence_svg(name, o),
        "The KKT residual of every start against its iteration.",
    );
    if let Some(curve) = curve {
        p.figure(
            "load-separation",
            &super::eval::load_curve_svg(
                &format!("The optimum's load against separation — {name}"),
                curve,
            ),
            &super::eval::load_curve_caption("The optimum design's load W", curve),
        );
        if let Some(svg) = super::eval::load_curve_tension_svg(
            &format!("The tensile part, enlarged — {name}"),
            curve,
        ) {
            p.figure(
                "load-separation-tension",
                &svg,
                "The same curve where the surfaces pull: the pull-off is the most tensile load the contact holds.",
            );
        }
    }
    p.finish()
}

/// A row's multiplier or shadow price as a table cell: "—" under `infeasible`,
/// where the rows carry none (see `Optimum::conflicting`).
fn price(o: &Optimum, v: f64) -> String {
    if o.status == OptimizationStatus::Infeasible {
        "—".to_string()
    } else {
        sig_exp(v, 3)
    }
}

/// The conflicting constraints' names, comma-separated.
fn conflict_names(o: &Optimum) -> String {
    o.conflicting
        .iter()
        .map(|q| q.as_str())
        .collect::<Vec<_>>()
        .join(", ")
}
