//! Capillary adhesion (docs/model.md §10): the capillary load against the 40-digit table
//! of `scripts/reference_capillary.py` (closed forms and direct quadrature, agreeing to
//! ≥ 25 digits), the rough surface's pull-off, unloaded separation and work of
//! separation against its 20-digit table (two methods agreeing to ≥ 15 digits), and the
//! limits §9 names: RH = 0 is the dry scene bit for bit, one asperity in contact pulls
//! with 4πRγ_L cos θ, the flooded interface gives Γ → γ_L (cos θ_a + cos θ_b), and the
//! single sign change of P̄' that the searches rely on.

use std::f64::consts::PI;

use crate::common::{num, rel, table};
use wearopt::model::capillary::{Capillary, Environment, Liquid};
use wearopt::model::{
    evaluate, landscape, pull_off_of, solve_separation, AsperityLaw, Attraction, Coefficients,
    EvaluationOptions, Model, Quadrature, Scene, SeparationOutcome,
};

/// ln|x| of a scaled mantissa.
fn ln_abs(mantissa: f64, exponent: f64) -> f64 {
    mantissa.abs().ln() - exponent
}

#[test]
fn capillary_load_matches_the_reference_table() {
    let rows = table("reference_capillary_points.csv");
    assert!(rows.len() >= 150, "{} rows", rows.len());
    let mut worst = [0.0f64; 4];
    for r in &rows {
        let cap = Capillary {
            range: num(&r["k"]),
            wetting: num(&r["f"]),
            flooded: num(&r["p"]),
        };
        let h = num(&r["h"]);
        let at = cap.at(h);
        let ln_load = num(&r["ln_load"]);
        // Logarithms: an absolute error in ln is a relative error of the value, beyond
        // the rounding of the scale exponent itself (4 ulps of ln: 1.5e-11 at h = 200,
        // where the value is e^{-2e4}).
        let ln_err =
            |got: f64, want: f64| ((got - want).abs() - 4.0 * f64::EPSILON * want.abs()).max(0.0);
        let errs = [
            ln_err(ln_abs(at.load, at.exponent), ln_load),
            ln_err(ln_abs(at.dload_dh, at.exponent), num(&r["ln_dload_dh"])),
            // P̄'' = -p e^{-F}(F'' - F'²) changes sign: measured against the size of
            // its terms, |P̄'| (1 + |h| + k⁻¹), as the DMT table measures N'.
            {
                let want = num(&r["d2_sign"]) * num(&r["ln_abs_d2load_dh2"]).exp();
                let got = at.d2load_dh2 * (-at.exponent).exp();
                let size = num(&r["ln_dload_dh"]).exp() * (1.0 + h.abs() + 1.0 / cap.range);
                if size > 1e-290 && size.is_finite() {
                    rel(got, want, size)
                } else {
                    // Underflowed values: the sign, and the logarithm.
                    assert!(at.d2load_dh2.signum() == num(&r["d2_sign"]), "{r:?}");
                    ln_err(
                        ln_abs(at.d2load_dh2, at.exponent),
                        num(&r["ln_abs_d2load_dh2"]),
                    ) / (1.0 + h.abs())
                }
            },
            {
                let want = num(&r["wetted_fraction"]);
                if want > 1e-290 {
                    rel(at.wetted_fraction, want, 0.0)
                } else {
                    0.0
                }
            },
        ];
        for (w, e) in worst.iter_mut().zip(errs) {
            assert!(e.is_finite(), "{r:?}: {errs:?}");
            *w = w.max(e);
        }
        assert!(at.load <= 0.0 && at.dload_dh >= 0.0, "{r:?}");
    }
    // Beyond 4 ulps of ln (the scale exponent's rounding), an absolute error in ln
    // is a relative one in the value. Measured with the closed forms of J: 5.4e-16,
    // 6.6e-16, 2.2e-14, 2.4e-14 (with the Dugdale quadrature they were 2.1e-15,
    // 1.9e-12, 1.7e-12).
    assert!(worst[0] < 1e-14, "load {worst:?}");
    assert!(worst[1] < 1e-14, "slope {worst:?}");
    assert!(worst[2] < 2e-13, "curvature {worst:?}");
    assert!(worst[3] < 1e-13, "wetted fraction {worst:?}");
}

