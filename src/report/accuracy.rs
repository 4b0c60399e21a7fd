//! The work–precision report of `wearopt accuracy`: a text table, CSV with the
//! columns `quantity,setting,max_rel_error,median_rel_error,time_per_eval_ns,is_default,adhesion_model,attraction`,
//! JSON (the run's provenance and one object per row), and a log–log SVG of error
//! against time per evaluation.

use std::fmt::Write;

use serde_json::{json, Value};

use crate::accuracy::{Quantity, Row, RowLaw, WorkPrecision};
use crate::model::lennard_jones::table::{
    INTERPOLATION_ERROR, INTERPOLATION_ERROR_ABOVE_CUSP, INTERPOLATION_ERROR_BELOW,
    INTERPOLATION_ERROR_SPARSE, INTERPOLATION_RANGES_BELOW, LIMIT_CHECK, LIMIT_ERROR, SOLVER_ERROR,
    TABLE_ERROR, TAIL_ERROR, TAIL_ERROR_BELOW, TAIL_RANGES_BELOW, TAIL_SCALES,
};
use crate::model::AttractionKind;

use super::number;

/// `{"at_z0_R": error}` for each range z0 = Z0/σ and its error.
fn by_range(ranges: &[f64], errors: &[f64]) -> Value {
    Value::Object(
        ranges
            .iter()
            .zip(errors)
            .map(|(z0, e)| (format!("at_z0_{z0}"), json!(e)))
            .collect(),
    )
}

/// The formats `wearopt accuracy` writes (the first is the default).
pub const FORMATS: &[super::Format] =
    &[super::Format::Text, super::Format::Json, super::Format::Csv];

/// CSV: one row per quantity and setting.
pub fn csv(wp: &WorkPrecision) -> String {
    let mut out = String::from(
        "quantity,setting,max_rel_error,median_rel_error,time_per_eval_ns,is_default,adhesion_model,attraction\n",
    );
    for r in &wp.rows {
        let _ = writeln!(
            out,
            "{},{},{},{},{},{},{},{}",
            r.quantity.as_str(),
            r.setting,
            number(r.max_rel_error),
            number(r.median_rel_error),
            number(r.time_per_eval_ns),
            r.is_default,
            r.law.adhesion_model().as_str(),
            r.law.attraction().map_or("", AttractionKind::as_str)
        );
    }
    out
}

