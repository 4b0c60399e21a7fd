//! `pareto` against the probability of an event and `sweep`'s
//! `feasible_probability` columns on robust problem files (issue 54 item 4),
//! checked against `optimize` at one level, closed forms of the plasticity
//! index's law and an exact probability inside the counted interval.

use serde_json::Value;

use crate::common::{self, wearopt};
use wearopt::uq::distribution::{std_normal_cdf, std_normal_quantile};

const SHIPPED: &str = "problems/micro-gear-robust.toml";

/// A fresh folder beside the test binaries.
fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("rpareto-{name}"));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// sd of ln ψ in the shipped study: ψ ∝ H⁻¹ σ^½ R^-½ with H, σ, R lognormal
/// (factors 1.05, 1.2, 1.2), so ln ψ is normal and FORM exact for ψ > 1.
fn ln_psi_sd() -> f64 {
    (1.05_f64.ln().powi(2) + 0.5 * 1.2_f64.ln().powi(2)).sqrt()
}

/// The shipped study without its p95 and its stiction constraint (fast: the
/// objective at the medians), `extra` appended before `[optimizer]`.
fn plastic_study(dir: &std::path::Path, name: &str, extra: &str) -> std::path::PathBuf {
    let text = std::fs::read_to_string(SHIPPED)
        .unwrap()
        .replace("statistic = \"p95\"", "")
        .replace("samples = 256", "")
        .replace(
            "[[constraint]]                  # at most 1 hub in 1000 stuck to its pin\nevent = \"stiction\"\nprobability_max = 1e-3\n",
            "",
        )
        .replace("[optimizer]", &format!("{extra}\n[optimizer]"));
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path
}

const FRONT: &str = "[pareto]\nevent = { quantity = \"plasticity_index\", above = 1.0 }\npoints = 2\nprobability_max = 1e-2\nprobability_min = 1e-3\n";

/// Each point of the front is `optimize`'s robust optimum at its level (the
/// file's plasticity constraint moved to that level): the same design. And the
/// closed form: at the robust optimum ψ at the medians is exp(−β_t s),
/// β_t = −Φ⁻¹(level); its sampled P brackets the level; the tighter level
/// costs more wear.
#[test]
fn a_front_point_is_optimize_at_its_level() {
    let dir = scratch("level");
    let front = plastic_study(&dir, "front", FRONT);
    let out = common::stdout(
        wearopt().args(["pareto", front.to_str().unwrap(), "--format", "json"]),
        0,
    );
    let doc: Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(doc["status"], "ok", "{doc}");
    assert_eq!(doc["front_measure"], "probability");
    let points = doc["points"].as_array().unwrap();
    assert_eq!(points.len(), 2);
    assert_eq!(num(&points[0]["level"]), 1e-2);
    assert_eq!(num(&points[1]["level"]), 1e-3);
    // optimize with the plasticity constraint at 1e-2.
    let text = std::fs::read_to_string(&front).unwrap().replacen(
        "probability_max = 1e-3",
        "probability_max = 1e-2",
        1,
    );
    assert!(
        text.contains("above = 1.0 }\nprobability_max = 1e-2\n"),
        "{text}"
    );
    let at = dir.join("optimize-1e-2.toml");
    std::fs::write(&at, text).unwrap();
    let opt: Value = serde_json::from_slice(&common::stdout(
        wearopt().args(["optimize", at.to_str().unwrap(), "--format", "json"]),
        0,
    ))
    .unwrap();
    let r = &opt["robust"];
    assert_eq!(r["status"], "optimal", "{r}");
    for (name, v) in r["design"].as_object().unwrap() {
        let (a, b) = (num(v), num(&points[0]["design"][name]));
        assert!(
            ((a - b) / a).abs() < 1e-9,
            "{name}: optimize {a}, front {b}"
        );
    }
    let psi = num(&r["evaluation"]["indices"]["plasticity_index"]);
    let want = (std_normal_quantile(1e-2) * ln_psi_sd()).exp();
    assert!(
        ((psi - want) / want).abs() < 1e-5,
        "ψ {psi}, closed form {want}"
    );
    for p in points {
        assert_eq!(p["status"], "optimal", "{p}");
        assert_eq!(p["on_front"], true, "{p}");
        // Each chance constraint says which it is: here the front's own event.
        assert_eq!(
            p["chance_constraints"][0]["label"], "plasticity_index > 1",
            "{p}"
        );
        let level = num(&p["level"]);
        let i = &p["probability_interval"];
        assert!(num(&i[0]) <= level && level <= num(&i[1]), "{p}");
    }
    assert!(num(&points[1]["statistic"]) > num(&points[0]["statistic"]));
    // The nominal optimum sits on ψ = 1: plastic in half the hubs.
    let n = &doc["nominal_optimum"]["probability_interval"];
    assert!(num(&n[0]) <= 0.5 && 0.5 <= num(&n[1]), "{n}");
}

