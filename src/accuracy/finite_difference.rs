//! Finite-difference elasticities `d ln(wear rate) / d ln x` under several step
//! rules, and a high-accuracy reference for them.
//!
//! The rules mirror [`crate::model::sensitivity`] (which is central differences
//! with Richardson at δ = [`LOG_STEP`](crate::model::sensitivity::LOG_STEP) = 1e-3):
//! x → x·e^{±δ} (central, 2 evaluations) and also
//! x·e^{±2δ} with `D = D₁ + (D₁ − D₂)/3` (Richardson, 4 evaluations).
//!
//! The reference differentiates the *reference* wear rate
//! ([`reference_ln_wear_rate`]: the separation solved on the adaptive-quadrature
//! reference P̄, then Ā there) by central differences at δ_k = 0.04/2^k,
//! k = 0..6, extrapolated in δ² by a Neville (Richardson) tableau. ln W is
//! analytic in ln x on a branch, so the tableau converges like δ^{2k}; the
//! reference's own noise (≈ 1e-15 relative per value, the quadrature tolerance)
//! enters as ≈ 1e-15/δ times the tableau's weights, a few 1e-13 at the smallest
//! step. The entry with the smallest difference to its predecessor is taken and
//! that difference is the error estimate (≈ 1e-12 in practice; the step rules
//! compared have errors of 1e-10 and above).

use std::f64::consts::{LN_10, PI};

use super::reference::ReferenceModel;
use crate::model::{
    evaluate, AsperityLaw, AttractionKind, Coefficients, EvaluationOptions, Quadrature, Scene,
    SceneParameter, Status, WearArea,
};

/// A finite-difference rule on ln x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepRule {
    /// δ, the step in ln x.
    pub log_step: f64,
    /// Central difference at δ combined with 2δ by Richardson (4 evaluations), or plain central (2).
    pub richardson: bool,
}

impl StepRule {
    /// The rule `wearopt::model::sensitivity` uses.
    pub const DEFAULT: StepRule = StepRule {
        log_step: crate::model::sensitivity::LOG_STEP,
        richardson: true,
    };

    /// Wear-rate evaluations per elasticity.
    pub fn evaluations(&self) -> usize {
        if self.richardson {
            4
        } else {
            2
        }
    }

    /// A short label, `fd=richardson;delta=1e-4`.
    pub fn label(&self) -> String {
        format!(
            "fd={};delta={:e}",
            if self.richardson {
                "richardson"
            } else {
                "central"
            },
            self.log_step
        )
    }
}

/// The parameter's value in a scene (the table's reading, [`SceneParameter::get`]).
pub fn parameter_value(p: SceneParameter, scene: &Scene) -> f64 {
    p.get(scene)
}

/// The scene with the parameter multiplied by e^{log_step}, moved as the table
/// moves it ([`SceneParameter::set`]: a shared modulus moves both bodies, as
/// `eval`'s sensitivities and a design variable move it).
pub fn perturbed(scene: &Scene, p: SceneParameter, log_step: f64) -> Scene {
    let mut s = scene.clone();
    p.set(&mut s, p.get(scene) * log_step.exp());
    s
}

/// True when the parameter can be differentiated (finite, non-zero).
pub fn differentiable(p: SceneParameter, scene: &Scene) -> bool {
    let x = parameter_value(p, scene);
    x.is_finite() && x != 0.0
}

/// ln(wear rate) by the fast evaluator (None when separated or zero).
pub fn ln_wear_rate(scene: &Scene, quadrature: Quadrature) -> Option<f64> {
    let ev = evaluate(
        scene,
        &EvaluationOptions {
            pull_off: false,
            quadrature,
            work_of_adhesion: false,
        },
    );
    (ev.status == Status::Ok && ev.log10_wear_rate.is_finite()).then(|| {
        if ev.wear_rate > 1e-290 {
            ev.wear_rate.ln()
        } else {
            ev.log10_wear_rate * LN_10
        }
    })
}

/// The elasticity of the wear rate by a step rule with the fast evaluator.
pub fn elasticity(
    scene: &Scene,
    p: SceneParameter,
    rule: StepRule,
    quadrature: Quadrature,
) -> Option<f64> {
    let at = |j: f64| ln_wear_rate(&perturbed(scene, p, j * rule.log_step), quadrature);
    let d1 = (at(1.0)? - at(-1.0)?) / (2.0 * rule.log_step);
    if !rule.richardson {
        return Some(d1);
    }
    let d2 = (at(2.0)? - at(-2.0)?) / (4.0 * rule.log_step);
    Some(d1 + (d1 - d2) / 3.0)
}

/// The dimensional scales of a scene, recomputed from docs/model.md §1–3.
struct Scales {
    coefficients: Coefficients,
    /// ln of the force one unit of P̄ stands for (N).
    load_scale: f64,
    /// ln of k · A_n π N R σ / √(2π) (m³/m per unit Ā).
    ln_wear_scale: f64,
}

fn scales(scene: &Scene) -> Scales {
    let compliance = |e: f64, nu: f64| {
        if e.is_infinite() {
            0.0
        } else {
            (1.0 - nu * nu) / e
        }
    };
    let e = 1.0
        / (compliance(scene.youngs_modulus_a, scene.poisson_ratio_a)
            + compliance(scene.youngs_modulus_b, scene.poisson_ratio_b));
    let k = 4.0 * e / 3.0;
    let (r, s, n, an) = (
        scene.asperity_radius,
        scene.sigma,
        scene.asperity_density,
        scene.nominal_area,
    );
    let sqrt_2pi = (2.0 * PI).sqrt();
    // θ = K σ^{3/2} R^{1/2} / (γ R), c_a = √(6π/θ); c_h = π R^{1/2} H / (K σ^{1/2}).
    let c_a = (6.0 * PI * scene.work_of_adhesion * r.sqrt() / (k * s * s.sqrt())).sqrt();
    let c_h = PI * r.sqrt() * scene.hardness / (k * s.sqrt());
    Scales {
        coefficients: Coefficients::new(c_a, c_h),
        load_scale: k * n * r.sqrt() * s * s.sqrt() * an / sqrt_2pi,
        ln_wear_scale: (scene.wear_coefficient * an * PI * n * r * s / sqrt_2pi).ln(),
    }
}