/// The row's solid law: DMT (θ, c_h, the attraction and its range) or JKR (θ, and λ in
/// the c_h column, as scripts/reference.py takes them), with the row's meniscus.
fn row_model(row: &std::collections::HashMap<String, String>) -> Model {
    let theta = num(&row["theta"]);
    let range = num(&row["range"]);
    let (c, law) = match row["attraction"].as_str() {
        "jkr" => (
            Coefficients::from_indices(theta, num(&row["c_h"])),
            AsperityLaw::Jkr,
        ),
        kind => {
            let mut c = Coefficients::new((6.0 * PI / theta).sqrt(), num(&row["c_h"]));
            c.c_0 = 2.0 * PI / theta;
            let attraction = match kind {
                "van_der_waals" => Attraction::VanDerWaals { range },
                "dugdale" => Attraction::Dugdale { range },
                other => panic!("attraction {other}"),
            };
            (c, AsperityLaw::Dmt(attraction))
        }
    };
    Model::with_law(c, law, Quadrature::default()).with_capillary(Some(Capillary {
        range: num(&row["k"]),
        wetting: num(&row["f"]),
        flooded: num(&row["p"]),
    }))
}

#[test]
fn pull_off_unloaded_separation_and_work_match_the_reference_table() {
    let rows = table("reference_capillary_extrema.csv");
    assert!(rows.len() >= 4);
    assert!(rows.iter().any(|r| r["attraction"] == "van_der_waals"));
    assert!(rows.iter().any(|r| r["attraction"] == "dugdale"));
    assert!(rows.iter().any(|r| r["attraction"] == "jkr"));
    // A scene whose menisci flood the interface (d_K = 20σ, √(2π) R N d_K = 50).
    assert!(
        rows.iter()
            .any(|r| num(&r["k"]) >= 10.0 && num(&r["f"]) >= 10.0),
        "a flooding scene"
    );
    for r in &rows {
        let model = row_model(r);
        let land = landscape(&model);
        let po = pull_off_of(&land).expect("a minimum");
        let (h_min, p_min) = (num(&r["h_min"]), num(&r["load_min"]));
        assert!(rel(po.separation, h_min, 0.0) < 1e-10, "{r:?}: {po:?}");
        assert!(rel(po.load.value(), p_min, 0.0) < 1e-10, "{r:?}: {po:?}");
        let h0 = match solve_separation(&model, 0.0) {
            SeparationOutcome::Contact { separation, .. } => separation,
            other => panic!("{r:?}: {other:?}"),
        };
        assert!(rel(h0, num(&r["h_0"]), 0.0) < 1e-10, "{r:?}: h0 {h0}");
        let (work, _) = wearopt::model::work::work_of_separation(&model, h0);
        assert!(rel(work, num(&r["work"]), 0.0) < 1e-8, "{r:?}: work {work}");
        // The weak Dugdale scene's load and work (e^-11780) underflow a double:
        // there the row checks the separations, and that the work is +0, not -0.
        assert!(
            work.is_sign_positive() || num(&r["work"]) < 0.0,
            "{r:?}: work {work}"
        );
    }
}

/// The polysilicon hub of `problems/micro-gear.toml` under DMT with van der Waals
/// attraction, in air at `rh`.
fn hub(rh: Option<f64>) -> Scene {
    let e = 160e9;
    Scene {
        youngs_modulus_a: e,
        poisson_ratio_a: 0.22,
        youngs_modulus_b: e,
        poisson_ratio_b: 0.22,
        hardness: 10e9,
        work_of_adhesion: 0.1,
        interatomic_distance: 0.3e-9,
        sigma: 3e-9,
        asperity_radius: 1e-6,
        asperity_density: 1e13,
        load: 800e-6,
        nominal_area: 1000e-12,
        sliding_distance: 1.0,
        wear_coefficient: 1e-4,
        wear_area: Default::default(),
        wear_law: Default::default(),
        temperature: 298.15,
        activation: None,
        real_area_scale: 1.0,
        requirements: Default::default(),
        adhesion_model: wearopt::model::AdhesionModel::Dmt,
        attraction: Default::default(),
        environment: rh.map(|rh| Environment {
            relative_humidity: rh,
            ..Environment::default()
        }),
    }
}

