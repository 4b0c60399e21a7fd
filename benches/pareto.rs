//! Wear–adhesion fronts: 15 points of the micro-gear study
//! (`problems/micro-gear.toml`), and 30 points of the five-variable latch study
//! (`tests/data/study_wide_latch.toml`, issue 10: ≤ 1 s on two cores).
//! Run with `cargo bench -p wearopt-benches --bench pareto`.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::Path;

use wearopt::optimize::pareto::{pareto, Silent};
use wearopt::optimize::Study;

fn micro_gear_front(c: &mut Criterion) {
    let path =
        Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join("problems/micro-gear.toml");
    let problem = wearopt::problem::load(&path).expect("micro-gear.toml loads");
    let mut spec = problem.study.pareto.expect("micro-gear.toml has [pareto]");
    spec.points = 15;
    let study = Study {
        scene: &problem.scene,
        design: &problem.study.design,
        objective: problem.study.objective,
        constraints: &problem.study.constraints,
        settings: &problem.study.optimizer,
    };
    let mut group = c.benchmark_group("pareto");
    group.sample_size(10);
    group.bench_function("micro-gear front, 15 points", |b| {
        b.iter(|| black_box(pareto(&study, &spec, &Silent).expect("front")))
    });
    group.finish();
}

fn five_variable_front(c: &mut Criterion) {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .join("tests/data/study_wide_latch.toml");
    let problem = wearopt::problem::load(&path).expect("study_wide_latch.toml loads");
    let mut spec = problem.study.pareto.expect("the study has [pareto]");
    spec.points = 30;
    let study = Study {
        scene: &problem.scene,
        design: &problem.study.design,
        objective: problem.study.objective,
        constraints: &problem.study.constraints,
        settings: &problem.study.optimizer,
    };
    let two = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let mut group = c.benchmark_group("pareto");
    group.sample_size(10);
    group.bench_function("five-variable latch front, 30 points, two threads", |b| {
        b.iter(|| two.install(|| black_box(pareto(&study, &spec, &Silent).expect("front"))))
    });
    group.finish();
}

criterion_group!(benches, micro_gear_front, five_variable_front);
criterion_main!(benches);
