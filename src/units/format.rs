//! Writing quantities for people (see [`crate::units`]).

use super::{symbol, Dimension};

/// Prefixes a unit of the first power may take, largest first.
const PREFIXES: [(i32, &str); 11] = [
    (12, "T"),
    (9, "G"),
    (6, "M"),
    (3, "k"),
    (0, ""),
    (-3, "m"),
    (-6, "µ"),
    (-9, "n"),
    (-12, "p"),
    (-15, "f"),
    (-18, "a"),
];

/// Prefixes of a length that is raised to a power (m², m³, m⁻²): what a designer says.
const LENGTH_POWER_PREFIXES: [(i32, &str); 4] = [(0, ""), (-3, "m"), (-6, "µ"), (-9, "n")];

/// How a unit string takes a prefix: on a length raised to `power` (then `rest` follows
/// the `m`), or on the whole leading symbol.
struct UnitShape<'a> {
    /// The power of the prefixed length (1 for units that are not lengths).
    power: i32,
    /// The unit as written, without prefix.
    unit: &'a str,
    /// True when the prefix stands on a power of a length.
    length_power: bool,
}

fn shape(unit: &str) -> UnitShape<'_> {
    let (power, length_power) = if unit.starts_with("m²") {
        (2, true)
    } else if unit.starts_with("m³") {
        (3, true)
    } else if unit.starts_with("m⁻²") {
        (-2, true)
    } else {
        (1, false)
    };
    UnitShape {
        power,
        unit,
        length_power,
    }
}

/// Chooses the prefix: `(exponent of the prefix, prefix)`, or None when no prefix puts
/// the value in a readable range (then the caller writes an exponent).
fn choose_prefix(a: f64, s: &UnitShape) -> Option<(i32, &'static str)> {
    if s.length_power {
        // Prefixes step by 1000^|power| on these units: take the one whose value falls
        // in [0.01, 0.01·1000^|power|): 0.5702 µm², 5000 µm², 57.02 µm³/m.
        let width = 3 * s.power.abs();
        LENGTH_POWER_PREFIXES.iter().copied().find(|&(e, _)| {
            let v = a / 10f64.powi(e * s.power);
            // Tolerance so that 1e-2 itself stays with this prefix despite rounding.
            v >= 0.01 * (1.0 - 5e-5) && v < 10f64.powi(width - 2) * (1.0 - 5e-5)
        })
    } else if s.unit == "m" {
        // Lengths below a nanometre read best in nm (σ = 0.5 nm, Z0 = 0.3 nm).
        PREFIXES[3..=7]
            .iter()
            .copied()
            .find(|&(e, _)| a >= 10f64.powi(e) * (1.0 - 5e-5) || (e == -9 && a >= 1e-12))
            .filter(|&(e, _)| a < 10f64.powi(e + 3) * (1.0 - 5e-5))
    } else {
        // [1, 1000), with values that round up to 1000 moved to the next prefix.
        PREFIXES
            .iter()
            .copied()
            .find(|&(e, _)| a >= 10f64.powi(e) * (1.0 - 5e-5))
            .filter(|&(e, _)| a < 10f64.powi(e + 3) * (1.0 - 5e-5))
    }
}

/// A value with its unit and SI prefix, `prec` significant digits: `si(1.5e-6, "N", 3)`
/// is `"1.50 µN"`; `si(5.702e-13, "m²", 4)` is `"0.5702 µm²"`. Values no prefix can
/// show are written with an exponent in the base unit (`"3.578e-197 m²"`); infinities
/// as `"inf N"`.
pub fn si(x: f64, unit: &str, prec: usize) -> String {
    if unit.is_empty() {
        return sig_exp(x, prec);
    }
    if x == 0.0 {
        return format!("0 {unit}");
    }
    if !x.is_finite() {
        return format!("{x} {unit}");
    }
    let s = shape(unit);
    match choose_prefix(x.abs(), &s) {
        Some((e, p)) => {
            let v = x / 10f64.powi(e * s.power);
            format!("{} {p}{}", sig(v, prec), s.unit)
        }
        None => format!("{} {unit}", sig_exp(x, prec)),
    }
}

