//! The report of a material study (`wearopt optimize` on a file with
//! `[design] materials`): a ranking table as text, or JSON.

use serde_json::{json, Map, Value};

use super::sig;
use crate::optimize::materials::{
    Exclusion, MaterialNote, MaterialOutcome, MaterialRanking, MaterialResult,
};
use crate::units::{format_quantity, Dimension};

/// The formats a material ranking is written in (those of `wearopt optimize`).
pub const FORMATS: &[super::Format] = &[
    super::Format::Text,
    super::Format::Json,
    super::Format::Html,
];

const METHOD: [&str; 4] = [
    "body a takes each material's E, ν and H (catalogue); body b is unchanged",
    "design variables on E, ν or H are dropped (the material fixes them)",
    "work_of_adhesion bounds are the study's intersected with the material's typical γ range (no overlap: excluded)",
    "ranked by the objective among results that meet every constraint; the others follow in list order",
];

fn row_json(r: &MaterialResult) -> Value {
    let scene = r.scene();
    let mut design = Map::new();
    let mut active_bounds = Value::Array(Vec::new());
    let mut constraints = Value::Array(Vec::new());
    let mut optimizer = Value::Null;
    match &r.outcome {
        MaterialOutcome::Optimized(o) => {
            for (n, v) in o.names.iter().zip(&o.design) {
                design.insert((*n).to_string(), json!(v));
            }
            active_bounds = json!(o.active_bounds);
            constraints = json!(o.constraints);
            optimizer = json!({
                "kkt_residual": o.kkt_residual,
                "gradient_error": o.gradient_error,
                "evaluations": o.evaluations,
                "starts": o.starts,
                "best_start": o.best_start,
                "baseline_objective": o.baseline_objective,
                "time_seconds": o.time_seconds,
            });
        }
        MaterialOutcome::Evaluated { constraints: c, .. } => constraints = json!(c),
        _ => {}
    }
    let bounds: Map<String, Value> = r
        .case
        .design
        .iter()
        .map(|v| (v.name.as_str().to_string(), json!([v.min, v.max])))
        .collect();
    json!({
        "rank": r.rank,
        "material": r.name(),
        "status": r.status.as_str(),
        "objective": r.objective(),
        "wear_rate": r.wear_rate(),
        "sigma": scene.sigma,
        "asperity_radius": scene.asperity_radius,
        "work_of_adhesion": scene.work_of_adhesion,
        "youngs_modulus": scene.youngs_modulus_a,
        "poisson_ratio": scene.poisson_ratio_a,
        "hardness": scene.hardness,
        "design": design,
        "design_bounds": bounds,
        "active_constraints": active(r),
        "active_bounds": active_bounds,
        "constraints": constraints,
        "pull_off_force": r.evaluation().and_then(|e| e.pull_off_force),
        "plasticity_index": r.evaluation().map(|e| e.indices.plasticity_index),
        "optimizer": optimizer,
        "excluded_reason": r.case.excluded.map(|e| exclusion_words(&e, r.name())),
        "notes": r.case.notes.iter().map(|n| note_words(n, r.name())).collect::<Vec<_>>(),
    })
}

/// One JSON object, SI units: `name`, `objective_name`, `method`, `best`, `ranking`
/// (rows with `rank`, `material`, `status`, `objective`, `wear_rate`, `sigma`,
/// `asperity_radius`, `work_of_adhesion`, `design`, `active_constraints`, …).
pub fn json(name: &str, ranking: &MaterialRanking) -> String {
    super::json_text(&json_value(name, ranking))
}

/// The object [`json()`] writes, as a value.
pub fn json_value(name: &str, ranking: &MaterialRanking) -> Value {
    json!({
        "name": name,
        "objective_name": ranking.objective_name,
        "method": METHOD,
        "best": ranking.best().map(|r| r.name()),
        "ranking": ranking.results.iter().map(row_json).collect::<Vec<_>>(),
        "time_seconds": ranking.time_seconds,
    })
}

/// The optimiser's trace of every optimised material, one CSV: the columns of
/// [`super::trace::trace_csv`] after a `material` column.
pub fn trace_csv(ranking: &MaterialRanking) -> String {
    let mut csv = String::new();
    for r in &ranking.results {
        if let MaterialOutcome::Optimized(o) = &r.outcome {
            let t = super::trace::trace_csv(o);
            for (i, l) in t.lines().enumerate() {
                if i == 0 && csv.is_empty() {
                    csv.push_str(&format!("material,{l}\n"));
                } else if i > 0 {
                    csv.push_str(&format!("{},{l}\n", r.name()));
                }
            }
        }
    }
    csv
}

/// "Least wear rate: polysilicon (…); next … with ×3.2 the wear rate", or that none
/// meets every constraint.
fn best_sentence(ranking: &MaterialRanking) -> String {
    let unit = super::objective_unit(ranking.objective_name);
    match ranking.best() {
        Some(best) => {
            let wr = |r: &MaterialResult| r.wear_rate().unwrap_or(f64::NAN);
            let runner = ranking.results.get(1).filter(|r| r.rank.is_some());
            format!(
                "Least {}: {} ({}){}",
                ranking.objective_name.as_str().replace('_', " "),
                best.name(),
                super::si(best.objective().unwrap_or(f64::NAN), unit, 4),
                runner.map_or(String::new(), |r| format!(
                    "; next {} with ×{} the wear rate",
                    r.name(),
                    sig(wr(r) / wr(best), 3)
                ))
            )
        }
        None => "No material meets every constraint.".into(),
    }
}