#[test]
fn dry_air_is_the_dry_scene_bit_for_bit() {
    let options = EvaluationOptions::default();
    for model in [
        wearopt::model::AdhesionModel::Jkr,
        wearopt::model::AdhesionModel::Dmt,
    ] {
        let dry = Scene {
            adhesion_model: model,
            ..hub(None)
        };
        let zero = Scene {
            adhesion_model: model,
            ..hub(Some(0.0))
        };
        let a = evaluate(&dry, &options);
        let mut b = evaluate(&zero, &options);
        let h = b
            .humidity
            .take()
            .expect("an [environment] reports its block");
        assert_eq!(a, b, "RH = 0 changes the evaluation under {model:?}");
        assert_eq!(h.kelvin_radius, None);
        assert_eq!(h.capillary_load, Some(0.0));
        assert_eq!(h.wetted_fraction, Some(0.0));
        // A hydrophobic pair at any humidity condenses nothing either.
        let mut phobic = hub(Some(0.9));
        phobic.adhesion_model = model;
        if let Some(env) = phobic.environment.as_mut() {
            env.contact_angle_a = 100f64.to_radians();
            env.contact_angle_b = 100f64.to_radians();
        }
        let mut c = evaluate(&phobic, &options);
        c.humidity = None;
        assert_eq!(a, c);
    }
}

#[test]
fn one_asperity_in_contact_pulls_with_four_pi_r_gamma_cos_theta() {
    // Sparse summits (2πRN d_K ~ 1e-9: independent menisci), pressed far into contact
    // (h ≈ -8: every summit touches), no solid adhesion: the capillary load per summit
    // is -2πR γ_L (cos θ_a + cos θ_b) = -4πRγ_L cos θ, to O(F_w) ~ 1e-9.
    let mut scene = hub(Some(0.7));
    scene.work_of_adhesion = 0.0;
    scene.asperity_density = 1e3;
    scene.nominal_area = 1.0;
    scene.sigma = 1e-9;
    let theta = 30f64.to_radians();
    if let Some(env) = scene.environment.as_mut() {
        env.contact_angle_a = theta;
        env.contact_angle_b = theta;
    }
    let env = scene.environment.unwrap();
    let m = env.meniscus().unwrap();
    let e = wearopt::model::wear::equivalent_modulus(&scene);
    let k = 4.0 * e / 3.0;
    let cap = Capillary::new(
        &m,
        k,
        scene.sigma,
        scene.asperity_radius,
        scene.asperity_density,
    );
    let at = cap.at(-8.0);
    let per_area = at.load
        * (-at.exponent).exp()
        * k
        * scene.asperity_density
        * scene.asperity_radius.sqrt()
        * scene.sigma.powf(1.5)
        / (2.0 * PI).sqrt();
    let per_summit = per_area / scene.asperity_density;
    let gamma_l = Liquid::Water.surface_tension(env.temperature);
    let want = -4.0 * PI * scene.asperity_radius * gamma_l * theta.cos();
    assert!(rel(per_summit, want, 0.0) < 1e-8, "{per_summit} vs {want}");
}

