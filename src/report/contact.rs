//! The report of `wearopt contact`: the boundary-element contact of a scan beside
//! the statistical model's, as text, CSV, JSON and an HTML page; the plot of real
//! area against pressure; the pressure and gap fields as `.npy`.

use serde_json::{json, Value};

use super::format::FormatError;
use super::svg::{Axis, LinePlot, Marker, Series};
use super::{number, sig, sig_exp, Format};
use crate::app::contact::{
    AdhesionResult, ContactDocument, ContactPoint, Outcome, RESOLVED_PIXELS,
};
use crate::units::{format_quantity, Dimension};

/// The formats `wearopt contact` writes (the first is the default).
pub const FORMATS: &[Format] = &[Format::Text, Format::Csv, Format::Json, Format::Html];

/// The CSV columns, in order.
/// The `adhesive_*` columns are empty without `--work-of-adhesion`.
pub const COLUMNS: [&str; 22] = [
    "pressure",
    "real_area_fraction",
    "plastic_area_fraction",
    "contact_patches",
    "mean_gap",
    "max_pressure",
    "residual",
    "iterations",
    "status",
    "gw_real_area_fraction",
    "gw_plastic_area_fraction",
    "gw_contact_count",
    "gw_status",
    "area_ratio",
    "adhesive_real_area_fraction",
    "adhesive_contact_patches",
    "adhesive_mean_gap",
    "adhesive_pressure",
    "adhesive_max_tension",
    "adhesive_residual",
    "adhesive_iterations",
    "adhesive_status",
];

/// The status word of a solve.
pub fn status_word(outcome: Outcome) -> &'static str {
    match outcome {
        Outcome::Converged => "converged",
        Outcome::IterationLimit => "iteration_limit",
    }
}

/// The document in `format` (every format there is; the `Result` keeps the
/// signature of the other reports').
pub fn render(doc: &ContactDocument, format: Format) -> Result<String, FormatError> {
    Ok(match format {
        Format::Text => text(doc),
        Format::Csv => csv(doc),
        Format::Json => super::json_text(&json_document(doc)),
        Format::Html => html(doc),
    })
}

fn cell(x: Option<f64>) -> String {
    x.map(number).unwrap_or_default()
}

/// CSV, one row per pressure in the order given; empty cells where the
/// statistical model has no answer.
pub fn csv(doc: &ContactDocument) -> String {
    let mut out = COLUMNS.join(",");
    out.push('\n');
    for pt in &doc.points {
        let s = &pt.solution;
        let gw = pt.statistical;
        let cells = [
            number(s.pressure),
            number(s.real_area_fraction),
            number(s.plastic_area_fraction),
            s.contact_patches.to_string(),
            number(s.mean_gap),
            number(s.max_pressure),
            number(s.residual),
            s.iterations.to_string(),
            status_word(s.outcome).to_string(),
            cell(gw.map(|g| g.real_area_fraction)),
            cell(gw.map(|g| g.plastic_area_fraction)),
            cell(gw.map(|g| g.contact_count)),
            gw.map(|g| g.status.as_str().to_string())
                .unwrap_or_default(),
            cell(pt.area_ratio()),
        ];
        let a = pt.adhesive.as_ref();
        let adhesive = [
            cell(a.map(|a| a.real_area_fraction)),
            a.map(|a| a.contact_patches.to_string()).unwrap_or_default(),
            cell(a.map(|a| a.mean_gap)),
            cell(a.map(|a| a.adhesive_pressure)),
            cell(a.map(|a| a.max_tension)),
            cell(a.map(|a| a.residual)),
            a.map(|a| a.iterations.to_string()).unwrap_or_default(),
            a.map(|a| status_word(a.outcome).to_string())
                .unwrap_or_default(),
        ];
        out.push_str(&cells.join(","));
        out.push(',');
        out.push_str(&adhesive.join(","));
        out.push('\n');
    }
    out
}

