//! `wearopt pareto`: the wear–adhesion front of a study with a `[pareto]` section,
//! by the ε-constraint method, with the study's constraints at its designs.

use crate::model::{self, EvaluationOptions};
use crate::optimize::functions::quantity_value;
use crate::optimize::pareto as front;
use crate::optimize::{DesignSpace, Study};
use crate::problem::{DesignKeys, Problem};

use super::{study, valid_scene, AppError, OptionName};

pub use crate::optimize::pareto::{
    Front, FrontPoint, FrontStatus, Observer, ParetoError, Reference, Silent,
};
pub use crate::optimize::{
    AdhesionMeasure, Constraint, Objective, ParetoDirection, ParetoSpec, SceneParameter,
};

/// The options of `wearopt pareto`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ParetoOptions {
    /// Points on the curve, in place of the `[pareto]` section's
    /// ([`ParetoSpec::MIN_POINTS`] to [`ParetoSpec::MAX_POINTS`]).
    pub points: Option<usize>,
    /// Also evaluate the study's constraint quantities at every design of the front
    /// (what the HTML page tabulates): one model evaluation per design.
    pub constraint_values: bool,
    /// The adhesion measure, in place of the `[pareto]` section's.
    pub adhesion: Option<AdhesionMeasure>,
    /// Which end of it is preferred, in place of the `[pareto]` section's.
    pub direction: Option<ParetoDirection>,
}

/// The adhesion measure named `text` (`pull_off_force`, …) for the option `option`.
pub fn measure(option: OptionName, text: &str) -> Result<AdhesionMeasure, AppError> {
    use crate::optimize::Named;
    AdhesionMeasure::from_name(text.trim()).ok_or_else(|| AppError::Invalid {
        options: vec![(option, format!("{text:?}"))],
        rule: format!("must be one of: {}", AdhesionMeasure::names().join(", ")),
    })
}

/// The direction named `text` (`low` or `high`) for the option `option`.
pub fn direction(option: OptionName, text: &str) -> Result<ParetoDirection, AppError> {
    use crate::optimize::Named;
    ParetoDirection::from_name(text.trim()).ok_or_else(|| AppError::Invalid {
        options: vec![(option, format!("{text:?}"))],
        rule: format!("must be one of: {}", ParetoDirection::names().join(", ")),
    })
}

impl ParetoOptions {
    /// Whether any part of the front is asked for on the command line (then a
    /// problem without `[pareto]` takes the defaults for the rest).
    pub fn any_front(&self) -> bool {
        self.points.is_some() || self.adhesion.is_some() || self.direction.is_some()
    }
}

/// What is known of a front before it is computed: what a streamed output's head
/// says.
#[derive(Debug, Clone, PartialEq)]
pub struct ParetoPlan {
    /// The problem's name.
    pub name: String,
    /// The `[pareto]` section with the points asked for.
    pub spec: ParetoSpec,
    /// The objective the front minimises.
    pub objective: Objective,
    /// The design variables, in file order.
    pub names: Vec<SceneParameter>,
    /// The study's constraints.
    pub constraints: Vec<Constraint>,
}

/// The study's constraint quantities at the designs of a front (SI, in the order of
/// the study's constraints; None where a quantity does not exist at a design).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ConstraintValues {
    /// At each point of [`Front::points`], in order.
    pub points: Vec<Vec<Option<f64>>>,
    /// At the least-wear design of the study.
    pub least_wear: Vec<Option<f64>>,
    /// At the baseline design, when the front has one.
    pub baseline: Option<Vec<Option<f64>>>,
}

/// What `wearopt pareto` computes: everything its reports print.
#[derive(Debug, Clone, PartialEq)]
pub struct ParetoDocument {
    /// What the front was asked for.
    pub plan: ParetoPlan,
    /// The front.
    pub front: Front,
    /// The constraint quantities at its designs, when asked for.
    pub constraint_values: Option<ConstraintValues>,
}

