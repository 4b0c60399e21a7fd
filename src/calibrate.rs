//! Calibration of the work of adhesion γ from friction measurements (docs/model.md §5, the
//! paper's eq. 14).
//!
//! A sphere of radius R slides on a flat under loads P_i and the friction F_i is
//! measured. With JKR adhesion and a friction force proportional to the apparent Hertz
//! load P₁ (the load that would give the JKR contact area without adhesion),
//!
//! ```text
//! F = μ P₁,   P₁ = P + 3πγR + √(6πγRP + (3πγR)²)
//! ```
//!
//! # What is computed
//!
//! * **Per point, exactly.** Writing a = 3πγR and s = F/μ − P, eq. 14 squared gives
//!   (s − a)² = 2aP + a², i.e. a = s² / (2F/μ): one linear equation, so
//!
//!   ```text
//!   γ_i = (F_i − μP_i)² / (6πR μ F_i)
//!   ```
//!
//!   and the root is a root of eq. 14 (not only of its square) exactly when s ≥ 0,
//!   i.e. F ≥ μP. Below that no γ ≥ 0 gives the measured friction.
//! * **A least-squares fit** of γ (and μ with [`FrictionCoefficient::Fit`]) to the
//!   friction values, minimising Σ (F_i − F(P_i; γ, μ))² (equal, unknown variance per
//!   point). The parameters are searched as ln γ and ln μ, so both stay positive: a
//!   1-D scan of γ over 16 decades (with μ eliminated in closed form when it is fitted,
//!   F being linear in μ) gives the start, then argmin's Gauss–Newton method polishes
//!   it. The Jacobian type is a small dense matrix of this module that implements
//!   argmin-math's traits.
//! * **Uncertainty.** With n points and p parameters, s² = SSR/(n − p) and the
//!   covariance s² (JᵀJ)⁻¹ with J the Jacobian in (γ, μ) at the fit; the 95 %
//!   interval is estimate ± t(0.975, n − p) · standard error with the Student t
//!   quantile computed from the inverse regularised incomplete beta function. γ ≥ 0,
//!   so a lower limit below 0 is clipped to 0 (and flagged). With n = p the fit is
//!   exact and no interval exists.
//! * **Contact radius and bond strength** when the equivalent modulus E is known:
//!   r³ = R P₁ / K with K = 4E/3 and P₁ from the fitted γ, and the interfacial shear
//!   (bond) strength τ_i = F_i / (π r_i²).
//! * **Comparison with a quoted value** (a paper's γ or bond strength): whether it lies
//!   in the 95 % interval (γ) or within the per-point range (τ), the friction it would
//!   predict at the measured loads, and the bond strength it would imply.
//!
//! Units are SI throughout: N, m, N/m (= J/m²), Pa.

use std::f64::consts::PI;
use std::path::Path;

use argmin::core::{Executor, Jacobian, Operator, State, TerminationReason};
use argmin::solver::gaussnewton::GaussNewton;
use serde::Serialize;

use crate::problem::catalogue::{self, Material};
use crate::units::{format_quantity, parse_quantity, Dimension};

/// Confidence level of the reported intervals.
pub const CONFIDENCE_LEVEL: f64 = 0.95;

/// μ when the user gives neither a value nor asks for a fit: the paper's 0.1
/// (docs/model.md §5). Reports say that it was assumed.
pub const DEFAULT_FRICTION_COEFFICIENT: f64 = 0.1;

/// The friction table of docs/model.md §5 (the paper's eq. 14 data, read from a plot):
/// steel ball R = 0.3 mm on silicon, μ = 0.1. Loads and friction in N.
pub const ANDO_TABLE: [(f64, f64); 4] = [
    (20e-6, 6e-6),
    (110e-6, 14e-6),
    (140e-6, 18e-6),
    (220e-6, 26e-6),
];
/// Ball radius of the paper's experiment (m).
pub const ANDO_RADIUS: f64 = 0.3e-3;
/// γ the paper quotes from its table (N/m).
pub const ANDO_QUOTED_WORK_OF_ADHESION: f64 = 0.1;
/// Bond strength F/(πr²) the paper quotes from its table (Pa).
pub const ANDO_QUOTED_BOND_STRENGTH: f64 = 65e6;