/// The JSON document as a value (what Python reads).
pub fn json_document(doc: &ContactDocument) -> Value {
    let o = &doc.options;
    let statistical_inputs = match &doc.roughness {
        Ok(r) => json!({
            "summit_sigma": r.parameters.summit_sigma,
            "summit_radius": r.parameters.summit_radius,
            "summit_density": r.parameters.summit_density,
            "bandwidth": r.parameters.bandwidth,
        }),
        Err(_) => Value::Null,
    };
    let points: Vec<Value> = doc
        .points
        .iter()
        .map(|pt| {
            let s = &pt.solution;
            let gw = pt.statistical;
            json!({
                "pressure": s.pressure,
                "real_area_fraction": s.real_area_fraction,
                "plastic_area_fraction": s.plastic_area_fraction,
                "contact_patches": s.contact_patches,
                "mean_gap": s.mean_gap,
                "max_pressure": s.max_pressure,
                "residual": s.residual,
                "iterations": s.iterations,
                "status": status_word(s.outcome),
                "gw_real_area_fraction": gw.map(|g| g.real_area_fraction),
                "gw_plastic_area_fraction": gw.map(|g| g.plastic_area_fraction),
                "gw_contact_count": gw.map(|g| g.contact_count),
                "gw_status": gw.map(|g| g.status.as_str()),
                "area_ratio": pt.area_ratio(),
                "adhesive": pt.adhesive.as_ref().map(|a| json!({
                    "pressure": a.pressure,
                    "real_area_fraction": a.real_area_fraction,
                    "contact_patches": a.contact_patches,
                    "mean_gap": a.mean_gap,
                    "adhesive_pressure": a.adhesive_pressure,
                    "max_pressure": a.max_pressure,
                    "max_tension": a.max_tension,
                    "residual": a.residual,
                    "iterations": a.iterations,
                    "status": status_word(a.outcome),
                })),
            })
        })
        .collect();
    let adhesion = doc.adhesion.as_ref().map(|a| {
        let r = &a.resolution;
        json!({
            "law": "exponential",
            "work_of_adhesion": a.work,
            "range": a.range,
            "range_asked": a.range_asked,
            "coarse_grained": a.coarse_grained(),
            "process_zone": r.process_zone,
            "process_zone_pixels": r.process_zone_pixels,
            "process_zone_pixels_asked": a.resolution_asked.process_zone_pixels,
            "pixel_over_range": r.pixel_over_range,
            "rise_over_range": r.rise_over_range,
            "marginal": a.marginal(),
            "pull_off_pressure": a.pull_off.pressure,
            "pull_off_force": a.pull_off_force,
            "pull_off_mean_gap": a.pull_off.mean_gap,
            "pull_off_real_area_fraction": a.pull_off.real_area_fraction,
            "pull_off_steps": a.pull_off.steps,
            "pull_off_step": a.pull_off.step,
            "pull_off_iterations": a.pull_off.iterations,
            "pull_off_status": status_word(a.pull_off.outcome),
            "area": a.area,
        })
    });
    json!({
        "file": doc.file,
        "format": doc.format.name(),
        "pixels": doc.pixels,
        "pixel_size": doc.pixel_size,
        "level": o.level.as_str(),
        "rms_height": doc.rms_height,
        "modulus": o.modulus,
        "hardness": o.hardness,
        "tolerance": o.tolerance,
        "statistical_inputs": statistical_inputs,
        "statistical_error": doc.roughness.as_ref().err(),
        "points": points,
        "adhesion": adhesion,
        "notes": notes(doc),
    })
}

/// The statistical model against the exact one over all pressures, in words.
pub fn comparison_words(doc: &ContactDocument) -> Option<String> {
    let ratios: Vec<f64> = doc
        .points
        .iter()
        .filter_map(ContactPoint::area_ratio)
        .collect();
    if ratios.is_empty() {
        return None;
    }
    let lo = ratios.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ratios.iter().copied().fold(0.0, f64::max);
    let range = if ratios.len() == 1 || sig(lo, 2) == sig(hi, 2) {
        format!("{}×", sig(lo, 2))
    } else {
        format!("{}–{}×", sig(lo, 2), sig(hi, 2))
    };
    let verdict = if hi < 0.95 {
        "the statistical model under-predicts the real area, and so Archard wear (proportional to it), by that factor; a problem file built on this scan can take the correction with [roughness] contact_model = \"bem_corrected\""
    } else if lo > 1.05 {
        "the statistical model over-predicts the real area, and so Archard wear, by that factor"
    } else if lo >= 0.95 && hi <= 1.05 {
        "the two agree within 5 %"
    } else {
        "how far the statistical model is depends on the load — it is off by more than 5 % at some of these pressures (the table gives each), and so is its Archard wear; bem_corrected takes the ratio at a problem file's own operating point"
    };
    Some(format!(
        "On this map the statistical (Greenwood–Williamson) real area is {range} the exact one: {verdict}."
    ))
}

