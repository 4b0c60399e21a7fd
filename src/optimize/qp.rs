//! The SQP subproblem, solved by clarabel:
//!
//! ```text
//! min_{p,t}  ½ pᵀBp + ∇fᵀp + ρ Σ t_j
//! s.t.       g_j + ∇g_jᵀp ≤ t_j,  t_j ≥ 0          (elastic mode: always feasible)
//!            lower ≤ x + p ≤ upper                  (the box)
//!            ‖p‖₂ ≤ Δ                               (trust region, a second-order cone)
//! ```
//!
//! (The SQP poses it in its trust region's scaled variables, `sqp`.)
//!
//! clarabel sees it normalised (`solve`): the step in a unit σ of its own
//! expected length, each row over its gradient's norm, the objective O(1),
//! the elastic slacks at cost 1, so that its tolerances mean the same
//! whatever the sizes of ρ, ∇f and the rows; the interior-point solution is
//! then moved onto the rows it holds active (`polish`).
//!
//! Every linear row carries a nonzero coefficient (the slack's on its row, the
//! ±1 of the box), so clarabel never sees a zero row. Only `Solved` counts as
//! solved.

#![allow(non_snake_case)]

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SecondOrderConeT,
    SolverStatus,
};
use nalgebra::{DMatrix, DVector};

/// The data of one subproblem.
pub struct Subproblem<'a> {
    /// The current point.
    pub x: &'a [f64],
    /// Lower bounds of x.
    pub lower: &'a [f64],
    /// Upper bounds of x.
    pub upper: &'a [f64],
    /// Which rows take part (a row that no step within the trust region can
    /// bring to its limit is left out: its multiplier is 0).
    pub include: &'a [bool],
    /// The quasi-Newton Hessian of the Lagrangian (positive definite).
    pub hessian: &'a DMatrix<f64>,
    /// ∇f.
    pub gradient: &'a [f64],
    /// g_j(x).
    pub rows: &'a [f64],
    /// ∇g_j(x).
    pub jacobian: &'a [Vec<f64>],
    /// Trust-region radius Δ.
    pub radius: f64,
    /// Elastic penalty ρ on the slack of each linearised row.
    pub penalty: f64,
    /// clarabel's duality-gap tolerance (absolute and relative).
    pub gap_tolerance: f64,
    /// clarabel's interior-point iteration cap.
    pub max_iterations: u32,
}

/// What the subproblem gave.
#[derive(Debug, Clone, PartialEq)]
pub struct Step {
    /// The step p.
    pub p: Vec<f64>,
    /// The elastic slacks t_j (0 where the linearisation is satisfied, or
    /// missed by less than a millionth of the step's scale).
    pub slack: Vec<f64>,
    /// Multipliers λ_j ≥ 0 of the linearised rows.
    pub multipliers: Vec<f64>,
    /// The model's change of the objective, ∇fᵀp + ½pᵀBp.
    pub objective_change: f64,
}

/// Why a subproblem gave no usable step.
#[derive(Debug, Clone, PartialEq)]
pub enum QpFailure {
    /// clarabel ended with a status other than `Solved` (kept as clarabel's enum).
    Status(SolverStatus),
    /// clarabel refused the settings or the problem data (a bug of ours: the
    /// subproblem is built well-formed), with its message.
    Setup(String),
}

/// The largest cost of an elastic slack relative to its coefficient in its
/// row (see `solve`).
const SLACK_SPLIT: f64 = 1e6;

/// The trust region of a subproblem is first narrowed to this many step
/// units σ (see `solve`).
const NARROW: f64 = 10.0;

/// A normalised row's slack below this (a millionth of the step unit σ) is
/// reported as none.
const ELASTIC: f64 = 1e-6;

/// The largest change `polish` makes, relative to the solution's size.
const POLISH: f64 = 1e-6;