/// Bad calibration input. Every message names the file (and line) and the value.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CalibrationError {
    /// The data file could not be read.
    #[error("{path}: cannot read the data file: {message}")]
    Io {
        /// The file.
        path: String,
        /// The system's message.
        message: String,
    },
    /// The file has no header line.
    #[error("{origin}: empty data file; expected the header `load,friction` and one row per measurement, e.g. `20 uN,6 uN`")]
    Empty {
        /// The file.
        origin: String,
    },
    /// The header is not `load,friction`.
    #[error("{origin}:{line}: header {found:?}: expected `load,friction` (one row per measurement, numbers in newtons or strings such as \"20 uN\")")]
    Header {
        /// The file.
        origin: String,
        /// 1-based line.
        line: usize,
        /// The header as written.
        found: String,
    },
    /// A row that is not two comma-separated fields.
    #[error("{origin}:{line}: {found:?}: expected two comma-separated values, load and friction (e.g. `20 uN,6 uN`)")]
    Row {
        /// The file.
        origin: String,
        /// 1-based line.
        line: usize,
        /// The row as written.
        found: String,
    },
    /// A value that is not a force.
    #[error("{origin}:{line}: {column} = {value:?}: {message}")]
    Value {
        /// The file.
        origin: String,
        /// 1-based line.
        line: usize,
        /// `load` or `friction`.
        column: &'static str,
        /// The value as written.
        value: String,
        /// Why it was refused.
        message: String,
    },
    /// Fewer measurements than parameters (or too few distinct loads).
    #[error("{origin}: {found}; fitting {parameters} needs at least {needed}")]
    TooFewPoints {
        /// The file.
        origin: String,
        /// What the file has, in words.
        found: String,
        /// What is fitted, in words.
        parameters: String,
        /// What is needed, in words.
        needed: String,
    },
    /// Fitting γ and μ to friction that falls as the load rises: eq. 14's F grows
    /// with P for every μ > 0 and γ ≥ 0, so no pair explains the trend.
    #[error("{origin}: the friction falls as the load rises (least-squares slope dF/dP = {slope:.3}); eq. 14 gives a friction that grows with the load for every μ > 0 and γ ≥ 0, so γ and μ cannot both be fitted: check the columns (load first, then friction) and units, or fix μ with --mu")]
    FrictionFalls {
        /// The file.
        origin: String,
        /// The least-squares slope of friction against load.
        slope: f64,
    },
    /// A friction below μP: no γ ≥ 0 can give it at the stated μ.
    #[error("{origin}:{line}: friction = {friction} at load = {load}: below μP = {floor} (μ = {mu}); eq. 14 gives F ≥ μP for every γ ≥ 0, so no work of adhesion explains this point: check the row, give a smaller --mu, or use --fit-mu")]
    FrictionBelowFloor {
        /// The file.
        origin: String,
        /// 1-based line.
        line: usize,
        /// The load as formatted.
        load: String,
        /// The friction as formatted.
        friction: String,
        /// μP as formatted.
        floor: String,
        /// μ.
        mu: f64,
    },
    /// A wear-rate file (`fit-wear`) whose header is not `stress_Pa,RATE[,temperature_K]`.
    #[error("{origin}:{line}: header {found:?}: expected `stress_Pa,` then the rate column named by its unit, `rate_atoms_per_s`, `rate_m3_per_s` or `rate_m3_per_m`, then optionally `temperature_K` (one row per measurement)")]
    WearHeader {
        /// The file.
        origin: String,
        /// 1-based line (0: the file is empty).
        line: usize,
        /// The header as written.
        found: String,
    },
    /// A wear-rate row with another number of values than its header.
    #[error("{origin}:{line}: {found:?} has {values} values: expected {expected} (the header's columns)")]
    WearRow {
        /// The file.
        origin: String,
        /// 1-based line.
        line: usize,
        /// The row as written.
        found: String,
        /// How many values it has.
        values: usize,
        /// The header's columns, comma-separated.
        expected: String,
    },
    /// A setting (radius, μ, modulus, quoted value, material) out of range.
    #[error("{name} {value}: {expected}")]
    Setting {
        /// The option, by its keyword name (`quoted_gamma`; the command line
        /// spells it as the flag `--quoted-gamma`).
        name: &'static str,
        /// The value given.
        value: String,
        /// What is accepted.
        expected: String,
    },
}

/// One friction measurement.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Measurement {
    /// Normal load P (N), ≥ 0.
    pub load: f64,
    /// Friction force F (N), > 0.
    pub friction: f64,
    /// 1-based line in the data file (0 when not read from a file).
    pub line: usize,
}

/// Friction measurements and where they came from.
#[derive(Debug, Clone, PartialEq)]
pub struct FrictionData {
    /// The file name, for messages.
    pub origin: String,
    /// The measurements, in file order.
    pub points: Vec<Measurement>,
}

impl FrictionData {
    /// Measurements given directly (no file): `(load, friction)` in N.
    pub fn from_pairs(origin: &str, pairs: &[(f64, f64)]) -> Result<Self, CalibrationError> {
        let data = FrictionData {
            origin: origin.to_string(),
            points: pairs
                .iter()
                .enumerate()
                .map(|(i, &(load, friction))| Measurement {
                    load,
                    friction,
                    line: i + 1,
                })
                .collect(),
        };
        for p in &data.points {
            check_point(&data.origin, p.line, p.load, p.friction, None)?;
        }
        Ok(data)
    }

    /// Whether these are the paper's measurements of docs/model.md §5 (to 1e-9 relative).
    pub fn is_ando_table(&self) -> bool {
        self.points.len() == ANDO_TABLE.len()
            && self
                .points
                .iter()
                .zip(ANDO_TABLE)
                .all(|(p, (l, f))| close(p.load, l) && close(p.friction, f))
    }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * b.abs()
}

fn check_point(
    origin: &str,
    line: usize,
    load: f64,
    friction: f64,
    text: Option<(&str, &str)>,
) -> Result<(), CalibrationError> {
    let value_err =
        |column, value: f64, written: Option<&str>, message: &str| CalibrationError::Value {
            origin: origin.to_string(),
            line,
            column,
            value: written.map_or_else(|| value.to_string(), str::to_string),
            message: message.to_string(),
        };
    if !load.is_finite() || load < 0.0 {
        return Err(value_err(
            "load",
            load,
            text.map(|t| t.0),
            "the load must be a finite compressive force ≥ 0 (eq. 14 is the JKR friction law under a pressing load)",
        ));
    }
    if !friction.is_finite() || friction <= 0.0 {
        return Err(value_err(
            "friction",
            friction,
            text.map(|t| t.1),
            "the friction must be a finite force > 0",
        ));
    }
    Ok(())
}

/// Reads a data file: see [`parse_csv`].
pub fn read_csv(path: &Path) -> Result<FrictionData, CalibrationError> {
    let text = std::fs::read_to_string(path).map_err(|e| CalibrationError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })?;
    parse_csv(&text, &path.display().to_string())
}

