//! One asperity's curve in Maugis units (`wearopt asperity`): a table, CSV,
//! JSON, an HTML page, and the plot of load against interference with the
//! branches, the jumps and the JKR and DMT curves.

use serde_json::json;

use super::format::FormatError;
use super::svg::{Axis, LinePlot, Marker, Series};
use super::Format;
use super::{number, sig};
use crate::app::asperity::{
    AsperityDocument, Branch, CurveLaw, CurveMark, CurvePoint, Limit, CURVE_ERROR,
    INDEPENDENTLY_CHECKED,
};

/// The formats `wearopt asperity` writes (the first is the default).
pub const FORMATS: &[Format] = &[Format::Text, Format::Csv, Format::Json, Format::Html];

/// The CSV columns, in order.
pub const COLUMNS: [&str; 4] = ["interference", "load", "contact_radius", "branch"];

/// A law's name for people.
fn law_words(law: CurveLaw) -> &'static str {
    match law {
        CurveLaw::LennardJones => "Lennard-Jones sphere (self-consistent)",
        CurveLaw::Jkr => "JKR",
        CurveLaw::Dmt => "DMT, van der Waals attraction",
    }
}

/// CSV with a header row; no rows when the curve was not traced.
pub fn csv(doc: &AsperityDocument) -> String {
    let mut out = COLUMNS.join(",");
    out.push('\n');
    for p in doc.curve.iter().flat_map(|c| &c.points) {
        out.push_str(&format!(
            "{},{},{},{}\n",
            number(p.interference),
            number(p.load),
            number(p.contact_radius),
            p.branch.as_str()
        ));
    }
    out
}

fn mark_words(m: &CurveMark) -> String {
    format!("P̂ = {} at δ̂ = {}", sig(m.load, 6), sig(m.interference, 6))
}

/// The limit used, in words.
/// Whether the curve is the Lennard-Jones solver's (not a closed form, nor a
/// limit standing in).
fn solved(doc: &AsperityDocument) -> bool {
    doc.options.law == CurveLaw::LennardJones && doc.limit.is_none()
}

/// What a solved Lennard-Jones curve's numbers are good to (none for a
/// closed form, or a limit standing in).
fn accuracy_words(doc: &AsperityDocument) -> Option<String> {
    if !solved(doc) {
        return None;
    }
    let (marks, out, within) = CURVE_ERROR;
    let (lo, hi) = INDEPENDENTLY_CHECKED;
    let checked = if (lo..=hi).contains(&doc.options.tabor) {
        format!("within {marks:.0e} of an independent solution")
    } else {
        format!(
            "within {marks:.0e} of an independent solution where one was computed, μ = {lo} … {hi}; not at this μ"
        )
    };
    Some(format!(
        "the pull-off and the jumps are converged (solved again on three nested meshes and extrapolated: {checked}); the rows are the solver's default mesh, within {out:.0e} out of contact and {within:.0e} in it"
    ))
}

fn limit_words(doc: &AsperityDocument) -> Option<String> {
    let l = doc.limit?;
    let (side, name) = match l.limit {
        Limit::BradleyDmt => (
            "below",
            "the rigid sphere (Bradley) out of contact and DMT in it",
        ),
        Limit::Jkr => ("above", "JKR"),
    };
    Some(format!(
        "μ = {} is {side} the solved range (μ {} {}): the curve is its limit, {name}; at the switch the limit's pull-off is off by {} %",
        sig(doc.options.tabor, 4),
        if l.limit == Limit::Jkr { ">" } else { "<" },
        sig(l.switch_tabor, 3),
        sig(100.0 * l.pull_off_error, 2)
    ))
}

