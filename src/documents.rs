//! The command line's JSON documents, computed in one place.
//!
//! `wearopt eval`, `optimize`, `pareto` and `roughness` each load an input, run
//! the library on it and hand the result to the report stage. This module is that
//! wiring, once: the command line and the Python package both call it, so their
//! results agree by construction. Each command has a function that computes the
//! result (for the callers that also write text, HTML or plots from it) and a
//! `*_json` function that returns the document `wearopt … --format json` writes,
//! as a [`serde_json::Value`] ([`crate::report::json_text`] gives the exact text).
//!
//! Errors are bad input, each message naming the input (`origin`: the file as
//! the caller names it), the field or option, the value and what is accepted.
//! Outcomes (separated, infeasible, not converged) are statuses inside the
//! documents, never errors.

use std::path::Path;

use serde_json::Value;

use crate::model::{self, Evaluation, EvaluationOptions, Sensitivity};
use crate::optimize::materials::{rank_materials, MaterialRanking};
use crate::optimize::pareto::{self, Front, Observer, ParetoError, Silent};
use crate::optimize::{ObserverFactory, OptimizeError, Optimum, ParetoSpec, Study};
use crate::problem::{catalogue, Problem};
use crate::report;
use crate::surface::psd::Psd;
use crate::surface::read::{self, parse_height_unit, Format, Overrides, ReadError};
use crate::surface::{analyse, level, Levelling, Roughness, Settings, SurfaceError};
use crate::units::{parse_quantity, Dimension};

/// Bad input to one of the documents (a command line program exits with code 2).
///
/// Every message is one line (the missing-`[pareto]` one adds an example block)
/// that names the input, the field or option and the accepted values; the
/// messages are the command line's.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum DocumentError {
    /// The problem's scene is not one the model can evaluate (a problem built
    /// or changed by hand; the loader builds only valid scenes).
    #[error("{origin}: scene: {error}")]
    Scene {
        /// The problem's origin.
        origin: String,
        /// The field, its value and what is accepted.
        error: crate::model::InputError,
    },
    /// `[design] materials` names a material the catalogue does not hold.
    #[error("{origin}: design.materials: {name:?} is not a catalogue material")]
    UnknownMaterial {
        /// The problem's origin.
        origin: String,
        /// The name as written.
        name: String,
    },
    /// The study cannot be optimised as defined.
    #[error("{origin}: {error}")]
    Optimize {
        /// The problem's origin.
        origin: String,
        /// What is wrong with the study.
        error: OptimizeError,
    },
    /// A Pareto front was asked of a problem without a `[pareto]` section.
    #[error("{origin}: no [pareto] section: add one to trade wear against adhesion, e.g.\n\n[pareto]\nadhesion = \"pull_off_force\"   # or \"work_of_adhesion\", \"elastic_adhesion_index\"\npoints = {default}\ndirection = \"low\"             # \"high\" when more adhesion is wanted (a latch, a switch)", default = ParetoSpec::DEFAULT_POINTS)]
    NoPareto {
        /// The problem's origin.
        origin: String,
    },
    /// A Pareto front was asked of a problem without an `[objective]`.
    #[error("{origin}: no [objective]: add [objective] minimize = \"wear_rate\" to say what the front trades against adhesion")]
    NoObjective {
        /// The problem's origin.
        origin: String,
    },
    /// The number of front points asked for is outside the accepted range.
    #[error("--points {points}: must lie in {min}..={max}", min = ParetoSpec::MIN_POINTS, max = ParetoSpec::MAX_POINTS)]
    Points {
        /// The number asked for.
        points: usize,
    },
    /// The Pareto sweep cannot run as defined.
    #[error("{origin}: {error}")]
    Pareto {
        /// The problem's origin.
        origin: String,
        /// What is wrong with the sweep.
        error: ParetoError,
    },
    /// A length option (`--cutoff`, `--pixel-size`) that is not a length.
    #[error("{option} {text:?}: {message}")]
    Length {
        /// The option, as the command line spells it.
        option: &'static str,
        /// The value as given.
        text: String,
        /// Why it is not accepted.
        message: String,
    },
    /// A length option that is zero, negative or infinite.
    #[error("{option} {text:?}: must be a positive finite length")]
    NotPositive {
        /// The option, as the command line spells it.
        option: &'static str,
        /// The value as given.
        text: String,
    },
    /// `--height-unit` that is not a length unit.
    #[error("--height-unit {text:?}: not a length unit; expected e.g. \"nm\", \"um\", \"m\" or \"1e-9\"")]
    HeightUnit {
        /// The value as given.
        text: String,
    },
    /// The height map cannot be read.
    #[error("{0}")]
    Read(ReadError),
    /// The height map cannot be analysed.
    #[error("{origin}: {error}")]
    Surface {
        /// The file as named by the caller.
        origin: String,
        /// What is wrong with the map.
        error: SurfaceError,
    },
}

/// The problem's scene, checked ([`crate::model::Scene::validate`]).
fn valid_scene(problem: &Problem, origin: &str) -> Result<(), DocumentError> {
    problem
        .scene
        .validate()
        .map_err(|error| DocumentError::Scene {
            origin: origin.to_string(),
            error,
        })
}

