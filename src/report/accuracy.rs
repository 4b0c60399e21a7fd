//! The work–precision report of `wearopt accuracy`: a text table, CSV with the
//! columns `quantity,setting,max_rel_error,median_rel_error,time_per_eval_ns,is_default`,
//! and a log–log SVG of error against time per evaluation.

use std::fmt::Write;

use crate::accuracy::{Quantity, Row, WorkPrecision};

use super::number;

/// CSV: one row per quantity and setting.
pub fn csv(wp: &WorkPrecision) -> String {
    let mut out = String::from(
        "quantity,setting,max_rel_error,median_rel_error,time_per_eval_ns,is_default\n",
    );
    for r in &wp.rows {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{}",
            r.quantity.as_str(),
            r.setting,
            number(r.max_rel_error),
            number(r.median_rel_error),
            number(r.time_per_eval_ns),
            r.is_default
        );
    }
    out
}

/// The text report: provenance, then one table per quantity.
pub fn text(wp: &WorkPrecision) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "Work–precision of the evaluator");
    let _ = writeln!(
        out,
        "reference: adaptive Gauss–Kronrod G7K15 on the direct form of docs/model.md §3 (Δ1(Δ) by root solve at each node), estimated error ≤ {:.1e} relative",
        wp.reference_error
    );
    let _ = writeln!(
        out,
        "samples: {} grid points (θ ∈ [1e-3, 1e8], λ ∈ [1e-6, 1e6], h ∈ [-4, 60], γ = 0, H = ∞{}), {} scene loads, {} elasticities",
        wp.grid_points,
        if wp.scenes.is_empty() {
            String::new()
        } else {
            format!(", and the region of {}", wp.scenes.join(", "))
        },
        wp.wear_points,
        wp.gradient_points
    );
    let _ = writeln!(
        out,
        "load errors are relative to max(|P̄|, |elastic| + |plastic|); the quadrature settings change only the elastic integral (areas are closed forms; Ā_p carries ε·Δc·(h+Δc) from rounding Δc); wear rates are compared in ln, resolved to ≈ 1e-14"
    );
    let _ = writeln!(
        out,
        "gradient: elasticities d ln(wear rate)/d ln x of E, H, γ, σ, R against a Richardson-tableau derivative of the reference wear rate (estimated error ≤ {:.1e}, normwise); time is per elasticity",
        wp.reference_gradient_error
    );
    for q in Quantity::ALL {
        let rows: Vec<&Row> = wp.rows.iter().filter(|r| r.quantity == q).collect();
        if rows.is_empty() {
            continue;
        }
        let _ = writeln!(out);
        let _ = writeln!(out, "{} ({} samples)", q.as_str(), rows[0].samples);
        let _ = writeln!(
            out,
            "  {:<28} {:>10} {:>10} {:>12} {:>6}",
            "setting", "max err", "median err", "time/eval", "evals"
        );
        for r in rows {
            let _ = writeln!(
                out,
                "  {:<28} {:>10.2e} {:>10.2e} {:>12} {:>6}{}",
                r.setting,
                r.max_rel_error,
                r.median_rel_error,
                duration(r.time_per_eval_ns),
                r.evaluations_per_value,
                if r.is_default { "  (default)" } else { "" }
            );
        }
    }
    out
}

fn duration(ns: f64) -> String {
    if ns >= 1e6 {
        format!("{:.2} ms", ns / 1e6)
    } else if ns >= 1e3 {
        format!("{:.2} µs", ns / 1e3)
    } else {
        format!("{ns:.0} ns")
    }
}

/// A log–log SVG (through [`super::svg::LinePlot`]): the max relative error
/// against time per evaluation, one series per quantity (a point per setting),
/// and the default settings as their own series. Zero errors are drawn at 1e-17.
pub fn svg(wp: &WorkPrecision) -> String {
    use super::svg::{Axis, LinePlot, Marker, Series};
    const FLOOR: f64 = 1e-17;
    let point = |r: &Row| (r.time_per_eval_ns, r.max_rel_error.max(FLOOR));
    let usable = |r: &&Row| r.time_per_eval_ns > 0.0 && r.max_rel_error.is_finite();
    let mut plot = LinePlot::new(
        "Work–precision of the wearopt evaluator",
        Axis::log("time per evaluation").with_unit("ns"),
        Axis::log("max relative error").with_unit("dimensionless"),
    );
    for (i, q) in Quantity::ALL.iter().enumerate() {
        let mut pts: Vec<(f64, f64)> = wp
            .rows
            .iter()
            .filter(usable)
            .filter(|r| r.quantity == *q)
            .map(point)
            .collect();
        if pts.is_empty() {
            continue;
        }
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        plot = plot.with_series(
            Series::new(q.as_str(), pts)
                .without_line()
                .with_marker(Marker::CYCLE[i % Marker::CYCLE.len()]),
        );
    }
    let defaults: Vec<(f64, f64)> = wp
        .rows
        .iter()
        .filter(usable)
        .filter(|r| r.is_default)
        .map(point)
        .collect();
    if !defaults.is_empty() {
        plot = plot.with_series(
            Series::new("default setting", defaults)
                .without_line()
                .with_marker(Marker::CYCLE[0])
                .with_color("#000000"),
        );
    }
    plot.to_svg()
}
