//! Sensitivities of an output quantity ([`Quantity`]; `eval` reports the wear
//! rate's) as elasticities `d ln q / d ln x`, by central finite differences in
//! ln x with Richardson extrapolation. ln q is read from the quantity's log10
//! ([`Quantity::log10_value`]: the evaluation's log10 companions, so a wear rate
//! that underflows still has one).
//!
//! Step rule: x -> x e^{+-d} and x e^{+-2d}, d = 1e-3. The evaluator is accurate
//! to about eta = 1e-13 relative, so the rounding error of a central difference is
//! about eta/d = 1e-10, while Richardson's combination `D = D1 + (D1 - D2)/3`
//! leaves a truncation error O(d^4), estimated as `|D1 - D2|/3 (d/l)^2` for
//! derivatives that vary on scales l >= 0.1 in ln x, plus rounding `2 eta/d`.
//! Against a reference derivative to 1e-12 (`wearopt accuracy`, its rows of the
//! step rules; measured: 3.2e-12 worst over the shipped scenes, and why d = 1e-3:
//! docs/history.md) the test `finite_differences_against_the_reference_derivative`
//! holds the wear rate's elasticity in σ within 1e-8. Each parameter is moved as
//! the scene-parameter table moves it ([`SceneParameter::set`]).

use serde::Serialize;

use super::parameter::SceneParameter;
use super::quantity::Quantity;
use super::scene::Scene;
use super::wear::{evaluate, EvaluationOptions, Status};

/// The relative step δ in ln x.
pub const LOG_STEP: f64 = 1e-3;

/// The smallest scale in ln x on which the derivatives are assumed to vary.
pub const VARIATION_SCALE: f64 = 0.1;

/// Relative accuracy assumed of one evaluation of the quantity in the error estimate.
pub const EVALUATION_ACCURACY: f64 = 1e-13;

/// One elasticity with its error estimate, or the reason there is none.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sensitivity {
    /// Which parameter.
    pub parameter: SceneParameter,
    /// d ln q / d ln x; None where it is not defined.
    pub elasticity: Option<f64>,
    /// Estimated absolute error of the elasticity.
    pub error: Option<f64>,
    /// Why there is no value, when there is none.
    pub note: Option<SensitivityGap>,
}

/// Why an elasticity has no value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SensitivityGap {
    /// The scene itself has no value of the quantity (for the wear rate: no
    /// wear, separated or zero).
    NoWear,
    /// The parameter is infinite in the scene.
    InfiniteParameter,
    /// The parameter is zero in the scene (its limit).
    ZeroParameter,
    /// The contact separates within the finite-difference step.
    SeparatesWithinStep,
}

/// The elasticities of `quantity` with respect to E1, H, γ, σ and R
/// ([`SceneParameter::SENSITIVITIES`]), each where the quantity is positive and
/// finite at the scene and at the four steps around it. The pull-off search runs
/// only for a quantity that needs it ([`Quantity::needs_pull_off`]).
pub fn sensitivities(
    scene: &Scene,
    quadrature: super::quadrature::Quadrature,
    quantity: Quantity,
) -> Vec<Sensitivity> {
    let options = EvaluationOptions {
        pull_off: quantity.needs_pull_off(),
        quadrature,
        work_of_adhesion: false,
    };
    let ln_q = |sc: &Scene| -> Option<f64> {
        let ev = evaluate(sc, &options);
        if ev.status != Status::Ok {
            return None;
        }
        quantity
            .log10_value(&ev, sc)
            .filter(|l| l.is_finite())
            .map(|l| l * std::f64::consts::LN_10)
    };
    let base_ok = ln_q(scene).is_some();
    SceneParameter::SENSITIVITIES
        .iter()
        .map(|&p| {
            let x = p.get(scene);
            let none = |why: SensitivityGap| Sensitivity {
                parameter: p,
                elasticity: None,
                error: None,
                note: Some(why),
            };
            if !base_ok {
                return none(SensitivityGap::NoWear);
            }
            if x.is_infinite() {
                return none(SensitivityGap::InfiniteParameter);
            }
            if x == 0.0 {
                return none(SensitivityGap::ZeroParameter);
            }
            let at = |j: f64| {
                let mut sc = scene.clone();
                p.set(&mut sc, x * (j * LOG_STEP).exp());
                ln_q(&sc)
            };
            match (at(1.0), at(-1.0), at(2.0), at(-2.0)) {
                (Some(f1), Some(m1), Some(f2), Some(m2)) => {
                    let d1 = (f1 - m1) / (2.0 * LOG_STEP);
                    let d2 = (f2 - m2) / (4.0 * LOG_STEP);
                    let value = d1 + (d1 - d2) / 3.0;
                    // D1 = f' + c δ² + d δ⁴: (D1 - D2)/3 ≈ c δ² is what Richardson
                    // removed; what is left, 4 d δ⁴, is ≲ c δ² (δ/ℓ)² when the
                    // derivatives vary on scales ℓ ≥ 0.1 in ln x (10 % changes).
                    let error = (d1 - d2).abs() / 3.0 * (LOG_STEP / VARIATION_SCALE).powi(2)
                        + 2.0 * EVALUATION_ACCURACY / LOG_STEP;
                    Sensitivity {
                        parameter: p,
                        elasticity: Some(value),
                        error: Some(error),
                        note: None,
                    }
                }
                _ => none(SensitivityGap::SeparatesWithinStep),
            }
        })
        .collect()
}
