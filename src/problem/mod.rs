//! Problem files: the TOML schema, units, the material catalogue and validation with
//! precise errors.
//!
//! Loading ([`load`], [`parse`]) has two stages. The first deserializes the file as
//! written (serde, unknown keys denied, every value `Spanned` so it knows its line);
//! the second reads units, looks up materials, fills defaults, checks ranges and
//! cross-field rules, and builds the [`Scene`] and [`Study`]. Every refusal is a [`ProblemError`] whose one-line
//! message names the file, the line, the dotted key, the value as written and what would
//! be accepted:
//!
//! ```text
//! problems/x.toml:7: contact.load = "10 uQ": unknown unit "uQ"; expected a force such as "10 uN", "2 mN" or a number in newtons
//! ```
//!
//! The schema (all values SI numbers or strings with units, see [`crate::units`]):
//!
//! ```toml
//! name = "Polysilicon micro-gear hub"   # optional; default: the file stem
//!
//! [contact]
//! load = "10 uN"                  # W, any finite force; > 0 presses, < 0 pulls
//! nominal_area = "1000 um^2"      # A_n > 0
//! sliding_distance = "1 m"        # L >= 0
//! wear_coefficient = 1e-4         # k in [0, 1]
//! wear_area = "total"             # or "plastic" (default "total")
//!
//! [bodies]
//! a = { material = "polysilicon" }                            # rough, softer body
//! b = { youngs_modulus = "160 GPa", poisson_ratio = 0.22 }    # or "inf": rigid
//!
//! [interface]
//! hardness = "10 GPa"             # H > 0 or "inf"; default: the softer body's catalogue value (a's, or b's when b is a softer catalogue material)
//! work_of_adhesion = "0.1 J/m^2"  # γ >= 0
//! interatomic_distance = "0.3 nm" # Z0 > 0 (default 0.3 nm); under DMT and Lennard-Jones also the attraction's range
//! adhesion_model = "jkr"          # or "dmt", "lennard_jones" (default "jkr"): the asperity law
//! attraction = "van_der_waals"    # DMT only: or "dugdale" (default "van_der_waals")
//!
//! [roughness]
//! sigma = "5 nm"
//! asperity_radius = "1 um"
//! asperity_density = "10 um^-2"
//! ```
//!
//! and optionally `[design]`, `[objective]`, `[[constraint]]`, `[pareto]` and
//! `[optimizer]` (see [`Study`]).

pub mod catalogue;
mod error;
mod locate;
pub mod notes;
pub(crate) mod raw;
pub mod robust;
mod study;
mod topography;
pub mod uncertainty;

use std::ops::Range;
use std::path::Path;
use std::time::Duration;

use serde::Serialize;
use toml::Spanned;

pub(crate) use error::suggest;
pub use error::{Location, ProblemError};
pub use notes::{BodyKey, CatalogueProperty, InputNote};
pub use robust::{
    ChanceConstraint, EventFront, Robust, DEFAULT_FRONT_POINTS, MAX_FRONT_POINTS, MIN_FRONT_POINTS,
};
pub(crate) use study::DesignKeys;
pub use study::{Dimensioned, Study};
pub use topography::{AreaCorrection, ContactModel, ExactContact, ScanSource};
pub use uncertainty::{Event, UncertainInput, Uncertainty};

use crate::model::wear_law::{Activation, ContactStress};
use crate::model::{
    AdhesionModel, AttractionKind, Cantilever, Environment, HumidityRange, Liquid, Scene, WearArea,
    WearModel,
};
use crate::optimize::{
    AdhesionMeasure, Constraint, ConstraintQuantity, DesignVariable, Named, Objective,
    OptimizerSettings, ParetoDirection, ParetoSpec, SceneParameter, DEFAULT_RELEASE_MARGIN,
};
use crate::units::{format_number, format_quantity, parse_quantity, Dimension};
use catalogue::Material;
use error::line_of;
use raw::{RawBody, RawBound, RawInteger, RawProblem, RawQuantity};

/// Z0 when the file does not give `interface.interatomic_distance`: 0.3 nm.
pub const DEFAULT_INTERATOMIC_DISTANCE: f64 = 0.3e-9;

/// A validated problem: one scene and what to do with it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Problem {
    /// `name`, or the file stem.
    pub name: String,
    /// The contact, in SI units.
    pub scene: Scene,
    /// Design variables, objective, constraints, Pareto front, optimiser settings.
    pub study: Study,
    /// Things the loader decided for the user, to show beside the results (values taken
    /// from the catalogue, overrides, implausible but accepted values); the report
    /// stage words them.
    pub notes: Vec<InputNote>,
    /// The measured scan σ, R and N came from (`[roughness] topography`), if any.
    pub scan: Option<ScanSource>,
    /// `[uncertainty]`: the inputs' distributions, outputs and events, if given.
    pub uncertainty: Option<Uncertainty>,
    /// A statistic objective, chance constraints, and how they are verified
    /// (empty for a nominal study).
    pub robust: Robust,
}

/// Reads and validates a problem file. The file must be UTF-8; its path (as given) is
/// the origin named in error messages. Nothing is solved here: a scan's
/// `contact_model = "bem_corrected"` stays a request (the scene's `real_area_scale`
/// 1) until `app::load` fulfils it.
pub fn load(path: &Path) -> Result<Problem, ProblemError> {
    let origin = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|io| ProblemError::Io {
        path: origin.clone(),
        io,
    })?;
    let text = match String::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => {
            let good = e.utf8_error().valid_up_to();
            let prefix = std::str::from_utf8(&e.as_bytes()[..good]).unwrap_or("");
            return Err(ProblemError::NotUtf8 {
                at: Location {
                    origin,
                    line: Some(line_of(prefix, good)),
                },
                byte: good,
            });
        }
    };
    parse(&text, &origin)
}

/// Parses and validates problem-file text. `origin` names the file in messages and
/// gives the default `name` (its stem).
pub fn parse(text: &str, origin: &str) -> Result<Problem, ProblemError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let located = |span: Option<Range<usize>>| Location {
        origin: origin.to_string(),
        line: span.map(|s| line_of(text, s.start)),
    };
    // The span-preserving document: syntax errors, emptiness, and later the paths of
    // serde errors.
    let tree = toml::de::DeTable::parse(text).map_err(|e| ProblemError::Syntax {
        at: located(e.span()),
        message: one_line(e.message()),
    })?;
    if tree.get_ref().is_empty() {
        return Err(ProblemError::Empty { at: located(None) });
    }
    let raw: RawProblem = toml::from_str(text).map_err(|e| serde_error(&e, text, origin, &tree))?;
    Problem::from_raw(raw, text, origin)
}

