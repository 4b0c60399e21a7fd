//! The Lennard-Jones asperity law in the evaluator (`adhesion_model =
//! "lennard_jones"`, docs/model.md §11): its rough-surface load with plastic
//! junctions against an adaptive quadrature of the tabulated curve, its
//! single-asperity pull-off against the reference solver's, its limits
//! outside the table and at γ = 0, and the scene numbers it gives.

use super::common::{self, wearopt};
use super::lennard_jones_rough::simpson;
use wearopt::model::lennard_jones::spacing;
use wearopt::model::lennard_jones::table::{curves, AT_HUNDREDTH};
use wearopt::model::warnings::Note;
use wearopt::model::{
    evaluate, AdhesionModel, AsperityLaw, AttractionKind, Coefficients, EvaluationOptions, Model,
    Quadrature,
};

fn hub() -> wearopt::model::Scene {
    let path = std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear.toml"
    ));
    wearopt::problem::load(path).expect("the hub loads").scene
}

fn with_law(scene: &wearopt::model::Scene, law: AdhesionModel) -> wearopt::model::Scene {
    wearopt::model::Scene {
        adhesion_model: law,
        attraction: AttractionKind::VanDerWaals,
        ..scene.clone()
    }
}

/// P̄ and dP̄/dh of the evaluator's model at a tabulated μ (one curve, no
/// interpolation in μ) with plastic junctions, against adaptive Simpson in Δ
/// of the summit load: the table's curve up to Δc (the model's), c_p Δ − c_0
/// beyond, the approach part below the switch (square-root end there, taken
/// in Δ = switch ∓ t²). Relative to ∫|p| φ̄ (P̄ is a difference of attraction
/// and repulsion near its zero): measured 8e-13.
#[test]
fn the_rough_load_with_plastic_junctions_matches_an_adaptive_quadrature() {
    let mut worst = 0.0f64;
    for index in [AT_HUNDREDTH + 12, AT_HUNDREDTH + 34, AT_HUNDREDTH + 60] {
        let curve = &curves()[index];
        for (ell, c_h) in [(3.0f64, 2.5f64), (30.0, 6.0), (30.0, f64::INFINITY)] {
            let c_a = 6f64.sqrt() * ell.powf(-0.75);
            let c = Coefficients::new(c_a, c_h);
            let z0 = spacing(curve.tabor) / ell;
            let model = Model::with_law(
                c,
                AsperityLaw::LennardJones { range: z0 },
                Quadrature::default(),
            );
            let table = wearopt::model::lennard_jones::law::table_of(model.tabulated())
                .expect("a tabulated μ");
            assert!((table.tabor / curve.tabor - 1.0).abs() < 1e-12);
            let dc = model.critical_interference();
            for h in [-1.0f64, 0.5, 2.0, 4.0] {
                let at = model.at(h);
                let want = reference_shares(curve, ell, &c, dc, h);
                let got = at.load().value();
                let slope = at.dload_dh().value();
                let e = ((got - want[0]).abs() / want[1]).max((slope - want[2]).abs() / want[1]);
                assert!(
                    e < 1e-8,
                    "μ={} ℓ={ell} c_h={c_h} h={h}: P̄ {got} vs {}, P̄' {slope} vs {}",
                    curve.tabor,
                    want[0],
                    want[2]
                );
                worst = worst.max(e);
            }
        }
    }
    eprintln!("worst {worst:e}");
}