#[test]
fn a_flooded_interface_has_the_liquids_work_of_adhesion() {
    // σ ≪ d_K and 2πRN d_K ≫ 1: Γ → γ_L (cos θ_a + cos θ_b). Smoother, denser summits and
    // wetter air bring Γ/γ_c monotonically to 1; the solid law adds its own adhesion
    // (here none) and stores a little elastic energy in the contacts (Γ < γ_c).
    let mut last = f64::INFINITY;
    for (sigma, density, rh) in [
        (1e-9, 1e13, 0.9),
        (0.5e-9, 1e14, 0.95),
        (0.2e-9, 1e15, 0.98),
    ] {
        let mut scene = hub(Some(rh));
        scene.work_of_adhesion = 0.0;
        scene.sigma = sigma;
        scene.asperity_density = density;
        let env = scene.environment.unwrap();
        let m = env.meniscus().unwrap();
        let ev = evaluate(&scene, &EvaluationOptions::default());
        let gamma = ev.humidity.unwrap().apparent_work_of_adhesion.unwrap();
        let miss = 1.0 - gamma / m.adhesion;
        assert!(
            miss > 0.0 && miss < last,
            "σ {sigma}: Γ {gamma} against {}",
            m.adhesion
        );
        last = miss;
    }
    assert!(last < 0.02, "{last}");
}

/// As RH → 1 the Kelvin gap outgrows any separation the quadrature reaches (k = d_K/σ
/// passes 1e6 near RH = 1 − 3e-7 at σ = 3 nm): the meniscus beyond it is taken in closed
/// form, and Γ stays at the flooded limit γ_L (cos θ_a + cos θ_b) (docs/model.md §10).
/// Before, the work fell to 0.041 J/m² at 1 − 1e-7 and 0.004 at 1 − 1e-8 (limit 0.1439).
/// Without solid adhesion the miss is the elastic energy stored and the unwetted fringe,
/// O(1/k + 1/F): below 1e-4 here.
#[test]
fn the_flooded_limit_holds_as_humidity_reaches_one() {
    for dry in [1e-6, 1e-7, 1e-8, 1e-10] {
        let mut scene = hub(Some(1.0 - dry));
        scene.work_of_adhesion = 0.0;
        let m = scene.environment.unwrap().meniscus().unwrap();
        let ev = evaluate(&scene, &EvaluationOptions::default());
        let gamma = ev.humidity.unwrap().apparent_work_of_adhesion.unwrap();
        let miss = 1.0 - gamma / m.adhesion;
        assert!(
            (0.0..1e-4).contains(&miss),
            "RH = 1 − {dry:e}: Γ {gamma} J/m² against γ_c {} (k = {})",
            m.adhesion,
            m.height / scene.sigma
        );
    }
}

/// Two right angles condense nothing (cos θ_a + cos θ_b = 0, docs/model.md §10), although
/// cos(π/2) in floating point is 6.1e-17: the humid scene is the dry one bit for bit.
#[test]
fn right_contact_angles_condense_no_meniscus() {
    let right = Environment {
        relative_humidity: 0.9,
        contact_angle_a: PI / 2.0,
        contact_angle_b: (90.0f64).to_radians(),
        ..Environment::default()
    };
    assert!(right.meniscus().is_none(), "{:?}", right.meniscus());
    let mut humid = hub(None);
    humid.environment = Some(right);
    let (wet, dry) = (
        evaluate(&humid, &EvaluationOptions::default()),
        evaluate(&hub(None), &EvaluationOptions::default()),
    );
    assert_eq!(wet.wear_rate.to_bits(), dry.wear_rate.to_bits());
    assert_eq!(wet.pull_off_force, dry.pull_off_force);
}