/// Collapses a multi-line parser message into one line.
fn one_line(message: &str) -> String {
    message.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The text of the backtick-quoted names in a serde message, in order.
fn backticked(message: &str) -> Vec<String> {
    message
        .split('`')
        .skip(1)
        .step_by(2)
        .map(str::to_string)
        .collect()
}

/// Maps a deserialization error (unknown key, wrong type) to a [`ProblemError`] with a
/// dotted key.
fn serde_error(
    err: &toml::de::Error,
    text: &str,
    origin: &str,
    tree: &Spanned<toml::de::DeTable<'_>>,
) -> ProblemError {
    let message = one_line(err.message());
    let span = err.span();
    let at = Location {
        origin: origin.to_string(),
        line: span.as_ref().map(|s| line_of(text, s.start)),
    };
    let hit = span.as_ref().and_then(|s| locate::find(tree, s));
    let written = span.as_ref().map(|s| written(text, s)).unwrap_or_default();
    if let Some(rest) = message.strip_prefix("unknown field ") {
        let names = backticked(rest);
        let name = names.first().cloned().unwrap_or_default();
        let valid: Vec<String> = names.into_iter().skip(1).collect();
        let table = match &hit {
            Some(h) if h.is_key => locate::render(&h.path[..h.path.len() - 1]),
            Some(h) => locate::render(&h.path),
            None => String::new(),
        };
        let key = if table.is_empty() {
            name.clone()
        } else {
            format!("{table}.{name}")
        };
        let suggestion = suggest(&name, valid.iter().map(String::as_str)).map(str::to_string);
        return ProblemError::UnknownKey {
            at,
            key,
            suggestion,
            valid,
        };
    }
    let key = hit
        .map(|h| locate::render(&h.path))
        .unwrap_or_else(|| "(document)".to_string());
    if let Some(rest) = message
        .strip_prefix("invalid type: ")
        .or_else(|| message.strip_prefix("invalid value: "))
    {
        return ProblemError::WrongType {
            at,
            key,
            value: written,
            message: rest.to_string(),
        };
    }
    ProblemError::WrongType {
        at,
        key,
        value: written,
        message,
    }
}

/// The source text of a span, on one line and at most 80 characters.
fn written(text: &str, span: &Range<usize>) -> String {
    let raw = text.get(span.clone()).unwrap_or("").trim();
    let flat = one_line(raw);
    if flat.chars().count() > 80 {
        let cut: String = flat.chars().take(77).collect();
        format!("{cut}...")
    } else {
        flat
    }
}

/// The accepted range of a dimensional value, and how to say it.
#[derive(Debug, Clone, Copy)]
struct Accept {
    dim: Dimension,
    lo: f64,
    lo_open: bool,
    hi: f64,
    hi_open: bool,
    /// `+inf` is allowed, and what it means.
    inf: Option<&'static str>,
    /// What the value is, for the message.
    why: Option<&'static str>,
}

impl Accept {
    fn any(dim: Dimension) -> Self {
        Accept {
            dim,
            lo: f64::NEG_INFINITY,
            lo_open: true,
            hi: f64::INFINITY,
            hi_open: true,
            inf: None,
            why: None,
        }
    }
    fn positive(dim: Dimension) -> Self {
        Accept {
            lo: 0.0,
            ..Self::any(dim)
        }
    }
    fn non_negative(dim: Dimension) -> Self {
        Accept {
            lo: 0.0,
            lo_open: false,
            ..Self::any(dim)
        }
    }
    fn interval(dim: Dimension, lo: f64, lo_open: bool, hi: f64, hi_open: bool) -> Self {
        Accept {
            lo,
            lo_open,
            hi,
            hi_open,
            ..Self::any(dim)
        }
    }
    fn or_inf(self, meaning: &'static str) -> Self {
        Accept {
            inf: Some(meaning),
            ..self
        }
    }
    fn why(self, why: &'static str) -> Self {
        Accept {
            why: Some(why),
            ..self
        }
    }

    fn with_unit(&self, x: f64) -> String {
        let (x, unit) = self.shown(x);
        if unit.is_empty() {
            format_number(x)
        } else {
            format!("{} {unit}", format_number(x))
        }
    }

    /// A bound as a message writes it: energies in eV, the rest in SI.
    fn shown(&self, x: f64) -> (f64, &'static str) {
        match self.dim {
            Dimension::Energy => (x / crate::units::ELECTRON_VOLT, "eV"),
            _ => (x, self.dim.si_unit()),
        }
    }

    fn describe(&self) -> String {
        let mut s = match (self.lo.is_finite(), self.hi.is_finite()) {
            (true, true) => {
                let (lo, unit) = self.shown(self.lo);
                let (hi, _) = self.shown(self.hi);
                format!(
                    "must be in {}{}, {}{}{}",
                    if self.lo_open { "(" } else { "[" },
                    format_number(lo),
                    format_number(hi),
                    if self.hi_open { ")" } else { "]" },
                    if unit.is_empty() {
                        String::new()
                    } else {
                        format!(" {unit}")
                    }
                )
            }
            (true, false) => format!(
                "must be {} {}",
                if self.lo_open { ">" } else { ">=" },
                self.with_unit(self.lo)
            ),
            (false, true) => format!(
                "must be {} {}",
                if self.hi_open { "<" } else { "<=" },
                self.with_unit(self.hi)
            ),
            (false, false) => "must be a finite number".to_string(),
        };
        if let Some(meaning) = self.inf {
            s.push_str(&format!(", or \"inf\" for {meaning}"));
        }
        let why = match self.why {
            Some(w) => Some(w.to_string()),
            None if self.lo == 0.0 && self.lo_open && !self.hi.is_finite() => {
                Some(format!("a positive {}", self.dim.name()))
            }
            None => None,
        };
        if let Some(why) = why {
            s.push_str(&format!(" ({why})"));
        }
        s
    }

    fn check(&self, x: f64) -> Result<(), String> {
        if x == f64::INFINITY && self.inf.is_some() {
            return Ok(());
        }
        if x.is_infinite() {
            return Err(format!("{}; infinity is not allowed here", self.describe()));
        }
        let above = if self.lo_open {
            x > self.lo
        } else {
            x >= self.lo
        };
        let below = if self.hi_open {
            x < self.hi
        } else {
            x <= self.hi
        };
        if above && below {
            Ok(())
        } else {
            Err(self.describe())
        }
    }
}

/// Stage two's state: the source text (for lines and values as written) and the notes
/// collected on the way.
struct Reader<'a> {
    text: &'a str,
    origin: &'a str,
    notes: Vec<InputNote>,
}

impl Reader<'_> {
    fn at(&self, span: Option<&Range<usize>>) -> Location {
        Location {
            origin: self.origin.to_string(),
            line: span.map(|s| line_of(self.text, s.start)),
        }
    }

    fn invalid(&self, key: &str, span: &Range<usize>, reason: impl Into<String>) -> ProblemError {
        ProblemError::InvalidValue {
            at: self.at(Some(span)),
            key: key.to_string(),
            value: written(self.text, span),
            reason: reason.into(),
        }
    }

    fn missing(&self, key: &str, table: Option<&Range<usize>>, hint: &str) -> ProblemError {
        ProblemError::MissingKey {
            at: self.at(table),
            key: key.to_string(),
            hint: hint.to_string(),
        }
    }

    /// A required value, or a [`ProblemError::MissingKey`] at the table's line.
    fn required<'r, T>(
        &self,
        value: &'r Option<Spanned<T>>,
        key: &str,
        table: Option<&Range<usize>>,
        hint: &str,
    ) -> Result<&'r Spanned<T>, ProblemError> {
        value.as_ref().ok_or_else(|| self.missing(key, table, hint))
    }

    /// A dimensional value in SI units, checked against its accepted range.
    fn quantity(
        &self,
        key: &str,
        value: &Spanned<RawQuantity>,
        accept: Accept,
    ) -> Result<f64, ProblemError> {
        let x = parse_quantity(value.get_ref().as_input(), accept.dim)
            .map_err(|e| self.invalid(key, &value.span(), e.to_string()))?;
        accept
            .check(x)
            .map_err(|reason| self.invalid(key, &value.span(), reason))?;
        Ok(x)
    }

    fn optional_quantity(
        &self,
        key: &str,
        value: &Option<Spanned<RawQuantity>>,
        accept: Accept,
    ) -> Result<Option<f64>, ProblemError> {
        value
            .as_ref()
            .map(|v| self.quantity(key, v, accept))
            .transpose()
    }

    /// An integer in `lo..=hi`.
    fn integer(
        &self,
        key: &str,
        value: &Spanned<RawInteger>,
        lo: i64,
        hi: i64,
        why: &str,
    ) -> Result<i64, ProblemError> {
        let x = value.get_ref().0;
        if (lo..=hi).contains(&x) {
            Ok(x)
        } else {
            let range = if hi == i64::MAX {
                format!(">= {lo}")
            } else {
                format!("in {lo}..={hi}")
            };
            Err(self.invalid(
                key,
                &value.span(),
                format!("must be an integer {range} ({why})"),
            ))
        }
    }

    /// One of a closed set of names, with a suggestion when it is a near miss.
    fn named<T: Named>(&self, key: &str, value: &Spanned<String>) -> Result<T, ProblemError> {
        let name = value.get_ref();
        T::from_name(name).ok_or_else(|| {
            let names = T::names();
            let hint = suggest(name, names.iter().copied())
                .map(|s| format!("; did you mean \"{s}\"?"))
                .unwrap_or_default();
            self.invalid(
                key,
                &value.span(),
                format!("unknown value{hint} (one of: {})", names.join(", ")),
            )
        })
    }

    /// A catalogue material, with the nearest name and the list when it is unknown.
    /// `or_constants`: the key may be replaced by explicit elastic constants (a body).
    fn material(
        &self,
        key: &str,
        value: &Spanned<String>,
        or_constants: bool,
    ) -> Result<&'static Material, ProblemError> {
        catalogue::lookup(value.get_ref()).ok_or_else(|| {
            let hint = catalogue::suggest(value.get_ref())
                .map(|s| format!("; did you mean \"{s}\"?"))
                .unwrap_or_default();
            let alternative = if or_constants {
                "; or give youngs_modulus and poisson_ratio instead"
            } else {
                ""
            };
            self.invalid(
                key,
                &value.span(),
                format!(
                    "unknown material{hint} (catalogue: {}{alternative})",
                    catalogue::names().join(", ")
                ),
            )
        })
    }
}

/// One body's elastic constants after catalogue look-up and overrides.
struct Body {
    youngs_modulus: f64,
    poisson_ratio: f64,
    material: Option<&'static Material>,
}

