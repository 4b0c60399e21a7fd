//! The report of a material study (`wearopt optimize` on a file with
//! `[design] materials`): a ranking table as text, or JSON.

use serde_json::{json, Map, Value};

use super::sig;
use crate::optimize::materials::{MaterialOutcome, MaterialRanking, MaterialResult};
use crate::problem::units::{format_quantity, Dimension};

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
        "active_constraints": r.active(),
        "active_bounds": active_bounds,
        "constraints": constraints,
        "pull_off_force": r.evaluation().and_then(|e| e.pull_off_force),
        "plasticity_index": r.evaluation().map(|e| e.indices.plasticity_index),
        "optimizer": optimizer,
        "excluded_reason": r.case.excluded,
        "notes": r.case.notes,
    })
}

/// One JSON object, SI units: `name`, `objective_name`, `method`, `best`, `ranking`
/// (rows with `rank`, `material`, `status`, `objective`, `wear_rate`, `sigma`,
/// `asperity_radius`, `work_of_adhesion`, `design`, `active_constraints`, …).
pub fn json(name: &str, ranking: &MaterialRanking) -> String {
    let v = json!({
        "name": name,
        "objective_name": ranking.objective_name,
        "method": METHOD,
        "best": ranking.best().map(|r| r.name()),
        "ranking": ranking.results.iter().map(row_json).collect::<Vec<_>>(),
        "time_seconds": ranking.time_seconds,
    });
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_else(|_| "{}".into());
    s.push('\n');
    s
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
    let show_objective = ranking.objective_name != "wear_rate";
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
        let active = r.active();
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
    if let Some(best) = ranking.best() {
        let wr = |r: &MaterialResult| r.wear_rate().unwrap_or(f64::NAN);
        let runner = ranking.results.get(1).filter(|r| r.rank.is_some());
        line(String::new());
        line(format!(
            "Least {}: {} ({}){}",
            ranking.objective_name.replace('_', " "),
            best.name(),
            super::si(best.objective().unwrap_or(f64::NAN), unit, 4),
            runner.map_or(String::new(), |r| format!(
                "; next {} with ×{} the wear rate",
                r.name(),
                sig(wr(r) / wr(best), 3)
            ))
        ));
    } else {
        line(String::new());
        line("No material meets every constraint.".into());
    }
    let any_notes = ranking
        .results
        .iter()
        .any(|r| !r.case.notes.is_empty() || r.case.excluded.is_some());
    if any_notes {
        line(String::new());
        line("Notes:".into());
        for r in &ranking.results {
            if let Some(why) = &r.case.excluded {
                line(format!("  {}: excluded: {why}", r.name()));
            }
            if let MaterialOutcome::NoContact(why) = &r.outcome {
                line(format!("  {}: {why}", r.name()));
            }
            for n in &r.case.notes {
                line(format!("  {}: {n}", r.name()));
            }
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