/// The optimiser's view of a problem's study (what every study command runs).
pub fn study(problem: &Problem) -> Study<'_> {
    Study {
        scene: &problem.scene,
        design: &problem.study.design,
        objective: problem.study.objective,
        constraints: &problem.study.constraints,
        settings: &problem.study.optimizer,
    }
}

// ---------------------------------------------------------------- eval

/// What `wearopt eval` computes for a scene.
#[derive(Debug, Clone)]
pub struct Eval {
    /// The evaluation, with the stiction verdict under the other asperity law
    /// where it applies ([`model::evaluate_with_other`]).
    pub evaluation: Evaluation,
    /// Wear-rate elasticities.
    pub sensitivities: Vec<Sensitivity>,
}

impl Eval {
    /// The report of this evaluation of `problem`.
    pub fn report<'a>(&'a self, problem: &'a Problem) -> report::eval::EvalReport<'a> {
        report::eval::EvalReport {
            name: &problem.name,
            scene: &problem.scene,
            input_notes: &problem.notes,
            scan: problem.scan.as_ref(),
            evaluation: &self.evaluation,
            sensitivities: &self.sensitivities,
        }
    }
}

/// Evaluates the problem's scene with the default options, as `wearopt eval`
/// does. `origin` names the problem in error messages.
pub fn eval(problem: &Problem, origin: &str) -> Result<Eval, DocumentError> {
    valid_scene(problem, origin)?;
    let options = EvaluationOptions::default();
    Ok(Eval {
        evaluation: model::evaluate_with_other(&problem.scene, &options),
        sensitivities: model::sensitivities(&problem.scene, options.quadrature),
    })
}

/// The document of `wearopt eval FILE --format json`.
pub fn eval_json(problem: &Problem, origin: &str) -> Result<Value, DocumentError> {
    Ok(report::eval::json_value(
        &eval(problem, origin)?.report(problem),
    ))
}

// ---------------------------------------------------------------- optimize

/// What `wearopt optimize` computes: one optimum, or a ranking when the study's
/// `[design]` lists materials.
#[derive(Debug, Clone)]
pub enum Optimized {
    /// The optimum of a single study.
    Optimum(Box<Optimum>),
    /// One study per material, ranked.
    Ranking(MaterialRanking),
}

impl Optimized {
    /// The JSON document of this result for the problem named `name`.
    pub fn json(&self, name: &str) -> Value {
        match self {
            Optimized::Optimum(o) => report::optimize::json_value(name, o),
            Optimized::Ranking(r) => report::materials::json_value(name, r),
        }
    }
}

/// Optimises the problem's study (ranks its materials when `[design]` lists
/// them), as `wearopt optimize` does; `observers` makes an argmin observer per
/// start. `origin` names the problem in error messages.
pub fn optimize(
    problem: &Problem,
    origin: &str,
    observers: Option<ObserverFactory>,
) -> Result<Optimized, DocumentError> {
    valid_scene(problem, origin)?;
    let optimize_error = |error| DocumentError::Optimize {
        origin: origin.to_string(),
        error,
    };
    if problem.study.materials.is_empty() {
        return crate::optimize::optimize_observed(&study(problem), observers)
            .map(|o| Optimized::Optimum(Box::new(o)))
            .map_err(optimize_error);
    }
    let materials = problem
        .study
        .materials
        .iter()
        .map(|n| {
            catalogue::lookup(n).ok_or_else(|| DocumentError::UnknownMaterial {
                origin: origin.to_string(),
                name: n.clone(),
            })
        })
        .collect::<Result<Vec<_>, _>>()?;
    rank_materials(&study(problem), &materials, observers)
        .map(Optimized::Ranking)
        .map_err(optimize_error)
}

/// The document of `wearopt optimize FILE --format json`.
pub fn optimize_json(problem: &Problem, origin: &str) -> Result<Value, DocumentError> {
    Ok(optimize(problem, origin, None)?.json(&problem.name))
}

// ---------------------------------------------------------------- pareto

/// The problem's `[pareto]` section with `points` (when given) in place of its
/// own; an error when the problem has no `[pareto]` or `[objective]`, or when
/// `points` is out of range.
pub fn pareto_spec(
    problem: &Problem,
    origin: &str,
    points: Option<usize>,
) -> Result<ParetoSpec, DocumentError> {
    let Some(mut spec) = problem.study.pareto else {
        return Err(DocumentError::NoPareto {
            origin: origin.to_string(),
        });
    };
    if problem.study.objective.is_none() {
        return Err(DocumentError::NoObjective {
            origin: origin.to_string(),
        });
    }
    if let Some(n) = points {
        if !(ParetoSpec::MIN_POINTS..=ParetoSpec::MAX_POINTS).contains(&n) {
            return Err(DocumentError::Points { points: n });
        }
        spec.points = n;
    }
    Ok(spec)
}

