//! The Lennard-Jones law's rows of the work–precision report: the evaluator's
//! P̄ (table, per-scene grid, plastic junctions in closed form) against an
//! independent adaptive Simpson quadrature in Δ of the same tabulated curves,
//! each with its plastic branch beyond its own Δc, weighted as the model
//! interpolates between them (docs/model.md §11).

use std::hint::black_box;
use std::time::Instant;

use crate::model::lennard_jones::rough::{stand_in_pull_off_error, RoughLaw};
use crate::model::lennard_jones::spacing;
use crate::model::lennard_jones::table::Curve;
use crate::model::{AsperityLaw, Coefficients, Model, Quadrature};

use super::{rel, stats, Quantity, Row, RowLaw, NEGLIGIBLE};

/// The reference's relative tolerance (of ∫|p| φ̄ over each piece).
pub const REFERENCE_TOLERANCE: f64 = 1e-12;

/// One point: the coefficients, z0 = Z0/σ and h.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LennardJonesPoint {
    /// The load coefficients (c_0 sets ℓ, c_h the junctions).
    pub coefficients: Coefficients,
    /// z0 = Z0/σ.
    pub range: f64,
    /// h.
    pub separation: f64,
}

/// The points: Tabor parameters across the table (μ = 0.02, 0.1, 0.374, 1, 3,
/// 10, 20: on both sides of the cusp and where the curves are JKR-like; 100
/// and 1e5 on the closed-form limit curves above it), weak and strong adhesion (ℓ = 30, 3), with and
/// without plasticity (c_h = 5, ∞), h = −1, 0.5, 2, 4; and the scenes' own
/// coefficients (where their μ lies in the table) at h = −1 … 4.
pub fn points(scenes: &[(Coefficients, f64)]) -> Vec<LennardJonesPoint> {
    let mut out = Vec::new();
    for mu in [0.02, 0.1, 0.374, 1.0, 3.0, 10.0, 20.0, 100.0, 1e5] {
        for ell in [3.0f64, 30.0] {
            for c_h in [5.0, f64::INFINITY] {
                let coefficients = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), c_h);
                for h in [-1.0, 0.5, 2.0, 4.0] {
                    out.push(LennardJonesPoint {
                        coefficients,
                        range: spacing(mu) / ell,
                        separation: h,
                    });
                }
            }
        }
    }
    for &(coefficients, range) in scenes {
        if RoughLaw::new(coefficients.c_0, coefficients.c_h, range).is_none() {
            continue;
        }
        for h in [-1.0, 0.0, 1.0, 2.0, 3.0, 4.0] {
            out.push(LennardJonesPoint {
                coefficients,
                range,
                separation: h,
            });
        }
    }
    out
}

/// Adaptive Simpson of `f` on [a, b] to `tol` absolute (depth-limited).
fn simpson(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    // (a, b, f(a), f(m), f(b), whole, tol, depth) on an explicit stack, summed in
    // a fixed order (left before right).
    let m = 0.5 * (a + b);
    let (fa, fm, fb) = (f(a), f(m), f(b));
    let mut stack = vec![(
        a,
        b,
        fa,
        fm,
        fb,
        (b - a) / 6.0 * (fa + 4.0 * fm + fb),
        tol,
        0u32,
    )];
    let mut sum = 0.0;
    while let Some((a, b, fa, fm, fb, whole, tol, depth)) = stack.pop() {
        let m = 0.5 * (a + b);
        let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
        let (flm, frm) = (f(lm), f(rm));
        let left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
        let right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
        if depth >= 40 || (left + right - whole).abs() <= 15.0 * tol {
            sum += left + right + (left + right - whole) / 15.0;
        } else {
            stack.push((m, b, fm, frm, fb, right, 0.5 * tol, depth + 1));
            stack.push((a, m, fa, flm, fm, left, 0.5 * tol, depth + 1));
        }
    }
    sum
}

/// The reference P̄(h) and its size ∫|p| φ̄ (the scale errors are taken
/// against: P̄ is a difference of attraction and repulsion near its zero).
pub fn reference_load(point: &LennardJonesPoint) -> Option<(f64, f64)> {
    let c = point.coefficients;
    let law = RoughLaw::new(c.c_0, c.c_h, point.range)?;
    Some(reference_load_of(
        law.curves(),
        law.ell,
        c,
        point.separation,
    ))
}

