//! Reading quantities: a number and a unit with one SI prefix (see [`crate::units`]).

use super::Dimension;

/// Why a quantity could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum UnitError {
    /// The string was empty or only whitespace.
    #[error("empty value; expected {}", .expected.expectation())]
    Empty {
        /// What the field wants.
        expected: Dimension,
    },
    /// The string does not start with a number.
    #[error("cannot read a number from {text:?}; expected {}", .expected.expectation())]
    Malformed {
        /// The offending text.
        text: String,
        /// What the field wants.
        expected: Dimension,
    },
    /// The unit is not one this parser knows.
    #[error("unknown unit {unit:?}; expected {}", .expected.expectation())]
    UnknownUnit {
        /// The unit as written.
        unit: String,
        /// What the field wants.
        expected: Dimension,
    },
    /// The unit is a real unit, but of another dimension.
    #[error("{unit:?} is a unit of {found}, not {expected}; expected {}", .expected.expectation())]
    WrongDimension {
        /// The unit as written.
        unit: String,
        /// The dimension the unit belongs to.
        found: Dimension,
        /// What the field wants.
        expected: Dimension,
    },
    /// NaN was given (as a TOML float or as text).
    #[error("NaN is not a value; expected {}", .expected.expectation())]
    NotANumber {
        /// What the field wants.
        expected: Dimension,
    },
}

/// A value as written in a file: a number (SI) or a string with a unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum QuantityInput<'a> {
    /// A plain number, read in SI units.
    Number(f64),
    /// A number followed by an optional unit.
    Text(&'a str),
}

impl From<f64> for QuantityInput<'_> {
    fn from(value: f64) -> Self {
        QuantityInput::Number(value)
    }
}

impl From<i64> for QuantityInput<'_> {
    fn from(value: i64) -> Self {
        QuantityInput::Number(value as f64)
    }
}

impl<'a> From<&'a str> for QuantityInput<'a> {
    fn from(value: &'a str) -> Self {
        QuantityInput::Text(value)
    }
}

impl<'a> From<&'a String> for QuantityInput<'a> {
    fn from(value: &'a String) -> Self {
        QuantityInput::Text(value)
    }
}

/// Reads a quantity of the given dimension and returns it in SI units.
///
/// ```
/// use wearopt::units::{parse_quantity, Dimension};
/// assert_eq!(parse_quantity("10 uN", Dimension::Force).unwrap(), 10e-6);
/// assert_eq!(parse_quantity(2.5, Dimension::Length).unwrap(), 2.5);
/// assert!(parse_quantity("10 GPa", Dimension::Force).is_err());
/// ```
pub fn parse_quantity<'a>(
    value: impl Into<QuantityInput<'a>>,
    expected: Dimension,
) -> Result<f64, UnitError> {
    match value.into() {
        QuantityInput::Number(x) if x.is_nan() => Err(UnitError::NotANumber { expected }),
        QuantityInput::Number(x) => Ok(x),
        QuantityInput::Text(text) => parse_text(text, expected),
    }
}

fn parse_text(text: &str, expected: Dimension) -> Result<f64, UnitError> {
    let trimmed = text.trim();
    if trimmed.is_empty() {
        return Err(UnitError::Empty { expected });
    }
    let (number, rest) = split_number(trimmed).ok_or_else(|| {
        if trimmed.to_ascii_lowercase().contains("nan") {
            UnitError::NotANumber { expected }
        } else {
            UnitError::Malformed {
                text: text.to_string(),
                expected,
            }
        }
    })?;
    let unit = rest.trim();
    let factor = unit_factor(unit, expected)?;
    Ok(number.scaled(factor.exp10, factor.mult))
}

/// Whether `text` is a number with no unit after it (`"150"`, `"2e-8"`), which
/// [`parse_quantity`] reads in SI units. A command line reads such a number at face
/// value only where it is plausible (see [`forgotten_prefix`]).
pub fn is_bare_number(text: &str) -> bool {
    split_number(text.trim()).is_some_and(|(_, rest)| rest.trim().is_empty())
}

/// The power of the length a prefix is raised with in `dimension`'s unit (2 in
/// `µm²`), 0 where a prefix is no part of the unit (a plain number).
fn prefix_power(dimension: Dimension) -> i32 {
    match dimension {
        Dimension::Area => 2,
        Dimension::InverseArea => -2,
        Dimension::Dimensionless => 0,
        _ => 1,
    }
}

