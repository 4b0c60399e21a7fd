//! A scene across relative humidity (`wearopt humidity`): a table, CSV, JSON, an
//! HTML page, and the plot of Γ and the pull-off force against RH.

use serde_json::json;

use super::format::FormatError;
use super::svg::{Axis, LinePlot, Series};
use super::Format;
use super::{number, si, sig, sig_exp};
use crate::app::humidity::{HumidityDocument, HumidityRow, THRESHOLD_RATIO};

/// The formats `wearopt humidity` writes (the first is the default).
pub const FORMATS: &[Format] = &[Format::Text, Format::Csv, Format::Json, Format::Html];

/// The CSV columns, in order.
pub const COLUMNS: [&str; 8] = [
    "relative_humidity",
    "separation",
    "capillary_load",
    "pull_off_force",
    "apparent_work_of_adhesion",
    "wetted_fraction",
    "wear_rate",
    "status",
];

fn cell(x: Option<f64>) -> String {
    x.map(number).unwrap_or_default()
}

/// CSV with a header row (an empty cell where a value does not exist: no separation
/// once the surfaces are apart).
pub fn csv(doc: &HumidityDocument) -> String {
    let mut out = COLUMNS.join(",");
    out.push('\n');
    for r in &doc.rows {
        let cells = [
            number(r.relative_humidity),
            cell(r.separation),
            cell(r.capillary_load),
            cell(r.pull_off_force),
            cell(r.apparent_work_of_adhesion),
            cell(r.wetted_fraction),
            number(r.wear_rate),
            r.status.as_str().to_string(),
        ];
        out.push_str(&cells.join(","));
        out.push('\n');
    }
    out
}

/// The air the sweep varies, in words.
fn air_words(doc: &HumidityDocument) -> String {
    let e = &doc.environment;
    let liquid = match e.liquid {
        crate::model::Liquid::Water => "water".to_string(),
        crate::model::Liquid::Given {
            surface_tension,
            molar_volume,
        } => format!(
            "a liquid of surface tension {} and molar volume {}",
            si(surface_tension, "N/m", 4),
            si(molar_volume, "m³/mol", 4)
        ),
    };
    format!(
        "{liquid} at {}, contact angles {}° (body a) and {}° (body b){}",
        si(e.temperature, "K", 5),
        sig(e.contact_angle_a.to_degrees(), 4),
        sig(e.contact_angle_b.to_degrees(), 4),
        if doc.environment_given {
            ""
        } else {
            "; the problem file has no [environment], so water wetting both bodies is assumed"
        }
    )
}

/// The threshold in words.
fn threshold_words(doc: &HumidityDocument) -> String {
    let last = doc.rows.last().map_or(0.0, |r| r.relative_humidity);
    match (doc.threshold_humidity, doc.dry_work_of_adhesion) {
        (Some(t), Some(g)) if doc.continuum_humidity.is_some_and(|c| t < c) => format!(
            "threshold humidity {} %, below the {} % where the Kelvin radius reaches 0.5 nm: as soon as a meniscus forms, Γ exceeds {} × its dry value {} (the dry adhesion is negligible against the liquid's)",
            sig_exp(100.0 * t, 3),
            sig(100.0 * doc.continuum_humidity.unwrap_or(0.0), 4),
            THRESHOLD_RATIO,
            si(g, "J/m²", 4)
        ),
        (Some(t), Some(g)) => format!(
            "threshold humidity {} %: Γ reaches {} × its dry value {} there",
            sig(100.0 * t, 4),
            THRESHOLD_RATIO,
            si(g, "J/m²", 4)
        ),
        (None, Some(g)) if g > 0.0 => format!(
            "no threshold up to RH = {} %: Γ stays below {} × its dry value {}",
            sig(100.0 * last, 4),
            THRESHOLD_RATIO,
            si(g, "J/m²", 4)
        ),
        _ => "no threshold: the scene has no adhesion in dry air to compare with".to_string(),
    }
}

