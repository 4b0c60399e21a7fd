//! The words for the library's structured warnings and notes, and the JSON form of an
//! evaluation with them worded (`warnings` and `notes` stay arrays of strings; the
//! structured values go beside them as `warning_details` and `note_details`).

use serde_json::{json, Value};

use crate::model::{Evaluation, Note, SceneParameter, SensitivityGap, Warning};
use crate::problem::{BodyKey, CatalogueProperty, InputNote};
use crate::units::Dimension;
use crate::units::{format_number, format_quantity, sig_exp};

/// The name of a scene parameter in words, with its symbol, and its dimension
/// (from the parameter table).
fn input_words(i: SceneParameter) -> (&'static str, Dimension) {
    let words = match i {
        SceneParameter::Sigma => "roughness σ",
        SceneParameter::AsperityRadius => "asperity radius R",
        SceneParameter::AsperityDensity => "asperity density N",
        SceneParameter::NominalArea => "nominal area A_n",
        SceneParameter::Load => "load |W|",
        SceneParameter::YoungsModulus => "Young's modulus E",
        SceneParameter::YoungsModulusA => "Young's modulus E1",
        SceneParameter::YoungsModulusB => "Young's modulus E2",
        SceneParameter::PoissonRatio => "Poisson ratio ν",
        SceneParameter::Hardness => "hardness H",
        SceneParameter::WorkOfAdhesion => "work of adhesion γ",
        SceneParameter::InteratomicDistance => "interatomic distance Z0",
        SceneParameter::ContactAngle => "contact angle θ",
        SceneParameter::ContactAngleA => "contact angle θ_a",
        SceneParameter::ContactAngleB => "contact angle θ_b",
        SceneParameter::Temperature => "temperature T",
        SceneParameter::WearCoefficient => "wear coefficient k",
        SceneParameter::SlidingDistance => "sliding distance L",
        SceneParameter::RelativeHumidity => "relative humidity RH",
        SceneParameter::ActivationEnergy => "activation energy ΔU",
        SceneParameter::ActivationVolume => "activation volume ΔV",
        SceneParameter::SlidingSpeed => "sliding speed v",
    };
    (words, i.dimension())
}

/// What the value would be had the number been written with a prefix that was left out
/// (σ = 2 m read as 2 nm, E = 160 Pa as 160 GPa), where that lands in the plausible range.
fn did_you_mean(value: f64, lo: f64, hi: f64, d: Dimension) -> Vec<String> {
    crate::units::forgotten_prefix(value, lo, hi, d)
        .into_iter()
        .map(|v| format_quantity(v, d))
        .collect()
}

