//! Finite-difference sensitivities of the study functions, with error estimates.
//!
//! Step rule: in unit coordinates (the box is [0, 1]^n, log-scaled), central
//! differences with h = 1e-4 and 2h, combined by Richardson extrapolation,
//! `D = (4 D_h - D_2h)/3`. With `D_h = f' + c h² + d h⁴`, `|D_h - D_2h|/3 ≈ c h²`
//! is the error Richardson removed and `4 d h⁴` the one left; assuming the
//! derivatives vary on scales ℓ ≥ 0.01 of the unit box, `d h⁴ ≲ c h² (h/ℓ)²`, so
//! the estimate reported is `|D_h - D_2h|/3 · (h/ℓ)² + 3η/h`, the second term the
//! rounding from an evaluator accurate to η ≈ 1e-13 in ln units. Near a bound the stencil shifts inside the box (one-sided second-order
//! differences `(-3f₀ + 4f₁ - f₂)/(2h)`, with the same pair-of-steps estimate).
//! Evaluations run in parallel with rayon; the result does not depend on the
//! thread count because each component is computed from the same points.

use rayon::prelude::*;

use super::functions::{Point, StudyFunctions};

/// The unit-coordinate step h.
pub const STEP: f64 = 1e-4;

/// The smallest scale (in unit coordinates) on which derivatives are assumed to vary.
pub const VARIATION_SCALE: f64 = 0.01;

/// Accuracy of one evaluation of ln(objective) or a row, used in the estimate.
pub const EVALUATION_NOISE: f64 = 1e-13;

/// Gradients of the objective and every row at one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Gradients {
    /// ∇ ln(objective).
    pub objective: Vec<f64>,
    /// ∇ g_j, one vector per row.
    pub rows: Vec<Vec<f64>>,
    /// The largest estimated absolute error over all components.
    pub error: f64,
    /// Model evaluations spent.
    pub evaluations: usize,
}

/// Gradients at `at` (whose values are known). None if the stencil leaves the
/// contact region in every direction it could use.
pub fn gradients(f: &StudyFunctions, at: &Point) -> Option<Gradients> {
    let n = f.dim();
    let m = f.rows.len();
    // Stencil offsets per variable: ±h, ±2h centred, or shifted inside the box.
    let stencils: Vec<[f64; 4]> =
        at.x.iter()
            .map(|&xi| {
                if xi - 2.0 * STEP >= 0.0 && xi + 2.0 * STEP <= 1.0 {
                    [STEP, -STEP, 2.0 * STEP, -2.0 * STEP]
                } else if xi - 2.0 * STEP < 0.0 {
                    [STEP, 2.0 * STEP, 3.0 * STEP, 4.0 * STEP]
                } else {
                    [-STEP, -2.0 * STEP, -3.0 * STEP, -4.0 * STEP]
                }
            })
            .collect();
    let jobs: Vec<(usize, f64)> = (0..n)
        .flat_map(|i| stencils[i].iter().map(move |&d| (i, d)))
        .collect();
    let values: Vec<Option<Point>> = jobs
        .par_iter()
        .map(|&(i, d)| {
            let mut x = at.x.clone();
            x[i] += d;
            f.at_from(&x, at.hints)
        })
        .collect();
    let mut objective = vec![0.0; n];
    let mut rows = vec![vec![0.0; n]; m];
    let mut error = 0.0f64;
    for i in 0..n {
        let pts: Vec<&Point> = values[4 * i..4 * i + 4].iter().flatten().collect();
        if pts.len() < 4 {
            return None;
        }
        let centred = stencils[i][1] < 0.0 && stencils[i][0] > 0.0;
        let sign = stencils[i][0].signum();
        let component = |get: &dyn Fn(&Point) -> f64| -> (f64, f64) {
            let f0 = get(at);
            let (d_h, d_2h) = if centred {
                (
                    (get(pts[0]) - get(pts[1])) / (2.0 * STEP),
                    (get(pts[2]) - get(pts[3])) / (4.0 * STEP),
                )
            } else {
                // One-sided, second order, with steps h and 2h.
                let (f1, f2, f4) = (get(pts[0]), get(pts[1]), get(pts[3]));
                (
                    sign * (-3.0 * f0 + 4.0 * f1 - f2) / (2.0 * STEP),
                    sign * (-3.0 * f0 + 4.0 * f2 - f4) / (4.0 * STEP),
                )
            };
            let value = (4.0 * d_h - d_2h) / 3.0;
            let err = (d_h - d_2h).abs() / 3.0 * (STEP / VARIATION_SCALE).powi(2)
                + 3.0 * EVALUATION_NOISE / STEP;
            (value, err)
        };
        let (g, e) = component(&|p: &Point| p.objective);
        objective[i] = g;
        error = error.max(e);
        for (j, row) in rows.iter_mut().enumerate() {
            let (g, e) = component(&|p: &Point| p.rows[j]);
            row[i] = g;
            error = error.max(e);
        }
    }
    Some(Gradients {
        objective,
        rows,
        error,
        evaluations: values.len(),
    })
}
