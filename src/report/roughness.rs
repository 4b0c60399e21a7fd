//! The report of a scan analysis (`wearopt roughness`): text, JSON and the PSD plot.

use serde_json::{json, Value};

use super::svg::{Axis, LinePlot, Marker, Series};
use super::{si, sig, sig_exp};
use crate::app::roughness::RoughnessDocument;
use crate::surface::psd::{Psd, PsdKind};
use crate::surface::read::Format;
use crate::surface::{Roughness, Warning};
use crate::units::{format_quantity, Dimension};

/// The formats `wearopt roughness` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[super::Format::Text, super::Format::Json];

/// The report's view of a document.
pub fn view(doc: &RoughnessDocument) -> RoughnessReport<'_> {
    RoughnessReport {
        file: &doc.file,
        format: doc.format,
        roughness: &doc.roughness,
        psd: Some(&doc.psd),
    }
}

/// The document in `format` (one of [`FORMATS`]).
pub fn render(
    doc: &RoughnessDocument,
    format: super::Format,
) -> Result<String, super::format::FormatError> {
    let r = view(doc);
    match format {
        super::Format::Text => Ok(text(&r)),
        super::Format::Json => Ok(super::json_text(&json_value(&r))),
        given => Err(super::format::FormatError::NotRendered {
            command: "roughness",
            given,
            accepted: FORMATS,
        }),
    }
}

/// The JSON document as a value (what Python reads).
pub fn json_document(doc: &RoughnessDocument) -> Value {
    json_value(&view(doc))
}

/// The power spectral density as a log–log SVG plot.
pub fn psd_plot(doc: &RoughnessDocument) -> String {
    psd_svg(&view(doc), &doc.psd)
}

/// Everything a roughness report shows.
pub struct RoughnessReport<'a> {
    /// The file as named by the user.
    pub file: &'a str,
    /// Its format.
    pub format: Format,
    /// The analysis.
    pub roughness: &'a Roughness,
    /// The PSD of the levelled map (before any cut-off).
    pub psd: Option<&'a Psd>,
}

/// One warning in words.
pub(crate) fn warning_text(w: &Warning) -> String {
    match w {
        Warning::Anisotropy { ratio } => format!(
            "anisotropy: m2 differs by a factor {} between x and y (above 2); the McCool formulas assume an isotropic surface, so σ, R and N are averages of two different directions",
            sig(*ratio, 3)
        ),
        Warning::CountingDisagrees {
            density_ratio,
            sigma_ratio,
            radius_ratio,
            cutoff_applied,
        } => {
            let mut parts = vec![format!("density ×{}", sig(*density_ratio, 3))];
            if let Some(s) = sigma_ratio {
                parts.push(format!("height spread ×{}", sig(*s, 3)));
            }
            if let Some(r) = radius_ratio {
                parts.push(format!("radius ×{}", sig(*r, 3)));
            }
            format!(
                "counted summits and the McCool estimates differ by more than 30 % ({}): roughness reaches the pixel scale; {}",
                parts.join(", "),
                if *cutoff_applied {
                    "try a longer cut-off"
                } else {
                    "a cut-off is needed (--cutoff, e.g. 5 to 10 pixels)"
                }
            )
        }
        Warning::GwProductOutOfRange { product } => format!(
            "η R σ = {} is outside the 0.03–0.05 that Greenwood–Williamson analyses assume",
            sig(*product, 3)
        ),
        Warning::MissingPoints { missing, total } => format!(
            "{missing} of {total} points are missing: left out of the moments and summit count, set to 0 in the PSD"
        ),
        Warning::Profile => "a profile (one line): m2 and m4 are along x only and the areal formulas assume an isotropic surface; summits cannot be counted on a line".to_string(),
        Warning::OneDirection { used, missing } => format!(
            "no two neighbouring points along {missing} are both valid (missing points interleave): m2 and m4 are taken along {used} alone, which assumes the surface isotropic"
        ),
    }
}

fn opt(x: Option<f64>) -> Value {
    x.map_or(Value::Null, |v| json!(v))
}

/// The `[roughness]` table the analysis gives, ready to paste into a problem file.
pub(crate) fn roughness_block(r: &RoughnessReport) -> String {
    let p = &r.roughness.parameters;
    let cut = match r.roughness.settings.cutoff {
        Some(c) => format!("cut-off {}", format_quantity(c, Dimension::Length)),
        None => "no cut-off".to_string(),
    };
    format!(
        "[roughness]   # from {}: {} levelling, {}, α = {}\nsigma = \"{}\"\nasperity_radius = \"{}\"\nasperity_density = \"{}\"\n",
        r.file,
        r.roughness.settings.level.as_str(),
        cut,
        sig(p.bandwidth, 3),
        format_quantity(p.summit_sigma, Dimension::Length),
        format_quantity(p.summit_radius, Dimension::Length),
        format_quantity(p.summit_density, Dimension::InverseArea),
    )
}

