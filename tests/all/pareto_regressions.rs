//! Regression study of issue 10 for fronts (tests/data/study_wide_latch.toml):
//! every point of the front is as good as a standalone multistart run at the
//! same ε, and the knee lies on the printed range.

use std::path::Path;

use wearopt::optimize::pareto::{pareto, Silent};
use wearopt::optimize::{optimize, OptimizationStatus, Study};
use wearopt::optimize::{Constraint, ConstraintQuantity, OptimizerSettings};
use wearopt::problem::Problem;

fn load(name: &str) -> Problem {
    wearopt::problem::load(Path::new(&format!(
        "{}/tests/data/{name}",
        env!("CARGO_MANIFEST_DIR")
    )))
    .expect("regression study loads")
}

#[test]
fn every_front_point_is_as_good_as_a_standalone_run_at_its_target() {
    let p = load("study_wide_latch.toml");
    let study = Study {
        scene: &p.scene,
        design: &p.study.design,
        objective: p.study.objective,
        constraints: &p.study.constraints,
        settings: &p.study.optimizer,
    };
    let front = pareto(&study, &p.study.pareto.unwrap(), &Silent).unwrap();
    assert!(front.points.iter().filter(|q| q.on_front).count() >= 3);
    let eight = OptimizerSettings {
        starts: 8,
        ..p.study.optimizer
    };
    for q in front.points.iter().filter(|q| q.target_kind == "equal") {
        assert!(q.feasible, "point {} infeasible", q.index);
        let mut constraints = p.study.constraints.clone();
        constraints.push(Constraint {
            quantity: ConstraintQuantity::PullOffForce,
            min: Some(q.target),
            max: Some(q.target),
            only_at_objective_humidity: false,
        });
        let alone = optimize(&Study {
            constraints: &constraints,
            settings: &eight,
            ..study.clone()
        })
        .unwrap();
        if alone.feasible() {
            assert!(
                q.objective <= alone.objective * (1.0 + 1e-6),
                "point {} ({}): wear {} against {} standalone",
                q.index,
                q.status,
                q.objective,
                alone.objective
            );
        }
        if q.status == OptimizationStatus::Optimal {
            assert!(q.objective <= alone.objective * (1.0 + 1e-6));
        }
    }
    // The knee is an interior front point, found on the clamped range.
    let k = front.knee.expect("a curved front has a knee");
    let on: Vec<usize> = front.front_indices();
    assert!(k != on[0] && k != *on.last().unwrap());
}
