//! The non-dimensional model along a range of separations (`wearopt curve`).

use super::number;

/// The formats `wearopt curve` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[super::Format::Csv, super::Format::Json];

use crate::app::curve::CurveDocument;
pub use crate::app::curve::CurveRow;

/// The column names, in order.
pub const COLUMNS: [&str; 7] = [
    "h",
    "load",
    "area",
    "plastic_area",
    "critical_interference",
    "dload_dh",
    "noncontact_load",
];

/// CSV with a header row.
pub fn csv(rows: &[CurveRow]) -> String {
    let mut out = COLUMNS.join(",");
    out.push('\n');
    for r in rows {
        let cells = [
            r.h,
            r.load,
            r.area,
            r.plastic_area,
            r.critical_interference,
            r.dload_dh,
            r.noncontact_load,
        ];
        out.push_str(&cells.map(number).join(","));
        out.push('\n');
    }
    out
}

/// A JSON array of objects keyed like the CSV columns.
pub fn json(rows: &[CurveRow]) -> String {
    let mut s = serde_json::to_string_pretty(rows).unwrap_or_else(|_| "[]".to_string());
    s.push('\n');
    s
}

/// The document in `format` (one of [`FORMATS`]).
pub fn render(
    doc: &CurveDocument,
    format: super::Format,
) -> Result<String, super::format::FormatError> {
    match format {
        super::Format::Csv => Ok(csv(&doc.rows)),
        super::Format::Json => Ok(json(&doc.rows)),
        given => Err(super::format::FormatError::NotRendered {
            command: "curve",
            given,
            accepted: FORMATS,
        }),
    }
}
