//! Bad input to a command, worded by the adapter that took it: flags for the command
//! line, keyword arguments for Python.

use std::fmt;

use crate::calibrate::CalibrationError;
use crate::figures::{FigureError, MAX_POINTS as FIGURE_MAX_POINTS};
use crate::model::AdhesionModel;
use crate::optimize::pareto::ParetoError;
use crate::optimize::{OptimizeError, ParetoSpec};
use crate::problem::ProblemError;
use crate::surface::read::ReadError;
use crate::surface::SurfaceError;
use crate::sweep::SweepError;

/// Whose words an error is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Vocabulary {
    /// The command line's: `--pixel-size "20 nm"`.
    Flags,
    /// Python's keyword arguments: `pixel_size="20 nm"`.
    Keywords,
}

/// An option of a command, by its keyword argument's name (snake case); the command
/// line spells it as a flag (`pixel_size` is `--pixel-size`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OptionName(pub &'static str);

impl OptionName {
    /// The option in `vocabulary`'s spelling.
    pub fn word(self, vocabulary: Vocabulary) -> String {
        match vocabulary {
            Vocabulary::Flags => format!("--{}", self.0.replace('_', "-")),
            Vocabulary::Keywords => self.0.to_string(),
        }
    }

    /// The option with its value: `--theta -1` or `theta=-1`.
    fn with(self, value: &str, vocabulary: Vocabulary) -> String {
        match vocabulary {
            Vocabulary::Flags => format!("{} {value}", self.word(vocabulary)),
            Vocabulary::Keywords => format!("{}={value}", self.word(vocabulary)),
        }
    }
}

/// Bad input to one of the commands (a command line program exits with code 2).
///
/// Every message is one line (the missing-`[pareto]` one adds an example block)
/// that names the input, the field or option and the accepted values.
/// [`fmt::Display`] words it for the command line; [`AppError::message`] in either
/// vocabulary.
#[derive(Debug)]
#[non_exhaustive]
pub enum AppError {
    /// The problem file cannot be read or is not valid.
    Problem(ProblemError),
    /// The problem's scene is not one the model can evaluate (a problem built
    /// or changed by hand; the loader builds only valid scenes).
    Scene {
        /// The problem's origin.
        origin: String,
        /// The field, its value and what is accepted.
        error: crate::model::InputError,
    },
    /// `[design] materials` names a material the catalogue does not hold.
    UnknownMaterial {
        /// The problem's origin.
        origin: String,
        /// The name as written.
        name: String,
    },
    /// The study cannot be optimised as defined.
    Optimize {
        /// The problem's origin.
        origin: String,
        /// What is wrong with the study.
        error: OptimizeError,
    },
    /// A Pareto front was asked of a problem without a `[pareto]` section.
    NoPareto {
        /// The problem's origin.
        origin: String,
    },
    /// An uncertainty study was asked of a problem without `[uncertainty]`.
    NoUncertainty {
        /// The problem's origin.
        origin: String,
    },
    /// A reliability study was asked of a problem without `[[uncertainty.event]]`.
    NoEvent {
        /// The problem's origin.
        origin: String,
    },
    /// A Pareto front was asked of a problem without an `[objective]`.
    NoObjective {
        /// The problem's origin.
        origin: String,
    },
    /// The Pareto sweep cannot run as defined.
    Pareto {
        /// The problem's origin.
        origin: String,
        /// What is wrong with the sweep.
        error: ParetoError,
    },
    /// Options whose values are outside their accepted ranges (one, or a pair that
    /// only together is wrong: `--from 3 --to 1`).
    Invalid {
        /// The options and their values as given.
        options: Vec<(OptionName, String)>,
        /// What is accepted, in words that name no option.
        rule: String,
    },
    /// Two options that must be in increasing order are not: `--from 3 --to 1`.
    Order {
        /// The option that should be the lower, and its value.
        low: (OptionName, String),
        /// The option that should be the higher, and its value.
        high: (OptionName, String),
    },
    /// A range of separations with one value but many points.
    EmptyRange {
        /// The value of both ends.
        value: f64,
        /// The points asked for.
        points: usize,
    },
    /// The model's coefficients cannot be formed from these indices.
    UndefinedCoefficients {
        /// θ.
        theta: f64,
        /// λ.
        lambda: f64,
    },
    /// One element of an array argument is bad.
    Element {
        /// Its index in the flattened arrays.
        index: usize,
        /// What is wrong with it.
        error: Box<AppError>,
    },
    /// `attraction` or `attraction_range` given with an asperity law that takes
    /// neither (JKR).
    AttractionNotTaken,
    /// `attraction` given with a law whose attraction is its own (the
    /// Lennard-Jones law; its range it takes).
    AttractionRefused {
        /// The law.
        law: AdhesionModel,
    },
    /// A law that needs a range (its attraction's, or its own) asked for without it.
    WithoutRange {
        /// The law.
        law: AdhesionModel,
    },
    /// The height map cannot be read.
    Read(ReadError),
    /// The height map cannot be solved for contact (too small, missing points).
    Contact {
        /// The map as the caller named it.
        origin: String,
        /// What the contact solver cannot take.
        error: crate::contact::ContactError,
    },
    /// The height map cannot be analysed.
    Surface {
        /// The file as named by the caller.
        origin: String,
        /// What is wrong with the map.
        error: SurfaceError,
    },
    /// The friction data or the fit's settings are not usable.
    Calibration(CalibrationError),
    /// The sweep cannot run as defined.
    Sweep {
        /// The problem's origin.
        origin: String,
        /// The number of samples asked for.
        samples: u64,
        /// What is wrong.
        error: SweepError,
    },
    /// The figures' settings are out of range.
    Figures(FigureError),
    /// Parts of an uncertainty study that cannot be merged.
    Part {
        /// The part (a file name), or "N parts" when the set is at fault.
        origin: String,
        /// What is wrong.
        error: crate::app::uncertainty::PartError,
    },
    /// A directory or file the command must write cannot be made.
    Output {
        /// The option that named it.
        option: OptionName,
        /// The path.
        path: String,
        /// Why.
        reason: String,
    },
}

