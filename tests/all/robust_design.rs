//! Robust and chance-constrained design through `wearopt optimize` on problem
//! files (issue 54): the robust optimum beside the nominal one, each chance
//! constraint verified by sampling, checked against closed forms of the
//! plasticity index's law. (The SORA engine itself is tested on analytic
//! problems in `robust.rs`.)

use serde_json::Value;

use crate::common::{self, wearopt};
use wearopt::uq::distribution::{std_normal_pdf, std_normal_quantile, std_normal_sf};

const SHIPPED: &str = "problems/micro-gear-robust.toml";

fn json_of(args: &[&str], code: i32) -> Value {
    let out = common::stdout(wearopt().args(args), code);
    serde_json::from_slice(&out).expect("JSON")
}

/// A fresh folder beside the test binaries.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("robust-{name}"));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// The shipped study: every uncertain input lognormal, so ln ψ = ln E − ln H +
/// ½ ln σ − ½ ln R is normal with sd s, s² = ln²1.05 + ¼ ln²1.2 + ¼ ln²1.2, and
/// FORM is exact for the plasticity event. Closed forms: the robust design has
/// ψ = exp(−β_t s) at the medians, β_t = −Φ⁻¹(1e-3); the nominal optimum, on
/// ψ = 1 at the medians, is plastic in exactly half the hubs.
#[test]
fn the_shipped_robust_hub_meets_its_targets_where_the_nominal_one_fails_half() {
    let doc = json_of(&["optimize", SHIPPED, "--format", "json"], 0);
    let r = &doc["robust"];
    assert_eq!(r["status"], "optimal", "{r}");
    assert_eq!(r["statistic"], "p95");
    let s = (1.05_f64.ln().powi(2) + 0.5 * 1.2_f64.ln().powi(2)).sqrt();
    let beta_t = -std_normal_quantile(1e-3);
    let psi = num(&r["evaluation"]["indices"]["plasticity_index"]);
    let want = (-beta_t * s).exp();
    assert!(
        ((psi - want) / want).abs() < 1e-5,
        "ψ at the medians {psi}, closed form {want}"
    );
    let plastic = &r["chance_constraints"][0];
    assert_eq!(plastic["violated"], false, "{plastic}");
    assert!(
        (num(&plastic["form_beta"]) - beta_t).abs() < 1e-4,
        "{plastic}"
    );
    let [lo, hi] = [
        num(&plastic["probability_interval"][0]),
        num(&plastic["probability_interval"][1]),
    ];
    assert!(
        lo <= 1e-3 && 1e-3 <= hi,
        "sampled [{lo}, {hi}] against 1e-3"
    );
    // The nominal optimum sits on ψ = 1: one half, inside the sampled interval.
    let nominal = &r["chance_at_nominal_optimum"][0];
    let [lo, hi] = [
        num(&nominal["probability_interval"][0]),
        num(&nominal["probability_interval"][1]),
    ];
    assert!(lo <= 0.5 && 0.5 <= hi, "nominal optimum: [{lo}, {hi}]");
    assert!(
        (num(&doc["evaluation"]["indices"]["plasticity_index"]) - 1.0).abs() < 1e-6,
        "the nominal optimum is on its limit"
    );
    // Stiction binds too (the Lennard-Jones pull-off): met at the robust design
    // to its interval, above its target at the nominal optimum, whose pull-off
    // limit holds only at the medians.
    let stiction = &r["chance_constraints"][1];
    assert_eq!(stiction["event"], "stiction");
    assert_eq!(stiction["violated"], false, "{stiction}");
    assert!(
        num(&stiction["probability_interval"][0]) <= 1e-3,
        "{stiction}"
    );
    let nominal = &r["chance_at_nominal_optimum"][1];
    assert!(num(&nominal["probability_interval"][0]) > 1e-3, "{nominal}");
    // The p95 on the common random numbers and on an independent sample of
    // 4096 agree within the first's stated interval.
    let o = &r["objective"];
    let v = num(&r["objective_verified"]["value"]);
    assert!(
        num(&o["interval"][0]) <= v && v <= num(&o["interval"][1]),
        "p95 {o} against the independent sample's {v}"
    );
}