/// A warning in words.
pub fn warning(w: &Warning) -> String {
    match w {
        Warning::OutsideJkrRegime { tabor_parameter } => {
            if *tabor_parameter < 0.3 {
                format!(
                    "Tabor parameter φ0 = {} < 0.3: the asperities are in the DMT regime, outside the JKR law used here, which leaves out the attraction of asperities not in contact and can understate the pull-off by many orders of magnitude; set [interface] adhesion_model = \"dmt\"",
                    sig_exp(*tabor_parameter, 3)
                )
            } else {
                format!(
                    "Tabor parameter φ0 = {} lies in the JKR–DMT transition (0.3–3), where JKR is not exact: the Lennard-Jones law, valid there, is evaluated alongside (the line \"under the Lennard-Jones law\"); set [interface] adhesion_model = \"lennard_jones\"",
                    sig_exp(*tabor_parameter, 3)
                )
            }
        }
        Warning::OutsideDmtRegime { tabor_parameter } => {
            if *tabor_parameter > 3.0 {
                format!(
                    "Tabor parameter φ0 = {} > 3: the asperities are in the JKR regime, outside the DMT law used here; set [interface] adhesion_model = \"jkr\"",
                    sig_exp(*tabor_parameter, 3)
                )
            } else {
                format!(
                    "Tabor parameter φ0 = {} lies in the JKR–DMT transition (0.3–3), where DMT is not exact: the Lennard-Jones law, valid there, is evaluated alongside (the line \"under the Lennard-Jones law\"); set [interface] adhesion_model = \"lennard_jones\"",
                    sig_exp(*tabor_parameter, 3)
                )
            }
        }
        Warning::SeparationNotConverged { evaluations, separation } => format!(
            "the separation search did not converge after {evaluations} evaluations; results are at the best estimate h = {separation:.6}"
        ),
        Warning::LoadBeyondModel { nondimensional_load, limit } => format!(
            "the load is {nondimensional_load:.3e} in model units (W over K N R^1/2 σ^3/2 A_n / √(2π)), beyond the {limit:.0e} the model can describe: check the load, nominal area and roughness"
        ),
        Warning::DenseContact { real_area_fraction } => format!(
            "the real area is {} of the nominal area (> 0.1): neighbouring asperities interact, outside the Greenwood–Williamson model; treat the numbers as rough",
            sig_exp(*real_area_fraction, 3)
        ),
        Warning::RealAreaExceedsNominal { real_area_fraction } => format!(
            "the real area would be {}× the nominal area, which is impossible: the load is {} what this rough surface can carry as separate asperity contacts (status out_of_range); check the load, nominal area and hardness",
            // Enough digits to show it above 1 (a search held at A_r ≤ A_n
            // can end a hair beyond it: 1.000003×, not "1.00×").
            (3..=15)
                .map(|d| sig_exp(*real_area_fraction, d))
                .find(|t| t.parse::<f64>().is_ok_and(|v| v > 1.0))
                .unwrap_or_else(|| sig_exp(*real_area_fraction, 3)),
            // A hair past A_n is the limit reached, not a load far beyond it.
            if *real_area_fraction < 1.1 {
                "at the limit of"
            } else if *real_area_fraction < 2.0 {
                "beyond"
            } else {
                "far beyond"
            }
        ),
        Warning::FewContacts { contact_count } => format!(
            "only {} asperities are expected in contact (fewer than 10): the Gaussian statistics of the model do not hold; enlarge the nominal area or check the asperity density",
            sig_exp(*contact_count, 3)
        ),
        Warning::RoughnessNotBelowRadius { sigma, asperity_radius } => format!(
            "roughness σ = {} is not below the asperity radius R = {}: the asperities are not gentle spherical caps, as the model assumes",
            format_quantity(*sigma, Dimension::Length),
            format_quantity(*asperity_radius, Dimension::Length)
        ),
        Warning::SummitParameter { product } => format!(
            "N·R·σ = {} lies outside 0.01–0.2, where measured surfaces lie (Greenwood–Williamson's have 0.03–0.05): check the asperity density, radius and roughness together",
            sig_exp(*product, 3)
        ),
        Warning::ImplausibleInput { input, value, plausible_min, plausible_max } => {
            let (name, d) = input_words(*input);
            let guesses = did_you_mean(*value, *plausible_min, *plausible_max, d);
            format!(
                "{name} = {} is outside {} – {}, the range of MEMS, NEMS and storage contacts{}",
                format_quantity(*value, d),
                format_quantity(*plausible_min, d),
                format_quantity(*plausible_max, d),
                if guesses.is_empty() {
                    String::new()
                } else {
                    format!(": did you mean {}?", guesses.join(" or "))
                }
            )
        }
        Warning::LiquidBelowFreezing { temperature, freezing_point } => format!(
            "the temperature T = {} is below water's freezing point, {} K: ice, not a liquid meniscus, and the capillary force does not hold there{}",
            format_quantity(*temperature, Dimension::Temperature),
            (freezing_point * 100.0).round() / 100.0,
            if *temperature <= 100.0 {
                format!(
                    "; a temperature in degrees Celsius read as kelvin? {} °C is \"{} K\"",
                    format_number(*temperature),
                    ((temperature + 273.15) * 100.0).round() / 100.0
                )
            } else {
                String::new()
            }
        ),
        Warning::KelvinRadiusBelowContinuum { kelvin_radius } => format!(
            "the Kelvin radius is {} (< 0.5 nm, a few molecules of water): the continuum Kelvin–Laplace picture of the capillary force is doubtful at this humidity; read the capillary numbers as an estimate",
            format_quantity(*kelvin_radius, Dimension::Length)
        ),
        Warning::PullOffNotFound { evaluations } => format!(
            "the pull-off search found no minimum of the load curve after {evaluations} evaluations: no pull-off force is reported (a defect of the search, not of the scene: please report it)"
        ),
        Warning::PullOffBeyondModel { separation, limit } => format!(
            "adhesion is negligible: the load curve's minimum lies at h ≈ {} σ, beyond the {limit:.0e} σ the model resolves, where the pull-off force is below 10^-1e11 N; no pull-off force is reported",
            sig_exp(*separation, 3)
        ),
        Warning::NonFiniteResult { quantity } => format!(
            "{quantity} came out non-finite: the scene is beyond what the evaluator can represent (status out_of_range)"
        ),
        Warning::DebrisRegime {
            wear_law,
            assumes_smoothing,
            debris_area_fraction,
            critical_junction_size,
        } => {
            let share = format!(
                "{} % of the real area is in junctions wider than the critical size d* = {}, which break off debris particles (wear_mechanism = debris)",
                super::sig(100.0 * debris_area_fraction, 3),
                format_quantity(*critical_junction_size, Dimension::Length)
            );
            if *assumes_smoothing {
                format!("{share}: the {wear_law} wear law assumes atom-by-atom smoothing, so its wear rate does not hold here")
            } else {
                format!("{share}: Archard's wear coefficient k ({wear_law} law) must then be one measured where junctions make debris")
            }
        }
    }
}

