//! Problem files: every example in `problems/` loads to the expected SI values, and every
//! malformed file in `tests/bad_input/` is refused with a message that names the field,
//! the line and what would be accepted.

use std::path::{Path, PathBuf};

use wearopt::model::WearArea;
use wearopt::optimize::{
    AdhesionMeasure, ConstraintQuantity, Objective, OptimizerSettings, ParetoDirection,
    SceneParameter,
};
use wearopt::problem::{self, ProblemError};

fn crate_path(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn example(name: &str) -> problem::Problem {
    let path = crate_path(&format!("problems/{name}"));
    problem::load(&path).unwrap_or_else(|e| panic!("{name}: {e}"))
}

/// Non-dimensional load P̄ = W √(2π) / (K N R^½ σ^{3/2} A_n), K = 4E/3 (docs/model.md §3).
fn nondimensional_load(s: &wearopt::model::Scene) -> f64 {
    let e = 1.0
        / ((1.0 - s.poisson_ratio_a.powi(2)) / s.youngs_modulus_a
            + (1.0 - s.poisson_ratio_b.powi(2)) / s.youngs_modulus_b);
    let k = 4.0 * e / 3.0;
    s.load * (2.0 * std::f64::consts::PI).sqrt()
        / (k * s.asperity_density * s.asperity_radius.sqrt() * s.sigma.powf(1.5) * s.nominal_area)
}

#[test]
fn every_example_loads_and_is_in_contact() {
    let dir = crate_path("problems");
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).expect("problems/ exists") {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("toml") {
            continue;
        }
        let p = problem::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let pbar = nondimensional_load(&p.scene);
        assert!(
            (1e-3..=10.0).contains(&pbar),
            "{}: non-dimensional load {pbar} outside 1e-3..10",
            path.display()
        );
        // And the model agrees: the surfaces are in contact under the load.
        let ev = wearopt::model::evaluate(&p.scene, &wearopt::model::EvaluationOptions::default());
        assert_eq!(ev.status, wearopt::model::Status::Ok, "{}", path.display());
        assert!(ev.wear_rate > 0.0 || p.scene.wear_area == wearopt::model::WearArea::Plastic);
        count += 1;
    }
    assert!(
        count >= 3,
        "expected at least 3 example problems, found {count}"
    );
}

#[test]
fn micro_gear_in_si() {
    let p = example("micro-gear.toml");
    let s = &p.scene;
    assert_eq!(p.name, "Polysilicon micro-gear hub");
    assert_eq!(s.load, 800e-6);
    assert_eq!(s.nominal_area, 1000e-12);
    assert_eq!(s.sliding_distance, 1.0);
    assert_eq!(s.wear_coefficient, 1e-4);
    assert_eq!(s.wear_area, WearArea::Total);
    assert_eq!(s.youngs_modulus_a, 160e9);
    assert_eq!(s.poisson_ratio_a, 0.22);
    assert_eq!(s.youngs_modulus_b, 160e9);
    assert_eq!(s.hardness, 10e9);
    assert_eq!(s.work_of_adhesion, 0.1);
    assert_eq!(s.interatomic_distance, 0.3e-9);
    assert_eq!(s.sigma, 3e-9);
    assert_eq!(s.asperity_radius, 1e-6);
    assert_eq!(s.asperity_density, 1e13);
    assert!(p
        .notes
        .contains(&problem::InputNote::HardnessFromCatalogue {
            material: "polysilicon",
            hardness: 10e9,
            body: problem::BodyKey::A,
        }));
    assert!(wearopt::report::words::input_notes(&p.notes)
        .iter()
        .any(|n| n == "hardness taken from catalogue: polysilicon, 10 GPa"));

    let study = &p.study;
    let names: Vec<_> = study.design.iter().map(|v| v.name).collect();
    assert_eq!(
        names,
        [
            SceneParameter::Sigma,
            SceneParameter::AsperityRadius,
            SceneParameter::WorkOfAdhesion
        ]
    );
    assert_eq!(study.design[0].min, 0.5e-9);
    assert_eq!(study.design[0].max, 20e-9);
    assert_eq!(study.design[2].min, 5e-3);
    assert_eq!(study.objective, Some(Objective::WearRate));
    assert_eq!(study.constraints.len(), 2);
    assert_eq!(
        study.constraints[0].quantity,
        ConstraintQuantity::PlasticityIndex
    );
    assert_eq!(study.constraints[0].max, Some(1.0));
    assert_eq!(study.constraints[0].min, None);
    assert_eq!(study.constraints[1].max, Some(100e-6));
    let pareto = study.pareto.expect("pareto");
    assert_eq!(pareto.adhesion, AdhesionMeasure::PullOffForce);
    assert_eq!(pareto.points, 15);
    assert_eq!(pareto.direction, ParetoDirection::Low);
    assert_eq!(study.optimizer, OptimizerSettings::default());
}

