//! The report of `wearopt figures`: each figure's points as CSV, the slopes as CSV,
//! each figure as an SVG plot, and the summary (least-squares lines and the verdict on
//! each claim of the paper's §4) as text or JSON. Rendering only: the numbers come
//! from [`crate::figures`], and the caller writes the files.

use std::fmt::Write as _;
use std::path::PathBuf;

use serde_json::json;

use super::number;
use super::svg::{Axis, LinePlot, Series};
use crate::app::figures::{FigureFile, FiguresDocument};
use crate::figures::{
    Claim, Evidence, Figure, FigureSettings, FigureSlopes, Slopes, Varied, EQUAL_SLOPE_RATIO,
    LINEAR_R_SQUARED,
};

/// The formats `wearopt figures` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[super::Format::Text, super::Format::Json];

/// The CSV header of each figure's points.
pub const FIGURE_COLUMNS: &str = "theta,lambda,load,wear_volume";
/// The CSV header of slopes.csv.
pub const SLOPE_COLUMNS: &str = "figure,theta,lambda,slope,r_squared";

const LOAD_LABEL: &str = "non-dimensional load P̄";
const WEAR_LABEL: &str = "non-dimensional wear volume V̄";

/// Every point of a figure's curves, one row each.
pub fn figure_csv(fig: &Figure) -> String {
    let mut out = format!("{FIGURE_COLUMNS}\n");
    for c in &fig.curves {
        for p in &c.points {
            let _ = writeln!(
                out,
                "{},{},{},{}",
                number(c.theta),
                number(c.lambda),
                number(p.load),
                number(p.wear_volume)
            );
        }
    }
    out
}

/// The least-squares slope and r² of every curve.
pub fn slopes_csv(figures: &[Figure]) -> String {
    let mut out = format!("{SLOPE_COLUMNS}\n");
    for f in figures {
        for c in &f.curves {
            let (slope, r2) = c
                .fit
                .map_or((f64::NAN, f64::NAN), |x| (x.slope, x.r_squared));
            let _ = writeln!(
                out,
                "{},{},{},{},{}",
                f.spec.number,
                number(c.theta),
                number(c.lambda),
                number(slope),
                number(r2)
            );
        }
    }
    out
}

fn series_name(fig: &Figure, theta: f64, lambda: f64) -> String {
    match fig.spec.varied {
        Varied::Theta => format!("θ = {theta}"),
        Varied::Lambda => format!("λ = {lambda}"),
    }
}

/// One figure as an SVG line plot: a curve per (θ, λ), markers on every tenth point.
pub fn svg(fig: &Figure) -> String {
    let mut plot = LinePlot::new(
        fig.spec.caption(),
        Axis::linear(LOAD_LABEL),
        Axis::linear(WEAR_LABEL),
    );
    for c in &fig.curves {
        let pts = c.points.iter().map(|p| (p.load, p.wear_volume)).collect();
        let every = (c.points.len() / 10).max(1);
        plot = plot.with_series(
            Series::new(series_name(fig, c.theta, c.lambda), pts).with_marker_every(every),
        );
    }
    plot.to_svg()
}

/// A slope or ratio for the evidence: four decimals, or three significant digits in
/// scientific notation when tiny or huge.
fn fmt(x: f64) -> String {
    if x.is_finite() && x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e5) {
        format!("{x:.3e}")
    } else {
        format!("{x:.4}")
    }
}

fn symbol(v: Varied) -> &'static str {
    match v {
        Varied::Theta => "θ",
        Varied::Lambda => "λ",
    }
}

fn slope_list(s: &Slopes) -> String {
    s.values
        .iter()
        .zip(&s.slopes)
        .map(|(v, sl)| format!("{}={v}: {}", symbol(s.varied), fmt(*sl)))
        .collect::<Vec<_>>()
        .join(", ")
}