/// Whether a row's Kelvin radius is under 0.5 nm (a humid row below the continuum
/// humidity).
fn below_continuum(doc: &HumidityDocument, r: &HumidityRow) -> bool {
    r.relative_humidity > 0.0
        && doc
            .continuum_humidity
            .is_some_and(|c| r.relative_humidity < c)
}

/// The continuum limit in words, when a row lies below it (the text and the page
/// mark those rows with † and put it before these words; the JSON's `notes` holds
/// them as they are).
fn continuum_words(doc: &HumidityDocument) -> Option<String> {
    let c = doc.continuum_humidity?;
    doc.rows.iter().any(|r| below_continuum(doc, r)).then(|| {
        format!(
            "below RH = {} % the Kelvin radius is under 0.5 nm (a few molecules of liquid): the continuum Kelvin–Laplace picture is doubtful there; read those rows as estimates",
            sig(100.0 * c, 4)
        )
    })
}

/// A row's numbers for people: RH %, separation, capillary load, pull-off, Γ, wet
/// fraction, wear rate ("—" where one does not exist).
fn cells(r: &HumidityRow) -> [String; 7] {
    let q = |x: Option<f64>, u: &str| x.map_or("—".into(), |x| si(x, u, 4));
    [
        sig(100.0 * r.relative_humidity, 4),
        q(r.separation, "m"),
        q(r.capillary_load, "N"),
        q(r.pull_off_force, "N"),
        q(r.apparent_work_of_adhesion, "J/m²"),
        r.wetted_fraction.map_or("—".into(), |w| sig_exp(w, 3)),
        si(r.wear_rate, "m³/m", 4),
    ]
}

/// The report for people.
pub fn text(doc: &HumidityDocument) -> String {
    let mut o = format!("wearopt humidity — {}\n\n", doc.name);
    o.push_str(&format!("  air: {}\n", air_words(doc)));
    o.push_str(&format!(
        "  dry air: Γ = {}, pull-off force {}\n",
        doc.dry_work_of_adhesion
            .map_or("—".into(), |g| si(g, "J/m²", 4)),
        doc.dry_pull_off_force.map_or("—".into(), |f| si(f, "N", 4))
    ));
    o.push_str(&format!("  {}\n", threshold_words(doc)));
    if let Some(c) = continuum_words(doc) {
        o.push_str(&format!("  † {c}\n"));
    }
    o.push('\n');
    o.push_str(&format!(
        "  {:>7}  {:>11}  {:>12}  {:>11}  {:>12}  {:>9}  {:>12}\n",
        "RH %", "separation", "capillary", "pull-off", "Γ", "wet", "wear rate"
    ));
    for r in &doc.rows {
        let [rh, d, cap, pull, gamma, wet, wear] = cells(r);
        o.push_str(&format!(
            "  {rh:>7}  {d:>11}  {cap:>12}  {pull:>11}  {gamma:>12}  {wet:>9}  {wear:>12}{}\n",
            match r.status {
                crate::model::Status::Ok => String::new(),
                s => format!("  ({})", s.as_str()),
            } + if below_continuum(doc, r) { "  †" } else { "" }
        ));
    }
    o
}

/// One JSON object.
pub fn json(doc: &HumidityDocument) -> String {
    let e = &doc.environment;
    super::json_text(&json!({
        "name": doc.name,
        "temperature": e.temperature,
        "contact_angle_a": e.contact_angle_a,
        "contact_angle_b": e.contact_angle_b,
        "surface_tension": e.liquid.surface_tension(e.temperature),
        "environment_given": doc.environment_given,
        "dry_work_of_adhesion": doc.dry_work_of_adhesion,
        "dry_pull_off_force": doc.dry_pull_off_force,
        "threshold_ratio": THRESHOLD_RATIO,
        "threshold_humidity": doc.threshold_humidity,
        "continuum_humidity": doc.continuum_humidity,
        "points": doc.rows,
        "notes": continuum_words(doc).into_iter().collect::<Vec<_>>(),
    }))
}