/// P(ψ > 1) at a design whose hardness is normal (mean H_d, sd 0.1 H_d) and
/// σ, R lognormal with factor 1.2: a one-dimensional integral over H of the
/// normal tail of ½ ln(σ/R), by Simpson's rule on ±8 sd (independent of the
/// sampling it checks).
fn plastic_probability(psi_median: f64) -> f64 {
    let s = 1.2_f64.ln() / 2f64.sqrt();
    let (cov, n) = (0.1, 4000);
    let (a, b) = (-8.0, 8.0);
    let h = (b - a) / n as f64;
    let f = |z: f64| {
        let ratio = 1.0 + cov * z; // H / H_d
        std_normal_pdf(z) * std_normal_sf((ratio.ln() - psi_median.ln()) / s)
    };
    let mut sum = f(a) + f(b);
    for k in 1..n {
        sum += f(a + k as f64 * h) * if k % 2 == 1 { 4.0 } else { 2.0 };
    }
    sum * h / 3.0
}

fn normal_hardness_study(dir: &std::path::Path, verify: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(SHIPPED)
        .unwrap()
        .replace(
            "hardness = { distribution = \"lognormal\", median = \"10 GPa\", factor = 1.05 }",
            "hardness = { distribution = \"normal\", mean = \"10 GPa\", sd = \"1 GPa\" }",
        )
        .replace("statistic = \"p95\"", "")
        .replace("samples = 256", "")
        .replace(
            "[[constraint]]                  # at most 1 hub in 1000 stuck to its pin\nevent = \"stiction\"\nprobability_max = 1e-3\n",
            "",
        )
        .replace("verify = \"report\"", &format!("verify = \"{verify}\""));
    let path = dir.join(format!("normal-hardness-{verify}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

/// With the hardness normal, ln ψ is no longer linear in the standard
/// variables and FORM's design is unconservative: the exact P(ψ > 1) there
/// (quadrature) is above 1e-3, sampling finds it inside its interval, and the
/// status says so (exit 1). `verify = "correct"` moves the target until the
/// sampled probability meets it.
#[test]
fn sampling_flags_a_form_design_that_is_unconservative_and_correct_mends_it() {
    let dir = scratch("normal-hardness");
    let path = normal_hardness_study(&dir, "report");
    let doc = json_of(&["optimize", path.to_str().unwrap(), "--format", "json"], 1);
    let r = &doc["robust"];
    assert_eq!(r["status"], "chance_constraint_violated", "{r}");
    let c = &r["chance_constraints"][0];
    assert_eq!(c["violated"], true);
    let exact = plastic_probability(num(&r["evaluation"]["indices"]["plasticity_index"]));
    assert!(exact > 1.02e-3, "exact P(ψ > 1) = {exact}");
    let [lo, hi] = [
        num(&c["probability_interval"][0]),
        num(&c["probability_interval"][1]),
    ];
    assert!(
        lo <= exact && exact <= hi,
        "exact {exact} outside [{lo}, {hi}]"
    );
    assert!((num(&c["excess"]) - (num(&c["probability"]) / 1e-3 - 1.0)).abs() < 1e-12);

    let path = normal_hardness_study(&dir, "correct");
    let doc = json_of(&["optimize", path.to_str().unwrap(), "--format", "json"], 0);
    let r = &doc["robust"];
    assert_eq!(r["status"], "optimal", "{r}");
    let c = &r["chance_constraints"][0];
    assert!(num(&r["corrections"]) >= 1.0);
    assert!(num(&c["corrected_target"]) < 1e-3, "{c}");
    // Met to the sampling's precision (±4 %): the exact probability at the
    // corrected design lies in the sampled interval, whose lower end is at or
    // below the target.
    let exact = plastic_probability(num(&r["evaluation"]["indices"]["plasticity_index"]));
    let [lo, hi] = [
        num(&c["probability_interval"][0]),
        num(&c["probability_interval"][1]),
    ];
    assert!(
        lo <= 1e-3 && lo <= exact && exact <= hi,
        "corrected: exact {exact}, {c}"
    );
    assert!(exact < 1.05e-3, "corrected: exact {exact}");
}

/// The text report words both designs and every verdict.
#[test]
fn the_text_report_puts_the_robust_optimum_beside_the_nominal_one() {
    let dir = scratch("text");
    let path = dir.join("no-statistic.toml");
    std::fs::write(
        &path,
        std::fs::read_to_string(SHIPPED)
            .unwrap()
            .replace("statistic = \"p95\"", "")
            .replace("samples = 256", "")
            // One start: the report's words, not the optimum, are checked here.
            .replace("starts = 4", "starts = 1"),
    )
    .unwrap();
    let out = String::from_utf8(common::stdout(
        wearopt().args(["optimize", path.to_str().unwrap()]),
        0,
    ))
    .unwrap();
    for want in [
        "Robust optimum — status: optimal",
        "robust  nominal optimum         baseline",
        "mean of wear_rate",
        "P(plasticity_index > 1) ≤",
        "at the nominal optimum: P(plasticity_index > 1) = 0.",
        "The nominal optimum (every input at its nominal value)",
    ] {
        assert!(out.contains(want), "missing {want:?} in\n{out}");
    }
}

/// Bad input exits 2 and names the field and what it accepts.
#[test]
fn bad_robust_input_names_the_field() {
    let dir = scratch("bad-input");
    let base = std::fs::read_to_string(SHIPPED).unwrap();
    let cases: [(&str, String, &str); 6] = [
        (
            "statistic without inputs",
            {
                let (head, tail) = base.split_at(base.find("[uncertainty]").unwrap());
                format!("{head}{}", &tail[tail.find("[optimizer]").unwrap()..])
            },
            "objective.statistic",
        ),
        (
            "probability_max out of range",
            base.replacen("probability_max = 1e-3", "probability_max = 0.7", 1),
            "constraint[0].probability_max",
        ),
        (
            "unknown event",
            base.replace("event = \"stiction\"", "event = \"sticktion\""),
            "constraint[1].event",
        ),
        (
            "a quantity without a threshold",
            base.replace(
                "event = { quantity = \"plasticity_index\", above = 1.0 }",
                "event = { quantity = \"plasticity_index\" }",
            ),
            "constraint[0].event",
        ),
        (
            "verify other than report or correct",
            base.replace("verify = \"report\"", "verify = \"fix\""),
            "uncertainty.verify",
        ),
        (
            "unknown statistic",
            base.replace("statistic = \"p95\"", "statistic = \"p90\""),
            "objective.statistic",
        ),
    ];
    for (what, text, field) in cases {
        let path = dir.join("bad.toml");
        std::fs::write(&path, text).unwrap();
        let err = String::from_utf8(common::stderr(
            wearopt().args(["optimize", path.to_str().unwrap()]),
            2,
        ))
        .unwrap();
        assert!(err.contains(field), "{what}: {err}");
    }
}

/// The p95 of the shipped study at its robust design against a check of 2²⁰
/// scrambled points of another seed (the 10⁶-sample check): inside the
/// interval the report states for it.
#[test]
#[ignore = "2^20 evaluations of the hub: cargo test --release --test all -- --ignored robust_design::p95_campaign"]
fn p95_campaign() {
    use wearopt::app::optimize::{optimize, OptimizeDocument};
    use wearopt::app::robust::RobustProgram;
    use wearopt::uq::robust::{common_points, estimate, Statistic, UncertainProgram};
    let problem = wearopt::problem::load(std::path::Path::new(SHIPPED)).unwrap();
    let doc = optimize(&problem, SHIPPED, Default::default()).unwrap();
    let OptimizeDocument::Optimum { robust, .. } = doc else {
        panic!("an optimum")
    };
    let r = robust.expect("a robust study");
    let program = RobustProgram::new(&problem).unwrap();
    let d = &r.result.design;
    let model = program.inputs(d);
    let points = common_points(model.dim(), 1 << 20, 12345);
    let values: Vec<f64> = {
        use rayon::prelude::*;
        points
            .par_iter()
            .filter_map(|u| {
                program
                    .outputs(d, &model.to_physical(u))
                    .map(|o| o.objective)
            })
            .collect()
    };
    let check = estimate(&values, Statistic::P95);
    let stated = r.robust_sample.statistic;
    eprintln!("p95 {stated:?}; 2^20-point check {check:?}");
    assert!(
        stated.interval[0] <= check.value && check.value <= stated.interval[1],
        "check {} outside the stated [{}, {}]",
        check.value,
        stated.interval[0],
        stated.interval[1]
    );
}

/// `sweep` keeps its columns nominal beside the feasible_probability ones and
/// says so for a robust file (`pareto` is robust against an adhesion measure
/// too: tests/all/robust_pareto.rs).
#[test]
fn sweep_says_its_columns_are_nominal() {
    // The shipped study has a p95 objective: the sweep says its columns are
    // nominal beside the feasible_probability ones.
    let err = String::from_utf8(common::stderr(
        wearopt().args(["sweep", SHIPPED, "--samples", "2", "--format", "json"]),
        0,
    ))
    .unwrap();
    assert!(
        err.contains("this sweep's columns are at the nominal inputs, beside one feasible_probability column per chance constraint"),
        "{err}"
    );
    let err = String::from_utf8(common::stderr(
        wearopt().args([
            "sweep",
            "tests/data/micro-gear-study-jkr.toml",
            "--samples",
            "2",
        ]),
        0,
    ))
    .unwrap();
    assert!(!err.contains("note:"), "{err}");
}
