//! One asperity's curve in Maugis units (`wearopt asperity`): a table, CSV,
//! JSON, an HTML page, and the plot of load against interference with the
//! branches, the jumps and the JKR and DMT curves.

use serde_json::json;

use super::format::FormatError;
use super::svg::{Axis, LinePlot, Marker, Series};
use super::Format;
use super::{number, sig};
use crate::app::asperity::{
    AsperityDocument, Branch, CurveLaw, CurveMark, CurvePoint, Limit, RowAccuracy, SiSphere,
    CURVE_ERROR, INDEPENDENTLY_CHECKED, MARKS_ERROR, ROWS_ERROR,
};

/// The formats `wearopt asperity` writes (the first is the default).
pub const FORMATS: &[Format] = &[Format::Text, Format::Csv, Format::Json, Format::Html];

/// The CSV columns, in order.
pub const COLUMNS: [&str; 4] = ["interference", "load", "contact_radius", "branch"];

/// The CSV columns added after [`COLUMNS`] when the sphere is given in SI:
/// the load (N), the interference and the contact radius (m).
pub const SI_COLUMNS: [&str; 3] = ["load_n", "interference_m", "contact_radius_m"];

/// An SI value for people: six significant figures in scientific notation
/// (newtons and metres span many decades), zero as 0.
fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.5e}")
    }
}

/// A row's load (N), interference (m) and contact radius (m).
fn si(sphere: &SiSphere, p: &CurvePoint) -> [f64; 3] {
    [
        p.load * sphere.load_scale(),
        p.interference * sphere.interference_scale(),
        p.contact_radius * sphere.radius_scale(),
    ]
}

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
    let sphere = doc.options.sphere;
    let mut out = COLUMNS.join(",");
    if sphere.is_some() {
        out.push(',');
        out.push_str(&SI_COLUMNS.join(","));
    }
    out.push('\n');
    for p in doc.curve.iter().flat_map(|c| &c.points) {
        out.push_str(&format!(
            "{},{},{},{}",
            number(p.interference),
            number(p.load),
            number(p.contact_radius),
            p.branch.as_str()
        ));
        if let Some(s) = &sphere {
            for x in si(s, p) {
                out.push(',');
                out.push_str(&number(x));
            }
        }
        out.push('\n');
    }
    out
}

fn mark_words(doc: &AsperityDocument, m: &CurveMark) -> String {
    let maugis = format!("P̂ = {} at δ̂ = {}", sig(m.load, 6), sig(m.interference, 6));
    match &doc.options.sphere {
        None => maugis,
        Some(s) => format!(
            "{maugis} (P = {} N at δ = {} m)",
            sci(m.load * s.load_scale()),
            sci(m.interference * s.interference_scale())
        ),
    }
}