/// Γ and the pull-off force against RH, each over its dry value, on a log axis, with
/// the threshold humidity marked.
pub fn plot_svg(doc: &HumidityDocument) -> String {
    let ratio = |v: fn(&HumidityRow) -> Option<f64>, dry: Option<f64>| -> Vec<(f64, f64)> {
        doc.rows
            .iter()
            .filter_map(|r| {
                let d = dry.filter(|d| *d > 0.0)?;
                let x = v(r)? / d;
                (x > 0.0 && x.is_finite()).then_some((100.0 * r.relative_humidity, x))
            })
            .collect()
    };
    let gamma = ratio(|r| r.apparent_work_of_adhesion, doc.dry_work_of_adhesion);
    let pull = ratio(|r| r.pull_off_force, doc.dry_pull_off_force);
    let mut plot = LinePlot::new(
        format!("Adhesion against humidity — {}", doc.name),
        Axis::linear("relative humidity RH").with_unit("%"),
        Axis::log("ratio to dry air"),
    );
    plot = plot.with_series(Series::new(
        format!(
            "Γ / Γ_dry (Γ_dry = {})",
            doc.dry_work_of_adhesion
                .map_or("—".into(), |g| si(g, "J/m²", 3))
        ),
        gamma.clone(),
    ));
    plot = plot.with_series(Series::new(
        format!(
            "pull-off / dry ({})",
            doc.dry_pull_off_force.map_or("—".into(), |f| si(f, "N", 3))
        ),
        pull.clone(),
    ));
    if let Some(t) = doc.threshold_humidity {
        let ys = gamma.iter().chain(&pull).map(|p| p.1);
        let (lo, hi) = ys.fold((f64::INFINITY, 0.0f64), |(a, b), y| (a.min(y), b.max(y)));
        if lo.is_finite() && hi > 0.0 {
            plot = plot.with_series(
                Series::new(
                    format!(
                        "threshold RH = {} % (Γ = {} Γ_dry)",
                        if t >= 1e-3 {
                            sig(100.0 * t, 4)
                        } else {
                            sig_exp(100.0 * t, 3)
                        },
                        THRESHOLD_RATIO
                    ),
                    vec![
                        (100.0 * t, lo.min(THRESHOLD_RATIO)),
                        (100.0 * t, hi.max(THRESHOLD_RATIO)),
                    ],
                )
                .with_marker(super::svg::Marker::None),
            );
        }
    }
    plot.to_svg()
}

/// One self-contained HTML page.
pub fn html(doc: &HumidityDocument) -> String {
    let mut p = super::html::Page::new(&format!("wearopt humidity — {}", doc.name));
    p.paragraph(&format!("Air: {}.", air_words(doc)), None);
    p.paragraph(
        &format!("{}.", capitalize(&threshold_words(doc))),
        Some("status"),
    );
    if let Some(c) = continuum_words(doc) {
        p.paragraph(&format!("† {}.", capitalize(&c)), Some("warn"));
    }
    let rows: Vec<Vec<String>> = doc
        .rows
        .iter()
        .map(|r| {
            let mut row = Vec::from(cells(r));
            row.push(
                r.status.as_str().to_string() + if below_continuum(doc, r) { " †" } else { "" },
            );
            row
        })
        .collect();
    p.figure(
        "humidity",
        &plot_svg(doc),
        "The apparent work of adhesion Γ (what a cantilever-beam test measures) and the pull-off force, each over its value in dry air, against the relative humidity; the vertical line marks the threshold humidity where Γ reaches ten times its dry value.",
    );
    p.table(
        &[
            "RH %",
            "separation",
            "capillary load",
            "pull-off force",
            "Γ",
            "wet fraction",
            "wear rate",
            "status",
        ],
        &rows,
        &[7],
    );
    p.finish()
}

fn capitalize(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().collect::<String>() + c.as_str())
        .unwrap_or_default()
}

/// The document in `format` (one of [`FORMATS`]).
pub fn render(doc: &HumidityDocument, format: Format) -> Result<String, FormatError> {
    Ok(match format {
        Format::Text => text(doc),
        Format::Csv => csv(doc),
        Format::Json => json(doc),
        Format::Html => html(doc),
    })
}
