//! Reports as a user meets them: units, small defects of the command line, and the
//! numbers a designer decides on. Each test runs the binary on a problem file.

use assert_cmd::Command;

fn wearopt() -> Command {
    Command::cargo_bin("wearopt").unwrap()
}

fn stdout_of(args: &[&str]) -> String {
    let out = wearopt().args(args).output().unwrap();
    String::from_utf8(out.stdout).unwrap()
}

fn stderr_failing(args: &[&str], code: i32) -> String {
    let out = wearopt()
        .args(args)
        .assert()
        .code(code)
        .get_output()
        .clone();
    assert!(out.stdout.is_empty(), "stdout not empty: {:?}", out.stdout);
    String::from_utf8(out.stderr).unwrap()
}

/// The micro-gear hub: A_r = 5.702e-13 m² and wear rate 5.702e-17 m³/m
/// (tests/problem_files.rs pins the SI values); the text says so with the prefix on the
/// length, and the line the contract names stays.
#[test]
fn eval_text_units_are_si() {
    let t = stdout_of(&["eval", "problems/micro-gear.toml"]);
    assert!(t.contains("real area A_r = 0.5702 µm²"), "{t}");
    assert!(t.contains("wear rate V/L = 57.02 µm³/m"), "{t}");
    assert!(t.contains("asperity density N = 10.0 µm⁻²"), "{t}");
    assert!(
        !t.contains("fm²") && !t.contains("am³") && !t.contains(" um"),
        "{t}"
    );
    assert!(t.contains("Richardson"), "{t}");
}

#[test]
fn curve_refuses_negative_indices_in_its_own_words() {
    for (flag, value) in [("--theta", "-1"), ("--lambda", "-2")] {
        let mut args = vec![
            "curve", "--theta", "1", "--lambda", "1", "--from", "0", "--to", "1", "--points", "2",
        ];
        let i = args.iter().position(|a| *a == flag).unwrap();
        args[i + 1] = value;
        let err = stderr_failing(&args, 2);
        assert!(
            err.contains(&format!("{flag} {value}: must be > 0")),
            "{err}"
        );
        assert!(!err.contains("unexpected argument"), "{err}");
    }
}

#[test]
fn json_and_a_csv_trace_never_share_stdout() {
    let err = stderr_failing(
        &[
            "optimize",
            "problems/switch-study.toml",
            "--format",
            "json",
            "--trace",
            "-",
        ],
        2,
    );
    assert!(
        err.contains("--trace -") && err.contains("file name"),
        "{err}"
    );
}

/// A scene written from the gold switch with `replace` edits, evaluated as JSON.
fn eval_json_of(edits: &[(&str, &str)]) -> (serde_json::Value, i32) {
    let mut text = std::fs::read_to_string("problems/gold-switch.toml").unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replacen(from, to, 1);
    }
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let name = format!("reports-{:x}.toml", {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        text.hash(&mut h);
        h.finish()
    });
    let path = dir.join(name);
    std::fs::write(&path, &text).unwrap();
    let out = wearopt()
        .args(["eval", path.to_str().unwrap(), "--format", "json"])
        .output()
        .unwrap();
    let v = serde_json::from_slice(&out.stdout).unwrap();
    (v, out.status.code().unwrap())
}

fn warnings_of(v: &serde_json::Value) -> Vec<String> {
    v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w.as_str().unwrap().to_string())
        .collect()
}

fn kinds_of(v: &serde_json::Value) -> Vec<String> {
    v["warning_details"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["kind"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn a_forgotten_unit_is_caught() {
    let (v, _) = eval_json_of(&[("sigma = \"5 nm\"", "sigma = 2")]);
    let w = warnings_of(&v);
    assert!(
        w.iter()
            .any(|w| w.contains("roughness σ = 2 m") && w.contains("did you mean 2 nm")),
        "{w:?}"
    );
    assert!(kinds_of(&v).contains(&"implausible_input".to_string()));
}

/// 1 N on 5 µm² of gold: Greenwood–Williamson would need a real area many times the
/// nominal one. That is not ok.
#[test]
fn impossible_real_area_is_out_of_range() {
    let (v, code) = eval_json_of(&[
        ("load = \"50 uN\"", "load = \"1 N\""),
        ("nominal_area = \"100 um^2\"", "nominal_area = \"5 um^2\""),
    ]);
    assert_eq!(v["status"], "out_of_range", "{v}");
    assert!(v["real_area_fraction"].as_f64().unwrap() > 1.0);
    assert!(kinds_of(&v).contains(&"real_area_exceeds_nominal".to_string()));
    assert_eq!(code, 1);
}

#[test]
fn few_contacts_and_dense_contact_are_said() {
    let (v, _) = eval_json_of(&[("nominal_area = \"100 um^2\"", "nominal_area = \"3 um^2\"")]);
    assert_eq!(v["status"], "ok");
    assert!(v["contact_count"].as_f64().unwrap() < 10.0);
    assert!(kinds_of(&v).contains(&"few_contacts".to_string()), "{v}");
    // The summit parameter of the shipped switch: 1 µm⁻² × 1 µm × 5 nm = 0.005.
    assert!(kinds_of(&v).contains(&"summit_parameter".to_string()));
    // The shipped micro-gear hub is plausible in every respect but φ0.
    let t = stdout_of(&["eval", "problems/micro-gear.toml", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&t).unwrap();
    assert_eq!(kinds_of(&v), vec!["outside_jkr_regime".to_string()]);
}
