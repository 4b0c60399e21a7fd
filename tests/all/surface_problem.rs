//! `[roughness] topography` in problem files, and `wearopt roughness` end to end on the
//! shipped scan.

use crate::common;
use crate::common::wearopt;

use std::path::{Path, PathBuf};

use wearopt::problem::{self, ProblemError};
use wearopt::surface::read::{self, Overrides};
use wearopt::surface::{analyse, Levelling, Settings};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// micro-gear-scan.toml with its [roughness] table replaced, written next to the scans.
fn with_roughness(table: &str, tag: &str) -> PathBuf {
    let text = std::fs::read_to_string(root().join("problems/micro-gear-scan.toml")).unwrap();
    let start = text.find("[roughness]").unwrap();
    let end = text.find("[design]").unwrap();
    let new = format!("{}{}\n\n{}", &text[..start], table, &text[end..]);
    let dir = std::env::temp_dir().join(format!("wearopt-scan-{}-{tag}", std::process::id()));
    std::fs::create_dir_all(dir.join("scans")).unwrap();
    for f in ["self-affine.gsf", "self-affine.x3p", "self-affine-nm.npy"] {
        std::fs::copy(
            root().join("problems/scans").join(f),
            dir.join("scans").join(f),
        )
        .unwrap();
    }
    let path = dir.join("p.toml");
    std::fs::write(&path, new).unwrap();
    path
}

fn err(table: &str, tag: &str) -> ProblemError {
    problem::load(&with_roughness(table, tag)).unwrap_err()
}

#[test]
fn the_shipped_scene_takes_sigma_r_and_n_from_its_scan() {
    let p = problem::load(&root().join("problems/micro-gear-scan.toml")).unwrap();
    let map = read::load(
        &root().join("problems/scans/self-affine.gsf"),
        &Overrides::default(),
    )
    .unwrap();
    let r = analyse(
        &map,
        &Settings {
            level: Levelling::Plane,
            cutoff: Some(100e-9),
        },
    )
    .unwrap();
    assert_eq!(p.scene.sigma, r.parameters.summit_sigma);
    assert_eq!(p.scene.asperity_radius, r.parameters.summit_radius);
    assert_eq!(p.scene.asperity_density, r.parameters.summit_density);
    let scan = p.scan.as_ref().unwrap();
    assert_eq!(scan.topography, "scans/self-affine.gsf");
    assert_eq!(scan.roughness.settings.cutoff, Some(100e-9));
    // The study still moves σ and R from that baseline.
    assert!(p.study.design.iter().any(|d| d.name.as_str() == "sigma"));
}

#[test]
fn the_same_scan_in_three_formats_gives_the_same_scene() {
    // The .gsf stores f32, the .x3p f64 and the .npy f64 in nanometres: σ, R, N agree to
    // the f32 rounding of the heights (relative 1e-6).
    let cut = "cutoff = \"100 nm\"";
    let a = problem::load(&with_roughness(
        &format!("[roughness]\ntopography = \"scans/self-affine.gsf\"\n{cut}"),
        "gsf",
    ))
    .unwrap();
    let b = problem::load(&with_roughness(
        &format!("[roughness]\ntopography = \"scans/self-affine.x3p\"\n{cut}"),
        "x3p",
    ))
    .unwrap();
    let c = problem::load(&with_roughness(&format!("[roughness]\ntopography = \"scans/self-affine-nm.npy\"\npixel_size = \"20 nm\"\nheight_unit = \"nm\"\n{cut}"), "npy")).unwrap();
    for q in [&b, &c] {
        for (x, y) in [
            (a.scene.sigma, q.scene.sigma),
            (a.scene.asperity_radius, q.scene.asperity_radius),
            (a.scene.asperity_density, q.scene.asperity_density),
        ] {
            assert!((x - y).abs() < 1e-6 * x, "{x} vs {y}");
        }
    }
}

#[test]
fn refusals_name_the_key_and_the_fix() {
    let e = err(
        "[roughness]\ntopography = \"scans/self-affine.gsf\"\nsigma = \"3 nm\"",
        "clash",
    );
    let m = e.to_string();
    assert!(
        m.contains("roughness.sigma") && m.contains("clashes with roughness.topography"),
        "{m}"
    );
    let m = err("[roughness]\nsigma = \"3 nm\"\nasperity_radius = \"1 um\"\nasperity_density = \"10 um^-2\"\ncutoff = \"100 nm\"", "nocut").to_string();
    assert!(
        m.contains("roughness.cutoff") && m.contains("only to a measured scan"),
        "{m}"
    );
    let m = err(
        "[roughness]\ntopography = \"scans/self-affine-nm.npy\"",
        "npy",
    )
    .to_string();
    assert!(
        m.contains("roughness.topography") && m.contains("pixel_size"),
        "{m}"
    );
    let m = err(
        "[roughness]\ntopography = \"scans/self-affine-nm.npy\"\npixel_size = \"20 nm\"",
        "npy2",
    )
    .to_string();
    assert!(m.contains("height_unit"), "{m}");
    let m = err("[roughness]\ntopography = \"scans/none.gsf\"", "missing").to_string();
    assert!(
        m.contains("roughness.topography") && m.contains("cannot read"),
        "{m}"
    );
    let m = err(
        "[roughness]\ntopography = \"scans/self-affine.gsf\"\nlevel = \"cubic\"",
        "level",
    )
    .to_string();
    assert!(
        m.contains("roughness.level") && m.contains("quadratic"),
        "{m}"
    );
    let m = err(
        "[roughness]\ntopography = \"scans/self-affine.gsf\"\ncutoff = \"3 um\"",
        "bigcut",
    )
    .to_string();
    assert!(
        m.contains("cut-off") && m.contains("use a cut-off below"),
        "{m}"
    );
    let m = err(
        "[roughness]\ntopography = \"scans/self-affine.gsf\"\nheight_unit = \"V\"",
        "unit",
    )
    .to_string();
    assert!(m.contains("roughness.height_unit"), "{m}");
    // Exit code 2 from the CLI, for eval, optimize and pareto alike.
    let p = with_roughness(
        "[roughness]\ntopography = \"scans/self-affine.gsf\"\nsigma = \"3 nm\"",
        "cli",
    );
    for cmd in ["eval", "optimize", "pareto"] {
        wearopt()
            .args([cmd, &p.display().to_string()])
            .assert()
            .code(2);
    }
}

