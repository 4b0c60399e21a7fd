//! Contracts of issue 10 that hold for any seed and any thread count:
//!
//! * with the default 8 starts and any `seed`, five-variable studies reach the
//!   global optimum to 1e-6 relative (micro-gear-study, the wide latch and the
//!   NEMS switch, whose starts alone miss it from some seeds);
//! * `optimize` and `pareto` give the same JSON on 1 and 2 threads (wall times
//!   aside) on the regression studies `tests/data/study_*.toml`;
//! * the false-infeasible study exits 0 through the CLI with any number of starts.

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use wearopt::optimize::{optimize, OptimizationStatus, OptimizerSettings, Study};
use wearopt::problem::Problem;

fn path(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn load(rel: &str) -> Problem {
    wearopt::problem::load(&path(rel)).expect("study loads")
}

fn run(p: &Problem, starts: usize, seed: u64) -> (f64, OptimizationStatus) {
    let settings = OptimizerSettings {
        starts,
        seed,
        ..p.study.optimizer
    };
    let o = optimize(&Study {
        scene: &p.scene,
        design: &p.study.design,
        objective: p.study.objective,
        constraints: &p.study.constraints,
        settings: &settings,
    })
    .expect("study runs");
    (o.objective, o.status)
}

/// The least wear rate (m³/m) of `tests/data/micro-gear-study-jkr.toml` (five
/// variables: E, H, γ, σ, R). Provenance: a 256-start run with seed 7 of
/// this solver (`many_start_references` below); every seed 1..=6 with 8 starts
/// lands within 5e-12 of it.
const MICRO_GEAR_STUDY_OPTIMUM: f64 = 6.512141158210e-18;

/// The least wear rate (m³/m) of the five-variable latch study
/// `tests/data/study_wide_latch.toml` (H, γ, σ, R, N; ψ ≤ 1, ≥ 20 contacts)
/// without an adhesion target: σ at its 0.5 nm bound, H = 4.80 GPa, ψ = 1 and
/// 20 contacts. Provenance: a 256-start run with seed 7
/// (`many_start_references`), in which 11 of the 256 starts reach it; the
/// other local optimum, 9.005e-18 (H at its 10 GPa bound, σ = 2.17 nm), is
/// where all 8 starts of seeds 1..=6 end: the vertex search (second phase of
/// the multistart) reaches the global optimum along the edge ψ = 1,
/// count = 20 that H leaves its bound by. The Pareto floor point of the same
/// study reaches 8.048e-18 through its neighbours' designs.
const WIDE_LATCH_OPTIMUM: f64 = 8.048207767094e-18;

/// The least wear rate (m³/m) of `tests/data/study_nems_switch.toml` (H, γ,
/// σ, R, N; ψ ≤ 1.5, ≥ 50 contacts under 20 µN). Provenance: 256-start runs
/// of this solver with seeds 7 and 11 (`many_start_references`) end at
/// 5.856370572567e-18 and 5.856370576449e-18, reached by 28 resp. 34 of the
/// 256 starts; the other starts end in local optima at 6.090e-18, 6.091e-18
/// and 6.18–6.19e-18. With 8 starts, seeds 1, 3 and 5 have no start reaching
/// it: the vertex search does.
const NEMS_SWITCH_OPTIMUM: f64 = 5.856370572567e-18;

fn assert_global_for_seeds(rel: &str, optimum: f64, seeds: std::ops::RangeInclusive<u64>) {
    let p = load(rel);
    for seed in seeds {
        let (f, status) = run(&p, 8, seed);
        assert_eq!(status, OptimizationStatus::Optimal, "{rel}, seed {seed}");
        assert!(
            (f / optimum - 1.0).abs() <= 1e-6,
            "{rel}, seed {seed}: {f:e} against the global optimum {optimum:e}"
        );
    }
}

#[test]
fn micro_gear_study_reaches_the_global_optimum_with_any_seed() {
    assert_global_for_seeds(
        "tests/data/micro-gear-study-jkr.toml",
        MICRO_GEAR_STUDY_OPTIMUM,
        1..=6,
    );
}

/// Every seed's 8 starts end in the 9.005e-18 local optimum; the vertex
/// search must find the global one from there.
#[test]
fn latch_study_reaches_the_global_optimum_with_any_seed() {
    assert_global_for_seeds(
        "tests/data/study_wide_latch.toml",
        WIDE_LATCH_OPTIMUM,
        1..=6,
    );
}

/// Four local optima; seeds 1, 3 and 5 need the vertex search.
#[test]
fn nems_switch_study_reaches_the_global_optimum_with_any_seed() {
    assert_global_for_seeds(
        "tests/data/study_nems_switch.toml",
        NEMS_SWITCH_OPTIMUM,
        1..=6,
    );
}

/// The same contracts over more seeds.
#[test]
#[ignore = "32 seeds of three studies; run with `cargo test --test all optimize_contracts::more_seeds -- --ignored`"]
fn more_seeds_reach_the_global_optimum() {
    assert_global_for_seeds(
        "tests/data/micro-gear-study-jkr.toml",
        MICRO_GEAR_STUDY_OPTIMUM,
        1..=32,
    );
    assert_global_for_seeds(
        "tests/data/study_wide_latch.toml",
        WIDE_LATCH_OPTIMUM,
        1..=32,
    );
    assert_global_for_seeds(
        "tests/data/study_nems_switch.toml",
        NEMS_SWITCH_OPTIMUM,
        1..=32,
    );
}

/// Recomputes the references above with 256 starts (slow in a debug build).
#[test]
#[ignore = "256-start reference runs (about 15 s); run with `cargo test --test all optimize_contracts::many_start -- --ignored`"]
fn many_start_references() {
    for (rel, reference, seeds) in [
        (
            "tests/data/micro-gear-study-jkr.toml",
            MICRO_GEAR_STUDY_OPTIMUM,
            &[7][..],
        ),
        ("tests/data/study_wide_latch.toml", WIDE_LATCH_OPTIMUM, &[7]),
        (
            "tests/data/study_nems_switch.toml",
            NEMS_SWITCH_OPTIMUM,
            &[7, 11],
        ),
    ] {
        for &seed in seeds {
            let (f, status) = run(&load(rel), 256, seed);
            assert_eq!(status, OptimizationStatus::Optimal, "{rel}");
            assert!((f / reference - 1.0).abs() <= 1e-6, "{rel}: {f:.12e}");
        }
    }
}

/// The vertex search says what it did, and costs no solve where it cannot
/// help: on micro-gear-study (every start reaches the optimum, no edge end
/// looks better) it follows edges and starts no solve; on the wide latch the
/// design reported comes from its solve (no start reaches it: see
/// WIDE_LATCH_OPTIMUM), and the JSON says so in `starts`.
#[test]
fn the_vertex_search_is_counted_and_reported() {
    let gear = path("tests/data/micro-gear-study-jkr.toml");
    let v = json_on(1, &["optimize", "--format", "json", gear.to_str().unwrap()]);
    let starts = &v["starts"];
    assert!(starts["edges"].as_u64().unwrap() >= 1, "{starts}");
    assert_eq!(starts["vertex_starts"], 0, "{starts}");
    assert_eq!(starts["vertex_reached_best"], 0, "{starts}");

    let latch = path("tests/data/study_wide_latch.toml");
    let v = json_on(
        1,
        &["optimize", "--format", "json", latch.to_str().unwrap()],
    );
    let starts = &v["starts"];
    let total = starts["total"].as_u64().unwrap();
    assert_eq!(starts["reached_best"], 0, "{starts}");
    assert!(starts["vertex_starts"].as_u64().unwrap() >= 1, "{starts}");
    assert!(
        starts["vertex_reached_best"].as_u64().unwrap() >= 1,
        "{starts}"
    );
    assert!(
        v["best_start"].as_u64().unwrap() >= total,
        "{}",
        v["best_start"]
    );
    assert!((v["objective"].as_f64().unwrap() / WIDE_LATCH_OPTIMUM - 1.0).abs() <= 1e-6);
}

/// JSON of a CLI run on `threads` rayon threads, without its wall times.
fn json_on(threads: usize, args: &[&str]) -> serde_json::Value {
    let out = Command::cargo_bin("wearopt")
        .unwrap()
        .env("RAYON_NUM_THREADS", threads.to_string())
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON output");
    strip_times(&mut v);
    v
}

fn strip_times(v: &mut serde_json::Value) {
    match v {
        serde_json::Value::Object(m) => {
            m.retain(|k, _| !k.starts_with("time"));
            m.values_mut().for_each(strip_times);
        }
        serde_json::Value::Array(a) => a.iter_mut().for_each(strip_times),
        _ => {}
    }
}

#[test]
fn optimize_json_is_the_same_on_one_and_two_threads() {
    for name in [
        "study_crawl.toml",
        "study_false_infeasible.toml",
        "study_tensile.toml",
        "study_wide_latch.toml",
        "study_nems_switch.toml",
    ] {
        let file = path(&format!("tests/data/{name}"));
        let file = file.to_str().unwrap();
        let args = ["optimize", "--format", "json", file];
        assert_eq!(json_on(1, &args), json_on(2, &args), "{name}");
    }
}

#[test]
fn pareto_json_is_the_same_on_one_and_two_threads() {
    let file = path("tests/data/study_wide_latch.toml");
    let args = ["pareto", "--format", "json", file.to_str().unwrap()];
    assert_eq!(json_on(1, &args), json_on(2, &args));
}

/// study_false_infeasible.toml through the CLI with 1 to 16 starts: a feasible
/// study exits 0 whatever the number of starts.
#[test]
fn false_infeasible_study_exits_0_with_any_number_of_starts() {
    let text = std::fs::read_to_string(path("tests/data/study_false_infeasible.toml")).unwrap();
    let dir = std::env::temp_dir().join(format!("wearopt-starts-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for starts in [1, 2, 3, 5, 8, 16] {
        let file = dir.join(format!("starts-{starts}.toml"));
        std::fs::write(
            &file,
            text.replace("starts = 1", &format!("starts = {starts}")),
        )
        .unwrap();
        let out = Command::cargo_bin("wearopt")
            .unwrap()
            .arg("optimize")
            .arg(&file)
            .output()
            .unwrap();
        assert_eq!(
            out.status.code(),
            Some(0),
            "starts = {starts}: {}",
            String::from_utf8_lossy(&out.stdout)
        );
    }
}
