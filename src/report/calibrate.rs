//! The report of a friction calibration (`wearopt fit-adhesion`): text and JSON.

use serde_json::{json, Value};

use super::{si, sig};
use crate::app::Vocabulary;
use crate::calibrate::{
    Calibration, CalibrationNote, FrictionCoefficient, PointNote, CONFIDENCE_LEVEL,
};
use crate::units::{format_number, format_quantity, Dimension};

/// The formats `wearopt fit-adhesion` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[super::Format::Text, super::Format::Json];

/// One JSON object, SI units (N, m, N/m, Pa). Keys: those of [`Calibration`]
/// (`notes` worded, options named as the command line's flags) plus
/// `note_details` (the notes as values), `confidence_level` and `model`.
pub fn json(c: &Calibration) -> String {
    json_for(c, Vocabulary::Flags)
}

/// [`json()`] with the notes naming options in `vocabulary` (Python's keyword
/// arguments for the Python package).
pub fn json_for(c: &Calibration, vocabulary: Vocabulary) -> String {
    let mut v = serde_json::to_value(c).unwrap_or(Value::Null);
    if let Value::Object(obj) = &mut v {
        obj.insert("note_details".into(), json!(c.notes));
        if let Some(Value::Array(points)) = obj.get_mut("per_point") {
            for (v, p) in points.iter_mut().zip(&c.per_point) {
                if let (Value::Object(o), Some(n)) = (v, &p.note) {
                    o.insert("note_detail".into(), json!(n));
                    o.insert("note".into(), json!(point_note(n)));
                }
            }
        }
        obj.insert(
            "notes".into(),
            json!(c
                .notes
                .iter()
                .map(|n| note_for(n, vocabulary))
                .collect::<Vec<_>>()),
        );
        obj.insert("confidence_level".into(), json!(CONFIDENCE_LEVEL));
        obj.insert(
            "model".into(),
            json!("F = mu [P + 3 pi gamma R + sqrt(6 pi gamma R P + (3 pi gamma R)^2)] (paper eq. 14, docs/model.md §5)"),
        );
    }
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_else(|_| "{}".into());
    s.push('\n');
    s
}

/// Why a measurement has no γ of its own, in words.
pub fn point_note(n: &PointNote) -> String {
    match *n {
        PointNote::FrictionBelowSliding {
            sliding_friction,
            friction_coefficient,
        } => format!(
            "F < μP = {} at μ = {}: no γ ≥ 0 gives this friction",
            format_quantity(sliding_friction, Dimension::Force),
            format_number(friction_coefficient)
        ),
    }
}

/// A calibration note in words, options named as the command line's flags.
pub fn note(n: &CalibrationNote) -> String {
    note_for(n, Vocabulary::Flags)
}

/// A calibration note in words, options named in `vocabulary`.
pub fn note_for(n: &CalibrationNote, vocabulary: Vocabulary) -> String {
    let (mu, fit_mu) = match vocabulary {
        Vocabulary::Flags => ("--mu", "--fit-mu"),
        Vocabulary::Keywords => ("mu=", "fit_mu=True"),
    };
    match *n {
        CalibrationNote::FrictionCoefficientAssumed { value } => format!(
            "μ = {value} assumed (the paper's value); give {mu} to set it or {fit_mu} to fit it"
        ),
        CalibrationNote::ExactFit {
            measurements,
            parameters,
        } => format!(
            "{measurements} measurement{} for {parameters} parameter{}: the fit is exact and has no uncertainty estimate",
            if measurements == 1 { "" } else { "s" },
            if parameters == 1 { "" } else { "s" }
        ),
        CalibrationNote::IntervalClippedAtZero => {
            "the 95 % interval of γ reaches below 0 and is clipped there (γ ≥ 0)".into()
        }
        CalibrationNote::NoAdhesion => {
            "γ is at the bottom of the range searched: the data are consistent with no adhesion"
                .into()
        }
        CalibrationNote::NotConverged => {
            "the Gauss–Newton iteration did not meet its tolerance; the estimate is the best point found"
                .into()
        }
        CalibrationNote::UncertaintyUndefined => format!(
            "the data do not determine γ and μ separately (their covariance is singular): no standard errors or intervals can be given; fix μ with {mu}, or add loads further apart"
        ),
    }
}

fn gamma(x: f64) -> String {
    si(x, "N/m", 3)
}