/// The length the subproblem's step is measured in: the longer of the
/// quasi-Newton step ‖B⁻¹∇f‖ and the largest distance to a violated row's
/// linearisation (g_j/‖∇g_j‖), at most the trust radius; the trust radius
/// where both are zero (and 1 where that is infinite).
fn step_scale(sp: &Subproblem, rows_in: &[usize], norms: &[f64]) -> f64 {
    let newton = sp
        .hessian
        .clone()
        .cholesky()
        .map(|c| c.solve(&DVector::from_column_slice(sp.gradient)).norm())
        .unwrap_or(0.0);
    let restore = rows_in
        .iter()
        .zip(norms)
        .fold(0.0f64, |m, (&j, d)| m.max(sp.rows[j] / d));
    let sigma = newton.max(restore).min(sp.radius);
    if sigma > 0.0 && sigma.is_finite() {
        sigma
    } else if sp.radius > 0.0 && sp.radius.is_finite() {
        sp.radius
    } else {
        1.0
    }
}

/// The subproblem normalised with step unit σ (see `solve`) within a trust
/// radius `radius` (the model change left 0).
fn solve_within(
    sp: &Subproblem,
    rows_in: &[usize],
    norms: &[f64],
    sigma: f64,
    radius: f64,
) -> Result<Step, QpFailure> {
    let n = sp.x.len();
    let m = rows_in.len();
    let nv = n + m;
    let penalty = sp.penalty.max(f64::MIN_POSITIVE);
    let gmax = sp.gradient.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    let bmax = sp.hessian.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    let c = (sigma * gmax).max(sigma * sigma * bmax);
    let c = if c > 0.0 && c.is_finite() { c } else { 1.0 };
    // κ_j = ρσ‖∇g_j‖/c, the cost of a unit of the normalised row's slack,
    // split as θ_j w_j (the row's slack) at cost γ_j w_j, γ_j/θ_j = κ_j:
    // θ_j = 1/κ_j and γ_j = 1 while κ_j ≤ `SLACK_SPLIT`, beyond that θ_j
    // stays 1/`SLACK_SPLIT` (a smaller coefficient makes an elastic row look
    // rigid to clarabel's infeasibility test) and γ_j grows. The row's
    // multiplier is at most κ_j.
    let kappa: Vec<f64> = norms.iter().map(|d| penalty * sigma * d / c).collect();
    let theta: Vec<f64> = kappa.iter().map(|k| 1.0 / k.min(SLACK_SPLIT)).collect();
    let gamma: Vec<f64> = kappa.iter().map(|k| (k / SLACK_SPLIT).max(1.0)).collect();
    // P: upper triangle of σ²B/c.
    let (mut pi, mut pj, mut pv) = (Vec::new(), Vec::new(), Vec::new());
    for j in 0..n {
        for i in 0..=j {
            pi.push(i);
            pj.push(j);
            pv.push(sp.hessian[(i, j)] * sigma * sigma / c);
        }
    }
    let P = CscMatrix::new_from_triplets(nv, nv, pi, pj, pv);
    let mut q: Vec<f64> = sp.gradient.iter().map(|g| g * sigma / c).collect();
    q.extend(&gamma);

    let (mut ai, mut aj, mut av) = (Vec::new(), Vec::new(), Vec::new());
    let mut b = Vec::new();
    let mut row = 0;
    // Linearised rows: ∇g_jᵀu/‖∇g_j‖ - w_j/κ_j ≤ -g_j/(σ‖∇g_j‖).
    for (k, &j) in rows_in.iter().enumerate() {
        for (i, &d) in sp.jacobian[j].iter().enumerate() {
            if d != 0.0 {
                ai.push(row);
                aj.push(i);
                av.push(d / norms[k]);
            }
        }
        ai.push(row);
        aj.push(n + k);
        av.push(-theta[k]);
        b.push(-sp.rows[j] / (sigma * norms[k]));
        row += 1;
    }
    // w_j ≥ 0.
    for j in 0..m {
        ai.push(row);
        aj.push(n + j);
        av.push(-1.0);
        b.push(0.0);
        row += 1;
    }
    // Box: u_i ≤ (upper_i - x_i)/σ and -u_i ≤ (x_i - lower_i)/σ; a side
    // farther than Δ cannot bind (|p_i| ≤ ‖p‖ ≤ Δ) and is left out.
    for i in 0..n {
        for (sign, room) in [
            (1.0, (sp.upper[i] - sp.x[i]).max(0.0)),
            (-1.0, (sp.x[i] - sp.lower[i]).max(0.0)),
        ] {
            if room <= radius {
                ai.push(row);
                aj.push(i);
                av.push(sign);
                b.push(room / sigma);
                row += 1;
            }
        }
    }
    let linear_rows = row;
    // Trust region: s = [Δ/σ; u] in the second-order cone (none where Δ is infinite).
    let trust = radius.is_finite();
    if trust {
        b.push(radius / sigma);
        row += 1;
        for i in 0..n {
            ai.push(row);
            aj.push(i);
            av.push(-1.0);
            b.push(0.0);
            row += 1;
        }
    }
    let mut dense = DMatrix::zeros(linear_rows, nv);
    for ((&i, &j), &v) in ai.iter().zip(&aj).zip(&av) {
        if i < linear_rows {
            dense[(i, j)] = v;
        }
    }
    let A = CscMatrix::new_from_triplets(row, nv, ai, aj, av);
    let mut cones = vec![NonnegativeConeT(linear_rows)];
    if trust {
        cones.push(SecondOrderConeT(n + 1));
    }
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .max_iter(sp.max_iterations)
        .tol_gap_abs(sp.gap_tolerance)
        .tol_gap_rel(sp.gap_tolerance)
        .build()
        .map_err(|e| QpFailure::Setup(format!("settings: {e:?}")))?;
    let mut solver = DefaultSolver::new(&P, &q, &A, &b, &cones, settings)
        .map_err(|e| QpFailure::Setup(format!("setup: {e:?}")))?;
    solver.solve();
    let sol = &solver.solution;
    if sol.status != SolverStatus::Solved {
        return Err(QpFailure::Status(sol.status));
    }
    let x = polish(&dense, &b[..linear_rows], sol);
    let p: Vec<f64> = x[..n].iter().map(|u| u * sigma).collect();
    let mut slack = vec![0.0; sp.rows.len()];
    let mut multipliers = vec![0.0; sp.rows.len()];
    for (k, &j) in rows_in.iter().enumerate() {
        // The interior point leaves each w_j a hair above 0: a slack below
        // `ELASTIC` of the step unit is none.
        let t = x[n + k].max(0.0) * theta[k];
        slack[j] = if t > ELASTIC {
            t * sigma * norms[k]
        } else {
            0.0
        };
        multipliers[j] = sol.z[k].max(0.0) * c / (sigma * norms[k]);
    }
    Ok(Step {
        p,
        slack,
        multipliers,
        objective_change: 0.0,
    })
}

