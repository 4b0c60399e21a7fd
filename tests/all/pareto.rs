//! `wearopt pareto` and the sweep behind it: the front is non-dominated and
//! monotone, every point meets the study's constraints, the ends agree with
//! separate single-objective runs, the output does not depend on the thread
//! count, the SVG is well-formed with the expected elements, and the command
//! line end to end (formats, streaming, exit codes).

use std::path::{Path, PathBuf};

use crate::common::parse_xml;
use assert_cmd::Command;
use wearopt::model::{evaluate, EvaluationOptions, Scene, Status};
use wearopt::optimize::pareto::{pareto, Front, FrontStatus, Silent, PULL_OFF_FLOOR};
use wearopt::optimize::{
    optimize, AdhesionMeasure, Constraint, ConstraintQuantity, OptimizationStatus, ParetoDirection,
    ParetoSpec, SceneParameter, Study,
};
use wearopt::problem::Problem;
use wearopt::report::pareto as report;

fn wearopt() -> Command {
    Command::cargo_bin("wearopt").expect("binary builds")
}

fn problem_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("problems")
        .join(name)
}

/// The hub under JKR: the tests that pin the optimiser on JKR's landscape
/// (a pull-off of 1e-63 N at the baseline, a front with no trade-off at the
/// low end) keep it, now that the shipped hub is under the Lennard-Jones law.
fn jkr_hub() -> PathBuf {
    crate::common::under_law("micro-gear", "jkr")
}

fn load(name: &str) -> Problem {
    wearopt::problem::load(&problem_path(name)).expect("problem loads")
}

fn study(p: &Problem) -> Study<'_> {
    Study {
        scene: &p.scene,
        design: &p.study.design,
        objective: p.study.objective,
        constraints: &p.study.constraints,
        settings: &p.study.optimizer,
    }
}

fn spec(adhesion: AdhesionMeasure, points: usize, direction: ParetoDirection) -> ParetoSpec {
    ParetoSpec {
        adhesion,
        points,
        direction,
    }
}

/// The scene at a point's design.
fn scene_at(p: &Problem, design: &[f64]) -> Scene {
    let mut scene = p.scene.clone();
    for (v, &x) in p.study.design.iter().zip(design) {
        v.name.set(&mut scene, x);
    }
    scene
}

/// Every constraint of the study holds at every feasible point, re-evaluated
/// from its design alone (with the pull-off, whatever the constraints ask).
fn assert_points_meet_constraints(p: &Problem, front: &Front) {
    let options = EvaluationOptions {
        pull_off: true,
        ..Default::default()
    };
    for pt in &front.points {
        if !pt.feasible {
            continue;
        }
        let scene = scene_at(p, &pt.design);
        let ev = evaluate(&scene, &options);
        assert_eq!(ev.status, Status::Ok, "point {}", pt.index);
        for c in &p.study.constraints {
            let v = wearopt::optimize::functions::quantity_value(c.quantity, &ev, &scene)
                .unwrap_or(0.0);
            if let Some(max) = c.max {
                assert!(
                    v <= max * (1.0 + 1e-6),
                    "point {}: {} = {v} > {max}",
                    pt.index,
                    c.quantity
                );
            }
            if let Some(min) = c.min {
                assert!(
                    v >= min * (1.0 - 1e-6),
                    "point {}: {} = {v} < {min}",
                    pt.index,
                    c.quantity
                );
            }
        }
        for (v, &x) in p.study.design.iter().zip(&pt.design) {
            assert!(x >= v.min * (1.0 - 1e-12) && x <= v.max * (1.0 + 1e-12));
        }
    }
}

