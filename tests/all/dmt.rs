//! The DMT asperity law (MODEL.md §7): limits, the facts the separation search
//! relies on, MODEL.md's worked hub, and the problem-file keys.

use std::path::Path;

use wearopt::model::{
    evaluate, evaluate_with_other, find_pull_off, landscape, solve_separation, AdhesionModel,
    AsperityLaw, Attraction, AttractionKind, Coefficients, EvaluationOptions, Model, Quadrature,
    SeparationOutcome, Status,
};

fn dmt(c: Coefficients, attraction: Attraction) -> Model {
    Model::with_law(c, AsperityLaw::Dmt(attraction), Quadrature::default())
}

const ATTRACTIONS: [Attraction; 6] = [
    Attraction::VanDerWaals { range: 1e-4 },
    Attraction::VanDerWaals { range: 0.1 },
    Attraction::VanDerWaals { range: 10.0 },
    Attraction::Dugdale { range: 1e-6 },
    Attraction::Dugdale { range: 0.1 },
    Attraction::Dugdale { range: 1e3 },
];

/// γ = 0: DMT is exactly the JKR model at γ = 0 (MODEL.md §7 "checks"): both are
/// Greenwood–Williamson with the same plastic junctions, bit for bit.
#[test]
fn no_adhesion_is_identical_to_jkr() {
    for c_h in [1e-3, 1.0, 5.12, 1e3, f64::INFINITY] {
        let c = Coefficients::new(0.0, c_h);
        let jkr = Model::new(c);
        for a in ATTRACTIONS {
            let m = dmt(c, a);
            assert_eq!(m.critical_interference(), jkr.critical_interference());
            for h in [-4.0, -1.0, 0.0, 0.5, 3.0, 12.0, 40.0, 60.0] {
                let (x, y) = (m.at(h), jkr.at(h));
                assert_eq!(x, y, "c_h={c_h} {a:?} h={h}");
                assert_eq!(x.noncontact_load().value(), 0.0);
            }
        }
    }
}

/// Δc = c_h² under DMT (Hertz mean contact pressure K a/(πR) reaches H), ∞ for H = ∞.
#[test]
fn critical_interference_is_c_h_squared() {
    let c = Coefficients::from_indices(184.0, 1.309e5);
    let m = dmt(c, ATTRACTIONS[1]);
    assert!((m.critical_interference() / (c.c_h * c.c_h) - 1.0).abs() < 1e-15);
    assert!((m.transition.jump / c.c_h.powi(3) - 1.0).abs() < 1e-15);
    let m = dmt(Coefficients::new(1.0, f64::INFINITY), ATTRACTIONS[0]);
    assert!(m.critical_interference().is_infinite());
}

/// The non-contact load is ≤ 0, and at h = 40 and 60 under van der Waals it is the
/// whole load: non-zero, finite, and the power law -c_0 √(2π) z0²/(z0+h)² to
/// leading order (MODEL.md §7).
#[test]
fn van_der_waals_tail_is_the_whole_load_far_out() {
    let c = Coefficients::from_indices(184.0, 1.309e5);
    for z0 in [1e-4, 0.1, 10.0] {
        let m = dmt(c, Attraction::VanDerWaals { range: z0 });
        for h in [40.0, 60.0, 1e3, 1e6] {
            let at = m.at(h);
            let p = at.load();
            assert!(p.value() < 0.0 && p.value().is_finite(), "{z0} {h}: {p:?}");
            let lead = -c.c_0 * 2.5066282746310002 * (z0 / (z0 + h)).powi(2);
            let b2 = (z0 + h).powi(2);
            let series = lead * (1.0 + 3.0 / b2 + 15.0 / (b2 * b2));
            // The next term is 105/b⁶ of the leading one.
            let next = 105.0 / (b2 * b2 * b2);
            assert!(
                (p.value() / series - 1.0).abs() < 2.0 * next + 1e-14,
                "{z0} {h}"
            );
            // The contact share is e^{-h²/2} small, but kept in scaled form.
            assert!(at.contact_load().value() >= 0.0 || h < 41.0);
            assert!(at.area().ln_abs().is_finite());
        }
    }
    for a in ATTRACTIONS {
        let m = dmt(c, a);
        for h in [-4.0, -1.0, 0.0, 0.3, 2.0, 5.0, 20.0, 60.0] {
            let n = m.at(h).noncontact_load();
            assert!(n.mantissa <= 0.0, "{a:?} {h}: {n:?}");
            assert!(n.mantissa.is_finite() && n.exponent.is_finite());
        }
    }
}

