//! `wearopt::documents` against the command line: each document equals the JSON
//! the CLI writes for the same input (parsed; `time_seconds` removed, the one
//! member that measures the run rather than the result), and each error is the
//! message the CLI prints. The CLI's Pareto JSON is streamed point by point by
//! its own writer, so the Pareto comparison checks two independent assemblies of
//! the same object.

use crate::common::wearopt;

use std::path::Path;

use serde_json::Value;

use wearopt::documents::{self, DocumentError, RoughnessOptions};
use wearopt::surface::Levelling;

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

fn load(file: &str) -> wearopt::problem::Problem {
    wearopt::problem::load(Path::new(file)).expect("shipped problems load")
}

const PROBLEMS: [&str; 9] = [
    "problems/micro-gear.toml",
    "problems/micro-gear-scan.toml",
    "problems/micro-gear-study.toml",
    "problems/gold-switch.toml",
    "problems/dlc-contact.toml",
    "problems/switch-study.toml",
    "problems/infeasible-study.toml",
    "problems/latch-pareto.toml",
    "problems/materials-study.toml",
];

#[test]
fn eval_documents_equal_the_cli_json() {
    for file in PROBLEMS {
        let (cli, _) = cli_json(&["eval", file, "--format", "json"]);
        let doc = documents::eval_json(&load(file), file).expect("a valid scene");
        assert_eq!(doc, cli, "{file}");
    }
}

#[test]
fn optimize_documents_equal_the_cli_json() {
    // Single studies (one infeasible) and a material ranking.
    for file in [
        "problems/micro-gear-study.toml",
        "problems/switch-study.toml",
        "problems/infeasible-study.toml",
        "problems/materials-study.toml",
    ] {
        let (cli, code) = cli_json(&["optimize", file, "--format", "json"]);
        let doc = documents::optimize_json(&load(file), file).expect("a study");
        assert_eq!(timeless(doc), timeless(cli), "{file}");
        let infeasible = file.contains("infeasible");
        assert_eq!(code, i32::from(infeasible), "{file}");
    }
}

#[test]
fn pareto_documents_equal_the_streamed_cli_json() {
    for (file, points) in [
        ("problems/latch-pareto.toml", None),
        ("problems/micro-gear.toml", Some(5)),
    ] {
        let mut args = vec!["pareto", file, "--format", "json"];
        let n = points.map(|n: usize| n.to_string());
        if let Some(n) = &n {
            args.extend(["--points", n]);
        }
        let (cli, _) = cli_json(&args);
        let doc = documents::pareto_json(&load(file), file, points).expect("a [pareto] study");
        assert!(doc["points"].as_array().is_some_and(|p| !p.is_empty()));
        assert_eq!(doc, cli, "{file}");
    }
}

#[test]
fn roughness_documents_equal_the_cli_json() {
    let npy = RoughnessOptions::parse(None, Levelling::Plane, Some("20nm"), Some("nm")).unwrap();
    let filtered =
        RoughnessOptions::parse(Some("100 nm"), Levelling::Quadratic, None, None).unwrap();
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
        let doc = documents::roughness_json(Path::new(file), &options).expect("analysable");
        assert_eq!(doc, cli, "{file}");
    }
}

#[test]
fn errors_are_the_cli_messages() {
    let gear = load("problems/micro-gear-study.toml");
    let origin = "problems/micro-gear-study.toml";
    let no_pareto = documents::pareto_json(&gear, origin, None).unwrap_err();
    assert!(matches!(no_pareto, DocumentError::NoPareto { .. }));
    assert_eq!(no_pareto.to_string(), cli_error(&["pareto", origin]));

    let latch = "problems/latch-pareto.toml";
    for points in [0, 1, 201] {
        let e = documents::pareto_json(&load(latch), latch, Some(points)).unwrap_err();
        assert!(matches!(e, DocumentError::Points { .. }));
        assert_eq!(
            e.to_string(),
            cli_error(&["pareto", latch, "--points", &points.to_string()])
        );
    }

    let npy = "problems/scans/self-affine-nm.npy";
    for (pixel, unit) in [("-3nm", "nm"), ("3 kg", "nm"), ("3nm", "furlong")] {
        let e =
            RoughnessOptions::parse(None, Levelling::Plane, Some(pixel), Some(unit)).unwrap_err();
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
    let e = documents::roughness(Path::new(npy), &RoughnessOptions::default()).unwrap_err();
    assert!(matches!(e, DocumentError::Read(_)));
    assert_eq!(e.to_string(), cli_error(&["roughness", npy]));
}