/// The front (feasible, not dominated) is monotone — adhesion gets worse and
/// wear better along it — and no point of it dominates another; every
/// dominated point is dominated by a front point.
fn assert_front_is_monotone_and_non_dominated(front: &Front) {
    let pref = |s: f64| match front.direction {
        ParetoDirection::Low => s,
        ParetoDirection::High => -s,
    };
    let f: Vec<_> = front.points.iter().filter(|p| p.on_front).collect();
    assert!(!f.is_empty());
    for w in f.windows(2) {
        assert!(pref(w[1].strength) > pref(w[0].strength), "{w:?}");
        assert!(w[1].objective < w[0].objective, "{w:?}");
    }
    for a in &f {
        for b in &f {
            if a.index != b.index {
                let dominates = pref(a.strength) <= pref(b.strength) && a.objective <= b.objective;
                assert!(!dominates, "{} dominates {}", a.index, b.index);
            }
        }
    }
    for d in front.points.iter().filter(|p| p.dominated) {
        assert!(!d.on_front);
        assert!(f.iter().any(|q| pref(q.strength) <= pref(d.strength) + 1e-6
            && q.objective <= d.objective * (1.0 + 1e-6)));
    }
    if let Some(k) = front.knee {
        assert!(front.points[k].on_front);
    }
}

/// The latch (under JKR) reaches its least wear over four decades of weak
/// pull-off: before, 11 of its 15 ε-points landed there, dominated, leaving a
/// 4-point front. Now the turn of the curve is found and the points asked for
/// all lie on the front, from the preferred (strong) end to the turn; the
/// dominated points past it come after and do not count.
#[test]
fn the_points_asked_for_describe_the_front_where_the_curve_turns() {
    let path = crate::common::under_law("latch-pareto", "jkr");
    let p = wearopt::problem::load(&path).expect("problem loads");
    let s = study(&p);
    let asked = 8;
    let front = pareto(
        &s,
        &spec(AdhesionMeasure::PullOffForce, asked, ParetoDirection::High),
        &Silent,
    )
    .unwrap();
    assert_eq!(front.status, FrontStatus::Ok);
    let t = front.turn.expect("the latch's curve turns");
    assert_eq!(t, asked - 1, "{:?}", front.points);
    assert_eq!(front.front_indices(), (0..asked).collect::<Vec<_>>());
    assert!(front.points.len() > asked);
    let turn = &front.points[t];
    // The turn has the study's least wear (to the sweep's tolerance), with more
    // adhesion than any point past it, each of which has no less wear.
    assert!(
        rel(turn.objective, front.least_wear.objective) <= 1e-6,
        "{} against {}",
        turn.objective,
        front.least_wear.objective
    );
    for d in &front.points[t + 1..] {
        assert!(d.dominated && d.feasible, "{d:?}");
        assert!(d.strength < turn.strength);
        assert!(d.objective >= turn.objective * (1.0 - 1e-6));
    }
    // The turn is sharp: the front point before it wears more than the
    // least wear, and the targets are spaced evenly from the strong end to it.
    assert!(front.points[t - 1].objective > turn.objective * (1.0 + 1e-6));
    let gaps: Vec<f64> = front.points[..asked]
        .windows(2)
        .map(|w| w[0].strength - w[1].strength)
        .collect();
    let (lo, hi) = gaps
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(l, h), &g| (l.min(g), h.max(g)));
    assert!(hi <= 2.0 * lo, "{gaps:?}");
    assert_points_meet_constraints(&p, &front);
    assert_front_is_monotone_and_non_dominated(&front);
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

