//! What a newcomer tripped over (issue 56): a unit forgotten on the command line,
//! one quantity in two spellings, caveats lost in HTML and JSON, small
//! inconsistencies between commands.

use crate::common;
use crate::common::wearopt;

const MAP: &str = "problems/scans/self-affine.gsf";

fn stderr_of(args: &[&str], code: i32) -> String {
    String::from_utf8(common::stderr(wearopt().args(args), code)).unwrap()
}

/// `--modulus 150` was E* = 150 Pa: a run to the iteration limit, exit 0. A bare
/// number is read in SI only where plausible; otherwise refused with the guess.
#[test]
fn a_bare_number_out_of_its_plausible_range_is_refused_with_a_guess() {
    let e = stderr_of(
        &["contact", MAP, "--modulus", "150", "--pressure", "50MPa"],
        2,
    );
    assert!(e.contains("--modulus \"150\""), "{e}");
    assert!(e.contains("did you mean \"150 GPa\""), "{e}");
    assert!(e.contains("1 MPa – 2 TPa"), "{e}");
    // Every dimensional flag of every command.
    for (args, flag) in [
        (
            vec!["contact", MAP, "--modulus", "150GPa", "--pressure", "50"],
            "--pressure \"50\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--hardness",
                "12",
            ],
            "--hardness \"12\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--work-of-adhesion",
                "50",
                "--adhesion-range",
                "1nm",
            ],
            "--work-of-adhesion \"50\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--work-of-adhesion",
                "50mJ/m^2",
                "--adhesion-range",
                "1",
            ],
            "--adhesion-range \"1\"",
        ),
        (
            vec![
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--pixel-size",
                "20",
            ],
            "--pixel-size \"20\"",
        ),
        (
            vec!["roughness", MAP, "--pixel-size", "20"],
            "--pixel-size \"20\"",
        ),
        (
            vec!["roughness", MAP, "--cutoff", "100"],
            "--cutoff \"100\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3",
            ],
            "--radius \"0.3\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3mm",
                "--modulus",
                "100",
            ],
            "--modulus \"100\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3mm",
                "--quoted-gamma",
                "100",
            ],
            "--quoted-gamma \"100\"",
        ),
        (
            vec![
                "fit-adhesion",
                "problems/ando-friction.csv",
                "--radius",
                "0.3mm",
                "--quoted-bond-strength",
                "65",
            ],
            "--quoted-bond-strength \"65\"",
        ),
    ] {
        let e = stderr_of(&args, 2);
        assert!(e.contains(flag), "{args:?}: {e}");
        assert!(e.contains("did you mean"), "{args:?}: {e}");
    }
    // Plausible bare numbers are SI, as before.
    common::stdout(wearopt().args(["roughness", MAP, "--cutoff", "1e-7"]), 0);
}