#[test]
fn the_load_slope_changes_sign_once_with_a_meniscus() {
    // capillary.rs proves P̄'/φ increasing for a law with J ≥ 0; check the sign of P̄'
    // on a fine grid for both laws and a few menisci, and that the landscape finds
    // exactly that one minimum.
    for law in [
        AsperityLaw::Jkr,
        AsperityLaw::Dmt(Attraction::VanDerWaals { range: 0.1 }),
        AsperityLaw::Dmt(Attraction::Dugdale { range: 0.1 }),
    ] {
        for (k, f, p) in [(0.5, 0.04, 1.3), (6.8, 0.51, 0.095), (30.0, 50.0, 0.01)] {
            let model = Model::with_law(
                Coefficients::from_indices(184.0, 1.0),
                law,
                Quadrature::default(),
            )
            .with_capillary(Some(Capillary {
                range: k,
                wetting: f,
                flooded: p,
            }));
            let mut changes = 0;
            let mut prev = model.at(-6.0).dload_dh().signum();
            let mut h = -6.0;
            while h < 80.0 {
                h += 0.01;
                let s = model.at(h).dload_dh().signum();
                if s != prev && s != 0.0 {
                    changes += 1;
                    prev = s;
                }
            }
            assert_eq!(changes, 1, "{law:?} k = {k}");
            let land = landscape(&model);
            assert_eq!(land.critical_points.len(), 1, "{law:?} k = {k}");
        }
    }
}

#[test]
fn humidity_raises_the_pull_off_and_the_work_of_adhesion() {
    // DelRio's shape on the hub (DMT, van der Waals): Γ barely above its dry value at
    // low humidity, then rising steeply; the model's §9 worked numbers: ≈ 0.06 mJ/m² dry,
    // ≈ 39 mJ/m² at RH = 0.95.
    let options = EvaluationOptions::default();
    let gamma = |rh: f64| {
        evaluate(&hub(Some(rh)), &options)
            .humidity
            .unwrap()
            .apparent_work_of_adhesion
            .unwrap()
    };
    let dry = gamma(0.0);
    assert!((dry - 5.5e-5).abs() < 0.5e-5, "{dry}");
    let wet = gamma(0.95);
    assert!((wet - 0.039).abs() < 0.001, "{wet}");
    let mut last = dry;
    for rh in [0.1, 0.3, 0.5, 0.7, 0.9, 0.95] {
        let g = gamma(rh);
        assert!(g > last, "Γ({rh}) = {g} ≤ {last}");
        last = g;
    }
    assert!(gamma(0.1) < 2.0 * dry);
}

/// `wearopt eval` on the shipped humid hub: the §9 keys, in JSON and text.
#[test]
fn eval_reports_the_humid_air() {
    use crate::common::{stdout, wearopt};
    let out = stdout(
        wearopt().args(["eval", "problems/micro-gear-humid.toml", "--format", "json"]),
        0,
    );
    let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
    for key in [
        "capillary_load",
        "kelvin_radius",
        "meniscus_height",
        "laplace_pressure",
        "wetted_fraction",
        "apparent_work_of_adhesion",
        "detachment_length",
        "relative_humidity",
    ] {
        assert!(v[key].is_number(), "{key}: {}", v[key]);
    }
    assert!(v["capillary_load"].as_f64().unwrap() < 0.0);
    // r_K at 50 % for water at 25 °C (kelvin_radius_of_water_at_half_humidity).
    assert!((v["kelvin_radius"].as_f64().unwrap() - 0.7568e-9).abs() < 1e-12);
    // A dry problem file has none of them (its JSON is as it was).
    let dry = stdout(
        wearopt().args(["eval", "problems/micro-gear.toml", "--format", "json"]),
        0,
    );
    let d: serde_json::Value = serde_json::from_slice(&dry).unwrap();
    assert!(d.get("capillary_load").is_none() && d.get("relative_humidity").is_none());
    let text = String::from_utf8(stdout(
        wearopt().args(["eval", "problems/micro-gear-humid.toml"]),
        0,
    ))
    .unwrap();
    for part in [
        "Humid air (capillary adhesion)",
        "Kelvin radius r_K: 0.7568 nm",
        "apparent work of adhesion Γ",
        "detachment length",
        "includes the capillary pull",
    ] {
        assert!(text.contains(part), "missing {part}:\n{text}");
    }
}

