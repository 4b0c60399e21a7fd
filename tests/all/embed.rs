//! The library is safe to embed: every scene or quadrature setting a caller can
//! build with a NaN, an infinity, a negative number or a zero where the model
//! cannot take one is refused with an error naming the field, the value and the
//! accepted range, by `Scene::validate`, `Quadrature::new` and the entry points
//! that take a scene (documents, sweeps); and the model does not panic on
//! quadrature settings built field by field without the checks.

use std::panic::catch_unwind;
use std::path::Path;

use wearopt::app::{self, AppError};
use wearopt::model::{AsperityLaw, Coefficients, Model, Quadrature, Scene};
use wearopt::sweep::{Method, Sweep, SweepError};

fn gear() -> wearopt::problem::Problem {
    wearopt::problem::load(Path::new("tests/data/micro-gear-study-jkr.toml")).expect("shipped")
}

type Field = (&'static str, fn(&mut Scene) -> &mut f64);

/// Every f64 field of a scene, with its accessor.
const FIELDS: [Field; 14] = [
    ("youngs_modulus_a", |s| &mut s.youngs_modulus_a),
    ("poisson_ratio_a", |s| &mut s.poisson_ratio_a),
    ("youngs_modulus_b", |s| &mut s.youngs_modulus_b),
    ("poisson_ratio_b", |s| &mut s.poisson_ratio_b),
    ("hardness", |s| &mut s.hardness),
    ("work_of_adhesion", |s| &mut s.work_of_adhesion),
    ("interatomic_distance", |s| &mut s.interatomic_distance),
    ("sigma", |s| &mut s.sigma),
    ("asperity_radius", |s| &mut s.asperity_radius),
    ("asperity_density", |s| &mut s.asperity_density),
    ("load", |s| &mut s.load),
    ("nominal_area", |s| &mut s.nominal_area),
    ("sliding_distance", |s| &mut s.sliding_distance),
    ("wear_coefficient", |s| &mut s.wear_coefficient),
];

/// Whether `field` accepts `x` (the documented ranges of `Scene`).
fn accepted(field: &str, x: f64) -> bool {
    match field {
        "poisson_ratio_a" | "poisson_ratio_b" => x > -1.0 && x <= 0.5,
        "youngs_modulus_b" | "hardness" => x > 0.0,
        "work_of_adhesion" | "sliding_distance" | "wear_coefficient" => x.is_finite() && x >= 0.0,
        "load" => x.is_finite(),
        _ => x.is_finite() && x > 0.0,
    }
}

const BAD: [f64; 7] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    -1.0,
    0.0,
    -1e-300,
    0.6,
];

#[test]
fn the_shipped_scene_is_valid() {
    assert_eq!(gear().scene.validate(), Ok(()));
}

#[test]
fn every_bad_field_is_refused_by_name_value_and_range() {
    let base = gear();
    let mut refused = 0;
    for (field, get) in FIELDS {
        for x in BAD {
            let mut scene = base.scene.clone();
            *get(&mut scene) = x;
            let result = scene.validate();
            if accepted(field, x) {
                assert_eq!(result, Ok(()), "{field} = {x}");
                continue;
            }
            refused += 1;
            let e = result.expect_err(field);
            assert_eq!(e.field, field);
            assert!(e.value.to_bits() == x.to_bits(), "{field}: {}", e.value);
            let message = e.to_string();
            assert!(
                message.starts_with(&format!("{field} = {x}: must be ")),
                "{message}"
            );

            // The entry points that take a scene refuse it with the same error.
            let mut problem = base.clone();
            problem.scene = scene.clone();
            let doc = app::eval::eval(&problem, "hand-built", &Default::default()).unwrap_err();
            assert!(matches!(&doc, AppError::Scene { error, .. } if error.field == field));
            assert_eq!(doc.to_string(), format!("hand-built: scene: {message}"));
            assert!(matches!(
                app::optimize::optimize(&problem, "hand-built", Default::default()),
                Err(AppError::Scene { .. })
            ));
            let sweep = Sweep::new(
                &scene,
                &problem.study.design,
                &problem.study.constraints,
                Method::Sobol,
                8,
                0,
            );
            assert!(matches!(sweep, Err(SweepError::Scene(ref s)) if s.field == field));
        }
    }
    // Every field refuses NaN and -∞; most refuse more.
    assert!(refused >= 2 * FIELDS.len(), "{refused}");
}

