//! Finite-difference gradients of a [`NonlinearProgram`], with error estimates.
//!
//! Step rule: for variable i, `h = fd_step · max(|x_i|, scale_i)` (the
//! problem's own scale, never the width of the box). Three accuracies:
//!
//! * **forward** (one evaluation per variable): `(f(x+h) - f(x))/h` (error
//!   ~ f″h/2, about 1e-4 relative at the default step): enough to steer the
//!   first steps from a start far from a solution;
//! * **central** (two evaluations per variable): `D_h`, the central difference
//!   with h (error ~ f‴h²/6, about 1e-9 relative at the default step): what a
//!   step far from a solution needs;
//! * **Richardson** (four per variable): central differences with h and 2h
//!   combined, `D = (4 D_h - D_2h)/3`: what the KKT test at tolerance 1e-8 needs.
//!
//! For the Richardson form: With
//! `D_h = f' + c h² + d h⁴`, `|D_h - D_2h|/3 ≈ c h²` is the error Richardson
//! removed; what is left is of order `c h² (h/ℓ)²` for derivatives varying on
//! a scale ℓ; the estimate reported is `|D_h - D_2h|/3 · (fd_step/0.01)² +
//! 3 η (1 + |f|)/h` with η = 1e-13 for the evaluation noise. Where a bound is
//! closer than 2h the stencil moves inside the box (one-sided second-order
//! differences `(-3f₀ + 4f₁ - f₂)/(2h)` with h and 2h; the forward difference
//! then points into the box); where a stencil point
//! cannot be evaluated the other side, then halved steps, are tried. Every
//! stencil point lies inside the bounds. Evaluations run in parallel (rayon);
//! the result does not depend on the thread count.

use rayon::prelude::*;

use super::program::{NonlinearProgram, Values};

/// Accuracy of one evaluation relative to 1 + |value|, used in the estimate.
pub const EVALUATION_NOISE: f64 = 1e-13;

/// How many stencil points per variable a gradient uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Accuracy {
    /// Forward (or, on a bound, backward) differences: one point per variable.
    Forward,
    /// Central (or one-sided second-order) differences: two points.
    Central,
    /// Richardson-extrapolated central differences: four points.
    Richardson,
}

impl Accuracy {
    /// Evaluations per variable.
    pub fn points(self) -> usize {
        match self {
            Accuracy::Forward => 1,
            Accuracy::Central => 2,
            Accuracy::Richardson => 4,
        }
    }
}

/// Gradients of the objective and every row at one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Gradients {
    /// ∇f.
    pub objective: Vec<f64>,
    /// ∇g_j, one vector per row.
    pub rows: Vec<Vec<f64>>,
    /// The largest estimated absolute error over all components.
    pub error: f64,
    /// Evaluations spent.
    pub evaluations: usize,
    /// The accuracy they were computed with.
    pub accuracy: Accuracy,
    /// The values at each variable's preferred stencil when it was used
    /// (None where a fallback stencil was needed): more accurate gradients
    /// at the same point reuse these points instead of evaluating them again.
    pub stencils: Vec<Option<Vec<Values>>>,
}

/// Where the four stencil points of one variable lie (offsets from x_i).
fn stencil(x: f64, lo: f64, hi: f64, h: f64, flip: bool) -> Option<[f64; 4]> {
    let centred = [h, -h, 2.0 * h, -2.0 * h];
    let up = [h, 2.0 * h, 3.0 * h, 4.0 * h];
    let down = [-h, -2.0 * h, -3.0 * h, -4.0 * h];
    let fits = |s: &[f64; 4]| s.iter().all(|d| x + d >= lo && x + d <= hi);
    let order: [[f64; 4]; 3] = if flip {
        [down, up, centred]
    } else {
        [centred, up, down]
    };
    order.into_iter().find(|s| fits(s))
}