fn pressure(x: f64) -> String {
    format_quantity(x, Dimension::Pressure)
}

fn length(x: f64) -> String {
    format_quantity(x, Dimension::Length)
}

fn percent(x: f64) -> String {
    format!("{} %", sig(100.0 * x, 3))
}

/// The header lines: the map, the pair, the method.
fn header(doc: &ContactDocument) -> Vec<String> {
    let o = &doc.options;
    let [nx, ny] = doc.pixels;
    let [dx, dy] = doc.pixel_size;
    let pixel = if dx == dy {
        length(dx)
    } else {
        format!("{} × {}", length(dx), length(dy))
    };
    let mut lines = vec![
        format!(
            "Map: {} ({}), {nx} × {ny} points, pixel {pixel}, {} levelled, rms height {}; taken as one period of a periodic surface.",
            doc.file,
            doc.format.name(),
            o.level.as_str(),
            length(doc.rms_height)
        ),
        format!(
            "Pair: composite modulus E* = {}, {}.",
            pressure(o.modulus),
            match o.hardness {
                Some(h) => format!("hardness H = {} (pixels capped at H: elastic–perfectly plastic)", pressure(h)),
                None => "no hardness cap (purely elastic)".to_string(),
            }
        ),
        format!(
            "Exact: periodic FFT boundary elements (Westergaard kernel), Polonsky–Keer conjugate gradient, residual tolerance {}.",
            sig_exp(o.tolerance, 2)
        ),
    ];
    match &doc.roughness {
        Ok(r) => {
            let p = r.parameters;
            lines.push(format!(
                "Statistical: Greenwood–Williamson with McCool's summit σ = {}, R = {}, density {}, no adhesion{}.",
                length(p.summit_sigma),
                length(p.summit_radius),
                format_quantity(p.summit_density, Dimension::InverseArea),
                if o.hardness.is_some() { ", the same H" } else { "" }
            ));
        }
        Err(e) => lines.push(format!(
            "Statistical: no McCool parameters for this map ({e}); only the exact answer."
        )),
    }
    if let Some(a) = &doc.adhesion {
        lines.push(adhesion_line(doc, a));
    }
    lines
}

/// The adhesion's law, range and resolution in words.
fn adhesion_line(doc: &ContactDocument, a: &AdhesionResult) -> String {
    let r = &a.resolution;
    let range = match a.coarse_grained() {
        Some(k) => format!(
            "ρ = {} (coarse-grained ×{} from the {} asked, whose process zone spans {} pixels)",
            length(a.range),
            sig(k, 3),
            length(a.range_asked),
            sig(a.resolution_asked.process_zone_pixels, 2)
        ),
        None => format!("ρ = {}", length(a.range)),
    };
    format!(
        "With adhesion: exponential law −γ e^(−g/ρ), γ = {}, {range}; process zone π E* ρ²/(4γ) = {} = {} pixels (≥ {} needed), pixel/ρ = {}, rms rise per pixel/ρ = {}. Rey–Anciaux–Molinari conjugate gradient on the gap, elastic{}, each pressure met along one approach from out of range.",
        format_quantity(a.work, Dimension::SurfaceEnergy),
        length(r.process_zone),
        sig(r.process_zone_pixels, 3),
        RESOLVED_PIXELS,
        sig(r.pixel_over_range, 3),
        sig(r.rise_over_range, 3),
        if doc.options.hardness.is_some() {
            " (the cap H applies to the adhesion-free solve only)"
        } else {
            ""
        }
    )
}

/// One point's adhesive cells, or None without adhesion.
fn adhesive_row(pt: &ContactPoint, solve: String) -> Option<Vec<String>> {
    let a = pt.adhesive.as_ref()?;
    Some(vec![
        pressure(a.pressure),
        percent(a.real_area_fraction),
        a.contact_patches.to_string(),
        length(a.mean_gap),
        pressure(a.adhesive_pressure),
        pressure(a.max_tension),
        solve,
        sig_exp(a.residual, 2),
        sig(
            a.real_area_fraction / pt.solution.real_area_fraction.max(f64::MIN_POSITIVE),
            3,
        ),
    ])
}

