//! `wearopt pareto`: the wear–adhesion front of a study with a `[pareto]` section,
//! by the ε-constraint method, with the study's constraints at its designs.

use crate::model::{self, EvaluationOptions};
use crate::optimize::functions::quantity_value;
use crate::optimize::pareto as front;
use crate::optimize::{DesignSpace, Study};
use crate::problem::Problem;

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

/// The front the problem asks for: its `[pareto]` section with `options.points`
/// (when given) in place of its own; an error when the problem has no `[pareto]`
/// or `[objective]`, or when the points are out of range.
pub fn plan(
    problem: &Problem,
    origin: &str,
    options: &ParetoOptions,
) -> Result<ParetoPlan, AppError> {
    let Some(mut spec) = problem.study.pareto else {
        return Err(AppError::NoPareto {
            origin: origin.to_string(),
        });
    };
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
