//! Quantities with units, on the ground floor: the physical [`Dimension`] of a value,
//! reading a quantity a person wrote ([`parse_quantity`]: `"10 uN"`, `"100 um^2"`,
//! `"0.1 J/m^2"`, or plain SI numbers) and writing one for a person ([`si`],
//! [`format_quantity`], [`number`]: `0.5702 µm²`). Problem files, scan readers,
//! command-line options and reports all read and write quantities through this
//! module; it imports nothing else of the crate.
//!
//! A problem file may give every dimensional value either as a TOML number, read as SI
//! (newtons, metres, pascals, ...), or as a string holding a number and a unit. The unit
//! takes one SI prefix:
//!
//! | prefix | factor |
//! |---|---|
//! | `p` | 1e-12 |
//! | `n` | 1e-9 |
//! | `u`, `µ` (micro sign), `μ` (Greek mu) | 1e-6 |
//! | `m` | 1e-3 |
//! | `k` | 1e3 |
//! | `M` | 1e6 |
//! | `G` | 1e9 |
//! | `T` | 1e12 |
//!
//! Where the unit is a power of a length (`m^2`, `m^-2`), the prefix belongs to the
//! length and is raised with it: `"100 um^2"` is 1e-10 m², `"10 um^-2"` is 1e13 m⁻².
//! In `"mJ/m^2"` and `"mN/m"` the prefix belongs to the J or the N. `²` and `⁻²` may be
//! written for `^2` and `^-2`, and `1/um^2` or `/um^2` for `um^-2`. Whitespace between the
//! number and the unit is optional. `"inf"` and `"infinity"` (any case, optionally signed
//! and optionally followed by a unit) read as infinity; whether a field accepts it is the
//! field's business, not the parser's. `NaN` is never a value.
//!
//! Writing: an SI prefix belongs to the unit it stands before, and on a power of a length it is
//! raised with the length: 5.702e-13 m² is `0.5702 µm²` (not `570.2 fm²`), a wear rate of
//! 5.7e-17 m³/m is `57.02 µm³/m`, an asperity density of 1e13 m⁻² is `10 µm⁻²`. Micro is
//! always `µ`, powers are superscripts. Every string these functions write is read back by
//! the problem-file reader ([`parse_quantity`]) as the same value
//! to the digits shown (tested for every dimension over many magnitudes).

use std::fmt;

mod format;
mod parse;

pub use format::{
    axis_unit, axis_unit_of, format_number, format_quantity, number, quantity, si, sig, sig_exp,
};
pub use parse::{
    forgotten_prefix, is_bare_number, parse_quantity, QuantityInput, UnitError, ELECTRON_VOLT,
};

/// The physical dimension a field expects.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dimension {
    /// Pa (hardness, Young's modulus, pressures).
    Pressure,
    /// N (load, pull-off force).
    Force,
    /// m (roughness, radii, distances).
    Length,
    /// m² (nominal area; also wear rate m³/m).
    Area,
    /// m³ (wear volume).
    Volume,
    /// m³/m (wear rate: volume per sliding distance; dimensionally an area, so "µm²"
    /// is read too).
    WearRate,
    /// m⁻² (asperity density).
    InverseArea,
    /// J/m² = N/m (work of adhesion).
    SurfaceEnergy,
    /// A pure number.
    Dimensionless,
    /// s (time limits).
    Time,
    /// K (temperature).
    Temperature,
    /// rad (contact angles); read from "deg", "°" or "rad".
    Angle,
    /// m³/mol (a liquid's molar volume).
    MolarVolume,
    /// J (an activation energy); read from "eV" too.
    Energy,
    /// Hz = 1/s (an attempt frequency).
    Frequency,
    /// m/s (a sliding speed).
    Speed,
}

impl Dimension {
    /// Every dimension, for looking up which one a unit belongs to.
    pub const ALL: [Dimension; 16] = [
        Dimension::Pressure,
        Dimension::Force,
        Dimension::Length,
        Dimension::Area,
        Dimension::Volume,
        Dimension::WearRate,
        Dimension::InverseArea,
        Dimension::SurfaceEnergy,
        Dimension::Dimensionless,
        Dimension::Time,
        Dimension::Temperature,
        Dimension::Angle,
        Dimension::MolarVolume,
        Dimension::Energy,
        Dimension::Frequency,
        Dimension::Speed,
    ];