/// The headings of the adhesive table.
const ADHESIVE_HEAD: [&str; 9] = [
    "mean pressure",
    "real area",
    "patches",
    "mean gap",
    "attraction",
    "max tension",
    "iterations",
    "residual",
    "area / dry",
];

/// The pull-off in words.
fn pull_off_words(a: &AdhesionResult) -> String {
    let p = &a.pull_off;
    format!(
        "Pull-off of the map (the most tensile mean pressure on the way out from the largest load, mean gap raised in steps of {} and an eighth of that about the minimum): {} mean, {} over its {}; at mean gap {}, {} still in contact; {} steps, {}.",
        length(p.step),
        pressure(p.pressure),
        format_quantity(a.pull_off_force, Dimension::Force),
        format_quantity(a.area, Dimension::Area),
        length(p.mean_gap),
        percent(p.real_area_fraction),
        p.steps,
        status_word(p.outcome)
    )
}

/// Warnings and notes on the adhesive solve.
fn adhesion_notes(doc: &ContactDocument, a: &AdhesionResult) -> Vec<String> {
    let mut notes = Vec::new();
    if let Some(k) = a.coarse_grained() {
        notes.push(format!(
            "note: ρ was coarse-grained ×{} (from {} to {}) so that the map resolves it well; the pull-off and the adhesive areas are those of the wider, weaker-peaked law (peak traction γ/ρ {} instead of {})",
            sig(k, 3),
            length(a.range_asked),
            length(a.range),
            pressure(a.work / a.range),
            pressure(a.work / a.range_asked)
        ));
    }
    if a.marginal() {
        notes.push(format!(
            "WARNING: the process zone spans only {} pixels (fewer than {}): the adhesive solution is marginally resolved; a finer map or a longer range would make it sure",
            sig(a.resolution.process_zone_pixels, 2),
            super::super::app::contact::WELL_RESOLVED_PIXELS
        ));
    }
    for pt in &doc.points {
        if let Some(s) = &pt.adhesive {
            if s.outcome == Outcome::IterationLimit {
                notes.push(format!(
                    "WARNING: with adhesion at {} the solve stopped at its iteration limit ({} iterations) with residual {}: that row is the last iterate, not a solution",
                    pressure(s.pressure),
                    s.iterations,
                    sig_exp(s.residual, 2)
                ));
            }
        }
    }
    if a.pull_off.outcome == Outcome::IterationLimit {
        notes.push("WARNING: some steps of the pull-off stopped at their iteration limit: the pull-off is approximate".to_string());
    }
    notes
}

/// One point's cells in the tables of the text and the HTML page; `solve`, the
/// seventh, says how the solve went (iterations, or status and iterations).
fn row(pt: &ContactPoint, solve: String) -> Vec<String> {
    let s = &pt.solution;
    let gw = pt.statistical;
    vec![
        pressure(s.pressure),
        percent(s.real_area_fraction),
        percent(s.plastic_area_fraction),
        s.contact_patches.to_string(),
        length(s.mean_gap),
        pressure(s.max_pressure),
        solve,
        sig_exp(s.residual, 2),
        gw.map_or("-".into(), |g| percent(g.real_area_fraction)),
        gw.map_or("-".into(), |g| sig(g.contact_count, 3)),
        pt.area_ratio().map_or("-".into(), |r| sig(r, 3)),
    ]
}

/// The caveats on the solves without adhesion, worded once for every format: a
/// row that is not a solution, a contact far beyond the statistical model's
/// reach, patches too small for the map to resolve their area.
fn dry_notes(doc: &ContactDocument) -> Vec<String> {
    let mut notes = Vec::new();
    for pt in &doc.points {
        let s = &pt.solution;
        if s.outcome == Outcome::IterationLimit {
            notes.push(format!(
                "WARNING: at {} the solve stopped at its iteration limit ({} iterations) with residual {} above the tolerance {}: that row is the last iterate, not a solution",
                pressure(s.pressure),
                s.iterations,
                sig_exp(s.residual, 2),
                sig_exp(doc.options.tolerance, 2)
            ));
        }
        if s.real_area_fraction > 0.3 {
            notes.push(format!(
                "note: at {} the contact covers {} of the map: far beyond the statistical model's reach (separate asperities, a few per cent of contact)",
                pressure(s.pressure),
                percent(s.real_area_fraction)
            ));
        }
    }
    let small: Vec<String> = doc
        .points
        .iter()
        .filter(|pt| {
            let s = &pt.solution;
            s.contact_patches > 0
                && (s.real_area_fraction * (doc.pixels[0] * doc.pixels[1]) as f64)
                    < 20.0 * s.contact_patches as f64
        })
        .map(|pt| pressure(pt.solution.pressure))
        .collect();
    if !small.is_empty() {
        notes.push(format!(
            "note: at {} the contact patches average fewer than 20 pixels: the real area there is resolution-limited (a finer scan of the same region gives a smaller, truer area)",
            small.join(", ")
        ));
    }
    notes
}