/// Parses friction data: a header `load,friction`, then one row per measurement, each
/// value a number in newtons or a string with a unit (`20 uN`, `"0.02 mN"`). Blank
/// lines and lines starting with `#` are skipped. Loads must be ≥ 0, friction > 0.
pub fn parse_csv(text: &str, origin: &str) -> Result<FrictionData, CalibrationError> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (hline, header) = lines.next().ok_or_else(|| CalibrationError::Empty {
        origin: origin.to_string(),
    })?;
    let names: Vec<String> = header
        .trim_start_matches('\u{feff}')
        .split(',')
        .map(|f| unquote(f).to_ascii_lowercase())
        .collect();
    if names != ["load", "friction"] {
        return Err(CalibrationError::Header {
            origin: origin.to_string(),
            line: hline,
            found: header.to_string(),
        });
    }
    let mut points = Vec::new();
    for (line, row) in lines {
        let fields: Vec<&str> = row.split(',').map(unquote).collect();
        if fields.len() != 2 {
            return Err(CalibrationError::Row {
                origin: origin.to_string(),
                line,
                found: row.to_string(),
            });
        }
        let value = |column: &'static str, field: &str| {
            parse_quantity(field, Dimension::Force).map_err(|e| CalibrationError::Value {
                origin: origin.to_string(),
                line,
                column,
                value: field.to_string(),
                message: e.to_string(),
            })
        };
        let load = value("load", fields[0])?;
        let friction = value("friction", fields[1])?;
        check_point(origin, line, load, friction, Some((fields[0], fields[1])))?;
        points.push(Measurement {
            load,
            friction,
            line,
        });
    }
    Ok(FrictionData {
        origin: origin.to_string(),
        points,
    })
}

fn unquote(field: &str) -> &str {
    let f = field.trim();
    f.strip_prefix('"')
        .and_then(|g| g.strip_suffix('"'))
        .unwrap_or(f)
        .trim()
}

/// How μ is treated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FrictionCoefficient {
    /// μ held at a value given by the user.
    Given(f64),
    /// μ held at [`DEFAULT_FRICTION_COEFFICIENT`] because nothing was said.
    Default,
    /// μ fitted together with γ.
    Fit,
}

/// A value someone quoted from these data, to compare the fit with.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Quoted {
    /// Who quoted it.
    pub source: String,
    /// The quoted work of adhesion (N/m).
    pub work_of_adhesion: Option<f64>,
    /// The quoted bond strength F/(πr²) (Pa).
    pub bond_strength: Option<f64>,
}

impl Quoted {
    /// The paper's claims about the docs/model.md §5 table: γ ≈ 0.1 N/m, 65 MPa.
    pub fn paper() -> Self {
        Quoted {
            source: "the paper (docs/model.md §5)".into(),
            work_of_adhesion: Some(ANDO_QUOTED_WORK_OF_ADHESION),
            bond_strength: Some(ANDO_QUOTED_BOND_STRENGTH),
        }
    }
}

/// The settings of a fit.
#[derive(Debug, Clone, PartialEq)]
pub struct FitSettings {
    /// R, radius of the sphere (m), > 0.
    pub radius: f64,
    /// How μ is treated.
    pub friction_coefficient: FrictionCoefficient,
    /// E, the equivalent modulus [(1−ν1²)/E1 + (1−ν2²)/E2]⁻¹ (Pa), for the contact
    /// radius and the bond strength; None: not computed.
    pub equivalent_modulus: Option<f64>,
    /// Values to compare the fit with.
    pub quoted: Option<Quoted>,
}

impl FitSettings {
    /// Checks each setting against its accepted range.
    pub fn validate(&self) -> Result<(), CalibrationError> {
        if !(self.radius.is_finite() && self.radius > 0.0) {
            return Err(CalibrationError::Setting {
                name: "radius",
                value: self.radius.to_string(),
                expected: "must be a finite length > 0, e.g. \"0.3 mm\"".into(),
            });
        }
        if let FrictionCoefficient::Given(mu) = self.friction_coefficient {
            if !(mu.is_finite() && mu > 0.0) {
                return Err(CalibrationError::Setting {
                    name: "mu",
                    value: mu.to_string(),
                    expected: "must be a finite number > 0, e.g. 0.1".into(),
                });
            }
        }
        if let Some(e) = self.equivalent_modulus {
            if !(e.is_finite() && e > 0.0) {
                return Err(CalibrationError::Setting {
                    name: "modulus",
                    value: e.to_string(),
                    expected: "must be a finite pressure > 0, e.g. \"100 GPa\"".into(),
                });
            }
        }
        if let Some(q) = &self.quoted {
            for (name, v) in [
                ("quoted_gamma", q.work_of_adhesion),
                ("quoted_bond_strength", q.bond_strength),
            ] {
                if let Some(v) = v {
                    if !(v.is_finite() && v > 0.0) {
                        return Err(CalibrationError::Setting {
                            name,
                            value: v.to_string(),
                            expected: "must be finite and > 0".into(),
                        });
                    }
                }
            }
        }
        Ok(())
    }

    /// μ held fixed, if it is.
    pub fn fixed_mu(&self) -> Option<f64> {
        match self.friction_coefficient {
            FrictionCoefficient::Given(mu) => Some(mu),
            FrictionCoefficient::Default => Some(DEFAULT_FRICTION_COEFFICIENT),
            FrictionCoefficient::Fit => None,
        }
    }
}

/// E = [(1−ν1²)/E1 + (1−ν2²)/E2]⁻¹ of two catalogue materials (docs/model.md §1).
pub fn equivalent_modulus(a: &Material, b: &Material) -> f64 {
    1.0 / ((1.0 - a.poisson_ratio.powi(2)) / a.youngs_modulus
        + (1.0 - b.poisson_ratio.powi(2)) / b.youngs_modulus)
}