    /// The dimension's name with an article: "a force".
    pub fn with_article(self) -> &'static str {
        match self {
            Dimension::Pressure => "a pressure",
            Dimension::Force => "a force",
            Dimension::Length => "a length",
            Dimension::Area => "an area",
            Dimension::Volume => "a volume",
            Dimension::WearRate => "a wear rate",
            Dimension::InverseArea => "an areal density",
            Dimension::SurfaceEnergy => "a surface energy",
            Dimension::Dimensionless => "a plain number",
            Dimension::Time => "a time",
            Dimension::Temperature => "a temperature",
            Dimension::Angle => "an angle",
            Dimension::MolarVolume => "a molar volume",
            Dimension::Energy => "an energy",
            Dimension::Frequency => "a frequency",
            Dimension::Speed => "a speed",
        }
    }

    /// The dimension's bare name: "force".
    pub fn name(self) -> &'static str {
        match self {
            Dimension::Pressure => "pressure",
            Dimension::Force => "force",
            Dimension::Length => "length",
            Dimension::Area => "area",
            Dimension::Volume => "volume",
            Dimension::WearRate => "wear rate",
            Dimension::InverseArea => "areal density",
            Dimension::SurfaceEnergy => "surface energy",
            Dimension::Dimensionless => "dimensionless number",
            Dimension::Time => "time",
            Dimension::Temperature => "temperature",
            Dimension::Angle => "angle",
            Dimension::MolarVolume => "molar volume",
            Dimension::Energy => "energy",
            Dimension::Frequency => "frequency",
            Dimension::Speed => "speed",
        }
    }

    /// The SI unit symbol used in messages ("" for dimensionless), as reports write it.
    pub fn si_unit(self) -> &'static str {
        symbol(self)
    }

    /// What to write instead, with examples: `a force such as "10 uN", "2 mN" or a
    /// number in newtons`.
    pub fn expectation(self) -> &'static str {
        match self {
            Dimension::Pressure => {
                "a pressure such as \"10 GPa\", \"500 MPa\" or a number in pascals"
            }
            Dimension::Force => "a force such as \"10 uN\", \"2 mN\" or a number in newtons",
            Dimension::Length => "a length such as \"5 nm\", \"1 um\" or a number in metres",
            Dimension::Area => {
                "an area such as \"100 um^2\", \"1 mm^2\" or a number in square metres"
            }
            Dimension::Volume => {
                "a volume such as \"50 um^3\", \"1e-18 m^3\" or a number in cubic metres"
            }
            Dimension::WearRate => {
                "a wear rate such as \"50 um^3/m\", \"1e-16 m^3/m\" or a number in m^3/m"
            }
            Dimension::InverseArea => {
                "an areal density such as \"10 um^-2\", \"1e13 m^-2\" or a number per square metre"
            }
            Dimension::SurfaceEnergy => {
                "a surface energy such as \"0.1 J/m^2\", \"50 mJ/m^2\" or a number in J/m^2"
            }
            Dimension::Dimensionless => "a plain number without a unit, such as 1e-4",
            Dimension::Time => "a time such as \"30 s\", \"2 min\" or a number in seconds",
            Dimension::Temperature => "a temperature such as \"298.15 K\" or a number in kelvin",
            Dimension::Angle => "an angle such as \"20 deg\", \"0.35 rad\" or a number in radians",
            Dimension::MolarVolume => {
                "a molar volume such as \"18.07 cm^3/mol\" or a number in m^3/mol"
            }
            Dimension::Energy => {
                "an energy such as \"0.91 eV\", \"1.5e-19 J\" or a number in joules"
            }
            Dimension::Frequency => {
                "a frequency such as \"1e13 Hz\", \"10 THz\" or a number in hertz"
            }
            Dimension::Speed => "a speed such as \"38 mm/s\", \"1 um/s\" or a number in m/s",
        }
    }
}

impl fmt::Display for Dimension {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The unit symbol reports write for a dimension (`""` for a plain number).
pub fn symbol(dimension: Dimension) -> &'static str {
    match dimension {
        Dimension::Pressure => "Pa",
        Dimension::Force => "N",
        Dimension::Length => "m",
        Dimension::Area => "m²",
        Dimension::Volume => "m³",
        Dimension::WearRate => "m³/m",
        Dimension::InverseArea => "m⁻²",
        Dimension::SurfaceEnergy => "J/m²",
        Dimension::Dimensionless => "",
        Dimension::Time => "s",
        Dimension::Temperature => "K",
        Dimension::Angle => "rad",
        Dimension::MolarVolume => "m³/mol",
        Dimension::Energy => "J",
        Dimension::Frequency => "Hz",
        Dimension::Speed => "m/s",
    }
}