/// One JSON object, SI units.
pub fn json(r: &RoughnessReport) -> String {
    super::json_text(&json_value(r))
}

/// The object [`json()`] writes, as a value.
pub fn json_value(r: &RoughnessReport) -> Value {
    let g = r.roughness;
    let m = &g.moments;
    let p = &g.parameters;
    let summits = g.summits.as_ref().map_or(Value::Null, |s| {
        json!({
            "count": s.count,
            "candidates": s.candidates,
            "density": s.density,
            "sigma": opt(s.sigma),
            "mean_radius": opt(s.mean_radius),
            "mean_height": opt(s.mean_height),
        })
    });
    let psd = r.psd.map_or(Value::Null, |psd| {
        json!({
            "kind": match psd.kind { PsdKind::Areal => "areal", PsdKind::Profile => "profile" },
            "unit": match psd.kind { PsdKind::Areal => "m^4", PsdKind::Profile => "m^3" },
            "q": psd.q,
            "c": psd.c,
            "filled_missing": psd.filled,
        })
    });
    json!({
        "file": r.file,
        "format": r.format,
        "nx": g.nx,
        "ny": g.ny,
        "pixel_size_x": g.pixel_size_x,
        "pixel_size_y": g.pixel_size_y,
        "valid_fraction": g.valid_fraction,
        "level": g.settings.level.as_str(),
        "cutoff": opt(g.settings.cutoff),
        "kept_nx": g.kept_nx,
        "kept_ny": g.kept_ny,
        "m0": m.m0,
        "m2": m.m2,
        "m4": m.m4,
        "m2_x": m.m2_x,
        "m2_y": opt(m.m2_y),
        "m4_x": m.m4_x,
        "m4_y": opt(m.m4_y),
        "anisotropy_ratio": m.anisotropy_ratio(),
        "rms_height": g.rms_height(),
        "rms_slope": g.rms_slope(),
        "bandwidth": p.bandwidth,
        "summit_sigma": p.summit_sigma,
        "summit_radius": p.summit_radius,
        "summit_density": p.summit_density,
        "mean_summit_height": p.mean_summit_height,
        "gw_product": p.gw_product(),
        "summits": summits,
        "warnings": g.warnings.iter().map(warning_text).collect::<Vec<_>>(),
        "psd": psd,
    })
}