/// dP̄/dh and d²P̄/dh² from the model against central differences of P̄ and of
/// dP̄/dh (the derivatives the Newton and Halley steps use), for both attractions,
/// with and without plasticity (step 1e-5: truncation ~1e-11, rounding ~1e-11 of
/// the scale).
#[test]
fn slope_and_curvature_match_central_differences() {
    let mut cases: Vec<Coefficients> = [(184.0, 1.309e5), (1.0, 1.0), (1e-3, 1e-2), (10.0, 1.0)]
        .iter()
        .map(|&(theta, lambda)| Coefficients::from_indices(theta, lambda))
        .collect();
    cases.push(Coefficients::new(1.0, f64::INFINITY));
    for c in cases {
        for a in ATTRACTIONS {
            let m = dmt(c, a);
            for h in [-2.0, -0.5, 0.0, 0.7, 1.0, 3.0, 10.0] {
                let d = 1e-5;
                let (lo, at, hi) = (m.at(h - d), m.at(h), m.at(h + d));
                let fd = (hi.load().value() - lo.load().value()) / (2.0 * d);
                let got = at.dload_dh().value();
                let scale = got.abs().max(at.load().value().abs()).max(1e-300);
                assert!(
                    (fd - got).abs() <= 1e-7 * scale,
                    "P̄' θ={} {a:?} h={h}: {got} vs {fd}",
                    c.elastic_adhesion_index()
                );
                let fd2 = (hi.dload_dh().value() - lo.dload_dh().value()) / (2.0 * d);
                let got2 = at.d2load_dh2().value();
                let scale2 = got2.abs().max(scale);
                assert!(
                    (fd2 - got2).abs() <= 1e-7 * scale2,
                    "P̄'' θ={} {a:?} h={h}: {got2} vs {fd2}",
                    c.elastic_adhesion_index()
                );
            }
        }
    }
}

/// The single-minimum fact (separation.rs module docs): P̄' changes sign exactly
/// once on a fine grid, at the minimum the landscape reports; and the single-root
/// facts: a compressive load has one root, a tensile one above the minimum one on
/// the falling branch.
#[test]
fn one_minimum_and_the_roots_the_rules_choose() {
    for (theta, lambda) in [(184.0, 1.309e5), (10.0, 1.0), (1.0, 1e-2), (1e-3, 1e-6)] {
        let c = Coefficients::from_indices(theta, lambda);
        for a in ATTRACTIONS {
            let m = dmt(c, a);
            let mut changes = Vec::new();
            let mut prev = m.at(-6.0).dload_dh().signum();
            let mut h = -6.0;
            while h < 80.0 {
                h += if h < 20.0 { 0.01 } else { 0.1 };
                let s = m.at(h).dload_dh().signum();
                if s != prev && s != 0.0 {
                    changes.push(h);
                }
                prev = s;
            }
            assert_eq!(changes.len(), 1, "θ={theta} λ={lambda} {a:?}: {changes:?}");
            let land = landscape(&m);
            assert_eq!(land.critical_points.len(), 1, "{a:?}");
            let po = find_pull_off(&m).expect("a pull-off with adhesion");
            assert!((po.separation - changes[0]).abs() < 0.02, "{a:?}");
            let p_min = po.load.value();
            // Compressive: one root, and P̄ < target to its right.
            for target in [1e-6, 0.01, 1.0, 100.0] {
                match solve_separation(&m, target) {
                    SeparationOutcome::Contact { separation, .. } => {
                        // The root to ~1e-9 in h (P̄ is ill-conditioned where the contact
                        // and non-contact shares nearly cancel): P̄ brackets the target.
                        let d = 1e-9 * separation.abs().max(1.0);
                        let (l, r) = (m.at(separation - d), m.at(separation + d));
                        assert!(
                            l.load().value() >= target && r.load().value() <= target,
                            "{a:?} {target}: {separation}"
                        );
                        assert!(m.at(separation + 0.1).load().value() < target);
                    }
                    other => panic!("{a:?} {target}: {other:?}"),
                }
            }
            // Tensile above the minimum: the root left of the minimum.
            if p_min.is_normal() {
                let target = 0.5 * p_min;
                match solve_separation(&m, target) {
                    SeparationOutcome::Contact { separation, .. } => {
                        assert!(separation < po.separation, "{a:?}");
                        let d = 1e-9 * separation.abs().max(1.0);
                        let (l, r) = (m.at(separation - d), m.at(separation + d));
                        assert!(
                            l.load().value() >= target && r.load().value() <= target,
                            "{a:?} {target}: {separation}"
                        );
                    }
                    other => panic!("{a:?}: {other:?}"),
                }
                assert!(matches!(
                    solve_separation(&m, 2.0 * p_min),
                    SeparationOutcome::Separated { .. }
                ));
            }
        }
    }
}