/// A note in words.
pub fn note(n: &Note) -> String {
    match n {
        Note::ElasticAdhesionMatters { elastic_adhesion_index } => format!(
            "elastic adhesion index θ = {} ≤ 10: adhesion matters for elastic asperities",
            sig_exp(*elastic_adhesion_index, 4)
        ),
        Note::PlasticAdhesionMatters { plastic_adhesion_index } => format!(
            "plastic adhesion index λ = {} ≤ 0.125: adhesion matters for plastic asperities",
            sig_exp(*plastic_adhesion_index, 4)
        ),
        Note::LoadDropsAtTransition => "the load drops when an asperity turns plastic (λ^{3/2}/θ < 0.0098): the load–separation curve can have several branches; the one reached by loading is used".to_string(),
        Note::Separated { adhesion: true } => {
            "the tensile load exceeds the pull-off force: the surfaces separate".to_string()
        }
        Note::Separated { adhesion: false } => {
            "without adhesion a load ≤ 0 cannot hold the surfaces in contact: they separate"
                .to_string()
        }
        Note::PullOffUnderflow { log10_force } => format!(
            "the pull-off force is below the smallest double: 10^{log10_force:.1} N; reported as 0"
        ),
        Note::RealAreaUnderflow { log10_area } => format!(
            "the real area is below the smallest double: 10^{log10_area:.1} m²; reported as 0"
        ),
        Note::LennardJonesStandIn {
            tabor_parameter,
            stand_in,
            pull_off_error,
        } => {
            // The closed form that holds above the law's curves (large μ) or
            // below them.
            let (lo, hi) = crate::model::lennard_jones::table::tabor_range();
            let (lo, hi) = (format_number(lo), format_number(hi));
            let (side, limit, error) = if stand_in.valid_tabor().1.is_infinite() {
                (
                    format!("above {hi}"),
                    "JKR's (its large-μ limit)",
                    format!(
                        "whose rough-surface pull-off differs from the law's last limit curve by {:.2} % there where adhesion is strong (ℓ = σ/ε ≤ 3; where it is weak both pull-offs are vanishingly small, JKR's far smaller)",
                        100.0 * pull_off_error
                    ),
                )
            } else {
                (
                    format!("below {lo}"),
                    "DMT's with van der Waals attraction (one sphere's small-μ limit)",
                    format!(
                        "whose single-asperity pull-off differs from the sphere's by {} % at the table's end, but which is not the rough surface's small-μ limit: its far attraction is 3/4 of the sphere's (Hamaker constant 12π Z0²γ against 16π) and its contact begins at the apex gap Z0, where the sphere's squeezed gap takes up about Z0 of interference. At the switch the rough surface's real area lies up to {:.0} % and its pull-off up to {:.0} % below the law's (measured for Z0/σ ≤ 1.7, more beyond; docs/model.md §11): treat these numbers as estimates",
                        sig_exp(100.0 * pull_off_error, 2),
                        100.0 * crate::model::lennard_jones::rough::STAND_IN_ROUGH_JUMP.0,
                        100.0 * crate::model::lennard_jones::rough::STAND_IN_ROUGH_JUMP.1,
                    ),
                )
            };
            format!(
                "Tabor parameter φ0 = {} lies {side}, outside the Lennard-Jones law's curves ({lo}–{hi}): the numbers are {limit}, {error}",
                sig_exp(*tabor_parameter, 3),
            )
        }
        Note::DebrisJunctionSizes { adhesion_model } => format!(
            "the debris shares take each junction's diameter as its contact diameter: an elastic summit's under the {} law ({}), a plastic junction's 2√(2Rδ)",
            adhesion_model.law().label(),
            match adhesion_model {
                crate::model::AdhesionModel::Dmt => "Hertz's 2√(Rδ)",
                crate::model::AdhesionModel::Jkr => "JKR's 2a, with δ = a²/R − √(2πwa/E*)",
                crate::model::AdhesionModel::LennardJones =>
                    "the sphere's, from the law's curves, between JKR's and Hertz's 2√(Rδ)",
            }
        ),
        Note::LennardJonesLimitCurves {
            tabor_parameter,
            pull_off_error,
        } => {
            let solved = format_number(crate::model::lennard_jones::table::solved_range().1);
            format!(
                "Tabor parameter φ0 = {} lies above the Lennard-Jones sphere's solved table (to {solved}): the law's curves there are its closed-form limit, JKR's contact branch from the sphere's jump in (at interference −(1.49 μ^(-4/7) − 0.565 μ^(-1)) in Maugis units, fitted to the solved curves) with the rigid sphere's attraction before it; at μ = {solved} the rough surface's pull-off under it was within {:.1} % of the solved sphere's, the difference falling as μ grows",
                sig_exp(*tabor_parameter, 3),
                100.0 * pull_off_error
            )
        }
    }
}

