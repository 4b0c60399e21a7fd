//! The scene's scalar parameters in one table: each one's key, symbol and
//! dimension, how it is read from and set on a [`Scene`], and which roles it takes
//! (a design variable, a wear-rate sensitivity, a magnitude checked for
//! plausibility, with its range). Design variables (`optimize`), sensitivities,
//! the plausibility warnings and the accuracy report all read it from here, so a
//! parameter means the same thing to each: moving `youngs_modulus` moves body b's
//! modulus too wherever the two bodies share one.
//!
//! A new scene parameter is one variant and one row here (and its problem-file key
//! in `problem`).

use serde::Serialize;

use super::scene::Scene;
use crate::units::Dimension;

/// A scalar of a scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SceneParameter {
    /// E, Young's modulus (Pa) of body a, and of body b too when both share it
    /// (the same modulus and Poisson ratio).
    YoungsModulus,
    /// E1, Young's modulus of body a alone (Pa).
    YoungsModulusA,
    /// E2, Young's modulus of the counterface b alone (Pa).
    YoungsModulusB,
    /// ν, Poisson ratio of body a, and of body b too when both share it.
    PoissonRatio,
    /// H, hardness of the softer body (Pa).
    Hardness,
    /// γ, work of adhesion (J/m²).
    WorkOfAdhesion,
    /// σ, standard deviation of asperity heights (m).
    Sigma,
    /// R, asperity tip radius (m).
    AsperityRadius,
    /// N, asperities per unit area (1/m²).
    AsperityDensity,
    /// A_n, nominal contact area (m²).
    NominalArea,
    /// |W|, the magnitude of the normal load (N).
    Load,
    /// Z0, the interatomic (equilibrium) distance (m).
    InteratomicDistance,
    /// θ, the liquid's contact angle on both bodies (rad; docs/model.md §10): body a's
    /// is read, both are set.
    ContactAngle,
    /// θ_a, the contact angle on body a alone (rad).
    ContactAngleA,
    /// θ_b, the contact angle on body b alone (rad).
    ContactAngleB,
    /// T, the temperature of the contact, and of the air and the liquid where the
    /// scene has an environment (K; docs/model.md §10, §12); 298.15 K by default.
    Temperature,
    /// k, the Archard wear coefficient (docs/model.md §1, §3).
    WearCoefficient,
    /// L, the sliding distance (m; docs/model.md §1, §3).
    SlidingDistance,
    /// RH, the relative humidity of the air (docs/model.md §10): read where the
    /// scene has an environment ([`SceneParameter::value`]).
    RelativeHumidity,
    /// ΔU, the stress-assisted wear law's activation energy (J; docs/model.md §12):
    /// read where the scene has that law.
    ActivationEnergy,
    /// ΔV, its activation volume (m³; docs/model.md §12).
    ActivationVolume,
    /// v, its sliding speed (m/s; docs/model.md §12).
    SlidingSpeed,
}

/// One row of the table.
struct Row {
    key: &'static str,
    symbol: &'static str,
    dimension: Dimension,
    design_variable: bool,
    sensitivity: bool,
    /// The range of magnitudes found in MEMS, NEMS and storage contacts; `None`:
    /// none known. Only [`SceneParameter::CHECKED`] warn outside it.
    plausible: Option<(f64, f64)>,
}

impl SceneParameter {
    /// Every parameter, in table order.
    pub const ALL: [SceneParameter; 22] = [
        SceneParameter::YoungsModulus,
        SceneParameter::YoungsModulusA,
        SceneParameter::YoungsModulusB,
        SceneParameter::PoissonRatio,
        SceneParameter::Hardness,
        SceneParameter::WorkOfAdhesion,
        SceneParameter::Sigma,
        SceneParameter::AsperityRadius,
        SceneParameter::AsperityDensity,
        SceneParameter::NominalArea,
        SceneParameter::Load,
        SceneParameter::InteratomicDistance,
        SceneParameter::ContactAngle,
        SceneParameter::ContactAngleA,
        SceneParameter::ContactAngleB,
        SceneParameter::Temperature,
        SceneParameter::WearCoefficient,
        SceneParameter::SlidingDistance,
        SceneParameter::RelativeHumidity,
        SceneParameter::ActivationEnergy,
        SceneParameter::ActivationVolume,
        SceneParameter::SlidingSpeed,
    ];