/// Looks up catalogue materials by name, with a suggestion for a typo.
pub fn lookup_materials(names: &[String]) -> Result<Vec<&'static Material>, CalibrationError> {
    if names.is_empty() || names.len() > 2 {
        return Err(CalibrationError::Setting {
            name: "materials",
            value: names.join(","),
            expected:
                "give one material (both bodies) or two, ball first: e.g. --materials steel,silicon"
                    .into(),
        });
    }
    names
        .iter()
        .map(|n| {
            catalogue::lookup(n).ok_or_else(|| CalibrationError::Setting {
                name: "materials",
                value: n.clone(),
                expected: format!(
                    "not in the catalogue{} (one of: {})",
                    catalogue::suggest(n)
                        .map(|s| format!("; did you mean \"{s}\"?"))
                        .unwrap_or_default(),
                    catalogue::names().join(", ")
                ),
            })
        })
        .collect()
}

/// a = 3πγR, the adhesive load term of eq. 14 (N).
fn adhesive_load(gamma: f64, radius: f64) -> f64 {
    3.0 * PI * gamma * radius
}

/// P₁ = P + 3πγR + √(6πγRP + (3πγR)²), the apparent Hertz load of a JKR contact (N).
pub fn apparent_hertz_load(load: f64, gamma: f64, radius: f64) -> f64 {
    let a = adhesive_load(gamma, radius);
    load + a + (a * (2.0 * load + a)).sqrt()
}

/// Eq. 14: F = μ P₁ (N).
pub fn jkr_friction(load: f64, gamma: f64, mu: f64, radius: f64) -> f64 {
    mu * apparent_hertz_load(load, gamma, radius)
}

/// dP₁/dγ = 3πR (1 + (P + a)/√(2aP + a²)), a = 3πγR > 0 (m).
fn dhertz_dgamma(load: f64, gamma: f64, radius: f64) -> f64 {
    let a = adhesive_load(gamma, radius);
    3.0 * PI * radius * (1.0 + (load + a) / (a * (2.0 * load + a)).sqrt())
}

/// γ from one point, exactly: (F − μP)² / (6πRμF). None when F < μP (no γ ≥ 0 gives
/// that friction) or F ≤ 0.
pub fn work_of_adhesion_from_point(load: f64, friction: f64, mu: f64, radius: f64) -> Option<f64> {
    let excess = friction - mu * load;
    (excess >= 0.0 && friction > 0.0).then(|| excess * excess / (6.0 * PI * radius * mu * friction))
}

/// Two-sided Student t quantile: the t with P(|T| ≤ t) = `level` for `dof` degrees of
/// freedom, from P(|T| > t) = I_{ν/(ν+t²)}(ν/2, 1/2).
pub fn student_t_quantile(level: f64, dof: usize) -> f64 {
    let nu = dof as f64;
    let x = puruspe::invbetai(1.0 - level, nu / 2.0, 0.5);
    (nu * (1.0 - x) / x).sqrt()
}

/// One measurement and what the fit says about it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PointFit {
    /// Line in the data file.
    pub line: usize,
    /// P (N).
    pub load: f64,
    /// F measured (N).
    pub friction: f64,
    /// F of eq. 14 at the fitted γ, μ (N).
    pub fitted_friction: f64,
    /// F measured − F fitted (N).
    pub residual: f64,
    /// γ from this point alone at the fit's μ (N/m); None when F < μP.
    pub work_of_adhesion: Option<f64>,
    /// P₁ at the fitted γ (N).
    pub apparent_hertz_load: f64,
    /// r = (R P₁ / K)^{1/3} (m), when E is known.
    pub contact_radius: Option<f64>,
    /// F / (π r²) (Pa), when E is known.
    pub bond_strength: Option<f64>,
    /// Why `work_of_adhesion` is missing, if it is.
    pub note: Option<PointNote>,
}

/// Why one measurement gives no work of adhesion of its own.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum PointNote {
    /// F < μP: the friction is below the adhesion-free friction, so no γ ≥ 0 gives it.
    FrictionBelowSliding {
        /// μP (N), the friction without adhesion.
        sliding_friction: f64,
        /// The μ of the fit.
        friction_coefficient: f64,
    },
}

/// The comparison of a quoted γ with the data.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QuotedGamma {
    /// The quoted value (N/m).
    pub quoted: f64,
    /// quoted / fitted.
    pub ratio_to_fit: f64,
    /// Whether it lies in the 95 % interval (None when there is none).
    pub within_confidence_interval: Option<bool>,
    /// Whether it lies within the per-point range of γ.
    pub within_per_point_range: bool,
    /// Friction eq. 14 predicts with the quoted γ and the fit's μ at each load (N).
    pub predicted_friction: Vec<f64>,
    /// Mean bond strength the quoted γ would imply (Pa), when E is known.
    pub implied_bond_strength: Option<f64>,
    /// Whether the data support it: inside the interval (or, with no interval, inside
    /// the per-point range).
    pub agrees: bool,
}

/// The comparison of a quoted bond strength with the data.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QuotedBond {
    /// The quoted value (Pa).
    pub quoted: f64,
    /// The data's mean F/(πr²) (Pa).
    pub from_data: f64,
    /// quoted / from_data.
    pub ratio: f64,
    /// Whether it lies within the per-point range of F/(πr²).
    pub agrees: bool,
}

/// Every comparison with quoted values.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    /// Who quoted.
    pub source: String,
    /// The γ comparison.
    pub work_of_adhesion: Option<QuotedGamma>,
    /// The bond-strength comparison (needs E).
    pub bond_strength: Option<QuotedBond>,
    /// A quoted bond strength that could not be checked for want of E.
    pub bond_strength_unchecked: Option<f64>,
}