/// An interior-point solution leaves each active constraint a slack of
/// about the duality gap over its multiplier (1e-8 of the step at a gap of
/// 1e-8): the rows a step should meet it misses by that much. The solution is
/// moved onto its active linear rows (those whose slack is below their
/// multiplier) by the least-norm change, unless that change is more than
/// `POLISH` of the solution's size (then the active set is not clear).
fn polish(a: &DMatrix<f64>, b: &[f64], sol: &clarabel::solver::DefaultSolution<f64>) -> Vec<f64> {
    let x = sol.x.clone();
    let active: Vec<usize> = (0..b.len())
        .filter(|&k| 1e3 * sol.s[k] < sol.z[k])
        .collect();
    if active.is_empty() {
        return x;
    }
    let sub = DMatrix::from_fn(active.len(), x.len(), |r, c| a[(active[r], c)]);
    let xv = DVector::from_column_slice(&x);
    let miss = DVector::from_iterator(
        active.len(),
        active
            .iter()
            .map(|&k| b[k])
            .zip((&sub * &xv).iter())
            .map(|(b, ax)| b - ax),
    );
    let Ok(delta) = sub.svd(true, true).solve(&miss, 1e-12) else {
        return x;
    };
    let size = xv.amax().max(1.0);
    if delta.amax() > POLISH * size || delta.iter().any(|d| !d.is_finite()) {
        return x;
    }
    (xv + delta).iter().copied().collect()
}