#[test]
fn dlc_contact_in_si() {
    let p = example("dlc-contact.toml");
    let s = &p.scene;
    assert_eq!(s.load, 50e-6);
    assert_eq!(s.nominal_area, 500e-12);
    assert_eq!(s.youngs_modulus_a, 200e9);
    assert_eq!(s.hardness, 20e9);
    assert_eq!(s.work_of_adhesion, 0.05);
    assert_eq!(s.sigma, 1e-9);
    assert_eq!(s.asperity_radius, 2e-6);
    assert_eq!(s.asperity_density, 1e12);
    assert!(!p.study.has_design());
    assert_eq!(p.study.objective, None);
}

#[test]
fn gold_switch_in_si() {
    let p = example("gold-switch.toml");
    let s = &p.scene;
    assert_eq!(s.wear_area, WearArea::Plastic);
    assert_eq!(s.youngs_modulus_a, 79e9);
    assert_eq!(s.poisson_ratio_a, 0.42);
    assert_eq!(s.youngs_modulus_b, 79e9);
    assert_eq!(s.poisson_ratio_b, 0.42);
    assert_eq!(s.hardness, 1e9);
    assert_eq!(s.sliding_distance, 0.01);
    assert_eq!(s.work_of_adhesion, 0.5);
}

const SCENE: &str = r#"
[contact]
load = 1e-5
nominal_area = 1e-10
sliding_distance = 1
wear_coefficient = 0

[bodies]
a = { youngs_modulus = 160e9, poisson_ratio = 0.22 }
b = { youngs_modulus = "inf", poisson_ratio = 0.3 }

[interface]
hardness = "inf"
work_of_adhesion = 0

[roughness]
sigma = 5e-9
asperity_radius = 1e-6
asperity_density = 1e13
"#;

#[test]
fn limits_are_accepted_where_the_schema_allows_them() {
    let p = problem::parse(SCENE, "dir/plain-numbers.toml").unwrap();
    assert_eq!(p.name, "plain-numbers");
    assert_eq!(p.scene.youngs_modulus_b, f64::INFINITY);
    assert_eq!(p.scene.hardness, f64::INFINITY);
    assert_eq!(p.scene.work_of_adhesion, 0.0);
    assert_eq!(p.scene.wear_coefficient, 0.0);
    assert_eq!(p.scene.sliding_distance, 1.0);
    assert!(p.notes.is_empty(), "{:?}", p.notes);

    for load in ["0", "-2e-6", "\"-2 uN\""] {
        let text = SCENE.replace("load = 1e-5", &format!("load = {load}"));
        let p = problem::parse(&text, "t.toml").unwrap();
        assert!(p.scene.load <= 0.0);
    }
    // Poisson ratio 0.5 (incompressible) is inside (-1, 0.5].
    let text = SCENE.replace("poisson_ratio = 0.3", "poisson_ratio = 0.5");
    assert_eq!(
        problem::parse(&text, "t.toml")
            .unwrap()
            .scene
            .poisson_ratio_b,
        0.5
    );
}