/// Works of adhesion that one line gives together, in one prefix, that of `lead`
/// (the fitted value, or the interval's larger bound): `1.48 ± 0.500 mN/m`, not
/// `1.48 mN/m ± 500 µN/m`. The numbers, and the prefixed unit.
fn gammas_in_prefix_of(lead: f64, values: &[f64]) -> (Vec<String>, String) {
    let (factor, unit) = crate::units::axis_unit(lead.abs(), "N/m");
    let numbers = values
        .iter()
        .map(|&v| {
            if v == 0.0 {
                "0".to_string()
            } else {
                sig(v / factor, 3)
            }
        })
        .collect();
    (numbers, unit)
}

fn force(x: f64) -> String {
    si(x, "N", 3)
}

/// A report for people.
pub fn text(c: &Calibration) -> String {
    let mut out = String::new();
    let mut line = |s: String| {
        out.push_str(&s);
        out.push('\n');
    };
    let n = c.per_point.len();
    let fitted_mu = c.friction_coefficient_source == FrictionCoefficient::Fit;
    line(format!("wearopt fit-adhesion — {}", c.origin));
    line(String::new());
    line(format!(
        "Model: F = μ [P + 3πγR + √(6πγRP + (3πγR)²)] (JKR friction, eq. 14), R = {}",
        si(c.radius, "m", 3)
    ));
    line(format!(
        "Fit: least squares on F, {n} point{}, {} ({} degree{} of freedom)",
        if n == 1 { "" } else { "s" },
        if fitted_mu {
            "γ and μ fitted".to_string()
        } else {
            format!("γ fitted, μ = {} held", sig(c.friction_coefficient, 4))
        },
        c.degrees_of_freedom,
        if c.degrees_of_freedom == 1 { "" } else { "s" }
    ));
    line(String::new());
    let pct = format!("{:.0} %", CONFIDENCE_LEVEL * 100.0);
    line(format!(
        "work of adhesion γ      {}",
        match c.standard_error {
            Some(se) => {
                let (n, unit) = gammas_in_prefix_of(c.work_of_adhesion, &[c.work_of_adhesion, se]);
                format!("{} ± {} {unit} (standard error)", n[0], n[1])
            }
            None => gamma(c.work_of_adhesion),
        }
    ));
    if let (Some(ci), Some(t)) = (c.confidence_interval, c.t_quantile) {
        let lead = if ci[1].abs() >= ci[0].abs() {
            ci[1]
        } else {
            ci[0]
        };
        let (n, unit) = gammas_in_prefix_of(lead, &ci);
        line(format!(
            "  {pct} interval          {} to {} {unit}{} (t = {})",
            n[0],
            n[1],
            if c.confidence_interval_clipped {
                ", clipped at 0"
            } else {
                ""
            },
            sig(t, 4)
        ));
    }
    let mu_source = match c.friction_coefficient_source {
        FrictionCoefficient::Fit => String::new(),
        FrictionCoefficient::Given(_) => " (given)".into(),
        FrictionCoefficient::Default => " (assumed: the paper's value)".into(),
    };
    line(format!(
        "friction coefficient μ  {}{}{}",
        sig(c.friction_coefficient, 4),
        c.friction_coefficient_standard_error
            .map_or(String::new(), |se| format!(
                " ± {} (standard error)",
                sig(se, 2)
            )),
        mu_source
    ));
    if let Some(ci) = c.friction_coefficient_confidence_interval {
        line(format!(
            "  {pct} interval          {} to {}{}",
            sig(ci[0], 4),
            sig(ci[1], 4),
            if c.friction_coefficient_interval_clipped {
                ", clipped at 0"
            } else {
                ""
            }
        ));
    }
    if let Some(r) = c.correlation {
        line(format!("  correlation of γ and μ estimates {}", sig(r, 3)));
    }
    line(format!(
        "residual standard deviation {}; {} Gauss–Newton iteration{}{}",
        c.residual_standard_deviation.map_or("—".into(), force),
        c.iterations,
        if c.iterations == 1 { "" } else { "s" },
        if c.converged { "" } else { " (not converged)" }
    ));
    line(String::new());
    let with_bond = c.equivalent_modulus.is_some();
    let mut header = format!(
        "{:>5} {:>11} {:>11} {:>11} {:>11} {:>15}",
        "line", "load P", "friction F", "fitted F", "residual", "γ (this point)"
    );
    if with_bond {
        header.push_str(&format!(
            " {:>11} {:>11} {:>11}",
            "P₁", "radius r", "F/(πr²)"
        ));
    }
    line(header);
    for p in &c.per_point {
        let mut row = format!(
            "{:>5} {:>11} {:>11} {:>11} {:>11} {:>15}",
            p.line,
            force(p.load),
            force(p.friction),
            force(p.fitted_friction),
            force(p.residual),
            p.work_of_adhesion.map_or("none".into(), gamma)
        );
        if with_bond {
            row.push_str(&format!(
                " {:>11} {:>11} {:>11}",
                force(p.apparent_hertz_load),
                p.contact_radius.map_or("—".into(), |r| si(r, "m", 3)),
                p.bond_strength.map_or("—".into(), |t| si(t, "Pa", 3))
            ));
        }
        line(row);
        if let Some(n) = &p.note {
            line(format!("      line {}: {}", p.line, point_note(n)));
        }
    }
    line("  residual = measured − fitted; γ (this point) solves eq. 14 exactly for that point at the fit's μ".into());
    if let Some(r) = c.per_point_range {
        line(format!(
            "  γ from single points: {} to {}",
            gamma(r[0]),
            gamma(r[1])
        ));
    }
    if let (Some(e), Some(mean)) = (c.equivalent_modulus, c.mean_bond_strength) {
        line(format!(
            "  contact radius r³ = R P₁ / K with K = 4E/3, E = {} (equivalent modulus), P₁ at the fitted γ; mean bond strength F/(πr²) = {}",
            si(e, "Pa", 3),
            si(mean, "Pa", 3)
        ));
    } else {
        line(
            "  contact radius and bond strength F/(πr²): give --materials A,B or --modulus E"
                .into(),
        );
    }

    if let Some(cmp) = &c.comparison {
        line(String::new());
        line(format!("Comparison with {}:", cmp.source));
        if let Some(q) = &cmp.work_of_adhesion {
            let where_ = match (q.within_confidence_interval, c.confidence_interval) {
                (Some(true), Some(_)) => format!("inside the fit's {pct} interval"),
                (Some(false), Some(ci)) => format!(
                    "outside the fit's {pct} interval ({} to {})",
                    gamma(ci[0]),
                    gamma(ci[1])
                ),
                _ if q.within_per_point_range => "inside the range of single-point values".into(),
                _ => "outside the range of single-point values".into(),
            };
            line(format!(
                "  quoted γ = {} is {}× the fitted {}, {where_}.",
                gamma(q.quoted),
                sig(q.ratio_to_fit, 3),
                gamma(c.work_of_adhesion)
            ));
            let predicted: Vec<String> = q
                .predicted_friction
                .iter()
                .map(|f| sig(f * 1e6, 3))
                .collect();
            let measured: Vec<String> = c
                .per_point
                .iter()
                .map(|p| sig(p.friction * 1e6, 3))
                .collect();
            line(format!(
                "  With the quoted γ and μ = {}, eq. 14 gives F = {} µN at these loads; measured: {} µN.",
                sig(c.friction_coefficient, 4),
                predicted.join(", "),
                measured.join(", ")
            ));
            if let Some(t) = q.implied_bond_strength {
                line(format!(
                    "  The quoted γ would make the mean bond strength F/(πr²) {}.",
                    si(t, "Pa", 3)
                ));
            }
            line(if q.agrees {
                "  The quoted γ is consistent with these data.".into()
            } else {
                "  The quoted γ does NOT follow from these data.".into()
            });
        }
        if let Some(b) = &cmp.bond_strength {
            line(format!(
                "  quoted bond strength = {} against {} from the data (mean F/(πr²) at the fitted γ; ratio {}): {}",
                si(b.quoted, "Pa", 3),
                si(b.from_data, "Pa", 3),
                sig(b.ratio, 3),
                if b.agrees {
                    "within the range of single points, consistent."
                } else {
                    "outside the range of single points: it does NOT follow from these data."
                }
            ));
        }
        if let Some(tq) = cmp.bond_strength_unchecked {
            line(format!(
                "  quoted bond strength = {}: not checked (give --materials A,B or --modulus E for contact radii)",
                si(tq, "Pa", 3)
            ));
        }
    }
    if !c.notes.is_empty() {
        line(String::new());
        for n in &c.notes {
            line(format!("Note: {}", note(n)));
        }
    }
    out
}

/// The document in `format` (one of [`FORMATS`]).
pub fn render(
    c: &Calibration,
    format: super::Format,
) -> Result<String, super::format::FormatError> {
    render_for(c, format, Vocabulary::Flags)
}

/// [`render`] with options named in `vocabulary` (the JSON's notes; the text is
/// the command line's).
pub fn render_for(
    c: &Calibration,
    format: super::Format,
    vocabulary: Vocabulary,
) -> Result<String, super::format::FormatError> {
    match format {
        super::Format::Text => Ok(text(c)),
        super::Format::Json => Ok(json_for(c, vocabulary)),
        given => Err(super::format::FormatError::NotRendered {
            command: "fit-adhesion",
            given,
            accepted: FORMATS,
        }),
    }
}
