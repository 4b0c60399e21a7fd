//! The second phase of the multistart: a search of the vertices adjacent to
//! the best local optimum.
//!
//! A local optimum of a study usually sits on a vertex of its active set: as
//! many bounds and rows active as there are variables (the latch studies:
//! H at its upper bound, γ and R at their lower bounds, ψ = 1 and the contact
//! count at its limit). Releasing one active constraint while the others stay
//! active leaves a curve, an *edge*, that ends where a variable reaches a bound:
//! an adjacent vertex, which may be a better local optimum that the starts
//! missed (on the wide latch study, the other end of the edge ψ = 1, count = 20
//! that H leaves from its bound is the global optimum, 12 % lower, which 11 of
//! 256 starts find). As the simplex method walks from vertex to vertex, this
//! phase follows each edge of the best local optimum to its end, linearised
//! (the tangent from the active rows' Jacobian, 2n model evaluations),
//! evaluates its end and midpoint (2 evaluations per edge), and solves from an
//! end only where the objective there, plus the rows it breaks weighted by the
//! optimum's multipliers (an exact-penalty merit), is below the best objective
//! known: the edges along which the objective only rises cost no solve. Every
//! distinct local optimum the starts found is searched so; a better optimum
//! found this way is searched in turn (at most n rounds). Everything is counted in the
//! study's evaluations; the order of results does not depend on threads.

use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;

use super::fd;
use super::functions::{Point, StudyFunctions};
use super::program::NonlinearProgram;

/// A variable within this of 0 or 1 (unit coordinates) is on its bound.
pub const ON_BOUND: f64 = 1e-6;
/// A row at or above this (scaled units) is active.
pub const ACTIVE_ROW: f64 = -1e-6;
/// The finite-difference step of the active rows' Jacobian (unit coordinates).
const JACOBIAN_STEP: f64 = 1e-5;

/// The start points a vertex search proposes from a local optimum, and the
/// model evaluations spent finding them.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct EdgeStarts {
    /// Edges followed (one per active bound or row).
    pub edges: usize,
    /// Start points: ends (or midpoints) of edges where the merit is below
    /// the incumbent's objective, in edge order.
    pub starts: Vec<Vec<f64>>,
    /// Model evaluations spent.
    pub evaluations: usize,
}

/// Which constraint an edge releases.
#[derive(Debug, Clone, Copy)]
enum Released {
    /// The bound of variable i.
    Bound(usize),
    /// The row j.
    Row(usize),
}

/// The edges of the active set at `optimum` (with row multipliers
/// `multipliers`), followed to their linearised ends; see the module docs.
/// An end is proposed only where its merit is below `incumbent` (an ln
/// objective: that of the optimum itself, or a better design known).
pub fn edge_starts(
    functions: &StudyFunctions,
    optimum: &Point,
    multipliers: &[f64],
    incumbent: f64,
) -> EdgeStarts {
    let x = &optimum.x;
    let n = x.len();
    let on_bound = |u: f64| u <= ON_BOUND || u >= 1.0 - ON_BOUND;
    let bounds: Vec<usize> = (0..n).filter(|&i| on_bound(x[i])).collect();
    let free: Vec<usize> = (0..n).filter(|&i| !on_bound(x[i])).collect();
    let rows: Vec<usize> = (0..optimum.rows.len())
        .filter(|&j| optimum.rows[j] >= ACTIVE_ROW || multipliers.get(j).is_some_and(|&l| l > 1e-9))
        .collect();
    let mut out = EdgeStarts::default();
    if bounds.is_empty() && rows.is_empty() {
        return out;
    }

    // The active rows' Jacobian: the SQP's own finite differences (central,
    // one-sided on a bound) at the Jacobian step.
    let jacobian = if rows.is_empty() {
        DMatrix::zeros(0, n)
    } else {
        let Some(at) = functions.evaluate(x, &[]) else {
            return out;
        };
        out.evaluations += 1;
        let gradients = fd::gradients(
            functions,
            x,
            &at,
            JACOBIAN_STEP,
            &functions.scale(),
            &functions.bounds(),
            fd::Accuracy::Central,
            None,
        );
        let Some(g) = gradients else {
            return out; // no stencil in contact: no linearisation here
        };
        out.evaluations += g.evaluations;
        DMatrix::from_fn(rows.len(), n, |r, i| g.rows[rows[r]][i])
    };

    // Each edge's direction and its linearised end.
    let released = bounds
        .iter()
        .map(|&i| Released::Bound(i))
        .chain((0..rows.len()).map(Released::Row));
    let mut probes: Vec<Vec<f64>> = Vec::new();
    for c in released {
        let Some(d) = edge_direction(&jacobian, &free, n, x, c) else {
            continue;
        };
        let Some((end, mid)) = edge_end(x, &d) else {
            continue;
        };
        out.edges += 1;
        probes.push(end);
        probes.push(mid);
    }
    if probes.is_empty() {
        return out;
    }
    // The exact-penalty merit with the optimum's multipliers as weights: at
    // the optimum it equals the objective, and an edge end that breaks a row
    // pays for it at the rate the optimum's objective would gain.
    let merit = |p: Point| -> f64 {
        p.objective
            + p.rows
                .iter()
                .zip(multipliers)
                .map(|(g, l)| l * g.max(0.0))
                .sum::<f64>()
    };
    let values: Vec<Option<f64>> = probes
        .par_iter()
        .map(|y| functions.at(y).map(merit))
        .collect();
    out.evaluations += probes.len();
    for (pair, value) in probes.chunks(2).zip(values.chunks(2)) {
        let below = |v: &Option<f64>| v.is_some_and(|f| f < incumbent.min(optimum.objective));
        if below(&value[0]) {
            out.starts.push(pair[0].clone());
        } else if below(&value[1]) {
            out.starts.push(pair[1].clone());
        }
    }
    out
}

