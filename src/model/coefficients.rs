//! The coefficients of the non-dimensional model (docs/model.md §3) and the
//! elastic–plastic transition of one asperity (eqs. 9 and 12, corrected).

use std::f64::consts::PI;

/// √(6π), the factor in `c_a = √(6π) θ^{-1/2}`.
const SQRT_6PI: f64 = 4.341_607_527_349_605;

/// π (18/π²)^{1/4}, the factor in `c_h = π (18/π²)^{1/4} λ^{1/4} θ^{-1/2}`.
fn c_h_factor() -> f64 {
    PI * (18.0 / (PI * PI)).powf(0.25)
}

/// The five coefficients of the non-dimensional load law.
///
/// They are carried instead of θ and λ so that the limits γ = 0 (no adhesion:
/// `c_a = c_d = c_0 = 0`, `c_h` finite) and H = ∞ (no plasticity: `c_h = ∞`)
/// are exact rather than ∞/∞.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    /// `c_a = √(6π) θ^{-1/2}`: adhesive term of the JKR asperity load (eq. 1).
    pub c_a: f64,
    /// `c_d = (2/3) c_a`: JKR displacement offset (eq. 10, corrected).
    pub c_d: f64,
    /// `c_h = π R^{1/2} H / (K σ^{1/2})`: hardness term of the plasticity onset (eq. 9); may be ∞.
    pub c_h: f64,
    /// `c_p = 2 c_h`: plastic asperity stiffness (eq. 2 with r_p² = 2Rδ); may be ∞.
    pub c_p: f64,
    /// `c_0 = 2π/θ = c_a²/3`: adhesive term of the plastic asperity load (eq. 2).
    pub c_0: f64,
}

/// The largest finite c_a or c_h the guarded entry points accept.
pub const MAX_COEFFICIENT: f64 = 1e100;

/// The largest |h| the guarded entry point accepts.
pub const MAX_SEPARATION: f64 = 1e6;

/// An input outside the model's domain (the guarded entry points return it).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DomainError {
    /// c_a must be finite and >= 0.
    #[error("c_a = {0}: must lie in [0, 1e100] (0 means no adhesion)")]
    AdhesiveCoefficient(f64),
    /// c_h must be > 0 (inf allowed).
    #[error("c_h = {0}: must lie in (0, 1e100] or be inf (no plasticity)")]
    HardnessCoefficient(f64),
    /// theta, lambda must be > 0 and not NaN.
    #[error("{name} = {value}: must be > 0")]
    Index {
        /// Which index.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// h must be finite.
    #[error("h = {0}: the separation must lie in [-1e6, 1e6]")]
    Separation(f64),
}

impl Coefficients {
    /// As [`Coefficients::new`], refusing inputs outside the model's domain
    /// (NaN anywhere, c_a < 0 or infinite, c_h <= 0) instead of letting them
    /// reach the special functions.
    ///
    /// The accepted box, c_a in [0, 1e100] and c_h in (0, 1e100] or inf, is where
    /// the stability properties hold (tests/all/stability.rs); it reaches far past any
    /// physical scene (theta = 6 pi / c_a^2 >= 2e-199).
    pub fn checked(c_a: f64, c_h: f64) -> Result<Self, DomainError> {
        if !(0.0..=MAX_COEFFICIENT).contains(&c_a) {
            return Err(DomainError::AdhesiveCoefficient(c_a));
        }
        let finite_ok = c_h > 0.0 && c_h <= MAX_COEFFICIENT;
        if !finite_ok && c_h != f64::INFINITY {
            return Err(DomainError::HardnessCoefficient(c_h));
        }
        Ok(Coefficients::new(c_a, c_h))
    }

    /// From the adhesive coefficient `c_a ≥ 0` and hardness coefficient `c_h ∈ (0, ∞]`.
    pub fn new(c_a: f64, c_h: f64) -> Self {
        Coefficients {
            c_a,
            c_d: 2.0 / 3.0 * c_a,
            c_h,
            c_p: 2.0 * c_h,
            c_0: c_a * c_a / 3.0,
        }
    }