fn hub() -> wearopt::problem::Problem {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear.toml"
    ));
    wearopt::problem::load(path).expect("the hub loads")
}

/// MODEL.md §7's worked scene: the polysilicon hub's pull-off under the three laws
/// (4.2785 µN van der Waals, 3.61e-21 N Dugdale, 2.08e-63 N JKR) and the pull of the
/// non-contacting asperities at 800 µN (≈ 51 µN, ≈ 14 µN).
#[test]
fn hub_reproduces_model_md() {
    let mut scene = hub().scene;
    scene.load = 800e-6;
    let opts = EvaluationOptions::default();
    scene.adhesion_model = AdhesionModel::Jkr;
    let jkr = evaluate(&scene, &opts);
    scene.adhesion_model = AdhesionModel::Dmt;
    scene.attraction = AttractionKind::VanDerWaals;
    let vdw = evaluate(&scene, &opts);
    scene.attraction = AttractionKind::Dugdale;
    let dug = evaluate(&scene, &opts);
    let po = |e: &wearopt::model::Evaluation| e.pull_off_force.unwrap();
    assert!((po(&vdw) / 4.2785e-6 - 1.0).abs() < 2e-5, "{}", po(&vdw));
    assert!((po(&dug) / 3.61e-21 - 1.0).abs() < 2e-3, "{}", po(&dug));
    assert!((po(&jkr) / 2.08e-63 - 1.0).abs() < 3e-3, "{}", po(&jkr));
    let nc = |e: &wearopt::model::Evaluation| -e.noncontact_load.unwrap();
    assert!((nc(&vdw) / 51e-6 - 1.0).abs() < 0.01, "{}", nc(&vdw));
    assert!((nc(&dug) / 14e-6 - 1.0).abs() < 0.04, "{}", nc(&dug));
    assert_eq!(jkr.noncontact_load, Some(0.0));
    let a = vdw.hamaker_constant.unwrap();
    assert!((a / 3.393e-19 - 1.0).abs() < 1e-3, "{a}");
    // Load balance: the shares add up to the load.
    let sum = vdw.elastic_load + vdw.plastic_load + vdw.noncontact_load.unwrap();
    assert!((sum / 800e-6 - 1.0).abs() < 1e-12, "{sum}");
}