/// Names of the constraints active at the design, then the design bounds reached
/// (`sigma at min`); for a fixed design, the constraints it violates.
fn active(r: &MaterialResult) -> Vec<String> {
    match &r.outcome {
        MaterialOutcome::Optimized(o) => o
            .constraints
            .iter()
            .filter(|c| c.active)
            .map(|c| c.quantity.to_string())
            .chain(
                o.active_bounds
                    .iter()
                    .map(|b| format!("{} at {}", b.variable, b.side)),
            )
            .collect(),
        MaterialOutcome::Evaluated { constraints, .. } => constraints
            .iter()
            .filter(|c| !c.satisfied)
            .map(|c| format!("{} violated", c.quantity))
            .collect(),
        _ => Vec::new(),
    }
}

/// Why a material cannot be studied, in words (`material` names it).
fn exclusion_words(why: &Exclusion, material: &str) -> String {
    let gamma = |x| format_quantity(x, Dimension::SurfaceEnergy);
    match *why {
        Exclusion::GammaRangesDisjoint { study, typical } => format!(
            "the study's γ range {} to {} does not overlap the typical range of {material}, {} to {}",
            gamma(study.0),
            gamma(study.1),
            gamma(typical.0),
            gamma(typical.1)
        ),
    }
}

/// A note of a material's case, in words (`material` names it).
fn note_words(note: &MaterialNote, material: &str) -> String {
    let gamma = |x| format_quantity(x, Dimension::SurfaceEnergy);
    match *note {
        MaterialNote::VariableFixed { variable, value } => format!(
            "design variable {variable} dropped: fixed by the material ({})",
            format_quantity(value, variable.dimension())
        ),
        MaterialNote::GammaBoundsIntersected { min, max } => format!(
            "work_of_adhesion bounds {} to {} (the study's, intersected with the material's typical range)",
            gamma(min),
            gamma(max)
        ),
        MaterialNote::BaselineGammaMoved { from, to } => format!(
            "baseline work_of_adhesion moved from {} to {} (into the bounds)",
            gamma(from),
            gamma(to)
        ),
        MaterialNote::GammaOutsideTypical { value, typical } => format!(
            "work_of_adhesion {} (the file's, kept) is outside the typical range of {material}, {} to {}",
            gamma(value),
            gamma(typical.0),
            gamma(typical.1)
        ),
    }
}

/// Why a material was excluded or had no contact, and the notes of its case, each
/// prefixed with the material's name.
fn notes(ranking: &MaterialRanking) -> Vec<String> {
    let mut out = Vec::new();
    for r in &ranking.results {
        if let Some(why) = &r.case.excluded {
            out.push(format!(
                "{}: excluded: {}",
                r.name(),
                exclusion_words(why, r.name())
            ));
        }
        if let MaterialOutcome::NoContact(why) = &r.outcome {
            out.push(format!("{}: {why}", r.name()));
        }
        for n in &r.case.notes {
            out.push(format!("{}: {}", r.name(), note_words(n, r.name())));
        }
    }
    out
}

/// The ranking table for people.
pub fn text(name: &str, ranking: &MaterialRanking) -> String {
    let mut out = String::new();
    let mut line = |s: String| {
        out.push_str(&s);
        out.push('\n');
    };
    line(format!("wearopt optimize — {name}: material ranking"));
    line(String::new());
    let unit = super::objective_unit(ranking.objective_name);
    let show_objective = ranking.objective_name != crate::optimize::Objective::WearRate;
    let mut header = format!(
        "{:>4}  {:<24} {:<16} {:>14}",
        "rank", "material", "status", "wear rate"
    );
    if show_objective {
        header.push_str(&format!(" {:>14}", ranking.objective_name));
    }
    header.push_str(&format!(
        " {:>10} {:>10} {:>12}  active constraints",
        "sigma", "R", "γ"
    ));
    line(header);
    for r in &ranking.results {
        let scene = r.scene();
        let has_result = r.evaluation().is_some();
        let q = |x: f64, d| {
            if has_result {
                format_quantity(x, d)
            } else {
                "—".into()
            }
        };
        let mut row = format!(
            "{:>4}  {:<24} {:<16} {:>14}",
            r.rank.map_or("—".into(), |k| k.to_string()),
            r.name(),
            r.status.as_str(),
            r.wear_rate()
                .map_or("—".into(), |w| super::si(w, "m³/m", 4))
        );
        if show_objective {
            row.push_str(&format!(
                " {:>14}",
                r.objective().map_or("—".into(), |o| super::si(o, unit, 4))
            ));
        }
        let active = active(r);
        row.push_str(&format!(
            " {:>10} {:>10} {:>12}  {}",
            q(scene.sigma, Dimension::Length),
            q(scene.asperity_radius, Dimension::Length),
            q(scene.work_of_adhesion, Dimension::SurfaceEnergy),
            if active.is_empty() {
                "none".to_string()
            } else {
                active.join(", ")
            }
        ));
        line(row);
    }
    line(String::new());
    line(best_sentence(ranking));
    let notes = notes(ranking);
    if !notes.is_empty() {
        line(String::new());
        line("Notes:".into());
        for n in notes {
            line(format!("  {n}"));
        }
    }
    line(String::new());
    line("Method:".into());
    for m in METHOD {
        line(format!("  {m}"));
    }
    line(format!(
        "{} materials in {} s",
        ranking.results.len(),
        sig(ranking.time_seconds, 3)
    ));
    out
}

