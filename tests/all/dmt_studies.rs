//! `optimize` and `pareto` under the DMT law, end to end through the CLI on problem
//! files (the DMT material ranking is tests/materials.rs: the shipped
//! `problems/materials-study.toml` is DMT).
//!
//! The scene is the polysilicon micro-gear hub of `problems/micro-gear.toml` (φ0 =
//! 0.374) with `adhesion_model = "dmt"`: under van der Waals attraction its pull-off is
//! 4.279 µN (docs/model.md §7, tests/dmt.rs), so a 1 µN pull-off limit makes the
//! baseline infeasible and the study has to move σ and R to release the hub, which
//! it cannot do under JKR (pull-off 2e-63 N there).

use assert_cmd::Command;
use serde_json::Value;

fn wearopt() -> Command {
    Command::cargo_bin("wearopt").expect("binary builds")
}

/// The hub under DMT with a two-variable study (σ, R), a pull-off limit and a Pareto
/// section; σ and R are TOML values (a quoted quantity or metres).
fn study(attraction: &str, sigma: &str, radius: &str) -> String {
    format!(
        r#"name = "Polysilicon hub under DMT ({attraction})"
[contact]
load = "800 uN"
nominal_area = "1000 um^2"
sliding_distance = "1 m"
wear_coefficient = 1e-4
[bodies]
a = {{ material = "polysilicon" }}
b = {{ material = "polysilicon" }}
[interface]
work_of_adhesion = "0.1 J/m^2"
interatomic_distance = "0.3 nm"
adhesion_model = "dmt"
attraction = "{attraction}"
[roughness]
sigma = {sigma}
asperity_radius = {radius}
asperity_density = "10 um^-2"
[design]
sigma = {{ min = "0.5 nm", max = "20 nm" }}
asperity_radius = {{ min = "0.2 um", max = "10 um" }}
[objective]
minimize = "wear_rate"
[[constraint]]
quantity = "pull_off_force"
max = "1 uN"
[[constraint]]
quantity = "plasticity_index"
max = 1.0
[pareto]
adhesion = "pull_off_force"
points = 7
direction = "low"
[optimizer]
starts = 4
seed = 1
tolerance = 1e-8
"#
    )
}