#[test]
fn optional_requirements_must_be_positive_and_finite() {
    let base = gear().scene;
    for x in [f64::NAN, f64::INFINITY, 0.0, -2.0] {
        let mut s = base.clone();
        s.requirements.restoring_force = Some(x);
        let e = s.validate().unwrap_err();
        assert_eq!(e.field, "requirements.restoring_force");
        assert_eq!(e.accepted, "finite and > 0");
        let mut s = base.clone();
        s.requirements.shear_strength = Some(x);
        assert_eq!(
            s.validate().unwrap_err().field,
            "requirements.shear_strength"
        );
    }
    let mut s = base;
    s.requirements.allowed_wear_depth = Some(1e-9);
    assert_eq!(s.validate(), Ok(()));
}

#[test]
fn quadrature_new_checks_each_setting() {
    let d = Quadrature::default();
    assert_eq!(
        Quadrature::new(d.order, d.log_weight_step, d.log_weight_cut),
        Ok(d)
    );
    for order in [0, 1, 5, 7, 33, usize::MAX] {
        let e = Quadrature::new(order, 12.0, 46.0).unwrap_err();
        assert_eq!(e.field, "order");
    }
    for cut in [f64::NAN, f64::INFINITY, -46.0, 0.0, 9.9, 201.0] {
        let e = Quadrature::new(20, 12.0, cut).unwrap_err();
        assert_eq!(e.field, "log_weight_cut", "{cut}");
    }
    // Steps giving fewer than 1 or more than 31 panels per side of a cut of 46.
    for step in [f64::NAN, f64::INFINITY, -12.0, 0.0, 46.1, 46.0 / 31.5] {
        let e = Quadrature::new(20, step, 46.0).unwrap_err();
        assert_eq!(e.field, "log_weight_step", "{step}");
        assert!(e.to_string().starts_with("log_weight_step = "), "{e}");
    }
    assert!(Quadrature::new(20, 46.0, 46.0).is_ok());
    assert!(Quadrature::new(20, 46.0 / 31.0, 46.0).is_ok());
}

#[test]
fn unchecked_quadratures_never_panic() {
    // Built field by field, bypassing `Quadrature::new`: the model must still
    // not panic (an unsupported order falls back to the largest rule below it).
    let c = Coefficients::from_indices(10.0, 0.125);
    for order in [0, 5, 7, 100] {
        let q = Quadrature {
            order,
            ..Quadrature::default()
        };
        let at = catch_unwind(|| {
            Model::with_law(c, AsperityLaw::Jkr, q)
                .at(0.5)
                .load()
                .value()
        });
        assert!(at.is_ok(), "order {order} panicked");
        assert!(at.unwrap().is_finite(), "order {order}");
    }
    for (step, cut) in [
        (f64::NAN, 46.0),
        (0.0, 46.0),
        (12.0, f64::NAN),
        (-1.0, 1e300),
    ] {
        let q = Quadrature {
            order: 20,
            log_weight_step: step,
            log_weight_cut: cut,
        };
        let at = catch_unwind(|| {
            Model::with_law(c, AsperityLaw::Jkr, q)
                .at(0.5)
                .load()
                .value()
        });
        // The numbers of settings that fail the check mean nothing (they may
        // be NaN); what is promised is no panic.
        assert!(at.is_ok(), "step {step}, cut {cut} panicked");
    }
}