    /// From the elastic adhesion index θ and plastic adhesion index λ (both
    /// finite and > 0). Use [`Coefficients::new`] for the limits.
    pub fn from_indices(theta: f64, lambda: f64) -> Self {
        let c_a = SQRT_6PI / theta.sqrt();
        let c_h = c_h_factor() * lambda.powf(0.25) / theta.sqrt();
        let mut c = Coefficients::new(c_a, c_h);
        c.c_0 = 2.0 * PI / theta;
        c
    }

    /// From θ and λ where either may be +∞ (γ = 0 makes both infinite; then
    /// `c_h_no_adhesion` supplies c_h, since it cannot be recovered from them).
    pub fn from_indices_or_limits(theta: f64, lambda: f64, c_h_no_adhesion: f64) -> Self {
        if theta.is_infinite() {
            Coefficients::new(0.0, c_h_no_adhesion)
        } else if lambda.is_infinite() {
            Coefficients::new(SQRT_6PI / theta.sqrt(), f64::INFINITY)
        } else {
            Coefficients::from_indices(theta, lambda)
        }
    }

    /// True when γ > 0.
    pub fn has_adhesion(&self) -> bool {
        self.c_a > 0.0
    }

    /// True when H < ∞.
    pub fn has_plasticity(&self) -> bool {
        self.c_h.is_finite()
    }

    /// θ = 6π / c_a² (∞ without adhesion).
    pub fn elastic_adhesion_index(&self) -> f64 {
        6.0 * PI / (self.c_a * self.c_a)
    }

    /// λ = (c_h θ^{1/2} / (π (18/π²)^{1/4}))⁴ (∞ without adhesion or plasticity).
    pub fn plastic_adhesion_index(&self) -> f64 {
        (self.c_h * self.elastic_adhesion_index().sqrt() / c_h_factor()).powi(4)
    }

    /// The single-asperity load at zero actual interference, `p_e(0) = -c_a c_d / 3`
    /// (the JKR value -(4/3)πγR in units of K R^{1/2} σ^{3/2}).
    pub fn load_at_touch(&self) -> f64 {
        -self.c_a * self.c_d / 3.0
    }

    /// The elastic–plastic transition of one asperity.
    pub fn transition(&self) -> Transition {
        Transition::new(self)
    }
}

/// The onset of plasticity in one asperity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Transition {
    /// t = Δcl^{1/4}, the positive root of `t³ - c_h t - c_a = 0` (eq. 9); ∞ without plasticity.
    pub t: f64,
    /// Δc, the actual critical interference `t⁴ - c_d t = t (c_h t + c_a/3)` (eq. 12).
    pub critical_interference: f64,
    /// J = p_p(Δc) - p_e(Δc), the load jump at the transition; negative when
    /// λ^{3/2}/θ < 0.009823 (strong adhesion, soft asperities). 0 without plasticity.
    pub jump: f64,
}

impl Transition {
    fn new(c: &Coefficients) -> Self {
        if !c.has_plasticity() {
            return Transition {
                t: f64::INFINITY,
                critical_interference: f64::INFINITY,
                jump: 0.0,
            };
        }
        let t = transition_root(c.c_a, c.c_h);
        let y = c.c_h * t;
        let critical_interference = if c.c_a == 0.0 {
            c.c_h * c.c_h
        } else {
            t * (y + c.c_a / 3.0)
        };
        Transition {
            t,
            critical_interference,
            jump: y * y - y * c.c_a / 3.0 - c.c_a * c.c_a / 3.0,
        }
    }
}

