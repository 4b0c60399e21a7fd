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
