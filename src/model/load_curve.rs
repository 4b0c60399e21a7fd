//! The load–separation curve of a scene in SI units, for plots: W(d) over a range of
//! mean-plane separations around the operating point and the pull-off.

use serde::Serialize;

use super::scene::Scene;
use super::wear::{Evaluation, EvaluationOptions};

/// W(d) sampled on evenly spaced separations.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadCurve {
    /// (d in m, W in N), d increasing.
    pub points: Vec<(f64, f64)>,
    /// The operating point (d, W) when the surfaces are in contact.
    pub operating_point: Option<(f64, f64)>,
    /// The pull-off point (d, −pull-off force) when it was found.
    pub pull_off_point: Option<(f64, f64)>,
}

/// The curve of `scene` over h = d/σ from one σ below the lower of the operating and
/// pull-off separations to two σ above the higher (at most 40 σ wide), `points` ≥ 2
/// samples. The model is the one [`super::evaluate`] uses, with the same quadrature.
pub fn load_curve(
    scene: &Scene,
    evaluation: &Evaluation,
    options: &EvaluationOptions,
    points: usize,
) -> LoadCurve {
    let model = super::wear::model_of(scene, options.quadrature);
    let s = scene.sigma;
    let h_op = evaluation.nondimensional_separation;
    let h_po = evaluation.nondimensional_pull_off_separation;
    let (lo, hi) = match (h_op, h_po) {
        (Some(a), Some(b)) => (a.min(b), a.max(b)),
        (Some(a), None) | (None, Some(a)) => (a, a),
        (None, None) => (0.0, 3.0),
    };
    let from = lo - 1.0;
    let to = (hi + 2.0).min(from + 40.0);
    let n = points.max(2);
    let pts = (0..n)
        .map(|i| {
            let h = from + (to - from) * i as f64 / (n - 1) as f64;
            (h * s, model.at(h).load().value() * evaluation.load_scale)
        })
        .filter(|(d, w)| d.is_finite() && w.is_finite())
        .collect();
    LoadCurve {
        points: pts,
        operating_point: evaluation.separation.map(|d| (d, scene.load)),
        pull_off_point: evaluation
            .pull_off_separation
            .zip(evaluation.pull_off_force)
            .map(|(d, f)| (d, -f)),
    }
}