/// The report for people.
pub fn text(doc: &AsperityDocument) -> String {
    let o = &doc.options;
    let mut t = format!(
        "wearopt asperity — {} at Tabor parameter μ = {} (Maugis–Dugdale λ ≈ {})\n\n",
        law_words(o.law),
        number(o.tabor),
        sig(1.16 * o.tabor, 4)
    );
    t.push_str("  units: load P̂ = P/(πγR), interference δ̂ = δ (K²/(π²γ²R))^(1/3), contact radius â = a (K/(πγR²))^(1/3)\n");
    if let Some(l) = limit_words(doc) {
        t.push_str(&format!("  note: {l}\n"));
    }
    if let Some(a) = accuracy_words(doc) {
        t.push_str(&format!("  accuracy: {a}\n"));
    }
    let Some(c) = &doc.curve else {
        t.push_str(&format!(
            "  status: {} — the continuation stalled at apex gap {} Z0; no curve\n",
            doc.status.as_str(),
            doc.stalled_at.map_or("—".into(), |g| sig(g, 6))
        ));
        return t;
    };
    t.push_str(&format!(
        "  pull-off (load control): {}\n",
        mark_words(&c.pull_off)
    ));
    match (&c.jump_in, &c.jump_out) {
        (Some(i), Some(j)) => {
            t.push_str(&format!("  jump into contact at {}\n", mark_words(i)));
            t.push_str(&format!("  jump out of contact at {}\n", mark_words(j)));
        }
        _ => t.push_str("  the curve is single-valued: no jumps\n"),
    }
    t.push('\n');
    t.push_str(&format!(
        "  {:>12}  {:>14}  {:>12}  {}\n",
        "δ̂", "P̂", "â", "branch"
    ));
    for p in &c.points {
        t.push_str(&format!(
            "  {:>12}  {:>14}  {:>12}  {}\n",
            sig(p.interference, 6),
            sig(p.load, 8),
            sig(p.contact_radius, 6),
            p.branch.as_str()
        ));
    }
    t
}

fn mark_json(m: &Option<CurveMark>) -> serde_json::Value {
    match m {
        Some(m) => json!({"interference": m.interference, "load": m.load}),
        None => serde_json::Value::Null,
    }
}

/// One JSON object.
pub fn json(doc: &AsperityDocument) -> String {
    let c = doc.curve.as_ref();
    super::json_text(&json!({
        "adhesion_model": doc.options.law.as_str(),
        "tabor": doc.options.tabor,
        "status": doc.status.as_str(),
        "limit": doc.limit.map(|l| json!({
            "limit": l.limit.as_str(),
            "switch_tabor": l.switch_tabor,
            "pull_off_error": l.pull_off_error,
        })),
        "points": c.map(|c| &c.points),
        "pull_off": c.map(|c| json!({"load": c.pull_off.load, "interference": c.pull_off.interference})),
        "jump_in": mark_json(&c.and_then(|c| c.jump_in)),
        "jump_out": mark_json(&c.and_then(|c| c.jump_out)),
        "accuracy": solved(doc).then(|| {
            let (marks, out, within) = CURVE_ERROR;
            let (lo, hi) = INDEPENDENTLY_CHECKED;
            json!({
                "marks": marks,
                "points_out_of_contact": out,
                "points_in_contact": within,
                "independent_solution": {
                    "tabor_from": lo,
                    "tabor_to": hi,
                    "covers_this_tabor": (lo..=hi).contains(&doc.options.tabor),
                },
            })
        }),
    }))
}

/// The path of a curve split at its branches, one series per stretch.
fn stretches(path: &[CurvePoint]) -> Vec<(Branch, Vec<(f64, f64)>)> {
    let mut out: Vec<(Branch, Vec<(f64, f64)>)> = Vec::new();
    for p in path {
        let xy = (p.interference, p.load);
        match out.last_mut() {
            Some((b, pts)) if *b == p.branch => pts.push(xy),
            Some((_, pts)) => {
                let joint = *pts.last().expect("a stretch has a point");
                out.push((p.branch, vec![joint, xy]));
            }
            None => out.push((p.branch, vec![xy])),
        }
    }
    out
}

