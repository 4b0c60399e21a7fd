//! The activation energy ΔU and volume ΔV of stress-assisted wear from measured wear
//! rates (`wearopt fit-wear`; docs/model.md §14).
//!
//! In the atom-by-atom regime (Γ a₀/v ≪ 1 in the stress-assisted law, docs/model.md
//! §12) the wear rate of a contact under stress σ at temperature T is
//!
//! ```text
//! rate = A exp(−(ΔU − σ ΔV) / (k_B T)),   so   ln rate = c + ΔV σ/(k_B T) − ΔU/(k_B T)
//! ```
//!
//! with c = ln A. That is linear in (c, ΔV, ΔU), so an ordinary least-squares fit of
//! ln rate (equal, unknown variance per point: a relative scatter of the rates) gives
//! the estimates, their standard errors s·√((XᵀX)⁻¹)_jj with s² = SSR/(n − p), and the
//! 95 % intervals estimate ± t(0.975, n − p)·se, as `fit-adhesion` reports them. At one
//! temperature the ΔU column is the intercept's multiple: ΔU cannot be identified and
//! c absorbs −ΔU/(k_B T) (the report says so). Rates in m³/m slid are turned into
//! m³/s with the sliding speed (rate per second = rate per metre × v).
//!
//! **Saturation.** When Γ a₀/v approaches 1 the rate stops growing exponentially
//! and levels off at the one-pass cap; ln rate then bends down against σ. With at
//! least two points to spare the fit is repeated with a term in (σ/k_B T)²; a negative
//! curvature beyond its 95 % one-sided bound marks the points as saturated (ΔV is
//! then underestimated: fit the lower stresses alone).
//!
//! The least squares use Householder QR on the columns scaled to unit length (no
//! normal equations), so noise-free data give ΔU and ΔV to about 1e-13.

use std::path::Path;

use serde::Serialize;

use crate::calibrate::{student_t_quantile, CalibrationError, CONFIDENCE_LEVEL};
use crate::units::{format_quantity, parse_quantity, Dimension};

/// Boltzmann's constant k_B (J/K), exact in the SI.
pub const BOLTZMANN: f64 = 1.380_649e-23;

/// One electronvolt (J), exact in the SI.
pub const ELECTRONVOLT: f64 = 1.602_176_634e-19;

/// The temperature when neither the data nor the options give one (K): the scene's
/// default (docs/model.md §10).
pub const DEFAULT_TEMPERATURE: f64 = 298.15;

/// The unit of the measured rates, from the CSV header's rate column.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RateUnit {
    /// `rate_atoms_per_s`: atoms removed per second.
    AtomsPerS,
    /// `rate_m3_per_s`: volume per second.
    M3PerS,
    /// `rate_m3_per_m`: volume per metre slid (needs the sliding speed).
    M3PerM,
}

impl RateUnit {
    /// Every unit, in the order the header messages list them.
    pub const ALL: [RateUnit; 3] = [RateUnit::AtomsPerS, RateUnit::M3PerS, RateUnit::M3PerM];

    /// The CSV column that gives rates in this unit.
    pub fn column(self) -> &'static str {
        match self {
            RateUnit::AtomsPerS => "rate_atoms_per_s",
            RateUnit::M3PerS => "rate_m3_per_s",
            RateUnit::M3PerM => "rate_m3_per_m",
        }
    }

    /// The unit as reports write it.
    pub fn symbol(self) -> &'static str {
        match self {
            RateUnit::AtomsPerS => "atoms/s",
            RateUnit::M3PerS => "m³/s",
            RateUnit::M3PerM => "m³/m",
        }
    }
}

/// One measured wear rate.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WearPoint {
    /// 1-based line in the data file.
    pub line: usize,
    /// σ, the contact stress (Pa).
    pub stress: f64,
    /// The rate, in the file's unit (> 0).
    pub rate: f64,
    /// T (K) when the file has a `temperature_K` column.
    pub temperature: Option<f64>,
}

/// Measured wear rates and where they came from.
#[derive(Debug, Clone, PartialEq)]
pub struct WearData {
    /// The file name, for messages.
    pub origin: String,
    /// The unit of the rate column.
    pub rate_unit: RateUnit,
    /// The measurements, in file order.
    pub points: Vec<WearPoint>,
}

fn header_error(origin: &str, line: usize, found: &str) -> CalibrationError {
    CalibrationError::WearHeader {
        origin: origin.to_string(),
        line,
        found: found.to_string(),
    }
}