/// φ0 = 0.374 (transition): `other_model` carries the Lennard-Jones law's
/// numbers, which equal that law's own evaluation, beside JKR and beside DMT.
#[test]
fn transition_scene_reports_the_other_law() {
    let mut scene = hub().scene;
    scene.adhesion_model = AdhesionModel::Jkr;
    let opts = EvaluationOptions::default();
    let ev = evaluate_with_other(&scene, &opts);
    let om = ev.other_model.expect("0.3 ≤ φ0 ≤ 3");
    assert_eq!(om.adhesion_model, AdhesionModel::LennardJones);
    let mut lj_scene = scene.clone();
    lj_scene.adhesion_model = AdhesionModel::LennardJones;
    let d = evaluate(&lj_scene, &opts);
    assert_eq!(om.pull_off_force, d.pull_off_force);
    assert_eq!(om.wear_rate, d.wear_rate);
    assert_eq!(om.nondimensional_separation, d.nondimensional_separation);
    let mut dmt_scene = scene.clone();
    dmt_scene.adhesion_model = AdhesionModel::Dmt;
    let beside_dmt = evaluate_with_other(&dmt_scene, &opts).other_model.unwrap();
    assert_eq!(beside_dmt, om);
    // The law valid in the transition needs nothing beside it.
    assert!(evaluate_with_other(&lj_scene, &opts).other_model.is_none());
    // Outside the transition there is none.
    let mut far = scene.clone();
    far.interatomic_distance = 0.05e-9; // φ0 grows as Z0^{-1}: 0.374 · 6 = 2.2 → still transition
    far.interatomic_distance = 0.01e-9; // 0.374 · 30 = 11 > 3
    assert!(evaluate_with_other(&far, &opts).other_model.is_none());
    // A tensile load beyond the DMT pull-off separates under DMT: null/0 there.
    let mut pull = scene;
    pull.load = -1e-3;
    let ev = evaluate_with_other(&pull, &opts);
    assert_eq!(ev.status, Status::Separated);
    assert_eq!(ev.noncontact_load, None);
    let om = ev.other_model.unwrap();
    assert_eq!(om.status, Status::Separated);
    assert_eq!(om.nondimensional_separation, None);
    assert_eq!(om.real_area, 0.0);
    assert_eq!(om.wear_rate, 0.0);
}

fn with_interface(extra: &str) -> String {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear.toml"
    ))
    .unwrap();
    // The hub's own law gives way to the one under test.
    let text = text.replacen("adhesion_model = \"lennard_jones\"", "", 1);
    text.replace("[interface]\n", &format!("[interface]\n{extra}\n"))
}

#[test]
fn problem_keys_and_bad_input() {
    let p = wearopt::problem::parse(&with_interface("adhesion_model = \"dmt\""), "t.toml").unwrap();
    assert_eq!(p.scene.adhesion_model, AdhesionModel::Dmt);
    assert_eq!(p.scene.attraction, AttractionKind::VanDerWaals);
    let p = wearopt::problem::parse(
        &with_interface("adhesion_model = \"dmt\"\nattraction = \"dugdale\""),
        "t.toml",
    )
    .unwrap();
    assert_eq!(p.scene.attraction, AttractionKind::Dugdale);
    let p = wearopt::problem::parse(&with_interface(""), "t.toml").unwrap();
    assert_eq!(p.scene.adhesion_model, AdhesionModel::Jkr);

    let err = |extra: &str| {
        wearopt::problem::parse(&with_interface(extra), "t.toml")
            .unwrap_err()
            .to_string()
    };
    let e = err("adhesion_model = \"dmtt\"");
    assert!(
        e.contains("interface.adhesion_model") && e.contains("jkr, dmt"),
        "{e}"
    );
    assert!(e.contains("did you mean \"dmt\""), "{e}");
    let e = err("adhesion_model = \"dmt\"\nattraction = \"vdw\"");
    assert!(
        e.contains("interface.attraction") && e.contains("van_der_waals, dugdale"),
        "{e}"
    );
    let e = err("attraction = \"dugdale\"");
    assert!(
        e.contains("interface.attraction")
            && e.contains("DMT law only")
            && e.contains("adhesion_model"),
        "{e}"
    );
    let text = with_interface("adhesion_model = \"dmt\"").replace(
        "interatomic_distance = \"0.3 nm\"",
        "interatomic_distance = \"0 nm\"",
    );
    let e = wearopt::problem::parse(&text, "t.toml")
        .unwrap_err()
        .to_string();
    assert!(e.contains("interface.interatomic_distance"), "{e}");
}

