//! `wearopt::app` (rendered by `wearopt::report`) against the command line: each
//! document equals the JSON
//! the CLI writes for the same input (parsed; `time_seconds` removed, the one
//! member that measures the run rather than the result), and each error is the
//! message the CLI prints. The CLI's Pareto JSON is streamed point by point by
//! its own writer, so the Pareto comparison checks two independent assemblies of
//! the same object.

use crate::common::wearopt;

use std::path::Path;

use serde_json::Value;

use wearopt::app::roughness::{self as rough, Levelling, RoughnessOptions};
use wearopt::app::{self, AppError, OptionName, Vocabulary};
use wearopt::report;

fn eval_json(problem: &app::Problem, origin: &str) -> Result<Value, AppError> {
    let doc = app::eval::eval(problem, origin, &Default::default())?;
    Ok(report::eval::json_document(&doc))
}

fn optimize_json(problem: &app::Problem, origin: &str) -> Result<Value, AppError> {
    let doc = app::optimize::optimize(problem, origin, Default::default())?;
    Ok(report::optimize::json_document(&doc))
}

fn pareto_json(
    problem: &app::Problem,
    origin: &str,
    points: Option<usize>,
) -> Result<Value, AppError> {
    let options = app::pareto::ParetoOptions {
        points,
        constraint_values: false,
        ..Default::default()
    };
    let doc = app::pareto::pareto(problem, origin, &options, &app::pareto::Silent)?;
    Ok(report::pareto::json_document(&doc))
}

/// The roughness options as the command line reads them from flags.
fn parse_options(
    cutoff: Option<&str>,
    level: Levelling,
    pixel_size: Option<&str>,
    height_unit: Option<&str>,
) -> Result<RoughnessOptions, AppError> {
    Ok(RoughnessOptions {
        pixel_size: pixel_size
            .map(|t| rough::length(OptionName("pixel_size"), t))
            .transpose()?,
        height_unit: height_unit
            .map(|t| rough::height_unit(OptionName("height_unit"), t))
            .transpose()?,
        cutoff: cutoff
            .map(|t| rough::length(OptionName("cutoff"), t))
            .transpose()?,
        level,
        decimal_comma: false,
    })
}

/// The CLI's stdout for `args`, parsed, and its exit code.
fn cli_json(args: &[&str]) -> (Value, i32) {
    let out = wearopt().args(args).output().expect("runs");
    let v = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "{args:?}: stdout is not JSON ({e}); stderr: {}",
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (v, out.status.code().unwrap_or(-1))
}

/// The CLI's error message for `args` (stderr without "Error: "), which must exit with 2.
fn cli_error(args: &[&str]) -> String {
    let out = wearopt().args(args).output().expect("runs");
    assert_eq!(out.status.code(), Some(2), "{args:?}");
    String::from_utf8_lossy(&out.stderr)
        .trim_end()
        .strip_prefix("Error: ")
        .expect("an error line")
        .to_string()
}

/// `v` without any `time_seconds` member, at any depth.
fn timeless(mut v: Value) -> Value {
    fn strip(v: &mut Value) {
        match v {
            Value::Object(m) => {
                m.remove("time_seconds");
                m.values_mut().for_each(strip);
            }
            Value::Array(a) => a.iter_mut().for_each(strip),
            _ => {}
        }
    }
    strip(&mut v);
    v
}

fn load(file: &str) -> app::Problem {
    app::load(Path::new(file)).expect("shipped problems load")
}

const PROBLEMS: [&str; 9] = [
    "problems/micro-gear.toml",
    "problems/micro-gear-scan.toml",
    "tests/data/micro-gear-study-jkr.toml",
    "problems/gold-switch.toml",
    "problems/dlc-contact.toml",
    "tests/data/switch-study-jkr.toml",
    "tests/data/infeasible-study-jkr.toml",
    "problems/latch-pareto.toml",
    "problems/materials-study.toml",
];

#[test]
fn eval_documents_equal_the_cli_json() {
    for file in PROBLEMS {
        let (cli, _) = cli_json(&["eval", file, "--format", "json"]);
        let doc = eval_json(&load(file), file).expect("a valid scene");
        assert_eq!(doc, cli, "{file}");
    }
}

#[test]
fn optimize_documents_equal_the_cli_json() {
    // Single studies (one infeasible) and a material ranking.
    for file in [
        "tests/data/micro-gear-study-jkr.toml",
        "tests/data/switch-study-jkr.toml",
        "tests/data/infeasible-study-jkr.toml",
        "problems/materials-study.toml",
    ] {
        let (cli, code) = cli_json(&["optimize", file, "--format", "json"]);
        let doc = optimize_json(&load(file), file).expect("a study");
        assert_eq!(timeless(doc), timeless(cli), "{file}");
        let infeasible = file.contains("infeasible");
        assert_eq!(code, i32::from(infeasible), "{file}");
    }
}