fn unquote(field: &str) -> &str {
    let f = field.trim();
    f.strip_prefix('"')
        .and_then(|g| g.strip_suffix('"'))
        .unwrap_or(f)
        .trim()
}

/// Reads a data file: see [`parse_wear_csv`].
pub fn read_wear_csv(path: &Path) -> Result<WearData, CalibrationError> {
    let text = std::fs::read_to_string(path).map_err(|e| CalibrationError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })?;
    parse_wear_csv(&text, &path.display().to_string())
}

/// Parses wear data: a header `stress_Pa,RATE[,temperature_K]` with RATE one of
/// `rate_atoms_per_s`, `rate_m3_per_s`, `rate_m3_per_m` (the rate's unit is in its
/// name), then one row per measurement. A stress or temperature may carry its
/// own unit (`1.2 GPa`, `350 K`); a plain number is in the column's unit. Blank lines
/// and lines starting with `#` are skipped. Stresses must be finite (a tensile one is
/// negative), rates finite and > 0, temperatures finite and > 0.
pub fn parse_wear_csv(text: &str, origin: &str) -> Result<WearData, CalibrationError> {
    let mut lines = text
        .lines()
        .enumerate()
        .map(|(i, l)| (i + 1, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'));
    let (hline, header) = lines.next().ok_or_else(|| header_error(origin, 0, ""))?;
    let names: Vec<String> = header
        .trim_start_matches('\u{feff}')
        .split(',')
        .map(|f| unquote(f).to_string())
        .collect();
    let rate_unit = match names.get(1) {
        Some(n) => RateUnit::ALL.into_iter().find(|u| u.column() == n),
        None => None,
    };
    let with_temperature = names.len() == 3 && names[2] == "temperature_K";
    let (Some(rate_unit), true) = (
        rate_unit,
        names[0] == "stress_Pa" && (names.len() == 2 || with_temperature),
    ) else {
        return Err(header_error(origin, hline, header));
    };
    let mut points = Vec::new();
    for (line, row) in lines {
        let fields: Vec<&str> = row.split(',').map(unquote).collect();
        if fields.len() != names.len() {
            return Err(CalibrationError::WearRow {
                origin: origin.to_string(),
                line,
                found: row.to_string(),
                values: fields.len(),
                expected: names.join(","),
            });
        }
        let bad = |column: &'static str, value: &str, message: String| CalibrationError::Value {
            origin: origin.to_string(),
            line,
            column,
            value: value.to_string(),
            message,
        };
        let stress = parse_quantity(fields[0], Dimension::Pressure)
            .map_err(|e| bad("stress_Pa", fields[0], e.to_string()))?;
        if !stress.is_finite() {
            return Err(bad(
                "stress_Pa",
                fields[0],
                "must be a finite stress".into(),
            ));
        }
        let column = rate_unit.column();
        let rate: f64 = fields[1].parse().map_err(|_| {
            bad(
                column,
                fields[1],
                "must be a number (the unit is in the column's name)".into(),
            )
        })?;
        if !(rate.is_finite() && rate > 0.0) {
            return Err(bad(
                column,
                fields[1],
                "must be finite and > 0 (a logarithm is fitted)".into(),
            ));
        }
        let temperature = if with_temperature {
            let t = parse_quantity(fields[2], Dimension::Temperature)
                .map_err(|e| bad("temperature_K", fields[2], e.to_string()))?;
            if !(t.is_finite() && t > 0.0) {
                return Err(bad(
                    "temperature_K",
                    fields[2],
                    "must be finite and > 0 K".into(),
                ));
            }
            Some(t)
        } else {
            None
        };
        points.push(WearPoint {
            line,
            stress,
            rate,
            temperature,
        });
    }
    Ok(WearData {
        origin: origin.to_string(),
        rate_unit,
        points,
    })
}

/// The settings of a fit.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct WearFitSettings {
    /// T (K), > 0: every point's temperature when the file has no `temperature_K`
    /// column (then [`DEFAULT_TEMPERATURE`] when None); refused beside the column.
    pub temperature: Option<f64>,
    /// v, the sliding speed (m/s), > 0: turns rates in m³/m into m³/s; needed for
    /// them and refused for the others.
    pub speed: Option<f64>,
}

/// An estimate with its standard error and 95 % interval (both None for an exact fit,
/// n equal to the number of parameters).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Estimate {
    /// The least-squares value.
    pub estimate: f64,
    /// √ of its variance from s² (XᵀX)⁻¹.
    pub standard_error: Option<f64>,
    /// estimate − t(0.975, n − p) · standard error.
    pub lower: Option<f64>,
    /// estimate + t(0.975, n − p) · standard error.
    pub upper: Option<f64>,
}