/// [∫ p φ̄, ∫ |p| φ̄, −∫ p (h + Δ) φ̄] over the summits at h for one tabulated
/// curve at ℓ: p its load (§3 units) up to Δc, c_p Δ − c_0 beyond; adaptive
/// Simpson to 1e-12 on each piece between the window's ends, the switch, 0 and
/// Δc, in Δ = switch ∓ t² next to the switch (a square-root end there).
fn reference_shares(
    curve: &wearopt::model::lennard_jones::table::Curve,
    ell: f64,
    c: &Coefficients,
    dc: f64,
    h: f64,
) -> [f64; 3] {
    let switch = curve.switch / ell;
    let p = |d: f64| {
        if d >= dc {
            c.c_p * d - c.c_0
        } else {
            ell.powf(-1.5) * curve.load(ell * d)
        }
    };
    let weight = |d: f64| (-0.5 * (h + d) * (h + d)).exp();
    let (lo, hi) = (-h - 10.0, -h + 10.0);
    let sums = |a: f64, b: f64| -> [f64; 3] {
        if a >= b {
            return [0.0; 3];
        }
        let part = |g: &dyn Fn(f64) -> f64| -> f64 {
            if b <= switch {
                let f = |t: f64| 2.0 * t * g(switch - t * t);
                simpson(&f, (switch - b).sqrt(), (switch - a).sqrt(), 1e-12)
            } else if a >= switch && a - switch < 1.0 {
                let f = |t: f64| 2.0 * t * g(switch + t * t);
                simpson(&f, (a - switch).sqrt(), (b - switch).sqrt(), 1e-12)
            } else {
                simpson(g, a, b, 1e-12)
            }
        };
        [
            part(&|d| p(d) * weight(d)),
            part(&|d| p(d).abs() * weight(d)),
            part(&|d| -p(d) * (h + d) * weight(d)),
        ]
    };
    let mut cuts = vec![lo, switch, 0.0, dc, hi];
    cuts.retain(|x| x.is_finite() && *x >= lo && *x <= hi);
    cuts.sort_by(f64::total_cmp);
    let mut want = [0.0; 3];
    for w in cuts.windows(2) {
        let s = sums(w[0], w[1]);
        for i in 0..3 {
            want[i] += s[i];
        }
    }
    want
}

/// With a meniscus (docs/model.md §10) the Lennard-Jones law's pull-off (the
/// deepest minimum of P̄) and unloaded separation (P̄ = 0) against the
/// independent quadrature above plus the capillary load (its closed form,
/// itself checked against the 40-digit table in capillary.rs), its extrema
/// found by bisection on the reference's own P̄' and P̄: at a tabulated μ on
/// a stiff and a soft scene, a sub-σ meniscus and one reaching 3σ. Measured:
/// the pull-off's separation 2.8e-14, its load 2.1e-13, h0 1.3e-13 (the
/// issue asks 1e-10). Γ is not checked here: under this law it is the
/// quadrature over h itself (`work::work_by_separation`).
#[test]
fn with_a_meniscus_the_extrema_match_an_independent_quadrature() {
    use wearopt::model::{landscape, pull_off_of, solve_separation, Capillary, SeparationOutcome};
    let mut worst = [0.0f64; 3];
    let scenes = [
        (AT_HUNDREDTH + 34, 30.0f64, 6.0f64, (0.5, 0.04)),
        (AT_HUNDREDTH + 60, 3.0, f64::INFINITY, (3.0, 0.5)),
    ];
    for (index, ell, c_h, (k, f)) in scenes {
        let curve = &curves()[index];
        let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), c_h);
        let cap = Capillary {
            range: k,
            wetting: f,
            flooded: 1.3,
        };
        let model = Model::with_law(
            c,
            AsperityLaw::LennardJones {
                range: spacing(curve.tabor) / ell,
            },
            Quadrature::default(),
        )
        .with_capillary(Some(cap));
        let dc = model.critical_interference();
        // The reference P̄ and P̄' at h.
        let reference = |h: f64| {
            let s = reference_shares(curve, ell, &c, dc, h);
            let m = cap.at(h);
            let scale = (-m.exponent).exp();
            (s[0] + m.load * scale, s[2] + m.dload_dh * scale)
        };
        // The root of g in [a, b] (a sign change) by bisection to the last bit.
        let bisect = |g: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64| {
            let ga = g(a);
            assert!(ga * g(b) < 0.0, "no sign change in [{a}, {b}]");
            loop {
                let m = 0.5 * (a + b);
                if m <= a || m >= b {
                    return m;
                }
                if (g(m) < 0.0) == (ga < 0.0) {
                    a = m;
                } else {
                    b = m;
                }
            }
        };
        let po = pull_off_of(&landscape(&model)).expect("a minimum");
        let h_min = bisect(
            &|h| reference(h).1,
            po.separation - 0.05,
            po.separation + 0.05,
        );
        let p_min = reference(h_min).0;
        let h0 = match solve_separation(&model, 0.0) {
            SeparationOutcome::Contact { separation, .. } => separation,
            other => panic!("μ={} ℓ={ell}: {other:?}", curve.tabor),
        };
        let h0_ref = bisect(&|h| reference(h).0, h0 - 0.05, h0 + 0.05);
        let errors = [
            (po.separation - h_min).abs() / h_min.abs(),
            (po.load.value() - p_min).abs() / p_min.abs(),
            (h0 - h0_ref).abs() / h0_ref.abs(),
        ];
        assert!(
            errors[0] < 1e-11 && errors[1] < 1e-11 && errors[2] < 1e-11,
            "μ={} ℓ={ell}: pull-off at {} ({h_min}), load {} ({p_min}), h0 {h0} ({h0_ref})",
            curve.tabor,
            po.separation,
            po.load.value()
        );
        for (w, e) in worst.iter_mut().zip(errors) {
            *w = w.max(e);
        }
    }
    eprintln!(
        "worst h_min, P_min, h0: {:e} {:e} {:e}",
        worst[0], worst[1], worst[2]
    );
}