/// Solves the subproblem.
pub fn solve(sp: &Subproblem) -> Result<Step, QpFailure> {
    let n = sp.x.len();
    let rows_in: Vec<usize> = (0..sp.rows.len()).filter(|&j| sp.include[j]).collect();
    // clarabel's residuals are measured against max(1, ‖data‖), so data far
    // from O(1) leave its steps inaccurate (a gradient of 1e-13 beside a
    // penalty of 1 is below its tolerances, and the step is noise; a step of
    // 1e-8 in a box of size 1 ends `AlmostSolved`). The subproblem is
    // therefore solved normalised: the step in units of σ (`step_scale`,
    // p = σu), each row divided by σ‖∇g_j‖, the objective by c (the larger of
    // its linear and quadratic terms at |u| = 1), and each elastic slack
    // measured so that its cost is 1, whatever ρ; the step, slacks and
    // multipliers are mapped back.
    let norms: Vec<f64> = rows_in
        .iter()
        .map(|&j| {
            let d = sp.jacobian[j].iter().map(|a| a * a).sum::<f64>().sqrt();
            if d > 0.0 && d.is_finite() {
                d
            } else {
                1.0
            }
        })
        .collect();
    // The trust region is first narrowed to `NARROW` × σ where that is
    // inside Δ: its radius is part of the data clarabel's tolerances are
    // relative to, so a wide region leaves the rows of a short step loose.
    // A step that does not reach the narrowed region is the subproblem's
    // solution (it is convex); one that does is solved again with a region
    // `NARROW` times wider, up to Δ.
    let mut sigma = step_scale(sp, &rows_in, &norms);
    let mut radius = sp.radius.min(NARROW * sigma);
    let step = loop {
        let step = solve_within(sp, &rows_in, &norms, sigma, radius)?;
        let length = step.p.iter().map(|a| a * a).sum::<f64>().sqrt();
        if radius >= sp.radius || length < 0.9 * radius {
            break step;
        }
        radius = sp.radius.min(NARROW * radius);
        sigma = radius / NARROW;
    };
    let p = &step.p;
    let mut quad = 0.0;
    for i in 0..n {
        for j in 0..n {
            quad += p[i] * sp.hessian[(i, j)] * p[j];
        }
    }
    let lin: f64 = sp.gradient.iter().zip(p).map(|(g, d)| g * d).sum();
    Ok(Step {
        objective_change: lin + 0.5 * quad,
        ..step
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// min ½‖p‖² + (-1, -1)ᵀp  s.t. p1 + p2 ≤ 0.5 (as g = -0.5 + [1,1]ᵀp), ‖p‖ ≤ 10, box from x = (0.5, 0.5).
    /// Closed form: p = (0.25, 0.25), λ = 0.75 (stationarity p - 1 + λ = 0).
    #[test]
    fn solves_a_qp_with_known_solution() {
        let b = DMatrix::identity(2, 2);
        let jac = vec![vec![1.0, 1.0]];
        let sp = Subproblem {
            x: &[0.5, 0.5],
            lower: &[0.0, 0.0],
            upper: &[1.0, 1.0],
            include: &[true],
            hessian: &b,
            gradient: &[-1.0, -1.0],
            rows: &[-0.5],
            jacobian: &jac,
            radius: 10.0,
            penalty: 100.0,
            gap_tolerance: 1e-12,
            max_iterations: 100,
        };
        let s = solve(&sp).unwrap();
        assert!(
            (s.p[0] - 0.25).abs() < 1e-7 && (s.p[1] - 0.25).abs() < 1e-7,
            "{:?}",
            s.p
        );
        assert!(
            (s.multipliers[0] - 0.75).abs() < 1e-6,
            "{:?}",
            s.multipliers
        );
        assert!(s.slack[0] < 1e-7);
        // With the trust region binding at Δ = 0.1 the step is (0.1/√2)(1, 1).
        let sp = Subproblem { radius: 0.1, ..sp };
        let s = solve(&sp).unwrap();
        assert!((s.p[0] - 0.1 / 2f64.sqrt()).abs() < 1e-6, "{:?}", s.p);
    }

    /// An inconsistent linearisation (g = 1 with a zero gradient) is absorbed by the slack.
    #[test]
    fn elastic_mode_keeps_it_feasible() {
        let b = DMatrix::identity(1, 1);
        let jac = vec![vec![0.0]];
        let sp = Subproblem {
            x: &[0.5],
            lower: &[0.0],
            upper: &[1.0],
            include: &[true],
            hessian: &b,
            gradient: &[1.0],
            rows: &[1.0],
            jacobian: &jac,
            radius: 1.0,
            penalty: 10.0,
            gap_tolerance: 1e-12,
            max_iterations: 100,
        };
        let s = solve(&sp).unwrap();
        assert!((s.slack[0] - 1.0).abs() < 1e-6);
        assert!((s.p[0] + 0.5).abs() < 1e-6, "{:?}", s.p);
    }
}
