//! Stage one of loading: the problem file exactly as written.
//!
//! Every table denies unknown keys, and every value is `Spanned` so that stage two
//! ([`super::Problem::from_raw`]) can name the line of anything it refuses. Keys that the
//! schema requires are still `Option` here: stage two reports their absence with the
//! table's line and an example, which serde's "missing field" cannot.

use std::collections::BTreeMap;
use std::fmt;

use serde::de::{self, Deserializer, Visitor};
use serde::Deserialize;
use toml::Spanned;

/// A dimensional value as written: a TOML number (SI) or a string with a unit.
#[derive(Debug, Clone, PartialEq)]
pub enum RawQuantity {
    /// A TOML integer or float, read in SI units.
    Number(f64),
    /// A string such as `"10 uN"`.
    Text(String),
}

impl RawQuantity {
    /// A quantity inside an untyped TOML value (an inline table's entry): a string or
    /// a number, else None.
    pub fn from_value(v: &toml::Value) -> Option<RawQuantity> {
        match v {
            toml::Value::String(s) => Some(RawQuantity::Text(s.clone())),
            toml::Value::Float(x) => Some(RawQuantity::Number(*x)),
            toml::Value::Integer(x) => Some(RawQuantity::Number(*x as f64)),
            _ => None,
        }
    }

    /// As input to [`crate::units::parse_quantity`].
    pub fn as_input(&self) -> crate::units::QuantityInput<'_> {
        match self {
            RawQuantity::Number(x) => crate::units::QuantityInput::Number(*x),
            RawQuantity::Text(s) => crate::units::QuantityInput::Text(s),
        }
    }
}

impl<'de> Deserialize<'de> for RawQuantity {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct QuantityVisitor;
        impl Visitor<'_> for QuantityVisitor {
            type Value = RawQuantity;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number in SI units or a string with a unit such as \"10 uN\"")
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Number(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Number(v as f64))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Number(v))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<RawQuantity, E> {
                Ok(RawQuantity::Text(v.to_string()))
            }
        }
        deserializer.deserialize_any(QuantityVisitor)
    }
}

/// An integer setting. Integral floats (`1e6`) are accepted so that the range check,
/// not the type check, explains what is wrong with them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RawInteger(pub i64);

impl<'de> Deserialize<'de> for RawInteger {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct IntegerVisitor;
        impl Visitor<'_> for IntegerVisitor {
            type Value = RawInteger;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an integer")
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<RawInteger, E> {
                Ok(RawInteger(v))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<RawInteger, E> {
                i64::try_from(v)
                    .map(RawInteger)
                    .map_err(|_| E::invalid_value(de::Unexpected::Unsigned(v), &self))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<RawInteger, E> {
                if v.fract() == 0.0 && v.abs() < 9.0e18 {
                    Ok(RawInteger(v as i64))
                } else {
                    Err(E::invalid_value(de::Unexpected::Float(v), &self))
                }
            }
        }
        deserializer.deserialize_any(IntegerVisitor)
    }
}

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawProblem {
    pub name: Option<Spanned<String>>,
    pub contact: Option<Spanned<RawContact>>,
    pub bodies: Option<Spanned<RawBodies>>,
    pub interface: Option<Spanned<RawInterface>>,
    pub roughness: Option<Spanned<RawRoughness>>,
    pub design: Option<Spanned<RawDesign>>,
    pub objective: Option<Spanned<RawObjective>>,
    #[serde(default)]
    pub constraint: Vec<Spanned<RawConstraint>>,
    pub pareto: Option<Spanned<RawPareto>>,
    pub optimizer: Option<Spanned<RawOptimizer>>,
    pub environment: Option<Spanned<RawEnvironment>>,
    pub stiction: Option<Spanned<RawStiction>>,
    pub uncertainty: Option<Spanned<RawUncertainty>>,
    pub wear: Option<Spanned<RawWear>>,
}

/// `[wear]`: the wear law and its inputs (docs/model.md §3, §12).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawWear {
    /// `"archard"` (default) or `"stress_assisted"`.
    pub law: Option<Spanned<String>>,
    pub activation_energy: Option<Spanned<RawQuantity>>,
    pub activation_volume: Option<Spanned<RawQuantity>>,
    pub attempt_frequency: Option<Spanned<RawQuantity>>,
    pub site_spacing: Option<Spanned<RawQuantity>>,
    pub atomic_volume: Option<Spanned<RawQuantity>>,
    /// `"normal"` (default) or `"shear"`.
    pub stress: Option<Spanned<String>>,
    pub sliding_speed: Option<Spanned<RawQuantity>>,
}

