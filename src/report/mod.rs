//! Rendering results: text reports, JSON and CSV. Knows nothing of how the
//! numbers were computed. Every number written to JSON or CSV is the shortest
//! string that round-trips the f64 exactly.

pub mod accuracy;
pub mod calibrate;
pub mod curve;
pub mod eval;
pub mod materials;
pub mod optimize;
pub mod pareto;
pub mod svg;

/// The SI unit of an objective (by its problem-file name).
pub fn objective_unit(name: &str) -> &'static str {
    match name {
        "wear_rate" => "m³/m",
        "wear_volume" => "m³",
        "real_area" => "m²",
        _ => "N",
    }
}

/// The dimension of a design variable (by its problem-file name).
pub fn design_dimension(name: &str) -> crate::problem::units::Dimension {
    use crate::problem::{DesignQuantity, Named};
    DesignQuantity::from_name(name).map_or(crate::problem::units::Dimension::Dimensionless, |q| {
        q.dimension()
    })
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

/// A number with SI prefix and unit for people (`12.3 µN`), `prec` significant digits.
pub fn si(x: f64, unit: &str, prec: usize) -> String {
    if x == 0.0 {
        return format!("0 {unit}");
    }
    if !x.is_finite() {
        return format!("{x} {unit}");
    }
    const PREFIXES: [(f64, &str); 11] = [
        (1e12, "T"),
        (1e9, "G"),
        (1e6, "M"),
        (1e3, "k"),
        (1.0, ""),
        (1e-3, "m"),
        (1e-6, "µ"),
        (1e-9, "n"),
        (1e-12, "p"),
        (1e-15, "f"),
        (1e-18, "a"),
    ];
    let a = x.abs();
    for (scale, p) in PREFIXES {
        if a >= scale * 0.999_999_5 {
            return format!("{} {p}{unit}", sig(x / scale, prec));
        }
    }
    format!("{} {unit}", sig_exp(x, prec))
}

/// `prec` significant digits, plain notation.
pub fn sig(x: f64, prec: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = x.abs().log10().floor() as i32;
    let decimals = (prec as i32 - 1 - digits).max(0) as usize;
    format!("{x:.decimals$}")
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

    #[test]
    fn numbers_round_trip() {
        for &x in &[0.1, 1.0 / 3.0, 1e-300, 6.02e23, -2.5e-7, 123456.789, 5e-324] {
            assert_eq!(number(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(number(f64::INFINITY), "inf");
    }

    #[test]
    fn si_prefixes() {
        assert_eq!(si(1.5e-6, "N", 3), "1.50 µN");
        assert_eq!(si(160e9, "Pa", 3), "160 GPa");
        assert_eq!(si(0.0, "m", 3), "0 m");
    }
}
