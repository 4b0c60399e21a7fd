//! `wearopt sweep` and `wearopt merge` end to end: sharding (by flag and by Slurm
//! variables) joins into the unsharded output byte for byte, reruns resume,
//! output does not depend on the thread count, and bad input is refused.

use crate::common;

use std::path::{Path, PathBuf};

use assert_cmd::Command;

use wearopt::model::{evaluate, EvaluationOptions};
use wearopt::optimize::DesignSpace;
use wearopt::sweep::{Method, Sweep};

const STUDY: &str = "tests/data/micro-gear-study-jkr.toml";

fn wearopt() -> Command {
    let mut c = Command::cargo_bin("wearopt").expect("binary builds");
    for v in [
        "SLURM_ARRAY_TASK_ID",
        "SLURM_ARRAY_TASK_COUNT",
        "SLURM_ARRAY_TASK_MIN",
        "SLURM_ARRAY_TASK_STEP",
    ] {
        c.env_remove(v);
    }
    c
}

fn sweep_out(args: &[&str]) -> Vec<u8> {
    wearopt()
        .arg("sweep")
        .arg(STUDY)
        .args(args)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone()
}

/// Asserts exit code 2 and that stderr contains `needle`.
fn fails_with(assert: assert_cmd::assert::Assert, needle: &str) {
    let out = assert.code(2).get_output().stderr.clone();
    let text = String::from_utf8_lossy(&out);
    assert!(text.contains(needle), "stderr {text:?} lacks {needle:?}");
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("wearopt-sweep-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn merge(parts: &[PathBuf], extra: &[&str]) -> Vec<u8> {
    wearopt()
        .arg("merge")
        .args(parts)
        .args(extra)
        .assert()
        .success()
        .get_output()
        .stdout
        .clone()
}

#[test]
fn sharded_union_equals_unsharded() {
    let samples = "20";
    for (method, format) in [
        ("sobol", "csv"),
        ("lhs", "json"),
        ("sobol", "json"),
        ("lhs", "csv"),
    ] {
        let whole = sweep_out(&[
            "--samples",
            samples,
            "--method",
            method,
            "--format",
            format,
            "--seed",
            "3",
        ]);
        for n in [1usize, 2, 3, 7, 20, 33] {
            let dir = scratch(&format!("{method}-{format}-{n}"));
            // Parts given to merge in reverse order: merge sorts them itself.
            let parts: Vec<PathBuf> = (0..n)
                .rev()
                .map(|i| {
                    let path = dir.join(format!("part-{i}.{format}"));
                    let shard = format!("{i}/{n}");
                    let out = sweep_out(&[
                        "--samples",
                        samples,
                        "--method",
                        method,
                        "--format",
                        format,
                        "--seed",
                        "3",
                        "--shard",
                        &shard,
                    ]);
                    std::fs::write(&path, out).unwrap();
                    path
                })
                .collect();
            let merged = merge(&parts, &["--samples", samples]);
            assert_eq!(
                String::from_utf8_lossy(&merged),
                String::from_utf8_lossy(&whole),
                "{method} {format} in {n} shards"
            );
        }
    }
}

#[test]
fn grid_shards_join_too() {
    // 5 design variables, 2 levels each: the 32 corners of the box.
    let whole = sweep_out(&["--samples", "32", "--method", "grid"]);
    let dir = scratch("grid");
    let parts: Vec<PathBuf> = (0..5)
        .map(|i| {
            let path = dir.join(format!("g{i}.csv"));
            std::fs::write(
                &path,
                sweep_out(&[
                    "--samples",
                    "32",
                    "--method",
                    "grid",
                    "--shard",
                    &format!("{i}/5"),
                ]),
            )
            .unwrap();
            path
        })
        .collect();
    assert_eq!(merge(&parts, &[]), whole);
}

#[test]
fn slurm_variables_choose_the_shard() {
    let by_flag = sweep_out(&["--samples", "12", "--shard", "2/3"]);
    for (id, min) in [("2", None), ("2", Some("0")), ("7", Some("5"))] {
        let mut c = wearopt();
        c.args(["sweep", STUDY, "--samples", "12"])
            .env("SLURM_ARRAY_TASK_ID", id)
            .env("SLURM_ARRAY_TASK_COUNT", "3");
        if let Some(m) = min {
            c.env("SLURM_ARRAY_TASK_MIN", m);
        }
        let out = c.assert().success().get_output().stdout.clone();
        assert_eq!(out, by_flag, "ID {id} MIN {min:?}");
    }
    // --shard wins over the variables.
    let out = wearopt()
        .args(["sweep", STUDY, "--samples", "12", "--shard", "2/3"])
        .env("SLURM_ARRAY_TASK_ID", "0")
        .env("SLURM_ARRAY_TASK_COUNT", "3")
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    assert_eq!(out, by_flag);
    // A task id outside the array is refused.
    fails_with(
        wearopt()
            .args(["sweep", STUDY, "--samples", "12"])
            .env("SLURM_ARRAY_TASK_ID", "3")
            .env("SLURM_ARRAY_TASK_COUNT", "3")
            .assert(),
        "SLURM_ARRAY_TASK_ID=3",
    );
}

#[test]
fn rerun_skips_a_complete_shard_and_redoes_a_partial_one() {
    let dir = scratch("resume");
    let path = dir.join("part.json");
    let run = || {
        wearopt()
            .args([
                "sweep",
                STUDY,
                "--samples",
                "9",
                "--shard",
                "1/2",
                "--format",
                "json",
                "--out",
            ])
            .arg(&path)
            .assert()
            .success()
            .get_output()
            .stderr
            .clone()
    };
    let stderr = run();
    assert!(!String::from_utf8_lossy(&stderr).contains("skipped"));
    let complete = std::fs::read(&path).unwrap();
    assert_eq!(
        complete,
        sweep_out(&["--samples", "9", "--shard", "1/2", "--format", "json"])
    );
    let stderr = run();
    assert!(String::from_utf8_lossy(&stderr).contains("complete (rows 4..9 of 9): skipped"));
    assert_eq!(std::fs::read(&path).unwrap(), complete);
    // Cut off mid-way (as a killed job leaves it): redone in full.
    std::fs::write(&path, &complete[..complete.len() * 2 / 3]).unwrap();
    let stderr = run();
    assert!(!String::from_utf8_lossy(&stderr).contains("skipped"));
    assert_eq!(std::fs::read(&path).unwrap(), complete);
    // A file of another sweep (other seed) at the same path is not taken for this one.
    wearopt()
        .args([
            "sweep",
            STUDY,
            "--samples",
            "9",
            "--shard",
            "1/2",
            "--format",
            "json",
            "--seed",
            "5",
            "--out",
        ])
        .arg(&path)
        .assert()
        .success();
    assert_ne!(std::fs::read(&path).unwrap(), complete);
}

#[test]
fn csv_completeness_is_read_from_the_rows() {
    let dir = scratch("csv-resume");
    let path = dir.join("p.csv");
    let run = || {
        wearopt()
            .args(["sweep", STUDY, "--samples", "10", "--shard", "0/2", "--out"])
            .arg(&path)
            .assert()
            .success()
            .get_output()
            .stderr
            .clone()
    };
    run();
    let complete = std::fs::read_to_string(&path).unwrap();
    assert_eq!(
        complete.lines().count(),
        7,
        "fingerprint, header and rows 0..5, nothing else"
    );
    // Drop the last row: the file still parses, but misses row 4.
    let cut: String = complete.lines().take(6).map(|l| format!("{l}\n")).collect();
    std::fs::write(&path, cut).unwrap();
    assert!(!String::from_utf8_lossy(&run()).contains("skipped"));
    assert_eq!(std::fs::read_to_string(&path).unwrap(), complete);
    assert!(String::from_utf8_lossy(&run()).contains("skipped"));
}

#[test]
fn output_does_not_depend_on_threads() {
    let run = |threads: &str| {
        wearopt()
            .args(["sweep", STUDY, "--samples", "1500", "--method", "lhs"])
            .env("RAYON_NUM_THREADS", threads)
            .assert()
            .success()
            .get_output()
            .stdout
            .clone()
    };
    assert_eq!(run("1"), run("2"));
    assert_eq!(run("1"), run("3"));
}

#[test]
fn rows_are_the_model_at_designs_inside_the_box() {
    let problem = wearopt::problem::load(Path::new(STUDY)).unwrap();
    let s = &problem.study;
    let n = 64;
    let sweep = Sweep::new(
        &problem.scene,
        &s.design,
        &s.constraints,
        Method::Lhs,
        n,
        11,
    )
    .unwrap();
    let space = DesignSpace::new(&problem.scene, &s.design);
    let mut strata = vec![vec![false; n as usize]; s.design.len()];
    for i in 0..n {
        let row = sweep.row(i);
        let x = sweep.unit_point(i);
        // The row is the model at its design, exactly.
        let ev = evaluate(&space.scene_at(&x), &EvaluationOptions::default());
        assert_eq!(row.wear_rate, ev.wear_rate);
        assert_eq!(row.real_area, ev.real_area);
        assert_eq!(row.pull_off_force, ev.pull_off_force);
        // Inside the box, and in log space one design per stratum of every variable.
        for (d, (v, var)) in row.design.iter().zip(&s.design).enumerate() {
            assert!(
                *v >= var.min && *v <= var.max,
                "{v} outside [{}, {}]",
                var.min,
                var.max
            );
            let u = (v / var.min).ln() / (var.max / var.min).ln();
            let j = ((u * n as f64) as usize).min(n as usize - 1);
            assert!(!strata[d][j], "variable {d}: stratum {j} twice");
            strata[d][j] = true;
        }
        // Feasible exactly when every constraint holds.
        let holds = s.constraints.iter().all(|c| {
            let v =
                wearopt::optimize::functions::quantity_value(c.quantity, &ev, &space.scene_at(&x));
            v.is_some_and(|v| {
                c.min.is_none_or(|m| v >= m * (1.0 - 1e-9))
                    && c.max.is_none_or(|m| v <= m * (1.0 + 1e-9))
            })
        });
        assert_eq!(row.feasible, holds, "row {i}");
    }
}

#[test]
fn the_map_marks_the_pareto_optimal_designs() {
    let dir = scratch("map");
    let plot = dir.join("map.svg");
    wearopt()
        .args(["sweep", STUDY, "--samples", "256", "--plot"])
        .arg(&plot)
        .assert()
        .success();
    let svg = std::fs::read_to_string(&plot).unwrap();
    common::parse_xml(&svg).expect("well-formed SVG");
    for text in [
        "feasible (",
        "infeasible (",
        "Pareto-optimal (",
        "wear rate",
        "pull-off force",
    ] {
        assert!(svg.contains(text), "missing {text}");
    }
}

#[test]
fn bad_input_is_refused_with_the_value_and_the_range() {
    let cases: &[(&[&str], &str)] = &[
        (
            &["--samples", "0"],
            "--samples 0: 0 samples: must lie in 1..=4294967296",
        ),
        (&["--samples", "10", "--method", "grid"], "must be m^5"),
        (
            &["--samples", "10", "--shard", "3/3"],
            "--shard 3/3: expected I/N",
        ),
        (&["--samples", "10", "--shard", "x"], "--shard x"),
    ];
    for (args, message) in cases {
        fails_with(
            wearopt().arg("sweep").arg(STUDY).args(*args).assert(),
            message,
        );
    }
    fails_with(
        wearopt()
            .args(["sweep", "problems/dlc-contact.toml", "--samples", "10"])
            .assert(),
        "no [design] variables",
    );
    fails_with(
        wearopt()
            .args(["sweep", "problems/materials-study.toml", "--samples", "10"])
            .assert(),
        "materials",
    );
}

#[test]
fn merge_refuses_gaps_overlaps_and_strangers() {
    let dir = scratch("merge-bad");
    let part = |i: usize, n: usize, seed: &str| {
        let path = dir.join(format!("p{i}-{n}-{seed}.csv"));
        std::fs::write(
            &path,
            sweep_out(&[
                "--samples",
                "9",
                "--shard",
                &format!("{i}/{n}"),
                "--seed",
                seed,
            ]),
        )
        .unwrap();
        path
    };
    let (a, b, c) = (part(0, 3, "0"), part(1, 3, "0"), part(2, 3, "0"));
    let bad = |parts: &[&PathBuf], extra: &[&str], message: &str| {
        fails_with(
            wearopt().arg("merge").args(parts).args(extra).assert(),
            message,
        );
    };
    bad(&[&a, &c], &[], "rows 3..6 are missing");
    bad(&[&a, &b, &b, &c], &[], "appears twice");
    bad(&[&a, &b], &["--samples", "9"], "rows 6..9 are missing");
    // Different seeds make different sweeps; JSON and CSV do not mix.
    let other = part(2, 3, "1");
    let _ = other;
    let json = dir.join("j.json");
    std::fs::write(
        &json,
        sweep_out(&["--samples", "9", "--shard", "2/3", "--format", "json"]),
    )
    .unwrap();
    bad(&[&a, &b, &json], &[], "differs from the first part");
    let junk = dir.join("junk.csv");
    std::fs::write(&junk, "a,b\n1,2\n").unwrap();
    bad(&[&junk], &[], "junk.csv: not the output of `wearopt sweep`");
    // A JSON part cut short is incomplete.
    let text = std::fs::read_to_string(&json).unwrap();
    std::fs::write(&json, &text[..text.len() - 3]).unwrap();
    bad(&[&json], &[], "incomplete");
}

/// Every output begins with its fingerprint. A rerun after editing the problem,
/// or with another seed, recomputes the part instead of keeping the old rows
/// ("complete … skipped"); merge refuses parts of different sweeps and, without
/// --samples, a CSV part cut short on a row boundary (its shard's rows are known
/// from N and I/N in its head); an explicit --shard wins over Slurm's variables,
/// so a resubmitted array task computes its own rows.
#[test]
fn fingerprints_keep_sweeps_apart() {
    let dir = scratch("fingerprint");
    let study = dir.join("study.toml");
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(STUDY)).unwrap();
    std::fs::write(&study, &text).unwrap();
    let part = |i: u64, seed: &str| {
        let path = dir.join(format!("part-{i}-{seed}.csv"));
        let err = wearopt()
            .args([
                "sweep",
                study.to_str().unwrap(),
                "--samples",
                "12",
                "--seed",
                seed,
            ])
            .args(["--shard", &format!("{i}/3"), "--out"])
            .arg(&path)
            .assert()
            .success()
            .get_output()
            .stderr
            .clone();
        (path, String::from_utf8(err).unwrap())
    };
    let (p0, _) = part(0, "1");
    let first = std::fs::read_to_string(&p0).unwrap();
    assert!(first.starts_with("# wearopt sweep fingerprint="), "{first}");
    assert!(first
        .lines()
        .next()
        .unwrap()
        .contains(" shard=0/3 samples=12 method=sobol seed=1 "));
    // The same run again: kept.
    assert!(part(0, "1").1.contains("skipped"));
    // The problem edited (a comment is content too): recomputed, a new fingerprint.
    std::fs::write(&study, format!("{text}\n# edited\n")).unwrap();
    assert!(!part(0, "1").1.contains("skipped"));
    let edited = std::fs::read_to_string(&p0).unwrap();
    assert_ne!(edited.lines().next(), first.lines().next());
    // Parts of two sweeps (another seed) are refused by merge.
    let (p1, _) = part(1, "1");
    let (p2_other, _) = part(2, "2");
    let out = wearopt()
        .arg("merge")
        .args([&p0, &p1, &p2_other])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("parts of different sweeps"));
    // A part cut short on a row boundary is found from N alone.
    let (p2, _) = part(2, "1");
    let whole = std::fs::read_to_string(&p1).unwrap();
    let cut: String = whole
        .lines()
        .take(whole.lines().count() - 1)
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(&p1, cut).unwrap();
    let out = wearopt()
        .arg("merge")
        .args([&p0, &p1, &p2])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("shard 1/3 of 12 designs, rows 4..8, but holds rows 4..7"),
        "{err}"
    );
    // --shard over Slurm's variables (a rerun of task 2 in an array of 1).
    let path = dir.join("slurm.csv");
    wearopt()
        .env("SLURM_ARRAY_TASK_ID", "2")
        .env("SLURM_ARRAY_TASK_COUNT", "1")
        .env("SLURM_ARRAY_TASK_MIN", "2")
        .args([
            "sweep",
            study.to_str().unwrap(),
            "--samples",
            "12",
            "--seed",
            "1",
            "--shard",
            "2/3",
            "--out",
        ])
        .arg(&path)
        .assert()
        .success();
    assert_eq!(std::fs::read(&path).unwrap(), std::fs::read(&p2).unwrap());
}