/// ln(wear rate) of a scene by the reference: h solved on the reference P̄
/// (Newton in ln P̄ for a compressive load, in P̄ otherwise, safeguarded by a
/// bracket), started from the fast evaluator's separation, which only picks the
/// branch docs/model.md §4 names; then k·A_n π N R σ Ā(h)/√(2π). None when the fast
/// evaluator finds no contact or the reference solve fails, and under the
/// Lennard-Jones law (its reference is the adaptive quadrature of
/// `tests/all/lennard_jones_rough.rs`, not this one's closed forms).
pub fn reference_ln_wear_rate(scene: &Scene) -> Option<f64> {
    let law = reference_law(scene)?;
    let fast = evaluate(
        scene,
        &EvaluationOptions {
            pull_off: false,
            quadrature: Quadrature::default(),
            work_of_adhesion: false,
        },
    );
    let h0 = fast
        .nondimensional_separation
        .filter(|_| fast.status == Status::Ok)?;
    let sc = scales(scene);
    let model = ReferenceModel::with_law(sc.coefficients, law);
    let target = scene.load / sc.load_scale;
    let h = reference_separation(&model, target, h0)?;
    let at = model.at(h);
    let area = match scene.wear_area {
        WearArea::Total => at.area.value,
        WearArea::Plastic => at.plastic_area.value,
    };
    (area > 0.0).then(|| sc.ln_wear_scale + area.ln() - at.scale_exponent)
}

/// The scene's asperity law, its attraction range taken from Z0/σ here
/// (z0 = Z0/σ; Δ_h = Z0/(1.03 σ), docs/model.md §7).
fn reference_law(scene: &Scene) -> Option<AsperityLaw> {
    let law = scene.adhesion_model.law();
    // The reference integrates the closed-form laws (a tabulated law has its
    // own reference: `accuracy::lennard_jones`).
    let z = scene.interatomic_distance / scene.sigma;
    let range = match scene.attraction {
        AttractionKind::Dugdale if law.takes_attraction() => z / 1.03,
        _ => z,
    };
    law.closed_form_pull_off()
        .map(|_| law.with_range(scene.attraction, range))
}

/// The root of the reference P̄(h) = target nearest h0 on its monotone piece.
pub fn reference_separation(model: &ReferenceModel, target: f64, h0: f64) -> Option<f64> {
    // Residual and its h-derivative; in logs for a compressive target.
    let residual = |h: f64| -> (f64, f64) {
        let at = model.at(h);
        if let AsperityLaw::Dmt(_) = model.law {
            // Two scales (contact e^{κ(h)}, non-contact e^{κ(-h)}): values, which
            // neither underflow nor overflow at a scene's separation.
            let (p, dp) = at.total_load_value();
            return if target > 0.0 && p > 0.0 {
                (p.ln() - target.ln(), dp / p)
            } else {
                (p - target, dp)
            };
        }
        let (p, dp) = (at.load(), at.dload_dh.value);
        if target > 0.0 && p > 0.0 {
            (p.ln() - at.scale_exponent - target.ln(), dp / p)
        } else {
            let k = (-at.scale_exponent).exp();
            (p * k - target, dp * k)
        }
    };
    let mut h = h0;
    let (mut r, mut dr) = residual(h);
    for _ in 0..60 {
        if r == 0.0 || dr == 0.0 || !dr.is_finite() {
            break;
        }
        let step = (r / dr).clamp(-0.5, 0.5);
        h -= step;
        (r, dr) = residual(h);
        if step.abs() <= 2.0 * f64::EPSILON * h.abs().max(1.0) {
            break;
        }
    }
    // Accept only a root close to the fast one (same branch) that solves the equation.
    ((h - h0).abs() < 1e-6 * h0.abs().max(1.0) && r.abs() < 1e-12).then_some(h)
}

/// A reference elasticity with its error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferenceElasticity {
    /// d ln W / d ln x.
    pub value: f64,
    /// Estimated absolute error.
    pub error: f64,
}

/// The reference elasticity (module docs): Neville tableau in δ² over central
/// differences of the reference ln W at δ = 0.04/2^k, k = 0..6.
pub fn reference_elasticity(scene: &Scene, p: SceneParameter) -> Option<ReferenceElasticity> {
    const LEVELS: usize = 7;
    let mut table = [[0.0f64; LEVELS]; LEVELS];
    let mut best: Option<ReferenceElasticity> = None;
    for k in 0..LEVELS {
        let d = 0.04 / (1u32 << k) as f64;
        let plus = reference_ln_wear_rate(&perturbed(scene, p, d))?;
        let minus = reference_ln_wear_rate(&perturbed(scene, p, -d))?;
        table[k][0] = (plus - minus) / (2.0 * d);
        for j in 1..=k {
            let factor = 4f64.powi(j as i32);
            table[k][j] =
                table[k][j - 1] + (table[k][j - 1] - table[k - 1][j - 1]) / (factor - 1.0);
        }
        if k >= 1 {
            for j in 1..=k {
                let err = (table[k][j] - table[k - 1][j - 1]).abs();
                if best.is_none_or(|b| err < b.error) {
                    best = Some(ReferenceElasticity {
                        value: table[k][j],
                        error: err,
                    });
                }
            }
        }
    }
    best
}
