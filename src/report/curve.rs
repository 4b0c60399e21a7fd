//! The non-dimensional model along a range of separations (`wearopt curve`).

use serde::Serialize;

use super::number;

/// The formats `wearopt curve` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[super::Format::Csv, super::Format::Json];

/// One row of a curve: the model at one separation h.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurveRow {
    /// h = d/σ.
    pub h: f64,
    /// P̄(h).
    pub load: f64,
    /// Ā(h), which is also the non-dimensional wear volume V̄ (eq. 16).
    pub area: f64,
    /// Ā_p(h).
    pub plastic_area: f64,
    /// Δc (∞ without plasticity: `inf` in CSV, `null` in JSON).
    pub critical_interference: f64,
    /// dP̄/dh.
    pub dload_dh: f64,
    /// The share of P̄ carried by attracted asperities not in contact (DMT; ≤ 0, 0 under JKR).
    pub noncontact_load: f64,
}

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