/// A report for people.
pub fn text(r: &RoughnessReport) -> String {
    let g = r.roughness;
    let m = &g.moments;
    let p = &g.parameters;
    let mut o = String::new();
    let mut line = |s: String| {
        o.push_str(&s);
        o.push('\n');
    };
    line(format!("wearopt roughness — {}", r.file));
    line(String::new());
    line("Scan".into());
    if g.ny == 1 {
        line(format!(
            "  profile ({}), {} points, pixel {} ({} long), {} of the points valid",
            r.format.name(),
            g.nx,
            si(g.pixel_size_x, "m", 4),
            si(g.pixel_size_x * g.nx as f64, "m", 4),
            percent(g.valid_fraction),
        ));
    } else {
        line(format!(
            "  map ({}), {} × {} points, pixel {} × {} ({} × {}), {} of the points valid",
            r.format.name(),
            g.nx,
            g.ny,
            si(g.pixel_size_x, "m", 4),
            si(g.pixel_size_y, "m", 4),
            si(g.pixel_size_x * g.nx as f64, "m", 4),
            si(g.pixel_size_y * g.ny as f64, "m", 4),
            percent(g.valid_fraction),
        ));
    }
    line(format!("  levelling: {}", g.settings.level.as_str()));
    match g.settings.cutoff {
        Some(c) => line(format!(
            "  cut-off λs = {} (ISO 16610-61 Gaussian, {} pixels along x); edge band of {} × {} pixels dropped, {} × {} points analysed, levelled again",
            si(c, "m", 4),
            sig(c / g.pixel_size_x, 3),
            g.edge_band.0,
            g.edge_band.1,
            g.kept_nx,
            g.kept_ny
        )),
        None => line("  cut-off: none".into()),
    }
    line(String::new());
    line("Spectral moments (finite differences)".into());
    line(format!(
        "  m0 = {} m²   rms height √m0 = {}",
        sig_exp(m.m0, 5),
        si(g.rms_height(), "m", 4)
    ));
    match (m.m2_y, m.m4_y) {
        (Some(m2y), Some(m4y)) => {
            line(format!(
                "  m2 = {}  (x {}, y {}; anisotropy ratio {})   rms slope √(2 m2) = {}",
                sig_exp(m.m2, 5),
                sig_exp(m.m2_x, 4),
                sig_exp(m2y, 4),
                sig(m.anisotropy_ratio(), 3),
                sig_exp(g.rms_slope(), 4)
            ));
            line(format!(
                "  m4 = {} m⁻²  (x {}, y {})",
                sig_exp(m.m4, 5),
                sig_exp(m.m4_x, 4),
                sig_exp(m4y, 4)
            ));
        }
        _ => {
            line(format!(
                "  m2 = {}   rms slope √(2 m2) = {}",
                sig_exp(m.m2, 5),
                sig_exp(g.rms_slope(), 4)
            ));
            line(format!("  m4 = {} m⁻²", sig_exp(m.m4, 5)));
        }
    }
    line(String::new());
    line("Greenwood–Williamson parameters (McCool 1986)".into());
    line(format!(
        "  bandwidth α = m0 m4 / m2²  = {}",
        sig(p.bandwidth, 4)
    ));
    line(format!(
        "  summit height spread σ    = {}",
        si(p.summit_sigma, "m", 4)
    ));
    line(format!(
        "  summit radius R           = {}",
        si(p.summit_radius, "m", 4)
    ));
    line(format!(
        "  summit density N          = {} per µm²",
        sig_exp(p.summit_density * 1e-12, 4)
    ));
    line(format!(
        "  mean summit height        = {} above the mean plane (the model's separation is measured from the summits' mean plane)",
        si(p.mean_summit_height, "m", 4)
    ));
    line(format!(
        "  η R σ                     = {}   (0.0204 √α; GW analyses assume 0.03–0.05)",
        sig(p.gw_product(), 3)
    ));
    line(String::new());
    match &g.summits {
        Some(s) => {
            line(format!(
                "Summits counted (higher than all 8 neighbours; {} candidate points)",
                s.candidates
            ));
            let ratio = |a: f64, b: f64| format!("×{}", sig(a / b, 3));
            line(format!(
                "  count {}, density {} per µm²  ({} the McCool value)",
                s.count,
                sig_exp(s.density * 1e-12, 4),
                ratio(s.density, p.summit_density)
            ));
            if let Some(sd) = s.sigma {
                line(format!(
                    "  height spread {}  ({})",
                    si(sd, "m", 4),
                    ratio(sd, p.summit_sigma)
                ));
            }
            if let Some(rad) = s.mean_radius {
                line(format!(
                    "  mean radius {}  ({})",
                    si(rad, "m", 4),
                    ratio(rad, p.summit_radius)
                ));
            }
        }
        None => line("Summits: not counted (a profile)".into()),
    }
    if let Some(psd) = r.psd {
        line(String::new());
        let (what, unit) = match psd.kind {
            PsdKind::Areal => ("areal, radially averaged", "m⁴"),
            PsdKind::Profile => ("profile", "m³"),
        };
        line(format!(
            "Power spectral density ({what}, Hann window, levelled map before any cut-off): {} bins from q = {} to {} rad/m, C in {unit}{}",
            psd.q.len(),
            psd.q.first().map_or("-".into(), |q| sig_exp(*q, 3)),
            psd.q.last().map_or("-".into(), |q| sig_exp(*q, 3)),
            if psd.filled > 0 {
                format!("; {} missing points set to 0", psd.filled)
            } else {
                String::new()
            }
        ));
        let integral = psd.integral();
        line(format!(
            "  its integral {} = {} m² (rms {}): the mean square of the levelled map before any cut-off",
            match psd.kind {
                PsdKind::Areal => "∫ C d²q",
                PsdKind::Profile => "∫ C dq",
            },
            sig_exp(integral, 4),
            si(integral.sqrt(), "m", 3)
        ));
    }
    if !g.warnings.is_empty() {
        line(String::new());
        for w in &g.warnings {
            let t = warning_text(w);
            match w {
                Warning::MissingPoints { .. } | Warning::Profile => line(format!("note: {t}")),
                _ => line(format!("WARNING: {t}")),
            }
        }
    }
    line(String::new());
    line("To use these values, paste into a problem file:".into());
    line(String::new());
    o.push_str(&roughness_block(r));
    o
}

