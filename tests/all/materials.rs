//! Discrete material choice (`[design] materials`): the ranking agrees with each
//! material's study run on its own, is sorted by wear rate, does not depend on the
//! thread count, and excludes or evaluates where the module docs say.

use crate::common;
use crate::common::wearopt;

use wearopt::model::AdhesionModel;
use wearopt::optimize::materials::{
    rank_materials, Exclusion, MaterialOutcome, MaterialRanking, MaterialStatus,
};
use wearopt::optimize::{optimize, OptimizationStatus, Study};
use wearopt::optimize::{DesignVariable, SceneParameter};
use wearopt::problem::{catalogue, Problem};

const FILE: &str = "problems/materials-study.toml";

fn problem() -> Problem {
    wearopt::problem::load(std::path::Path::new(FILE)).expect("shipped study loads")
}

fn rank(p: &Problem) -> MaterialRanking {
    let study = Study {
        scene: &p.scene,
        design: &p.study.design,
        objective: p.study.objective,
        constraints: &p.study.constraints,
        settings: &p.study.optimizer,
    };
    let materials: Vec<_> = p
        .study
        .materials
        .iter()
        .map(|n| catalogue::lookup(n).unwrap())
        .collect();
    rank_materials(&study, &materials, None).unwrap()
}

#[test]
fn ranking_agrees_with_each_material_studied_alone() {
    let p = problem();
    assert!(p.study.materials.len() >= 3);
    let ranking = rank(&p);
    assert_eq!(ranking.results.len(), p.study.materials.len());
    assert_eq!(
        ranking.objective_name,
        wearopt::optimize::Objective::WearRate
    );

    for r in &ranking.results {
        // The single-material study, built here from the catalogue by hand.
        let m = catalogue::lookup(r.name()).unwrap();
        let mut scene = p.scene.clone();
        scene.youngs_modulus_a = m.youngs_modulus;
        scene.poisson_ratio_a = m.poisson_ratio;
        scene.hardness = m.hardness;
        let design: Vec<DesignVariable> = p
            .study
            .design
            .iter()
            .map(|v| {
                if v.name == SceneParameter::WorkOfAdhesion {
                    let (lo, hi) = m.work_of_adhesion;
                    DesignVariable {
                        name: v.name,
                        min: v.min.max(lo),
                        max: v.max.min(hi),
                    }
                } else {
                    *v
                }
            })
            .collect();
        let wa = design
            .iter()
            .find(|v| v.name == SceneParameter::WorkOfAdhesion)
            .unwrap();
        scene.work_of_adhesion = scene.work_of_adhesion.clamp(wa.min, wa.max);
        let alone = optimize(&Study {
            scene: &scene,
            design: &design,
            objective: p.study.objective,
            constraints: &p.study.constraints,
            settings: &p.study.optimizer,
        })
        .unwrap();
        let MaterialOutcome::Optimized(o) = &r.outcome else {
            panic!("{}: not optimised", r.name())
        };
        assert_eq!(
            r.status,
            MaterialStatus::Optimized(alone.status),
            "{}",
            r.name()
        );
        assert_eq!(o.objective, alone.objective, "{}", r.name());
        assert_eq!(o.design, alone.design, "{}", r.name());
        assert_eq!(o.scene, alone.scene, "{}", r.name());
        assert_eq!(r.wear_rate(), Some(alone.evaluation.wear_rate));
        assert_eq!(r.scene().sigma, alone.scene.sigma);
        assert_eq!(r.scene().asperity_radius, alone.scene.asperity_radius);
    }

    // The study is DMT (φ0 = 0.16): van der Waals pulls on the asperities out of contact.
    // Nickel (γ ≥ 0.1 J/m², E/H = 50) cannot meet pull-off ≤ 1 µN with ψ ≤ 1 anywhere in
    // its box: a 65536-point Sobol′ `wearopt sweep` of that box (σ, R, γ) found no
    // feasible design, the least pull-off with ψ ≤ 1 being 15.4 µN. Every other film is
    // feasible, ranked and sorted by wear rate (the objective); nickel follows unranked.
    assert_eq!(p.scene.adhesion_model, AdhesionModel::Dmt);
    let (ranked, unranked): (Vec<_>, Vec<_>) =
        ranking.results.iter().partition(|r| r.rank.is_some());
    let rates: Vec<f64> = ranked.iter().map(|r| r.wear_rate().unwrap()).collect();
    assert!(rates.windows(2).all(|w| w[0] <= w[1]), "{rates:?}");
    for (i, r) in ranked.iter().enumerate() {
        assert_eq!(r.rank, Some(i + 1));
        assert_ne!(
            r.status,
            MaterialStatus::Optimized(OptimizationStatus::Infeasible)
        );
    }
    assert_eq!(ranked.len(), 4);
    assert_eq!(unranked.len(), 1);
    assert_eq!(unranked[0].name(), "nickel");
    assert_eq!(
        unranked[0].status,
        MaterialStatus::Optimized(OptimizationStatus::Infeasible)
    );
}

