//! What the testers found (issue 57, item 6), each with its reproduction: hangs
//! and unbounded work, silent wrong answers, data lost or overwritten, unclear
//! messages. Each test fails on the build before its fix.

use std::path::{Path, PathBuf};
use std::time::Duration;

use crate::common;

const MAP: &str = "problems/scans/self-affine.gsf";
const STUDY: &str = "tests/data/micro-gear-study-jkr.toml";

/// The binary, without Slurm's variables (which would pick a shard).
fn wearopt() -> assert_cmd::Command {
    let mut c = common::wearopt();
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

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("wearopt-testers-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn root(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// Runs `cmd`, expects exit code 2, returns stderr.
fn refused(cmd: &mut assert_cmd::Command) -> String {
    String::from_utf8(common::stderr(cmd, 2)).unwrap()
}

// ------------------------------------------------------------ hangs and memory

/// `sweep --out /dev/stdout | cat` waited forever (the resume check read its own
/// output, a pipe, to its end); `--out /dev/full` read the device into memory
/// until the kernel killed it (21 GB). A device or a pipe is a fresh output now.
#[test]
fn sweep_into_a_pipe_or_a_device_does_not_read_it() {
    let out = wearopt()
        .args(["sweep", STUDY, "--samples", "2", "--out", "/dev/stdout"])
        .timeout(Duration::from_secs(120))
        .assert()
        .success()
        .get_output()
        .stdout
        .clone();
    let text = String::from_utf8(out).unwrap();
    assert!(text.starts_with("# wearopt sweep "), "{text}");
    assert_eq!(
        text.lines().count(),
        4,
        "fingerprint, header, two rows: {text}"
    );
    if Path::new("/dev/full").exists() {
        let err = wearopt()
            .args(["sweep", STUDY, "--samples", "2", "--out", "/dev/full"])
            .timeout(Duration::from_secs(120))
            .assert()
            .failure()
            .get_output()
            .stderr
            .clone();
        let err = String::from_utf8(err).unwrap();
        assert!(err.contains("writing to /dev/full"), "{err}");
    }
}

/// `asperity --tabor 1 --from -1e4 --to -1 --points 3` ran 166 s to
/// `not_converged`, `--to 1e6` was still tracing after 32 min, `--points 10000`
/// ran 25 min: the traced Lennard-Jones curve is bounded (|δ̂| ≤ 1000: 41 s from
/// −1000; 1000 points) and what lies beyond is refused with the range that
/// can finish. The closed forms keep their full range.
#[test]
fn asperity_refuses_a_trace_that_cannot_finish() {
    let run = |from: &str, to: &str, points: &str| {
        let mut c = wearopt();
        c.args([
            "asperity", "--tabor", "1", "--from", from, "--to", to, "--points", points,
        ])
        .timeout(Duration::from_secs(60));
        c
    };
    let e = refused(&mut run("-1e4", "-1", "3"));
    assert!(e.contains("--from -10000") && e.contains("±1000"), "{e}");
    let e = refused(&mut run("-1", "1e6", "3"));
    assert!(e.contains("--to 1000000") && e.contains("±1000"), "{e}");
    let e = refused(&mut run("-1", "1", "10000"));
    assert!(
        e.contains("--points 10000") && e.contains("2..=1000"),
        "{e}"
    );
    // JKR is a closed form: 10 000 points over ±1e6 are fine.
    let out = common::stdout(
        run("-1e6", "1e6", "10000").args(["--adhesion-model", "jkr", "--format", "csv"]),
        0,
    );
    assert!(String::from_utf8(out).unwrap().lines().count() > 10_000);
    // Outside the solved Tabor range a closed-form limit stands in: not bounded.
    let mut c = wearopt();
    c.args([
        "asperity", "--tabor", "500", "--from", "-1e4", "--to", "10", "--points", "3",
    ]);
    common::stdout(&mut c, 0);
}

// ------------------------------------------------------------ silent wrong

/// Copies `problems/micro-gear-scan.toml` into `dir`, reading its scan from a
/// copy of the shipped .npy (256 × 256 heights in nm, 20 nm pixels); returns the
/// problem's path and the scan's.
fn scan_study(dir: &Path) -> (PathBuf, PathBuf) {
    let text = std::fs::read_to_string(root("problems/micro-gear-scan.toml")).unwrap();
    let text = text.replace(
        "topography = \"scans/self-affine.gsf\"",
        "topography = \"scan.npy\"\npixel_size = \"20 nm\"\nheight_unit = \"nm\"",
    );
    assert!(text.contains("scan.npy"));
    let problem = dir.join("study.toml");
    std::fs::write(&problem, text).unwrap();
    let scan = dir.join("scan.npy");
    std::fs::copy(root("problems/scans/self-affine-nm.npy"), &scan).unwrap();
    (problem, scan)
}

/// The fingerprint ignored the scan a problem names: with another `.npy` under
/// the same name a rerun said "complete … skipped" and kept the old rows.
#[test]
fn a_changed_scan_is_another_sweep() {
    let dir = scratch("scan-fingerprint");
    let (problem, scan) = scan_study(&dir);
    let out = dir.join("rows.csv");
    let run = || {
        let err = wearopt()
            .arg("sweep")
            .arg(&problem)
            .args(["--samples", "2", "--out"])
            .arg(&out)
            .assert()
            .success()
            .get_output()
            .stderr
            .clone();
        String::from_utf8(err).unwrap()
    };
    assert!(!run().contains("skipped"));
    let first = std::fs::read_to_string(&out).unwrap();
    assert!(run().contains("skipped"), "the same scan: kept");
    // The last height's lowest mantissa bit flipped: still a valid map, another scan.
    let mut bytes = std::fs::read(&scan).unwrap();
    let last = bytes.len() - 8;
    bytes[last] ^= 1;
    std::fs::write(&scan, bytes).unwrap();
    assert!(!run().contains("skipped"), "a changed scan is recomputed");
    let second = std::fs::read_to_string(&out).unwrap();
    assert_ne!(
        first.lines().next(),
        second.lines().next(),
        "another fingerprint"
    );
}

/// Parts from two builds merged (rows 2.8 % apart): the head names the build
/// (a hash of the sources, `report::sweep::BUILD`), a rerun by another build
/// recomputes, and merge refuses parts of two builds.
#[test]
fn parts_of_another_build_are_neither_kept_nor_merged() {
    let build = wearopt::report::sweep::BUILD;
    assert_eq!(build.len(), 16);
    assert!(build.bytes().all(|b| b.is_ascii_hexdigit()), "{build}");
    let dir = scratch("build");
    let part = |i: u64| {
        let path = dir.join(format!("p{i}.csv"));
        let err = wearopt()
            .args([
                "sweep",
                STUDY,
                "--samples",
                "4",
                "--shard",
                &format!("{i}/2"),
                "--out",
            ])
            .arg(&path)
            .assert()
            .success()
            .get_output()
            .stderr
            .clone();
        (path, String::from_utf8(err).unwrap())
    };
    let (p0, _) = part(0);
    let (p1, _) = part(1);
    let text = std::fs::read_to_string(&p0).unwrap();
    let head = text.lines().next().unwrap();
    assert!(head.ends_with(&format!(" build={build}")), "{head}");
    // The same part as another build wrote it.
    let other = if build == "0000000000000000" {
        "1111111111111111"
    } else {
        "0000000000000000"
    };
    std::fs::write(&p0, text.replacen(build, other, 1)).unwrap();
    let e = refused(wearopt().arg("merge").args([&p0, &p1]));
    assert!(
        e.contains("parts of different sweeps") && e.contains("build"),
        "{e}"
    );
    assert!(
        !part(0).1.contains("skipped"),
        "another build's part is recomputed"
    );
    assert_eq!(std::fs::read_to_string(&p0).unwrap(), text);
    // The JSON head names it too.
    let out = common::stdout(
        wearopt().args(["sweep", STUDY, "--samples", "2", "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["build"], build);
}

/// The humid hub with its temperature as a design variable up to `max`.
fn hot_hub(dir: &Path, max: &str) -> PathBuf {
    let text = std::fs::read_to_string(root("problems/micro-gear-humid.toml")).unwrap();
    let path = dir.join(format!("hot-{}.toml", max.replace(' ', "")));
    std::fs::write(
        &path,
        format!(
            "{text}\n[design]\ntemperature = {{ min = \"200 K\", max = \"{max}\" }}\n\n[objective]\nminimize = \"wear_rate\"\n"
        ),
    )
    .unwrap();
    path
}

/// `temperature = { min = "200 K", max = "700 K" }` on the humid hub:
/// `optimize` said `optimal` at 700 K, which `eval` refuses (water has no liquid
/// at or above its critical point, 647.096 K, IAPWS). The design range is
/// refused at loading, with the accepted range; one below it loads.
#[test]
fn a_design_temperature_beyond_what_eval_accepts_is_refused() {
    let dir = scratch("hot");
    let hot = hot_hub(&dir, "700 K");
    for command in ["optimize", "eval", "sweep"] {
        let mut c = wearopt();
        c.arg(command).arg(&hot);
        if command == "sweep" {
            c.args(["--samples", "2"]);
        }
        let e = refused(&mut c);
        assert!(
            e.contains("design.temperature.max") && e.contains("700 K") && e.contains("647.096 K"),
            "{command}: {e}"
        );
    }
    common::stdout(wearopt().arg("eval").arg(hot_hub(&dir, "600 K")), 0);
}

/// `temperature = 25` (Celsius meant) was read as 25 K without a word: water
/// below its freezing point (273.15 K) is ice, not a meniscus. A warning, with
/// the Celsius reading (25 °C = 298.15 K); none at the shipped 298.15 K.
#[test]
fn water_below_its_freezing_point_is_warned_of() {
    let dir = scratch("cold");
    let text = std::fs::read_to_string(root("problems/micro-gear-humid.toml")).unwrap();
    let cold = text.replace("temperature = \"298.15 K\"", "temperature = 25");
    assert_ne!(cold, text);
    let path = dir.join("cold.toml");
    std::fs::write(&path, cold).unwrap();
    let out = String::from_utf8(common::stdout(wearopt().arg("eval").arg(&path), 0)).unwrap();
    assert!(
        out.contains("below water's freezing point, 273.15 K"),
        "{out}"
    );
    assert!(out.contains("25 °C is \"298.15 K\""), "{out}");
    let json = common::stdout(
        wearopt().arg("eval").arg(&path).args(["--format", "json"]),
        0,
    );
    assert!(String::from_utf8(json)
        .unwrap()
        .contains("\"liquid_below_freezing\""));
    let warm = String::from_utf8(common::stdout(
        wearopt().args(["eval", "problems/micro-gear-humid.toml"]),
        0,
    ))
    .unwrap();
    assert!(!warm.contains("freezing"), "{warm}");
}

/// `contact --tolerance 0.999` reported converged after 0 iterations at 100 %
/// contact (true: 5.7 %); `--modulus "1e300 Pa"` reported converged on one
/// pixel. Both refused with the accepted range; just inside the tolerance's
/// bound the solve iterates and lands within 10 % of the converged area
/// (1.70 % on this map at 50 MPa; 1.82 % at 0.01, measured).
#[test]
fn contact_refuses_a_meaningless_tolerance_or_modulus() {
    let base = ["contact", MAP, "--modulus", "150GPa", "--pressure", "50MPa"];
    let e = refused(wearopt().args(base).args(["--tolerance", "0.999"]));
    assert!(
        e.contains("--tolerance 0.999") && e.contains("(0, 0.01)"),
        "{e}"
    );
    let e = refused(wearopt().args(base).args(["--tolerance", "0.01"]));
    assert!(e.contains("--tolerance 0.01"), "{e}");
    let e = refused(wearopt().args([
        "contact",
        MAP,
        "--modulus",
        "1e300 Pa",
        "--pressure",
        "50MPa",
    ]));
    assert!(e.contains("--modulus") && e.contains("10 TPa"), "{e}");
    let area = |tolerance: &str| {
        let out = common::stdout(
            wearopt()
                .args(base)
                .args(["--tolerance", tolerance, "--format", "json"]),
            0,
        );
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        let p = &v["points"][0];
        assert_eq!(p["status"], "converged");
        assert!(p["iterations"].as_u64().unwrap() > 0);
        p["real_area_fraction"].as_f64().unwrap()
    };
    let converged = area("1e-10");
    let loose = area("0.009");
    assert!(
        (loose / converged - 1.0).abs() < 0.1,
        "{loose} vs {converged}"
    );
}

// ------------------------------------------------------------ data lost or overwritten

/// `contact scan … --plot scan` and `eval p.toml --out p.toml` overwrote their
/// input; a symbolic link named `DIR/pressure_1.npy` made `--fields DIR` write
/// through to its target. All refused before the work, the files untouched.
#[test]
fn outputs_never_overwrite_the_input_or_write_through_a_link() {
    let dir = scratch("overwrite");
    let scan = dir.join("scan.gsf");
    std::fs::copy(root(MAP), &scan).unwrap();
    let original = std::fs::read(&scan).unwrap();
    let contact = |extra: &[&str]| {
        let mut c = wearopt();
        c.arg("contact")
            .arg(&scan)
            .args(["--modulus", "150GPa", "--pressure", "50MPa"])
            .args(extra);
        c
    };
    let e = refused(&mut contact(&["--plot", scan.to_str().unwrap()]));
    assert!(e.contains("it is the input"), "{e}");
    assert_eq!(std::fs::read(&scan).unwrap(), original);
    // The same file by another name.
    let e = refused(&mut contact(&[
        "--plot",
        &format!("{}/./scan.gsf", dir.display()),
    ]));
    assert!(e.contains("it is the input"), "{e}");
    assert_eq!(std::fs::read(&scan).unwrap(), original);

    let problem = dir.join("p.toml");
    std::fs::copy(root("problems/micro-gear.toml"), &problem).unwrap();
    let text = std::fs::read(&problem).unwrap();
    let e = refused(
        wearopt()
            .arg("eval")
            .arg(&problem)
            .arg("--out")
            .arg(&problem),
    );
    assert!(e.contains("it is the input"), "{e}");
    assert_eq!(std::fs::read(&problem).unwrap(), text);
    let e = refused(wearopt().args(["sweep", STUDY, "--samples", "2", "--out", STUDY]));
    assert!(e.contains("it is the input"), "{e}");

    let fields = dir.join("fields");
    std::fs::create_dir_all(&fields).unwrap();
    let target = dir.join("precious.txt");
    std::fs::write(&target, "keep").unwrap();
    std::os::unix::fs::symlink(&target, fields.join("pressure_1.npy")).unwrap();
    let e = refused(&mut contact(&["--fields", fields.to_str().unwrap()]));
    assert!(e.contains("pressure_1.npy is a symbolic link"), "{e}");
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep");
}

/// `asperity … --plot no/dir/a.svg` and `contact --fields` into a folder it
/// cannot write computed for seconds, then exited 2 and lost the result: the
/// outputs are checked first (the asperity curve below takes about 20 s).
#[test]
fn outputs_are_checked_before_the_work() {
    let dir = scratch("before");
    let plot = dir.join("no").join("dir").join("a.svg");
    let e = refused(
        wearopt()
            .args([
                "asperity", "--tabor", "1", "--from", "-1.5", "--to", "1", "--points", "200",
                "--plot",
            ])
            .arg(&plot)
            .timeout(Duration::from_secs(10)),
    );
    assert!(
        e.contains("cannot write the plot") && e.contains("a.svg"),
        "{e}"
    );
    // A field's file cannot be written where a folder of its name stands (a
    // read-only folder would do, but not for root).
    let fields = dir.join("fields");
    std::fs::create_dir_all(fields.join("gap_1.npy")).unwrap();
    let e = refused(
        wearopt()
            .args([
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--fields",
            ])
            .arg(&fields),
    );
    assert!(e.contains("gap_1.npy"), "{e}");
    assert!(
        !fields.join("pressure_1.npy").exists(),
        "nothing written before the check"
    );
    // `--plot -` with JSON mixed the SVG into the JSON on stdout.
    let e = refused(wearopt().args([
        "contact",
        MAP,
        "--modulus",
        "150GPa",
        "--pressure",
        "50MPa",
        "--plot",
        "-",
        "--format",
        "json",
    ]));
    assert!(e.contains("--plot -"), "{e}");
}

/// Parts of a 10-design sweep in 2 shards, as CSV, written into `dir`.
fn csv_parts(dir: &Path) -> Vec<PathBuf> {
    (0..2)
        .map(|i| {
            let path = dir.join(format!("p{i}.csv"));
            wearopt()
                .args([
                    "sweep",
                    STUDY,
                    "--samples",
                    "10",
                    "--shard",
                    &format!("{i}/2"),
                    "--out",
                ])
                .arg(&path)
                .assert()
                .success();
            path
        })
        .collect()
}

/// CSV parts without their `# wearopt sweep` line: `merge` accepted a cut last
/// part (33 000 of 40 001 lines). Without the line nothing gives N: refused
/// unless `--samples` gives it, and then a cut part is found.
#[test]
fn merge_needs_n_for_csv_parts_without_their_fingerprint() {
    let dir = scratch("headless");
    let parts = csv_parts(&dir);
    for p in &parts {
        let text = std::fs::read_to_string(p).unwrap();
        let body: String = text.lines().skip(1).map(|l| format!("{l}\n")).collect();
        std::fs::write(p, body).unwrap();
    }
    // The last part cut on a row boundary.
    let last = std::fs::read_to_string(&parts[1]).unwrap();
    let cut: String = last.lines().take(3).map(|l| format!("{l}\n")).collect();
    std::fs::write(&parts[1], &cut).unwrap();
    let e = refused(wearopt().arg("merge").args(&parts));
    assert!(
        e.contains("give --samples N") && e.contains("rows 0..7"),
        "{e}"
    );
    let e = refused(
        wearopt()
            .arg("merge")
            .args(&parts)
            .args(["--samples", "10"]),
    );
    assert!(e.contains("rows 7..10 are missing"), "{e}");
    std::fs::write(&parts[1], &last).unwrap();
    let merged = common::stdout(
        wearopt()
            .arg("merge")
            .args(&parts)
            .args(["--samples", "10"]),
        0,
    );
    assert_eq!(String::from_utf8(merged).unwrap().lines().count(), 11);
}

/// `merge --samples 200` on 400 rows said "rows 400..200 are missing"; a cut
/// CSV was called "the JSON output"; CR LF line ends were "different sweeps".
#[test]
fn merge_says_what_is_wrong() {
    let dir = scratch("merge-words");
    let parts = csv_parts(&dir);
    let e = refused(wearopt().arg("merge").args(&parts).args(["--samples", "4"]));
    assert!(
        e.contains("more than the 4 designs") && !e.contains("10..4"),
        "{e}"
    );
    let text = std::fs::read_to_string(&parts[1]).unwrap();
    std::fs::write(&parts[1], &text[..text.len() - 5]).unwrap();
    let e = refused(wearopt().arg("merge").args(&parts));
    assert!(
        e.contains("CSV output stops in the middle of a line") && !e.contains("JSON"),
        "{e}"
    );
    std::fs::write(&parts[1], text.replace('\n', "\r\n")).unwrap();
    let e = refused(wearopt().arg("merge").args(&parts));
    assert!(
        e.contains("CR LF") && !e.contains("different sweeps"),
        "{e}"
    );
}

// ------------------------------------------------------------ unclear

/// The humid hub with `from` in its text replaced by `to`, in `dir`.
fn humid_hub_with(dir: &Path, name: &str, from: &str, to: &str) -> PathBuf {
    let text = std::fs::read_to_string(root("problems/micro-gear-humid.toml")).unwrap();
    let edited = text.replace(from, to);
    assert_ne!(edited, text, "{from:?} is in the file");
    let path = dir.join(name);
    std::fs::write(&path, edited).unwrap();
    path
}

/// The README's own `molar_volume = "18.07 cm^3/mol"` was refused: it reads as
/// the same liquid as 1.807e-5 m^3/mol (the same quantity in SI), to the byte.
#[test]
fn a_molar_volume_in_cm3_per_mol_is_read() {
    let dir = scratch("molar-volume");
    let liquid =
        |v: &str| format!("liquid = {{ surface_tension = \"72 mN/m\", molar_volume = \"{v}\" }}");
    let cm3 = humid_hub_with(
        &dir,
        "cm3.toml",
        "liquid = \"water\"",
        &liquid("18.07 cm^3/mol"),
    );
    let si = humid_hub_with(
        &dir,
        "si.toml",
        "liquid = \"water\"",
        &liquid("1.807e-5 m^3/mol"),
    );
    let json = |p: &Path| {
        let out = common::stdout(wearopt().arg("eval").arg(p).args(["--format", "json"]), 0);
        let mut v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        v.as_object_mut().unwrap().remove("file");
        v
    };
    // 18.07e-6 and 1.807e-5 are one decimal number: the same double.
    assert_eq!(json(&cm3), json(&si));
}

/// `cantilever = [1, 2, 3]` was read by position (thickness, gap, modulus), and
/// a wrong length named the Rust struct `RawCantilever`: only a table is read.
#[test]
fn a_cantilever_is_a_table_not_a_list() {
    let dir = scratch("cantilever");
    let shipped =
        "cantilever = { thickness = \"2 um\", gap = \"2 um\", youngs_modulus = \"160 GPa\" }";
    for list in ["[\"2 um\", \"2 um\", \"160 GPa\"]", "[1, 2]"] {
        let path = humid_hub_with(&dir, "list.toml", shipped, &format!("cantilever = {list}"));
        let e = refused(wearopt().arg("eval").arg(&path));
        assert!(
            e.contains("cantilever") && e.contains("expected a table"),
            "{e}"
        );
        assert!(!e.contains("RawCantilever"), "{e}");
    }
}

/// `humidity` where every row is `out_of_range` exited 0 (`eval` of the same
/// scene exits 1): 1 N on 5 µm² of the humid hub needs a real area above the
/// nominal one at every humidity. No usable row: exit 1; the shipped hub: 0.
#[test]
fn humidity_without_a_usable_row_exits_1() {
    let dir = scratch("humidity");
    let text = std::fs::read_to_string(root("problems/micro-gear-humid.toml")).unwrap();
    let heavy = text
        .replacen("load = \"800 uN\"", "load = \"1 N\"", 1)
        .replacen(
            "nominal_area = \"1000 um^2\"",
            "nominal_area = \"5 um^2\"",
            1,
        );
    let path = dir.join("heavy.toml");
    std::fs::write(&path, heavy).unwrap();
    let range = [
        "--from", "0", "--to", "0.9", "--points", "3", "--format", "json",
    ];
    let out = common::stdout(wearopt().arg("humidity").arg(&path).args(range), 1);
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 3);
    assert!(points.iter().all(|p| p["status"] == "out_of_range"), "{v}");
    common::stdout(wearopt().arg("eval").arg(&path), 1);
    common::stdout(
        wearopt()
            .args(["humidity", "problems/micro-gear-humid.toml"])
            .args(range),
        0,
    );
}