/// The result of a calibration.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Calibration {
    /// The data file.
    pub origin: String,
    /// R (m).
    pub radius: f64,
    /// γ, the least-squares estimate (N/m).
    pub work_of_adhesion: f64,
    /// Its standard error (N/m); None when n = p.
    pub standard_error: Option<f64>,
    /// Its 95 % interval (N/m), lower end clipped at 0; None when n = p.
    pub confidence_interval: Option<[f64; 2]>,
    /// Whether the lower end was clipped at 0.
    pub confidence_interval_clipped: bool,
    /// μ (fitted or held).
    pub friction_coefficient: f64,
    /// How μ was treated.
    pub friction_coefficient_source: FrictionCoefficient,
    /// Standard error of μ when fitted.
    pub friction_coefficient_standard_error: Option<f64>,
    /// 95 % interval of μ when fitted, lower end clipped at 0 (μ ≥ 0).
    pub friction_coefficient_confidence_interval: Option<[f64; 2]>,
    /// Whether that lower end was clipped at 0.
    pub friction_coefficient_interval_clipped: bool,
    /// Correlation of the γ and μ estimates when both are fitted.
    pub correlation: Option<f64>,
    /// n − p.
    pub degrees_of_freedom: usize,
    /// t(0.975, n − p) used for the intervals (None when n = p).
    pub t_quantile: Option<f64>,
    /// √(SSR/(n − p)) (N); None when n = p.
    pub residual_standard_deviation: Option<f64>,
    /// Σ residual² (N²).
    pub sum_of_squares: f64,
    /// Per point, in file order.
    pub per_point: Vec<PointFit>,
    /// Smallest and largest per-point γ (N/m), over points that have one.
    pub per_point_range: Option<[f64; 2]>,
    /// E used for contact radii (Pa).
    pub equivalent_modulus: Option<f64>,
    /// Mean F/(πr²) over the points (Pa).
    pub mean_bond_strength: Option<f64>,
    /// Comparison with quoted values.
    pub comparison: Option<Comparison>,
    /// Whether the Gauss–Newton iteration met its tolerance.
    pub converged: bool,
    /// Gauss–Newton iterations.
    pub iterations: u64,
    /// Remarks for the reader (assumptions, boundary estimates), as values: the
    /// report stage words them.
    pub notes: Vec<CalibrationNote>,
}

/// A remark on a calibration the reader should see beside its numbers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum CalibrationNote {
    /// μ was neither given nor fitted: the paper's value was used.
    FrictionCoefficientAssumed {
        /// The μ used.
        value: f64,
    },
    /// As many measurements as parameters: the fit is exact, with no uncertainty.
    ExactFit {
        /// Number of measurements.
        measurements: usize,
        /// Number of fitted parameters (1: γ; 2: γ and μ).
        parameters: usize,
    },
    /// The confidence interval of γ reached below 0 and was clipped there.
    IntervalClippedAtZero,
    /// γ ended at the bottom of the searched range: the data show no adhesion.
    NoAdhesion,
    /// The Gauss–Newton iteration did not meet its tolerance.
    NotConverged,
    /// The covariance of the estimates is not defined (γ and μ not separately
    /// determined by the data): no standard errors or intervals are given.
    UncertaintyUndefined,
}

/// A small dense row-major matrix: the Jacobian type handed to argmin's Gauss–Newton
/// (argmin-math's `Vec` backend has no matrix inverse).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Matrix {
    rows: usize,
    cols: usize,
    data: Vec<f64>,
}

impl Matrix {
    fn new(rows: usize, cols: usize, data: Vec<f64>) -> Self {
        debug_assert_eq!(data.len(), rows * cols);
        Matrix { rows, cols, data }
    }
    fn at(&self, i: usize, j: usize) -> f64 {
        self.data[i * self.cols + j]
    }
}

impl argmin_math::ArgminTranspose<Matrix> for Matrix {
    fn t(self) -> Matrix {
        let mut data = vec![0.0; self.data.len()];
        for i in 0..self.rows {
            for j in 0..self.cols {
                data[j * self.rows + i] = self.at(i, j);
            }
        }
        Matrix::new(self.cols, self.rows, data)
    }
}

impl argmin_math::ArgminDot<Matrix, Matrix> for Matrix {
    fn dot(&self, other: &Matrix) -> Matrix {
        let mut data = vec![0.0; self.rows * other.cols];
        for i in 0..self.rows {
            for j in 0..other.cols {
                data[i * other.cols + j] =
                    (0..self.cols).map(|k| self.at(i, k) * other.at(k, j)).sum();
            }
        }
        Matrix::new(self.rows, other.cols, data)
    }
}

impl argmin_math::ArgminDot<Vec<f64>, Vec<f64>> for Matrix {
    fn dot(&self, v: &Vec<f64>) -> Vec<f64> {
        (0..self.rows)
            .map(|i| (0..self.cols).map(|k| self.at(i, k) * v[k]).sum())
            .collect()
    }
}

/// Why [`Matrix`] has no inverse (handed to argmin, which stops the fit).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
enum MatrixError {
    /// Only square matrices are inverted.
    #[error("cannot invert a {rows}×{cols} matrix")]
    NotSquare { rows: usize, cols: usize },
    /// A zero or non-finite pivot.
    #[error("singular matrix")]
    Singular,
}