/// What `value` (SI) would be had its number been written with a prefix that was
/// left out (σ = 2 m meant as 2 nm, E = 160 Pa as 160 GPa), where that lands in
/// the plausible range `lo..=hi`: the values, most likely first. Problem-file
/// warnings and the command line's refusals of a bare number both ask this.
pub fn forgotten_prefix(value: f64, lo: f64, hi: f64, dimension: Dimension) -> Vec<f64> {
    let p = prefix_power(dimension);
    if p == 0 {
        return Vec::new();
    }
    // Too large: a small prefix was dropped; too small: a large one.
    let exps: &[i32] = if value > hi {
        &[-9, -6, -3]
    } else {
        &[9, 6, 3]
    };
    exps.iter()
        .map(|e| value * 10f64.powi(e * p))
        .filter(|v| (lo..=hi).contains(v))
        .collect()
}

/// A number as written: decimal digits with a power of ten, or an infinity.
#[derive(Debug, Clone, Copy)]
enum Number<'a> {
    /// `mantissa` × 10^`exp`; the mantissa is the sign, digits and point as written.
    Finite { mantissa: &'a str, exp: i64 },
    /// ±inf.
    Infinite(f64),
}

impl Number<'_> {
    /// The value times 10^`shift` times `mult`. The power of ten is applied while
    /// parsing, so `"10 uN"` is exactly the double nearest 1e-5.
    fn scaled(self, shift: i32, mult: f64) -> f64 {
        match self {
            Number::Infinite(x) => x,
            Number::Finite { mantissa, exp } => {
                let e = exp
                    .saturating_add(i64::from(shift))
                    .clamp(-100_000, 100_000);
                let x: f64 = format!("{mantissa}e{e}").parse().unwrap_or(f64::NAN);
                x * mult
            }
        }
    }
}

/// Splits a leading number (decimal, exponent, or inf/infinity) from the rest.
fn split_number(s: &str) -> Option<(Number<'_>, &str)> {
    let bytes = s.as_bytes();
    let mut i = 0;
    let mut negative = false;
    if i < bytes.len() && (bytes[i] == b'+' || bytes[i] == b'-') {
        negative = bytes[i] == b'-';
        i += 1;
    }
    let after_sign = &s[i..];
    let head: String = after_sign.chars().take(8).collect::<String>();
    let head = head.to_ascii_lowercase();
    let word = if head.starts_with("infinity") {
        Some(8)
    } else if head.starts_with("inf") {
        Some(3)
    } else {
        None
    };
    if let Some(len) = word {
        let rest = &after_sign[len..];
        // "info" or "infGPa" is not infinity: a unit after inf needs a space.
        if rest.starts_with(|c: char| c.is_alphanumeric()) {
            return None;
        }
        let value = if negative {
            f64::NEG_INFINITY
        } else {
            f64::INFINITY
        };
        return Some((Number::Infinite(value), rest));
    }
    let mut digits = 0;
    while i < bytes.len() && bytes[i].is_ascii_digit() {
        i += 1;
        digits += 1;
    }
    if i < bytes.len() && bytes[i] == b'.' {
        i += 1;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            i += 1;
            digits += 1;
        }
    }
    if digits == 0 {
        return None;
    }
    let mantissa = &s[..i];
    // "5." and ".5" are numbers; Rust's parser agrees, check it once here.
    mantissa.parse::<f64>().ok()?;
    let mut exp = 0_i64;
    // An exponent only counts when digits follow: "1e-6 N" but "1 eV" is a unit.
    if i < bytes.len() && (bytes[i] == b'e' || bytes[i] == b'E') {
        let mut j = i + 1;
        if j < bytes.len() && (bytes[j] == b'+' || bytes[j] == b'-') {
            j += 1;
        }
        let exp_start = j;
        while j < bytes.len() && bytes[j].is_ascii_digit() {
            j += 1;
        }
        if j > exp_start {
            let digits = &s[exp_start..j];
            let magnitude: i64 = digits.parse().unwrap_or(i64::from(i32::MAX));
            exp = if bytes[i + 1] == b'-' {
                -magnitude
            } else {
                magnitude
            };
            i = j;
        }
    }
    Some((Number::Finite { mantissa, exp }, &s[i..]))
}