/// Every caveat of the document, in the order the text gives them: the dry
/// solves' (`dry_notes`), then the adhesive solve's. The text ends with them,
/// the HTML page lists them under their tables, the JSON's `notes` holds them.
pub fn notes(doc: &ContactDocument) -> Vec<String> {
    let mut notes = dry_notes(doc);
    if let Some(a) = &doc.adhesion {
        notes.extend(adhesion_notes(doc, a));
    }
    notes
}

/// The text report.
pub fn text(doc: &ContactDocument) -> String {
    let mut out = header(doc).join("\n");
    out.push_str("\n\n");
    let head = [
        "mean pressure",
        "real area",
        "plastic",
        "patches",
        "mean gap",
        "max pressure",
        "iterations",
        "residual",
        "GW area",
        "GW contacts",
        "GW/exact",
    ];
    let rows: Vec<Vec<String>> = doc
        .points
        .iter()
        .map(|pt| row(pt, pt.solution.iterations.to_string()))
        .collect();
    out.push_str(&aligned(&head, &rows));
    if let Some(a) = &doc.adhesion {
        let rows: Vec<Vec<String>> = doc
            .points
            .iter()
            .filter_map(|pt| adhesive_row(pt, pt.adhesive.as_ref()?.iterations.to_string()))
            .collect();
        out.push_str("\nWith adhesion (attraction: the mean adhesive traction; area / dry: over the adhesion-free real area):\n");
        out.push_str(&aligned(&ADHESIVE_HEAD, &rows));
        out.push('\n');
        out.push_str(&pull_off_words(a));
        out.push('\n');
    }
    let notes = notes(doc);
    if let Some(w) = comparison_words(doc) {
        out.push('\n');
        out.push_str(&w);
        out.push('\n');
    }
    if !notes.is_empty() {
        out.push('\n');
        out.push_str(&notes.join("\n"));
        out.push('\n');
    }
    out
}

/// Columns padded to their widest cell, the first left-aligned.
fn aligned(head: &[&str], rows: &[Vec<String>]) -> String {
    let width = |s: &str| s.chars().count();
    let mut widths: Vec<usize> = head.iter().map(|h| width(h)).collect();
    for r in rows {
        for (w, c) in widths.iter_mut().zip(r) {
            *w = (*w).max(width(c));
        }
    }
    let line = |cells: Vec<&str>| {
        let mut s = String::new();
        for (i, (c, w)) in cells.iter().zip(&widths).enumerate() {
            let pad = " ".repeat(w - width(c));
            if i == 0 {
                s.push_str(c);
                s.push_str(&pad);
            } else {
                s.push_str("  ");
                s.push_str(&pad);
                s.push_str(c);
            }
        }
        s.trim_end().to_string() + "\n"
    };
    let mut out = line(head.to_vec());
    for r in rows {
        out.push_str(&line(r.iter().map(String::as_str).collect()));
    }
    out
}