/// `wearopt humidity`: the CSV contract, the threshold, the plot, and bad options.
#[test]
fn humidity_command_end_to_end() {
    use crate::common::{stderr, stdout, wearopt};
    let dir = std::env::temp_dir().join(format!("wearopt-humidity-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("h.svg");
    let csv = String::from_utf8(stdout(
        wearopt().args([
            "humidity",
            "problems/micro-gear-humid.toml",
            "--from",
            "0",
            "--to",
            "0.9",
            "--points",
            "10",
            "--format",
            "csv",
            "--plot",
            svg.to_str().unwrap(),
        ]),
        0,
    ))
    .unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "relative_humidity,separation,capillary_load,pull_off_force,apparent_work_of_adhesion,wetted_fraction,wear_rate,status"
    );
    assert_eq!(lines.count(), 10);
    let plot = std::fs::read_to_string(&svg).unwrap();
    assert!(plot.contains("threshold RH"), "{plot}");
    let json: serde_json::Value = serde_json::from_slice(&stdout(
        wearopt().args([
            "humidity",
            "problems/micro-gear-humid.toml",
            "--from",
            "0",
            "--to",
            "0.9",
            "--points",
            "10",
            "--format",
            "json",
        ]),
        0,
    ))
    .unwrap();
    let t = json["threshold_humidity"].as_f64().unwrap();
    // Γ at the threshold is ten times the dry Γ (bisected to 1e-12 in RH);
    // the shipped humid hub takes the Lennard-Jones law.
    let g = |rh: f64| {
        let scene = Scene {
            adhesion_model: wearopt::model::AdhesionModel::LennardJones,
            ..hub(Some(rh))
        };
        evaluate(&scene, &EvaluationOptions::default())
            .humidity
            .unwrap()
            .apparent_work_of_adhesion
            .unwrap()
    };
    let dry = json["dry_work_of_adhesion"].as_f64().unwrap();
    assert!(
        g(t) >= 10.0 * dry && g(t - 1e-9) < 10.0 * dry,
        "threshold {t}"
    );
    for (args, words) in [
        (
            vec!["--from", "0.5", "--to", "0.2", "--points", "5"],
            "--from 0.5 is above --to 0.2",
        ),
        (
            vec!["--from", "0", "--to", "0.5", "--points", "1"],
            "--points 1: must lie in 2..=",
        ),
        (
            vec!["--from", "0", "--to", "1", "--points", "5"],
            "--to 1: a relative humidity must lie in [0, 1)",
        ),
    ] {
        let mut cmd = wearopt();
        cmd.args(["humidity", "problems/micro-gear-humid.toml"])
            .args(&args);
        let err = String::from_utf8(stderr(&mut cmd, 2)).unwrap();
        assert!(err.contains(words), "{args:?}: {err}");
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// The shipped coating study (`problems/micro-gear-coating-study.toml`): at 90 % humidity
/// the bare oxide sticks (its capillary pull is 2.3 mN against a 50 µN spring); the
/// optimum coats the hub so that water no longer condenses (cos θ_a + cos θ_b ≤ 0, θ ≥ 90°),
/// where the pull-off is the dry van der Waals one, and keeps the least wear there.
#[test]
fn a_hydrophobic_coating_frees_the_hub_in_humid_air() {
    use wearopt::model::SceneParameter;
    let path = std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear-coating-study.toml"
    ));
    let problem = wearopt::problem::load(path).unwrap();
    let angle = problem
        .study
        .design
        .iter()
        .find(|d| d.name == SceneParameter::ContactAngle)
        .expect("contact_angle is a design variable");
    assert!(angle.min == 0.0 && (angle.max - 110f64.to_radians()).abs() < 1e-15);
    let doc = wearopt::app::optimize::optimize(&problem, "coating", Default::default()).unwrap();
    let json = wearopt::report::optimize::json_document(&doc);
    assert_eq!(json["status"], "optimal", "{json}");
    let theta = json["design"]["contact_angle"].as_f64().unwrap();
    assert!(
        theta >= 90f64.to_radians() && theta <= 110f64.to_radians(),
        "θ = {}°",
        theta.to_degrees()
    );
    let pull_off = json["evaluation"]["pull_off_force"].as_f64().unwrap();
    assert!(pull_off <= 50e-6, "{pull_off}");
    // No meniscus at the optimum: the capillary load is gone.
    let mut scene = problem.scene.clone();
    SceneParameter::ContactAngle.set(&mut scene, theta);
    SceneParameter::WorkOfAdhesion.set(
        &mut scene,
        json["design"]["work_of_adhesion"].as_f64().unwrap(),
    );
    let ev = evaluate(&scene, &EvaluationOptions::default());
    assert_eq!(ev.humidity.unwrap().kelvin_radius, None);
}

/// A study over a humidity range (`relative_humidity = { min, max }`): every limit holds at
/// each of `humidity_points` humidities, the objective is taken at the worst one for it,
/// and the report says where each limit binds.
#[test]
fn a_study_over_a_humidity_range_holds_at_every_humidity() {
    use wearopt::model::SceneParameter;
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear-coating-study.toml"
    ))
    .unwrap()
    .replace("humidity_points = 9", "humidity_points = 7")
    .replace(
        "min = \"0 deg\", max = \"110 deg\"",
        "min = \"0 deg\", max = \"80 deg\"",
    )
    .replace("max = \"50 uN\"", "max = \"1 mN\"");
    let problem = wearopt::problem::parse(&text, "range.toml").unwrap();
    let range = problem.scene.environment.unwrap().humidity_range.unwrap();
    assert_eq!((range.min, range.max, range.points), (0.0, 0.9, 7));
    let doc = wearopt::app::optimize::optimize(&problem, "range", Default::default()).unwrap();
    let json = wearopt::report::optimize::json_document(&doc);
    assert_eq!(json["status"], "optimal", "{json}");
    // Wear grows with humidity: the objective's worst humidity is the wettest.
    assert_eq!(json["objective_humidity"], 0.9);
    // Pull-off grows with humidity: the limit binds at the wettest end.
    assert_eq!(json["constraints"][0]["humidity"], 0.9, "{json}");
    // Every humidity of the range meets the limit at the optimum.
    let mut scene = problem.scene.clone();
    for (k, p) in [
        ("contact_angle", SceneParameter::ContactAngle),
        ("work_of_adhesion", SceneParameter::WorkOfAdhesion),
    ] {
        p.set(&mut scene, json["design"][k].as_f64().unwrap());
    }
    for rh in range.humidities() {
        if let Some(env) = scene.environment.as_mut() {
            env.relative_humidity = rh;
        }
        let f = evaluate(&scene, &EvaluationOptions::default())
            .pull_off_force
            .unwrap();
        assert!(f <= 1e-3, "RH {rh}: pull-off {f}");
    }
    // Bad ranges name the field.
    for (bad, words) in [
        (
            "relative_humidity = { min = 0.9, max = 0.5 }",
            "min must be < max",
        ),
        (
            "relative_humidity = { min = 0.0, max = 1.0 }",
            "must be in [0, 1)",
        ),
        (
            "relative_humidity = 0.5\nhumidity_points = 3",
            "applies to a humidity range only",
        ),
    ] {
        let t = text
            .replace("humidity_points = 7", "")
            .replace("relative_humidity = { min = 0.0, max = 0.9 }", bad);
        let err = wearopt::problem::parse(&t, "bad.toml")
            .unwrap_err()
            .to_string();
        assert!(err.contains(words), "{bad}: {err}");
    }
}

