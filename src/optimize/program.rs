//! The vocabulary of the SQP: a smooth nonlinear program with finite bounds,
//!
//! ```text
//! min f(x)   s.t.   g(x) ≤ 0,   lower ≤ x ≤ upper,
//! ```
//!
//! known to the solver only through values (gradients are finite differences
//! inside [`super::minimize`]). A wear study is one such program
//! ([`super::StudyFunctions`]); the Hock–Schittkowski problems of the tests are
//! others.

/// A problem `min f(x) s.t. g(x) ≤ 0, lower ≤ x ≤ upper` given by values.
///
/// Four methods are required; the others have default bodies that a problem
/// may override to be faster (one evaluation for both `f` and `g`, warm-start
/// data for nearby evaluations) or better scaled (`scale`).
pub trait NonlinearProgram {
    /// n, the number of variables.
    fn dimension(&self) -> usize;
    /// Finite lower and upper bounds, each of length n, lower < upper.
    fn bounds(&self) -> (Vec<f64>, Vec<f64>);
    /// f(x); None where x cannot be evaluated (the solver then shrinks its step).
    fn objective(&self, x: &[f64]) -> Option<f64>;
    /// g(x), one value per constraint row, g ≤ 0 feasible; None where x cannot be evaluated.
    fn constraints(&self, x: &[f64]) -> Option<Vec<f64>>;

    /// f(x) and g(x) together, with data (`warm_start` of the result) that
    /// evaluations near x may start from. `near` is such data from a nearby
    /// point (empty at the first evaluation). The default calls
    /// [`NonlinearProgram::objective`] and [`NonlinearProgram::constraints`]
    /// and ignores `near`; an override must return the same values whatever
    /// `near` is (to the last few ulps), so that results do not depend on it.
    fn evaluate(&self, x: &[f64], near: &[f64]) -> Option<Values> {
        let _ = near;
        Some(Values {
            objective: self.objective(x)?,
            constraints: self.constraints(x)?,
            warm_start: Vec::new(),
        })
    }

    /// The typical magnitude of each variable (default 1): a finite-difference
    /// step for x_i is `fd_step · max(|x_i|, scale_i)`.
    fn scale(&self) -> Vec<f64> {
        vec![1.0; self.dimension()]
    }

    /// Whether f is the logarithm of a positive quantity (default false). A
    /// difference of such an f is a relative change of the quantity, the same
    /// in every unit system, so the KKT test measures the objective's share of
    /// complementarity, Σ|λ_j g_j|, on its own; for any other f it is measured
    /// against max(1, |f|), which a unit change of a logarithm would move (the
    /// wear rate's ln is −41 in m³/m and +0.4 in µm³/m).
    fn logarithmic_objective(&self) -> bool {
        false
    }
}

/// The values of a program at one point.
#[derive(Debug, Clone, PartialEq)]
pub struct Values {
    /// f(x).
    pub objective: f64,
    /// g(x).
    pub constraints: Vec<f64>,
    /// Data from which evaluations near x may start (problem-defined; may be empty).
    pub warm_start: Vec<f64>,
}

impl Values {
    /// max_j max(0, g_j): the largest violation.
    pub fn max_violation(&self) -> f64 {
        self.constraints.iter().fold(0.0, |m, g| m.max(*g))
    }

    /// Σ_j max(0, g_j): the ℓ1 infeasibility.
    pub fn violation(&self) -> f64 {
        self.constraints.iter().map(|g| g.max(0.0)).sum()
    }
}
