//! Reports as a user meets them: units, small defects of the command line, and the
//! numbers a designer decides on. Each test runs the binary on a problem file.

use crate::common::wearopt;

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

/// The micro-gear hub (Lennard-Jones law): A_r = 6.404e-13 m² and wear rate
/// 6.404e-17 m³/m; the text says so with the prefix on the length, and the line
/// the contract names stays.
#[test]
fn eval_text_units_are_si() {
    let t = stdout_of(&["eval", "problems/micro-gear.toml"]);
    assert!(t.contains("real area A_r = 0.6404 µm²"), "{t}");
    assert!(t.contains("wear rate V/L = 64.04 µm³/m"), "{t}");
    assert!(t.contains("asperity density N = 10.0 µm⁻²"), "{t}");
    assert!(
        !t.contains("fm²") && !t.contains("am³") && !t.contains(" um"),
        "{t}"
    );
    assert!(t.contains("Richardson"), "{t}");
}

/// W/A_r above the hardness is the model's area measure at work (every contact
/// counted as πRδ, a plastic junction carrying H over 2πRδ): the report says
/// so beside the number on a stiff, soft-surfaced hub (E 400 GPa, H 1 GPa: 80 %
/// of the area plastic, W/A_r = 1.54 GPa), and says nothing where W/A_r < H.
/// The `mean real pressure` line of `wearopt ARGS`' text report.
fn pressure_line(args: &[&str]) -> String {
    stdout_of(args)
        .lines()
        .find(|l| l.contains("mean real pressure"))
        .unwrap()
        .to_string()
}