/// [`reference_load`] of any curves, each with its weight and Δc, at ℓ = σ/ε,
/// the coefficients `c` (c_p, c_0 of the plastic branch) and h: also a curve
/// that is not in the table (one the solver wrote at a μ between the table's,
/// weight 1, to measure the interpolation in μ).
pub fn reference_load_of<'a>(
    curves: impl IntoIterator<Item = (&'a Curve, f64, f64)>,
    ell: f64,
    c: Coefficients,
    h: f64,
) -> (f64, f64) {
    let (lo, hi) = (-h - 10.0, -h + 10.0);
    let weight = |d: f64| (-0.5 * (h + d) * (h + d)).exp();
    let (mut load, mut size) = (0.0, 0.0);
    for (curve, w, dc) in curves {
        let switch = curve.switch / ell;
        let p = |d: f64| {
            if d >= dc {
                c.c_p * d - c.c_0
            } else {
                ell.powf(-1.5) * curve.load(ell * d)
            }
        };
        let mut cuts = vec![lo, switch, 0.0, dc, hi];
        cuts.retain(|x| x.is_finite() && *x >= lo && *x <= hi);
        cuts.sort_by(f64::total_cmp);
        for piece in cuts.windows(2) {
            let (a, b) = (piece[0], piece[1]);
            if a >= b {
                continue;
            }
            // Each side of the switch in s², Δ = switch ∓ s²: the load has a
            // square-root end at the jump.
            let g = |d: f64| p(d) * weight(d);
            let (f, ta, tb): (Box<dyn Fn(f64) -> f64>, f64, f64) = if b <= switch {
                (
                    Box::new(move |t: f64| 2.0 * t * g(switch - t * t)),
                    (switch - b).sqrt(),
                    (switch - a).sqrt(),
                )
            } else if a >= switch && a - switch < 1.0 {
                (
                    Box::new(move |t: f64| 2.0 * t * g(switch + t * t)),
                    (a - switch).sqrt(),
                    (b - switch).sqrt(),
                )
            } else {
                (Box::new(g), a, b)
            };
            // ∫|f| by a 64-point midpoint sum: the scale of the tolerance.
            let n = 64;
            let magnitude = (0..n)
                .map(|i| f(ta + (tb - ta) * (i as f64 + 0.5) / n as f64).abs())
                .sum::<f64>()
                * (tb - ta)
                / n as f64;
            let tol = REFERENCE_TOLERANCE * magnitude.max(NEGLIGIBLE);
            load += w * simpson(&f, ta, tb, tol);
            size += w.abs() * magnitude;
        }
    }
    (load, size)
}

/// The rows: P̄ at the default setting against the reference, and the time
/// of one `Model::at` (on the scene's grid).
pub fn rows(points: &[LennardJonesPoint], repetitions: usize) -> Vec<Row> {
    let (mut errors, mut times) = (Vec::new(), Vec::new());
    for p in points {
        let Some((want, size)) = reference_load(p) else {
            continue;
        };
        let model = Model::with_law(
            p.coefficients,
            AsperityLaw::LennardJones { range: p.range },
            Quadrature::default(),
        );
        let got = model.at(p.separation).load().value();
        errors.push(rel(got, want, size.max(want.abs()).max(NEGLIGIBLE)));
        let start = Instant::now();
        for _ in 0..repetitions.max(1) {
            black_box(model.at(black_box(p.separation)));
        }
        times.push(start.elapsed().as_nanos() as f64 / repetitions.max(1) as f64);
    }
    let (max, median, time, samples) = stats(errors, times);
    vec![Row {
        quantity: Quantity::Load,
        setting: "table+grid".to_string(),
        max_rel_error: max,
        median_rel_error: median,
        time_per_eval_ns: time,
        is_default: true,
        samples,
        evaluations_per_value: 1,
        law: RowLaw::LennardJones,
    }]
}

/// The pull-off's relative error of the closed-form laws where they take
/// over from the law's curves: (below μ = 0.01 one summit's, above μ = 3.58e6
/// the rough surface's where adhesion is strong).
pub fn stand_in_errors() -> (f64, f64) {
    (
        stand_in_pull_off_error(false),
        stand_in_pull_off_error(true),
    )
}