#[test]
fn rigid_counterface_needs_no_poisson_ratio() {
    let text = SCENE.replace(
        "b = { youngs_modulus = \"inf\", poisson_ratio = 0.3 }",
        "b = { youngs_modulus = \"inf\" }",
    );
    assert_ne!(text, SCENE);
    let with = problem::parse(SCENE, "t.toml").unwrap().scene;
    let without = problem::parse(&text, "t.toml").unwrap().scene;
    assert!(without.youngs_modulus_b.is_infinite());
    // ν of a rigid body never enters E: the evaluation is identical.
    let options = wearopt::model::EvaluationOptions::default();
    assert_eq!(
        wearopt::model::evaluate(&with, &options).real_area,
        wearopt::model::evaluate(&without, &options).real_area
    );
    // A finite modulus still needs its Poisson ratio.
    let finite = SCENE.replace(
        "b = { youngs_modulus = \"inf\", poisson_ratio = 0.3 }",
        "b = { youngs_modulus = \"100 GPa\" }",
    );
    let err = problem::parse(&finite, "t.toml").unwrap_err().to_string();
    assert!(err.contains("bodies.b.poisson_ratio"), "{err}");
}

#[test]
fn units_in_every_spelling() {
    let text = SCENE
        .replace("load = 1e-5", "load = \"10µN\"")
        .replace("nominal_area = 1e-10", "nominal_area = \"100 μm^2\"")
        .replace("sigma = 5e-9", "sigma = \"5nm\"")
        .replace("asperity_density = 1e13", "asperity_density = \"10 /um^2\"")
        .replace("work_of_adhesion = 0", "work_of_adhesion = \"100 mN/m\"")
        .replace("hardness = \"inf\"", "hardness = \"Infinity\"");
    let s = problem::parse(&text, "t.toml").unwrap().scene;
    assert_eq!(s.load, 10e-6);
    assert_eq!(s.nominal_area, 100e-12);
    assert_eq!(s.sigma, 5e-9);
    assert_eq!(s.asperity_density, 10e12);
    assert_eq!(s.work_of_adhesion, 0.1);
    assert_eq!(s.hardness, f64::INFINITY);
}

#[test]
fn catalogue_override_is_noted() {
    let text = SCENE.replace(
        "a = { youngs_modulus = 160e9, poisson_ratio = 0.22 }",
        "a = { material = \"Silicon\", youngs_modulus = \"130 GPa\" }",
    );
    let p = problem::parse(&text, "t.toml").unwrap();
    assert_eq!(p.scene.youngs_modulus_a, 130e9);
    assert_eq!(p.scene.poisson_ratio_a, 0.22);
    assert!(p.notes.iter().any(|n| matches!(
        n,
        problem::InputNote::CatalogueOverride {
            body: problem::BodyKey::A,
            property: problem::CatalogueProperty::YoungsModulus,
            value,
            ..
        } if *value == 130e9
    )));
    assert!(wearopt::report::words::input_notes(&p.notes)
        .iter()
        .any(|n| n.starts_with("bodies.a: youngs_modulus 130 GPa overrides the catalogue value")));
}

