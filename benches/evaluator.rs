//! Speed of the evaluator (issue: non-dimensional evaluation ≤ 1 µs median,
//! dimensional evaluation with the separation solve ≤ 20 µs median), for the JKR
//! law and the DMT law with both attractions (issue 11: one DMT P̄ + Ā ≤ 1 µs, a DMT
//! scene with separation solve and pull-off ≤ 20 µs).
//!
//! The Lennard-Jones law's integrals (issue 23: one P̄ + Ā ≤ 2 µs) at one h.
//!
//! Run: `cargo bench -p wearopt-benches --bench evaluator`

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use wearopt::model::{
    evaluate, AdhesionModel, AsperityLaw, Attraction, AttractionKind, Coefficients,
    EvaluationOptions, Model, Quadrature,
};

fn nondimensional(c: &mut Criterion) {
    let mut g = c.benchmark_group("nondimensional P̄, Ā at one h");
    for &(theta, lambda, h) in &[
        (10.0, 1.0, 1.0),
        (100.0, 5.0, 3.0),
        (0.1, 1e-3, -2.0),
        (1e4, 100.0, 20.0),
    ] {
        let m = Model::new(Coefficients::from_indices(theta, lambda));
        g.bench_function(format!("theta={theta} lambda={lambda} h={h}"), |b| {
            b.iter(|| {
                let at = m.at(black_box(h));
                black_box((at.load(), at.area()))
            })
        });
    }
    let gw = Model::new(Coefficients::new(0.0, f64::INFINITY));
    g.bench_function("greenwood-williamson h=1", |b| {
        b.iter(|| black_box(gw.at(black_box(1.0)).load()))
    });
    g.finish();
}

/// DMT P̄ and Ā at one h: the hub's θ = 184 with its ranges (z0 = Z0/σ = 0.1, Δ_h =
/// 0.1/1.03), and θ = 10, λ = 1, h = 1 as for JKR.
fn nondimensional_dmt(c: &mut Criterion) {
    let mut g = c.benchmark_group("nondimensional DMT P̄, Ā at one h");
    for &(theta, lambda, h) in &[(10.0, 1.0, 1.0), (184.0, 10.0, 2.0)] {
        for attraction in [
            Attraction::VanDerWaals { range: 0.1 },
            Attraction::Dugdale { range: 0.1 / 1.03 },
        ] {
            let m = Model::with_law(
                Coefficients::from_indices(theta, lambda),
                AsperityLaw::Dmt(attraction),
                Quadrature::default(),
            );
            let name = match attraction {
                Attraction::VanDerWaals { .. } => "van der Waals",
                Attraction::Dugdale { .. } => "Dugdale",
            };
            g.bench_function(format!("{name} theta={theta} lambda={lambda} h={h}"), |b| {
                b.iter(|| {
                    let at = m.at(black_box(h));
                    black_box((at.load(), at.area()))
                })
            });
        }
    }
    g.finish();
}

/// The micro-gear hub (φ0 = 0.374) under DMT with either attraction, and the
/// shipped DLC contact (DMT with van der Waals): separation solve and pull-off.
fn dimensional_dmt(c: &mut Criterion) {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../problems/");
    let mut g = c.benchmark_group("dimensional DMT scene evaluation");
    let hub = wearopt::problem::load(std::path::Path::new(&format!("{dir}micro-gear.toml")))
        .expect("shipped problem loads");
    for attraction in [AttractionKind::VanDerWaals, AttractionKind::Dugdale] {
        let mut scene = hub.scene.clone();
        scene.adhesion_model = AdhesionModel::Dmt;
        scene.attraction = attraction;
        g.bench_function(
            format!("micro-gear DMT {}: solve + pull-off", attraction.as_str()),
            |b| b.iter(|| black_box(evaluate(black_box(&scene), &EvaluationOptions::default()))),
        );
    }
    g.finish();
}

fn dimensional(c: &mut Criterion) {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../problems/");
    let mut g = c.benchmark_group("dimensional scene evaluation");
    for name in ["micro-gear", "dlc-contact", "gold-switch"] {
        let problem = wearopt::problem::load(std::path::Path::new(&format!("{dir}{name}.toml")))
            .expect("shipped problem loads");
        let solve_only = EvaluationOptions {
            pull_off: false,
            ..EvaluationOptions::default()
        };
        g.bench_function(format!("{name}: separation solve"), |b| {
            b.iter(|| black_box(evaluate(black_box(&problem.scene), &solve_only)))
        });
        g.bench_function(format!("{name}: solve + pull-off"), |b| {
            b.iter(|| {
                black_box(evaluate(
                    black_box(&problem.scene),
                    &EvaluationOptions::default(),
                ))
            })
        });
    }
    g.finish();
}

