//! What reading a problem file decided for the user, as values: a catalogue value
//! taken or overridden, an input far from its material's typical range. The report
//! stage words them (`report::words::input_note`); the problem stage writes no English.

use serde::Serialize;

/// A body of the contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyKey {
    /// `[bodies.a]`: the rough, softer body.
    A,
    /// `[bodies.b]`: the counterface.
    B,
}

impl BodyKey {
    /// The problem file's table name, "bodies.a" or "bodies.b".
    pub fn table(self) -> &'static str {
        match self {
            BodyKey::A => "bodies.a",
            BodyKey::B => "bodies.b",
        }
    }
}

/// A catalogue property a body may override.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CatalogueProperty {
    /// E (Pa).
    YoungsModulus,
    /// ν (dimensionless).
    PoissonRatio,
}

impl CatalogueProperty {
    /// The problem-file key.
    pub fn key(self) -> &'static str {
        match self {
            CatalogueProperty::YoungsModulus => "youngs_modulus",
            CatalogueProperty::PoissonRatio => "poisson_ratio",
        }
    }
}

/// Something the reader decided or noticed, to show beside the results (SI values).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum InputNote {
    /// A body gives a value of its own beside `material`: it replaces the catalogue's.
    CatalogueOverride {
        /// Which body.
        body: BodyKey,
        /// Which property.
        property: CatalogueProperty,
        /// The value given (SI).
        value: f64,
        /// The catalogue value it replaces (SI).
        catalogue_value: f64,
        /// The catalogue material.
        material: &'static str,
    },
    /// `[interface] hardness` is absent: the softer body's catalogue hardness is
    /// used (body a's unless body b is a catalogue material and softer).
    HardnessFromCatalogue {
        /// The catalogue material it came from.
        material: &'static str,
        /// Its hardness (Pa).
        hardness: f64,
        /// The body it came from.
        body: BodyKey,
    },
    /// γ lies more than a factor of 10 outside the catalogue's typical range for body
    /// a's material (accepted: a treated or contaminated surface may be so).
    AtypicalWorkOfAdhesion {
        /// γ as given (J/m²).
        value: f64,
        /// The typical range's lower end (J/m²).
        typical_min: f64,
        /// The typical range's upper end (J/m²).
        typical_max: f64,
        /// The catalogue material of body a.
        material: &'static str,
    },
    /// `[interface] hardness` is given and body b's catalogue material is softer
    /// than body a's: the model's H is the softer body's, so the given value
    /// should be b's.
    SofterCounterface {
        /// Body a's catalogue material.
        material_a: &'static str,
        /// Its hardness (Pa).
        hardness_a: f64,
        /// Body b's catalogue material.
        material_b: &'static str,
        /// Its hardness (Pa).
        hardness_b: f64,
    },
}