/// The pull-off force; one that underflows to 0 N is given by its decade.
fn pull_off_text(e: &crate::model::Evaluation) -> String {
    match (e.pull_off_force, e.log10_pull_off_force) {
        (Some(f), Some(l)) if f == 0.0 && l.is_finite() => format!("1e{} N", sig(l, 4)),
        (Some(f), _) => super::si(f, "N", 4),
        (None, _) => "—".into(),
    }
}

/// A self-contained HTML page: the verdict, the objective of each material as bars on
/// a log axis, the ranking table (with each material's E, ν, H and the design found),
/// the notes and the method.
pub fn html(name: &str, ranking: &MaterialRanking) -> String {
    let mut p = super::html::Page::new(&format!("wearopt optimize — {name}: material ranking"));
    p.paragraph(&best_sentence(ranking), Some("status"));
    let unit = super::objective_unit(ranking.objective_name);
    let objective = ranking.objective_name.as_str().replace('_', " ");
    let bars: Vec<(String, f64, String)> = ranking
        .results
        .iter()
        .map(|r| {
            let v = r.objective().unwrap_or(f64::NAN);
            let label = match r.rank {
                Some(k) => format!("{k}. {}", r.name()),
                None => format!("{} ({})", r.name(), r.status.as_str()),
            };
            (label, v, super::si(v, unit, 4))
        })
        .collect();
    let axis = if unit.is_empty() {
        objective.clone()
    } else {
        format!("{objective} ({unit}), log scale")
    };
    p.figure(
        "ranking",
        &super::svg::log_bar_chart(
            &format!("{name}: {objective} of each material"),
            &axis,
            &bars,
        ),
        "The objective at each material's best design; ranked materials meet every constraint, the others are named with their status.",
    );
    p.heading("Ranking");
    let show_objective = ranking.objective_name != crate::optimize::Objective::WearRate;
    let mut header: Vec<String> = vec![
        "rank".into(),
        "material".into(),
        "status".into(),
        "wear rate".into(),
    ];
    if show_objective {
        header.push(objective.clone());
    }
    for h in ["pull-off force", "σ", "R", "γ", "E", "ν", "H"] {
        header.push(h.into());
    }
    let rows: Vec<Vec<String>> = ranking
        .results
        .iter()
        .map(|r| {
            let scene = r.scene();
            let ev = r.evaluation();
            let q = |x: f64, d| {
                if ev.is_some() {
                    format_quantity(x, d)
                } else {
                    "—".into()
                }
            };
            let mut row = vec![
                r.rank.map_or("—".into(), |k| k.to_string()),
                r.name().to_string(),
                r.status.as_str().to_string(),
                r.wear_rate()
                    .map_or("—".into(), |w| super::si(w, "m³/m", 4)),
            ];
            if show_objective {
                row.push(r.objective().map_or("—".into(), |o| super::si(o, unit, 4)));
            }
            row.extend([
                ev.map_or("—".into(), pull_off_text),
                q(scene.sigma, Dimension::Length),
                q(scene.asperity_radius, Dimension::Length),
                q(scene.work_of_adhesion, Dimension::SurfaceEnergy),
                format_quantity(scene.youngs_modulus_a, Dimension::Pressure),
                super::number(scene.poisson_ratio_a),
                format_quantity(scene.hardness, Dimension::Pressure),
            ]);
            row
        })
        .collect();
    let header_refs: Vec<&str> = header.iter().map(String::as_str).collect();
    p.table(&header_refs, &rows, &[1, 2]);
    p.heading("Active constraints and bounds");
    let rows: Vec<Vec<String>> = ranking
        .results
        .iter()
        .filter(|r| r.evaluation().is_some())
        .map(|r| {
            let active = active(r);
            vec![
                r.name().to_string(),
                if active.is_empty() {
                    "none".to_string()
                } else {
                    active.join(", ")
                },
            ]
        })
        .collect();
    p.table(&["material", "at its limit"], &rows, &[1]);
    let notes = notes(ranking);
    if !notes.is_empty() {
        p.heading("Notes");
        p.list(&notes, "note");
    }
    p.heading("Method");
    p.list(&METHOD.map(String::from), "note");
    p.paragraph(
        &format!(
            "{} materials in {} s.",
            ranking.results.len(),
            sig(ranking.time_seconds, 3)
        ),
        Some("note"),
    );
    p.finish()
}