    /// The parameters a design may move (the keys of `[design]`), in the order
    /// problem files and messages list them.
    pub const DESIGN: [SceneParameter; 16] = [
        SceneParameter::YoungsModulus,
        SceneParameter::YoungsModulusA,
        SceneParameter::YoungsModulusB,
        SceneParameter::PoissonRatio,
        SceneParameter::Hardness,
        SceneParameter::WorkOfAdhesion,
        SceneParameter::Sigma,
        SceneParameter::AsperityRadius,
        SceneParameter::AsperityDensity,
        SceneParameter::ContactAngle,
        SceneParameter::ContactAngleA,
        SceneParameter::ContactAngleB,
        SceneParameter::Temperature,
        SceneParameter::ActivationEnergy,
        SceneParameter::ActivationVolume,
        SceneParameter::SlidingSpeed,
    ];

    /// The parameters of the wear rate's elasticities, in report order.
    pub const SENSITIVITIES: [SceneParameter; 5] = [
        SceneParameter::YoungsModulus,
        SceneParameter::Hardness,
        SceneParameter::WorkOfAdhesion,
        SceneParameter::Sigma,
        SceneParameter::AsperityRadius,
    ];

    /// The magnitudes checked for plausibility, in warning order.
    pub const CHECKED: [SceneParameter; 10] = [
        SceneParameter::Sigma,
        SceneParameter::AsperityRadius,
        SceneParameter::AsperityDensity,
        SceneParameter::NominalArea,
        SceneParameter::Load,
        SceneParameter::YoungsModulusA,
        SceneParameter::YoungsModulusB,
        SceneParameter::Hardness,
        SceneParameter::WorkOfAdhesion,
        SceneParameter::InteratomicDistance,
    ];

    /// The table. Plausible ranges, SI units: σ 0.01 nm – 10 µm; R 1 nm – 10 mm;
    /// N 1 mm⁻² – 1000 µm⁻²; A_n 10 nm² – 100 cm²; |W| 1 pN – 100 N; E 1 MPa
    /// (elastomers) – 2 TPa (diamond is 1.1 TPa); H 1 MPa – 200 GPa; γ 10 µJ/m² –
    /// 10 J/m²; Z0 0.05 – 2 nm: generously wide, so that outside a value is more
    /// likely a forgotten unit than a design. Zero loads and γ, and infinite E or H
    /// (a rigid body, no plasticity) are limits the model treats exactly and are
    /// not checked. Known but not checked: k 10⁻¹² (a lubricated diamond-like
    /// film) – 1; L 1 nm (one stroke of a switch) – 10⁹ m (a year of a
    /// micro-motor's rim at 30 m/s); RH 0 – 1.
    fn row(self) -> Row {
        let row = |key, symbol, dimension, design_variable, sensitivity, plausible| Row {
            key,
            symbol,
            dimension,
            design_variable,
            sensitivity,
            plausible,
        };
        use Dimension::*;
        match self {
            SceneParameter::YoungsModulus => row("youngs_modulus", "E", Pressure, true, true, None),
            SceneParameter::YoungsModulusA => row(
                "youngs_modulus_a",
                "E1",
                Pressure,
                true,
                false,
                Some((1e6, 2e12)),
            ),
            SceneParameter::YoungsModulusB => row(
                "youngs_modulus_b",
                "E2",
                Pressure,
                true,
                false,
                Some((1e6, 2e12)),
            ),
            SceneParameter::PoissonRatio => {
                row("poisson_ratio", "ν", Dimensionless, true, false, None)
            }
            SceneParameter::Hardness => {
                row("hardness", "H", Pressure, true, true, Some((1e6, 2e11)))
            }
            SceneParameter::WorkOfAdhesion => row(
                "work_of_adhesion",
                "γ",
                SurfaceEnergy,
                true,
                true,
                Some((1e-5, 10.0)),
            ),
            SceneParameter::Sigma => row("sigma", "σ", Length, true, true, Some((1e-11, 1e-5))),
            SceneParameter::AsperityRadius => row(
                "asperity_radius",
                "R",
                Length,
                true,
                true,
                Some((1e-9, 1e-2)),
            ),
            SceneParameter::AsperityDensity => row(
                "asperity_density",
                "N",
                InverseArea,
                true,
                false,
                Some((1e6, 1e15)),
            ),
            SceneParameter::NominalArea => row(
                "nominal_area",
                "A_n",
                Area,
                false,
                false,
                Some((1e-17, 1e-2)),
            ),
            SceneParameter::Load => row("load", "|W|", Force, false, false, Some((1e-12, 100.0))),
            SceneParameter::InteratomicDistance => row(
                "interatomic_distance",
                "Z0",
                Length,
                false,
                false,
                Some((5e-11, 2e-9)),
            ),
            SceneParameter::ContactAngle => row("contact_angle", "θ", Angle, true, false, None),
            SceneParameter::ContactAngleA => {
                row("contact_angle_a", "θ_a", Angle, true, false, None)
            }
            SceneParameter::ContactAngleB => {
                row("contact_angle_b", "θ_b", Angle, true, false, None)
            }
            SceneParameter::Temperature => row("temperature", "T", Temperature, true, false, None),
            SceneParameter::WearCoefficient => row(
                "wear_coefficient",
                "k",
                Dimensionless,
                false,
                false,
                Some((1e-12, 1.0)),
            ),
            SceneParameter::SlidingDistance => row(
                "sliding_distance",
                "L",
                Length,
                false,
                false,
                Some((1e-9, 1e9)),
            ),
            SceneParameter::RelativeHumidity => row(
                "relative_humidity",
                "RH",
                Dimensionless,
                false,
                false,
                Some((0.0, 1.0)),
            ),
            SceneParameter::ActivationEnergy => {
                row("activation_energy", "ΔU", Energy, true, false, None)
            }
            SceneParameter::ActivationVolume => {
                row("activation_volume", "ΔV", Volume, true, false, None)
            }
            SceneParameter::SlidingSpeed => row("sliding_speed", "v", Speed, true, false, None),
        }
    }