/// One summit's pull-off from the table (its curves' minima, interpolated in
/// ln μ between nodes) against the reference solver's
/// (`tests/data/reference_lennard_jones_extrema.csv`, another discretisation):
/// within 3e-7 (measured 9.9e-8 at μ = 5, 2.6e-8 at μ = 1, below 2.1e-8
/// elsewhere; 2.9e-6 at μ = 1 on the table of 67 curves, 1.15e-3 before the
/// table's nodes were extrapolated to the converged solver).
#[test]
fn the_asperity_pull_off_matches_the_reference_solver() {
    for row in common::table("reference_lennard_jones_extrema.csv") {
        let mu = common::num(&row["mu"]);
        if mu > wearopt::model::lennard_jones::table::solved_range().1 {
            continue;
        }
        let want = -common::num(&row["pull_off_load"]);
        // A scene with this μ: c_0 = 2 ℓ^{-3/2} at ℓ = 10.
        let ell = 10.0f64;
        let c = Coefficients::new(6f64.sqrt() * ell.powf(-0.75), f64::INFINITY);
        let model = Model::with_law(
            c,
            AsperityLaw::LennardJones {
                range: spacing(mu) / ell,
            },
            Quadrature::default(),
        );
        let got = model.asperity_pull_off();
        eprintln!(
            "μ = {mu}: table's pull-off off the reference by {:.2e}",
            got / want - 1.0
        );
        assert!((got / want - 1.0).abs() < 3e-7, "μ={mu}: {got} vs {want}");
    }
}

/// Without adhesion every law is Hertz's: the Lennard-Jones scene's numbers
/// are the JKR and DMT scenes' bit for bit.
#[test]
fn without_adhesion_every_law_agrees() {
    let mut scene = hub();
    scene.work_of_adhesion = 0.0;
    let opts = EvaluationOptions::default();
    let lj = evaluate(&with_law(&scene, AdhesionModel::LennardJones), &opts);
    for law in [AdhesionModel::Jkr, AdhesionModel::Dmt] {
        let other = evaluate(&with_law(&scene, law), &opts);
        assert_eq!(
            lj.nondimensional_separation,
            other.nondimensional_separation
        );
        assert_eq!(lj.real_area, other.real_area);
        assert_eq!(lj.wear_rate, other.wear_rate);
        assert_eq!(lj.pull_off_force, other.pull_off_force);
    }
}