/// A note of the problem-file reader in words.
pub fn input_note(n: &InputNote) -> String {
    match n {
        InputNote::CatalogueOverride {
            body,
            property,
            value,
            catalogue_value,
            material,
        } => {
            let q = |x: f64| match property {
                CatalogueProperty::YoungsModulus => format_quantity(x, Dimension::Pressure),
                CatalogueProperty::PoissonRatio => format_number(x),
            };
            format!(
                "{}: {} {} overrides the catalogue value {} for {material}",
                body.table(),
                property.key(),
                q(*value),
                q(*catalogue_value)
            )
        }
        InputNote::HardnessFromCatalogue {
            material,
            hardness,
            body,
        } => match body {
            BodyKey::A => format!(
                "hardness taken from catalogue: {material}, {}",
                format_quantity(*hardness, Dimension::Pressure)
            ),
            BodyKey::B => format!(
                "hardness taken from catalogue: {material}, {} — the counterface's (bodies.b): the model's H is the softer body's",
                format_quantity(*hardness, Dimension::Pressure)
            ),
        },
        InputNote::AtypicalWorkOfAdhesion {
            value,
            typical_min,
            typical_max,
            material,
        } => format!(
            "work_of_adhesion {} is far outside the typical range {} to {} for {material} (catalogue)",
            format_quantity(*value, Dimension::SurfaceEnergy),
            format_quantity(*typical_min, Dimension::SurfaceEnergy),
            format_quantity(*typical_max, Dimension::SurfaceEnergy)
        ),
        InputNote::SofterCounterface {
            material_a,
            hardness_a,
            material_b,
            hardness_b,
        } => format!(
            "body b ({material_b}, H = {}) is softer than body a ({material_a}, H = {}): the model's H is the softer body's, so the interface.hardness given should be b's",
            format_quantity(*hardness_b, Dimension::Pressure),
            format_quantity(*hardness_a, Dimension::Pressure)
        ),
    }
}

/// Why a sensitivity has no value, in words.
pub fn sensitivity_gap(g: SensitivityGap) -> &'static str {
    match g {
        SensitivityGap::NoWear => "no wear at the scene (separated or zero wear)",
        SensitivityGap::InfiniteParameter => "the parameter is infinite in this scene",
        SensitivityGap::ZeroParameter => "the parameter is zero in this scene (its limit)",
        SensitivityGap::SeparatesWithinStep => {
            "the contact separates within the finite-difference step"
        }
    }
}

/// Every note of the problem-file reader in words.
pub fn input_notes(notes: &[InputNote]) -> Vec<String> {
    notes.iter().map(input_note).collect()
}

/// Every warning of an evaluation in words.
pub fn warnings(ev: &Evaluation) -> Vec<String> {
    ev.warnings.iter().map(warning).collect()
}

