//! One asperity (docs/model.md §3): the JKR elastic law in the loading branch, the
//! plastic law beyond the transition, and the single-asperity pull-off.
//! Lengths are over σ, loads over K R^{1/2} σ^{3/2}.

use super::integrals::Model;

/// Apparent Hertz interference Δ1 for an actual interference Δ ≥ 0: the root
/// Δ1 ≥ Δ0 = c_d^{4/3} of `Δ = Δ1 - c_d Δ1^{1/4}` (eq. 10, corrected).
pub fn apparent_interference(model: &Model, delta: f64) -> f64 {
    model.s_of_interference(delta).powi(4)
}

/// p_e(Δ) = Δ1^{3/2} - c_a Δ1^{3/4} (eq. 1) at actual interference Δ ≥ 0.
pub fn elastic_load(model: &Model, delta: f64) -> f64 {
    let s3 = model.s_of_interference(delta).powi(3);
    s3 * (s3 - model.coefficients.c_a)
}

/// p_p(Δ) = c_p Δ - c_0 (eq. 2 with r_p² = 2RΔσ).
pub fn plastic_load(model: &Model, delta: f64) -> f64 {
    let c = &model.coefficients;
    c.c_p * delta - c.c_0
}

/// The asperity load law of the model: elastic up to Δc, plastic beyond.
pub fn load(model: &Model, delta: f64) -> f64 {
    if delta <= model.critical_interference() {
        elastic_load(model, delta)
    } else {
        plastic_load(model, delta)
    }
}

/// The JKR pull-off of one asperity, `min over Δ1 of (Δ1^{3/2} - c_a Δ1^{3/4}) = -c_a²/4`,
/// i.e. -(3/2)πγR dimensionally. It lies at Δ < 0, on the unloading neck the
/// loading model leaves out.
pub fn jkr_pull_off(model: &Model) -> f64 {
    let c_a = model.coefficients.c_a;
    -0.25 * c_a * c_a
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Coefficients;

    #[test]
    fn jkr_values() {
        let m = Model::new(Coefficients::from_indices(2.0, 1.0));
        let c = m.coefficients;
        // At Δ = 0: -c_a c_d / 3, the JKR -(4/3)πγR (docs/model.md §3).
        assert!((elastic_load(&m, 0.0) - c.load_at_touch()).abs() < 1e-14);
        // Δ1(0) = Δ0 = c_d^{4/3} (eq. 11, corrected).
        assert!((apparent_interference(&m, 0.0) / c.c_d.powf(4.0 / 3.0) - 1.0).abs() < 1e-14);
        // The minimum over Δ1 of p_e, found numerically, is -c_a²/4.
        let mut best = f64::INFINITY;
        for i in 1..200_000 {
            let d1: f64 = i as f64 * 1e-5;
            best = best.min(d1.powf(1.5) - c.c_a * d1.powf(0.75));
        }
        assert!((best / jkr_pull_off(&m) - 1.0).abs() < 1e-8);
        // Inverse map: Δ = Δ1 - c_d Δ1^{1/4}, checked relative to Δ1 since
        // recomputing Δ from Δ1 cancels when Δ ≪ Δ0.
        for &d in &[1e-9, 0.3, 7.0, 1e6] {
            let d1 = apparent_interference(&m, d);
            assert!((d1 - c.c_d * d1.powf(0.25) - d).abs() < 1e-14 * d1, "{d}");
        }
    }
}