/// Same file, same bytes: the CSV of the front twice (the JSON carries times).
#[test]
fn a_probability_front_is_deterministic() {
    let dir = scratch("twice");
    let front = plastic_study(&dir, "front", FRONT);
    let run = || {
        common::stdout(
            wearopt().args(["pareto", front.to_str().unwrap(), "--format", "csv"]),
            0,
        )
    };
    let (a, b) = (run(), run());
    assert_eq!(a, b);
    let text = String::from_utf8(a).unwrap();
    assert!(text.starts_with("index,level,youngs_modulus,hardness,sigma,asperity_radius,statistic,statistic_low,statistic_high,at_medians,probability,probability_low,probability_high,status,on_front\n"), "{text}");
    assert_eq!(text.lines().count(), 3);
}

/// The sweep's feasible_probability at each design against the exact
/// P(ψ ≤ 1) = Φ(−ln ψ_m / s), ψ_m the design's plasticity index at the
/// medians (a column of its own through a loose constraint): inside the
/// counted 95 % interval of 256 common random numbers at every design.
/// The same bytes twice.
#[test]
fn feasible_probability_brackets_the_exact_probability() {
    let dir = scratch("sweep");
    let file = plastic_study(
        &dir,
        "sweep",
        "[[constraint]]\nquantity = \"plasticity_index\"\nmax = 100\n",
    );
    let run = || {
        common::stdout(
            wearopt().args(["sweep", file.to_str().unwrap(), "--samples", "8"]),
            0,
        )
    };
    let out = run();
    assert_eq!(out, run());
    let text = String::from_utf8(out).unwrap();
    let mut lines = text.lines().skip(1);
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |n: &str| {
        header
            .iter()
            .position(|c| *c == n)
            .unwrap_or_else(|| panic!("{n}: {header:?}"))
    };
    let (psi, p, lo, hi) = (
        col("plasticity_index"),
        col("feasible_probability_plasticity_index_above"),
        col("feasible_probability_plasticity_index_above_low"),
        col("feasible_probability_plasticity_index_above_high"),
    );
    let mut inside = 0;
    for line in lines {
        let cells: Vec<f64> = line
            .split(',')
            .map(|c| c.parse().unwrap_or(f64::NAN))
            .collect();
        let exact = std_normal_cdf(-cells[psi].ln() / ln_psi_sd());
        assert!(cells[lo] <= cells[p] && cells[p] <= cells[hi], "{line}");
        assert!(
            cells[lo] <= exact && exact <= cells[hi],
            "exact {exact}: {line}"
        );
        if exact > 0.01 && exact < 0.99 {
            inside += 1;
        }
    }
    assert!(
        inside >= 1,
        "no design with a probability strictly inside: {text}"
    );
}

/// The sweep's fingerprint covers the uncertainty section: another input law,
/// another fingerprint, so that their parts do not merge.
#[test]
fn the_sweep_fingerprint_covers_the_uncertainty_section() {
    let dir = scratch("print");
    let a = plastic_study(&dir, "a", "");
    let text = std::fs::read_to_string(&a).unwrap().replace(
        "median = \"10 GPa\", factor = 1.05",
        "median = \"10 GPa\", factor = 1.10",
    );
    let b = dir.join("b.toml");
    std::fs::write(&b, text).unwrap();
    let head = |f: &std::path::Path| {
        let out = common::stdout(
            wearopt().args(["sweep", f.to_str().unwrap(), "--samples", "1"]),
            0,
        );
        String::from_utf8(out)
            .unwrap()
            .lines()
            .next()
            .unwrap()
            .to_string()
    };
    assert_ne!(head(&a), head(&b));
}