impl AppError {
    /// The message in `vocabulary`'s words.
    pub fn message(&self, vocabulary: Vocabulary) -> String {
        let opt = |name: &'static str| OptionName(name).word(vocabulary);
        match self {
            AppError::Problem(e) => e.to_string(),
            AppError::Scene { origin, error } => format!("{origin}: scene: {error}"),
            AppError::UnknownMaterial { origin, name } => {
                format!("{origin}: design.materials: {name:?} is not a catalogue material")
            }
            AppError::Optimize { origin, error } => format!("{origin}: {error}"),
            AppError::NoPareto { origin } => format!(
                "{origin}: no [pareto] section: give the front on the command line (--adhesion, --points, --direction: any one, the rest defaulting to pull_off_force, {0} points, low) or add a section to trade wear against adhesion, e.g.\n\n[pareto]\nadhesion = \"pull_off_force\"   # or \"work_of_adhesion\", \"elastic_adhesion_index\"\npoints = {0}\ndirection = \"low\"             # \"high\" when more adhesion is wanted (a latch, a switch)",
                ParetoSpec::DEFAULT_POINTS
            ),
            AppError::NoUncertainty { origin } => format!(
                "{origin}: no [uncertainty] section: say which inputs are uncertain, e.g.\n\n[uncertainty]\nsamples = 4096\noutputs = [\"wear_rate\", \"pull_off_force\"]\n[uncertainty.inputs]\nsigma = {{ distribution = \"lognormal\", median = \"3 nm\", factor = 1.5 }}\nwork_of_adhesion = {{ distribution = \"normal\", mean = \"0.1 J/m^2\", sd = \"0.01 J/m^2\" }}"
            ),
            AppError::NoEvent { origin } => format!(
                "{origin}: the reliability method needs an event: add [[uncertainty.event]] name = \"stiction\" (or \"wear_out\", or quantity = \"wear_rate\", above = \"50 um^3/m\")"
            ),
            AppError::NoObjective { origin } => format!(
                "{origin}: no [objective]: add [objective] minimize = \"wear_rate\" to say what the front trades against adhesion"
            ),
            AppError::Pareto { origin, error } => format!("{origin}: {error}"),
            AppError::Invalid { options, rule } => {
                let given: Vec<String> = options
                    .iter()
                    .map(|(o, v)| o.with(v, vocabulary))
                    .collect();
                let sep = match vocabulary {
                    Vocabulary::Flags => " ",
                    Vocabulary::Keywords => ", ",
                };
                format!("{}: {rule}", given.join(sep))
            }
            AppError::Order { low, high } => format!(
                "{} is above {}: give an increasing range",
                low.0.with(&low.1, vocabulary),
                high.0.with(&high.1, vocabulary)
            ),
            AppError::EmptyRange { value, points } => format!(
                "{} and {} are both {value}: with {} the range must not be empty",
                opt("from"),
                opt("to"),
                OptionName("points").with(&points.to_string(), vocabulary)
            ),
            AppError::UndefinedCoefficients { theta, lambda } => {
                format!("coefficients are undefined for θ = {theta}, λ = {lambda}")
            }
            AppError::Element { index, error } => {
                format!("{} (element {index})", error.message(vocabulary))
            }
            AppError::AttractionNotTaken => {
                let (takes, default) = (AdhesionModel::taking_attraction().as_str(), AdhesionModel::default().as_str());
                match vocabulary {
                    Vocabulary::Flags => format!("--attraction and --attraction-range apply to --adhesion-model {takes} only (the default is {default})"),
                    Vocabulary::Keywords => format!("attraction and attraction_range apply to adhesion_model=\"{takes}\" only (the default is \"{default}\")"),
                }
            }
            AppError::AttractionRefused { law } => {
                let (takes, name) = (AdhesionModel::taking_attraction().as_str(), law.as_str());
                match vocabulary {
                    Vocabulary::Flags => format!("--attraction applies to --adhesion-model {takes} only: the {name} law's attraction is its own (give its range with --attraction-range Z0/σ)"),
                    Vocabulary::Keywords => format!("attraction applies to adhesion_model=\"{takes}\" only: the \"{name}\" law's attraction is its own (give its range with attraction_range = Z0/σ)"),
                }
            }
            AppError::WithoutRange { law } => format!(
                "{} needs {}: {} (e.g. 0.1)",
                OptionName("adhesion_model").with(
                    &if vocabulary == Vocabulary::Flags {
                        law.as_str().to_string()
                    } else {
                        format!("{:?}", law.as_str())
                    },
                    vocabulary
                ),
                match vocabulary {
                    Vocabulary::Flags if law.takes_attraction() => "--attraction-range D".to_string(),
                    Vocabulary::Flags => "--attraction-range Z0/σ".to_string(),
                    Vocabulary::Keywords => "attraction_range".to_string(),
                },
                law.law().range_meaning()
            ),
            AppError::Read(e) => read_message(e, vocabulary),
            AppError::Surface { origin, error } => format!("{origin}: {error}"),
            AppError::Part { origin, error } => format!("{origin}: {error}"),
            AppError::Contact { origin, error } => format!("{origin}: {error}"),
            AppError::Calibration(e) => calibration_message(e, vocabulary),
            AppError::Sweep {
                origin,
                samples,
                error,
            } => match error {
                SweepError::Samples { .. } | SweepError::Grid { .. } => {
                    format!("{}: {error}", OptionName("samples").with(&samples.to_string(), vocabulary))
                }
                _ => format!("{origin}: {error}"),
            },
            AppError::Figures(FigureError::Points(n)) => format!(
                "{}: must lie in 3..={FIGURE_MAX_POINTS} (a least-squares line needs 3 points)",
                OptionName("points").with(&n.to_string(), vocabulary)
            ),
            AppError::Figures(FigureError::LoadRange { min, max }) => format!(
                "{} {}: need 0 < {} < {} < inf (compressive loads, e.g. 0.05 and 5)",
                OptionName("load_min").with(&min.to_string(), vocabulary),
                OptionName("load_max").with(&max.to_string(), vocabulary),
                opt("load_min").trim_start_matches('-'),
                opt("load_max").trim_start_matches('-'),
            ),
            AppError::Output {
                option,
                path,
                reason,
            } => format!(
                "{}: cannot create the directory: {reason}",
                option.with(path, vocabulary)
            ),
        }
    }
}