/// SI prefixes and their factors. `u`, `µ` (U+00B5) and `μ` (U+03BC) all mean micro.
const PREFIXES: [(&str, i32); 12] = [
    ("a", -18),
    ("f", -15),
    ("p", -12),
    ("n", -9),
    ("u", -6),
    ("\u{00b5}", -6),
    ("\u{03bc}", -6),
    ("m", -3),
    ("k", 3),
    ("M", 6),
    ("G", 9),
    ("T", 12),
];

/// A unit's factor to SI: 10^`exp10` × `mult`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Factor {
    exp10: i32,
    mult: f64,
}

impl Factor {
    const ONE: Factor = Factor {
        exp10: 0,
        mult: 1.0,
    };
    fn pow10(exp10: i32) -> Factor {
        Factor { exp10, mult: 1.0 }
    }
}

/// One electronvolt in joules (exact in the SI since 2019).
pub const ELECTRON_VOLT: f64 = 1.602_176_634e-19;

/// Canonical spelling of a unit: no whitespace, `^` powers, `**` read as `^`.
fn normalize(unit: &str) -> String {
    let mut s: String = unit.chars().filter(|c| !c.is_whitespace()).collect();
    s = s.replace("**", "^");
    s = s.replace("\u{207b}\u{00b2}", "^-2"); // ⁻²
    s = s.replace('\u{00b2}', "^2"); // ²
    s = s.replace('\u{00b3}', "^3"); // ³
    if let Some(rest) = s.strip_prefix("1/") {
        s = format!("/{rest}");
    }
    if let Some(rest) = s.strip_prefix("per") {
        if rest.ends_with("^2") {
            s = format!("/{rest}");
        }
    }
    // "/um^2" is "um^-2".
    if let Some(rest) = s.strip_prefix('/') {
        if let Some(base) = rest.strip_suffix("^2") {
            s = format!("{base}^-2");
        }
    }
    s
}

/// Splits an optional prefix from a base unit and returns the prefix's power of ten.
fn prefixed(unit: &str, base: &str) -> Option<i32> {
    if unit == base {
        return Some(0);
    }
    let head = unit.strip_suffix(base)?;
    PREFIXES
        .iter()
        .find(|(p, _)| *p == head)
        .map(|(_, exp)| *exp)
}

/// The factor that turns a value in `unit` into SI units of `dimension`, if `unit` is a
/// unit of that dimension.
fn factor_in(unit: &str, dimension: Dimension) -> Option<Factor> {
    let pow10 = |e: Option<i32>| e.map(Factor::pow10);
    match dimension {
        Dimension::Dimensionless => match unit {
            "" => Some(Factor::ONE),
            "%" => Some(Factor::pow10(-2)),
            _ => None,
        },
        Dimension::Temperature => pow10(prefixed(unit, "K")),
        Dimension::Angle => match unit {
            "deg" | "\u{00b0}" | "degree" | "degrees" => Some(Factor {
                exp10: 0,
                mult: std::f64::consts::PI / 180.0,
            }),
            _ => pow10(prefixed(unit, "rad")),
        },
        // cm³/mol as well: the unit molar volumes are tabulated in (water's
        // 18.07 cm³/mol, the README's example), though centi is no prefix here.
        Dimension::MolarVolume => pow10(
            prefixed(unit, "m^3/mol")
                .map(|e| 3 * e)
                .or_else(|| (unit == "cm^3/mol").then_some(-6)),
        ),
        Dimension::Pressure => pow10(prefixed(unit, "Pa")),
        Dimension::Force => pow10(prefixed(unit, "N")),
        // cm and cm² too (a sliding distance of "10 cm"), though centi is no
        // prefix elsewhere.
        Dimension::Length => pow10(
            prefixed(unit, "m")
                .or_else(|| (unit == "\u{00c5}" || unit == "\u{212b}").then_some(-10))
                .or_else(|| (unit == "cm").then_some(-2)),
        ),
        Dimension::Area => pow10(
            prefixed(unit, "m^2")
                .map(|e| 2 * e)
                .or_else(|| (unit == "cm^2").then_some(-4)),
        ),
        Dimension::Volume => pow10(prefixed(unit, "m^3").map(|e| 3 * e)),
        Dimension::WearRate => pow10(
            prefixed(unit, "m^3/m")
                .map(|e| 3 * e)
                .or_else(|| prefixed(unit, "m^2").map(|e| 2 * e)),
        ),
        Dimension::InverseArea => pow10(prefixed(unit, "m^-2").map(|e| -2 * e)),
        Dimension::SurfaceEnergy => {
            pow10(prefixed(unit, "J/m^2").or_else(|| prefixed(unit, "N/m")))
        }
        Dimension::Energy => prefixed(unit, "eV")
            .map(|exp10| Factor {
                exp10,
                mult: ELECTRON_VOLT,
            })
            .or_else(|| pow10(prefixed(unit, "J"))),
        Dimension::Frequency => pow10(prefixed(unit, "Hz").or_else(|| (unit == "/s").then_some(0))),
        Dimension::Speed => pow10(prefixed(unit, "m/s")),
        Dimension::Time => match unit {
            "min" => Some(Factor {
                exp10: 0,
                mult: 60.0,
            }),
            "h" => Some(Factor {
                exp10: 0,
                mult: 3600.0,
            }),
            _ => pow10(prefixed(unit, "s")),
        },
    }
}