impl Reader<'_> {
    fn body(
        &mut self,
        body: BodyKey,
        raw: &Spanned<RawBody>,
        rigid_allowed: bool,
    ) -> Result<Body, ProblemError> {
        let key = body.table();
        let span = raw.span();
        let raw = raw.get_ref();
        let material = raw
            .material
            .as_ref()
            .map(|m| self.material(&format!("{key}.material"), m, true))
            .transpose()?;
        let mut e_accept = Accept::positive(Dimension::Pressure).why("a positive Young's modulus");
        if rigid_allowed {
            e_accept = e_accept.or_inf("a rigid counterface");
        }
        let nu_accept =
            Accept::interval(Dimension::Dimensionless, -1.0, true, 0.5, false).why("Poisson ratio");
        let how = "give material = \"polysilicon\" (or another catalogue name), or both youngs_modulus and poisson_ratio";
        let youngs_modulus = match (&raw.youngs_modulus, material) {
            (Some(v), m) => {
                let e = self.quantity(&format!("{key}.youngs_modulus"), v, e_accept)?;
                if let Some(m) = m {
                    self.notes.push(InputNote::CatalogueOverride {
                        body,
                        property: CatalogueProperty::YoungsModulus,
                        value: e,
                        catalogue_value: m.youngs_modulus,
                        material: m.name,
                    });
                }
                e
            }
            (None, Some(m)) => m.youngs_modulus,
            (None, None) => {
                return Err(self.missing(&format!("{key}.youngs_modulus"), Some(&span), how))
            }
        };
        let poisson_ratio = match (&raw.poisson_ratio, material) {
            (Some(v), m) => {
                let nu = self.quantity(&format!("{key}.poisson_ratio"), v, nu_accept)?;
                if let Some(m) = m {
                    self.notes.push(InputNote::CatalogueOverride {
                        body,
                        property: CatalogueProperty::PoissonRatio,
                        value: nu,
                        catalogue_value: m.poisson_ratio,
                        material: m.name,
                    });
                }
                nu
            }
            (None, Some(m)) => m.poisson_ratio,
            // A rigid body has no compliance, so its Poisson ratio never enters E.
            (None, None) if youngs_modulus.is_infinite() => 0.0,
            (None, None) => {
                return Err(self.missing(&format!("{key}.poisson_ratio"), Some(&span), how))
            }
        };
        Ok(Body {
            youngs_modulus,
            poisson_ratio,
            material,
        })
    }
}

const CONTACT_HINT: &str =
    "add a [contact] table with load, nominal_area, sliding_distance and wear_coefficient";
const BODIES_HINT: &str =
    "add a [bodies] table, e.g. a = { material = \"polysilicon\" } and b = { material = \"polysilicon\" }";
const INTERFACE_HINT: &str =
    "add an [interface] table with work_of_adhesion (and hardness unless body a is a catalogue material)";
const ROUGHNESS_HINT: &str =
    "add a [roughness] table with sigma, asperity_radius and asperity_density, or topography = \"scans/x.gsf\" (a measured height map)";