#[test]
fn micro_gear_low_has_no_trade_off_and_ends_at_the_least_wear_design() {
    let p = wearopt::problem::load(&jkr_hub()).unwrap();
    let s = study(&p);
    let front = pareto(&s, &p.study.pareto.unwrap(), &Silent).unwrap();
    assert_eq!(front.points.len(), 15);
    assert_eq!(front.status, FrontStatus::NoTradeOff);
    assert_eq!(front.front_indices(), vec![0]);
    assert_eq!(front.knee, None, "a front of one design has no knee");
    assert!(front.floor_end);
    assert_points_meet_constraints(&p, &front);
    assert_front_is_monotone_and_non_dominated(&front);
    // The single front point is the study's own least-wear design.
    let single = optimize(&s).unwrap();
    let end = &front.points[0];
    assert!(
        rel(end.objective, single.objective) < 1e-6,
        "{} vs {}",
        end.objective,
        single.objective
    );
    // ... and the least pull-off the study can reach is below the floor too.
    let least_adhesion = optimize(&Study {
        objective: Some(wearopt::optimize::Objective::PullOffForce),
        ..s.clone()
    })
    .unwrap();
    assert!(least_adhesion.evaluation.pull_off_force.unwrap() < PULL_OFF_FLOOR);
    assert!(end.log10_adhesion < PULL_OFF_FLOOR.log10());
    // The whole curve rises: wear grows with adhesion here.
    for w in front.points.windows(2) {
        assert!(w[1].strength > w[0].strength && w[1].objective > w[0].objective);
    }
    let text = report::text(&p.name, &front, &p.study.constraints);
    assert!(
        text.contains("no trade-off: the least-wear design is also the least-adhesion design"),
        "{text}"
    );
}

#[test]
fn micro_gear_high_is_a_trade_off_whose_ends_agree_with_single_runs() {
    let p = wearopt::problem::load(&jkr_hub()).unwrap();
    let s = study(&p);
    let front = pareto(
        &s,
        &spec(AdhesionMeasure::PullOffForce, 7, ParetoDirection::High),
        &Silent,
    )
    .unwrap();
    assert_eq!(front.status, FrontStatus::Ok);
    assert_points_meet_constraints(&p, &front);
    assert_front_is_monotone_and_non_dominated(&front);
    let f: Vec<_> = front.points.iter().filter(|q| q.on_front).collect();
    assert!(f.len() >= 5, "{f:?}");
    // The most-adhesion end sits at the study's own cap on the pull-off and
    // agrees with a separate run of the study with the pull-off pinned there.
    let top = f[0];
    assert!(rel(top.adhesion, 100e-6) < 1e-6, "{}", top.adhesion);
    let mut pinned = p.study.constraints.clone();
    pinned.push(Constraint {
        quantity: ConstraintQuantity::PullOffForce,
        min: Some(100e-6),
        max: Some(100e-6),
        only_at_objective_humidity: false,
    });
    let single = optimize(&Study {
        constraints: &pinned,
        ..s.clone()
    })
    .unwrap();
    assert_eq!(single.status, OptimizationStatus::Optimal);
    assert!(
        rel(top.objective, single.objective) < 1e-5,
        "{} vs {}",
        top.objective,
        single.objective
    );
    // The least-wear end is the study's least-wear design.
    let last = f[f.len() - 1];
    let least = optimize(&s).unwrap();
    assert!(
        rel(last.objective, least.objective) < 1e-6,
        "{} vs {}",
        last.objective,
        least.objective
    );
    let knee = front.knee.expect("a curved front has a knee");
    assert!(knee != top.index && knee != last.index);
}

