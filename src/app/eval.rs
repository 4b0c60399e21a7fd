//! `wearopt eval`: one scene evaluated, with its sensitivities.

use crate::model::{self, Evaluation, EvaluationOptions, LoadCurve, Scene, Sensitivity, Status};
use crate::problem::{InputNote, Problem, ScanSource};

use super::{valid_scene, AppError};

/// Samples of the load–separation curve the HTML pages draw (dense enough that the
/// stretch around the operating point stays smooth when the page shows only that).
pub const LOAD_CURVE_POINTS: usize = 1001;

/// The options of `wearopt eval`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct EvalOptions {
    /// Also sample the load–separation curve at this many separations (what the
    /// HTML page draws; [`LOAD_CURVE_POINTS`]); `None`: no curve.
    pub load_curve_points: Option<usize>,
}

/// What `wearopt eval` computes for a scene: everything its report prints.
#[derive(Debug, Clone)]
pub struct EvalDocument {
    /// The problem's name.
    pub name: String,
    /// The scene as evaluated.
    pub scene: Scene,
    /// Notes from reading the problem file (catalogue values taken, overrides, …).
    pub input_notes: Vec<InputNote>,
    /// The measured scan σ, R and N came from, if any.
    pub scan: Option<ScanSource>,
    /// The evaluation, with the stiction verdict under the other asperity law
    /// where it applies ([`model::evaluate_with_other`]).
    pub evaluation: Evaluation,
    /// Wear-rate elasticities.
    pub sensitivities: Vec<Sensitivity>,
    /// The load–separation curve, when asked for.
    pub load_curve: Option<LoadCurve>,
    /// For a scene built on a scan: the exact contact on that scan at the
    /// operating point, or why there is none.
    pub scan_contact: Option<Result<super::contact::ScanContact, String>>,
}

impl EvalDocument {
    /// Whether the evaluation has no usable result (not converged, or out of the
    /// model's range): the command line's exit code 1.
    pub fn failed(&self) -> bool {
        matches!(
            self.evaluation.status,
            Status::NotConverged | Status::OutOfRange
        )
    }
}

/// Evaluates the problem's scene with the default options, as `wearopt eval`
/// does. `origin` names the problem in error messages.
pub fn eval(
    problem: &Problem,
    origin: &str,
    options: &EvalOptions,
) -> Result<EvalDocument, AppError> {
    valid_scene(problem, origin)?;
    let evaluation_options = EvaluationOptions::default();
    let evaluation = model::evaluate_with_other(&problem.scene, &evaluation_options);
    let load_curve = options
        .load_curve_points
        .map(|n| model::load_curve(&problem.scene, &evaluation, &evaluation_options, n));
    let scan_contact = problem.scan.as_ref().map(|scan| {
        super::contact::scan_contact(scan, &problem.scene, evaluation.equivalent_modulus)
    });
    Ok(EvalDocument {
        scan_contact,
        name: problem.name.clone(),
        scene: problem.scene.clone(),
        input_notes: problem.notes.clone(),
        scan: problem.scan.clone(),
        sensitivities: model::sensitivities(
            &problem.scene,
            evaluation_options.quadrature,
            model::Quantity::WearRate,
        ),
        evaluation,
        load_curve,
    })
}