/// The sphere given in SI and its scales, in words.
fn sphere_words(s: &SiSphere) -> String {
    format!(
        "sphere: R = {} m, γ = {} J/m², E* = {} Pa, Z0 = {} m, so μ = {}; P = P̂ × {} N, δ = δ̂ × {} m, a = â × {} m",
        sci(s.radius),
        sig(s.work_of_adhesion, 6),
        sci(s.modulus),
        sci(s.interatomic_distance),
        sig(s.tabor(), 6),
        sci(s.load_scale()),
        sci(s.interference_scale()),
        sci(s.radius_scale())
    )
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
    let (_, out, within) = CURVE_ERROR;
    let (lo, hi) = INDEPENDENTLY_CHECKED;
    let (pull_off, jump_in, jump_out) = MARKS_ERROR;
    let marks = format!("the pull-off within {pull_off:.0e}, the jump in within {jump_in:.0e} and the jump out within {jump_out:.0e}");
    let checked = if (lo..=hi).contains(&doc.options.tabor) {
        format!("{marks} of an independent solution")
    } else {
        format!(
            "{marks} of an independent solution where one was computed, μ = {lo} … {hi}; not at this μ"
        )
    };
    let rows = match doc.options.rows {
        RowAccuracy::Converged => format!(
            "the rows are converged too (each solved again so), within {:.0e} of the load relative ({:.0e} absolute where |P̂| < 1e-3)",
            ROWS_ERROR.0, ROWS_ERROR.1
        ),
        RowAccuracy::Fast => format!(
            "the rows are the trace's mesh, within {out:.0e} out of contact and {within:.0e} in it ({})",
            if doc.options.tabor > crate::app::asperity::CONVERGED_ROWS_UP_TO {
                "the default above μ = 5, where converging them takes minutes: --converged does"
            } else {
                "--fast"
            }
        ),
    };
    Some(format!(
        "the pull-off and the jumps are converged (solved again on three nested meshes and extrapolated: {checked}); {rows}"
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
    if let Some(s) = &o.sphere {
        t.push_str(&format!("  {}\n", sphere_words(s)));
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
        mark_words(doc, &c.pull_off)
    ));
    match (&c.jump_in, &c.jump_out) {
        (Some(i), Some(j)) => {
            t.push_str(&format!("  jump into contact at {}\n", mark_words(doc, i)));
            t.push_str(&format!(
                "  jump out of contact at {}\n",
                mark_words(doc, j)
            ));
        }
        _ => t.push_str("  the curve is single-valued: no jumps\n"),
    }
    t.push('\n');
    let width = if o.sphere.is_some() { 8 } else { 0 };
    t.push_str(&format!(
        "  {:>12}  {:>14}  {:>12}  {:<width$}",
        "δ̂", "P̂", "â", "branch"
    ));
    if o.sphere.is_some() {
        t.push_str(&format!(
            "  {:>13}  {:>13}  {:>13}",
            "P (N)", "δ (m)", "a (m)"
        ));
    }
    t.push('\n');
    for p in &c.points {
        t.push_str(&format!(
            "  {:>12}  {:>14}  {:>12}  {:<width$}",
            sig(p.interference, 6),
            sig(p.load, 8),
            sig(p.contact_radius, 6),
            p.branch.as_str()
        ));
        if let Some(s) = &o.sphere {
            for x in si(s, p) {
                t.push_str(&format!("  {:>13}", sci(x)));
            }
        }
        t.push('\n');
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
        "rows_accuracy": solved(doc).then(|| doc.options.rows.as_str()),
        "sphere": doc.options.sphere.map(|s| json!({
            "radius": s.radius,
            "work_of_adhesion": s.work_of_adhesion,
            "modulus": s.modulus,
            "interatomic_distance": s.interatomic_distance,
            "load_scale": s.load_scale(),
            "interference_scale": s.interference_scale(),
            "contact_radius_scale": s.radius_scale(),
        })),
        "points": c.map(|c| match &doc.options.sphere {
            None => json!(c.points),
            Some(s) => c.points.iter().map(|p| {
                let [load, interference, radius] = si(s, p);
                json!({
                    "interference": p.interference,
                    "load": p.load,
                    "contact_radius": p.contact_radius,
                    "branch": p.branch.as_str(),
                    "load_n": load,
                    "interference_m": interference,
                    "contact_radius_m": radius,
                })
            }).collect(),
        }),
        "pull_off": c.map(|c| json!({"load": c.pull_off.load, "interference": c.pull_off.interference})),
        "jump_in": mark_json(&c.and_then(|c| c.jump_in)),
        "jump_out": mark_json(&c.and_then(|c| c.jump_out)),
        "accuracy": solved(doc).then(|| {
            let (marks, out, within) = CURVE_ERROR;
            let (lo, hi) = INDEPENDENTLY_CHECKED;
            let fast = doc.options.rows == RowAccuracy::Fast;
            json!({
                "marks": marks,
                "pull_off": MARKS_ERROR.0,
                "jump_in": MARKS_ERROR.1,
                "jump_out": MARKS_ERROR.2,
                "points_out_of_contact": fast.then_some(out),
                "points_in_contact": fast.then_some(within),
                "rows_relative": (!fast).then_some(ROWS_ERROR.0),
                "rows_absolute": (!fast).then_some(ROWS_ERROR.1),
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

/// The runs of a polyline (interference, load) inside from ≤ δ̂ ≤ to, each cut at
/// the range's ends where a segment crosses them (the crossing by linear
/// interpolation, so that a curve starts at `from` itself, not at the first point
/// past it), and split where the polyline leaves the range and comes back.
fn clipped(pts: &[(f64, f64)], from: f64, to: f64) -> Vec<Vec<(f64, f64)>> {
    let inside = |x: f64| x >= from && x <= to;
    let cross = |a: (f64, f64), b: (f64, f64), x: f64| {
        let t = (x - a.0) / (b.0 - a.0);
        (x, a.1 + t * (b.1 - a.1))
    };
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for (i, &p) in pts.iter().enumerate() {
        let prev = i.checked_sub(1).map(|j| pts[j]);
        match (prev, inside(p.0)) {
            (Some(q), true) if !inside(q.0) => {
                // Entering: from the end it crossed.
                let edge = if q.0 < from { from } else { to };
                run.push(cross(q, p, edge));
                run.push(p);
            }
            (_, true) => run.push(p),
            (Some(q), false) if inside(q.0) => {
                // Leaving: to the end it crosses, and the run ends.
                let edge = if p.0 < from { from } else { to };
                run.push(cross(q, p, edge));
                runs.push(std::mem::take(&mut run));
            }
            (Some(q), false) => {
                // Across the whole range between two points outside it.
                if (q.0 < from && p.0 > to) || (q.0 > to && p.0 < from) {
                    let (a, b) = if q.0 < p.0 { (from, to) } else { (to, from) };
                    runs.push(vec![cross(q, p, a), cross(q, p, b)]);
                }
            }
            (None, false) => {}
        }
    }
    if !run.is_empty() {
        runs.push(run);
    }
    runs.retain(|r| !r.is_empty());
    runs
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
            .map(|p| (p.interference, p.load))
            .collect();
        for (i, run) in clipped(&pts, o.from, o.to).into_iter().enumerate() {
            let name = if i == 0 {
                format!("{} (comparison)", law_words(other.law))
            } else {
                String::new()
            };
            plot = plot.with_series(Series::new(name, run).with_marker(Marker::None).with_color(
                match other.law {
                    CurveLaw::Jkr => "#999999",
                    _ => "#c8a2c8",
                },
            ));
        }
    }
    if let Some(c) = &doc.curve {
        // A Lennard-Jones curve without jumps is single-valued: no branch to name
        // (its rows' `contact` says only that the contact radius is above zero,
        // which it is on the whole curve at small μ, far out of contact too), one
        // curve in one colour. JKR's and DMT's branches are their own.
        let single_valued =
            c.law == CurveLaw::LennardJones && c.jump_in.is_none() && c.jump_out.is_none();
        let mut named = [false; 3];
        for (branch, pts) in stretches(&c.path)
            .into_iter()
            .flat_map(|(b, pts)| clipped(&pts, o.from, o.to).into_iter().map(move |r| (b, r)))
        {
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
    if let Some(s) = &o.sphere {
        p.paragraph(&format!("The {}.", sphere_words(s)), None);
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
            let mut s = format!("Pull-off (load control): {}.", mark_words(doc, &c.pull_off));
            if let (Some(i), Some(j)) = (&c.jump_in, &c.jump_out) {
                s.push_str(&format!(
                    " Jump into contact at {}; jump out at {}.",
                    mark_words(doc, i),
                    mark_words(doc, j)
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
            let mut row = vec![
                sig(p.interference, 6),
                sig(p.load, 8),
                sig(p.contact_radius, 6),
                p.branch.as_str().to_string(),
            ];
            if let Some(s) = &o.sphere {
                row.extend(si(s, p).map(sci));
            }
            row
        })
        .collect();
    let mut header = vec!["δ̂", "P̂", "â", "branch"];
    if o.sphere.is_some() {
        header.extend(["P (N)", "δ (m)", "a (m)"]);
    }
    p.table(&header, &rows, &[3]);
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

#[cfg(test)]
mod tests {
    use super::clipped;

    /// A path clipped to the range starts and ends at the range's ends (the
    /// crossings interpolated on their segments), splits where it leaves and
    /// comes back, and keeps a segment that spans the whole range.
    #[test]
    fn a_path_is_cut_at_the_range_ends() {
        let line = [(-2.0, 0.0), (-0.5, 3.0), (0.5, 5.0), (2.0, 8.0)];
        assert_eq!(
            clipped(&line, -1.0, 1.0),
            vec![vec![(-1.0, 2.0), (-0.5, 3.0), (0.5, 5.0), (1.0, 6.0)]]
        );
        // Out and back in (an S-curve's fold past `to`).
        let fold = [(0.0, 0.0), (2.0, 1.0), (0.5, 2.0)];
        let runs = clipped(&fold, -1.0, 1.0);
        assert_eq!(runs.len(), 2);
        assert_eq!(runs[0], vec![(0.0, 0.0), (1.0, 0.5)]);
        assert_eq!((runs[1][0].0, runs[1][1]), (1.0, (0.5, 2.0)));
        assert!((runs[1][0].1 - 5.0 / 3.0).abs() < 1e-15);
        // One segment across the whole range, and nothing inside.
        assert_eq!(
            clipped(&[(-3.0, 0.0), (3.0, 6.0)], -1.0, 1.0),
            vec![vec![(-1.0, 2.0), (1.0, 4.0)]]
        );
        assert!(clipped(&[(2.0, 0.0), (3.0, 1.0)], -1.0, 1.0).is_empty());
    }
}