impl Problem {
    /// Stage two: units, catalogue look-ups, defaults, ranges and cross-field checks.
    /// `text` is the source `raw` was read from (for line numbers and values as
    /// written); `origin` names it in messages.
    pub(crate) fn from_raw(
        raw: RawProblem,
        text: &str,
        origin: &str,
    ) -> Result<Problem, ProblemError> {
        let mut r = Reader {
            text,
            origin,
            notes: Vec::new(),
        };

        let name = match &raw.name {
            Some(n) if n.get_ref().trim().is_empty() => {
                return Err(r.invalid(
                    "name",
                    &n.span(),
                    "must not be empty (or leave it out to use the file name)",
                ))
            }
            Some(n) => n.get_ref().trim().to_string(),
            None => Path::new(origin)
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_else(|| origin.to_string()),
        };

        // [contact]
        let contact = r.required(&raw.contact, "table [contact]", None, CONTACT_HINT)?;
        let cspan = contact.span();
        let c = contact.get_ref();
        let load = r.quantity(
            "contact.load",
            r.required(
                &c.load,
                "contact.load",
                Some(&cspan),
                "the normal load, e.g. load = \"10 uN\" (positive presses the bodies together)",
            )?,
            Accept::any(Dimension::Force).why("positive compressive, negative tensile"),
        )?;
        let nominal_area = r.quantity(
            "contact.nominal_area",
            r.required(
                &c.nominal_area,
                "contact.nominal_area",
                Some(&cspan),
                "the nominal contact area, e.g. nominal_area = \"1000 um^2\"",
            )?,
            Accept::positive(Dimension::Area),
        )?;
        let sliding_distance = r.quantity(
            "contact.sliding_distance",
            r.required(
                &c.sliding_distance,
                "contact.sliding_distance",
                Some(&cspan),
                "the sliding distance, e.g. sliding_distance = \"1 m\"",
            )?,
            Accept::non_negative(Dimension::Length).why("a sliding distance"),
        )?;
        // A law that computes its own coefficient (`[wear] law`) needs no k (an
        // unknown law's name is refused with `[wear]`).
        let law_computes_k = raw
            .wear
            .as_ref()
            .and_then(|w| w.get_ref().law.as_ref())
            .is_some_and(|l| l.get_ref() != WearModel::Archard.as_str());
        let wear_coefficient = match (&c.wear_coefficient, law_computes_k) {
            (None, true) => 0.0,
            _ => r.quantity(
                "contact.wear_coefficient",
                r.required(
                    &c.wear_coefficient,
                    "contact.wear_coefficient",
                    Some(&cspan),
                    "the dimensionless Archard wear coefficient k in [0, 1], e.g. wear_coefficient = 1e-4",
                )?,
                Accept::interval(Dimension::Dimensionless, 0.0, false, 1.0, false)
                    .why("the dimensionless Archard wear coefficient"),
            )?,
        };
        let wear_area = match &c.wear_area {
            None => WearArea::default(),
            Some(w) => match w.get_ref().as_str() {
                "total" => WearArea::Total,
                "plastic" => WearArea::Plastic,
                other => {
                    let hint = suggest(other, ["total", "plastic"])
                        .map(|s| format!("; did you mean \"{s}\"?"))
                        .unwrap_or_default();
                    return Err(r.invalid(
                        "contact.wear_area",
                        &w.span(),
                        format!("unknown value{hint} (one of: total, plastic)"),
                    ));
                }
            },
        };

        let allowed_wear_depth = r.optional_quantity(
            "contact.allowed_wear_depth",
            &c.allowed_wear_depth,
            Accept::positive(Dimension::Length).why("the wear depth the part may lose"),
        )?;
        let sliding_per_cycle = r.optional_quantity(
            "contact.sliding_per_cycle",
            &c.sliding_per_cycle,
            Accept::positive(Dimension::Length).why("the sliding distance of one cycle"),
        )?;
        let restoring_force = r.optional_quantity(
            "contact.restoring_force",
            &c.restoring_force,
            Accept::positive(Dimension::Force).why("the force that pulls the part free"),
        )?;

        // [bodies]
        let bodies = r.required(&raw.bodies, "table [bodies]", None, BODIES_HINT)?;
        let bspan = bodies.span();
        let a = r.required(
            &bodies.get_ref().a,
            "bodies.a",
            Some(&bspan),
            "the rough, softer body, e.g. a = { material = \"polysilicon\" }",
        )?;
        let b = r.required(
            &bodies.get_ref().b,
            "bodies.b",
            Some(&bspan),
            "the counterface, e.g. b = { material = \"polysilicon\" } or b = { youngs_modulus = \"inf\" } (rigid)",
        )?;
        let body_a = r.body(BodyKey::A, a, false)?;
        let body_b = r.body(BodyKey::B, b, true)?;

        // [interface]
        let interface = r.required(&raw.interface, "table [interface]", None, INTERFACE_HINT)?;
        let ispan = interface.span();
        let i = interface.get_ref();
        // The model's H is the hardness of the softer body.
        let hardness = match (&i.hardness, body_a.material, body_b.material) {
            (Some(h), _, _) => r.quantity(
                "interface.hardness",
                h,
                Accept::positive(Dimension::Pressure)
                    .or_inf("no plasticity")
                    .why("hardness of the softer body"),
            )?,
            (None, Some(ma), mb) => {
                let (body, m) = match mb {
                    Some(mb) if mb.hardness < ma.hardness => (BodyKey::B, mb),
                    _ => (BodyKey::A, ma),
                };
                r.notes.push(InputNote::HardnessFromCatalogue {
                    material: m.name,
                    hardness: m.hardness,
                    body,
                });
                m.hardness
            }
            (None, None, _) => {
                return Err(r.missing(
                    "interface.hardness",
                    Some(&ispan),
                    "required because body a is not a catalogue material; e.g. hardness = \"10 GPa\", or \"inf\" for no plasticity",
                ))
            }
        };
        let work_of_adhesion = r.quantity(
            "interface.work_of_adhesion",
            r.required(
                &i.work_of_adhesion,
                "interface.work_of_adhesion",
                Some(&ispan),
                "the work of adhesion, e.g. work_of_adhesion = \"0.1 J/m^2\" (0 for no adhesion)",
            )?,
            Accept::non_negative(Dimension::SurfaceEnergy).why("0 means no adhesion"),
        )?;
        let interatomic_distance = r
            .optional_quantity(
                "interface.interatomic_distance",
                &i.interatomic_distance,
                Accept::positive(Dimension::Length),
            )?
            .unwrap_or(DEFAULT_INTERATOMIC_DISTANCE);

        if let Some(m) = body_a.material {
            let (lo, hi) = m.work_of_adhesion;
            if work_of_adhesion > 0.0
                && (work_of_adhesion < lo / 10.0 || work_of_adhesion > hi * 10.0)
            {
                r.notes.push(InputNote::AtypicalWorkOfAdhesion {
                    value: work_of_adhesion,
                    typical_min: lo,
                    typical_max: hi,
                    material: m.name,
                });
            }
        }
        if let (Some(ma), Some(mb), Some(_)) = (body_a.material, body_b.material, &i.hardness) {
            if mb.hardness < ma.hardness {
                r.notes.push(InputNote::SofterCounterface {
                    material_a: ma.name,
                    hardness_a: ma.hardness,
                    material_b: mb.name,
                    hardness_b: mb.hardness,
                });
            }
        }

        // [roughness]
        let roughness = r.required(&raw.roughness, "table [roughness]", None, ROUGHNESS_HINT)?;
        let rspan = roughness.span();
        let g = roughness.get_ref();
        let scan_values = r.topography(g)?;
        let (sigma, asperity_radius, asperity_density, scan) =
            if let Some((s, rad, n, src)) = scan_values {
                (s, rad, n, Some(src))
            } else {
                let sigma = r.quantity(
                    "roughness.sigma",
                    r.required(
                        &g.sigma,
                        "roughness.sigma",
                        Some(&rspan),
                        "the standard deviation of asperity heights, e.g. sigma = \"5 nm\"",
                    )?,
                    Accept::positive(Dimension::Length),
                )?;
                let asperity_radius = r.quantity(
                    "roughness.asperity_radius",
                    r.required(
                        &g.asperity_radius,
                        "roughness.asperity_radius",
                        Some(&rspan),
                        "the asperity tip radius, e.g. asperity_radius = \"1 um\"",
                    )?,
                    Accept::positive(Dimension::Length),
                )?;
                let asperity_density = r.quantity(
                    "roughness.asperity_density",
                    r.required(
                        &g.asperity_density,
                        "roughness.asperity_density",
                        Some(&rspan),
                        "asperities per unit area, e.g. asperity_density = \"10 um^-2\"",
                    )?,
                    Accept::positive(Dimension::InverseArea),
                )?;

                (sigma, asperity_radius, asperity_density, None)
            };

        let adhesion_model = match &i.adhesion_model {
            None => AdhesionModel::default(),
            Some(w) => match AdhesionModel::from_name(w.get_ref()) {
                Some(m) => m,
                None => {
                    let names = AdhesionModel::names();
                    let hint = suggest(w.get_ref(), names)
                        .map(|s| format!("; did you mean \"{s}\"?"))
                        .unwrap_or_default();
                    return Err(r.invalid(
                        "interface.adhesion_model",
                        &w.span(),
                        format!("unknown asperity law{hint} (one of: {})", names.join(", ")),
                    ));
                }
            },
        };
        let attraction = match &i.attraction {
            None => AttractionKind::default(),
            Some(w) if !adhesion_model.takes_attraction() => {
                let takes = AdhesionModel::taking_attraction();
                return Err(r.invalid(
                    "interface.attraction",
                    &w.span(),
                    format!(
                        "attraction applies to the {} law only, and adhesion_model is {:?}{}: remove attraction, or set adhesion_model = {:?}",
                        takes.label(),
                        adhesion_model.as_str(),
                        adhesion_model.law().attraction_refused(),
                        takes.as_str()
                    ),
                ));
            }
            Some(w) => match AttractionKind::from_name(w.get_ref()) {
                Some(a) => a,
                None => {
                    let names = AttractionKind::names();
                    let hint = suggest(w.get_ref(), names)
                        .map(|s| format!("; did you mean \"{s}\"?"))
                        .unwrap_or_default();
                    return Err(r.invalid(
                        "interface.attraction",
                        &w.span(),
                        format!("unknown attraction{hint} (one of: {})", names.join(", ")),
                    ));
                }
            },
        };

        let shear_strength = r.optional_quantity(
            "interface.shear_strength",
            &i.shear_strength,
            Accept::positive(Dimension::Pressure).why("the junctions' shear strength τ"),
        )?;
        let debris_shape_factor = r.optional_quantity(
            "interface.debris_shape_factor",
            &i.debris_shape_factor,
            Accept::positive(Dimension::Dimensionless)
                .why("Λ of the critical junction size d* = Λ w G / τ², default 12"),
        )?;
        let environment = r.environment(&raw, i)?;
        let cantilever = r.cantilever(&raw)?;
        let temperature = r.temperature(&raw, c, environment.as_ref())?;
        let environment = environment.map(|e| Environment { temperature, ..e });
        let (wear_law, activation) = r.wear(&raw, body_a.material, shear_strength)?;
        let scene = Scene {
            youngs_modulus_a: body_a.youngs_modulus,
            poisson_ratio_a: body_a.poisson_ratio,
            youngs_modulus_b: body_b.youngs_modulus,
            poisson_ratio_b: body_b.poisson_ratio,
            hardness,
            work_of_adhesion,
            interatomic_distance,
            sigma,
            asperity_radius,
            asperity_density,
            load,
            nominal_area,
            sliding_distance,
            wear_coefficient,
            wear_area,
            wear_law,
            temperature,
            activation,
            real_area_scale: 1.0,
            requirements: crate::model::Requirements {
                allowed_wear_depth,
                sliding_per_cycle,
                restoring_force,
                shear_strength,
                debris_shape_factor,
                cantilever,
            },
            adhesion_model,
            attraction,
            environment,
        };

        let study = r.study(&raw, &scene)?;
        let uncertainty = raw
            .uncertainty
            .as_ref()
            .map(|u| r.uncertainty(u, &scene))
            .transpose()?;
        let robust = r.robust(
            &raw,
            &scene,
            &study,
            uncertainty.as_ref(),
            raw.uncertainty.as_ref().map(|u| u.span()),
        )?;
        Ok(Problem {
            robust,
            name,
            scene,
            study,
            notes: r.notes,
            scan,
            uncertainty,
        })
    }
}

/// The accepted values of a design variable's bounds.
fn design_accept(q: SceneParameter) -> Accept {
    let dim = q.dimension();
    match q {
        SceneParameter::ContactAngle
        | SceneParameter::ContactAngleA
        | SceneParameter::ContactAngleB => {
            Accept::interval(dim, 0.0, false, std::f64::consts::PI, false)
                .why("the liquid's contact angle, 0° to 180°")
        }
        SceneParameter::PoissonRatio => {
            Accept::interval(dim, -1.0, true, 0.5, false).why("Poisson ratio")
        }
        SceneParameter::WorkOfAdhesion => Accept::non_negative(dim),
        _ => Accept::positive(dim),
    }
}