/// The front the problem asks for: its `[pareto]` section with `options.points`,
/// `adhesion` and `direction` (when given) in place of its own — without a
/// section, those and the defaults (`pull_off_force`, 15 points, `low`); an
/// error when the problem has neither a `[pareto]` section nor any of those
/// options, no `[objective]`, or the points are out of range.
pub fn plan(
    problem: &Problem,
    origin: &str,
    options: &ParetoOptions,
) -> Result<ParetoPlan, AppError> {
    let mut spec = match problem.study.pareto {
        Some(spec) => spec,
        // No section: what the command line gives, the defaults for the rest
        // (pull_off_force, the file's-default point count, direction low).
        None if options.any_front() => ParetoSpec {
            adhesion: AdhesionMeasure::PullOffForce,
            points: ParetoSpec::DEFAULT_POINTS,
            direction: ParetoDirection::Low,
        },
        None => {
            return Err(AppError::NoPareto {
                origin: origin.to_string(),
            })
        }
    };
    if let Some(a) = options.adhesion {
        spec.adhesion = a;
    }
    if let Some(d) = options.direction {
        spec.direction = d;
    }
    if problem.study.design.is_empty() {
        return Err(AppError::Invalid {
            options: vec![(OptionName("adhesion"), spec.adhesion.as_str().to_string())],
            rule: format!(
                "{origin}: a front needs something to vary: add a [design] table with at least one variable"
            ),
        });
    }
    if spec.adhesion == AdhesionMeasure::WorkOfAdhesion
        && !problem
            .study
            .design
            .iter()
            .any(|v| v.name == SceneParameter::WorkOfAdhesion)
    {
        return Err(AppError::Invalid {
            options: vec![(OptionName("adhesion"), spec.adhesion.as_str().to_string())],
            rule: format!(
                "{origin}: trading against work_of_adhesion needs it among the design variables: add work_of_adhesion = {} to [design]",
                SceneParameter::WorkOfAdhesion.example_bounds()
            ),
        });
    }
    let Some(objective) = problem.study.objective else {
        return Err(AppError::NoObjective {
            origin: origin.to_string(),
        });
    };
    if let Some(n) = options.points {
        if !(ParetoSpec::MIN_POINTS..=ParetoSpec::MAX_POINTS).contains(&n) {
            return Err(AppError::Invalid {
                options: vec![(OptionName("points"), n.to_string())],
                rule: format!(
                    "must lie in {}..={}",
                    ParetoSpec::MIN_POINTS,
                    ParetoSpec::MAX_POINTS
                ),
            });
        }
        spec.points = n;
    }
    Ok(ParetoPlan {
        name: problem.name.clone(),
        spec,
        objective,
        names: problem.study.design.iter().map(|d| d.name).collect(),
        constraints: problem.study.constraints.clone(),
    })
}

/// The wear–adhesion front of the problem's study, as `wearopt pareto` computes it;
/// `observer` sees each point as it is final (a streamed output's rows).
pub fn pareto(
    problem: &Problem,
    origin: &str,
    options: &ParetoOptions,
    observer: &dyn Observer,
) -> Result<ParetoDocument, AppError> {
    let plan = plan(problem, origin, options)?;
    valid_scene(problem, origin)?;
    let study = study(problem);
    let front = front::pareto(&study, &plan.spec, observer).map_err(|error| AppError::Pareto {
        origin: origin.to_string(),
        error,
    })?;
    let constraint_values = options
        .constraint_values
        .then(|| constraint_values(&study, &front));
    Ok(ParetoDocument {
        plan,
        front,
        constraint_values,
    })
}

/// The study's constraint quantities at every design of the front, the least-wear
/// design and the baseline: one model evaluation each, of the scene the optimiser's
/// own design space builds from the design.
fn constraint_values(study: &Study, front: &Front) -> ConstraintValues {
    let space = DesignSpace::new(study.scene, study.design);
    let options = EvaluationOptions::default();
    let at = |design: &[f64]| -> Vec<Option<f64>> {
        let scene = space.scene_at(&space.unit(design));
        let ev = model::evaluate(&scene, &options);
        study
            .constraints
            .iter()
            .map(|c| quantity_value(c.quantity, &ev, &scene).filter(|v| v.is_finite()))
            .collect()
    };
    ConstraintValues {
        points: front.points.iter().map(|p| at(&p.design)).collect(),
        least_wear: at(&front.least_wear.design),
        baseline: front.baseline.as_ref().map(|b| at(&b.design)),
    }
}