/// DelRio et al. (2007): the threshold humidity rises with the roughness. The humid hub at
/// σ = 1, 3 and 10 nm (DMT, van der Waals, water wetting both bodies): 46 %, 76 % and 93 %.
#[test]
fn the_threshold_humidity_rises_with_roughness() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/problems/micro-gear-humid.toml"
    ))
    .unwrap();
    let options = wearopt::app::humidity::HumidityOptions {
        from: 0.0,
        to: 0.98,
        points: 50,
    };
    let mut last = 0.0;
    for sigma in ["1 nm", "3 nm", "10 nm"] {
        let t = text.replace("sigma = \"3 nm\"", &format!("sigma = \"{sigma}\""));
        let problem = wearopt::problem::parse(&t, "hub.toml").unwrap();
        let doc = wearopt::app::humidity::humidity(&problem, "hub", &options).unwrap();
        let threshold = doc
            .threshold_humidity
            .expect("Γ reaches ten times its dry value");
        assert!(
            threshold > last,
            "σ = {sigma}: threshold {threshold} ≤ {last}"
        );
        last = threshold;
    }
}

/// A meniscus's flat pull no longer sends the separation search far out: on
/// the humid hub (under the Lennard-Jones law as shipped, and under DMT) the
/// load's Newton step from the plateau, where P̄ ≤ 0 < W, went to h = −9
/// and the solve took 14 and 16 evaluations; a unit step towards the
/// contacts takes 9.
#[test]
fn a_meniscus_plateau_costs_few_evaluations() {
    for law in [
        wearopt::model::AdhesionModel::LennardJones,
        wearopt::model::AdhesionModel::Dmt,
    ] {
        let scene = Scene {
            adhesion_model: law,
            ..hub(Some(0.5))
        };
        let ev = evaluate(&scene, &EvaluationOptions::default());
        assert!(
            ev.evaluations <= 10,
            "{law:?}: {} evaluations",
            ev.evaluations
        );
    }
}

