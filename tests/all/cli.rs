//! The command line end to end: outputs, contracts of JSON/CSV keys, exit codes.

use crate::common;
use crate::common::wearopt;

#[test]
fn eval_json_has_the_contract_keys() {
    for name in ["micro-gear", "dlc-contact", "gold-switch"] {
        let out = common::stdout(
            wearopt().args(["eval", &format!("problems/{name}.toml"), "--format", "json"]),
            0,
        );
        let v: serde_json::Value = serde_json::from_slice(&out).expect("valid JSON");
        for key in [
            "status",
            "warnings",
            "separation",
            "real_area",
            "plastic_real_area",
            "contact_count",
            "pull_off_force",
            "wear_volume",
            "wear_rate",
            "elastic_adhesion_index",
            "plastic_adhesion_index",
            "plasticity_index",
            "tabor_parameter",
            "sensitivities",
        ] {
            assert!(v.get(key).is_some(), "{name}: missing {key}");
        }
        assert_eq!(v["status"], "ok");
        let sens = &v["sensitivities"];
        for key in [
            "youngs_modulus",
            "hardness",
            "work_of_adhesion",
            "sigma",
            "asperity_radius",
        ] {
            assert!(sens.get(key).is_some(), "{name}: sensitivities.{key}");
        }
        // Wear rate = k · area, volume = rate · L (eq. 13), as written.
        let rate = v["wear_rate"].as_f64().unwrap();
        let vol = v["wear_volume"].as_f64().unwrap();
        let l = v["scene"]["sliding_distance"].as_f64().unwrap();
        assert!((vol / (rate * l) - 1.0).abs() < 1e-15);
        assert!(rate > 0.0);
    }
}

#[test]
fn eval_text_reports_the_sections() {
    let out = common::stdout(wearopt().args(["eval", "problems/micro-gear.toml"]), 0);
    let text = String::from_utf8(out).unwrap();
    for part in [
        "Indices and regime",
        "separation d =",
        "real area",
        "pull-off force",
        "wear rate",
        "Sensitivity",
    ] {
        assert!(text.contains(part), "missing {part}:\n{text}");
    }
}

#[test]
fn curve_csv_and_json() {
    let out = common::stdout(
        wearopt().args([
            "curve", "--theta", "inf", "--lambda", "inf", "--from", "0", "--to", "2", "--points",
            "3",
        ]),
        0,
    );
    let csv = String::from_utf8(out).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "h,load,area,plastic_area,critical_interference,dload_dh,noncontact_load"
    );
    let first: Vec<f64> = lines
        .next()
        .unwrap()
        .split(',')
        .map(|c| c.parse().unwrap())
        .collect();
    // Greenwood–Williamson at h = 0: P̄ = 2^{1/4} Γ(5/4), Ā = 1 (closed forms).
    assert_eq!(first[0], 0.0);
    assert!((first[1] / (2f64.powf(0.25) * 0.906_402_477_055_477) - 1.0).abs() < 1e-13);
    assert!((first[2] - 1.0).abs() < 1e-15);
    assert_eq!(csv.lines().count(), 4);

    let out = common::stdout(
        wearopt().args([
            "curve", "--theta", "10", "--lambda", "0.125", "--from", "-1", "--to", "-1",
            "--points", "1", "--format", "json",
        ]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 1);
    for key in ["h", "load", "area", "plastic_area", "critical_interference"] {
        assert!(rows[0].get(key).is_some());
    }
}