fn ordering_words(f: &FigureSlopes) -> String {
    match f {
        FigureSlopes::Missing(n) => format!("figure {n} not computed"),
        FigureSlopes::Computed(s) => {
            let mut e = format!("Fig. {} slopes {}", s.figure, slope_list(s));
            if !s.falls {
                let breaks: Vec<String> =
                    s.breaks.iter().map(|(a, b)| format!("{a} → {b}")).collect();
                e.push_str(&format!(
                    "; slope does not fall with {} at {}",
                    symbol(s.varied),
                    breaks.join(", ")
                ));
            }
            e
        }
    }
}

/// What the paper says, for a claim's id.
pub fn statement(id: &str) -> &'static str {
    match id {
        "linear" => "wear volume depends linearly on load for all parameter combinations",
        "low_lambda_low_theta_wears_more" => {
            "at low λ (0.1) the wear rate is larger for lower θ (Fig. 1)"
        }
        "high_lambda_theta_insensitive" => {
            "at high λ (5) the wear rate is more or less the same for all θ (Fig. 2)"
        }
        "low_lambda_wears_more" => {
            "the wear rate is larger for lower λ at both low and high θ (Figs. 3 and 4)"
        }
        _ => "",
    }
}

/// The test applied to a claim, with its threshold.
pub fn criterion(id: &str) -> String {
    match id {
        "linear" => format!("every curve's least-squares r² ≥ {LINEAR_R_SQUARED}"),
        "low_lambda_low_theta_wears_more" => {
            "slope of V̄ against P̄ falls strictly as θ rises".to_string()
        }
        "high_lambda_theta_insensitive" => format!("max/min slope ≤ {EQUAL_SLOPE_RATIO}"),
        "low_lambda_wears_more" => {
            "slope falls strictly as λ rises, at θ = 10 and at θ = 25".to_string()
        }
        _ => String::new(),
    }
}

/// The numbers that decide a claim, in words.
pub fn evidence(e: &Evidence) -> String {
    match e {
        Evidence::Linearity {
            worst,
            below,
            curves,
        } => match worst {
            None => "no curves".to_string(),
            Some(w) => format!(
                "smallest r² = {} (Fig. {}, θ = {}, λ = {}); {below} of {curves} curves below {LINEAR_R_SQUARED}",
                w.r_squared
                    .map_or("none".to_string(), |r| format!("{r:.6}")),
                w.figure,
                w.theta,
                w.lambda
            ),
        },
        Evidence::Ordering { figures } => figures
            .iter()
            .map(ordering_words)
            .collect::<Vec<_>>()
            .join("; "),
        Evidence::EqualSlopes { figure, ratio } => match figure {
            FigureSlopes::Computed(s) => {
                format!("Fig. {} slopes {}; max/min = {}", s.figure, slope_list(s), fmt(*ratio))
            }
            FigureSlopes::Missing(n) => format!("figure {n} not computed"),
        },
    }
}

fn verdict(holds: Option<bool>) -> &'static str {
    match holds {
        Some(true) => "holds",
        Some(false) => "does not hold",
        None => "undecided",
    }
}