fn fingerprint(r: &MaterialRanking) -> Vec<(String, String, Vec<u64>)> {
    r.results
        .iter()
        .map(|x| {
            let mut bits = vec![x.objective().unwrap_or(f64::NAN).to_bits()];
            if let MaterialOutcome::Optimized(o) = &x.outcome {
                bits.extend(o.design.iter().map(|v| v.to_bits()));
                bits.push(o.kkt_residual.to_bits());
            }
            (x.name().to_string(), x.status.as_str().to_string(), bits)
        })
        .collect()
}

#[test]
fn ranking_is_identical_with_one_and_two_threads() {
    let p = problem();
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| fingerprint(&rank(&p)))
    };
    assert_eq!(run(1), run(2));
}

#[test]
fn disjoint_gamma_ranges_exclude_and_fixed_designs_are_evaluated() {
    let mut p = problem();
    // Gold's typical γ (0.2-1.5 J/m²) does not overlap the study's 5 mJ/m²-0.2 J/m².
    p.study.materials = vec!["gold".into(), "DLC".into()];
    let ranking = rank(&p);
    let gold = ranking.results.iter().find(|r| r.name() == "gold").unwrap();
    assert_eq!(gold.status, MaterialStatus::Excluded);
    assert!(matches!(
        gold.case.excluded,
        Some(Exclusion::GammaRangesDisjoint { .. })
    ));
    assert_eq!(gold.rank, None);
    assert_eq!(ranking.results[0].name(), "DLC");
    assert_eq!(ranking.best().unwrap().name(), "DLC");

    // Only materials, no continuous variable: each scene is evaluated.
    p.study.design.clear();
    p.study.materials = vec!["polysilicon".into(), "silicon carbide".into()];
    let ranking = rank(&p);
    for r in &ranking.results {
        assert!(
            matches!(r.outcome, MaterialOutcome::Evaluated { .. }),
            "{}",
            r.name()
        );
        let m = catalogue::lookup(r.name()).unwrap();
        let mut scene = p.scene.clone();
        scene.youngs_modulus_a = m.youngs_modulus;
        scene.poisson_ratio_a = m.poisson_ratio;
        scene.hardness = m.hardness;
        let ev = wearopt::model::evaluate(&scene, &Default::default());
        assert_eq!(r.wear_rate(), Some(ev.wear_rate));
    }
}

#[test]
fn cli_ranks_the_shipped_study() {
    let out = common::stdout(wearopt().args(["optimize", FILE, "--format", "json"]), 0);
    let v: serde_json::Value = serde_json::from_slice(&out).expect("valid JSON");
    let rows = v["ranking"].as_array().unwrap();
    assert_eq!(rows.len(), 5);
    for row in rows {
        for key in [
            "rank",
            "material",
            "status",
            "wear_rate",
            "sigma",
            "asperity_radius",
            "active_constraints",
        ] {
            assert!(row.get(key).is_some(), "missing {key}");
        }
    }
    assert_eq!(v["best"], rows[0]["material"]);
    // A DMT ranking: each row's pull-off is the DMT one (the constraint binds at 1 µN or
    // holds below it for the ranked films), to the solver's feasibility tolerance 1e-7
    // relative (`optimal` allows a row that far over its limit).
    for row in rows.iter().filter(|r| r["rank"].is_u64()) {
        let pull_off = row["pull_off_force"].as_f64().unwrap();
        assert!(pull_off <= 1e-6 * (1.0 + 1e-7), "{row}");
    }
    assert_eq!(rows[4]["material"], "nickel");
    assert_eq!(rows[4]["status"], "infeasible");

    let out = common::stdout(wearopt().args(["optimize", FILE]), 0);
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("material ranking"), "{text}");
    assert!(text.contains("active constraints"), "{text}");
}
