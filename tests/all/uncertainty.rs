//! `wearopt uncertainty` on problem files: `[uncertainty]` read and refused
//! precisely, known answers on a shipped scene, the JSON contract, determinism.

use wearopt::app::uncertainty::{uncertainty, Analysis, Method, UncertaintyOptions};
use wearopt::app::Quiet;
use wearopt::problem::parse;
use wearopt::uq::reliability::EventStatus;

use crate::common::{stderr, stdout, wearopt};

const SCATTER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/problems/micro-gear-scatter.toml"
);

/// The shipped hub's scene with an `[uncertainty]` section of our own.
fn hub_with(section: &str) -> String {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear.toml"
    ))
    .unwrap();
    // The scene alone (no study), then the section.
    let scene: String = text.split("\n[design]").next().unwrap().replace(
        "wear_area = \"total\"",
        "wear_area = \"total\"\nrestoring_force = \"20 uN\"\nallowed_wear_depth = \"0.5 um\"",
    );
    format!("{scene}\n{section}")
}

fn run(
    text: &str,
    method: Method,
    samples: Option<u64>,
) -> wearopt::app::uncertainty::UncertaintyDocument {
    let problem = parse(text, "test.toml").expect("a valid problem");
    uncertainty(
        &problem,
        "test.toml",
        &UncertaintyOptions {
            method,
            samples,
            seed: None,
        },
        &Quiet,
    )
    .expect("runs")
}

/// Φ(−2) (closed form: 0.5 erfc(√2), 20 digits from mpmath).
#[allow(clippy::excessive_precision)] // the digits as mpmath gives them
const PHI_MINUS_2: f64 = 0.022750131948179207200;

/// k alone, lognormal with a decade at two standard deviations (factor √10):
/// the wear rate is proportional to k, so P(wear rate > 10 × its median) is
/// P(Z > 2) = Φ(−2) exactly, and FORM on the log limit state is exact.
#[test]
fn wear_coefficient_alone_gives_phi_of_minus_two() {
    let median_rate = {
        let problem = parse(&hub_with(""), "hub.toml").unwrap();
        wearopt::app::eval::eval(&problem, "hub.toml", &Default::default())
            .unwrap()
            .evaluation
            .wear_rate
    };
    let text = hub_with(&format!(
        "[uncertainty]\n[uncertainty.inputs]\nwear_coefficient = {{ distribution = \"lognormal\", median = 1e-4, factor = {} }}\n[[uncertainty.event]]\nquantity = \"wear_rate\"\nabove = {}\n",
        10f64.sqrt(),
        10.0 * median_rate
    ));
    let doc = run(&text, Method::Reliability, None);
    let Analysis::Reliability(events) = &doc.analysis else {
        panic!("reliability")
    };
    let r = &events[0].1;
    let form = r.form.probability.unwrap();
    assert!((form / PHI_MINUS_2 - 1.0).abs() < 1e-8, "FORM {form}");
    assert!((r.form.beta.unwrap() - 2.0).abs() < 1e-8);
    // The sampled value within its interval of the truth, and within 3 %.
    let p = r.probability.unwrap();
    let iv = r.interval.unwrap();
    assert!(iv[0] <= PHI_MINUS_2 && PHI_MINUS_2 <= iv[1], "{p} {iv:?}");
    assert!((p / PHI_MINUS_2 - 1.0).abs() < 0.1, "{p}");
    assert!(matches!(r.status, EventStatus::Converged), "{:?}", r.status);
}