/// The real-area fraction against the mean pressure, both models.
pub fn area_plot(doc: &ContactDocument) -> String {
    let exact: Vec<(f64, f64)> = sorted(
        doc.points
            .iter()
            .map(|pt| (pt.solution.pressure, pt.solution.real_area_fraction))
            .collect(),
    );
    let gw: Vec<(f64, f64)> = sorted(
        doc.points
            .iter()
            .filter_map(|pt| {
                pt.statistical
                    .map(|g| (pt.solution.pressure, g.real_area_fraction))
            })
            .filter(|p| p.1 > 0.0)
            .collect(),
    );
    // Pressures in the tables' unit: the prefix the largest takes there.
    let (pf, pu) =
        crate::units::axis_unit_of(doc.points.iter().map(|pt| pt.solution.pressure), "Pa");
    let in_unit = |v: Vec<(f64, f64)>| -> Vec<(f64, f64)> {
        v.into_iter().map(|(p, a)| (p / pf, a)).collect()
    };
    let (exact, gw) = (in_unit(exact), in_unit(gw));
    let mut plot = LinePlot::new(
        format!("Real area against pressure — {}", doc.file),
        Axis::log("mean pressure p̄").with_unit(pu),
        Axis::log("real area / nominal area"),
    )
    .with_series(Series::new("exact (FFT boundary elements)", exact).with_marker(Marker::Circle));
    let adhesive: Vec<(f64, f64)> = sorted(
        doc.points
            .iter()
            .filter_map(|pt| {
                pt.adhesive
                    .as_ref()
                    .map(|a| (a.pressure, a.real_area_fraction))
            })
            .filter(|p| p.1 > 0.0)
            .collect(),
    );
    if !adhesive.is_empty() {
        plot = plot.with_series(
            Series::new("exact with adhesion", in_unit(adhesive))
                .with_marker(Marker::Triangle)
                .with_color("#009e73"),
        );
    }
    if !gw.is_empty() {
        plot = plot.with_series(
            Series::new("statistical (GW, McCool σ, R, N)", gw)
                .with_marker(Marker::Square)
                .with_color("#d55e00"),
        );
    }
    plot.to_svg()
}

fn sorted(mut v: Vec<(f64, f64)>) -> Vec<(f64, f64)> {
    v.sort_by(|a, b| a.0.total_cmp(&b.0));
    v
}

/// The largest side of an image on the HTML page (larger maps are averaged
/// over blocks of pixels).
const IMAGE_SIDE: usize = 256;

/// Block size and image size for a map of `nx` × `ny`.
fn blocks(nx: usize, ny: usize) -> (usize, usize, usize) {
    let b = nx.max(ny).div_ceil(IMAGE_SIDE).max(1);
    (b, nx.div_ceil(b), ny.div_ceil(b))
}

/// The levelled map as a grey image (black low, white high), block-averaged.
fn map_image(doc: &ContactDocument) -> Vec<u8> {
    let [nx, ny] = doc.pixels;
    let (b, w, h) = blocks(nx, ny);
    let mean = block_mean(&doc.heights, nx, ny, b);
    let lo = mean.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = mean.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let span = if hi > lo { hi - lo } else { 1.0 };
    let mut rgb = Vec::with_capacity(3 * w * h);
    for v in mean {
        let g = (255.0 * (v - lo) / span).round() as u8;
        rgb.extend_from_slice(&[g, g, g]);
    }
    super::png::rgb_png(w, h, &rgb)
}

/// The contact at one pressure: the map in pale grey, the contacting share of
/// each block in blue (red where saturated at H); `touching` and `saturated`
/// are 1 or 0 per pixel.
fn contact_image(doc: &ContactDocument, touching: &[f64], saturated: &[f64]) -> Vec<u8> {
    let [nx, ny] = doc.pixels;
    let (b, w, h) = blocks(nx, ny);
    let heights = block_mean(&doc.heights, nx, ny, b);
    let lo = heights.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = heights.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let span = if hi > lo { hi - lo } else { 1.0 };
    let contact = block_mean(touching, nx, ny, b);
    let plastic = block_mean(saturated, nx, ny, b);
    let mut rgb = Vec::with_capacity(3 * w * h);
    for i in 0..w * h {
        let grey = 200.0 + 55.0 * (heights[i] - lo) / span;
        let mix = |base: f64, ink: f64, share: f64| (base + (ink - base) * share).round() as u8;
        let (c, p) = (contact[i], plastic[i]);
        let ink = if p > 0.0 {
            [200.0, 30.0, 30.0]
        } else {
            [0.0, 90.0, 200.0]
        };
        rgb.extend_from_slice(&[
            mix(grey, ink[0], c),
            mix(grey, ink[1], c),
            mix(grey, ink[2], c),
        ]);
    }
    super::png::rgb_png(w, h, &rgb)
}

/// The mean of `field` over `b` × `b` blocks (the last ones partial).
fn block_mean(field: &[f64], nx: usize, ny: usize, b: usize) -> Vec<f64> {
    let (w, h) = (nx.div_ceil(b), ny.div_ceil(b));
    let mut sum = vec![0.0; w * h];
    let mut count = vec![0usize; w * h];
    for j in 0..ny {
        for i in 0..nx {
            let k = (j / b) * w + i / b;
            sum[k] += field[j * nx + i];
            count[k] += 1;
        }
    }
    sum.iter()
        .zip(&count)
        .map(|(s, &c)| s / c.max(1) as f64)
        .collect()
}

