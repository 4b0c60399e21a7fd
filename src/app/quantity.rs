//! Quantities given as options (flags of the command line, keyword arguments of
//! Python): a number with its unit ("150 GPa"), or a bare number read in SI units,
//! but only where that is plausible. `--modulus 150` is 150 Pa read literally, a
//! forgotten "GPa" in all likelihood, and a solve at 150 Pa runs to its iteration
//! limit: such a number is refused, with the values a forgotten prefix would have
//! given ("did you mean 150 GPa?", as a problem file's implausible value is warned
//! of). A unit written out is taken as meant.

use crate::model::SceneParameter;
use crate::units::{forgotten_prefix, format_quantity, is_bare_number, parse_quantity, Dimension};

use super::{AppError, OptionName};

/// What an option's quantity is, for its dimension and the magnitudes a bare
/// number is read at face value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OptionQuantity {
    /// A Young's modulus, or the composite E* of a pair (the scene's range of E).
    Modulus,
    /// A mean (nominal) pressure on a contact.
    MeanPressure,
    /// A hardness (the scene's range of H).
    Hardness,
    /// A bond strength F/(πr²), a stress.
    Stress,
    /// A work of adhesion (the scene's range of γ).
    WorkOfAdhesion,
    /// The range of an attraction (ρ of the exponential law).
    AttractionRange,
    /// A length along a measured map: a pixel size, a cut-off wavelength.
    ScanLength,
    /// The radius of a sphere (the scene's range of R).
    SphereRadius,
    /// The equilibrium spacing Z0 of a Lennard-Jones law (the scene's range).
    InteratomicDistance,
}

impl OptionQuantity {
    /// The dimension of its values.
    pub fn dimension(self) -> Dimension {
        match self {
            OptionQuantity::Modulus
            | OptionQuantity::MeanPressure
            | OptionQuantity::Hardness
            | OptionQuantity::Stress => Dimension::Pressure,
            OptionQuantity::WorkOfAdhesion => Dimension::SurfaceEnergy,
            OptionQuantity::AttractionRange
            | OptionQuantity::ScanLength
            | OptionQuantity::SphereRadius
            | OptionQuantity::InteratomicDistance => Dimension::Length,
        }
    }

    /// The magnitudes (SI) a bare number is read at face value, and whose they
    /// are. Where the scene has the quantity, its plausible range
    /// ([`SceneParameter::plausible_range`]); otherwise as generous: a mean
    /// pressure or a stress of 1 kPa – 200 GPa (below the hardest H), an
    /// attraction's range of 0.01 nm – 1 µm, a scan's pixel or cut-off of
    /// 0.01 nm – 1 cm.
    pub fn plausible_range(self) -> (f64, f64) {
        let scene = |p: SceneParameter| p.plausible_range().expect("a checked parameter");
        match self {
            OptionQuantity::Modulus => scene(SceneParameter::YoungsModulusA),
            OptionQuantity::Hardness => scene(SceneParameter::Hardness),
            OptionQuantity::WorkOfAdhesion => scene(SceneParameter::WorkOfAdhesion),
            OptionQuantity::SphereRadius => scene(SceneParameter::AsperityRadius),
            OptionQuantity::InteratomicDistance => scene(SceneParameter::InteratomicDistance),
            OptionQuantity::MeanPressure | OptionQuantity::Stress => (1e3, 2e11),
            OptionQuantity::AttractionRange => (1e-11, 1e-6),
            OptionQuantity::ScanLength => (1e-11, 1e-2),
        }
    }
}

/// A positive finite quantity for the option `option`: a number with its unit, or
/// a bare number (SI) inside the quantity's plausible range.
pub fn positive_quantity(
    option: OptionName,
    text: &str,
    quantity: OptionQuantity,
) -> Result<f64, AppError> {
    let dimension = quantity.dimension();
    let invalid = |rule: String| AppError::Invalid {
        options: vec![(option, format!("{text:?}"))],
        rule,
    };
    let x = parse_quantity(text, dimension).map_err(|e| invalid(e.to_string()))?;
    if !(x.is_finite() && x > 0.0) {
        return Err(invalid(format!(
            "must be a positive finite {}",
            dimension.name()
        )));
    }
    let (lo, hi) = quantity.plausible_range();
    if is_bare_number(text) && !(lo..=hi).contains(&x) {
        return Err(invalid(bare_number_rule(text, x, lo, hi, dimension)));
    }
    Ok(x)
}

/// Why the bare number `text` (read as `x`) is refused: how it was read, the
/// plausible range, the values a forgotten prefix would have given, and how to
/// insist.
fn bare_number_rule(text: &str, x: f64, lo: f64, hi: f64, dimension: Dimension) -> String {
    let guesses: Vec<String> = forgotten_prefix(x, lo, hi, dimension)
        .into_iter()
        .map(|v| format!("{:?}", format_quantity(v, dimension)))
        .collect();
    format!(
        "read without a unit as {}, outside {} – {}, the range of MEMS, NEMS and storage contacts{} Write the unit ({:?} if that is meant).",
        format_quantity(x, dimension),
        format_quantity(lo, dimension),
        format_quantity(hi, dimension),
        if guesses.is_empty() {
            ".".to_string()
        } else {
            format!(": did you mean {}?", guesses.join(" or "))
        },
        format!("{} {}", text.trim(), dimension.si_unit())
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::app::Vocabulary;

    #[test]
    fn a_bare_number_is_read_in_si_only_where_plausible() {
        let q = |t: &str| positive_quantity(OptionName("modulus"), t, OptionQuantity::Modulus);
        assert_eq!(q("150e9").unwrap(), 150e9);
        assert_eq!(q("150 GPa").unwrap(), 150e9);
        // Written out, a unit is meant, however small the value.
        assert_eq!(q("150 Pa").unwrap(), 150.0);
        let e = q("150").unwrap_err().message(Vocabulary::Flags);
        assert!(e.starts_with("--modulus \"150\": "), "{e}");
        assert!(e.contains("did you mean \"150 GPa\""), "{e}");
        assert!(e.contains("1 MPa – 2 TPa"), "{e}");
        let e = q("150").unwrap_err().message(Vocabulary::Keywords);
        assert!(e.starts_with("modulus=\"150\": "), "{e}");
    }
}