fn write(name: &str, text: &str) -> String {
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

fn json(args: &[&str]) -> Value {
    let out = wearopt()
        .args(args)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    serde_json::from_slice(&out).expect("valid JSON")
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// `wearopt eval` of the hub at a design (σ, R in metres).
fn eval_at(attraction: &str, design: &Value, tag: &str) -> Value {
    let sigma = design["sigma"].as_f64().unwrap();
    let radius = design["asperity_radius"].as_f64().unwrap();
    let file = write(
        &format!("dmt-eval-{attraction}-{tag}.toml"),
        &study(attraction, &format!("{sigma:e}"), &format!("{radius:e}")),
    );
    json(&["eval", &file, "--format", "json"])
}

#[test]
fn dmt_study_is_solved_to_its_tolerance_and_eval_agrees() {
    for attraction in ["van_der_waals", "dugdale"] {
        let file = write(
            &format!("dmt-study-{attraction}.toml"),
            &study(attraction, "\"3 nm\"", "\"1 um\""),
        );
        let v = json(&["optimize", &file, "--format", "json"]);
        assert_eq!(v["status"], "optimal", "{attraction}: {v}");
        assert!(
            v["kkt_residual"].as_f64().unwrap() <= 1e-8,
            "{attraction}: {v}"
        );
        let ev = &v["evaluation"];
        assert_eq!(ev["adhesion_model"], "dmt");
        assert_eq!(ev["attraction"], attraction);
        // In contact at the optimum, every constraint met.
        assert_eq!(ev["status"], "ok", "{attraction}");
        assert!(ev["nondimensional_separation"]
            .as_f64()
            .unwrap()
            .is_finite());
        assert!(ev["real_area"].as_f64().unwrap() > 0.0);
        assert!(ev["pull_off_force"].as_f64().unwrap() <= 1e-6 * (1.0 + 1e-9));
        if attraction == "van_der_waals" {
            // The baseline sticks under van der Waals (4.279 µN > 1 µN, tests/dmt.rs).
            assert_eq!(v["baseline_feasible"], false, "{v}");
            let pulled = v["baseline_violations"][0]["value"].as_f64().unwrap();
            assert!(rel(pulled, 4.2785e-6) < 1e-4, "{pulled}");
            assert!(ev["noncontact_load"].as_f64().unwrap() < 0.0);
        }

        // `eval` of the optimum's design gives the optimiser's numbers.
        let e = eval_at(attraction, &v["design"], "optimum");
        assert_eq!(e["adhesion_model"], "dmt");
        assert_eq!(e["status"], "ok");
        let objective = v["objective"].as_f64().unwrap();
        assert!(rel(e["wear_rate"].as_f64().unwrap(), objective) < 1e-10);
        for key in ["pull_off_force", "real_area", "nondimensional_separation"] {
            let (a, b) = (e[key].as_f64().unwrap(), ev[key].as_f64().unwrap());
            assert!(
                a == b || rel(a, b) < 1e-10,
                "{attraction} {key}: {a} vs {b}"
            );
        }

        // The text report prints the KKT residual, within the study's tolerance.
        let out = wearopt().args(["optimize", &file]).assert().success();
        let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
        assert!(text.contains("Status: optimal"), "{text}");
        let kkt: f64 = text
            .split("KKT residual ")
            .nth(1)
            .and_then(|t| t.split_whitespace().next())
            .expect("KKT residual printed")
            .parse()
            .unwrap();
        assert!(kkt <= 1e-8, "{text}");
    }
}

#[test]
fn dmt_pareto_front_trades_wear_against_pull_off() {
    let file = write(
        "dmt-pareto.toml",
        &study("van_der_waals", "\"3 nm\"", "\"1 um\""),
    );
    let v = json(&["pareto", &file, "--format", "json"]);
    assert_eq!(v["status"], "ok", "{v}");
    let points = v["points"].as_array().unwrap();
    let front: Vec<&Value> = points.iter().filter(|p| p["on_front"] == true).collect();
    // The seven points asked for describe the front; where the curve turns,
    // the dominated points past it come on top.
    assert!(points.len() >= 7, "{v}");
    if points.len() > 7 {
        assert_eq!(front.len(), 7, "{v}");
        assert!(v["turn"].is_u64(), "{v}");
    } else {
        assert!(front.len() >= 3, "{v}");
    }
    // Along the front (ascending pull-off, direction low) wear falls: a trade-off.
    for w in front.windows(2) {
        let (a, b) = (w[0], w[1]);
        assert!(a["adhesion"].as_f64().unwrap() < b["adhesion"].as_f64().unwrap());
        assert!(a["wear_rate"].as_f64().unwrap() > b["wear_rate"].as_f64().unwrap());
    }
    for p in &front {
        assert_eq!(p["status"], "optimal", "{p}");
        assert!(p["adhesion"].as_f64().unwrap() <= 1e-6 * (1.0 + 1e-9));
    }
    // Every front point is a DMT design: eval at its σ, R gives its pull-off and wear.
    for (k, p) in front.iter().enumerate() {
        let e = eval_at("van_der_waals", &p["design"], &format!("front{k}"));
        assert_eq!(e["status"], "ok");
        assert!(
            rel(
                e["pull_off_force"].as_f64().unwrap(),
                p["adhesion"].as_f64().unwrap()
            ) < 1e-10
        );
        assert!(
            rel(
                e["wear_rate"].as_f64().unwrap(),
                p["wear_rate"].as_f64().unwrap()
            ) < 1e-10
        );
    }
}