fn image_tag(png: &[u8], alt: &str, side: usize) -> String {
    format!(
        "<img alt=\"{}\" width=\"{side}\" style=\"image-rendering:pixelated;border:1px solid #ccc\" src=\"data:image/png;base64,{}\"/>",
        super::svg::escape(alt),
        super::png::base64(png)
    )
}

/// One self-contained HTML page: the map, its contact at each pressure, the
/// comparison table and plot.
pub fn html(doc: &ContactDocument) -> String {
    let mut p = super::html::Page::new(&format!("wearopt contact — {}", doc.file));
    for l in header(doc) {
        p.paragraph(&l, None);
    }
    if let Some(w) = comparison_words(doc) {
        p.paragraph(&w, Some("status"));
    }
    p.heading("Real area, both ways");
    let rows: Vec<Vec<String>> = doc
        .points
        .iter()
        .map(|pt| {
            let s = &pt.solution;
            row(
                pt,
                format!("{} ({} it.)", status_word(s.outcome), s.iterations),
            )
        })
        .collect();
    p.table(
        &[
            "mean pressure",
            "real area",
            "plastic",
            "patches",
            "mean gap",
            "max pressure",
            "status",
            "residual",
            "GW real area",
            "GW contacts",
            "GW / exact",
        ],
        &rows,
        &[6],
    );
    p.list(&dry_notes(doc), "warn");
    if let Some(a) = &doc.adhesion {
        p.heading("With adhesion");
        let rows: Vec<Vec<String>> = doc
            .points
            .iter()
            .filter_map(|pt| {
                let s = pt.adhesive.as_ref()?;
                adhesive_row(
                    pt,
                    format!("{} ({} it.)", status_word(s.outcome), s.iterations),
                )
            })
            .collect();
        let mut head = ADHESIVE_HEAD;
        head[6] = "status";
        p.table(&head, &rows, &[6]);
        p.paragraph(&pull_off_words(a), Some("status"));
        let notes = adhesion_notes(doc, a);
        if !notes.is_empty() {
            p.list(&notes, "warn");
        }
    }
    p.figure(
        "area",
        &area_plot(doc),
        if doc.adhesion.is_some() {
            "Real-area fraction against mean pressure: the exact boundary-element solution without adhesion (circles) and with it (triangles), and the statistical model with McCool's parameters of the same map, without adhesion (squares)."
        } else {
            "Real-area fraction against mean pressure: the exact boundary-element solution (circles) and the statistical model with McCool's parameters of the same map (squares)."
        },
    );
    p.heading("The map and its contact");
    let [nx, ny] = doc.pixels;
    let (b, w, _) = blocks(nx, ny);
    let side = (2 * w).min(360);
    let averaged = if b > 1 {
        format!(" (averaged over {b} × {b} pixel blocks)")
    } else {
        String::new()
    };
    // The map on its own row; then one row per pressure, the contact without
    // adhesion and with it side by side (the same pressure, the same scale).
    let mut rows = vec![format!(
        "<figure style=\"width:{side}px;margin:0\">{}<figcaption>levelled map, black low to white high, {} to {}{averaged}</figcaption></figure>",
        image_tag(&map_image(doc), "height map", side),
        length(doc.heights.iter().copied().fold(f64::INFINITY, f64::min)),
        length(doc.heights.iter().copied().fold(f64::NEG_INFINITY, f64::max)),
    )];
    for pt in &doc.points {
        let s = &pt.solution;
        if s.pressures.is_empty() {
            continue;
        }
        let cap = doc.options.hardness.unwrap_or(f64::INFINITY);
        let touching: Vec<f64> = s.pressures.iter().map(|&p| f64::from(p > 0.0)).collect();
        let saturated: Vec<f64> = s.pressures.iter().map(|&p| f64::from(p >= cap)).collect();
        let mut pair = vec![format!(
            "<figure style=\"width:{side}px;margin:0\">{}<figcaption>{}at {}: {} in contact (blue{}), {} patches</figcaption></figure>",
            image_tag(&contact_image(doc, &touching, &saturated), "contact", side),
            if pt.adhesive.is_some() { "without adhesion " } else { "" },
            pressure(s.pressure),
            percent(s.real_area_fraction),
            if s.plastic_area_fraction > 0.0 { "; red at H" } else { "" },
            s.contact_patches
        )];
        if let Some(a) = pt.adhesive.as_ref().filter(|a| !a.gaps.is_empty()) {
            let touching: Vec<f64> = a.gaps.iter().map(|&g| f64::from(g <= 0.0)).collect();
            let none = vec![0.0; touching.len()];
            pair.push(format!(
                "<figure style=\"width:{side}px;margin:0\">{}<figcaption>with adhesion at {}: {} in contact, {} patches</figcaption></figure>",
                image_tag(&contact_image(doc, &touching, &none), "adhesive contact", side),
                pressure(a.pressure),
                percent(a.real_area_fraction),
                a.contact_patches
            ));
        }
        rows.push(pair.join("\n"));
    }
    if doc.adhesion.is_some() {
        p.raw(
            &rows
                .iter()
                .map(|r| {
                    format!("<div style=\"display:flex;flex-wrap:wrap;gap:1em;margin-bottom:1em\">\n{r}\n</div>")
                })
                .collect::<Vec<_>>()
                .join("\n"),
        );
    } else {
        p.raw(&format!(
            "<div style=\"display:flex;flex-wrap:wrap;gap:1em\">\n{}\n</div>",
            rows.join("\n")
        ));
    }
    p.finish()
}