    /// The key as problem files and reports write it.
    pub fn as_str(self) -> &'static str {
        self.row().key
    }

    /// The parameter whose key is `name`.
    pub fn from_key(name: &str) -> Option<SceneParameter> {
        Self::ALL.into_iter().find(|p| p.as_str() == name)
    }

    /// The paper's symbol.
    pub fn symbol(self) -> &'static str {
        self.row().symbol
    }

    /// The dimension of its values.
    pub fn dimension(self) -> Dimension {
        self.row().dimension
    }

    /// Whether a design may move it.
    pub fn is_design_variable(self) -> bool {
        self.row().design_variable
    }

    /// Whether `eval` reports the wear rate's elasticity with respect to it.
    pub fn is_sensitivity(self) -> bool {
        self.row().sensitivity
    }

    /// The range of plausible magnitudes (SI), where one is known; the scene's
    /// warnings check those of [`SceneParameter::CHECKED`].
    pub fn plausible_range(self) -> Option<(f64, f64)> {
        self.row().plausible
    }

    /// Whether it is one of the environment's values (relative humidity,
    /// temperature, contact angles), which a dry scene does not have.
    pub fn is_environmental(self) -> bool {
        // (The wear law's inputs are not: see [`SceneParameter::is_wear_law_input`].)
        matches!(
            self,
            SceneParameter::ContactAngle
                | SceneParameter::ContactAngleA
                | SceneParameter::ContactAngleB
                | SceneParameter::RelativeHumidity
        )
    }

    /// Whether it is an input of the stress-assisted wear law (ΔU, ΔV, v), which a
    /// scene under Archard's does not have.
    pub fn is_wear_law_input(self) -> bool {
        matches!(
            self,
            SceneParameter::ActivationEnergy
                | SceneParameter::ActivationVolume
                | SceneParameter::SlidingSpeed
        )
    }

    /// Its value in `scene` where the scene has it ([`SceneParameter::get`]):
    /// None for the environment's values of a scene without an environment (dry
    /// air, docs/model.md §10), whose defaults mean nothing to its evaluation, and
    /// for the wear law's inputs of a scene without that law.
    pub fn value(self, s: &Scene) -> Option<f64> {
        let has = (s.environment.is_some() || !self.is_environmental())
            && (s.activation.is_some() || !self.is_wear_law_input());
        has.then(|| self.get(s))
    }

    /// Its value in `scene` (SI; |W| for the load; body a's for a shared modulus or
    /// Poisson ratio; the dry air's defaults for the environment's values of a scene
    /// without one: RH = 0, T = 298.15 K, θ = 0).
    pub fn get(self, s: &Scene) -> f64 {
        match self {
            SceneParameter::YoungsModulus | SceneParameter::YoungsModulusA => s.youngs_modulus_a,
            SceneParameter::YoungsModulusB => s.youngs_modulus_b,
            SceneParameter::PoissonRatio => s.poisson_ratio_a,
            SceneParameter::Hardness => s.hardness,
            SceneParameter::WorkOfAdhesion => s.work_of_adhesion,
            SceneParameter::Sigma => s.sigma,
            SceneParameter::AsperityRadius => s.asperity_radius,
            SceneParameter::AsperityDensity => s.asperity_density,
            SceneParameter::NominalArea => s.nominal_area,
            SceneParameter::Load => s.load.abs(),
            SceneParameter::InteratomicDistance => s.interatomic_distance,
            SceneParameter::ContactAngle | SceneParameter::ContactAngleA => {
                s.environment.unwrap_or_default().contact_angle_a
            }
            SceneParameter::ContactAngleB => s.environment.unwrap_or_default().contact_angle_b,
            SceneParameter::Temperature => s.temperature,
            SceneParameter::WearCoefficient => s.wear_coefficient,
            SceneParameter::SlidingDistance => s.sliding_distance,
            SceneParameter::RelativeHumidity => s.environment.unwrap_or_default().relative_humidity,
            SceneParameter::ActivationEnergy => s.activation.map_or(0.0, |a| a.activation_energy),
            SceneParameter::ActivationVolume => s.activation.map_or(0.0, |a| a.activation_volume),
            SceneParameter::SlidingSpeed => s.activation.map_or(0.0, |a| a.sliding_speed),
        }
    }

    /// Sets its value in `scene` (SI). `youngs_modulus` and `poisson_ratio` move
    /// body b's value too when the bodies share modulus and Poisson ratio (one film
    /// on itself), as a design variable and a sensitivity both mean them; the load
    /// keeps its sign. An environment's value set on a dry scene gives it the dry
    /// air's defaults with that value: water at 25 °C on fully wetting surfaces
    /// (θ = 0) for a relative humidity, dry air (RH = 0) for the others.
    pub fn set(self, s: &mut Scene, value: f64) {
        let shared =
            s.youngs_modulus_b == s.youngs_modulus_a && s.poisson_ratio_b == s.poisson_ratio_a;
        match self {
            SceneParameter::YoungsModulus => {
                if shared {
                    s.youngs_modulus_b = value;
                }
                s.youngs_modulus_a = value;
            }
            SceneParameter::YoungsModulusA => s.youngs_modulus_a = value,
            SceneParameter::YoungsModulusB => s.youngs_modulus_b = value,
            SceneParameter::PoissonRatio => {
                if shared {
                    s.poisson_ratio_b = value;
                }
                s.poisson_ratio_a = value;
            }
            SceneParameter::Hardness => s.hardness = value,
            SceneParameter::WorkOfAdhesion => s.work_of_adhesion = value,
            SceneParameter::Sigma => s.sigma = value,
            SceneParameter::AsperityRadius => s.asperity_radius = value,
            SceneParameter::AsperityDensity => s.asperity_density = value,
            SceneParameter::NominalArea => s.nominal_area = value,
            SceneParameter::Load => s.load = value.copysign(s.load),
            SceneParameter::InteratomicDistance => s.interatomic_distance = value,
            SceneParameter::ContactAngle => {
                let env = s.environment.get_or_insert_with(Default::default);
                env.contact_angle_a = value;
                env.contact_angle_b = value;
            }
            SceneParameter::ContactAngleA => {
                s.environment
                    .get_or_insert_with(Default::default)
                    .contact_angle_a = value
            }
            SceneParameter::ContactAngleB => {
                s.environment
                    .get_or_insert_with(Default::default)
                    .contact_angle_b = value
            }
            SceneParameter::Temperature => {
                // One temperature: the air's follows the contact's.
                s.temperature = value;
                if let Some(env) = s.environment.as_mut() {
                    env.temperature = value;
                }
            }
            SceneParameter::WearCoefficient => s.wear_coefficient = value,
            SceneParameter::SlidingDistance => s.sliding_distance = value,
            SceneParameter::RelativeHumidity => {
                s.environment
                    .get_or_insert_with(Default::default)
                    .relative_humidity = value
            }
            // A scene without the stress-assisted law has none of its inputs to move.
            SceneParameter::ActivationEnergy => {
                if let Some(a) = s.activation.as_mut() {
                    a.activation_energy = value;
                }
            }
            SceneParameter::ActivationVolume => {
                if let Some(a) = s.activation.as_mut() {
                    a.activation_volume = value;
                }
            }
            SceneParameter::SlidingSpeed => {
                if let Some(a) = s.activation.as_mut() {
                    a.sliding_speed = value;
                }
            }
        }
    }
}

