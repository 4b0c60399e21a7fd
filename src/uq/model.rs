//! The joint law of the inputs: marginal distributions joined by a Gaussian
//! copula (the Nataf model).
//!
//! A point is described in three coordinates:
//!
//! * `u`: independent standard normal variables (the space in which FORM works and
//!   in which Sobol′ indices of correlated inputs are defined);
//! * `z = L·u`: correlated standard normal scores, L the Cholesky factor of the
//!   copula correlation matrix R;
//! * `x_i = F_i⁻¹(Φ(z_i))`: the physical inputs, in their own units.
//!
//! The correlation ρ given for a pair is the correlation of the normal scores
//! z_i, z_j (the copula parameter), not the Pearson correlation of x_i, x_j; the
//! two agree for normal marginals and differ slightly otherwise. Without
//! correlations L = I and u = z.

use nalgebra::DMatrix;

use super::distribution::{std_normal_cdf, std_normal_quantile, Distribution, ParameterError};

/// Why an input model cannot be built. Inputs are named by their 0-based index
/// in the list given.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// No inputs.
    #[error("there are no uncertain inputs")]
    Empty,
    /// A marginal law has a parameter outside its range.
    #[error("input {index}: {source}")]
    Distribution {
        /// The input's index.
        index: usize,
        /// What is wrong with its law.
        source: ParameterError,
    },
    /// A correlation refers to an input that does not exist.
    #[error("correlation ({i}, {j}) refers to input {missing}, but there are {dim} inputs")]
    UnknownInput {
        /// First index of the pair.
        i: usize,
        /// Second index of the pair.
        j: usize,
        /// The index out of range.
        missing: usize,
        /// The number of inputs.
        dim: usize,
    },
    /// A correlation of an input with itself.
    #[error("correlation ({i}, {i}) of an input with itself")]
    SelfCorrelation {
        /// The input's index.
        i: usize,
    },
    /// The same pair given twice.
    #[error("correlation ({i}, {j}) is given twice")]
    Duplicate {
        /// First index of the pair.
        i: usize,
        /// Second index of the pair.
        j: usize,
    },
    /// |ρ| ≥ 1 or not finite.
    #[error("correlation ({i}, {j}) = {rho} is not accepted: it must be finite with |ρ| < 1")]
    OutOfRange {
        /// First index of the pair.
        i: usize,
        /// Second index of the pair.
        j: usize,
        /// The value given.
        rho: f64,
    },
    /// The correlation matrix is not positive definite: the correlations given
    /// contradict each other. `pair` is the largest given correlation of the first
    /// input at which the leading block stops being positive definite.
    #[error("the correlations are not consistent (the matrix is not positive definite){}", match pair {
        Some((i, j)) => format!("; the contradiction appears with correlation ({i}, {j})"),
        None => String::new(),
    })]
    NotPositiveDefinite {
        /// The pair blamed, if one can be.
        pair: Option<(usize, usize)>,
    },
}

/// The joint input model: marginals and the Cholesky factor of the copula.
#[derive(Debug, Clone)]
pub struct InputModel {
    marginals: Vec<Distribution>,
    /// Lower Cholesky factor of the copula correlation matrix; `None`: independent.
    cholesky: Option<DMatrix<f64>>,
}

impl InputModel {
    /// The model of `marginals` joined by a Gaussian copula with the normal-score
    /// correlations `(i, j, ρ)` (0-based indices, each unordered pair at most once,
    /// pairs not given uncorrelated). Checks every marginal, |ρ| < 1, and that
    /// the correlation matrix is positive definite.
    pub fn new(
        marginals: Vec<Distribution>,
        correlations: &[(usize, usize, f64)],
    ) -> Result<InputModel, ModelError> {
        let dim = marginals.len();
        if dim == 0 {
            return Err(ModelError::Empty);
        }
        for (index, m) in marginals.iter().enumerate() {
            m.validate()
                .map_err(|source| ModelError::Distribution { index, source })?;
        }
        let mut r = DMatrix::<f64>::identity(dim, dim);
        let mut given = vec![false; dim * dim];
        for &(i, j, rho) in correlations {
            for missing in [i, j] {
                if missing >= dim {
                    return Err(ModelError::UnknownInput { i, j, missing, dim });
                }
            }
            if i == j {
                return Err(ModelError::SelfCorrelation { i });
            }
            if !(rho.is_finite() && rho.abs() < 1.0) {
                return Err(ModelError::OutOfRange { i, j, rho });
            }
            let (a, b) = (i.min(j), i.max(j));
            if given[a * dim + b] {
                return Err(ModelError::Duplicate { i, j });
            }
            given[a * dim + b] = true;
            r[(a, b)] = rho;
            r[(b, a)] = rho;
        }
        let cholesky = if correlations.iter().all(|c| c.2 == 0.0) {
            None
        } else {
            match r.clone().cholesky() {
                Some(c) => Some(c.l()),
                None => return Err(ModelError::NotPositiveDefinite { pair: blame(&r) }),
            }
        };
        Ok(InputModel {
            marginals,
            cholesky,
        })
    }

    /// Independent inputs with these marginals.
    pub fn independent(marginals: Vec<Distribution>) -> Result<InputModel, ModelError> {
        InputModel::new(marginals, &[])
    }

    /// The number of inputs.
    pub fn dim(&self) -> usize {
        self.marginals.len()
    }

    /// The marginal laws.
    pub fn marginals(&self) -> &[Distribution] {
        &self.marginals
    }

    /// Whether the inputs are correlated.
    pub fn is_correlated(&self) -> bool {
        self.cholesky.is_some()
    }