/// The unique positive root of `t³ - c_h t - c_a = 0` for `c_a ≥ 0`, `0 < c_h < ∞`.
///
/// Newton's method from `√c_h + c_a^{1/3}`, which lies right of the root (the
/// cubic is ≥ 0 there) where the cubic is convex and increasing, so the
/// iterates fall monotonically to the root; f'(t) = 3t² - c_h > 2c_h at the
/// root, so convergence is quadratic and the root well conditioned.
pub fn transition_root(c_a: f64, c_h: f64) -> f64 {
    if c_a == 0.0 {
        return c_h.sqrt();
    }
    let mut t = c_h.sqrt() + c_a.cbrt();
    for _ in 0..100 {
        let f = t * (t * t - c_h) - c_a;
        let step = f / (3.0 * t * t - c_h);
        let next = t - step;
        if next >= t || next.is_nan() {
            break;
        }
        t = next;
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_decimals() {
        // docs/model.md §3: c_a ≈ 4.342/√θ, c_d ≈ 2.894/√θ, c_h ≈ 3.651 λ^{1/4}/√θ, c_0 ≈ 6.283/θ.
        let c = Coefficients::from_indices(1.0, 1.0);
        assert!((c.c_a - 4.342).abs() < 5e-4);
        assert!((c.c_d - 2.894).abs() < 5e-4);
        assert!((c.c_h - 3.651).abs() < 5e-4);
        assert!((c.c_p - 7.302).abs() < 1e-3);
        // The paper prints 6.28 for c_0 = 2π.
        assert!((c.c_0 - std::f64::consts::TAU).abs() < 1e-15);
        // c_0 = c_a²/3 exactly.
        assert!((c.c_0 - c.c_a * c.c_a / 3.0).abs() < 1e-14 * c.c_0);
        // Round trip of the indices.
        let c = Coefficients::from_indices(25.0, 0.125);
        assert!((c.elastic_adhesion_index() / 25.0 - 1.0).abs() < 1e-14);
        assert!((c.plastic_adhesion_index() / 0.125 - 1.0).abs() < 1e-13);
    }

    #[test]
    fn transition_root_solves_the_cubic() {
        for &(c_a, c_h) in &[
            (1.0, 1.0),
            (137.0, 1e-5),
            (1e-4, 3650.0),
            (13.7, 2.05),
            (1e-12, 1e12),
        ] {
            let t = transition_root(c_a, c_h);
            let residual = t * t * t - c_h * t - c_a;
            // Relative to the size of the terms.
            assert!(
                residual.abs() <= 4e-16 * (t * t * t + c_h * t + c_a),
                "{c_a} {c_h}"
            );
            assert!(t > 0.0);
        }
        // Without adhesion Δc = c_h² (docs/model.md §3).
        let tr = Coefficients::new(0.0, 3.0).transition();
        assert_eq!(tr.critical_interference, 9.0);
        // The jump equals p_p(Δc) - p_e(Δc) evaluated directly.
        let c = Coefficients::from_indices(0.1, 1e-3);
        let tr = c.transition();
        let dc = tr.critical_interference;
        let pe = tr.t.powi(6) - c.c_a * tr.t.powi(3);
        let pp = c.c_p * dc - c.c_0;
        assert!(((pp - pe) - tr.jump).abs() < 1e-12 * pe.abs());
        assert!(tr.jump < 0.0);
        // docs/model.md: Δc for θ = 0.1, λ = 1e-3 makes the local extrema sit near h ≈ -27.
        assert!((dc - 26.95).abs() < 0.05, "{dc}");
    }

    #[test]
    fn jump_sign_threshold() {
        // J < 0 exactly when λ^{3/2}/θ < 0.009823 (docs/model.md §3).
        for &theta in &[0.01, 1.0, 100.0] {
            let lambda_at = |r: f64| (r * theta).powf(2.0 / 3.0);
            let below = Coefficients::from_indices(theta, lambda_at(0.0098))
                .transition()
                .jump;
            let above = Coefficients::from_indices(theta, lambda_at(0.00985))
                .transition()
                .jump;
            assert!(below < 0.0 && above > 0.0, "θ={theta}: {below} {above}");
        }
    }
}