#[test]
fn elastic_adhesion_index_is_inverted_and_work_of_adhesion_is_fixed_in_the_scene() {
    let p = load("micro-gear.toml");
    let s = study(&p);
    // θ: a larger θ is less adhesion, so "low" runs from the largest θ down.
    let theta = pareto(
        &s,
        &spec(
            AdhesionMeasure::ElasticAdhesionIndex,
            6,
            ParetoDirection::Low,
        ),
        &Silent,
    )
    .unwrap();
    assert_ne!(theta.status, FrontStatus::Infeasible);
    assert_points_meet_constraints(&p, &theta);
    assert_front_is_monotone_and_non_dominated(&theta);
    let feasible: Vec<_> = theta.points.iter().filter(|q| q.feasible).collect();
    for w in feasible.windows(2) {
        assert!(
            w[1].adhesion < w[0].adhesion,
            "θ falls along a low sweep: {w:?}"
        );
    }
    // γ: every point's work of adhesion is its target.
    let gamma = pareto(
        &s,
        &spec(AdhesionMeasure::WorkOfAdhesion, 5, ParetoDirection::High),
        &Silent,
    )
    .unwrap();
    assert_ne!(gamma.status, FrontStatus::Infeasible);
    assert_points_meet_constraints(&p, &gamma);
    assert_front_is_monotone_and_non_dominated(&gamma);
    let gi = p
        .study
        .design
        .iter()
        .position(|d| d.name == SceneParameter::WorkOfAdhesion)
        .unwrap();
    for q in &gamma.points {
        if q.target_kind == "equal" && q.feasible {
            assert!(rel(q.design[gi], q.target) < 1e-12, "{q:?}");
            assert!(rel(q.adhesion, q.target) < 1e-12);
        }
    }
    // The γ sweep covers the design bounds (nothing else limits γ here).
    let (lo, hi) = gamma.strength_range;
    assert!((lo - 5e-3f64.log10()).abs() < 0.011 && (hi - 0.2f64.log10()).abs() < 0.011);
}

#[test]
fn output_is_identical_for_one_and_two_threads() {
    let p = load("micro-gear.toml");
    let s = study(&p);
    let sp = spec(AdhesionMeasure::PullOffForce, 6, ParetoDirection::High);
    let run = |k: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(k)
            .build()
            .unwrap()
            .install(|| {
                let f = pareto(&s, &sp, &Silent).unwrap();
                (
                    report::json(&p.name, &f),
                    report::csv(&f),
                    report::svg(&p.name, &f),
                )
            })
    };
    assert_eq!(run(1), run(2));
}

#[test]
fn streamed_pieces_make_the_whole_document() {
    let p = load("micro-gear.toml");
    let s = study(&p);
    let sp = spec(AdhesionMeasure::PullOffForce, 4, ParetoDirection::High);
    // An observer that rebuilds the CSV and JSON from the points as they come.
    struct Collect(std::sync::Mutex<Vec<wearopt::optimize::pareto::FrontPoint>>);
    impl wearopt::optimize::pareto::Observer for Collect {
        fn point_done(&self, p: &wearopt::optimize::pareto::FrontPoint) {
            self.0.lock().unwrap().push(p.clone());
        }
    }
    let c = Collect(Default::default());
    let front = pareto(&s, &sp, &c).unwrap();
    let streamed = c.0.into_inner().unwrap();
    assert_eq!(streamed, front.points);
    let json = report::json(&p.name, &front);
    let v: serde_json::Value = serde_json::from_str(&json).expect("valid JSON");
    for key in ["status", "adhesion_measure", "points", "knee"] {
        assert!(v.get(key).is_some(), "{key}");
    }
    assert_eq!(v["adhesion_measure"], "pull_off_force");
    let pt = &v["points"][0];
    for key in ["adhesion", "wear_rate", "status", "dominated", "design"] {
        assert!(pt.get(key).is_some(), "{key}");
    }
    let csv = report::csv(&front);
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "index,target,adhesion,log10_adhesion,wear_rate,objective,status,dominated,on_front,sigma,asperity_radius,work_of_adhesion"
    );
    assert_eq!(lines.count(), front.points.len());
    assert!(front.points.len() >= 4);
}