impl std::fmt::Display for SceneParameter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reports align tables with `{:<20}`: a name must honour the width.
    #[test]
    fn names_pad_in_tables() {
        assert_eq!(format!("{:<8}|", SceneParameter::Sigma), "sigma   |");
        assert_eq!(format!("{:>6}", SceneParameter::Load), "  load");
    }

    #[test]
    fn the_role_lists_agree_with_the_table() {
        let with = |f: fn(SceneParameter) -> bool| -> Vec<SceneParameter> {
            SceneParameter::ALL.into_iter().filter(|&p| f(p)).collect()
        };
        assert_eq!(
            with(SceneParameter::is_design_variable),
            SceneParameter::DESIGN
        );
        assert_eq!(
            with(SceneParameter::is_sensitivity).len(),
            SceneParameter::SENSITIVITIES.len()
        );
        for p in SceneParameter::SENSITIVITIES {
            assert!(p.is_sensitivity(), "{p}");
        }
        for p in SceneParameter::ALL {
            assert_eq!(SceneParameter::from_key(p.as_str()), Some(p));
        }
        for p in SceneParameter::CHECKED {
            assert!(p.plausible_range().is_some(), "{p}");
        }
    }

    fn scene(file: &str) -> Scene {
        crate::problem::load(std::path::Path::new(file))
            .unwrap()
            .scene
    }

    /// What `set` puts in, `get` reads back, for every row, on a dry and a humid
    /// scene and one under the stress-assisted wear law (whose inputs the others
    /// do not have: setting them there changes nothing).
    #[test]
    fn get_returns_what_set_put() {
        for file in [
            "problems/micro-gear.toml",
            "problems/micro-gear-humid.toml",
            "problems/silicon-sidewall-wear.toml",
        ] {
            for p in SceneParameter::ALL {
                let mut s = scene(file);
                if p.is_wear_law_input() && s.activation.is_none() {
                    let before = s.clone();
                    p.set(&mut s, 1.0);
                    assert_eq!(s, before, "{file}: {p}");
                    assert_eq!(p.value(&s), None, "{file}: {p}");
                    continue;
                }
                let x = match p {
                    SceneParameter::RelativeHumidity => 0.3,
                    SceneParameter::PoissonRatio => 0.25,
                    SceneParameter::ContactAngle
                    | SceneParameter::ContactAngleA
                    | SceneParameter::ContactAngleB => 0.5,
                    _ => p.get(&s) * 1.25,
                };
                p.set(&mut s, x);
                assert_eq!(p.get(&s), x, "{file}: {p}");
                assert_eq!(p.value(&s), Some(x), "{file}: {p}");
            }
        }
    }

    #[test]
    fn a_dry_scene_has_no_humidity() {
        let dry = scene("problems/micro-gear.toml");
        assert_eq!(SceneParameter::RelativeHumidity.value(&dry), None);
        assert_eq!(SceneParameter::RelativeHumidity.get(&dry), 0.0);
        // The temperature is the scene's own, humid or dry (docs/model.md §12).
        assert_eq!(SceneParameter::Temperature.value(&dry), Some(298.15));
        // The wear law's inputs exist only under the stress-assisted law.
        assert_eq!(SceneParameter::SlidingSpeed.value(&dry), None);
        assert_eq!(
            SceneParameter::WearCoefficient.value(&dry),
            Some(dry.wear_coefficient)
        );
        let humid = scene("problems/micro-gear-humid.toml");
        assert_eq!(SceneParameter::RelativeHumidity.value(&humid), Some(0.5));
    }

    /// The rows an uncertainty study samples besides the design variables.
    #[test]
    fn the_uncertain_rows_are_no_design_variables() {
        for p in [
            SceneParameter::WearCoefficient,
            SceneParameter::SlidingDistance,
            SceneParameter::RelativeHumidity,
        ] {
            assert!(!p.is_design_variable(), "{p}");
            assert!(!SceneParameter::CHECKED.contains(&p), "{p}");
            let (lo, hi) = p.plausible_range().unwrap();
            assert!(lo < hi, "{p}");
        }
        assert_eq!(
            SceneParameter::from_key("wear_coefficient"),
            Some(SceneParameter::WearCoefficient)
        );
        assert_eq!(
            SceneParameter::RelativeHumidity.dimension(),
            Dimension::Dimensionless
        );
        assert_eq!(
            SceneParameter::SlidingDistance.dimension(),
            Dimension::Length
        );
    }
}
