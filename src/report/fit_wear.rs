//! The report of a wear-rate fit (`wearopt fit-wear`): text and JSON.

use serde_json::{json, Value};

use super::{si, sig};
use crate::app::Vocabulary;
use crate::calibrate::CONFIDENCE_LEVEL;
use crate::units::format_number;
use crate::wear_fit::{Estimate, TemperatureSource, WearFit, WearFitNote};

/// The formats `wearopt fit-wear` writes (the first is the default).
pub const FORMATS: &[super::Format] = &[super::Format::Text, super::Format::Json];

/// The model's words, in the JSON's `model` and the text's first line.
const MODEL: &str = "ln rate = ln A + sigma dV/(kB T) - dU/(kB T) (stress-assisted, atom by atom: docs/model.md §14)";

/// A note in words, options named in `vocabulary`.
pub fn note_for(n: &WearFitNote, vocabulary: Vocabulary) -> String {
    let temperature = match vocabulary {
        Vocabulary::Flags => "--temperature",
        Vocabulary::Keywords => "temperature=",
    };
    match *n {
        WearFitNote::ActivationEnergyNotIdentified { temperature: t } => format!(
            "every point is at T = {} K: the activation energy ΔU cannot be identified (at one temperature −ΔU/k_BT is a constant that the prefactor absorbs); measure at two temperatures or more (a temperature_K column) to separate it",
            format_number(t)
        ),
        WearFitNote::Saturated { t_statistic } => format!(
            "the points look saturated: ln rate bends down against the stress (curvature t = {}, beyond the one-sided 95 % bound); near the one-pass cap the rate stops growing exponentially, so ΔV is underestimated: fit the lower stresses alone",
            sig(t_statistic, 3)
        ),
        WearFitNote::SaturationNotChecked => {
            "too few points to check for saturation (it needs two more points than parameters)"
                .into()
        }
        WearFitNote::ExactFit => {
            "as many points as parameters: the fit is exact and has no uncertainty estimate".into()
        }
        WearFitNote::DefaultTemperature { temperature: t } => format!(
            "no temperature given: T = {} K assumed; give {temperature} or a temperature_K column",
            format_number(t)
        ),
    }
}

/// One JSON object, SI units (J, m³, K, Pa; rates per second): the keys of
/// [`WearFit`] with `notes` worded in `vocabulary`, plus `note_details`,
/// `confidence_level` and `model`.
pub fn json_for(f: &WearFit, vocabulary: Vocabulary) -> String {
    let mut v = serde_json::to_value(f).unwrap_or(Value::Null);
    if let Value::Object(obj) = &mut v {
        obj.insert("note_details".into(), json!(f.notes));
        obj.insert(
            "notes".into(),
            json!(f
                .notes
                .iter()
                .map(|n| note_for(n, vocabulary))
                .collect::<Vec<_>>()),
        );
        obj.insert("confidence_level".into(), json!(CONFIDENCE_LEVEL));
        obj.insert("model".into(), json!(MODEL));
    }
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_else(|_| "{}".into());
    s.push('\n');
    s
}

/// An estimate with its standard error and interval, each value through `show`.
fn estimate(e: &Estimate, show: impl Fn(f64) -> String) -> String {
    match (e.standard_error, e.lower, e.upper) {
        (Some(se), Some(lo), Some(hi)) => format!(
            "{} ± {} (standard error); {:.0} % interval {} to {}",
            show(e.estimate),
            show(se),
            CONFIDENCE_LEVEL * 100.0,
            show(lo),
            show(hi)
        ),
        _ => show(e.estimate),
    }
}

/// A report for people (options named as the command line's flags).
pub fn text(f: &WearFit) -> String {
    let mut out = String::new();
    let mut line = |s: String| {
        out.push_str(&s);
        out.push('\n');
    };
    line(format!("wearopt fit-wear — {}", f.origin));
    line(String::new());
    line("Model: rate = A exp(−(ΔU − σΔV)/(k_B T)), fitted as ln rate by least squares".into());
    line(format!(
        "Data: {} points, rates in {}{}; T {} ({})",
        f.points,
        f.data_rate_unit.symbol(),
        f.speed.map_or(String::new(), |v| format!(
            ", × v = {} → m³/s",
            si(v, "m/s", 4)
        )),
        f.temperatures
            .iter()
            .map(|t| format!("{} K", format_number(*t)))
            .collect::<Vec<_>>()
            .join(", "),
        match f.temperature_source {
            TemperatureSource::Data => "from the file",
            TemperatureSource::Option => "given",
            TemperatureSource::Default => "assumed",
        }
    ));
    line(format!(
        "Fit: {} degree{} of freedom{}",
        f.degrees_of_freedom,
        if f.degrees_of_freedom == 1 { "" } else { "s" },
        f.residual_standard_deviation
            .map_or(String::new(), |s| format!(
                ", residual scatter of ln rate s = {}",
                sig(s, 3)
            ))
    ));
    line(String::new());
    line(format!(
        "activation volume ΔV    {}",
        estimate(&f.activation_volume, |v| format!("{} Å³", sig(v * 1e30, 4)))
    ));
    match &f.activation_energy_ev {
        Some(e) => line(format!(
            "activation energy ΔU    {}",
            estimate(e, |v| format!("{} eV", sig(v, 4)))
        )),
        None => line("activation energy ΔU    not identified (one temperature)".into()),
    }
    line(format!(
        "ln prefactor ln A       {} (A in {}{})",
        estimate(&f.ln_prefactor, |v| sig(v, 6)),
        f.rate_unit,
        if f.activation_energy.is_none() {
            "; includes −ΔU/k_BT"
        } else {
            ""
        }
    ));
    line(format!(
        "saturation              {}",
        if f.saturated {
            "the points look saturated (see the notes)"
        } else {
            "none seen"
        }
    ));
    line(String::new());
    line(format!(
        "  {:>5} {:>12} {:>8} {:>12} {:>12} {:>10}",
        "line", "stress", "T (K)", "rate", "fitted", "ln ratio"
    ));
    for p in &f.per_point {
        line(format!(
            "  {:>5} {:>12} {:>8} {:>12} {:>12} {:>+10.4}",
            p.line,
            si(p.stress, "Pa", 4),
            format_number(p.temperature),
            format!("{:.4e}", p.rate),
            format!("{:.4e}", p.fitted_rate),
            p.residual
        ));
    }
    if !f.notes.is_empty() {
        line(String::new());
        line("Notes".into());
        for n in &f.notes {
            line(format!("  - {}", note_for(n, Vocabulary::Flags)));
        }
    }
    out
}

/// The fit in `format` (one of [`FORMATS`]), options named as the command line's flags.
pub fn render(f: &WearFit, format: super::Format) -> Result<String, super::format::FormatError> {
    render_for(f, format, Vocabulary::Flags)
}

/// [`render`] with the JSON's notes naming options in `vocabulary`.
pub fn render_for(
    f: &WearFit,
    format: super::Format,
    vocabulary: Vocabulary,
) -> Result<String, super::format::FormatError> {
    match format {
        super::Format::Text => Ok(text(f)),
        super::Format::Json => Ok(json_for(f, vocabulary)),
        given => Err(super::format::FormatError::NotRendered {
            command: "fit-wear",
            given,
            accepted: FORMATS,
        }),
    }
}
