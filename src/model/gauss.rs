//! Gauss–Legendre rules on [-1, 1], computed once per order by Newton's method
//! on the Legendre recurrence (nodes and weights to about 1 ulp).

use std::sync::OnceLock;

/// A Gauss–Legendre rule: `∫_{-1}^{1} f ≈ Σ w_i f(x_i)`.
#[derive(Debug)]
pub struct GaussRule {
    /// Nodes in (-1, 1), ascending.
    pub nodes: Vec<f64>,
    /// Positive weights summing to 2.
    pub weights: Vec<f64>,
}

/// The Gauss–Kronrod 7–15 pair (QUADPACK's qk15): the 15 Kronrod nodes on [0, 1)
/// (each ± but the last, 0). Checked by `kronrod_pair_is_exact` (`model/work.rs`):
/// degree 22 and 13. The adaptive rules of `work.rs`, `accuracy/reference.rs` and the
/// stress-assisted law's tests share the pair.
#[allow(clippy::excessive_precision)] // QUADPACK's published digits
pub const KRONROD_NODES: [f64; 8] = [
    0.991_455_371_120_812_639_206_854_697_526_329,
    0.949_107_912_342_758_524_526_189_684_047_851,
    0.864_864_423_359_769_072_789_712_788_640_926,
    0.741_531_185_599_394_439_863_864_773_280_788,
    0.586_087_235_467_691_130_294_144_845_693_013,
    0.405_845_151_377_397_166_906_606_412_076_961,
    0.207_784_955_007_898_467_600_689_403_773_245,
    0.0,
];
/// The 15-point Kronrod weights of [`KRONROD_NODES`].
#[allow(clippy::excessive_precision)] // QUADPACK's published digits
pub const KRONROD_WEIGHTS: [f64; 8] = [
    0.022_935_322_010_529_224_963_732_008_058_970,
    0.063_092_092_629_978_553_290_700_663_189_204,
    0.104_790_010_322_250_183_839_876_322_541_518,
    0.140_653_259_715_525_918_745_189_590_510_238,
    0.169_004_726_639_267_902_826_583_426_598_550,
    0.190_350_578_064_785_409_913_256_402_421_014,
    0.204_432_940_075_298_892_414_161_999_234_649,
    0.209_482_141_084_727_828_012_999_174_891_714,
];
/// The 7-point Gauss weights of the odd-indexed [`KRONROD_NODES`] (1, 3, 5, 7).
#[allow(clippy::excessive_precision)] // QUADPACK's published digits
pub const KRONROD_GAUSS_WEIGHTS: [f64; 4] = [
    0.129_484_966_168_869_693_270_611_432_679_082,
    0.279_705_391_489_276_667_901_467_771_423_780,
    0.381_830_050_505_118_944_950_369_775_488_975,
    0.417_959_183_673_469_387_755_102_040_816_327,
];

/// The orders a [`crate::model::Quadrature`] may ask for.
pub const ORDERS: [usize; 8] = [4, 6, 8, 12, 16, 20, 24, 32];

fn compute(n: usize) -> GaussRule {
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    let nf = n as f64;
    for i in 0..n.div_ceil(2) {
        // Tricomi's initial guess for the i-th largest root.
        let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (nf + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, x);
            for k in 2..=n {
                let kf = k as f64;
                let p2 = ((2.0 * kf - 1.0) * x * p1 - (kf - 1.0) * p0) / kf;
                p0 = p1;
                p1 = p2;
            }
            dp = nf * (x * p1 - p0) / (x * x - 1.0);
            let dx = p1 / dp;
            x -= dx;
            if dx.abs() <= 1e-17 {
                break;
            }
        }
        let w = 2.0 / ((1.0 - x * x) * dp * dp);
        nodes[n - 1 - i] = x;
        nodes[i] = -x;
        weights[n - 1 - i] = w;
        weights[i] = w;
    }
    GaussRule { nodes, weights }
}

/// The rule of order `n`, one of [`ORDERS`].
///
/// # Panics
/// If `n` is not in [`ORDERS`]; settings are validated before they get here.
pub fn rule(n: usize) -> &'static GaussRule {
    static RULES: [OnceLock<GaussRule>; ORDERS.len()] = [const { OnceLock::new() }; ORDERS.len()];
    let slot = ORDERS
        .iter()
        .position(|&m| m == n)
        .expect("Gauss–Legendre order validated against ORDERS");
    RULES[slot].get_or_init(|| compute(n))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_exactly() {
        // An n-point rule is exact for degree 2n-1: ∫ x^k over [-1,1] = 2/(k+1) for even k.
        for &n in &ORDERS {
            let r = rule(n);
            for k in 0..(2 * n) {
                let exact = if k % 2 == 0 {
                    2.0 / (k as f64 + 1.0)
                } else {
                    0.0
                };
                let got: f64 = r
                    .nodes
                    .iter()
                    .zip(&r.weights)
                    .map(|(x, w)| w * x.powi(k as i32))
                    .sum();
                assert!((got - exact).abs() < 1e-14, "n={n} k={k} got {got}");
            }
        }
    }
}