#[test]
fn bad_input_exits_2_with_a_message() {
    let dir = std::env::temp_dir().join(format!("wearopt-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("bad.toml");
    std::fs::write(
        &f,
        std::fs::read_to_string("problems/micro-gear.toml")
            .unwrap()
            .replacen("load = \"800 uN\"", "load = \"800 uQ\"", 1),
    )
    .unwrap();
    let out = common::stderr(wearopt().args(["eval", f.to_str().unwrap()]), 2);
    let msg = String::from_utf8(out).unwrap();
    assert!(
        msg.contains("contact.load") && msg.contains("uQ") && msg.contains("bad.toml"),
        "{msg}"
    );

    wearopt()
        .args(["eval", "no/such/file.toml"])
        .assert()
        .code(2);
    wearopt()
        .args([
            "curve", "--theta", "-1", "--lambda", "1", "--from", "0", "--to", "1", "--points", "2",
        ])
        .assert()
        .code(2);
    wearopt()
        .args([
            "curve", "--theta", "1", "--lambda", "1", "--from", "2", "--to", "1", "--points", "2",
        ])
        .assert()
        .code(2);
    wearopt()
        .args([
            "curve", "--theta", "1", "--lambda", "1", "--from", "0", "--to", "1", "--points", "0",
        ])
        .assert()
        .code(2);
    wearopt().args(["frobnicate"]).assert().code(2);
}

#[test]
fn tensile_beyond_pull_off_is_an_outcome() {
    let dir = std::env::temp_dir().join(format!("wearopt-cli-sep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("pulled.toml");
    std::fs::write(
        &f,
        std::fs::read_to_string("problems/micro-gear.toml")
            .unwrap()
            .replacen("load = \"800 uN\"", "load = \"-1 mN\"", 1),
    )
    .unwrap();
    let out = common::stdout(
        wearopt().args(["eval", f.to_str().unwrap(), "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["status"], "separated");
    assert_eq!(v["wear_rate"], 0.0);
}

#[test]
fn optimize_json_contract_and_exit_codes() {
    let out = common::stdout(
        wearopt().args([
            "optimize",
            "tests/data/micro-gear-study-jkr.toml",
            "--format",
            "json",
        ]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    for key in [
        "status",
        "design",
        "baseline_design",
        "objective",
        "baseline_objective",
        "constraints",
        "kkt_residual",
        "evaluations",
        "starts",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["status"], "optimal");
    for key in [
        "youngs_modulus",
        "hardness",
        "work_of_adhesion",
        "sigma",
        "asperity_radius",
    ] {
        assert!(v["design"][key].as_f64().unwrap() > 0.0, "design.{key}");
        assert!(v["baseline_design"][key].as_f64().unwrap() > 0.0);
    }
    for c in v["constraints"].as_array().unwrap() {
        for key in ["quantity", "value", "min", "max", "active", "multiplier"] {
            assert!(c.get(key).is_some(), "constraint.{key}");
        }
    }
    assert!(v["objective"].as_f64().unwrap() < v["baseline_objective"].as_f64().unwrap());

    // Infeasible: exit 1, status and the conflicting constraint named.
    let out = common::stdout(
        wearopt().args([
            "optimize",
            "tests/data/infeasible-study-jkr.toml",
            "--format",
            "json",
        ]),
        1,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["status"], "infeasible");
    assert_eq!(v["conflicting_constraints"][0], "plasticity_index");
    // The page names the conflict too, and shows no multiplier.
    let out = common::stdout(
        wearopt().args([
            "optimize",
            "tests/data/infeasible-study-jkr.toml",
            "--format",
            "html",
        ]),
        1,
    );
    let page = String::from_utf8(out).unwrap();
    assert!(
        page.contains("Conflicting constraints") && page.contains("plasticity_index.</p>"),
        "the page names the conflict"
    );
    assert!(page.contains("No multiplier or shadow price"));

    // No [design]: bad input, exit 2, the file named.
    let out = common::stderr(wearopt().args(["optimize", "problems/dlc-contact.toml"]), 2);
    let msg = String::from_utf8(out).unwrap();
    assert!(
        msg.contains("dlc-contact.toml") && msg.contains("[design]"),
        "{msg}"
    );
}

#[test]
fn optimize_trace_has_one_row_per_iteration() {
    let dir = std::env::temp_dir().join(format!("wearopt-trace-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let trace = dir.join("trace.csv");
    wearopt()
        .args([
            "optimize",
            "tests/data/switch-study-jkr.toml",
            "--trace",
            trace.to_str().unwrap(),
        ])
        .assert()
        .success();
    let text = std::fs::read_to_string(&trace).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next().unwrap(),
        "start,iteration,time_s,objective,ln_objective,kkt_residual,constraint_violation"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert!(rows.len() >= 4);
    // The KKT residual of each start's last row is what the report calls converged.
    let last = rows.last().unwrap();
    assert!(last[5] < 1e-6, "{last:?}");
    // Time never runs backwards within a start.
    for w in rows.windows(2) {
        if w[0][0] == w[1][0] {
            assert!(w[1][2] >= w[0][2]);
        }
    }
}

/// Every command reads `--format` as one of the report stage's formats and refuses one
/// it does not write with exit code 2, naming the formats it accepts; its help lists
/// exactly those.
#[test]
fn every_command_names_the_formats_it_writes() {
    let cases: &[(&[&str], &str, &str)] = &[
        (
            &["eval", "problems/micro-gear.toml"],
            "csv",
            "text, json, html",
        ),
        (
            &["optimize", "tests/data/micro-gear-study-jkr.toml"],
            "csv",
            "text, json, html",
        ),
        // pareto writes every format: only the unknown name is refused.
        (
            &["pareto", "problems/latch-pareto.toml"],
            "",
            "text, json, csv, html",
        ),
        (&["accuracy"], "html", "text, json, csv"),
        (&["figures"], "html", "text, json"),
        (
            &[
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3mm",
            ],
            "csv",
            "text, json",
        ),
        (
            &["roughness", "problems/scans/self-affine.gsf"],
            "html",
            "text, json",
        ),
        (
            &["fit-wear", "problems/wear-rates.csv"],
            "csv",
            "text, json",
        ),
        (
            &[
                "curve", "--theta", "10", "--lambda", "1", "--from", "0", "--to", "1", "--points",
                "2",
            ],
            "text",
            "csv, json",
        ),
        (
            &[
                "sweep",
                "tests/data/micro-gear-study-jkr.toml",
                "--samples",
                "4",
            ],
            "text",
            "csv, json",
        ),
    ];
    for (args, bad, accepted) in cases {
        let command = args[0];
        if bad.is_empty() {
            assert_eq!(command, "pareto");
        }
        let out = wearopt()
            .args(*args)
            .args(["--format", if bad.is_empty() { "xml" } else { bad }])
            .output()
            .unwrap();
        if !bad.is_empty() {
            assert_eq!(out.status.code(), Some(2), "{args:?} --format {bad}");
            assert!(out.stdout.is_empty(), "{args:?}: wrote before refusing");
            let err = String::from_utf8_lossy(&out.stderr);
            assert!(
                err.contains(&format!(
                    "--format {bad}: {command} does not write {bad}; accepted: {accepted}"
                )),
                "{args:?}: {err}"
            );
        }
        // Not a format at all.
        let out = wearopt()
            .args(*args)
            .args(["--format", "xml"])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&out.stderr).contains(&format!(
            "--format \"xml\": not a format; {command} accepts: {accepted}"
        )));
        // Help lists exactly the accepted formats.
        let help = wearopt().args([command, "--help"]).output().unwrap();
        let help = String::from_utf8_lossy(&help.stdout);
        let listed: Vec<&str> = help
            .lines()
            .skip_while(|l| !l.trim_start().starts_with("--format"))
            .skip_while(|l| !l.contains("Possible values"))
            .skip(1)
            .take_while(|l| l.trim_start().starts_with("- "))
            .map(|l| {
                let l = l.trim_start().trim_start_matches("- ");
                &l[..l.find(':').unwrap()]
            })
            .collect();
        assert_eq!(listed.join(", "), *accepted, "{command}: {help}");
    }
}

/// The text report's single-asperity pull-off follows the scene's law: JKR's
/// 1.5πγR (the micro-gear under JKR, γ = 0.1 J/m², R = 1 µm: 471 nN), the
/// Lennard-Jones sphere's at the hub's μ = 0.374 (1.836πγR from its table,
/// 577 nN) and DMT's 2πγR, 4/3 of JKR's (the DLC contact, γ = 50 mJ/m²,
/// R = 2 µm: 628 nN); the JSON key
/// `asperity_pull_off_force` keeps JKR's value whatever the law.
#[test]
fn eval_text_names_the_single_asperity_pull_off_of_the_law() {
    let text = |name: &str| {
        let out = common::stdout(wearopt().args(["eval", &format!("{name}.toml")]), 0);
        String::from_utf8(out).unwrap()
    };
    let jkr = common::under_law("micro-gear", "jkr");
    let gear = text(jkr.with_extension("").to_str().unwrap());
    assert!(gear.contains("one asperity (JKR 1.5πγR): 471 nN"), "{gear}");
    let gear = text("problems/micro-gear");
    assert!(
        gear.contains("one asperity (Lennard-Jones sphere 1.836πγR): 577 nN"),
        "{gear}"
    );
    let dlc = text("problems/dlc-contact");
    assert!(dlc.contains("one asperity (DMT 2πγR): 628 nN"), "{dlc}");
    let out = common::stdout(
        wearopt().args(["eval", "problems/dlc-contact.toml", "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let f = v["asperity_pull_off_force"].as_f64().unwrap();
    assert!(
        (f / (1.5 * std::f64::consts::PI * 0.05 * 2e-6) - 1.0).abs() < 1e-12,
        "{f}"
    );
}

/// An optimum whose wear is too small for a double (only plastic junctions wear,
/// and at the optimum's hardness asperities tall enough to turn plastic are
/// astronomically rare) is said in words with its logarithm, not as "improvement
/// ×inf"; the JSON `improvement_factor` is then null, never Inf.
#[test]
fn optimize_says_why_an_optimum_wears_nothing() {
    let out = common::stdout(
        wearopt().args(["optimize", "tests/data/study_zero_wear.toml"]),
        0,
    );
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("Status: optimal"), "{text}");
    assert!(
        text.contains(" m³/m at the optimum, below the smallest number a double holds: only plastic junctions wear, and asperities tall enough to turn plastic are that rare; every design this far down is as good to the optimiser"),
        "{text}"
    );
    assert!(!text.contains("inf"), "{text}");
    let out = common::stdout(
        wearopt().args([
            "optimize",
            "tests/data/study_zero_wear.toml",
            "--format",
            "json",
        ]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["objective"].as_f64(), Some(0.0));
    assert!(
        v["improvement_factor"].is_null(),
        "{}",
        v["improvement_factor"]
    );
    assert!(v["baseline_objective"].as_f64().unwrap() > 0.0);
}

/// A reader that goes away (`wearopt … | head -c 1`) ends the output quietly, exit 0,
/// for every command that writes to stdout; it used to panic ("failed printing to
/// stdout: Broken pipe") in curve, roughness, accuracy, figures and fit-adhesion.
#[test]
fn a_closed_pipe_is_not_a_panic() {
    let figures = std::env::temp_dir().join(format!("wearopt-pipe-{}", std::process::id()));
    let figures = figures.display().to_string();
    let commands: Vec<Vec<&str>> = vec![
        vec![
            "curve", "--theta", "10", "--lambda", "1", "--from", "-2", "--to", "4", "--points",
            "20000",
        ],
        vec!["roughness", "problems/scans/self-affine.gsf"],
        vec!["eval", "problems/micro-gear.toml", "--format", "html"],
        vec!["figures", "--out", &figures, "--points", "5"],
        vec![
            "fit-adhesion",
            "problems/ando-friction.csv",
            "--radius",
            "0.3mm",
            "--format",
            "json",
        ],
    ];
    for args in commands {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_wearopt"))
            .args(&args)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("runs");
        drop(child.stdout.take());
        let out = child.wait_with_output().expect("ends");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        assert_eq!(out.status.code(), Some(0), "{args:?}: {stderr}");
    }
    let _ = std::fs::remove_dir_all(&figures);
}

/// An output path that cannot be written is the user's input: exit code 2, with the
/// path and what was to be written (issue 21, item 6: it was exit code 1).
#[test]
fn unwritable_output_paths_exit_2() {
    let missing = std::env::temp_dir()
        .join(format!("wearopt-no-such-folder-{}", std::process::id()))
        .join("x");
    let path = missing.to_str().unwrap();
    for args in [
        vec!["eval", "problems/micro-gear.toml", "--out", path],
        vec![
            "optimize",
            "tests/data/micro-gear-study-jkr.toml",
            "--trace",
            path,
        ],
        vec![
            "humidity",
            "problems/micro-gear-humid.toml",
            "--from",
            "0",
            "--to",
            "0.5",
            "--points",
            "2",
            "--plot",
            path,
        ],
        vec![
            "sweep",
            "tests/data/micro-gear-study-jkr.toml",
            "--samples",
            "4",
            "--out",
            path,
        ],
    ] {
        let err = String::from_utf8(common::stderr(wearopt().args(&args), 2)).unwrap();
        assert!(
            err.contains("cannot write") && err.contains(path),
            "{args:?}: {err}"
        );
    }
}
