//! The SQP subproblem, solved by clarabel:
//!
//! ```text
//! min_{p,t}  ½ pᵀBp + ∇fᵀp + ρ Σ t_j
//! s.t.       g_j + ∇g_jᵀp ≤ t_j,  t_j ≥ 0          (elastic mode: always feasible)
//!            lower ≤ x + p ≤ upper                  (the box)
//!            ‖p‖₂ ≤ Δ                               (trust region, a second-order cone)
//! ```
//!
//! Every linear row carries a nonzero coefficient (the -1 on t_j, the ±1 of the
//! box), so clarabel never sees a zero row. Only `Solved` counts as solved.

#![allow(non_snake_case)]

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SecondOrderConeT,
    SolverStatus,
};
use nalgebra::DMatrix;

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
    /// The elastic slacks t_j (0 where the linearisation is satisfied).
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

/// Solves the subproblem.
pub fn solve(sp: &Subproblem) -> Result<Step, QpFailure> {
    let n = sp.x.len();
    let rows_in: Vec<usize> = (0..sp.rows.len()).filter(|&j| sp.include[j]).collect();
    let m = rows_in.len();
    let nv = n + m;
    // The objective is divided by max(1, ρ) so that a large penalty does not
    // swamp the interior-point solver; the multipliers are scaled back.
    let weight = sp.penalty.max(1.0);
    // P: upper triangle of B.
    let (mut pi, mut pj, mut pv) = (Vec::new(), Vec::new(), Vec::new());
    for j in 0..n {
        for i in 0..=j {
            pi.push(i);
            pj.push(j);
            pv.push(sp.hessian[(i, j)] / weight);
        }
    }
    let P = CscMatrix::new_from_triplets(nv, nv, pi, pj, pv);
    let mut q: Vec<f64> = sp.gradient.iter().map(|g| g / weight).collect();
    q.extend(std::iter::repeat_n(sp.penalty / weight, m));

    let (mut ai, mut aj, mut av) = (Vec::new(), Vec::new(), Vec::new());
    let mut b = Vec::new();
    let mut row = 0;
    // Linearised rows: ∇g_jᵀp - t_j ≤ -g_j.
    for (k, &j) in rows_in.iter().enumerate() {
        for (i, &d) in sp.jacobian[j].iter().enumerate() {
            if d != 0.0 {
                ai.push(row);
                aj.push(i);
                av.push(d);
            }
        }
        ai.push(row);
        aj.push(n + k);
        av.push(-1.0);
        b.push(-sp.rows[j]);
        row += 1;
    }
    // t_j ≥ 0.
    for j in 0..m {
        ai.push(row);
        aj.push(n + j);
        av.push(-1.0);
        b.push(0.0);
        row += 1;
    }
    // Box: p_i ≤ upper_i - x_i and -p_i ≤ x_i - lower_i.
    for i in 0..n {
        ai.push(row);
        aj.push(i);
        av.push(1.0);
        b.push((sp.upper[i] - sp.x[i]).max(0.0));
        row += 1;
        ai.push(row);
        aj.push(i);
        av.push(-1.0);
        b.push((sp.x[i] - sp.lower[i]).max(0.0));
        row += 1;
    }
    let linear_rows = row;
    // Trust region: s = [Δ; p] in the second-order cone.
    b.push(sp.radius);
    row += 1;
    for i in 0..n {
        ai.push(row);
        aj.push(i);
        av.push(-1.0);
        b.push(0.0);
        row += 1;
    }
    let A = CscMatrix::new_from_triplets(row, nv, ai, aj, av);
    let cones = [NonnegativeConeT(linear_rows), SecondOrderConeT(n + 1)];
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
    let p: Vec<f64> = sol.x[..n].to_vec();
    let mut slack = vec![0.0; sp.rows.len()];
    let mut multipliers = vec![0.0; sp.rows.len()];
    for (k, &j) in rows_in.iter().enumerate() {
        slack[j] = sol.x[n + k].max(0.0);
        multipliers[j] = sol.z[k].max(0.0) * weight;
    }
    let mut quad = 0.0;
    for i in 0..n {
        for j in 0..n {
            quad += p[i] * sp.hessian[(i, j)] * p[j];
        }
    }
    let lin: f64 = sp.gradient.iter().zip(&p).map(|(g, d)| g * d).sum();
    Ok(Step {
        p,
        slack,
        multipliers,
        objective_change: lin + 0.5 * quad,
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