/// `[environment]`: the humid air around the contact (docs/model.md §10).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawEnvironment {
    /// A humidity (`0.5`, `"50 %"`) or, in a study, a range (`{ min = 0, max = 0.9 }`).
    pub relative_humidity: Option<Spanned<toml::Value>>,
    pub humidity_points: Option<Spanned<RawInteger>>,
    pub design_humidity: Option<Spanned<RawQuantity>>,
    pub temperature: Option<Spanned<RawQuantity>>,
    /// `"water"` or `{ surface_tension = …, molar_volume = … }`.
    pub liquid: Option<Spanned<toml::Value>>,
}

/// `[stiction]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawStiction {
    pub cantilever: Option<Spanned<RawCantilever>>,
}

/// `stiction.cantilever`: a beam held down by the interface. A table only: an
/// array (`cantilever = [1, 2, 3]`) was read by position, its wrong length
/// named this struct.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[serde(remote = "Self")]
pub struct RawCantilever {
    pub thickness: Option<Spanned<RawQuantity>>,
    pub gap: Option<Spanned<RawQuantity>>,
    pub youngs_modulus: Option<Spanned<RawQuantity>>,
}

impl<'de> Deserialize<'de> for RawCantilever {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Table;
        impl<'de> serde::de::Visitor<'de> for Table {
            type Value = RawCantilever;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str(
                    "a table { thickness = \"2 um\", gap = \"2 um\", youngs_modulus = \"160 GPa\" }",
                )
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                map: A,
            ) -> Result<Self::Value, A::Error> {
                RawCantilever::deserialize(serde::de::value::MapAccessDeserializer::new(map))
            }
        }
        deserializer.deserialize_map(Table)
    }
}

/// `[contact]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawContact {
    pub load: Option<Spanned<RawQuantity>>,
    pub nominal_area: Option<Spanned<RawQuantity>>,
    pub sliding_distance: Option<Spanned<RawQuantity>>,
    pub wear_coefficient: Option<Spanned<RawQuantity>>,
    pub wear_area: Option<Spanned<String>>,
    /// T of the contact (K); `[environment] temperature` in humid air.
    pub temperature: Option<Spanned<RawQuantity>>,
    pub allowed_wear_depth: Option<Spanned<RawQuantity>>,
    pub sliding_per_cycle: Option<Spanned<RawQuantity>>,
    pub restoring_force: Option<Spanned<RawQuantity>>,
}

/// `[bodies]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBodies {
    pub a: Option<Spanned<RawBody>>,
    pub b: Option<Spanned<RawBody>>,
}

/// `bodies.a` or `bodies.b`: a catalogue material, explicit constants, or both
/// (explicit constants override the catalogue).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBody {
    pub material: Option<Spanned<String>>,
    pub youngs_modulus: Option<Spanned<RawQuantity>>,
    pub poisson_ratio: Option<Spanned<RawQuantity>>,
}

/// `[interface]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawInterface {
    pub hardness: Option<Spanned<RawQuantity>>,
    pub work_of_adhesion: Option<Spanned<RawQuantity>>,
    pub interatomic_distance: Option<Spanned<RawQuantity>>,
    pub adhesion_model: Option<Spanned<String>>,
    pub attraction: Option<Spanned<String>>,
    pub shear_strength: Option<Spanned<RawQuantity>>,
    pub debris_shape_factor: Option<Spanned<RawQuantity>>,
    pub contact_angle: Option<Spanned<RawQuantity>>,
    pub contact_angle_a: Option<Spanned<RawQuantity>>,
    pub contact_angle_b: Option<Spanned<RawQuantity>>,
}

/// `[roughness]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRoughness {
    pub sigma: Option<Spanned<RawQuantity>>,
    pub asperity_radius: Option<Spanned<RawQuantity>>,
    pub asperity_density: Option<Spanned<RawQuantity>>,
    /// A height-map file (relative to the problem file) in place of the three values.
    pub topography: Option<Spanned<String>>,
    pub cutoff: Option<Spanned<RawQuantity>>,
    pub level: Option<Spanned<String>>,
    pub pixel_size: Option<Spanned<RawQuantity>>,
    pub height_unit: Option<Spanned<String>>,
    /// "statistical" (default) or "bem_corrected": see `ContactModel`.
    pub contact_model: Option<Spanned<String>>,
    /// An ASCII matrix written with decimal commas.
    pub decimal_comma: Option<Spanned<bool>>,
}

/// `{ min = …, max = … }` of one design variable.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBound {
    pub min: Option<Spanned<RawQuantity>>,
    pub max: Option<Spanned<RawQuantity>>,
}