fn wearopt(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_wearopt"))
        .args(args)
        .output()
        .expect("wearopt runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `curve`: the DMT flags, the `noncontact_load` column, and the clashes (exit 2).
#[test]
fn curve_flags() {
    let (code, out, _) = wearopt(&[
        "curve",
        "--theta",
        "184",
        "--lambda",
        "1.309e5",
        "--from",
        "0",
        "--to",
        "60",
        "--points",
        "4",
        "--adhesion-model",
        "dmt",
        "--attraction-range",
        "0.1",
    ]);
    assert_eq!(code, 0);
    let mut lines = out.lines();
    assert_eq!(
        lines.next().unwrap(),
        "h,load,area,plastic_area,critical_interference,dload_dh,noncontact_load"
    );
    let last: Vec<f64> = lines
        .last()
        .unwrap()
        .split(',')
        .map(|x| x.parse().unwrap())
        .collect();
    // h = 60: the van der Waals term is the whole (negative, non-zero) load.
    assert_eq!(last[0], 60.0);
    assert!(last[1] < 0.0 && last[1] == last[6], "{last:?}");
    // γ = 0: DMT equals JKR and the non-contact load is exactly 0.
    let gw = |law: &[&str]| {
        let mut a = vec![
            "curve",
            "--theta",
            "inf",
            "--lambda",
            "inf",
            "--hardness-coefficient",
            "3",
            "--from",
            "-1",
            "--to",
            "3",
            "--points",
            "5",
            "--format",
            "json",
        ];
        a.extend_from_slice(law);
        wearopt(&a).1
    };
    let jkr = gw(&[]);
    let dmt = gw(&[
        "--adhesion-model",
        "dmt",
        "--attraction",
        "dugdale",
        "--attraction-range",
        "1e-3",
    ]);
    assert_eq!(jkr, dmt);
    assert!(jkr.contains("\"noncontact_load\": 0.0"));
    for bad in [
        vec!["--attraction", "dugdale"],
        vec!["--attraction-range", "0.1"],
        vec!["--adhesion-model", "dmt"],
        vec!["--adhesion-model", "dmt", "--attraction-range", "-1"],
        vec!["--adhesion-model", "dmx"],
    ] {
        let mut a = vec![
            "curve", "--theta", "1", "--lambda", "1", "--from", "0", "--to", "1", "--points", "2",
        ];
        a.extend_from_slice(&bad);
        let (code, _, err) = wearopt(&a);
        assert_eq!(code, 2, "{bad:?}: {err}");
        assert!(
            err.contains("attraction") || err.contains("jkr, dmt"),
            "{bad:?}: {err}"
        );
    }
}

/// Every shipped problem uses a law that holds where it lies: DMT below 0.3 (the
/// DLC contact, φ0 = 0.257; the materials study, 0.164); in the transition 0.3–3
/// the Lennard-Jones law, exact at every φ0, for the hub (dry, humid, under
/// scatter, and its robust study), the gold switch, the latch study, the scan and
/// the five-variable, switch and infeasible studies (whose optima leave the
/// transition: their JKR copies for the regression tests are `tests/data/*-jkr.toml`),
/// and the coating study under DMT (its optimum lies at φ0 = 0.05); no shipped
/// problem keeps JKR, and none lies above 3. Where a study's optimum leaves its
/// law's regime, `optimize` says so on the status line (`law_regime.rs`).
#[test]
fn shipped_scenes_use_the_law_their_tabor_parameter_calls_for() {
    let dir = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/problems"));
    let mut seen = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("toml") {
            continue;
        }
        let p = wearopt::problem::load(&path).expect("shipped problem loads");
        let ev = evaluate_with_other(&p.scene, &EvaluationOptions::default());
        let phi = ev.indices.tabor_parameter;
        let humid = p.scene.environment.is_some();
        let stem = path.file_stem().unwrap().to_str().unwrap();
        let want = if [
            "micro-gear",
            "micro-gear-humid",
            "micro-gear-scatter",
            "micro-gear-robust",
            "gold-switch",
            "latch-pareto",
            "micro-gear-scan",
            "micro-gear-study",
            "switch-study",
            "infeasible-study",
            // Stress-assisted wear on the Lennard-Jones law at φ0 = 0.125,
            // beside the DMT file silicon-sidewall-wear.toml: the law's
            // summit stresses where DMT's would do.
            "silicon-sidewall-wear-lj",
        ]
        .contains(&stem)
        {
            AdhesionModel::LennardJones
        } else if phi < 0.3 || humid {
            AdhesionModel::Dmt
        } else {
            // The transition: the law that holds there.
            AdhesionModel::LennardJones
        };
        assert!(phi <= 3.0, "{}: φ0 = {phi}", path.display());
        assert_eq!(
            p.scene.adhesion_model,
            want,
            "{}: φ0 = {phi}",
            path.display()
        );
        let beside = phi >= 0.3 && want != AdhesionModel::LennardJones;
        assert_eq!(ev.other_model.is_some(), beside, "{}", path.display());
        seen += 1;
    }
    assert!(seen >= 10);
}

/// The DLC contact under DMT with van der Waals (Z0 = 0.3 nm, z0 = 0.3), 50 µN.
/// Checked independently with scripts/reference_dmt.py's `total_load` (mpmath, 40
/// digits, both of its methods) at the evaluator's θ = 62.112999374994, λ =
/// 3638330.96641759: P̄(1.4113802900901362) = 0.0403559367580650620 (the file's
/// non-dimensional load 0.04035593675806507); the minimum of P̄ by findroot on
/// P̄'/|P̄| at h = 2.6121740529175257, giving 4.3226131583860236e-6 N through the
/// load scale 1.238975080661647e-3 N. Under JKR the same scene gave 3.2e-20 N.
#[test]
fn dlc_contact_is_dmt_and_matches_the_reference() {
    let path = Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/dlc-contact.toml"
    ));
    let p = wearopt::problem::load(path).unwrap();
    assert_eq!(p.scene.adhesion_model, AdhesionModel::Dmt);
    assert_eq!(p.scene.attraction, AttractionKind::VanDerWaals);
    let ev = evaluate_with_other(&p.scene, &EvaluationOptions::default());
    assert_eq!(ev.status, Status::Ok);
    assert!(
        ev.other_model.is_none(),
        "φ0 = 0.257 is below the transition"
    );
    let rel = |a: f64, b: f64| (a / b - 1.0).abs();
    assert!(rel(ev.nondimensional_load, 0.040_355_936_758_065_062) < 1e-14);
    let h = ev.nondimensional_separation.unwrap();
    assert!((h - 1.411_380_290_090_136_2).abs() < 1e-12, "{h}");
    let po = ev.pull_off_force.unwrap();
    assert!(rel(po, 4.322_613_158_386_024e-6) < 1e-12, "{po}");
    let hp = ev.nondimensional_pull_off_separation.unwrap();
    assert!((hp - 2.612_174_052_917_526).abs() < 1e-9, "{hp}");
    // The attracted asperities pull; the shares add up to the load.
    let nc = ev.noncontact_load.unwrap();
    assert!(nc < 0.0);
    let sum = ev.elastic_load + ev.plastic_load + nc;
    assert!(rel(sum, 50e-6) < 1e-12, "{sum}");
}

/// Found by the million-case stability run: θ = 1, H = ∞, Dugdale Δ_h ≈ 20. The
/// pull-off search started at the attraction's reach (h = 21), where P̄' is nearly
/// flat, and Newton jumped to h ≈ −2e15; it must find the minimum between h = 0 and 1
/// (P̄' < 0 at h = 0 and > 0 at h = 1, by the evaluator's own values there).
#[test]
fn far_start_finds_the_minimum() {
    let mut c = Coefficients::new((6.0 * std::f64::consts::PI).sqrt(), f64::INFINITY);
    c.c_0 = 2.0 * std::f64::consts::PI;
    let m = dmt(
        c,
        Attraction::Dugdale {
            range: 19.971557374648555,
        },
    );
    assert!(m.at(0.0).dload_dh().signum() < 0.0);
    assert!(m.at(1.0).dload_dh().signum() > 0.0);
    let p = find_pull_off(&m).expect("a minimum with γ > 0");
    assert!(p.separation > 0.0 && p.separation < 1.0, "{p:?}");
    assert!(p.load.signum() < 0.0, "{p:?}");
    assert_eq!(p.local_minima, 1);
}