/// Capillary adhesion (docs/model.md §10): P̄ and Ā at one h with a meniscus, and the
/// humid hub (`problems/micro-gear-humid.toml`, RH = 50 %) against the same scene dry,
/// under its own law (Lennard-Jones) and under DMT: the separation solve alone; solve
/// and pull-off (what a study asks for); and the whole evaluation `eval` asks for
/// (and the apparent work of adhesion Γ, one integral over the summit heights and
/// one of the meniscus over h). Dry, Γ is computed where the file has a cantilever:
/// "dry with the cantilever" is the humid file without `[environment]` (the same
/// numbers asked for), "dry" drops the cantilever too (no Γ).
fn capillary(c: &mut Criterion) {
    let mut g = c.benchmark_group("capillary");
    let m = Model::with_law(
        Coefficients::from_indices(184.0, 10.0),
        AsperityLaw::Dmt(Attraction::VanDerWaals { range: 0.1 }),
        Quadrature::default(),
    );
    let wet = m.clone().with_capillary(Some(wearopt::model::Capillary {
        range: 0.5,
        wetting: 0.04,
        flooded: 1.3,
    }));
    for (name, model) in [("dry", m), ("with a meniscus", wet)] {
        g.bench_function(
            format!("DMT van der Waals P̄, Ā theta=184 h=2, {name}"),
            |b| {
                b.iter(|| {
                    let at = model.at(black_box(2.0));
                    black_box((at.load(), at.area()))
                })
            },
        );
    }
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../problems/");
    let humid =
        wearopt::problem::load(std::path::Path::new(&format!("{dir}micro-gear-humid.toml")))
            .expect("shipped problem loads")
            .scene;
    let dry = wearopt::model::Scene {
        environment: None,
        requirements: wearopt::model::Requirements {
            cantilever: None,
            ..humid.requirements
        },
        ..humid.clone()
    };
    let solve_only = EvaluationOptions {
        pull_off: false,
        ..EvaluationOptions::default()
    };
    // What studies ask for (no Γ), and what `eval` asks for (Γ in humid air).
    let without_work = EvaluationOptions {
        work_of_adhesion: false,
        ..EvaluationOptions::default()
    };
    let under_dmt = |scene: &wearopt::model::Scene| wearopt::model::Scene {
        adhesion_model: wearopt::model::AdhesionModel::Dmt,
        ..scene.clone()
    };
    // The same file without `[environment]`: its cantilever asks for Γ in dry
    // air too (what `eval` of that file computes).
    let dry_cantilever = wearopt::model::Scene {
        environment: None,
        ..humid.clone()
    };
    let (dry_dmt, humid_dmt, dry_cantilever_dmt) = (
        under_dmt(&dry),
        under_dmt(&humid),
        under_dmt(&dry_cantilever),
    );
    for (name, scene) in [
        ("dry", &dry),
        ("dry with the cantilever", &dry_cantilever),
        ("RH 50 %", &humid),
        ("DMT dry", &dry_dmt),
        ("DMT dry with the cantilever", &dry_cantilever_dmt),
        ("DMT RH 50 %", &humid_dmt),
    ] {
        g.bench_function(format!("micro-gear-humid {name}: separation solve"), |b| {
            b.iter(|| black_box(evaluate(black_box(scene), &solve_only)))
        });
        if scene.environment.is_some() {
            g.bench_function(format!("micro-gear-humid {name}: solve + pull-off"), |b| {
                b.iter(|| black_box(evaluate(black_box(scene), &without_work)))
            });
        }
        g.bench_function(
            format!("micro-gear-humid {name}: solve + pull-off (+ Γ)"),
            |b| b.iter(|| black_box(evaluate(black_box(scene), &EvaluationOptions::default()))),
        );
    }
    g.finish();
}

