//! The humid air around a contact (docs/model.md §10): the liquid, the humidity and
//! temperature, the contact angles, and the Kelvin meniscus they make. A scene's input
//! (`Scene::environment`); imports nothing of the crate, so the scene, the capillary
//! term and the reports can all read it.

use serde::Serialize;

/// R_g, the molar gas constant (J/(mol K)), CODATA 2018 (exact).
pub const GAS_CONSTANT: f64 = 8.314_462_618;
/// T_c of water (K), IAPWS 1994.
pub const WATER_CRITICAL_TEMPERATURE: f64 = 647.096;
/// V_m of liquid water (m³/mol) at 25 °C (docs/model.md §10).
pub const WATER_MOLAR_VOLUME: f64 = 1.8069e-5;
/// 25 °C in kelvin, the default temperature.
pub const ROOM_TEMPERATURE: f64 = 298.15;
/// Below this Kelvin radius (m) the continuum Kelvin equation is doubtful.
pub const MIN_KELVIN_RADIUS: f64 = 0.5e-9;

/// The condensing liquid.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Liquid {
    /// Water: γ_L(T) by the IAPWS 1994 formula, V_m = 1.8069e-5 m³/mol.
    #[default]
    Water,
    /// A liquid given by its surface tension and molar volume.
    Given {
        /// γ_L (N/m), > 0.
        surface_tension: f64,
        /// V_m (m³/mol), > 0.
        molar_volume: f64,
    },
}

impl Liquid {
    /// γ_L at temperature T (N/m); for water 0 at and above its critical point.
    pub fn surface_tension(self, temperature: f64) -> f64 {
        match self {
            Liquid::Water => water_surface_tension(temperature),
            Liquid::Given {
                surface_tension, ..
            } => surface_tension,
        }
    }

    /// V_m (m³/mol).
    pub fn molar_volume(self) -> f64 {
        match self {
            Liquid::Water => WATER_MOLAR_VOLUME,
            Liquid::Given { molar_volume, .. } => molar_volume,
        }
    }
}

/// γ_L of water (N/m), IAPWS 1994: 0.2358 τ^1.256 (1 - 0.625 τ), τ = 1 - T/T_c
/// (71.97 mN/m at 298.15 K); 0 at and above T_c.
pub fn water_surface_tension(temperature: f64) -> f64 {
    let tau = 1.0 - temperature / WATER_CRITICAL_TEMPERATURE;
    if tau > 0.0 {
        0.2358 * tau.powf(1.256) * (1.0 - 0.625 * tau)
    } else {
        0.0
    }
}

/// The air around the contact: humidity, temperature, the liquid and its
/// contact angles on the two bodies (the problem file's `[environment]` and
/// `[interface] contact_angle`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Environment {
    /// RH in [0, 1); 0 is dry air (no meniscus).
    pub relative_humidity: f64,
    /// T (K), > 0.
    pub temperature: f64,
    /// The condensing liquid.
    pub liquid: Liquid,
    /// θ_a, the liquid's contact angle on body a (rad), in [0, π].
    pub contact_angle_a: f64,
    /// θ_b, on body b (rad), in [0, π].
    pub contact_angle_b: f64,
    /// A study's humidity range (`relative_humidity = { min, max }`): its limits hold
    /// at each of these humidities; None for one humidity. An evaluation uses
    /// `relative_humidity` (the design humidity) and ignores the range.
    pub humidity_range: Option<HumidityRange>,
}

/// The humidities a design must hold over (docs/model.md §10), evenly spaced, both
/// ends included.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HumidityRange {
    /// The driest, in [0, 1).
    pub min: f64,
    /// The wettest, in (min, 1).
    pub max: f64,
    /// How many humidities, ≥ 2 (`humidity_points`, default 9).
    pub points: usize,
    /// Whether the file named the humidity the objective is taken at
    /// (`design_humidity`); otherwise a study takes the worst one for the objective.
    pub design_given: bool,
}

impl HumidityRange {
    /// The humidities, ascending, both ends exact.
    pub fn humidities(&self) -> Vec<f64> {
        let n = self.points.max(2);
        (0..n)
            .map(|i| {
                if i == n - 1 {
                    self.max
                } else {
                    self.min + (self.max - self.min) * i as f64 / (n - 1) as f64
                }
            })
            .collect()
    }
}

impl Default for Environment {
    /// Dry air at 25 °C, water, fully wetting surfaces.
    fn default() -> Self {
        Environment {
            relative_humidity: 0.0,
            temperature: ROOM_TEMPERATURE,
            liquid: Liquid::Water,
            contact_angle_a: 0.0,
            contact_angle_b: 0.0,
            humidity_range: None,
        }
    }
}

/// The Kelvin meniscus at a humidity (SI).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Meniscus {
    /// γ_L (N/m).
    pub surface_tension: f64,
    /// r_K = γ_L V_m / (R_g T ln(1/RH)) (m).
    pub kelvin_radius: f64,
    /// d_K = r_K (cos θ_a + cos θ_b): the widest gap the liquid bridges (m).
    pub height: f64,
    /// Δp = γ_L / r_K (Pa): the tension in the liquid.
    pub laplace_pressure: f64,
    /// γ_c = γ_L (cos θ_a + cos θ_b) = Δp d_K (N/m): the flooded interface's Γ.
    pub adhesion: f64,
}

impl Environment {
    /// cos θ_a + cos θ_b, 0 where its magnitude is below the rounding of the
    /// cosines near 90° (|sum| ≤ 8 ε ≈ 1.8e-15, an angle within 1e-13° of 90°):
    /// cos(π/2) in floating point is 6.1e-17, not 0, and two right angles would
    /// otherwise condense a meniscus 6e-25 m high where docs/model.md §10 says none.
    pub fn cos_sum(&self) -> f64 {
        let sum = self.contact_angle_a.cos() + self.contact_angle_b.cos();
        if sum.abs() <= 8.0 * f64::EPSILON {
            0.0
        } else {
            sum
        }
    }

    /// The meniscus, or None where nothing condenses: RH = 0, cos θ_a + cos θ_b ≤ 0,
    /// or a liquid without surface tension (water at or above its critical point).
    pub fn meniscus(&self) -> Option<Meniscus> {
        let rh = self.relative_humidity;
        let cos_sum = self.cos_sum();
        let gamma = self.liquid.surface_tension(self.temperature);
        if !(rh > 0.0 && rh < 1.0 && cos_sum > 0.0 && gamma > 0.0) {
            return None;
        }
        // ln(1/RH) = -ln RH, with ln_1p near RH = 1 (no cancellation in 1 - RH).
        let log_inverse = if rh > 0.5 {
            -(-(1.0 - rh)).ln_1p()
        } else {
            -rh.ln()
        };
        let kelvin_radius =
            gamma * self.liquid.molar_volume() / (GAS_CONSTANT * self.temperature * log_inverse);
        let height = kelvin_radius * cos_sum;
        let laplace_pressure = gamma / kelvin_radius;
        Some(Meniscus {
            surface_tension: gamma,
            kelvin_radius,
            height,
            laplace_pressure,
            adhesion: gamma * cos_sum,
        })
    }
}