/// `[design]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDesign {
    pub youngs_modulus: Option<Spanned<RawBound>>,
    pub youngs_modulus_a: Option<Spanned<RawBound>>,
    pub youngs_modulus_b: Option<Spanned<RawBound>>,
    pub poisson_ratio: Option<Spanned<RawBound>>,
    pub hardness: Option<Spanned<RawBound>>,
    pub work_of_adhesion: Option<Spanned<RawBound>>,
    pub sigma: Option<Spanned<RawBound>>,
    pub asperity_radius: Option<Spanned<RawBound>>,
    pub asperity_density: Option<Spanned<RawBound>>,
    pub contact_angle: Option<Spanned<RawBound>>,
    pub contact_angle_a: Option<Spanned<RawBound>>,
    pub contact_angle_b: Option<Spanned<RawBound>>,
    pub temperature: Option<Spanned<RawBound>>,
    pub activation_energy: Option<Spanned<RawBound>>,
    pub activation_volume: Option<Spanned<RawBound>>,
    pub sliding_speed: Option<Spanned<RawBound>>,
    pub materials: Option<Spanned<Vec<Spanned<String>>>>,
}

/// `[objective]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawObjective {
    pub minimize: Option<Spanned<String>>,
    /// A statistic over the uncertain inputs (`"p95"`, …) instead of the nominal value.
    pub statistic: Option<Spanned<String>>,
    /// The common random numbers the statistic is taken over.
    pub samples: Option<Spanned<RawInteger>>,
}

/// One `[[constraint]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawConstraint {
    pub quantity: Option<Spanned<String>>,
    pub min: Option<Spanned<RawQuantity>>,
    pub max: Option<Spanned<RawQuantity>>,
    /// A chance constraint's event: `"stiction"`, `"wear_out"`, the name of an
    /// `[[uncertainty.event]]`, or `{ quantity = …, above = … }`.
    pub event: Option<Spanned<toml::Value>>,
    /// A chance constraint's largest probability.
    pub probability_max: Option<Spanned<RawQuantity>>,
}

/// `[pareto]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPareto {
    pub adhesion: Option<Spanned<String>>,
    pub points: Option<Spanned<RawInteger>>,
    pub direction: Option<Spanned<String>>,
    /// A probability front's event (as a chance constraint's): the front's
    /// second axis is P(event).
    pub event: Option<Spanned<toml::Value>>,
    /// The loosest level of P(event) a probability front sweeps.
    pub probability_max: Option<Spanned<RawQuantity>>,
    /// The tightest level.
    pub probability_min: Option<Spanned<RawQuantity>>,
}

/// `[optimizer]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawOptimizer {
    pub starts: Option<Spanned<RawInteger>>,
    pub seed: Option<Spanned<RawInteger>>,
    pub tolerance: Option<Spanned<RawQuantity>>,
    pub max_iterations: Option<Spanned<RawInteger>>,
    pub time_limit: Option<Spanned<RawQuantity>>,
}

/// `[uncertainty]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawUncertainty {
    pub samples: Option<Spanned<RawInteger>>,
    /// What a robust study does when sampling contradicts a chance constraint's
    /// FORM-based design: `"report"` or `"correct"`.
    pub verify: Option<Spanned<String>>,
    pub seed: Option<Spanned<RawInteger>>,
    pub outputs: Option<Spanned<Vec<Spanned<String>>>>,
    pub inputs: Option<Spanned<BTreeMap<String, Spanned<RawInput>>>>,
    #[serde(default)]
    pub correlation: Vec<Spanned<RawCorrelation>>,
    #[serde(default)]
    pub event: Vec<Spanned<RawEvent>>,
}

/// One `[uncertainty.inputs]` entry as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawInput {
    pub distribution: Option<Spanned<String>>,
    pub median: Option<Spanned<RawQuantity>>,
    pub factor: Option<Spanned<RawQuantity>>,
    pub mean: Option<Spanned<RawQuantity>>,
    pub sd: Option<Spanned<RawQuantity>>,
    pub min: Option<Spanned<RawQuantity>>,
    pub max: Option<Spanned<RawQuantity>>,
    pub mode: Option<Spanned<RawQuantity>>,
    pub alpha: Option<Spanned<RawQuantity>>,
    pub beta: Option<Spanned<RawQuantity>>,
}

/// One `[[uncertainty.correlation]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCorrelation {
    pub between: Option<Spanned<Vec<Spanned<String>>>>,
    pub rho: Option<Spanned<f64>>,
}

/// One `[[uncertainty.event]]` as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawEvent {
    pub name: Option<Spanned<String>>,
    pub quantity: Option<Spanned<String>>,
    pub above: Option<Spanned<RawQuantity>>,
    pub below: Option<Spanned<RawQuantity>>,
}