/// Issue 21, item 6: a sweep once wrote 9 215 of 50 630 `ok` rows with an empty
/// pull-off and no reason. On the five-variable latch that report came from
/// (E, H, γ, σ, R over wide boxes; H/E ≤ 0.1, ψ ≤ 1; 10 µN on 100 µm²), under
/// each asperity law and across a humidity range (2 048 designs; the same study
/// at 50 630 designs per law, and 8 192 humid, gave none either), every `ok`
/// row carries a finite pull-off ≥ 0, and a positive one its log10.
#[test]
fn ok_rows_always_carry_a_pull_off() {
    let dir = scratch("pull-off");
    let laws = [
        ("jkr", ""),
        ("dmt", ""),
        ("lennard_jones", "interatomic_distance = \"0.3 nm\"\n"),
        (
            "dmt",
            "[environment]\nrelative_humidity = { min = 0.0, max = 0.9 }\nhumidity_points = 3\n",
        ),
    ];
    for (k, (law, extra)) in laws.iter().enumerate() {
        let (interface_extra, environment) = if extra.starts_with('[') {
            ("", *extra)
        } else {
            (*extra, "")
        };
        let text = format!(
            "name = \"five-variable latch\"\n\
             [contact]\nload = \"10 uN\"\nnominal_area = \"100 um^2\"\nsliding_distance = \"10 mm\"\nwear_coefficient = 1e-3\n\
             [bodies]\na = {{ youngs_modulus = \"79 GPa\", poisson_ratio = 0.42 }}\nb = {{ youngs_modulus = \"79 GPa\", poisson_ratio = 0.42 }}\n\
             [interface]\nhardness = \"1 GPa\"\nwork_of_adhesion = \"0.5 J/m^2\"\nadhesion_model = \"{law}\"\n{interface_extra}\
             [roughness]\nsigma = \"5 nm\"\nasperity_radius = \"1 um\"\nasperity_density = \"1 um^-2\"\n\
             {environment}\
             [design]\nyoungs_modulus = {{ min = \"10 GPa\", max = \"400 GPa\" }}\nhardness = {{ min = \"0.5 GPa\", max = \"30 GPa\" }}\n\
             work_of_adhesion = {{ min = \"1e-3 J/m^2\", max = \"2 J/m^2\" }}\nsigma = {{ min = \"0.3 nm\", max = \"100 nm\" }}\n\
             asperity_radius = {{ min = \"0.05 um\", max = \"50 um\" }}\n\
             [objective]\nminimize = \"wear_rate\"\n\
             [[constraint]]\nquantity = \"hardness_to_modulus\"\nmax = 0.1\n\
             [[constraint]]\nquantity = \"plasticity_index\"\nmax = 1\n"
        );
        let file = dir.join(format!("latch-{k}.toml"));
        std::fs::write(&file, text).unwrap();
        let out = wearopt()
            .arg("sweep")
            .arg(&file)
            .args(["--samples", "512"])
            .assert()
            .success()
            .get_output()
            .stdout
            .clone();
        let text = String::from_utf8(out).unwrap();
        let mut lines = text.lines().filter(|l| !l.starts_with('#'));
        let header: Vec<&str> = lines.next().unwrap().split(',').collect();
        let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
        let (status, pull_off, log10) = (
            col("status"),
            col("pull_off_force"),
            col("log10_pull_off_force"),
        );
        let mut ok = 0;
        for line in lines {
            let cells: Vec<&str> = line.split(',').collect();
            if cells[status] != "ok" {
                continue;
            }
            ok += 1;
            let f: f64 = cells[pull_off]
                .parse()
                .unwrap_or_else(|_| panic!("{law} {environment}: ok row without pull-off: {line}"));
            assert!(f.is_finite() && f >= 0.0, "{line}");
            if f > 0.0 {
                let l: f64 = cells[log10].parse().unwrap_or_else(|_| panic!("{line}"));
                assert!((l - f.log10()).abs() < 1e-9, "{line}");
            }
        }
        assert!(ok > 400, "{law}: only {ok} ok rows");
    }
}