impl Estimate {
    fn new(estimate: f64, standard_error: Option<f64>, t: f64) -> Estimate {
        Estimate {
            estimate,
            standard_error,
            lower: standard_error.map(|s| estimate - t * s),
            upper: standard_error.map(|s| estimate + t * s),
        }
    }

    /// The same estimate in another unit (`factor` > 0 per unit of this one).
    fn scaled(self, factor: f64) -> Estimate {
        Estimate {
            estimate: self.estimate * factor,
            standard_error: self.standard_error.map(|s| s * factor),
            lower: self.lower.map(|s| s * factor),
            upper: self.upper.map(|s| s * factor),
        }
    }

    /// Whether `value` lies in the interval (false without one).
    pub fn covers(&self, value: f64) -> bool {
        matches!((self.lower, self.upper), (Some(l), Some(u)) if l <= value && value <= u)
    }
}

/// Where the temperature came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TemperatureSource {
    /// The file's `temperature_K` column.
    Data,
    /// The `temperature` option.
    Option,
    /// Nothing said: [`DEFAULT_TEMPERATURE`].
    Default,
}

/// What the report must say beside the numbers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum WearFitNote {
    /// All points at one temperature: ΔU is not identified, and the intercept
    /// includes −ΔU/(k_B T).
    ActivationEnergyNotIdentified {
        /// The one temperature (K).
        temperature: f64,
    },
    /// ln rate bends down against σ (a significant negative curvature): the rates
    /// approach the one-pass cap, and ΔV is underestimated.
    Saturated {
        /// The curvature's t statistic (negative).
        t_statistic: f64,
    },
    /// Too few points to spare for the saturation check (it needs n ≥ p + 2).
    SaturationNotChecked,
    /// As many points as parameters: the fit is exact, without intervals.
    ExactFit,
    /// No temperature given: [`DEFAULT_TEMPERATURE`] assumed.
    DefaultTemperature {
        /// T (K).
        temperature: f64,
    },
}

/// One measurement and what the fit says about it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WearPointFit {
    /// Line in the data file.
    pub line: usize,
    /// σ (Pa).
    pub stress: f64,
    /// T (K).
    pub temperature: f64,
    /// The measured rate, per second (the file's rate × v for m³/m).
    pub rate: f64,
    /// The fitted rate, per second.
    pub fitted_rate: f64,
    /// ln(rate / fitted rate).
    pub residual: f64,
}

/// The result of a fit, SI (J, m³, K; the rates per second in `rate_unit`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WearFit {
    /// The data file.
    pub origin: String,
    /// The unit of the file's rates.
    pub data_rate_unit: RateUnit,
    /// The unit of the fitted rates and the prefactor: atoms/s or m³/s.
    pub rate_unit: &'static str,
    /// v (m/s) when rates in m³/m were turned into m³/s.
    pub speed: Option<f64>,
    /// Where T came from.
    pub temperature_source: TemperatureSource,
    /// The distinct temperatures (K), ascending.
    pub temperatures: Vec<f64>,
    /// n, the points.
    pub points: usize,
    /// n − p.
    pub degrees_of_freedom: usize,
    /// ΔV, the activation volume (m³).
    pub activation_volume: Estimate,
    /// ΔU, the activation energy (J); None at one temperature.
    pub activation_energy: Option<Estimate>,
    /// ΔU in eV; None at one temperature.
    pub activation_energy_ev: Option<Estimate>,
    /// c = ln A (A in `rate_unit`): with ΔU identified the rate at σ = 0 and T → ∞;
    /// at one temperature ln of the rate at σ = 0 there (A e^{−ΔU/k_BT}).
    pub ln_prefactor: Estimate,
    /// s, the residual standard deviation of ln rate (None for an exact fit).
    pub residual_standard_deviation: Option<f64>,
    /// t(0.975, n − p), the interval's multiplier (None for an exact fit).
    pub t_quantile: Option<f64>,
    /// Whether the points look saturated (see [`WearFitNote::Saturated`]).
    pub saturated: bool,
    /// Each point with its fitted rate.
    pub per_point: Vec<WearPointFit>,
    /// What the report must say.
    pub notes: Vec<WearFitNote>,
}