/// One input acting monotonically on an event: P(stiction) = 1 − F(γ*) where γ*
/// is the work of adhesion at which the pull-off equals the restoring force,
/// found by bisection on the evaluator.
#[test]
fn stiction_probability_is_the_tail_beyond_the_bisected_threshold() {
    use wearopt::model::{evaluate, EvaluationOptions};
    let base = parse(&hub_with(""), "hub.toml").unwrap();
    let restoring = base.scene.requirements.restoring_force.unwrap();
    let pull_off = |gamma: f64| {
        let mut s = base.scene.clone();
        s.work_of_adhesion = gamma;
        evaluate(&s, &EvaluationOptions::default())
            .pull_off_force
            .unwrap()
    };
    let (mut lo, mut hi) = (0.1f64, 1.0f64);
    assert!(pull_off(lo) < restoring && pull_off(hi) > restoring);
    for _ in 0..60 {
        let mid = (lo * hi).sqrt();
        if pull_off(mid) < restoring {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let gamma_star = (lo * hi).sqrt();
    // γ lognormal, median 0.1 J/m², factor 2: P(γ > γ*) = Φ(−ln(γ*/0.1)/ln 2).
    let z = (gamma_star / 0.1).ln() / 2f64.ln();
    let exact = wearopt::uq::distribution::std_normal_sf(z);
    let text = hub_with(
        "[uncertainty]\n[uncertainty.inputs]\nwork_of_adhesion = { distribution = \"lognormal\", median = \"0.1 J/m^2\", factor = 2 }\n[[uncertainty.event]]\nname = \"stiction\"\n",
    );
    let doc = run(&text, Method::Reliability, None);
    let Analysis::Reliability(events) = &doc.analysis else {
        panic!()
    };
    let r = &events[0].1;
    let form = r.form.probability.unwrap();
    assert!((form / exact - 1.0).abs() < 1e-4, "FORM {form} vs {exact}");
    let iv = r.interval.unwrap();
    assert!(iv[0] <= exact && exact <= iv[1], "{iv:?} vs {exact}");
}

/// The shipped study: sampling gives every statistic with an interval that
/// holds it, the life percentiles in order; the JSON carries the contract's keys.
#[test]
fn shipped_scatter_sampling_json_contract() {
    let out = stdout(
        wearopt().args([
            "uncertainty",
            SCATTER,
            "--method",
            "sampling",
            "--samples",
            "256",
            "--format",
            "json",
        ]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    for key in [
        "method",
        "samples",
        "seed",
        "fingerprint",
        "evaluations",
        "failed",
    ] {
        assert!(!v[key].is_null(), "{key}");
    }
    assert_eq!(v["samples"], 256);
    let outputs = v["outputs"].as_array().unwrap();
    assert_eq!(outputs.len(), 3);
    for o in outputs {
        for s in ["mean", "sd", "p1", "p5", "p50", "p95", "p99"] {
            let x = o[s].as_f64().unwrap();
            let iv = o[format!("{s}_interval")].as_array().unwrap();
            // null: the interval's end lies beyond the sample (p1 and p99 at N = 256).
            let a = iv[0].as_f64().unwrap_or(f64::NEG_INFINITY);
            let b = iv[1].as_f64().unwrap_or(f64::INFINITY);
            assert!(a <= x && x <= b, "{} {s}: {x} not in [{a}, {b}]", o["name"]);
            if !["p1", "p99"].contains(&s) {
                assert!(a.is_finite() && b.is_finite(), "{} {s}", o["name"]);
            }
        }
        let p: Vec<f64> = ["p1", "p5", "p50", "p95", "p99"]
            .iter()
            .map(|s| o[s].as_f64().unwrap())
            .collect();
        assert!(p.windows(2).all(|w| w[0] <= w[1]), "{p:?}");
    }
    let life = &v["life"];
    assert_eq!(life["quantity"], "life_cycles");
    assert!(life["b1"].as_f64().unwrap() <= life["b10"].as_f64().unwrap());
}

/// Sobol′ indices of the shipped study: the JSON's index objects, each with its
/// interval; k alone decides most of the wear rate's variance (it spans a decade),
/// and the load, the only input the pull-off does not see, has no share in it.
#[test]
fn shipped_scatter_sobol_indices() {
    let text = std::fs::read_to_string(SCATTER).unwrap();
    let doc = run(&text, Method::Sobol, Some(512));
    let Analysis::Sobol(results) = &doc.analysis else {
        panic!()
    };
    assert_eq!(doc.samples, 512);
    let names: Vec<&str> = doc.inputs.iter().map(|i| i.parameter.as_str()).collect();
    let k = names.iter().position(|&n| n == "wear_coefficient").unwrap();
    let load = names.iter().position(|&n| n == "load").unwrap();
    let wear = &results[0];
    assert!(wear.total[k].value > 0.5, "{:?}", wear.total[k]);
    let pull_off = &results[1];
    // The pull-off is a property of the surfaces: the load does not move it
    // (Jansen's ST is a mean of squares of differences at rounding: the searches
    // of a sample's points start from its point A's answers).
    assert!(
        pull_off.total[load].value.abs() <= 1e-25,
        "{:?}",
        pull_off.total[load]
    );
    let v = wearopt::report::uncertainty::json_value(&doc);
    let row = &v["indices"][0];
    for key in [
        "input",
        "output",
        "first_order",
        "first_order_interval",
        "total_order",
        "total_order_interval",
    ] {
        assert!(!row[key].is_null(), "{key}: {row}");
    }
}

/// The same numbers on one and two threads.
#[test]
fn identical_on_any_number_of_threads() {
    let text = std::fs::read_to_string(SCATTER).unwrap();
    let on = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| wearopt::report::uncertainty::json(&run(&text, Method::Sobol, Some(128))))
    };
    assert_eq!(on(1), on(2));
}

/// Bad `[uncertainty]` sections: exit code 2, the field and the accepted range named.
#[test]
fn bad_sections_are_refused_naming_the_field() {
    let cases: [(&str, &str); 12] = [
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"normal\", mean = \"3 nm\", sd = \"0 nm\" }\n",
            "uncertainty.inputs.sigma.sd",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"uniform\", min = \"3 nm\", max = \"2 nm\" }\n",
            "uncertainty.inputs.sigma.max",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 1 }\n",
            "uncertainty.inputs.sigma.factor",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"-3 nm\", factor = 2 }\n",
            "uncertainty.inputs.sigma.median",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"normal\", mean = \"3 nm\", sd = \"1 nm\" }\n",
            "lognormal",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\nasperity_radius = { distribution = \"lognormal\", median = \"1 um\", factor = 2 }\n[[uncertainty.correlation]]\nbetween = [\"sigma\", \"asperity_radius\"]\nrho = 1.0\n",
            "uncertainty.correlation.rho",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\n[[uncertainty.correlation]]\nbetween = [\"sigma\", \"load\"]\nrho = 0.5\n",
            "not an uncertain input",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigmaa = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\n",
            "did you mean `sigma`",
        ),
        (
            "[uncertainty]\noutputs = [\"wear_rat\"]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\n",
            "did you mean \"wear_rate\"",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\n[[uncertainty.event]]\nname = \"stick\"\n",
            "uncertainty.event.name",
        ),
        (
            "[uncertainty]\nsamples = 10\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\n",
            "uncertainty.samples",
        ),
        (
            "[uncertainty]\n[uncertainty.inputs]\nrelative_humidity = { distribution = \"uniform\", min = 0.2, max = 0.8 }\n",
            "[environment]",
        ),
    ];
    let dir = std::env::temp_dir().join("wearopt-uncertainty-bad");
    std::fs::create_dir_all(&dir).unwrap();
    for (k, (section, needle)) in cases.iter().enumerate() {
        let path = dir.join(format!("bad{k}.toml"));
        std::fs::write(&path, hub_with(section)).unwrap();
        let err = String::from_utf8(stderr(
            wearopt().args(["uncertainty", path.to_str().unwrap()]),
            2,
        ))
        .unwrap();
        assert!(err.contains(needle), "case {k}: {err}");
        assert!(err.contains(&format!("bad{k}.toml")), "case {k}: {err}");
    }
    // Four correlations that cannot hold together.
    let path = dir.join("not-pd.toml");
    std::fs::write(
        &path,
        hub_with("[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\nasperity_radius = { distribution = \"lognormal\", median = \"1 um\", factor = 2 }\nwork_of_adhesion = { distribution = \"lognormal\", median = \"0.1 J/m^2\", factor = 2 }\n[[uncertainty.correlation]]\nbetween = [\"sigma\", \"asperity_radius\"]\nrho = 0.9\n[[uncertainty.correlation]]\nbetween = [\"sigma\", \"work_of_adhesion\"]\nrho = 0.9\n[[uncertainty.correlation]]\nbetween = [\"asperity_radius\", \"work_of_adhesion\"]\nrho = -0.9\n"),
    )
    .unwrap();
    let err = String::from_utf8(stderr(
        wearopt().args(["uncertainty", path.to_str().unwrap()]),
        2,
    ))
    .unwrap();
    assert!(err.contains("positive definite"), "{err}");
    // No section at all; no event for reliability.
    let plain = concat!(env!("CARGO_MANIFEST_DIR"), "/problems/micro-gear.toml");
    let err = String::from_utf8(stderr(wearopt().args(["uncertainty", plain]), 2)).unwrap();
    assert!(err.contains("no [uncertainty] section"), "{err}");
    let path = dir.join("no-event.toml");
    std::fs::write(
        &path,
        hub_with("[uncertainty]\n[uncertainty.inputs]\nsigma = { distribution = \"lognormal\", median = \"3 nm\", factor = 2 }\n"),
    )
    .unwrap();
    let err = String::from_utf8(stderr(
        wearopt().args([
            "uncertainty",
            path.to_str().unwrap(),
            "--method",
            "reliability",
        ]),
        2,
    ))
    .unwrap();
    assert!(err.contains("needs an event"), "{err}");
}

/// Every format renders the shipped study; a non-power-of-two N is rounded up,
/// with a note.
#[test]
fn every_format_and_the_rounding_note() {
    for format in ["text", "json", "csv", "html"] {
        let out = stdout(
            wearopt().args([
                "uncertainty",
                SCATTER,
                "--samples",
                "100",
                "--format",
                format,
            ]),
            0,
        );
        let text = String::from_utf8(out).unwrap();
        assert!(
            !text.contains("NaN") && !text.contains("inf"),
            "{format}: {text}"
        );
        if format == "text" {
            assert!(
                text.contains("asked 100, rounded up to a power of two"),
                "{text}"
            );
            assert!(text.contains("N too small"), "{text}");
        }
    }
}

// ---------------------------------------------------------------- shards

/// A fresh directory for one test's parts.
fn part_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("wearopt-uq-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Writes the parts of `--shard i/3` (i = 0, 1, 2) of the shipped study; their paths.
fn three_parts(dir: &std::path::Path, method: &str, samples: &str) -> Vec<std::path::PathBuf> {
    (0..3)
        .map(|i| {
            let path = dir.join(format!("{method}-{i}.json"));
            stdout(
                wearopt().args([
                    "uncertainty",
                    SCATTER,
                    "--method",
                    method,
                    "--samples",
                    samples,
                    "--shard",
                    &format!("{i}/3"),
                    "--out",
                    path.to_str().unwrap(),
                ]),
                0,
            );
            path
        })
        .collect()
}

/// A rerun of a shard whose `--out` already holds that very part, whole, keeps it and
/// says so on stderr (as a sweep's rerun does); another seed (another fingerprint) or a
/// cut file is computed again.
#[test]
fn a_rerun_of_a_complete_shard_is_skipped() {
    let dir = part_dir("resume");
    let path = dir.join("part-1.json");
    let run = |seed: &str, code: i32| {
        let out = wearopt()
            .args([
                "uncertainty",
                SCATTER,
                "--method",
                "sampling",
                "--samples",
                "64",
            ])
            .args([
                "--seed",
                seed,
                "--shard",
                "1/3",
                "--out",
                path.to_str().unwrap(),
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(code), "{out:?}");
        String::from_utf8(out.stderr).unwrap()
    };
    assert!(!run("1", 0).contains("skipped"));
    let first = std::fs::read(&path).unwrap();
    // Mark the kept file: a skipped rerun leaves it as it is, byte for byte.
    let marked = format!("{}\n \n", String::from_utf8(first.clone()).unwrap());
    std::fs::write(&path, &marked).unwrap();
    let err = run("1", 0);
    assert!(err.contains("complete") && err.contains("skipped"), "{err}");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), marked);
    // Another seed is another study: computed and written anew.
    assert!(!run("2", 0).contains("skipped"));
    assert_ne!(std::fs::read(&path).unwrap(), first);
    // A cut part is not a part: computed again.
    let whole = std::fs::read(&path).unwrap();
    std::fs::write(&path, &whole[..whole.len() / 2]).unwrap();
    assert!(!run("2", 0).contains("skipped"));
    assert_eq!(std::fs::read(&path).unwrap(), whole);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Merged shards (given out of order) are the unsharded run, byte for byte, in
/// every format, for each method that shards; a Slurm job-array task writes the
/// part `--shard` writes.
#[test]
fn merged_shards_equal_the_unsharded_run() {
    let dir = part_dir("merge");
    // 100 is rounded up to 128 by Sobol′ (samples_asked must survive the merge);
    // Morris takes ⌈100 / 6⌉ = 17 trajectories.
    for method in ["sobol", "sampling", "morris"] {
        let parts = three_parts(&dir, method, "100");
        for format in ["json", "text", "csv", "html"] {
            let whole = stdout(
                wearopt().args([
                    "uncertainty",
                    SCATTER,
                    "--method",
                    method,
                    "--samples",
                    "100",
                    "--format",
                    format,
                ]),
                0,
            );
            let merged = stdout(
                wearopt()
                    .arg("merge")
                    .args([&parts[2], &parts[0], &parts[1]])
                    .args(["--format", format]),
                0,
            );
            assert!(
                merged == whole,
                "{method} {format}: merged shards differ from the unsharded run:\n{}",
                String::from_utf8_lossy(&merged)
            );
        }
        // The default format is the unsharded command's: text.
        let text = stdout(wearopt().arg("merge").args(&parts), 0);
        assert!(String::from_utf8(text)
            .unwrap()
            .contains("Polysilicon micro-gear hub"));
        let part: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&parts[1]).unwrap()).unwrap();
        assert_eq!(part["wearopt"], "uncertainty part");
        assert_eq!(part["shard"], "1/3");
        let slurm = stdout(
            wearopt()
                .args([
                    "uncertainty",
                    SCATTER,
                    "--method",
                    method,
                    "--samples",
                    "100",
                ])
                .env("SLURM_ARRAY_TASK_ID", "2")
                .env("SLURM_ARRAY_TASK_MIN", "1")
                .env("SLURM_ARRAY_TASK_COUNT", "3"),
            0,
        );
        assert_eq!(slurm, std::fs::read(&parts[1]).unwrap(), "{method}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// A part of another study (another seed) is refused naming the file and both
/// fingerprints; a missing part, and one given twice, naming the ranges; a
/// sweep's part among them; --samples that is not the study's.
#[test]
fn merge_refuses_foreign_missing_and_doubled_parts() {
    let dir = part_dir("refuse");
    let parts = three_parts(&dir, "sampling", "64");
    let foreign = dir.join("foreign.json");
    stdout(
        wearopt().args([
            "uncertainty",
            SCATTER,
            "--method",
            "sampling",
            "--samples",
            "64",
            "--seed",
            "2",
            "--shard",
            "1/3",
            "--out",
            foreign.to_str().unwrap(),
        ]),
        0,
    );
    let print = |p: &std::path::Path| -> String {
        let v: serde_json::Value = serde_json::from_slice(&std::fs::read(p).unwrap()).unwrap();
        v["fingerprint"].as_str().unwrap().to_string()
    };
    let err = String::from_utf8(stderr(
        wearopt()
            .arg("merge")
            .args([&parts[0], &foreign, &parts[2]]),
        2,
    ))
    .unwrap();
    assert!(err.contains("foreign.json"), "{err}");
    assert!(err.contains(&print(&foreign)), "{err}");
    assert!(err.contains(&print(&parts[0])), "{err}");

    // Shard 1/3 of 64 samples holds 21..42.
    let err = String::from_utf8(stderr(
        wearopt().arg("merge").args([&parts[2], &parts[0]]),
        2,
    ))
    .unwrap();
    assert!(
        err.contains("samples 21..42") && err.contains("missing"),
        "{err}"
    );
    let err = String::from_utf8(stderr(wearopt().arg("merge").args([&parts[0]]), 2)).unwrap();
    assert!(err.contains("samples 21..64"), "{err}");
    let err = String::from_utf8(stderr(
        wearopt()
            .arg("merge")
            .args([&parts[0], &parts[1], &parts[1], &parts[2]]),
        2,
    ))
    .unwrap();
    assert!(err.contains("21..42 are in both"), "{err}");

    let err = String::from_utf8(stderr(
        wearopt()
            .arg("merge")
            .args(&parts)
            .args(["--samples", "65"]),
        2,
    ))
    .unwrap();
    assert!(err.contains("64 samples, not 65"), "{err}");

    // A part cut short.
    let text = std::fs::read_to_string(&parts[1]).unwrap();
    let cut = dir.join("cut.json");
    let at = text.rfind(",\n    [").unwrap();
    std::fs::write(&cut, format!("{}\n  ]\n}}\n", &text[..at])).unwrap();
    let err = String::from_utf8(stderr(
        wearopt().arg("merge").args([&parts[0], &cut, &parts[2]]),
        2,
    ))
    .unwrap();
    assert!(
        err.contains("cut.json") && err.contains("cut short"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// Reliability is sequential: --shard (or a Slurm array task) is refused with
/// exit 2, and so is a shard asked for a report format.
#[test]
fn shard_refuses_reliability_and_report_formats() {
    let err = String::from_utf8(stderr(
        wearopt().args([
            "uncertainty",
            SCATTER,
            "--method",
            "reliability",
            "--shard",
            "0/2",
        ]),
        2,
    ))
    .unwrap();
    assert!(
        err.contains("--shard 0/2") && err.contains("reliability cannot be sharded"),
        "{err}"
    );
    let err = String::from_utf8(stderr(
        wearopt()
            .args(["uncertainty", SCATTER, "--method", "reliability"])
            .env("SLURM_ARRAY_TASK_ID", "0")
            .env("SLURM_ARRAY_TASK_COUNT", "2"),
        2,
    ))
    .unwrap();
    assert!(
        err.contains("SLURM_ARRAY_TASK_ID") && err.contains("cannot be sharded"),
        "{err}"
    );
    let err = String::from_utf8(stderr(
        wearopt().args([
            "uncertainty",
            SCATTER,
            "--samples",
            "64",
            "--shard",
            "0/2",
            "--format",
            "html",
        ]),
        2,
    ))
    .unwrap();
    assert!(
        err.contains("wearopt merge") && err.contains("--format html"),
        "{err}"
    );
}

/// In the library: the parts of any number of shards (more than there are
/// units: some empty), read back from their JSON, merge into the document of
/// the unsharded run.
#[test]
fn parts_of_any_count_merge_into_the_document() {
    use wearopt::app::uncertainty::{merge, uncertainty_part};
    use wearopt::report::uncertainty::{is_part, parse_part, part_json};
    let source = std::fs::read_to_string(SCATTER).unwrap();
    let problem = parse(&source, SCATTER).unwrap();
    for method in [Method::Sobol, Method::Morris, Method::Sampling] {
        let options = UncertaintyOptions {
            method,
            samples: Some(64),
            seed: Some(3),
        };
        let whole = uncertainty(&problem, SCATTER, &options, &Quiet).unwrap();
        for count in [1, 2, 5, 70] {
            let parts: Vec<_> = (0..count)
                .rev()
                .map(|i| {
                    let shard = wearopt::sweep::Shard::new(i, count).unwrap();
                    let part =
                        uncertainty_part(&problem, SCATTER, &source, &options, shard, &Quiet)
                            .unwrap();
                    let text = part_json(&part);
                    assert!(is_part(&text));
                    let back = parse_part(&text).unwrap();
                    assert_eq!(back, part, "{method:?} {i}/{count}: the JSON reads back");
                    (format!("part {i}"), back)
                })
                .collect();
            let merged = merge(parts, None).unwrap();
            assert_eq!(merged, whole, "{method:?} in {count} shards");
        }
    }
}