/// Outside its curves (μ > 3.58e6, μ < 9.91e-5) the law is its closed-form
/// limit, JKR above and DMT with van der Waals attraction below, exactly, with
/// a note that says so; inside, the hub's loads add up to W and the far
/// attraction's Hamaker constant is 16π Z0² γ.
#[test]
fn outside_the_table_the_limits_stand_in() {
    let opts = EvaluationOptions::default();
    // The hub's μ = 0.374 at Z0 = 0.3 nm, γ = 0.1 J/m²: 1.1e7 at 1e-17 m,
    // 7.5e-5 at 15 nm and γ = 1e-4 J/m² (μ ∝ γ^{2/3}/Z0).
    for (z0, gamma, limit) in [
        (1e-17, 0.1, AdhesionModel::Jkr),
        (15e-9, 1e-4, AdhesionModel::Dmt),
    ] {
        let mut scene = hub();
        scene.interatomic_distance = z0;
        scene.work_of_adhesion = gamma;
        let lj = evaluate(&with_law(&scene, AdhesionModel::LennardJones), &opts);
        let other = evaluate(&with_law(&scene, limit), &opts);
        assert_eq!(lj.stand_in_model, Some(limit));
        assert_eq!(
            lj.nondimensional_separation,
            other.nondimensional_separation
        );
        assert_eq!(lj.pull_off_force, other.pull_off_force);
        assert_eq!(lj.wear_rate, other.wear_rate);
        assert_eq!(
            lj.law_asperity_pull_off_force,
            other.law_asperity_pull_off_force
        );
        let note = lj
            .notes
            .iter()
            .find_map(|n| match n {
                Note::LennardJonesStandIn {
                    stand_in,
                    pull_off_error,
                    ..
                } => Some((*stand_in, *pull_off_error)),
                _ => None,
            })
            .expect("the stand-in is noted");
        assert_eq!(note.0, limit);
        // Above, the rough surface's pull-off under JKR's law against the
        // last limit curve's (2.9e-3 where adhesion is strong); below,
        // Bradley's 2 against the table's 1.9999990 at μ = 9.91e-5.
        let expected = if limit == AdhesionModel::Jkr {
            (1e-4, 2e-2)
        } else {
            (1e-7, 1e-6)
        };
        assert!(note.1 > expected.0 && note.1 < expected.1, "{note:?}");
    }
    let scene = with_law(&hub(), AdhesionModel::LennardJones);
    let ev = evaluate(&scene, &opts);
    assert_eq!(ev.stand_in_model, None);
    let sum = ev.elastic_load + ev.plastic_load + ev.noncontact_load.unwrap();
    assert!((sum / scene.load - 1.0).abs() < 1e-12, "{sum}");
    assert!(ev.noncontact_load.unwrap() < 0.0);
    let a = 16.0 * std::f64::consts::PI * 0.3e-9f64.powi(2) * 0.1;
    assert!((ev.hamaker_constant.unwrap() / a - 1.0).abs() < 1e-12);
    // One summit's pull-off lies between JKR's 1.5πγR and Bradley's 2πγR.
    let ratio = ev.law_asperity_pull_off_force / ev.asperity_pull_off_force;
    assert!(ratio > 1.0 && ratio < 4.0 / 3.0, "{ratio}");
}

/// `attraction` is refused under the Lennard-Jones law (its attraction is its
/// own), naming the clash; an unknown law lists the three.
#[test]
fn bad_input_names_the_clash() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear.toml"
    ))
    .unwrap();
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let clash = dir.join("lj-attraction.toml");
    std::fs::write(
        &clash,
        text.replace("[interface]\n", "[interface]\nattraction = \"dugdale\"\n"),
    )
    .unwrap();
    let err = String::from_utf8(common::stderr(
        wearopt().args(["eval", clash.to_str().unwrap()]),
        2,
    ))
    .unwrap();
    assert!(err.contains("interface.attraction"), "{err}");
    assert!(err.contains("\"lennard_jones\""), "{err}");
    let unknown = dir.join("lj-unknown.toml");
    std::fs::write(
        &unknown,
        text.replace(
            "adhesion_model = \"lennard_jones\"",
            "adhesion_model = \"lennard-jones\"",
        ),
    )
    .unwrap();
    let err = String::from_utf8(common::stderr(
        wearopt().args(["eval", unknown.to_str().unwrap()]),
        2,
    ))
    .unwrap();
    assert!(err.contains("jkr, dmt, lennard_jones"), "{err}");
    assert!(err.contains("did you mean \"lennard_jones\""), "{err}");
}