/// Ordinary least squares of y on the columns of x (n × p, column-major), by
/// Householder QR on the columns scaled to unit length: (β, the p × p (XᵀX)⁻¹, SSR).
/// None when a column is (numerically) a combination of the others.
fn least_squares(x: &[Vec<f64>], y: &[f64]) -> Option<(Vec<f64>, Vec<Vec<f64>>, f64)> {
    let p = x.len();
    let n = y.len();
    let scale: Vec<f64> = x
        .iter()
        .map(|c| c.iter().map(|v| v * v).sum::<f64>().sqrt())
        .collect();
    if scale.iter().any(|&s| !(s > 0.0 && s.is_finite())) {
        return None;
    }
    let mut a: Vec<Vec<f64>> = x
        .iter()
        .zip(&scale)
        .map(|(c, s)| c.iter().map(|v| v / s).collect())
        .collect();
    let mut b = y.to_vec();
    for k in 0..p {
        let norm = a[k][k..].iter().map(|v| v * v).sum::<f64>().sqrt();
        if norm < 1e-10 {
            return None;
        }
        let alpha = if a[k][k] > 0.0 { -norm } else { norm };
        let mut v: Vec<f64> = a[k][k..].to_vec();
        v[0] -= alpha;
        let vv: f64 = v.iter().map(|t| t * t).sum();
        for col in a.iter_mut().skip(k) {
            let dot: f64 = v.iter().zip(&col[k..]).map(|(a, b)| a * b).sum();
            let f = 2.0 * dot / vv;
            for (c, vi) in col[k..].iter_mut().zip(&v) {
                *c -= f * vi;
            }
        }
        let dot: f64 = v.iter().zip(&b[k..]).map(|(a, b)| a * b).sum();
        let f = 2.0 * dot / vv;
        for (c, vi) in b[k..].iter_mut().zip(&v) {
            *c -= f * vi;
        }
    }
    // R is a[j][i] for i ≤ j; solve R β = Qᵀy and invert R.
    let r = |i: usize, j: usize| a[j][i];
    let mut rinv = vec![vec![0.0; p]; p];
    #[allow(clippy::needless_range_loop)] // the triangular solve reads rinv[k][j] across rows
    for j in 0..p {
        rinv[j][j] = 1.0 / r(j, j);
        for i in (0..j).rev() {
            let s: f64 = (i + 1..=j).map(|k| r(i, k) * rinv[k][j]).sum();
            rinv[i][j] = -s / r(i, i);
        }
    }
    let beta_scaled: Vec<f64> = (0..p)
        .map(|i| (i..p).map(|k| rinv[i][k] * b[k]).sum())
        .collect();
    let ssr: f64 = b[p..n].iter().map(|v| v * v).sum();
    let beta: Vec<f64> = beta_scaled.iter().zip(&scale).map(|(b, s)| b / s).collect();
    let cov: Vec<Vec<f64>> = (0..p)
        .map(|i| {
            (0..p)
                .map(|j| {
                    let s: f64 = (i.max(j)..p).map(|k| rinv[i][k] * rinv[j][k]).sum();
                    s / (scale[i] * scale[j])
                })
                .collect()
        })
        .collect();
    Some((beta, cov, ssr))
}

fn too_few(origin: &str, found: String, parameters: &str, needed: &str) -> CalibrationError {
    CalibrationError::TooFewPoints {
        origin: origin.to_string(),
        found,
        parameters: parameters.to_string(),
        needed: needed.to_string(),
    }
}

fn distinct(mut v: Vec<f64>) -> Vec<f64> {
    v.sort_by(f64::total_cmp);
    v.dedup_by(|a, b| (*a - *b).abs() <= 1e-12 * b.abs());
    v
}