#[test]
fn eval_reports_the_scan() {
    let file = "problems/micro-gear-scan.toml";
    let out = common::stdout(wearopt().args(["eval", file]), 0);
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("σ, R and N come from the scan scans/self-affine.gsf"),
        "{text}"
    );
    assert!(
        text.contains("bandwidth α = ") && text.contains("cut-off 100.0 nm"),
        "{text}"
    );
    let out = common::stdout(wearopt().args(["eval", file, "--format", "json"]), 0);
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let s = &v["roughness_source"];
    assert_eq!(s["topography"], "scans/self-affine.gsf");
    assert_eq!(s["cutoff"], 100e-9);
    assert!(s["bandwidth"].as_f64().unwrap() > 1.5);
    assert_eq!(s["summit_sigma"], v["scene"]["sigma"]);
    // optimize and pareto run on it.
    wearopt().args(["optimize", file]).assert().success();
    wearopt()
        .args(["pareto", file, "--points", "3"])
        .assert()
        .success();
}

#[test]
fn roughness_json_has_the_contract_keys_and_the_text_block_round_trips() {
    let file = "problems/scans/self-affine.gsf";
    let out = common::stdout(
        wearopt().args(["roughness", file, "--cutoff", "100nm", "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    for key in [
        "nx",
        "ny",
        "pixel_size_x",
        "pixel_size_y",
        "valid_fraction",
        "level",
        "cutoff",
        "m0",
        "m2",
        "m4",
        "m2_x",
        "m2_y",
        "m4_x",
        "m4_y",
        "rms_height",
        "rms_slope",
        "bandwidth",
        "summit_sigma",
        "summit_radius",
        "summit_density",
        "mean_summit_height",
        "summits",
        "warnings",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    for key in ["count", "density", "sigma", "mean_radius"] {
        assert!(v["summits"].get(key).is_some(), "missing summits.{key}");
    }
    assert_eq!(v["nx"], 256);
    assert_eq!(v["pixel_size_x"], 20e-9);
    assert_eq!(v["level"], "plane");
    assert_eq!(v["cutoff"], 100e-9);
    let m2 = v["m2"].as_f64().unwrap();
    assert!((v["rms_slope"].as_f64().unwrap() - (2.0 * m2).sqrt()).abs() < 1e-15);
    let no_cut = common::stdout(wearopt().args(["roughness", file, "--format", "json"]), 0);
    let w: serde_json::Value = serde_json::from_slice(&no_cut).unwrap();
    assert!(w["cutoff"].is_null());

    // The text ends with a [roughness] table that loads to the same scene (4 digits).
    let out = common::stdout(wearopt().args(["roughness", file, "--cutoff", "100nm"]), 0);
    let text = String::from_utf8(out).unwrap();
    let block = &text[text.rfind("[roughness]").unwrap()..];
    let path = with_roughness(block, "paste");
    let pasted = problem::load(&path).unwrap();
    let scan = problem::load(Path::new(&root().join("problems/micro-gear-scan.toml"))).unwrap();
    for (x, y) in [
        (pasted.scene.sigma, scan.scene.sigma),
        (pasted.scene.asperity_radius, scan.scene.asperity_radius),
        (pasted.scene.asperity_density, scan.scene.asperity_density),
    ] {
        assert!((x - y).abs() < 5e-4 * y, "{x} vs {y}");
    }
}

#[test]
fn psd_plot_is_written() {
    let dir = std::env::temp_dir().join(format!("wearopt-psd-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("psd.svg");
    wearopt()
        .args([
            "roughness",
            "problems/scans/self-affine.x3p",
            "--cutoff",
            "100 nm",
            "--psd",
        ])
        .arg(&svg)
        .assert()
        .success();
    let s = std::fs::read_to_string(&svg).unwrap();
    assert!(s.starts_with("<?xml") && s.contains("cut-off λs = 100 nm") && s.contains("C(q)"));
}