impl argmin_math::ArgminInv<Matrix> for Matrix {
    /// Gauss–Jordan elimination with partial pivoting (the matrices here are 1×1 or 2×2).
    fn inv(&self) -> Result<Matrix, argmin_math::Error> {
        let n = self.rows;
        if n != self.cols {
            return Err(MatrixError::NotSquare {
                rows: self.rows,
                cols: self.cols,
            }
            .into());
        }
        let mut a = self.data.clone();
        let mut inv = vec![0.0; n * n];
        for i in 0..n {
            inv[i * n + i] = 1.0;
        }
        for c in 0..n {
            let p = (c..n)
                .max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs()))
                .unwrap_or(c);
            let pivot = a[p * n + c];
            if pivot == 0.0 || !pivot.is_finite() {
                return Err(MatrixError::Singular.into());
            }
            for k in 0..n {
                a.swap(c * n + k, p * n + k);
                inv.swap(c * n + k, p * n + k);
            }
            for k in 0..n {
                a[c * n + k] /= pivot;
                inv[c * n + k] /= pivot;
            }
            for r in 0..n {
                if r != c {
                    let f = a[r * n + c];
                    for k in 0..n {
                        a[r * n + k] -= f * a[c * n + k];
                        inv[r * n + k] -= f * inv[c * n + k];
                    }
                }
            }
        }
        Ok(Matrix::new(n, n, inv))
    }
}

/// The least-squares problem in u = (ln γ[, ln μ]), residuals scaled by `scale`.
#[derive(Debug, Clone)]
struct Residuals<'a> {
    points: &'a [Measurement],
    radius: f64,
    fixed_mu: Option<f64>,
    scale: f64,
}

impl Residuals<'_> {
    fn unpack(&self, u: &[f64]) -> (f64, f64) {
        (u[0].exp(), self.fixed_mu.unwrap_or_else(|| u[1].exp()))
    }
}

impl Operator for Residuals<'_> {
    type Param = Vec<f64>;
    type Output = Vec<f64>;
    fn apply(&self, u: &Vec<f64>) -> Result<Vec<f64>, argmin::core::Error> {
        let (gamma, mu) = self.unpack(u);
        Ok(self
            .points
            .iter()
            .map(|p| (jkr_friction(p.load, gamma, mu, self.radius) - p.friction) / self.scale)
            .collect())
    }
}

impl Jacobian for Residuals<'_> {
    type Param = Vec<f64>;
    type Jacobian = Matrix;
    fn jacobian(&self, u: &Vec<f64>) -> Result<Matrix, argmin::core::Error> {
        let (gamma, mu) = self.unpack(u);
        let cols = if self.fixed_mu.is_some() { 1 } else { 2 };
        let mut data = Vec::with_capacity(self.points.len() * cols);
        for p in self.points {
            data.push(mu * gamma * dhertz_dgamma(p.load, gamma, self.radius) / self.scale);
            if cols == 2 {
                data.push(jkr_friction(p.load, gamma, mu, self.radius) / self.scale);
            }
        }
        Ok(Matrix::new(self.points.len(), cols, data))
    }
}

/// Σ (F − μ P₁)² with μ fixed or, when `None`, at its optimum for this γ
/// (F is linear in μ: μ* = Σ F P₁ / Σ P₁²). Returns (SSR, μ).
fn profile(points: &[Measurement], gamma: f64, radius: f64, fixed_mu: Option<f64>) -> (f64, f64) {
    let p1: Vec<f64> = points
        .iter()
        .map(|p| apparent_hertz_load(p.load, gamma, radius))
        .collect();
    let mu = fixed_mu.unwrap_or_else(|| {
        let num: f64 = points.iter().zip(&p1).map(|(p, g)| p.friction * g).sum();
        let den: f64 = p1.iter().map(|g| g * g).sum();
        num / den
    });
    let ssr = points
        .iter()
        .zip(&p1)
        .map(|(p, g)| (mu * g - p.friction).powi(2))
        .sum();
    (ssr, mu)
}