/// Fits ΔV (and ΔU where the temperature varies) to `data`: see the module's
/// documentation. Bad input (fewer than 3 points, one stress value, a missing or
/// needless speed, a temperature both in the file and in the settings) is an error
/// naming the file, the field and what is accepted.
pub fn fit_wear(data: &WearData, settings: &WearFitSettings) -> Result<WearFit, CalibrationError> {
    let origin = &data.origin;
    let setting = |name: &'static str, value: String, expected: &str| CalibrationError::Setting {
        name,
        value,
        expected: expected.to_string(),
    };
    if let Some(t) = settings.temperature {
        if !(t.is_finite() && t > 0.0) {
            return Err(setting(
                "temperature",
                format_quantity(t, Dimension::Temperature),
                "must be a finite temperature > 0 K, e.g. \"300 K\"",
            ));
        }
    }
    let has_column = data.points.first().is_some_and(|p| p.temperature.is_some());
    if let (Some(t), true) = (settings.temperature, has_column) {
        return Err(setting(
            "temperature",
            format_quantity(t, Dimension::Temperature),
            &format!("{origin} has a temperature_K column: give the temperatures there or with this option, not both"),
        ));
    }
    let speed = match (data.rate_unit, settings.speed) {
        (RateUnit::M3PerM, None) => {
            return Err(setting(
                "speed",
                "(none)".into(),
                &format!("{origin} gives rates in m³ per metre slid (rate_m3_per_m): the sliding speed is needed to turn them into m³/s, e.g. \"1 mm/s\""),
            ))
        }
        (RateUnit::M3PerM, Some(v)) => {
            if !(v.is_finite() && v > 0.0) {
                return Err(setting("speed", v.to_string(), "must be a finite speed > 0 m/s, e.g. \"1 mm/s\""));
            }
            Some(v)
        }
        (unit, Some(v)) => {
            return Err(setting(
                "speed",
                v.to_string(),
                &format!("{origin} gives rates per second ({}): the speed applies only to rates per metre slid (rate_m3_per_m)", unit.column()),
            ))
        }
        (_, None) => None,
    };
    let n = data.points.len();
    if n < 3 {
        return Err(too_few(
            origin,
            format!("{n} point{}", if n == 1 { "" } else { "s" }),
            "ΔV with its interval",
            "3 points",
        ));
    }
    let stresses = distinct(data.points.iter().map(|p| p.stress).collect());
    if stresses.len() < 2 {
        return Err(too_few(
            origin,
            format!(
                "one stress value only (stress_Pa = {} on every row)",
                format_quantity(stresses[0], Dimension::Pressure)
            ),
            "ΔV, the slope of ln rate against stress,",
            "2 distinct stresses",
        ));
    }
    let (source, fixed) = match (has_column, settings.temperature) {
        (true, _) => (TemperatureSource::Data, DEFAULT_TEMPERATURE),
        (false, Some(t)) => (TemperatureSource::Option, t),
        (false, None) => (TemperatureSource::Default, DEFAULT_TEMPERATURE),
    };
    let temps: Vec<f64> = data
        .points
        .iter()
        .map(|p| p.temperature.unwrap_or(fixed))
        .collect();
    let temperatures = distinct(temps.clone());
    let identified = temperatures.len() > 1;
    let per_second = speed.unwrap_or(1.0);
    let y: Vec<f64> = data
        .points
        .iter()
        .map(|p| (p.rate * per_second).ln())
        .collect();
    let x1: Vec<f64> = data
        .points
        .iter()
        .zip(&temps)
        .map(|(p, t)| p.stress / (BOLTZMANN * t))
        .collect();
    let mut columns = vec![vec![1.0; n], x1.clone()];
    if identified {
        columns.push(temps.iter().map(|t| -1.0 / (BOLTZMANN * t)).collect());
    }
    let p = columns.len();
    let (beta, cov, ssr) = least_squares(&columns, &y).ok_or_else(|| {
        too_few(
            origin,
            "stresses and temperatures that vary together (σ/T and 1/T are proportional)".into(),
            "ΔV and ΔU apart",
            "stresses that vary at a fixed temperature",
        )
    })?;
    let dof = n - p;
    let (s, t) = if dof > 0 {
        let s = (ssr / dof as f64).sqrt();
        (Some(s), Some(student_t_quantile(CONFIDENCE_LEVEL, dof)))
    } else {
        (None, None)
    };
    let estimate = |j: usize| {
        Estimate::new(
            beta[j],
            s.map(|s| s * cov[j][j].max(0.0).sqrt()),
            t.unwrap_or(0.0),
        )
    };
    let mut notes = Vec::new();
    if source == TemperatureSource::Default {
        notes.push(WearFitNote::DefaultTemperature {
            temperature: DEFAULT_TEMPERATURE,
        });
    }
    if !identified {
        notes.push(WearFitNote::ActivationEnergyNotIdentified {
            temperature: temperatures[0],
        });
    }
    if dof == 0 {
        notes.push(WearFitNote::ExactFit);
    }
    // Saturation: one more column, (σ/k_BT)², and its one-sided t test.
    let mut saturated = false;
    if n >= p + 2 {
        let mut more = columns.clone();
        more.push(x1.iter().map(|v| v * v).collect());
        if let Some((b2, cov2, ssr2)) = least_squares(&more, &y) {
            let dof2 = n - p - 1;
            let s2 = (ssr2 / dof2 as f64).sqrt();
            let se = s2 * cov2[p][p].max(0.0).sqrt();
            let curvature = b2[p];
            // One-sided 95 %: the two-sided 90 % quantile.
            let bound = student_t_quantile(2.0 * CONFIDENCE_LEVEL - 1.0, dof2);
            let t_stat = if se > 0.0 {
                curvature / se
            } else if curvature < 0.0 {
                f64::NEG_INFINITY
            } else {
                0.0
            };
            // A curvature of more than a relative 1e-6 of the slope over the data's
            // span: noise-free exponential data give a round-off curvature only.
            let span = x1.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
                - x1.iter().cloned().fold(f64::INFINITY, f64::min);
            let material = curvature.abs() * span * span > 1e-6 * (1.0 + (beta[1] * span).abs());
            if t_stat < -bound && material {
                saturated = true;
                notes.push(WearFitNote::Saturated {
                    t_statistic: if t_stat.is_finite() { t_stat } else { -1e300 },
                });
            }
        }
    } else {
        notes.push(WearFitNote::SaturationNotChecked);
    }
    let per_point = data
        .points
        .iter()
        .enumerate()
        .map(|(i, pt)| {
            let fitted: f64 = (0..p).map(|j| beta[j] * columns[j][i]).sum();
            WearPointFit {
                line: pt.line,
                stress: pt.stress,
                temperature: temps[i],
                rate: pt.rate * per_second,
                fitted_rate: fitted.exp(),
                residual: y[i] - fitted,
            }
        })
        .collect();
    let activation_energy = identified.then(|| estimate(2));
    Ok(WearFit {
        origin: origin.clone(),
        data_rate_unit: data.rate_unit,
        rate_unit: match data.rate_unit {
            RateUnit::AtomsPerS => "atoms/s",
            _ => "m³/s",
        },
        speed,
        temperature_source: source,
        temperatures,
        points: n,
        degrees_of_freedom: dof,
        activation_volume: estimate(1),
        activation_energy,
        activation_energy_ev: activation_energy.map(|e| e.scaled(1.0 / ELECTRONVOLT)),
        ln_prefactor: estimate(0),
        residual_standard_deviation: s,
        t_quantile: t,
        saturated,
        per_point,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data(unit: RateUnit, rows: &[(f64, f64, Option<f64>)]) -> WearData {
        WearData {
            origin: "test.csv".into(),
            rate_unit: unit,
            points: rows
                .iter()
                .enumerate()
                .map(|(i, &(stress, rate, temperature))| WearPoint {
                    line: i + 2,
                    stress,
                    rate,
                    temperature,
                })
                .collect(),
        }
    }

    /// QR least squares against a fit whose answer is known exactly: y = 1 + 2x on
    /// x = 0..4 with residuals ±1 alternating about it has β = (1, 2) shifted by the
    /// residuals' own projection; here the residuals (1, −1, 0, −1, 1) are orthogonal
    /// to 1 and x, so β = (1, 2) exactly and SSR = 4; (XᵀX)⁻¹ of [1, x] is
    /// [[0.6, −0.2], [−0.2, 0.1]] by hand.
    #[test]
    fn least_squares_by_hand() {
        let x = vec![vec![1.0; 5], vec![0.0, 1.0, 2.0, 3.0, 4.0]];
        let e = [1.0, -1.0, 0.0, -1.0, 1.0];
        let y: Vec<f64> = (0..5).map(|i| 1.0 + 2.0 * i as f64 + e[i]).collect();
        let (b, cov, ssr) = least_squares(&x, &y).unwrap();
        assert!(
            (b[0] - 1.0).abs() < 1e-14 && (b[1] - 2.0).abs() < 1e-14,
            "{b:?}"
        );
        assert!((ssr - 4.0).abs() < 1e-13);
        let want = [[0.6, -0.2], [-0.2, 0.1]];
        for i in 0..2 {
            for j in 0..2 {
                assert!((cov[i][j] - want[i][j]).abs() < 1e-14, "{cov:?}");
            }
        }
        // A column that repeats another is refused.
        assert!(least_squares(&[vec![1.0; 3], vec![2.0; 3]], &[1.0, 2.0, 3.0]).is_none());
    }

    #[test]
    fn header_and_values() {
        let d = parse_wear_csv(
            "# comment\nstress_Pa,rate_m3_per_m,temperature_K\n1 GPa,1e-20,300\n\"2e9\",2e-20,350 K\n",
            "x.csv",
        )
        .unwrap();
        assert_eq!(d.rate_unit, RateUnit::M3PerM);
        assert_eq!(d.points[1].stress, 2e9);
        assert_eq!(d.points[1].temperature, Some(350.0));
        assert_eq!(d.points[0].line, 3);
        for bad in [
            "stress,rate\n",
            "stress_Pa,rate_m3\n",
            "stress_Pa,rate_m3_per_s,T\n",
            "",
        ] {
            let e = parse_wear_csv(bad, "x.csv").unwrap_err().to_string();
            assert!(
                e.contains("stress_Pa") && e.contains("rate_atoms_per_s"),
                "{e}"
            );
        }
        let e = parse_wear_csv("stress_Pa,rate_atoms_per_s\n1e9,0\n", "x.csv").unwrap_err();
        let e = e.to_string();
        assert!(
            e.contains("x.csv:2") && e.contains("rate_atoms_per_s") && e.contains("> 0"),
            "{e}"
        );
    }
    const DU: f64 = 1.0 * ELECTRONVOLT;
    const DV: f64 = 5e-29;
    const A: f64 = 1e12;

    /// Rates of the law itself (A e^{−(ΔU − σΔV)/k_BT}) at 4 stresses × `temps`,
    /// each times e^{noise(i)}.
    fn generated(temps: &[f64], noise: impl Fn(usize) -> f64) -> WearData {
        let mut rows = Vec::new();
        for &t in temps {
            for s in [0.5e9, 1.0e9, 1.5e9, 2.0e9] {
                let i = rows.len();
                let rate = A * (-(DU - s * DV) / (BOLTZMANN * t)).exp() * noise(i).exp();
                rows.push((s, rate, Some(t)));
            }
        }
        data(RateUnit::AtomsPerS, &rows)
    }

    /// Noise-free data from known ΔU = 1 eV, ΔV = 50 Å³, A = 1e12 /s come back to
    /// 1e-10 (the issue's requirement; QR on scaled columns gives ~1e-13).
    #[test]
    fn recovers_known_values_without_noise() {
        let f = fit_wear(
            &generated(&[300.0, 350.0, 400.0], |_| 0.0),
            &WearFitSettings::default(),
        )
        .unwrap();
        let du = f.activation_energy.unwrap().estimate;
        assert!((du / DU - 1.0).abs() < 1e-10, "{du}");
        assert!((f.activation_volume.estimate / DV - 1.0).abs() < 1e-10);
        assert!((f.ln_prefactor.estimate / A.ln() - 1.0).abs() < 1e-10);
        assert!((f.activation_energy_ev.unwrap().estimate - 1.0).abs() < 1e-10);
        assert!(!f.saturated, "{:?}", f.notes);
        assert_eq!(f.temperature_source, TemperatureSource::Data);
        assert_eq!((f.points, f.degrees_of_freedom), (12, 9));
    }

    /// 100 sets with 5 % log-normal noise (σ_ln = 0.05, from the crate's seeded
    /// generator and Box–Muller): the 95 % intervals of ΔU and ΔV each hold the
    /// true value in at least 90 sets (expected 95; P(fewer than 90 | 95 %) ≈ 0.02,
    /// and the seed is fixed, so the test is deterministic).
    #[test]
    fn intervals_cover_the_truth_under_noise() {
        let mut rng = crate::uq::rng::Rng::new(55, 0);
        let mut normal = move || {
            let u1 = crate::uq::rng::open_unit(rng.next_u64());
            let u2 = crate::uq::rng::open_unit(rng.next_u64());
            (-2.0 * u1.ln()).sqrt() * (2.0 * std::f64::consts::PI * u2).cos()
        };
        let (mut du_in, mut dv_in) = (0, 0);
        for _ in 0..100 {
            let noise: Vec<f64> = (0..12).map(|_| 0.05 * normal()).collect();
            let f = fit_wear(
                &generated(&[300.0, 350.0, 400.0], |i| noise[i]),
                &WearFitSettings::default(),
            )
            .unwrap();
            du_in += usize::from(f.activation_energy.unwrap().covers(DU));
            dv_in += usize::from(f.activation_volume.covers(DV));
            // The interval is the estimate ± t·se, t(0.975, 9) = 2.262.
            let e = f.activation_volume;
            assert!(
                (e.upper.unwrap() - e.estimate - 2.262157 * e.standard_error.unwrap()).abs()
                    < 1e-6 * e.standard_error.unwrap()
            );
        }
        assert!(du_in >= 90 && dv_in >= 90, "ΔU {du_in}, ΔV {dv_in} of 100");
    }

    /// One temperature: ΔU not identified, said; the intercept is ln(A e^{−ΔU/k_BT}).
    #[test]
    fn one_temperature_cannot_give_the_activation_energy() {
        let f = fit_wear(&generated(&[300.0], |_| 0.0), &WearFitSettings::default()).unwrap();
        assert!(f.activation_energy.is_none());
        assert!(f
            .notes
            .contains(&WearFitNote::ActivationEnergyNotIdentified { temperature: 300.0 }));
        let c = A.ln() - DU / (BOLTZMANN * 300.0);
        assert!((f.ln_prefactor.estimate / c - 1.0).abs() < 1e-10);
        assert!((f.activation_volume.estimate / DV - 1.0).abs() < 1e-10);
    }

    /// Rates of the full law, cap·(1 − exp(−Γ a₀/v)), whose top stresses reach the
    /// cap: the bend is found; the same stresses far below the cap are not flagged.
    #[test]
    fn saturation_is_said() {
        let rows_at = |c: f64| -> Vec<(f64, f64, Option<f64>)> {
            (0..8)
                .map(|i| {
                    let s = 0.5e9 + 0.25e9 * i as f64;
                    let x = c * (s * DV / (BOLTZMANN * 300.0)).exp();
                    (s, -(-x).exp_m1(), None)
                })
                .collect()
        };
        let settings = WearFitSettings {
            temperature: Some(300.0),
            speed: None,
        };
        // Γ a₀/v from 4e-7 at 0.5 GPa to 630 at 2.25 GPa: the top three at the cap.
        let f = fit_wear(&data(RateUnit::M3PerS, &rows_at(1e-9)), &settings).unwrap();
        assert!(f.saturated, "{:?}", f.notes);
        // Γ a₀/v at most 6e-7: ln rate departs from the line by 3e-7, below the
        // 1e-6 of the slope's span that counts.
        let f = fit_wear(&data(RateUnit::M3PerS, &rows_at(1e-18)), &settings).unwrap();
        assert!(!f.saturated, "{:?}", f.notes);
        assert!((f.activation_volume.estimate / DV - 1.0).abs() < 1e-5);
    }

    #[test]
    fn bad_input_names_the_field() {
        let s = WearFitSettings::default();
        let two = data(RateUnit::AtomsPerS, &[(1e9, 1.0, None), (2e9, 2.0, None)]);
        let e = fit_wear(&two, &s).unwrap_err().to_string();
        assert!(
            e.contains("2 points") && e.contains("at least 3 points"),
            "{e}"
        );
        let flat = data(
            RateUnit::AtomsPerS,
            &[(1e9, 1.0, None), (1e9, 2.0, None), (1e9, 3.0, None)],
        );
        let e = fit_wear(&flat, &s).unwrap_err().to_string();
        assert!(
            e.contains("one stress value only") && e.contains("2 distinct stresses"),
            "{e}"
        );
        let per_m = data(
            RateUnit::M3PerM,
            &[(1e9, 1.0, None), (2e9, 2.0, None), (3e9, 3.0, None)],
        );
        let e = fit_wear(&per_m, &s).unwrap_err().to_string();
        assert!(e.starts_with("speed") && e.contains("rate_m3_per_m"), "{e}");
        let f = fit_wear(
            &per_m,
            &WearFitSettings {
                speed: Some(1e-3),
                temperature: None,
            },
        )
        .unwrap();
        // Per second = per metre × v: the intercept moves by ln v, ΔV does not.
        let g = fit_wear(
            &per_m,
            &WearFitSettings {
                speed: Some(1.0),
                temperature: None,
            },
        )
        .unwrap();
        assert!((f.ln_prefactor.estimate - g.ln_prefactor.estimate - 1e-3f64.ln()).abs() < 1e-12);
        assert!((f.activation_volume.estimate / g.activation_volume.estimate - 1.0).abs() < 1e-12);
        assert!(f.notes.contains(&WearFitNote::DefaultTemperature {
            temperature: 298.15
        }));
        let per_s = data(
            RateUnit::M3PerS,
            &[(1e9, 1.0, None), (2e9, 2.0, None), (3e9, 3.0, None)],
        );
        let e = fit_wear(
            &per_s,
            &WearFitSettings {
                speed: Some(1.0),
                temperature: None,
            },
        )
        .unwrap_err();
        assert!(e.to_string().starts_with("speed"), "{e}");
    }
}