#[test]
fn plot_is_well_formed_svg_with_front_knee_and_baseline() {
    let p = load("micro-gear.toml");
    let s = study(&p);
    let front = pareto(
        &s,
        &spec(AdhesionMeasure::PullOffForce, 7, ParetoDirection::High),
        &Silent,
    )
    .unwrap();
    let svg = report::svg(&p.name, &front);
    let elements = parse_xml(&svg).expect("well-formed XML");
    assert_eq!(elements[0].name, "svg");
    let count = |name: &str| elements.iter().filter(|e| e.name == name).count();
    assert!(count("polyline") >= 2, "curve and front lines");
    assert!(count("circle") >= 5, "front markers");
    let series: Vec<&str> = elements
        .iter()
        .filter(|e| {
            e.name == "g" && e.attributes.get("class").map(String::as_str) == Some("series")
        })
        .filter_map(|e| e.attributes.get("data-name").map(String::as_str))
        .collect();
    assert!(
        series.iter().any(|s| s.starts_with("Pareto front")),
        "{series:?}"
    );
    assert!(
        series.contains(&"knee") && series.contains(&"baseline design"),
        "{series:?}"
    );
    // The tables' units (the prefix of the largest value), not SI's base units.
    assert!(
        svg.contains("pull-off force (µN)") && svg.contains("wear rate (µm³/m)"),
        "{svg}"
    );
    assert!(svg.contains("<title>"));
    // The front spans decades of pull-off (a log x axis, decade ticks) and less
    // than one of wear (a linear y axis fitted to what is drawn): at least four
    // labels each.
    assert!(
        svg.contains(">0.01</text>") && svg.contains(">10</text>"),
        "log x axis"
    );
    let y_axis = &svg[svg.find("<g class=\"y-axis\">").unwrap()..];
    let y_axis = &y_axis[..y_axis.find("</g>").unwrap()];
    assert!(
        y_axis.matches("text-anchor=\"end\"").count() >= 4,
        "linear y axis: {y_axis}"
    );
}

