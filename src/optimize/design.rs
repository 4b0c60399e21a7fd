//! The design space: the variables a study may move, searched in [0, 1]^n with
//! logarithmic scaling, so that 1e-9 m and 1e11 Pa look alike to the solver.

use super::study::{DesignVariable, SceneParameter};
use crate::model::Scene;

/// One design variable and its map from the unit interval.
#[derive(Debug, Clone, PartialEq)]
pub struct Variable {
    /// Which scene quantity it moves.
    pub quantity: SceneParameter,
    /// Lower bound (SI).
    pub min: f64,
    /// Upper bound (SI).
    pub max: f64,
    /// Logarithmic (min > 0) or linear (a Poisson ratio, a γ range starting at 0) scaling.
    pub logarithmic: bool,
}

impl Variable {
    fn value_at(&self, u: f64) -> f64 {
        let u = u.clamp(0.0, 1.0);
        // A variable fixed by its bounds (min = max) is its bound at every u, not
        // exp(ln min) an ulp away.
        if u == 0.0 || self.min == self.max {
            return self.min;
        }
        if u == 1.0 {
            return self.max;
        }
        if self.logarithmic {
            (self.min.ln() + u * (self.max.ln() - self.min.ln())).exp()
        } else {
            self.min + u * (self.max - self.min)
        }
    }

    fn unit_of(&self, value: f64) -> f64 {
        let u = if self.logarithmic {
            (value.ln() - self.min.ln()) / (self.max.ln() - self.min.ln())
        } else {
            (value - self.min) / (self.max - self.min)
        };
        if u.is_nan() {
            0.5
        } else {
            u.clamp(0.0, 1.0)
        }
    }
}

/// The scaled design space around a baseline scene.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignSpace {
    /// The variables, in problem-file order.
    pub variables: Vec<Variable>,
    /// The scene the fixed parameters come from.
    pub baseline: Scene,
    /// True when both bodies share the baseline Young's modulus: a
    /// `youngs_modulus` design variable then moves both.
    pub shared_modulus: bool,
}

impl DesignSpace {
    /// The space of `design` around `baseline`.
    pub fn new(baseline: &Scene, design: &[DesignVariable]) -> Self {
        DesignSpace {
            variables: design
                .iter()
                .map(|d| Variable {
                    quantity: d.name,
                    min: d.min,
                    max: d.max,
                    // Poisson ratios may be negative, and contact angles are
                    // read on a linear scale (cos θ drives the meniscus): linear.
                    logarithmic: d.min > 0.0
                        && !matches!(
                            d.name,
                            SceneParameter::PoissonRatio
                                | SceneParameter::ContactAngle
                                | SceneParameter::ContactAngleA
                                | SceneParameter::ContactAngleB
                        ),
                })
                .collect(),
            baseline: baseline.clone(),
            shared_modulus: baseline.youngs_modulus_a == baseline.youngs_modulus_b
                && baseline.poisson_ratio_a == baseline.poisson_ratio_b,
        }
    }

    /// n, the number of variables.
    pub fn dim(&self) -> usize {
        self.variables.len()
    }

    /// The baseline design in unit coordinates (clamped into the box).
    pub fn baseline_unit(&self) -> Vec<f64> {
        self.variables
            .iter()
            .map(|v| v.unit_of(v.quantity.get(&self.baseline)))
            .collect()
    }

    /// The unit point of the SI design `values` (the inverse of [`DesignSpace::values`],
    /// clamped into the box; a value the map cannot place, NaN or a degenerate
    /// variable, is the box's middle).
    pub fn unit(&self, values: &[f64]) -> Vec<f64> {
        self.variables
            .iter()
            .zip(values)
            .map(|(v, &value)| v.unit_of(value))
            .collect()
    }

    /// SI values of the variables at unit point x.
    pub fn values(&self, x: &[f64]) -> Vec<f64> {
        self.variables
            .iter()
            .zip(x)
            .map(|(v, &u)| v.value_at(u))
            .collect()
    }

    /// The scene at unit point x.
    pub fn scene_at(&self, x: &[f64]) -> Scene {
        let mut scene = self.baseline.clone();
        for (v, &u) in self.variables.iter().zip(x) {
            let value = v.value_at(u);
            v.quantity.set(&mut scene, value);
            if self.shared_modulus {
                match v.quantity {
                    SceneParameter::YoungsModulus => scene.youngs_modulus_b = value,
                    SceneParameter::PoissonRatio => scene.poisson_ratio_b = value,
                    _ => {}
                }
            }
        }
        scene
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_map_round_trips_and_hits_the_bounds() {
        let v = Variable {
            quantity: SceneParameter::Sigma,
            min: 0.5e-9,
            max: 20e-9,
            logarithmic: true,
        };
        assert_eq!(v.value_at(0.0), 0.5e-9);
        assert_eq!(v.value_at(1.0), 20e-9);
        for &x in &[1e-9, 3e-9, 19e-9] {
            assert!((v.value_at(v.unit_of(x)) / x - 1.0).abs() < 1e-14);
        }
        // The geometric midpoint maps to 1/2.
        assert!((v.unit_of((0.5e-9f64 * 20e-9).sqrt()) - 0.5).abs() < 1e-14);
    }

    /// A variable whose bounds meet (min = max) is its bound at every unit point,
    /// exactly: the map's middle (where `unit_of` puts it) must not come back as
    /// exp(ln min), which can be an ulp away.
    #[test]
    fn a_variable_fixed_by_its_bounds_is_its_bound() {
        for &x in &[3e-9, 7.3e-9, 1.1e11, 0.17] {
            let v = Variable {
                quantity: SceneParameter::Sigma,
                min: x,
                max: x,
                logarithmic: true,
            };
            for u in [0.0, 0.25, 0.5, 1.0, v.unit_of(x)] {
                assert_eq!(v.value_at(u), x, "{x} at {u}");
            }
        }
        // Some x is an ulp off through exp(ln x): the case the rule is for.
        assert!((1..2000)
            .map(|i| i as f64 * 1.37e-9)
            .any(|x: f64| x.ln().exp() != x));
    }
}