fn unit_factor(unit: &str, expected: Dimension) -> Result<Factor, UnitError> {
    let norm = normalize(unit);
    if let Some(factor) = factor_in(&norm, expected) {
        return Ok(factor);
    }
    if norm.is_empty() {
        // A bare number in a string is SI, like a TOML number.
        return Ok(Factor::ONE);
    }
    for other in Dimension::ALL {
        if other != expected && factor_in(&norm, other).is_some() {
            return Err(UnitError::WrongDimension {
                unit: unit.to_string(),
                found: other,
                expected,
            });
        }
    }
    Err(UnitError::UnknownUnit {
        unit: unit.to_string(),
        expected,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs().max(1e-300)
    }

    fn q(text: &str, d: Dimension) -> f64 {
        parse_quantity(text, d).unwrap_or_else(|e| panic!("{text}: {e}"))
    }

    #[test]
    fn every_prefix_on_force() {
        let cases = [
            ("1 pN", 1e-12),
            ("1 nN", 1e-9),
            ("1 uN", 1e-6),
            ("1 \u{00b5}N", 1e-6),
            ("1 \u{03bc}N", 1e-6),
            ("1 mN", 1e-3),
            ("1 N", 1.0),
            ("1 kN", 1e3),
            ("1 MN", 1e6),
            ("1 GN", 1e9),
            ("1 TN", 1e12),
        ];
        for (text, want) in cases {
            assert!(close(q(text, Dimension::Force), want), "{text}");
        }
    }

    #[test]
    fn every_unit() {
        assert!(close(q("160 GPa", Dimension::Pressure), 160e9));
        assert!(close(q("500 MPa", Dimension::Pressure), 500e6));
        assert!(close(q("3 kPa", Dimension::Pressure), 3e3));
        assert!(close(q("7 Pa", Dimension::Pressure), 7.0));
        assert!(close(q("5 nm", Dimension::Length), 5e-9));
        assert!(close(q("1 um", Dimension::Length), 1e-6));
        assert!(close(q("2 mm", Dimension::Length), 2e-3));
        assert!(close(q("10 cm", Dimension::Length), 0.1));
        assert!(close(q("1 cm²", Dimension::Area), 1e-4));
        assert!(close(q("3 m", Dimension::Length), 3.0));
        assert!(close(q("3 \u{00c5}", Dimension::Length), 3e-10));
        assert!(close(q("100 um^2", Dimension::Area), 1e-10));
        assert!(close(q("1 mm^2", Dimension::Area), 1e-6));
        assert!(close(q("1 m^2", Dimension::Area), 1.0));
        assert!(close(q("4 nm\u{00b2}", Dimension::Area), 4e-18));
        assert!(close(q("10 um^-2", Dimension::InverseArea), 1e13));
        assert!(close(q("10 /um^2", Dimension::InverseArea), 1e13));
        assert!(close(q("10 1/um^2", Dimension::InverseArea), 1e13));
        assert!(close(
            q("10 um\u{207b}\u{00b2}", Dimension::InverseArea),
            1e13
        ));
        assert!(close(q("1e13 m^-2", Dimension::InverseArea), 1e13));
        assert!(close(q("0.1 J/m^2", Dimension::SurfaceEnergy), 0.1));
        assert!(close(q("50 mJ/m^2", Dimension::SurfaceEnergy), 0.05));
        assert!(close(q("50 mN/m", Dimension::SurfaceEnergy), 0.05));
        assert!(close(q("0.2 N/m", Dimension::SurfaceEnergy), 0.2));
        assert!(close(q("30 s", Dimension::Time), 30.0));
        assert!(close(q("250 ms", Dimension::Time), 0.25));
        assert!(close(q("2 min", Dimension::Time), 120.0));
        assert!(close(q("1 h", Dimension::Time), 3600.0));
        assert!(close(q("1e-4", Dimension::Dimensionless), 1e-4));
        // The units of the stress-assisted wear law (docs/model.md §12).
        assert!(close(
            q("0.91 eV", Dimension::Energy),
            0.91 * 1.602_176_634e-19
        ));
        assert!(close(q("1 meV", Dimension::Energy), 1.602_176_634e-22));
        assert!(close(q("2e-19 J", Dimension::Energy), 2e-19));
        assert!(close(q("1e13 Hz", Dimension::Frequency), 1e13));
        assert!(close(q("10 THz", Dimension::Frequency), 1e13));
        assert!(close(q("38 mm/s", Dimension::Speed), 0.038));
        assert!(close(q("1 um/s", Dimension::Speed), 1e-6));
        assert!(close(q("2 m/s", Dimension::Speed), 2.0));
        assert!(close(q("0.0067 nm^3", Dimension::Volume), 6.7e-30));
    }

    #[test]
    fn prefixes_scale_exactly() {
        // The power of ten is applied while parsing, so the result is the double
        // nearest the decimal value, as if the SI number had been typed.
        assert_eq!(q("10 uN", Dimension::Force), 10e-6);
        assert_eq!(q("800 uN", Dimension::Force), 800e-6);
        assert_eq!(q("100 um^2", Dimension::Area), 100e-12);
        assert_eq!(q("10 um^-2", Dimension::InverseArea), 10e12);
        assert_eq!(q("50 mJ/m^2", Dimension::SurfaceEnergy), 0.05);
        assert_eq!(q("0.3 nm", Dimension::Length), 0.3e-9);
        assert_eq!(q("1.5e-3 GPa", Dimension::Pressure), 1.5e6);
        assert_eq!(q("1e99999 N", Dimension::Force), f64::INFINITY);
    }

    #[test]
    fn spacing_and_exponents() {
        assert!(close(q("10uN", Dimension::Force), 10e-6));
        assert!(close(q("  10   uN  ", Dimension::Force), 10e-6));
        assert!(close(q("1e-6 N", Dimension::Force), 1e-6));
        assert!(close(q("1E-6N", Dimension::Force), 1e-6));
        assert!(close(q("1.5e+3 Pa", Dimension::Pressure), 1.5e3));
        assert!(close(q(".5 nm", Dimension::Length), 0.5e-9));
        assert!(close(q("5. nm", Dimension::Length), 5e-9));
        assert!(close(q("-2 uN", Dimension::Force), -2e-6));
        assert!(close(q("+2 uN", Dimension::Force), 2e-6));
        assert!(close(q("100 um ^ 2", Dimension::Area), 1e-10));
        assert!(close(q("100 um**2", Dimension::Area), 1e-10));
        assert!(close(q("0.1 J / m^2", Dimension::SurfaceEnergy), 0.1));
        // A string holding only a number is SI, like a TOML number.
        assert!(close(q("1e-6", Dimension::Force), 1e-6));
    }

    #[test]
    fn plain_numbers_are_si() {
        assert_eq!(parse_quantity(1e-6, Dimension::Force), Ok(1e-6));
        assert_eq!(parse_quantity(3_i64, Dimension::Length), Ok(3.0));
        assert_eq!(
            parse_quantity(f64::INFINITY, Dimension::Pressure),
            Ok(f64::INFINITY)
        );
        assert_eq!(
            parse_quantity(f64::NAN, Dimension::Pressure),
            Err(UnitError::NotANumber {
                expected: Dimension::Pressure
            })
        );
    }

    #[test]
    fn infinity() {
        for text in ["inf", "INF", "Inf", "infinity", "Infinity", "+inf", " inf "] {
            assert_eq!(q(text, Dimension::Pressure), f64::INFINITY, "{text}");
        }
        assert_eq!(q("-inf", Dimension::Pressure), f64::NEG_INFINITY);
        assert_eq!(q("inf GPa", Dimension::Pressure), f64::INFINITY);
        assert!(matches!(
            parse_quantity("info", Dimension::Pressure),
            Err(UnitError::Malformed { .. })
        ));
        assert!(matches!(
            parse_quantity("inf N", Dimension::Pressure),
            Err(UnitError::WrongDimension { .. })
        ));
    }

    #[test]
    fn nan_is_rejected() {
        for text in ["nan", "NaN", "-nan", "NaN Pa"] {
            assert!(
                matches!(
                    parse_quantity(text, Dimension::Pressure),
                    Err(UnitError::NotANumber { .. })
                ),
                "{text}"
            );
        }
    }

    #[test]
    fn wrong_dimension_names_both() {
        let err = parse_quantity("10 GPa", Dimension::Force).unwrap_err();
        assert_eq!(
            err,
            UnitError::WrongDimension {
                unit: "GPa".into(),
                found: Dimension::Pressure,
                expected: Dimension::Force
            }
        );
        let msg = err.to_string();
        assert!(
            msg.contains("pressure") && msg.contains("a force such as"),
            "{msg}"
        );
        // A length where an area is wanted, and the reverse.
        assert!(matches!(
            parse_quantity("100 um", Dimension::Area),
            Err(UnitError::WrongDimension {
                found: Dimension::Length,
                ..
            })
        ));
        assert!(matches!(
            parse_quantity("100 um^2", Dimension::Length),
            Err(UnitError::WrongDimension {
                found: Dimension::Area,
                ..
            })
        ));
        assert!(matches!(
            parse_quantity("1 nm", Dimension::Dimensionless),
            Err(UnitError::WrongDimension { .. })
        ));
        assert!(matches!(
            parse_quantity("0.1 N/m", Dimension::Force),
            Err(UnitError::WrongDimension {
                found: Dimension::SurfaceEnergy,
                ..
            })
        ));
    }

    #[test]
    fn unknown_units() {
        let err = parse_quantity("10 uQ", Dimension::Force).unwrap_err();
        assert_eq!(
            err.to_string(),
            "unknown unit \"uQ\"; expected a force such as \"10 uN\", \"2 mN\" or a number in newtons"
        );
        for text in ["10 xN", "10 GGPa", "10 um^-3", "1 erg", "3 furlongs"] {
            assert!(
                matches!(
                    parse_quantity(text, Dimension::Force),
                    Err(UnitError::UnknownUnit { .. })
                ),
                "{text}"
            );
        }
    }

    #[test]
    fn volumes_and_wear_rates() {
        assert_eq!(q("57.02 µm³/m", Dimension::WearRate), 57.02e-18);
        assert_eq!(q("57.02 um^3/m", Dimension::WearRate), 57.02e-18);
        // m³/m is an area: µm² reads as a wear rate too.
        assert_eq!(q("57.02 µm²", Dimension::WearRate), 57.02e-12);
        assert_eq!(q("2 nm³", Dimension::Volume), 2e-27);
        assert_eq!(q("570.2 fm²", Dimension::Area), 570.2e-30);
        assert_eq!(q("3 aN", Dimension::Force), 3e-18);
        assert!(matches!(
            parse_quantity("10 nm^3", Dimension::Force),
            Err(UnitError::WrongDimension {
                found: Dimension::Volume,
                ..
            })
        ));
        assert!(matches!(
            parse_quantity("1 um^3/m", Dimension::Area),
            Err(UnitError::WrongDimension {
                found: Dimension::WearRate,
                ..
            })
        ));
    }

    #[test]
    fn malformed_numbers() {
        for text in ["abc", "uN", "e5 N", ".", "-", "--1 N", "ten uN"] {
            assert!(
                matches!(
                    parse_quantity(text, Dimension::Force),
                    Err(UnitError::Malformed { .. })
                ),
                "{text}"
            );
        }
        for text in ["", "   "] {
            assert!(matches!(
                parse_quantity(text, Dimension::Force),
                Err(UnitError::Empty { .. })
            ));
        }
        // Junk after a number is an unknown unit, not silently ignored.
        assert!(parse_quantity("1.2.3 N", Dimension::Force).is_err());
        assert!(parse_quantity("1e N", Dimension::Force).is_err());
    }
}
