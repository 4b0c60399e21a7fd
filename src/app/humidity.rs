//! `wearopt humidity`: a scene across relative humidity (docs/model.md §10): the
//! separation, capillary load, pull-off force, apparent work of adhesion Γ, wet
//! fraction and wear rate at evenly spaced humidities, and the threshold humidity
//! where Γ reaches ten times its dry value.

use crate::model::{self, Environment, EvaluationOptions, Scene, Status};
use crate::problem::Problem;

use super::{valid_scene, AppError, OptionName};

/// The most humidities one run evaluates.
pub const MAX_POINTS: usize = 100_000;

/// Γ at the threshold humidity over Γ in dry air (docs/model.md §10).
pub const THRESHOLD_RATIO: f64 = 10.0;

/// The options of `wearopt humidity`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HumidityOptions {
    /// The first relative humidity, in [0, 1).
    pub from: f64,
    /// The last (inclusive), in [from, 1).
    pub to: f64,
    /// How many evenly spaced humidities, ≥ 2.
    pub points: usize,
}

impl HumidityOptions {
    /// Refuses values outside their ranges, naming the options.
    pub fn validate(&self) -> Result<(), AppError> {
        for (name, x) in [("from", self.from), ("to", self.to)] {
            if !(0.0..1.0).contains(&x) {
                return Err(AppError::Invalid {
                    options: vec![(OptionName(name), x.to_string())],
                    rule: "a relative humidity must lie in [0, 1) (0: dry air, 1: saturated, where every gap floods), or in [0 %, 100 %) written as a percentage".into(),
                });
            }
        }
        if self.from > self.to {
            return Err(AppError::Order {
                low: (OptionName("from"), self.from.to_string()),
                high: (OptionName("to"), self.to.to_string()),
            });
        }
        if !(2..=MAX_POINTS).contains(&self.points) {
            return Err(AppError::Invalid {
                options: vec![(OptionName("points"), self.points.to_string())],
                rule: format!("must lie in 2..={MAX_POINTS}"),
            });
        }
        if self.from == self.to {
            return Err(AppError::EmptyRange {
                value: self.from,
                points: self.points,
            });
        }
        Ok(())
    }
}

/// A relative humidity as an option gives it: a fraction (`0.5`) or a percentage
/// (`"50 %"`, `"50%"`), as a problem file's `relative_humidity` is. Its range is
/// checked by [`HumidityOptions::validate`]; a bare number above 1 and at most 100,
/// a percentage written without its sign in all likelihood, is refused here with
/// the guess.
pub fn relative_humidity(option: OptionName, text: &str) -> Result<f64, AppError> {
    let invalid = |rule: String| AppError::Invalid {
        options: vec![(option, text.to_string())],
        rule,
    };
    let x = crate::units::parse_quantity(text, crate::units::Dimension::Dimensionless).map_err(
        |_| {
            invalid(
                "a relative humidity is a fraction in [0, 1) such as 0.5, or a percentage such as \"50 %\""
                    .to_string(),
            )
        },
    )?;
    if crate::units::is_bare_number(text) && x > 1.0 && x < 100.0 {
        return Err(invalid(format!(
            "a relative humidity must lie in [0, 1) (0: dry air, 1: saturated, where every gap floods), or in [0 %, 100 %) written as a percentage: did you mean \"{} %\"?",
            text.trim()
        )));
    }
    Ok(x)
}

/// The scene at one humidity.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HumidityRow {
    /// RH.
    pub relative_humidity: f64,
    /// The evaluation's status under the load.
    pub status: Status,
    /// d (m); None when the surfaces separate.
    pub separation: Option<f64>,
    /// The capillary load at the operating point (N, ≤ 0); None when separated.
    pub capillary_load: Option<f64>,
    /// The pull-off force, capillary pull included (N).
    pub pull_off_force: Option<f64>,
    /// Γ (J/m²).
    pub apparent_work_of_adhesion: Option<f64>,
    /// 1 - e^{-F_w} at the operating point; None when separated.
    pub wetted_fraction: Option<f64>,
    /// k A_r (m³/m).
    pub wear_rate: f64,
}

/// What `wearopt humidity` computes.
#[derive(Debug, Clone)]
pub struct HumidityDocument {
    /// The problem's name.
    pub name: String,
    /// The scene (its environment at the problem's humidity, or None).
    pub scene: Scene,
    /// The air the sweep varies the humidity of: the problem's `[environment]`, or
    /// water at 25 °C wetting both bodies (contact angle 0) when it has none.
    pub environment: Environment,
    /// Whether the problem file had an `[environment]` table.
    pub environment_given: bool,
    /// The rows, in increasing humidity.
    pub rows: Vec<HumidityRow>,
    /// Γ in dry air (RH = 0), J/m².
    pub dry_work_of_adhesion: Option<f64>,
    /// The pull-off force in dry air (N).
    pub dry_pull_off_force: Option<f64>,
    /// The lowest humidity at which Γ reaches [`THRESHOLD_RATIO`] times its dry
    /// value, if it does at or below the last humidity asked for.
    pub threshold_humidity: Option<f64>,
    /// Below this humidity the Kelvin radius is under 0.5 nm, where the continuum
    /// Kelvin–Laplace picture is doubtful (RH = exp(-γ_L V_m / (R_g T · 0.5 nm)));
    /// None where the liquid has no surface tension.
    pub continuum_humidity: Option<f64>,
}

