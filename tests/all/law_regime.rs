//! A study whose optimum leaves its asperity law's regime says so on its status
//! line, in JSON (`law_regime`) and in HTML, with the edit that re-runs it under the
//! law that holds (issue 56 item 1). The exit code stays 0: the optimum is a valid
//! optimum of the model the file states; the words say what it is worth.

use crate::common::{stdout, wearopt};

/// The hub's study under the paper's JKR law: its optimum (E 400 GPa, γ 5 mJ/m²,
/// R 200 nm, both bodies polysilicon with ν = 0.22) lies at φ0 = 0.0161, deep on
/// the DMT side, where JKR is not exact (it is for φ0 ≥ 3).
const JKR_STUDY: &str = "tests/data/micro-gear-study-jkr.toml";

/// φ0 = (R γ² / (E*² Z0³))^{1/3} (docs/model.md §2), E* = E / (2 (1 − ν²)) for two
/// bodies of one film: the closed form, computed here from the optimum's design.
fn tabor(design: &serde_json::Value) -> f64 {
    let e = design["youngs_modulus"].as_f64().unwrap();
    let gamma = design["work_of_adhesion"].as_f64().unwrap();
    let r = design["asperity_radius"].as_f64().unwrap();
    let z0: f64 = 0.3e-9; // the file's interatomic_distance
    let e_star = e / (2.0 * (1.0 - 0.22 * 0.22));
    (r * gamma * gamma / (e_star * e_star * z0.powi(3))).cbrt()
}

#[test]
fn the_status_line_says_the_law_left_its_regime_with_the_rerun() {
    let out = stdout(wearopt().args(["optimize", JKR_STUDY]), 0);
    let text = String::from_utf8(out).unwrap();
    let status = text.lines().find(|l| l.starts_with("Status:")).unwrap();
    assert_eq!(
        status,
        "Status: optimal (outside the JKR law's regime at the optimum: φ0 = 0.0161 < 3): the KKT conditions hold to tolerance at a feasible design",
        "{text}"
    );
    let next = text
        .lines()
        .skip_while(|l| !l.starts_with("Status:"))
        .nth(1)
        .unwrap();
    assert!(
        next.contains("the JKR law is exact for φ0 ≥ 3 only"),
        "{next}"
    );
    assert!(
        next.contains(&format!(
            "re-run under the Lennard-Jones law, which holds at every φ0: set [interface] adhesion_model = \"lennard_jones\" in {JKR_STUDY}, then wearopt optimize {JKR_STUDY}"
        )),
        "{next}"
    );
    // The warning further down stays.
    assert!(
        text.contains("WARNING: Tabor parameter φ0 = 0.0161 < 0.3"),
        "{text}"
    );
}

#[test]
fn json_and_html_carry_the_law_regime() {
    let out = stdout(
        wearopt().args(["optimize", JKR_STUDY, "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["status"], "optimal");
    let l = &v["law_regime"];
    assert_eq!(l["law"], "jkr");
    assert_eq!(l["law_that_holds"], "lennard_jones");
    assert_eq!(l["valid_tabor_min"], 3.0);
    assert!(l["valid_tabor_max"].is_null());
    let phi = l["tabor_parameter"].as_f64().unwrap();
    let want = tabor(&v["design"]);
    assert!(((phi - want) / want).abs() < 1e-12, "{phi} against {want}");
    assert!(phi < 0.3, "{phi}");
    assert!(
        l["rerun"]
            .as_str()
            .unwrap()
            .contains("adhesion_model = \"lennard_jones\""),
        "{l}"
    );
    // Existing keys stay: the warning is still in `warnings`.
    assert!(v["warnings"][0]
        .as_str()
        .unwrap()
        .contains("Tabor parameter"));

    let out = stdout(
        wearopt().args(["optimize", JKR_STUDY, "--format", "html"]),
        0,
    );
    let html = String::from_utf8(out).unwrap();
    assert!(
        html.contains("<p class=\"status\">Status: optimal (outside the JKR law&apos;s regime at the optimum: φ0 = 0.0161 &lt; 3)</p>"),
        "{html}"
    );
    assert!(
        html.contains("re-run under the Lennard-Jones law"),
        "{html}"
    );
}

/// The shipped study, under the Lennard-Jones law (exact at every φ0), has no such
/// words and no `law_regime` key.
#[test]
fn the_shipped_study_holds_its_law_at_its_optimum() {
    let f = "problems/micro-gear-study.toml";
    let text = String::from_utf8(stdout(wearopt().args(["optimize", f]), 0)).unwrap();
    assert!(
        text.contains(
            "Status: optimal: the KKT conditions hold to tolerance at a feasible design\n"
        ),
        "{text}"
    );
    assert!(!text.contains("regime"), "{text}");
    let out = stdout(wearopt().args(["optimize", f, "--format", "json"]), 0);
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert!(v.get("law_regime").is_none(), "{v}");
    assert_eq!(v["evaluation"]["adhesion_model"], "lennard_jones", "{v}");
}