/// JSON: the run's provenance and its rows (a non-finite number is `null`).
pub fn json(wp: &WorkPrecision) -> String {
    let num = |x: f64| {
        if x.is_finite() {
            json!(x)
        } else {
            Value::Null
        }
    };
    let rows: Vec<Value> = wp
        .rows
        .iter()
        .map(|r| {
            json!({
                "quantity": r.quantity.as_str(),
                "setting": r.setting,
                "adhesion_model": r.law.adhesion_model().as_str(),
                "attraction": r.law.attraction().map(AttractionKind::as_str),
                "max_rel_error": num(r.max_rel_error),
                "median_rel_error": num(r.median_rel_error),
                "time_per_eval_ns": num(r.time_per_eval_ns),
                "is_default": r.is_default,
                "samples": r.samples,
                "evaluations_per_value": r.evaluations_per_value,
            })
        })
        .collect();
    let v = json!({
        "grid_points": wp.grid_points,
        "wear_points": wp.wear_points,
        "gradient_points": wp.gradient_points,
        "reference_error": num(wp.reference_error),
        "reference_gradient_error": num(wp.reference_gradient_error),
        "dmt_grid_points": wp.dmt_grid_points,
        "dmt_reference_error": num(wp.dmt_reference_error),
        "lennard_jones_points": wp.lennard_jones_points,
        "lennard_jones_stand_in_error": {
            "below": num(wp.lennard_jones_stand_in_error.0),
            "above": num(wp.lennard_jones_stand_in_error.1),
            "below_tabor": crate::model::lennard_jones::table::tabor_range().0,
            "above_tabor": crate::model::lennard_jones::table::tabor_range().1,
        },
        "lennard_jones_limit_curves": {
            "from_tabor": crate::model::lennard_jones::table::solved_range().1,
            "to_tabor": crate::model::lennard_jones::table::tabor_range().1,
            "pull_off_error": LIMIT_ERROR.0,
            "load_error": LIMIT_ERROR.1,
            "check_tabor": LIMIT_CHECK.0,
            "check_pull_off_error": LIMIT_CHECK.1,
            "check_load_error": LIMIT_CHECK.2,
        },
        "lennard_jones_error": {
            "table_against_solver": TABLE_ERROR,
            "solver_against_reference": SOLVER_ERROR,
            "interpolation_in_tabor": INTERPOLATION_ERROR.0,
            "interpolation_in_tabor_at_cusp": INTERPOLATION_ERROR.1,
            "cusp_tabor": crate::model::lennard_jones::rough::CUSP_TABOR,
            "interpolation_in_tabor_just_above_cusp": {
                "tabor": INTERPOLATION_ERROR_ABOVE_CUSP.0,
                "error": INTERPOLATION_ERROR_ABOVE_CUSP.1,
            },
            "interpolation_in_tabor_sparse": INTERPOLATION_ERROR_SPARSE,
            "sparse_above_tabor": crate::model::lennard_jones::rough::SPARSE_ABOVE,
            "tail": TAIL_ERROR
                .iter()
                .map(|row| {
                    let mut m = serde_json::Map::new();
                    m.insert("tabor".into(), json!(row[0]));
                    for (ell, e) in TAIL_SCALES.iter().zip(&row[1..]) {
                        m.insert(format!("at_ell_{ell}"), json!(e));
                    }
                    Value::Object(m)
                })
                .collect::<Vec<_>>(),
            "interpolation_in_tabor_below_hundredth": by_range(&INTERPOLATION_RANGES_BELOW, &INTERPOLATION_ERROR_BELOW),
            "tail_at_lowest": {
                "tabor": TAIL_ERROR_BELOW[0],
                "by_range": by_range(&TAIL_RANGES_BELOW, &TAIL_ERROR_BELOW[1..]),
            },
        },
        "scenes": wp.scenes,
        "rows": rows,
    });
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_else(|_| "{}".into());
    s.push('\n');
    s
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
    for law in RowLaw::ALL {
        if law == RowLaw::LennardJones {
            if !wp.rows.iter().any(|r| r.law == law) {
                continue;
            }
            let _ = writeln!(out);
            let _ = writeln!(
                out,
                "Lennard-Jones asperity law (docs/model.md §11), its table and the scene's grid of nodes at the default setting: {} points (μ = 0.02, 0.1, 0.374, 1, 3, 10, 20, and 100 and 1e5 on the limit curves; ℓ = σ/ε = 3 and 30; c_h = 5 and ∞; h = -1 … 4; and the scenes' own coefficients where μ lies in the table)",
                wp.lennard_jones_points
            );
            let _ = writeln!(
                out,
                "reference: adaptive Simpson in Δ of the same tabulated curves, each with its plastic branch c_p Δ - c_0 beyond its own Δc, weighted as the model interpolates in μ (square-root ends at the jumps removed by Δ = Δ_s ∓ s²), to {:.0e} of ∫|p| φ̄; load errors are relative to ∫|p| φ̄",
                crate::accuracy::lennard_jones::REFERENCE_TOLERANCE
            );
            let (between, cusp) = INTERPOLATION_ERROR;
            let (above_cusp_tabor, above_cusp) = INTERPOLATION_ERROR_ABOVE_CUSP;
            let cusp_tabor = crate::model::lennard_jones::rough::CUSP_TABOR;
            let (lo, hi) = crate::model::lennard_jones::table::tabor_range();
            let (lo, hi) = (
                crate::units::format_number(lo),
                crate::units::format_number(hi),
            );
            let _ = writeln!(
                out,
                "the table against the sphere (docs/model.md §11), not in the rows below: one summit's load P̂ within {TABLE_ERROR:.0e} of the converged solver between the table's nodes (to δ̂ = 50, or 16 ẑ0 where that is further), the solver {SOLVER_ERROR:.1e} from an independent discretisation; between the table's curves P̄ is interpolated cubically in 1/μ, within {between:.1e} of P̄ from the solver's own curve at the midpoints ({cusp:.1e} beside the cusp μ_c = {cusp_tabor}, where the curves turn S-shaped, {above_cusp:.1e} between it and the first S-shaped curve, at μ = {above_cusp_tabor}, interpolated through the cusp itself; {INTERPOLATION_ERROR_SPARSE:.1e} above μ = {} to the solved table's end, where the grid is sparser, quintically from six curves); beyond that a Hertz tail whose shift follows the squeezed gap stands in, which weighs where ℓ = σ/ε is large: P̄ off the solver's curve (written two to eight times as far) by {}",
                crate::units::format_number(crate::model::lennard_jones::rough::SPARSE_ABOVE),
                TAIL_ERROR
                    .iter()
                    .map(|row| format!(
                        "{} at μ = {}",
                        row[1..]
                            .iter()
                            .map(|&e| if e <= 1e-12 {
                                "≤ 1e-12".to_string()
                            } else {
                                format!("{e:.1e}")
                            })
                            .collect::<Vec<_>>()
                            .join(" / "),
                        row[0]
                    ))
                    .collect::<Vec<_>>()
                    .join(", ")
                    + " (ℓ = 30 / 100 / 300 / 1000)"
            );
            let listed = |ranges: &[f64], errors: &[f64]| {
                ranges
                    .iter()
                    .zip(errors)
                    .map(|(z0, &e)| {
                        if e <= 1e-12 {
                            format!("≤ 1e-12 at z0 = {z0}")
                        } else {
                            format!("{e:.1e} at z0 = {z0}")
                        }
                    })
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let _ = writeln!(
                out,
                "below μ = 0.01 (to the table's lowest curve, μ = {lo}, where ℓ = σ/ε is large), by the range z0 = Z0/σ: P̄ interpolated in μ within {} of the solver's own curve at the midpoints; the tail at the lowest curve {}",
                listed(&INTERPOLATION_RANGES_BELOW, &INTERPOLATION_ERROR_BELOW),
                listed(&TAIL_RANGES_BELOW, &TAIL_ERROR_BELOW[1..]),
            );
            let solved =
                crate::units::format_number(crate::model::lennard_jones::table::solved_range().1);
            let _ = writeln!(
                out,
                "above the solved table (μ = {solved}) to μ = {hi} the law's curves are its closed-form limit, JKR's contact branch from the sphere's jump in (δ̂_s = −(C μ^(-4/7) − D μ^(-1)) through the last two solved curves) and the rigid sphere's approach: at μ = {solved} the rough surface's pull-off under it is within {:.1} % of the solved sphere's, P̄ within {:.2e} of ∫|p| φ̄ (JKR's law there: 33 % at ℓ = 1, 75 % at ℓ = 3); at μ = {}, against a curve the solver wrote there, the law's pull-off within {:.1} %, P̄ within {:.1e}",
                100.0 * LIMIT_ERROR.0,
                LIMIT_ERROR.1,
                crate::units::format_number(LIMIT_CHECK.0),
                100.0 * LIMIT_CHECK.1,
                LIMIT_CHECK.2
            );
            let _ = writeln!(
                out,
                "outside the law's curves the closed-form laws stand in: DMT with van der Waals attraction below μ = {lo} (one summit's pull-off {:.2} % off the table's there), JKR above μ = {hi} (the rough surface's pull-off {:.2} % off the limit curve's where adhesion is strong, ℓ ≤ 3)",
                100.0 * wp.lennard_jones_stand_in_error.0,
                100.0 * wp.lennard_jones_stand_in_error.1
            );
            table(&mut out, wp, law);
            continue;
        }
        if law != RowLaw::Jkr {
            if !wp.rows.iter().any(|r| r.law == law) {
                continue;
            }
            let _ = writeln!(out);
            let _ = writeln!(
                out,
                "DMT asperity law (docs/model.md §7) with {} attraction, at the default setting: {} grid points per attraction (θ ∈ [1e-3, 1e8], λ ∈ [1e-6, 1e6], H = ∞, {}, h ∈ [-4, 60], and the scenes' regions under DMT)",
                match law.attraction() {
                    Some(AttractionKind::Dugdale) => "Dugdale",
                    _ => "van der Waals",
                },
                wp.dmt_grid_points,
                match law.attraction() {
                    Some(AttractionKind::Dugdale) => "Δ_h ∈ [1e-6, 1e3]",
                    _ => "z0 ∈ [1e-4, 10]",
                }
            );
            let _ = writeln!(
                out,
                "reference: the direct form by adaptive G7K15 (Hertz load Δ^{{3/2}} − c_0, attraction in the gap), estimated error ≤ {:.1e} relative; load = the contact share against |elastic| + |plastic|, noncontact_load against |N|",
                wp.dmt_reference_error
            );
        }
        table(&mut out, wp, law);
    }
    out
}

/// The tables of one law, quantity by quantity.
fn table(out: &mut String, wp: &WorkPrecision, law: RowLaw) {
    for q in Quantity::ALL {
        let rows: Vec<&Row> = wp
            .rows
            .iter()
            .filter(|r| r.quantity == q && r.law == law)
            .collect();
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
        // Where no setting changes the error (closed forms: the quadrature settings move
        // only the elastic integral), one row says so instead of one per setting.
        let same = rows.iter().all(|r| {
            r.max_rel_error.to_bits() == rows[0].max_rel_error.to_bits()
                && r.median_rel_error.to_bits() == rows[0].median_rel_error.to_bits()
        });
        if same && rows.len() > 1 {
            let r = rows.iter().find(|r| r.is_default).unwrap_or(&rows[0]);
            let _ = writeln!(
                out,
                "  {:<28} {:>10.2e} {:>10.2e} {:>12} {:>6}  (closed form: the same for all {} settings; time of the default)",
                "closed form",
                r.max_rel_error,
                r.median_rel_error,
                duration(r.time_per_eval_ns),
                r.evaluations_per_value,
                rows.len()
            );
            continue;
        }
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
            .filter(|r| r.quantity == *q && r.law == RowLaw::Jkr)
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
    // DMT (default setting only): one series per attraction, a point per quantity.
    for (i, law) in RowLaw::ALL.iter().skip(1).enumerate() {
        let mut pts: Vec<(f64, f64)> = wp
            .rows
            .iter()
            .filter(usable)
            .filter(|r| r.law == *law)
            .map(point)
            .collect();
        if pts.is_empty() {
            continue;
        }
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let name = match (law, law.attraction()) {
            (RowLaw::LennardJones, _) => "Lennard-Jones (table and grid)",
            (_, Some(AttractionKind::Dugdale)) => "DMT, Dugdale (default setting)",
            _ => "DMT, van der Waals (default setting)",
        };
        plot = plot.with_series(
            Series::new(name, pts)
                .without_line()
                .with_marker(Marker::CYCLE[(Quantity::ALL.len() + i) % Marker::CYCLE.len()]),
        );
    }
    let defaults: Vec<(f64, f64)> = wp
        .rows
        .iter()
        .filter(usable)
        .filter(|r| r.is_default && r.law == RowLaw::Jkr)
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

/// The document in `format` (one of [`FORMATS`]).
pub fn render(
    wp: &WorkPrecision,
    format: super::Format,
) -> Result<String, super::format::FormatError> {
    match format {
        super::Format::Text => Ok(text(wp)),
        super::Format::Csv => Ok(csv(wp)),
        super::Format::Json => Ok(json(wp)),
        given => Err(super::format::FormatError::NotRendered {
            command: "accuracy",
            given,
            accepted: FORMATS,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(quantity: Quantity, setting: &str, max: f64, is_default: bool) -> Row {
        Row {
            quantity,
            setting: setting.to_string(),
            max_rel_error: max,
            median_rel_error: 1e-16,
            time_per_eval_ns: 500.0,
            is_default,
            samples: 3,
            evaluations_per_value: 1,
            law: RowLaw::Jkr,
        }
    }

    #[test]
    fn closed_forms_are_said_once() {
        let wp = WorkPrecision {
            rows: vec![
                row(Quantity::Load, "order=8", 1e-6, false),
                row(Quantity::Load, "order=20", 1e-14, true),
                row(Quantity::Area, "order=8", 1.4e-14, false),
                row(Quantity::Area, "order=20", 1.4e-14, true),
                row(Quantity::Area, "order=30", 1.4e-14, false),
            ],
            grid_points: 3,
            wear_points: 0,
            gradient_points: 0,
            reference_error: 1e-15,
            reference_gradient_error: 0.0,
            scenes: vec![],
            dmt_grid_points: 0,
            dmt_reference_error: 0.0,
            lennard_jones_points: 0,
            lennard_jones_stand_in_error: (0.0, 0.0),
        };
        let t = text(&wp);
        // The load differs by setting: a row each. The area is a closed form: one row.
        assert_eq!(t.matches("order=").count(), 2, "{t}");
        assert_eq!(t.matches("closed form (").count(), 0, "{t}");
        assert_eq!(
            t.matches("closed form: the same for all 3 settings")
                .count(),
            1,
            "{t}"
        );
        // CSV keeps every row.
        assert_eq!(csv(&wp).lines().count(), 6);
    }
}