/// Every note of an evaluation in words.
pub fn notes(ev: &Evaluation) -> Vec<String> {
    ev.notes.iter().map(note).collect()
}

/// An evaluation as JSON: its fields, with `warnings` and `notes` as strings and the
/// structured values as `warning_details` and `note_details`.
pub fn evaluation_json(ev: &Evaluation) -> Value {
    let mut v = serde_json::to_value(ev).unwrap_or(Value::Null);
    if let Value::Object(obj) = &mut v {
        obj.insert("warning_details".into(), json!(ev.warnings));
        obj.insert("note_details".into(), json!(ev.notes));
        obj.insert("warnings".into(), json!(warnings(ev)));
        obj.insert("notes".into(), json!(notes(ev)));
    }
    v
}

/// The line every report of a scene with a corrected real area carries (none
/// for the statistical model as it is).
pub fn real_area_scale_note(scale: f64) -> Option<String> {
    (scale != 1.0).then(|| {
        format!(
            "contact model: bem_corrected — every real area, wear and friction here is the statistical model's × {} (the exact-to-statistical ratio on the scan at the file's operating point, held fixed as the design moves)",
            super::sig(scale, 4)
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_real_area_past_the_nominal_one_is_worded_by_how_far() {
        let words = |f: f64| {
            warning(&Warning::RealAreaExceedsNominal {
                real_area_fraction: f,
            })
        };
        let hair = words(1.000003);
        assert!(hair.contains("1.000003× the nominal area"), "{hair}");
        assert!(hair.contains("the load is at the limit of what"), "{hair}");
        assert!(words(1.5).contains("the load is beyond what"));
        assert!(words(40.0).contains("the load is far beyond what"));
    }

    #[test]
    fn input_notes_are_worded_with_units() {
        use crate::problem::BodyKey;
        let n = InputNote::CatalogueOverride {
            body: BodyKey::A,
            property: CatalogueProperty::YoungsModulus,
            value: 130e9,
            catalogue_value: 160e9,
            material: "polysilicon",
        };
        assert_eq!(
            input_note(&n),
            "bodies.a: youngs_modulus 130 GPa overrides the catalogue value 160 GPa for polysilicon"
        );
        let n = InputNote::CatalogueOverride {
            body: BodyKey::B,
            property: CatalogueProperty::PoissonRatio,
            value: 0.3,
            catalogue_value: 0.22,
            material: "polysilicon",
        };
        assert_eq!(
            input_note(&n),
            "bodies.b: poisson_ratio 0.3 overrides the catalogue value 0.22 for polysilicon"
        );
        let n = InputNote::AtypicalWorkOfAdhesion {
            value: 5.0,
            typical_min: 0.02,
            typical_max: 0.1,
            material: "polysilicon",
        };
        assert_eq!(
            input_note(&n),
            "work_of_adhesion 5 J/m² is far outside the typical range 20 mJ/m² to 100 mJ/m² for polysilicon (catalogue)"
        );
        let n = InputNote::SofterCounterface {
            material_a: "silicon carbide",
            hardness_a: 28e9,
            material_b: "gold",
            hardness_b: 1e9,
        };
        assert_eq!(
            input_note(&n),
            "body b (gold, H = 1 GPa) is softer than body a (silicon carbide, H = 28 GPa): the model's H is the softer body's, so the interface.hardness given should be b's"
        );
        // The structured value serialises with its kind, for JSON readers.
        let v = serde_json::to_value(&n).unwrap();
        assert_eq!(v["kind"], "softer_counterface");
        assert_eq!(v["hardness_b"], 1e9);
    }

    #[test]
    fn a_forgotten_unit_is_guessed() {
        let w = Warning::ImplausibleInput {
            input: SceneParameter::Sigma,
            value: 2.0,
            plausible_min: 1e-11,
            plausible_max: 1e-5,
        };
        let s = warning(&w);
        assert!(s.starts_with("roughness σ = 2 m is outside"), "{s}");
        assert!(s.contains("did you mean 2 nm or 2 µm?"), "{s}");
        let w = Warning::ImplausibleInput {
            input: SceneParameter::YoungsModulusA,
            value: 160.0,
            plausible_min: 1e6,
            plausible_max: 2e12,
        };
        assert!(warning(&w).contains("did you mean 160 GPa or 160 MPa?"));
    }
}