/// The wear–adhesion front of the problem's study under `spec` (from
/// [`pareto_spec`]), as `wearopt pareto` computes it; `observer` sees each point
/// as it is final.
pub fn pareto(
    problem: &Problem,
    origin: &str,
    spec: &ParetoSpec,
    observer: &dyn Observer,
) -> Result<Front, DocumentError> {
    valid_scene(problem, origin)?;
    pareto::pareto(&study(problem), spec, observer).map_err(|error| DocumentError::Pareto {
        origin: origin.to_string(),
        error,
    })
}

/// The document of `wearopt pareto FILE [--points N] --format json`.
pub fn pareto_json(
    problem: &Problem,
    origin: &str,
    points: Option<usize>,
) -> Result<Value, DocumentError> {
    let spec = pareto_spec(problem, origin, points)?;
    let front = pareto(problem, origin, &spec, &Silent)?;
    Ok(report::pareto::json_value(&problem.name, &front))
}

// ---------------------------------------------------------------- roughness

/// The options of `wearopt roughness`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoughnessOptions {
    /// Short-wavelength cut-off λs in metres; `None` for no filter.
    pub cutoff: Option<f64>,
    /// Form removal before the analysis.
    pub level: Levelling,
    /// Pixel size in metres, overriding the file's (required for `.npy` and a
    /// bare ASCII matrix).
    pub pixel_size: Option<f64>,
    /// Metres per stored height unit, overriding the file's (required for
    /// `.npy` and a bare ASCII matrix).
    pub height_unit: Option<f64>,
}

impl Default for RoughnessOptions {
    fn default() -> Self {
        RoughnessOptions {
            cutoff: None,
            level: Levelling::Plane,
            pixel_size: None,
            height_unit: None,
        }
    }
}

impl RoughnessOptions {
    /// The options from their written forms, as the command line takes them
    /// (`cutoff` and `pixel_size` like "100 nm", `height_unit` like "nm" or "1e-9").
    pub fn parse(
        cutoff: Option<&str>,
        level: Levelling,
        pixel_size: Option<&str>,
        height_unit: Option<&str>,
    ) -> Result<Self, DocumentError> {
        // As the command line checks them: pixel size, height unit, cut-off.
        let pixel_size = pixel_size.map(|t| length("--pixel-size", t)).transpose()?;
        let height_unit = height_unit
            .map(|t| {
                parse_height_unit(t).ok_or_else(|| DocumentError::HeightUnit {
                    text: t.to_string(),
                })
            })
            .transpose()?;
        let cutoff = cutoff.map(|t| length("--cutoff", t)).transpose()?;
        Ok(RoughnessOptions {
            cutoff,
            level,
            pixel_size,
            height_unit,
        })
    }
}

/// A positive finite length written with its unit.
fn length(option: &'static str, text: &str) -> Result<f64, DocumentError> {
    let x = parse_quantity(text, Dimension::Length).map_err(|e| DocumentError::Length {
        option,
        text: text.to_string(),
        message: e.to_string(),
    })?;
    if !(x.is_finite() && x > 0.0) {
        return Err(DocumentError::NotPositive {
            option,
            text: text.to_string(),
        });
    }
    Ok(x)
}

/// What `wearopt roughness` computes for a height map.
#[derive(Debug, Clone)]
pub struct RoughnessAnalysis {
    /// The file as named by the caller.
    pub file: String,
    /// Its format (by extension; ASCII when the extension says nothing).
    pub format: Format,
    /// The analysis.
    pub roughness: Roughness,
    /// The power spectral density of the levelled map (before any cut-off).
    pub psd: Psd,
}

impl RoughnessAnalysis {
    /// The report of this analysis.
    pub fn report(&self) -> report::roughness::RoughnessReport<'_> {
        report::roughness::RoughnessReport {
            file: &self.file,
            format: self.format,
            roughness: &self.roughness,
            psd: Some(&self.psd),
        }
    }
}

/// Reads and analyses the height map at `path`, as `wearopt roughness` does.
pub fn roughness(
    path: &Path,
    options: &RoughnessOptions,
) -> Result<RoughnessAnalysis, DocumentError> {
    let origin = path.display().to_string();
    let overrides = Overrides {
        pixel_size: options.pixel_size,
        height_unit: options.height_unit,
    };
    let format = Format::from_path(path).unwrap_or(Format::Ascii);
    let map = read::load(path, &overrides).map_err(DocumentError::Read)?;
    let settings = Settings {
        level: options.level,
        cutoff: options.cutoff,
    };
    let surface_error = |error| DocumentError::Surface {
        origin: origin.clone(),
        error,
    };
    let roughness = analyse(&map, &settings).map_err(surface_error)?;
    let levelled = level(&map, options.level).map_err(surface_error)?;
    let psd = Psd::of(&levelled);
    Ok(RoughnessAnalysis {
        file: origin,
        format,
        roughness,
        psd,
    })
}

/// The document of `wearopt roughness FILE --format json` with these options.
pub fn roughness_json(path: &Path, options: &RoughnessOptions) -> Result<Value, DocumentError> {
    Ok(report::roughness::json_value(
        &roughness(path, options)?.report(),
    ))
}
