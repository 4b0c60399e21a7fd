//! `wearopt fit-wear`: the activation energy and volume of stress-assisted wear from
//! measured wear rates (docs/model.md §14).

use std::path::Path;

use crate::wear_fit::{self, WearData};

use super::AppError;

pub use crate::wear_fit::{WearFit, WearFitSettings};

/// Reads the wear data at `path` and fits them, as `wearopt fit-wear` does.
pub fn fit_wear(path: &Path, settings: &WearFitSettings) -> Result<WearFit, AppError> {
    let data = wear_fit::read_wear_csv(path)?;
    fit_data(&data, settings)
}

/// Parses wear data given as CSV text (`origin` names them in messages) and fits
/// them: what Python's `fit_wear` does with rows instead of a file.
pub fn fit_wear_text(
    text: &str,
    origin: &str,
    settings: &WearFitSettings,
) -> Result<WearFit, AppError> {
    let data = wear_fit::parse_wear_csv(text, origin)?;
    fit_data(&data, settings)
}

fn fit_data(data: &WearData, settings: &WearFitSettings) -> Result<WearFit, AppError> {
    Ok(wear_fit::fit_wear(data, settings)?)
}

/// The `temperature` option: "350 K" or a bare number in kelvin, finite and > 0.
pub fn temperature_option(text: &str) -> Result<f64, AppError> {
    let invalid = |rule: String| AppError::Invalid {
        options: vec![(super::OptionName("temperature"), format!("{text:?}"))],
        rule,
    };
    let t = crate::units::parse_quantity(text, crate::units::Dimension::Temperature)
        .map_err(|e| invalid(e.to_string()))?;
    if !(t.is_finite() && t > 0.0) {
        return Err(invalid(
            "must be a finite temperature > 0 K, e.g. \"350 K\"".into(),
        ));
    }
    Ok(t)
}

/// The `speed` option: a number with one of the units m/s, cm/s, mm/s, um/s (µm/s),
/// nm/s, or a bare number in m/s; finite and > 0.
pub fn speed_option(text: &str) -> Result<f64, AppError> {
    let invalid = |rule: &str| AppError::Invalid {
        options: vec![(super::OptionName("speed"), format!("{text:?}"))],
        rule: rule.to_string(),
    };
    const RULE: &str = "must be a finite speed > 0: a number with m/s, cm/s, mm/s, um/s or nm/s (a bare number is m/s), e.g. \"1 mm/s\"";
    let t = text.trim();
    let split = t
        .find(|c: char| c.is_alphabetic() || c == 'µ')
        .unwrap_or(t.len());
    let (number, unit) = (t[..split].trim(), t[split..].trim());
    let factor = match unit {
        "" | "m/s" => 1.0,
        "cm/s" => 1e-2,
        "mm/s" => 1e-3,
        "um/s" | "µm/s" => 1e-6,
        "nm/s" => 1e-9,
        _ => return Err(invalid(RULE)),
    };
    match number.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v * factor),
        _ => Err(invalid(RULE)),
    }
}