/// Γ starts its search for the unloaded equilibrium (P̄ = 0) where the
/// landscape's points, the operating point and the pull-off bracket it, and
/// stops within 1e-3 (in units of the length over which P̄ bends) of the
/// root, integrating the strip left from P̄ and its derivatives there
/// (`work::work_of_separation_near`): on the humid hub under the
/// Lennard-Jones law and DMT, from dry to wet air, the same Γ to 1e-12 as
/// from the root solved to rounding from the search's own start, in fewer
/// evaluations (the hub at RH 0.5 under the Lennard-Jones law: 4 against 6).
#[test]
fn the_unloaded_equilibrium_is_found_from_what_the_evaluation_knows() {
    use wearopt::model::separation::{solve_separation_at, solve_separation_within, unloaded_hint};
    use wearopt::model::work::{work_of_separation, UNLOADED_TOLERANCE};
    let (mut cheaper, mut cases) = (0, 0);
    for law in [
        wearopt::model::AdhesionModel::LennardJones,
        wearopt::model::AdhesionModel::Dmt,
    ] {
        for rh in [0.05, 0.5, 0.9] {
            let scene = Scene {
                adhesion_model: law,
                ..hub(Some(rh))
            };
            let ev = evaluate(&scene, &EvaluationOptions::default());
            let got = ev.humidity.unwrap().apparent_work_of_adhesion.unwrap();
            let m = wearopt::model::wear::model_of(&scene, Quadrature::default());
            let land = landscape(&m);
            let (strict, _) = solve_separation_at(&m, 0.0, Some(&land), None);
            let SeparationOutcome::Contact {
                separation,
                evaluations: slow,
            } = strict
            else {
                panic!("{law:?} RH {rh}: no unloaded equilibrium");
            };
            let scale = ev.load_scale / scene.nominal_area * scene.sigma;
            let want = work_of_separation(&m, separation).0 * scale;
            assert!(
                (got - want).abs() <= 1e-12 * want,
                "{law:?} RH {rh}: Γ {got} against {want}"
            );
            let (_, op) = solve_separation_at(&m, ev.nondimensional_load, Some(&land), None);
            let hint = unloaded_hint(op.as_ref(), &land, &pull_off_of(&land).unwrap());
            let (near, _) = solve_separation_within(&m, 0.0, Some(&land), hint, UNLOADED_TOLERANCE);
            let SeparationOutcome::Contact {
                evaluations: fast, ..
            } = near
            else {
                panic!("{law:?} RH {rh}: {near:?}");
            };
            assert!(fast <= slow, "{law:?} RH {rh}: {fast} > {slow} evaluations");
            cheaper += usize::from(fast < slow);
            cases += 1;
        }
    }
    assert!(cheaper * 2 >= cases, "cheaper in {cheaper} of {cases}");
}