/// A read error, with the way to supply a missing pixel size or height unit named
/// in the caller's words.
fn read_message(e: &ReadError, vocabulary: Vocabulary) -> String {
    let (path, format, what, option, example) = match e {
        ReadError::NoPixelSize { path, format } => {
            (path, format, "pixel size", "pixel_size", "\"10 nm\"")
        }
        ReadError::NoHeightUnit { path, format } => {
            (path, format, "height unit", "height_unit", "\"nm\"")
        }
        _ => return e.to_string(),
    };
    let how = match vocabulary {
        Vocabulary::Flags => format!(
            "{} (command line) or {option} (problem file [roughness])",
            OptionName(option).word(vocabulary)
        ),
        Vocabulary::Keywords => {
            format!("the keyword argument {option}= or {option} in a problem file's [roughness]")
        }
    };
    format!("{path}: the {format} file gives no {what}; supply it with {how}, e.g. {example}")
}

/// A calibration error with its settings named in the caller's words.
fn calibration_message(e: &CalibrationError, vocabulary: Vocabulary) -> String {
    match e {
        CalibrationError::Setting {
            name,
            value,
            expected,
        } => {
            let expected = match vocabulary {
                Vocabulary::Flags => expected.clone(),
                Vocabulary::Keywords => expected.replace(
                    "--materials steel,silicon",
                    "materials=[\"steel\", \"silicon\"]",
                ),
            };
            format!("{}: {expected}", OptionName(name).with(value, vocabulary))
        }
        CalibrationError::FrictionFalls { .. } if vocabulary == Vocabulary::Keywords => {
            e.to_string().replace("fix μ with --mu", "fix μ with mu=")
        }
        CalibrationError::FrictionBelowFloor { .. } if vocabulary == Vocabulary::Keywords => {
            e.to_string().replace(
                "give a smaller --mu, or use --fit-mu",
                "give a smaller mu=, or fit_mu=True",
            )
        }
        _ => e.to_string(),
    }
}

impl fmt::Display for AppError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message(Vocabulary::Flags))
    }
}

impl std::error::Error for AppError {}

impl From<ProblemError> for AppError {
    fn from(e: ProblemError) -> Self {
        AppError::Problem(e)
    }
}

impl From<CalibrationError> for AppError {
    fn from(e: CalibrationError) -> Self {
        AppError::Calibration(e)
    }
}