impl Reader<'_> {
    /// `[environment]` and `[interface] contact_angle` (docs/model.md §10): None
    /// without an `[environment]` table.
    /// T of the contact: `contact.temperature`, or in humid air
    /// `environment.temperature` (one of them), else 298.15 K.
    fn temperature(
        &self,
        raw: &RawProblem,
        c: &raw::RawContact,
        environment: Option<&Environment>,
    ) -> Result<f64, ProblemError> {
        let accept = Accept::positive(Dimension::Temperature).why("the absolute temperature");
        let given = self.optional_quantity("contact.temperature", &c.temperature, accept)?;
        let in_air = raw
            .environment
            .as_ref()
            .is_some_and(|e| e.get_ref().temperature.is_some());
        match (given, c.temperature.as_ref()) {
            (Some(_), Some(w)) if in_air => Err(self.invalid(
                "contact.temperature",
                &w.span(),
                "is given twice: environment.temperature is the same temperature (one for the air and the contact); keep one",
            )),
            (Some(t), Some(w))
                if t >= crate::model::capillary::WATER_CRITICAL_TEMPERATURE
                    && environment.is_some_and(|e| e.liquid == Liquid::Water) =>
            {
                Err(self.invalid(
                    "contact.temperature",
                    &w.span(),
                    "must be below water's critical point, 647.096 K, in humid air (no liquid water above it)",
                ))
            }
            (Some(t), _) => Ok(t),
            (None, _) => Ok(environment
                .map_or(crate::model::capillary::ROOM_TEMPERATURE, |e| e.temperature)),
        }
    }

    /// `[wear]`: the law (default Archard, which takes no other key) and the
    /// stress-assisted law's inputs (docs/model.md §12), a₀ and Ω defaulting to
    /// body a's catalogue material.
    fn wear(
        &self,
        raw: &RawProblem,
        material: Option<&'static Material>,
        shear_strength: Option<f64>,
    ) -> Result<(WearModel, Option<Activation>), ProblemError> {
        let Some(table) = &raw.wear else {
            return Ok((WearModel::Archard, None));
        };
        let span = table.span();
        let w = table.get_ref();
        let law = match &w.law {
            None => WearModel::Archard,
            Some(name) => WearModel::from_name(name.get_ref()).ok_or_else(|| {
                let names = WearModel::names();
                let hint = suggest(name.get_ref(), names.iter().copied())
                    .map(|s| format!("; did you mean \"{s}\"?"))
                    .unwrap_or_default();
                self.invalid(
                    "wear.law",
                    &name.span(),
                    format!("unknown wear law{hint} (one of: {})", names.join(", ")),
                )
            })?,
        };
        let law_inputs: [(&str, Option<Range<usize>>); 7] = [
            (
                "activation_energy",
                w.activation_energy.as_ref().map(|v| v.span()),
            ),
            (
                "activation_volume",
                w.activation_volume.as_ref().map(|v| v.span()),
            ),
            (
                "attempt_frequency",
                w.attempt_frequency.as_ref().map(|v| v.span()),
            ),
            ("site_spacing", w.site_spacing.as_ref().map(|v| v.span())),
            ("atomic_volume", w.atomic_volume.as_ref().map(|v| v.span())),
            ("stress", w.stress.as_ref().map(|v| v.span())),
            ("sliding_speed", w.sliding_speed.as_ref().map(|v| v.span())),
        ];
        if law == WearModel::Archard {
            if let Some((key, Some(at))) = law_inputs.iter().find(|(_, at)| at.is_some()) {
                return Err(self.invalid(
                    &format!("wear.{key}"),
                    at,
                    format!(
                        "is an input of law = \"{}\", and the law is \"{}\" (its wear coefficient is contact.wear_coefficient): set law = \"{}\", or remove {key}",
                        WearModel::StressAssisted.as_str(),
                        law.as_str(),
                        WearModel::StressAssisted.as_str()
                    ),
                ));
            }
            return Ok((law, None));
        }
        let ev = crate::units::ELECTRON_VOLT;
        let activation_energy = self.quantity(
            "wear.activation_energy",
            self.required(
                &w.activation_energy,
                "wear.activation_energy",
                Some(&span),
                "the activation energy ΔU of removing one atom, e.g. activation_energy = \"0.91 eV\"",
            )?,
            Accept::interval(Dimension::Energy, 0.0, true, 10.0 * ev, false)
                .why("the activation energy ΔU"),
        )?;
        let activation_volume = self.quantity(
            "wear.activation_volume",
            self.required(
                &w.activation_volume,
                "wear.activation_volume",
                Some(&span),
                "the activation volume ΔV, e.g. activation_volume = \"0.0067 nm^3\" (0: no stress assistance)",
            )?,
            Accept::interval(Dimension::Volume, 0.0, false, 1e-27, false)
                .why("the activation volume ΔV, 0 to 1 nm^3"),
        )?;
        let attempt_frequency = self
            .optional_quantity(
                "wear.attempt_frequency",
                &w.attempt_frequency,
                Accept::positive(Dimension::Frequency).why("the attempt frequency f0"),
            )?
            .unwrap_or(crate::model::wear_law::ATTEMPT_FREQUENCY);
        let scale = material.and_then(|m| catalogue::atomic_scale(m.name));
        let from_catalogue = |key: &str, example: &str| {
            self.missing(
                &format!("wear.{key}"),
                Some(&span),
                &format!(
                    "{example}; the catalogue gives it only for body a of {}",
                    catalogue::ATOMIC_SCALE_MATERIALS.join(", ")
                ),
            )
        };
        let site_spacing = match &w.site_spacing {
            Some(v) => self.quantity(
                "wear.site_spacing",
                v,
                Accept::positive(Dimension::Length).why("the spacing a0 of surface sites"),
            )?,
            None => scale.map(|s| s.0).ok_or_else(|| {
                from_catalogue(
                    "site_spacing",
                    "the spacing a0 of surface sites, e.g. site_spacing = \"0.384 nm\"",
                )
            })?,
        };
        let atomic_volume = match &w.atomic_volume {
            Some(v) => {
                let omega = self.quantity(
                    "wear.atomic_volume",
                    v,
                    Accept::positive(Dimension::Volume).why("the volume Ω of one atom"),
                )?;
                let cap = crate::model::wear_law::MAX_ATOMIC_VOLUME_RATIO * site_spacing.powi(3);
                if omega > cap {
                    return Err(self.invalid(
                        "wear.atomic_volume",
                        &v.span(),
                        format!(
                            "must be at most 10 a0^3 = {} with site_spacing a0 = {} (one atom's volume is about a0^3)",
                            format_quantity(cap, Dimension::Volume),
                            format_quantity(site_spacing, Dimension::Length)
                        ),
                    ));
                }
                omega
            }
            None => scale.map(|s| s.1).ok_or_else(|| {
                from_catalogue(
                    "atomic_volume",
                    "the volume Ω of one atom, e.g. atomic_volume = \"0.02002 nm^3\"",
                )
            })?,
        };
        let stress = match &w.stress {
            None => ContactStress::Normal,
            Some(word) => ContactStress::ALL
                .into_iter()
                .find(|s| s.as_str() == word.get_ref())
                .ok_or_else(|| {
                    let names = ContactStress::ALL.map(ContactStress::as_str);
                    let hint = suggest(word.get_ref(), names)
                        .map(|s| format!("; did you mean \"{s}\"?"))
                        .unwrap_or_default();
                    self.invalid(
                        "wear.stress",
                        &word.span(),
                        format!("unknown stress{hint} (one of: normal, shear)"),
                    )
                })?,
        };
        if let (ContactStress::Shear, None) = (stress, shear_strength) {
            let at = w.stress.as_ref().map_or(span.clone(), |s| s.span());
            return Err(self.invalid(
                "wear.stress",
                &at,
                "\"shear\" reads the junctions' shear strength τ: add interface.shear_strength, e.g. shear_strength = \"1 GPa\"",
            ));
        }
        let sliding_speed = self.quantity(
            "wear.sliding_speed",
            self.required(
                &w.sliding_speed,
                "wear.sliding_speed",
                Some(&span),
                "the sliding speed v, e.g. sliding_speed = \"38 mm/s\" (the law's rate depends on it)",
            )?,
            Accept::positive(Dimension::Speed).why("the sliding speed v"),
        )?;
        Ok((
            law,
            Some(Activation {
                activation_energy,
                activation_volume,
                attempt_frequency,
                site_spacing,
                atomic_volume,
                stress,
                sliding_speed,
            }),
        ))
    }

    fn environment(
        &self,
        raw: &RawProblem,
        i: &raw::RawInterface,
    ) -> Result<Option<Environment>, ProblemError> {
        let angle = Accept::interval(Dimension::Angle, 0.0, false, std::f64::consts::PI, false)
            .why("the liquid's contact angle, 0° to 180°");
        let one = self.optional_quantity("interface.contact_angle", &i.contact_angle, angle)?;
        let a = self.optional_quantity("interface.contact_angle_a", &i.contact_angle_a, angle)?;
        let b = self.optional_quantity("interface.contact_angle_b", &i.contact_angle_b, angle)?;
        if let (Some(w), true) = (&i.contact_angle, a.is_some() || b.is_some()) {
            return Err(self.invalid(
                "interface.contact_angle",
                &w.span(),
                "give either contact_angle (both bodies) or contact_angle_a / contact_angle_b (one each), not both",
            ));
        }
        let Some(env) = &raw.environment else {
            if let Some(w) = i
                .contact_angle
                .as_ref()
                .or(i.contact_angle_a.as_ref())
                .or(i.contact_angle_b.as_ref())
            {
                return Err(self.invalid(
                    "interface.contact_angle",
                    &w.span(),
                    "a contact angle needs a liquid: add an [environment] table with relative_humidity, e.g. relative_humidity = \"50 %\"",
                ));
            }
            return Ok(None);
        };
        let espan = env.span();
        let e = env.get_ref();
        let rh_accept = Accept::interval(Dimension::Dimensionless, 0.0, false, 1.0, true)
            .why("the relative humidity, 0 (dry) to below 1 (saturated)");
        let rh_value = self.required(
            &e.relative_humidity,
            "environment.relative_humidity",
            Some(&espan),
            "the relative humidity, e.g. relative_humidity = 0.5 or \"50 %\"",
        )?;
        let (rh, humidity_range) = self.humidity(rh_value, e, rh_accept)?;
        let temperature = self
            .optional_quantity(
                "environment.temperature",
                &e.temperature,
                Accept::positive(Dimension::Temperature).why("the absolute temperature"),
            )?
            .unwrap_or(crate::model::capillary::ROOM_TEMPERATURE);
        let liquid = match &e.liquid {
            None => Liquid::Water,
            Some(v) => self.liquid(v)?,
        };
        if liquid == Liquid::Water
            && temperature >= crate::model::capillary::WATER_CRITICAL_TEMPERATURE
        {
            let at = e.temperature.as_ref().map_or(espan.clone(), |t| t.span());
            return Err(self.invalid(
                "environment.temperature",
                &at,
                "must be below water's critical point, 647.096 K (no liquid water above it)",
            ));
        }
        let (theta_a, theta_b) = match (one, a, b) {
            (Some(t), _, _) => (t, t),
            (None, a, b) => (a.unwrap_or(0.0), b.unwrap_or(0.0)),
        };
        Ok(Some(Environment {
            relative_humidity: rh,
            temperature,
            liquid,
            contact_angle_a: theta_a,
            contact_angle_b: theta_b,
            humidity_range,
        }))
    }

    /// `relative_humidity` as one value or a `{ min, max }` range with
    /// `humidity_points` and `design_humidity`: the humidity an evaluation uses (the
    /// design humidity, else the range's wettest end) and the range.
    fn humidity(
        &self,
        value: &Spanned<toml::Value>,
        e: &raw::RawEnvironment,
        accept: Accept,
    ) -> Result<(f64, Option<HumidityRange>), ProblemError> {
        let span = value.span();
        let key = "environment.relative_humidity";
        let read = |field: &str, v: &toml::Value| -> Result<f64, ProblemError> {
            let raw = RawQuantity::from_value(v).ok_or_else(|| {
                self.invalid(
                    field,
                    &span,
                    "must be a number such as 0.5 or a string such as \"50 %\"",
                )
            })?;
            let x = parse_quantity(raw.as_input(), Dimension::Dimensionless)
                .map_err(|err| self.invalid(field, &span, err.to_string()))?;
            accept
                .check(x)
                .map_err(|reason| self.invalid(field, &span, reason))?;
            Ok(x)
        };
        let toml::Value::Table(t) = value.get_ref() else {
            for (k, v) in [
                (
                    "humidity_points",
                    e.humidity_points.as_ref().map(|p| p.span()),
                ),
                (
                    "design_humidity",
                    e.design_humidity.as_ref().map(|p| p.span()),
                ),
            ] {
                if let Some(at) = v {
                    return Err(self.invalid(
                        &format!("environment.{k}"),
                        &at,
                        "applies to a humidity range only: write relative_humidity = { min = …, max = … }",
                    ));
                }
            }
            return Ok((read(key, value.get_ref())?, None));
        };
        for k in t.keys() {
            if k != "min" && k != "max" {
                return Err(self.invalid(
                    key,
                    &span,
                    format!("unknown key {k:?}: a humidity range is {{ min = 0.0, max = 0.9 }}"),
                ));
            }
        }
        let get = |k: &str| -> Result<f64, ProblemError> {
            let field = format!("{key}.{k}");
            match t.get(k) {
                Some(v) => read(&field, v),
                None => Err(self.invalid(
                    &field,
                    &span,
                    "missing: a humidity range needs both ends, e.g. { min = 0.0, max = 0.9 }",
                )),
            }
        };
        let (min, max) = (get("min")?, get("max")?);
        if min >= max {
            return Err(self.invalid(
                key,
                &span,
                format!("min must be < max (min is {min}, max is {max})"),
            ));
        }
        let points = match &e.humidity_points {
            None => 9,
            Some(p) => self.integer(
                "environment.humidity_points",
                p,
                2,
                101,
                "humidities the limits must hold at, both ends included",
            )? as usize,
        };
        let design = e
            .design_humidity
            .as_ref()
            .map(|d| {
                self.quantity(
                    "environment.design_humidity",
                    d,
                    Accept::interval(Dimension::Dimensionless, min, false, max, false)
                        .why("the humidity the objective is taken at, inside the range"),
                )
            })
            .transpose()?;
        Ok((
            design.unwrap_or(max),
            Some(HumidityRange {
                min,
                max,
                points,
                design_given: design.is_some(),
            }),
        ))
    }

    /// `environment.liquid`: `"water"` or a table of its two properties.
    fn liquid(&self, value: &Spanned<toml::Value>) -> Result<Liquid, ProblemError> {
        let span = value.span();
        match value.get_ref() {
            toml::Value::String(s) if s == "water" => Ok(Liquid::Water),
            toml::Value::Table(t) => {
                for key in t.keys() {
                    if key != "surface_tension" && key != "molar_volume" {
                        return Err(self.invalid(
                            "environment.liquid",
                            &span,
                            format!("unknown key {key:?}: a liquid is {{ surface_tension = \"…\", molar_volume = \"…\" }}"),
                        ));
                    }
                }
                let get = |key: &str, dim: Dimension, example: &str| -> Result<f64, ProblemError> {
                    let field = format!("environment.liquid.{key}");
                    let raw = match t.get(key) {
                        Some(v) => RawQuantity::from_value(v)
                            .ok_or_else(|| self.invalid(&field, &span, dim.expectation()))?,
                        None => {
                            return Err(self.invalid(
                                &field,
                                &span,
                                format!("missing: give {key}, e.g. {key} = \"{example}\""),
                            ));
                        }
                    };
                    let x = crate::units::parse_quantity(raw.as_input(), dim)
                        .map_err(|e| self.invalid(&field, &span, e.to_string()))?;
                    Accept::positive(dim)
                        .check(x)
                        .map_err(|reason| self.invalid(&field, &span, reason))?;
                    Ok(x)
                };
                Ok(Liquid::Given {
                    surface_tension: get("surface_tension", Dimension::SurfaceEnergy, "72 mN/m")?,
                    molar_volume: get("molar_volume", Dimension::MolarVolume, "18.07 cm^3/mol")?,
                })
            }
            _ => Err(self.invalid(
                "environment.liquid",
                &span,
                "must be \"water\" or a table { surface_tension = \"…\", molar_volume = \"…\" }",
            )),
        }
    }

    /// `[stiction] cantilever = { thickness, gap, youngs_modulus }`.
    fn cantilever(&self, raw: &RawProblem) -> Result<Option<Cantilever>, ProblemError> {
        let Some(st) = &raw.stiction else {
            return Ok(None);
        };
        let Some(c) = &st.get_ref().cantilever else {
            return Ok(None);
        };
        let span = c.span();
        let c = c.get_ref();
        let get = |key: &str, value: &Option<Spanned<RawQuantity>>, dim, example: &str| {
            let field = format!("stiction.cantilever.{key}");
            let v = self.required(
                value,
                &field,
                Some(&span),
                &format!(
                    "the beam's {}, e.g. {key} = \"{example}\"",
                    key.replace('_', " ")
                ),
            )?;
            self.quantity(&field, v, Accept::positive(dim))
        };
        Ok(Some(Cantilever {
            thickness: get("thickness", &c.thickness, Dimension::Length, "2 um")?,
            gap: get("gap", &c.gap, Dimension::Length, "2 um")?,
            youngs_modulus: get(
                "youngs_modulus",
                &c.youngs_modulus,
                Dimension::Pressure,
                "160 GPa",
            )?,
        }))
    }

    fn study(&mut self, raw: &RawProblem, scene: &Scene) -> Result<Study, ProblemError> {
        let mut study = Study::default();

        // [design]
        if let Some(design) = &raw.design {
            let d = design.get_ref();
            if let (Some(both), true) = (
                &d.youngs_modulus,
                d.youngs_modulus_a.is_some() || d.youngs_modulus_b.is_some(),
            ) {
                return Err(self.invalid(
                    "design.youngs_modulus",
                    &both.span(),
                    "give either youngs_modulus (body a, and b when they share it) or youngs_modulus_a / youngs_modulus_b (one body by name), not both",
                ));
            }
            let mut placed = Vec::new();
            for q in SceneParameter::DESIGN {
                let bound = match q {
                    SceneParameter::YoungsModulus => &d.youngs_modulus,
                    SceneParameter::YoungsModulusA => &d.youngs_modulus_a,
                    SceneParameter::YoungsModulusB => &d.youngs_modulus_b,
                    SceneParameter::PoissonRatio => &d.poisson_ratio,
                    SceneParameter::Hardness => &d.hardness,
                    SceneParameter::WorkOfAdhesion => &d.work_of_adhesion,
                    SceneParameter::Sigma => &d.sigma,
                    SceneParameter::AsperityRadius => &d.asperity_radius,
                    SceneParameter::AsperityDensity => &d.asperity_density,
                    SceneParameter::ContactAngle => &d.contact_angle,
                    SceneParameter::ContactAngleA => &d.contact_angle_a,
                    SceneParameter::ContactAngleB => &d.contact_angle_b,
                    SceneParameter::Temperature => &d.temperature,
                    SceneParameter::ActivationEnergy => &d.activation_energy,
                    SceneParameter::ActivationVolume => &d.activation_volume,
                    SceneParameter::SlidingSpeed => &d.sliding_speed,
                    // Not design variables (SceneParameter::DESIGN leaves them out).
                    SceneParameter::NominalArea
                    | SceneParameter::Load
                    | SceneParameter::InteratomicDistance
                    | SceneParameter::WearCoefficient
                    | SceneParameter::SlidingDistance
                    | SceneParameter::RelativeHumidity => &None,
                };
                if let Some(bound) = bound {
                    if q.is_environmental() && scene.environment.is_none() {
                        return Err(self.invalid(
                            &format!("design.{}", q.as_str()),
                            &bound.span(),
                            "moves the humid air's liquid, and the file has no [environment]: add one with relative_humidity, e.g. relative_humidity = \"90 %\"",
                        ));
                    }
                    if q.is_wear_law_input() && scene.activation.is_none() {
                        return Err(self.invalid(
                            &format!("design.{}", q.as_str()),
                            &bound.span(),
                            "moves an input of the stress-assisted wear law, and the file's law is Archard's: add [wear] law = \"stress_assisted\" with its inputs (docs/model.md §12)",
                        ));
                    }
                    placed.push((bound.span().start, self.design_variable(q, bound, scene)?));
                }
            }
            // File order, as the user wrote them.
            placed.sort_by_key(|(start, _)| *start);
            study.design = placed.into_iter().map(|(_, v)| v).collect();
            if let Some(list) = &d.materials {
                if list.get_ref().is_empty() {
                    return Err(self.invalid(
                        "design.materials",
                        &list.span(),
                        format!(
                            "empty list; name at least one catalogue material ({}) or remove the key",
                            catalogue::names().join(", ")
                        ),
                    ));
                }
                for item in list.get_ref() {
                    let m = self.material("design.materials", item, false)?;
                    if study.materials.iter().any(|n| n == m.name) {
                        return Err(self.invalid(
                            "design.materials",
                            &item.span(),
                            format!("{} is listed twice", m.name),
                        ));
                    }
                    study.materials.push(m.name.to_string());
                }
            }
        }

        // [objective]
        if let Some(objective) = &raw.objective {
            let minimize = self.required(
                &objective.get_ref().minimize,
                "objective.minimize",
                Some(&objective.span()),
                &format!(
                    "what to make small, one of: {}",
                    Objective::names().join(", ")
                ),
            )?;
            let o: Objective = self.named("objective.minimize", minimize)?;
            if matches!(o, Objective::FrictionForce | Objective::FrictionCoefficient)
                && scene.requirements.shear_strength.is_none()
            {
                return Err(self.invalid(
                    "objective.minimize",
                    &minimize.span(),
                    format!("{} needs interface.shear_strength (τ of the junctions), e.g. shear_strength = \"100 MPa\"", o.as_str()),
                ));
            }
            study.objective = Some(o);
            if !study.has_design() {
                return Err(self.invalid(
                    "objective.minimize",
                    &minimize.span(),
                    "nothing to optimise: add a [design] table with at least one variable, e.g. sigma = { min = \"1 nm\", max = \"20 nm\" }",
                ));
            }
        }

        // [[constraint]]
        for (index, constraint) in raw.constraint.iter().enumerate() {
            let rc = constraint.get_ref();
            if robust::is_chance(rc) {
                // A chance constraint: read with [uncertainty] (robust.rs).
                for (key, given) in [
                    ("quantity", rc.quantity.as_ref().map(|v| v.span())),
                    ("min", rc.min.as_ref().map(|v| v.span())),
                    ("max", rc.max.as_ref().map(|v| v.span())),
                ] {
                    if let Some(span) = given {
                        return Err(self.invalid(
                            &format!("constraint[{index}].{key}"),
                            &span,
                            "a chance constraint bounds the probability of its event (event = …, probability_max = …); a limit on a quantity goes in a [[constraint]] of its own, or in the event: event = { quantity = \"wear_rate\", above = \"50 um^3/m\" }",
                        ));
                    }
                }
                continue;
            }
            if let Some(p) = &rc.probability_max {
                return Err(self.invalid(
                    &format!("constraint[{index}].probability_max"),
                    &p.span(),
                    "bounds the probability of an event: give event = \"stiction\" (or wear_out, or { quantity = …, above = … }) beside it",
                ));
            }
            let c = self.constraint(index, constraint)?;
            let needs = match c.quantity {
                ConstraintQuantity::ReleaseMargin => (scene.load >= 0.0)
                    .then_some("a tensile load (contact.load < 0): it measures how far a pulled contact is from snapping apart"),
                ConstraintQuantity::StictionMargin => scene
                    .requirements
                    .restoring_force
                    .is_none()
                    .then_some("contact.restoring_force (the force that must free the part), e.g. restoring_force = \"5 uN\""),
                ConstraintQuantity::FrictionForce | ConstraintQuantity::FrictionCoefficient => scene
                    .requirements
                    .shear_strength
                    .is_none()
                    .then_some("interface.shear_strength (τ of the junctions), e.g. shear_strength = \"100 MPa\""),
                _ => None,
            };
            if let Some(what) = needs {
                return Err(self.invalid(
                    &format!("constraint[{index}].quantity"),
                    &constraint.span(),
                    format!("{} needs {what}", c.quantity.as_str()),
                ));
            }
            study.constraints.push(c);
        }
        // A tensile study keeps a margin to its pull-off unless it sets its own.
        if scene.load < 0.0
            && study.has_design()
            && !study
                .constraints
                .iter()
                .any(|c| c.quantity == ConstraintQuantity::ReleaseMargin)
        {
            study.constraints.push(Constraint {
                quantity: ConstraintQuantity::ReleaseMargin,
                min: Some(DEFAULT_RELEASE_MARGIN),
                max: None,
                only_at_objective_humidity: false,
            });
        }

        // [pareto]
        // A probability front (`event = …`) is read with the robust keys.
        if let Some(pareto) = raw.pareto.as_ref().filter(|p| p.get_ref().event.is_none()) {
            let p = pareto.get_ref();
            for (key, value) in [
                ("pareto.probability_max", &p.probability_max),
                ("pareto.probability_min", &p.probability_min),
            ] {
                if let Some(v) = value {
                    return Err(self.invalid(
                        key,
                        &v.span(),
                        "bounds the levels of a probability front: give event = \"stiction\" (or another event) beside it, or remove it",
                    ));
                }
            }
            let adhesion_raw = self.required(
                &p.adhesion,
                "pareto.adhesion",
                Some(&pareto.span()),
                &format!(
                    "the adhesion measure of the front, one of: {}",
                    AdhesionMeasure::names().join(", ")
                ),
            )?;
            let adhesion: AdhesionMeasure = self.named("pareto.adhesion", adhesion_raw)?;
            let points = match &p.points {
                None => ParetoSpec::DEFAULT_POINTS,
                Some(v) => self.integer(
                    "pareto.points",
                    v,
                    ParetoSpec::MIN_POINTS as i64,
                    ParetoSpec::MAX_POINTS as i64,
                    "points on the Pareto front",
                )? as usize,
            };
            let direction = match &p.direction {
                None => ParetoDirection::Low,
                Some(v) => self.named("pareto.direction", v)?,
            };
            if !study.has_design() {
                return Err(self.invalid(
                    "pareto.adhesion",
                    &adhesion_raw.span(),
                    "a front needs something to vary: add a [design] table with at least one variable",
                ));
            }
            if adhesion == AdhesionMeasure::WorkOfAdhesion
                && !study
                    .design
                    .iter()
                    .any(|v| v.name == SceneParameter::WorkOfAdhesion)
            {
                return Err(self.invalid(
                    "pareto.adhesion",
                    &adhesion_raw.span(),
                    format!(
                        "trading against work_of_adhesion needs it among the design variables: add work_of_adhesion = {} to [design]",
                        SceneParameter::WorkOfAdhesion.example_bounds()
                    ),
                ));
            }
            study.pareto = Some(ParetoSpec {
                adhesion,
                points,
                direction,
            });
        }

        // [optimizer]
        if let Some(optimizer) = &raw.optimizer {
            study.optimizer = self.optimizer(optimizer)?;
        }
        Ok(study)
    }

    fn design_variable(
        &self,
        q: SceneParameter,
        bound: &Spanned<RawBound>,
        scene: &Scene,
    ) -> Result<DesignVariable, ProblemError> {
        let key = format!("design.{}", q.as_str());
        let example = format!(
            "a design variable needs both bounds, e.g. {} = {}",
            q.as_str(),
            q.example_bounds()
        );
        let b = bound.get_ref();
        let accept = design_accept(q);
        let min_raw =
            self.required(&b.min, &format!("{key}.min"), Some(&bound.span()), &example)?;
        let max_raw =
            self.required(&b.max, &format!("{key}.max"), Some(&bound.span()), &example)?;
        let min = self.quantity(&format!("{key}.min"), min_raw, accept)?;
        let max = self.quantity(&format!("{key}.max"), max_raw, accept)?;
        let dim = q.dimension();
        if min >= max {
            return Err(self.invalid(
                &key,
                &bound.span(),
                format!(
                    "min must be < max (min is {}, max is {})",
                    format_quantity(min, dim),
                    format_quantity(max, dim)
                ),
            ));
        }
        // The same limit as the scene's own temperature: a design the study
        // reaches must be one `eval` accepts (700 K was once "optimal").
        let critical = crate::model::capillary::WATER_CRITICAL_TEMPERATURE;
        if q == SceneParameter::Temperature
            && scene.environment.is_some_and(|e| e.liquid == Liquid::Water)
            && max >= critical
        {
            return Err(self.invalid(
                &format!("{key}.max"),
                &bound.span(),
                format!(
                    "is {}: must be below water's critical point, 647.096 K (no liquid water above it); accepted: 0 K < min < max < 647.096 K",
                    format_quantity(max, dim)
                ),
            ));
        }
        let value = q.get(scene);
        if !(min..=max).contains(&value) {
            return Err(self.invalid(
                &key,
                &bound.span(),
                format!(
                    "[{}, {}] does not contain the scene's {} = {}; widen the range or change {}",
                    format_quantity(min, dim),
                    format_quantity(max, dim),
                    q.scene_key(),
                    format_quantity(value, dim),
                    q.scene_key()
                ),
            ));
        }
        Ok(DesignVariable { name: q, min, max })
    }

    fn constraint(
        &self,
        index: usize,
        constraint: &Spanned<raw::RawConstraint>,
    ) -> Result<Constraint, ProblemError> {
        let prefix = format!("constraint[{index}]");
        let c = constraint.get_ref();
        let span = constraint.span();
        let quantity_raw = self.required(
            &c.quantity,
            &format!("{prefix}.quantity"),
            Some(&span),
            &format!(
                "what to bound, one of: {} (or, for a chance constraint, event = \"stiction\" with probability_max = 1e-3)",
                ConstraintQuantity::names().join(", ")
            ),
        )?;
        let quantity: ConstraintQuantity =
            self.named(&format!("{prefix}.quantity"), quantity_raw)?;
        let (lo, hi) = quantity.natural_range();
        let mut accept = Accept::interval(quantity.dimension(), lo, false, hi, false);
        if !lo.is_finite() && !hi.is_finite() {
            accept = Accept::any(quantity.dimension());
        } else if !hi.is_finite() {
            accept = Accept::non_negative(quantity.dimension());
        }
        let min = self.optional_quantity(&format!("{prefix}.min"), &c.min, accept)?;
        let max = self.optional_quantity(&format!("{prefix}.max"), &c.max, accept)?;
        if min.is_none() && max.is_none() {
            return Err(self.missing(
                &format!("{prefix}.min/max"),
                Some(&span),
                &format!(
                    "a constraint on {} needs min, max or both ({})",
                    quantity.as_str(),
                    match quantity.dimension() {
                        Dimension::Dimensionless => "plain numbers".to_string(),
                        d => format!("each {}", d.with_article()),
                    }
                ),
            ));
        }
        if let (Some(lo), Some(hi), Some(min_raw)) = (min, max, &c.min) {
            if lo >= hi {
                let dim = quantity.dimension();
                return Err(self.invalid(
                    &format!("{prefix}.min"),
                    &min_raw.span(),
                    format!(
                        "min must be < max for {} (min is {}, max is {})",
                        quantity.as_str(),
                        format_quantity(lo, dim),
                        format_quantity(hi, dim)
                    ),
                ));
            }
        }
        Ok(Constraint {
            quantity,
            min,
            max,
            only_at_objective_humidity: false,
        })
    }

    fn optimizer(
        &self,
        optimizer: &Spanned<raw::RawOptimizer>,
    ) -> Result<OptimizerSettings, ProblemError> {
        let o = optimizer.get_ref();
        let mut settings = OptimizerSettings::default();
        if let Some(v) = &o.starts {
            let (lo, hi) = OptimizerSettings::STARTS;
            settings.starts = self.integer(
                "optimizer.starts",
                v,
                lo as i64,
                hi as i64,
                "starting points",
            )? as usize;
        }
        if let Some(v) = &o.seed {
            settings.seed = self.integer(
                "optimizer.seed",
                v,
                0,
                i64::MAX,
                "seed of the random starts",
            )? as u64;
        }
        if let Some(v) = &o.tolerance {
            settings.tolerance = self.quantity(
                "optimizer.tolerance",
                v,
                Accept::interval(Dimension::Dimensionless, 0.0, true, 1.0, true)
                    .why("relative tolerance, e.g. 1e-8"),
            )?;
        }
        if let Some(v) = &o.max_iterations {
            let (lo, hi) = OptimizerSettings::MAX_ITERATIONS;
            settings.max_iterations = self.integer(
                "optimizer.max_iterations",
                v,
                lo as i64,
                hi as i64,
                "iterations per start",
            )? as usize;
        }
        if let Some(v) = &o.time_limit {
            let seconds = self.quantity(
                "optimizer.time_limit",
                v,
                Accept::non_negative(Dimension::Time)
                    .why("wall-clock limit, e.g. \"30 s\" (0: evaluate the starts only)"),
            )?;
            settings.time_limit = Duration::try_from_secs_f64(seconds).map_err(|_| {
                self.invalid(
                    "optimizer.time_limit",
                    &v.span(),
                    "too large for a time limit",
                )
            })?;
        }
        settings.validate().map_err(|e| {
            let span = match e.field {
                "starts" => o.starts.as_ref().map(|v| v.span()),
                "tolerance" => o.tolerance.as_ref().map(|v| v.span()),
                "max_iterations" => o.max_iterations.as_ref().map(|v| v.span()),
                "time_limit" => o.time_limit.as_ref().map(|v| v.span()),
                _ => None,
            }
            .unwrap_or_else(|| optimizer.span());
            self.invalid(&format!("optimizer.{}", e.field), &span, e.expected)
        })?;
        Ok(settings)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = r#"
[contact]
load = "10 uN"
nominal_area = "1000 um^2"
sliding_distance = "1 m"
wear_coefficient = 1e-4

[bodies]
a = { material = "polysilicon" }
b = { material = "polysilicon" }

[interface]
work_of_adhesion = "0.1 J/m^2"

[roughness]
sigma = "5 nm"
asperity_radius = "1 um"
asperity_density = "10 um^-2"
"#;

    fn err(text: &str) -> String {
        parse(text, "t.toml").unwrap_err().to_string()
    }

    #[test]
    fn minimal_scene() {
        let p = parse(MINIMAL, "problems/min.toml").unwrap();
        assert_eq!(p.name, "min");
        assert_eq!(p.scene.load, 10e-6);
        assert_eq!(p.scene.hardness, 10e9);
        assert_eq!(p.scene.wear_area, WearArea::Total);
        assert_eq!(p.scene.interatomic_distance, DEFAULT_INTERATOMIC_DISTANCE);
        assert!(p.notes.contains(&InputNote::HardnessFromCatalogue {
            material: "polysilicon",
            hardness: 10e9,
            body: BodyKey::A,
        }));
        assert_eq!(p.study, Study::default());
    }

    #[test]
    fn accept_messages() {
        let a = Accept::positive(Dimension::Length);
        assert_eq!(
            a.check(-5e-9).unwrap_err(),
            "must be > 0 m (a positive length)"
        );
        let nu = Accept::interval(Dimension::Dimensionless, -1.0, true, 0.5, false);
        assert_eq!(nu.check(0.6).unwrap_err(), "must be in (-1, 0.5]");
        assert!(nu.check(0.5).is_ok());
        let e = Accept::positive(Dimension::Pressure).or_inf("a rigid counterface");
        assert!(e.check(f64::INFINITY).is_ok());
        assert!(Accept::positive(Dimension::Pressure)
            .check(f64::INFINITY)
            .unwrap_err()
            .contains("infinity is not allowed"));
    }

    #[test]
    fn serde_errors_get_dotted_keys() {
        let text = MINIMAL.replace("load =", "lod =");
        let msg = err(&text);
        assert!(
            msg.starts_with("t.toml:3: unknown key `contact.lod`; did you mean `load`?"),
            "{msg}"
        );
        let text = MINIMAL.replace(
            "{ material = \"polysilicon\" }\nb",
            "{ materal = \"polysilicon\" }\nb",
        );
        let msg = err(&text);
        assert!(
            msg.contains("t.toml:9: unknown key `bodies.a.materal`; did you mean `material`?"),
            "{msg}"
        );
        let text = MINIMAL.replace("wear_coefficient = 1e-4", "wear_coefficient = true");
        let msg = err(&text);
        assert!(
            msg.starts_with("t.toml:6: contact.wear_coefficient = true: wrong type"),
            "{msg}"
        );
    }
}