/// Each malformed file, the line its error must point at, and the parts its message
/// must contain (field, value, accepted range or fix).
const BAD: &[(&str, Option<usize>, &[&str])] = &[
    (
        "design-contact-angle-without-environment",
        Some(17),
        &["design.contact_angle", "no [environment]", "relative_humidity = \"90 %\""],
    ),
    (
        "environment-humidity-one",
        Some(17),
        &["environment.relative_humidity = \"100 %\"", "must be in [0, 1)"],
    ),
    (
        "environment-liquid-negative-tension",
        Some(18),
        &["environment.liquid.surface_tension", "must be > 0 J/m²"],
    ),
    (
        "environment-temperature-zero",
        Some(18),
        &["environment.temperature = \"0 K\"", "must be > 0 K"],
    ),
    (
        "interface-contact-angle-above-180",
        Some(16),
        &["interface.contact_angle = \"200 deg\"", "0° to 180°"],
    ),
    (
        "interface-contact-angle-without-environment",
        Some(16),
        &["interface.contact_angle", "add an [environment] table"],
    ),
    (
        "stiction-cantilever-without-gap",
        Some(17),
        &["missing stiction.cantilever.gap", "gap = \"2 um\""],
    ),
    ("syntax-error", Some(3), &["TOML syntax error"]),
    ("duplicate-key", Some(5), &["TOML syntax error", "duplicate key"]),
    (
        "wrong-type",
        Some(6),
        &["contact.wear_coefficient = true", "wrong type", "a number"],
    ),
    (
        "wrong-unit",
        Some(3),
        &[
            "contact.load = \"10 GPa\"",
            "\"GPa\" is a unit of pressure, not force",
            "expected a force such as \"10 uN\"",
        ],
    ),
    (
        "unknown-unit",
        Some(3),
        &["contact.load = \"10 uQ\": unknown unit \"uQ\"; expected a force such as \"10 uN\", \"2 mN\" or a number in newtons"],
    ),
    (
        "wrong-dimension-density",
        Some(19),
        &[
            "roughness.asperity_density = \"10 um^2\"",
            "unit of area, not areal density",
            "\"10 um^-2\"",
        ],
    ),
    (
        "wrong-unit-time-limit",
        Some(22),
        &["optimizer.time_limit = \"30 uN\"", "a time such as \"30 s\""],
    ),
    (
        "malformed-number",
        Some(17),
        &["roughness.sigma = \"five nm\"", "a length such as \"5 nm\""],
    ),
    (
        "zero-area",
        Some(4),
        &["contact.nominal_area = 0: must be > 0 m² (a positive area)"],
    ),
    (
        "negative-sigma",
        Some(17),
        &["roughness.sigma = -5e-9: must be > 0 m (a positive length)"],
    ),
    (
        "nan-load",
        Some(3),
        &["contact.load = nan", "NaN is not a value", "a force such as"],
    ),
    (
        "inf-radius",
        Some(18),
        &[
            "roughness.asperity_radius = \"inf\"",
            "must be > 0 m",
            "infinity is not allowed",
        ],
    ),
    (
        "rigid-body-a",
        Some(9),
        &["bodies.a.youngs_modulus = \"inf\"", "must be > 0 Pa", "infinity is not allowed"],
    ),
    (
        "poisson-out-of-range",
        Some(10),
        &["bodies.b.poisson_ratio = 0.7: must be in (-1, 0.5]"],
    ),
    (
        "wear-coefficient-above-one",
        Some(6),
        &["contact.wear_coefficient = 2: must be in [0, 1]"],
    ),
    (
        "negative-work-of-adhesion",
        Some(14),
        &["interface.work_of_adhesion = \"-0.1 J/m^2\": must be >= 0 J/m²"],
    ),
    (
        "unknown-key",
        Some(3),
        &[
            "unknown key `contact.lod`; did you mean `load`?",
            "(valid keys: load, nominal_area, sliding_distance, wear_coefficient, wear_area, temperature, allowed_wear_depth, sliding_per_cycle, restoring_force)",
        ],
    ),
    (
        "unknown-key-in-body",
        Some(9),
        &[
            "unknown key `bodies.a.materal`; did you mean `material`?",
            "valid keys: material, youngs_modulus, poisson_ratio",
        ],
    ),
    (
        "unknown-table",
        Some(16),
        &["unknown key `roughnes`; did you mean `roughness`?", "valid keys: name, contact"],
    ),
    (
        "unknown-wear-area",
        Some(7),
        &[
            "contact.wear_area = \"plastik\"",
            "did you mean \"plastic\"?",
            "one of: total, plastic",
        ],
    ),
    (
        "missing-field",
        Some(2),
        &["missing contact.sliding_distance", "sliding_distance = \"1 m\""],
    ),
    (
        "missing-table",
        None,
        &["missing table [roughness]", "sigma, asperity_radius and asperity_density"],
    ),
    (
        "missing-hardness",
        Some(12),
        &["missing interface.hardness", "not a catalogue material", "\"10 GPa\""],
    ),
    (
        "body-without-constants",
        Some(10),
        &["missing bodies.b.poisson_ratio", "material = \"polysilicon\""],
    ),
    (
        "unknown-material",
        Some(9),
        &[
            "bodies.a.material = \"polysilcon\": unknown material",
            "did you mean \"polysilicon\"?",
            "catalogue: polysilicon, single-crystal silicon",
        ],
    ),
    (
        "design-min-above-max",
        Some(22),
        &["design.sigma = ", "min must be < max (min is 20 nm, max is 0.5 nm)"],
    ),
    (
        "design-excludes-scene",
        Some(22),
        &[
            "design.sigma = ",
            "[10 nm, 20 nm] does not contain the scene's roughness.sigma = 5 nm",
        ],
    ),
    (
        "design-missing-max",
        Some(22),
        &["missing design.sigma.max", "needs both bounds, e.g. sigma = { min = \"0.5 nm\", max = \"20 nm\" }"],
    ),
    (
        "design-unknown-material",
        Some(22),
        &["design.materials = \"unobtainium\": unknown material (catalogue: polysilicon,"],
    ),
    (
        "unknown-constraint",
        Some(28),
        &[
            "constraint[0].quantity = \"plasticity_idx\"",
            "did you mean \"plasticity_index\"?",
            "one of: pull_off_force, plasticity_index",
        ],
    ),
    (
        "constraint-min-above-max",
        Some(33),
        &["constraint[1].min = \"5 uN\": min must be < max for pull_off_force (min is 5 µN, max is 2 µN)"],
    ),
    (
        "constraint-without-bounds",
        Some(27),
        &["missing constraint[0].min/max", "needs min, max or both"],
    ),
    (
        "constraint-fraction-above-one",
        Some(29),
        &["constraint[0].max = 1.5: must be in [0, 1]"],
    ),
    (
        "unknown-objective",
        Some(25),
        &["objective.minimize = \"wear_rat\"", "did you mean \"wear_rate\"?"],
    ),
    (
        "objective-without-design",
        Some(22),
        &["objective.minimize = \"wear_rate\"", "nothing to optimise", "[design]"],
    ),
    (
        "pareto-points",
        Some(26),
        &["pareto.points = 1000000: must be an integer in 2..=200"],
    ),
    (
        "optimizer-zero-starts",
        Some(28),
        &["optimizer.starts = 0: must be an integer in 1..=1000"],
    ),
    (
        "optimizer-tolerance",
        Some(22),
        &["optimizer.tolerance = 1.0: must be in (0, 1)"],
    ),
    ("empty", None, &["the file is empty", "[contact]"]),
];