#[test]
fn a_mean_real_pressure_above_the_hardness_is_explained() {
    let dir = std::env::temp_dir().join(format!("wearopt-pressure-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let hub = std::fs::read_to_string("problems/micro-gear.toml").unwrap();
    let stiff = hub
        .replace(
            "a = { material = \"polysilicon\" }",
            "a = { youngs_modulus = \"400 GPa\", poisson_ratio = 0.22 }",
        )
        .replace(
            "work_of_adhesion = \"0.1 J/m^2\"",
            "work_of_adhesion = \"0.1 J/m^2\"\nhardness = \"1 GPa\"",
        );
    let path = dir.join("stiff.toml");
    std::fs::write(&path, stiff).unwrap();
    let line = pressure_line(&["eval", path.to_str().unwrap()]);
    assert!(
        line.contains("GPa (above H = 1.00 GPa: A_r counts every contact as πRδ"),
        "{line}"
    );
    let html = stdout_of(&["eval", path.to_str().unwrap(), "--format", "html"]);
    assert!(html.contains("above H = 1.00 GPa"), "{html}");
    let line = pressure_line(&["eval", "problems/micro-gear.toml"]);
    assert!(!line.contains("above H"), "{line}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Where adhesion makes the contacts bear far more than the load (a
/// lubricated head–disk pad of 0.5 nm roughness in office air: 5 µN applied,
/// 62 mN on the contacts against the solid and capillary pulls), W/A_r alone
/// (27 kPa) would tell a designer the contacts are idle: the report adds what
/// they bear over A_r, and JSON carries it as `mean_contact_pressure` =
/// (elastic + plastic load)/A_r; so too when the pad is pulled apart by
/// 20 mN and W/A_r turns negative while the contacts bear compression. The
/// shipped hub, where the pulls are a tenth of W, keeps the plain line.
#[test]
fn contacts_that_bear_the_adhesive_pull_are_said_to() {
    let dir = std::env::temp_dir().join(format!("wearopt-contact-pressure-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("head.toml");
    std::fs::write(
        &path,
        r#"name = "Head-disk interface pad"
[contact]
load = "5 uN"
nominal_area = "2500 um^2"
sliding_distance = "10 km"
wear_coefficient = 1e-7
[bodies]
a = { youngs_modulus = "200 GPa", poisson_ratio = 0.25 }
b = { youngs_modulus = "200 GPa", poisson_ratio = 0.25 }
[interface]
hardness = "20 GPa"
work_of_adhesion = "0.04 J/m^2"
adhesion_model = "lennard_jones"
contact_angle = "70 deg"
[roughness]
sigma = "0.5 nm"
asperity_radius = "5 um"
asperity_density = "20 um^-2"
[environment]
relative_humidity = "40 %"
"#,
    )
    .unwrap();
    let file = path.to_str().unwrap();
    let line = pressure_line(&["eval", file]);
    assert!(
        line.contains("kPa (the contacts bear the load and the adhesive pulls besides: ")
            && line.contains("MPa over A_r)"),
        "{line}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&stdout_of(&["eval", file, "--format", "json"])).unwrap();
    let num = |k: &str| json[k].as_f64().unwrap();
    let contacts = (num("elastic_load") + num("plastic_load")) / num("real_area");
    assert!((num("mean_contact_pressure") / contacts - 1.0).abs() < 1e-12);
    assert!(num("mean_contact_pressure") > 1e4 * num("mean_real_pressure"));
    let html = stdout_of(&["eval", file, "--format", "html"]);
    assert!(html.contains("the contacts bear the load and the adhesive pulls besides"));
    // Pulled apart by 20 mN, the pad still touches: W/A_r is negative while
    // the contacts bear compression.
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(
        &path,
        text.replace(r#"load = "5 uN""#, r#"load = "-20 mN""#),
    )
    .unwrap();
    let line = pressure_line(&["eval", file]);
    assert!(
        line.contains("= -")
            && line.contains("the contacts bear the load and the adhesive pulls besides"),
        "{line}"
    );
    let line = pressure_line(&["eval", "problems/micro-gear.toml"]);
    assert!(!line.contains("("), "{line}");
    std::fs::remove_dir_all(&dir).ok();
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
            "tests/data/switch-study-jkr.toml",
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
    // The shipped micro-gear hub is plausible in every respect, φ0 too (the
    // Lennard-Jones law holds in the transition); under JKR φ0 is warned of.
    let t = stdout_of(&["eval", "problems/micro-gear.toml", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&t).unwrap();
    assert!(kinds_of(&v).is_empty(), "{v}");
    let jkr = crate::common::under_law("micro-gear", "jkr");
    let t = stdout_of(&["eval", jkr.to_str().unwrap(), "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&t).unwrap();
    assert_eq!(kinds_of(&v), vec!["outside_jkr_regime".to_string()]);
}

/// Wear depth, life, stiction and friction follow from the evaluation by their
/// definitions (the issue's contract): depth rate = wear rate / A_n, life = allowed
/// depth / depth rate, cycles = life / sliding per cycle, margin = pull-off / restoring
/// force with `sticks` iff ≥ 1, friction = τ A_r, coefficient = friction / load.
#[test]
fn designer_numbers_follow_their_definitions() {
    let (v, code) = eval_json_of(&[
        (
            "wear_area = \"plastic\"",
            "wear_area = \"plastic\"\nallowed_wear_depth = \"50 nm\"\nsliding_per_cycle = \"10 nm\"\nrestoring_force = \"1 aN\"",
        ),
        (
            "interatomic_distance = \"0.3 nm\"",
            "interatomic_distance = \"0.3 nm\"\nshear_strength = \"100 MPa\"",
        ),
    ]);
    assert_eq!(code, 0);
    let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("{k}: {v}"));
    let rel = |a: f64, b: f64| (a - b).abs() <= 1e-14 * b.abs();
    let an = 100e-12;
    assert!(rel(f("wear_depth_rate"), f("wear_rate") / an));
    assert!(rel(
        f("life_sliding_distance"),
        50e-9 / f("wear_depth_rate")
    ));
    assert!(rel(f("life_cycles"), f("life_sliding_distance") / 10e-9));
    let st = &v["stiction"];
    let pull_off = st["pull_off_force"].as_f64().unwrap();
    assert_eq!(pull_off, f("pull_off_force"));
    assert_eq!(st["restoring_force"].as_f64().unwrap(), 1e-18);
    assert!(rel(st["margin"].as_f64().unwrap(), pull_off / 1e-18));
    // The switch's pull-off (2.3e-15 N under JKR) beats a restoring force of 1 aN.
    assert!(pull_off > 1e-18, "{pull_off}");
    assert_eq!(st["verdict"], "sticks");
    assert!(rel(f("friction_force"), 100e6 * f("real_area")));
    assert!(rel(f("friction_coefficient"), f("friction_force") / 50e-6));
    // Without the inputs the keys are there, null.
    let (v, _) = eval_json_of(&[]);
    for k in [
        "life_sliding_distance",
        "life_cycles",
        "stiction",
        "friction_force",
        "friction_coefficient",
    ] {
        assert!(v.get(k).is_some_and(|x| x.is_null()), "{k}: {v}");
    }
    assert!(v["wear_depth_rate"].as_f64().unwrap() > 0.0);
}

#[test]
fn stiction_text_names_the_law() {
    for (law, words) in [
        ("lennard_jones", "adhesion law: Lennard-Jones sphere"),
        ("jkr", "adhesion law: JKR"),
    ] {
        let jkr = crate::common::under_law("gold-switch", law);
        let mut text = std::fs::read_to_string(jkr).unwrap();
        text = text.replacen(
            "wear_area = \"plastic\"",
            "wear_area = \"plastic\"\nrestoring_force = \"1 aN\"",
            1,
        );
        let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("stiction-law-{law}.toml"));
        std::fs::write(&path, text).unwrap();
        let t = stdout_of(&["eval", path.to_str().unwrap()]);
        assert!(t.contains("STICKS (margin ≥ 1)"), "{t}");
        assert!(t.contains(words), "{t}");
        // φ0 = 1.59: the transition, where JKR's verdict is weighed against
        // the Lennard-Jones law's; that law's own needs nothing beside it.
        assert_eq!(
            t.contains("JKR–DMT transition (0.3–3)"),
            law == "jkr",
            "{t}"
        );
    }
}

#[test]
fn friction_and_stiction_need_their_inputs() {
    let mut text = std::fs::read_to_string("tests/data/switch-study-jkr.toml").unwrap();
    text.push_str("\n[[constraint]]\nquantity = \"stiction_margin\"\nmax = 0.5\n");
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("needs-restoring.toml");
    std::fs::write(&path, text).unwrap();
    let err = stderr_failing(&["optimize", path.to_str().unwrap()], 2);
    assert!(
        err.contains("stiction_margin needs contact.restoring_force"),
        "{err}"
    );
}

/// A baseline that breaks a limit is said to be infeasible, with the limit, and no
/// improvement factor is claimed; constraint values carry units; the optimum's regime
/// warnings are in the text.
#[test]
fn optimize_text_says_an_infeasible_baseline_plainly() {
    let text = std::fs::read_to_string("tests/data/micro-gear-study-jkr.toml")
        .unwrap()
        .replacen("max = 1.0", "max = 0.3", 1);
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("tight-psi.toml");
    std::fs::write(&path, text).unwrap();
    let t = stdout_of(&["optimize", path.to_str().unwrap()]);
    assert!(t.contains("Status: optimal"), "{t}");
    assert!(
        t.contains(
            "the baseline is INFEASIBLE: plasticity_index = 0.4605 breaks its max of 0.3000"
        ),
        "{t}"
    );
    assert!(!t.contains("improvement ×"), "{t}");
    assert!(t.contains("WARNING: Tabor parameter"), "{t}");
    let j = stdout_of(&["optimize", path.to_str().unwrap(), "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&j).unwrap();
    assert_eq!(v["baseline_feasible"], false);
    assert_eq!(v["baseline_violations"][0]["quantity"], "plasticity_index");
    // Units on constraint values: the pull-off limit of the shipped study.
    let t = stdout_of(&["optimize", "tests/data/micro-gear-study-jkr.toml"]);
    assert!(t.contains("1.000 µN"), "{t}");
    assert!(t.contains("(improvement ×"), "{t}");
}

/// The polysilicon hub (φ0 = 0.374, in the transition) with a 2 µN spring: JKR's
/// pull-off (2.08e-63 N) releases it, the Lennard-Jones law's (5.999 µN; DMT with
/// van der Waals attraction gives 4.2785 µN, docs/model.md §7's worked scene) makes
/// it stick. The report gives both and says they disagree.
#[test]
fn stiction_under_both_laws_in_the_transition() {
    let text = std::fs::read_to_string(crate::common::under_law("micro-gear", "jkr"))
        .unwrap()
        .replacen(
            "wear_area = \"total\"",
            "wear_area = \"total\"\nrestoring_force = \"2 uN\"",
            1,
        );
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("hub-spring.toml");
    std::fs::write(&path, text).unwrap();
    let t = stdout_of(&["eval", path.to_str().unwrap()]);
    assert!(t.contains("→ releases (margin < 1)"), "{t}");
    assert!(
        t.contains("under the Lennard-Jones law instead: pull-off force 5.999 µN"),
        "{t}"
    );
    assert!(t.contains("they DISAGREE"), "{t}");
    let j = stdout_of(&["eval", path.to_str().unwrap(), "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&j).unwrap();
    assert_eq!(v["stiction"]["verdict"], "releases");
    assert_eq!(
        v["stiction"]["other_model"]["adhesion_model"],
        "lennard_jones"
    );
    assert_eq!(v["stiction"]["other_model"]["verdict"], "sticks");
    let m = v["stiction"]["other_model"]["margin"].as_f64().unwrap();
    assert!((m - 5.999e-6 / 2e-6).abs() < 1e-3 * m, "{m}");
}

/// The reader's notes reach eval JSON as words in `notes` (as before) and as values in
/// `input_note_details`, one per note, in the same order.
#[test]
fn input_notes_are_words_and_values() {
    let t = stdout_of(&["eval", "problems/micro-gear.toml", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&t).unwrap();
    let details = v["input_note_details"].as_array().unwrap();
    assert_eq!(details.len(), 1, "{details:?}");
    assert_eq!(details[0]["kind"], "hardness_from_catalogue");
    assert_eq!(details[0]["material"], "polysilicon");
    assert_eq!(details[0]["hardness"], 10e9);
    assert_eq!(
        v["notes"][0],
        "hardness taken from catalogue: polysilicon, 10 GPa"
    );
    let text = stdout_of(&["eval", "problems/micro-gear.toml"]);
    assert!(text.contains("note: hardness taken from catalogue: polysilicon, 10 GPa"));
}

/// A hard DLC-like slider pad whose wear counts plastic junctions only: with
/// H = 20 GPa the critical interference is Δc·σ = 1.9 µm against σ = 1.5 nm, so a
/// plastic asperity would stand ~1270 σ tall (weight e^{-8e5}): the model gives no
/// plastic area and zero wear. The text says why in words, never "10^-inf", and
/// JSON has `wear_rate` 0 with `log10_wear_rate` null.
#[test]
fn a_wear_too_small_for_a_double_is_said_in_words() {
    let text = "name = \"slider pad\"\n\
        [contact]\nload = \"20 uN\"\nnominal_area = \"2000 um^2\"\nsliding_distance = \"100 m\"\n\
        wear_coefficient = 1e-6\nwear_area = \"plastic\"\n\
        [bodies]\na = { youngs_modulus = \"170 GPa\", poisson_ratio = 0.25 }\n\
        b = { youngs_modulus = \"120 GPa\", poisson_ratio = 0.3 }\n\
        [interface]\nhardness = \"20 GPa\"\nwork_of_adhesion = \"0.06 J/m^2\"\n\
        interatomic_distance = \"0.3 nm\"\nadhesion_model = \"dmt\"\n\
        [roughness]\nsigma = \"1.5 nm\"\nasperity_radius = \"5 um\"\nasperity_density = \"2 um^-2\"\n";
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("reports-zero-wear.toml");
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    let t = stdout_of(&["eval", p]);
    // Too small for a double, not zero: the logarithm is the number (it was
    // printed as 0 with a null log10).
    assert!(
        t.contains("wear rate V/L = 10^-351300 m³/m  (negligible: below the smallest number a double holds;"),
        "{t}"
    );
    assert!(!t.contains("-inf") && !t.contains("NaN"), "{t}");
    let out = wearopt()
        .args(["eval", p, "--format", "json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["status"], "ok", "{v}");
    assert_eq!(v["wear_rate"].as_f64(), Some(0.0), "{v}");
    let log10 = v["log10_wear_rate"].as_f64().expect("a finite log10");
    assert!((-351_301.0..-351_300.0).contains(&log10), "{v}");
}

/// The hub under JKR: its plastic share is 6e-185 of the real area. The text
/// says "negligible" (with the share) instead of printing 3.578e-197 m² beside
/// µm², and the transition warning names the line a designer reads, not a JSON
/// key.
#[test]
fn negligible_parts_and_the_other_law_are_said_in_words() {
    let path = crate::common::under_law("micro-gear", "jkr");
    let t = stdout_of(&["eval", path.to_str().unwrap()]);
    assert!(
        t.contains("plastic junctions negligible (6e-185 of the total)"),
        "{t}"
    );
    assert!(
        t.contains("contacts: 168.3 in all; plastic: negligible"),
        "{t}"
    );
    assert!(
        t.contains("load carried: elastic 800.0 µN, plastic negligible"),
        "{t}"
    );
    assert!(
        !t.contains("e-197") && !t.contains("plastic fraction"),
        "{t}"
    );
    assert!(!t.contains("other_model"), "{t}");
    assert!(
        t.contains("evaluated alongside (the line \"under the Lennard-Jones law\")"),
        "{t}"
    );
    assert!(
        t.contains("under the Lennard-Jones law, valid in this transition"),
        "{t}"
    );
}

/// A nitride bump on a silicon substrate: without [interface] hardness the
/// model's H is the softer body's, the counterface's silicon (11 GPa), not the
/// nitride's 18 GPa (which understated ψ 1.6×), and the note says which body it
/// came from; with a hardness given, the note says it should be b's.
#[test]
fn the_hardness_is_the_softer_bodys() {
    let text = "name = \"nitride bump on silicon\"\n\
        [contact]\nload = \"5 uN\"\nnominal_area = \"25 um^2\"\nsliding_distance = \"10 mm\"\nwear_coefficient = 1e-5\n\
        [bodies]\na = { material = \"silicon nitride\" }\nb = { material = \"silicon\" }\n\
        [interface]\nwork_of_adhesion = \"50 mJ/m^2\"\nadhesion_model = \"dmt\"\n\
        [roughness]\nsigma = \"2 nm\"\nasperity_radius = \"500 nm\"\nasperity_density = \"20 um^-2\"\n";
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join("reports-softer-b.toml");
    std::fs::write(&path, text).unwrap();
    let t = stdout_of(&["eval", path.to_str().unwrap()]);
    assert!(t.contains("hardness H = 11.0 GPa"), "{t}");
    assert!(
        t.contains("note: hardness taken from catalogue: single-crystal silicon, 11 GPa — the counterface's (bodies.b): the model's H is the softer body's"),
        "{t}"
    );
    assert!(!t.contains("takes a as the rough, softer body"), "{t}");
    let given = text.replace("[interface]\n", "[interface]\nhardness = \"18 GPa\"\n");
    let path = dir.join("reports-softer-b-given.toml");
    std::fs::write(&path, given).unwrap();
    let t = stdout_of(&["eval", path.to_str().unwrap()]);
    assert!(t.contains("hardness H = 18.0 GPa"), "{t}");
    assert!(
        t.contains(
            "the model's H is the softer body's, so the interface.hardness given should be b's"
        ),
        "{t}"
    );
}

/// A cold contact under the stress-assisted law (the DMT sidewall at 1 K: ΔU/k_BT
/// ≈ 10⁴) wears below a double's range: the report says so in the law's words,
/// not the plastic-junction reason of an Archard scene, and gives k_eff as the
/// logarithm of rate/A_r (the two logarithms it prints) rather than 0.
#[test]
fn a_cold_stress_assisted_contact_is_worded_by_its_law() {
    let dir = std::env::temp_dir().join(format!("wearopt-cold-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = std::fs::read_to_string("problems/silicon-sidewall-wear.toml")
        .unwrap()
        .replace("temperature = \"300 K\"", "temperature = \"1 K\"");
    let path = dir.join("cold.toml");
    std::fs::write(&path, file).unwrap();
    let text = stdout_of(&["eval", path.to_str().unwrap()]);
    let rate = text.lines().find(|l| l.contains("wear rate V/L")).unwrap();
    assert!(
        rate.contains("below the smallest number a double holds; the thermally activated removal"),
        "{rate}"
    );
    let k = text.lines().find(|l| l.contains("k_eff =")).unwrap();
    assert!(
        k.contains("k_eff = 10^-") && k.contains("below the smallest number a double holds"),
        "{k}"
    );
    // k_eff = rate / A_r: the two logarithms printed above it.
    let log10 = |line: &str, key: &str| -> f64 {
        let at = line.find(key).unwrap() + key.len();
        line[at..]
            .split([' ', ')'])
            .next()
            .unwrap()
            .parse()
            .unwrap()
    };
    let area = text.lines().find(|l| l.contains("real area A_r")).unwrap();
    let want = log10(rate, "V/L = 10^") - log10(area, "; 10^");
    let got = log10(k, "k_eff = 10^");
    // Each printed to five digits (0.1 at this size).
    assert!(
        (got - want).abs() < 0.15,
        "{got} vs {want}: {k} / {rate} / {area}"
    );
    // The JSON carries k_eff's logarithm beside the 0 it underflows to.
    let json: serde_json::Value = serde_json::from_str(&stdout_of(&[
        "eval",
        path.to_str().unwrap(),
        "--format",
        "json",
    ]))
    .unwrap();
    assert_eq!(json["effective_wear_coefficient"], 0.0);
    let log10_k = json["log10_effective_wear_coefficient"].as_f64().unwrap();
    assert!((log10_k - want).abs() < 0.15, "{log10_k} vs {want}");
    std::fs::remove_dir_all(&dir).ok();
}