/// Fits γ (and μ) to the data by least squares; see the module documentation.
pub fn fit(data: &FrictionData, settings: &FitSettings) -> Result<Calibration, CalibrationError> {
    settings.validate()?;
    let fixed_mu = settings.fixed_mu();
    let n_params = if fixed_mu.is_some() { 1 } else { 2 };
    let parameters = if n_params == 1 { "γ" } else { "γ and μ" };
    let n = data.points.len();
    if n < n_params {
        return Err(CalibrationError::TooFewPoints {
            origin: data.origin.clone(),
            found: format!("{n} measurement{}", if n == 1 { "" } else { "s" }),
            parameters: parameters.into(),
            needed: format!("{n_params} (and more than {n_params} for an uncertainty)"),
        });
    }
    let mut loads: Vec<f64> = data.points.iter().map(|p| p.load).collect();
    loads.sort_by(f64::total_cmp);
    loads.dedup();
    if n_params == 2 && loads.len() < 2 {
        return Err(CalibrationError::TooFewPoints {
            origin: data.origin.clone(),
            found: format!("every measurement is at the same load ({})", format_quantity(loads[0], Dimension::Force)),
            parameters: parameters.into(),
            needed: "two distinct loads (at one load only the product of μ and the adhesive term is determined)".into(),
        });
    }
    if n_params == 2 {
        let (mp, mf) = data.points.iter().fold((0.0, 0.0), |(a, b), p| {
            (a + p.load / n as f64, b + p.friction / n as f64)
        });
        let (sxy, sxx) = data.points.iter().fold((0.0, 0.0), |(a, b), p| {
            (
                a + (p.load - mp) * (p.friction - mf),
                b + (p.load - mp).powi(2),
            )
        });
        let slope = sxy / sxx;
        if slope <= 0.0 {
            return Err(CalibrationError::FrictionFalls {
                origin: data.origin.clone(),
                slope,
            });
        }
    }
    if let Some(mu) = fixed_mu {
        for p in &data.points {
            if p.friction < mu * p.load {
                return Err(CalibrationError::FrictionBelowFloor {
                    origin: data.origin.clone(),
                    line: p.line,
                    load: format_quantity(p.load, Dimension::Force),
                    friction: format_quantity(p.friction, Dimension::Force),
                    floor: format_quantity(mu * p.load, Dimension::Force),
                    mu,
                });
            }
        }
    }
    let radius = settings.radius;
    let points = &data.points;

    // Start: scan ln γ over 16 decades around the scale where 3πγR is comparable to
    // the forces measured.
    let force_scale = points
        .iter()
        .map(|p| p.load.max(p.friction))
        .fold(0.0, f64::max);
    let gamma_scale = force_scale / (3.0 * PI * radius);
    let (mut best_gamma, mut best_ssr) = (gamma_scale, f64::INFINITY);
    for k in -320..=160 {
        let gamma = gamma_scale * 10f64.powf(k as f64 / 20.0);
        let (ssr, _) = profile(points, gamma, radius, fixed_mu);
        if ssr < best_ssr {
            (best_gamma, best_ssr) = (gamma, ssr);
        }
    }
    let (_, mu_start) = profile(points, best_gamma, radius, fixed_mu);
    let mut u0 = vec![best_gamma.ln()];
    if fixed_mu.is_none() {
        u0.push(mu_start.ln());
    }

    // Polish with argmin's Gauss–Newton (full steps; the start is within a factor
    // 10^(1/20) of the optimum).
    let problem = Residuals {
        points,
        radius,
        fixed_mu,
        scale: force_scale,
    };
    let solver = GaussNewton::new()
        .with_tolerance(1e-15)
        .expect("a positive tolerance");
    let run = Executor::new(problem.clone(), solver)
        .configure(|s| s.param(u0.clone()).max_iters(200))
        .run();
    let (u, converged, iterations) = match run {
        Ok(res) => {
            let converged = matches!(
                res.state.get_termination_reason(),
                Some(TerminationReason::SolverConverged)
            );
            let iters = res.state.get_iter();
            let u = res
                .state
                .get_best_param()
                .or(res.state.get_param())
                .cloned()
                .unwrap_or(u0.clone());
            (u, converged, iters)
        }
        Err(_) => (u0.clone(), false, 0),
    };
    // Keep whichever of the start and the polished point is better (a diverging
    // Gauss–Newton must not make things worse).
    let (mut gamma, mut mu) = problem.unpack(&u);
    let mut converged = converged && gamma.is_finite() && mu.is_finite();
    let ssr_of = |g: f64, m: f64| -> f64 {
        points
            .iter()
            .map(|p| (jkr_friction(p.load, g, m, radius) - p.friction).powi(2))
            .sum()
    };
    let polished = ssr_of(gamma, mu);
    if polished.is_nan() || polished > best_ssr {
        (gamma, mu) = (best_gamma, mu_start);
        converged = false;
    }
    let ssr = ssr_of(gamma, mu);

    // Uncertainty from the Jacobian in (γ, μ).
    let dof = n - n_params;
    let mut jtj = [[0.0f64; 2]; 2];
    for p in points {
        let row = [
            mu * dhertz_dgamma(p.load, gamma, radius),
            apparent_hertz_load(p.load, gamma, radius),
        ];
        for i in 0..n_params {
            for j in 0..n_params {
                jtj[i][j] += row[i] * row[j];
            }
        }
    }
    let (t_quantile, residual_sd, se_gamma, se_mu, correlation) = if dof > 0 {
        let s2 = ssr / dof as f64;
        let t = student_t_quantile(CONFIDENCE_LEVEL, dof);
        if n_params == 1 {
            (
                Some(t),
                Some(s2.sqrt()),
                Some((s2 / jtj[0][0]).sqrt()),
                None,
                None,
            )
        } else {
            let det = jtj[0][0] * jtj[1][1] - jtj[0][1] * jtj[1][0];
            let (c00, c11, c01) = (
                s2 * jtj[1][1] / det,
                s2 * jtj[0][0] / det,
                -s2 * jtj[0][1] / det,
            );
            (
                Some(t),
                Some(s2.sqrt()),
                Some(c00.sqrt()),
                Some(c11.sqrt()),
                Some(c01 / (c00 * c11).sqrt()),
            )
        }
    } else {
        (None, None, None, None, None)
    };
    // Uncertainties the data cannot define (a singular or ill-conditioned JᵀJ) are
    // left out and said, never printed as NaN.
    let finite = |x: Option<f64>| x.filter(|v| v.is_finite());
    let undefined = [se_gamma, se_mu, correlation]
        .iter()
        .any(|x| x.is_some_and(|v| !v.is_finite()));
    let (se_gamma, se_mu, correlation) = (finite(se_gamma), finite(se_mu), finite(correlation));
    let interval = |est: f64, se: Option<f64>| -> Option<[f64; 2]> {
        Some([est - t_quantile? * se?, est + t_quantile? * se?])
    };
    let raw_ci = interval(gamma, se_gamma);
    let clipped = raw_ci.is_some_and(|ci| ci[0] < 0.0);
    let confidence_interval = raw_ci.map(|ci| [ci[0].max(0.0), ci[1]]);

    let k_modulus = settings.equivalent_modulus.map(|e| 4.0 * e / 3.0);
    let per_point: Vec<PointFit> = points
        .iter()
        .map(|p| {
            let fitted = jkr_friction(p.load, gamma, mu, radius);
            let p1 = apparent_hertz_load(p.load, gamma, radius);
            let contact_radius = k_modulus.map(|k| (radius * p1 / k).cbrt());
            let own = work_of_adhesion_from_point(p.load, p.friction, mu, radius);
            PointFit {
                line: p.line,
                load: p.load,
                friction: p.friction,
                fitted_friction: fitted,
                residual: p.friction - fitted,
                work_of_adhesion: own,
                apparent_hertz_load: p1,
                contact_radius,
                bond_strength: contact_radius.map(|r| p.friction / (PI * r * r)),
                note: own.is_none().then_some(PointNote::FrictionBelowSliding {
                    sliding_friction: mu * p.load,
                    friction_coefficient: mu,
                }),
            }
        })
        .collect();
    let own: Vec<f64> = per_point
        .iter()
        .filter_map(|p| p.work_of_adhesion)
        .collect();
    let per_point_range = (!own.is_empty()).then(|| {
        [
            own.iter().copied().fold(f64::INFINITY, f64::min),
            own.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        ]
    });
    let bonds: Vec<f64> = per_point.iter().filter_map(|p| p.bond_strength).collect();
    let mean_bond_strength =
        (!bonds.is_empty()).then(|| bonds.iter().sum::<f64>() / bonds.len() as f64);

    let mut notes = Vec::new();
    if settings.friction_coefficient == FrictionCoefficient::Default {
        notes.push(CalibrationNote::FrictionCoefficientAssumed {
            value: DEFAULT_FRICTION_COEFFICIENT,
        });
    }
    if dof == 0 {
        notes.push(CalibrationNote::ExactFit {
            measurements: n,
            parameters: n_params,
        });
    }
    if clipped {
        notes.push(CalibrationNote::IntervalClippedAtZero);
    }
    if gamma <= gamma_scale * 1e-15 {
        notes.push(CalibrationNote::NoAdhesion);
    }
    if !converged {
        notes.push(CalibrationNote::NotConverged);
    }
    if undefined {
        notes.push(CalibrationNote::UncertaintyUndefined);
    }

    let comparison = settings.quoted.as_ref().map(|q| {
        let work_of_adhesion = q.work_of_adhesion.map(|gq| {
            let predicted_friction: Vec<f64> = points
                .iter()
                .map(|p| jkr_friction(p.load, gq, mu, radius))
                .collect();
            let implied_bond_strength = k_modulus.map(|k| {
                points
                    .iter()
                    .map(|p| {
                        let r = (radius * apparent_hertz_load(p.load, gq, radius) / k).cbrt();
                        p.friction / (PI * r * r)
                    })
                    .sum::<f64>()
                    / n as f64
            });
            let within_ci = confidence_interval.map(|ci| ci[0] <= gq && gq <= ci[1]);
            let within_range = per_point_range.is_some_and(|r| r[0] <= gq && gq <= r[1]);
            QuotedGamma {
                quoted: gq,
                ratio_to_fit: gq / gamma,
                within_confidence_interval: within_ci,
                within_per_point_range: within_range,
                predicted_friction,
                implied_bond_strength,
                agrees: within_ci.unwrap_or(within_range),
            }
        });
        let bond_strength = match (q.bond_strength, mean_bond_strength) {
            (Some(tq), Some(mean)) => {
                let lo = bonds.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = bonds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                Some(QuotedBond {
                    quoted: tq,
                    from_data: mean,
                    ratio: tq / mean,
                    agrees: lo <= tq && tq <= hi,
                })
            }
            _ => None,
        };
        Comparison {
            source: q.source.clone(),
            work_of_adhesion,
            bond_strength_unchecked: if bond_strength.is_none() {
                q.bond_strength
            } else {
                None
            },
            bond_strength,
        }
    });

    Ok(Calibration {
        origin: data.origin.clone(),
        radius,
        work_of_adhesion: gamma,
        standard_error: se_gamma,
        confidence_interval,
        confidence_interval_clipped: clipped,
        friction_coefficient: mu,
        friction_coefficient_source: settings.friction_coefficient,
        friction_coefficient_standard_error: se_mu,
        friction_coefficient_confidence_interval: interval(mu, se_mu)
            .map(|ci| [ci[0].max(0.0), ci[1]]),
        friction_coefficient_interval_clipped: interval(mu, se_mu).is_some_and(|ci| ci[0] < 0.0),
        correlation,
        degrees_of_freedom: dof,
        t_quantile,
        residual_standard_deviation: residual_sd,
        sum_of_squares: ssr,
        per_point,
        per_point_range,
        equivalent_modulus: settings.equivalent_modulus,
        mean_bond_strength,
        comparison,
        converged,
        iterations,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn t_quantiles_match_tables() {
        // Two-sided 95 % quantiles, e.g. Abramowitz & Stegun table 26.10.
        for (dof, t) in [
            (1, 12.706_204_736),
            (2, 4.302_652_730),
            (3, 3.182_446_305),
            (10, 2.228_138_852),
            (30, 2.042_272_456),
        ] {
            let q = student_t_quantile(0.95, dof);
            assert!((q / t - 1.0).abs() < 1e-8, "dof {dof}: {q} vs {t}");
        }
    }

    #[test]
    fn matrix_inverse() {
        use argmin_math::{ArgminDot, ArgminInv};
        let m = Matrix::new(2, 2, vec![4.0, 3.0, 6.0, 3.0]);
        let i = m.inv().unwrap();
        let e = m.dot(&i);
        for (k, want) in [1.0, 0.0, 0.0, 1.0].iter().enumerate() {
            assert!((e.data[k] - want).abs() < 1e-14);
        }
        assert!(Matrix::new(2, 2, vec![1.0, 2.0, 2.0, 4.0]).inv().is_err());
    }
}