/// A row that is not a solution is no usable result: exit 1, as the README says.
#[test]
fn a_contact_row_that_is_not_a_solution_exits_1() {
    // A unit written out is taken as meant: 150 Pa runs to the iteration limit.
    // On a 32 × 32 map (heights from a fixed generator, as a text grid): the
    // shipped 256² scan takes the same 5000 iterations some 60 times longer.
    let dir = scratch("not-a-solution");
    std::fs::create_dir_all(&dir).unwrap();
    let map = dir.join("map.txt");
    let mut state = 0x2545_f491_4f6c_dd1d_u64;
    let mut grid = String::new();
    for _ in 0..32 {
        let row: Vec<String> = (0..32)
            .map(|_| {
                state ^= state << 13;
                state ^= state >> 7;
                state ^= state << 17;
                format!("{:.6}", (state >> 11) as f64 / (1u64 << 53) as f64)
            })
            .collect();
        grid.push_str(&row.join("\t"));
        grid.push('\n');
    }
    std::fs::write(&map, grid).unwrap();
    let out = common::stdout(
        wearopt().args([
            "contact",
            map.to_str().unwrap(),
            "--pixel-size",
            "20nm",
            "--height-unit",
            "nm",
            "--modulus",
            "150 Pa",
            "--pressure",
            "50MPa",
        ]),
        1,
    );
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("not a solution"), "{text}");
    assert!(
        text.contains("stopped at its iteration limit (5000 iterations)"),
        "{text}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

const HUMID: &str = "problems/micro-gear-humid.toml";

/// A problem file takes `relative_humidity = "50 %"`; the command line took only
/// fractions (`--from 0%` refused, `--to 90` "must lie in [0, 1)"). Both
/// spellings now, the same numbers either way.
#[test]
fn humidity_flags_take_a_fraction_or_a_percentage() {
    let run = |from: &str, to: &str| {
        common::stdout(
            wearopt().args([
                "humidity", HUMID, "--from", from, "--to", to, "--points", "4", "--format", "json",
            ]),
            0,
        )
    };
    let fractions = run("0", "0.9");
    assert_eq!(run("0%", "90 %"), fractions);
    assert_eq!(run("0 %", "0.9"), fractions);
    // A bare 90 is most likely a percentage without its sign: refused, with the guess.
    let e = stderr_of(
        &[
            "humidity", HUMID, "--from", "0", "--to", "90", "--points", "4",
        ],
        2,
    );
    assert!(e.contains("--to 90"), "{e}");
    assert!(e.contains("did you mean \"90 %\"?"), "{e}");
    // Out of range as a percentage too, named with both ranges.
    let e = stderr_of(
        &[
            "humidity", HUMID, "--from", "0", "--to", "120%", "--points", "4",
        ],
        2,
    );
    assert!(e.contains("--to 1.2") && e.contains("[0 %, 100 %)"), "{e}");
}

/// One spelling shown: the table's "RH %" column and the plot's axis and
/// threshold are all percentages (JSON and CSV stay fractions).
#[test]
fn the_humidity_page_shows_percentages_throughout() {
    let dir = std::env::temp_dir().join(format!("wearopt-newcomer-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("humidity.svg");
    let html = String::from_utf8(common::stdout(
        wearopt().args([
            "humidity",
            HUMID,
            "--from",
            "0",
            "--to",
            "0.9",
            "--points",
            "4",
            "--format",
            "html",
            "--plot",
            svg.to_str().unwrap(),
        ]),
        0,
    ))
    .unwrap();
    assert!(html.contains("RH %"), "the table's header");
    for doc in [html, std::fs::read_to_string(&svg).unwrap()] {
        assert!(
            doc.contains("relative humidity RH (%)"),
            "the axis in percent"
        );
        assert!(
            doc.contains("threshold RH = 77.82 %"),
            "the threshold in percent"
        );
    }
    let json: serde_json::Value = serde_json::from_slice(&common::stdout(
        wearopt().args([
            "humidity", HUMID, "--from", "0", "--to", "0.9", "--points", "4", "--format", "json",
        ]),
        0,
    ))
    .unwrap();
    assert_eq!(json["points"][3]["relative_humidity"], 0.9);
    std::fs::remove_dir_all(&dir).ok();
}

/// `contact`'s "patches average fewer than 20 pixels" (the area is
/// resolution-limited) was in the text only; now in the JSON's `notes` and on the
/// page too, word for word.
#[test]
fn contact_caveats_reach_every_format() {
    let run = |format: &str| {
        String::from_utf8(common::stdout(
            wearopt().args([
                "contact",
                MAP,
                "--modulus",
                "150GPa",
                "--pressure",
                "50MPa",
                "--format",
                format,
            ]),
            0,
        ))
        .unwrap()
    };
    let caveat = "the contact patches average fewer than 20 pixels";
    assert!(run("text").contains(caveat));
    assert!(run("html").contains(caveat), "the page");
    let json: serde_json::Value = serde_json::from_str(&run("json")).unwrap();
    let notes = json["notes"].as_array().expect("a notes array");
    assert!(
        notes.iter().any(|n| n.as_str().unwrap().contains(caveat)),
        "{notes:?}"
    );
}

/// The humidity page marked rows "ok †" and never said what † means; the JSON had
/// only the number (continuum_humidity). Both carry the words now.
#[test]
fn humidity_caveats_reach_every_format() {
    let run = |format: &str| {
        String::from_utf8(common::stdout(
            wearopt().args([
                "humidity", HUMID, "--from", "0", "--to", "0.95", "--points", "11", "--format",
                format,
            ]),
            0,
        ))
        .unwrap()
    };
    let caveat = "the Kelvin radius is under 0.5 nm";
    let html = run("html");
    assert!(html.contains("ok †"), "a marked row");
    assert!(
        html.contains(&format!("† Below RH = 35.02 % {caveat}")),
        "what † means"
    );
    let json: serde_json::Value = serde_json::from_str(&run("json")).unwrap();
    let notes = json["notes"].as_array().expect("a notes array");
    assert!(
        notes.iter().any(|n| n.as_str().unwrap().contains(caveat)),
        "{notes:?}"
    );
    assert!(run("text").contains(&format!("† below RH = 35.02 % {caveat}")));
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("wearopt-newcomer-{name}-{}", std::process::id()));
    std::fs::remove_dir_all(&dir).ok();
    dir
}

/// `pareto --out` worked only with HTML; the README shows it for every format.
#[test]
fn pareto_out_writes_every_format() {
    let dir = scratch("pareto");
    std::fs::create_dir_all(&dir).unwrap();
    for format in ["text", "csv", "json", "html"] {
        let args = [
            "pareto",
            "problems/micro-gear.toml",
            "--points",
            "3",
            "--format",
            format,
        ];
        let to_stdout = common::stdout(wearopt().args(args), 0);
        let path = dir.join(format!("front.{format}"));
        let printed = common::stdout(wearopt().args(args).arg("--out").arg(&path), 0);
        assert!(printed.is_empty(), "{format}: nothing on stdout");
        let written = std::fs::read_to_string(&path).unwrap();
        let to_stdout = String::from_utf8(to_stdout).unwrap();
        // The text and the page say how long the front took: the rest is the same.
        let timeless = |s: &str| -> Vec<String> {
            s.lines()
                .filter(|l| !l.contains(" s.") && !l.contains(" s,"))
                .map(String::from)
                .collect()
        };
        assert!(
            timeless(&written) == timeless(&to_stdout),
            "{format}: {written}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// `contact --fields` needed an existing folder where `figures --out` makes one.
#[test]
fn contact_fields_makes_its_folder() {
    let dir = scratch("fields").join("nested");
    common::stdout(
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
            .arg(&dir),
        0,
    );
    assert!(dir.join("pressure_1.npy").is_file() && dir.join("gap_1.npy").is_file());
    std::fs::remove_dir_all(dir.parent().unwrap()).ok();
}

/// `Error:` (ours) and `error:` (clap's usage errors) both occurred: one spelling.
#[test]
fn usage_errors_are_spelled_like_every_other_error() {
    for args in [
        vec!["eval"],
        vec!["eval", "problems/micro-gear.toml", "--bogus"],
        vec![
            "contact",
            MAP,
            "--modulus",
            "150GPa",
            "--pressure",
            "50MPa",
            "--level",
            "cubic",
        ],
        vec!["eval", "no-such-file.toml"],
    ] {
        let e = stderr_of(&args, 2);
        assert!(e.starts_with("Error: "), "{args:?}: {e}");
        assert!(!e.contains("error:"), "{args:?}: {e}");
    }
    // Help is no error.
    common::stdout(wearopt().args(["eval", "--help"]), 0);
}

/// `fit-adhesion` printed "1.48 mN/m ± 500 µN/m": one prefix per line.
#[test]
fn fit_adhesion_gives_one_prefix_per_line() {
    let text = String::from_utf8(common::stdout(
        wearopt().args([
            "fit-adhesion",
            "problems/ando-friction.csv",
            "--radius",
            "0.3mm",
            "--materials",
            "steel,silicon",
        ]),
        0,
    ))
    .unwrap();
    assert!(
        text.contains("work of adhesion γ      1.48 ± 0.500 mN/m (standard error)"),
        "{text}"
    );
    assert!(
        text.contains("95 % interval          0 to 3.07 mN/m, clipped at 0"),
        "{text}"
    );
}