/// The summary for people: files written, the least-squares line of every curve,
/// and each claim's verdict with its test and evidence.
pub fn text(
    settings: &FigureSettings,
    files: &[PathBuf],
    figures: &[Figure],
    claims: &[Claim],
) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "Figures 1-4 (paper §4): wear volume V̄ = Ā against load P̄ for P̄ = {} to {} \
({} evenly spaced loads per curve; each solved for h on the loading branch, docs/model.md §4).",
        settings.load_min, settings.load_max, settings.points
    );
    let _ = writeln!(o, "\nFiles written:");
    for f in files {
        let _ = writeln!(o, "  {}", f.display());
    }
    let _ = writeln!(o, "\nLeast-squares lines V̄ ≈ slope·P̄ + intercept:");
    let _ = writeln!(
        o,
        "  {:>3} {:>6} {:>7} {:>8} {:>9} {:>9} {:>11} {:>11}",
        "fig", "θ", "λ", "slope", "intercept", "r²", "V̄(P̄ min)", "V̄(P̄ max)"
    );
    let mut failed = 0;
    for f in figures {
        for c in &f.curves {
            failed += c.failed;
            let (slope, icpt, r2) = c.fit.map_or((f64::NAN, f64::NAN, f64::NAN), |x| {
                (x.slope, x.intercept, x.r_squared)
            });
            let first = c.points.first().map_or(f64::NAN, |p| p.wear_volume);
            let last = c.points.last().map_or(f64::NAN, |p| p.wear_volume);
            let _ = writeln!(
                o,
                "  {:>3} {:>6} {:>7} {:>8.4} {:>9.4} {:>9.5} {:>11.4} {:>11.4}",
                f.spec.number, c.theta, c.lambda, slope, icpt, r2, first, last
            );
        }
    }
    if failed > 0 {
        let _ = writeln!(
            o,
            "  {failed} load(s) had no converged separation and are left out"
        );
    }
    let _ = writeln!(
        o,
        "\nClaims of §4 under the exact model (thresholds: r² ≥ {LINEAR_R_SQUARED}, max/min slope ≤ {EQUAL_SLOPE_RATIO}):"
    );
    for (i, c) in claims.iter().enumerate() {
        let _ = writeln!(
            o,
            "  ({}) {}: {}. Test: {}. {}.",
            i + 1,
            verdict(c.holds).to_uppercase(),
            statement(c.id),
            criterion(c.id),
            evidence(&c.evidence)
        );
    }
    o
}

/// The summary as one JSON object: `settings`, `thresholds`, `files`, `curves`, `claims`.
pub fn json(
    settings: &FigureSettings,
    files: &[PathBuf],
    figures: &[Figure],
    claims: &[Claim],
) -> String {
    let curves: Vec<_> = figures
        .iter()
        .flat_map(|f| {
            f.curves.iter().map(move |c| {
                json!({
                    "figure": f.spec.number,
                    "theta": c.theta,
                    "lambda": c.lambda,
                    "slope": c.fit.map(|x| x.slope),
                    "intercept": c.fit.map(|x| x.intercept),
                    "r_squared": c.fit.map(|x| x.r_squared),
                    "points": c.points.len(),
                    "failed": c.failed,
                    "pull_off_load": c.pull_off_load,
                    "plastic_jump": c.plastic_jump,
                })
            })
        })
        .collect();
    let claims: Vec<_> = claims
        .iter()
        .map(|c| {
            json!({
                "id": c.id,
                "statement": statement(c.id),
                "criterion": criterion(c.id),
                "holds": c.holds,
                "evidence": evidence(&c.evidence),
            })
        })
        .collect();
    let v = json!({
        "settings": settings,
        "thresholds": {
            "linear_r_squared": LINEAR_R_SQUARED,
            "equal_slope_ratio": EQUAL_SLOPE_RATIO,
        },
        "files": files.iter().map(|f| f.display().to_string()).collect::<Vec<_>>(),
        "curves": curves,
        "claims": claims,
    });
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_else(|_| "{}".to_string());
    s.push('\n');
    s
}

/// The document's summary in `format` (one of [`FORMATS`]), listing its files.
pub fn render(
    doc: &FiguresDocument,
    format: super::Format,
) -> Result<String, super::format::FormatError> {
    let files: Vec<PathBuf> = doc.files.iter().map(|(p, _)| p.clone()).collect();
    match format {
        super::Format::Text => Ok(text(&doc.settings, &files, &doc.figures, &doc.claims)),
        super::Format::Json => Ok(json(&doc.settings, &files, &doc.figures, &doc.claims)),
        given => Err(super::format::FormatError::NotRendered {
            command: "figures",
            given,
            accepted: FORMATS,
        }),
    }
}

/// The contents of one of the document's files.
pub fn file(doc: &FiguresDocument, which: FigureFile) -> String {
    match which {
        FigureFile::Csv(i) => doc.figures.get(i).map_or_else(String::new, figure_csv),
        FigureFile::Svg(i) => doc.figures.get(i).map_or_else(String::new, svg),
        FigureFile::Slopes => slopes_csv(&doc.figures),
    }
}