    /// The normal scores z = L·u of independent standard normal `u`.
    pub fn scores(&self, u: &[f64]) -> Vec<f64> {
        match &self.cholesky {
            None => u.to_vec(),
            Some(l) => (0..self.dim())
                .map(|i| (0..=i).map(|j| l[(i, j)] * u[j]).sum())
                .collect(),
        }
    }

    /// The physical point x_i = F_i⁻¹(Φ(z_i)), z = L·u, of independent standard
    /// normal `u` (length [`InputModel::dim`]).
    pub fn to_physical(&self, u: &[f64]) -> Vec<f64> {
        debug_assert_eq!(u.len(), self.dim());
        self.scores(u)
            .iter()
            .zip(&self.marginals)
            .map(|(&z, m)| m.from_std_normal(z))
            .collect()
    }

    /// The independent standard normal `u` of a physical point `x` (the inverse of
    /// [`InputModel::to_physical`]): z_i = Φ⁻¹(F_i(x_i)), u = L⁻¹·z.
    pub fn to_standard(&self, x: &[f64]) -> Vec<f64> {
        debug_assert_eq!(x.len(), self.dim());
        let z: Vec<f64> = x
            .iter()
            .zip(&self.marginals)
            .map(|(&x, m)| m.to_std_normal(x))
            .collect();
        match &self.cholesky {
            None => z,
            Some(l) => {
                let mut u = vec![0.0; z.len()];
                for i in 0..z.len() {
                    let s: f64 = (0..i).map(|j| l[(i, j)] * u[j]).sum();
                    u[i] = (z[i] - s) / l[(i, i)];
                }
                u
            }
        }
    }

    /// The physical point of a point `v` of the open unit cube (0, 1)^d of
    /// independent uniform variables: u_i = Φ⁻¹(v_i), then [`InputModel::to_physical`].
    /// Without correlations x_i = F_i⁻¹(v_i).
    pub fn from_unit(&self, v: &[f64]) -> Vec<f64> {
        if self.cholesky.is_none() {
            return v
                .iter()
                .zip(&self.marginals)
                .map(|(&v, m)| m.quantile(v))
                .collect();
        }
        let u: Vec<f64> = v.iter().map(|&v| std_normal_quantile(v)).collect();
        self.to_physical(&u)
    }

    /// The unit-cube point of a physical point (the inverse of [`InputModel::from_unit`]).
    pub fn to_unit(&self, x: &[f64]) -> Vec<f64> {
        self.to_standard(x)
            .iter()
            .map(|&u| std_normal_cdf(u))
            .collect()
    }
}

/// The pair to blame for a matrix that is not positive definite: the largest
/// |ρ| in the row of the first leading block that fails.
fn blame(r: &DMatrix<f64>) -> Option<(usize, usize)> {
    let n = r.nrows();
    for k in 2..=n {
        let block = r.view((0, 0), (k, k)).clone_owned();
        if block.cholesky().is_none() {
            let row = k - 1;
            return (0..row)
                .filter(|&j| r[(row, j)] != 0.0)
                .max_by(|&a, &b| r[(row, a)].abs().total_cmp(&r[(row, b)].abs()))
                .map(|j| (j, row));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn normals(n: usize) -> Vec<Distribution> {
        vec![Distribution::Normal { mean: 0.0, sd: 1.0 }; n]
    }

    #[test]
    fn rejects_bad_correlations() {
        assert_eq!(
            InputModel::new(normals(2), &[(0, 1, 1.0)]).unwrap_err(),
            ModelError::OutOfRange {
                i: 0,
                j: 1,
                rho: 1.0
            }
        );
        assert!(matches!(
            InputModel::new(normals(2), &[(0, 2, 0.1)]),
            Err(ModelError::UnknownInput { missing: 2, .. })
        ));
        assert!(matches!(
            InputModel::new(normals(2), &[(0, 1, 0.1), (1, 0, 0.2)]),
            Err(ModelError::Duplicate { .. })
        ));
        // ρ01 = ρ12 = 0.9 and ρ02 = −0.9 cannot hold together.
        let e = InputModel::new(normals(3), &[(0, 1, 0.9), (1, 2, 0.9), (0, 2, -0.9)]).unwrap_err();
        assert!(
            matches!(e, ModelError::NotPositiveDefinite { pair: Some((_, 2)) }),
            "{e:?}"
        );
        let e = InputModel::new(
            vec![Distribution::Normal {
                mean: 0.0,
                sd: -1.0,
            }],
            &[],
        )
        .unwrap_err();
        assert!(e.to_string().starts_with("input 0: normal sd = -1"), "{e}");
    }

    #[test]
    fn physical_and_standard_roundtrip() {
        let m = InputModel::new(
            vec![
                Distribution::Lognormal {
                    median: 2.0,
                    factor: 1.5,
                },
                Distribution::Beta {
                    alpha: 2.0,
                    beta: 3.0,
                    min: -1.0,
                    max: 4.0,
                },
                Distribution::Triangular {
                    min: 0.0,
                    mode: 1.0,
                    max: 3.0,
                },
            ],
            &[(0, 1, 0.5), (1, 2, -0.3)],
        )
        .unwrap();
        let u = [0.3, -1.2, 2.0];
        let x = m.to_physical(&u);
        let back = m.to_standard(&x);
        for (a, b) in u.iter().zip(&back) {
            assert!((a - b).abs() < 1e-10, "{u:?} -> {back:?}");
        }
        let v = m.to_unit(&x);
        let again = m.from_unit(&v);
        for (a, b) in x.iter().zip(&again) {
            assert!((a - b).abs() < 1e-10 * a.abs().max(1.0));
        }
    }
}