/// Gradients at `x` (whose values `at` are known), with steps scaled by
/// `fd_step`, to the `accuracy` asked (forward, central or one-sided
/// second-order, and Richardson differences use the first one, two and four
/// points of the same stencil). None when no stencil of any tried step can be evaluated.
/// `same_point`: gradients computed earlier at this very x (same `at`, step
/// and bounds), whose stencil values are reused rather than evaluated again
/// (evaluations are deterministic, so the result is the same either way).
#[allow(clippy::too_many_arguments)]
pub(crate) fn gradients<P: NonlinearProgram + Sync + ?Sized>(
    problem: &P,
    x: &[f64],
    at: &Values,
    fd_step: f64,
    scale: &[f64],
    bounds: &(Vec<f64>, Vec<f64>),
    accuracy: Accuracy,
    same_point: Option<&Gradients>,
) -> Option<Gradients> {
    let used = accuracy.points();
    let n = x.len();
    let m = at.constraints.len();
    let mut objective = vec![0.0; n];
    let mut rows = vec![vec![0.0; n]; m];
    let mut error = 0.0f64;
    let mut evaluations = 0;
    // First try every variable with its preferred stencil in one parallel batch.
    let base_h: Vec<f64> = (0..n).map(|i| fd_step * x[i].abs().max(scale[i])).collect();
    let first: Vec<Option<[f64; 4]>> = (0..n)
        .map(|i| stencil(x[i], bounds.0[i], bounds.1[i], base_h[i], false))
        .collect();
    // The preferred stencils are the same at the same point: what was
    // evaluated there already is taken, not evaluated again.
    let known: Vec<Vec<Values>> = (0..n)
        .map(|i| {
            same_point
                .and_then(|g| g.stencils.get(i).cloned().flatten())
                .filter(|_| first[i].is_some())
                .map(|mut v| {
                    v.truncate(used);
                    v
                })
                .unwrap_or_default()
        })
        .collect();
    let jobs: Vec<(usize, f64)> = (0..n)
        .flat_map(|i| {
            let skip = known[i].len();
            first[i]
                .into_iter()
                .flat_map(move |s| s.into_iter().take(used).skip(skip))
                .map(move |d| (i, d))
        })
        .collect();
    let values: Vec<Option<Values>> = jobs
        .par_iter()
        .map(|&(i, d)| {
            let mut y = x.to_vec();
            y[i] += d;
            problem.evaluate(&y, &at.warm_start)
        })
        .collect();
    evaluations += values.len();
    let mut k = 0;
    let mut stencils = vec![None; n];
    for i in 0..n {
        let mut found = None;
        if let Some(s) = first[i] {
            let fresh = used - known[i].len();
            let mut pts = known[i].clone();
            pts.extend(values[k..k + fresh].iter().flatten().cloned());
            k += fresh;
            if pts.len() == used {
                stencils[i] = Some(pts.clone());
                found = Some((s, pts, base_h[i]));
            }
        }
        // Fall back: the other side, then smaller steps, serially.
        let mut h = base_h[i];
        let mut tries = 0;
        while found.is_none() && tries < 8 {
            let flip = tries % 2 == 0;
            if tries > 0 && flip {
                h *= 0.25;
            }
            tries += 1;
            let Some(s) = stencil(x[i], bounds.0[i], bounds.1[i], h, flip) else {
                continue;
            };
            let pts: Vec<Option<Values>> = s[..used]
                .par_iter()
                .map(|&d| {
                    let mut y = x.to_vec();
                    y[i] += d;
                    problem.evaluate(&y, &at.warm_start)
                })
                .collect();
            evaluations += used;
            if pts.iter().all(Option::is_some) {
                found = Some((s, pts.into_iter().flatten().collect(), h));
            }
        }
        let (s, pts, h) = found?;
        let centred = s[0] > 0.0 && s[1] < 0.0;
        let sign = s[0].signum();
        let component = |get: &dyn Fn(&Values) -> f64| -> (f64, f64) {
            let f0 = get(at);
            let noise = 3.0 * EVALUATION_NOISE * (1.0 + f0.abs()) / h;
            if accuracy == Accuracy::Forward {
                // The first stencil point is x + h, or x ∓ h inside the box.
                let d = sign * (get(&pts[0]) - f0) / h;
                return (d, noise);
            }
            if accuracy == Accuracy::Central {
                let d_h = if centred {
                    (get(&pts[0]) - get(&pts[1])) / (2.0 * h)
                } else {
                    sign * (-3.0 * f0 + 4.0 * get(&pts[0]) - get(&pts[1])) / (2.0 * h)
                };
                // Without a second step the truncation error is not
                // estimated: only the noise part is reported.
                return (d_h, noise);
            }
            let (d_h, d_2h) = if centred {
                (
                    (get(&pts[0]) - get(&pts[1])) / (2.0 * h),
                    (get(&pts[2]) - get(&pts[3])) / (4.0 * h),
                )
            } else {
                let (f1, f2, f4) = (get(&pts[0]), get(&pts[1]), get(&pts[3]));
                (
                    sign * (-3.0 * f0 + 4.0 * f1 - f2) / (2.0 * h),
                    sign * (-3.0 * f0 + 4.0 * f2 - f4) / (4.0 * h),
                )
            };
            let value = (4.0 * d_h - d_2h) / 3.0;
            let err = (d_h - d_2h).abs() / 3.0 * (fd_step / 0.01).powi(2) + noise;
            (value, err)
        };
        let (g, e) = component(&|p: &Values| p.objective);
        objective[i] = g;
        error = error.max(e);
        for (j, row) in rows.iter_mut().enumerate() {
            let (g, e) = component(&|p: &Values| p.constraints[j]);
            row[i] = g;
            // Rows far inside their limit do not take part; their error is not the gradient's.
            if at.constraints[j] > -1.0 {
                error = error.max(e);
            }
        }
    }
    Some(Gradients {
        objective,
        rows,
        error,
        evaluations,
        accuracy,
        stencils,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f = x₀² x₁ + eˣ¹, g = (x₀ x₁ − 1, sin x₀) on [−2, 2]².
    struct Smooth;
    impl NonlinearProgram for Smooth {
        fn dimension(&self) -> usize {
            2
        }
        fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
            (vec![-2.0; 2], vec![2.0; 2])
        }
        fn objective(&self, x: &[f64]) -> Option<f64> {
            Some(x[0] * x[0] * x[1] + x[1].exp())
        }
        fn constraints(&self, x: &[f64]) -> Option<Vec<f64>> {
            Some(vec![x[0] * x[1] - 1.0, x[0].sin()])
        }
    }

    /// Richardson gradients that reuse the central stage's points are the
    /// very numbers of a fresh Richardson evaluation (the same sums of the
    /// same values), for half the evaluations; both match the closed-form
    /// derivatives ∇f = (2x₀x₁, x₀² + eˣ¹), ∇g₁ = (x₁, x₀), ∇g₂ = (cos x₀, 0)
    /// within their error estimate. The point 1.9999 lies within 2h of the
    /// bound, so one variable uses the one-sided stencil.
    #[test]
    fn richardson_reuses_the_central_points() {
        let p = Smooth;
        let bounds = p.bounds();
        for x in [[0.7, -0.3], [1.9999, 0.4]] {
            let at = p.evaluate(&x, &[]).unwrap();
            let scale = [1.0, 1.0];
            let stencil = |accuracy, reuse| {
                gradients(&p, &x, &at, 1e-4, &scale, &bounds, accuracy, reuse).unwrap()
            };
            let central = stencil(Accuracy::Central, None);
            assert_eq!(central.evaluations, 4);
            let fresh = stencil(Accuracy::Richardson, None);
            let reused = stencil(Accuracy::Richardson, Some(&central));
            assert_eq!(fresh.evaluations, 8);
            assert_eq!(reused.evaluations, 4);
            assert_eq!(fresh.objective, reused.objective);
            assert_eq!(fresh.rows, reused.rows);
            assert_eq!(fresh.error, reused.error);
            let exact = [
                vec![2.0 * x[0] * x[1], x[0] * x[0] + x[1].exp()],
                vec![x[1], x[0]],
                vec![x[0].cos(), 0.0],
            ];
            let got = [&reused.objective, &reused.rows[0], &reused.rows[1]];
            for (e, g) in exact.iter().zip(got) {
                for (a, b) in e.iter().zip(g.iter()) {
                    assert!((a - b).abs() <= reused.error.max(1e-12), "{e:?} {g:?}");
                }
            }
        }
    }

    /// Forward differences cost one evaluation per variable and are within
    /// their truncation bound h/2 · max|∂²/∂x_i²| (over [x, x ± h]; the
    /// closed-form second derivatives 2x₁ and eˣ¹ of f, 0 of g₁ and −sin x₀ of
    /// g₂ are bounded by their values at the stencil's ends) of the closed
    /// form; at 1.9999 the difference for x₀ points into the box. Central
    /// gradients at the same point reuse the forward point: the very numbers
    /// of a fresh central evaluation, for one more evaluation per variable.
    #[test]
    fn forward_differences_and_their_reuse() {
        let p = Smooth;
        let bounds = p.bounds();
        let h = 1e-4;
        for x in [[0.7, -0.3], [1.9999, 0.4]] {
            let at = p.evaluate(&x, &[]).unwrap();
            let scale = [1.0, 1.0];
            let stencil = |accuracy, reuse| {
                gradients(&p, &x, &at, h, &scale, &bounds, accuracy, reuse).unwrap()
            };
            let forward = stencil(Accuracy::Forward, None);
            assert_eq!(forward.evaluations, 2);
            // Steps h·max(|x_i|, 1).
            let hs = [h * x[0].abs().max(1.0), h * x[1].abs().max(1.0)];
            let curvature = |i: usize, k: usize| -> f64 {
                // Largest |second derivative| of component k along x_i near x.
                let ends = [x[i] - hs[i], x[i] + hs[i]];
                ends.iter()
                    .map(|&e| match (k, i) {
                        (0, 0) => 2.0 * x[1].abs(),
                        (0, _) => e.exp(),
                        (1, _) => 0.0,
                        (_, 0) => e.sin().abs(),
                        _ => 0.0,
                    })
                    .fold(0.0, f64::max)
            };
            let exact = [
                vec![2.0 * x[0] * x[1], x[0] * x[0] + x[1].exp()],
                vec![x[1], x[0]],
                vec![x[0].cos(), 0.0],
            ];
            let got = [&forward.objective, &forward.rows[0], &forward.rows[1]];
            for (k, (e, g)) in exact.iter().zip(got).enumerate() {
                for i in 0..2 {
                    let bound = 0.5 * hs[i] * curvature(i, k) * 1.001 + 1e-11;
                    assert!((e[i] - g[i]).abs() <= bound, "{k} {i}: {e:?} {g:?} {bound}");
                }
            }
            let fresh = stencil(Accuracy::Central, None);
            let reused = stencil(Accuracy::Central, Some(&forward));
            assert_eq!(reused.evaluations, 2);
            assert_eq!(fresh.objective, reused.objective);
            assert_eq!(fresh.rows, reused.rows);
        }
    }
}