/// Bad input: exit 2 naming the field.
#[test]
fn bad_probability_fronts_name_the_field() {
    let dir = scratch("bad");
    let cases = [
        ("[pareto]\nevent = \"stick\"\n", "pareto.event"),
        (
            "[pareto]\nevent = \"stiction\"\nprobability_max = 1e-3\nprobability_min = 1e-2\n",
            "pareto.probability_min",
        ),
        (
            "[pareto]\nevent = \"stiction\"\nprobability_max = 0.7\n",
            "pareto.probability_max",
        ),
        (
            "[pareto]\nevent = \"stiction\"\nadhesion = \"pull_off_force\"\n",
            "pareto.adhesion",
        ),
        (
            "[pareto]\nevent = \"stiction\"\npoints = 1\n",
            "pareto.points",
        ),
        (
            "[pareto]\nadhesion = \"pull_off_force\"\nprobability_min = 1e-4\n",
            "pareto.probability_min",
        ),
    ];
    for (k, (extra, key)) in cases.iter().enumerate() {
        let f = plastic_study(&dir, &format!("bad{k}"), extra);
        let err = String::from_utf8(common::stderr(
            wearopt().args(["pareto", f.to_str().unwrap()]),
            2,
        ))
        .unwrap();
        assert!(err.contains(key), "{extra}: {err}");
    }
    // No uncertainty at all.
    let text = std::fs::read_to_string("problems/micro-gear-study.toml").unwrap();
    assert!(!text.contains("[pareto]"));
    let f = dir.join("nominal.toml");
    std::fs::write(&f, format!("{text}\n[pareto]\nevent = \"stiction\"\n")).unwrap();
    let err = String::from_utf8(common::stderr(
        wearopt().args(["pareto", f.to_str().unwrap()]),
        2,
    ))
    .unwrap();
    assert!(err.contains("pareto.event"), "{err}");
    // A flag that a probability front has no use for.
    let f = plastic_study(&dir, "flag", FRONT);
    let err = String::from_utf8(common::stderr(
        wearopt().args([
            "pareto",
            f.to_str().unwrap(),
            "--adhesion",
            "pull_off_force",
        ]),
        2,
    ))
    .unwrap();
    assert!(err.contains("--adhesion"), "{err}");
}

const ADHESION_FRONT: &str = "[pareto]\nadhesion = \"pull_off_force\"\npoints = 3\n";

/// [`plastic_study`] under the DMT law, whose pull-off is cheap (ψ, what its
/// chance constraint holds, does not depend on the law): a robust front against
/// the pull-off force in about a second a level.
fn dmt_study(dir: &std::path::Path, name: &str, extra: &str) -> std::path::PathBuf {
    let path = plastic_study(dir, name, extra);
    let text = std::fs::read_to_string(&path).unwrap();
    let law = "adhesion_model = \"lennard_jones\"";
    assert!(text.contains(law));
    std::fs::write(&path, text.replace(law, "adhesion_model = \"dmt\"")).unwrap();
    path
}