fn percent(x: f64) -> String {
    if x == 1.0 {
        "all".to_string()
    } else {
        format!("{} %", sig(100.0 * x, 4))
    }
}

/// The PSD against q, log–log, with the cut-off wavenumber q_s = 2π/λs marked.
pub fn psd_svg(r: &RoughnessReport, psd: &Psd) -> String {
    let points: Vec<(f64, f64)> = psd.q.iter().copied().zip(psd.c.iter().copied()).collect();
    let unit = match psd.kind {
        PsdKind::Areal => "m⁴",
        PsdKind::Profile => "m³",
    };
    let mut plot = LinePlot::new(
        format!("Power spectral density — {}", r.file),
        Axis::log("wavenumber q = 2π/λ").with_unit("rad/m"),
        Axis::log("C(q)").with_unit(unit),
    )
    .with_series(Series::new("radially averaged PSD", points.clone()).with_marker(Marker::Circle));
    if let Some(cut) = r.roughness.settings.cutoff {
        let qs = 2.0 * std::f64::consts::PI / cut;
        let (lo, hi) = points
            .iter()
            .filter(|p| p.1 > 0.0)
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), p| {
                (lo.min(p.1), hi.max(p.1))
            });
        if lo.is_finite() && hi > 0.0 {
            plot = plot.with_series(
                Series::new(
                    format!("cut-off λs = {}", si(cut, "m", 3)),
                    vec![(qs, lo), (qs, hi)],
                )
                .with_marker(Marker::None)
                .with_color("#d55e00"),
            );
        }
    }
    plot.to_svg()
}

/// Lines for a scene report whose roughness came from a scan: where from, α, cut-off,
/// levelling, and the analysis' warnings.
pub(crate) fn scan_lines(scan: &crate::problem::ScanSource) -> Vec<String> {
    let g = &scan.roughness;
    let p = &g.parameters;
    let mut lines = vec![format!(
        "  σ, R and N come from the scan {} ({}, {} × {} points of {} × {}): bandwidth α = {}, {} levelling, cut-off {}; the summits' mean plane (from which d is measured) lies {} above the surface's",
        scan.topography,
        scan.format.name(),
        g.nx,
        g.ny,
        si(g.pixel_size_x, "m", 4),
        si(g.pixel_size_y, "m", 4),
        sig(p.bandwidth, 4),
        g.settings.level.as_str(),
        g.settings
            .cutoff
            .map_or("none".to_string(), |c| si(c, "m", 4)),
        si(p.mean_summit_height, "m", 4),
    )];
    for w in &g.warnings {
        let text = match w {
            // No PSD is taken for a scene.
            Warning::MissingPoints { missing, total } => format!(
                "{missing} of {total} points are missing: left out of the moments and summit count"
            ),
            _ => warning_text(w),
        };
        lines.push(format!("  scan: {text}"));
    }
    if let Some(l) = bem_corrected_words(scan) {
        lines.push(format!("  {l}"));
    }
    lines
}

/// Under `contact_model = "bem_corrected"`: what the scene's real area is, in
/// words, for every report that shows the scene.
pub(crate) fn bem_corrected_words(scan: &crate::problem::ScanSource) -> Option<String> {
    if scan.contact_model != crate::problem::ContactModel::BemCorrected {
        return None;
    }
    let measured = scan.correction.as_ref()?;
    Some(format!(
        "contact model: bem_corrected — the statistical real area, and so the wear and friction, × {} (the exact-to-statistical ratio of real areas on the scan at the operating point {}, both without adhesion; held fixed as a study moves the design)",
        sig(1.0 / measured.ratio, 4),
        si(measured.pressure, "Pa", 3)
    ))
}

/// The JSON object of a scene's scan source (SI units).
pub(crate) fn scan_json(scan: &crate::problem::ScanSource) -> Value {
    let g = &scan.roughness;
    let p = &g.parameters;
    json!({
        "topography": scan.topography,
        "path": scan.path,
        "format": scan.format,
        "nx": g.nx,
        "ny": g.ny,
        "pixel_size_x": g.pixel_size_x,
        "pixel_size_y": g.pixel_size_y,
        "level": g.settings.level.as_str(),
        "cutoff": opt(g.settings.cutoff),
        "bandwidth": p.bandwidth,
        "summit_sigma": p.summit_sigma,
        "summit_radius": p.summit_radius,
        "summit_density": p.summit_density,
        "mean_summit_height": p.mean_summit_height,
        "warnings": g.warnings.iter().map(warning_text).collect::<Vec<_>>(),
        "contact_model": scan.contact_model.as_str(),
    })
}