impl HumidityDocument {
    /// True when no row is a usable result (every one not converged or out of
    /// range): the study finished without one, as `eval`'s failed evaluation
    /// (exit code 1).
    pub fn failed(&self) -> bool {
        self.rows
            .iter()
            .all(|r| matches!(r.status, Status::NotConverged | Status::OutOfRange))
    }
}

/// The scene evaluated at humidity `rh`.
fn row(scene: &Scene, environment: &Environment, rh: f64) -> HumidityRow {
    let s = Scene {
        environment: Some(Environment {
            relative_humidity: rh,
            ..*environment
        }),
        ..scene.clone()
    };
    let ev = model::evaluate(&s, &EvaluationOptions::default());
    // A scene with an environment always reports its humidity block.
    let h = ev.humidity;
    HumidityRow {
        relative_humidity: rh,
        status: ev.status,
        separation: ev.separation,
        capillary_load: h.and_then(|h| h.capillary_load),
        pull_off_force: ev.pull_off_force,
        apparent_work_of_adhesion: h.and_then(|h| h.apparent_work_of_adhesion),
        wetted_fraction: h.and_then(|h| h.wetted_fraction),
        wear_rate: ev.wear_rate,
    }
}

/// The problem's scene at `options.points` humidities from `options.from` to
/// `options.to`. `origin` names the problem in error messages.
pub fn humidity(
    problem: &Problem,
    origin: &str,
    options: &HumidityOptions,
) -> Result<HumidityDocument, AppError> {
    humidity_with(problem, origin, options, &super::Quiet)
}

/// As [`humidity`], telling `progress` of each humidity (and of dry air) as it is
/// evaluated.
pub fn humidity_with(
    problem: &Problem,
    origin: &str,
    options: &HumidityOptions,
    progress: &dyn super::Progress,
) -> Result<HumidityDocument, AppError> {
    options.validate()?;
    valid_scene(problem, origin)?;
    let scene = &problem.scene;
    let environment = scene.environment.unwrap_or_default();
    // Evenly spaced, both ends exact: the humidities a study's range holds at.
    let humidities = model::HumidityRange {
        min: options.from,
        max: options.to,
        points: options.points,
        design_given: false,
    }
    .humidities();
    progress.begin(humidities.len() + 1);
    let rows: Vec<HumidityRow> = humidities
        .into_iter()
        .map(|rh| {
            let r = row(scene, &environment, rh);
            progress.advance();
            r
        })
        .collect();
    let dry = row(scene, &environment, 0.0);
    progress.advance();
    let threshold = threshold(scene, &environment, &rows, &dry);
    let gamma = environment.liquid.surface_tension(environment.temperature);
    let continuum = (gamma > 0.0).then(|| {
        (-gamma * environment.liquid.molar_volume()
            / (model::capillary::GAS_CONSTANT
                * environment.temperature
                * model::capillary::MIN_KELVIN_RADIUS))
            .exp()
    });
    Ok(HumidityDocument {
        name: problem.name.clone(),
        scene: scene.clone(),
        environment,
        environment_given: scene.environment.is_some(),
        rows,
        dry_work_of_adhesion: dry.apparent_work_of_adhesion,
        dry_pull_off_force: dry.pull_off_force,
        threshold_humidity: threshold,
        continuum_humidity: continuum,
    })
}

/// The lowest humidity where Γ reaches ten times its dry value: the first sampled
/// humidity at or above it brackets it with the one before (or with dry air), and
/// bisection on RH finds it to 1e-12 (Γ grows with RH: the Kelvin length and the
/// wet area grow; docs/model.md §10). None when no sample reaches it, or where dry
/// Γ is 0 (no adhesion to multiply).
fn threshold(
    scene: &Scene,
    environment: &Environment,
    rows: &[HumidityRow],
    dry: &HumidityRow,
) -> Option<f64> {
    let dry_gamma = dry.apparent_work_of_adhesion.filter(|g| *g > 0.0)?;
    let target = THRESHOLD_RATIO * dry_gamma;
    let reached = |r: &HumidityRow| r.apparent_work_of_adhesion.is_some_and(|g| g >= target);
    let i = rows.iter().position(reached)?;
    let mut lo = if i == 0 {
        0.0
    } else {
        rows[i - 1].relative_humidity
    };
    let mut hi = rows[i].relative_humidity;
    if i == 0 && reached(dry) {
        return Some(0.0);
    }
    while hi - lo > 1e-12 {
        let mid = 0.5 * (lo + hi);
        if reached(&row(scene, environment, mid)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    Some(hi)
}