/// A robust study against an adhesion measure: each point is `optimize`'s
/// robust optimum of the file with the pull-off force held at its level as a
/// `[[constraint]]` (the same design, to 1e-9), the first level is the file's
/// own robust optimum's pull-off, the pull-off at the medians meets each
/// level, each sampled chance constraint reaches down to its target at a
/// usable point, and holding the pull-off lower costs wear.
#[test]
fn a_robust_adhesion_front_point_is_optimize_with_its_row() {
    let dir = scratch("adhesion");
    let front = dmt_study(&dir, "front", ADHESION_FRONT);
    let run = wearopt()
        .args(["pareto", front.to_str().unwrap(), "--format", "json"])
        .assert()
        .code(0);
    let (out, err) = (&run.get_output().stdout, &run.get_output().stderr);
    // The robust part is no longer ignored, so nothing says it is.
    assert!(!String::from_utf8_lossy(err).contains("nominal study"));
    let doc: Value = serde_json::from_slice(out).unwrap();
    assert_eq!(doc["front_measure"], "adhesion", "{doc}");
    assert_eq!(doc["adhesion_measure"], "pull_off_force");
    assert_eq!(
        doc["held_chance_constraints"][0]["label"],
        "plasticity_index > 1"
    );
    let points = doc["points"].as_array().unwrap();
    assert_eq!(points.len(), 3);
    // The first level is the file's robust optimum's pull-off (to the round
    // trip through log10).
    let (t0, a0) = (
        num(&points[0]["target"]),
        num(&doc["robust_optimum"]["adhesion"]),
    );
    assert!(((t0 - a0) / a0).abs() < 1e-12, "{doc}");
    let usable: Vec<&Value> = points
        .iter()
        .filter(|p| p["status"] == "optimal" || p["status"] == "chance_constraint_violated")
        .collect();
    assert!(usable.len() >= 2, "{doc}");
    for p in &usable {
        let (a, t) = (num(&p["adhesion"]), num(&p["target"]));
        assert!(a <= t * (1.0 + 1e-6), "pull-off {a} above its level {t}");
        for c in p["chance_constraints"].as_array().unwrap() {
            let i = &c["probability_interval"];
            assert!(num(&i[0]) <= num(&c["target"]), "{c}");
        }
    }
    let last = usable.last().unwrap();
    assert!(
        num(&last["statistic"]) > num(&usable[0]["statistic"]),
        "{doc}"
    );
    assert!(
        num(&last["adhesion"]) < num(&usable[0]["adhesion"]),
        "{doc}"
    );
    // optimize with the pull-off row at the last usable point's level.
    let text = std::fs::read_to_string(&front).unwrap().replace(
        "[optimizer]",
        &format!(
            "[[constraint]]\nquantity = \"pull_off_force\"\nmax = {:e}\n\n[optimizer]",
            num(&last["target"])
        ),
    );
    let at = dir.join("optimize-row.toml");
    std::fs::write(&at, text).unwrap();
    let opt: Value = serde_json::from_slice(&common::stdout(
        wearopt().args(["optimize", at.to_str().unwrap(), "--format", "json"]),
        0,
    ))
    .unwrap();
    let r = &opt["robust"];
    assert_eq!(r["status"], last["status"], "{r}");
    for (name, v) in r["design"].as_object().unwrap() {
        let (a, b) = (num(v), num(&last["design"][name]));
        assert!(
            ((a - b) / a).abs() < 1e-9,
            "{name}: optimize {a}, front {b}"
        );
    }
}

/// The same front as text, CSV and HTML: the CSV's head and one row per level,
/// the text's and page's words; and the shipped example's file loads with its
/// robust study and its adhesion front.
#[test]
fn a_robust_adhesion_front_reads_in_every_format() {
    let dir = scratch("adhesion-formats");
    let front = dmt_study(
        &dir,
        "front",
        "[pareto]\nadhesion = \"pull_off_force\"\npoints = 2\n",
    );
    let csv = String::from_utf8(common::stdout(
        wearopt().args(["pareto", front.to_str().unwrap(), "--format", "csv"]),
        0,
    ))
    .unwrap();
    assert!(csv.starts_with("index,target,youngs_modulus,hardness,sigma,asperity_radius,adhesion,statistic,statistic_low,statistic_high,at_medians,status,on_front\n"), "{csv}");
    assert_eq!(csv.lines().count(), 3, "{csv}");
    let text = String::from_utf8(common::stdout(
        wearopt().args(["pareto", front.to_str().unwrap()]),
        0,
    ))
    .unwrap();
    assert!(
        text.contains("Robust front of wear_rate at the medians against pull_off_force"),
        "{text}"
    );
    assert!(
        text.contains("Held at every point: P(plasticity_index > 1) <= 0.0010"),
        "{text}"
    );
    assert!(text.contains("pull_off_force <= "), "{text}");
    let page = dir.join("front.html");
    let plot = dir.join("front.svg");
    common::stdout(
        wearopt().args([
            "pareto",
            front.to_str().unwrap(),
            "--format",
            "html",
            "--out",
            page.to_str().unwrap(),
            "--plot",
            plot.to_str().unwrap(),
        ]),
        0,
    );
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(html.contains("<svg"), "{html}");
    assert!(
        html.contains("P(plasticity_index &gt; 1) [95 %]")
            || html.contains("P(plasticity_index > 1) [95 %]"),
        "{html}"
    );
    assert!(std::fs::read_to_string(&plot).unwrap().contains("<svg"));
    let p = wearopt::problem::load(std::path::Path::new(
        "problems/micro-gear-robust-adhesion-front.toml",
    ))
    .unwrap();
    assert!(p.robust.is_robust() && p.robust.front.is_none());
    assert_eq!(
        p.study.pareto.map(|s| s.adhesion),
        Some(wearopt::optimize::AdhesionMeasure::PullOffForce)
    );
}