/// The tangent of the edge that releases `c`: the free variables (and the
/// released bound's variable, moving off its bound) change so that the other
/// active rows stay at first order, and a released row moves inside its limit.
/// Least squares, minimum norm (SVD); None when nothing moves.
fn edge_direction(
    jacobian: &DMatrix<f64>,
    free: &[usize],
    n: usize,
    x: &[f64],
    c: Released,
) -> Option<Vec<f64>> {
    let mut d = vec![0.0; n];
    let m = jacobian.nrows();
    let mut rhs = DVector::zeros(m);
    match c {
        Released::Bound(i) => {
            let s = if x[i] < 0.5 { 1.0 } else { -1.0 };
            d[i] = s;
            for r in 0..m {
                rhs[r] = -jacobian[(r, i)] * s;
            }
        }
        Released::Row(r) => rhs[r] = -1.0,
    }
    if !free.is_empty() && m > 0 {
        let a = jacobian.select_columns(free);
        let df = a.svd(true, true).solve(&rhs, 1e-12).ok()?;
        for (k, &i) in free.iter().enumerate() {
            d[i] = df[k];
        }
    }
    let norm = d.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    (norm.is_finite() && norm > 1e-9).then_some(d)
}

/// Where x + t·d first meets a bound (that variable set on it exactly), and the
/// midpoint; None when the edge has no length.
fn edge_end(x: &[f64], d: &[f64]) -> Option<(Vec<f64>, Vec<f64>)> {
    let mut t = f64::INFINITY;
    let mut hit = (0, 0.0);
    for (i, (&u, &di)) in x.iter().zip(d).enumerate() {
        let (ti, side) = if di > 1e-12 {
            ((1.0 - u) / di, 1.0)
        } else if di < -1e-12 {
            (-u / di, 0.0)
        } else {
            continue;
        };
        if ti < t {
            t = ti;
            hit = (i, side);
        }
    }
    if !(t.is_finite() && t > 1e-6) {
        return None;
    }
    let at = |s: f64| -> Vec<f64> {
        x.iter()
            .zip(d)
            .map(|(&u, &di)| (u + s * t * di).clamp(0.0, 1.0))
            .collect()
    };
    let mut end = at(1.0);
    end[hit.0] = hit.1;
    Some((end, at(0.5)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12)
    }

    /// Releasing the only active row g = x0 − 2 x1 at (0.6, 0.3): the
    /// minimum-norm tangent with ∇g·d = −1 is −∇g/|∇g|² = (−0.2, 0.4), which
    /// meets x1 = 1 at t = 0.7/0.4 = 1.75 (hand-computed).
    #[test]
    fn a_released_row_moves_inside_its_limit_to_the_first_bound() {
        let jac = DMatrix::from_row_slice(1, 2, &[1.0, -2.0]);
        let x = [0.6, 0.3];
        let d = edge_direction(&jac, &[0, 1], 2, &x, Released::Row(0)).unwrap();
        assert!(close(&d, &[-0.2, 0.4]), "{d:?}");
        let (end, mid) = edge_end(&x, &d).unwrap();
        assert!(close(&end, &[0.25, 1.0]), "{end:?}");
        assert!(close(&mid, &[0.425, 0.65]), "{mid:?}");
    }

    /// x0 on its upper bound, the row g = x1 − x0/2 + 0.2 active at
    /// (1, 0.3, 0.6): releasing the bound moves x0 down and x1 with it along
    /// the line g = 0 (x2 does not enter g: it stays), to x1 = 0 at x0 = 0.4,
    /// the adjacent vertex (hand-computed).
    #[test]
    fn a_released_bound_follows_the_active_rows_to_the_adjacent_vertex() {
        let jac = DMatrix::from_row_slice(1, 3, &[-0.5, 1.0, 0.0]);
        let x = [1.0, 0.3, 0.6];
        let d = edge_direction(&jac, &[1, 2], 3, &x, Released::Bound(0)).unwrap();
        assert!(close(&d, &[-1.0, -0.5, 0.0]), "{d:?}");
        let (end, _) = edge_end(&x, &d).unwrap();
        assert!(close(&end, &[0.4, 0.0, 0.6]), "{end:?}");
    }

    /// An edge of no length (the step would leave the box at once) is none.
    #[test]
    fn an_edge_without_length_is_skipped() {
        assert!(edge_end(&[1.0, 0.5], &[1.0, 0.0]).is_none());
        let jac = DMatrix::zeros(1, 2);
        assert!(edge_direction(&jac, &[0, 1], 2, &[0.5, 0.5], Released::Row(0)).is_none());
    }
}