/// The prefixed unit for an axis whose values reach `max_abs`, the prefix [`si`] gives
/// that value: values are divided by the returned factor. `(1e-6, "µN")` for 8e-4 N;
/// `(1e-18, "µm³/m")` for 4.9e-17 m³/m.
pub fn axis_unit(max_abs: f64, unit: &str) -> (f64, String) {
    if unit.is_empty() {
        return (1.0, String::new());
    }
    let s = shape(unit);
    match choose_prefix(max_abs, &s).filter(|_| max_abs > 0.0 && max_abs.is_finite()) {
        Some((e, p)) => (10f64.powi(e * s.power), format!("{p}{unit}")),
        None => (1.0, unit.to_string()),
    }
}

/// [`axis_unit`] for an axis drawing `values` (the largest finite magnitude sets
/// the prefix).
pub fn axis_unit_of(values: impl IntoIterator<Item = f64>, unit: &str) -> (f64, String) {
    let largest = values
        .into_iter()
        .map(f64::abs)
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    axis_unit(largest, unit)
}

/// [`si`] for a dimension (a plain number for [`Dimension::Dimensionless`]).
pub fn quantity(x: f64, dimension: Dimension, prec: usize) -> String {
    match dimension {
        Dimension::Dimensionless => sig_exp(x, prec),
        // Angles in degrees, as designers quote contact angles (read back as "deg").
        Dimension::Angle if x.is_finite() => format!("{} deg", sig(x.to_degrees(), prec)),
        d => si(x, symbol(d), prec),
    }
}