/// The JSON names the law as problem files do: `adhesion_model` of the
/// shipped hub and of a JKR scene's `other_model` read "lennard_jones".
#[test]
fn json_names_the_law_as_problem_files_do() {
    let out = common::stdout(
        wearopt().args(["eval", "problems/micro-gear.toml", "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["adhesion_model"], "lennard_jones");
    assert!(v.get("other_model").is_none());
    assert!(v.get("stand_in_model").is_none());
    let jkr = common::under_law("micro-gear", "jkr");
    let out = common::stdout(
        wearopt().args(["eval", jkr.to_str().unwrap(), "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["adhesion_model"], "jkr");
    assert_eq!(v["other_model"]["adhesion_model"], "lennard_jones");
    // μ ∝ 1/Z0: 37.4 at 3 pm, above the solved table, on the limit curves
    // (noted, no stand-in).
    let above = std::fs::read_to_string("problems/micro-gear.toml")
        .unwrap()
        .replace(
            "interatomic_distance = \"0.3 nm\"",
            "interatomic_distance = \"0.003 nm\"",
        );
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("lj-limit.toml");
    std::fs::write(&path, above).unwrap();
    let out = common::stdout(
        wearopt().args(["eval", path.to_str().unwrap(), "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert!(v.get("stand_in_model").is_none());
    let notes = v["note_details"].as_array().unwrap();
    assert!(
        notes
            .iter()
            .any(|n| n["kind"] == "lennard_jones_limit_curves"),
        "{notes:?}"
    );
    // 1.1e7 at 1e-8 nm: above the limit curves, JKR stands in.
    let far = std::fs::read_to_string("problems/micro-gear.toml")
        .unwrap()
        .replace(
            "interatomic_distance = \"0.3 nm\"",
            "interatomic_distance = \"1e-8 nm\"",
        );
    let path = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("lj-stand-in.toml");
    std::fs::write(&path, far).unwrap();
    let out = common::stdout(
        wearopt().args(["eval", path.to_str().unwrap(), "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(v["stand_in_model"], "jkr");
    let notes = v["note_details"].as_array().unwrap();
    assert!(
        notes.iter().any(|n| n["kind"] == "lennard_jones_stand_in"),
        "{notes:?}"
    );
}

/// Humid air under the Lennard-Jones law (docs/model.md §10 on this law's
/// load): at RH = 0 the humid hub is the dry hub bit for bit; at 50 % the
/// meniscus pulls (capillary load < 0), the pull-off and Γ grow, and the
/// loads still add up to W.
#[test]
fn humid_air_adds_to_the_lennard_jones_load() {
    let wet = wearopt::problem::load(std::path::Path::new("problems/micro-gear-humid.toml"))
        .unwrap()
        .scene;
    assert_eq!(wet.adhesion_model, AdhesionModel::LennardJones);
    let mut dry = wet.clone();
    dry.environment = dry.environment.map(|mut e| {
        e.relative_humidity = 0.0;
        e
    });
    let opts = EvaluationOptions::default();
    let (w, d) = (evaluate(&wet, &opts), evaluate(&dry, &opts));
    let plain = evaluate(
        &wearopt::model::Scene {
            environment: None,
            requirements: Default::default(),
            ..dry.clone()
        },
        &opts,
    );
    assert_eq!(d.nondimensional_separation, plain.nondimensional_separation);
    assert_eq!(d.pull_off_force, plain.pull_off_force);
    let hum = w.humidity.unwrap();
    assert!(hum.capillary_load.unwrap() < 0.0);
    assert!(w.pull_off_force.unwrap() > d.pull_off_force.unwrap());
    assert!(
        hum.apparent_work_of_adhesion.unwrap()
            > d.humidity.unwrap().apparent_work_of_adhesion.unwrap()
    );
    let sum =
        w.elastic_load + w.plastic_load + w.noncontact_load.unwrap() + hum.capillary_load.unwrap();
    assert!((sum / wet.load - 1.0).abs() < 1e-10, "{sum}");
}

/// The scene the million-case run found (2026-11-27): humid, μ = 3.13, deep in
/// contact (h ≈ −16.9), where the curves' plastic shares weighted in μ left
/// their own range and a switch to another rule made P̄ jump by 1 % of the
/// load; the separation stopped on the jump with its load balance 0.56 % off.
/// Now: P̄ continuous across a fine grid of h there (no step larger than its
/// slope allows), and the parts balance the load.
#[test]
fn the_plastic_share_between_curves_is_continuous() {
    use wearopt::model::{
        evaluate, AdhesionModel, AttractionKind, Environment, EvaluationOptions, Liquid,
        Requirements, Scene, WearArea,
    };
    let scene = Scene {
        youngs_modulus_a: 16514808950.318605,
        poisson_ratio_a: 0.3891634196935382,
        youngs_modulus_b: 244189220264.5358,
        poisson_ratio_b: 0.32555596290678207,
        hardness: 134849729.30299535,
        work_of_adhesion: 0.5530860174720567,
        interatomic_distance: 3e-10,
        sigma: 1.1928070289691145e-10,
        asperity_radius: 8.912177314434484e-7,
        asperity_density: 24890697020033.754,
        load: 3.0775436766577374e-14,
        nominal_area: 0.0001,
        sliding_distance: 1.0,
        wear_coefficient: 0.0001,
        wear_area: WearArea::Total,
        wear_law: Default::default(),
        temperature: 417.38730563955676,
        activation: None,
        real_area_scale: 1.0,
        requirements: Requirements::default(),
        adhesion_model: AdhesionModel::LennardJones,
        attraction: AttractionKind::VanDerWaals,
        environment: Some(Environment {
            relative_humidity: 0.9587427546493464,
            temperature: 417.38730563955676,
            liquid: Liquid::Water,
            contact_angle_a: 0.6380465330618044,
            contact_angle_b: 0.27741419295897934,
            humidity_range: None,
        }),
    };
    let model = wearopt::model::wear::model_of(&scene, Quadrature::default());
    let (mut previous, step) = (model.at(-16.95).load().value(), 5e-4);
    for i in 1..=80 {
        let h = -16.95 + step * i as f64;
        let at = model.at(h);
        let p = at.load().value();
        let slope = at.dload_dh().value().abs();
        assert!(
            (p - previous).abs() <= 2.0 * slope * step,
            "P̄ jumps at h = {h}: {previous} → {p}"
        );
        previous = p;
    }
    let ev = evaluate(&scene, &EvaluationOptions::default());
    let cap = ev.humidity.and_then(|h| h.capillary_load).unwrap_or(0.0);
    let nc = ev.noncontact_load.unwrap_or(0.0);
    let sum = ev.elastic_load + ev.plastic_load + nc + cap;
    assert!(
        (sum - scene.load).abs() <= 1e-9 * (ev.elastic_load.abs() + cap.abs()),
        "{} + {} + {nc} + {cap} = {sum}",
        ev.elastic_load,
        ev.plastic_load
    );
}

/// One scene at the Lennard-Jones table's lower end (E 200 GPa, ν 0 on both
/// bodies, H 10 GPa, N 10 µm⁻², A_n 1000 µm²; σ, Z0 in nm, R in µm, W in µN) with
/// γ set so that μ is the table's lowest, 9.91e-5 (1 ± 1e-3): the stand-in's real area and pull-off
/// (below) over the law's (above), minus 1.
fn stand_in_jump(sigma: f64, z0: f64, r: f64, load: f64) -> (f64, f64) {
    let text = |gamma: f64| {
        format!(
            "name = \"switch\"\n[contact]\nload = \"{load} uN\"\nnominal_area = \"1000 um^2\"\n\
             sliding_distance = \"1 m\"\nwear_coefficient = 1e-6\n[bodies]\n\
             a = {{ youngs_modulus = \"200 GPa\", poisson_ratio = 0.0 }}\n\
             b = {{ youngs_modulus = \"200 GPa\", poisson_ratio = 0.0 }}\n[interface]\n\
             hardness = \"10 GPa\"\nwork_of_adhesion = \"{gamma} J/m^2\"\n\
             interatomic_distance = \"{z0} nm\"\nadhesion_model = \"lennard_jones\"\n\
             [roughness]\nsigma = \"{sigma} nm\"\nasperity_radius = \"{r} um\"\n\
             asperity_density = \"10 um^-2\"\n"
        )
    };
    let scene = |gamma: f64| {
        let dir = std::env::temp_dir().join(format!("wearopt-switch-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(format!("s{sigma}-{z0}-{r}-{load}-{gamma}.toml"));
        std::fs::write(&path, text(gamma)).unwrap();
        let scene = wearopt::problem::load(&path).expect("loads").scene;
        std::fs::remove_file(&path).ok();
        scene
    };
    let opts = EvaluationOptions::default();
    // μ ∝ γ^{2/3}.
    let mu = evaluate(&scene(5e-4), &opts).indices.tabor_parameter;
    let lowest = wearopt::model::lennard_jones::table::tabor_range().0;
    let gamma: f64 = 5e-4 * (lowest / mu).powf(1.5);
    let below = evaluate(&scene(gamma * 0.999f64.powf(1.5)), &opts);
    let above = evaluate(&scene(gamma * 1.001f64.powf(1.5)), &opts);
    assert!(below.indices.tabor_parameter < lowest && above.indices.tabor_parameter > lowest);
    assert!(below.stand_in_model.is_some() && above.stand_in_model.is_none());
    (
        below.real_area / above.real_area - 1.0,
        below.pull_off_force.unwrap() / above.pull_off_force.unwrap() - 1.0,
    )
}

/// Below μ = 9.91e-5 DMT with van der Waals attraction stands in for the
/// Lennard-Jones law, and the rough surface jumps there (issue 57, 2a): at the
/// worst scene of `stand_in_jump_campaign` the real area and the pull-off fall
/// by what the note states (`STAND_IN_ROUGH_JUMP`, 96 % and 53 %), and the note
/// says so in words.
#[test]
fn the_stand_in_below_the_table_jumps_as_stated() {
    use wearopt::model::lennard_jones::rough::STAND_IN_ROUGH_JUMP;
    let (area, pull_off) = stand_in_jump(0.3, 0.5, 5.0, 10.0);
    assert!(
        (-area / STAND_IN_ROUGH_JUMP.0 - 1.0).abs() < 1e-3,
        "{area} against {:?}",
        STAND_IN_ROUGH_JUMP
    );
    assert!(
        (-pull_off / STAND_IN_ROUGH_JUMP.1 - 1.0).abs() < 1e-3,
        "{pull_off} against {:?}",
        STAND_IN_ROUGH_JUMP
    );
    let mut scene = hub();
    scene.interatomic_distance = 15e-9;
    scene.work_of_adhesion = 1e-4;
    let ev = evaluate(
        &with_law(&scene, AdhesionModel::LennardJones),
        &EvaluationOptions::default(),
    );
    let words: Vec<String> = ev.notes.iter().map(wearopt::report::words::note).collect();
    assert!(
        words
            .iter()
            .any(|w| w
                .contains("real area lies up to 96 % and its pull-off up to 53 % below the law's")),
        "{words:?}"
    );
}

/// The stand-in's jump over σ 0.3–3 nm, Z0 0.2–0.5 nm, R 0.2–5 µm and W 10 µN–1 mN
/// (81 scenes, Z0/σ 0.07–1.7): every fall within `STAND_IN_ROUGH_JUMP`, the worst
/// at it. It grows with Z0/σ and as the load lightens.
#[test]
#[ignore = "campaign: cargo test --release --test all -- --ignored stand_in_jump_campaign"]
fn stand_in_jump_campaign() {
    use wearopt::model::lennard_jones::rough::STAND_IN_ROUGH_JUMP;
    let mut worst = (0.0f64, 0.0f64);
    for sigma in [0.3, 1.0, 3.0] {
        for z0 in [0.2, 0.3, 0.5] {
            for r in [0.2, 1.0, 5.0] {
                for load in [10.0, 100.0, 1000.0] {
                    let (area, pull_off) = stand_in_jump(sigma, z0, r, load);
                    eprintln!(
                        "σ {sigma} Z0 {z0} R {r} W {load}: area {area:+.4} pull-off {pull_off:+.4}"
                    );
                    assert!(area < 0.0 && pull_off < 0.0);
                    worst = (worst.0.max(-area), worst.1.max(-pull_off));
                }
            }
        }
    }
    eprintln!("worst {worst:?}");
    assert!(
        worst.0 <= STAND_IN_ROUGH_JUMP.0 && worst.1 <= STAND_IN_ROUGH_JUMP.1,
        "{worst:?}"
    );
    assert!(
        worst.0 > 0.999 * STAND_IN_ROUGH_JUMP.0 && worst.1 > 0.999 * STAND_IN_ROUGH_JUMP.1,
        "{worst:?}"
    );
}