fn check_refused(path: &Path, line: Option<usize>, parts: &[&str]) -> ProblemError {
    let err = match problem::load(path) {
        Ok(p) => panic!("{}: accepted, but should be refused: {p:?}", path.display()),
        Err(e) => e,
    };
    let msg = err.to_string();
    let file = path.file_name().unwrap().to_string_lossy().into_owned();
    assert!(
        !msg.contains('\n'),
        "{file}: message is not one line:\n{msg}"
    );
    assert_eq!(err.exit_code(), 2);
    assert_eq!(err.line(), line, "{file}: wrong line in: {msg}");
    match line {
        Some(n) => assert!(
            msg.contains(&format!("{file}:{n}: ")),
            "{file}: message does not start with the file and line {n}: {msg}"
        ),
        None => assert!(
            msg.contains(&format!("{file}: ")),
            "{file}: message does not name the file: {msg}"
        ),
    }
    for part in parts {
        assert!(msg.contains(part), "{file}: message lacks {part:?}:\n{msg}");
    }
    err
}

#[test]
fn every_bad_input_is_refused_precisely() {
    let dir = crate_path("tests/bad_input");
    for (name, line, parts) in BAD {
        check_refused(&dir.join(format!("{name}.toml")), *line, parts);
    }
    // Every file in the folder has an expectation (none is silently skipped).
    let on_disk = std::fs::read_dir(&dir)
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .path()
                .extension()
                .and_then(|x| x.to_str())
                == Some("toml")
        })
        .count();
    assert_eq!(on_disk, BAD.len(), "bad_input/*.toml and BAD disagree");
    assert!(BAD.len() >= 20);
}