/// The Lennard-Jones law's P̄ shares at one h (docs/model.md §11), on the hub
/// (θ = 184, z0 = 0.1: μ = 0.374, between the table's curves, so four of them
/// are integrated) and at one of the table's curves (μ = 0.358).
fn nondimensional_lennard_jones(c: &mut Criterion) {
    use wearopt::model::lennard_jones::rough::RoughLaw;
    let mut g = c.benchmark_group("nondimensional Lennard-Jones P̄ at one h");
    let c_0 = 2.0 * std::f64::consts::PI / 184.0;
    let ell = (2.0 / c_0).powf(2.0 / 3.0);
    for (name, z0) in [
        ("hub mu=0.374", 0.1),
        (
            "one curve mu=0.358",
            wearopt::model::lennard_jones::spacing(
                wearopt::model::lennard_jones::table::curves()
                    [wearopt::model::lennard_jones::table::AT_HUNDREDTH + 76]
                    .tabor,
            ) / ell,
        ),
    ] {
        let law = RoughLaw::new(c_0, 10.0, z0).expect("in the table");
        for h in [0.5, 2.0] {
            g.bench_function(format!("{name} h={h}"), |b| {
                b.iter(|| black_box(law.at(black_box(h))))
            });
        }
        // The evaluator's P̄ + Ā (and the rest of `Integrals`): sums over the
        // scene's grid of nodes, built once with the model.
        let coefficients = wearopt::model::Coefficients::from_indices(184.0, 1.3e5);
        let model = Model::with_law(
            coefficients,
            wearopt::model::AsperityLaw::LennardJones { range: z0 },
            Quadrature::default(),
        );
        for h in [0.5, 2.0] {
            g.bench_function(format!("{name} model (grid) h={h}"), |b| {
                b.iter(|| black_box(model.at(black_box(h))))
            });
        }
        // Per scene: each curve's layout (cached), its weight and the panel
        // its Δc cuts.
        g.bench_function(format!("{name} build the grid"), |b| {
            b.iter(|| black_box(law.grid()))
        });
        // Once per process and scale: one curve's nodes laid out afresh.
        let index = law.curves().next().map_or(0, |(c, _, _)| {
            wearopt::model::lennard_jones::table::curves()
                .iter()
                .position(|d| std::ptr::eq(c, d))
                .unwrap_or(0)
        });
        g.bench_function(format!("{name} lay out one curve's nodes (once)"), |b| {
            b.iter(|| {
                black_box(wearopt::model::lennard_jones::rough::lay_out_uncached(
                    index,
                    black_box(law.ell),
                ))
            })
        });
    }
    g.finish();
}

/// The stress-assisted wear law (docs/model.md §12; issue 55: an eval ≤ 1.5× the
/// Archard eval of the same scene): `problems/silicon-sidewall-wear.toml` and its
/// Lennard-Jones twin `silicon-sidewall-wear-lj.toml`, each under its own law (normal stress, the summit integral), under `stress = "shear"` (a closed
/// form) and under Archard (the same scene, k = 1e-4), separation solve alone and with
/// the pull-off.
fn stress_assisted(c: &mut Criterion) {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../problems/");
    let load = |name: &str| {
        wearopt::problem::load(std::path::Path::new(&format!("{dir}{name}")))
            .expect("shipped problem loads")
            .scene
    };
    let mut g = c.benchmark_group("stress-assisted wear");
    for (file, scene_name) in [
        ("silicon-sidewall-wear.toml", "silicon sidewall"),
        ("silicon-sidewall-wear-lj.toml", "silicon sidewall LJ"),
    ] {
        let normal = load(file);
        let mut shear = normal.clone();
        shear.requirements.shear_strength = Some(1e9);
        if let Some(a) = shear.activation.as_mut() {
            a.stress = wearopt::model::wear_law::ContactStress::Shear;
        }
        let mut archard = normal.clone();
        archard.wear_law = wearopt::model::WearModel::Archard;
        archard.activation = None;
        archard.wear_coefficient = 1e-4;
        for (label, options) in [
            (
                "separation solve",
                EvaluationOptions {
                    pull_off: false,
                    ..EvaluationOptions::default()
                },
            ),
            ("solve + pull-off", EvaluationOptions::default()),
        ] {
            for (law, scene) in [
                ("archard", &archard),
                ("normal", &normal),
                ("shear", &shear),
            ] {
                g.bench_function(format!("{scene_name}, {law}: {label}"), |b| {
                    b.iter(|| black_box(evaluate(black_box(scene), &options)))
                });
            }
        }
    }
    g.finish();
}

criterion_group!(
    benches,
    stress_assisted,
    nondimensional,
    nondimensional_dmt,
    nondimensional_lennard_jones,
    dimensional,
    dimensional_dmt,
    capillary
);
criterion_main!(benches);