/// Load against interference: the law's path by branch, its jumps, and the
/// JKR and DMT curves over the same interferences.
pub fn plot_svg(doc: &AsperityDocument) -> String {
    let o = &doc.options;
    let within = |x: f64| x >= o.from && x <= o.to;
    let mut plot = LinePlot::new(
        format!(
            "One asperity — {}, μ = {}",
            law_words(o.law),
            number(o.tabor)
        ),
        Axis::linear("interference δ̂ = δ (K²/(π²γ²R))^(1/3)"),
        Axis::linear("load P̂ = P/(πγR)"),
    );
    for other in &doc.comparison {
        let pts: Vec<(f64, f64)> = other
            .path
            .iter()
            .filter(|p| within(p.interference))
            .map(|p| (p.interference, p.load))
            .collect();
        plot = plot.with_series(
            Series::new(format!("{} (comparison)", law_words(other.law)), pts)
                .with_marker(Marker::None)
                .with_color(match other.law {
                    CurveLaw::Jkr => "#999999",
                    _ => "#c8a2c8",
                }),
        );
    }
    if let Some(c) = &doc.curve {
        // A Lennard-Jones curve without jumps is single-valued: no branch to name
        // (its rows' `contact` says only that the contact radius is above zero,
        // which it is on the whole curve at small μ, far out of contact too), one
        // curve in one colour. JKR's and DMT's branches are their own.
        let single_valued =
            c.law == CurveLaw::LennardJones && c.jump_in.is_none() && c.jump_out.is_none();
        let mut named = [false; 3];
        for (branch, pts) in stretches(&c.path) {
            let pts: Vec<(f64, f64)> = pts.into_iter().filter(|p| within(p.0)).collect();
            if pts.is_empty() {
                continue;
            }
            let k = if single_valued { 0 } else { branch as usize };
            let name = if named[k] {
                String::new()
            } else if single_valued {
                named[k] = true;
                "single-valued curve (no jumps)".to_string()
            } else {
                named[k] = true;
                format!("{} branch", branch.as_str())
            };
            let branch = if single_valued {
                Branch::Approach
            } else {
                branch
            };
            plot = plot.with_series(Series::new(name, pts).with_marker(Marker::None).with_color(
                match branch {
                    Branch::Approach => "#1f77b4",
                    Branch::Unstable => "#ff7f0e",
                    Branch::Contact => "#2ca02c",
                },
            ));
        }
        let marks: Vec<(&str, CurveMark)> = [
            ("pull-off", Some(c.pull_off)),
            ("jump in", c.jump_in),
            ("jump out", c.jump_out),
        ]
        .into_iter()
        .filter_map(|(n, m)| m.map(|m| (n, m)))
        .filter(|(_, m)| within(m.interference))
        .collect();
        for (name, m) in marks {
            plot = plot.with_series(
                Series::new(
                    format!("{name}: P̂ = {}", sig(m.load, 4)),
                    vec![(m.interference, m.load)],
                )
                .without_line(),
            );
        }
    }
    plot.to_svg()
}

/// One self-contained HTML page.
pub fn html(doc: &AsperityDocument) -> String {
    let o = &doc.options;
    let mut p = super::html::Page::new(&format!(
        "wearopt asperity — {}, μ = {}",
        law_words(o.law),
        number(o.tabor)
    ));
    p.paragraph(
        "Maugis units: load P̂ = P/(πγR), interference δ̂ = δ (K²/(π²γ²R))^(1/3), contact radius â = a (K/(πγR²))^(1/3). The Maugis–Dugdale parameter is λ ≈ 1.16 μ.",
        None,
    );
    if let Some(l) = limit_words(doc) {
        p.paragraph(&format!("{l}."), Some("status"));
    }
    if let Some(a) = accuracy_words(doc) {
        p.paragraph(&format!("Accuracy: {a}."), None);
    }
    match &doc.curve {
        None => p.paragraph(
            &format!(
                "Status {}: the continuation stalled at apex gap {} Z0; no curve.",
                doc.status.as_str(),
                doc.stalled_at.map_or("—".into(), |g| sig(g, 6))
            ),
            Some("status"),
        ),
        Some(c) => {
            let mut s = format!("Pull-off (load control): {}.", mark_words(&c.pull_off));
            if let (Some(i), Some(j)) = (&c.jump_in, &c.jump_out) {
                s.push_str(&format!(
                    " Jump into contact at {}; jump out at {}.",
                    mark_words(i),
                    mark_words(j)
                ));
            } else {
                s.push_str(" The curve is single-valued: no jumps.");
            }
            p.paragraph(&s, None);
        }
    }
    p.figure(
        "asperity",
        &plot_svg(doc),
        "Load against interference of one asperity: the law's branches (approach until the jump into contact, unstable between the jumps, contact until the jump out on retraction), its pull-off and jumps, and the JKR and DMT curves for comparison.",
    );
    let rows: Vec<Vec<String>> = doc
        .curve
        .iter()
        .flat_map(|c| &c.points)
        .map(|p| {
            vec![
                sig(p.interference, 6),
                sig(p.load, 8),
                sig(p.contact_radius, 6),
                p.branch.as_str().to_string(),
            ]
        })
        .collect();
    p.table(&["δ̂", "P̂", "â", "branch"], &rows, &[3]);
    p.finish()
}

/// The document in `format` (one of [`FORMATS`]).
pub fn render(doc: &AsperityDocument, format: Format) -> Result<String, FormatError> {
    Ok(match format {
        Format::Text => text(doc),
        Format::Csv => csv(doc),
        Format::Json => json(doc),
        Format::Html => html(doc),
    })
}