#[test]
fn pareto_documents_equal_the_streamed_cli_json() {
    for (file, points) in [
        ("problems/latch-pareto.toml", Some(4)),
        ("problems/micro-gear.toml", Some(3)),
    ] {
        let mut args = vec!["pareto", file, "--format", "json"];
        let n = points.map(|n: usize| n.to_string());
        if let Some(n) = &n {
            args.extend(["--points", n]);
        }
        let (cli, _) = cli_json(&args);
        let doc = pareto_json(&load(file), file, points).expect("a [pareto] study");
        assert!(doc["points"].as_array().is_some_and(|p| !p.is_empty()));
        assert_eq!(doc, cli, "{file}");
    }
}

#[test]
fn roughness_documents_equal_the_cli_json() {
    let npy = parse_options(None, Levelling::Plane, Some("20nm"), Some("nm")).unwrap();
    let filtered = parse_options(Some("100 nm"), Levelling::Quadratic, None, None).unwrap();
    for (file, options, flags) in [
        (
            "problems/scans/self-affine.gsf",
            RoughnessOptions::default(),
            vec![],
        ),
        (
            "problems/scans/self-affine.x3p",
            filtered,
            vec!["--cutoff", "100 nm", "--level", "quadratic"],
        ),
        (
            "problems/scans/self-affine-nm.npy",
            npy,
            vec!["--pixel-size", "20nm", "--height-unit", "nm"],
        ),
    ] {
        let mut args = vec!["roughness", file, "--format", "json"];
        args.extend(flags);
        let (cli, _) = cli_json(&args);
        let doc = report::roughness::json_document(
            &rough::roughness(Path::new(file), &options).expect("analysable"),
        );
        assert_eq!(doc, cli, "{file}");
    }
}

#[test]
fn errors_are_the_cli_messages() {
    let gear = load("tests/data/micro-gear-study-jkr.toml");
    let origin = "tests/data/micro-gear-study-jkr.toml";
    let no_pareto = pareto_json(&gear, origin, None).unwrap_err();
    assert!(matches!(no_pareto, AppError::NoPareto { .. }));
    assert_eq!(no_pareto.to_string(), cli_error(&["pareto", origin]));

    let latch = "problems/latch-pareto.toml";
    for points in [0, 1, 201] {
        let e = pareto_json(&load(latch), latch, Some(points)).unwrap_err();
        assert!(matches!(e, AppError::Invalid { .. }));
        assert_eq!(
            e.to_string(),
            cli_error(&["pareto", latch, "--points", &points.to_string()])
        );
    }

    let npy = "problems/scans/self-affine-nm.npy";
    for (pixel, unit) in [("-3nm", "nm"), ("3 kg", "nm"), ("3nm", "furlong")] {
        let e = parse_options(None, Levelling::Plane, Some(pixel), Some(unit)).unwrap_err();
        assert_eq!(
            e.to_string(),
            cli_error(&[
                "roughness",
                npy,
                "--pixel-size",
                pixel,
                "--height-unit",
                unit
            ])
        );
    }
    // A .npy without pixel size and height unit cannot be read.
    let e = rough::roughness(Path::new(npy), &RoughnessOptions::default()).unwrap_err();
    assert!(matches!(e, AppError::Read(_)));
    assert_eq!(e.to_string(), cli_error(&["roughness", npy]));
}

#[test]
fn python_words_its_errors_in_keyword_arguments() {
    // The same errors, worded for Python: keyword arguments, never a flag.
    let latch = "problems/latch-pareto.toml";
    let e = pareto_json(&load(latch), latch, Some(1)).unwrap_err();
    assert_eq!(
        e.message(Vocabulary::Keywords),
        "points=1: must lie in 2..=200"
    );
    assert_eq!(
        e.message(Vocabulary::Flags),
        "--points 1: must lie in 2..=200"
    );
    let e = parse_options(None, Levelling::Plane, Some("-3nm"), None).unwrap_err();
    assert_eq!(
        e.message(Vocabulary::Keywords),
        "pixel_size=\"-3nm\": must be a positive finite length"
    );
    let npy = "problems/scans/self-affine-nm.npy";
    let e = rough::roughness(Path::new(npy), &RoughnessOptions::default()).unwrap_err();
    let words = e.message(Vocabulary::Keywords);
    assert!(
        words.contains("the keyword argument pixel_size="),
        "{words}"
    );
    assert!(!words.contains("--"), "{words}");
    let law = app::curve::LawOptions {
        adhesion_model: app::curve::AdhesionModel::Dmt,
        attraction: None,
        attraction_range: None,
    };
    let e = law.law().unwrap_err();
    assert_eq!(
        e.message(Vocabulary::Keywords),
        "adhesion_model=\"dmt\" needs attraction_range: z0 = Z0/σ for van_der_waals, h0/σ for dugdale (e.g. 0.1)"
    );
    assert!(e
        .to_string()
        .starts_with("--adhesion-model dmt needs --attraction-range D"));
}