#[test]
fn non_utf8_file_is_refused() {
    let dir = std::env::temp_dir().join(format!("wearopt-problem-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("latin1.toml");
    // "10 µN" saved as Latin-1: the micro sign is the single byte 0xB5.
    std::fs::write(
        &path,
        b"# saved as Latin-1\n[contact]\nload = \"10 \xb5N\"\n",
    )
    .unwrap();
    let err = check_refused(&path, Some(3), &["not valid UTF-8", "save it as UTF-8"]);
    assert!(
        matches!(err, ProblemError::NotUtf8 { byte: 40, .. }),
        "{err:?}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn missing_file_is_an_io_error() {
    let err = problem::load(Path::new("no/such/problem.toml")).unwrap_err();
    assert!(matches!(err, ProblemError::Io { .. }));
    assert!(err
        .to_string()
        .starts_with("no/such/problem.toml: cannot read the file"));
    assert_eq!(err.exit_code(), 2);
}

#[test]
fn garbage_never_panics() {
    // A few hostile inputs: none may panic, all must be refused.
    let inputs = [
        "",
        "\u{feff}",
        "[",
        "[[contact]]\nload = 1",
        "contact = 5",
        "[contact]\nload = [1, 2]",
        "[contact]\nload = { value = 1 }",
        "[contact]\nload = 1979-05-27",
        "[bodies]\na = \"polysilicon\"",
        "[[constraint]]\n[[constraint]]\nquantity = 3",
        "[pareto]\npoints = 1.5",
        "[optimizer]\nseed = -1",
        "[contact]\nload = \"\u{00b5}\"",
        "[contact]\nload = \"1e99999 N\"",
    ];
    for text in inputs {
        let result = problem::parse(text, "g.toml");
        assert!(result.is_err(), "{text:?} was accepted");
        let msg = result.unwrap_err().to_string();
        assert!(msg.starts_with("g.toml"), "{text:?}: {msg}");
    }
}

#[test]
fn modulus_for_both_and_for_one_body_cannot_be_mixed() {
    let text = std::fs::read_to_string(crate_path("problems/micro-gear.toml"))
        .unwrap()
        .replace(
            "[design]",
            "[design]\nyoungs_modulus = { min = \"100 GPa\", max = \"300 GPa\" }\nyoungs_modulus_b = { min = \"100 GPa\", max = \"300 GPa\" }",
        );
    let err = problem::parse(&text, "mixed.toml").unwrap_err().to_string();
    assert!(
        err.contains("design.youngs_modulus") && err.contains("youngs_modulus_b"),
        "{err}"
    );
    let text = std::fs::read_to_string(crate_path("problems/micro-gear.toml"))
        .unwrap()
        .replace(
            "[design]",
            "[design]\nyoungs_modulus_b = { min = \"100 GPa\", max = \"300 GPa\" }",
        );
    let p = problem::parse(&text, "b.toml").unwrap();
    assert_eq!(p.study.design[0].name.as_str(), "youngs_modulus_b");
}