/// A short form for notes, messages and tables: up to 4 significant digits without
/// trailing zeros, `"10 nm"`, `"100 µm²"`, `"inf"`.
pub fn format_quantity(value: f64, dimension: Dimension) -> String {
    if value.is_infinite() {
        return if value > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    if dimension == Dimension::Angle {
        return format!("{} deg", trim(&sig(value.to_degrees(), 4)));
    }
    let unit = symbol(dimension);
    if unit.is_empty() {
        return format_number(value);
    }
    if value == 0.0 {
        return format!("0 {unit}");
    }
    let s = shape(unit);
    match choose_prefix(value.abs(), &s) {
        Some((e, p)) => format!(
            "{} {p}{}",
            trim(&sig(value / 10f64.powi(e * s.power), 4)),
            s.unit
        ),
        None => format!("{} {unit}", format_number(value)),
    }
}

fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A short decimal form of a number: up to 4 significant digits, no trailing zeros.
pub fn format_number(value: f64) -> String {
    if value == 0.0 {
        return "0".to_string();
    }
    if value.is_infinite() {
        return if value > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    let magnitude = value.abs().log10().floor();
    if !(-4.0..6.0).contains(&magnitude) {
        let s = format!("{value:.3e}");
        // 1.000e-9 -> 1e-9
        if let Some((mantissa, exp)) = s.split_once('e') {
            let m = mantissa.trim_end_matches('0').trim_end_matches('.');
            return format!("{m}e{exp}");
        }
        return s;
    }
    let decimals = (3.0 - magnitude).max(0.0) as usize;
    trim(&format!("{value:.decimals$}"))
}

/// The shortest round-trip form of an f64, in plain notation for moderate
/// magnitudes and exponent notation otherwise (`inf`, `-inf`, `NaN` spelled so).
pub fn number(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || (1e-4..1e15).contains(&a) || !x.is_finite() {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// `prec` significant digits, plain notation.
pub fn sig(x: f64, prec: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    // Round first, so that 999.96 at 4 digits is 1000, not 1000.0.
    let rounded: f64 = format!("{:.*e}", prec.saturating_sub(1), x)
        .parse()
        .unwrap_or(x);
    let digits = rounded.abs().log10().floor() as i32;
    let decimals = (prec as i32 - 1 - digits).max(0) as usize;
    format!("{rounded:.decimals$}")
}

/// `prec` significant digits; exponent notation outside [1e-3, 1e5).
pub fn sig_exp(x: f64, prec: usize) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-3..1e5).contains(&a) {
        sig(x, prec)
    } else {
        format!("{:.*e}", prec.saturating_sub(1), x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::parse_quantity;

    #[test]
    fn numbers_round_trip() {
        for &x in &[0.1, 1.0 / 3.0, 1e-300, 6.02e23, -2.5e-7, 123456.789, 5e-324] {
            assert_eq!(number(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(number(f64::INFINITY), "inf");
    }

    #[test]
    fn prefixes_on_the_right_symbol() {
        // The issue's own numbers: the micro-gear hub's real area and wear rate.
        assert_eq!(si(5.702e-13, "m²", 4), "0.5702 µm²");
        assert_eq!(si(5.702e-17, "m³/m", 4), "57.02 µm³/m");
        assert_eq!(si(5.702e-17, "m³", 4), "57.02 µm³");
        assert_eq!(si(1e13, "m⁻²", 3), "10.0 µm⁻²");
        assert_eq!(si(1e-9, "m²", 3), "1000 µm²");
        assert_eq!(si(3.578e-197, "m²", 4), "3.578e-197 m²");
        assert_eq!(si(1.5e-6, "N", 3), "1.50 µN");
        assert_eq!(si(160e9, "Pa", 3), "160 GPa");
        assert_eq!(si(0.0, "m", 3), "0 m");
        assert_eq!(si(0.05, "J/m²", 3), "50.0 mJ/m²");
        assert_eq!(format_quantity(0.5e-9, Dimension::Length), "0.5 nm");
        assert_eq!(si(2.0, "m", 3), "2.00 m");
        // Rounding up crosses to the next prefix: never "1000 MPa".
        assert_eq!(si(999.99e6, "Pa", 4), "1.000 GPa");
        assert_eq!(format_quantity(999_999_999.9, Dimension::Pressure), "1 GPa");
        assert_eq!(format_quantity(1e9, Dimension::Pressure), "1 GPa");
    }

    #[test]
    fn short_forms() {
        assert_eq!(format_quantity(10e9, Dimension::Pressure), "10 GPa");
        assert_eq!(format_quantity(1e-8, Dimension::Length), "10 nm");
        assert_eq!(format_quantity(1e-10, Dimension::Area), "100 µm²");
        assert_eq!(format_quantity(1e13, Dimension::InverseArea), "10 µm⁻²");
        assert_eq!(format_quantity(0.1, Dimension::SurfaceEnergy), "100 mJ/m²");
        assert_eq!(format_quantity(f64::INFINITY, Dimension::Pressure), "inf");
        assert_eq!(format_quantity(0.0, Dimension::Force), "0 N");
        assert_eq!(format_quantity(-2e-6, Dimension::Force), "-2 µN");
        assert_eq!(format_quantity(6.5e-18, Dimension::WearRate), "6.5 µm³/m");
        assert_eq!(format_number(0.22), "0.22");
        assert_eq!(format_number(1e-9), "1e-9");
    }

    /// Every unit a report prints reads back as the same value, to the digits shown:
    /// each dimension, both signs, 1e-30 to 1e30 in steps of a fifth of a decade.
    #[test]
    fn every_printed_unit_reads_back() {
        let dims = [
            Dimension::Pressure,
            Dimension::Force,
            Dimension::Length,
            Dimension::Area,
            Dimension::Volume,
            Dimension::WearRate,
            Dimension::InverseArea,
            Dimension::SurfaceEnergy,
            Dimension::Time,
            Dimension::Dimensionless,
            Dimension::Temperature,
            Dimension::Angle,
            Dimension::MolarVolume,
        ];
        for d in dims {
            for k in -150..=150 {
                for sign in [1.0, -1.0] {
                    let x = sign * 1.234_567 * 10f64.powf(f64::from(k) / 5.0);
                    for (text, digits) in [
                        (quantity(x, d, 4), 4),
                        (quantity(x, d, 6), 6),
                        (format_quantity(x, d), 4),
                    ] {
                        let back = parse_quantity(text.as_str(), d)
                            .unwrap_or_else(|e| panic!("{d}: {x:e} printed as {text:?}: {e}"));
                        let tol = 0.6 * 10f64.powi(1 - digits);
                        assert!(
                            (back - x).abs() <= tol * x.abs(),
                            "{d}: {x:e} printed as {text:?} reads back as {back:e}"
                        );
                    }
                }
            }
        }
    }
}