/// A field as a NumPy `.npy` file: little-endian f64, C order, shape (ny, nx).
pub fn npy(nx: usize, ny: usize, field: &[f64]) -> Vec<u8> {
    let mut header = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': ({ny}, {nx}), }}");
    // Magic (6) + version (2) + length (2) + header + newline, padded to 64.
    let total = 10 + header.len() + 1;
    header.push_str(&" ".repeat((64 - total % 64) % 64));
    header.push('\n');
    let mut out = Vec::with_capacity(10 + header.len() + 8 * field.len());
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    for x in field {
        out.extend_from_slice(&x.to_le_bytes());
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::contact::{ContactOptions, Statistical};
    use crate::contact::Solution;
    use crate::surface::read::Format as MapFormat;

    fn point(exact: f64, gw: f64) -> ContactPoint {
        ContactPoint {
            solution: Solution {
                pressure: 1e6,
                real_area_fraction: exact,
                plastic_area_fraction: 0.0,
                contact_patches: 3,
                mean_gap: 1e-9,
                max_pressure: 1e9,
                residual: 1e-11,
                iterations: 10,
                outcome: Outcome::Converged,
                pressures: Vec::new(),
                gaps: Vec::new(),
            },
            statistical: Some(Statistical {
                real_area_fraction: gw,
                plastic_area_fraction: 0.0,
                contact_count: 5.0,
                separation: Some(2.0),
                status: crate::model::Status::Ok,
            }),
            adhesive: None,
        }
    }

    fn doc(points: Vec<ContactPoint>) -> ContactDocument {
        ContactDocument {
            file: "map".into(),
            format: MapFormat::Npy,
            pixels: [8, 8],
            pixel_size: [1e-8, 1e-8],
            options: ContactOptions::default(),
            rms_height: 1e-9,
            heights: vec![0.0; 64],
            roughness: Err("none".into()),
            points,
            adhesion: None,
        }
    }

    /// The verdict follows the whole range of ratios: under, over, within 5 %,
    /// and load-dependent when the range straddles the band (0.64–0.99 was once
    /// called agreement).
    #[test]
    fn the_verdict_covers_the_whole_range_of_ratios() {
        let words = |pairs: &[(f64, f64)]| {
            comparison_words(&doc(pairs.iter().map(|&(e, g)| point(e, g)).collect())).unwrap()
        };
        assert!(words(&[(0.1, 0.05), (0.2, 0.12)]).contains("under-predicts"));
        assert!(words(&[(0.1, 0.12), (0.2, 0.25)]).contains("over-predicts"));
        assert!(words(&[(0.1, 0.099), (0.2, 0.202)]).contains("agree within 5 %"));
        let mixed = words(&[(0.1, 0.099), (0.2, 0.128)]);
        assert!(mixed.contains("depends on the load"), "{mixed}");
        assert!(!mixed.contains("agree"), "{mixed}");
    }
}