#[test]
fn cli_streams_csv_and_json_and_writes_the_plot() {
    let dir = std::env::temp_dir().join(format!("wearopt-pareto-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let plot = dir.join("front.svg");
    let out = wearopt()
        .args(["pareto", problem_path("micro-gear.toml").to_str().unwrap()])
        .args([
            "--points",
            "5",
            "--format",
            "csv",
            "--plot",
            plot.to_str().unwrap(),
        ])
        .env("CI", "true")
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = String::from_utf8(out.stdout).unwrap();
    // Five points on the front; dominated points past a turn come on top.
    let on_front = csv
        .lines()
        .skip(1)
        .filter(|l| l.split(',').nth(8) == Some("true"))
        .count();
    assert!(csv.lines().count() >= 6, "{csv}");
    assert!(
        on_front <= 5 && (on_front == 5 || csv.lines().count() == 6),
        "{csv}"
    );
    assert!(csv.starts_with("index,target,adhesion,"));
    assert!(parse_xml(&std::fs::read_to_string(&plot).unwrap()).is_ok());

    let out = wearopt()
        .args(["pareto", jkr_hub().to_str().unwrap()])
        .args(["--points", "3", "--format", "json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    assert_eq!(v["status"], "no_trade_off");
    assert_eq!(v["points"].as_array().unwrap().len(), 3);
    assert!(v["knee"].is_null());

    let out = wearopt()
        .args(["pareto", jkr_hub().to_str().unwrap()])
        .args(["--points", "3"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.contains("no trade-off: the least-wear design is also the least-adhesion design"));
    assert!(text.contains("plasticity_index ≤ 1"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn cli_refuses_a_file_without_pareto_and_bad_points() {
    let file = problem_path("micro-gear-study.toml");
    let out = wearopt()
        .args(["pareto", file.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("micro-gear-study.toml") && err.contains("[pareto]"),
        "{err}"
    );
    assert!(err.contains("adhesion = \"pull_off_force\""), "{err}");

    for bad in ["1", "201"] {
        let out = wearopt()
            .args([
                "pareto",
                problem_path("micro-gear.toml").to_str().unwrap(),
                "--points",
                bad,
            ])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "--points {bad}");
        assert!(String::from_utf8(out.stderr).unwrap().contains("--points"));
    }
    let out = wearopt()
        .args(["pareto", "no/such/file.toml"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

/// A study without a `[pareto]` section draws its front from the command line:
/// any of --points, --adhesion, --direction, the rest defaulting to
/// pull_off_force, 15 points and low; the same front as the section would give.
/// Without any of them the error says how; a bad name exits 2 naming the choices.
#[test]
fn the_front_can_be_asked_for_on_the_command_line() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/micro-gear-study-jkr.toml");
    let file = file.to_str().unwrap();
    let json = |args: &[&str]| -> serde_json::Value {
        let out = wearopt()
            .args(["pareto", file, "--format", "json"])
            .args(args)
            .assert()
            .code(0)
            .get_output()
            .stdout
            .clone();
        serde_json::from_slice(&out).unwrap()
    };
    let v = json(&["--points", "3"]);
    assert_eq!(v["adhesion_measure"], "pull_off_force");
    assert_eq!(v["direction"], "low");
    assert_eq!(v["points"].as_array().unwrap().len(), 3);
    let v = json(&[
        "--adhesion",
        "elastic_adhesion_index",
        "--direction",
        "high",
        "--points",
        "3",
    ]);
    assert_eq!(v["adhesion_measure"], "elastic_adhesion_index");
    assert_eq!(v["direction"], "high");
    // The same front as a [pareto] section with those values.
    let text = std::fs::read_to_string(file).unwrap()
        + "\n[pareto]\nadhesion = \"elastic_adhesion_index\"\ndirection = \"high\"\npoints = 3\n";
    let with_section = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("study-with-pareto.toml");
    std::fs::write(&with_section, text).unwrap();
    let out = wearopt()
        .args(["pareto", with_section.to_str().unwrap(), "--format", "json"])
        .assert()
        .code(0)
        .get_output()
        .stdout
        .clone();
    let w: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(w["points"], v["points"]);
    let err = |args: &[&str]| {
        let out = wearopt()
            .args(["pareto", file])
            .args(args)
            .assert()
            .code(2)
            .get_output()
            .stderr
            .clone();
        String::from_utf8(out).unwrap()
    };
    assert!(err(&[]).contains("--adhesion, --points, --direction"));
    let e = err(&["--adhesion", "pulloff"]);
    assert!(
        e.contains("--adhesion \"pulloff\"")
            && e.contains("pull_off_force, work_of_adhesion, elastic_adhesion_index"),
        "{e}"
    );
    assert!(err(&["--direction", "up"]).contains("low, high"));
}

/// The range's strong end is the strongest adhesion any design reaches under
/// the study's rows and A_r ≤ A_n, found as an optimisation problem, not the
/// strongest box corner that is in range (`tests/data/latch_area_end.toml`:
/// the corner that bounds it has A_r > A_n; the corners gave 34.3 mN). The
/// end is checked by independent runs of the study with the pull-off bounded
/// below and A_r ≤ A_n as a row: 0.99× the end is feasible (`optimal`), 1.02×
/// is `infeasible`, naming both limits as the conflict. The end is on the
/// front (not dominated).
#[test]
fn the_strong_end_is_the_strongest_design_not_the_strongest_corner_in_range() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/latch_area_end.toml");
    let p = wearopt::problem::load(&path).unwrap();
    let s = study(&p);
    let front = pareto(&s, &p.study.pareto.unwrap(), &Silent).unwrap();
    let top = &front.points[0];
    assert!(top.on_front && top.feasible, "{top:?}");
    assert!((top.strength - front.strength_range.1).abs() < 1e-9);
    assert!(top.adhesion > 40e-3, "{}", top.adhesion);
    for (factor, feasible) in [(0.99, true), (1.02, false)] {
        let mut c = p.study.constraints.clone();
        c.push(Constraint {
            quantity: ConstraintQuantity::PullOffForce,
            min: Some(factor * top.adhesion),
            max: None,
            only_at_objective_humidity: false,
        });
        c.push(Constraint {
            quantity: ConstraintQuantity::RealAreaFraction,
            min: None,
            max: Some(1.0),
            only_at_objective_humidity: false,
        });
        let o = optimize(&Study {
            constraints: &c,
            ..s.clone()
        })
        .unwrap();
        let want = if feasible {
            OptimizationStatus::Optimal
        } else {
            OptimizationStatus::Infeasible
        };
        assert_eq!(o.status, want, "pull-off ≥ {factor} × {}", top.adhesion);
        if !feasible {
            // Both limits hold the violation up: the pull-off (violated) and
            // A_r ≤ A_n (met exactly); a least-violating design is no optimum,
            // so no row carries a multiplier.
            for q in [
                ConstraintQuantity::PullOffForce,
                ConstraintQuantity::RealAreaFraction,
            ] {
                assert!(o.conflicting.contains(&q), "{:?}", o.conflicting);
            }
            assert!(o
                .constraints
                .iter()
                .all(|c| c.multiplier == 0.0 && c.shadow_price == 0.0));
        }
    }
}

/// Over a humidity range every limit holds at each humidity, but a front's
/// adhesion is one number per design: it is measured at the objective's
/// humidity, and its ε-row holds there only. Held at every humidity, as it
/// once was, one pull-off could not be met at all where the coating lets water
/// condense (the pull-off grows with RH): on the coating study with contact
/// angles up to 70° (water condenses at every design) every point came out
/// `infeasible` and the front said the study had no feasible point, though its
/// own optimum is feasible. Each point is what `eval` says at that humidity.
#[test]
fn a_front_over_a_humidity_range_is_measured_at_one_humidity() {
    let text = std::fs::read_to_string(problem_path("micro-gear-coating-study.toml"))
        .unwrap()
        .replace(
            "contact_angle = { min = \"0 deg\", max = \"110 deg\" }",
            "contact_angle = { min = \"0 deg\", max = \"70 deg\" }",
        )
        .replace("max = \"50 uN\"", "max = \"5 mN\"");
    assert!(text.contains("max = \"70 deg\"") && text.contains("5 mN"));
    let file =
        std::env::temp_dir().join(format!("wearopt-wet-coating-{}.toml", std::process::id()));
    std::fs::write(&file, text).unwrap();
    let p = wearopt::problem::load(&file).unwrap();
    let front = pareto(
        &study(&p),
        &spec(AdhesionMeasure::PullOffForce, 5, ParetoDirection::Low),
        &Silent,
    )
    .unwrap();
    assert_ne!(front.status, FrontStatus::Infeasible);
    // The worst humidity for wear at the baseline (bare oxide) is the wettest.
    assert_eq!(front.adhesion_humidity, Some(0.9));
    for pt in &front.points {
        assert!(pt.feasible, "{pt:?}");
        assert_eq!(pt.status, OptimizationStatus::Optimal, "{pt:?}");
        let scene = wearopt::optimize::functions::at_humidity(scene_at(&p, &pt.design), 0.9);
        let ev = evaluate(&scene, &EvaluationOptions::default());
        assert_eq!(ev.status, Status::Ok);
        assert!(
            rel(ev.pull_off_force.unwrap(), pt.adhesion) < 1e-9,
            "{pt:?}"
        );
        assert!(rel(ev.wear_rate, pt.wear_rate) < 1e-9, "{pt:?}");
    }
    // The reachable range runs from the least-wear design to the bare oxide.
    let (lo, hi) = front.strength_range;
    assert!(hi - lo > 2.0, "{lo} {hi}");
    // Said in every format.
    let json = report::json("wet coating", &front);
    assert!(json.contains("\"adhesion_humidity\": 0.9"), "{json}");
    let text = report::text("wet coating", &front, &p.study.constraints);
    assert!(text.contains("taken at RH = 90.00 %"), "{text}");
    let _ = std::fs::remove_file(&file);
}
